from __future__ import annotations

import asyncio
import json
import threading

from langnav.web.broadcast import Broadcaster


def _run(coro):  # type: ignore[no-untyped-def]
    return asyncio.run(coro)


def test_slow_client_gets_only_the_latest_frame() -> None:
    async def main() -> list[dict]:  # type: ignore[type-arg]
        b = Broadcaster()
        sub = b.subscribe()
        for i in range(100):
            b.publish_frame("state", {"type": "state", "i": i})
        await asyncio.sleep(0.05)  # let the loop run the thread-safe callbacks
        batch = await sub.next_batch(timeout_s=1.0)
        assert sub.dropped_frames == 99
        return [json.loads(t) for t in batch]

    assert _run(main()) == [{"type": "state", "i": 99}]


def test_events_before_frames_and_map_before_state() -> None:
    async def main() -> list[str]:
        b = Broadcaster()
        sub = b.subscribe()
        b.publish_frame("state", {"type": "state"})
        b.publish_frame("map", {"type": "map"})
        b.publish_event({"type": "message", "n": 1})
        b.publish_event({"type": "message", "n": 2})
        await asyncio.sleep(0.05)
        return [json.loads(t).get("n", json.loads(t)["type"]) for t in await sub.next_batch(1.0)]

    assert _run(main()) == [1, 2, "map", "state"]


def test_event_overflow_asks_for_resync_and_stays_bounded() -> None:
    async def main() -> list[str]:
        b = Broadcaster()
        sub = b.subscribe(max_events=10)
        for i in range(25):
            b.publish_event({"type": "message", "n": i})
        await asyncio.sleep(0.05)
        return [t for t in await sub.next_batch(1.0)]

    out = _run(main())
    assert json.loads(out[0]) == {"type": "resync"}
    assert len(out) <= 11
    assert json.loads(out[-1])["n"] == 24


def test_newcomer_gets_last_frames_and_publish_from_thread_never_blocks() -> None:
    async def main() -> tuple[list[str], int]:
        b = Broadcaster()
        b.publish_frame("map", {"type": "map", "v": 1})
        sub = b.subscribe()
        t = threading.Thread(target=lambda: [b.publish_frame("state", {"type": "state", "i": i})
                                             for i in range(1000)])
        t.start()
        t.join(5)  # nobody reads: a blocking publish would hang here
        alive = t.is_alive()
        await asyncio.sleep(0.05)
        batch = await sub.next_batch(1.0)
        b.unsubscribe(sub)
        return [json.loads(x)["type"] for x in batch], int(alive) + b.subscriber_count

    types, leftovers = _run(main())
    assert types == ["map", "state"]
    assert leftovers == 0


def test_quiet_stream_times_out_empty() -> None:
    async def main() -> list[str]:
        sub = Broadcaster().subscribe()
        return await sub.next_batch(timeout_s=0.05)

    assert _run(main()) == []


def test_closed_subscriber_wakes_and_returns_nothing() -> None:
    async def main() -> list[str]:
        sub = Broadcaster().subscribe()
        waiter = asyncio.create_task(sub.next_batch(timeout_s=10.0))
        await asyncio.sleep(0.01)
        sub.close()
        return await asyncio.wait_for(waiter, 1.0)

    assert _run(main()) == []
