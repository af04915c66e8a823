"""Session 11 readings (offline translator, no map): code-style input read as the words it spells, small amounts
in other languages, a destination the reading cannot ground, take-backs between two instructions. Each a rule
about language in general, asserted on the exact steps, with the neighbours that must still ask."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from offline_plans import Plan, asks, plan

from langnav.language.intent import Amount, Detail, Element, Movement, Query, Side, Superlative
from langnav.language.offline.code import is_code, plain_code
from langnav.language.offline.lexicon import FOREIGN_AMOUNTS
from langnav.language.offline.translator import translate_offline


# ---------------------------------------------------------------- code notation: the words it spells
@pytest.mark.parametrize(("code", "words"), [
    ("move_forward(1.5m)", "move forward 1.5m"),
    ("rotate(left, 45deg)", "rotate left 45deg"),
    ("emergency_stop()", "emergency stop"),
    ("get_pose()", "get pose"),
    ("strafe_left(0.75 m)", "strafe left 0.75 m"),
    ("turnLeft(90deg)", "turn left 90deg"),
    ("robot.move_backward(distance_m=2)", "robot move backward 2 m"),
    ("forward(3ft); turn_right(15deg)", "forward 3ft. turn right 15deg"),
    ("rotate(right, 30) // typo, meant left", "rotate right 30. typo, i meant left"),
    ("repeat 3x: forward 0.5 m", "forward 0.5 m 3 times"),
    ("for i in range(2): turn_left(10deg)", "turn left 10deg 2 times"),
    ("goto(biggest_room)", "go to the biggest room"),
    ("goto(nearest_corner)", "go to the nearest corner"),
    ("goto(room=biggest, where=middle)", "go to the middle of the biggest room"),
    ("go_through(narrow_gap, ahead)", "go through the narrow gap ahead"),
    ("go_through(door, side=left)", "go through the door on the left"),
    ("goto(center_of_this_room)", "go to the center of this room"),
    ("turn_to(heading=south)", "turn to heading south"),
    ("move(dir=back, distance_m=0.5)", "move back 0.5 m"),        # a part word with no place is said as it is
    ("forward(1m)\nturn_left(90deg)", "forward 1m. turn left 90deg"),  # calls one after another: statements
])
def test_code_is_read_as_the_words_it_spells(code: str, words: str) -> None:
    assert plain_code(code) == words


@pytest.mark.parametrize("speech", [
    "turn left 90 degrees", "Rotate 30 deg left (clockwise).", "go to door #2", "go forward 1.5 m; then stop",
])
def test_speech_is_no_code(speech: str) -> None:
    """Only the notation of code is rewritten: an aside in brackets, a numbered door, a semicolon are speech."""
    assert not is_code(speech)
    assert plain_code(speech) == speech


@pytest.mark.parametrize(("prompt", "expected"), [
    ("move_forward(1.5m)", [("move", "forward", 1.5, None)]),
    ("rotate(left, 45deg)", [("rotate", "left", None, 45.0)]),
    ("strafe_left(0.75 m)", [("move", "left", 0.75, None)]),
    ("emergency_stop()", [("stop", None, None, None)]),
    ("forward(3ft); turn_right(15deg)", [("move", "forward", 0.9144, None), ("rotate", "right", None, 15.0)]),
    # a comment may put the line right: "typo, meant left" is "I meant left"
    ("rotate(right, 30) // typo, meant left", [("rotate", "left", None, 30.0)]),
    ("rotate(right, 30) # typo, meant left", [("rotate", "left", None, 30.0)]),
    ("repeat 3x: forward 0.5 m", [("move", "forward", 1.5, None)]),
    ("backward(40cm)", [("move", "backward", 0.4, None)]),
    ("rotate_in_place(360deg)", [("rotate", "left", None, 360.0)]),
])
def test_code_plans(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


def test_a_getter_asks_for_the_value() -> None:
    steps = translate_offline("get_pose()").steps
    assert [(s.movement, s.query) for s in steps] == [(Movement.QUERY, Query.POSE)]


@pytest.mark.parametrize(("prompt", "kind", "detail", "superlative", "side", "here"), [
    ("goto(biggest_room)", Element.ROOM, Detail.TO, Superlative.BIGGEST, None, False),
    ("goto(nearest_corner)", Element.CORNER, Detail.TO, Superlative.NEAREST, None, False),
    ("goto(room=biggest, where=middle)", Element.ROOM, Detail.MIDDLE, Superlative.BIGGEST, None, False),
    ("go_through(narrow_gap, ahead)", Element.NARROW_PASSAGE, Detail.THROUGH, None, Side.AHEAD, False),
    ("go_through(door, side=left)", Element.DOOR, Detail.THROUGH, None, Side.LEFT, False),
    ("goto(center_of_this_room)", Element.ROOM, Detail.MIDDLE, None, None, True),
])
def test_code_reaches_the_places_words_name(prompt: str, kind: Element, detail: Detail,
                                            superlative: Superlative | None, side: Side | None, here: bool) -> None:
    """The place a call names is the place its words name: one step to it, and nothing else (no extra turn)."""
    intent = translate_offline(prompt)
    assert len(intent.steps) == 1 and intent.clarification is None
    step = intent.steps[0]
    assert step.movement == Movement.NAVIGATE and step.target is not None
    assert (step.target.kind, step.detail, step.target.superlative, step.target.side,
            step.target.in_current_room) == (kind, detail, superlative, side, here)


@pytest.mark.parametrize("prompt", [
    "goto(kitchen)",                  # a name the map cannot know
    "goto(rack_B12)",
    "forward(6)",                     # no unit
    "capture_image()",                # no camera
])
def test_code_that_must_ask(prompt: str) -> None:
    assert asks(prompt)


# ---------------------------------------------------------------- a destination the reading cannot ground
@pytest.mark.parametrize("prompt", [
    "go to the robot and turn left",          # the robot is spoken to, never gone to
    "go to my friend and turn left",
    "turn left and go to the robot",
    "head towards the robot, then go forward two metres",
])
def test_an_unread_destination_blocks_the_whole_request(prompt: str) -> None:
    assert asks(prompt)


@pytest.mark.parametrize(("prompt", "expected"), [
    ("robot, turn left", [("rotate", "left", None, None)]),   # the robot addressed: a vocative
    ("turn left robot", [("rotate", "left", None, None)]),
    # "to the side" says a way, not a place to go to
    ("step to the side, left, half a metre", [("move", "left", 0.5, None)]),
])
def test_the_robot_addressed_is_no_destination(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


# ---------------------------------------------------------------- small amounts in other languages
@pytest.mark.parametrize(("prompt", "expected"), [
    ("back up un poquito, a little", [("move", "backward", None, None)]),
    ("forward a little bit más, poquito", [("move", "forward", None, None)]),
    ("turn left un peu", [("rotate", "left", None, None)]),
    ("move forward thoda sa", [("move", "forward", None, None)]),
    ("turn right biraz", [("rotate", "right", None, None)]),
    ("go back konti, a little", [("move", "backward", None, None)]),
    ("go forward ein bisschen", [("move", "forward", None, None)]),
])
def test_a_little_in_other_languages_is_a_little(prompt: str, expected: Plan) -> None:
    intent = translate_offline(prompt)
    assert plan(prompt) == expected
    assert [s.amount for s in intent.steps] == [Amount.LITTLE]


@settings(max_examples=40, deadline=None, derandomize=True)
@given(word=st.sampled_from(sorted(w for w, v in FOREIGN_AMOUNTS.items() if v == "a little")),
       motion=st.sampled_from(["move forward", "back up", "turn left", "turn right"]))
def test_every_small_amount_is_bounded(word: str, motion: str) -> None:
    """Any small amount said in another language is the contract's small amount: never a default or a guess."""
    intent = translate_offline(f"{motion} {word}")
    assert [s.amount for s in intent.steps] == [Amount.LITTLE]


