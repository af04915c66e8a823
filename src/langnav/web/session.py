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
once and the plan goes on; a prompt that would move the robot is not run silently over the
running plan: the robot asks whether to replace it (the page resends it with ``replace``).
STOP, and a prompt that starts with stop, always win at once.
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

from langnav.analysis.elements import MapAnalysis, element_kind, reference_point
from langnav.analysis.identity import StableAnalyzer, label
from langnav.errors import LangnavError
from langnav.language.translator import available as translator_names
from langnav.language.translator import clean_prompt, get_translator
from langnav.maps.demo import DEMO_KNOWN_MAP, DEMO_START
from langnav.maps.grid import FREE, OccupancyGrid
from langnav.pipeline import Planner, PlanResult, default_analyzer
from langnav.places import JsonPlaceStore, NamedPlace, PlaceError, PlaceStore
from langnav.plan.commands import (
    Command,
    GetCurrentPath,
    GetMap,
    GetRobotPoseLast,
    NavigateThroughPoses,
    Stop,
    describe,
)
from langnav.plan.errors import PlanRejected
from langnav.plan.events import EventKind, ExecEvent
from langnav.plan.executor import PlanExecutor
from langnav.plan.executor import PlanRun as ExecutorRun
from langnav.plan.validator import CheckedPlan, validate_plan
from langnav.robot.errors import RobotError
from langnav.robot.protocol import Pose2D, RobotBackend, create_backend
from langnav.web import conversation
from langnav.web.broadcast import Broadcaster
from langnav.web.feedback import (
    FeedbackManager,
    asks_for_numbers,
    describe_intent,
    heading_word,
    where_words,
)
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
#: The starter examples are planned again when the robot has moved this far or turned this much
#: ("the door on your left" changes with the heading) or the map's analysis changed.
EXAMPLES_CELL_M: Final = 0.5
EXAMPLES_TURN_DEG: Final = 30.0
QUERY_NAMES: Final = ("GetRobotPoseLast", "GetCurrentPath", "GetMap")


@dataclass(frozen=True)
class ClickItem:
    """A plan item made from a map click (already validated; nothing to re-ground)."""

    commands: tuple[Command, ...]
    explore: bool = False


def _moves(result: PlanResult) -> bool:
    """Whether a plan would move the robot (not only answer questions, not a Stop)."""
    flat = [c for it in result.items for c in it.commands]
    if any(it.explore for it in result.items):
        return True
    if flat and isinstance(flat[0], Stop):
        return False
    return any(not isinstance(c, QUERY_COMMANDS) for c in flat)


