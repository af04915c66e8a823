"""Session 10 readings of spoken English (offline translator, no map): each a rule about speech in general,
asserted on the exact steps, with the neighbours that must still ask."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from offline_plans import Plan, asks, plan

from langnav.language.intent import Movement
from langnav.language.offline.ask import SPATIAL_WORDS
from langnav.language.offline.lexicon import FOREIGN_WAY_WORDS
from langnav.language.offline.particles import is_particle_word
from langnav.language.offline.translator import translate_offline


# ---------------------------------------------------------------- a word of another language between two motions
@pytest.mark.parametrize("prompt", [
    "turn right ninety, zzyzx, turn left ninety",       # an unknown word: the left turn may replace the right one
    "turn right forty five, hup, turn right fifteen",
    "go forward two metres, blorp, go back one metre",
    "turn left, nahin ji, turn right thirty degrees",   # a "no" with a word after it is no "no" alone
])
def test_an_unknown_foreign_word_between_two_motions_asks(prompt: str) -> None:
    assert asks(prompt)


@pytest.mark.parametrize(("prompt", "expected"), [
    # an English word the reading does not know takes nothing back (the English corrections are known)
    ("slew right, easy, about thirty degrees", [("rotate", "right", None, 30.0)]),
    # before the first motion or after the last, an unknown word takes nothing back
    ("unit one, turn left ninety degrees", [("rotate", "left", None, 90.0)]),
    ("turn around po", [("rotate", "around", None, 180.0)]),
    # "yes" in other languages is assent, never a correction
    ("turn to the left, ja, ninety degrees", [("rotate", "left", None, 90.0)]),
    ("go forward two metres, oui, turn left", [("move", "forward", 2.0, None), ("rotate", "left", None, None)]),
])
def test_words_that_take_nothing_back(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


@settings(max_examples=60, deadline=None, derandomize=True)
@given(first=st.sampled_from(["turn right ninety", "go forward two metres", "turn left forty five"]),
       word=st.sampled_from(["nein", "nie", "hayir", "iie", "khong", "zzyzx", "blorp", "aniyo"]),
       second=st.sampled_from(["turn left ninety", "go back one metre", "turn right fifteen degrees"]))
def test_two_motions_around_an_unknown_foreign_word_never_both_run(first: str, word: str, second: str) -> None:
    """Whatever the unknown word between two motions, both are never run: it may have taken the first back."""
    intent = translate_offline(f"{first}, {word}, {second}")
    assert len([s for s in intent.steps if s.movement in (Movement.MOVE, Movement.ROTATE)]) < 2


# ---------------------------------------------------------------- the ways said in other languages
@pytest.mark.parametrize("prompt", [
    "turn right, izquierda izquierda, ninety degrees",  # Spanish "left" where the side goes
    "turn links, ninety degrees",                       # Dutch / German "left" (also an English word)
    "turn right, izquierda",                            # a correction after the instruction, maybe
    "rechtdoor three meter",                            # Dutch "straight on"
    "go forward two metres, links",
])
def test_a_way_said_in_another_language_asks(prompt: str) -> None:
    assert asks(prompt)


def test_foreign_way_words_are_words_of_where_and_never_particles() -> None:
    assert FOREIGN_WAY_WORDS <= SPATIAL_WORDS
    assert not any(is_particle_word(w) for w in FOREIGN_WAY_WORDS)
    assert not FOREIGN_WAY_WORDS & {"you", "no", "la", "para", "a", "to"}  # read as English


@pytest.mark.parametrize(("prompt", "expected"), [
    ("nee nee, stop", [("stop", None, None, None)]),   # only a stop: nothing unread can make it go farther
    ("dur, stop!", [("stop", None, None, None)]),
])
def test_a_stop_is_never_held_back_by_a_word_left_unread(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


# ---------------------------------------------------------------- radio procedure: "disregard", "belay"
@pytest.mark.parametrize(("prompt", "expected"), [
    ("turn right forty five, disregard, turn right fifteen degrees", [("rotate", "right", None, 15.0)]),
    ("turn right forty five degrees disregard turn right fifteen degrees", [("rotate", "right", None, 15.0)]),
    ("go forward two metres, belay that, go back one metre", [("move", "backward", 1.0, None)]),
    ("go forward three metres, disregard my last, go forward one metre", [("move", "forward", 1.0, None)]),
])
def test_disregard_and_belay_take_the_last_instruction_back(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


def test_disregard_alone_runs_nothing() -> None:
    intent = translate_offline("disregard")
    assert intent.steps == [] and intent.clarification


# ---------------------------------------------------------------- a request or question relayed by someone else
@pytest.mark.parametrize(("prompt", "expected"), [
    ("he'd like you to turn right, about forty five degrees", [("rotate", "right", None, 45.0)]),
    ("she would like you to go forward two metres", [("move", "forward", 2.0, None)]),
    ("she's signing turn left", [("rotate", "left", None, None)]),
    ("he is asking you to back up one metre", [("move", "backward", 1.0, None)]),
    ("she asks where you are right now", [("query", None, None, None)]),
    ("he wants to know where you are", [("query", None, None, None)]),
])
def test_a_relayed_request_is_the_request(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


@pytest.mark.parametrize("prompt", ["nobody said turn left", "he said turn left?"])
def test_a_relay_that_asks_nothing_of_the_robot_is_not_read(prompt: str) -> None:
    assert plan(prompt) != [("rotate", "left", None, None)]


def test_where_you_are_right_now_is_no_affirmation() -> None:
    assert plan("tell me where you are right now") == [("query", None, None, None)]
    assert plan("that's right now turn left") == [("rotate", "left", None, None)]  # the affirmation still is one


# ---------------------------------------------------------------- fillers and focus words before an amount
@pytest.mark.parametrize(("prompt", "expected"), [
    ("go back yani two meter", [("move", "backward", 2.0, None)]),      # Arabic / Turkish "I mean"
    ("turn left ano ninety degrees", [("rotate", "left", None, 90.0)]),  # Tagalog / Japanese "um"
    ("go even one meter back", [("move", "backward", 1.0, None)]),      # "even" = "just"
])
def test_a_filler_or_focus_word_before_the_amount_changes_nothing(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


def test_este_is_east_and_no_filler() -> None:
    """Spanish and Portuguese "este" is also "east": never dropped as a filler."""
    assert asks("go forward, este, two meters") or plan("go forward, este, two meters") != [
        ("move", "forward", 2.0, None)]


# ---------------------------------------------------------------- radio "twenty", apologies, consent
@pytest.mark.parametrize("prompt", ["unit one, what's your twenty", "what is your 20", "what's your 10-20"])
def test_whats_your_twenty_asks_the_position(prompt: str) -> None:
    assert plan(prompt) == [("query", None, None, None)]


def test_my_error_corrects() -> None:
    assert plan("turn left, my error, turn right") == [("rotate", "right", None, None)]


@pytest.mark.parametrize(("prompt", "expected"), [
    ("is it safe to turn right ninety degrees? okay, please do", [("rotate", "right", None, 90.0)]),
    ("is it okay to go forward two metres? yes, go ahead", [("move", "forward", 2.0, None)]),
])
def test_consent_after_a_may_i_question_asks_for_the_instruction(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


def test_a_may_i_question_alone_runs_nothing() -> None:
    assert asks("is it safe to turn right ninety degrees?")


def test_the_sideless_turn_asked_about_is_not_described_with_a_side() -> None:
    message = translate_offline("turn links, ninety degrees").clarification or ""
    assert "turn 90 degrees (which way?)" in message and "turn left" not in message


# ---------------------------------------------------------------- "no" in another language corrects as "no" does
@pytest.mark.parametrize(("prompt", "expected"), [
    ("turn right ninety, nein, turn left ninety", [("rotate", "left", None, 90.0)]),
    ("turn left forty, hayır, fifty degree", [("rotate", "left", None, 50.0)]),      # Turkish, dotless i kept
    ("turn left, nahi nahi, right side forty five", [("rotate", "right", None, 45.0)]),  # Hindi, said twice
    ("go forward two metres, hayir, go back one metre", [("move", "backward", 1.0, None)]),
])
def test_no_in_another_language_corrects(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


# ---------------------------------------------------------------- a way said in both languages
@pytest.mark.parametrize(("prompt", "expected"), [
    ("peeche, back side, thirty centimetre only", [("move", "backward", 0.3, None)]),  # Hindi "back"
    ("turn left, izquierda, ninety degrees", [("rotate", "left", None, 90.0)]),
    ("derecha, turn right forty five degrees", [("rotate", "right", None, 45.0)]),
])
def test_a_way_said_in_both_languages_is_read_once(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "turn right, izquierda, ninety degrees",  # the other way: it may be the one meant
    "turn links, ninety degrees",             # no side said in English: the placeholder side agrees with nothing
    "peeche, go forward two metres",
])
def test_a_way_in_another_language_that_disagrees_asks(prompt: str) -> None:
    assert asks(prompt)


# ---------------------------------------------------------------- the recogniser's spellings
@pytest.mark.parametrize(("prompt", "expected"), [
    ("turn write nine tee degrees", [("rotate", "right", None, 90.0)]),     # a number of tens split in two
    ("turn left for tee five degrees", [("rotate", "left", None, 45.0)]),
    ("rotate ninety deg c w", [("rotate", "right", None, 90.0)]),           # letters said one by one
    ("rotate thirty degrees c c w", [("rotate", "left", None, 30.0)]),
    ("move, atrás, two metres", None),                                       # accents dropped: "atras" asks
    ("where even are you", [("query", None, None, None)]),
    ("turn to your right hand side, ninety", [("rotate", "right", None, 90.0)]),
    ("move to your left hand side one metre", [("move", "left", 1.0, None)]),
])
def test_spellings_and_sides_as_said(prompt: str, expected: Plan | None) -> None:
    if expected is None:
        assert asks(prompt)
    else:
        assert plan(prompt) == expected


def test_plain_letters_drops_accents_only() -> None:
    from langnav.language.offline.speech import plain_letters
    assert plain_letters("atrás yavaş hayır chút xíu łódź") == "atras yavas hayir chut xiu lodz"
    assert plain_letters("go 1½ m, turn 45°") == "go 1½ m, turn 45°"


# ---------------------------------------------------------------- English ways of saying "I said it wrong"
@pytest.mark.parametrize(("prompt", "expected"), [
    ("turn left ninety, wrong, turn right ninety", [("rotate", "right", None, 90.0)]),
    ("turn left ninety, strike that, turn right ninety", [("rotate", "right", None, 90.0)]),
    ("turn left ninety, scrap that, turn right ninety", [("rotate", "right", None, 90.0)]),
    ("turn left ninety, i misspoke, turn right ninety", [("rotate", "right", None, 90.0)]),
    ("turn left ninety, on second thought, turn right ninety", [("rotate", "right", None, 90.0)]),
    ("turn left ninety, or actually turn right ninety", [("rotate", "right", None, 90.0)]),
    ("go forward two metres, delete that, go back one metre", [("move", "backward", 1.0, None)]),
    ("go forward two metres, turn left, start over, turn right", [("rotate", "right", None, None)]),
])
def test_english_corrections_take_the_instruction_back(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "turn left ninety, hmm not quite, turn right ninety",  # English words the reading does not know between two
    "go forward two metres, not that, go back one metre",  # whole instructions: they may take the first back
    "turn left ninety, not left, turn right ninety",
])
def test_unread_english_between_two_whole_instructions_asks(prompt: str) -> None:
    assert asks(prompt)


@pytest.mark.parametrize(("prompt", "expected"), [
    ("turn to your left, dear, ninety degrees", [("rotate", "left", None, 90.0)]),  # an amount completing it
    ("face north, dear? face north", [("rotate", None, None, None)]),               # the same facing said again
])
def test_unread_english_before_what_completes_or_repeats_takes_nothing_back(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


@pytest.mark.parametrize(("prompt", "expected"), [
    ("turn left thirty degrees not forty", [("rotate", "left", None, 30.0)]),  # amount against amount
    ("turn left, not right", [("rotate", "left", None, None)]),                # side against side
])
def test_a_contrast_sets_alternatives_of_one_kind_against_each_other(prompt: str, expected: Plan) -> None:
    assert plan(prompt) == expected


def test_not_a_side_after_an_amount_takes_the_side_back_and_asks() -> None:
    """"turn left ninety, not left, turn right ninety": "not left" is no contrast with "ninety"; both turns never run."""
    assert asks("turn left ninety, not left, turn right ninety")
