"""LLM translators: a command context generator, one shared translator, thin vendor backends.

Registered translators (see :func:`langnav.language.translator.get_translator`):

- ``gemini``  Google Gemini via google-genai (GEMINI_API_KEY)
- ``openai``  the openai SDK: OpenAI, or any chat-completions server via LANGNAV_OPENAI_BASE_URL
- ``local``   a GGUF model in-process (the ``local`` extra: xllamacpp + a model from PyPI)
- ``auto``    offline first, the configured LLM for what offline cannot read

Vendor SDKs are imported only when their backend is built. Building a backend whose key or
model is missing raises LLMError naming the environment variable to set.
"""

from __future__ import annotations

from functools import lru_cache

from langnav.language.llm.auto import AutoTranslator, configured_backend, make_auto
from langnav.language.llm.base import (
    DEFAULT_TIMEOUT_S,
    LOCAL_TIMEOUT_S,
    ChatBackend,
    LLMTranslator,
    Message,
    answer_schema,
    missing_references,
    parse_answer,
    timeout_from_env,
)
from langnav.language.llm.context import (
    build_messages,
    describe_map,
    element_views,
    example_messages,
    request_text,
    system_prompt,
)
from langnav.language.translator import Translator, register

#: Elements listed for the local model: every room and the nearest doors still fit.
LOCAL_MAX_ELEMENTS = 24


def gemini_translator() -> LLMTranslator:
    from langnav.language.llm.gemini_backend import GeminiBackend

    return LLMTranslator(GeminiBackend.from_env(), timeout_s=timeout_from_env(DEFAULT_TIMEOUT_S))


def openai_translator() -> LLMTranslator:
    from langnav.language.llm.openai_backend import OpenAIBackend

    return LLMTranslator(OpenAIBackend.from_env(), timeout_s=timeout_from_env(DEFAULT_TIMEOUT_S))


def local_translator() -> LLMTranslator:
    from langnav.language.llm.local_backend import LocalConfig

    # Decoding is constrained to the schema, so it is left out of the prompt, and the element list is
    # shorter: prompt reading dominates a small model's time on a CPU.
    return LLMTranslator(_local_backend(LocalConfig.from_env()), timeout_s=timeout_from_env(LOCAL_TIMEOUT_S),
                         max_elements=LOCAL_MAX_ELEMENTS, schema_in_prompt=False)


@lru_cache(maxsize=2)
def _local_backend(config: object) -> ChatBackend:
    """One in-process model per configuration, kept loaded for every later prompt."""
    from langnav.language.llm.local_backend import LocalBackend, LocalConfig

    assert isinstance(config, LocalConfig)
    return LocalBackend(config)


LLM_TRANSLATORS = {"gemini": gemini_translator, "openai": openai_translator, "local": local_translator}


def auto_translator() -> Translator:
    return make_auto(LLM_TRANSLATORS)


for _name, _factory in LLM_TRANSLATORS.items():
    register(_name, _factory)
register("auto", auto_translator)

__all__ = ["DEFAULT_TIMEOUT_S", "LOCAL_TIMEOUT_S", "AutoTranslator", "ChatBackend", "LLMTranslator", "Message",
           "answer_schema", "build_messages", "configured_backend", "describe_map", "element_views",
           "example_messages", "missing_references", "parse_answer", "request_text", "system_prompt"]
