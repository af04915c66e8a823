"""The plan checker: safe plans pass, near-misses are repaired, unsafe plans are refused with reasons."""

from __future__ import annotations

import pytest

from langnav.maps.draw import MapBuilder
from langnav.maps.grid import OccupancyGrid
from langnav.plan.commands import Move, NavigateThroughPoses, Rotate, Stop
from langnav.plan.errors import PlanRejected
from langnav.plan.validator import validate_plan


@pytest.fixture(scope="module")
def grid() -> OccupancyGrid:
    """A 6 x 4 m room with a closed 1 x 1 m pocket (free inside, walled off) and an unknown corner."""
    b = MapBuilder(8.0, 6.0)
    b.room(1.0, 1.0, 7.0, 5.0)
    b.room(5.5, 3.5, 6.5, 4.5)          # walled pocket inside the room
    b.unknown(1.0, 4.0, 2.0, 5.0)
    return b.build("validator_room")


START = (2.0, 2.0, 0.0)


def test_a_safe_plan_passes_unchanged(grid: OccupancyGrid) -> None:
    cmds = [NavigateThroughPoses(poses=[[3.0, 2.0], [4.0, 3.0]]), Rotate(direction="left", repeat=9),
            Move(direction="forward", repeat=20), Stop()]
    checked = validate_plan(cmds, grid, START)
    assert list(checked.commands) == cmds and checked.repairs == ()
    # at (4, 3) heading 45 deg (along the last leg), turned to 135 deg, then 0.6 m forward
    assert checked.end_pose.x_m == pytest.approx(4.0 - 0.6 * 0.5**0.5)
    assert checked.end_pose.y_m == pytest.approx(3.0 + 0.6 * 0.5**0.5)


def test_a_pose_too_close_to_a_wall_is_snapped_and_reported(grid: OccupancyGrid) -> None:
    checked = validate_plan([NavigateThroughPoses(poses=[[3.0, 1.05]])], grid, START)
    (x, y), = [p[:2] for p in checked.commands[0].poses]
    assert abs(x - 3.0) <= 0.025 + 1e-9 and y == pytest.approx(1.175)  # the nearest cell 0.2 m from the wall
    assert "moved from (3.00, 1.05)" in checked.repairs[0] and "from a wall" in checked.repairs[0]


@pytest.mark.parametrize(("pose", "reason"), [
    ([30.0, 2.0], "outside the map"),
    ([1.4, 4.6], "in unmapped space, and no valid cell is within 0.5 m"),
    ([6.0, 4.0], "cannot reach it through free space"),
])
def test_unsafe_poses_are_refused(grid: OccupancyGrid, pose: list[float], reason: str) -> None:
    with pytest.raises(PlanRejected) as exc:
        validate_plan([NavigateThroughPoses(poses=[pose])], grid, START)
    assert reason in exc.value.reasons[0]


def test_move_into_a_wall_is_refused(grid: OccupancyGrid) -> None:
    with pytest.raises(PlanRejected, match=r"moving backward 1\.50 m .* runs into a wall"):
        validate_plan([Move(direction="backward", repeat=50)], grid, START)


def test_moves_are_checked_from_where_earlier_commands_leave_the_robot(grid: OccupancyGrid) -> None:
    # 1 m forward is fine from the start, but not after navigating next to the east wall
    validate_plan([Move(direction="forward", repeat=33)], grid, START)
    with pytest.raises(PlanRejected, match="command 2: moving forward"):
        validate_plan([NavigateThroughPoses(poses=[[6.5, 2.0]]), Move(direction="forward", repeat=33)], grid, START)


def test_malformed_dicts_are_refused_with_the_field(grid: OccupancyGrid) -> None:
    with pytest.raises(PlanRejected) as exc:
        validate_plan([{"command": "Move", "direction": "up", "repeat": 3},
                       {"command": "Rotate", "direction": "left", "repeat": 0}], grid, START)
    assert len(exc.value.reasons) == 2
    assert "command 1 (Move) is malformed" in exc.value.reasons[0] and "direction" in exc.value.reasons[0]
    assert "repeat" in exc.value.reasons[1]


def test_dicts_that_are_valid_are_parsed(grid: OccupancyGrid) -> None:
    checked = validate_plan([{"command": "Rotate", "direction": "right", "repeat": 3}], grid, START)
    assert checked.commands == (Rotate(direction="right", repeat=3),)


def test_a_stop_between_motions_is_dropped_and_a_stop_first_kept(grid: OccupancyGrid) -> None:
    checked = validate_plan([Rotate(direction="left", repeat=1), Stop(), Rotate(direction="left", repeat=1)],
                            grid, START)
    assert checked.commands == (Rotate(direction="left", repeat=1), Rotate(direction="left", repeat=1))
    assert "command 2: a Stop between motions does nothing" in checked.repairs[0]
    first = validate_plan([Stop(), Rotate(direction="left", repeat=18)], grid, START)
    assert first.commands[0] == Stop() and first.repairs == ()


def test_robot_pose_in_a_wall_cannot_navigate(grid: OccupancyGrid) -> None:
    with pytest.raises(PlanRejected, match="no free space around the robot"):
        validate_plan([NavigateThroughPoses(poses=[[3.0, 2.0]])], grid, (0.2, 0.2, 0.0))
