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
from langnav.language.offline.sidetalk import without_side_talk
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


def _moves_without_reading(prompt: str, word: str) -> bool:
    """Whether ``prompt`` runs a move or turn while ``word`` was left unread (a word the reading reads, as
    "twice" is a count, may move)."""
    intent = translate_offline(prompt)
    unread = " ".join(intent.unread).lower().split()
    return any(s.movement in _MOTIONS for s in intent.steps) and word in unread


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
@example(word="twice", n=1, template="go {w} {n} metres")  # read: a count (found by hypothesis)
def test_an_unknown_word_where_the_way_goes_never_moves(word: str, n: int, template: str) -> None:
    """The way of a move is never assumed (forward) around a word not understood: that word may be the
    way, and the assumed one its opposite."""
    prompt = template.format(w=word, n=n)
    assume(_unknown(word, prompt))
    assert not _moves_without_reading(prompt, word)


@given(word=st.text(alphabet="abcdefghijklmnopqrstuvwxyz", min_size=3, max_size=9), n=st.integers(2, 9),
       template=st.sampled_from(["move forward {w} {n} metres", "go back {w} {n} feet",
                                 "turn left {w} {n}0 degrees", "move forward {w} metres", "turn right {w} degrees",
                                 "go forward {w}", "back up {w}"]))
@example(word="zorbl", n=2, template="move forward {w} {n} metres")
def test_an_unknown_word_where_the_amount_goes_never_moves(word: str, n: int, template: str) -> None:
    prompt = template.format(w=word, n=n)
    assume(_unknown(word, prompt))
    assert not _moves_without_reading(prompt, word)


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


# ------------------------------------------------------------------ speech not addressed to the robot
@pytest.mark.parametrize(("prompt", "expected"), [
    ("sorry, one second, bed twelve is calling, okay, back up two feet, quietly",
     [("move", "backward", round(2 * FT, 4), None)]),
    ("water line about eighteen inches on this wall, okay, go forward three feet",
     [("move", "forward", round(3 * FT, 4), None)]),
    ("robot turn left, no, jack, sit down, turn left forty five degrees", [("rotate", "left", None, 45.0)]),
    ("robot, back up eight metres, no, harper, that's mine", [("move", "backward", 8.0, None)]),
    ("and five, six, seven, eight, step forward two feet", [("move", "forward", round(2 * FT, 4), None)]),
    ("fire table six! robot, forward three feet", [("move", "forward", round(3 * FT, 4), None)]),
    ("all day two salmon, robot, turn around", [("rotate", "around", None, 180.0)]),
    ("note, drywall is soft here. turn around please", [("rotate", "around", None, 180.0)]),
    ("mommy's talking to the robot, okay, turn right ninety", [("rotate", "right", None, 90.0)]),
])
def test_talk_to_someone_else_or_notes_are_no_instruction(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


@pytest.mark.parametrize(("prompt", "kind"), [
    ("okay robot, go to the last door on the right, no, sam, leave it", "door"),
    ("carpet's stained all along here, noted. okay, go to the third door on your left", "door"),
    ("okay robot, go towards the unexplored part in front of you, sorry, she's asking about the robot",
     "unexplored_area"),
    ("okay robot, go to the first door on your left, ava, hands off", "door"),
])
def test_talk_to_someone_else_after_a_place_leaves_the_trip(prompt: str, kind: str) -> None:
    steps = translate_offline(prompt).steps
    assert [(s.movement, s.target.kind.value if s.target else None) for s in steps] == [(Movement.NAVIGATE, kind)]


@pytest.mark.parametrize(("prompt", "expected"), [
    # a correction, a hesitation, a question or a stop after a pause is never taken for talk to someone else
    ("forward five metres, oops, I meant feet", [("move", "forward", round(5 * FT, 4), None)]),
    ("face north. uh, actually, face south", [("rotate", None, None, None)]),
    ("turn right sixty, um, no, ninety degrees", [("rotate", "right", None, 90.0)]),
    ("move forward, two metres, okay", [("move", "forward", 2.0, None)]),
    ("turn left, it's about thirty degrees", [("rotate", "left", None, 30.0)]),
])
def test_corrections_and_amounts_after_a_pause_are_kept(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "turn left, zed, ninety degrees", "zed, go left two metres", "lily, stop it. robot, go back one metre",
    "there's a door on your left, go through it", "move forward, um, two metres", "rover, say your position, over",
])
def test_talk_that_may_be_meant_for_the_robot_is_kept(prompt: str) -> None:
    """A name followed by a way, an amount, a place, a stop or a question: a listener cannot tell the name
    from a word of the instruction, so nothing is taken out (the reading asks about what it cannot read)."""
    assert without_side_talk(prompt) == prompt


