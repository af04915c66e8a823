"""Frontier exploration, as explore_lite does it: "explore", "map this floor".

A *frontier* is a connected run of free cells that border unknown space on the robot's own map.
Each frontier is scored by the cost of the path to it and by its size (explore_lite's
``potential_scale * distance - gain_scale * size``); the robot drives to the best one, the map
grows, frontiers are found again every few seconds, and the goal switches when the one it was
heading for has been mapped. A frontier whose goal fails is blacklisted (as is one where the robot
makes no progress). Exploration ends when no reachable frontier is left (succeeded), when the time
or distance budget runs out (succeeded, with the reason), or when it is cancelled.

Pause holds the robot: :meth:`Explorer.pause` cancels the goal being driven to and stops the robot
at once, and no new goal is sent until :meth:`Explorer.resume` (then the frontiers are looked for
afresh from where the robot stands) or :meth:`Explorer.cancel`. Time spent paused does not count
against the time budget; a pause longer than ``pause_timeout_s`` cancels the exploration.

:func:`find_frontiers` is pure (a grid and a pose in, frontiers out); :class:`Explorer` drives any
:class:`~langnav.robot.protocol.RobotBackend` and reports :class:`~langnav.plan.events.ExecEvent`.
"""

from __future__ import annotations

import logging
import math
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Final

import numpy as np
from scipy import ndimage
from skimage.graph import MCP_Geometric

from langnav.maps.grid import OccupancyGrid
from langnav.plan.events import EventKind, EventSink, ExecEvent, PlanStatus, pose_tuple
from langnav.robot.errors import RobotError, RobotTimeout
from langnav.robot.protocol import Pose2D, RobotBackend, TaskHandle, TaskStatus
from langnav.robot.sim.costmap import InflationParams, inflate
from langnav.robot.sim.planner import traversal_costs

log = logging.getLogger(__name__)

#: Smallest frontier worth a trip (explore_lite's min_frontier_size is 0.75 m; smaller here so
#: alcoves and room corners get mapped too).
MIN_FRONTIER_SIZE_M: Final = 0.4
#: explore_lite's weights: metres of path cost against metres of frontier.
POTENTIAL_SCALE: Final = 3.0
GAIN_SCALE: Final = 1.0
#: A failed goal blacklists frontier goals within this distance of it.
BLACKLIST_RADIUS_M: Final = 0.5
#: Look for better frontiers this often while driving (explore_lite's planner_frequency 0.33 Hz).
REPLAN_PERIOD_S: Final = 3.0
#: Blacklist the goal when the robot gets no closer to it for this long (explore_lite's progress_timeout).
PROGRESS_TIMEOUT_S: Final = 30.0
PROGRESS_MIN_M: Final = 0.2
#: Default budgets: a floor of a few hundred square metres takes minutes, not hours.
DEFAULT_TIME_BUDGET_S: Final = 1800.0
DEFAULT_DISTANCE_BUDGET_M: Final = 1000.0
#: A paused exploration is cancelled if nobody resumes it within this long (the executor's rule).
DEFAULT_PAUSE_TIMEOUT_S: Final = 600.0


@dataclass(frozen=True)
class ExploreParams:
    min_frontier_size_m: float = MIN_FRONTIER_SIZE_M
    potential_scale: float = POTENTIAL_SCALE
    gain_scale: float = GAIN_SCALE
    blacklist_radius_m: float = BLACKLIST_RADIUS_M
    replan_period_s: float = REPLAN_PERIOD_S
    progress_timeout_s: float = PROGRESS_TIMEOUT_S
    time_budget_s: float = DEFAULT_TIME_BUDGET_S
    distance_budget_m: float = DEFAULT_DISTANCE_BUDGET_M
    pause_timeout_s: float = DEFAULT_PAUSE_TIMEOUT_S
    inflation: InflationParams = field(default_factory=InflationParams)


@dataclass(frozen=True)
class Frontier:
    size_m: float
    centroid_xy: tuple[float, float]
    goal_xy: tuple[float, float]   # a reachable frontier cell near the centroid
    distance_m: float              # cost of the path there, in metres of free floor
    cost: float                    # explore_lite's score: lower is better


