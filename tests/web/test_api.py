"""The HTTP and WebSocket API, on the real simulator and the offline translator."""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import Any

from fastapi.testclient import TestClient

AppFactory = Callable[..., Any]

JSON = {"Content-Type": "application/json"}


def _prompt(client: TestClient, text: str, **headers: str) -> Any:
    return client.post("/api/prompt", json={"text": text}, headers=headers)


def _wait_idle(client: TestClient, timeout_s: float = 30.0) -> dict[str, Any]:
    end = time.monotonic() + timeout_s
    while time.monotonic() < end:
        st = client.get("/api/status").json()
        if st["plan"]["state"] == "idle":
            return st
        time.sleep(0.1)
    raise AssertionError(f"the plan did not finish within {timeout_s} s")


def test_prompt_shows_the_plan(make_client: AppFactory) -> None:
    with make_client() as client:
        r = _prompt(client, "go to the nearest door")
        assert r.status_code == 200, r.text
        kinds = [m["kind"] for m in r.json()["messages"]]
        assert kinds == ["prompt", "plan"]
        prompt, plan = r.json()["messages"]
        assert prompt["text"] == "go to the nearest door"
        assert plan["intent_text"] == "I'll go to the nearest door."
        assert plan["translator"] == "offline"
        assert plan["commands"][0]["command"]["command"] == "NavigateThroughPoses"
        assert plan["commands"][0]["text"].startswith("Navigate to (")
        assert " — " in plan["commands"][0]["text"]  # the note says which door
        client.post("/api/stop")


def test_question_is_answered_in_plain_words(make_client: AppFactory) -> None:
    with make_client() as client:
        r = _prompt(client, "where are you?")
        msgs = r.json()["messages"]
        assert [m["kind"] for m in msgs] == ["prompt", "answer"]
        assert msgs[1]["text"] == "I'm in the hallway at x 1.5, y 5.0, facing east."


def test_clarification_moves_nothing(make_client: AppFactory) -> None:
    with make_client() as client:
        before = client.get("/api/status").json()["pose"]
        r = _prompt(client, "make me a sandwich")
        msgs = r.json()["messages"]
        assert [m["kind"] for m in msgs] == ["prompt", "clarification"]
        assert len(msgs[1]["text"]) > 10
        time.sleep(0.3)
        st = client.get("/api/status").json()
        assert st["plan"]["state"] == "idle"
        assert st["pose"] == before


def test_stop_halts_at_once(make_client: AppFactory) -> None:
    with make_client() as client:
        _prompt(client, "go to the farthest door")
        time.sleep(1.0)
        r = client.post("/api/stop")  # no JSON body, no token: stopping is never refused
        assert r.status_code == 200
        assert r.json()["message"]["text"].startswith("Stopped (you pressed STOP).")
        st = _wait_idle(client, 5.0)
        time.sleep(0.5)
        assert client.get("/api/status").json()["pose"] == st["pose"]


def test_plan_runs_to_the_goal_and_reports(make_client: AppFactory) -> None:
    with make_client() as client:
        _prompt(client, "move forward 0.6 meters")
        _wait_idle(client, 30.0)
        hist = client.get("/api/history").json()["messages"]
        steps = [(m["index"], m["status"]) for m in hist if m["kind"] == "step"]
        assert steps == [(0, "running"), (0, "succeeded")]
        outcome = [m for m in hist if m["kind"] == "outcome"][-1]
        assert outcome["status"] == "succeeded"
        assert outcome["text"].startswith("Done. I'm in the hallway at x 2.1, y 5.0, facing east")


def test_click_goes_through_the_validator(make_client: AppFactory) -> None:
    with make_client() as client:
        outside = client.post("/api/goto", json={"x": -0.8, "y": -0.8})  # outside the building
        msgs = outside.json()["messages"]
        assert msgs[-1]["kind"] == "rejected"
        assert msgs[-1]["reasons"]
        ok = client.post("/api/goto", json={"x": 3.0, "y": 5.0})
        card = ok.json()["messages"][-1]
        assert card["kind"] == "plan"
        assert card["commands"][0]["text"] == "Navigate to (3.0, 5.0) — the point you clicked"
        client.post("/api/stop")


