"""Frontier exploration: frontiers found on built maps, blacklisting, budgets, cancel, and a small
floor explored from an empty map (headless simulator)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import pytest
from scipy import ndimage

from langnav.maps.draw import MapBuilder
from langnav.maps.grid import FREE, UNKNOWN, OccupancyGrid
from langnav.plan.commands import Command
from langnav.plan.events import EventKind, ExecEvent, PlanStatus
from langnav.plan.executor import ExecutorConfig, PlanExecutor
from langnav.robot.explore import ExploreParams, Explorer, find_frontiers, frontier_mask
from langnav.robot.sim import create_sim


def floor() -> OccupancyGrid:
    """Three rooms: west [0,4]x[0,4], east [4.2,9]x[0,4] (door at y=1), north [0,9]x[4.2,7] (door at x=2)."""
    b = MapBuilder(11.0, 9.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 4.0, 4.0)
    b.room(4.15, 0.0, 9.0, 4.0)
    b.room(0.0, 4.15, 9.0, 7.0)
    b.door_v(4.075, 1.0, 0.9)
    b.door_h(2.0, 4.075, 0.9)
    b.box(6.0, 5.2, 7.0, 6.0)
    return b.build("three rooms")


def reachable_free(world: OccupancyGrid, x: float, y: float) -> np.ndarray:
    labels, _ = ndimage.label(world.free)
    r, c = world.world_to_index(x, y)
    return labels == labels[int(r), int(c)]


def half_known() -> OccupancyGrid:
    """A 4 m x 2 m free strip whose east half is unknown."""
    b = MapBuilder(6.0, 4.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 4.0, 2.0)
    b.unknown(2.0, 0.0, 4.0, 2.0)
    return b.build("half known")


def test_frontier_is_the_edge_of_the_unknown() -> None:
    g = half_known()
    mask = frontier_mask(g)
    rows, cols = np.nonzero(mask)
    xs, _ = g.cell_to_world(rows, cols)
    assert np.allclose(xs, 1.975, atol=0.03)  # the last free column before x = 2
    fr = find_frontiers(g, (0.5, 1.0))
    assert len(fr) == 1
    f = fr[0]
    assert f.size_m == pytest.approx(2.0, abs=0.15)
    assert f.goal_xy[0] == pytest.approx(1.975, abs=0.03)
    assert 0.5 < f.goal_xy[1] < 1.5  # near the middle, clear of the walls
    assert f.distance_m == pytest.approx(1.5, abs=0.3)


def test_blacklisted_and_small_frontiers_are_left_out() -> None:
    g = half_known()
    goal = find_frontiers(g, (0.5, 1.0))[0].goal_xy
    assert find_frontiers(g, (0.5, 1.0), blacklist=[goal]) == []
    assert find_frontiers(g, (0.5, 1.0), ExploreParams(min_frontier_size_m=3.0)) == []


def test_no_frontier_on_a_closed_known_room_or_when_walled_off() -> None:
    b = MapBuilder(6.0, 4.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 4.0, 2.0)
    assert find_frontiers(b.build(), (1.0, 1.0)) == []
    # a frontier exists, but a wall separates it from the robot
    cells = half_known().cells.copy()
    g = half_known()
    _, c = g.world_to_index(1.0, 1.0)
    cells[:, int(c)] = 100
    walled = g.with_cells(cells)
    assert frontier_mask(walled).any()
    assert find_frontiers(walled, (0.5, 1.0)) == []


def test_scores_prefer_the_nearer_of_equal_frontiers() -> None:
    cells = np.full((40, 120), UNKNOWN, dtype=np.int8)
    cells[10:30, 10:110] = FREE  # a 5 m x 1 m corridor, walled along its length, open at both ends
    cells[9, 10:110] = 100
    cells[30, 10:110] = 100
    g = OccupancyGrid(cells, 0.05)
    fr = find_frontiers(g, (1.0, 1.0))
    assert len(fr) == 2
    assert fr[0].goal_xy[0] < 1.0 < 5.0 < fr[1].goal_xy[0]
    assert fr[0].cost < fr[1].cost
    assert fr[0].size_m == pytest.approx(fr[1].size_m)


def test_explores_a_small_floor_from_an_empty_map() -> None:
    world = floor()
    robot = create_sim(world, (1.0, 1.0, 0.0), known_map=False, seed=3)
    events: list[ExecEvent] = []
    status = Explorer(robot, on_event=events.append).run()
    assert status is PlanStatus.SUCCEEDED
    reach = reachable_free(world, 1.0, 1.0)
    covered = (robot.get_map().free & reach).sum() / reach.sum()
    assert covered >= 0.9
    assert robot.collisions == 0
    assert events[0].kind is EventKind.STARTED
    assert events[-1].kind is EventKind.SUCCEEDED and "exploration done" in events[-1].message
    assert "frontier" not in events[-1].message


def test_budget_ends_exploration() -> None:
    robot = create_sim(floor(), (1.0, 1.0, 0.0), known_map=False)
    events: list[ExecEvent] = []
    status = Explorer(robot, ExploreParams(time_budget_s=8.0), on_event=events.append).run()
    assert status is PlanStatus.SUCCEEDED
    assert "budget" in events[-1].message
    assert robot.time_s < 8.0 + 2 * ExploreParams().replan_period_s + 1


def test_cancel_stops_exploring_and_the_robot() -> None:
    robot = create_sim(floor(), (1.0, 1.0, 0.0), known_map=False)
    ex: list[Explorer] = []

    def on_event(ev: ExecEvent) -> None:
        if ev.kind is EventKind.PROGRESS and robot.time_s > 4.0:
            ex[0].cancel()

    explorer = Explorer(robot, on_event=on_event)
    ex.append(explorer)
    assert explorer.run() is PlanStatus.CANCELLED
    assert robot.linear_mps == 0.0 and not robot.state().busy


@dataclass
class ExploreItem:
    commands: list[Command] = field(default_factory=list)
    explore: bool = True


def test_the_executor_runs_an_exploration_item() -> None:
    world = floor()
    robot = create_sim(world, (1.0, 1.0, 0.0), known_map=False)
    events: list[ExecEvent] = []
    cfg = ExecutorConfig(explore_params=ExploreParams(time_budget_s=10.0))
    status = PlanExecutor(robot, cfg).run([ExploreItem()], on_event=events.append, timeout_s=120)
    assert status is PlanStatus.SUCCEEDED
    assert events[0].kind is EventKind.STARTED and events[0].text == "Explore"
    assert events[-1].kind is EventKind.FINISHED and events[-1].status is PlanStatus.SUCCEEDED
    done = [e for e in events if e.kind is EventKind.SUCCEEDED]
    assert len(done) == 1 and "budget" in done[0].message
    assert robot.get_map().free.sum() * 0.0025 > 20.0  # the first room and more, in ten seconds


def test_done_message_agrees_with_the_map() -> None:
    """An unmapped edge the robot cannot reach is reported as such, never as 'nothing left'."""
    from langnav.robot.explore import done_message

    assert done_message(0, 0) == "exploration done: everything I can reach is mapped"
    assert "2 edges of the map are still unmapped, but I cannot reach them" in done_message(2, 0)
    assert "could not get there" in done_message(1, 1)
    b = MapBuilder(8.0, 5.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 3.0, 3.0)
    b.room(3.5, 0.0, 6.0, 3.0)       # a walled-off room, half of it never seen
    b.unknown(4.5, 0.5, 5.5, 2.5)
    g = b.build("sealed")
    left = find_frontiers(g, (1.5, 1.5), reachable_only=False)
    assert find_frontiers(g, (1.5, 1.5)) == []
    assert len(left) >= 1 and all(f.distance_m == float("inf") for f in left)
