"""The plan executor on the simulator: event order, failures, cancel, pause / resume, time-outs,
re-grounding, and the one-plan-per-robot rule (Stop wins; queries answer alongside)."""

from __future__ import annotations

import math
import threading
from dataclasses import dataclass, field
from typing import Any

import pytest

from langnav.grounding.errors import GroundingError
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import OccupancyGrid
from langnav.plan.commands import (
    Command,
    GetMap,
    GetRobotPoseLast,
    Move,
    NavigateThroughPoses,
    Rotate,
    Stop,
)
from langnav.plan.events import EventKind, ExecEvent, PlanStatus
from langnav.plan.executor import ExecutorConfig, PlanExecutor, remainder
from langnav.robot.protocol import Pose2D
from langnav.robot.sim import SimBackend, create_sim

WAIT_S = 60.0


def world() -> OccupancyGrid:
    b = MapBuilder(10.0, 6.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 8.0, 4.0)
    b.box(6.5, 2.6, 8.0, 4.0)
    b.free(6.65, 2.75, 7.9, 3.9)  # a sealed closet
    return b.build("executor room")


@pytest.fixture
def robot() -> SimBackend:
    return create_sim(world(), (1.0, 1.0, 0.0), known_map=True)


class Recorder:
    def __init__(self) -> None:
        self.events: list[ExecEvent] = []
        self.lock = threading.Lock()

    def __call__(self, ev: ExecEvent) -> None:
        with self.lock:
            self.events.append(ev)

    def kinds(self) -> list[str]:
        return [e.kind.value for e in self.events if e.kind is not EventKind.PROGRESS]


def test_event_order_and_query_answers(robot: SimBackend) -> None:
    rec = Recorder()
    plan = [[Move(direction="forward", repeat=33)], [Rotate(direction="left", repeat=9)], [GetRobotPoseLast()]]
    status = PlanExecutor(robot).run(plan, on_event=rec, timeout_s=WAIT_S)
    assert status is PlanStatus.SUCCEEDED
    assert rec.kinds() == ["started", "succeeded", "started", "succeeded", "started", "succeeded", "finished"]
    assert [e.index for e in rec.events if e.kind is EventKind.STARTED] == [0, 1, 2]
    assert rec.events[-1].status is PlanStatus.SUCCEEDED
    answer = [e for e in rec.events if e.kind is EventKind.SUCCEEDED][-1]
    x, y, yaw = answer.data["pose"]
    assert (x, y) == pytest.approx((1.99, 1.0), abs=0.02)
    assert yaw == pytest.approx(90.0, abs=1.5)
    assert rec.events[0].command == {"command": "Move", "direction": "forward", "repeat": 33}
    assert rec.events[-1].to_json()["event"] == "finished"


def test_progress_events_have_rising_fractions(robot: SimBackend) -> None:
    rec = Recorder()
    cfg = ExecutorConfig(poll_s=0.5)
    PlanExecutor(robot, cfg).run([NavigateThroughPoses(poses=[[5.0, 1.0]])], on_event=rec, timeout_s=WAIT_S)
    fr = [e.fraction for e in rec.events if e.kind is EventKind.PROGRESS and e.fraction is not None]
    assert len(fr) >= 5
    assert fr[-1] > fr[0]
    assert all(0.0 <= f <= 1.0 for f in fr)


def test_failure_stops_the_plan_with_the_reason(robot: SimBackend) -> None:
    rec = Recorder()
    plan = [NavigateThroughPoses(poses=[[7.2, 3.3]]), Move(direction="forward", repeat=5)]
    status = PlanExecutor(robot).run(plan, on_event=rec, timeout_s=WAIT_S)
    assert status is PlanStatus.FAILED
    failed = [e for e in rec.events if e.kind is EventKind.FAILED]
    assert len(failed) == 1 and "cannot reach the goal" in failed[0].message
    assert [e.index for e in rec.events if e.kind is EventKind.STARTED] == [0]
    assert rec.events[-1].kind is EventKind.FINISHED and rec.events[-1].status is PlanStatus.FAILED
    assert robot.linear_mps == 0.0


