"""End to end in real headless Chromium (Debian's /usr/bin/chromium, driven by playwright).

The server runs on an ephemeral loopback port in a thread; the page is driven as a person would:
type a prompt, see the plan, watch the robot reach the goal on the map, press STOP mid-way, click
the map, drag a goal, name a spot. Screenshots go to test-artifacts/ (gitignored), the phone
viewport (390 x 844) included.
"""

from __future__ import annotations

import asyncio
import math
import os
import socket
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
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
DESK = {"width": 1400, "height": 860}
PHONE = {"width": 390, "height": 844}
TB3_WORLD = Path(__file__).resolve().parents[3] / "shared" / "maps" / "ros" / "turtlebot3_world.yaml"

pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(not CHROMIUM.exists(), reason="Debian chromium is not installed (make browser-deps)"),
]


@contextmanager
def serving(**settings: Any) -> Iterator[str]:
    """A langnav web app on an ephemeral loopback port, in a thread."""
    import uvicorn

    from langnav.web.app import create_app
    from langnav.web.settings import WebSettings

    app = create_app(WebSettings(**settings))
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
    try:
        yield f"http://127.0.0.1:{port}"
    finally:
        srv.should_exit = True
        thread.join(10)
        sock.close()


@pytest.fixture(scope="module")
def server(tmp_path_factory: pytest.TempPathFactory) -> Iterator[str]:
    db = tmp_path_factory.mktemp("web") / "chat.db"
    with serving(db_path=db, known_map=True, start_pose=START) as url:
        yield url


@pytest.fixture(scope="module")
def browser() -> Iterator[Any]:
    from playwright.sync_api import sync_playwright

    with sync_playwright() as pw:
        b = pw.chromium.launch(executable_path=str(CHROMIUM), args=CHROMIUM_ARGS, headless=True)
        yield b
        b.close()


@contextmanager
def opened(browser: Any, url: str, viewport: dict[str, int] | None = None) -> Iterator[Any]:
    """A page on ``url``, live and drawn; fails the test on any JavaScript error."""
    ARTIFACTS.mkdir(exist_ok=True)
    # bypass_csp lets the test's own wait expressions run; the page itself needs no eval (the
    # policy is checked in test_api.py).
    p = browser.new_page(viewport=viewport or DESK, bypass_csp=True)
    errors: list[str] = []
    p.on("pageerror", lambda e: errors.append(str(e)))
    p.goto(url)
    p.wait_for_function("document.querySelector('#link-status').textContent === 'live'", timeout=SHORT_MS)
    p.wait_for_function("window.langnav && window.langnav.mapMeta && window.langnav.state && window.langnav.elements",
                        timeout=SHORT_MS)
    try:
        yield p
    finally:
        p.close()
    assert errors == [], f"JavaScript errors on the page: {errors}"


@pytest.fixture
def page(browser: Any, server: str) -> Iterator[Any]:
    with opened(browser, server) as p:
        yield p


def _pose(page: Any) -> tuple[float, float, float]:
    x, y, yaw = page.evaluate("window.langnav.state.pose")
    return float(x), float(y), float(yaw)


def _send(page: Any, text: str) -> None:
    page.fill("#prompt", text)
    page.press("#prompt", "Enter")


def _screen(page: Any, x: float, y: float) -> tuple[float, float]:
    """Page coordinates of a map point."""
    box = page.locator("#map").bounding_box()
    sx, sy = page.evaluate(f"window.langnav.toScreen({x}, {y})")
    return box["x"] + sx, box["y"] + sy


