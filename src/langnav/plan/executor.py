"""The plan executor: runs a validated plan on a robot, one command at a time, waiting for each.

>>> run = PlanExecutor(robot).start(result.items, on_event=print)   # doctest: +SKIP
>>> run.wait(600)                                                    # doctest: +SKIP
<PlanStatus.SUCCEEDED: 'succeeded'>

A plan is a sequence of *items*: a grounding :class:`~langnav.pipeline.PlanItem` (anything with
``.commands``, and optionally ``.reground(pose, grid)`` and ``.explore``), a list of commands, or
one command. Every item after the first is **re-grounded** just before it runs, against the
robot's pose and map of that moment (the map grows while the robot drives or explores); an item
with ``explore`` set runs frontier exploration (:mod:`langnav.robot.explore`).

Events (:class:`~langnav.plan.events.ExecEvent`) go to the ``on_event`` callback in order:
``started`` / ``progress`` / ``succeeded`` | ``failed`` (with the reason) | ``cancelled`` per
command, ``paused`` / ``resumed`` between, and ``finished`` with the plan's status last.

Control, from any thread: :meth:`PlanRun.pause` stops the robot and holds the plan;
:meth:`PlanRun.resume` re-issues what was left of the command (the rest of a Move or Rotate, the
poses not yet passed); :meth:`PlanRun.cancel` stops the robot at once and ends the plan.
Every command has a time-out (:class:`ExecutorConfig`); one that runs out fails the plan.

**One plan per robot.** The rule for a prompt that arrives while a plan runs
(:meth:`PlanExecutor.start`):

* a plan of queries only (where am I, the path, the map) is answered at once, alongside the
  running plan, which goes on undisturbed;
* a plan that starts with Stop stops the robot and cancels the running plan *at once* (Stop
  always wins), then runs the rest of the new plan, if any;
* any other plan replaces the running one: that plan is cancelled (the robot stops), and the new
  one starts when it has ended.
"""

from __future__ import annotations

import itertools
import logging
import math
import threading
import time
import weakref
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from typing import Any, Final, Protocol

from langnav.errors import LangnavError
from langnav.maps.grid import OccupancyGrid
from langnav.plan.commands import (
    MOVE_STEP_M,
    ROTATE_STEP_DEG,
    Command,
    GetCurrentPath,
    GetMap,
    GetRobotPoseLast,
    Move,
    NavigateThroughPoses,
    Rotate,
    Stop,
    describe,
    to_bench,
)
from langnav.plan.events import EventKind, EventSink, ExecEvent, PlanStatus, pose_tuple
from langnav.robot.errors import RobotError, RobotTimeout
from langnav.robot.protocol import (
    DEFAULT_TASK_TIMEOUT_S,
    Pose2D,
    RobotBackend,
    TaskFeedback,
    TaskHandle,
    TaskResult,
    TaskStatus,
)

log = logging.getLogger(__name__)

#: How often a running command reports progress (and the executor looks at pause / cancel).
DEFAULT_POLL_S: Final = 1.0
#: Time-outs per command kind: Nav2 routes across a building take minutes; a Move of 30 m at
#: 0.3 m/s takes 100 s; ten full turns at 1 rad/s take a minute.
DEFAULT_NAVIGATE_TIMEOUT_S: Final = DEFAULT_TASK_TIMEOUT_S
DEFAULT_MOVE_TIMEOUT_S: Final = 180.0
DEFAULT_ROTATE_TIMEOUT_S: Final = 120.0
#: Exploration runs until done or its own budget; this bounds the whole of it.
DEFAULT_EXPLORE_TIMEOUT_S: Final = 1800.0
#: A paused plan is cancelled if nobody resumes it within this long.
DEFAULT_PAUSE_TIMEOUT_S: Final = 600.0
#: How long a new plan waits for the plan it replaces to stop.
HANDOVER_TIMEOUT_S: Final = 30.0
#: A resumed command with less than this left is done.
RESUME_MIN_DISTANCE_M: Final = MOVE_STEP_M / 2
RESUME_MIN_ANGLE_DEG: Final = ROTATE_STEP_DEG / 2

QUERY_TYPES: Final = (GetCurrentPath, GetMap, GetRobotPoseLast)


class Regroundable(Protocol):
    """What the executor needs of a plan item (``langnav.pipeline.PlanItem`` is one)."""

    @property
    def commands(self) -> Sequence[Command]: ...


PlanInput = Iterable[Any]


