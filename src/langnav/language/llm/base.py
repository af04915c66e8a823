"""The shared logic of every LLM translator, written once: vendor backends only move text.

Flow of :meth:`LLMTranslator.translate`::

    prompt -> clean_prompt -> command context (context.py) -> backend.complete(messages, schema, timeout)
           -> parse JSON -> Intent (pydantic) -> check against the map
           -> on a schema error: re-ask once with the error -> still wrong: LLMError

The model's answer is data: it is parsed into :class:`~langnav.language.intent.Intent` and
validated; nothing in it is executed. Names of elements the map does not hold (a kind with no
element, "the third door" when there are two, a name the user never gave) turn the answer into
a clarification: the robot runs nothing and the user is told why. A plan is never guessed.
"""

from __future__ import annotations

import json
import logging
import math
import os
import time
from collections.abc import Mapping, Sequence
from typing import Any, Final, Protocol, TypedDict

from pydantic import ValidationError

from langnav.analysis.elements import ElementKind, MapAnalysis, element_kind, reference_point
from langnav.language.errors import LLMError
from langnav.language.intent import Element, ElementRef, Intent, Side
from langnav.language.translator import Context, clean_prompt
from langnav.places.store import place_key

log = logging.getLogger(__name__)

#: Seconds one model call may take. Hosted models answer in 1-5 s; a local 1.5B model on a
#: 2-core CPU needs 10-40 s, and 2-4 times that for the first call on a busy machine (it loads the
#: model and reads the whole context), so its translator passes its own, longer, default.
DEFAULT_TIMEOUT_S: Final = 30.0
LOCAL_TIMEOUT_S: Final = 240.0
ENV_TIMEOUT: Final = "LANGNAV_LLM_TIMEOUT_S"
#: How many times the model is asked again after an answer that fails validation.
MAX_REASKS: Final = 1
#: Bound on the raw answer we parse (an intent of 20 full steps is under 10 kB).
MAX_ANSWER_CHARS: Final = 20_000
#: Fields of Intent that langnav sets, not the model.
_BOOKKEEPING: Final = ("translator", "confidence", "unread")

#: Bench contract (../shared/bench/README.md): "ahead" within ±60° of the heading, "behind" beyond ±120°.
AHEAD_MAX_DEG: Final = 60.0
BEHIND_MIN_DEG: Final = 120.0


class Message(TypedDict):
    role: str  # "system" | "user" | "assistant"
    content: str


class ChatBackend(Protocol):
    """One vendor: send chat messages, get the answer's text. Raises LLMError on any failure
    (not configured, unreachable, refused, timed out); must return within ``timeout_s``."""

    name: str

    def complete(self, messages: Sequence[Message], schema: dict[str, Any], timeout_s: float) -> str: ...


class AnswerError(ValueError):
    """The model's answer does not fit the intent schema (message is fed back to the model)."""


def answer_schema() -> dict[str, Any]:
    """The JSON schema the model answers in: Intent without the fields langnav fills itself,
    compacted (no titles, no null defaults) so it costs fewer tokens."""
    schema = Intent.model_json_schema()
    for key in _BOOKKEEPING:
        schema["properties"].pop(key, None)
    return _strip_titles(schema)


def _strip_titles(node: Any) -> Any:
    if isinstance(node, dict):
        return {k: _strip_titles(v) for k, v in node.items()
                if not (k == "title" and isinstance(v, str)) and not (k == "default" and v is None)}
    if isinstance(node, list):
        return [_strip_titles(v) for v in node]
    return node


