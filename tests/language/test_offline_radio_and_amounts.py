"""Readings added from new paraphrase material (issue 9, session 5): radio talk, amounts said alone
after a move or turn, restated bare moves, contrasts, compound measures, digit-by-digit numbers, and
the one number-word pattern every stage shares."""

from __future__ import annotations

import re

import pytest
from hypothesis import example, given
from hypothesis import strategies as st
from offline_plans import Plan
from offline_plans import asks as _asks
from offline_plans import plan as _plan

from langnav.language.intent import Amount, Movement
from langnav.language.offline import numbers, speech, splitter
from langnav.language.offline.numbers import ONES, TENS, canonical_numbers
from langnav.language.offline.translator import translate_offline

FT, IN = 0.3048, 0.0254


@pytest.mark.parametrize(("prompt", "expected"), [
    ("move forward. you're breaking up. move forward two metres", [("move", "forward", 2.0, None)]),
    ("move forward, you are breaking up, move forward three metres, over", [("move", "forward", 3.0, None)]),
    ("go forward, did you hear me, go forward four feet", [("move", "forward", round(4 * FT, 4), None)]),
])
def test_a_bare_move_said_again_with_its_amount_is_one_move_and_asks_nothing(prompt: str, expected: Plan) -> None:
    intent = translate_offline(prompt)
    assert _plan(prompt) == expected and intent.clarification is None


def test_a_bare_move_said_twice_still_asks_how_far() -> None:
    assert _asks("move forward. you're breaking up. move forward")


@pytest.mark.parametrize(("prompt", "expected"), [
    ("go forward seven feet, my bad, six feet", [("move", "forward", round(6 * FT, 4), None)]),
    ("go forward 2 feet, sorry, 3 feet", [("move", "forward", round(3 * FT, 4), None)]),
    ("move forward two metres, two metres", [("move", "forward", 2.0, None)]),
])
def test_an_amount_alone_put_right_or_said_again_is_done_once(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "move forward four metres, er, four feet",   # no word corrects the first: which one?
    "turn left forty, fifty degrees",
    "go forward ten feet... ten metres",
])
def test_a_different_amount_alone_with_no_correcting_word_is_asked_about(prompt: str) -> None:
    assert _asks(prompt)


@given(a=st.integers(1, 30), b=st.integers(1, 30), unit=st.sampled_from(["feet", "metres", "inches"]))
@example(a=2, b=3, unit="metres")
def test_an_amount_said_again_never_adds_up(a: int, b: int, unit: str) -> None:
    """"move forward A units, B units" is A units once when A == B, and asks otherwise: never the sum."""
    metres = {"feet": FT, "metres": 1.0, "inches": IN}[unit]
    steps = translate_offline(f"move forward {a} {unit}, {b} {unit}").steps
    expected = [(Movement.MOVE, pytest.approx(a * metres))] if a == b else []
    assert [(s.movement, s.distance_m) for s in steps] == expected


