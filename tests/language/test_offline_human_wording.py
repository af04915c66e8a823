"""What real people say to a robot (issue 9): each test is a rule of English or of spoken commands,
checked on several paraphrases we made up (politeness, fillers, chat spelling, numbers in words,
"more / another"), never on one prompt alone."""

from __future__ import annotations

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from langnav.language.intent import Amount, Direction, Element, Intent, Movement, Step
from langnav.language.offline import lexicon as lx
from langnav.language.offline import translate_offline
from langnav.language.offline.ask import SPATIAL_WORDS
from langnav.language.offline.parser import read_clause

FT, IN = 0.3048, 0.0254


def _plain(intent: Intent) -> list[tuple[Movement, Direction | None, float | None]]:
    """(movement, direction, amount) of each step, amounts rounded to the millimetre / degree."""
    out: list[tuple[Movement, Direction | None, float | None]] = []
    for s in intent.steps:
        value = s.distance_m if s.movement == Movement.MOVE else s.angle_deg
        out.append((s.movement, s.direction, None if value is None else round(value, 3)))
    return out


def _move(direction: Direction, metres: float) -> tuple[Movement, Direction, float]:
    return (Movement.MOVE, direction, round(metres, 3))


def _turn(direction: Direction, degrees: float) -> tuple[Movement, Direction, float]:
    return (Movement.ROTATE, direction, round(float(degrees), 3))


# ------------------------------------------------------------------------------ names
@pytest.mark.parametrize("known", ["'Kitchen'", "The Kitchen", "  kitchen ", '"the kitchen"'])
def test_a_known_name_is_matched_by_the_one_rule_for_names(known: str) -> None:
    """Place names compare by ``langnav.places.place_key`` (case, spaces, article, quotes), in every
    stage that reads them."""
    reading = read_clause("go to the kitchen", known_names=[known])
    assert reading.problem is None, reading
    assert [s.target.name if s.target else None for s in reading.steps] == [known]


# ------------------------------------------------------------------------------ words never dropped
#: Words that change where or how far the robot goes: never "harmless" leftovers.
_WHERE_OR_HOW_FAR = ("left", "right", "around", "more", "same", "distance", "amount", "degrees", "meters",
                     "north", "back", "forward", "twice", "half", "further")


@pytest.mark.parametrize("word", _WHERE_OR_HOW_FAR)
def test_no_word_of_where_or_how_far_is_a_stopword(word: str) -> None:
    assert word not in lx.STOPWORDS
    assert word in SPATIAL_WORDS


