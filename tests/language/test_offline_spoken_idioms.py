"""Spoken motion idioms and the ways a speaker says one amount (issue 9): each test is a rule of
spoken English, checked on paraphrases made up for it (none is a bench prompt)."""

from __future__ import annotations

import pytest

from langnav.language.intent import Direction, Intent, Movement
from langnav.language.offline import translate_offline
from langnav.language.offline.numbers import Quantity, QuantityKind, one_amount
from langnav.language.offline.speech import unfinished_number

FT, IN, YD = 0.3048, 0.0254, 0.9144
Plain = tuple[Movement, Direction | None, float | None]


def _plain(intent: Intent) -> list[Plain]:
    out: list[Plain] = []
    for s in intent.steps:
        value = s.distance_m if s.movement == Movement.MOVE else s.angle_deg
        out.append((s.movement, s.direction, None if value is None else round(value, 3)))
    return out


def _move(direction: Direction, metres: float) -> Plain:
    return (Movement.MOVE, direction, round(metres, 3))


def _turn(direction: Direction, degrees: float | None) -> Plain:
    return (Movement.ROTATE, direction, None if degrees is None else round(float(degrees), 3))


def _asks(intent: Intent) -> bool:
    return not intent.steps and intent.clarification is not None


# ------------------------------------------------------------------------------ informal verbs of going
@pytest.mark.parametrize(("prompt", "want"), [
    ("push forward two metres", [_move(Direction.FORWARD, 2)]),
    ("push ahead 3 feet please", [_move(Direction.FORWARD, 3 * FT)]),
    ("press on another metre", [_move(Direction.FORWARD, 1)]),
    ("push back half a metre", [_move(Direction.BACKWARD, 0.5)]),
    ("mosey forward a yard", [_move(Direction.FORWARD, YD)]),
    ("scoot left two feet", [_move(Direction.LEFT, 2 * FT)]),
    ("trundle ahead four metres", [_move(Direction.FORWARD, 4)]),
    ("glide forward one metre", [_move(Direction.FORWARD, 1)]),
    ("zoom ahead 2 m", [_move(Direction.FORWARD, 2)]),
    ("shuffle back six inches", [_move(Direction.BACKWARD, 6 * IN)]),
    ("push up one metre", [_move(Direction.FORWARD, 1)]),
])
def test_a_verb_of_going_with_no_object_moves_the_robot(prompt: str, want: list[Plain]) -> None:
    assert _plain(translate_offline(prompt)) == want


@pytest.mark.parametrize("prompt", ["push the box", "push the door open", "push on the door", "push back the chair",
                                    "press the button"])
