"""The embedded simulator backend: a differential-drive robot with a lidar, mapping as it goes,
navigating like Nav2 (costmap with inflation, global planner, regulated pure pursuit, replanning).

Time. The simulator keeps its own clock. Headless, nothing moves until someone calls
:meth:`SimBackend.step` or waits on a task handle: ``wait()`` then drives the clock itself, as fast
as the CPU allows, and its timeout is in *simulated* seconds (so tests are fast and deterministic).
After :meth:`SimBackend.start` a thread drives the clock (in real time for the web view, or
free-running) and ``wait()`` blocks on an event with a wall-clock timeout. Only one thing should
drive the clock: either the thread, or one waiting caller.

Commands (the seven of :class:`~langnav.robot.protocol.RobotBackend`):

* ``navigate_through_poses``: plan through every pose on the robot's *own* map (unknown space may
  be crossed, as NavFn's ``allow_unknown``), follow the path, replan when a scan shows the path
  blocked (and every few seconds while the map changes), fail with a reason when no path exists,
  when the robot makes no progress, or when the bumper is hit. Intermediate poses count as passed
  within 0.5 m; the last within the goal tolerance (0.25 m), then turn to its yaw if one is given.
* ``move``: 3 cm steps. A differential base cannot drive sideways, so ``left`` / ``right`` turn
  90 degrees that way, drive, and turn back to the original heading. A move stops and fails when
  the robot's map shows an obstacle in the way (like Nav2's DriveOnHeading "collision ahead").
* ``rotate``: 10 degree steps, left = counter-clockwise, turning in place.
* ``stop``: cancels whatever runs and zeroes the velocity at once.

Teleop (``set_velocity``, what ``/cmd_vel`` drives over rosbridge): the base follows a commanded
(linear, angular) velocity, within its speed and acceleration limits, for ``TELEOP_TIMEOUT_S`` of
robot time after the last command, then brakes to a stop (a cmd_vel timeout, as
diff_drive_controller's ``cmd_vel_timeout``). A non-zero command cancels a running task (its
handle ends CANCELED), as teleop overrides Nav2 through a twist mux; a zero command only stops
teleop motion and never cancels a task (a released joystick, or a watchdog's zero). Like Nav2's
collision monitor, a teleop drive that its map shows running into an obstacle within braking
distance is stopped (turning in place stays allowed); the bumper is the last resort.
``stop()`` holds against teleop too: a joystick still held when STOP (or Pause) was pressed keeps
publishing its velocity, and the robot must not lurch off again by itself. After ``stop()`` non-zero
velocity commands are ignored until a zero command comes (the stick released, or a teleop
panel's own stop), as a dead-man switch must be let go before the robot moves again.

A new task preempts the one running (its handle ends CANCELED), as a new Nav2 goal does, and ends
teleop.
Determinism: the only randomness is the lidar noise, drawn from ``numpy.random.default_rng(seed)``;
headless runs with the same seed and the same calls give the same trajectory.
"""

from __future__ import annotations

import logging
import math
import threading
import time
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Final

import numpy as np
import numpy.typing as npt

from langnav.maps.grid import OCCUPIED, OccupancyGrid
from langnav.maps.io import load_map
from langnav.robot.errors import RobotError, RobotTimeout
from langnav.robot.protocol import (
    DEFAULT_REQUEST_TIMEOUT_S,
    DEFAULT_TASK_TIMEOUT_S,
    LaserScan,
    Pose2D,
    RobotState,
    TaskFeedback,
    TaskResult,
    TaskStatus,
)
from langnav.robot.sim.controller import (
    TIGHT_LOOKAHEAD_M,
    XY_GOAL_TOLERANCE_M,
    YAW_GOAL_TOLERANCE_RAD,
    Limits,
    pure_pursuit,
    ramp,
    rotate_command,
    stopping_speed,
    wrap_angle,
)
from langnav.robot.sim.costmap import InflationParams, inflate
from langnav.robot.sim.lidar import Lidar, LidarSpec
from langnav.robot.sim.mapping import LogOddsMap
from langnav.robot.sim.planner import (
    NoPathError,
    WalledOffError,
    path_length_m,
    plan,
    traversal_costs,
)
from langnav.robot.sim.world import ROBOT_RADIUS_M, World, disc_clearances_m

log = logging.getLogger(__name__)