def _labels_apart(page: Any) -> list[dict[str, Any]]:
    """The placed labels; asserts none overlaps another, none is cut off, none covers the robot."""
    placed: list[dict[str, Any]] = page.evaluate("window.langnav.placedLabels")
    for i, a in enumerate(placed):
        for b in placed[i + 1:]:
            assert not (a["x"] < b["x"] + b["w"] and b["x"] < a["x"] + a["w"] and a["y"] < b["y"] + b["h"]
                        and b["y"] < a["y"] + a["h"]), (a, b)
    w, h = page.evaluate("[document.querySelector('#map').clientWidth, document.querySelector('#map').clientHeight]")
    assert all(a["x"] >= 0 and a["x"] + a["w"] <= w and a["y"] >= 0 and a["y"] + a["h"] <= h for a in placed)
    sx, sy = page.evaluate("window.langnav.toScreen(...window.langnav.state.pose)")
    assert not any(a["x"] - 6 < sx < a["x"] + a["w"] + 6 and a["y"] - 6 < sy < a["y"] + a["h"] + 6 for a in placed)
    return placed


# -- the first screen ------------------------------------------------------------------------------
def test_every_starter_example_works_on_the_first_screen(browser: Any, tmp_path: Path) -> None:
    """`make run`'s first screen (the demo world, its default start): each example, clicked and
    sent on a fresh first screen, does what it says."""
    with serving(db_path=tmp_path / "first.db") as url, opened(browser, url) as page:
        page.wait_for_selector("#examples .chip", timeout=SHORT_MS)
        examples = page.locator("#examples .chip").all_inner_texts()
        assert len(examples) == 5 and examples[0] == "where are you?"
        assert page.locator("#empty-hint li.example").count() == 5
        page.screenshot(path=str(ARTIFACTS / "web-first-screen.png"))
    for i, text in enumerate(examples):
        with serving(db_path=tmp_path / f"first-{i}.db") as url, opened(browser, url) as page:
            page.wait_for_selector("#examples .chip", timeout=SHORT_MS)
            chip = page.locator("#examples .chip").nth(i)
            assert chip.inner_text() == text  # the same first screen every time
            chip.click()
            assert page.input_value("#prompt") == text
            page.click("#send")
            page.wait_for_selector(".msg.answer, .plan-card, .msg.clarification, .msg.rejected", timeout=SHORT_MS)
            assert page.locator(".msg.clarification, .msg.rejected").count() == 0, (
                text, page.locator(".msg.clarification, .msg.rejected").all_inner_texts())
            if page.locator(".msg.answer").count():
                assert page.locator(".msg.answer").last.inner_text().startswith(("I'm in ", "I see "))
                continue
            if text == "explore":  # runs until the floor is mapped: check that it drives, then stop it
                start = _pose(page)
                page.wait_for_function(
                    f"Math.hypot(window.langnav.state.pose[0] - {start[0]}, window.langnav.state.pose[1] - {start[1]}) > 0.5",
                    timeout=DRIVE_MS)
                page.click("#stop")
                continue
            page.locator(".msg.outcome").last.wait_for(timeout=DRIVE_MS)
            outcome = page.locator(".msg.outcome").last
            assert "succeeded" in (outcome.get_attribute("class") or ""), (text, outcome.inner_text())
            page.screenshot(path=str(ARTIFACTS / f"web-example-{i + 1}.png"))


# -- driving ---------------------------------------------------------------------------------------
def test_prompt_plan_and_arrival(page: Any) -> None:
    page.click("#stop")  # a clean start whatever ran before
    _send(page, "go to the door on your right")
    card = page.locator(".plan-card").last
    card.wait_for(timeout=SHORT_MS)
    assert card.locator(".intent").inner_text().startswith("I'll go to the door on your right.")
    first = card.locator(".cmd .text").first
    assert first.inner_text() == "Go to the door on your right (in hallway 2 near door 2)"
    detail = first.get_attribute("title") or ""  # the exact command, on hover
    assert detail.startswith("Navigate to (")
    goal = [float(v) for v in detail.split("(")[1].split(")")[0].split(",")]
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
    n_msgs = page.locator(".msg").count()
    page.keyboard.press("Escape")  # the Escape key stops, wherever the focus is
    page.locator(".msg.system", has_text="Stopped (you pressed STOP)").last.wait_for(timeout=SHORT_MS)
    page.wait_for_function("!window.langnav.state.busy", timeout=SHORT_MS)
    halted = _pose(page)
    time.sleep(1.0)
    later = _pose(page)
    assert math.dist(halted[:2], later[:2]) < 0.02
    assert math.dist(start[:2], halted[:2]) > 0.5
    assert page.locator(".msg").count() == n_msgs + 1  # STOP writes one message
    page.screenshot(path=str(ARTIFACTS / "web-stopped.png"))


