"""Session 9 readings of spoken English (offline translator, no map): each a rule of how people speak,
asserted on the exact steps, with the dangerous neighbours that must still ask."""

from __future__ import annotations

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from langnav.language.intent import Direction, Movement
from langnav.language.offline.translator import translate_offline


def _steps(prompt: str) -> list[tuple[str, str | None, float | None]]:
    """(movement, direction, amount in m or degrees) of each step."""
    out = []
    for s in translate_offline(prompt).steps:
        amount = s.distance_m if s.movement == Movement.MOVE else s.angle_deg
        out.append((s.movement.value, s.direction.value if s.direction else None,
                    None if amount is None else round(amount, 4)))
    return out


def _asks(prompt: str) -> bool:
    intent = translate_offline(prompt)
    return intent.steps == [] and bool(intent.clarification)


# ---------------------------------------------------------------- a turn's side is never taken back by a sideless amount
@pytest.mark.parametrize(("prompt", "expected"), [
    ("turn right, em, thirty degrees", [("rotate", "right", 30.0)]),       # "em": the Irish / Scottish "um"
    ("turn left, erm, forty five degrees", [("rotate", "left", 45.0)]),
    ("turn right, easy, about thirty degrees", [("rotate", "right", 30.0)]),  # a word between, not a side
])
def test_the_side_said_before_a_pause_holds(prompt: str, expected: list[tuple[str, str | None, float | None]]) -> None:
    assert _steps(prompt) == expected


_PAUSE_WORDS = st.sampled_from(["em", "um", "easy", "blah", "like", "so", "okay", "gently", "steady"])


@settings(max_examples=60, deadline=None, derandomize=True)
@given(side=st.sampled_from(["left", "right"]), pause=_PAUSE_WORDS,
       angle=st.sampled_from(["thirty", "forty five", "ninety", "fifteen", "sixty"]))
def test_a_turn_never_goes_to_the_side_not_said(side: str, pause: str, angle: str) -> None:
    """"turn SIDE, WORD, N degrees": whatever the word between, the robot turns to SIDE or asks, never the other."""
    intent = translate_offline(f"turn {side}, {pause}, {angle} degrees")
    assert all(s.direction == Direction(side) for s in intent.steps if s.movement == Movement.ROTATE)


def test_em_stays_them_with_its_apostrophe() -> None:
    assert _steps("back 'em up two metres") == _steps("back them up two metres")


# ---------------------------------------------------------------- "right," opening an instruction with its own verb
@pytest.mark.parametrize(("prompt", "expected"), [
    ("right, back up a metre would ya", [("move", "backward", 1.0)]),
    ("right, back off two metres", [("move", "backward", 2.0)]),
    ("right, stop there", [("stop", None, None)]),
])
def test_right_opening_an_instruction_is_no_turn(prompt: str, expected: list[tuple[str, str | None, float | None]]) -> None:
    assert _steps(prompt) == expected


def test_right_before_a_way_is_still_a_turn() -> None:
    assert _steps("right, ninety degrees") == [("rotate", "right", 90.0)]


# ---------------------------------------------------------------- a bearing in degrees: two conventions, so ask
@pytest.mark.parametrize("prompt", [
    "turn to heading one eight zero",
    "turn left heading two seven zero, then go forward two metres",
    "come to a bearing of 90",
    "steer course 045",
])
def test_a_bearing_in_degrees_asks(prompt: str) -> None:
    assert _asks(prompt)


@pytest.mark.parametrize(("prompt", "expected"), [
    ("what's your heading", [("query", None, None)]),
    ("face south", [("rotate", None, None)]),
    ("keep heading 2 metres forward", [("move", "forward", 2.0)]),
])
def test_heading_without_a_bearing_is_read_as_before(prompt: str,
                                                     expected: list[tuple[str, str | None, float | None]]) -> None:
    assert _steps(prompt) == expected


# ---------------------------------------------------------------- particles of another language
@pytest.mark.parametrize(("prompt", "expected"), [
    ("turn around po", [("rotate", "around", 180.0)]),
    ("turn around yalla", [("rotate", "around", 180.0)]),
    ("turn around sige po", [("rotate", "around", 180.0)]),
    ("go forward, ano, one and a half meters", [("move", "forward", 1.5)]),  # a filler before the amount
    ("go forward, eto, two metres", [("move", "forward", 2.0)]),
    ("forward a little bit more po", [("move", "forward", None)]),
    ("go forward two metres yalla", [("move", "forward", 2.0)]),
    ("stop po", [("stop", None, None)]),
])
def test_a_particle_of_another_language_changes_nothing(
        prompt: str, expected: list[tuple[str, str | None, float | None]]) -> None:
    assert _steps(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "go to the konti",                    # where a place goes: a name the map cannot know
    "go zorp",
    "go forward three zorp",              # where the unit goes
    "turn left, no, derecha",             # the word a correction puts right
    "basta",                              # said alone: nothing to attach it to
    "turn left ri",                       # two letters of "right": a word cut short
    "go forward zwei metres",             # where the number goes
    "go back zorp",                       # no amount said: how far?
    "turn right cuarenta grados",         # where the amount goes: maybe the amount, in another language
    "go forward three meters then turn right po",
    "get zorp",                           # right after a verb: its place or its object
    "come zorp",
    # an unknown word before the amount that is no known filler may be the way or the amount in the speaker's
    # other language (the session-9 review): ask ("konti", Tagalog "a little", is known since session 11: "go back
    # konti, a little" is a little, test_offline_s11)
    "go back zorp, a little",
    "ay sorry, turn left, no, right pala, thirty degrees",
    "move, atras, two metres",
    "go forward, atras, two metres",
    "go left, derecha, two metres",
    "turn left, migi, forty five",
    "back up, adelante, two metres",
])
def test_a_word_that_may_say_where_or_how_far_still_asks(prompt: str) -> None:
    assert _asks(prompt)