def test_a_word_after_an_article_is_a_name() -> None:
    assert asks("go to the konti")


# ---------------------------------------------------------------- a way said alone, relayed corrections, asides
@pytest.mark.parametrize(("prompt", "expected"), [
    ("behind! back up two feet", [("move", "backward", 0.6096, None)]),   # the way said again
    ("she says turn left, sorry, she signed right, forty degrees", [("rotate", "right", None, 40.0)]),
    ("turn left, hands, ninety", [("rotate", "left", None, 90.0)]),      # a kitchen call between turn and amount
    ("how is the map now, show me", [("query", None, None, None)]),
    # a bare number after a turn said by name counts its degrees
    ("turn around, one hundred eighty", [("rotate", "around", None, 180.0)]),
    ("turn to back side, one hundred eighty", [("rotate", "around", None, 180.0)]),
    # (only a turn whose name says its amount: "spin it" says none, and "full three sixty" is its amount)
    ("spin it, full three sixty", [("rotate", "left", None, 360.0)]),
])
def test_session_11_speech(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "ahead! back up two feet",           # a way said alone that disagrees: maybe the way meant
    "move forward, hands, ninety",       # a bare number completing a move has no unit
    "turn around, ninety",               # another number than the named turn's: which way?
])
def test_session_11_neighbours_that_ask(prompt: str) -> None:
    assert asks(prompt)