def parse_answer(raw: str) -> Intent:
    """Model text -> Intent, or AnswerError saying what is wrong in words the model can act on."""
    if len(raw) > MAX_ANSWER_CHARS:
        raise AnswerError(f"the answer is {len(raw)} characters long; answer with one short JSON object")
    text = _unfence(raw)
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise AnswerError(f"the answer is not valid JSON ({exc.msg} at line {exc.lineno} column {exc.colno}); "
                          "answer with one JSON object only, no prose") from None
    except (ValueError, RecursionError) as exc:  # a number of thousands of digits, nesting too deep
        raise AnswerError(f"the answer is not usable JSON ({str(exc)[:80]}); answer with one short JSON "
                          "object, numbers in plain decimals") from None
    if not isinstance(data, dict):
        raise AnswerError(f"the answer must be a JSON object with 'steps' and 'clarification', not a {type(data).__name__}")
    for key in _BOOKKEEPING:
        data.pop(key, None)
    try:
        intent = Intent.model_validate(data)
    except ValidationError as exc:
        problems = "; ".join(
            f"{'.'.join(str(p) for p in e['loc']) or 'answer'}: {e['msg']}" for e in exc.errors()[:8])
        raise AnswerError(f"the answer does not fit the schema: {problems}") from None
    if not intent.steps and not intent.clarification:
        raise AnswerError("the answer has no steps and no clarification; give the steps, or a clarification "
                          "saying why nothing should run")
    return intent


def _unfence(raw: str) -> str:
    """Servers without structured output sometimes wrap JSON in a Markdown fence; take the inside."""
    text = raw.strip()
    if text.startswith("```"):
        text = text.split("\n", 1)[1] if "\n" in text else ""
        text = text.rsplit("```", 1)[0]
    return text.strip()


# --- checking the answer against the map ------------------------------------------------------

_KINDS: Final[dict[Element, ElementKind]] = {
    Element.DOOR: ElementKind.DOOR, Element.WALL: ElementKind.WALL, Element.ROOM: ElementKind.ROOM,
    Element.HALLWAY: ElementKind.HALLWAY, Element.NARROW_PASSAGE: ElementKind.NARROW_PASSAGE,
    Element.OBSTACLE: ElementKind.OBSTACLE, Element.CORNER: ElementKind.CORNER,
    Element.UNEXPLORED_AREA: ElementKind.UNEXPLORED,
}
#: For these, ``side`` picks one of a room's corners / walls ("the left corner"), not a side of the robot.
_SIDE_IS_WHICH_ONE: Final = (Element.CORNER, Element.WALL)
_SIDE_WORDS: Final = {Side.LEFT: " on the robot's left", Side.RIGHT: " on the robot's right",
                      Side.AHEAD: " ahead of the robot", Side.BEHIND: " behind the robot"}
_WORDS: Final[dict[Element, str]] = {e: e.value.replace("_", " ") for e in Element}


def robot_side(pose: tuple[float, float, float], point: tuple[float, float]) -> set[Side]:
    """The sides of the robot a point lies on, by the bench's contract (a point can be left and ahead)."""
    x, y, yaw_deg = pose
    dx, dy = point[0] - x, point[1] - y
    yaw = math.radians(yaw_deg)
    forward = dx * math.cos(yaw) + dy * math.sin(yaw)
    lateral = -dx * math.sin(yaw) + dy * math.cos(yaw)
    bearing = abs(math.degrees(math.atan2(lateral, forward)))
    sides: set[Side] = set()
    if lateral > 0:
        sides.add(Side.LEFT)
    elif lateral < 0:
        sides.add(Side.RIGHT)
    if bearing <= AHEAD_MAX_DEG:
        sides.add(Side.AHEAD)
    if bearing >= BEHIND_MIN_DEG:
        sides.add(Side.BEHIND)
    return sides


def missing_references(intent: Intent, context: Context) -> list[str]:
    """What the answer names that this map (or the user) cannot supply, in words for the user.

    Only what is certainly absent is reported: a kind with no element at all, an ordinal beyond
    how many there are (on the named side), a proper name the user never gave.
    """
    problems: list[str] = []
    known = {place_key(n) for n in context.known_names}
    analysis = context.analysis
    for step in intent.steps:
        for ref in (step.target, step.second_target):
            if ref is None:
                continue
            if ref.name and place_key(ref.name) not in known:
                problems.append(f"I don't know where '{ref.name}' is: the map has no labels. "
                                "Describe it by what the map shows (a door, a room, a corner ...)")
                continue
            if analysis is not None:
                problems.extend(_absent_in_map(ref, analysis, context.pose))
    return list(dict.fromkeys(problems))


