"""An instruction said twice in a row, with the same amount and no word asking for it again, is
done once (langnav.language.offline.translator._restates): doing it twice would take the robot
farther than asked."""

from __future__ import annotations

import pytest

from langnav.language.intent import Movement
from langnav.language.offline.translator import translate_offline


def _plan(prompt: str) -> list[tuple[str, str | None, float | None, float | None]]:
    intent = translate_offline(prompt)
    return [(s.movement.value, s.direction.value if s.direction else None, s.distance_m, s.angle_deg)
            for s in intent.steps]


@pytest.mark.parametrize("prompt, expected", [
    ("back up one metre. Back up one metre.", [("move", "backward", 1.0, None)]),
    ("okay go forward four metres... yes, forward four metres", [("move", "forward", 4.0, None)]),
    ("rotate right twenty degrees. twenty degrees right.", [("rotate", "right", None, 20.0)]),
    ("move left half a metre. To the left. Half a metre.", [("move", "left", 0.5, None)]),
])
def test_an_instruction_said_again_is_done_once(prompt: str, expected: list[tuple[str, str | None, float | None,
                                                                                  float | None]]) -> None:
    assert _plan(prompt) == expected


@pytest.mark.parametrize("prompt, moves", [
    ("turn right 90 degrees, then turn right 90 degrees", 2),   # sequenced: meant twice
    ("go forward 1 m and then another 1 m", 2),                  # "another" asks for more
    ("move forward 1 metre, move forward 1 metre again", 2),     # "again" asks for more
    ("go forward 2 m, turn left, go forward 2 m", 2),            # not in a row
    ("move forward 1 metre. Move forward 2 metres.", 2),         # not the same amount
])
def test_a_repeat_asked_for_is_kept(prompt: str, moves: int) -> None:
    steps = translate_offline(prompt).steps
    assert sum(s.movement in (Movement.MOVE, Movement.ROTATE) and s.amount is None for s in steps) >= moves


@pytest.mark.parametrize("prompt, expected", [
    ("rotate right. you're breaking up. rotate right thirty degrees", [("rotate", "right", None, 30.0)]),
])
def test_an_instruction_said_again_with_its_amount_is_done_once(
        prompt: str, expected: list[tuple[str, str | None, float | None, float | None]]) -> None:
    """_completes: the bare instruction and its restatement with an amount are one instruction."""
    assert _plan(prompt) == expected


def test_a_bare_turn_then_another_side_is_kept() -> None:
    """_completes joins only a turn to the same side; with nothing between them but a pause, a bare turn and a
    turn to the other side are a false start (test_offline_false_starts), so here the two are put in order."""
    assert [s.direction.value for s in translate_offline("turn left. then turn right 30 degrees").steps
            if s.direction] == ["left", "right"]
