"""The robot backend seam: the seven commands, in the shape of nav2_simple_commander's API.

Start a long action and get a :class:`TaskHandle`; poll ``feedback()``, ``cancel()``, wait with a
timeout, read a :class:`TaskResult`. Every wait takes a timeout with a named default.
Backends are registered by name (``sim``, ``rosbridge``, ``ros2``).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from enum import StrEnum
from typing import Any, Final, Protocol, runtime_checkable

from langnav.maps.grid import OccupancyGrid

#: Default limit for waiting on one long action (a long Nav2 route across a building).
DEFAULT_TASK_TIMEOUT_S: Final = 300.0
#: Default limit for a short request (pose, map, path).
DEFAULT_REQUEST_TIMEOUT_S: Final = 5.0


class TaskStatus(StrEnum):
    """nav2_simple_commander's TaskResult, plus RUNNING while the task is under way."""

    RUNNING = "running"
    SUCCEEDED = "succeeded"
    FAILED = "failed"
    CANCELED = "canceled"


@dataclass(frozen=True)
class Pose2D:
    x_m: float
    y_m: float
    yaw_rad: float

    def as_tuple(self) -> tuple[float, float, float]:
        return (self.x_m, self.y_m, self.yaw_rad)


@dataclass(frozen=True)
class TaskFeedback:
    """Progress of a long action: where the robot is, how far is left, for how long."""

    pose: Pose2D
    distance_remaining_m: float | None = None
    elapsed_s: float = 0.0
    poses_remaining: int | None = None
    recoveries: int = 0
    message: str = ""
    #: turning still to do (Rotate, and the turns of a sideways Move), when the backend knows it
    angle_remaining_rad: float | None = None


@dataclass(frozen=True)
class TaskResult:
    status: TaskStatus
    message: str = ""
    pose: Pose2D | None = None


@dataclass(frozen=True)
class LaserScan:
    angle_min_rad: float
    angle_increment_rad: float
    range_max_m: float
    ranges_m: tuple[float, ...]
    pose: Pose2D  # the sensor pose when the scan was taken


@dataclass(frozen=True)
class RobotState:
    """A snapshot for displays: pose, velocity, last scan, current path and goals, connection."""

    pose: Pose2D
    connected: bool = True
    linear_mps: float = 0.0
    angular_radps: float = 0.0
    scan: LaserScan | None = None
    path: tuple[tuple[float, float], ...] = ()
    goals: tuple[tuple[float, float], ...] = ()
    busy: bool = False
    time_s: float = 0.0
    extra: dict[str, Any] = field(default_factory=dict)


@runtime_checkable
class TaskHandle(Protocol):
    def status(self) -> TaskStatus: ...

    def feedback(self) -> TaskFeedback | None: ...

    def cancel(self) -> None: ...

    def wait(self, timeout_s: float = DEFAULT_TASK_TIMEOUT_S) -> TaskResult:
        """Block until the task ends; raises RobotTimeout (and leaves the task running) on timeout."""
        ...


@runtime_checkable
class RobotBackend(Protocol):
    name: str

    def navigate_through_poses(self, poses: list[tuple[float, float] | tuple[float, float, float]]) -> TaskHandle:
        """Plan through every pose (x, y[, yaw_deg]) and stop at the last."""
        ...

    def move(self, direction: str, steps: int) -> TaskHandle:
        """Drive ``steps`` x 3 cm forward / backward / left / right."""
        ...

    def rotate(self, direction: str, steps: int) -> TaskHandle:
        """Turn ``steps`` x 10 degrees left (counter-clockwise) or right."""
        ...

    def stop(self) -> None:
        """Cancel whatever runs and halt now."""
        ...

    def get_current_path(self, timeout_s: float = DEFAULT_REQUEST_TIMEOUT_S) -> list[tuple[float, float]]: ...

    def get_map(self, timeout_s: float = DEFAULT_REQUEST_TIMEOUT_S) -> OccupancyGrid: ...

    def get_robot_pose(self, timeout_s: float = DEFAULT_REQUEST_TIMEOUT_S) -> Pose2D: ...

    def state(self) -> RobotState: ...

    def close(self) -> None: ...


@runtime_checkable
class StopConfirmable(Protocol):
    """A backend that can tell whether its last stop took (the rosbridge backend): optional."""

    def wait_stopped(self, timeout_s: float | None = None) -> None:
        """Block until every cancelled goal is confirmed ended; raise RobotError (the robot may
        still be moving, and what to do) when one was not, within the backend's own bound."""
        ...


BackendFactory = Callable[..., RobotBackend]
_REGISTRY: dict[str, BackendFactory] = {}
#: Built-in backends: name -> the module that registers it (imported on first use, so that
#: roslibpy / rclpy are only loaded when that backend is asked for).
_BUILTIN: dict[str, str] = {
    "sim": "langnav.robot.sim",
    "rosbridge": "langnav.robot.ros.rosbridge_backend",
    "ros2": "langnav.robot.ros.backend",
}


def register_backend(name: str, factory: BackendFactory) -> None:
    _REGISTRY[name] = factory


def backend_names() -> list[str]:
    return sorted(set(_REGISTRY) | set(_BUILTIN))


def create_backend(name: str, **options: Any) -> RobotBackend:
    """Build the backend registered under ``name`` (sim, rosbridge, ros2) with its options."""
    import importlib

    from langnav.robot.errors import RobotError

    if name not in _REGISTRY and name in _BUILTIN:
        importlib.import_module(_BUILTIN[name])
    try:
        factory = _REGISTRY[name]
    except KeyError:
        raise RobotError(f"unknown robot backend {name!r}; choose one of: {', '.join(backend_names())}") from None
    return factory(**options)
