"""The plan executor on the simulator under faults: controls used twice or at the wrong time, a
map that changes under a plan, a connection lost mid-command, a time-out. The plan ends with a
reason and the robot is stopped; nothing raises."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from langnav.language.translator import get_translator
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import UNKNOWN, OccupancyGrid
from langnav.pipeline import Planner
from langnav.plan.commands import Move, Rotate
from langnav.plan.events import EventKind, ExecEvent, PlanStatus
from langnav.plan.executor import ExecutorConfig, PlanExecutor
from langnav.robot.errors import RobotError
from langnav.robot.protocol import TaskHandle, TaskResult
from langnav.robot.sim import SimBackend, create_sim

WAIT_S = 60.0


def _world() -> OccupancyGrid:
    b = MapBuilder(10.0, 6.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 8.0, 4.0)
    return b.build("fault room")


@pytest.fixture
def robot() -> SimBackend:
    return create_sim(_world(), (1.0, 1.0, 0.0), known_map=True)


def _of(events: list[ExecEvent], kind: EventKind) -> list[ExecEvent]:
    return [e for e in events if e.kind is kind]


def test_controls_twice_and_when_idle(robot: SimBackend) -> None:
    ex = PlanExecutor(robot)
    ex.stop()
    ex.stop()  # stop while idle: nothing to cancel, the robot is told to stop
    assert robot.linear_mps == 0.0 and ex.current() is None
    run = ex.start([Move(direction="forward", repeat=150)])
    run.cancel()
    run.cancel()
    assert run.wait(WAIT_S) is PlanStatus.CANCELLED
    run.cancel()
    run.pause()
    run.resume()  # all after the end: no effect, no error
    assert run.status is PlanStatus.CANCELLED and robot.linear_mps == 0.0
    x0 = robot.pose.x_m  # the cancelled move may have gone a little way
    run = ex.start([Move(direction="forward", repeat=10)])
    run.resume()  # resume when nothing is paused
    assert run.wait(WAIT_S) is PlanStatus.SUCCEEDED
    assert robot.pose.x_m - x0 == pytest.approx(0.3, abs=0.03)


def test_a_timeout_names_its_budget(robot: SimBackend) -> None:
    ev: list[ExecEvent] = []
    cfg = ExecutorConfig(poll_s=0.1, move_timeout_s=0.5)
    assert PlanExecutor(robot, cfg).run([Move(direction="forward", repeat=150)], on_event=ev.append,
                                        timeout_s=WAIT_S) is PlanStatus.FAILED
    (failed,) = _of(ev, EventKind.FAILED)
    assert failed.message == "timed out after 0.5 s; the robot stopped"
    assert robot.linear_mps == 0.0


class _LostHandle:
    """A task handle whose connection drops on the second wait."""

    def __init__(self, inner: TaskHandle) -> None:
        self.inner = inner
        self.waits = 0

    def status(self) -> Any:
        return self.inner.status()

    def feedback(self) -> Any:
        return self.inner.feedback()

    def cancel(self) -> None:
        self.inner.cancel()

    def wait(self, timeout_s: float = 1.0) -> TaskResult:
        self.waits += 1
        if self.waits >= 2:
            raise RobotError("the connection to the robot was lost")
        return self.inner.wait(timeout_s)


class _Wrapped:
    """The simulator with some of its methods replaced by a subclass."""

    def __init__(self, sim: SimBackend) -> None:
        self.sim = sim
        self.stops = 0

    def __getattr__(self, name: str) -> Any:
        return getattr(self.sim, name)


class _LosingRobot(_Wrapped):
    """The simulator, but the link drops during a Move; counts the stops it is sent."""

    def move(self, direction: str, steps: int) -> TaskHandle:
        return _LostHandle(self.sim.move(direction, steps))

    def stop(self) -> None:
        self.stops += 1
        self.sim.stop()


def test_a_connection_lost_mid_command_stops_the_robot(robot: SimBackend) -> None:
    robot.start(realtime=True)
    try:
        flaky = _LosingRobot(robot)
        ev: list[ExecEvent] = []
        run = PlanExecutor(flaky, ExecutorConfig(poll_s=0.05)).start(  # type: ignore[arg-type]
            [Move(direction="forward", repeat=150)], on_event=ev.append)
        assert run.wait(WAIT_S) is PlanStatus.FAILED
        assert run.message == "the connection to the robot was lost"
        assert flaky.stops >= 1
        assert not robot.state().busy
    finally:
        robot.close()


class _ShrinkingMap(_Wrapped):
    """The simulator, but its map has lost all its free space (as seen when re-grounding)."""

    def get_map(self, timeout_s: float = 5.0) -> OccupancyGrid:
        grid = self.sim.get_map(timeout_s)
        return grid.with_cells(np.full_like(grid.cells, UNKNOWN))


def test_regrounding_on_a_changed_map_fails_the_plan_with_the_reason(robot: SimBackend) -> None:
    planner = Planner(get_translator("offline"))
    result = planner.plan("turn left 30 degrees then go to the middle of the room", robot.get_map(),
                          (1.0, 1.0, 0.0))
    assert result.ok, result.clarification
    ev: list[ExecEvent] = []
    wrapped = _ShrinkingMap(robot)
    status = PlanExecutor(wrapped).run(result.items, on_event=ev.append, timeout_s=WAIT_S)  # type: ignore[arg-type]
    assert status is PlanStatus.FAILED
    (failed,) = _of(ev, EventKind.FAILED)
    assert failed.message.startswith("could not re-plan this step from here: ")
    assert "no free space" in failed.message
    assert [e.kind for e in ev if e.kind is EventKind.STARTED] == [EventKind.STARTED]  # only the turn
    assert robot.linear_mps == 0.0


def test_reground_directly_on_a_broken_map_raises_a_langnav_error(robot: SimBackend) -> None:
    from langnav.errors import LangnavError

    planner = Planner(get_translator("offline"))
    result = planner.plan("rotate left 10 degrees then go to the nearest corner", robot.get_map(), (1.0, 1.0, 0.0))
    assert result.ok
    grid = robot.get_map()
    with pytest.raises(LangnavError):
        result.items[1].reground((1.0, 1.0, 0.0), grid.with_cells(np.full_like(grid.cells, UNKNOWN)))
    with pytest.raises(LangnavError, match="outside the map"):
        result.items[1].reground((999.0, 999.0, 0.0), grid)
    assert [type(c) for c in result.items[0].commands] == [Rotate]
