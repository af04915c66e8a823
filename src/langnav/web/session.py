"""One robot, its planner and its plan executor, shared by every page the app serves.

:class:`RobotSession` owns
* the robot backend (``create_backend``; the simulator runs its clock in real time),
* the planner (prompt -> intent -> grounded, validated commands) and the plan executor,
* the conversation store, and the :class:`~langnav.web.broadcast.Broadcaster` of state frames.

A sampler thread reads ``robot.state()`` at ``settings.state_hz`` (<= 10 Hz) and publishes one
state frame; it checks the map every MAP_CHECK_PERIOD_S and publishes it only when its cells
changed; a map change also schedules a new analysis (at most every ANALYSIS_MIN_PERIOD_S, on
its own thread), whose elements are published for drawing. None of this holds the robot's lock
for longer than one ``state()`` / ``get_map()`` call, so the control loop never waits on a client.

Mid-plan prompts: a prompt that only asks (where are you, what path, the map) is answered at
once and the plan goes on; any other prompt replaces the running plan (it is cancelled first),
as a person redirecting the robot would expect. STOP always wins at once.
"""

from __future__ import annotations

import logging
import math
import threading
import time
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, Final

import numpy as np

from langnav.analysis.elements import MapAnalysis
from langnav.errors import LangnavError
from langnav.language.translator import available as translator_names
from langnav.language.translator import clean_prompt, get_translator
from langnav.maps.grid import FREE, OccupancyGrid
from langnav.pipeline import Planner, PlanResult
from langnav.plan.commands import (
    Command,
    GetCurrentPath,
    GetMap,
    GetRobotPoseLast,
    NavigateThroughPoses,
    describe,
)
from langnav.plan.errors import PlanRejected
from langnav.plan.events import EventKind, ExecEvent
from langnav.plan.executor import PlanExecutor
from langnav.plan.executor import PlanRun as ExecutorRun
from langnav.plan.validator import CheckedPlan, validate_plan
from langnav.robot.errors import RobotError
from langnav.robot.protocol import Pose2D, RobotBackend, create_backend
from langnav.web.broadcast import Broadcaster
from langnav.web.feedback import FeedbackManager, describe_intent
from langnav.web.mapframes import (
    elements_frame,
    grid_digest,
    map_frame,
    map_png,
    path_frame,
    scan_frame,
    state_frame,
)
from langnav.web.settings import WebSettings
from langnav.web.store import ConversationStore, Message

log = logging.getLogger(__name__)

#: Map changes are looked for twice a second: slam-like maps change at the scan rate (5 Hz) but a
#: person cannot follow faster, and each check copies the grid.
MAP_CHECK_PERIOD_S: Final = 0.5
#: Re-analyse a changing map at most this often (an analysis of a floor takes ~0.1-1 s).
ANALYSIS_MIN_PERIOD_S: Final = 2.0
#: Re-analyse only when this much of the map changed (m²): a lidar's noise flickers a few dozen
#: cells at the edges of walls and unknown space all the time (0.05-0.15 m² at 5 cm cells);
#: a new doorway or room seen while exploring changes square metres.
ANALYSIS_MIN_CHANGED_M2: Final = 0.5
#: The robot's radius for drawing when the backend does not say (TurtleBot 4 / Create 3).
DEFAULT_RADIUS_M: Final = 0.17
#: Wait this long for a cancelled plan to wind down before starting the next one.
CANCEL_WAIT_S: Final = 3.0
#: Wait this long for the sampler thread to end when closing.
THREAD_JOIN_S: Final = 3.0
QUERY_COMMANDS: Final = (GetRobotPoseLast, GetCurrentPath, GetMap)
QUERY_NAMES: Final = ("GetRobotPoseLast", "GetCurrentPath", "GetMap")


@dataclass(frozen=True)
class ClickItem:
    """A plan item made from a map click (already validated; nothing to re-ground)."""

    commands: tuple[Command, ...]
    explore: bool = False


class SessionBusy(LangnavError):
    """Another prompt is being planned right now."""


def load_world(settings: WebSettings) -> OccupancyGrid:
    """The world map: ``settings.world``, or the bundled demo world."""
    from langnav.maps.io import load_map

    if settings.world is not None:
        return load_map(settings.world)
    try:
        from langnav.maps.demo import demo_map_path
    except ModuleNotFoundError as exc:
        raise LangnavError("no --world given and the bundled demo world is not installed; "
                           "pass --world MAP.yaml") from exc
    return load_map(demo_map_path())