def _absent_in_map(ref: ElementRef, analysis: MapAnalysis,
                   pose: tuple[float, float, float] | None) -> list[str]:
    out: list[str] = []
    for kind in (ref.kind, ref.within):
        if kind is None or kind == Element.NONE:
            continue
        if not _of_kind(analysis, kind):
            out.append(f"there is no {_WORDS[kind]} in this map")
    if out or ref.kind == Element.NONE:
        return out
    candidates = _of_kind(analysis, ref.kind)
    side_note = ""
    if ref.side is not None and pose is not None and ref.kind not in _SIDE_IS_WHICH_ONE:
        candidates = [e for e in candidates if ref.side in robot_side(pose, reference_point(e))]
        side_note = _SIDE_WORDS[ref.side]
        if not candidates:
            out.append(f"there is no {_WORDS[ref.kind]}{side_note}")
            return out
    if ref.ordinal is not None and ref.ordinal > len(candidates):
        n = len(candidates)
        out.append(f"there {'is' if n == 1 else 'are'} only {n} {_WORDS[ref.kind]}{'' if n == 1 else 's'}"
                   f"{side_note}, so there is no number {ref.ordinal}")
    return out


def _of_kind(analysis: MapAnalysis, kind: Element) -> list[Any]:
    target = _KINDS[kind]
    return [e for e in analysis.elements if element_kind(e) == target]


# --- the translator ---------------------------------------------------------------------------


def timeout_from_env(default_s: float, env: Mapping[str, str] | None = None) -> float:
    env = os.environ if env is None else env
    raw = env.get(ENV_TIMEOUT)
    if not raw:
        return default_s
    try:
        value = float(raw)
    except ValueError:
        raise LLMError(f"{ENV_TIMEOUT}={raw!r} is not a number of seconds") from None
    if not (0 < value <= 3600):
        raise LLMError(f"{ENV_TIMEOUT}={raw!r} must be between 0 and 3600 seconds")
    return value


class LLMTranslator:
    """A :class:`~langnav.language.translator.Translator` over any :class:`ChatBackend`."""

    def __init__(self, backend: ChatBackend, *, timeout_s: float = DEFAULT_TIMEOUT_S,
                 max_elements: int | None = None, schema_in_prompt: bool = True) -> None:
        from langnav.language.llm.context import MAX_ELEMENTS

        if not (timeout_s > 0):
            raise LLMError(f"the LLM timeout must be positive, got {timeout_s!r}")
        self.backend = backend
        self.name = backend.name
        self.timeout_s = timeout_s
        self.max_elements = MAX_ELEMENTS if max_elements is None else max_elements
        self.schema_in_prompt = schema_in_prompt
        self._schema = answer_schema()

    def translate(self, prompt: str, context: Context) -> Intent:
        from langnav.language.llm.context import build_messages

        text = clean_prompt(prompt)
        messages = build_messages(text, context, max_elements=self.max_elements, schema=self._schema,
                                  include_schema=self.schema_in_prompt)
        deadline = time.monotonic() + self.timeout_s * (1 + MAX_REASKS)
        error: AnswerError | None = None
        for attempt in range(1 + MAX_REASKS):
            remaining = max(0.001, min(self.timeout_s, deadline - time.monotonic()))
            raw = self.backend.complete(messages, self._schema, remaining)
            try:
                intent = parse_answer(raw)
            except AnswerError as exc:
                error = exc
                log.info("%s answer %d rejected: %s", self.name, attempt + 1, exc)
                messages = [*messages, Message(role="assistant", content=raw[:MAX_ANSWER_CHARS]),
                            Message(role="user", content=reask_text(str(exc)))]
                continue
            return self._finish(intent, context)
        raise LLMError(
            f"the {self.name} model answered twice in a form langnav cannot use ({error}); nothing will run. "
            "Rephrase the request, or use the offline translator")

    def _finish(self, intent: Intent, context: Context) -> Intent:
        problems = missing_references(intent, context)
        if problems:
            log.info("%s answer names what the map does not hold: %s", self.name, problems)
            reason = "; ".join(problems)
            intent = Intent(steps=[], clarification=(reason[0].upper() + reason[1:] + ".")[:500])
        return intent.model_copy(update={"translator": self.name})


def reask_text(error: str) -> str:
    return (f"Your answer could not be used: {error}. Answer the same request again with one JSON object "
            "that fits the schema exactly (only the listed fields and values).")
