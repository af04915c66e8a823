"""Prompt -> intent -> grounded, validated robot commands: the whole way, with an analysis cache.

>>> planner = Planner(get_translator("offline"))                      # doctest: +SKIP
>>> result = planner.plan("go to the second door on your left", grid, (1.5, 5.75, 0.0))
>>> result.commands, result.clarification

Every failure a user can cause (a prompt that cannot be read, an element the map does not have,
an unsafe move) comes back as ``clarification`` with a readable reason and no commands; nothing
runs. Each step is a :class:`PlanItem` whose ``reground`` re-computes that step's commands from
the pose and map of the moment it is executed.
"""

from __future__ import annotations

import logging
import math
import threading
import weakref
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, Final

from langnav.analysis.elements import MapAnalysis
from langnav.analysis.params import DEFAULT_PARAMS, AnalysisParams
from langnav.errors import LangnavError
from langnav.grounding.errors import GroundingError
from langnav.grounding.geometry import Point, Pose, free_space_for
from langnav.grounding.ground import (
    GroundedPlan,
    GroundedStep,
    GroundingContext,
    advance_way,
    as_pose,
    ground,
    ground_step,
)
from langnav.grounding.history import PoseHistory
from langnav.language.errors import TranslationError
from langnav.language.intent import Intent, Step
from langnav.language.offline.ask import ask_message, only_stops, spatial
from langnav.language.translator import Context, Translator, clean_prompt
from langnav.maps.grid import OccupancyGrid
from langnav.places.errors import PlaceError
from langnav.places.store import MemoryPlaceStore, NamedPlace, PlaceStore
from langnav.plan.commands import Command, NavigateThroughPoses, to_bench
from langnav.plan.errors import PlanRejected
from langnav.plan.validator import validate_plan

log = logging.getLogger(__name__)

#: Analyses kept per planner (maps of one robot session: a few snapshots of the same floor).
ANALYSIS_CACHE_SIZE: Final = 8

Analyzer = Callable[[OccupancyGrid, AnalysisParams], MapAnalysis]


def default_analyzer(grid: OccupancyGrid, params: AnalysisParams) -> MapAnalysis:
    from langnav.analysis.pipeline import analyze  # imported lazily: the heaviest module

    return analyze(grid, params)


@dataclass(frozen=True)
class PlanItem:
    """One step of the plan: its commands as grounded now, and how to ground it again later."""

    index: int
    step: Step
    commands: tuple[Command, ...]
    note: str
    explore: bool
    _planner: Planner = field(repr=False, compare=False)
    #: the pose the whole prompt started from ("go back to where you started" goes there)
    origin: Pose | None = None
    #: where the earlier steps of the prompt that moved the robot began ("back to where you were")
    moved_from: tuple[Pose, ...] = ()
    #: the prompt's way up to this step, as planned ("the door you just passed")
    route: tuple[Point, ...] = ()

    def reground(self, pose: Pose | tuple[float, float, float], grid: OccupancyGrid | MapAnalysis) -> list[Command]:
        """This step's commands from the robot's pose ((x, y, yaw_deg) or Pose) and map of now.
        Raises GroundingError or PlanRejected with a readable reason."""
        return self._planner.reground_step(self.step, pose, grid, self.index, origin=self.origin,
                                           moved_from=self.moved_from, route=self.route)


@dataclass(frozen=True)
class PlanResult:
    prompt: str
    intent: Intent | None
    commands: tuple[Command, ...]
    items: tuple[PlanItem, ...]
    messages: tuple[str, ...]
    clarification: str | None
    translator: str

    @property
    def ok(self) -> bool:
        return self.clarification is None

    def to_bench(self, case_id: str) -> dict[str, Any]:
        """The bench's output line for this result. A result that runs nothing says why: its refusal,
        else what its steps said ("I am in room 6 already", "I did not understand: 'sofa'")."""
        said = self.clarification
        if said is None and not self.commands:
            said = " ".join(self.messages) or "Nothing was run."
        return {"id": case_id, "commands": [to_bench(c) for c in self.commands], "clarification": said}

    def to_json(self) -> dict[str, Any]:
        return {
            "prompt": self.prompt,
            "translator": self.translator,
            "intent": self.intent.model_dump(mode="json") if self.intent is not None else None,
            "commands": [{**to_bench(c), "note": c.note} for c in self.commands],
            "steps": [{"index": it.index, "text": it.step.text, "note": it.note, "explore": it.explore,
                       "commands": [to_bench(c) for c in it.commands]} for it in self.items],
            "messages": list(self.messages),
            "clarification": self.clarification,
        }


