"""The translator seam: prompt (+ map context) -> Intent. Implementations register by name."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Final, Protocol, runtime_checkable

from langnav.analysis.elements import MapAnalysis
from langnav.language.errors import TranslationError
from langnav.language.intent import Intent

#: Longest prompt accepted, in characters (a paragraph of instructions is ~500).
MAX_PROMPT_CHARS: Final = 2000


@dataclass(frozen=True)
class Context:
    """What a translator may know besides the words: the map analysis and the robot's pose."""

    analysis: MapAnalysis | None = None
    pose: tuple[float, float, float] | None = None  # x_m, y_m, yaw_deg
    #: names the user has given to places earlier ("call this the kitchen")
    known_names: tuple[str, ...] = ()


@runtime_checkable
class Translator(Protocol):
    name: str

    def translate(self, prompt: str, context: Context) -> Intent:
        """Read a prompt. Raises TranslationError (LLMError for LLM failures); never guesses a plan."""
        ...


def clean_prompt(prompt: str) -> str:
    """Normalise and bound a prompt: strip control characters, collapse whitespace, refuse empty/huge."""
    if not isinstance(prompt, str):
        raise TranslationError("the prompt must be text")
    if len(prompt) > MAX_PROMPT_CHARS * 4:
        raise TranslationError(
            f"the prompt is {len(prompt)} characters long; langnav reads at most {MAX_PROMPT_CHARS}. "
            "Give the robot one short instruction or a few steps.")
    text = "".join(ch if ch.isprintable() or ch in "\n\t" else " " for ch in prompt)
    text = " ".join(text.split())
    if not text:
        raise TranslationError("the prompt is empty: tell the robot where to go, e.g. 'go to the nearest door'")
    if len(text) > MAX_PROMPT_CHARS:
        raise TranslationError(
            f"the prompt is {len(text)} characters long; langnav reads at most {MAX_PROMPT_CHARS}. "
            "Give the robot one short instruction or a few steps.")
    return text


TranslatorFactory = Callable[[], Translator]
_REGISTRY: dict[str, TranslatorFactory] = {}


def register(name: str, factory: TranslatorFactory) -> None:
    _REGISTRY[name] = factory


def available() -> list[str]:
    _load_builtin()
    return sorted(_REGISTRY)


def get_translator(name: str) -> Translator:
    """Build the translator registered under ``name`` (offline, gemini, openai, local, auto)."""
    _load_builtin()
    try:
        factory = _REGISTRY[name]
    except KeyError:
        raise TranslationError(
            f"unknown translator {name!r}; choose one of: {', '.join(sorted(_REGISTRY))}") from None
    return factory()


def _load_builtin() -> None:
    # Importing the modules registers them; LLM SDKs are imported lazily inside each backend.
    import importlib

    for mod in ("langnav.language.offline", "langnav.language.llm"):
        try:
            importlib.import_module(mod)
        except ModuleNotFoundError as exc:
            if exc.name != mod:
                raise