def test_pause_holds_and_resume_carries_on(page: Any) -> None:
    page.click("#stop")
    _send(page, "go to the farthest door")
    page.wait_for_selector(".plan-card .cmd.running", timeout=SHORT_MS)
    page.wait_for_function("window.langnav.state.busy", timeout=SHORT_MS)
    time.sleep(1.0)
    page.click("#pause")
    page.wait_for_function("document.querySelector('#pause').textContent === 'Resume'", timeout=SHORT_MS)
    time.sleep(0.5)
    held = _pose(page)
    time.sleep(2.0)
    assert math.dist(held[:2], _pose(page)[:2]) < 0.005
    page.click("#pause")
    page.wait_for_function(
        f"Math.hypot(window.langnav.state.pose[0] - {held[0]}, window.langnav.state.pose[1] - {held[1]}) > 0.2",
        timeout=SHORT_MS)
    page.click("#stop")


def test_a_new_prompt_mid_plan_asks_before_replacing(page: Any) -> None:
    page.click("#stop")
    _send(page, "go to the farthest door")
    page.wait_for_selector(".plan-card .cmd.running", timeout=SHORT_MS)
    _send(page, "go to the nearest door")
    ask = page.locator(".msg.confirm").last
    ask.wait_for(timeout=SHORT_MS)
    assert "instead?" in ask.inner_text()
    cards = page.locator(".plan-card").count()
    ask.locator("button", has_text="Yes").click()
    page.wait_for_function(f"document.querySelectorAll('.plan-card').length > {cards}", timeout=SHORT_MS)
    page.click("#stop")


# -- the map ---------------------------------------------------------------------------------------
def test_hover_names_an_element_and_a_click_describes_it(page: Any) -> None:
    page.click("#stop")
    page.click("#zoom-fit")
    door = next(d for d in page.evaluate("window.langnav.elements.doors") if d["id"] == "door_5")
    page.mouse.move(*_screen(page, *door["center"]))
    page.wait_for_selector("#map-tip:not([hidden])", timeout=SHORT_MS)
    tip = page.locator("#map-tip").inner_text()
    assert tip.startswith("door 5 · ") and tip.endswith(" m wide")
    page.mouse.click(*_screen(page, *door["center"]))
    page.wait_for_selector("#popup:not([hidden])", timeout=SHORT_MS)
    text = page.locator("#popup-text").inner_text()
    assert text.startswith("door 5 · door · ") and "m wide" in text
    buttons = page.locator("#popup-actions button").all_inner_texts()
    assert buttons[:3] == ["Send robot here", "Go to it", "Go through it"] and "Name it…" in buttons
    box, mp = page.locator("#popup").bounding_box(), page.locator("#map").bounding_box()
    rx, ry = page.evaluate("window.langnav.toScreen(...window.langnav.state.pose)")
    rx, ry = rx + mp["x"], ry + mp["y"]
    assert not (box["x"] <= rx <= box["x"] + box["width"] and box["y"] <= ry <= box["y"] + box["height"])
    page.screenshot(path=str(ARTIFACTS / "web-click-door.png"))
    page.click("#popup-close")
    # furniture: described, and no "Send robot here"
    table = max(page.evaluate("window.langnav.elements.obstacles"), key=lambda o: o["centroid"][1])
    page.mouse.click(*_screen(page, *table["centroid"]))
    page.wait_for_selector("#popup:not([hidden])", timeout=SHORT_MS)
    assert " · obstacle · " in page.locator("#popup-text").inner_text()
    assert "wall or an obstacle" in page.locator(".popup-reason").inner_text()
    assert "Send robot here" not in page.locator("#popup-actions").inner_text()
    page.screenshot(path=str(ARTIFACTS / "web-click-obstacle.png"))
    page.click("#popup-close")
    assert page.locator("#popup").is_hidden()


