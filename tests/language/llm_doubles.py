"""Test doubles for the LLM translators: a scripted chat backend, a local HTTP server that answers
like a model API, a small hand-built map analysis, and a guard that refuses real network calls."""

from __future__ import annotations

import json
import socket
import threading
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Any

import numpy as np
import pytest

from langnav.analysis.elements import Corner, Door, ElementKind, MapAnalysis, Obstacle, Room, Wall
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.language.errors import LLMError
from langnav.language.llm.base import Message
from langnav.maps.grid import OccupancyGrid

# --- no network ---------------------------------------------------------------------------------

_LOOPBACK = ("127.0.0.1", "::1", "localhost")


@pytest.fixture
def no_network(monkeypatch: pytest.MonkeyPatch) -> None:
    """Refuse every connection that is not to this machine: a test must never reach a real model."""
    real_connect = socket.socket.connect

    def guarded(self: socket.socket, address: Any) -> Any:
        host = address[0] if isinstance(address, tuple) else address
        if isinstance(host, str) and host not in _LOOPBACK and not host.startswith("127."):
            raise OSError(f"tests must not use the network (tried {address!r})")
        return real_connect(self, address)

    monkeypatch.setattr(socket.socket, "connect", guarded)
    monkeypatch.setattr(socket, "getaddrinfo", _loopback_only(socket.getaddrinfo))


def _loopback_only(real: Any) -> Any:
    def getaddrinfo(host: Any, *args: Any, **kwargs: Any) -> Any:
        if host not in (None, *_LOOPBACK) and not str(host).startswith("127."):
            raise OSError(f"tests must not resolve {host!r}")
        return real(host, *args, **kwargs)
    return getaddrinfo


# --- a scripted backend (the offline stand-in for a model) -------------------------------------


@dataclass
class ScriptedBackend:
    """Answers with the scripted texts in order; an LLMError in the script is raised instead."""

    answers: list[str | LLMError]
    name: str = "scripted"
    calls: list[list[Message]] = field(default_factory=list)
    timeouts: list[float] = field(default_factory=list)

    def complete(self, messages: Sequence[Message], schema: dict[str, Any], timeout_s: float) -> str:
        self.calls.append(list(messages))
        self.timeouts.append(timeout_s)
        if not self.answers:
            raise AssertionError("the translator asked more often than the script allows")
        answer = self.answers.pop(0)
        if isinstance(answer, LLMError):
            raise answer
        return answer


# --- a local HTTP server speaking a model API ----------------------------------------------------


@dataclass
class Reply:
    body: Any
    status: int = 200
    delay_s: float = 0.0


@dataclass
class Recorded:
    path: str
    headers: dict[str, str]
    body: Any


class ModelServer:
    """A ThreadingHTTPServer on an ephemeral loopback port that answers POSTs with scripted replies."""

    def __init__(self) -> None:
        self.replies: list[Reply] = []
        self.requests: list[Recorded] = []
        self._stop = threading.Event()
        outer = self

        class Handler(BaseHTTPRequestHandler):
            def do_POST(self) -> None:
                length = int(self.headers.get("Content-Length") or 0)
                raw = self.rfile.read(length)
                try:
                    body: Any = json.loads(raw)
                except json.JSONDecodeError:
                    body = raw.decode("utf-8", "replace")
                outer.requests.append(Recorded(self.path, {k.lower(): v for k, v in self.headers.items()}, body))
                reply = outer.replies.pop(0) if outer.replies else Reply({"error": "no scripted reply"}, 500)
                if reply.delay_s and outer._stop.wait(reply.delay_s):
                    return
                data = reply.body if isinstance(reply.body, bytes) else json.dumps(reply.body).encode()
                try:
                    self.send_response(reply.status)
                    self.send_header("Content-Type", "application/json")
                    self.send_header("Content-Length", str(len(data)))
                    self.end_headers()
                    self.wfile.write(data)
                except (BrokenPipeError, ConnectionResetError):  # the client gave up (a timeout test)
                    pass

            def log_message(self, format: str, *args: Any) -> None:
                pass

        self._httpd = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        self._httpd.daemon_threads = True
        self._thread = threading.Thread(target=self._httpd.serve_forever, kwargs={"poll_interval": 0.05},
                                        daemon=True)

    @property
    def url(self) -> str:
        host, port = self._httpd.server_address[:2]
        return f"http://{host!s}:{port}"

    def __enter__(self) -> ModelServer:
        self._thread.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self._stop.set()
        self._httpd.shutdown()
        self._httpd.server_close()
        self._thread.join(timeout=5)