def test_token_required_when_not_loopback(make_client: AppFactory) -> None:
    token = "t" * 32
    with make_client(host="0.0.0.0", token=token) as client:
        r = _prompt(client, "where are you?")
        assert r.status_code == 401
        assert "token" in r.json()["error"]["message"]
        assert _prompt(client, "where are you?", **{"X-Langnav-Token": "wrong" * 8}).status_code == 401
        assert _prompt(client, "where are you?", **{"X-Langnav-Token": token}).status_code == 200
        assert _prompt(client, "where are you?", Authorization=f"Bearer {token}").status_code == 200
        assert client.post("/api/stop").status_code == 200
        assert client.get("/api/status").json()["requires_token"] is True


def test_loopback_needs_no_token(make_client: AppFactory) -> None:
    with make_client() as client:
        assert client.get("/api/status").json()["requires_token"] is False
        assert _prompt(client, "where are you?").status_code == 200


def test_rate_limit_per_client(make_client: AppFactory) -> None:
    with make_client(rate_burst=2, rate_refill_s=60.0) as client:
        codes = [_prompt(client, "where are you?").status_code for _ in range(3)]
        assert codes == [200, 200, 429]
        r = _prompt(client, "where are you?")
        assert int(r.headers["Retry-After"]) >= 1
        assert r.json()["error"]["title"] == "Too many requests"
        assert client.post("/api/stop").status_code == 200  # STOP is never rate limited


def test_oversized_prompt_is_refused(make_client: AppFactory) -> None:
    with make_client() as client:
        r = _prompt(client, "go " * 1000)
        assert r.status_code == 413
        assert "at most 2000" in r.json()["error"]["message"]
        big = client.post("/api/prompt", content=b'{"text": "' + b"a" * 20000 + b'"}', headers=JSON)
        assert big.status_code == 413
        assert client.get("/api/history").json()["messages"] == []


def test_bad_requests_get_clear_errors(make_client: AppFactory) -> None:
    with make_client() as client:
        form = client.post("/api/prompt", content=b"text=hi", headers={"Content-Type": "text/plain"})
        assert form.status_code == 415
        assert client.post("/api/prompt", json={"txt": "hi"}).json()["error"]["status"] == 422
        cross = client.post("/api/prompt", json={"text": "hi"}, headers={"Origin": "http://evil.example"})
        assert cross.status_code == 403
        empty = _prompt(client, "   ")
        assert empty.status_code == 400
        assert "empty" in empty.json()["error"]["message"]
        assert client.post("/api/goto", content=b'{"x": NaN, "y": 1}', headers=JSON).status_code == 422


def test_error_page_escapes_html(make_client: AppFactory) -> None:
    with make_client() as client:
        r = client.get("/<script>alert(1)</script>", headers={"Accept": "text/html"})
        assert r.status_code == 404
        assert r.headers["content-type"].startswith("text/html")
        assert "<script>alert" not in r.text
        assert "&lt;script&gt;alert(1)&lt;/script&gt;" in r.text
        api = client.get("/api/nothing")
        assert api.json()["error"]["status"] == 404


def test_page_is_served_locally_with_a_strict_policy(make_client: AppFactory) -> None:
    with make_client() as client:
        page = client.get("/")
        assert page.status_code == 200
        assert "script-src 'self'" in page.headers["content-security-policy"]
        for asset in ("/static/app.js", "/static/app.css"):
            assert client.get(asset).status_code == 200
        text = page.text + client.get("/static/app.js").text + client.get("/static/app.css").text
        assert "http://" not in text and "https://" not in text  # no CDN, no external font
        assert "innerHTML" not in client.get("/static/app.js").text


def test_history_survives_an_app_restart(make_client: AppFactory) -> None:
    with make_client() as client:
        _prompt(client, "where are you?")
        first = client.get("/api/history").json()["messages"]
    with make_client() as client:
        again = client.get("/api/history").json()["messages"]
        assert [(m["id"], m["kind"], m["text"]) for m in again] == [(m["id"], m["kind"], m["text"]) for m in first]
        _prompt(client, "where are you?")
        assert len(client.get("/api/history").json()["messages"]) == 4