@dataclass(frozen=True)
class ExecutorConfig:
    poll_s: float = DEFAULT_POLL_S
    navigate_timeout_s: float = DEFAULT_NAVIGATE_TIMEOUT_S
    move_timeout_s: float = DEFAULT_MOVE_TIMEOUT_S
    rotate_timeout_s: float = DEFAULT_ROTATE_TIMEOUT_S
    explore_timeout_s: float = DEFAULT_EXPLORE_TIMEOUT_S
    pause_timeout_s: float = DEFAULT_PAUSE_TIMEOUT_S
    explore_params: Any = None  # langnav.robot.explore.ExploreParams, or None for its defaults

    def timeout_for(self, cmd: Command) -> float:
        if isinstance(cmd, NavigateThroughPoses):
            return self.navigate_timeout_s
        if isinstance(cmd, Move):
            return self.move_timeout_s
        if isinstance(cmd, Rotate):
            return self.rotate_timeout_s
        return self.poll_s


@dataclass
class _Item:
    commands: list[Command]
    reground: Callable[..., list[Command]] | None = None
    explore: bool = False


def normalise(plan: PlanInput) -> list[_Item]:
    """Plan items of any accepted shape -> the executor's items."""
    out: list[_Item] = []
    for item in plan:
        if isinstance(item, NavigateThroughPoses | Move | Rotate | Stop | GetCurrentPath | GetMap | GetRobotPoseLast):
            out.append(_Item([item]))
        elif hasattr(item, "commands"):
            out.append(_Item(list(item.commands), getattr(item, "reground", None), bool(getattr(item, "explore", False))))
        elif isinstance(item, list | tuple):
            out.append(_Item(list(item)))
        else:
            raise LangnavError(f"a plan item must be a command, a list of commands or a PlanItem, got {type(item).__name__}")
    return out


def _is_query_only(items: list[_Item]) -> bool:
    cmds = [c for it in items for c in it.commands]
    return bool(cmds) and not any(it.explore for it in items) and all(isinstance(c, QUERY_TYPES) for c in cmds)


def _starts_with_stop(items: list[_Item]) -> bool:
    return bool(items) and bool(items[0].commands) and isinstance(items[0].commands[0], Stop)


class _Cancelled(Exception):
    pass


@dataclass
class _Budget:
    """Time left for one command (robot time: the simulator's clock when headless), and the
    largest remaining distance seen, for the progress fraction."""

    total_s: float
    left_s: float = math.nan
    first_remaining_m: float | None = None

    def __post_init__(self) -> None:
        self.left_s = self.total_s

    def fraction(self, cmd: Command, fb: TaskFeedback) -> float | None:
        frac, self.first_remaining_m = progress_fraction(cmd, fb, self.first_remaining_m)
        return frac


