"""The conversation, kept in SQLite (stdlib sqlite3, WAL) so a reload or a restart loses nothing.

One row per chat message: who said it (``user``, ``robot``, ``system``), a ``kind`` the page
knows how to draw (``prompt``, ``plan``, ``clarification``, ``rejected``, ``step``, ``outcome``,
``answer``, ``error``, ``info``) and a JSON payload. Plans also get ``plan_id`` so later
progress rows can find their card. Thread-safe: one connection guarded by a lock.
"""

from __future__ import annotations

import json
import sqlite3
import threading
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Final

from langnav.errors import LangnavError

ROLES: Final = ("user", "robot", "system")
#: A page asks for at most this many rows at once (a long day of chatting is a few thousand).
MAX_HISTORY_ROWS: Final = 1000
#: Wait this long for another writer's lock before failing (WAL makes waits rare and short).
BUSY_TIMEOUT_S: Final = 5.0
SCHEMA_VERSION: Final = 1
#: SQLite's largest INTEGER; a larger Python int cannot even be bound as a parameter.
SQLITE_MAX_INT: Final = 2**63 - 1

_SCHEMA = """
CREATE TABLE IF NOT EXISTS messages (
    id INTEGER PRIMARY KEY AUTOINCREMENT,
    created_s REAL NOT NULL,
    role TEXT NOT NULL,
    kind TEXT NOT NULL,
    plan_id INTEGER,
    payload TEXT NOT NULL
);
CREATE INDEX IF NOT EXISTS messages_plan ON messages(plan_id);
"""


class StoreError(LangnavError):
    """The conversation database cannot be opened or written."""


@dataclass(frozen=True)
class Message:
    id: int
    created_s: float
    role: str
    kind: str
    plan_id: int | None
    payload: dict[str, Any]

    def to_json(self) -> dict[str, Any]:
        return {"id": self.id, "t": round(self.created_s, 3), "role": self.role, "kind": self.kind,
                "plan_id": self.plan_id, **self.payload}


class ConversationStore:
    """Append-only chat history in one SQLite file (``:memory:`` for a throwaway store)."""

    def __init__(self, path: str | Path) -> None:
        self.path = str(path)
        try:
            if self.path != ":memory:":
                Path(self.path).parent.mkdir(parents=True, exist_ok=True)
            self._db = sqlite3.connect(self.path, timeout=BUSY_TIMEOUT_S, check_same_thread=False,
                                       isolation_level=None)
            if self.path != ":memory:":
                self._db.execute("PRAGMA journal_mode=WAL")
            self._db.execute("PRAGMA synchronous=NORMAL")
            self._db.executescript(_SCHEMA)
            self._db.execute(f"PRAGMA user_version={SCHEMA_VERSION}")
        except (sqlite3.Error, OSError) as exc:
            raise StoreError(f"cannot open the conversation database {self.path}: {exc}; "
                             "check the path is writable or pass another --db") from exc
        self._lock = threading.Lock()

    def add(self, role: str, kind: str, payload: dict[str, Any], plan_id: int | None = None) -> Message:
        if role not in ROLES:
            raise StoreError(f"unknown role {role!r}; choose one of: {', '.join(ROLES)}")
        now = time.time()
        text = json.dumps(payload, ensure_ascii=False, allow_nan=False)
        with self._lock:
            try:
                cur = self._db.execute(
                    "INSERT INTO messages(created_s, role, kind, plan_id, payload) VALUES (?, ?, ?, ?, ?)",
                    (now, role, kind, plan_id, text))
            except sqlite3.Error as exc:
                raise StoreError(f"cannot write to {self.path}: {exc}") from exc
        return Message(int(cur.lastrowid or 0), now, role, kind, plan_id, dict(payload))

    def history(self, after_id: int = 0, limit: int = MAX_HISTORY_ROWS) -> list[Message]:
        """Messages with id > ``after_id``, oldest first; the newest ``limit`` of them."""
        limit = max(1, min(int(limit), MAX_HISTORY_ROWS))
        after_id = max(0, min(int(after_id), SQLITE_MAX_INT))  # ids are positive int64s
        with self._lock:
            rows = self._db.execute(
                "SELECT id, created_s, role, kind, plan_id, payload FROM messages WHERE id > ? "
                "ORDER BY id DESC LIMIT ?", (after_id, limit)).fetchall()
        return [Message(r[0], r[1], r[2], r[3], r[4], json.loads(r[5])) for r in reversed(rows)]

    def last_plan_id(self) -> int:
        with self._lock:
            row = self._db.execute("SELECT MAX(plan_id) FROM messages").fetchone()
        return int(row[0] or 0)

    def count(self) -> int:
        with self._lock:
            return int(self._db.execute("SELECT COUNT(*) FROM messages").fetchone()[0])

    def close(self) -> None:
        with self._lock:
            self._db.close()