# ---------------------------------------------------------------- order and take-backs
@pytest.mark.parametrize(("prompt", "expected"), [
    ("stop but first turn left", [("rotate", "left", None, None), ("stop", None, None, None)]),
    ("go forward one metre, but first turn right ninety degrees",
     [("rotate", "right", None, 90.0), ("move", "forward", 1.0, None)]),
    ("turn left ninety, cancel, turn right ninety", [("rotate", "right", None, 90.0)]),
    ("turn left ninety, wait, turn right ninety", [("rotate", "right", None, 90.0)]),
    ("turn left ninety, the opposite, turn right ninety", [("rotate", "right", None, 90.0)]),
    ("turn left ninety, opposite, right ninety", [("rotate", "right", None, 90.0)]),
    ("go forward two metres, cancel, go back one metre", [("move", "backward", 1.0, None)]),
    # a pause between two kinds of instruction orders them
    ("go forward two metres, wait, turn left", [("move", "forward", 2.0, None), ("rotate", "left", None, None)]),
])
def test_order_and_take_backs(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


@pytest.mark.parametrize("prompt", ["turn left fully, turn right forty five", "turn left fully",
                                    "turn right all the way"])
def test_a_turn_as_far_as_it_goes_asks(prompt: str) -> None:
    assert asks(prompt)


def test_fully_around_is_a_half_turn() -> None:
    assert plan("turn around fully") == [("rotate", "around", None, 180.0)]


# ---------------------------------------------------------------- an amount said in another language and in English
@pytest.mark.parametrize(("prompt", "expected"), [
    ("aage jao, do meter, two meter forward", [("move", "forward", 2.0, None)]),   # Hindi "do": two
    ("go forward two metres, iki metre", [("move", "forward", 2.0, None)]),         # Turkish "iki": two
])
def test_an_amount_said_in_both_languages_is_read(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "go forward two metres, teen meter",    # Hindi three beside two: which one?
    "go forward, do meter",                 # the amount only in another language
    "turn left, iki, forty five",           # two beside forty five
])
def test_an_amount_in_another_language_that_disagrees_asks(prompt: str) -> None:
    assert asks(prompt)


@settings(max_examples=40, deadline=None, derandomize=True)
@given(verb=st.sampled_from(["move forward", "move backward", "turn left", "turn right", "strafe left", "back up"]),
       amount=st.sampled_from(["1.5m", "2 m", "45deg", "3ft", "40cm", "90 degrees"]),
       style=st.sampled_from(["snake", "camel"]))
def test_a_call_plans_as_the_words_it_spells(verb: str, amount: str, style: str) -> None:
    """Whatever the verb and amount, the call written in code plans exactly as the words said."""
    first, *rest = verb.split()
    name = "_".join(verb.split()) if style == "snake" else first + "".join(w.capitalize() for w in rest)
    assert translate_offline(f"{name}({amount})").steps == translate_offline(f"{verb} {amount}").steps
