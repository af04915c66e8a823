"""Where a bench case must leave the robot, for running cases end to end (on the simulator, or on
a robot through ROS 2) rather than comparing commands.

A case's expected commands end either in a NavigateThroughPoses goal region (the robot must stop
inside it) or in a Move, whose step range (``repeat``) is a segment of end points; a case whose
commands do not move the robot (rotations only, a clarification) has no expected end.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any, Final

from langnav.eval.metrics import in_region
from langnav.plan.commands import MOVE_STEP_M, ROTATE_STEP_DEG

#: A Move ends within this distance of where its steps lead: the simulator's and Nav2's controllers
#: stop within a few centimetres of the distance asked for, and the referee's step is 3 cm.
MOVE_TOLERANCE_M: Final = 0.1

#: Where a Move takes the robot, relative to its heading (degrees to the left).
_MOVE_BEARING_DEG: Final = {"forward": 0.0, "backward": 180.0, "left": 90.0, "right": -90.0}

Point = tuple[float, float]
#: ("region", region) after a NavigateThroughPoses, ("segment", (a, b)) after a Move.
End = tuple[str, Any]


def expected_end(case: Mapping[str, Any]) -> End | None:
    """What the robot's last position must satisfy after the case's expected commands, or None when
    they do not move it. A Move after a NavigateThroughPoses cannot be placed (the robot may stop
    anywhere in the region), so the region stays the end only if nothing follows it."""
    x, y, yaw = case["pose"]
    end: End | None = None
    for cmd in case["expect"]:
        kind = cmd["command"]
        if kind == "NavigateThroughPoses":
            end = ("region", cmd["goal"])
            x = y = math.nan
        elif kind == "Rotate":
            lo, hi = cmd["repeat"]
            turn = (lo + hi) / 2 * ROTATE_STEP_DEG
            yaw += -turn if cmd["direction"] == "right" else turn
        elif kind == "Move":
            lo, hi = cmd["repeat"]
            ang = math.radians(yaw + _MOVE_BEARING_DEG[cmd["direction"]])
            a = (x + lo * MOVE_STEP_M * math.cos(ang), y + lo * MOVE_STEP_M * math.sin(ang))
            b = (x + hi * MOVE_STEP_M * math.cos(ang), y + hi * MOVE_STEP_M * math.sin(ang))
            end = ("segment", (a, b))
            x, y = (a[0] + b[0]) / 2, (a[1] + b[1]) / 2
    return end


def segment_distance(p: Point, a: Point, b: Point) -> float:
    """Distance from ``p`` to the segment ``a``-``b`` (to ``a`` when the two coincide)."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    length2 = dx * dx + dy * dy
    t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2))
    return math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy)


def ended_as_expected(end: End, x: float, y: float, move_tolerance_m: float = MOVE_TOLERANCE_M) -> bool:
    """Whether a robot stopped at (x, y) satisfies ``end`` (from :func:`expected_end`)."""
    kind, target = end
    if kind == "region":
        return in_region(target, x, y)
    a, b = target
    return segment_distance((x, y), a, b) <= move_tolerance_m
