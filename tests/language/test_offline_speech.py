"""Spoken commands (issue 9; README "Spoken commands"): units, spoken numbers, compass, corrections,
fillers, cut-off words, photos, chat spelling, and the safety property that a reading never moves
farther or turns more than was asked. The prompts are our own paraphrases of each pattern."""

from __future__ import annotations

import math

import pytest
from hypothesis import assume, example, given
from hypothesis import strategies as st

from langnav.language.intent import Amount, Direction, Intent, Movement, Step
from langnav.language.offline import translate_offline
from langnav.language.offline.speech import plain_speech

FT, IN, YD = 0.3048, 0.0254, 0.9144


def _moves(intent: Intent) -> list[Step]:
    return [s for s in intent.steps if s.movement == Movement.MOVE]


def _turns(intent: Intent) -> list[Step]:
    return [s for s in intent.steps if s.movement == Movement.ROTATE]


# ------------------------------------------------------------------------------ amounts
@pytest.mark.parametrize(("prompt", "direction", "metres"), [
    ("roll three more feet", Direction.FORWARD, 3 * FT),
    ("scoot ahead another two feet", Direction.FORWARD, 2 * FT),
    ("could you go one more yard forward", Direction.FORWARD, YD),
    ("go a foot and a half forward", Direction.FORWARD, 1.5 * FT),
    ("back up six more inches", Direction.BACKWARD, 6 * IN),
    ("drive forward one hundred and twenty centimetres", Direction.FORWARD, 1.2),
    ("move forward, uh, seven feet", Direction.FORWARD, 7 * FT),
    ("move two or three feet forward", Direction.FORWARD, 2 * FT),  # a range: never more than allowed
    ("keep rolling another eight feet until i tell you to stop", Direction.FORWARD, 8 * FT),
    ("slide to your left two feet", Direction.LEFT, 2 * FT),
    ("nine inches, go straight", Direction.FORWARD, 9 * IN),
    ("move forward five inch", Direction.FORWARD, 5 * IN),
])
def test_spoken_distances(prompt: str, direction: Direction, metres: float) -> None:
    intent = translate_offline(prompt)
    moves = _moves(intent)
    assert len(moves) == 1 and len(intent.steps) == 1, intent
    assert moves[0].direction == direction
    assert moves[0].distance_m == pytest.approx(metres)


@pytest.mark.parametrize(("prompt", "direction", "degrees"), [
    ("rotate forty five more degrees to your left", Direction.LEFT, 45),
    ("could you move thirty more degrees to the right", Direction.RIGHT, 30),
    ("turn two seventy to the right", Direction.RIGHT, 270),
    ("spin one twenty degrees left", Direction.LEFT, 120),
    ("turn a hundred and twenty degrees clockwise", Direction.RIGHT, 120),
    ("pivot, sixty degrees, counter clockwise", Direction.LEFT, 60),
    ("er perhaps thirty degrees, to the left", Direction.LEFT, 30),
    ("turn roughly twenty degrees to the right", Direction.RIGHT, 20),
    ("turn le- left forty degrees", Direction.LEFT, 40),
    ("tu turn right fifteen degrees", Direction.RIGHT, 15),
    ("turn right, hmm, fifty five degrees", Direction.RIGHT, 55),
    ("turn, seventy degrees, to your left", Direction.LEFT, 70),
    ("make a sixty degree turn to your right", Direction.RIGHT, 60),
])
def test_spoken_turns_are_one_turn(prompt: str, direction: Direction, degrees: float) -> None:
    intent = translate_offline(prompt)
    assert len(intent.steps) == 1, intent
    turn = intent.steps[0]
    assert turn.movement == Movement.ROTATE and turn.direction == direction
    assert turn.angle_deg == pytest.approx(degrees)