def test_english_words_are_no_particles() -> None:
    from langnav.language.offline.particles import is_particle_word
    for word in ("abeam", "athwart", "aslant", "upwind", "downfield", "widdershins", "diagonally", "easy", "lang"):
        assert not is_particle_word(word), word
    for word in ("po", "konti", "yalla", "pala", "ano", "eto", "sige", "muna", "tamam"):
        assert is_particle_word(word), word


def test_a_named_place_is_no_particle() -> None:
    from langnav.language.offline.particles import is_particle_word
    assert not is_particle_word("konti", known_names=("konti",))


_COMMANDS = st.sampled_from(["turn around", "turn left ninety degrees", "go forward two metres", "stop",
                             "back up one metre", "face north", "move left half a metre", "go back a little"])
#: Made-up words of two to six letters: consonant-vowel pairs ("pi" is left out: it is the number, 180 degrees
#: as radians); the test keeps those that are no English word and no slip of a word of way or amount.
_MADE_UP = st.lists(st.sampled_from(["ka", "po", "mu", "zi", "yo", "ku", "zo", "gu", "ji"]), min_size=1,
                    max_size=3).map("".join)


@settings(max_examples=80, deadline=None, derandomize=True)
@given(command=_COMMANDS, word=_MADE_UP)
def test_a_made_up_word_after_a_whole_command_changes_nothing(command: str, word: str) -> None:
    from langnav.language.offline.particles import is_particle_word
    assume(is_particle_word(word))
    assert _steps(f"{command} {word}") == _steps(command)


@settings(max_examples=80, deadline=None, derandomize=True)
@given(word=_MADE_UP, slot=st.sampled_from(["go to the {w}", "go forward three {w}", "turn left, no, {w}",
                                           "go through the {w}", "turn left ninety, sorry, {w}"]))
def test_a_made_up_word_where_a_place_unit_or_correction_goes_never_moves(word: str, slot: str) -> None:
    assert translate_offline(slot.format(w=word)).steps == []


# ---------------------------------------------------------------- words of English and of radio procedure
@pytest.mark.parametrize(("prompt", "expected"), [
    # "there" ending a turn on the spot or a move with its amount names no place
    ("turn around there", [("rotate", "around", 180.0)]),
    ("go forward, em, four feet there", [("move", "forward", 1.2192)]),
    ("back up a bit there", [("move", "backward", None)]),
    # "straight" before the way a backward verb says is "directly"
    ("withdraw fifteen metres, straight back", [("move", "backward", 15.0)]),
    # "backpedal": to step backwards
    ("back pedal five yards", [("move", "backward", 4.572)]),
    ("backpedal two metres", [("move", "backward", 2.0)]),
    # "whereabouts" asks where; radio's "say" asks to be told
    ("whereabouts are you to now", [("query", None, None)]),
    ("say position", [("query", None, None)]),
    # "go along" with no object is onward
    ("now go along five feet and turn left", [("move", "forward", 1.524), ("rotate", "left", None)]),
    # the radiotelephony digits, where a number goes
    ("go forward fife metres", [("move", "forward", 5.0)]),
    ("turn right niner zero degrees", [("rotate", "right", 90.0)]),
    ("go back tree metres", [("move", "backward", 3.0)]),
])
def test_english_and_radio_words(prompt: str, expected: list[tuple[str, str | None, float | None]]) -> None:
    assert _steps(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "go there",                           # "there" as the place: which?
    "go back there",                      # back to a place said before: none was
    "go forward two metres over there",   # "over there" points at a place
    "go to the tree",                     # a tree is a place the map cannot know, not three
    "move along",                         # onward, but how far?
    "inch it forward",                    # the driver's "it"; how far is not said
])
def test_neighbours_still_ask(prompt: str) -> None:
    assert _asks(prompt)


@settings(max_examples=60, deadline=None, derandomize=True)
@given(command=st.sampled_from(["turn right", "turn left", "go forward", "back up", "move left"]), word=_MADE_UP)
def test_a_made_up_word_where_the_amount_goes_never_moves(command: str, word: str) -> None:
    """"turn right cuarenta": a word after a move or turn with no amount may be the amount in another language."""
    assert translate_offline(f"{command} {word}").steps == []

