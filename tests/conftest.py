from __future__ import annotations

import os
from pathlib import Path

import pytest

SHARED = Path(__file__).resolve().parents[2] / "shared"


@pytest.fixture(scope="session")
def shared_dir() -> Path:
    """../shared (bench, real maps); tests that need it skip when it is absent."""
    if not SHARED.is_dir():
        pytest.skip(f"../shared not present at {SHARED}: the bench and real maps are not on this machine")
    return SHARED


# The real-ROS 2 tier (tests/ros2) needs its own venv and environment: `make test-ros2` runs it.
collect_ignore = [] if os.environ.get("LANGNAV_ROS2_TIER") == "1" else ["ros2"]