@pytest.fixture
def model_server(no_network: None) -> Iterator[ModelServer]:
    with ModelServer() as server:
        yield server


def chat_completion(content: str | None, *, model: str = "test-model", finish: str = "stop") -> dict[str, Any]:
    """An OpenAI chat-completions response body, as servers send it."""
    return {"id": "chatcmpl-test", "object": "chat.completion", "created": 1_763_800_000, "model": model,
            "choices": [{"index": 0, "finish_reason": finish,
                         "message": {"role": "assistant", "content": content, "refusal": None}}],
            "usage": {"prompt_tokens": 2400, "completion_tokens": 40, "total_tokens": 2440}}


# --- a small map, built by hand ------------------------------------------------------------------

RES_M = 0.1


def two_room_analysis() -> MapAnalysis:
    """A 10 x 10 m floor split at x = 5 m into room_1 (west, 25 m2) and room_2 (east, 20 m2 of it
    free); doors at (5, 3) and (5, 7); one box in room_1 at (2, 8); one corner; two walls.
    No hallway, no narrow passage, no unexplored area."""
    n = int(10 / RES_M)
    cells = np.zeros((n, n), dtype=np.int8)
    grid = OccupancyGrid(cells=cells, resolution_m=RES_M, source="two_rooms")
    labels = np.zeros((n, n), dtype=np.int32)
    labels[:, : n // 2] = 1
    labels[:, n // 2:] = 2
    ys, xs = np.mgrid[0:n, 0:n]
    centres = np.stack([(xs + 0.5) * RES_M, (ys + 0.5) * RES_M], axis=-1)
    west = centres[:, : n // 2].reshape(-1, 2)
    east = centres[:, n // 2:].reshape(-1, 2)
    box_cells = np.array([[1.8 + 0.1 * i, 7.8 + 0.1 * j] for i in range(5) for j in range(5)])
    rooms = (
        Room("room_1", 1, ElementKind.ROOM, 25.0, 24.75, (2.5, 5.0), 10.0, 5.0, west, np.zeros((0, 2))),
        Room("room_2", 2, ElementKind.ROOM, 20.0, 20.0, (7.5, 5.0), 10.0, 5.0, east, np.zeros((0, 2))),
    )
    doors = (
        Door("door_1", (5.0, 3.0), 0.9, ((5.0, 2.55), (5.0, 3.45)), (1.0, 0.0), ("room_1", "room_2")),
        Door("door_2", (5.0, 7.0), 0.8, ((5.0, 6.6), (5.0, 7.4)), (1.0, 0.0), ("room_1", "room_2")),
    )
    walls = (
        Wall("wall_1", (0.0, 0.0), (0.0, 10.0), "room_1", (1.0, 0.0)),
        Wall("wall_2", (0.0, 0.0), (5.0, 0.0), "room_1", (0.0, 1.0)),
    )
    corners = (Corner("corner_1", (0.0, 0.0), "room_1", ("wall_1", "wall_2"), (0.4, 0.4)),)
    obstacles = (Obstacle("obstacle_1", (2.0, 8.0), 0.25, (0.5, 0.5), "room_1", box_cells),)
    return MapAnalysis(grid=grid, params=DEFAULT_PARAMS, rooms=rooms, doors=doors, walls=walls, corners=corners,
                       obstacles=obstacles, narrow_passages=(), unexplored=(), labels=labels)


#: The robot in room_1 at (2, 5), facing east: door_1 is ahead-right, door_2 ahead-left.
POSE = (2.0, 5.0, 0.0)


def answer(steps: list[dict[str, Any]] | None = None, clarification: str | None = None, **extra: Any) -> str:
    return json.dumps({"steps": steps or [], "clarification": clarification, **extra})


GO_TO_LEFT_DOOR = {"movement": "navigate", "detail": "to", "target": {"kind": "door", "side": "left"},
                   "text": "go to the door on your left"}
