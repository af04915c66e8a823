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
    as_pose,
    ground,
    ground_step,
)
from langnav.language.errors import TranslationError
from langnav.language.intent import Intent, Step
from langnav.language.translator import Context, Translator, clean_prompt
from langnav.maps.grid import OccupancyGrid
from langnav.plan.commands import Command, to_bench
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

    def reground(self, pose: Pose | tuple[float, float, float], grid: OccupancyGrid | MapAnalysis) -> list[Command]:
        """This step's commands from the robot's pose ((x, y, yaw_deg) or Pose) and map of now.
        Raises GroundingError or PlanRejected with a readable reason."""
        return self._planner.reground_step(self.step, pose, grid, self.index, origin=self.origin)


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
        """The bench's output line for this result."""
        return {"id": case_id, "commands": [to_bench(c) for c in self.commands],
                "clarification": self.clarification}

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
    """Translator + map analysis (cached per grid object) + grounding + validation."""

    def __init__(self, translator: Translator, params: AnalysisParams = DEFAULT_PARAMS, *,
                 analyzer: Analyzer = default_analyzer) -> None:
        self.translator = translator
        self.params = params
        self._analyzer = analyzer
        self._cache: weakref.WeakKeyDictionary[OccupancyGrid, MapAnalysis] = weakref.WeakKeyDictionary()
        self._lock = threading.Lock()
        self.named_places: dict[str, Point] = {}

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

    def name_place(self, name: str, xy: Point) -> None:
        """Remember a user's name for a place ("call this the kitchen")."""
        if not name.strip() or not all(math.isfinite(v) for v in xy):
            raise GroundingError("a place needs a name and a finite position")
        self.named_places[name.strip().lower()] = (float(xy[0]), float(xy[1]))

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
            analysis = self.analysis_for(grid_or_analysis)
            text = clean_prompt(prompt)
            ctx = Context(analysis=analysis, pose=(start.x_m, start.y_m, start.yaw_deg),
                          known_names=tuple(self.named_places))
            intent = self.translator.translate(text, ctx)
        except LangnavError as exc:
            return self._refusal(prompt, None, str(exc), name)
        name = intent.translator or name
        if intent.clarification and not intent.steps:
            return self._refusal(prompt, intent, intent.clarification, name)
        try:
            grounded = ground(intent, analysis, start, params=self.params, named_places=self.named_places)
            checked = validate_plan(grounded.commands, analysis.grid, start, params=self.params,
                                    space=free_space_for(analysis.grid, self.params))
        except PlanRejected as exc:
            return self._refusal(prompt, intent, "I will not run that: " + "; ".join(exc.reasons) + ".", name)
        except GroundingError as exc:
            return self._refusal(prompt, intent, str(exc), name)
        messages = [m for s in grounded.steps for m in s.messages]
        messages.extend(checked.repairs)
        if intent.clarification:
            messages.append(intent.clarification)
        if intent.unread:
            messages.append("I did not understand: " + "; ".join(f"'{u}'" for u in intent.unread))
        items = self._items(grounded, checked.commands)
        return PlanResult(prompt, intent, tuple(checked.commands), items, tuple(messages), None, name)

    def _items(self, grounded: GroundedPlan, commands: tuple[Command, ...]) -> tuple[PlanItem, ...]:
        items: list[PlanItem] = []
        k = 0
        for s in grounded.steps:
            n = len(s.commands)
            items.append(PlanItem(s.index, s.step, tuple(commands[k:k + n]), s.note, s.explore, self,
                                  grounded.start_pose))
            k += n
        return tuple(items)

    def _refusal(self, prompt: str, intent: Intent | None, reason: str, name: str) -> PlanResult:
        log.info("plan refused: %s", reason)
        return PlanResult(prompt, intent, (), (), (), reason, name)

    def reground_step(self, step: Step, pose: Pose | tuple[float, float, float],
                      grid_or_analysis: OccupancyGrid | MapAnalysis, index: int = 0, *,
                      origin: Pose | None = None) -> list[Command]:
        """One step's commands from ``pose`` on the map of now, validated. ``origin`` is the pose the
        prompt started from (for "go back"). Raises GroundingError / PlanRejected with a readable reason."""
        analysis = self.analysis_for(grid_or_analysis)
        start = as_pose(pose)
        ctx = GroundingContext(analysis, free_space_for(analysis.grid, self.params), self.params,
                               dict(self.named_places), origin=origin)
        gs: GroundedStep = ground_step(step, ctx, start, index)
        checked = validate_plan(list(gs.commands), analysis.grid, start, params=self.params, space=ctx.space)
        return list(checked.commands)


def bench_line(case_id: str, result: PlanResult) -> dict[str, Any]:
    return result.to_bench(case_id)


__all__ = ["ANALYSIS_CACHE_SIZE", "Analyzer", "PlanItem", "PlanResult", "Planner", "TranslationError",
           "bench_line", "default_analyzer"]

