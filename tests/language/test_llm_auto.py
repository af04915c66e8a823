"""The auto translator: offline first, the LLM backend for what offline cannot read; and the registry."""

from __future__ import annotations

from dataclasses import dataclass, field

import pytest
from llm_doubles import (
    GO_TO_LEFT_DOOR,
    POSE,
    ModelServer,
    Reply,
    ScriptedBackend,
    answer,
    chat_completion,
    model_server,
    no_network,
    two_room_analysis,
)

from langnav.language.errors import LLMError
from langnav.language.intent import Intent, Movement, Step
from langnav.language.llm.auto import AutoTranslator, configured_backend, make_auto
from langnav.language.llm.base import LLMTranslator
from langnav.language.translator import Context, Translator, get_translator

__all__ = ["model_server", "no_network"]  # fixtures used by these tests

CTX = Context(analysis=two_room_analysis(), pose=POSE)


@dataclass
class FixedOffline:
    """Stands in for the offline translator: returns a given reading and counts calls."""

    reading: Intent
    name: str = "offline"
    prompts: list[str] = field(default_factory=list)

    def translate(self, prompt: str, context: Context) -> Intent:
        self.prompts.append(prompt)
        return self.reading


SURE = Intent(steps=[Step(movement=Movement.STOP, text="stop")], translator="offline")
UNSURE = Intent(steps=[Step(movement=Movement.NAVIGATE, text="go")], translator="offline", confidence=0.4,
                unread=["by the squeaky chair"])
UNREAD = Intent(steps=[Step(movement=Movement.STOP)], translator="offline", unread=["wiggle"])
NOT_UNDERSTOOD = Intent(clarification="I did not understand 'wiggle'.", translator="offline", confidence=0.2)


def _llm(*answers: str | LLMError) -> tuple[LLMTranslator, ScriptedBackend]:
    backend = ScriptedBackend(list(answers), name="openai")
    return LLMTranslator(backend, timeout_s=5), backend


def test_confident_offline_reading_is_kept() -> None:
    llm, backend = _llm()
    intent = AutoTranslator(FixedOffline(SURE), llm).translate("stop", CTX)
    assert intent == SURE and intent.translator == "offline" and backend.calls == []


@pytest.mark.parametrize("reading", [UNSURE, UNREAD, NOT_UNDERSTOOD])
def test_unsure_reading_goes_to_the_llm(reading: Intent) -> None:
    llm, backend = _llm(answer([GO_TO_LEFT_DOOR]))
    intent = AutoTranslator(FixedOffline(reading), llm).translate("go to the door by the squeaky chair", CTX)
    assert intent.translator == "offline+openai"
    assert intent.steps[0].target is not None and intent.steps[0].target.kind == "door"
    assert len(backend.calls) == 1


def test_without_llm_auto_is_offline() -> None:
    intent = AutoTranslator(FixedOffline(UNSURE), None).translate("go", CTX)
    assert intent == UNSURE and intent.translator == "offline"


def test_llm_failure_never_runs_an_unsure_plan() -> None:
    llm, _ = _llm(LLMError("the openai backend did not answer within 5.0 s"))
    with pytest.raises(LLMError, match=r"unsure of this prompt \(could not read: by the squeaky chair\).*5\.0 s"):
        AutoTranslator(FixedOffline(UNSURE), llm).translate("go by the squeaky chair", CTX)


def test_llm_failure_keeps_an_offline_clarification() -> None:
    llm, _ = _llm(LLMError("down"))
    intent = AutoTranslator(FixedOffline(NOT_UNDERSTOOD), llm).translate("wiggle", CTX)
    assert intent.steps == [] and intent.clarification == "I did not understand 'wiggle'."


