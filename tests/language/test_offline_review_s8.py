"""Readings the session-8 review found moving where the session's start asked or did more: each must ask,
or keep every instruction said (offline translator, no map)."""

from __future__ import annotations

import pytest

from langnav.language.offline.translator import translate_offline


@pytest.mark.parametrize("prompt", [
    "nobody said turn left",              # reported speech relayed only from someone named as a speaker
    "who said turn around?",
    "you said turn left?",                # a question about what was said, not a request
    "he said turn left?",
    "turn right, two metres ahead",       # the turn's place, or a move? ask
    "turn left, about three metres ahead",
    "go over there two metres",           # "there" may point at a place
    "go right there two metres",
    "six-sixteen metres forward",         # a number said whole is no stammer
])
def test_asks(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert intent.steps == [] and intent.clarification


def _plan(prompt: str) -> list[tuple[str, str | None]]:
    return [(s.movement.value, s.direction.value if s.direction else None) for s in translate_offline(prompt).steps]


@pytest.mark.parametrize(("prompt", "expected"), [
    # dismay puts right a slip of its own kind only
    ("turn left, damn, go forward two metres", [("rotate", "left"), ("move", "forward")]),
    ("turn right, turn left, aiya, turn right sixty degree", [("rotate", "right")]),
    # where something goes is a trip, not a note of where a thing is
    ("hurry to the door, okay, turn right", [("navigate", None), ("rotate", "right")]),
    ("chipped paint by the door, fine. turn left", [("rotate", "left")]),
    # still read
    ("chat says turn left, okay, turn left forty five", [("rotate", "left")]),
    ("right face, forward ten metres", [("rotate", "right"), ("move", "forward")]),
    ("g-g-go forward two metres", [("move", "forward")]),
])
def test_keeps_what_was_said(prompt: str, expected: list[tuple[str, str | None]]) -> None:
    assert _plan(prompt) == expected
