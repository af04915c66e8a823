"""The allocator thresholds the analysis sets (glibc only), and when it leaves them alone."""

from __future__ import annotations

import platform
from collections.abc import Iterator

import pytest

from langnav.analysis import allocator

ON_GLIBC = platform.system() == "Linux" and platform.libc_ver()[0] == "glibc"


@pytest.fixture(autouse=True)
def _fresh() -> Iterator[None]:
    allocator.keep_freed_arrays.cache_clear()
    yield
    allocator.keep_freed_arrays.cache_clear()


@pytest.mark.skipif(not ON_GLIBC, reason="mallopt thresholds are glibc's")
def test_the_thresholds_are_set_on_glibc(monkeypatch: pytest.MonkeyPatch) -> None:
    for name in allocator.USER_SETTINGS:
        monkeypatch.delenv(name, raising=False)
    assert allocator.keep_freed_arrays() is True


@pytest.mark.parametrize("name", ["MALLOC_TRIM_THRESHOLD_", "GLIBC_TUNABLES"])
def test_a_users_own_allocator_settings_are_left_alone(monkeypatch: pytest.MonkeyPatch, name: str) -> None:
    monkeypatch.setenv(name, "131072" if name.startswith("MALLOC") else "glibc.malloc.trim_threshold=131072")
    assert allocator.keep_freed_arrays() is False


def test_other_allocators_are_left_alone(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(allocator.platform, "libc_ver", lambda: ("musl", "1.2"))
    assert allocator.keep_freed_arrays() is False