#: Controller rate: Nav2's controller_frequency is 20 Hz.
CONTROL_DT_S: Final = 0.05
#: Lidar rate: an RPLIDAR A1 spins at 5.5-10 Hz.
SCAN_PERIOD_S: Final = 0.2
#: Replan this often while the map keeps changing (paths through unknown space get better).
REPLAN_PERIOD_S: Final = 3.0
#: Plan in a window reaching this far beyond start and goal (a detour through a neighbouring
#: room fits), ...
PLAN_MARGIN_M: Final = 10.0
#: ... grown this many times over while the goal is walled off in it, up to the whole map.
PLAN_GROWTH: Final = 4
#: An intermediate pose of NavigateThroughPoses counts as passed within this distance.
VIA_TOLERANCE_M: Final = 0.5
#: Give up after this many failed plans in a row, retrying once a second (Nav2's recoveries).
MAX_PLAN_FAILURES: Final = 3
PLAN_RETRY_S: Final = 1.0
#: Nav2's progress checker: the robot must move this far ...
PROGRESS_MIN_M: Final = 0.25
#: ... within this long, or the goal fails.
PROGRESS_TIMEOUT_S: Final = 20.0
#: A robot that an obstacle keeps from getting nearer has reached its goal within this distance
#: (Nav2's default xy_goal_tolerance).
NEAR_GOAL_M: Final = 0.25
#: Stopped this long by an obstacle in the way (on the robot's map): replan.
BLOCKED_REPLAN_S: Final = 1.0
#: Look this far along the path for new obstacles after each scan.
BLOCK_CHECK_M: Final = 2.0
#: Extra clearance kept when checking the way ahead (the lidar noise, a cell of map error).
SAFETY_MARGIN_M: Final = 0.02
#: Straight drives and turns end within these tolerances.
DRIVE_TOLERANCE_M: Final = 0.003
TURN_TOLERANCE_RAD: Final = math.radians(0.5)
MIN_DRIVE_MPS: Final = 0.02
#: Heading hold gain while driving straight (rad/s per rad of drift).
HEADING_GAIN: Final = 2.0
#: A teleop velocity is held this long (robot time) after the last command, then the base stops:
#: diff_drive_controller's default cmd_vel_timeout, so a dropped teleop link cannot run the robot away.
TELEOP_TIMEOUT_S: Final = 0.5
MOVE_STEP_M: Final = 0.03
ROTATE_STEP_RAD: Final = math.radians(10.0)
MOVE_DIRECTIONS: Final = ("forward", "backward", "left", "right")
ROTATE_DIRECTIONS: Final = ("left", "right")

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True)
class SimConfig:
    seed: int = 0
    known_map: bool = False
    robot_radius_m: float = ROBOT_RADIUS_M
    control_dt_s: float = CONTROL_DT_S
    scan_period_s: float = SCAN_PERIOD_S
    replan_period_s: float = REPLAN_PERIOD_S
    limits: Limits = field(default_factory=Limits)
    lidar: LidarSpec = field(default_factory=LidarSpec)
    inflation: InflationParams = field(default_factory=InflationParams)


# ---------------------------------------------------------------------------------------------
# tasks: one per long action; tick() returns the velocity the task commands for this step


class _Task:
    kind = "task"

    def __init__(self, sim: SimBackend) -> None:
        self.status = TaskStatus.RUNNING
        self.message = ""
        self.done = threading.Event()
        self.started_s = sim.time_s
        self.result: TaskResult | None = None

    def tick(self, sim: SimBackend, dt: float) -> tuple[float, float]:
        raise NotImplementedError

    def feedback(self, sim: SimBackend) -> TaskFeedback:
        return TaskFeedback(pose=sim.pose, elapsed_s=sim.time_s - self.started_s)

    def finish(self, sim: SimBackend, status: TaskStatus, message: str) -> None:
        if self.done.is_set():
            return
        self.status = status
        self.message = message
        self.result = TaskResult(status, message, sim.pose)
        log.debug("%s %s: %s", self.kind, status.value, message)
        self.done.set()

    def path(self) -> list[tuple[float, float]]:
        return []

    def goals(self) -> list[tuple[float, float]]:
        return []


class _Phase:
    """One straight drive or one turn in place, measured from where it starts."""

    def __init__(self, drive_m: float = 0.0, turn_rad: float = 0.0) -> None:
        self.drive_m = drive_m
        self.turn_rad = turn_rad
        self.start: Pose2D | None = None
        self.turned_rad = 0.0
        self.last_yaw = 0.0

    def begin(self, pose: Pose2D) -> None:
        self.start = pose
        self.last_yaw = pose.yaw_rad

    def travelled_m(self, pose: Pose2D) -> float:
        assert self.start is not None
        dx, dy = pose.x_m - self.start.x_m, pose.y_m - self.start.y_m
        return math.cos(self.start.yaw_rad) * dx + math.sin(self.start.yaw_rad) * dy

    def remaining(self, pose: Pose2D) -> float:
        """Metres (drive) or radians (turn) still to go, signed."""
        if self.drive_m:
            return self.drive_m - self.travelled_m(pose)
        return self.turn_rad - self.turned_rad


