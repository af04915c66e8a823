"""Session 11 readings of spoken wording (issue 9, offline translator, no map): each a rule about speech in
general, asserted on the exact steps, with the neighbours that must still ask."""

from __future__ import annotations

import pytest
from offline_plans import Plan, asks, plan

from langnav.language.intent import Amount, Element, Movement, Query, Superlative
from langnav.language.offline.translator import translate_offline


# ---------------------------------------------------------------- calls that are no instruction
@pytest.mark.parametrize(("prompt", "expected"), [
    # a stage manager's cue call: the cue's number names the cue, "go" calls the instruction
    ("cue two go, quarter turn stage left", [("rotate", "left", None, 90.0)]),
    ("cue three, back up one metre, go", [("move", "backward", 1.0, None)]),
    ("cue seven go, turn right thirty, sorry, sixty", [("rotate", "right", None, 60.0)]),
    ("cue eleven go, forward four feet six inches", [("move", "forward", 1.3716, None)]),
    ("standby cue 4, turn left ninety degrees", [("rotate", "left", None, 90.0)]),
    # "stand by" opening what follows is the call to get ready
    ("stand by, turn left thirty degrees, go", [("rotate", "left", None, 30.0)]),
])
def test_cue_and_stand_by_calls_are_no_instruction(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


def test_a_cue_call_with_an_element_keeps_the_element() -> None:
    steps = translate_offline("cue twelve go, exit through the door behind you").steps
    assert [(s.movement, s.target.kind if s.target else None) for s in steps] == [(Movement.NAVIGATE, Element.DOOR)]


@pytest.mark.parametrize("prompt", [
    "move cue three metres",    # "cue" inside an instruction is no call: the amount is not taken
    "cue three",                # a call alone asks for nothing the robot can do
])
def test_cue_words_inside_or_alone_still_ask(prompt: str) -> None:
    assert asks(prompt)


# ---------------------------------------------------------------- reporting the arrival
@pytest.mark.parametrize("prompt", [
    "move to the centre of the largest room and announce when there",
    "go to the largest room, let me know when you get there",
])
def test_a_request_to_report_the_arrival_adds_no_place(prompt: str) -> None:
    steps = translate_offline(prompt).steps
    assert len(steps) == 1
    assert steps[0].movement == Movement.NAVIGATE and steps[0].target is not None
    assert (steps[0].target.kind, steps[0].target.superlative) == (Element.ROOM, Superlative.BIGGEST)


@pytest.mark.parametrize(("prompt", "expected"), [
    ("and rest there", [("stop", None, None, None)]),
    ("rest here", [("stop", None, None, None)]),
])
def test_resting_is_staying(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


def test_the_rest_of_the_way_is_no_stop() -> None:
    assert [s.movement for s in translate_offline("go the rest of the way").steps] != [Movement.STOP]


# ---------------------------------------------------------------- around, said alone or again
@pytest.mark.parametrize(("prompt", "expected"), [
    ("around", [("rotate", "around", None, 180.0)]),
    ("turn around, around, yeah", [("rotate", "around", None, 180.0)]),
    ("around, around", [("rotate", "around", None, 180.0)]),
    ("turn around one time lah", [("rotate", "around", None, 180.0)]),   # "one time" is once
])
def test_around_alone_or_said_again_is_one_turn_around(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


def test_around_after_another_turn_asks() -> None:
    assert asks("turn left, around")   # a correction or a second turn: not guessed


# ---------------------------------------------------------------- restarts and shares
@pytest.mark.parametrize(("prompt", "expected"), [
    ("move forward one point, one point five metres", [("move", "forward", 1.5, None)]),
    ("turn left a quarter, lad", [("rotate", "left", None, 90.0)]),
    ("rotate right a half", [("rotate", "right", None, 180.0)]),
])
def test_restarted_numbers_and_shares_of_a_turn(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


def test_an_unfinished_point_before_another_number_still_asks() -> None:
    assert asks("move forward two point, one point five metres")


def test_a_share_of_a_unit_after_a_turn_is_no_share_of_a_turn() -> None:
    assert ("rotate", "left", None, 90.0) not in plan("turn left a quarter metre")


# ---------------------------------------------------------------- small amounts
@pytest.mark.parametrize(("prompt", "movement", "direction"), [
    ("just a small turn to the right", Movement.ROTATE, "right"),
    ("a slight turn left", Movement.ROTATE, "left"),
    ("back up nobbut a bit", Movement.MOVE, "backward"),    # Yorkshire "nobbut": only
    ("go back shwayya", Movement.MOVE, "backward"),         # Arabic "shwayya": a little
    ("turn right shwayya, a little", Movement.ROTATE, "right"),
    ("shift a bit to thi left", Movement.MOVE, "left"),      # Yorkshire "thi": your
])
def test_small_amount_words_are_a_little(prompt: str, movement: Movement, direction: str) -> None:
    steps = translate_offline(prompt).steps
    assert [(s.movement, s.direction.value if s.direction else None, s.amount) for s in steps] == [
        (movement, direction, Amount.LITTLE)]


# ---------------------------------------------------------------- Yorkshire words and pronouns
@pytest.mark.parametrize(("prompt", "expected"), [
    ("now then, turn reet round", [("rotate", "around", None, 180.0)]),
    ("turn thee right, about forty-five", [("rotate", "right", None, 45.0)]),
    ("go back three yard an' a half", [("move", "backward", 3.2004, None)]),
    ("right, forrard five metres then turn reet", [("move", "forward", 5.0, None), ("rotate", "right", None, None)]),
])
def test_yorkshire_words(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


def test_yorkshire_place_words() -> None:
    steps = translate_offline("get thisen to t' littlest room").steps
    assert len(steps) == 1 and steps[0].target is not None
    assert (steps[0].target.kind, steps[0].target.superlative) == (Element.ROOM, Superlative.SMALLEST)


def test_thee_before_a_noun_is_a_slip_for_the() -> None:
    steps = translate_offline("go to thee door").steps
    assert [(s.movement, s.target.kind if s.target else None) for s in steps] == [(Movement.NAVIGATE, Element.DOOR)]


# ---------------------------------------------------------------- where the robot is, asked in other orders
@pytest.mark.parametrize("prompt", ["where's tha got to", "you are where now habibi", "you now where ah"])
def test_where_are_you_in_other_word_orders(prompt: str) -> None:
    steps = translate_offline(prompt).steps
    assert [(s.movement, s.query) for s in steps] == [(Movement.QUERY, Query.POSE)]
