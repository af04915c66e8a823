"""What the plan executor and the explorer report, one event at a time, to a callback.

Per command: ``started`` -> any number of ``progress`` -> one of ``succeeded`` / ``failed`` /
``cancelled`` (``paused`` and ``resumed`` may come between). Per plan, last of all: ``finished``
with the plan's status. Events are pydantic models: ``event.to_json()`` is one line of
``langnav run --json`` and one message of the web view.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from enum import StrEnum
from typing import Any

from pydantic import BaseModel, ConfigDict, Field

from langnav.robot.protocol import Pose2D


class EventKind(StrEnum):
    STARTED = "started"
    PROGRESS = "progress"
    SUCCEEDED = "succeeded"
    FAILED = "failed"
    CANCELLED = "cancelled"
    PAUSED = "paused"
    RESUMED = "resumed"
    FINISHED = "finished"


class PlanStatus(StrEnum):
    RUNNING = "running"
    SUCCEEDED = "succeeded"
    FAILED = "failed"
    CANCELLED = "cancelled"
    REJECTED = "rejected"


class ExecEvent(BaseModel):
    """One thing that happened while a plan ran."""

    model_config = ConfigDict(frozen=True)

    kind: EventKind
    #: the command's position in the whole plan (0-based); None for plan-level events
    index: int | None = None
    #: the plan step (item) the command belongs to
    step: int | None = None
    #: the command in the bench's shape ({"command": "Move", ...}), when there is one
    command: dict[str, Any] | None = None
    #: the command in plain words
    text: str = ""
    #: what happened, in plain words (the failure reason for ``failed``)
    message: str = ""
    #: progress of the command, 0..1, when known
    fraction: float | None = None
    #: the plan's status, on ``finished``
    status: PlanStatus | None = None
    #: the robot's pose when the event was made: x_m, y_m, yaw_deg
    pose: tuple[float, float, float] | None = None
    #: answers to queries (pose, path, map summary) and exploration figures
    data: dict[str, Any] = Field(default_factory=dict)
    #: seconds since the plan started (wall clock)
    time_s: float = 0.0

    def to_json(self) -> dict[str, Any]:
        """A compact JSON-able dict: the kind as ``event``, empty fields left out."""
        out: dict[str, Any] = {"event": self.kind.value}
        body = self.model_dump(mode="json", exclude={"kind"}, exclude_none=True)
        for key, val in body.items():
            if val in ("", {}, []):
                continue
            out[key] = val
        return out


EventSink = Callable[[ExecEvent], None]


def pose_tuple(pose: Pose2D) -> tuple[float, float, float]:
    """(x_m, y_m, yaw_deg), rounded to the millimetre and the tenth of a degree."""
    return (round(pose.x_m, 3), round(pose.y_m, 3), round(math.degrees(pose.yaw_rad), 1))