@pytest.mark.parametrize(("prompt", "expected"), [
    ("go forward two metres and then two more", [("move", "forward", 2.0, None)] * 2),
    ("turn right ninety, then another ninety", [("rotate", "right", None, 90.0)] * 2),
    ("turn left 45 degrees, 20 more", [("rotate", "left", None, 45.0), ("rotate", "left", None, 20.0)]),
    ("go forward two feet, then two more", [("move", "forward", round(2 * FT, 4), None)] * 2),
    ("fwd 1.5m then lft 90", [("move", "forward", 1.5, None), ("rotate", "left", None, 90.0)]),
])
def test_more_of_the_same_takes_the_unit_just_used(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


@pytest.mark.parametrize("prompt", ["go forward two feet, then 2", "turn left thirty. forty"])
def test_a_number_alone_with_no_word_of_more_is_asked_about(prompt: str) -> None:
    assert _asks(prompt)


@pytest.mark.parametrize(("prompt", "expected"), [
    ("go forward ten feet, actually make that eight", [("move", "forward", round(8 * FT, 4), None)]),
    ("move forward three feet, no, three and a half", [("move", "forward", round(3.5 * FT, 4), None)]),
    ("move back two feet, wait, no, forward two feet", [("move", "forward", round(2 * FT, 4), None)]),
    ("move forward one metre, i said one metre", [("move", "forward", 1.0, None)]),
    ("turn right, i said left", [("rotate", "left", None, None)]),
])
def test_a_correction_keeps_the_unit_and_drops_the_wait(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


@pytest.mark.parametrize(("prompt", "expected"), [
    ("turn left ninety, and again", [("rotate", "left", None, 90.0)] * 2),
    ("go forward three feet and then do it again", [("move", "forward", round(3 * FT, 4), None)] * 2),
    ("move forward 2 m, repeat that", [("move", "forward", 2.0, None)] * 2),
    ("move forward 2 m, repeat", [("move", "forward", 2.0, None)]),  # the radio's "I repeat"
    ("go to the door. again", [("navigate", None, None, None)]),     # a place reached is reached
])
def test_again_alone_does_the_move_or_turn_before_once_more(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


@pytest.mark.parametrize(("prompt", "expected"), [
    ("base to robot, rotate left one three five degrees, over", [("rotate", "left", None, 135.0)]),
    ("robot, move ahead one five feet, over", [("move", "forward", round(15 * FT, 4), None)]),
    ("robot, forward two zero feet, over", [("move", "forward", round(20 * FT, 4), None)]),
    ("robot this is base, advance six feet, over", [("move", "forward", round(6 * FT, 4), None)]),
    ("robot, negative on that, hold, hold", [("stop", None, None, None)]),
    ("if you could go backwards about two feet that would be great", [("move", "backward", round(2 * FT, 4), None)]),
    ("i want that you turn to the left thirty degrees", [("rotate", "left", None, 30.0)]),
    ("can you hear me? move forward six feet", [("move", "forward", round(6 * FT, 4), None)]),
])
def test_radio_talk(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "move forward two three feet",   # two digits one apart: "two or three feet"?
    "go to door one two",
])
def test_digits_that_may_be_a_range_are_asked_about(prompt: str) -> None:
    assert _asks(prompt)


@pytest.mark.parametrize(("prompt", "expected"), [
    ("okay so turn right ninety degrees. Again: turn right ninety degrees.", [("rotate", "right", None, 90.0)]),
    ("turn left ninety. Again, turn left ninety", [("rotate", "left", None, 90.0)]),
    ("turn left ninety. again.", [("rotate", "left", None, 90.0)] * 2),
])
def test_again_opening_the_same_instruction_says_it_again(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


@given(n=st.integers(10, 9999))
@example(n=105)
@example(n=120)
def test_digit_by_digit_reads_the_number(n: int) -> None:
    digits = str(n)
    names = {v: w for w, v in ONES.items() if v <= 9 and w not in ("nought",)}
    spoken = " ".join(names[int(d)] for d in digits)
    one_apart = len(digits) == 2 and abs(int(digits[1]) - int(digits[0])) == 1
    if len(set(digits)) == 1 or digits[0] == digits[1] or one_apart:
        return  # a digit said again (a restart or a stutter) or a possible range: read elsewhere
    assert canonical_numbers(f"move forward {spoken} feet") == f"move forward {n} feet"


@pytest.mark.parametrize(("text", "kept"), [
    ("move forward one point two five metres", "move forward one point two five metres"),
    ("turn left one eighty", "turn left one eighty"),
    ("move forward four four feet", "move forward four four feet"),
    ("go one hundred and five feet", "go one hundred and five feet"),
])
def test_digit_runs_leave_other_numbers_alone(text: str, kept: str) -> None:
    assert canonical_numbers(text) == kept


@pytest.mark.parametrize(("prompt", "expected"), [
    ("negative, negative, turn left not right, thirty degrees, over", [("rotate", "left", None, 30.0)]),
    ("turn not left but right", [("rotate", "right", None, None)]),
    ("go forward three feet not four", [("move", "forward", round(3 * FT, 4), None)]),
    ("move forward two metres but don't turn", [("move", "forward", 2.0, None)]),
])
def test_a_contrast_keeps_what_is_meant(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


@pytest.mark.parametrize("prompt", ["do not back up", "do not turn left"])
def test_a_negation_is_still_no_instruction(prompt: str) -> None:
    assert _asks(prompt)


@pytest.mark.parametrize(("prompt", "metres"), [
    ("move forward three ft six in", 3 * FT + 6 * IN),
    ("go forward 5 ft 10 in", 5 * FT + 10 * IN),
    ("go forward 5'10\"", 5 * FT + 10 * IN),
    ("go forward 4'", 4 * FT),
    ("go forward one metre twenty", 1.2),
    ("go forward 1 m 20", 1.2),
    ("move for the front one meter and half", 1.5),
    ("drive forward one metre and twenty centimetres", 1.2),
])
def test_compound_measures(prompt: str, metres: float) -> None:
    assert _plan(prompt) == [("move", "forward", round(metres, 4), None)]


def test_inches_of_a_place_are_no_unit() -> None:
    assert _asks("go forward 5 feet 2 in the hallway")


@pytest.mark.parametrize(("prompt", "expected"), [
    ("retreat two metres", [("move", "backward", 2.0, None)]),
    ("turn left by a right angle", [("rotate", "left", None, 90.0)]),
    ("transmit the map", [("query", None, None, None)]),
    ("shw me teh map", [("query", None, None, None)]),
    ("turn around and hold", [("rotate", "around", None, 180.0), ("stop", None, None, None)]),
    ("turn back please, i want see behind", [("rotate", "around", None, 180.0)]),
])
def test_words_from_new_speakers(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


def test_a_small_turn_is_a_little_turn() -> None:
    steps = translate_offline("make small turn to the left").steps
    assert [(s.movement, s.amount) for s in steps] == [(Movement.ROTATE, Amount.LITTLE)]


def test_holding_a_thing_is_out_of_scope() -> None:
    assert _asks("hold the door")


_ALL_NUMBER_WORDS = sorted(w for w, v in (ONES | TENS).items() if v > 0)


@pytest.mark.parametrize("word", _ALL_NUMBER_WORDS)
def test_every_stage_knows_every_number_word(word: str) -> None:
    """One pattern (numbers.NUMBER_WORDS) serves the restart, the correction, the splitter's "and" and the
    cut-off reading: each knows every number word the number reading knows."""
    assert re.fullmatch(numbers.NUMBER_WORDS, word)
    assert speech.NUMBER_RESTART.sub("", f"{word}, {word} feet") == f"{word} feet"
    assert splitter._inside_a_number("one hundred", f"{word} degrees")
    assert any(w.startswith(word[:3]) for w in speech.NUMBER_WORD_LIST)


@pytest.mark.parametrize(("prompt", "expected"), [
    ("robot, come left ninety, over", [("rotate", "left", None, 90.0)]),
    ("robot, move up nine feet then come right forty, over",
     [("move", "forward", round(9 * FT, 4), None), ("rotate", "right", None, 40.0)]),
    ("robot, hold your position, over", [("stop", None, None, None)]),
    ("robot, report position, over", [("query", None, None, None)]),
    ("robot, give me a three sixty, over", [("rotate", "left", None, 360.0)]),
    ("robot, turn left, turn left, over", [("rotate", "left", None, None)]),
    ("make the turn around please", [("rotate", "around", None, 180.0)]),
    ("where you are now", [("query", None, None, None)]),
    ("lol turn around", [("rotate", "around", None, 180.0)]),
    ("hey wru", [("query", None, None, None)]),
    ("trn left 45 n fwd 1m", [("rotate", "left", None, 45.0), ("move", "forward", 1.0, None)]),
    ("move forward four and three quarter feet", [("move", "forward", round(4.75 * FT, 4), None)]),
    ("keep turning right, another twenty", [("rotate", "right", None, 20.0)]),
    ("go forward two feet and again two feet", [("move", "forward", round(2 * FT, 4), None)] * 2),
    ("robot, back three, uh, three feet, over", [("move", "backward", round(3 * FT, 4), None)]),
    ("negative robot, i said left, left twenty, over", [("rotate", "left", None, 20.0)]),
])
def test_more_words_from_new_speakers(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "go forward a few feet",     # how far is "a few"? asked, never guessed
    "go backside one meter",     # a word not read where the way should be: it may be the way
])
def test_a_guess_about_how_far_or_which_way_is_asked(prompt: str) -> None:
    assert _asks(prompt)


def test_a_turn_said_twice_in_sequence_is_done_twice() -> None:
    assert _plan("turn left, then turn left") == [("rotate", "left", None, None)] * 2


@pytest.mark.parametrize(("prompt", "expected"), [
    ("carry on forward another metre", [("move", "forward", 1.0, None)]),
    ("advance niner feet, over", [("move", "forward", round(9 * FT, 4), None)]),
    ("go straight only, three metres", [("move", "forward", 3.0, None)]),
    ("be a love and turn round", [("rotate", "around", None, 180.0)]),
    ("where've you got to", [("query", None, None, None)]),
    ("can you do a twirl", [("rotate", "left", None, 360.0)]),
    ("come about, then advance one zero feet, over", [("rotate", "around", None, 180.0),
                                                     ("move", "forward", round(10 * FT, 4), None)]),
    ("now turn to your left, a quarter of the way round", [("rotate", "left", None, 90.0)]),
    ("turn to your right, a quarter turn", [("rotate", "right", None, 90.0)]),
    ("have a look to your right", [("rotate", "right", None, None)]),
    ("turn left no right thirty degrees", [("rotate", "right", None, 30.0)]),
    ("move forward seven feet turn right", [("move", "forward", round(7 * FT, 4), None), ("rotate", "right", None, None)]),
    ("move forward five feet stop", [("move", "forward", round(5 * FT, 4), None), ("stop", None, None, None)]),
    ("go forward and stop after two metres", [("move", "forward", 2.0, None)]),
    ("please do one thing, turn left ninety degrees", [("rotate", "left", None, 90.0)]),
    ("180 then fwd 5 ft", [("rotate", "around", None, 180.0), ("move", "forward", round(5 * FT, 4), None)]),
    ("one eighty, then go forward 2 m", [("rotate", "around", None, 180.0), ("move", "forward", 2.0, None)]),
    ("go forward five-ish feet", [("move", "forward", round(5 * FT, 4), None)]),
    ("go forward 2 metres or 6 feet", [("move", "forward", round(6 * FT, 4), None)]),
    ("go forward six feet or two metres", [("move", "forward", round(6 * FT, 4), None)]),
    ("go forward 2 metres and stop after the door", [("move", "forward", 2.0, None), ("navigate", None, None, None)]),
])
def test_words_from_a_third_set_of_speakers(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "one eighty, then go forward",          # the turn, then a move of unsaid length: asked
    "move two feet twelve inches",          # no compound (12 inches is a foot): which amount?
    "okay so advance about two ft, maybe 12 inches.",
])
def test_amounts_that_disagree_are_asked_about(prompt: str) -> None:
    assert _asks(prompt)


_SPOKEN_AMOUNTS = st.sampled_from([("two feet", 2 * FT), ("three metres", 3.0), ("eight inches", 8 * IN),
                                   ("1.5 m", 1.5), ("a yard", 0.9144), ("twenty five feet", 25 * FT)])


@given(first=_SPOKEN_AMOUNTS, second=_SPOKEN_AMOUNTS,
       frame=st.sampled_from(["move forward {a}, {b}", "move forward {a}, i mean {b}", "move forward {a} or {b}",
                              "move forward {a}, sorry, {b}", "move forward {a}. move forward {a}",
                              "move forward. you're breaking up. move forward {a}", "go forward {a}, that's {a}",
                              "uh, go forward, uh, {a}, go forward {a}", "move forward {a}, no, {b}",
                              "move forward {a}. Again: move forward {a}", "move forward {a}... {b}"]))
@example(first=("three metres", 3.0), second=("two feet", 2 * FT), frame="move forward {a}, {b}")
def test_one_move_said_in_pieces_never_goes_farther_than_the_largest_amount_said(
        first: tuple[str, float], second: tuple[str, float], frame: str) -> None:
    prompt = frame.format(a=first[0], b=second[0])
    moved = sum(s.distance_m or 0.0 for s in translate_offline(prompt).steps if s.movement == Movement.MOVE)
    assert moved <= max(first[1], second[1]) + 1e-9


@pytest.mark.parametrize(("prompt", "expected"), [
    ("where are ya", [("query", None, None, None)]),
    ("where is you", [("query", None, None, None)]),
    ("I would like you to move forward a distance of exactly two metres, please", [("move", "forward", 2.0, None)]),
    ("please rotate to your left by an angle of forty-five degrees", [("rotate", "left", None, 45.0)]),
    ("move in the backward direction two feet", [("move", "backward", round(2 * FT, 4), None)]),
    ("go forward eight feet, oh sorry, eight inches", [("move", "forward", round(8 * IN, 4), None)]),
    ("forward five metres, oops, I meant feet", [("move", "forward", round(5 * FT, 4), None)]),
    ("one more turn to the left, ninety degrees", [("rotate", "left", None, 90.0)]),
    ("turn left one more time", [("rotate", "left", None, None)]),
    # the same amount said again in another unit is one move, the smaller of the two
    ("move forward two metres, that is, about six and a half feet", [("move", "forward", round(6.5 * FT, 4), None)]),
    ("go forward ten feet, about three metres", [("move", "forward", 3.0, None)]),
])
def test_words_from_a_fourth_set_of_speakers(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


def test_a_number_word_left_unread_is_asked_about() -> None:
    assert _asks("rover, advance one two feet, over")


@pytest.mark.parametrize(("prompt", "ordinal", "label", "side"), [
    ("go to door no. 2 on the right", 2, None, "right"),
    ("Go to the door No. 2 on your left.", 2, None, "left"),
    ("go through room No.3", None, 3, None),
    ("go to door nr. 4", None, 4, None),
])
def test_no_dot_before_a_numeral_after_a_noun_is_number(prompt: str, ordinal: int | None, label: int | None,
                                                        side: str | None) -> None:
    # "no." abbreviates "number": its dot ends no sentence and "2 on the right" is no 2-degree turn
    intent = translate_offline(prompt)
    assert len(intent.steps) == 1, intent
    (step,) = intent.steps
    assert step.movement == Movement.NAVIGATE and step.target is not None
    assert step.target.kind.value == ("room" if "room" in prompt else "door")
    assert (step.target.ordinal, step.target.label) == (ordinal, label)
    assert (step.target.side.value if step.target.side is not None else None) == side


@pytest.mark.parametrize(("text", "read"), [
    ("door no. 2 on the right", "door number 2 on the right"),
    ("room No.3", "room number 3"),
    # after an amount "no" corrects it, and after a full stop or a comma it is the word "no"
    ("turn 80 degrees no. 85", "turn 80 degrees no. 85"),
    ("go forward. no. 3 metres", "go forward. no. 3 metres"),
    ("no. 5", "no. 5"),
])
def test_the_number_abbreviation_is_read_only_after_a_noun(text: str, read: str) -> None:
    assert canonical_numbers(text) == read