def test_goal_tool_press_and_drag_sets_the_heading(page: Any) -> None:
    page.click("#stop")
    page.click("#zoom-fit")
    page.wait_for_function("!window.langnav.state.busy", timeout=SHORT_MS)
    n_out = page.locator(".msg.outcome").count()
    page.click("#goal-tool")
    x, y = _screen(page, 3.5, 4.95)
    page.mouse.move(x, y)
    page.mouse.down()
    page.mouse.move(x, y - 20, steps=3)
    page.mouse.move(x, y - 60, steps=3)   # dragged up the screen: face north
    page.screenshot(path=str(ARTIFACTS / "web-goal-drag.png"))
    page.mouse.up()
    card = page.locator(".plan-card").last
    card.wait_for(timeout=SHORT_MS)
    page.wait_for_function("document.querySelector('.plan-card:last-of-type .intent') && "
                           "[...document.querySelectorAll('.plan-card')].pop().textContent.includes('facing north')",
                           timeout=SHORT_MS)
    page.wait_for_function(f"document.querySelectorAll('.msg.outcome').length > {n_out}", timeout=DRIVE_MS)
    assert "succeeded" in (page.locator(".msg.outcome").last.get_attribute("class") or "")
    x_m, y_m, yaw = _pose(page)
    assert math.dist((x_m, y_m), (3.5, 4.95)) < 0.3 and abs(yaw - math.pi / 2) < 0.2
    # refused up front on furniture: nothing is sent
    plans = page.locator(".plan-card").count()
    table = max(page.evaluate("window.langnav.elements.obstacles"), key=lambda o: o["centroid"][1])
    page.mouse.click(*_screen(page, *table["centroid"]))
    page.wait_for_selector("#popup:not([hidden])", timeout=SHORT_MS)
    assert "wall or an obstacle" in page.locator(".popup-reason").inner_text()
    time.sleep(0.5)
    assert page.locator(".plan-card").count() == plans
    page.click("#goal-tool")


def test_labels_never_overlap_nor_cover_the_robot(page: Any) -> None:
    page.click("#zoom-fit")
    page.wait_for_timeout(300)
    placed = _labels_apart(page)
    assert len(placed) >= 8
    assert {"door 5", "hallway 2"} <= {a["text"] for a in placed}
    page.click("#zoom-out")
    page.click("#zoom-out")
    page.wait_for_timeout(300)
    _labels_apart(page)


def test_phone_layout(browser: Any, server: str) -> None:
    with opened(browser, server, PHONE) as page:
        page.click("#zoom-fit")
        page.wait_for_timeout(300)
        assert page.evaluate("document.scrollingElement.scrollWidth") <= PHONE["width"]
        for sel in ("#stop", "#map", "#prompt", "#send"):
            box = page.locator(sel).bounding_box()
            assert box is not None and box["x"] >= 0 and box["x"] + box["width"] <= PHONE["width"], sel
        stop = page.locator("#stop").bounding_box()
        assert stop["y"] + stop["height"] <= 100  # STOP is at hand at the top
        assert page.locator("#map").bounding_box()["height"] >= 250
        _labels_apart(page)
        page.screenshot(path=str(ARTIFACTS / "web-phone.png"))
        _send(page, "where are you?")
        page.locator(".msg.answer").last.wait_for(timeout=SHORT_MS)
        page.screenshot(path=str(ARTIFACTS / "web-phone-answer.png"), full_page=True)