class PlanRun:
    """One plan running on a robot (in its own thread). Control it from any thread."""

    def __init__(self, robot: RobotBackend, items: list[_Item], config: ExecutorConfig, sink: EventSink | None) -> None:
        self.robot = robot
        self.items = items
        self.config = config
        self._sink = sink
        self._cancel = threading.Event()
        self._paused = threading.Event()
        self._resume = threading.Event()
        self._done = threading.Event()
        self._lock = threading.Lock()
        self._handle: TaskHandle | None = None
        self._explorer: Any = None
        self._t0 = time.monotonic()
        self.status = PlanStatus.RUNNING
        self.message = ""
        self.events: list[ExecEvent] = []
        self._thread: threading.Thread | None = None
        self._index = 0

    # -- control ------------------------------------------------------------------------------------
    def cancel(self) -> None:
        """Stop the robot at once and end the plan (status CANCELLED)."""
        self._cancel.set()
        self._resume.set()
        with self._lock:
            explorer = self._explorer
        if explorer is not None:
            explorer.cancel()
        try:
            self.robot.stop()
        except RobotError as exc:
            log.warning("stop failed while cancelling: %s", exc)

    def pause(self) -> None:
        """Stop the robot and hold the plan until :meth:`resume` (or the pause time-out)."""
        if self._done.is_set():
            return
        self._resume.clear()
        self._paused.set()
        with self._lock:
            handle = self._handle
            explorer = self._explorer
        if explorer is not None:
            explorer.pause()  # it holds its own loop (no new frontier goal) until resumed
        if handle is not None:
            handle.cancel()
        self._safe_stop()

    def resume(self) -> None:
        self._paused.clear()
        with self._lock:
            explorer = self._explorer
        if explorer is not None:
            explorer.resume()
        self._resume.set()

    @property
    def paused(self) -> bool:
        return self._paused.is_set()

    @property
    def done(self) -> bool:
        return self._done.is_set()

    def wait(self, timeout_s: float = DEFAULT_EXPLORE_TIMEOUT_S) -> PlanStatus:
        """Block until the plan ends; raises RobotTimeout (leaving it running) on time-out."""
        if not self._done.wait(timeout_s):
            raise RobotTimeout(f"the plan is still running after {timeout_s:.0f} s; it was left running")
        return self.status

    # -- running ------------------------------------------------------------------------------------
    def start(self, after: PlanRun | None = None) -> None:
        self._thread = threading.Thread(target=self._main, args=(after,), name="langnav-plan", daemon=True)
        self._thread.start()

    def _emit(self, kind: EventKind, cmd: Command | None = None, message: str = "", *, step: int | None = None,
              fraction: float | None = None, status: PlanStatus | None = None, data: dict[str, Any] | None = None,
              index: int | None = None) -> None:
        try:
            pose: tuple[float, float, float] | None = pose_tuple(self.robot.get_robot_pose())
        except RobotError:
            pose = None
        ev = ExecEvent(kind=kind, index=index, step=step,
                       command=to_bench(cmd) if cmd is not None else None,
                       text=describe(cmd) if cmd is not None else "", message=message,
                       fraction=None if fraction is None else round(min(max(fraction, 0.0), 1.0), 3),
                       status=status, pose=pose, data=data or {},
                       time_s=round(time.monotonic() - self._t0, 3))
        self.events.append(ev)
        if self._sink is not None:
            try:
                self._sink(ev)
            except Exception:  # a broken display must not stop the robot's plan
                log.exception("event callback failed on %s", ev.kind)

    def _main(self, after: PlanRun | None) -> None:
        status, message = PlanStatus.FAILED, ""
        try:
            if after is not None and not after.done:
                after.cancel()
                try:
                    after.wait(HANDOVER_TIMEOUT_S)
                except RobotTimeout:
                    log.warning("the previous plan did not stop within %.0f s", HANDOVER_TIMEOUT_S)
            status, message = self._run_items()
        except _Cancelled:
            status, message = PlanStatus.CANCELLED, "cancelled"
        except LangnavError as exc:  # a lost connection, a robot that refused: stop what may be moving
            status, message = PlanStatus.FAILED, str(exc)
            log.info("plan failed: %s", exc)
            self._safe_stop()
        except Exception as exc:  # report, never leave the plan hanging; the robot is stopped
            log.exception("plan crashed")
            status, message = PlanStatus.FAILED, f"internal error: {exc}"
            self._safe_stop()
        finally:
            self.status, self.message = status, message
            self._emit(EventKind.FINISHED, message=message, status=status)
            self._done.set()

    def _safe_stop(self) -> None:
        try:
            self.robot.stop()
        except RobotError as exc:
            log.warning("stop failed: %s", exc)

    def _run_items(self) -> tuple[PlanStatus, str]:
        for step, item in enumerate(self.items):
            if self._cancel.is_set():
                raise _Cancelled
            commands = item.commands
            if step > 0 and item.reground is not None and not item.explore:
                fresh = self._reground(step, item)
                if fresh is None:
                    return PlanStatus.FAILED, f"step {step + 1} could not be planned from where the robot is now"
                commands = fresh
            if item.explore:
                outcome = self._explore(step)
                if outcome is not PlanStatus.SUCCEEDED:
                    return outcome, "exploration " + outcome.value
                continue
            for cmd in commands:
                outcome, why = self._run_command(cmd, step)
                if outcome is not PlanStatus.SUCCEEDED:
                    return outcome, why
        return PlanStatus.SUCCEEDED, "done"

    def _reground(self, step: int, item: _Item) -> list[Command] | None:
        assert item.reground is not None
        try:
            pose = self.robot.get_robot_pose()
            grid: OccupancyGrid = self.robot.get_map()
            return list(item.reground((pose.x_m, pose.y_m, math.degrees(pose.yaw_rad)), grid))
        except LangnavError as exc:
            first = item.commands[0] if item.commands else None
            self._emit(EventKind.FAILED, first, f"could not re-plan this step from here: {exc}", step=step,
                       index=self._index)
            return None

    def _explore(self, step: int) -> PlanStatus:
        from langnav.robot.explore import Explorer

        index = self._index
        self._index += 1
        explorer = Explorer(self.robot, self.config.explore_params, self._emit_passthrough, index=index, step=step)
        with self._lock:
            self._explorer = explorer
            if self._paused.is_set():
                explorer.pause()  # paused between the steps: the exploration starts held
        try:
            if self._cancel.is_set():
                return PlanStatus.CANCELLED
            return explorer.run()
        finally:
            with self._lock:
                self._explorer = None

    def _emit_passthrough(self, ev: ExecEvent) -> None:
        ev = ev.model_copy(update={"time_s": round(time.monotonic() - self._t0, 3)})
        self.events.append(ev)
        if self._sink is not None:
            try:
                self._sink(ev)
            except Exception:
                log.exception("event callback failed on %s", ev.kind)

    # -- one command ----------------------------------------------------------------------------------
    def _run_command(self, cmd: Command, step: int) -> tuple[PlanStatus, str]:
        index = self._index
        self._index += 1
        if self._cancel.is_set():
            raise _Cancelled
        self._emit(EventKind.STARTED, cmd, step=step, index=index)
        if isinstance(cmd, Stop):
            self._safe_stop()
            self._emit(EventKind.SUCCEEDED, cmd, "stopped", step=step, index=index)
            return PlanStatus.SUCCEEDED, ""
        if isinstance(cmd, QUERY_TYPES):
            message, data = answer_query(self.robot, cmd)
            self._emit(EventKind.SUCCEEDED, cmd, message, step=step, index=index, data=data)
            return PlanStatus.SUCCEEDED, ""
        return self._run_action(cmd, step, index)

    def _run_action(self, cmd: Command, step: int, index: int) -> tuple[PlanStatus, str]:
        start_pose = self.robot.get_robot_pose()
        budget = _Budget(self.config.timeout_for(cmd))
        current: Command | None = cmd
        while current is not None:
            if self._paused.is_set():  # paused between commands or right after a resume
                current = self._hold(cmd, step, index, start_pose, None)
                continue
            handle = start_action(self.robot, current)
            with self._lock:
                self._handle = handle
            try:
                result = self._await(handle, cmd, step, index, budget)
            finally:
                with self._lock:
                    self._handle = None
            if result is None:  # paused
                current = self._hold(cmd, step, index, start_pose, handle.feedback())
                continue
            if result.status is TaskStatus.SUCCEEDED:
                self._emit(EventKind.SUCCEEDED, cmd, result.message, step=step, index=index, fraction=1.0)
                return PlanStatus.SUCCEEDED, ""
            if result.status is TaskStatus.CANCELED:
                # cancelled on the robot's side (another client, a preempting goal)
                self._emit(EventKind.CANCELLED, cmd, result.message or "cancelled", step=step, index=index)
                return PlanStatus.CANCELLED, result.message or "cancelled"
            why = result.message or "the robot reported a failure"
            self._emit(EventKind.FAILED, cmd, why, step=step, index=index)
            return PlanStatus.FAILED, why
        self._emit(EventKind.SUCCEEDED, cmd, "done (it had finished before the pause)", step=step, index=index,
                   fraction=1.0)
        return PlanStatus.SUCCEEDED, ""

    def _await(self, handle: TaskHandle, cmd: Command, step: int, index: int, budget: _Budget) -> TaskResult | None:
        """The one wait loop: wait in slices, report progress, obey cancel and pause, time out.
        Returns the result, or None when paused; raises _Cancelled (robot stopped) on cancel."""
        while True:
            if self._cancel.is_set():
                handle.cancel()
                self._safe_stop()
                self._emit(EventKind.CANCELLED, cmd, "cancelled: the robot stopped", step=step, index=index)
                raise _Cancelled
            if self._paused.is_set():
                handle.cancel()
                return None
            slice_s = min(self.config.poll_s, budget.left_s)
            if slice_s <= 0:
                handle.cancel()
                self._safe_stop()
                return TaskResult(TaskStatus.FAILED, f"timed out after {budget.total_s:g} s; the robot stopped")
            try:
                result = handle.wait(slice_s)
            except RobotTimeout:
                budget.left_s -= slice_s
                fb = handle.feedback()
                if fb is not None:
                    frac = budget.fraction(cmd, fb)
                    self._emit(EventKind.PROGRESS, cmd, progress_message(fb), step=step, index=index, fraction=frac)
                continue
            if result.status is TaskStatus.CANCELED and (self._cancel.is_set() or self._paused.is_set()):
                continue  # our own cancel: reported above
            return result

    def _hold(self, cmd: Command, step: int, index: int, start_pose: Pose2D,
              feedback: TaskFeedback | None) -> Command | None:
        """Paused: wait for resume (or cancel, or the pause time-out); return what is left to do."""
        self._safe_stop()
        self._emit(EventKind.PAUSED, cmd, "paused: the robot stopped", step=step, index=index)
        if not self._resume.wait(self.config.pause_timeout_s):
            self._emit(EventKind.CANCELLED, cmd, f"paused for more than {self.config.pause_timeout_s:.0f} s",
                       step=step, index=index)
            raise _Cancelled
        if self._cancel.is_set():
            self._emit(EventKind.CANCELLED, cmd, "cancelled while paused", step=step, index=index)
            raise _Cancelled
        rest = remainder(cmd, start_pose, self.robot.get_robot_pose(), feedback)
        self._emit(EventKind.RESUMED, cmd, "resumed" if rest is not None else "resumed: nothing was left to do",
                   step=step, index=index)
        return rest


