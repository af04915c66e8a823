from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import pytest
from fastapi.testclient import TestClient

from langnav.web.app import create_app
from langnav.web.settings import WebSettings

#: A robot in the demo hallway, facing east, with the floor already mapped.
HALLWAY_POSE = (1.5, 4.95, 0.0)

AppFactory = Callable[..., Any]


@pytest.fixture
def make_client(tmp_path: Path) -> Iterator[AppFactory]:
    """``with make_client(**settings) as client:`` a TestClient on a fresh app (lifespan run)."""

    @contextmanager
    def factory(**overrides: Any) -> Iterator[TestClient]:
        values: dict[str, Any] = {"db_path": tmp_path / "chat.db", "known_map": True,
                                  "start_pose": HALLWAY_POSE}
        values.update(overrides)
        app = create_app(WebSettings(**values))
        with TestClient(app, base_url="http://127.0.0.1:8000") as client:
            yield client

    yield factory
