"""Whatever the intent and wherever the robot, grounding either refuses with a GroundingError or
gives poses the bench counts as valid (free, >= 0.15 m from walls / unknown, reachable) and Moves
whose path and end are clear; and the validator accepts what grounding gives."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from langnav.analysis.elements import MapAnalysis
from langnav.eval.metrics import ValidityMap, move_end_flags
from langnav.grounding import GroundingError, ground
from langnav.language.intent import (
    Detail,
    Direction,
    Element,
    ElementRef,
    Intent,
    Movement,
    Side,
    Step,
    Superlative,
)
from langnav.plan.commands import to_bench
from langnav.plan.validator import validate_plan

refs = st.builds(
    ElementRef,
    kind=st.sampled_from(list(Element)),
    ordinal=st.none() | st.integers(1, 4),
    superlative=st.none() | st.sampled_from(list(Superlative)),
    side=st.none() | st.sampled_from(list(Side)),
    in_current_room=st.booleans(),
    within=st.none() | st.sampled_from([Element.ROOM, Element.HALLWAY]),
)
steps = st.builds(
    Step,
    # naming places is no motion; it has tests of its own (tests/places)
    movement=st.sampled_from([m for m in Movement if m not in (Movement.NAME_PLACE, Movement.FORGET_PLACE)]),
    detail=st.none() | st.sampled_from(list(Detail)),
    target=st.none() | refs,
    second_target=st.none() | refs,
    direction=st.none() | st.sampled_from(list(Direction)),
    distance_m=st.none() | st.floats(0.1, 4.0),
    angle_deg=st.none() | st.floats(5, 360),
)


@pytest.fixture(scope="module")
def vm(two_rooms: MapAnalysis) -> ValidityMap:
    return ValidityMap(two_rooms.grid)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(steps, min_size=1, max_size=3), st.integers(0, 10_000), st.floats(-180, 180))
def test_grounded_plans_are_valid_or_refused(two_rooms: MapAnalysis, vm: ValidityMap, plan_steps: list[Step],
                                             seed: int, yaw: float) -> None:
    free = np.argwhere(vm.ok)
    r, c = free[seed % len(free)]
    x, y = (float(v) for v in two_rooms.grid.cell_to_world(r, c))
    try:
        plan = ground(Intent(steps=plan_steps), two_rooms, (x, y, yaw))
    except GroundingError as exc:
        assert str(exc)  # a sentence for the user
        return
    cmds = [to_bench(cmd) for cmd in plan.commands]
    comp = vm.component_of(x, y)
    for cmd in cmds:
        for p in cmd.get("poses", []):
            assert vm.reachable(p[0], p[1], comp), (p, cmds)
    assert all(move_end_flags((x, y, yaw), cmds, vm, comp))
    validate_plan(plan.commands, two_rooms.grid, (x, y, yaw))
