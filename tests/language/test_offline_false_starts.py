"""False starts and slips in spoken turns (langnav.language.offline.restarts.drop_false_start_turns and the
exclamations of dismay of corrections.DISMAY): a bare turn taken back at once by a turn to the other side,
or an instruction followed by "aiya" / "argh" / "oh no", is not a request; the last version counts, and the
robot never turns more than the last turn said. The prompts are our own paraphrases of each pattern."""

from __future__ import annotations

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from langnav.language.intent import Amount, Direction, Movement
from langnav.language.offline import translate_offline

_SIDES = {"left": Direction.LEFT, "right": Direction.RIGHT}
_WORDS = {20: "twenty", 30: "thirty", 40: "forty", 45: "forty five", 60: "sixty", 90: "ninety", 120: "a hundred and twenty"}


def _plan(prompt: str) -> list[tuple[str, str | None, float | None, float | None]]:
    return [(s.movement.value, s.direction.value if s.direction else None, s.distance_m, s.angle_deg)
            for s in translate_offline(prompt).steps]


@pytest.mark.parametrize(("prompt", "expected"), [
    # a bare turn and a turn to the other side, back to back: a fumbled start, the last one counts
    ("turn left, turn right", [("rotate", "right", None, None)]),
    ("turn right, turn left, turn right, turn left ninety", [("rotate", "left", None, 90.0)]),
    ("rotate left, um, rotate right forty five degrees", [("rotate", "right", None, 45.0)]),
    ("turn left, uh, turn left, turn right forty", [("rotate", "right", None, 40.0)]),
    # an exclamation of dismay marks the instruction before it as a slip
    ("turn left, argh, turn right thirty degrees", [("rotate", "right", None, 30.0)]),
    ("turn right, turn left, aiyo, turn right fifty degree", [("rotate", "right", None, 50.0)]),
    ("move back, ugh, forward one metre", [("move", "forward", 1.0, None)]),
    ("go forward two metres, damn it, go back one metre", [("move", "backward", 1.0, None)]),
    ("turn left twenty degrees, whoops, thirty", [("rotate", "left", None, 30.0)]),
    ("turn left, eish, right", [("rotate", "right", None, None)]),
    # an oath the reading does not know is no instruction between them either
    ("turn left, oh blimey, right, sixty", [("rotate", "right", None, 60.0)]),
    ("turn right, heck, turn left", [("rotate", "left", None, None)]),
    # a stop said between them is no pause ("turn right, stop, turn left" is read by drop_stopped)
    ("turn right ninety, no hang on, sixty", [("rotate", "right", None, 60.0)]),
    # a side said on its own is a bare turn too (the session-9 review)
    ("rotate left. left, uh, turn right", [("rotate", "right", None, None)]),
    ("left. no, right. turn left ninety", [("rotate", "left", None, 90.0)]),
    ("no, right, uh, turn left ninety, uh, go forward two metres", [("rotate", "left", None, 90.0), ("move", "forward", 2.0, None)]),
])
def test_the_last_version_counts(prompt: str, expected: list[tuple[str, str | None, float | None, float | None]]) -> None:
    assert _plan(prompt) == expected


@pytest.mark.parametrize(("prompt", "expected"), [
    # a word that puts them in order: both turns are meant (a look around)
    ("turn left, then turn right", [("rotate", "left", None, None), ("rotate", "right", None, None)]),
    ("turn left and turn right", [("rotate", "left", None, None), ("rotate", "right", None, None)]),
    # something else said between them: both are meant
    ("turn left, take a picture, turn right", [("rotate", "left", None, None), ("rotate", "right", None, None)]),
    # a turn with its amount said is no false start
    ("turn right forty, turn left", [("rotate", "right", None, 40.0), ("rotate", "left", None, None)]),
    # an exclamation with nothing before it corrects nothing
    ("argh, turn left thirty degrees", [("rotate", "left", None, 30.0)]),
])
def test_ordered_or_complete_turns_are_all_kept(
        prompt: str, expected: list[tuple[str, str | None, float | None, float | None]]) -> None:
    assert _plan(prompt) == expected


_PAUSES = [", ", ", uh, ", ", um, ", ", aiya, ", ", argh, ", ", oh no, ", ", ugh, ", " ... ", ", oh bugger, ", ", jeez, "]