@given(name=st.sampled_from(["jack", "sam", "ava", "emma", "harper", "mia", "noah"]),
       said=st.sampled_from(["sit down", "leave it", "hands off", "not now", "shoes on", "that's mine"]),
       metres=st.integers(1, 9))
@example(name="jack", said="sit down", metres=2)
def test_talk_to_a_named_person_never_adds_or_removes_a_motion(name: str, said: str, metres: int) -> None:
    for prompt in (f"go forward {metres} metres, {name}, {said}", f"{name}, {said}, okay, go forward {metres} metres"):
        assert _plan(prompt) == [("move", "forward", float(metres), None)]


# ------------------------------------------------------------------ varieties of English and learners
@pytest.mark.parametrize(("prompt", "expected"), [
    # a boat's words
    ("hard to port, ninety degrees", [("rotate", "left", None, 90.0)]),
    ("ahead one metre, then starboard ninety, then ahead three metres",
     [("move", "forward", 1.0, None), ("rotate", "right", None, 90.0), ("move", "forward", 3.0, None)]),
    ("come round to face north", [("rotate", None, None, None)]),
    ("turn left, i mean port, forty, belay that, sixty degrees", [("rotate", "left", None, 60.0)]),
    # Scots as a recogniser writes it
    ("aye, just turn yerself around", [("rotate", "around", None, 180.0)]),
    ("go back oot the way, one metre back", [("move", "backward", 1.0, None)]),
    # French-English
    ("turn on the right of forty-five degrees", [("rotate", "right", None, 45.0)]),
    ("turn on the left of one hundred thirty-five degrees and advance of four meters",
     [("rotate", "left", None, 135.0), ("move", "forward", 4.0, None)]),
    ("move forward of eighty centimeters, and after turn on the right",
     [("move", "forward", 0.8, None), ("rotate", "right", None, None)]),
    # learners and trades
    ("take left", [("rotate", "left", None, None)]),
    ("back out eighteen inches", [("move", "backward", round(18 * 0.0254, 4), None)]),
    ("do a slow three sixty", [("rotate", "left", None, 360.0)]),
    ("an eighth of a turn to the left", [("rotate", "left", None, 45.0)]),
    ("a third of a turn to the right", [("rotate", "right", None, 120.0)]),
    # a unit put right after "wait"
    ("go forward like five feet, wait, metres, five metres", [("move", "forward", 5.0, None)]),
    # purposes and wishes to see are no places to go to
    ("turn left ninety degrees, i want to see the hallway", [("rotate", "left", None, 90.0)]),
    ("please turn around so the group can see you", [("rotate", "around", None, 180.0)]),
])
def test_words_of_english_varieties_and_learners(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


@pytest.mark.parametrize("prompt", ["turn of thirty degrees", "can ye tell me where ye are"])
def test_varieties_keep_asking_what_is_not_said(prompt: str) -> None:
    """"Turn of thirty degrees" still has no side (asks); "ye" is "you" (a question the robot answers)."""
    intent = translate_offline(prompt)
    assert (intent.steps == []) == (prompt.startswith("turn"))
    if intent.steps:
        assert [s.movement for s in intent.steps] == [Movement.QUERY]


def test_take_the_left_door_is_still_a_place() -> None:
    steps = translate_offline("take the left door").steps
    assert [s.movement for s in steps] == [Movement.NAVIGATE]


@pytest.mark.parametrize(("prompt", "side"), [
    ("make your way through the door on your starboard side", "right"),
    ("make your way to the last door on your port side", "left"),
    ("go to the starboard door", "right"),
])
def test_a_boats_sides_name_the_side_of_a_place(prompt: str, side: str) -> None:
    steps = translate_offline(prompt).steps
    assert [s.target.side.value if s.target and s.target.side else None for s in steps] == [side]


@pytest.mark.parametrize(("prompt", "details"), [
    ("Go to the door of this room and after through it.", ["to", "through"]),
    ("sand from the sandpit everywhere in here. okay, go to the middle of this room", ["middle"]),
    ("aye, head tae the unexplored bit o' this room", ["towards"]),
])
def test_learners_and_notes_around_places(prompt: str, details: list[str]) -> None:
    steps = translate_offline(prompt).steps
    assert [s.detail.value if s.detail else None for s in steps] == details


@pytest.mark.parametrize(("prompt", "asks"), [
    ("Go to the room of the babies.", True), ("go to the door of the kitchen", True),
    ("go to the room for the staff", True), ("Go to the entrance of the building.", False),
    ("go to the corner of the room", False), ("go to the end of the hallway", False),
])
def test_a_place_named_by_whom_it_belongs_to_asks(prompt: str, asks: bool) -> None:
    """"The room of the babies": the map holds no names of who uses a room, so which one is meant is a guess."""
    assert _asks(prompt) == asks