class Planner:
    """Translator + map analysis (cached per grid object) + grounding + validation.

    ``places`` holds the places the user named ("call this spot the kitchen"; default: in memory,
    give a ``JsonPlaceStore`` to keep them across restarts); ``history`` the way the robot drove this
    session ("back to where you were", "the door you just passed"). Both may be shared by several
    planners (the web app makes a new one when the translator changes)."""

    def __init__(self, translator: Translator, params: AnalysisParams = DEFAULT_PARAMS, *,
                 analyzer: Analyzer = default_analyzer, places: PlaceStore | None = None,
                 history: PoseHistory | None = None) -> None:
        self.translator = translator
        self.params = params
        self._analyzer = analyzer
        self._cache: weakref.WeakKeyDictionary[OccupancyGrid, MapAnalysis] = weakref.WeakKeyDictionary()
        self._lock = threading.Lock()
        self.places: PlaceStore = places if places is not None else MemoryPlaceStore()
        self.history: PoseHistory = history if history is not None else PoseHistory()

    # -- analysis ------------------------------------------------------------------------------
    def analysis_for(self, grid_or_analysis: OccupancyGrid | MapAnalysis) -> MapAnalysis:
        if isinstance(grid_or_analysis, MapAnalysis):
            return grid_or_analysis
        with self._lock:
            hit = self._cache.get(grid_or_analysis)
            if hit is not None:
                return hit
        analysis = self._analyzer(grid_or_analysis, self.params)
        with self._lock:
            if len(self._cache) >= ANALYSIS_CACHE_SIZE:
                self._cache.clear()
            self._cache[grid_or_analysis] = analysis
        return analysis

    @property
    def named_places(self) -> dict[str, NamedPlace]:
        """The named places now, by name as shown."""
        return {p.name: p for p in self.places.all()}

    def name_place(self, name: str, xy: Point, yaw_deg: float | None = None) -> NamedPlace:
        """Remember a user's name for a spot ("call this the kitchen"). Raises PlaceError (a
        LangnavError) for a bad name or position, saying why."""
        if not all(math.isfinite(v) for v in xy):
            raise PlaceError(f"a place needs a finite position, not {tuple(xy)}")
        return self.places.put(NamedPlace.spot(name, float(xy[0]), float(xy[1]), yaw_deg))

    # -- planning ------------------------------------------------------------------------------
    def plan(self, prompt: str, grid_or_analysis: OccupancyGrid | MapAnalysis,
             pose: Pose | tuple[float, float, float]) -> PlanResult:
        """Read, ground and validate a prompt. Never raises: the reason for refusing comes back as
        ``clarification`` (and no commands). A bug is logged with its traceback and refused too."""
        try:
            return self._plan(prompt, grid_or_analysis, pose)
        except Exception as exc:  # the last guard: a robot must never act on a half-made plan
            log.exception("planning %r failed", prompt)
            return self._refusal(prompt, None, f"I could not plan that because of an internal error "
                                 f"({type(exc).__name__}: {exc}); nothing was run.",
                                 getattr(self.translator, "name", "unknown"))

    def _plan(self, prompt: str, grid_or_analysis: OccupancyGrid | MapAnalysis,
              pose: Pose | tuple[float, float, float]) -> PlanResult:
        name = getattr(self.translator, "name", "unknown")
        try:
            start = as_pose(pose)
            self.history.observe(start)
            analysis = self.analysis_for(grid_or_analysis)
            text = clean_prompt(prompt)
            named = {p.key: p for p in self.places.all()}
            ctx = Context(analysis=analysis, pose=(start.x_m, start.y_m, start.yaw_deg),
                          known_names=tuple(p.name for p in named.values()))
            intent = self.translator.translate(text, ctx)
        except LangnavError as exc:
            return self._refusal(prompt, None, str(exc), name)
        name = intent.translator or name
        if intent.clarification and not intent.steps:
            return self._refusal(prompt, intent, intent.clarification, name)
        try:
            grounded = ground(intent, analysis, start, params=self.params, named_places=named,
                              history=self.history.view())
            checked = validate_plan(grounded.commands, analysis.grid, start, params=self.params,
                                    space=free_space_for(analysis.grid, self.params))
        except PlanRejected as exc:
            return self._refusal(prompt, intent, "I will not run that: " + "; ".join(exc.reasons) + ".", name)
        except GroundingError as exc:
            return self._refusal(prompt, intent, str(exc), name)
        doubtful = [] if only_stops(intent.steps) else [u for u in intent.unread if spatial(u)]
        if doubtful:
            # ask, don't guess: words not read that could change where or how far the robot goes
            return self._refusal(prompt, intent, unread_question(intent, grounded, doubtful), name)
        try:
            messages = self._apply_place_changes(grounded)
        except PlaceError as exc:
            return self._refusal(prompt, intent, f"I could not change the named places: {exc}", name)
        messages.extend(m for s in grounded.steps for m in s.messages)
        messages.extend(checked.repairs)
        if intent.clarification:
            messages.append(intent.clarification)
        if intent.unread:
            messages.append("I did not understand: " + "; ".join(f"'{u}'" for u in intent.unread))
        if not checked.commands and not messages:
            # a prompt that runs nothing always says why: silence would leave the user waiting for a
            # motion that never comes
            messages.append(nothing_runs_reason(grounded))
        items = self._items(grounded, checked.commands)
        if any(s.moves for s in grounded.steps):
            self.history.planned(start, [p for it in items for p in _route_of(it.commands)])
        return PlanResult(prompt, intent, tuple(checked.commands), items, tuple(messages), None, name)

    def _apply_place_changes(self, grounded: GroundedPlan) -> list[str]:
        """Remember / forget the places the plan names, in order; what was done, in words."""
        said: list[str] = []
        for s in grounded.steps:
            if s.name_place is not None:
                place = self.places.put(s.name_place)
                said.append(f"I will remember {s.named_what} as '{place.name}'.")
            elif s.forget_place is not None:
                gone = self.places.remove(s.forget_place)
                said.append(f"I forgot '{gone.name}'.")
            elif s.list_places:
                said.append(s.note[0].upper() + s.note[1:] + ".")
        return said

    def _items(self, grounded: GroundedPlan, commands: tuple[Command, ...]) -> tuple[PlanItem, ...]:
        items: list[PlanItem] = []
        k = 0
        moved_from: list[Pose] = []
        route: list[Point] = [grounded.start_pose.xy]
        for s in grounded.steps:
            n = len(s.commands)
            items.append(PlanItem(s.index, s.step, tuple(commands[k:k + n]), s.note, s.explore, self,
                                  grounded.start_pose, tuple(moved_from), tuple(route)))
            advance_way(route, moved_from, s)
            k += n
        return tuple(items)

    def _refusal(self, prompt: str, intent: Intent | None, reason: str, name: str) -> PlanResult:
        log.info("plan refused: %s", reason)
        return PlanResult(prompt, intent, (), (), (), reason, name)

    def reground_step(self, step: Step, pose: Pose | tuple[float, float, float],
                      grid_or_analysis: OccupancyGrid | MapAnalysis, index: int = 0, *,
                      origin: Pose | None = None, moved_from: tuple[Pose, ...] = (),
                      route: tuple[Point, ...] = ()) -> list[Command]:
        """One step's commands from ``pose`` on the map of now, validated. ``origin`` is the pose the
        prompt started from (for "go back"), ``moved_from`` where its earlier moving steps began and
        ``route`` its way so far. Raises GroundingError / PlanRejected with a readable reason."""
        analysis = self.analysis_for(grid_or_analysis)
        start = as_pose(pose)
        ctx = GroundingContext(analysis, free_space_for(analysis.grid, self.params), self.params,
                               {p.key: p for p in self.places.all()}, origin=origin, history=self.history.view(),
                               route=list(route), moved_from=list(moved_from))
        gs: GroundedStep = ground_step(step, ctx, start, index)
        checked = validate_plan(list(gs.commands), analysis.grid, start, params=self.params, space=ctx.space)
        return list(checked.commands)


