"""A move goes one way: a second way said in the same clause is never dropped silently."""

from __future__ import annotations

import pytest

from langnav.language.intent import Direction, Movement
from langnav.language.offline import translate_offline


@pytest.mark.parametrize(("prompt", "unread"), [
    ("move forward 2 m before turning left", "left"),
    ("move forward 2 m before you turn left", "turn left"),
    ("reverse 1 m before going left", "left"),
    ("go left forward 2 m", "forward"),
])
def test_a_second_direction_asks_instead_of_being_dropped(prompt: str, unread: str) -> None:
    intent = translate_offline(prompt)
    assert intent.steps == []
    assert intent.clarification is not None and f"'{unread}'" in intent.clarification
    assert "Nothing was run" in intent.clarification


@pytest.mark.parametrize(("prompt", "direction", "distance_m"), [
    ("go forward straight ahead 2 m", Direction.FORWARD, 2.0),   # the same way said twice
    ("back up backwards 1 m", Direction.BACKWARD, 1.0),
    ("move forward 2 m", Direction.FORWARD, 2.0),
])
def test_one_way_said_once_or_twice_still_moves(prompt: str, direction: Direction, distance_m: float) -> None:
    intent = translate_offline(prompt)
    assert intent.clarification is None
    assert [(s.movement, s.direction, s.distance_m) for s in intent.steps] == [(Movement.MOVE, direction, distance_m)]
