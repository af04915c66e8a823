"""End to end in real headless Chromium (Debian's /usr/bin/chromium, driven by playwright).

The server runs on an ephemeral loopback port in a thread; the page is driven as a person would:
type a prompt, see the plan, watch the robot reach the goal on the map, press STOP mid-way.
Screenshots go to test-artifacts/ (gitignored).
"""

from __future__ import annotations

import asyncio
import math
import socket
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

CHROMIUM = Path("/usr/bin/chromium")
ARTIFACTS = Path(__file__).resolve().parents[2] / "test-artifacts"
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync"]
#: The robot starts in the demo hallway, facing east, on a floor it has already mapped.
START = (1.5, 4.95, 0.0)
#: Waits in the page, in milliseconds.
SHORT_MS = 10_000
DRIVE_MS = 60_000

pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(not CHROMIUM.exists(), reason="Debian chromium is not installed (make browser-deps)"),
]


@pytest.fixture(scope="module")
def server(tmp_path_factory: pytest.TempPathFactory) -> Iterator[str]:
    import uvicorn

    from langnav.web.app import create_app
    from langnav.web.settings import WebSettings

    db = tmp_path_factory.mktemp("web") / "chat.db"
    app = create_app(WebSettings(db_path=db, known_map=True, start_pose=START))
    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    sock.bind(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    srv = uvicorn.Server(uvicorn.Config(app, log_level="warning", ws_ping_interval=None,
                                       ws_per_message_deflate=False))
    thread = threading.Thread(target=lambda: asyncio.run(srv.serve(sockets=[sock])), daemon=True)
    thread.start()
    end = time.monotonic() + 30
    while not srv.started and time.monotonic() < end:
        time.sleep(0.05)
    assert srv.started, "the server did not start within 30 s"
    yield f"http://127.0.0.1:{port}"
    srv.should_exit = True
    thread.join(10)
    sock.close()


@pytest.fixture(scope="module")
def browser() -> Iterator[Any]:
    from playwright.sync_api import sync_playwright

    with sync_playwright() as pw:
        b = pw.chromium.launch(executable_path=str(CHROMIUM), args=CHROMIUM_ARGS, headless=True)
        yield b
        b.close()


@pytest.fixture
def page(browser: Any, server: str) -> Iterator[Any]:
    ARTIFACTS.mkdir(exist_ok=True)
    # bypass_csp lets the test's own wait expressions run; the page itself needs no eval (the
    # policy is checked in test_api.py).
    p = browser.new_page(viewport={"width": 1400, "height": 860}, bypass_csp=True)
    errors: list[str] = []
    p.on("pageerror", lambda e: errors.append(str(e)))
    p.goto(server)
    p.wait_for_function("document.querySelector('#link-status').textContent === 'live'", timeout=SHORT_MS)
    p.wait_for_function("window.langnav && window.langnav.mapMeta && window.langnav.state", timeout=SHORT_MS)
    yield p
    p.close()
    assert errors == [], f"JavaScript errors on the page: {errors}"


def _pose(page: Any) -> tuple[float, float, float]:
    x, y, yaw = page.evaluate("window.langnav.state.pose")
    return float(x), float(y), float(yaw)


def _send(page: Any, text: str) -> None:
    page.fill("#prompt", text)
    page.press("#prompt", "Enter")


def test_prompt_plan_and_arrival(page: Any) -> None:
    page.click("#stop")  # a clean start whatever ran before
    _send(page, "go to the door on your right")
    card = page.locator(".plan-card").last
    card.wait_for(timeout=SHORT_MS)
    assert card.locator(".intent").inner_text().startswith("I'll go to the door on your right.")
    first = card.locator(".cmd .text").first.inner_text()
    assert first.startswith("Navigate to (")
    goal = [float(v) for v in first.split("(")[1].split(")")[0].split(",")]
    page.wait_for_selector(".plan-card .cmd.running", timeout=SHORT_MS)
    page.screenshot(path=str(ARTIFACTS / "web-driving.png"))
    page.locator(".msg.outcome").last.wait_for(timeout=DRIVE_MS)
    outcome = page.locator(".msg.outcome").last
    assert "succeeded" in (outcome.get_attribute("class") or "")
    assert outcome.inner_text().startswith("Done. I'm in")
    x, y, _ = _pose(page)
    assert math.dist((x, y), goal) < 0.3  # Nav2's goal tolerance is 0.25 m
    assert card.locator(".cmd.succeeded").count() == card.locator(".cmd").count()
    page.screenshot(path=str(ARTIFACTS / "web-arrived.png"))


def test_stop_mid_way_halts_the_robot(page: Any) -> None:
    page.click("#stop")
    page.wait_for_function("!window.langnav.state.busy", timeout=SHORT_MS)
    start = _pose(page)
    _send(page, "go to the farthest door")
    page.wait_for_selector(".plan-card .cmd.running", timeout=SHORT_MS)
    page.wait_for_function(
        f"Math.hypot(window.langnav.state.pose[0] - {start[0]}, window.langnav.state.pose[1] - {start[1]}) > 0.5",
        timeout=DRIVE_MS)
    page.keyboard.press("Escape")  # the Escape key stops, wherever the focus is
    page.locator(".msg.system", has_text="Stopped (you pressed STOP)").last.wait_for(timeout=SHORT_MS)
    page.wait_for_function("!window.langnav.state.busy", timeout=SHORT_MS)
    halted = _pose(page)
    time.sleep(1.0)
    later = _pose(page)
    assert math.dist(halted[:2], later[:2]) < 0.02
    assert math.dist(start[:2], halted[:2]) > 0.5
    page.screenshot(path=str(ARTIFACTS / "web-stopped.png"))


def test_click_on_map_shows_coordinates(page: Any) -> None:
    page.click("#stop")
    box = page.locator("#map").bounding_box()
    page.mouse.click(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
    text = page.locator("#popup-text").inner_text()
    assert text.startswith("x ") and ", y " in text
    page.screenshot(path=str(ARTIFACTS / "web-click.png"))
    page.click("#popup-close")
    assert page.locator("#popup").is_hidden()


def test_user_text_is_never_html(page: Any) -> None:
    _send(page, "<img src=x onerror=alert(1)> where are you?")
    bubble = page.locator(".msg.user").last
    bubble.wait_for(timeout=SHORT_MS)
    assert bubble.locator("img").count() == 0
    assert "<img src=x onerror=alert(1)>" in bubble.inner_text()
