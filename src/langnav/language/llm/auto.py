"""The ``auto`` translator: the offline translator first, an LLM backend for what it cannot read.

A prompt the offline translator reads with confidence (``confidence >= AUTO_MIN_CONFIDENCE`` and
nothing ``unread``) is answered by it alone (``translator == "offline"``). Otherwise the whole
prompt goes to the configured LLM backend, which reads it with the map context; the answer says
so (``translator == "offline+openai"``). The LLM reads the whole prompt rather than the unread
fragments: steps refer to each other ("then through it"), and order must be kept.

The backend: ``LANGNAV_LLM`` (gemini, openai, local, or none), else the first configured of
gemini (a key is set) and openai (a key or a base URL is set). ``local`` is used only when named
or when ``LANGNAV_LOCAL_MODEL`` is set, since it takes 10-40 s a prompt on a CPU. With no
backend, auto is the offline translator (a note is logged once).

When the backend fails, auto raises LLMError unless the offline answer runs nothing (a
clarification): an unsure offline plan is never run as if it were sure.
"""

from __future__ import annotations

import logging
import os
from collections.abc import Callable, Mapping
from typing import Final

from langnav.language.errors import LLMError
from langnav.language.intent import Intent
from langnav.language.translator import Context, Translator

log = logging.getLogger(__name__)

ENV_LLM: Final = "LANGNAV_LLM"
#: Below this the offline reading is treated as unsure. The offline translator reports 1.0 for a
#: full reading and lowers it for each guessed or skipped part; 0.8 lets one minor doubt through.
AUTO_MIN_CONFIDENCE: Final = 0.8
LLM_CHOICES: Final = ("gemini", "openai", "local")
_OFF: Final = ("none", "off", "offline", "")


def configured_backend(env: Mapping[str, str] | None = None) -> str | None:
    """The LLM backend auto should use, from the environment; None when there is none."""
    env = os.environ if env is None else env
    if ENV_LLM in env:
        choice = env[ENV_LLM].strip().lower()
        if choice in _OFF:
            return None
        if choice not in LLM_CHOICES:
            raise LLMError(f"{ENV_LLM}={env[ENV_LLM]!r} is not a backend; choose one of: "
                           f"{', '.join(LLM_CHOICES)}, or none")
        return choice
    if env.get("GEMINI_API_KEY") or env.get("GOOGLE_API_KEY"):
        return "gemini"
    if env.get("OPENAI_API_KEY") or env.get("LANGNAV_OPENAI_BASE_URL") or env.get("OPENAI_BASE_URL"):
        return "openai"
    if env.get("LANGNAV_LOCAL_MODEL"):
        return "local"
    return None


class AutoTranslator:
    name = "auto"

    def __init__(self, offline: Translator, llm: Translator | None, *,
                 min_confidence: float = AUTO_MIN_CONFIDENCE) -> None:
        self.offline = offline
        self.llm = llm
        self.min_confidence = min_confidence
        if llm is None:
            log.info("auto translator: no LLM backend configured (set %s=gemini|openai|local and its key); "
                     "prompts the offline translator cannot read are answered by it alone", ENV_LLM)

    def confident(self, intent: Intent) -> bool:
        return intent.confidence >= self.min_confidence and not intent.unread

    def translate(self, prompt: str, context: Context) -> Intent:
        first = self.offline.translate(prompt, context)
        first_name = first.translator if first.translator != "unknown" else self.offline.name
        if self.llm is None or self.confident(first):
            return first.model_copy(update={"translator": first_name})
        log.info("auto: offline reading unsure (confidence %.2f, unread %s); asking %s",
                 first.confidence, first.unread, self.llm.name)
        try:
            second = self.llm.translate(prompt, context)
        except LLMError as exc:
            if not first.steps:
                log.warning("auto: %s failed (%s); keeping the offline clarification", self.llm.name, exc)
                return first.model_copy(update={"translator": first_name})
            unread = f" (could not read: {'; '.join(first.unread)})" if first.unread else ""
            raise LLMError(f"the offline translator was unsure of this prompt{unread} and the {self.llm.name} "
                           f"backend failed: {exc}") from exc
        return second.model_copy(update={"translator": f"{first_name}+{self.llm.name}"})


def make_auto(llm_factories: Mapping[str, Callable[[], Translator]],
              env: Mapping[str, str] | None = None) -> AutoTranslator:
    from langnav.language.translator import get_translator

    offline = get_translator("offline")
    choice = configured_backend(env)
    llm = llm_factories[choice]() if choice is not None else None
    return AutoTranslator(offline, llm)