def test_cancel_mid_way_stops_the_robot(robot: SimBackend) -> None:
    rec = Recorder()
    runs: list[Any] = []

    def on_event(ev: ExecEvent) -> None:
        rec(ev)
        if ev.kind is EventKind.PROGRESS and len(runs) == 1:
            runs[0].cancel()

    run = PlanExecutor(robot, ExecutorConfig(poll_s=0.5)).start(
        [NavigateThroughPoses(poses=[[6.0, 1.0]]), Move(direction="forward", repeat=3)], on_event=on_event)
    runs.append(run)
    assert run.wait(WAIT_S) is PlanStatus.CANCELLED
    assert rec.kinds()[-2:] == ["cancelled", "finished"]
    assert robot.linear_mps == 0.0 and not robot.state().busy
    assert robot.pose.x_m < 5.0


def test_pause_then_resume_finishes_the_rest_of_a_move(robot: SimBackend) -> None:
    rec = Recorder()
    paused = threading.Event()
    runs: list[Any] = []

    def on_event(ev: ExecEvent) -> None:
        rec(ev)
        if ev.kind is EventKind.PROGRESS and not paused.is_set():
            paused.set()
            runs[0].pause()

    run = PlanExecutor(robot, ExecutorConfig(poll_s=1.0)).start([Move(direction="forward", repeat=60)], on_event=on_event)
    runs.append(run)
    assert paused.wait(WAIT_S)
    for _ in range(200):
        if "paused" in rec.kinds():
            break
        threading.Event().wait(0.01)
    assert "paused" in rec.kinds()
    held = robot.pose
    assert robot.linear_mps == 0.0 and 0.05 < held.x_m - 1.0 < 1.75
    run.resume()
    assert run.wait(WAIT_S) is PlanStatus.SUCCEEDED
    assert robot.pose.x_m - 1.0 == pytest.approx(1.8, abs=0.03)
    kinds = rec.kinds()
    assert kinds.index("paused") < kinds.index("resumed") < kinds.index("succeeded")


def test_per_command_timeout_fails_and_stops(robot: SimBackend) -> None:
    rec = Recorder()
    cfg = ExecutorConfig(poll_s=0.5, move_timeout_s=1.0)
    status = PlanExecutor(robot, cfg).run([Move(direction="forward", repeat=60)], on_event=rec, timeout_s=WAIT_S)
    assert status is PlanStatus.FAILED
    assert any("timed out" in e.message for e in rec.events if e.kind is EventKind.FAILED)
    assert robot.linear_mps == 0.0


def test_stop_wins_at_once_over_a_running_plan(robot: SimBackend) -> None:
    ex = PlanExecutor(robot, ExecutorConfig(poll_s=0.2))
    started = threading.Event()
    a = ex.start([NavigateThroughPoses(poses=[[6.0, 1.0]])],
                 on_event=lambda ev: started.set() if ev.kind is EventKind.PROGRESS else None)
    assert started.wait(WAIT_S)
    b = PlanExecutor(robot).start([Stop()])
    assert a.wait(WAIT_S) is PlanStatus.CANCELLED
    assert b.wait(WAIT_S) is PlanStatus.SUCCEEDED
    assert robot.linear_mps == 0.0 and robot.pose.x_m < 5.9


def test_a_new_plan_replaces_the_running_one(robot: SimBackend) -> None:
    ex = PlanExecutor(robot, ExecutorConfig(poll_s=0.2))
    started = threading.Event()
    a = ex.start([NavigateThroughPoses(poses=[[6.0, 1.0]])],
                 on_event=lambda ev: started.set() if ev.kind is EventKind.PROGRESS else None)
    assert started.wait(WAIT_S)
    b = ex.start([Rotate(direction="left", repeat=9)])
    assert a.wait(WAIT_S) is PlanStatus.CANCELLED
    assert b.wait(WAIT_S) is PlanStatus.SUCCEEDED
    assert math.degrees(robot.pose.yaw_rad) == pytest.approx(90.0, abs=15.0)


