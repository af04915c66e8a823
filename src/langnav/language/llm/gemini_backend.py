"""The ``gemini`` backend (the paper's choice): Google's google-genai SDK, the Gemini API.

Environment:
    GEMINI_API_KEY (or GOOGLE_API_KEY)   the key
    LANGNAV_GEMINI_MODEL                 the model (default DEFAULT_MODEL)
    LANGNAV_GEMINI_BASE_URL              another endpoint (a proxy, or a test server)

Structured output: ``response_mime_type="application/json"`` with ``response_json_schema`` set to
the intent schema. The per-call timeout goes in ``http_options`` (milliseconds); the SDK does not
retry (no ``retry_options``): the translator decides whether to ask again.
"""

from __future__ import annotations

import logging
import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Final

from langnav.language.errors import LLMError
from langnav.language.llm.base import Message

log = logging.getLogger(__name__)

ENV_KEYS: Final = ("GEMINI_API_KEY", "GOOGLE_API_KEY")
ENV_MODEL: Final = "LANGNAV_GEMINI_MODEL"
ENV_BASE_URL: Final = "LANGNAV_GEMINI_BASE_URL"
#: A current Flash model: fast and cheap, enough for short intents.
DEFAULT_MODEL: Final = "gemini-3.8-flash"
MAX_ANSWER_TOKENS: Final = 1500


@dataclass(frozen=True)
class GeminiConfig:
    api_key: str
    model: str
    base_url: str | None = None

    @classmethod
    def from_env(cls, env: Mapping[str, str] | None = None) -> GeminiConfig:
        env = os.environ if env is None else env
        key = next((env[k] for k in ENV_KEYS if env.get(k)), None)
        if key is None:
            raise LLMError("the gemini translator is not configured: set GEMINI_API_KEY (or GOOGLE_API_KEY) "
                           "to a Gemini API key")
        return cls(api_key=key, model=env.get(ENV_MODEL) or DEFAULT_MODEL, base_url=env.get(ENV_BASE_URL) or None)


def _transport_errors() -> tuple[tuple[type[BaseException], ...], tuple[type[BaseException], ...]]:
    """(timeouts, other transport errors) of whichever httpx flavours the SDK may use."""
    timeouts: list[type[BaseException]] = []
    others: list[type[BaseException]] = [OSError]
    for module in ("httpx", "httpx2"):
        try:
            mod = __import__(module)
        except ImportError:
            continue
        timeouts.append(mod.TimeoutException)
        others.append(mod.HTTPError)
    return tuple(timeouts), tuple(others)


class GeminiBackend:
    name = "gemini"

    def __init__(self, config: GeminiConfig) -> None:
        from google import genai  # lazily: the SDK is needed only when this backend is used
        from google.genai import errors, types

        self.config = config
        self._types = types
        self._errors = errors
        options = types.HttpOptions(base_url=config.base_url) if config.base_url else None
        self._client = genai.Client(api_key=config.api_key, vertexai=False, http_options=options)
        self._timeouts, self._transport = _transport_errors()

    @classmethod
    def from_env(cls) -> GeminiBackend:
        return cls(GeminiConfig.from_env())

    def complete(self, messages: Sequence[Message], schema: dict[str, Any], timeout_s: float) -> str:
        types, errors = self._types, self._errors
        system = "\n\n".join(m["content"] for m in messages if m["role"] == "system")
        contents = [types.Content(role="model" if m["role"] == "assistant" else "user",
                                  parts=[types.Part(text=m["content"])])
                    for m in messages if m["role"] != "system"]
        config = types.GenerateContentConfig(
            system_instruction=system or None, temperature=0.0, max_output_tokens=MAX_ANSWER_TOKENS,
            response_mime_type="application/json", response_json_schema=schema,
            http_options=types.HttpOptions(timeout=max(1, round(timeout_s * 1000)), base_url=self.config.base_url))
        try:
            response = self._client.models.generate_content(model=self.config.model, contents=contents, config=config)
        except self._timeouts:
            raise LLMError(f"the gemini backend did not answer within {timeout_s:.1f} s; try again, raise "
                           "LANGNAV_LLM_TIMEOUT_S, or use the offline translator") from None
        except errors.ClientError as exc:
            if exc.code in (401, 403):
                raise LLMError(f"Gemini rejected the API key ({exc.code} {exc.status}): check GEMINI_API_KEY") from None
            if exc.code == 404:
                raise LLMError(f"Gemini has no model {self.config.model!r}: check {ENV_MODEL}") from None
            raise LLMError(f"Gemini refused the request ({exc.code} {exc.status}): {exc.message}") from None
        except errors.APIError as exc:
            raise LLMError(f"Gemini failed ({exc.code} {exc.status}): {exc.message}; try again later") from None
        except self._transport as exc:
            raise LLMError(f"cannot reach Gemini: {exc}") from None
        feedback = response.prompt_feedback
        if feedback is not None and feedback.block_reason is not None:
            raise LLMError(f"Gemini blocked the prompt ({feedback.block_reason}); rephrase it")
        try:
            text = response.text
        except ValueError as exc:  # the SDK raises on some malformed candidate lists
            raise LLMError(f"Gemini answered in an unexpected form: {exc}") from None
        # No text (e.g. finish_reason MAX_TOKENS with nothing usable): let the translator re-ask.
        return text or ""
