from __future__ import annotations

import os
from pathlib import Path

import pytest
from hypothesis import HealthCheck, settings

SHARED = Path(__file__).resolve().parents[2] / "shared"

# Property tests are reproducible (issue 9 item 7): the default profile "ci" draws the same examples
# on every run and machine (derandomize), keeps no example database between runs, and has no
# per-example deadline (the machine is shared; speed is measured by `make bench`, not by tests).
# Every counterexample hypothesis ever found is kept in the test as an explicit @example, so it is
# tried on every run. `HYPOTHESIS_PROFILE=explore` searches with fresh random examples instead, to
# find new counterexamples (add each one as an @example).
settings.register_profile("ci", derandomize=True, database=None, deadline=None, print_blob=True,
                          suppress_health_check=[HealthCheck.too_slow])
settings.register_profile("explore", derandomize=False, deadline=None, max_examples=1000, print_blob=True,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))


@pytest.fixture(scope="session")
def shared_dir() -> Path:
    """../shared (bench, real maps); tests that need it skip when it is absent."""
    if not SHARED.is_dir():
        pytest.skip(f"../shared not present at {SHARED}: the bench and real maps are not on this machine")
    return SHARED


# The real-ROS 2 tier (tests/ros2) needs its own venv and environment: `make test-ros2` runs it.
collect_ignore = [] if os.environ.get("LANGNAV_ROS2_TIER") == "1" else ["ros2"]
