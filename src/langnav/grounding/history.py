"""Where the robot has been: the trail a session drove and where each trip started.

"Go back to where you started", "back to where you were", "the door you just passed" are read
from this. The planner observes the robot's pose each time a prompt arrives (a real pose); a
plan's route is taken as driven only when the next observed pose is where that route ended (the
plan ran); a robot executor may also ``record`` the poses it reaches, which is better still.

Pure data and small geometry; thread-safe, bounded.
"""

from __future__ import annotations

import itertools
import math
import threading
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Final

from langnav.grounding.geometry import Point, Pose

#: Trail points closer than this to the last one add nothing (a Nav2 goal tolerance is ~0.25 m).
TRAIL_SPACING_M: Final = 0.25
#: The trail keeps at most this many points (about 2.5 km of driving at the spacing above).
MAX_TRAIL_POINTS: Final = 10_000
#: Trips remembered (starts of prompts that moved the robot).
MAX_TRIPS: Final = 1_000
#: A planned route counts as driven when the next observed pose is within this of its end (Nav2's
#: goal tolerance and the executor's re-grounding move the end a little).
ROUTE_DONE_M: Final = 1.0
#: A remembered pose this close to where the robot is now is "here", not a place to go back to.
SAME_PLACE_M: Final = 0.5


@dataclass(frozen=True)
class HistoryView:
    """A snapshot: ``trail`` is the driven polyline (oldest first), ``trips`` the poses prompts that
    moved the robot started from (oldest first)."""

    trail: tuple[Point, ...] = ()
    trips: tuple[Pose, ...] = ()

    @property
    def session_start(self) -> Pose | None:
        """Where the robot was when the session's first trip began (or, before any trip, where it was
        first seen)."""
        if self.trips:
            return self.trips[0]
        return Pose(self.trail[0][0], self.trail[0][1], 0.0) if self.trail else None

    def last_trip_start_away_from(self, xy: Point) -> Pose | None:
        """The start of the latest trip that began somewhere else than ``xy`` ("where you were")."""
        for p in reversed(self.trips):
            if math.dist(p.xy, xy) > SAME_PLACE_M:
                return p
        return None


EMPTY_HISTORY: Final = HistoryView()


class PoseHistory:
    """The session's trail and trips, fed by the planner (``observe``, ``planned``) and, when it can,
    by the executor (``record``)."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._trail: list[Point] = []
        self._trips: list[Pose] = []
        self._pending: tuple[Point, ...] = ()

    def observe(self, pose: Pose) -> None:
        """The robot's real pose when a prompt arrives. A pending planned route whose end is here
        was driven: its points join the trail first."""
        with self._lock:
            if self._pending and math.dist(self._pending[-1], pose.xy) <= ROUTE_DONE_M:
                for p in self._pending:
                    self._append(p)
            self._pending = ()
            self._append(pose.xy)

    def record(self, pose: Pose | Point) -> None:
        """A pose the robot really reached (an executor's feedback): it supersedes the planned route."""
        xy = pose.xy if isinstance(pose, Pose) else (float(pose[0]), float(pose[1]))
        if not all(math.isfinite(v) for v in xy):
            return
        with self._lock:
            self._pending = ()
            self._append(xy)

    def planned(self, start: Pose, route: Sequence[Point]) -> None:
        """A plan that moves the robot was made from ``start``; ``route`` is where it should drive."""
        with self._lock:
            self._trips.append(start)
            if len(self._trips) > MAX_TRIPS:
                del self._trips[: len(self._trips) - MAX_TRIPS]
            self._pending = tuple((float(x), float(y)) for x, y in route)

    def view(self) -> HistoryView:
        with self._lock:
            return HistoryView(tuple(self._trail), tuple(self._trips))

    def clear(self) -> None:
        with self._lock:
            self._trail.clear()
            self._trips.clear()
            self._pending = ()

    def _append(self, xy: Point) -> None:
        if not all(math.isfinite(v) for v in xy):
            return
        if self._trail and math.dist(self._trail[-1], xy) < TRAIL_SPACING_M:
            return
        self._trail.append(xy)
        if len(self._trail) > MAX_TRAIL_POINTS:
            del self._trail[: len(self._trail) - MAX_TRAIL_POINTS]


def closest_approach(polyline: Sequence[Point], p: Point) -> tuple[float, float, float]:
    """(distance, arc length at the closest point, total length) of ``p`` to a polyline."""
    if not polyline:
        return (math.inf, 0.0, 0.0)
    best = (math.dist(polyline[0], p), 0.0)
    s = 0.0
    for a, b in itertools.pairwise(polyline):
        vx, vy = b[0] - a[0], b[1] - a[1]
        seg = math.hypot(vx, vy)
        if seg > 0:
            t = max(0.0, min(1.0, ((p[0] - a[0]) * vx + (p[1] - a[1]) * vy) / (seg * seg)))
            q = (a[0] + t * vx, a[1] + t * vy)
            d = math.dist(q, p)
            if d < best[0] - 1e-9:
                best = (d, s + t * seg)
        s += seg
    return (best[0], best[1], s)


__all__ = ["EMPTY_HISTORY", "HistoryView", "PoseHistory", "closest_approach"]
