"""A distance in a turn's clause that another instruction says (its own verb, or offered with "or") is not the
straight-on move of "turn right three feet" (review, session 11): read as that, "turn left 90 move back 1 foot"
went FORWARD 0.3 m after the turn, and "turn right 45 degrees or go back 1 foot" did both, forward."""

from __future__ import annotations

import pytest

from langnav.language.intent import Movement
from langnav.language.offline.translator import translate_offline


def _steps(prompt: str) -> list[tuple[str, str | None, float | None]]:
    out = []
    for s in translate_offline(prompt).steps:
        amount = s.distance_m if s.movement == Movement.MOVE else s.angle_deg
        out.append((s.movement.value, s.direction.value if s.direction else None,
                    None if amount is None else round(amount, 4)))
    return out


@pytest.mark.parametrize("prompt", [
    "turn left 90 move back 1 foot",
    "turn left 90 or move back 1 foot",
    "turn right 45 degrees or go back 1 foot",
    "turn left 90 degrees or back up 2 feet",
    "spin 360 or move 3 feet to the right",
    "turn left 90 or move 2 metres left",
])
def test_a_distance_said_with_another_verb_or_an_or_asks(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert intent.steps == []
    assert intent.clarification is not None and "did not understand" in intent.clarification


@pytest.mark.parametrize(("prompt", "expected"), [
    ("turn right three feet", [("rotate", "right", None), ("move", "forward", 0.9144)]),
    ("turn left 2 metres", [("rotate", "left", None), ("move", "forward", 2.0)]),
    ("turn right 90 degrees 3 feet or so", [("rotate", "right", 90.0), ("move", "forward", 0.9144)]),
    ("turn left and move back 1 foot", [("rotate", "left", None), ("move", "backward", 0.3048)]),
])
def test_the_turn_then_straight_on_reading_holds(prompt: str, expected: list[tuple[str, str | None, float | None]]) -> None:
    assert _steps(prompt) == expected
