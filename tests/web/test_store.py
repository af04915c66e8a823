from __future__ import annotations

import threading
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from langnav.web.store import ConversationStore, StoreError


def test_history_survives_reopening(tmp_path: Path) -> None:
    db = tmp_path / "chat.db"
    s = ConversationStore(db)
    a = s.add("user", "prompt", {"text": "go to the door"})
    b = s.add("robot", "plan", {"intent_text": "I'll go to the nearest door."}, plan_id=1)
    s.close()
    s2 = ConversationStore(db)
    rows = s2.history()
    assert [(m.id, m.role, m.kind, m.plan_id) for m in rows] == [(a.id, "user", "prompt", None),
                                                                  (b.id, "robot", "plan", 1)]
    assert rows[0].payload == {"text": "go to the door"}
    assert s2.last_plan_id() == 1
    assert [m.id for m in s2.history(after_id=a.id)] == [b.id]


def test_wal_mode(tmp_path: Path) -> None:
    s = ConversationStore(tmp_path / "x.db")
    assert s._db.execute("PRAGMA journal_mode").fetchone()[0] == "wal"


def test_limit_keeps_the_newest(tmp_path: Path) -> None:
    s = ConversationStore(tmp_path / "x.db")
    for i in range(10):
        s.add("user", "prompt", {"text": str(i)})
    assert [m.payload["text"] for m in s.history(limit=3)] == ["7", "8", "9"]


def test_unknown_role_is_refused() -> None:
    s = ConversationStore(":memory:")
    with pytest.raises(StoreError, match="unknown role 'robotx'"):
        s.add("robotx", "prompt", {})


def test_concurrent_writers_lose_nothing(tmp_path: Path) -> None:
    s = ConversationStore(tmp_path / "x.db")

    def write(k: int) -> None:
        for i in range(50):
            s.add("user", "prompt", {"text": f"{k}-{i}"})

    threads = [threading.Thread(target=write, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(10)
    assert s.count() == 200
    assert len({m.payload["text"] for m in s.history()}) == 200


@settings(max_examples=30, deadline=None)
@given(st.text(max_size=300))
def test_any_text_round_trips(text: str) -> None:
    s = ConversationStore(":memory:")
    m = s.add("user", "prompt", {"text": text})
    assert s.history()[-1].payload["text"] == text
    assert m.to_json()["text"] == text