@pytest.mark.parametrize("prompt", ["turn one eighty", "spin a hundred and eighty degrees", "do a one eighty turn"])
def test_half_turns_in_words(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert len(intent.steps) == 1
    assert intent.steps[0].movement == Movement.ROTATE
    assert intent.steps[0].angle_deg == pytest.approx(180)


def test_a_full_circle_is_one_full_turn() -> None:
    turn = translate_offline("go around in a circle").steps
    assert len(turn) == 1 and turn[0].angle_deg == pytest.approx(360)


# ------------------------------------------------------------------------------ compass
@pytest.mark.parametrize(("prompt", "heading", "metres"), [
    ("face west", 180, None), ("turn due north", 90, None), ("could you turn to the south", 270, None),
    ("pivot toward the east", 0, None), ("face north west", 135, None), ("look southeast", 315, None),
    ("head south six feet", 270, 6 * FT), ("go east, about ten feet", 0, 10 * FT),
    ("move four feet north east", 45, 4 * FT), ("proceed due west, for two yards", 180, 2 * YD),
])
def test_compass_points(prompt: str, heading: float, metres: float | None) -> None:
    intent = translate_offline(prompt)
    face = intent.steps[0]
    assert face.movement == Movement.ROTATE and face.heading_deg == pytest.approx(heading)
    if metres is None:
        assert len(intent.steps) == 1
    else:
        assert len(intent.steps) == 2
        assert intent.steps[1].movement == Movement.MOVE and intent.steps[1].direction == Direction.FORWARD
        assert intent.steps[1].distance_m == pytest.approx(metres)


# ------------------------------------------------------------------------------ corrections
@pytest.mark.parametrize(("prompt", "direction", "degrees"), [
    ("turn sixty degrees left, actually right", Direction.RIGHT, 60),
    ("turn right thirty degrees, sorry, turn left thirty degrees", Direction.LEFT, 30),
    ("turn left, forty degrees, no wait right", Direction.RIGHT, 40),
    ("rotate fifty degrees to your right, i'm sorry, fifty degrees to your left", Direction.LEFT, 50),
    ("turn left twenty degrees, i mean thirty", Direction.LEFT, 30),
    ("back up two feet, never mind, turn right eighty degrees", Direction.RIGHT, 80),
])
def test_self_corrections_keep_only_the_correction(prompt: str, direction: Direction, degrees: float) -> None:
    intent = translate_offline(prompt)
    assert len(intent.steps) == 1, intent
    assert intent.steps[0].direction == direction
    assert intent.steps[0].angle_deg == pytest.approx(degrees)


def test_a_correction_of_the_amount_keeps_the_side() -> None:
    intent = translate_offline("move back four feet, no wait, two feet")
    assert [(s.direction, s.distance_m) for s in intent.steps] == [(Direction.BACKWARD, pytest.approx(2 * FT))]


# ------------------------------------------------------------------------------ speech clean-up
@pytest.mark.parametrize(("said", "plain"), [
    ("turn nin- degree- ninety degrees right", "turn ninety degrees right"),
    ("uh move um forward, like, two feet", "move forward, like, two feet"),
    ("go go to the door", "go to the door"),
    ("tur turn left", "turn left"),
    ("ff face north", "face north"),
    ("reverse 800 mm", "reverse 800 mm"),
    ("turn right actually left", "turn right, actually left"),
])
def test_plain_speech(said: str, plain: str) -> None:
    assert plain_speech(said) == plain


@pytest.mark.parametrize("prompt", [
    "pls trun rigth 90 degress", "can u turn to ur right ninety degrees", "could you please turn right 90 degrees?",
    "hey robot, would you mind turning right ninety degrees", "okay go ahead, turn right ninety degrees",
    "teh robot should turn right 90 degrees"])
def test_chat_spelling_typos_and_politeness(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert [(s.movement, s.direction, s.angle_deg) for s in intent.steps] == [
        (Movement.ROTATE, Direction.RIGHT, 90.0)], intent


# ------------------------------------------------------------------------------ photos
@pytest.mark.parametrize("prompt", ["take a picture", "send me a photo please", "what do you see?",
                                    "snap a picture of the room in front of you", "give me a visual"])
def test_a_photo_alone_is_explained(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert intent.steps == []
    assert intent.clarification is not None and "camera" in intent.clarification


def test_a_photo_with_motion_does_the_motion_and_says_what_was_left_out() -> None:
    intent = translate_offline("back up a foot, then snap a photo")
    assert [(s.direction, s.distance_m) for s in intent.steps] == [(Direction.BACKWARD, pytest.approx(FT))]
    assert intent.clarification is not None and "camera" in intent.clarification


@pytest.mark.parametrize(("prompt", "direction"), [
    ("take a picture to your left", Direction.LEFT), ("show me what is behind you", Direction.AROUND)])
def test_a_photo_to_one_side_turns_that_way(prompt: str, direction: Direction) -> None:
    intent = translate_offline(prompt)
    assert [s.direction for s in intent.steps] == [direction]


# ------------------------------------------------------------------------------ never farther, never more
_UNITS = {"feet": FT, "foot": FT, "inches": IN, "yards": YD, "metres": 1.0, "meters": 1.0, "centimetres": 0.01}
_WORDS = ["", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve",
          "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen"]
_TENS = {2: "twenty", 3: "thirty", 4: "forty", 5: "fifty", 6: "sixty", 7: "seventy", 8: "eighty", 9: "ninety"}
_FILLERS = ["", "uh", "um", "maybe", "uh maybe", "please", "like"]
_LEAD_INS = ["", "go ahead and", "yeah go ahead and", "okay go ahead,", "so,", "alright now"]
_MORE = ["", "more", "another", "further"]  # "another" is said before the amount, the others after


def _spoken(n: int) -> str:
    if n < 20:
        return _WORDS[n]
    if n < 100:
        return _TENS[n // 10] + ("" if n % 10 == 0 else " " + _WORDS[n % 10])
    hundreds, rest = divmod(n, 100)
    if rest == 0:
        return f"{_WORDS[hundreds]} hundred"
    return f"{_WORDS[hundreds]} {_spoken(rest)}" if rest >= 20 else f"{_WORDS[hundreds]} hundred and {_spoken(rest)}"


def _total(steps: list[Step], field: str) -> float:
    return sum(getattr(s, field) or 0.0 for s in steps)


@given(st.integers(min_value=1, max_value=60), st.sampled_from(sorted(_UNITS)), st.sampled_from(_MORE),
       st.sampled_from(["move", "go", "drive", "back up", "keep going", "continue"]),
       st.sampled_from(["", "forward", "back", "to your left", "to the right"]),
       st.lists(st.sampled_from(_FILLERS), min_size=3, max_size=3), st.integers(min_value=0, max_value=3),
       st.booleans(), st.sampled_from(_LEAD_INS))
@example(n=2, unit="feet", more="more", verb="move", direction="", fillers=["", "", ""], shape=0, digits=False,
         lead="")
@example(n=45, unit="feet", more="more", verb="move", direction="to the right", fillers=["", "", ""], shape=0,
         digits=False, lead="")
@example(n=3, unit="feet", more="", verb="move", direction="forward", fillers=["", "", ""], shape=0,
         digits=False, lead="yeah go ahead and")  # was a default move and then the three feet
def test_a_move_never_goes_farther_than_asked(n: int, unit: str, more: str, verb: str, direction: str,
                                               fillers: list[str], shape: int, digits: bool, lead: str) -> None:
    number = str(n) if digits else _spoken(n)
    amount = " ".join(w for w in ((more, number, unit) if more == "another" else (number, more, unit)) if w)
    f1, f2, f3 = fillers
    shapes = [f"{verb} {f1} {amount} {f2} {direction}", f"{verb} {direction}, {f1} {amount}",
              f"{f1} {amount}, {f2} {verb} {direction}", f"{verb}, {f3} {direction} {f1} {amount}"]
    intent = translate_offline(" ".join(f"{lead} {shapes[shape]}".split()))
    asked = n * _UNITS[unit]
    assert _total(_moves(intent), "distance_m") <= asked * (1 + 1e-9), intent
    assert not any(s.amount == Amount.DEFAULT for s in _moves(intent)), intent  # never a guessed distance
    assert _turns(intent) == [] or direction in ("to your left", "to the right"), intent


@given(st.integers(min_value=1, max_value=359), st.sampled_from(["left", "right", "clockwise", "counter clockwise"]),
       st.sampled_from(_MORE), st.sampled_from(["turn", "rotate", "pivot", "spin", "move"]),
       st.lists(st.sampled_from(_FILLERS), min_size=3, max_size=3), st.integers(min_value=0, max_value=3))
@example(n=150, side="right", more="", verb="pivot", fillers=["", "", ""], shape=0)
@example(n=45, side="right", more="more", verb="move", fillers=["", "", ""], shape=1)
@example(n=45, side="right", more="", verb="turn", fillers=["maybe", "", ""], shape=2)
@example(n=10, side="left", more="another", verb="turn", fillers=["", "", ""], shape=0)
def test_a_turn_never_turns_more_than_asked(n: int, side: str, more: str, verb: str, fillers: list[str],
                                            shape: int) -> None:
    amount = " ".join(w for w in ((more, _spoken(n), "degrees") if more == "another" else (_spoken(n), more, "degrees"))
                      if w)
    where = side if "clockwise" in side else f"to your {side}"
    f1, f2, f3 = fillers
    shapes = [f"{verb} {f1} {amount} {f2} {where}", f"{verb} {where}, {f1} {amount}",
              f"{f1} {amount}, {f2} {where}", f"{verb}, {f3} {amount} {f1} {where}"]
    intent = translate_offline(" ".join(shapes[shape].split()))
    want = Direction.LEFT if side in ("left", "counter clockwise") else Direction.RIGHT
    assert _moves(intent) == [], intent
    assert _total(_turns(intent), "angle_deg") <= n + 1e-9, intent
    assert all(s.direction in (want, Direction.AROUND) for s in _turns(intent)), intent
    if intent.steps:
        assert math.isclose(_total(_turns(intent), "angle_deg"), n), intent


@given(st.integers(min_value=10, max_value=170), st.integers(min_value=10, max_value=170),
       st.sampled_from(["actually", "sorry", "no wait", "i'm sorry", "i mean"]), st.booleans())
@example(first=10, second=100, marker="sorry", restate=False)  # "one hundred degrees": no "and" after it
def test_a_self_correction_is_the_only_turn(first: int, second: int, marker: str, restate: bool) -> None:
    said = f"turn {_spoken(first)} degrees to your left, {marker}, "
    said += f"turn {_spoken(second)} degrees to your right" if restate else f"{_spoken(second)} degrees right"
    intent = translate_offline(said)
    assert [(s.direction, s.angle_deg) for s in intent.steps] == [(Direction.RIGHT, pytest.approx(second))], intent


# ------------------------------------------------------------------------------ typing slips
def _swap(word: str, i: int) -> str:
    return word[:i] + word[i + 1] + word[i] + word[i + 2:]


_PLAIN = {"left": ("turn left 40 degrees", Direction.LEFT), "right": ("turn right 40 degrees", Direction.RIGHT),
          "turn": ("turn right 40 degrees", Direction.RIGHT), "rotate": ("rotate left 40 degrees", Direction.LEFT),
          "degrees": ("turn right 40 degrees", Direction.RIGHT)}


@given(st.sampled_from(sorted(_PLAIN)), st.data())
@example(word="right", data=None)
def test_two_swapped_letters_read_as_the_word(word: str, data: st.DataObject | None) -> None:
    """A typing slip (two letters swapped, not the first) in a word of the command changes nothing."""
    i = data.draw(st.integers(min_value=1, max_value=len(word) - 2)) if data is not None else 2
    plain, side = _PLAIN[word]
    said = " ".join(_swap(word, i) if w == word else w for w in plain.split())
    assume(said != plain)  # swapping two equal letters ("degrees") is no slip
    assert [(s.direction, s.angle_deg) for s in translate_offline(said).steps] == [(side, 40.0)], said
