"""The result-once state of a task handle whose outcome another thread reports (the rosbridge and
ROS 2 backends): status, latest feedback and result under one condition variable, ``wait`` with a
timeout, the first outcome wins."""

from __future__ import annotations

import threading

from langnav.robot.errors import RobotTimeout
from langnav.robot.protocol import (
    DEFAULT_TASK_TIMEOUT_S,
    Pose2D,
    TaskFeedback,
    TaskResult,
    TaskStatus,
)


class ReportedTask:
    """Task state set from a transport's thread and read from the caller's."""

    #: Appended to the timeout message of :meth:`wait`.
    wait_hint = ""

    def __init__(self, kind: str) -> None:
        self.kind = kind
        self._cond = threading.Condition()
        self._status = TaskStatus.RUNNING
        self._feedback: TaskFeedback | None = None
        self._result: TaskResult | None = None

    def status(self) -> TaskStatus:
        with self._cond:
            return self._status

    def feedback(self) -> TaskFeedback | None:
        with self._cond:
            return self._feedback

    def wait(self, timeout_s: float = DEFAULT_TASK_TIMEOUT_S) -> TaskResult:
        with self._cond:
            if not self._cond.wait_for(lambda: self._result is not None, timeout_s):
                raise RobotTimeout(f"{self.kind} still running after {timeout_s} s; it was left running"
                                   f"{self.wait_hint}")
            assert self._result is not None
            return self._result

    def _set_result(self, status: TaskStatus, message: str, pose: Pose2D | None) -> bool:
        """Set the result once and wake the waiters; False when it was already set."""
        with self._cond:
            if self._result is not None:
                return False
            self._status = status
            self._result = TaskResult(status, message, pose)
            self._cond.notify_all()
            return True

    @property
    def done(self) -> bool:
        with self._cond:
            return self._result is not None