@given(st.lists(st.sampled_from(sorted(_SIDES)), min_size=1, max_size=5),
       st.lists(st.sampled_from(_PAUSES), min_size=5, max_size=5),
       st.sampled_from(sorted(_SIDES)), st.sampled_from(sorted(_WORDS)), st.booleans())
@example(starts=["right", "left"], pauses=[", ", ", aiya, ", ", ", ", ", ", "], side="right", degrees=60, said=True)
@example(starts=["left", "left", "right"], pauses=[", "] * 5, side="left", degrees=90, said=False)
def test_false_start_turns_never_turn_more_than_the_last_turn_said(
        starts: list[str], pauses: list[str], side: str, degrees: int, said: bool) -> None:
    """A stream of bare turns said and taken back, then the turn meant: at most the last turn's amount (the
    default quarter turn when it has none), only to its side, and nothing else."""
    last = f"turn {side} {_WORDS[degrees]} degrees" if said else f"turn {side}"
    prompt = "".join(f"turn {s}{p}" for s, p in zip(starts, pauses, strict=False)) + last
    intent = translate_offline(prompt)
    turns = [s for s in intent.steps if s.movement == Movement.ROTATE]
    assert len(turns) == len(intent.steps), intent
    asked = degrees if said else 90.0
    assert sum(s.angle_deg if s.angle_deg is not None else 90.0 for s in turns) <= asked + 1e-9, intent
    if intent.steps:  # when it runs, it is the last turn said
        assert [(s.direction, s.angle_deg, s.amount) for s in turns] == [
            (_SIDES[side], float(degrees) if said else None, None if said else Amount.DEFAULT)], intent


_CORRECTIONS = [", correction, ", ", sorry, ", ", I mean, ", ", no, make that ", ", scratch that, "]


@given(st.lists(st.sampled_from(sorted(_SIDES)), min_size=1, max_size=3),
       st.sampled_from(_PAUSES), st.sampled_from(sorted(_SIDES)), st.sampled_from(sorted(_WORDS)),
       st.sampled_from(sorted(_WORDS)), st.sampled_from(_CORRECTIONS))
@example(starts=["left"], pause=", uh, ", side="right", first=20, then=20, correction=", correction, ")
def test_a_false_start_before_a_corrected_turn_never_turns_more_than_the_correction(
        starts: list[str], pause: str, side: str, first: int, then: int, correction: str) -> None:
    """"rotate left, uh, rotate right fifteen, correction, twenty" (round 8): the amount corrected on the way
    does not hide that the bare turn before it was taken back; at most the corrected turn runs."""
    prompt = "".join(f"rotate {s}{pause}" for s in starts) + f"rotate {side} {_WORDS[first]}{correction}{_WORDS[then]}"
    intent = translate_offline(prompt)
    assert all(s.movement == Movement.ROTATE for s in intent.steps), intent
    assert sum(s.angle_deg if s.angle_deg is not None else 90.0 for s in intent.steps) <= then + 1e-9, intent
    if intent.steps:
        assert [(s.direction, s.angle_deg) for s in intent.steps] == [(_SIDES[side], float(then))], intent


@pytest.mark.parametrize("prompt", [
    # the session-9 review: a first turn that asked something is no false start, its question stays
    "turn left a lot, turn right ninety, I mean forty five, then go forward two metres",
    "turn left quite a bit, uh, rotate right fifteen, correction, twenty",
    "turn left a fair bit, turn right 45, no wait, 30",
    "turn left a lot, turn right forty five",
    # a word between them the reading left unread may size or repeat the turn: ask
    "turn left, twice, turn right ninety, no, forty five, go forward two metres",
    "turn left, x, turn right ninety, I mean forty five",
    "turn left, twice, turn right forty five",
])
def test_a_turn_that_asked_is_not_taken_back(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert intent.steps == [] and intent.clarification, intent


@pytest.mark.parametrize("prompt", [
    # a word that puts the turns in order, known or not, in chat spelling too: both turns were meant
    "turn left, next, turn right ninety, I mean forty five",
    "turn left, later, turn right forty five",
    "turn left, plus, turn right forty five",
    "turn left, subsequently, turn right forty five",
    "turn left, n, turn right forty five",
    "turn left, &, turn right forty five",
])
def test_a_word_of_order_keeps_both_turns(prompt: str) -> None:
    turns = [(s.direction, s.angle_deg) for s in translate_offline(prompt).steps]
    assert turns[:2] == [(Direction.LEFT, None), (Direction.RIGHT, 45.0)]