@pytest.mark.parametrize(("env", "expected"), [
    ({}, None),
    ({"LANGNAV_LLM": "none", "GEMINI_API_KEY": "k"}, None),
    ({"LANGNAV_LLM": "Local"}, "local"),
    ({"GOOGLE_API_KEY": "k", "OPENAI_API_KEY": "k"}, "gemini"),
    ({"OPENAI_API_KEY": "k"}, "openai"),
    ({"LANGNAV_OPENAI_BASE_URL": "http://127.0.0.1:8080/v1"}, "openai"),
    ({"LANGNAV_LOCAL_MODEL": "/models/q.gguf"}, "local"),
])
def test_backend_choice(env: dict[str, str], expected: str | None) -> None:
    assert configured_backend(env) == expected


def test_unknown_backend_choice_is_an_error() -> None:
    with pytest.raises(LLMError, match="gemini, openai, local, or none"):
        configured_backend({"LANGNAV_LLM": "claude"})


def test_make_auto_builds_the_configured_backend(monkeypatch: pytest.MonkeyPatch) -> None:
    built: list[str] = []

    def factory() -> Translator:
        built.append("openai")
        return _llm(answer([GO_TO_LEFT_DOOR]))[0]

    offline = FixedOffline(UNSURE)
    monkeypatch.setattr("langnav.language.translator.get_translator", lambda name: offline)
    auto = make_auto({"openai": factory}, env={"OPENAI_API_KEY": "k"})
    assert built == ["openai"] and auto.offline is offline
    assert auto.translate("go", CTX).translator == "offline+openai"
    assert make_auto({"openai": factory}, env={}).llm is None


@pytest.mark.parametrize(("name", "var"), [("openai", "OPENAI_API_KEY"), ("gemini", "GEMINI_API_KEY")])
def test_unconfigured_backends_name_their_variable(monkeypatch: pytest.MonkeyPatch, name: str, var: str) -> None:
    for v in ("OPENAI_API_KEY", "LANGNAV_OPENAI_BASE_URL", "OPENAI_BASE_URL", "GEMINI_API_KEY", "GOOGLE_API_KEY"):
        monkeypatch.delenv(v, raising=False)
    with pytest.raises(LLMError, match=var):
        get_translator(name)


def test_local_with_a_missing_model_file_names_the_variable(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("LANGNAV_LOCAL_MODEL", "/nonexistent/model.gguf")
    with pytest.raises(LLMError, match=r"LANGNAV_LOCAL_MODEL=/nonexistent/model\.gguf is not a file"):
        get_translator("local")


def test_registered_auto_with_the_real_offline_translator(monkeypatch: pytest.MonkeyPatch) -> None:
    pytest.importorskip("langnav.language.offline")
    monkeypatch.setenv("LANGNAV_LLM", "none")
    auto = get_translator("auto")
    assert isinstance(auto, AutoTranslator) and auto.llm is None
    intent = auto.translate("wiggle around the squeaky chair please", CTX)
    assert intent.translator == "offline" and intent.steps == [] and intent.clarification


def test_registered_auto_asks_a_chat_completions_server(monkeypatch: pytest.MonkeyPatch,
                                                        model_server: ModelServer) -> None:
    pytest.importorskip("langnav.language.offline")
    for var in ("GEMINI_API_KEY", "GOOGLE_API_KEY", "OPENAI_API_KEY", "OPENAI_BASE_URL", "LANGNAV_LLM"):
        monkeypatch.delenv(var, raising=False)
    monkeypatch.setenv("LANGNAV_OPENAI_BASE_URL", model_server.url + "/v1")
    monkeypatch.setenv("LANGNAV_OPENAI_MODEL", "test-model")
    model_server.replies.append(Reply(chat_completion(answer(
        [{"movement": "rotate", "direction": "left", "amount": "little", "text": "wiggle"}]))))
    auto = get_translator("auto")
    assert auto.translate("go to the door on your left", CTX).translator == "offline"
    assert model_server.requests == []
    intent = auto.translate("wiggle around the squeaky chair please", CTX)
    assert intent.translator == "offline+openai" and intent.steps[0].movement == Movement.ROTATE
    assert len(model_server.requests) == 1