def start_action(robot: RobotBackend, cmd: Command) -> TaskHandle:
    """Send one long command to the robot."""
    if isinstance(cmd, NavigateThroughPoses):
        return robot.navigate_through_poses([tuple(p) for p in cmd.poses])  # type: ignore[misc]
    if isinstance(cmd, Move):
        return robot.move(cmd.direction, cmd.repeat)
    if isinstance(cmd, Rotate):
        return robot.rotate(cmd.direction, cmd.repeat)
    raise LangnavError(f"{type(cmd).__name__} is not a robot action")


def answer_query(robot: RobotBackend, cmd: Command) -> tuple[str, dict[str, Any]]:
    """The answer to a query command, in words and as data."""
    if isinstance(cmd, GetRobotPoseLast):
        p = robot.get_robot_pose()
        x, y, yaw = pose_tuple(p)
        return f"I am at ({x:.2f}, {y:.2f}), facing {yaw:.0f}°", {"pose": [x, y, yaw]}
    if isinstance(cmd, GetCurrentPath):
        path = robot.get_current_path()
        if not path:
            return "I have no path: I am not driving anywhere", {"path": []}
        length = sum(math.dist(a, b) for a, b in itertools.pairwise(path))
        end = path[-1]
        return (f"my path runs {length:.1f} m to ({end[0]:.2f}, {end[1]:.2f})",
                {"path": [[round(x, 3), round(y, 3)] for x, y in path]})
    if isinstance(cmd, GetMap):
        g = robot.get_map()
        free_m2 = float(g.free.sum()) * g.cell_area_m2
        known = 1.0 - float(g.unknown.mean())
        return (f"my map is {g.width} x {g.height} cells at {g.resolution_m:.2f} m; "
                f"{free_m2:.0f} m² of it is free floor",
                {"map": {"width": g.width, "height": g.height, "resolution_m": g.resolution_m,
                         "origin": [g.origin_x_m, g.origin_y_m, g.origin_yaw_rad],
                         "free_m2": round(free_m2, 2), "known_fraction": round(known, 4)}})
    raise LangnavError(f"{type(cmd).__name__} is not a query")


