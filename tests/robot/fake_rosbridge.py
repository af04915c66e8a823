"""A raw rosbridge-protocol server for tests: a websocket on loopback, served from its own thread
and event loop, whose behaviour a subclass gives in :meth:`RawRosbridge.serve_one` (what it answers
to each client). For the faults of real rosbridges that langnav's own server does not emulate."""

from __future__ import annotations

import asyncio
import contextlib
import threading

from websockets.asyncio.server import ServerConnection, serve
from websockets.exceptions import ConnectionClosed

#: How long the server may take to start listening (s).
START_TIMEOUT_S = 5.0
#: How long close() waits for the server's thread (s).
CLOSE_TIMEOUT_S = 5.0


class RawRosbridge:
    """Listens on 127.0.0.1 at a free ``port``; ``close()`` stops it. A client's dropped
    connection ends only that client's handler."""

    def __init__(self) -> None:
        self.port = 0
        self._ready = threading.Event()
        self._stop: asyncio.Event | None = None
        self._loop: asyncio.AbstractEventLoop | None = None
        self._thread = threading.Thread(target=lambda: asyncio.run(self._main()), daemon=True)
        self._thread.start()
        if not self._ready.wait(START_TIMEOUT_S):
            raise RuntimeError(f"{type(self).__name__} did not start within {START_TIMEOUT_S} s")

    async def _main(self) -> None:
        self._loop = asyncio.get_running_loop()
        self._stop = asyncio.Event()
        async with serve(self._handle, "127.0.0.1", 0) as server:
            self.port = next(iter(server.sockets)).getsockname()[1]
            self._ready.set()
            await self._stop.wait()

    async def _handle(self, ws: ServerConnection) -> None:
        with contextlib.suppress(ConnectionClosed):
            await self.serve_one(ws)

    async def serve_one(self, ws: ServerConnection) -> None:
        """Answer one client until it leaves (a subclass says how)."""
        raise NotImplementedError

    def close(self) -> None:
        if self._loop is not None and self._stop is not None:
            self._loop.call_soon_threadsafe(self._stop.set)
        self._thread.join(CLOSE_TIMEOUT_S)