@pytest.mark.skipif(not TB3_WORLD.exists(), reason="turtlebot3_world is in ../shared/maps/ros")
def test_fit_frames_the_known_area(browser: Any, tmp_path: Path) -> None:
    with serving(db_path=tmp_path / "tb3.db", world=TB3_WORLD, known_map=True) as url, \
            opened(browser, url) as page:
        page.click("#zoom-fit")
        page.wait_for_timeout(300)
        x0, y0, x1, y1 = page.evaluate("window.langnav.mapMeta.known")
        a = page.evaluate(f"window.langnav.toScreen({x0}, {y0})")
        b = page.evaluate(f"window.langnav.toScreen({x1}, {y1})")
        w, h = page.evaluate("[document.querySelector('#map').clientWidth, document.querySelector('#map').clientHeight]")
        share = max(abs(b[0] - a[0]) / w, abs(b[1] - a[1]) / h)
        assert share > 0.85, f"the known area fills {share:.2f} of the panel"
        page.screenshot(path=str(ARTIFACTS / "web-fit-tb3.png"))


# -- the conversation ------------------------------------------------------------------------------
def test_translator_menu_shows_what_is_in_use(page: Any) -> None:
    if os.environ.get("GEMINI_API_KEY") or os.environ.get("GOOGLE_API_KEY"):
        pytest.skip("a Gemini key is set: gemini can be chosen")
    page.select_option("#translator", "gemini")
    page.locator(".msg.error", has_text="GEMINI_API_KEY").last.wait_for(timeout=SHORT_MS)
    page.wait_for_function("document.querySelector('#translator').value === 'offline'", timeout=SHORT_MS)


def test_whitespace_prompt_gets_a_reply(page: Any) -> None:
    n = page.locator(".msg.clarification").count()
    page.fill("#prompt", "   ")
    page.click("#send")
    page.wait_for_function(f"document.querySelectorAll('.msg.clarification').length > {n}", timeout=SHORT_MS)
    assert page.locator(".msg.clarification").last.inner_text().startswith("Your message was empty")


def test_help_lists_examples_that_work_here(page: Any) -> None:
    n = page.locator(".msg.answer").count()
    _send(page, "what can you do?")
    page.wait_for_function(f"document.querySelectorAll('.msg.answer').length > {n}", timeout=SHORT_MS)
    answer = page.locator(".msg.answer").last
    for chip in page.locator("#examples .chip").all_inner_texts():
        assert chip in answer.inner_text()


def test_named_places_are_pins_renamable_and_deletable(page: Any) -> None:
    page.click("#stop")
    page.click("#zoom-fit")
    page.once("dialog", lambda d: d.accept("kitchen"))
    page.mouse.click(*_screen(page, 2.0, 3.0))   # room 3's free floor
    page.wait_for_selector("#popup:not([hidden])", timeout=SHORT_MS)
    page.locator("#popup-actions button", has_text="Name this spot").click()
    page.wait_for_function("window.langnav.places.some((p) => p.name === 'kitchen')", timeout=SHORT_MS)
    page.screenshot(path=str(ARTIFACTS / "web-pin.png"))
    pin = page.evaluate("window.langnav.places.find((p) => p.name === 'kitchen')")
    px, py = _screen(page, pin["x"], pin["y"])
    page.once("dialog", lambda d: d.accept("pantry"))
    page.mouse.click(px, py - 12)
    page.locator("#popup-actions button", has_text="Rename").click()
    page.wait_for_function("window.langnav.places.some((p) => p.name === 'pantry')", timeout=SHORT_MS)
    page.mouse.click(px, py - 12)
    page.locator("#popup-actions button", has_text="Delete").click()
    page.wait_for_function("window.langnav.places.length === 0", timeout=SHORT_MS)


def test_user_text_is_never_html(page: Any) -> None:
    n = page.locator(".msg.user").count()
    _send(page, "<img src=x onerror=alert(1)> where are you?")
    page.wait_for_function(f"document.querySelectorAll('.msg.user').length > {n}", timeout=SHORT_MS)
    bubble = page.locator(".msg.user").last
    assert bubble.locator("img").count() == 0
    assert "<img src=x onerror=alert(1)>" in bubble.inner_text()