def progress_fraction(cmd: Command, fb: TaskFeedback, total: float | None) -> tuple[float | None, float | None]:
    """How far a command has come (0..1), from the feedback and the first remaining amount seen."""
    if isinstance(cmd, Rotate):
        if fb.angle_remaining_rad is None:
            return None, total
        whole = math.radians(cmd.angle_deg)
        return 1.0 - fb.angle_remaining_rad / whole if whole else None, total
    if isinstance(cmd, Move) and cmd.direction in ("forward", "backward"):
        if fb.distance_remaining_m is None:
            return None, total
        return 1.0 - fb.distance_remaining_m / cmd.distance_m, total
    if fb.distance_remaining_m is None:
        return None, total
    if total is None or fb.distance_remaining_m > total:
        total = fb.distance_remaining_m
    return (1.0 - fb.distance_remaining_m / total if total > 0 else None), total


def progress_message(fb: TaskFeedback) -> str:
    parts = []
    if fb.distance_remaining_m is not None:
        parts.append(f"{fb.distance_remaining_m:.2f} m to go")
    if fb.angle_remaining_rad is not None and fb.angle_remaining_rad > 0:
        parts.append(f"{math.degrees(fb.angle_remaining_rad):.0f}° to turn")
    if fb.recoveries:
        parts.append(f"{fb.recoveries} replans")
    if fb.message:
        parts.append(fb.message)
    return ", ".join(parts) or "under way"