def _goals(result: PlanResult) -> list[tuple[float, float]]:
    """Every navigation goal of a plan, in order."""
    return [(float(p[0]), float(p[1])) for it in result.items for c in it.commands
            if isinstance(c, NavigateThroughPoses) for p in c.poses]


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
        demo = settings.world is None
        options.setdefault("known_map", DEMO_KNOWN_MAP if settings.known_map is None and demo
                           else bool(settings.known_map))
        if settings.start_pose is not None:
            options.setdefault("pose", settings.start_pose)
        elif demo:
            options.setdefault("pose", DEMO_START)
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
        # every analysis of this robot's map (the sampler's and the planner's re-grounding ones)
        # keeps the element ids of the ones before: "door 2" stays door 2 while the map grows
        self.identity = StableAnalyzer(default_analyzer)
        try:
            self.place_store: PlaceStore = JsonPlaceStore(settings.places_file)
        except PlaceError:
            self.store.close()
            raise
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
        self._exact = False  # the last prompt asked for coordinates
        self._examples: tuple[Any, list[str]] | None = None
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
                "pose": list(st.pose.as_tuple()), "where": self.feedback.where_am_i(st.pose),
                "examples": self.examples()}

    def map_png(self) -> bytes:
        return map_png(self.robot.get_map())

    def analysis(self) -> MapAnalysis | None:
        return self._analysis

    # -- chat ------------------------------------------------------------------------------------
    def say(self, role: str, kind: str, payload: dict[str, Any], plan_id: int | None = None) -> Message:
        """Store a chat message and send it to every page. What the robot says is put in plain
        words (no "pose", no "frontier", places named rather than given as coordinates); the
        user's own words, and a plan's exact commands (shown on request), are left as they are."""
        if role != "user":
            payload = dict(payload)
            for key in ("text", "intent_text"):
                if isinstance(payload.get(key), str) and not (key == "text" and self._exact and kind == "answer"):
                    payload[key] = self.feedback.plain(payload[key])
            for key in ("reasons", "notes"):
                if isinstance(payload.get(key), list):
                    payload[key] = [self.feedback.plain(str(v)) for v in payload[key]]
        if kind in ("rejected", "error") or (kind == "outcome" and payload.get("status") == "failed"):
            log.warning("told the user (%s): %s %s", kind, payload.get("text", ""), payload.get("reasons") or "")
        msg = self.store.add(role, kind, payload, plan_id)
        self.broadcaster.publish_event({"type": "message", "message": msg.to_json()})
        return msg

    def submit_prompt(self, text: str, replace: bool = False) -> list[Message]:
        """Read, ground and validate a prompt; show the plan; run it. Returns the new messages.

        Help and questions about the map are answered from the map; a prompt that would move the
        robot while a plan runs is not run at once: the robot asks whether to replace the running
        plan (``replace=True`` says yes; STOP always wins at once)."""
        if not "".join(ch for ch in text if ch.isprintable()).strip():
            examples = self.examples()
            hint = f" For example: “{examples[1] if len(examples) > 1 else examples[0]}”." if examples else ""
            return [self.say("robot", "clarification", {"text": "Your message was empty: tell me what to do "
                                                                 "in your own words." + hint})]
        text = clean_prompt(text)
        if not self._plan_lock.acquire(timeout=0.1):
            raise SessionBusy("still working out the previous prompt; try again in a moment")
        try:
            out = [self.say("user", "prompt", {"text": text})]
            self._exact = asks_for_numbers(text)
            pose = self.robot.get_robot_pose()
            analysis = self._current_analysis()
            reply = conversation.answer(text, analysis, pose, self.examples)
            if reply is not None:
                out.append(self.say("robot", "answer", {"text": reply}))
                return out
            source: MapAnalysis | OccupancyGrid = analysis or self.robot.get_map()
            places_before = self.places()
            # The planner never raises for a user's mistake: the reason comes back as clarification.
            result = self._planner.plan(text, source, (pose.x_m, pose.y_m, math.degrees(pose.yaw_rad)))
            if analysis is not None and not result.clarification:
                # a name from the map ("door 5") must be where the plan goes: a reading that lost the
                # number would send the robot to another door
                missed = [e for e in conversation.named_elements(text, analysis)
                          if not conversation.plan_reaches(_goals(result), analysis, e)]
                if missed and _moves(result):
                    names = ", ".join(label(e) for e in missed)
                    out.append(self.say("robot", "clarification", {
                        "text": f"My plan for that would not take me to {names}, so nothing moved. "
                                f"Try e.g. “go to the nearest door” or click {names} on the map.",
                        "translator": result.translator}))
                    return out
            running = self._run
            if (not replace and running is not None and not running.done and not result.clarification
                    and _moves(result)):
                out.append(self.say("robot", "confirm", {
                    "text": f"I'm still carrying out the plan before (step {(running.index or 0) + 1} of "
                            f"{running.total}). Stop it and do “{text}” instead?",
                    "prompt": text}))
                return out
            out.extend(self._show_and_run(result, source="prompt"))
            if self.places() != places_before:
                self._places_changed()  # the prompt named or forgot a place: the pins follow
            return out
        finally:
            self._plan_lock.release()

    def examples(self) -> list[str]:
        """Prompts that would run on this map from where the robot is (each one planned; kept
        while the map analysis and the robot's spot stay the same, so many pages opening at once
        do not plan them again and again)."""
        pose = self.robot.get_robot_pose()
        analysis = self._analysis or self._current_analysis()
        key = (analysis, round(pose.x_m / EXAMPLES_CELL_M), round(pose.y_m / EXAMPLES_CELL_M),
               round(math.degrees(pose.yaw_rad) / EXAMPLES_TURN_DEG), self.translator)
        cached = self._examples
        if cached is not None and cached[0] == key:
            return list(cached[1])
        out = self._plan_examples(pose, analysis)
        self._examples = (key, out)
        return list(out)

    def _plan_examples(self, pose: Pose2D, analysis: MapAnalysis | None) -> list[str]:
        xyz = (pose.x_m, pose.y_m, math.degrees(pose.yaw_rad))

        def plan_ok(prompt: str) -> bool:
            if conversation.answer(prompt, analysis, pose, list) is not None:
                return True
            result = self._planner.plan(prompt, analysis or self.robot.get_map(), xyz)
            if result.clarification or not any(it.commands or it.explore for it in result.items):
                return False
            # an example that names an element ("go to room 4") must go there
            named = conversation.named_elements(prompt, analysis) if analysis is not None else []
            goals = _goals(result)
            return all(conversation.plan_reaches(goals, analysis, e) for e in named if analysis is not None)

        return conversation.starter_examples(analysis, pose, plan_ok)

    def spot(self, x_m: float, y_m: float) -> dict[str, Any]:
        """What is at a map point: free floor / obstacle / unmapped / outside, the element there
        (name, kind, size, actions), and whether the robot may be sent there."""
        grid = self.robot.get_map()
        r, c = grid.world_to_index(x_m, y_m)
        analysis = self._analysis or self._current_analysis()
        element = conversation.element_at(analysis, x_m, y_m) if analysis is not None else None
        out: dict[str, Any] = {"x": round(x_m, 2), "y": round(y_m, 2),
                               "element": conversation.element_card(element) if element is not None else None}
        if not grid.in_bounds(int(r), int(c)):
            out.update(cell="outside", go=False, reason="That is outside the map.")
            return out
        value = int(grid.cells[int(r), int(c)])
        if value == FREE:
            where = where_words(analysis, x_m, y_m)
            out.update(cell="free", go=True, reason="", where=where)
        elif value == -1:
            out.update(cell="unknown", go=False,
                       reason="I haven't mapped that spot yet, so I can't plan a way there. "
                              "Send me to the edge of what I know, or ask me to explore.")
        else:
            out.update(cell="obstacle", go=False, reason="That spot is taken by a wall or an obstacle: "
                                                         "I can't drive there.")
        return out

    def go_to(self, x_m: float, y_m: float, yaw_deg: float | None = None) -> list[Message]:
        """Send the robot to a clicked point (facing ``yaw_deg`` when given, as RViz's Nav2 goal
        tool does), through the same validator as any prompt. Refused up front, with the reason,
        on an obstacle, on unmapped space or outside the map."""
        if not self._plan_lock.acquire(timeout=0.1):
            raise SessionBusy("still working out the previous prompt; try again in a moment")
        try:
            spot = self.spot(x_m, y_m)
            facing = f", facing {heading_word(math.radians(yaw_deg))}" if yaw_deg is not None else ""
            where = spot.get("where") or f"x {x_m:.1f}, y {y_m:.1f}"
            out = [self.say("user", "prompt", {"text": f"Go to the spot I clicked ({where}){facing}"})]
            if not spot["go"]:
                out.append(self.say("robot", "rejected", {"text": spot["reason"] + " Nothing moved.",
                                                           "reasons": [spot["reason"]]}))
                return out
            pose_cmd: list[float] = [x_m, y_m] if yaw_deg is None else [x_m, y_m, yaw_deg]
            cmd = NavigateThroughPoses(poses=[pose_cmd], note="the point you clicked")
            try:
                checked = self._validate([cmd])
            except PlanRejected as exc:
                out.append(self.say("robot", "rejected", {"text": "I can't go there, nothing moved.",
                                                           "reasons": exc.reasons}))
                return out
            out.extend(self._start_plan(f"I'll go to the spot you clicked ({where}){facing}.", "map click",
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
        self._confirm_stop()
        return {"ok": True, "message": msg.to_json()}

    def _confirm_stop(self) -> None:
        """On a backend that can tell whether a stop took (``StopConfirmable``: it holds zero
        velocity until the robot confirms the cancel, within its own bound), watch in the background
        and say so when it did not: the user must know the robot may still be moving. The cancelled
        plan's own outcome is silenced on STOP, so this is the only place that would tell them."""
        wait_stopped = getattr(self.robot, "wait_stopped", None)
        if wait_stopped is None:
            return

        def watch() -> None:
            try:
                wait_stopped()
            except RobotError as e:
                self.say("system", "error", {"text": str(e)})

        threading.Thread(target=watch, name="langnav-stop-confirm", daemon=True).start()

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

    # -- named places (pins on the map) ---------------------------------------------------------
    # The session's place store (a JSON file kept across restarts) is the one the planner reads
    # ("go to the kitchen", "call this spot the kitchen"); the pins show and edit it.
    def places(self) -> list[dict[str, Any]]:
        return [{"name": p.name, "x": round(p.xy[0], 2), "y": round(p.xy[1], 2)}
                for p in sorted(self.place_store.all(), key=lambda p: p.key)]

    def _places_changed(self) -> None:
        self.broadcaster.publish_event({"type": "places", "places": self.places()})

    def name_place(self, name: str, x_m: float, y_m: float, element_id: str | None = None) -> dict[str, Any]:
        """Name a spot of free floor, or a map element ("front door", kept at the element)."""
        if element_id is not None:
            analysis = self._analysis or self._current_analysis()
            try:
                element = analysis.by_id(element_id) if analysis is not None else None
            except KeyError:
                element = None
            if element is None:
                raise LangnavError(f"there is no {label(element_id)} on the map now; click it again")
            x, y = reference_point(element)
            place = self.place_store.put(NamedPlace.element(name, element_kind(element).value, element_id, x, y))
            where = label(element_id)
        else:
            spot = self.spot(x_m, y_m)
            if spot["cell"] != "free":
                raise LangnavError(f"a named place must be on free floor: {spot['reason']}")
            place = self.place_store.put(NamedPlace.spot(name, x_m, y_m))
            where = spot.get("where") or "here"
        self.say("system", "info", {"text": f"I'll remember {where} as “{place.name}”. "
                                            f"Say e.g. “go to the {place.name}”."})
        self._places_changed()
        return {"ok": True, "places": self.places()}

    def rename_place(self, old: str, new: str) -> dict[str, Any]:
        place = self.place_store.rename(old, new)
        self.say("system", "info", {"text": f"“{old.strip()}” is now called “{place.name}”."})
        self._places_changed()
        return {"ok": True, "places": self.places()}

    def forget_place(self, name: str) -> dict[str, Any]:
        place = self.place_store.remove(name)
        self.say("system", "info", {"text": f"I forgot the place “{place.name}”."})
        self._places_changed()
        return {"ok": True, "places": self.places()}

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
        # one place store and one pose history for the session: they survive a translator change
        old = getattr(self, "_planner", None)
        return Planner(get_translator(translator), analyzer=self.identity, places=self.place_store,
                       history=old.history if old is not None else None)

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
        if not any(item.commands or item.explore for item in result.items) and result.messages:
            # done without moving (a place named or forgotten, "I am already there"): say so
            text = " ".join(self.feedback.placed(m) for m in result.messages)
            return [self.say("robot", "answer", {"text": text, "translator": result.translator})]
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
            rows.extend({"index": len(rows), "text": self.feedback.command(c), "detail": describe(c),
                         "command": c.model_dump(exclude={"note"})} for c in it.commands)
        card = self.say("robot", "plan", {"intent_text": intent_text, "translator": translator, "source": source,
                                          "commands": rows, "notes": notes}, plan_id=plan_id)
        view = PlanView(self, plan_id, len(rows))
        self._run = view
        view.start(list(items))
        return [card]

    def _answer(self, cmd: Command) -> str:
        if isinstance(cmd, GetRobotPoseLast):
            return self.feedback.where_am_i(self.robot.get_robot_pose(), exact=self._exact)
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
        try:
            return self.identity(grid, self._planner.params)
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
        message = event.message
        if kind == EventKind.SUCCEEDED and event.text == "Explore":
            message = s.feedback.exploration_left(message)
        elif kind == EventKind.SUCCEEDED and (event.command or {}).get("command") not in QUERY_NAMES:
            message = "done"  # the backend's own words carry coordinates ("reached (2.98, 4.53)")
        s.say("robot", "step", {"index": event.index, "status": status, "text": message,
                                "command_text": event.text}, plan_id=self.plan_id)
        if kind == EventKind.SUCCEEDED and event.command and event.command.get("command") in QUERY_NAMES:
            s.say("robot", "answer", {"text": self._answer(event)}, plan_id=self.plan_id)

    def _answer(self, event: ExecEvent) -> str:
        name = (event.command or {}).get("command")
        if name == "GetRobotPoseLast" and event.pose is not None:
            x, y, yaw_deg = event.pose
            return self.session.feedback.where_am_i(Pose2D(x, y, math.radians(yaw_deg)), exact=self.session._exact)
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
            try:  # the robot is somewhere else now: the examples (and the plan state) with it
                s.broadcaster.publish_event({"type": "status", "status": s.status()})
            except LangnavError as exc:
                log.warning("status after the plan: %s", exc)
