"""The result-once task state the rosbridge and ROS 2 handles share."""

from __future__ import annotations

import threading

import pytest

from langnav.robot import RobotTimeout, TaskStatus
from langnav.robot.protocol import Pose2D
from langnav.robot.ros.backend import _Ros2Task
from langnav.robot.ros.rosbridge_backend import _Task
from langnav.robot.task_state import ReportedTask


def test_both_transport_handles_share_it() -> None:
    assert issubclass(_Task, ReportedTask) and issubclass(_Ros2Task, ReportedTask)


def test_first_outcome_wins_and_wakes_a_waiter() -> None:
    t = _Task("navigate", on_cancel=lambda _: None)
    assert not t.done
    timer = threading.Timer(0.05, t.finish, (TaskStatus.SUCCEEDED, "reached", Pose2D(1.0, 2.0, 0.0)))
    timer.start()
    r = t.wait(5.0)
    timer.join()
    assert (r.status, r.message, r.pose) == (TaskStatus.SUCCEEDED, "reached", Pose2D(1.0, 2.0, 0.0))
    assert t.finish(TaskStatus.FAILED, "late") is False
    assert t.status() is TaskStatus.SUCCEEDED and t.done


def test_wait_times_out_with_the_transports_hint() -> None:
    t = _Task("move", on_cancel=lambda _: None)
    with pytest.raises(RobotTimeout, match=r"move still running after 0.01 s; it was left running \(cancel"):
        t.wait(0.01)
    r2 = _Ros2Task("rotate", backend=None)  # type: ignore[arg-type]
    r2.finish(TaskStatus.CANCELED, "canceled", None)
    r2.finish(TaskStatus.SUCCEEDED, "too late", None)
    assert r2.wait(0.01).status is TaskStatus.CANCELED