def remainder(cmd: Command, start: Pose2D, now: Pose2D, fb: TaskFeedback | None) -> Command | None:
    """What is left of a command interrupted by a pause, or None if nothing is.

    NavigateThroughPoses: the poses not yet passed (from the feedback; all of them if unknown).
    Move forward / backward: the rest of the distance along the start heading. Move left / right:
    the rest of the sideways distance, measured from the start pose (the robot turns to the side
    again and back, as every sideways Move does). Rotate: the angle the feedback says is left, or
    the difference of the headings when the backend gives no angle.
    """
    if isinstance(cmd, NavigateThroughPoses):
        left = fb.poses_remaining if fb is not None and fb.poses_remaining else len(cmd.poses)
        return cmd.model_copy(update={"poses": cmd.poses[-left:]})
    if isinstance(cmd, Move):
        dx, dy = now.x_m - start.x_m, now.y_m - start.y_m
        fwd = math.cos(start.yaw_rad) * dx + math.sin(start.yaw_rad) * dy
        side = -math.sin(start.yaw_rad) * dx + math.cos(start.yaw_rad) * dy
        done = {"forward": fwd, "backward": -fwd, "left": side, "right": -side}[cmd.direction]
        rest = cmd.distance_m - done
        if rest < RESUME_MIN_DISTANCE_M:
            return None
        return cmd.model_copy(update={"repeat": max(1, round(rest / MOVE_STEP_M))})
    if isinstance(cmd, Rotate):
        if fb is not None and fb.angle_remaining_rad is not None:
            rest_deg = math.degrees(fb.angle_remaining_rad)
        else:
            turned = math.degrees(math.atan2(math.sin(now.yaw_rad - start.yaw_rad), math.cos(now.yaw_rad - start.yaw_rad)))
            rest_deg = cmd.angle_deg - (turned if cmd.direction == "left" else -turned)
        if rest_deg < RESUME_MIN_ANGLE_DEG:
            return None
        return cmd.model_copy(update={"repeat": max(1, round(rest_deg / ROTATE_STEP_DEG))})
    return cmd


# one running plan per robot: the executor objects are cheap and may be made per plan
_ACTIVE: weakref.WeakKeyDictionary[Any, PlanRun] = weakref.WeakKeyDictionary()
_ACTIVE_LOCK = threading.Lock()


@dataclass
class PlanExecutor:
    """Runs plans on one robot (see the module docstring for the one-plan-per-robot rule)."""

    robot: RobotBackend
    config: ExecutorConfig = field(default_factory=ExecutorConfig)
    on_event: EventSink | None = None

    def start(self, plan: PlanInput, on_event: EventSink | None = None) -> PlanRun:
        """Start a plan in its own thread and return its :class:`PlanRun` at once."""
        items = normalise(plan)
        run = PlanRun(self.robot, items, self.config, on_event or self.on_event)
        with _ACTIVE_LOCK:
            current = _ACTIVE.get(self.robot)
            running = current if current is not None and not current.done else None
            if _is_query_only(items) and running is not None:
                run.start()  # answered alongside; the running plan goes on
                return run
            if running is not None and _starts_with_stop(items):
                running.cancel()  # Stop wins at once, before the new thread even starts
            _ACTIVE[self.robot] = run
        run.start(after=running)
        return run

    def run(self, plan: PlanInput, on_event: EventSink | None = None,
            timeout_s: float = DEFAULT_EXPLORE_TIMEOUT_S) -> PlanStatus:
        """Run a plan to its end (blocking); raises RobotTimeout (after cancelling it) on time-out."""
        run = self.start(plan, on_event)
        try:
            return run.wait(timeout_s)
        except RobotTimeout:
            run.cancel()
            raise

    def current(self) -> PlanRun | None:
        with _ACTIVE_LOCK:
            run = _ACTIVE.get(self.robot)
        return run if run is not None and not run.done else None

    def stop(self) -> None:
        """Stop wins: stop the robot and cancel the running plan, at once."""
        run = self.current()
        if run is not None:
            run.cancel()
        else:
            self.robot.stop()


__all__ = ["ExecutorConfig", "PlanExecutor", "PlanRun", "answer_query", "normalise", "progress_fraction",
           "remainder", "start_action"]
