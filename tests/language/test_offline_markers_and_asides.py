"""Readings added in session 6 (issue 9) from blind round 5's misses, each as the class of speech it
stands for: discourse markers that open an utterance ("right, ..."), contradictions of side, idioms of a
whole turn ("right around"), small amounts said by what they must not exceed, asides (reasons, similes,
comments, pseudo-clefts), hedges on an amount, dialect questions of where the robot is, named amounts,
how the robot holds its heading, spoken decimals as fragments, and directions typed by their consonants."""

from __future__ import annotations

import pytest
from hypothesis import example, given
from hypothesis import strategies as st
from offline_plans import Plan
from offline_plans import asks as _asks
from offline_plans import plan as _plan

from langnav.language.intent import Amount, Movement, Query
from langnav.language.offline import speech
from langnav.language.offline.idioms import plain_idioms
from langnav.language.offline.translator import translate_offline

FT = 0.3048


# ------------------------------------------------------------------ discourse markers
@pytest.mark.parametrize(("prompt", "expected"), [
    ("right then, could you go forward two metres please", [("move", "forward", 2.0, None)]),
    ("right, so, go forward four metres", [("move", "forward", 4.0, None)]),
    ("okay, right, go back one metre", [("move", "backward", 1.0, None)]),
    ("right, turn left thirty degrees", [("rotate", "left", None, 30.0)]),
])
def test_right_opening_an_instruction_of_its_own_is_a_discourse_marker(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


def test_right_opening_a_stop_is_no_turn() -> None:
    intent = translate_offline("right, stop there, thanks")
    assert [s.movement for s in intent.steps] == [Movement.STOP]


@pytest.mark.parametrize(("prompt", "expected"), [
    ("right, ninety degrees", [("rotate", "right", None, 90.0)]),
    ("right. forty five degrees", [("rotate", "right", None, 45.0)]),
    ("turn right then go forward two metres", [("rotate", "right", None, None), ("move", "forward", 2.0, None)]),
])
def test_right_followed_by_what_completes_a_side_is_a_direction(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


def test_right_before_a_turn_with_no_side_asks_which_way() -> None:
    """"Right, turn ninety degrees": the marker reading is likelier, but a turn's side is never guessed."""
    assert _asks("right, turn ninety degrees")


@given(marker=st.sampled_from(["right", "right then", "right so", "okay right", "right, so", "well, right"]),
       metres=st.integers(1, 9))
@example(marker="right then", metres=2)
def test_an_opening_marker_never_adds_a_turn(marker: str, metres: int) -> None:
    steps = translate_offline(f"{marker}, could you go forward {metres} metres please").steps
    assert [(s.movement, s.distance_m) for s in steps] == [(Movement.MOVE, pytest.approx(float(metres)))]


def test_without_discourse_markers_leaves_other_openings_alone() -> None:
    assert speech.without_discourse_markers("okay, go forward") == "okay, go forward"
    assert speech.without_discourse_markers("right, so, stop") == "stop"


# ------------------------------------------------------------------ contradictions of side
@pytest.mark.parametrize("prompt", [
    "rotate clockwise to the left, like, fifty",
    "turn counterclockwise to the right 30 degrees",
    "turn left clockwise",
    "right, left ninety degrees",
    "left right 30 degrees",
])
def test_both_sides_in_one_turn_ask(prompt: str) -> None:
    assert _asks(prompt)


@pytest.mark.parametrize(("prompt", "expected"), [
    ("turn left counterclockwise 30 degrees", [("rotate", "left", None, 30.0)]),
    ("turn right clockwise", [("rotate", "right", None, None)]),
    ("turn right, no, left, 30 degrees", [("rotate", "left", None, 30.0)]),
])
def test_one_side_said_twice_or_corrected_turns(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


# ------------------------------------------------------------------ whole turns
@pytest.mark.parametrize(("prompt", "angle"), [
    ("spin yourself right around, all the way, three sixty", 360.0),
    ("spin, spin all the way around once", 360.0),
    ("spin all the way around", 360.0),
    ("turn all the way around", 180.0),
    ("turn right round", 180.0),
    ("spin around", 180.0),
])
def test_right_around_and_spinning_all_the_way_round(prompt: str, angle: float) -> None:
    steps = translate_offline(prompt).steps
    assert [(s.movement, s.angle_deg) for s in steps] == [(Movement.ROTATE, angle)]


def test_right_around_a_place_keeps_the_side() -> None:
    assert plain_idioms("turn right around the corner") == "turn right around the corner"
    assert plain_idioms("spin yourself right around") == "spin all the way around"


# ------------------------------------------------------------------ small amounts, similes
@pytest.mark.parametrize(("prompt", "movement"), [
    ("okay, now, i'd like you to turn right, not too far, just a little, like you're peeking round a corner",
     Movement.ROTATE),
    ("turn right, not too far", Movement.ROTATE),
    ("go forward, not too much", Movement.MOVE),
])
def test_not_too_far_is_a_little(prompt: str, movement: Movement) -> None:
    steps = translate_offline(prompt).steps
    assert [(s.movement, s.amount, s.angle_deg, s.distance_m) for s in steps] == [(movement, Amount.LITTLE, None, None)]


# ------------------------------------------------------------------ asides, clefts, hedges
@pytest.mark.parametrize(("prompt", "expected"), [
    ("let's have you back up, oh, about a yard, because i think you might be a bit close to that wall",
     [("move", "backward", 0.9144, None)]),
    ("right, so, what i'd like you to do now, and bear with me, it's been a long day out here, is to go forward, "
     "oh, i'd say four metres, yes, four metres", [("move", "forward", 4.0, None)]),
    ("okay now, and this is the bit i was telling jim about earlier, i want you to turn to your left, about ninety "
     "degrees, just a proper left turn", [("rotate", "left", None, 90.0)]),
    ("and now, this is important, go forward for, ooh, twenty feet, give or take", [("move", "forward", round(20 * FT, 4), None)]),
    ("go back eighty centimetres, give or take", [("move", "backward", 0.8, None)]),
    ("go back, um, more or less half a metre", [("move", "backward", 0.5, None)]),
    ("move forward three feet or thereabouts", [("move", "forward", round(3 * FT, 4), None)]),
    ("right, so, after all that, go forward, what, nine and a half feet, and then turn left about forty degrees",
     [("move", "forward", round(9.5 * FT, 4), None), ("rotate", "left", None, 40.0)]),
])
def test_asides_and_hedges_leave_the_request(prompt: str, expected: Plan) -> None:
    intent = translate_offline(prompt)
    assert _plan(prompt) == expected and intent.clarification is None


@pytest.mark.parametrize(("prompt", "heading"), [
    ("so what i'd really like, if you don't mind, is for you to face south, because that's where the noise was "
     "coming from, i think", 270.0),
    ("right then, if you'd be so good, turn yourself to face east, that's where i think the exit is, or so i'm told",
     0.0),
    ("face sth", 270.0),
    ("proceed nrth", 90.0),
])
def test_a_facing_inside_a_verbose_frame_or_typed_short(prompt: str, heading: float) -> None:
    steps = translate_offline(prompt).steps
    assert [(s.movement, s.heading_deg) for s in steps][:1] == [(Movement.ROTATE, heading)]


def test_a_remark_with_no_instruction_is_still_no_instruction() -> None:
    assert _asks("because i think you might be a bit close to that wall")


# ------------------------------------------------------------------ questions, frames, named amounts
@pytest.mark.parametrize("prompt", ["where you at right now", "Where do you stand now?", "where ya at"])
def test_dialect_questions_of_where_the_robot_is(prompt: str) -> None:
    steps = translate_offline(prompt).steps
    assert [(s.movement, s.query) for s in steps] == [(Movement.QUERY, Query.POSE)]


@pytest.mark.parametrize(("prompt", "expected"), [
    ("reckon you oughta turn around", [("rotate", "around", None, 180.0)]),
    ("proceed south, distance eight metres", None),
    ("turn left, angle forty five", [("rotate", "left", None, 45.0)]),
    ("sidestep right two feet, keep facing forward", [("move", "right", round(2 * FT, 4), None)]),
    ("slide left one metre, without turning", [("move", "left", 1.0, None)]),
    ("back up, uh, one point two metres, and then turn around", [("move", "backward", 1.2, None),
                                                                ("rotate", "around", None, 180.0)]),
])
def test_frames_named_amounts_and_headings_held(prompt: str, expected: Plan | None) -> None:
    intent = translate_offline(prompt)
    if expected is None:
        assert [(s.movement, s.heading_deg, s.distance_m) for s in intent.steps] == [
            (Movement.ROTATE, 270.0, None), (Movement.MOVE, None, 8.0)]
    else:
        assert _plan(prompt) == expected
    assert intent.clarification is None


def test_a_turn_said_with_its_amount_and_again_bare_is_done_once() -> None:
    assert _plan("turn left ninety degrees, turn left") == [("rotate", "left", None, 90.0)]
    assert _plan("turn left ninety degrees, then turn left") == [("rotate", "left", None, 90.0),
                                                                  ("rotate", "left", None, None)]


# ------------------------------------------------------------------ places described by what the map cannot show
@pytest.mark.parametrize("prompt", [
    "Please drive to the room with the sofa.",
    "go to the room where the printer is",
    "go to the big room with a piano",
])
def test_a_room_named_by_a_thing_in_it_asks(prompt: str) -> None:
    assert _asks(prompt)


@pytest.mark.parametrize(("prompt", "superlative"), [
    ("Go to the room which is the smallest.", "smallest"),
    ("go to the door that is nearest", "nearest"),
    ("go to the room that is the biggest one", "biggest"),
    ("go to whichever room is smallest", "smallest"),
])
def test_a_relative_clause_naming_a_superlative(prompt: str, superlative: str) -> None:
    steps = translate_offline(prompt).steps
    assert [(s.movement, s.target.superlative.value if s.target and s.target.superlative else None)
            for s in steps] == [(Movement.NAVIGATE, superlative)]


def test_going_in_there_after_finding_a_room_is_one_trip() -> None:
    steps = translate_offline("find the biggest room in the whole building and go in there").steps
    assert [s.movement for s in steps] == [Movement.NAVIGATE]
    assert len(translate_offline("go to the next door, then to the next door").steps) == 2


def test_coming_back_through_a_door_goes_through_it_again() -> None:
    steps = translate_offline("through the door on your right, then come back through it").steps
    assert [(s.movement, s.detail.value if s.detail else None) for s in steps] == [
        (Movement.NAVIGATE, "through"), (Movement.NAVIGATE, "through")]


@pytest.mark.parametrize(("prompt", "expected"), [
    ("go forward ten feet, turn around, come back ten feet",
     [("move", "forward", round(10 * FT, 4), None), ("rotate", "around", None, 180.0),
      ("move", "forward", round(10 * FT, 4), None)]),
    ("go forward ten feet, come back ten feet",
     [("move", "forward", round(10 * FT, 4), None), ("move", "backward", round(10 * FT, 4), None)]),
])
def test_come_back_is_towards_where_the_robot_came_from(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


@pytest.mark.parametrize("prompt", ["move +x 2 m", "move along the x axis 2 m"])
def test_a_way_in_the_map_frame_is_asked_about(prompt: str) -> None:
    assert _asks(prompt)


# ------------------------------------------------------------------ spoken decimals and list numbers
@pytest.mark.parametrize(("prompt", "metres"), [
    ("go forward point five metres", 0.5),
    ("back up point two five metres", 0.25),
    ("point five metres forward", 0.5),
    ("go forward two point five metres", 2.5),
    ("step two feet to the left", round(2 * FT, 4)),
    ("step two point five metres forward", 2.5),
])
def test_a_decimal_said_from_its_point_is_below_one(prompt: str, metres: float) -> None:
    steps = translate_offline(prompt).steps
    assert [round(s.distance_m or 0.0, 4) for s in steps] == [metres]


@given(digits=st.lists(st.sampled_from(["one", "two", "three", "five", "seven", "nine"]), min_size=1, max_size=2))
@example(digits=["five"])
def test_point_and_digits_never_reads_more_than_one(digits: list[str]) -> None:
    """"point N..." is always below one metre: never the 5 m (ten times too far) it was once read as."""
    steps = translate_offline(f"go forward point {' '.join(digits)} metres").steps
    assert len(steps) == 1 and steps[0].distance_m is not None and 0.0 < steps[0].distance_m < 1.0


def test_a_list_number_before_an_instruction_is_still_no_amount() -> None:
    assert _plan("step one, turn left. step two, go forward 2 m") == [("rotate", "left", None, None),
                                                                      ("move", "forward", 2.0, None)]


# ------------------------------------------------------------------ restarts across a pause, learner phrasing
@pytest.mark.parametrize(("prompt", "metres"), [
    ("go forward eleven ... eleven feet, how copy", round(11 * FT, 4)),
    ("go forward seven and a ... seven and a half feet", round(7.5 * FT, 4)),
    ("go forward fourteen, uh, ... fourteen inches", round(14 * 0.0254, 4)),
    ("back out six feet", round(6 * FT, 4)),
])
def test_a_number_restarted_after_a_pause_is_said_once(prompt: str, metres: float) -> None:
    steps = translate_offline(prompt).steps
    assert [round(s.distance_m or 0.0, 4) for s in steps] == [metres]


@pytest.mark.parametrize(("prompt", "movement"), [
    ("Turn yourself completely, all the circle.", Movement.ROTATE),
    ("Where you are now? Tell me the position.", Movement.QUERY),
    ("Go out from this room by the door.", Movement.NAVIGATE),
])
def test_learner_phrasing(prompt: str, movement: Movement) -> None:
    assert [s.movement for s in translate_offline(prompt).steps] == [movement]


@pytest.mark.parametrize("prompt", ["tell me the position of the door", "tell me the distance to the door"])
def test_a_question_about_a_place_is_no_trip_to_it(prompt: str) -> None:
    assert _asks(prompt)


def test_a_remark_about_the_room_before_but_is_no_name_for_it() -> None:
    steps = translate_offline("right, so, this room is lovely but i want you to leave it now, go out through the door, "
                              "yes, that one").steps
    assert [(s.movement, s.detail.value if s.detail else None) for s in steps] == [(Movement.NAVIGATE, "through")]
    assert [(s.movement, s.place_name) for s in translate_offline("this room is the lab").steps] == [
        (Movement.NAME_PLACE, "the lab")]


@pytest.mark.parametrize(("prompt", "sides"), [
    ("go to the door behind you on the left", ("behind", "left")),
    ("Go to the door ahead on your left.", ("ahead", "left")),
    ("go to the door on your left behind you", ("left", "behind")),
    ("go to the door behind you", ("behind", None)),
])
def test_a_second_side_of_a_place_narrows_it(prompt: str, sides: tuple[str, str | None]) -> None:
    steps = translate_offline(prompt).steps
    assert [(s.target.side.value if s.target and s.target.side else None,
             s.target.also_side.value if s.target and s.target.also_side else None) for s in steps] == [sides]


@pytest.mark.parametrize("prompt", ["go to the door on your left on the right", "go to the corner behind you on the left"])
def test_sides_that_cannot_both_hold_ask(prompt: str) -> None:
    assert _asks(prompt)


def test_a_politeness_tail_is_no_second_trip() -> None:
    steps = translate_offline("could you go to the last door on your right, if that's okay").steps
    assert [s.movement for s in steps] == [Movement.NAVIGATE]


@pytest.mark.parametrize(("prompt", "expected"), [
    ("left turn forty five, that's four five degrees left", [("rotate", "left", None, 45.0)]),
    ("go forward twenty three feet, two three feet", [("move", "forward", round(23 * FT, 4), None)]),
])
def test_digits_one_apart_restating_a_number_said_whole_are_that_number(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


def test_digits_one_apart_said_alone_may_be_a_range_and_ask() -> None:
    assert _asks("turn left four five degrees") and _asks("go forward two three feet")


@pytest.mark.parametrize("prompt", ["turn to look behind you", "Give yourself the turn to look behind.",
                                    "turn so you can see behind you"])
def test_a_turn_to_look_behind_is_a_turn_around(prompt: str) -> None:
    assert _plan(prompt) == [("rotate", "around", None, 180.0)]


@pytest.mark.parametrize(("prompt", "kind"), [("look at the door", "door"), ("turn to look at the door", "door"),
                                              ("turn around and look at the corner", "corner")])
def test_looking_at_a_place_faces_it_without_going_there(prompt: str, kind: str) -> None:
    steps = translate_offline(prompt).steps
    assert [(s.movement, s.target.kind.value if s.target else None) for s in steps] == [(Movement.ROTATE, kind)]


@pytest.mark.parametrize(("prompt", "expected"), [
    ("right so go forward three metres", [("move", "forward", 3.0, None)]),
    ("shift left a metre without turning around", [("move", "left", 1.0, None)]),
    ("go forward one point five, er, one point five metres", [("move", "forward", 1.5, None)]),
])
def test_markers_headings_and_restarts_without_the_commas(prompt: str, expected: Plan) -> None:
    intent = translate_offline(prompt)
    assert _plan(prompt) == expected and intent.clarification is None