class _StepsTask(_Task):
    """Move and Rotate: a list of drives and turns, done in order."""

    def __init__(self, sim: SimBackend, kind: str, phases: list[_Phase], description: str) -> None:
        super().__init__(sim)
        self.kind = kind
        self.phases = phases
        self.i = 0
        self.description = description
        phases[0].begin(sim.pose)

    def tick(self, sim: SimBackend, dt: float) -> tuple[float, float]:
        lim = sim.config.limits
        while self.i < len(self.phases):
            ph = self.phases[self.i]
            pose = sim.pose
            if ph.turn_rad:
                ph.turned_rad += wrap_angle(pose.yaw_rad - ph.last_yaw)
                ph.last_yaw = pose.yaw_rad
            rem = ph.remaining(pose)
            tol = DRIVE_TOLERANCE_M if ph.drive_m else TURN_TOLERANCE_RAD
            if abs(rem) > tol:
                break
            if abs(sim.linear_mps) > MIN_DRIVE_MPS or abs(sim.angular_radps) > 0.1:
                return 0.0, 0.0  # let the base settle before the next phase
            self.i += 1
            if self.i < len(self.phases):
                self.phases[self.i].begin(pose)
        else:
            self.finish(sim, TaskStatus.SUCCEEDED, f"{self.description}: done")
            return 0.0, 0.0
        if ph.turn_rad:
            return 0.0, rotate_command(rem, lim)
        # straight drive: brake before the end, hold the heading, look ahead for obstacles
        speed = max(stopping_speed(abs(rem), lim.max_linear_mps, lim.max_linear_accel_mps2), MIN_DRIVE_MPS)
        speed = min(speed, abs(rem) / dt)
        v = math.copysign(speed, rem)
        assert ph.start is not None
        w = HEADING_GAIN * wrap_angle(ph.start.yaw_rad - pose.yaw_rad)
        brake_m = v * v / (2.0 * lim.max_linear_accel_mps2)
        look = min(abs(rem), brake_m + 2 * SAFETY_MARGIN_M + abs(v) * dt)
        heading = pose.yaw_rad if v > 0 else pose.yaw_rad + math.pi
        ahead = (pose.x_m + look * math.cos(heading), pose.y_m + look * math.sin(heading))
        if sim.map_blocks(pose.x_m, pose.y_m, *ahead):
            done_m = abs(ph.travelled_m(pose))
            self.finish(sim, TaskStatus.FAILED,
                        f"{self.description}: obstacle ahead, stopped after {done_m:.2f} of "
                        f"{abs(ph.drive_m):.2f} m")
            return 0.0, 0.0
        return v, w

    def feedback(self, sim: SimBackend) -> TaskFeedback:
        pose = sim.pose
        drive = 0.0
        turn = 0.0
        for k, ph in enumerate(self.phases[self.i:], start=self.i):
            if ph.drive_m:
                drive += abs(ph.remaining(pose)) if k == self.i else abs(ph.drive_m)
            else:
                turn += abs(ph.remaining(pose)) if k == self.i else abs(ph.turn_rad)
        drives = any(ph.drive_m for ph in self.phases)
        turns = any(ph.turn_rad for ph in self.phases)
        return TaskFeedback(pose=pose, distance_remaining_m=drive if drives else None,
                            elapsed_s=sim.time_s - self.started_s, angle_remaining_rad=turn if turns else None,
                            message=self.description)


class _NavTask(_Task):
    kind = "navigate"

    def __init__(self, sim: SimBackend, poses: list[tuple[float, float, float | None]]) -> None:
        super().__init__(sim)
        self.poses = poses
        self.target = 0  # index of the next pose to pass
        self.path_xy: FloatArray | None = None
        self.path_i = 0
        self.need_plan = True
        self.plan_failures = 0
        self.next_plan_s = sim.time_s
        self.planned_s = -math.inf
        self.planned_map_version = -1
        self.recoveries = 0
        self.final_turn = False
        self.anchor = sim.pose
        self.anchor_s = sim.time_s
        self.checked_map_version = -1
        self.blocked_steps = 0
        self.planned_goal: tuple[float, float] | None = None

    def goals(self) -> list[tuple[float, float]]:
        return [(x, y) for x, y, _ in self.poses[self.target:]]

    def path(self) -> list[tuple[float, float]]:
        if self.path_xy is None:
            return []
        return [(float(x), float(y)) for x, y in self.path_xy[self.path_i:]]

    def _replan(self, sim: SimBackend) -> bool:
        pose = sim.pose
        try:
            pts: list[tuple[float, float]] = []
            start = (pose.x_m, pose.y_m)
            for x, y, _ in self.poses[self.target:]:
                seg = sim.plan_path(start, (x, y))
                pts.extend(seg if not pts else seg[1:])
                start = seg[-1]
        except NoPathError as exc:
            self.plan_failures += 1
            self.path_xy = None
            if self.plan_failures >= MAX_PLAN_FAILURES:
                self.finish(sim, TaskStatus.FAILED, f"cannot reach the goal: {exc}")
            else:
                self.recoveries += 1
                self.next_plan_s = sim.time_s + PLAN_RETRY_S
            return False
        self.plan_failures = 0
        self.path_xy = np.asarray(pts, dtype=np.float64)
        self.planned_goal = pts[-1]
        self.path_i = 0
        self.need_plan = False
        self.planned_s = sim.time_s
        self.planned_map_version = sim.map_cells_version
        return True

    def tick(self, sim: SimBackend, dt: float) -> tuple[float, float]:
        pose = sim.pose
        lim = sim.config.limits
        while self.target < len(self.poses) - 1 and math.hypot(
                self.poses[self.target][0] - pose.x_m, self.poses[self.target][1] - pose.y_m) < VIA_TOLERANCE_M:
            self.target += 1
        gx, gy, gyaw = self.poses[-1]
        if self.target == len(self.poses) - 1 and self.planned_goal is not None:
            # the planner may have moved a goal that is too close to an obstacle (planner tolerance)
            gx, gy = self.planned_goal
        last = self.target == len(self.poses) - 1
        if self.final_turn or (last and math.hypot(gx - pose.x_m, gy - pose.y_m) < XY_GOAL_TOLERANCE_M):
            self.final_turn = True
            if gyaw is None:
                return self._succeed(sim)
            err = wrap_angle(gyaw - pose.yaw_rad)
            if abs(err) < YAW_GOAL_TOLERANCE_RAD / 2:
                return self._succeed(sim)
            return 0.0, rotate_command(err, lim)
        # no-progress check (Nav2's progress checker)
        if math.hypot(pose.x_m - self.anchor.x_m, pose.y_m - self.anchor.y_m) >= PROGRESS_MIN_M:
            self.anchor, self.anchor_s = pose, sim.time_s
        elif sim.time_s - self.anchor_s > PROGRESS_TIMEOUT_S:
            if last and math.hypot(gx - pose.x_m, gy - pose.y_m) < NEAR_GOAL_M:
                return self._succeed(sim)
            self.finish(sim, TaskStatus.FAILED,
                        f"no progress: the robot moved less than {PROGRESS_MIN_M} m in {PROGRESS_TIMEOUT_S:.0f} s")
            return 0.0, 0.0
        # replanning: when asked, when a scan showed the path blocked, or periodically as the map grows
        if self.path_xy is not None and self.checked_map_version != sim.map_cells_version:
            self.checked_map_version = sim.map_cells_version
            if sim.path_blocked(self.path_xy, self.path_i):
                log.debug("path blocked at t=%.1f s: replanning", sim.time_s)
                self.need_plan = True
            elif (sim.time_s - self.planned_s >= sim.config.replan_period_s
                  and sim.map_cells_version != self.planned_map_version):
                self.need_plan = True
        if (self.need_plan or self.path_xy is None) and (sim.time_s < self.next_plan_s or not self._replan(sim)):
            return 0.0, 0.0
        assert self.path_xy is not None
        cmd = pure_pursuit(pose.as_tuple(), self.path_xy, self.path_i, sim.linear_mps, lim)
        self.path_i = cmd.index
        if sim.motion_blocked(pose, cmd.linear_mps, cmd.angular_radps, dt):
            # the carrot cuts a corner: hug the path instead; if even that is blocked, stop and replan
            cmd = pure_pursuit(pose.as_tuple(), self.path_xy, self.path_i, sim.linear_mps, lim,
                               max_lookahead_m=TIGHT_LOOKAHEAD_M)
            if sim.motion_blocked(pose, cmd.linear_mps, cmd.angular_radps, dt):
                if last and math.hypot(gx - pose.x_m, gy - pose.y_m) < NEAR_GOAL_M:
                    return self._succeed(sim)  # as near as the obstacles let it: Nav2's tolerance
                self.blocked_steps += 1
                if self.blocked_steps * dt >= BLOCKED_REPLAN_S:
                    self.need_plan = True
                    self.recoveries += 1
                    self.blocked_steps = 0
                return 0.0, 0.0
        self.blocked_steps = 0
        return cmd.linear_mps, cmd.angular_radps

    def _succeed(self, sim: SimBackend) -> tuple[float, float]:
        if sim.linear_mps != 0.0 or sim.angular_radps != 0.0:
            return 0.0, 0.0  # brake to a stop first: a goal is reached when the robot stands on it
        gx, gy, _ = self.poses[-1]
        self.path_xy = None
        pose = sim.pose
        off = math.hypot(gx - pose.x_m, gy - pose.y_m)
        self.finish(sim, TaskStatus.SUCCEEDED, f"reached ({gx:.2f}, {gy:.2f}), {off:.2f} m away")
        return 0.0, 0.0

    def feedback(self, sim: SimBackend) -> TaskFeedback:
        pose = sim.pose
        path = self.path()
        remaining = path_length_m([(pose.x_m, pose.y_m), *path]) if path else math.hypot(
            self.poses[-1][0] - pose.x_m, self.poses[-1][1] - pose.y_m)
        return TaskFeedback(pose=pose, distance_remaining_m=remaining, elapsed_s=sim.time_s - self.started_s,
                            poses_remaining=len(self.poses) - self.target, recoveries=self.recoveries,
                            message="turning to the goal heading" if self.final_turn else "following the path")