def test_queries_answer_alongside_a_running_plan(robot: SimBackend) -> None:
    ex = PlanExecutor(robot, ExecutorConfig(poll_s=0.2))
    started = threading.Event()
    a = ex.start([NavigateThroughPoses(poses=[[3.0, 1.0]])],
                 on_event=lambda ev: started.set() if ev.kind is EventKind.PROGRESS else None)
    assert started.wait(WAIT_S)
    rec = Recorder()
    q = ex.start([GetRobotPoseLast(), GetMap()], on_event=rec)
    assert q.wait(WAIT_S) is PlanStatus.SUCCEEDED
    assert a.wait(WAIT_S) is PlanStatus.SUCCEEDED
    answers = [e for e in rec.events if e.kind is EventKind.SUCCEEDED]
    assert "pose" in answers[0].data and answers[1].data["map"]["free_m2"] > 20


@dataclass
class FakeItem:
    """A plan item as the grounding helper makes them: commands now, and how to ground them later."""

    commands: list[Command]
    later: list[Command] | None = None
    fail: bool = False
    calls: list[tuple[tuple[float, float, float], OccupancyGrid]] = field(default_factory=list)

    def reground(self, pose: tuple[float, float, float], grid: OccupancyGrid) -> list[Command]:
        self.calls.append((pose, grid))
        if self.fail:
            raise GroundingError("no door on your left from here")
        return list(self.later or self.commands)


def test_later_steps_are_regrounded_from_the_pose_of_that_moment(robot: SimBackend) -> None:
    first = FakeItem([Move(direction="forward", repeat=33)])
    second = FakeItem([Rotate(direction="right", repeat=9)], later=[Rotate(direction="left", repeat=9)])
    status = PlanExecutor(robot).run([first, second], timeout_s=WAIT_S)
    assert status is PlanStatus.SUCCEEDED
    assert first.calls == []
    assert len(second.calls) == 1
    (x, y, yaw), grid = second.calls[0]
    assert (x, y) == pytest.approx((1.99, 1.0), abs=0.02) and yaw == pytest.approx(0.0, abs=1.0)
    assert grid.value_at(2.0, 2.0) == 0
    assert math.degrees(robot.pose.yaw_rad) == pytest.approx(90.0, abs=1.5)  # the re-grounded turn ran


def test_a_step_that_cannot_be_regrounded_fails_the_plan(robot: SimBackend) -> None:
    rec = Recorder()
    plan = [FakeItem([Move(direction="forward", repeat=3)]), FakeItem([Move(direction="forward", repeat=3)], fail=True)]
    assert PlanExecutor(robot).run(plan, on_event=rec, timeout_s=WAIT_S) is PlanStatus.FAILED
    failed = [e for e in rec.events if e.kind is EventKind.FAILED]
    assert "no door on your left" in failed[0].message


def test_a_broken_event_callback_does_not_stop_the_robot(robot: SimBackend) -> None:
    def boom(ev: ExecEvent) -> None:
        raise ValueError("display crashed")

    assert PlanExecutor(robot).run([Rotate(direction="left", repeat=3)], on_event=boom, timeout_s=WAIT_S) is PlanStatus.SUCCEEDED


@pytest.mark.parametrize(("cmd", "now", "expect"), [
    (Move(direction="forward", repeat=60), Pose2D(1.6, 1.0, 0.0), 40),
    (Move(direction="left", repeat=20), Pose2D(1.0, 1.3, math.pi / 2), 10),
    (Move(direction="backward", repeat=10), Pose2D(0.71, 1.0, 0.0), None),
    (Rotate(direction="left", repeat=9), Pose2D(1.0, 1.0, math.radians(30)), 6),
    (Rotate(direction="right", repeat=9), Pose2D(1.0, 1.0, math.radians(-87)), None),
])
def test_remainder_after_a_pause(cmd: Command, now: Pose2D, expect: int | None) -> None:
    rest = remainder(cmd, Pose2D(1.0, 1.0, 0.0), now, None)
    if expect is None:
        assert rest is None
    else:
        assert isinstance(rest, Move | Rotate) and isinstance(cmd, Move | Rotate)
        assert rest.repeat == expect and rest.direction == cmd.direction
