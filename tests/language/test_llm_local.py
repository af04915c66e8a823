"""The local backend: assembling and checking the model file (always), and one real prompt through
the installed model (``local_llm``: only with ``-m local_llm`` and the ``local`` extra installed)."""

from __future__ import annotations

import hashlib
import time
from pathlib import Path

import pytest
from llm_doubles import POSE, two_room_analysis

from langnav.language.errors import LLMError
from langnav.language.intent import Direction, Movement
from langnav.language.llm import local_backend
from langnav.language.llm.local_backend import LocalConfig, cache_dir, runtime_available
from langnav.language.translator import Context


def _fake_parts(tmp_path: Path, chunks: list[bytes]) -> list[Path]:
    files = []
    for i, chunk in enumerate(chunks, start=1):
        f = tmp_path / f"part{i:02d}.bin"
        f.write_bytes(chunk)
        files.append(f)
    return files


def test_parts_are_joined_in_order_and_checked(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    chunks = [b"GGUF" + bytes(range(50)), b"middle" * 1000, b"end"]
    monkeypatch.setattr(local_backend, "part_files", lambda: _fake_parts(tmp_path, chunks))
    monkeypatch.setattr(local_backend, "DEFAULT_MODEL_SHA256", hashlib.sha256(b"".join(chunks)).hexdigest())
    target = local_backend.assemble_default_model(tmp_path / "cache")
    assert target.read_bytes() == b"".join(chunks)
    assert local_backend.assemble_default_model(tmp_path / "cache") == target  # cached, still verified
    target.write_bytes(b"corrupted")
    assert local_backend.assemble_default_model(tmp_path / "cache").read_bytes() == b"".join(chunks)


def test_wrong_parts_are_refused(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(local_backend, "part_files", lambda: _fake_parts(tmp_path, [b"not", b"the model"]))
    with pytest.raises(LLMError, match="sha256"):
        local_backend.assemble_default_model(tmp_path / "cache")
    assert not list((tmp_path / "cache").iterdir())  # no half-written file is left


def test_configuration(tmp_path: Path) -> None:
    model = tmp_path / "m.gguf"
    model.write_bytes(b"GGUF")
    assert LocalConfig.from_env({"LANGNAV_LOCAL_MODEL": str(model), "LANGNAV_LOCAL_THREADS": "3"}) == \
        LocalConfig(model_path=model, threads=3)
    with pytest.raises(LLMError, match="LANGNAV_LOCAL_THREADS"):
        LocalConfig.from_env({"LANGNAV_LOCAL_THREADS": "many"})
    assert cache_dir({"LANGNAV_CACHE_DIR": "/c"}) == Path("/c")
    assert cache_dir({"XDG_CACHE_HOME": "/x"}) == Path("/x/langnav")


def _local_selected(config: pytest.Config) -> bool:
    return "local_llm" in (config.getoption("markexpr") or "")


@pytest.mark.local_llm
@pytest.mark.slow
def test_one_prompt_through_the_installed_model(request: pytest.FixtureRequest) -> None:
    if not _local_selected(request.config):
        pytest.skip("runs the 1.1 GB local model (~1 min): select it with -m local_llm")
    if not runtime_available():
        pytest.skip("the 'local' extra (xllamacpp) is not installed")
    try:
        local_backend.part_files()
    except LLMError as exc:
        pytest.skip(str(exc))
    from langnav.language.llm import local_translator

    translator = local_translator()
    ctx = Context(analysis=two_room_analysis(), pose=POSE)
    start = time.monotonic()
    intent = translator.translate("Turn right 90 degrees, then move forward half a meter.", ctx)
    print(f"local model: {time.monotonic() - start:.1f} s (first call, includes loading)")
    assert intent.translator == "local"
    assert [s.movement for s in intent.steps] == [Movement.ROTATE, Movement.MOVE]
    assert intent.steps[0].direction == Direction.RIGHT and intent.steps[0].angle_deg == 90
    assert intent.steps[1].direction == Direction.FORWARD and intent.steps[1].distance_m == 0.5


def test_decoding_schema_is_compact_and_still_the_intent() -> None:
    from langnav.language.llm.base import answer_schema, parse_answer

    schema = answer_schema()
    strict = local_backend.decoding_schema(schema)
    assert strict["x-guidance"] == {"whitespace_flexible": False}
    assert "text" not in strict["$defs"]["Step"]["properties"]
    assert "text" in schema["$defs"]["Step"]["properties"]  # the original is untouched
    intent = parse_answer('{"steps":[{"movement":"rotate","direction":"right","angle_deg":90}]}')
    assert intent.steps[0].angle_deg == 90