def frontier_mask(grid: OccupancyGrid) -> np.ndarray:
    """Free cells with an unknown 4-neighbour."""
    unknown = grid.unknown
    near_unknown = ndimage.binary_dilation(unknown, structure=ndimage.generate_binary_structure(2, 1))
    return grid.free & near_unknown


def done_message(edges_left: int, given_up: int) -> str:
    """How an exploration ended, in plain words that agree with the map: when unmapped edges are
    left (out of reach, too narrow to see into, or goals that failed), say so rather than "done"."""
    if edges_left == 0:
        return "exploration done: everything I can reach is mapped"
    what = "one edge of the map is" if edges_left == 1 else f"{edges_left} edges of the map are"
    why = " (I tried and could not get there)" if given_up else ""
    return f"exploration done: {what} still unmapped, but I cannot reach {'it' if edges_left == 1 else 'them'}{why}"


def find_frontiers(grid: OccupancyGrid, pose_xy: tuple[float, float], params: ExploreParams | None = None,
                   blacklist: list[tuple[float, float]] | None = None, *,
                   reachable_only: bool = True) -> list[Frontier]:
    """The reachable frontiers of a map, best first (with ``reachable_only=False``, the others
    too, at an infinite distance). Pure."""
    p = params or ExploreParams()
    res = grid.resolution_m
    mask = frontier_mask(grid)
    if not mask.any():
        return []
    labels, n = ndimage.label(mask, structure=np.ones((3, 3), dtype=bool))
    costs = traversal_costs(inflate(grid, p.inflation), allow_unknown=False)
    r0, c0 = (int(v) for v in grid.world_to_index(*pose_xy))
    if not grid.in_bounds(r0, c0):
        return []
    costs[r0, c0] = 1.0
    cum, _ = MCP_Geometric(costs).find_costs([(r0, c0)])
    sizes = np.bincount(labels.ravel(), minlength=n + 1)
    out: list[Frontier] = []
    bl = np.asarray(blacklist or [], dtype=float).reshape(-1, 2)
    rows, cols = np.nonzero(labels)
    lab = labels[rows, cols]
    order = np.argsort(lab, kind="stable")
    rows, cols, lab = rows[order], cols[order], lab[order]
    bounds = np.searchsorted(lab, np.arange(1, n + 2))
    for k in range(1, n + 1):
        size_m = float(sizes[k]) * res
        if size_m < p.min_frontier_size_m:
            continue
        rr, cc = rows[bounds[k - 1]:bounds[k]], cols[bounds[k - 1]:bounds[k]]
        reach = cum[rr, cc]
        ok = np.isfinite(reach)
        if not ok.any():
            if not reachable_only:
                xs, ys = grid.cell_to_world(rr, cc)
                c = (float(xs.mean()), float(ys.mean()))
                out.append(Frontier(size_m, c, c, math.inf, math.inf))
            continue
        xs, ys = grid.cell_to_world(rr, cc)
        cx, cy = float(xs.mean()), float(ys.mean())
        d_centroid = np.where(ok, np.hypot(xs - cx, ys - cy), np.inf)
        i = int(np.argmin(d_centroid))
        gx, gy = float(xs[i]), float(ys[i])
        if bl.size and (np.hypot(bl[:, 0] - gx, bl[:, 1] - gy) < p.blacklist_radius_m).any():
            continue
        dist_m = float(reach[i]) * res
        out.append(Frontier(size_m, (cx, cy), (gx, gy), dist_m,
                            p.potential_scale * dist_m - p.gain_scale * size_m))
    out.sort(key=lambda f: f.cost)
    return out


