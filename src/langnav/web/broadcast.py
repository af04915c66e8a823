"""Fan-out of robot state and chat events to WebSocket clients, without ever blocking the robot.

A producer thread (the session's sampler, the plan executor's callbacks) calls
:meth:`Broadcaster.publish_frame` or :meth:`Broadcaster.publish_event`. The message is serialised
once, then handed to each event loop that has subscribers with one ``call_soon_threadsafe``:
the producer never waits for a client.

Each :class:`Subscriber` keeps
* one *slot* per frame kind (``map``, ``elements``, ``path``, ``scan``, ``state``): a newer frame replaces an unsent
  older one, so a slow client skips frames instead of falling behind (``dropped`` counts them);
* a bounded queue of *events* (chat messages, progress). Events are also in the SQLite store, so
  a client whose queue overflows is told to reload its history instead of the server growing.
"""

from __future__ import annotations

import asyncio
import json
import logging
import threading
from collections import deque
from typing import Any, Final

log = logging.getLogger(__name__)

#: Frame kinds sent latest-wins, in the order a client needs them (the map before the pose on it).
FRAME_KINDS: Final = ("map", "elements", "path", "scan", "state")
#: Events queued per client before it must resync from the store (minutes of chat at human speed).
MAX_QUEUED_EVENTS: Final = 256
#: A client that has received nothing for this long gets a keep-alive ping.
KEEPALIVE_S: Final = 15.0


#: ``<``, ``>`` and ``&`` are sent as JSON escapes: whatever text a user or a model wrote, the
#: bytes on the wire can never be read as HTML, even by a careless consumer.
_HTML_SAFE: Final = str.maketrans({"<": "\\u003c", ">": "\\u003e", "&": "\\u0026"})


def encode(message: Any) -> str:
    """Compact, HTML-safe JSON (``JSON.parse`` gives back the original text)."""
    return json.dumps(message, separators=(",", ":"), ensure_ascii=False, allow_nan=False).translate(_HTML_SAFE)


class Subscriber:
    """One client's pending messages. Its methods run on the event loop that owns it."""

    def __init__(self, loop: asyncio.AbstractEventLoop, max_events: int = MAX_QUEUED_EVENTS) -> None:
        self.loop = loop
        self._slots: dict[str, str] = {}
        self._events: deque[str] = deque()
        self._max_events = max_events
        self._wake = asyncio.Event()
        self.dropped_frames = 0
        self.overflowed = False
        self.closed = False

    def offer_frame(self, kind: str, text: str) -> None:
        if kind in self._slots:
            self.dropped_frames += 1
        self._slots[kind] = text
        self._wake.set()

    def offer_event(self, text: str) -> None:
        if len(self._events) >= self._max_events:
            # Keep memory bounded: forget the backlog, tell the client to reload from the store.
            self._events.clear()
            self.overflowed = True
        self._events.append(text)
        self._wake.set()

    def close(self) -> None:
        """The client has gone: wake the sender so it can end (call on the owning loop)."""
        self.closed = True
        self._wake.set()

    async def next_batch(self, timeout_s: float = KEEPALIVE_S) -> list[str]:
        """Everything pending, events first then frames; [] after ``timeout_s`` of quiet or once closed."""
        if self.closed:
            return []
        if not (self._slots or self._events or self.overflowed):
            try:
                await asyncio.wait_for(self._wake.wait(), timeout_s)
            except TimeoutError:
                return []
        self._wake.clear()
        out: list[str] = []
        if self.overflowed:
            out.append(encode({"type": "resync"}))
            self.overflowed = False
        out.extend(self._events)
        self._events.clear()
        for kind in FRAME_KINDS:
            text = self._slots.pop(kind, None)
            if text is not None:
                out.append(text)
        return out


class Broadcaster:
    """Thread-safe publish; per-loop fan-out. Remembers the last frame of each kind for newcomers."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._subs: dict[asyncio.AbstractEventLoop, set[Subscriber]] = {}
        self._last: dict[str, str] = {}

    @property
    def subscriber_count(self) -> int:
        with self._lock:
            return sum(len(s) for s in self._subs.values())

    def subscribe(self, loop: asyncio.AbstractEventLoop | None = None,
                  max_events: int = MAX_QUEUED_EVENTS) -> Subscriber:
        """A new subscriber (call on its event loop); it starts with the latest map, elements, state."""
        loop = loop or asyncio.get_running_loop()
        sub = Subscriber(loop, max_events)
        with self._lock:
            self._subs.setdefault(loop, set()).add(sub)
            last = dict(self._last)
        for kind in FRAME_KINDS:
            if kind in last:
                sub.offer_frame(kind, last[kind])
        return sub

    def unsubscribe(self, sub: Subscriber) -> None:
        sub.closed = True
        with self._lock:
            subs = self._subs.get(sub.loop)
            if subs is not None:
                subs.discard(sub)
                if not subs:
                    del self._subs[sub.loop]

    def publish_frame(self, kind: str, message: dict[str, Any]) -> None:
        """Latest-wins frame (``kind`` in FRAME_KINDS); safe from any thread, never blocks on clients."""
        if kind not in FRAME_KINDS:
            raise ValueError(f"unknown frame kind {kind!r}; choose one of: {', '.join(FRAME_KINDS)}")
        text = encode(message)
        with self._lock:
            self._last[kind] = text
        self._dispatch(lambda s: s.offer_frame(kind, text))

    def publish_event(self, message: dict[str, Any]) -> None:
        """A queued event (chat message, progress); safe from any thread."""
        text = encode(message)
        self._dispatch(lambda s: s.offer_event(text))

    def _dispatch(self, offer: Any) -> None:
        with self._lock:
            targets = [(loop, tuple(subs)) for loop, subs in self._subs.items()]
        for loop, subs in targets:
            try:
                loop.call_soon_threadsafe(_fan_out, subs, offer)
            except RuntimeError:  # that loop has closed: its clients are gone
                log.debug("dropping %d subscribers of a closed event loop", len(subs))
                for s in subs:
                    self.unsubscribe(s)


def _fan_out(subs: tuple[Subscriber, ...], offer: Any) -> None:
    for s in subs:
        if not s.closed:
            offer(s)