# ---------------------------------------------------------------------------------------------


class SimTaskHandle:
    """The handle of one simulated task (see the module docstring for how ``wait`` keeps time)."""

    def __init__(self, sim: SimBackend, task: _Task) -> None:
        self._sim = sim
        self._task = task

    def status(self) -> TaskStatus:
        return self._task.status

    def feedback(self) -> TaskFeedback | None:
        with self._sim.lock:
            return self._task.feedback(self._sim)

    def cancel(self) -> None:
        self._sim.cancel_task(self._task, "canceled")

    def wait(self, timeout_s: float = DEFAULT_TASK_TIMEOUT_S) -> TaskResult:
        self._sim.wait_event(self._task.done, timeout_s, what=f"the {self._task.kind} task")
        assert self._task.result is not None
        return self._task.result


class SimBackend:
    """The simulated robot. See the module docstring."""

    name = "sim"

    def __init__(self, world: OccupancyGrid | World, pose: Pose2D, config: SimConfig | None = None) -> None:
        self.config = config or SimConfig()
        self.world = world if isinstance(world, World) else World(world)
        frame = self.world.frame
        self.lock = threading.RLock()
        self._rng = np.random.default_rng(self.config.seed)
        self._lidar = Lidar(self.world, self.config.lidar)
        self._map = LogOddsMap(frame, known=self.world.frame if self.config.known_map else None)
        check_start(self.world, pose, self.config.robot_radius_m)
        self._pose = Pose2D(pose.x_m, pose.y_m, wrap_angle(pose.yaw_rad))
        self._v = 0.0
        self._w = 0.0
        self._t = 0.0
        self._steps = 0
        self._task: _Task | None = None
        #: teleop: (linear_mps, angular_radps, held until this robot time)
        self._teleop: tuple[float, float, float] | None = None
        #: how often teleop was kept from driving into an obstacle (the collision monitor's stops)
        self.teleop_blocks = 0
        self._teleop_blocked = False
        #: set by stop(): teleop is ignored until a zero velocity command releases it
        self._teleop_held = False
        self._scan: LaserScan | None = None
        self._next_scan_s = 0.0
        self._occupied = self._map.cells() == OCCUPIED
        self.map_cells_version = 0
        self.collisions = 0
        self._thread: threading.Thread | None = None
        self._halt = threading.Event()
        self._closed = False
        self._sense()

    # -- clock ------------------------------------------------------------------------------------
    @property
    def time_s(self) -> float:
        return self._t

    @property
    def steps(self) -> int:
        return self._steps

    @property
    def pose(self) -> Pose2D:
        return self._pose

    @property
    def linear_mps(self) -> float:
        return self._v

    @property
    def angular_radps(self) -> float:
        return self._w

    @property
    def running(self) -> bool:
        return self._thread is not None and self._thread.is_alive()

    def step(self, dt_s: float | None = None) -> None:
        """Advance the simulation by ``dt_s`` (default one control period), in control periods."""
        n = 1 if dt_s is None else max(1, round(dt_s / self.config.control_dt_s))
        for _ in range(n):
            with self.lock:
                self._step_once()

    def start(self, realtime: bool = True, speed: float = 1.0) -> None:
        """Run the clock in a thread: in real time (times ``speed``) for a live view, or free-running."""
        if self.running:
            return
        if self._closed:
            raise RobotError("the simulator is closed; create a new one")
        if speed <= 0:
            raise RobotError(f"speed must be positive, got {speed}")
        self._halt.clear()
        self._thread = threading.Thread(target=self._loop, args=(realtime, speed), name="langnav-sim", daemon=True)
        self._thread.start()

    def stop_thread(self, timeout_s: float = DEFAULT_REQUEST_TIMEOUT_S) -> None:
        self._halt.set()
        if self._thread is not None:
            self._thread.join(timeout_s)
            if self._thread.is_alive():
                raise RobotTimeout(f"the simulator thread did not stop within {timeout_s} s")
        self._thread = None

    def _loop(self, realtime: bool, speed: float) -> None:
        dt = self.config.control_dt_s
        t0 = time.monotonic()
        n = 0
        while not self._halt.is_set():
            self.step()
            n += 1
            if realtime:
                due = t0 + n * dt / speed
                lag = due - time.monotonic()
                if lag > 0:
                    self._halt.wait(lag)
                elif lag < -0.5:  # fell far behind (a slow machine): do not try to catch up
                    t0, n = time.monotonic(), 0

    def wait_event(self, event: threading.Event, timeout_s: float, what: str = "the robot") -> None:
        """Wait for ``event``: on the wall clock when the thread runs, else by driving the sim clock."""
        if event.is_set():
            return
        if self.running:
            if not event.wait(timeout_s):
                raise RobotTimeout(f"{what} is still running after {timeout_s:.1f} s; it was left running")
            return
        deadline = self._t + timeout_s
        while not event.is_set():
            if self._t >= deadline - 1e-9:
                raise RobotTimeout(f"{what} is still running after {timeout_s:.1f} s of simulated time; "
                                   "it was left running")
            if self.running:  # a thread took over the clock meanwhile
                self.wait_event(event, max(deadline - self._t, 0.0), what)
                return
            self.step()

    # -- one control period -------------------------------------------------------------------------
    def _step_once(self) -> None:
        cfg = self.config
        dt = cfg.control_dt_s
        self._t += dt
        self._steps += 1
        if self._t + 1e-9 >= self._next_scan_s:
            self._sense()
        v_cmd, w_cmd = (0.0, 0.0)
        if self._task is not None:
            v_cmd, w_cmd = self._task.tick(self, dt)
            if self._task.done.is_set():
                self._task = None
                v_cmd, w_cmd = 0.0, 0.0
        elif self._teleop is not None:
            v_cmd, w_cmd = self._teleop_tick(dt)
        lim = cfg.limits
        v = ramp(self._v, max(-lim.max_linear_mps, min(lim.max_linear_mps, v_cmd)), lim.max_linear_accel_mps2 * dt)
        w = ramp(self._w, max(-lim.max_angular_radps, min(lim.max_angular_radps, w_cmd)),
                 lim.max_angular_accel_radps2 * dt)
        if v == 0.0 and w == 0.0:
            self._v = self._w = 0.0
            return
        p = self._pose
        mid = p.yaw_rad + 0.5 * w * dt
        nx, ny = p.x_m + v * dt * math.cos(mid), p.y_m + v * dt * math.sin(mid)
        if v != 0.0 and self.world.collides(nx, ny, cfg.robot_radius_m):
            self.collisions += 1
            self._v = self._w = 0.0
            log.warning("bumper hit at (%.2f, %.2f)", nx, ny)
            self._teleop = None
            if self._task is not None:
                self._task.finish(self, TaskStatus.FAILED, f"collision: the bumper hit something at "
                                                            f"({nx:.2f}, {ny:.2f}); stopped")
                self._task = None
            return
        self._pose = Pose2D(nx, ny, wrap_angle(p.yaw_rad + w * dt))
        self._v, self._w = v, w

    def _teleop_tick(self, dt: float) -> tuple[float, float]:
        """The teleop velocity for this step: zero once the command timed out, or when driving on
        would hit an obstacle of the robot's map before the base could brake."""
        assert self._teleop is not None
        v, w, until_s = self._teleop
        if self._t > until_s + 1e-9:
            self._teleop = None
            log.debug("teleop: no velocity command for %.1f s: stopping", TELEOP_TIMEOUT_S)
            return 0.0, 0.0
        lim = self.config.limits
        v = max(-lim.max_linear_mps, min(lim.max_linear_mps, v))
        w = max(-lim.max_angular_radps, min(lim.max_angular_radps, w))
        blocked = v != 0.0 and self.motion_blocked(self._pose, v, w, dt)
        if blocked:
            if not self._teleop_blocked:
                self.teleop_blocks += 1
                log.info("teleop: obstacle ahead of (%.2f, %.2f): linear velocity held at zero",
                         self._pose.x_m, self._pose.y_m)
            v = 0.0
        self._teleop_blocked = blocked
        return v, w

    def _sense(self) -> None:
        p = self._pose
        ranges = self._lidar.scan(p.x_m, p.y_m, p.yaw_rad, self._rng)
        spec = self._lidar.spec
        changed = self._map.integrate(p.x_m, p.y_m, p.yaw_rad, self._lidar.angles_rad, ranges, spec.range_max_m)
        self._scan = LaserScan(spec.angle_min_rad, spec.angle_increment_rad, spec.range_max_m,
                               tuple(ranges.tolist()), p)
        if changed is not None:  # only the scan's window can have changed
            self._occupied[changed] = self._map.cells()[changed] == OCCUPIED
            self.map_cells_version += 1
        self._next_scan_s = self._t + self.config.scan_period_s

    # -- perception helpers used by tasks -------------------------------------------------------------
    def plan_path(self, start_xy: tuple[float, float], goal_xy: tuple[float, float]) -> list[tuple[float, float]]:
        """A path on the robot's map, planned in a window around start and goal (PLAN_MARGIN_M
        around them, grown PLAN_GROWTH times while the goal is walled off in it, up to the whole
        map): the cost scales with the trip, not with the map. The costmap is inflated over the
        window plus the inflation radius, so obstacles just outside it still count."""
        frame = self.world.frame
        for what, (x, y) in (("start", start_xy), ("goal", goal_xy)):
            r, c = (float(v) for v in frame.world_to_cell(x, y))
            if not (0.0 <= r < frame.height and 0.0 <= c < frame.width):
                raise NoPathError(f"the {what} ({x:.2f}, {y:.2f}) is outside the map (extent {_extent(frame)})")
        rs, cs = frame.world_to_index([start_xy[0], goal_xy[0]], [start_xy[1], goal_xy[1]])
        h, w = frame.height, frame.width
        pad = math.ceil(self.config.inflation.inflation_radius_m / frame.resolution_m) + 1
        margin = math.ceil(PLAN_MARGIN_M / frame.resolution_m)
        while True:
            r0, r1 = max(int(rs.min()) - margin, 0), min(int(rs.max()) + margin + 1, h)
            c0, c1 = max(int(cs.min()) - margin, 0), min(int(cs.max()) + margin + 1, w)
            whole = r0 == 0 and c0 == 0 and r1 == h and c1 == w
            p0, p1 = max(r0 - pad, 0), min(r1 + pad, h)
            q0, q1 = max(c0 - pad, 0), min(c1 + pad, w)
            costmap = inflate(self._map.window_grid(slice(p0, p1), slice(q0, q1)), self.config.inflation)
            costs = traversal_costs(costmap)
            inner = np.zeros(costs.shape, dtype=bool)
            inner[r0 - p0:r1 - p0, c0 - q0:c1 - q0] = True
            costs[~inner] = np.inf  # the pad only informs the inflation
            try:
                return plan(costmap, start_xy, goal_xy, costs=costs)
            except WalledOffError:
                if whole:
                    raise
                margin *= PLAN_GROWTH
                log.debug("no path within %.0f m of start and goal: searching a wider window",
                          margin * frame.resolution_m / PLAN_GROWTH)

    def map_blocks(self, x0: float, y0: float, x1: float, y1: float) -> bool:
        """Whether the robot's map shows an obstacle in the robot's way from (x0, y0) to (x1, y1):
        a disc on the way has less clearance than needed and less than where it starts."""
        frame = self.world.frame
        need = self.config.robot_radius_m + SAFETY_MARGIN_M
        n = max(1, math.ceil(math.hypot(x1 - x0, y1 - y0) / frame.resolution_m))
        k = np.arange(n + 1) / n
        c = disc_clearances_m(self._occupied, frame, x0 + (x1 - x0) * k, y0 + (y1 - y0) * k, need)
        return bool(((c[1:] < need) & (c[1:] < c[0])).any())

    def motion_blocked(self, pose: Pose2D, v: float, w: float, dt: float) -> bool:
        """Whether driving at (v, w) would bring the robot into an obstacle of its map before it
        could brake (collision imminent). Turning in place never is."""
        if v == 0.0:
            return False
        lim = self.config.limits
        horizon = v * v / (2 * lim.max_linear_accel_mps2) + 2 * SAFETY_MARGIN_M + abs(v) * dt
        heading = pose.yaw_rad + w * (horizon / abs(v)) / 2 + (0.0 if v > 0 else math.pi)
        return self.map_blocks(pose.x_m, pose.y_m, pose.x_m + horizon * math.cos(heading),
                               pose.y_m + horizon * math.sin(heading))

    def path_blocked(self, path: FloatArray, start: int) -> bool:
        """Whether the next BLOCK_CHECK_M of a path runs through an occupied cell's reach on the map."""
        pts = path[start:]
        if len(pts) == 0:
            return False
        seg = np.hypot(*np.diff(pts, axis=0).T) if len(pts) > 1 else np.zeros(0)
        along = np.concatenate([[0.0], np.cumsum(seg)])
        pts = pts[along <= BLOCK_CHECK_M]
        c = disc_clearances_m(self._occupied, self.world.frame, pts[:, 0], pts[:, 1], self.config.robot_radius_m)
        # the first point (the robot itself) may already be close: only points ahead count
        return bool((c[1:] < self.config.robot_radius_m).any())

    # -- the seven commands ---------------------------------------------------------------------------
    def _begin(self, task: _Task) -> SimTaskHandle:
        with self.lock:
            if self._closed:
                raise RobotError("the simulator is closed; create a new one")
            if self._task is not None:
                self._task.finish(self, TaskStatus.CANCELED, "preempted by a new command")
            self._task = task
            self._teleop = None
        return SimTaskHandle(self, task)

    def set_velocity(self, linear_mps: float, angular_radps: float) -> None:
        """Teleop: drive at this velocity (clamped to the base's limits) for ``TELEOP_TIMEOUT_S`` of
        robot time; call again to keep going. A non-zero command cancels the running task."""
        if not (math.isfinite(linear_mps) and math.isfinite(angular_radps)):
            raise RobotError(f"a velocity is two finite numbers (m/s, rad/s), got ({linear_mps!r}, {angular_radps!r})")
        with self.lock:
            if self._closed:
                raise RobotError("the simulator is closed; create a new one")
            moving = linear_mps != 0.0 or angular_radps != 0.0
            if not moving:
                self._teleop = None  # stop teleop motion; a running task is left alone
                self._teleop_held = False
                return
            if self._teleop_held:
                return  # stopped: the stick must be released (a zero command) before it drives again
            if self._task is not None:
                self._task.finish(self, TaskStatus.CANCELED, "cancelled by teleop (a velocity command)")
                self._task = None
            self._teleop = (float(linear_mps), float(angular_radps), self._t + TELEOP_TIMEOUT_S)

    def navigate_through_poses(self, poses: list[tuple[float, float] | tuple[float, float, float]]) -> SimTaskHandle:
        if not poses:
            raise RobotError("navigate_through_poses needs at least one pose (x, y[, yaw_deg])")
        goals: list[tuple[float, float, float | None]] = []
        for p in poses:
            if len(p) not in (2, 3) or not all(math.isfinite(float(v)) for v in p):
                raise RobotError(f"a pose is (x, y) or (x, y, yaw_deg) with finite numbers, got {p!r}")
            goals.append((float(p[0]), float(p[1]), math.radians(float(p[2])) if len(p) == 3 else None))
        with self.lock:
            return self._begin(_NavTask(self, goals))

    def move(self, direction: str, steps: int) -> SimTaskHandle:
        if direction not in MOVE_DIRECTIONS:
            raise RobotError(f"move direction {direction!r} is not one of {', '.join(MOVE_DIRECTIONS)}")
        if steps < 1:
            raise RobotError(f"move needs at least one 3 cm step, got {steps}")
        d = steps * MOVE_STEP_M
        quarter = math.pi / 2
        phases = {
            "forward": [_Phase(drive_m=d)],
            "backward": [_Phase(drive_m=-d)],
            "left": [_Phase(turn_rad=quarter), _Phase(drive_m=d), _Phase(turn_rad=-quarter)],
            "right": [_Phase(turn_rad=-quarter), _Phase(drive_m=d), _Phase(turn_rad=quarter)],
        }[direction]
        with self.lock:
            return self._begin(_StepsTask(self, "move", phases, f"move {direction} {d:.2f} m"))

    def rotate(self, direction: str, steps: int) -> SimTaskHandle:
        if direction not in ROTATE_DIRECTIONS:
            raise RobotError(f"rotate direction {direction!r} is not one of {', '.join(ROTATE_DIRECTIONS)}")
        if steps < 1:
            raise RobotError(f"rotate needs at least one 10 degree step, got {steps}")
        angle = steps * ROTATE_STEP_RAD * (1 if direction == "left" else -1)
        with self.lock:
            return self._begin(_StepsTask(self, "rotate", [_Phase(turn_rad=angle)],
                                          f"rotate {direction} {math.degrees(abs(angle)):.0f} deg"))

    def drive(self, distance_m: float) -> SimTaskHandle:
        """Drive straight by ``distance_m`` (negative: backwards), as Nav2's DriveOnHeading / BackUp."""
        if not math.isfinite(distance_m) or distance_m == 0.0:
            raise RobotError(f"drive needs a finite, non-zero distance in metres, got {distance_m!r}")
        with self.lock:
            return self._begin(_StepsTask(self, "move", [_Phase(drive_m=float(distance_m))],
                                          f"drive {distance_m:+.2f} m"))

    def turn(self, angle_rad: float) -> SimTaskHandle:
        """Turn in place by ``angle_rad`` (counter-clockwise positive), as Nav2's Spin."""
        if not math.isfinite(angle_rad) or angle_rad == 0.0:
            raise RobotError(f"turn needs a finite, non-zero angle in radians, got {angle_rad!r}")
        with self.lock:
            return self._begin(_StepsTask(self, "rotate", [_Phase(turn_rad=float(angle_rad))],
                                          f"turn {math.degrees(angle_rad):+.0f} deg"))

    def cancel_task(self, task: _Task, message: str) -> None:
        with self.lock:
            task.finish(self, TaskStatus.CANCELED, message)
            if self._task is task:
                self._task = None
                self._v = self._w = 0.0

    def stop(self) -> None:
        with self.lock:
            if self._task is not None:
                self._task.finish(self, TaskStatus.CANCELED, "stopped")
                self._task = None
            self._teleop = None
            self._teleop_held = True
            self._v = self._w = 0.0

    def get_current_path(self, timeout_s: float = DEFAULT_REQUEST_TIMEOUT_S) -> list[tuple[float, float]]:
        with self.lock:
            return self._task.path() if self._task is not None else []

    def get_map(self, timeout_s: float = DEFAULT_REQUEST_TIMEOUT_S) -> OccupancyGrid:
        with self.lock:
            return self._map.grid()

    def get_robot_pose(self, timeout_s: float = DEFAULT_REQUEST_TIMEOUT_S) -> Pose2D:
        with self.lock:
            return self._pose

    def state(self) -> RobotState:
        with self.lock:
            task = self._task
            return RobotState(
                pose=self._pose, connected=not self._closed, linear_mps=self._v, angular_radps=self._w,
                scan=self._scan, path=tuple(task.path()) if task else (), goals=tuple(task.goals()) if task else (),
                busy=task is not None, time_s=self._t,
                extra={"collisions": self.collisions, "map_version": self.map_cells_version,
                       "task": task.kind if task else None, "steps": self._steps,
                       "teleop": self._teleop is not None, "teleop_held": self._teleop_held},
            )

    def close(self) -> None:
        self.stop()
        self.stop_thread()
        self._closed = True

    # -- world changes (tests, demos, the web view) ---------------------------------------------------
    def add_obstacle(self, x_m: float, y_m: float, radius_m: float = 0.2) -> None:
        """Put a round obstacle into the ground truth; the robot learns of it from its scans."""
        with self.lock:
            self.world.add_obstacle(x_m, y_m, radius_m)