class Explorer:
    """Frontier exploration on a robot. ``run()`` blocks; ``cancel()`` may come from any thread."""

    def __init__(self, robot: RobotBackend, params: ExploreParams | None = None,
                 on_event: EventSink | None = None, *, index: int | None = None, step: int | None = None,
                 clock: Callable[[], float] | None = None) -> None:
        self.robot = robot
        self.params = params or ExploreParams()
        self._sink = on_event
        self._index = index
        self._step = step
        self._cancel = threading.Event()
        self._paused = threading.Event()
        self._resume = threading.Event()
        self._lock = threading.Lock()   # the handle and the paused flag change together
        self._handle: TaskHandle | None = None
        self._paused_s = 0.0            # clock time spent paused (not charged to the budget)
        self.blacklist: list[tuple[float, float]] = []
        self.goals_reached = 0
        self.distance_m = 0.0
        self._t0 = time.monotonic()
        self._clock = clock or self._default_clock
        self._robot_t0 = float(robot.state().time_s)

    def _default_clock(self) -> float:
        """Seconds since the explorer was made: the robot's clock (the simulator's, which may run
        faster than real time) or the wall clock, whichever has gone further (a backend whose
        state carries no time still gets its budget enforced)."""
        return max(float(self.robot.state().time_s) - self._robot_t0, time.monotonic() - self._t0)

    def cancel(self) -> None:
        self._cancel.set()
        self._resume.set()
        with self._lock:
            handle = self._handle
        if handle is not None:
            handle.cancel()
        self._stop_robot()

    def pause(self) -> None:
        """Stop the robot now and send no goal until :meth:`resume` (or :meth:`cancel`)."""
        with self._lock:
            self._resume.clear()
            self._paused.set()
            handle = self._handle
        if handle is not None:
            handle.cancel()
        self._stop_robot()

    def resume(self) -> None:
        self._paused.clear()
        self._resume.set()

    @property
    def paused(self) -> bool:
        return self._paused.is_set()

    def _stop_robot(self) -> None:
        try:
            self.robot.stop()
        except RobotError as exc:  # a lost link: the backend's own watchdog stops the base
            log.warning("stop failed: %s", exc)

    def _hold(self) -> bool:
        """Paused: keep the robot stopped until resumed; False when cancelled (or paused too long)."""
        t0 = self._clock()
        self._stop_robot()
        self._emit(EventKind.PAUSED, "paused: the robot stopped")
        resumed = self._resume.wait(self.params.pause_timeout_s)
        self._paused_s += self._clock() - t0
        if not resumed or self._cancel.is_set():
            return False
        self._emit(EventKind.RESUMED, "resumed: exploring again")
        return True

    def _emit(self, kind: EventKind, message: str, **extra: object) -> None:
        if self._sink is None:
            return
        pose = self.robot.get_robot_pose()
        self._sink(ExecEvent(kind=kind, index=self._index, step=self._step, text="Explore", message=message,
                             pose=pose_tuple(pose), time_s=round(time.monotonic() - self._t0, 3),
                             **extra))  # type: ignore[arg-type]

    def _figures(self, grid: OccupancyGrid, frontiers: int) -> dict[str, float | int]:
        return {"known_free_m2": round(float(grid.free.sum()) * grid.cell_area_m2, 2),
                "frontiers": frontiers, "goals_reached": self.goals_reached,
                "blacklisted": len(self.blacklist), "distance_m": round(self.distance_m, 2)}

    def run(self) -> PlanStatus:
        """Explore until nothing reachable is left, the budget runs out, or cancel(). Emits events;
        returns SUCCEEDED (done or budget spent) or CANCELLED."""
        p = self.params
        start_t = self._clock()
        last = self.robot.get_robot_pose()
        self._emit(EventKind.STARTED, "exploring: looking for the edges of the map")
        while True:
            if self._paused.is_set() and not self._hold():
                self._cancel.set()
            if self._cancel.is_set():
                self._emit(EventKind.CANCELLED, "exploration cancelled")
                return PlanStatus.CANCELLED
            spent = self._clock() - start_t - self._paused_s
            if spent >= p.time_budget_s or self.distance_m >= p.distance_budget_m:
                grid = self.robot.get_map()
                self._emit(EventKind.SUCCEEDED, f"exploration budget spent ({spent:.0f} s, {self.distance_m:.0f} m)",
                           data=self._figures(grid, -1))
                return PlanStatus.SUCCEEDED
            grid = self.robot.get_map()
            pose = self.robot.get_robot_pose()
            frontiers = find_frontiers(grid, (pose.x_m, pose.y_m), p, self.blacklist)
            if not frontiers:
                left = len(find_frontiers(grid, (pose.x_m, pose.y_m), p, None, reachable_only=False))
                figures = {**self._figures(grid, 0), "edges_left": left}
                self._emit(EventKind.SUCCEEDED, done_message(left, len(self.blacklist)), data=figures)
                return PlanStatus.SUCCEEDED
            target = frontiers[0]
            self._emit(EventKind.PROGRESS,
                       f"heading for the edge of what I have mapped, {target.distance_m:.0f} m away",
                       data=self._figures(grid, len(frontiers)))
            last = self._drive_to(target, last)

    def _drive_to(self, target: Frontier, last: Pose2D) -> Pose2D:
        """Drive towards one frontier until it is reached, mapped, failed, stalled or a better one
        shows up. Returns the last pose (for the distance tally)."""
        p = self.params
        with self._lock:
            if self._paused.is_set() or self._cancel.is_set():
                return last  # paused or cancelled while the frontiers were being worked out
            handle = self.robot.navigate_through_poses([target.goal_xy])
            self._handle = handle
        goal = target.goal_xy
        best_d = math.inf
        best_t = self._clock()
        try:
            while True:
                try:
                    result = handle.wait(p.replan_period_s)
                except RobotTimeout:
                    result = None
                pose = self.robot.get_robot_pose()
                self.distance_m += math.hypot(pose.x_m - last.x_m, pose.y_m - last.y_m)
                last = pose
                if result is not None and result.status is TaskStatus.CANCELED and (
                        self._paused.is_set() or self._cancel.is_set()):
                    return last  # our own pause or cancel: not the frontier's fault
                if result is not None:
                    if result.status is TaskStatus.SUCCEEDED:
                        self.goals_reached += 1
                        if self._still_frontier(self.robot.get_map(), goal):
                            # reached, yet nothing more can be seen from there (an opening to the
                            # unmapped outside, a lidar shadow): do not come back
                            self.blacklist.append(goal)
                    elif result.status is TaskStatus.FAILED:
                        log.info("frontier goal (%.2f, %.2f) failed: %s", *goal, result.message)
                        self.blacklist.append(goal)
                    return last
                if self._cancel.is_set() or self._paused.is_set():
                    handle.cancel()
                    return last
                d = math.hypot(goal[0] - pose.x_m, goal[1] - pose.y_m)
                now = self._clock()
                if d < best_d - PROGRESS_MIN_M:
                    best_d, best_t = d, now
                elif now - best_t > p.progress_timeout_s:
                    log.info("no progress towards frontier (%.2f, %.2f): blacklisted", *goal)
                    self.blacklist.append(goal)
                    handle.cancel()
                    return last
                # is the frontier still there, and still the best?
                grid = self.robot.get_map()
                if not self._still_frontier(grid, goal):
                    handle.cancel()
                    return last
        finally:
            with self._lock:
                self._handle = None

    @staticmethod
    def _still_frontier(grid: OccupancyGrid, goal: tuple[float, float], radius_m: float = 0.3) -> bool:
        """Whether unknown space still borders free space near the goal."""
        r, c = (int(v) for v in grid.world_to_index(*goal))
        k = max(1, round(radius_m / grid.resolution_m))
        window = (slice(max(r - k, 0), r + k + 1), slice(max(c - k, 0), c + k + 1))
        cells = grid.cells[window]
        if cells.size == 0:
            return False
        unknown = cells == -1
        free = cells == 0
        near = ndimage.binary_dilation(unknown, structure=ndimage.generate_binary_structure(2, 1))
        return bool((free & near).any())


def explore(robot: RobotBackend, params: ExploreParams | None = None, on_event: EventSink | None = None) -> PlanStatus:
    """Run an exploration to its end (the budget in ``params`` bounds it)."""
    return Explorer(robot, params, on_event).run()