def _make_robot(settings: WebSettings) -> RobotBackend:
    """The robot backend the settings name (the simulator in ``settings.world``)."""
    options: dict[str, Any] = dict(settings.backend_options)
    if settings.backend == "sim":
        options.setdefault("world", load_world(settings))
        options.setdefault("known_map", settings.known_map)
        if settings.start_pose is not None:
            options.setdefault("pose", settings.start_pose)
    import langnav.robot  # noqa: F401  (registers the built-in backends)

    return create_backend(settings.backend, **options)


class RobotSession:
    """See the module docstring. Create, :meth:`start`, use from any thread, :meth:`close`."""

    def __init__(self, settings: WebSettings, robot: RobotBackend | None = None) -> None:
        self.settings = settings
        self.store = ConversationStore(settings.db_path)
        self.broadcaster = Broadcaster()
        if robot is None:
            try:
                robot = _make_robot(settings)
            except BaseException:
                self.store.close()  # a world or robot that cannot be used leaves no open database
                raise
        self.robot = robot
        self.radius_m = float(getattr(getattr(robot, "config", None), "robot_radius_m", DEFAULT_RADIUS_M))
        self.translator = settings.translator
        self._planner = self._make_planner(self.translator)
        self._plan_lock = threading.Lock()   # one prompt planned at a time
        self._state_lock = threading.Lock()
        self._analysis: MapAnalysis | None = None
        self._analysis_digest = ""
        self._analysis_running = False
        self._last_analysis_s = -math.inf
        self._map_digest = ""
        self._map_version: Any = None
        self._grid: OccupancyGrid | None = None
        self._plan_id = self.store.last_plan_id()
        self._run: PlanView | None = None
        self.executor = PlanExecutor(robot)
        self.feedback = FeedbackManager(lambda: self._analysis)
        self._halt = threading.Event()
        self._sampler: threading.Thread | None = None
        self.frames_published = 0

    # -- lifecycle -------------------------------------------------------------------------------
    def start(self) -> None:
        starter = getattr(self.robot, "start", None)
        if callable(starter) and not getattr(self.robot, "running", False):
            starter(realtime=True)
        self._refresh_map(force=True)
        self._sampler = threading.Thread(target=self._sample_loop, name="langnav-web-sampler", daemon=True)
        self._sampler.start()

    def close(self) -> None:
        self._halt.set()
        run = self._run
        if run is not None and not run.done:
            run.cancel()
            run.join(CANCEL_WAIT_S)  # let it write its outcome before the store closes
        if self._sampler is not None:
            self._sampler.join(THREAD_JOIN_S)
        try:
            self.robot.close()
        finally:
            self.store.close()

    # -- status ----------------------------------------------------------------------------------
    def plan_state(self) -> dict[str, Any]:
        run = self._run
        if run is None or run.done:
            return {"state": "idle"}
        return {"state": "paused" if run.paused else "running", "plan_id": run.plan_id,
                "index": run.index, "total": run.total}

    def status(self) -> dict[str, Any]:
        st = self.robot.state()
        return {"backend": self.robot.name, "connected": st.connected, "translator": self.translator,
                "translators": translator_names(), "plan": self.plan_state(),
                "max_prompt_chars": self.settings.max_prompt_chars,
                "requires_token": self.settings.requires_token, "viewers": self.broadcaster.subscriber_count,
                "pose": list(st.pose.as_tuple()), "where": self.feedback.where_am_i(st.pose)}

    def map_png(self) -> bytes:
        return map_png(self.robot.get_map())

    def analysis(self) -> MapAnalysis | None:
        return self._analysis

    # -- chat ------------------------------------------------------------------------------------
    def say(self, role: str, kind: str, payload: dict[str, Any], plan_id: int | None = None) -> Message:
        """Store a chat message and send it to every page."""
        msg = self.store.add(role, kind, payload, plan_id)
        self.broadcaster.publish_event({"type": "message", "message": msg.to_json()})
        return msg

    def submit_prompt(self, text: str) -> list[Message]:
        """Read, ground and validate a prompt; show the plan; run it. Returns the new messages."""
        text = clean_prompt(text)
        if not self._plan_lock.acquire(timeout=0.1):
            raise SessionBusy("still working out the previous prompt; try again in a moment")
        try:
            out = [self.say("user", "prompt", {"text": text})]
            pose = self.robot.get_robot_pose()
            source: MapAnalysis | OccupancyGrid = self._current_analysis() or self.robot.get_map()
            # The planner never raises for a user's mistake: the reason comes back as clarification.
            result = self._planner.plan(text, source, (pose.x_m, pose.y_m, math.degrees(pose.yaw_rad)))
            out.extend(self._show_and_run(result, source="prompt"))
            return out
        finally:
            self._plan_lock.release()

    def go_to(self, x_m: float, y_m: float) -> list[Message]:
        """Send the robot to a clicked point, through the same validator as any prompt."""
        if not self._plan_lock.acquire(timeout=0.1):
            raise SessionBusy("still working out the previous prompt; try again in a moment")
        try:
            out = [self.say("user", "prompt", {"text": f"Go to the point I clicked: x {x_m:.2f}, y {y_m:.2f}"})]
            cmd = NavigateThroughPoses(poses=[[x_m, y_m]], note="the point you clicked")
            try:
                checked = self._validate([cmd])
            except PlanRejected as exc:
                out.append(self.say("robot", "rejected", {"text": "I can't go there, nothing moved.",
                                                           "reasons": exc.reasons}))
                return out
            out.extend(self._start_plan(f"I'll go to x {x_m:.2f}, y {y_m:.2f}.", "map click",
                                        [ClickItem(checked.commands)], list(checked.repairs), source="click"))
            return out
        finally:
            self._plan_lock.release()

    def stop(self) -> dict[str, Any]:
        """Halt now: the robot first, then the plan; then say so, once (the cancelled plan's own
        outcome is not written as a second message)."""
        self.robot.stop()
        run = self._run
        if run is not None and not run.done:
            run.silence_outcome()
            run.cancel()
        pose = self.robot.get_robot_pose()
        msg = self.say("system", "info", {"text": self.feedback.stopped(pose, "you pressed STOP")})
        return {"ok": True, "message": msg.to_json()}

    def pause(self) -> dict[str, Any]:
        """Hold the running plan (the robot stops at once); with no plan, stop whatever moves
        (teleop included: the simulator then ignores a still-held stick until it is released)."""
        run = self._run
        if run is None or run.done:
            self.robot.stop()
            return {"ok": False, "plan": self.plan_state()}
        run.pause()
        msg = self.say("system", "info", {"text": "Paused. Press Resume to carry on, or STOP."})
        return {"ok": True, "plan": self.plan_state(), "message": msg.to_json()}

    def resume(self) -> dict[str, Any]:
        run = self._run
        if run is None or run.done or not run.paused:
            return {"ok": False, "plan": self.plan_state()}
        run.resume()
        msg = self.say("system", "info", {"text": "Resuming the plan."})
        return {"ok": True, "plan": self.plan_state(), "message": msg.to_json()}

    def set_translator(self, name: str) -> dict[str, Any]:
        names = translator_names()
        if name not in names:
            raise LangnavError(f"unknown translator {name!r}; choose one of: {', '.join(names)}")
        planner = self._make_planner(name)
        with self._plan_lock:
            self._planner, self.translator = planner, name
        self.say("system", "info", {"text": f"Translator: {name}."})
        self.broadcaster.publish_event({"type": "status", "status": self.status()})
        return {"ok": True, "translator": name}

    # -- planning internals -----------------------------------------------------------------------
    def _make_planner(self, translator: str) -> Planner:
        return Planner(get_translator(translator))

    def _validate(self, commands: Sequence[Command]) -> CheckedPlan:
        """Commands made here (a map click) go through the same validator as a prompt's."""
        pose = self.robot.get_robot_pose()
        analysis = self._current_analysis()
        grid = analysis.grid if analysis is not None else self.robot.get_map()
        return validate_plan(list(commands), grid, (pose.x_m, pose.y_m, math.degrees(pose.yaw_rad)),
                             params=self._planner.params)

    def _show_and_run(self, result: PlanResult, source: str) -> list[Message]:
        if result.clarification:
            payload: dict[str, Any] = {"text": result.clarification, "translator": result.translator}
            if result.intent is not None and result.intent.steps:
                payload["intent_text"] = describe_intent(result.intent)
            return [self.say("robot", "clarification", payload)]
        if not any(item.commands or item.explore for item in result.items):
            return [self.say("robot", "clarification", {
                "text": "I did not find anything to do in that. Try e.g. “go to the nearest door”."})]
        intent_text = describe_intent(result.intent) if result.intent is not None else "Here is the plan."
        return self._start_plan(intent_text, result.translator, result.items, list(result.messages), source)

    def _start_plan(self, intent_text: str, translator: str, items: Sequence[Any], notes: list[str],
                    source: str) -> list[Message]:
        """Show the plan card and hand the plan to the executor (it cancels a running plan first)."""
        flat = [c for it in items for c in it.commands]
        explores = any(getattr(it, "explore", False) for it in items)
        if flat and not explores and all(isinstance(c, QUERY_COMMANDS) for c in flat):
            # Questions are answered at once, in plain words; a running plan goes on.
            return [self.say("robot", "answer", {"text": self._answer(c)}) for c in flat]
        with self._state_lock:
            self._plan_id += 1
            plan_id = self._plan_id
        rows: list[dict[str, Any]] = []
        for it in items:
            if getattr(it, "explore", False):
                rows.append({"index": len(rows), "text": "Explore until there is nothing left to map",
                             "command": {"command": "Explore"}})
                continue
            rows.extend({"index": len(rows), "text": describe(c), "command": c.model_dump(exclude={"note"})}
                        for c in it.commands)
        card = self.say("robot", "plan", {"intent_text": intent_text, "translator": translator, "source": source,
                                          "commands": rows, "notes": notes}, plan_id=plan_id)
        view = PlanView(self, plan_id, len(rows))
        self._run = view
        view.start(list(items))
        return [card]

    def _answer(self, cmd: Command) -> str:
        if isinstance(cmd, GetRobotPoseLast):
            return self.feedback.where_am_i(self.robot.get_robot_pose())
        if isinstance(cmd, GetCurrentPath):
            return self.feedback.path(self.robot.get_current_path())
        return self.feedback.map(self.robot.get_map())

    # -- map, analysis, state frames -------------------------------------------------------------------
    def _current_analysis(self) -> MapAnalysis | None:
        """An analysis of the robot's map that is good enough to plan on *now*.

        The cached one (kept fresh by the sampler) unless the map has changed materially since,
        or the robot stands where that analysis has no free floor; then the map is analysed here.
        Re-analysing on every prompt would cost most of the time a prompt may take."""
        grid = self.robot.get_map()
        cached = self._analysis
        if cached is not None and self._changed_m2(cached, grid) < ANALYSIS_MIN_CHANGED_M2:
            pose = self.robot.get_robot_pose()
            if cached.grid.value_at(pose.x_m, pose.y_m) == FREE:
                return cached
        analysis = self._analyze(grid)
        if analysis is not None:
            self._set_analysis(analysis, grid_digest(grid))
        return analysis

    @staticmethod
    def _changed_m2(analysis: MapAnalysis, grid: OccupancyGrid) -> float:
        """Area of the cells that differ between an analysed grid and ``grid`` (inf if the frame differs)."""
        old = analysis.grid
        if old.cells.shape != grid.cells.shape or old.resolution_m != grid.resolution_m:
            return math.inf
        return float(np.count_nonzero(old.cells != grid.cells)) * grid.cell_area_m2

    def _analyze(self, grid: OccupancyGrid) -> MapAnalysis | None:
        from langnav.analysis.pipeline import analyze

        try:
            return analyze(grid)
        except LangnavError as exc:
            log.warning("map analysis failed: %s", exc)
            return None
        except Exception:  # a bug in the analysis: keep the last good elements, log it, stay up
            log.exception("map analysis crashed on a %dx%d map; keeping the previous elements",
                          grid.width, grid.height)
            return None

    def _set_analysis(self, analysis: MapAnalysis, digest: str) -> None:
        with self._state_lock:
            self._analysis, self._analysis_digest = analysis, digest
        self.broadcaster.publish_frame("elements", elements_frame(analysis, digest))

    def _analysis_worker(self, grid: OccupancyGrid, digest: str) -> None:
        try:
            analysis = self._analyze(grid)
            if analysis is not None:
                self._set_analysis(analysis, digest)
        finally:
            self._analysis_running = False

    def _refresh_map(self, force: bool = False) -> None:
        version = self.robot.state().extra.get("map_version")
        if not force and version is not None and version == self._map_version:
            return
        grid = self.robot.get_map()
        digest = grid_digest(grid)
        self._map_version = version
        if digest == self._map_digest:
            return
        self._map_digest, self._grid = digest, grid
        self.broadcaster.publish_frame("map", map_frame(grid, digest))
        now = time.monotonic()
        cached = self._analysis
        material = cached is None or self._changed_m2(cached, grid) >= ANALYSIS_MIN_CHANGED_M2
        if not self._analysis_running and (force or (material and now - self._last_analysis_s >= ANALYSIS_MIN_PERIOD_S)):
            self._analysis_running = True
            self._last_analysis_s = now
            threading.Thread(target=self._analysis_worker, args=(grid, digest), name="langnav-web-analysis",
                             daemon=True).start()

    def _sample_loop(self) -> None:
        period = 1.0 / self.settings.state_hz
        next_map = 0.0
        last_scan: Any = None
        last_path: Any = None
        while not self._halt.wait(period):
            try:
                st = self.robot.state()
                self.broadcaster.publish_frame("state", state_frame(
                    st, self.robot.name, self.feedback.where_am_i(st.pose), self.plan_state(), self.radius_m))
                if st.scan is not last_scan:
                    last_scan = st.scan
                    self.broadcaster.publish_frame("scan", scan_frame(st))
                if (st.path, st.goals) != last_path:
                    last_path = (st.path, st.goals)
                    self.broadcaster.publish_frame("path", path_frame(st))
                self.frames_published += 1
                now = time.monotonic()
                if now >= next_map:
                    next_map = now + MAP_CHECK_PERIOD_S
                    self._refresh_map()
            except RobotError as exc:
                log.warning("robot state unavailable: %s", exc)
                self._halt.wait(1.0)
            except Exception:  # one bad frame must not end the live view for good
                log.exception("publishing the robot's state failed; trying again")
                self._halt.wait(1.0)