def _as_pose(pose: Pose2D | tuple[float, float] | tuple[float, float, float] | None, world: World) -> Pose2D:
    if isinstance(pose, Pose2D):
        return pose
    if pose is None:
        return default_start(world.frame)
    try:
        values = [float(v) for v in pose]
    except (TypeError, ValueError):
        raise RobotError(f"a start pose is (x, y[, yaw_deg]) in numbers, got {pose!r}") from None
    if len(values) not in (2, 3):
        raise RobotError(f"a start pose is (x, y[, yaw_deg]), got {pose!r}")
    return Pose2D(values[0], values[1], math.radians(values[2]) if len(values) == 3 else 0.0)


def _extent(grid: OccupancyGrid) -> str:
    x0, y0, x1, y1 = grid.bounds_m
    return f"x {x0:.2f}..{x1:.2f} m, y {y0:.2f}..{y1:.2f} m"


def check_start(world: World, pose: Pose2D, radius_m: float) -> None:
    """Refuse a start pose the robot cannot stand on, saying why: not finite numbers, off the map,
    a map with no spot wide enough for the robot, or too near an obstacle."""
    frame = world.frame
    if not all(math.isfinite(v) for v in (pose.x_m, pose.y_m, pose.yaw_rad)):
        raise RobotError(f"the start pose ({pose.x_m!r}, {pose.y_m!r}, yaw {pose.yaw_rad!r} rad) must be finite "
                         f"numbers on the map (extent {_extent(frame)})")
    r, c = (float(v) for v in frame.world_to_cell(pose.x_m, pose.y_m))  # floats: 1e300 fits no integer
    if not (0.0 <= r < frame.height and 0.0 <= c < frame.width):
        raise RobotError(f"the start pose ({pose.x_m:.2f}, {pose.y_m:.2f}) is outside the map "
                         f"(extent {_extent(frame)}); pick a free spot on it")
    if world.collides(pose.x_m, pose.y_m, radius_m):
        if world.widest_clearance_m() < radius_m:
            raise RobotError(f"{frame.source}: the map has no spot wide enough for the robot "
                             f"(radius {radius_m} m); it is {frame.width}x{frame.height} cells of "
                             f"{frame.resolution_m} m")
        raise RobotError(f"the start pose ({pose.x_m:.2f}, {pose.y_m:.2f}) is inside an obstacle or closer "
                         f"than {radius_m} m to one; pick a free spot")