@pytest.mark.parametrize("prompt", [
    "drive backwards 1 m while heading right",
    "reverse 2 metres while veering left",
    "go forward 3 feet and bear right",
    "move forward 1 m, drifting right",
    "move the same distance again",
    "go forward the same amount",
])
def test_a_way_or_an_amount_not_read_is_asked_about(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert intent.steps == [], intent
    assert intent.clarification


# ------------------------------------------------------------------------------ more / another
@pytest.mark.parametrize(("prompt", "want"), [
    ("uh, another two feet forward", [_move(Direction.FORWARD, 2 * FT)]),
    ("go a further three metres", [_move(Direction.FORWARD, 3)]),
    ("move forward five feet more", [_move(Direction.FORWARD, 5 * FT)]),
    ("could u go an extra 20 cm forward pls", [_move(Direction.FORWARD, 0.2)]),
    ("move forward around three feet", [_move(Direction.FORWARD, 3 * FT)]),
    ("can you go about another foot", [_move(Direction.FORWARD, FT)]),
    ("pls go fwd another 2 ft", [_move(Direction.FORWARD, 2 * FT)]),
    ("back up an additional six inches", [_move(Direction.BACKWARD, 6 * IN)]),
    ("turn another forty five degrees to your right", [_turn(Direction.RIGHT, 45)]),
    ("turn ten degrees more to your left", [_turn(Direction.LEFT, 10)]),
    ("five degrees more to your right", [_turn(Direction.RIGHT, 5)]),
    ("maybe turn uh more to the right another forty five degrees", [_turn(Direction.RIGHT, 45)]),
    ("rotate a further 30 degrees clockwise", [_turn(Direction.RIGHT, 30)]),
    ("turn right about another twenty degrees", [_turn(Direction.RIGHT, 20)]),
])
def test_more_and_another_keep_the_amount_said(prompt: str, want: list[tuple[Movement, Direction, float]]) -> None:
    """'Another two feet', 'five feet more', 'a further 3 m': the amount is the number said (it adds to
    what was done), never dropped, never its unit lost."""
    assert _plain(translate_offline(prompt)) == want


@pytest.mark.parametrize("prompt", ["move forward a little bit more", "go a tad further forward",
                                    "inch forward a bit more", "move forward a little more please"])
def test_a_little_more_is_a_little(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert [(s.movement, s.direction, s.amount) for s in intent.steps] == [
        (Movement.MOVE, Direction.FORWARD, Amount.LITTLE)], intent


@given(st.sampled_from(["another", "a further", "an extra", "an additional", "about", "around", ""]),
       st.sampled_from(["", "more", "further"]), st.integers(min_value=2, max_value=12),
       st.sampled_from(["feet", "metres", "inches"]))
@example(lead="another", tail="", n=2, unit="feet")
def test_more_never_moves_farther_than_the_number_said(lead: str, tail: str, n: int, unit: str) -> None:
    per = {"feet": FT, "metres": 1.0, "inches": IN}[unit]
    prompt = " ".join(f"move forward {lead} {n} {unit} {tail}".split())
    intent = translate_offline(prompt)
    assert _plain(intent) == [_move(Direction.FORWARD, n * per)], prompt


# ------------------------------------------------------------------------------ numbers and units
@pytest.mark.parametrize(("prompt", "want"), [
    ("rotate three fifteen degrees clockwise", [_turn(Direction.RIGHT, 315)]),
    ("turn one ten degrees left", [_turn(Direction.LEFT, 110)]),
    ("spin two oh five degrees to the right", [_turn(Direction.RIGHT, 205)]),
    ("turn one twelve degrees to your right", [_turn(Direction.RIGHT, 112)]),
    ("go ahead 5 feets", [_move(Direction.FORWARD, 5 * FT)]),
    ("move two inchs forward", [_move(Direction.FORWARD, 2 * IN)]),
    ("robot go front three meter", [_move(Direction.FORWARD, 3)]),
])
def test_spoken_numbers_and_learner_units(prompt: str, want: list[tuple[Movement, Direction, float]]) -> None:
    assert _plain(translate_offline(prompt)) == want


# ------------------------------------------------------------------------------ chat spelling
@pytest.mark.parametrize(("prompt", "want"), [
    ("go fwd 10 ft then turn rt 90", [_move(Direction.FORWARD, 10 * FT), _turn(Direction.RIGHT, 90)]),
    ("go str8 5 meters", [_move(Direction.FORWARD, 5)]),
    ("turn lft 30 deg", [_turn(Direction.LEFT, 30)]),
    ("go bk 2 ft", [_move(Direction.BACKWARD, 2 * FT)]),
    ("pls turn rght 45 degs thx", [_turn(Direction.RIGHT, 45)]),
    ("go strait 2 metres", [_move(Direction.FORWARD, 2)]),
])
def test_chat_spelling_of_directions(prompt: str, want: list[tuple[Movement, Direction, float]]) -> None:
    """Chat abbreviations are words, not noise ('fwd', 'rt' are not sounds like 'fff')."""
    assert _plain(translate_offline(prompt)) == want


# ------------------------------------------------------------------------------ joining steps
@pytest.mark.parametrize("prompt", ["go straight 2 meter and after turn right 90 degrees",
                                    "drive 2 m forward, after turn right 90",
                                    "move forward 2 metres and after that turn right 90 degrees"])
def test_after_with_no_event_is_then(prompt: str) -> None:
    assert _plain(translate_offline(prompt)) == [_move(Direction.FORWARD, 2), _turn(Direction.RIGHT, 90)]


@pytest.mark.parametrize("prompt", ["turn right right now", "turn right, right away", "rotate right right now please"])
def test_right_as_a_side_then_right_now(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert [(s.movement, s.direction) for s in intent.steps] == [(Movement.ROTATE, Direction.RIGHT)], intent


def test_the_same_position_is_where_the_robot_is() -> None:
    for prompt in ("in the same position you're in move three feet to your right",
                   "from the same spot, move three feet to your right"):
        intent = translate_offline(prompt)
        assert _plain(intent) == [_move(Direction.RIGHT, 3 * FT)], prompt


def _steps_of(intent: Intent, movement: Movement) -> list[Step]:
    return [s for s in intent.steps if s.movement == movement]


def test_element_words_still_read() -> None:
    """The stopword audit keeps places read: 'right' as a side of a door."""
    intent = translate_offline("go to the door on your right")
    assert [s.target.kind if s.target else None for s in intent.steps] == [Element.DOOR]


# ------------------------------------------------------------------------------ corrections
@pytest.mark.parametrize(("prompt", "want"), [
    ("go back two feet, no, forward two feet", [_move(Direction.FORWARD, 2 * FT)]),
    ("move back 3 feet, sorry, I meant forward", [_move(Direction.FORWARD, 3 * FT)]),
    ("reverse one metre, actually go forward", [_move(Direction.FORWARD, 1)]),
    ("move five meters, I mean five feet, forward", [_move(Direction.FORWARD, 5 * FT)]),
    ("turn ninety degrees, sorry, forty five degrees, to the left", [_turn(Direction.LEFT, 45)]),
    ("move forward ten feet, scratch that, six feet", [_move(Direction.FORWARD, 6 * FT)]),
    ("turn right 30 degrees, scratch that, left", [_turn(Direction.LEFT, 30)]),
    ("turn left 90, scratch that, turn right 45", [_turn(Direction.RIGHT, 45)]),
    ("go forward 2 m, turn left 90, scratch that", [_move(Direction.FORWARD, 2)]),
    ("go forward 2 m, turn left 90, never mind, turn right 45", [_turn(Direction.RIGHT, 45)]),
    ("keep going two more feet, then go south, go two t-, i'm sorry never mind forget that, so go three more "
     "feet", [_move(Direction.FORWARD, 3 * FT)]),
])
def test_a_correction_replaces_what_it_corrects(prompt: str, want: list[tuple[Movement, Direction, float]]) -> None:
    """The last version counts: a side or an amount said after a correction word replaces the one said
    before (also "back"); a take-back followed by an amount corrects it; 'never mind' drops the request
    so far, 'scratch that' the last instruction."""
    assert _plain(translate_offline(prompt)) == want


@pytest.mark.parametrize("prompt", ["turn left uhh thirty five degrees, nevermind", "go forward 2 feet, never mind",
                                    "move back a metre, scratch that"])
def test_a_take_back_at_the_end_runs_nothing(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert intent.steps == [] and intent.clarification, intent


# ------------------------------------------------------------------------------ clock directions
@pytest.mark.parametrize(("hour", "want"), [
    (1, (Direction.RIGHT, 30)), (2, (Direction.RIGHT, 60)), (3, (Direction.RIGHT, 90)), (4, (Direction.RIGHT, 120)),
    (5, (Direction.RIGHT, 150)), (6, (Direction.AROUND, 180)), (7, (Direction.LEFT, 150)), (8, (Direction.LEFT, 120)),
    (9, (Direction.LEFT, 90)), (10, (Direction.LEFT, 60)), (11, (Direction.LEFT, 30)),
])
def test_clock_hours_are_turns(hour: int, want: tuple[Direction, float]) -> None:
    """Twelve o'clock is ahead, each hour 30 degrees; one to five to the right, seven to eleven to the
    left, six behind. Said in digits or words, with or without 'your', after 'turn to' or 'face'."""
    words = ["", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven"]
    for prompt in (f"turn to your {words[hour]} o'clock", f"face your {hour} o'clock", f"rotate to {hour} oclock",
                   f"could you turn towards your {words[hour]} o clock please"):
        assert _plain(translate_offline(prompt)) == [_turn(*want)], prompt


@pytest.mark.parametrize(("prompt", "want"), [
    ("go 3 metres toward your nine o'clock", [_turn(Direction.LEFT, 90), _move(Direction.FORWARD, 3)]),
    ("go two feet at your three o'clock", [_turn(Direction.RIGHT, 90), _move(Direction.FORWARD, 2 * FT)]),
    ("head towards your 11 oclock, then 2 metres", [_turn(Direction.LEFT, 30), _move(Direction.FORWARD, 2)]),
    ("drive five feet to your one o'clock", [_turn(Direction.RIGHT, 30), _move(Direction.FORWARD, 5 * FT)]),
])
def test_going_towards_a_clock_hour_is_that_turn_then_forward(
        prompt: str, want: list[tuple[Movement, Direction, float]]) -> None:
    assert _plain(translate_offline(prompt)) == want


# ------------------------------------------------------------------------------ speech recognition
@pytest.mark.parametrize(("prompt", "want"), [
    ("move forward to feet", [_move(Direction.FORWARD, 2 * FT)]),
    ("back up too metres", [_move(Direction.BACKWARD, 2)]),
    ("turn write ninety degrees", [_turn(Direction.RIGHT, 90)]),
    ("turn lift for degrees", [_turn(Direction.LEFT, 4)]),
    ("go forward won meter period then turn left 90", [_move(Direction.FORWARD, 1), _turn(Direction.LEFT, 90)]),
    ("move forward too metres comma turn to your write 45 degrees",
     [_move(Direction.FORWARD, 2), _turn(Direction.RIGHT, 45)]),
    ("go ate feet forward new line turn left 90", [_move(Direction.FORWARD, 8 * FT), _turn(Direction.LEFT, 90)]),
])
def test_misheard_words_in_their_slot(prompt: str, want: list[tuple[Movement, Direction, float]]) -> None:
    """A homophone is the number, side or mark the slot expects ('to feet', 'turn write', 'comma')."""
    assert _plain(translate_offline(prompt)) == want


@pytest.mark.parametrize("prompt", ["go to the door", "take the lift", "go through the door for me"])
def test_homophones_keep_their_meaning_elsewhere(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert not any(s.movement in (Movement.MOVE, Movement.ROTATE) for s in intent.steps), intent


# ------------------------------------------------------------------------------ vowels dropped
@pytest.mark.parametrize(("prompt", "want"), [
    ("trn lft 90 dgrs", [_turn(Direction.LEFT, 90)]),
    ("go bak 2 ft", [_move(Direction.BACKWARD, 2 * FT)]),
    ("mov fwd 1.2 m thn trn rght 45 deg", [_move(Direction.FORWARD, 1.2), _turn(Direction.RIGHT, 45)]),
    ("go bckwrds 3 ft", [_move(Direction.BACKWARD, 3 * FT)]),
    ("go fwd 1m n trn lft 90", [_move(Direction.FORWARD, 1), _turn(Direction.LEFT, 90)]),
    ("rotate clckwse 30", [_turn(Direction.RIGHT, 30)]),
    ("go strght 2 metres", [_move(Direction.FORWARD, 2)]),
])
def test_words_typed_by_their_consonants(prompt: str, want: list[tuple[Movement, Direction, float]]) -> None:
    assert _plain(translate_offline(prompt)) == want


@pytest.mark.parametrize("word", ["red", "cold", "rat", "bin", "fan", "wet", "gun", "bike", "den", "pc"])
def test_short_real_words_are_not_read_as_skeletons(word: str) -> None:
    from langnav.language.offline.normalize import normalize
    assert normalize(f"the {word}") == f"the {word}"


# ------------------------------------------------------------------------------ small amounts
@pytest.mark.parametrize("prompt", ["could you turn right... just a little bit?", "turn left, a teeny bit",
                                    "spin to the left a teeny bit", "move forward a lil bit",
                                    "go back just a teeny tiny bit", "rotate right a tiny touch",
                                    "nudge forward an itsy bitsy bit"])
def test_small_amounts_are_a_little(prompt: str) -> None:
    """'A teeny bit', 'a lil bit', '... just a little bit' (after a pause): a little, never the 90 degrees
    of a bare turn."""
    intent = translate_offline(prompt)
    assert len(intent.steps) == 1 and intent.steps[0].amount == Amount.LITTLE, intent


@pytest.mark.parametrize(("prompt", "heading"), [("face nor east", 45.0), ("turn to the nor'west", 135.0),
                                                 ("head sou west", 225.0), ("face the north-east", 45.0)])
def test_short_forms_of_the_compass_diagonals(prompt: str, heading: float) -> None:
    intent = translate_offline(prompt)
    assert [s.heading_deg for s in intent.steps] == [heading], intent


# ------------------------------------------------------------------------------ amounts that continue
@pytest.mark.parametrize(("prompt", "want"), [
    ("back up 2 m and then another 3 feet", [_move(Direction.BACKWARD, 2), _move(Direction.BACKWARD, 3 * FT)]),
    ("turn left 45 degrees, then another 20 degrees", [_turn(Direction.LEFT, 45), _turn(Direction.LEFT, 20)]),
    ("go left 1 m, then 2 more metres", [_move(Direction.LEFT, 1), _move(Direction.LEFT, 2)]),
    ("move forward two metres and then another three feet", [_move(Direction.FORWARD, 2),
                                                             _move(Direction.FORWARD, 3 * FT)]),
])
def test_an_amount_alone_goes_on_the_way_before(prompt: str, want: list[tuple[Movement, Direction, float]]) -> None:
    assert _plain(translate_offline(prompt)) == want


@pytest.mark.parametrize(("prompt", "metres"), [
    ("move 2 foot 6 forward", 2 * FT + 6 * IN), ("go forward five feet three", 5 * FT + 3 * IN),
    ("move forward 1 metre 6 inches", 1 + 6 * IN), ("go forward 1 m and 6 inches", 1 + 6 * IN),
    ("walk forward four feets", 4 * FT), ("move forward 2 m 30", 2.3),
])
def test_compound_lengths_add_up(prompt: str, metres: float) -> None:
    assert _plain(translate_offline(prompt)) == [_move(Direction.FORWARD, metres)]


# ------------------------------------------------------------------------------ polite frames, remarks
@pytest.mark.parametrize(("prompt", "want"), [
    ("is it okay if you back up, um, half a metre? sorry", [_move(Direction.BACKWARD, 0.5)]),
    ("Would it be possible for you to reverse by roughly one metre so that I can see the door?",
     [_move(Direction.BACKWARD, 1)]),
    ("is it possible to turn left 30 degrees?", [_turn(Direction.LEFT, 30)]),
    ("I'd be most grateful if you could turn left 90 degrees and then move forward 2 metres",
     [_turn(Direction.LEFT, 90), _move(Direction.FORWARD, 2)]),
    ("i was wondering if you could go forward 3 feet", [_move(Direction.FORWARD, 3 * FT)]),
    ("do you think you could turn right 45 degrees?", [_turn(Direction.RIGHT, 45)]),
    ("could you possibly move back 1 m", [_move(Direction.BACKWARD, 1)]),
    ("turn left 90 degrees, is that a thing you can do?", [_turn(Direction.LEFT, 90)]),
    ("turn right 17 degrees, sorry if that's a weird number", [_turn(Direction.RIGHT, 17)]),
    ("Would you mind going forward about, oh, let's say two and a half feet?", [_move(Direction.FORWARD, 2.5 * FT)]),
    ("go forward, hmm, let me think, one and a half metres", [_move(Direction.FORWARD, 1.5)]),
    ("I don't want to crash it... move forward maybe thirty centimetres?", [_move(Direction.FORWARD, 0.3)]),
    ("drive forward 2 m, careful not to bump into anything", [_move(Direction.FORWARD, 2)]),
    ("Could you possibly turn all the way around, so that you are facing the other direction?",
     [(Movement.ROTATE, Direction.AROUND, 180.0)]),
])
def test_polite_frames_and_side_remarks_change_nothing(prompt: str,
                                                       want: list[tuple[Movement, Direction, float]]) -> None:
    """A request wrapped in a polite question ('is it okay if you ...', 'may I ask you to ...') is the
    request; a remark beside it ('is that a thing you can do?', 'so that I can see ...', a worry about
    crashing) asks for nothing."""
    intent = translate_offline(prompt)
    assert _plain(intent) == want
    assert intent.clarification is None or "camera" in intent.clarification


def test_may_i_ask_you_to_move_slightly() -> None:
    intent = translate_offline("May I ask you to move slightly forward?")
    assert [(s.movement, s.direction, s.amount) for s in intent.steps] == [
        (Movement.MOVE, Direction.FORWARD, Amount.LITTLE)]


@pytest.mark.parametrize("prompt", ["crash into the wall", "please ram the box", "I want you to crash into it"])
def test_a_request_to_crash_is_still_refused(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert intent.steps == [] and intent.clarification


# ------------------------------------------------------------------------------ restarts
@pytest.mark.parametrize(("prompt", "want"), [
    ("move three feet forward, and fifteen degrees turn, turn to your left",
     [_move(Direction.FORWARD, 3 * FT), _turn(Direction.LEFT, 15)]),
    ("rotate thirty degrees, rotate to the right", [_turn(Direction.RIGHT, 30)]),
    ("turn left, turn left two hundred seventy degrees", [_turn(Direction.LEFT, 270)]),
    ("turn right, uh, turn right forty degrees", [_turn(Direction.RIGHT, 40)]),
    ("robot turn right, robot stop, robot turn left 90", [_turn(Direction.LEFT, 90)]),
    ("move forward, stop, back up 2 feet", [_move(Direction.BACKWARD, 2 * FT)]),
    ("robot turn left, uh, robot stop, robot turn left forty five degrees, and then turn left ninety degrees",
     [_turn(Direction.LEFT, 45), _turn(Direction.LEFT, 90)]),
    ("turn right forty five degrees, go forward three feet, stop, turn left forty five degrees",
     [_turn(Direction.RIGHT, 45), _move(Direction.FORWARD, 3 * FT), _turn(Direction.LEFT, 45)]),
])
def test_a_turn_said_again_or_stopped_is_one_turn(prompt: str, want: list[tuple[Movement, Direction, float]]) -> None:
    """A turn started again with what it missed is one turn; a 'stop' between instructions takes back
    the motion before it when that had no amount (how far it ran cannot be known); a motion with its
    amount is kept."""
    assert _plain(translate_offline(prompt)) == want


@pytest.mark.parametrize(("prompt", "heading"), [("face up, face north", 90.0), ("turn around, face south", 270.0),
                                                 ("turn left, face west", 180.0), ("turn, um, face east", 0.0),
                                                 ("turn so that you face north", 90.0)])
def test_a_facing_after_a_bare_turn_is_that_turn(prompt: str, heading: float) -> None:
    intent = translate_offline(prompt)
    assert [(s.movement, s.heading_deg) for s in intent.steps] == [(Movement.ROTATE, heading)], intent


@given(st.sampled_from(["left", "right"]), st.sampled_from(["", "uh, ", "robot "]),
       st.integers(min_value=10, max_value=170))
def test_a_restated_turn_never_turns_more_than_the_amount_said(side: str, filler: str, n: int) -> None:
    intent = translate_offline(f"turn {side}, {filler}turn {side} {n} degrees")
    assert _plain(intent) == [_turn(Direction(side), n)]


# ------------------------------------------------------------------------------ place phrases
@pytest.mark.parametrize(("prompt", "kind"), [
    ("go to the, uh, the first door", Element.DOOR), ("go to the nearest, um, corner", Element.CORNER),
    ("go over towards the bit that hasn't been mapped yet", Element.UNEXPLORED_AREA),
    ("go check out the part of the map that hasn't been scanned yet", Element.UNEXPLORED_AREA),
    ("head for the area we have not explored", Element.UNEXPLORED_AREA),
    ("go out into the hallway", Element.HALLWAY), ("go bak out thru the door", Element.DOOR),
])
def test_place_phrases_as_people_say_them(prompt: str, kind: Element) -> None:
    """Fillers inside a noun phrase, a negation inside a relative clause (it describes the place), 'out
    into': the place is read, and nothing is asked."""
    intent = translate_offline(prompt)
    assert [s.target.kind if s.target else None for s in intent.steps] == [kind], intent
    assert intent.clarification is None


@pytest.mark.parametrize("prompt", ["point yourself at the door", "aim at the door", "turn to face the door"])
def test_pointing_at_an_element_is_facing_it(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert [(s.movement, s.target.kind if s.target else None) for s in intent.steps] == [
        (Movement.ROTATE, Element.DOOR)], intent


# ------------------------------------------------------------------------------ doors along a hallway
@pytest.mark.parametrize(("prompt", "count", "side"), [
    ("go to the room 2 doors down", 2, None),
    ("please go to the room that's two doors down from here", 2, None),
    ("go into the office three doors down the hall on the left", 3, "left"),
    ("head to the room a couple of doors back", 2, "behind"),
    ("go to the one 2 doors down", 2, None),
    ("drive to the room one door further down on your right", 1, "right"),
])
def test_a_count_of_doors_picks_one_room(prompt: str, count: int, side: str | None) -> None:
    """'The room two doors down' is one room (a relation along the hallway), not a room and then a door."""
    from langnav.language.intent import Relation

    intent = translate_offline(prompt)
    assert len(intent.steps) == 1, intent
    target = intent.steps[0].target
    assert target is not None and target.kind == Element.ROOM
    assert (target.relation, target.ordinal, target.side.value if target.side else None) == (
        Relation.DOORS_ALONG, count, side)


# ------------------------------------------------------------------------------ appositions, "across from"
@pytest.mark.parametrize(("prompt", "ordinal", "side"), [
    ("go to the door on your left, the one after the first", 2, "left"),
    ("go to the second door, the one on your right", 2, "right"),
    ("drive to the doorway on the right, I mean the one after the second", 3, "right"),
])
def test_an_apposition_names_the_same_place_more_exactly(prompt: str, ordinal: int, side: str) -> None:
    """'X, the one ...' is one place, not a second trip; 'the one after the first' is the second."""
    intent = translate_offline(prompt)
    assert len(intent.steps) == 1, intent
    target = intent.steps[0].target
    assert target is not None and (target.ordinal, target.side.value if target.side else None) == (ordinal, side)


def test_the_one_after_a_connective_is_a_step_of_its_own() -> None:
    intent = translate_offline("go to the door, then the one after the second")
    assert [s.target.ordinal if s.target else None for s in intent.steps] == [None, 3]


@pytest.mark.parametrize(("prompt", "near"), [
    ("pls go into the room across from the first room on your left", {"ordinal": 1, "side": "left"}),
    ("go to the room opposite room 3", {"label": 3}),
    ("go to the room across the hall from the biggest room", {"superlative": "biggest"}),
])
def test_across_from_another_room(prompt: str, near: dict[str, object]) -> None:
    from langnav.language.intent import Relation

    intent = translate_offline(prompt)
    assert len(intent.steps) == 1, intent
    target = intent.steps[0].target
    assert target is not None and target.relation == Relation.ACROSS and target.near is not None
    assert target.near.model_dump(mode="json", exclude_defaults=True) == {"kind": "room", **near}


# ------------------------------------------------------------------------------ more corrections and words
@pytest.mark.parametrize(("prompt", "want"), [
    ("move forward three- no, wait, two metres", [_move(Direction.FORWARD, 2)]),
    ("back up two feet, actually, make it one foot", [_move(Direction.BACKWARD, FT)]),
    ("turn right ninety, sorry, I meant to say left ninety", [_turn(Direction.LEFT, 90)]),
    ("turn around silly", [(Movement.ROTATE, Direction.AROUND, 180.0)]),
    ("rotate counter clock wise ninety", [_turn(Direction.LEFT, 90)]),
    ("spin clock wise 45 degrees", [_turn(Direction.RIGHT, 45)]),
])
def test_more_spoken_corrections_and_words(prompt: str, want: list[tuple[Movement, Direction, float]]) -> None:
    assert _plain(translate_offline(prompt)) == want


@pytest.mark.parametrize(("prompt", "heading"), [("turn around to face north", 90.0), ("swing round to face east", 0.0),
                                                 ("turn around and face north", 90.0),
                                                 ("spin round to the west", 180.0)])
def test_turning_around_to_face_a_point_is_facing_it(prompt: str, heading: float) -> None:
    intent = translate_offline(prompt)
    assert [(s.movement, s.heading_deg) for s in intent.steps] == [(Movement.ROTATE, heading)], intent


@pytest.mark.parametrize(("prompt", "want"), [
    ("move right- left, move left a metre", [_move(Direction.LEFT, 1)]),
    ("go forward, go forward 2 metres", [_move(Direction.FORWARD, 2)]),
    ("back up, uh, back up three feet", [_move(Direction.BACKWARD, 3 * FT)]),
])
def test_a_move_said_again_with_its_amount_is_one_move(prompt: str,
                                                       want: list[tuple[Movement, Direction, float]]) -> None:
    assert _plain(translate_offline(prompt)) == want


@pytest.mark.parametrize("prompt", ["go to the neighbouring room", "drive into the adjoining room",
                                    "go to the room next door"])
def test_the_neighbouring_room_is_the_room_next_to_this_one(prompt: str) -> None:
    from langnav.language.intent import Relation

    intent = translate_offline(prompt)
    assert [(s.target.relation if s.target else None) for s in intent.steps] == [Relation.ADJACENT], intent


@pytest.mark.parametrize(("prompt", "want"), [
    ("fwd 2.5 m, cw 90", [_move(Direction.FORWARD, 2.5), _turn(Direction.RIGHT, 90)]),
    ("2 m forward, then counterclockwise 90", [_move(Direction.FORWARD, 2), _turn(Direction.LEFT, 90)]),
    ("forward 1 m, clockwise 45 degrees", [_move(Direction.FORWARD, 1), _turn(Direction.RIGHT, 45)]),
])
def test_a_clockwise_fragment_is_a_turn(prompt: str, want: list[tuple[Movement, Direction, float]]) -> None:
    assert _plain(translate_offline(prompt)) == want


@pytest.mark.parametrize(("prompt", "want"), [
    ("sorry, I mean, um... go forward two feet. just two.", [_move(Direction.FORWARD, 2 * FT)]),
    ("turn left 30 degrees. only 30 please", [_turn(Direction.LEFT, 30)]),
])
def test_a_number_said_again_insists_on_it(prompt: str, want: list[tuple[Movement, Direction, float]]) -> None:
    assert _plain(translate_offline(prompt)) == want


def test_a_new_bare_number_after_a_move_is_asked_about() -> None:
    intent = translate_offline("go forward two feet, then 2")
    assert intent.steps == [] and intent.clarification