class PlanView:
    """One plan on the executor, with its events turned into chat messages and progress frames."""

    def __init__(self, session: RobotSession, plan_id: int, total: int) -> None:
        self.session = session
        self.plan_id = plan_id
        self.total = total
        self.index: int | None = None
        self._run: ExecutorRun | None = None
        self._finished = threading.Event()
        self._silent = False

    @property
    def paused(self) -> bool:
        return self._run is not None and self._run.paused

    @property
    def done(self) -> bool:
        return self._finished.is_set()

    def start(self, plan: Sequence[Any]) -> None:
        self._run = self.session.executor.start(plan, on_event=self._on_event)

    def cancel(self) -> None:
        if self._run is not None:
            self._run.cancel()

    def silence_outcome(self) -> None:
        """The plan's end is announced by someone else (STOP says it once)."""
        self._silent = True

    def pause(self) -> None:
        if self._run is not None:
            self._run.pause()

    def resume(self) -> None:
        if self._run is not None:
            self._run.resume()

    def join(self, timeout_s: float) -> bool:
        return self._finished.wait(timeout_s)

    def _on_event(self, event: ExecEvent) -> None:
        """Runs on the executor's thread: quick, and never raises into it."""
        s = self.session
        kind = event.kind
        if event.index is not None:
            self.index = event.index
        if kind == EventKind.PROGRESS:
            s.broadcaster.publish_event({"type": "progress", "plan_id": self.plan_id, "index": event.index,
                                         "text": event.message, "fraction": event.fraction})
            return
        if kind == EventKind.FINISHED:
            self._finish(event)
            return
        status = {EventKind.STARTED: "running", EventKind.RESUMED: "running"}.get(kind, kind.value)
        s.say("robot", "step", {"index": event.index, "status": status, "text": event.message,
                                "command_text": event.text}, plan_id=self.plan_id)
        if kind == EventKind.SUCCEEDED and event.command and event.command.get("command") in QUERY_NAMES:
            s.say("robot", "answer", {"text": self._answer(event)}, plan_id=self.plan_id)

    def _answer(self, event: ExecEvent) -> str:
        name = (event.command or {}).get("command")
        if name == "GetRobotPoseLast" and event.pose is not None:
            x, y, yaw_deg = event.pose
            return self.session.feedback.where_am_i(Pose2D(x, y, math.radians(yaw_deg)))
        if name == "GetCurrentPath":
            return self.session.feedback.path([tuple(p) for p in event.data.get("path", [])])
        return event.message[:1].upper() + event.message[1:] + "."

    def _finish(self, event: ExecEvent) -> None:
        s = self.session
        try:
            pose = s.robot.get_robot_pose()
            status = event.status.value if event.status is not None else "failed"
            if status == "cancelled" and self._silent:
                return
            if status == "succeeded":
                text = s.feedback.arrived(pose)
            elif status == "cancelled":
                text = s.feedback.cancelled(pose)
            else:
                text = s.feedback.failed(event.message or "the plan failed", pose)
            s.say("robot", "outcome", {"status": status, "text": text}, plan_id=self.plan_id)
        finally:
            self._finished.set()