def test_websocket_streams_map_elements_and_state(make_client: AppFactory) -> None:
    with make_client() as client, client.websocket_connect("/ws") as ws:
        hello = ws.receive_json()
        assert hello["type"] == "hello"
        assert hello["status"]["backend"] == "sim"
        seen: dict[str, Any] = {}
        end = time.monotonic() + 10
        while time.monotonic() < end and not {"map", "state", "elements", "scan", "path"} <= seen.keys():
            m = ws.receive_json()
            seen[m["type"]] = m
        assert seen["map"]["width"] == 320 and seen["map"]["height"] == 220
        assert seen["map"]["png"].startswith("iVBOR")  # base64 of the PNG signature
        assert seen["state"]["pose"][:2] == [1.5, 4.95]
        assert len(seen["scan"]["points"]) > 100
        assert seen["path"] == {"type": "path", "path": [], "goals": []}  # not driving
        assert {d["id"] for d in seen["elements"]["doors"]}


def test_pause_and_resume(make_client: AppFactory) -> None:
    with make_client() as client:
        _prompt(client, "go to the farthest door")
        time.sleep(1.0)
        r = client.post("/api/pause")
        assert r.json()["ok"] is True
        time.sleep(0.5)
        st = client.get("/api/status").json()
        assert st["plan"]["state"] == "paused"
        time.sleep(0.5)
        assert client.get("/api/status").json()["pose"] == st["pose"]  # the robot holds still
        r = client.post("/api/resume", json={})
        assert r.json()["ok"] is True
        time.sleep(1.0)
        moving = client.get("/api/status").json()
        assert moving["plan"]["state"] == "running"
        assert moving["pose"] != st["pose"]
        client.post("/api/stop")


def test_translator_choice(make_client: AppFactory) -> None:
    with make_client() as client:
        bad = client.post("/api/translator", json={"name": "psychic"})
        assert bad.status_code == 400
        assert "choose one of" in bad.json()["error"]["message"] and "offline" in bad.json()["error"]["message"]
        ok = client.post("/api/translator", json={"name": "offline"})
        assert ok.json() == {"ok": True, "translator": "offline"}
        assert client.get("/api/status").json()["translator"] == "offline"


def test_user_text_is_escaped_on_the_wire(make_client: AppFactory) -> None:
    with make_client() as client:
        r = _prompt(client, "<img src=x onerror=alert(1)> where are you?")
        assert "<img" not in r.text
        assert "\\u003cimg src=x onerror=alert(1)\\u003e" in r.text
        assert r.json()["messages"][0]["text"] == "<img src=x onerror=alert(1)> where are you?"
        assert "<img" not in client.get("/api/history").text


def test_stop_writes_one_message(make_client: AppFactory) -> None:
    with make_client() as client:
        _prompt(client, "go to the farthest door")
        time.sleep(0.8)
        last = client.get("/api/history").json()["messages"][-1]["id"]
        client.post("/api/stop")
        _wait_idle(client, 5.0)
        time.sleep(0.5)
        new = [m for m in client.get("/api/history").json()["messages"] if m["id"] > last and m["kind"] != "step"]
        assert [m["text"][:8] for m in new] == ["Stopped "]


def test_pause_holds_exploration_and_resume_carries_on(make_client: AppFactory) -> None:
    with make_client(known_map=False) as client:
        _prompt(client, "explore")
        end = time.monotonic() + 20
        while client.get("/api/status").json()["plan"]["state"] != "running" and time.monotonic() < end:
            time.sleep(0.05)
        time.sleep(1.5)
        assert client.post("/api/pause").json()["ok"] is True
        time.sleep(0.5)
        held = client.get("/api/status").json()["pose"]
        time.sleep(2.0)
        assert client.get("/api/status").json()["pose"] == held
        assert client.get("/api/status").json()["plan"]["state"] == "paused"
        assert client.post("/api/resume", json={}).json()["ok"] is True
        end = time.monotonic() + 10
        while client.get("/api/status").json()["pose"] == held and time.monotonic() < end:
            time.sleep(0.1)
        assert client.get("/api/status").json()["pose"] != held
        client.post("/api/stop")
