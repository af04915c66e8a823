"""The ``openai`` backend: the official openai SDK, chat completions, any OpenAI-compatible server.

With ``LANGNAV_OPENAI_BASE_URL`` (or ``OPENAI_BASE_URL``) it talks to Ollama
(``http://localhost:11434/v1``), vLLM, a llama.cpp server (``http://localhost:8080/v1``) or any
other server that speaks the chat-completions protocol; without it, to OpenAI.

Environment:
    OPENAI_API_KEY            the key (OpenAI); local servers take any placeholder, and one is used if unset
    LANGNAV_OPENAI_BASE_URL   the server (falls back to OPENAI_BASE_URL)
    LANGNAV_OPENAI_MODEL      the model name (required with a base URL; default DEFAULT_MODEL for OpenAI)

Structured output: ``response_format`` json_schema; a server that refuses it gets json_object
(then the schema is only in the system prompt, and validation catches the rest).
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

ENV_KEY: Final = "OPENAI_API_KEY"
ENV_BASE_URL: Final = "LANGNAV_OPENAI_BASE_URL"
ENV_BASE_URL_SDK: Final = "OPENAI_BASE_URL"
ENV_MODEL: Final = "LANGNAV_OPENAI_MODEL"
#: A small current OpenAI model: intents are short, latency matters more than depth.
DEFAULT_MODEL: Final = "gpt-5.4-mini"
#: Local servers check no key, but the SDK requires one.
PLACEHOLDER_KEY: Final = "not-needed"
#: An intent of a few steps is a few hundred tokens; the schema caps steps at 20.
MAX_ANSWER_TOKENS: Final = 1500


@dataclass(frozen=True)
class OpenAIConfig:
    api_key: str
    base_url: str | None
    model: str

    @classmethod
    def from_env(cls, env: Mapping[str, str] | None = None) -> OpenAIConfig:
        env = os.environ if env is None else env
        base_url = env.get(ENV_BASE_URL) or env.get(ENV_BASE_URL_SDK) or None
        key = env.get(ENV_KEY) or None
        if key is None and base_url is None:
            raise LLMError(
                f"the openai translator is not configured: set {ENV_KEY} for OpenAI, or {ENV_BASE_URL} "
                "(and LANGNAV_OPENAI_MODEL) for a local server such as Ollama (http://localhost:11434/v1), "
                "vLLM or llama.cpp")
        model = env.get(ENV_MODEL) or None
        if model is None:
            if base_url is not None:
                raise LLMError(f"{ENV_BASE_URL} is set to {base_url}: also set {ENV_MODEL} to the name of a "
                               "model that server serves (e.g. 'qwen2.5:7b' on Ollama)")
            model = DEFAULT_MODEL
        return cls(api_key=key or PLACEHOLDER_KEY, base_url=base_url, model=model)


class OpenAIBackend:
    name = "openai"

    def __init__(self, config: OpenAIConfig) -> None:
        import openai  # lazily: the SDK is needed only when this backend is used

        self.config = config
        self._openai = openai
        # Retries are ours to decide (the translator re-asks once); the SDK's would multiply the timeout.
        self._client = openai.OpenAI(api_key=config.api_key, base_url=config.base_url, max_retries=0)
        self._json_schema_ok = True

    @classmethod
    def from_env(cls) -> OpenAIBackend:
        return cls(OpenAIConfig.from_env())

    @property
    def _where(self) -> str:
        return self.config.base_url or "api.openai.com"

    def _format(self, schema: dict[str, Any]) -> dict[str, Any]:
        if self._json_schema_ok:
            return {"type": "json_schema", "json_schema": {"name": "intent", "schema": schema, "strict": False}}
        return {"type": "json_object"}

    def complete(self, messages: Sequence[Message], schema: dict[str, Any], timeout_s: float) -> str:
        openai = self._openai
        create: Any = self._client.chat.completions.create  # kwargs built at run time; the SDK checks them
        kwargs: dict[str, Any] = {"model": self.config.model, "messages": list(messages), "timeout": timeout_s,
                                  "max_completion_tokens": MAX_ANSWER_TOKENS}
        if self.config.base_url is not None:
            kwargs["temperature"] = 0.0  # local servers: deterministic answers (OpenAI reasoning models refuse it)
        try:
            try:
                response = create(response_format=self._format(schema), **kwargs)
            except openai.BadRequestError as exc:
                if not (self._json_schema_ok and _mentions_format(exc)):
                    raise
                log.info("%s refused response_format json_schema (%s); using json_object", self._where, exc)
                self._json_schema_ok = False
                response = create(response_format=self._format(schema), **kwargs)
        except openai.APITimeoutError:
            raise LLMError(f"the openai backend ({self._where}) did not answer within {timeout_s:.1f} s; "
                           "try again, raise LANGNAV_LLM_TIMEOUT_S, or use the offline translator") from None
        except openai.APIConnectionError as exc:
            raise LLMError(f"cannot reach the openai backend at {self._where}: {exc}. Is the server running? "
                           f"Check {ENV_BASE_URL}") from None
        except openai.AuthenticationError:
            raise LLMError(f"{self._where} rejected the API key: check {ENV_KEY}") from None
        except openai.NotFoundError:
            raise LLMError(f"{self._where} does not serve the model {self.config.model!r}: check {ENV_MODEL}") from None
        except openai.APIStatusError as exc:
            raise LLMError(f"the openai backend ({self._where}) answered HTTP {exc.status_code}: "
                           f"{_short(exc.message)}") from None
        except openai.OpenAIError as exc:
            raise LLMError(f"the openai backend ({self._where}) failed: {_short(str(exc))}") from None
        if not response.choices:
            raise LLMError(f"the openai backend ({self._where}) answered with no choices")
        message = response.choices[0].message
        if message.content is None:
            # A refusal or an empty answer: hand back its text so the translator re-asks once.
            return message.refusal or ""
        return message.content


def _mentions_format(exc: Exception) -> bool:
    text = str(exc).lower()
    return "response_format" in text or "json_schema" in text


def _short(text: str, limit: int = 300) -> str:
    return text if len(text) <= limit else text[:limit] + "..."
