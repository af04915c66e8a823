from __future__ import annotations

import pytest

from langnav.web.app import RateLimiter
from langnav.web.settings import SettingsError, WebSettings, is_loopback


@pytest.mark.parametrize(("host", "loop"), [("127.0.0.1", True), ("127.8.9.1", True), ("localhost", True),
                                            ("::1", True), ("0.0.0.0", False), ("192.168.1.4", False),
                                            ("example.org", False), ("::", False)])
def test_is_loopback(host: str, loop: bool) -> None:
    assert is_loopback(host) is loop


def test_non_loopback_needs_a_token() -> None:
    with pytest.raises(SettingsError, match="token is required"):
        WebSettings(host="0.0.0.0").checked()
    s = WebSettings(host="0.0.0.0", token="x" * 32).checked()
    assert s.requires_token


def test_from_env_and_overrides() -> None:
    s = WebSettings.from_env({"LANGNAV_PORT": "8123", "LANGNAV_TRANSLATOR": "auto"}, translator="offline")
    assert (s.port, s.translator, s.host) == (8123, "offline", "127.0.0.1")
    with pytest.raises(SettingsError, match="port"):
        WebSettings.from_env({"LANGNAV_PORT": "99999"})


def test_rate_limiter_burst_then_refill() -> None:
    rl = RateLimiter(burst=3, refill_s=2.0)
    assert [rl.check("a", now=0.0) for _ in range(3)] == [0.0, 0.0, 0.0]
    assert rl.check("a", now=0.0) == pytest.approx(2.0)
    assert rl.check("b", now=0.0) == 0.0  # per client
    assert rl.check("a", now=2.0) == 0.0
    assert rl.check("a", now=2.5) == pytest.approx(1.5)


def test_rate_limiter_memory_is_bounded() -> None:
    rl = RateLimiter(burst=1, refill_s=1.0, max_clients=5)
    for i in range(50):
        rl.check(f"c{i}", now=0.0)
    assert len(rl._buckets) == 5


def test_serve_makes_a_token_only_off_loopback(monkeypatch: pytest.MonkeyPatch) -> None:
    from langnav.cli import build_parser
    from langnav.cli.serve import settings_from_args

    monkeypatch.delenv("LANGNAV_TOKEN", raising=False)
    local = settings_from_args(build_parser().parse_args(["serve"]))
    assert (local.host, local.port, local.token, local.translator, local.backend) == (
        "127.0.0.1", 8000, None, "offline", "sim")
    shared = settings_from_args(build_parser().parse_args(
        ["serve", "--host", "0.0.0.0", "--port", "8080", "--known-map", "--pose", "1,2,90"]))
    assert shared.requires_token and shared.token is not None and len(shared.token) >= 32
    assert (shared.known_map, shared.start_pose) == (True, (1.0, 2.0, 90.0))
    again = settings_from_args(build_parser().parse_args(["serve", "--host", "0.0.0.0"]))
    assert again.token != shared.token  # made fresh at each start