def test_a_verb_of_going_with_a_thing_as_object_moves_that_thing_and_is_refused(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert not intent.steps and intent.clarification


# ------------------------------------------------------------------------------ informal verbs of turning
@pytest.mark.parametrize(("prompt", "want"), [
    ("swing left", [_turn(Direction.LEFT, None)]),
    ("swing right 45 degrees", [_turn(Direction.RIGHT, 45)]),
    ("whip around", [_turn(Direction.AROUND, 180)]),
    ("bank hard right thirty degrees", [_turn(Direction.RIGHT, 30)]),
    ("hook left twenty degrees", [_turn(Direction.LEFT, 20)]),
    ("swerve to the left 15 degrees", [_turn(Direction.LEFT, 15)]),
    ("kick it around", [_turn(Direction.AROUND, 180)]),
    ("bring it around", [_turn(Direction.AROUND, 180)]),
    ("swing it round to the right ninety degrees", [_turn(Direction.RIGHT, 90)]),
])
def test_a_verb_of_swinging_a_vehicle_with_a_side_is_a_turn(prompt: str, want: list[Plain]) -> None:
    assert _plain(translate_offline(prompt)) == want


@pytest.mark.parametrize(("prompt", "want"), [
    ("back it up two feet", [_move(Direction.BACKWARD, 2 * FT)]),
    ("roll it forward a metre", [_move(Direction.FORWARD, 1)]),
    ("move it left half a metre", [_move(Direction.LEFT, 0.5)]),
])
def test_the_drivers_it_is_the_robot_not_a_place(prompt: str, want: list[Plain]) -> None:
    assert _plain(translate_offline(prompt)) == want


@pytest.mark.parametrize(("prompt", "want"), [
    ("hit a three sixty", [_turn(Direction.LEFT, 360)]),
    ("pull a one eighty", [_turn(Direction.AROUND, 180)]),
    ("bust a 180", [_turn(Direction.AROUND, 180)]),
    ("pull a u-turn", [_turn(Direction.AROUND, 180)]),
    ("throw a quick left", [_turn(Direction.LEFT, None)]),
    ("hit a right", [_turn(Direction.RIGHT, None)]),
    ("do a full three sixty", [_turn(Direction.LEFT, 360)]),
])
def test_a_turn_named_as_a_thing_one_does_is_that_turn(prompt: str, want: list[Plain]) -> None:
    assert _plain(translate_offline(prompt)) == want


@pytest.mark.parametrize("prompt", ["hit a wall", "hit the box", "hit the person in front of you", "hit a chair"])
def test_hitting_a_thing_is_still_refused(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert not intent.steps and "won't" in (intent.clarification or "")


@pytest.mark.parametrize(("prompt", "want"), [
    ("one eighty", [_turn(Direction.AROUND, 180)]),
    ("180, then drive forward two metres", [_turn(Direction.AROUND, 180), _move(Direction.FORWARD, 2)]),
    ("a quick three sixty please", [_turn(Direction.LEFT, 360)]),
    ("spin around, one eighty", [_turn(Direction.AROUND, 180)]),
    ("turn right, 180", [_turn(Direction.RIGHT, 180)]),
])
def test_one_eighty_and_three_sixty_alone_are_turns_never_metres(prompt: str, want: list[Plain]) -> None:
    assert _plain(translate_offline(prompt)) == want


@pytest.mark.parametrize(("prompt", "want"), [
    ("give me two more feet", [_move(Direction.FORWARD, 2 * FT)]),
    ("give me a yard backwards", [_move(Direction.BACKWARD, YD)]),
    ("give me ninety degrees to the left", [_turn(Direction.LEFT, 90)]),
])
def test_give_me_an_amount_is_that_motion(prompt: str, want: list[Plain]) -> None:
    assert _plain(translate_offline(prompt)) == want


@pytest.mark.parametrize(("prompt", "want"), [
    ("please make turn on left, thirty degree", [_turn(Direction.LEFT, 30)]),
    ("do turn to right 45 degree", [_turn(Direction.RIGHT, 45)]),
    ("make turn left ninety", [_turn(Direction.LEFT, 90)]),
])
def test_learner_grammar_without_the_article_is_read(prompt: str, want: list[Plain]) -> None:
    assert _plain(translate_offline(prompt)) == want


# ------------------------------------------------------------------------------ stopping
@pytest.mark.parametrize("prompt", ["hold it", "hold it, hold it", "hold it right there", "hold up", "hang on",
                                    "that'll do", "whoa there", "ok stop", "stop stop stop", "wait a second"])
def test_stopping_idioms_are_one_stop(prompt: str) -> None:
    assert _plain(translate_offline(prompt)) == [(Movement.STOP, None, None)]


@pytest.mark.parametrize("prompt", [
    "where are you? where are you now?",
    "Where are you, love? Tell me where you are.",
    "show me the map. can I see the map?",
    "show me the minimap",
])
def test_a_question_asked_again_is_answered_once(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert [s.movement for s in intent.steps] == [Movement.QUERY]


def test_a_question_after_a_motion_is_a_new_question() -> None:
    intent = translate_offline("where are you? move forward 2 m. where are you now?")
    assert [s.movement for s in intent.steps] == [Movement.QUERY, Movement.MOVE, Movement.QUERY]


# ------------------------------------------------------------------------------ one amount, said several ways
@pytest.mark.parametrize(("prompt", "metres"), [
    ("go forward two feet and six inches", 2 * FT + 6 * IN),
    ("move ahead 1 foot 3 inches", FT + 3 * IN),
    ("drive forward one metre and twenty centimetres", 1.2),
    ("go forward a yard and a foot", YD + FT),
])
def test_a_compound_measure_largest_unit_first_is_one_amount(prompt: str, metres: float) -> None:
    assert _plain(translate_offline(prompt)) == [_move(Direction.FORWARD, metres)]


@pytest.mark.parametrize(("prompt", "want"), [
    ("do a full spin, three sixty", [_turn(Direction.LEFT, 360)]),
    ("spin all the way around, a full three sixty", [_turn(Direction.LEFT, 360)]),
    ("turn left ninety, ninety degrees", [_turn(Direction.LEFT, 90)]),
    ("move forward two hundred centimetres, that's two metres", [_move(Direction.FORWARD, 2)]),
    ("go forward two metres, that's about six feet", [_move(Direction.FORWARD, 2)]),
    ("I think it's about two metres? go forward two metres", [_move(Direction.FORWARD, 2)]),
])
def test_the_same_amount_said_again_is_done_once(prompt: str, want: list[Plain]) -> None:
    assert _plain(translate_offline(prompt)) == want


@pytest.mark.parametrize("prompt", ["turn left 90 degrees 45 degrees", "move forward 3 feet 2 feet",
                                    "go forward six inches two feet", "go forward two metres, that's about sixty feet"])
def test_two_different_amounts_for_one_motion_are_asked_about(prompt: str) -> None:
    assert _asks(translate_offline(prompt))


def test_one_amount_rule() -> None:
    ft = Quantity(QuantityKind.LENGTH, 2 * FT, 0, 1, unit=FT)
    inch = Quantity(QuantityKind.LENGTH, 6 * IN, 2, 3, unit=IN)
    metres = Quantity(QuantityKind.LENGTH, 2.0, 0, 1, unit=1.0)
    cm = Quantity(QuantityKind.LENGTH, 2.0, 2, 3, unit=0.01)
    assert one_amount([ft, inch]) == pytest.approx(2 * FT + 6 * IN)
    assert one_amount([inch, ft]) is None  # a larger unit after a smaller one is no compound
    assert one_amount([metres, cm]) == pytest.approx(2.0)  # the same amount in other units
    assert one_amount([ft, ft]) == pytest.approx(2 * FT)
    assert one_amount([]) is None


@pytest.mark.parametrize(("prompt", "want"), [
    ("turn left, it's about thirty degrees", [_turn(Direction.LEFT, 30)]),
    ("okay, it's forty five degrees to your right", [_turn(Direction.RIGHT, 45)]),
    ("go forward, that would be three feet", [_move(Direction.FORWARD, 3 * FT)]),
])
def test_an_amount_stated_completes_the_instruction(prompt: str, want: list[Plain]) -> None:
    assert _plain(translate_offline(prompt)) == want


@pytest.mark.parametrize(("prompt", "want"), [
    ("turn a little to the right. only a little.", [(Movement.ROTATE, Direction.RIGHT, None)]),
    ("back up a bit, just a bit", [(Movement.MOVE, Direction.BACKWARD, None)]),
])
def test_a_little_said_again_insists_on_it(prompt: str, want: list[Plain]) -> None:
    assert _plain(translate_offline(prompt)) == want


# ------------------------------------------------------------------------------ cut-off numbers
@pytest.mark.parametrize("prompt", ["turn left forty fi-", "go forward twenty t-", "rotate right thir-",
                                    "move back fif-", "turn one hun-"])
def test_a_number_cut_off_is_asked_about(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert _asks(intent)
    assert "cut off" in (intent.clarification or "")


@pytest.mark.parametrize(("prompt", "want"), [
    ("turn left forty fi- forty five degrees", [_turn(Direction.LEFT, 45)]),
    ("move forward two fe- two feet", [_move(Direction.FORWARD, 2 * FT)]),
    ("turn nin- ninety degrees right", [_turn(Direction.RIGHT, 90)]),
    ("turn left forty fi-, sorry, fifty degrees", [_turn(Direction.LEFT, 50)]),
    ("go fo- forward two metres", [_move(Direction.FORWARD, 2)]),
])
def test_a_number_cut_off_and_said_again_is_read(prompt: str, want: list[Plain]) -> None:
    assert _plain(translate_offline(prompt)) == want


def test_unfinished_number_points_at_the_words() -> None:
    assert unfinished_number("turn left forty fi-") == "left forty fi-"
    assert unfinished_number("turn deg- ninety degrees") is None


# ------------------------------------------------------------------------------ lists and remarks
@pytest.mark.parametrize("prompt", [
    "Step one, turn left sixty degrees. Step two, go forward one metre.",
    "1) turn left 60 degrees 2) go forward 1 m",
    "number one: turn left sixty degrees; number two: move forward one metre",
    "1. Turn left 60 degrees. 2. Move forward 1 metre.",
])
def test_the_numbers_of_a_list_are_no_amounts(prompt: str) -> None:
    assert _plain(translate_offline(prompt)) == [_turn(Direction.LEFT, 60), _move(Direction.FORWARD, 1)]


@pytest.mark.parametrize(("prompt", "want"), [
    ("move forward two metres, okay?", [_move(Direction.FORWARD, 2)]),
    ("back up one foot, that's one foot, right?", [_move(Direction.BACKWARD, FT)]),
    ("wait, which way is north... okay, face north", [(Movement.ROTATE, None, None)]),
    ("hang on, turn left 30 degrees", [_turn(Direction.LEFT, 30)]),
])
def test_tag_questions_and_holding_the_floor_ask_for_nothing(prompt: str, want: list[Plain]) -> None:
    assert _plain(translate_offline(prompt)) == want


@pytest.mark.parametrize(("prompt", "want"), [
    ("go forward 3 feet, then 3 feet to your right, then turn left",
     [_move(Direction.FORWARD, 3 * FT), _move(Direction.RIGHT, 3 * FT), _turn(Direction.LEFT, None)]),
    ("back up a metre, 2 feet to the left, turn right",
     [_move(Direction.BACKWARD, 1), _move(Direction.LEFT, 2 * FT), _turn(Direction.RIGHT, None)]),
])
def test_an_amount_with_its_way_completes_no_later_instruction(prompt: str, want: list[Plain]) -> None:
    assert _plain(translate_offline(prompt)) == want


# ------------------------------------------------------------------------------ restated instructions
@pytest.mark.parametrize(("prompt", "want"), [
    ("turn right, I say again, turn right thirty degrees", [_turn(Direction.RIGHT, 30)]),
    ("rotate left, I repeat, rotate left 45 degrees", [_turn(Direction.LEFT, 45)]),
    ("back up, let me repeat that, back up two feet", [_move(Direction.BACKWARD, 2 * FT)]),
    ("go forward one metre, like I said, go forward one metre", [_move(Direction.FORWARD, 1)]),
    ("face west, I repeat, face west", [(Movement.ROTATE, None, None)]),
])
def test_an_instruction_restated_after_a_repetition_marker_is_done_once(prompt: str, want: list[Plain]) -> None:
    assert _plain(translate_offline(prompt)) == want


def test_the_same_instruction_in_a_sequence_is_done_twice() -> None:
    assert _plain(translate_offline("go forward two metres, then go forward two metres")) == [
        _move(Direction.FORWARD, 2), _move(Direction.FORWARD, 2)]


# ------------------------------------------------------------------------------ radio talk and restarts
@pytest.mark.parametrize(("prompt", "want"), [
    ("negative, turn right, I say again, turn right twenty degrees, over", [_turn(Direction.RIGHT, 20)]),
    ("roger, back up three feet, over and out", [_move(Direction.BACKWARD, 3 * FT)]),
    ("copy that, move forward two metres", [_move(Direction.FORWARD, 2)]),
    ("drive forward three, three and a half feet", [_move(Direction.FORWARD, 3.5 * FT)]),
    ("head east, um, ten, ten feet even", [(Movement.ROTATE, None, None), _move(Direction.FORWARD, 10 * FT)]),
    ("turn left ninety degrees exactly", [_turn(Direction.LEFT, 90)]),
    ("slide to the left, about a foot, sideways", [_move(Direction.LEFT, FT)]),
])
def test_radio_words_and_restarted_numbers_say_nothing_more(prompt: str, want: list[Plain]) -> None:
    assert _plain(translate_offline(prompt)) == want


def test_wanting_to_see_is_a_request_for_a_picture_the_motion_is_done() -> None:
    intent = translate_offline("could you turn left, I'd like to see what's on your left")
    assert [s.movement for s in intent.steps] == [Movement.ROTATE]
    assert "camera" in (intent.clarification or "")


@pytest.mark.parametrize("prompt", ["hmm, which way is west? okay, face west",
                                    "where is south... uh, turn to face south"])
def test_a_question_the_instruction_answers_is_thinking_aloud(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert [s.movement for s in intent.steps] == [Movement.ROTATE]
    assert not intent.unread


def test_a_question_the_instruction_does_not_answer_stays_unread() -> None:
    intent = translate_offline("which way is the door? turn left")
    assert intent.unread


@pytest.mark.parametrize(("prompt", "want"), [
    ("turn seventy degrees left no seventy five", [_turn(Direction.LEFT, 75)]),
    ("back up four feet no three feet", [_move(Direction.BACKWARD, 3 * FT)]),
])
def test_no_before_a_number_corrects_the_amount(prompt: str, want: list[Plain]) -> None:
    assert _plain(translate_offline(prompt)) == want
