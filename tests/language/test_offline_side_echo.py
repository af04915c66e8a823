"""A side word said on its own straight after an instruction to go to a place (translator._side_word_after_place):
the same side as the place's is that side said again, no turn; any other side asks whether it names the
place or adds a turn. Our own paraphrases of the pattern (round 8's "go to the left corner, left")."""

from __future__ import annotations

import pytest

from langnav.language.offline import translate_offline


def _plan(prompt: str) -> list[tuple[str, str | None, str | None]]:
    return [(s.movement.value, s.direction.value if s.direction else None,
             s.target.side.value if s.target is not None and s.target.side is not None else None)
            for s in translate_offline(prompt).steps]


@pytest.mark.parametrize(("prompt", "expected"), [
    ("go to the left corner, left", [("navigate", None, "left")]),
    ("head to the right corner... right", [("navigate", None, "right")]),
    ("go through the door on your left, on your left", [("navigate", None, "left")]),
    # an ordering word makes it a turn once there
    ("go to the left corner, then left", [("navigate", None, "left"), ("rotate", "left", None)]),
    # after a move there is no place the side could describe: a turn, as before
    ("move forward two metres, left", [("move", "forward", None), ("rotate", "left", None)]),
])
def test_side_said_again_or_turn(prompt: str, expected: list[tuple[str, str | None, str | None]]) -> None:
    assert _plan(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "go to the left corner, right",       # the right corner, or a right turn once there?
    "go to the nearest corner, left",     # the corner on the left, or a left turn?
    "go through the door on your right, left",
])
def test_another_side_asks(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert intent.steps == [] and intent.clarification is not None and "turn" in intent.clarification
