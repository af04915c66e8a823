"""Words of English varieties, settings and speech habits (langnav.language.offline.speech PIDGIN, PARTICLES,
REPORTED, the "right then," opener; idioms: "small" as an adverb, "give it a turn", drill "right face", the way
of the speaker's setting, vague "there"; corrections: "nah", praise clauses, a move after a turn). Each is a
class of speech; the prompts are our own paraphrases of each."""

from __future__ import annotations

import pytest

from langnav.language.offline import translate_offline

FT = 0.3048
Plan = list[tuple[str, str | None, float | None, float | None, str | None]]


def _plan(prompt: str) -> Plan:
    return [(s.movement.value, s.direction.value if s.direction else None, s.distance_m, s.angle_deg,
             s.amount.value if s.amount else None) for s in translate_offline(prompt).steps]


@pytest.mark.parametrize(("prompt", "expected"), [
    # Nigerian English and Pidgin
    ("go back small", [("move", "backward", None, None, "little")]),
    ("shift left small small", [("move", "left", None, None, "little")]),
    ("na right i say, turn right forty degrees", [("rotate", "right", None, 40.0, None)]),
    ("turn around make you see me", [("rotate", "around", None, 180.0, None)]),
    ("where u dey", [("query", None, None, None, None)]),
    # Singapore English particles
    ("turn around lah", [("rotate", "around", None, 180.0, None)]),
    ("go straight one metre lor", [("move", "forward", 1.0, None, None)]),
    # reported speech followed by the speaker's own instruction: one instruction
    ("my boss says go back, okay, go back two metres", [("move", "backward", 2.0, None, None)]),
    ("the viewers want you to turn right", [("rotate", "right", None, None, "default")]),
    # British / Irish "right then," / "right so," opening the utterance: no side
    ("right then, forward ten feet", [("move", "forward", 10 * FT, None, None)]),
    ("right so, back two metres", [("move", "backward", 2.0, None, None)]),
    # "nah", "nope" correct what was said before
    ("turn left, nah, right, thirty degrees", [("rotate", "right", None, 30.0, None)]),
    ("forward one metre, nope, two metres", [("move", "forward", 2.0, None, None)]),
    # praise of what was done opens the next request
    ("brilliant, now go forward one metre", [("move", "forward", 1.0, None, None)]),
    # "give it a turn"
    ("give it a little turn to the right", [("rotate", "right", None, None, "little")]),
    # drill orders: "right face" is a quarter turn; the move after it is its own instruction
    ("left face, forward five metres", [("rotate", "left", None, None, "default"), ("move", "forward", 5.0, None, None)]),
    ("turn left, forward two metres", [("rotate", "left", None, None, "default"), ("move", "forward", 2.0, None, None)]),
    # the way of the speaker's setting
    ("go down the aisle three metres", [("move", "forward", 3.0, None, None)]),
    # vague "there" between a way and an amount
    ("go back there two feet", [("move", "backward", 2 * FT, None, None)]),
    # informal words
    ("scooch forward a skosh", [("move", "forward", None, None, "little")]),
    ("drop back one metre", [("move", "backward", 1.0, None, None)]),
    ("10-4, turn right", [("rotate", "right", None, None, "default")]),
    # greetings, addresses and tags at the edges of an instruction; how fast it is said to go
    ("yo, back up one metre", [("move", "backward", 1.0, None, None)]),
    ("turn right innit", [("rotate", "right", None, None, "default")]),
    ("go forward a little eh", [("move", "forward", None, None, "little")]),
    ("turn around real quick, dude", [("rotate", "around", None, 180.0, None)]),
    # a first syllable dropped in writing, as said
    ("spin 'round", [("rotate", "around", None, 180.0, None)]),
    ("'bout face", [("rotate", "around", None, 180.0, None)]),
])
def test_words_of_varieties_and_settings(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "go up the row",                 # how far up it is not said: ask
    "go up two rows",                # a row is no unit the robot knows
    "right then, turn",              # the opener is no side: which way?
    "turn, forward",                 # nothing says how far or which way
    "turn left blah",                # an unknown word next to a default turn: never a guess
    "go to the break room",          # a room named by what it is for: the map cannot know it (no stop)
    "head into the rest area",
])
def test_what_they_leave_unsaid_is_asked(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert intent.steps == [] and intent.clarification


@pytest.mark.parametrize(("prompt", "expected"), [
    # "small" is an adverb only where it ends the instruction: "the small room" is a place
    ("go to the small room", "navigate"),
    # "there" before a place is no filler
    ("go over there to the door", "navigate"),
    # "there" after the place it points at is no second place
    ("go to the second door on the right there", "navigate"),
])
def test_the_words_keep_their_meaning_elsewhere(prompt: str, expected: str) -> None:
    steps = translate_offline(prompt).steps
    assert [s.movement.value for s in steps] == [expected]


@pytest.mark.parametrize(("prompt", "expected"), [
    # a note about a place, before "fine" / "noted": no trip along it
    ("water stains all along this wall, noted. go forward one metre", [("move", "forward", 1.0, None, None)]),
    ("chipped paint by the door, fine. turn left", [("rotate", "left", None, None, "default")]),
    # a shouted word before an instruction is a warning to people around
    ("door! back up one metre", [("move", "backward", 1.0, None, None)]),
    # a count-in said with no pauses
    ("one two three four, go forward two metres", [("move", "forward", 2.0, None, None)]),
    # a stammered word
    ("t-t-turn left thirty degrees", [("rotate", "left", None, 30.0, None)]),
    # "not X, Y": Y
    ("not left, right, twenty degrees", [("rotate", "right", None, 20.0, None)]),
    # the copula dropped before "now"
    ("where you right now", [("query", None, None, None, None)]),
])
def test_talk_around_the_request(prompt: str, expected: Plan) -> None:
    assert _plan(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "corner!",                                 # a warning, or the place? ask
    # a shout with a way in it is kept: a way other than the motion's may be the way meant, ask (one that agrees,
    # "behind! back up two feet", says the way again: test_offline_s11)
    "ahead! okay robot, back up two feet",
    "along this wall, fine. go forward",       # no thing before the place: it may be an instruction; and how far?
])
def test_shouts_and_notes_that_may_be_meant_are_asked(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert intent.steps == [] and intent.clarification
