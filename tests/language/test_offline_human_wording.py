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
