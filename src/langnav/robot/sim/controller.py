"""Path following for a differential-drive base: regulated pure pursuit (Nav2's RPP, simplified),
plus the base's speed and acceleration limits. Pure functions: pose and path in, velocity out.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Final

import numpy as np
import numpy.typing as npt

#: Create 3 limits: 0.306 m/s top speed; Nav2's TurtleBot 4 config drives at 0.26-0.3.
MAX_LINEAR_MPS: Final = 0.3
#: Create 3 turns at up to 1.9 rad/s; Nav2 configs keep it near 1.0 for a steady lidar.
MAX_ANGULAR_RADPS: Final = 1.0
MAX_LINEAR_ACCEL_MPS2: Final = 0.5
MAX_ANGULAR_ACCEL_RADPS2: Final = 2.0
#: Goal tolerance: Nav2's SimpleGoalChecker default is 0.25 m; 0.15 m keeps a goal in a doorway in the doorway.
XY_GOAL_TOLERANCE_M: Final = 0.15
#: Yaw tolerance when the goal gives a heading (SimpleGoalChecker's 0.25 rad).
YAW_GOAL_TOLERANCE_RAD: Final = 0.25
#: Pure pursuit lookahead: speed x time, clamped (RPP's lookahead_time 1.5 s, 0.3..0.9 m).
LOOKAHEAD_TIME_S: Final = 1.5
MIN_LOOKAHEAD_M: Final = 0.3
MAX_LOOKAHEAD_M: Final = 0.9
#: The lookahead used to hug the path when the normal carrot would cut a corner into an obstacle.
TIGHT_LOOKAHEAD_M: Final = 0.12
#: Turn in place first when the carrot is more than this far off the heading (RPP's 0.785 rad).
ROTATE_TO_HEADING_MIN_ANGLE_RAD: Final = 0.785
#: Slow down within this distance of the goal (RPP's approach_velocity_scaling_dist 0.6 m).
APPROACH_DIST_M: Final = 0.6
MIN_APPROACH_MPS: Final = 0.05
#: Slow down on turns tighter than this radius (RPP's regulated_linear_scaling_min_radius 0.9 m).
MIN_TURN_RADIUS_M: Final = 0.9
MIN_REGULATED_MPS: Final = 0.08
#: How far along the path to look for the robot's nearest point (a path may loop back on itself).
NEAREST_SEARCH_M: Final = 1.5

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True)
class Limits:
    max_linear_mps: float = MAX_LINEAR_MPS
    max_angular_radps: float = MAX_ANGULAR_RADPS
    max_linear_accel_mps2: float = MAX_LINEAR_ACCEL_MPS2
    max_angular_accel_radps2: float = MAX_ANGULAR_ACCEL_RADPS2


@dataclass(frozen=True)
class Command:
    linear_mps: float
    angular_radps: float
    carrot: tuple[float, float]
    index: int  # the path point the robot is nearest to


def wrap_angle(a: float) -> float:
    """An angle in (-pi, pi]."""
    return math.atan2(math.sin(a), math.cos(a))


def ramp(current: float, target: float, max_delta: float) -> float:
    """Move ``current`` towards ``target`` by at most ``max_delta`` (an acceleration limit)."""
    return current + max(-max_delta, min(max_delta, target - current))


def stopping_speed(remaining: float, max_speed: float, max_accel: float) -> float:
    """The highest speed from which the base can still stop within ``remaining``."""
    return min(max_speed, math.sqrt(2.0 * max_accel * max(remaining, 0.0)))


def rotate_command(yaw_error_rad: float, limits: Limits) -> float:
    """Angular speed for turning in place through ``yaw_error_rad``, braking before the end."""
    speed = stopping_speed(abs(yaw_error_rad), limits.max_angular_radps, limits.max_angular_accel_radps2)
    return math.copysign(max(speed, 0.1), yaw_error_rad)


def pure_pursuit(pose: tuple[float, float, float], path: FloatArray, start_index: int, speed_mps: float,
                 limits: Limits, max_lookahead_m: float = MAX_LOOKAHEAD_M) -> Command:
    """Regulated pure pursuit towards the carrot on ``path`` (N x 2), searching from ``start_index``."""
    x, y, yaw = pose
    n = len(path)
    # nearest point at or after the last one, looking only a little way along (a path may loop back)
    window = path[start_index:]
    d = np.hypot(window[:, 0] - x, window[:, 1] - y)
    seg = np.hypot(*np.diff(window, axis=0).T) if len(window) > 1 else np.zeros(0)
    along = np.concatenate([[0.0], np.cumsum(seg)])
    limit = int(np.searchsorted(along, NEAREST_SEARCH_M)) + 1
    idx = start_index + int(np.argmin(d[:limit]))
    lookahead = min(max(abs(speed_mps) * LOOKAHEAD_TIME_S, MIN_LOOKAHEAD_M), max_lookahead_m)
    rest = path[idx:]
    dr = np.hypot(rest[:, 0] - x, rest[:, 1] - y)
    beyond = np.flatnonzero(dr >= lookahead)
    carrot_i = idx + int(beyond[0]) if beyond.size else n - 1
    cx, cy = float(path[carrot_i, 0]), float(path[carrot_i, 1])
    dx, dy = cx - x, cy - y
    local_x = math.cos(yaw) * dx + math.sin(yaw) * dy
    local_y = -math.sin(yaw) * dx + math.cos(yaw) * dy
    angle = math.atan2(local_y, local_x)
    if abs(angle) > ROTATE_TO_HEADING_MIN_ANGLE_RAD:
        return Command(0.0, rotate_command(angle, limits), (cx, cy), idx)
    dist2 = local_x * local_x + local_y * local_y
    curvature = 2.0 * local_y / dist2 if dist2 > 1e-9 else 0.0
    v = limits.max_linear_mps
    if abs(curvature) > 1e-9 and 1.0 / abs(curvature) < MIN_TURN_RADIUS_M:
        v = max(v * (1.0 / abs(curvature)) / MIN_TURN_RADIUS_M, MIN_REGULATED_MPS)
    to_goal = float(np.hypot(path[-1, 0] - x, path[-1, 1] - y))
    if to_goal < APPROACH_DIST_M:
        v = min(v, max(limits.max_linear_mps * to_goal / APPROACH_DIST_M, MIN_APPROACH_MPS))
    w = v * curvature
    if abs(w) > limits.max_angular_radps:
        w = math.copysign(limits.max_angular_radps, w)
        v = abs(w / curvature) if abs(curvature) > 1e-9 else v
    return Command(v, w, (cx, cy), idx)
