from __future__ import annotations

from pathlib import Path

import pytest

SHARED = Path(__file__).resolve().parents[2] / "shared"


@pytest.fixture(scope="session")
def shared_dir() -> Path:
    """../shared (bench, real maps); tests that need it skip when it is absent."""
    if not SHARED.is_dir():
        pytest.skip(f"../shared not present at {SHARED}: the bench and real maps are not on this machine")
    return SHARED
