"""Readings added in session 7 (issue 9) from blind round 6's misses, each as the class of speech it
stands for: a word not understood where the way or the amount of a move goes asks (never the default
way); amounts said only to be large ask; a boat's words for the ways; speech addressed to someone else or
commenting, between or around the instructions to the robot."""

from __future__ import annotations

import re

import pytest
from hypothesis import assume, example, given
from hypothesis import strategies as st
from offline_plans import Plan
from offline_plans import asks as _asks
from offline_plans import plan as _plan

from langnav.language.intent import Movement
from langnav.language.offline import lexicon as lx
from langnav.language.offline.idioms import plain_idioms
from langnav.language.offline.normalize import normalize
from langnav.language.offline.numbers import canonical_numbers
from langnav.language.offline.patterns import FILLER_RE
from langnav.language.offline.speech import HESITATIONS, plain_speech
from langnav.language.offline.translator import translate_offline
from langnav.language.offline.vocabulary import VOCABULARY

FT = 0.3048
_MOTIONS = (Movement.MOVE, Movement.ROTATE)
#: Short consonant runs are sounds to the speech clean-up ("ff", "tsk"), not words.
_SOUND_RE = re.compile(r"^[bcdfghjklmnpqrstvwxz]{2,4}$")


def _unknown(word: str, prompt: str) -> bool:
    """A word the reading does not know and would not repair into one it knows (in ``prompt``: "press
    forward" is "move forward")."""
    said = normalize(plain_idioms(plain_speech(canonical_numbers(prompt)))).split()
    return (word not in VOCABULARY and word not in lx.STOPWORDS and word not in HESITATIONS
            and _SOUND_RE.match(word) is None and FILLER_RE.search(word) is None and word in said)


def _moves(prompt: str) -> bool:
    return any(s.movement in _MOTIONS for s in translate_offline(prompt).steps)


# ------------------------------------------------------------------ the way's and the amount's slots
@pytest.mark.parametrize(("prompt", "expected"), [
    ("go astern one metre", [("move", "backward", 1.0, None)]),
    ("ahead one metre", [("move", "forward", 1.0, None)]),
    ("go ahead two metres please", [("move", "forward", 2.0, None)]),
    ("move for word too feet", [("move", "forward", round(2 * FT, 4), None)]),
    ("Move Ford 3 meters.", [("move", "forward", 3.0, None)]),
    ("turn ninety degrees to the right, and then start moving ten feet",
     [("rotate", "right", None, 90.0), ("move", "forward", round(10 * FT, 4), None)]),
    ("unit one, advance two five feet, over", [("move", "forward", round(25 * FT, 4), None)]),
    # the side put right replaces the word said where the side goes
    ("Turn lest 30 degrees. No. Left. Turn left 30 degrees.", [("rotate", "left", None, 30.0)]),
    ("turn lest 30 degrees, no, left", [("rotate", "left", None, 30.0)]),
])
def test_ways_of_general_english_and_of_the_recogniser(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "go aft one metre", "go abaft one metre", "move sternwards two feet", "move forward zorbl two metres",
    "go forward zorbl metres", "turn left zorbl degrees", "go forward zorbl",
])
def test_a_word_not_understood_in_the_way_or_amount_slot_asks(prompt: str) -> None:
    assert _asks(prompt)


@given(word=st.text(alphabet="abcdefghijklmnopqrstuvwxyz", min_size=3, max_size=9), n=st.integers(1, 9),
       template=st.sampled_from(["go {w} {n} metres", "move {w} {n} feet", "drive {w} {n} metres",
                                 "roll {w} {n} feet", "head {w} {n} metres please"]))
@example(word="astern", n=1, template="go {w} {n} metres")
@example(word="zorbl", n=2, template="move {w} {n} feet")
def test_an_unknown_word_where_the_way_goes_never_moves(word: str, n: int, template: str) -> None:
    """The way of a move is never assumed (forward) around a word not understood: that word may be the
    way, and the assumed one its opposite."""
    prompt = template.format(w=word, n=n)
    assume(_unknown(word, prompt))
    assert not _moves(prompt)


@given(word=st.text(alphabet="abcdefghijklmnopqrstuvwxyz", min_size=3, max_size=9), n=st.integers(2, 9),
       template=st.sampled_from(["move forward {w} {n} metres", "go back {w} {n} feet",
                                 "turn left {w} {n}0 degrees", "move forward {w} metres", "turn right {w} degrees",
                                 "go forward {w}", "back up {w}"]))
@example(word="zorbl", n=2, template="move forward {w} {n} metres")
def test_an_unknown_word_where_the_amount_goes_never_moves(word: str, n: int, template: str) -> None:
    prompt = template.format(w=word, n=n)
    assume(_unknown(word, prompt))
    assert not _moves(prompt)


# ------------------------------------------------------------------ large amounts without a number
@pytest.mark.parametrize("prompt", [
    "go forward a fair bit", "go forward a fair bit more", "move forward quite a way", "back up a good bit",
    "go forward a lot", "turn left a fair bit", "rotate quite a bit to the right", "go forward a decent amount",
    "give it a fair whack forward",
])
def test_an_amount_said_only_to_be_large_asks(prompt: str) -> None:
    assert _asks(prompt)


@pytest.mark.parametrize(("prompt", "movement"), [
    ("go forward a wee bit more", "move"), ("go a bit further", "move"),
])
def test_small_amounts_stay_a_little(prompt: str, movement: str) -> None:
    steps = translate_offline(prompt).steps
    assert [(s.movement.value, s.amount.value if s.amount else None) for s in steps] == [(movement, "little")]