def _route_of(commands: tuple[Command, ...] | list[Command]) -> list[Point]:
    return [(float(p[0]), float(p[1])) for c in commands if isinstance(c, NavigateThroughPoses) for p in c.poses]


def unread_question(intent: Intent, grounded: GroundedPlan, unread: list[str]) -> str:
    """What was understood (the grounded plan, in its notes) and what was not, as a question: nothing
    runs on a partial reading. The words are the offline parser's ask message, one for both."""
    notes = "; then ".join(s.note for s in grounded.steps if s.note)
    return ask_message(intent.steps, unread, (), plan=notes)


def nothing_runs_reason(grounded: GroundedPlan) -> str:
    """Why a plan with no command and no message of its steps runs nothing: what was understood."""
    notes = "; then ".join(s.note for s in grounded.steps if s.note)
    said = f"I understood: {notes}, which needs no motion from where I am." if notes else \
        "I found nothing to do in that."
    return f"{said} Nothing was run: tell me where to go if you meant somewhere else."


def bench_line(case_id: str, result: PlanResult) -> dict[str, Any]:
    return result.to_bench(case_id)


__all__ = ["ANALYSIS_CACHE_SIZE", "Analyzer", "PlanItem", "PlanResult", "Planner", "TranslationError",
           "bench_line", "default_analyzer"]