def default_start(grid: OccupancyGrid) -> Pose2D:
    """The most open free spot of a map (largest clearance), facing +x: a safe default start."""
    from scipy import ndimage

    free = grid.free
    if not free.any():
        raise RobotError(f"{grid.source}: the map has no free cell to start the robot on")
    dist = ndimage.distance_transform_edt(free)
    r, c = np.unravel_index(int(np.argmax(dist)), dist.shape)
    x, y = grid.cell_to_world(r, c)
    return Pose2D(float(x), float(y), 0.0)


def create_sim(world: OccupancyGrid | World | str | Path | None = None, pose: Any = None, *,
               known_map: bool = False, seed: int = 0, **config: Any) -> SimBackend:
    """The registry factory: ``create_backend("sim", world=..., pose=(x, y, yaw_deg), known_map=...)``.

    ``world`` is a grid, a map file (map_server YAML or image), or ``None`` / ``"demo"`` for the
    bundled demo world; ``pose`` defaults to the most open free spot. Extra keyword arguments set
    :class:`SimConfig` fields.
    """
    from langnav.maps.demo import DEMO_NAME, build_demo_grid

    if world is None or world == DEMO_NAME:
        world = build_demo_grid()
    elif isinstance(world, str | Path):
        world = load_map(world)
    w = world if isinstance(world, World) else World(world)
    try:
        cfg = replace(SimConfig(), seed=seed, known_map=known_map, **config)
    except TypeError as exc:
        raise RobotError(f"unknown simulator option: {exc}; options are the fields of SimConfig") from None
    return SimBackend(w, _as_pose(pose, w), cfg)
