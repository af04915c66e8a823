"""Pause and STOP hold in every behaviour: the robot's speed is zero within 0.5 s of robot time and
stays zero while held (sampled for 2 s), and Resume carries on.

The simulator runs its clock in a thread (faster than real time, so the test is short); the
plan runs on the executor, as the web app and the CLI run it. Times are the robot's clock.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import pytest

from langnav.maps.draw import MapBuilder
from langnav.maps.grid import OccupancyGrid
from langnav.plan.commands import Command, Move, NavigateThroughPoses, Rotate
from langnav.plan.events import EventKind, ExecEvent, PlanStatus
from langnav.plan.executor import ExecutorConfig, PlanExecutor, PlanRun
from langnav.robot.explore import ExploreParams
from langnav.robot.sim import SimBackend, create_sim

#: The robot must be still this soon after Pause / STOP (robot time).
STILL_WITHIN_S = 0.5
#: ... and stay still this long (robot time).
HOLD_S = 2.0
#: The simulator's clock runs this much faster than the wall clock in these tests.
SPEED = 3.0
WALL_TIMEOUT_S = 60.0


def world() -> OccupancyGrid:
    """Two rooms joined by a door, the east one unknown to an exploring robot."""
    b = MapBuilder(13.0, 7.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 6.0, 5.0)
    b.room(6.15, 0.0, 11.0, 5.0)
    b.door_v(6.075, 2.5, 1.0)
    return b.build("pause hold")


@dataclass
class ExploreItem:
    commands: list[Command] = field(default_factory=list)
    explore: bool = True


def _plans() -> dict[str, tuple[list[Any], bool]]:
    """behaviour -> (plan, known map)."""
    return {
        "navigate": ([NavigateThroughPoses(poses=[[9.5, 2.5]])], True),
        "move": ([Move(direction="forward", repeat=130)], True),
        "rotate": ([Rotate(direction="left", repeat=36)], True),
        "follow": ([NavigateThroughPoses(poses=[[3.0, 1.0], [5.0, 1.0], [5.0, 4.0], [1.0, 4.0]])], True),
        "explore": ([ExploreItem()], False),
    }


def _speed(robot: SimBackend) -> float:
    st = robot.state()
    return abs(st.linear_mps) + abs(st.angular_radps)


def _until(cond: Callable[[], bool], what: str, timeout_s: float = WALL_TIMEOUT_S) -> None:
    end = time.monotonic() + timeout_s
    while not cond():
        if time.monotonic() > end:
            raise AssertionError(f"timed out waiting for {what}")
        time.sleep(0.005)


def _held(robot: SimBackend) -> tuple[float, list[tuple[float, float, float, float]]]:
    """Sample (robot time, speed, x, y) from now for STILL_WITHIN_S + HOLD_S of robot time."""
    t0 = robot.time_s
    samples: list[tuple[float, float, float, float]] = []
    while robot.time_s < t0 + STILL_WITHIN_S + HOLD_S:
        st = robot.state()
        samples.append((st.time_s - t0, abs(st.linear_mps) + abs(st.angular_radps), st.pose.x_m, st.pose.y_m))
        time.sleep(0.01)
    return t0, samples


def _assert_still(samples: list[tuple[float, float, float, float]]) -> None:
    late = [s for s in samples if s[0] >= STILL_WITHIN_S]
    # enough samples, spread over the whole hold (a loaded machine samples less often)
    assert len(late) >= 5, f"too few samples while held: {len(late)}"
    assert late[-1][0] - late[0][0] >= HOLD_S - 0.3, "the samples do not cover the hold"
    assert max(s[1] for s in late) == 0.0, f"the robot moved while held: {[s for s in late if s[1]]}"
    xs = [s[2] for s in late]
    ys = [s[3] for s in late]
    assert max(xs) - min(xs) < 1e-6 and max(ys) - min(ys) < 1e-6


def _start(behaviour: str) -> tuple[SimBackend, PlanRun, list[ExecEvent]]:
    plan, known = _plans()[behaviour]
    start = (1.0, 2.5, 0.0)
    robot = create_sim(world(), start, known_map=known)
    events: list[ExecEvent] = []
    lock = threading.Lock()

    def sink(ev: ExecEvent) -> None:
        with lock:
            events.append(ev)

    cfg = ExecutorConfig(poll_s=0.2, explore_params=ExploreParams(time_budget_s=600.0))
    robot.start(realtime=True, speed=SPEED)
    run = PlanExecutor(robot, cfg).start(plan, on_event=sink)
    # moving for a moment (the robot at speed), so that stopping is a real test
    _until(lambda: _speed(robot) > 0.1, f"{behaviour} to get the robot moving")
    t_moving = robot.time_s
    _until(lambda: robot.time_s > t_moving + 0.5, "half a second of motion")
    assert _speed(robot) > 0.05, f"{behaviour}: the robot should be moving before the pause"
    return robot, run, events


@pytest.mark.parametrize("behaviour", list(_plans()))
def test_pause_holds_then_resume_carries_on(behaviour: str) -> None:
    robot, run, events = _start(behaviour)
    try:
        run.pause()
        _, samples = _held(robot)
        _assert_still(samples)
        assert run.paused and not run.done
        assert any(e.kind is EventKind.PAUSED for e in list(events))
        before = robot.state().pose
        run.resume()
        _until(lambda: _speed(robot) > 0.05, f"{behaviour} to carry on after resume")
        _until(lambda: any(e.kind is EventKind.RESUMED for e in list(events)), "the resumed event")
        if behaviour == "explore":
            _until(lambda: abs(robot.state().pose.x_m - before.x_m) + abs(robot.state().pose.y_m - before.y_m) > 0.2,
                   "exploration to drive on")
            run.cancel()
            assert run.wait(WALL_TIMEOUT_S) is PlanStatus.CANCELLED
        else:
            assert run.wait(WALL_TIMEOUT_S) is PlanStatus.SUCCEEDED
    finally:
        run.cancel()
        robot.close()


@pytest.mark.parametrize("behaviour", list(_plans()))
def test_stop_holds(behaviour: str) -> None:
    robot, run, _ = _start(behaviour)
    try:
        PlanExecutor(robot).stop()  # what STOP does: the robot first, then the plan
        _, samples = _held(robot)
        _assert_still(samples)
        assert run.wait(WALL_TIMEOUT_S) is PlanStatus.CANCELLED
        assert not robot.state().busy
    finally:
        robot.close()


def _joystick(robot: SimBackend, v: float, halt: threading.Event) -> threading.Thread:
    """A teleop panel publishing a held stick at 20 Hz until ``halt``."""
    def loop() -> None:
        while not halt.is_set():
            robot.set_velocity(v, 0.0)
            halt.wait(0.05)
    t = threading.Thread(target=loop, daemon=True)
    t.start()
    return t


@pytest.mark.parametrize("how", ["stop", "pause"])
def test_stop_holds_teleop_while_the_stick_is_still_held(how: str) -> None:
    robot = create_sim(world(), (1.0, 2.5, 0.0), known_map=True)
    robot.start(realtime=True, speed=SPEED)
    halt = threading.Event()
    stick = _joystick(robot, 0.2, halt)
    try:
        _until(lambda: robot.state().linear_mps > 0.1, "teleop to drive")
        if how == "stop":
            PlanExecutor(robot).stop()
        else:  # Pause with no plan running stops the robot the same way (the web app's rule)
            robot.stop()
        _, samples = _held(robot)
        _assert_still(samples)  # the stick still publishes 0.2 m/s all along
        halt.set()
        stick.join(2)
        robot.set_velocity(0.0, 0.0)   # the stick released ...
        robot.set_velocity(0.2, 0.0)   # ... and pushed again: teleop carries on
        _until(lambda: robot.state().linear_mps > 0.05, "teleop to drive again after the release")
    finally:
        halt.set()
        robot.close()
