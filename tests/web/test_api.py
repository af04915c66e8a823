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
        assert plan["commands"][0]["text"] == "Go to the nearest door (in hallway 2 near door 2)"
        assert plan["commands"][0]["detail"].startswith("Navigate to (")  # the exact command, on request
        assert " — " in plan["commands"][0]["detail"]  # the note says which door
        client.post("/api/stop")


def test_question_is_answered_in_plain_words(make_client: AppFactory) -> None:
    with make_client() as client:
        r = _prompt(client, "where are you?")
        msgs = r.json()["messages"]
        assert [m["kind"] for m in msgs] == ["prompt", "answer"]
        assert msgs[1]["text"] == "I'm in hallway 2 near door 2, facing east."
        exact = _prompt(client, "what are your exact coordinates?").json()["messages"]
        assert exact[1]["text"] == "I'm in hallway 2 near door 2, at x 1.5, y 5.0 (metres on the map), facing east."


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
        assert outcome["text"].startswith("Done. I'm in hallway 2 near door 2, facing east")


def test_click_goes_through_the_validator(make_client: AppFactory) -> None:
    with make_client() as client:
        outside = client.post("/api/goto", json={"x": -0.8, "y": -0.8})  # outside the building
        msgs = outside.json()["messages"]
        assert msgs[-1]["kind"] == "rejected"
        assert msgs[-1]["text"].startswith("I haven't mapped that spot yet")
        ok = client.post("/api/goto", json={"x": 3.0, "y": 5.0})
        card = ok.json()["messages"][-1]
        assert card["kind"] == "plan"
        assert card["commands"][0]["text"] == "Go to the point you clicked (in hallway 2 near door 2)"
        assert card["commands"][0]["detail"] == "Navigate to (3.0, 5.0) — the point you clicked"
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
        empty = _prompt(client, "   \t ")  # whitespace only: a reply, not silence
        assert empty.status_code == 200
        (reply,) = empty.json()["messages"]
        assert reply["kind"] == "clarification" and reply["text"].startswith("Your message was empty")
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


def test_help_and_map_questions_are_answered_from_this_map(make_client: AppFactory) -> None:
    with make_client() as client:
        examples = client.get("/api/status").json()["examples"]
        assert len(examples) == 5 and examples[0] == "where are you?"
        for text in ("help", "What can you do?"):
            msgs = _prompt(client, text).json()["messages"]
            assert msgs[1]["kind"] == "answer"
            assert all(e in msgs[1]["text"] for e in examples)
        rooms = _prompt(client, "how many rooms are there?").json()["messages"][1]
        assert rooms["text"] == "I see 3 rooms: room 1, room 3 and room 4."
        door = _prompt(client, "where is door 5?").json()["messages"][1]
        assert door["kind"] == "answer"
        assert door["text"] == "Door 5 is 2.7 m ahead of me (to the east), between hallway 2 and room 4."
        missing = _prompt(client, "where is door 42?").json()["messages"][1]["text"]
        assert missing.startswith("I don't see door 42 on my map. The ones I know: door 1, door 2")
        assert client.get("/api/status").json()["plan"]["state"] == "idle"  # nothing moved


def test_every_starter_example_plans_on_the_first_screen(make_client: AppFactory) -> None:
    """The examples the page offers are planned on this map before they are offered."""
    with make_client() as client:
        for text in client.get("/api/status").json()["examples"]:
            msgs = _prompt(client, text).json()["messages"]
            assert msgs[-1]["kind"] in ("plan", "answer"), (text, msgs[-1])
            client.post("/api/stop")
            _wait_idle(client, 5.0)


def test_a_new_prompt_while_a_plan_runs_asks_first(make_client: AppFactory) -> None:
    with make_client() as client:
        _prompt(client, "go to the farthest door")
        time.sleep(0.5)
        msgs = _prompt(client, "go to the nearest door").json()["messages"]
        assert [m["kind"] for m in msgs] == ["prompt", "confirm"]
        assert msgs[1]["prompt"] == "go to the nearest door" and "instead?" in msgs[1]["text"]
        assert client.get("/api/status").json()["plan"]["state"] == "running"  # still the first plan
        ask = _prompt(client, "where are you?").json()["messages"]
        assert ask[1]["kind"] == "answer"  # questions are answered alongside
        again = client.post("/api/prompt", json={"text": "go to the nearest door", "replace": True}).json()
        assert again["messages"][-1]["kind"] == "plan"
        client.post("/api/stop")


def test_spot_names_what_is_clicked_and_goto_refuses_obstacles_up_front(make_client: AppFactory) -> None:
    with make_client() as client:
        door = client.get("/api/spot", params={"x": 4.0, "y": 5.85}).json()
        assert door["element"]["name"] == "door 5" and door["element"]["kind"] == "door"
        assert [a["prompt"] for a in door["element"]["actions"] if "prompt" in a] == ["go to door 5", "go through door 5"]
        table = client.get("/api/spot", params={"x": 2.8, "y": 7.5}).json()
        assert table["cell"] == "obstacle" and table["go"] is False
        assert table["element"]["kind"] == "obstacle" and table["element"]["size"] == "1.6 × 0.8 m"
        refused = client.post("/api/goto", json={"x": 2.8, "y": 7.5}).json()["messages"]
        assert refused[-1]["kind"] == "rejected" and "wall or an obstacle" in refused[-1]["text"]
        assert client.get("/api/status").json()["plan"]["state"] == "idle"
        ok = client.post("/api/goto", json={"x": 3.0, "y": 5.0, "yaw_deg": 90.0}).json()["messages"]
        assert ok[-1]["kind"] == "plan" and ok[-1]["commands"][0]["command"]["poses"] == [[3.0, 5.0, 90.0]]
        assert ok[0]["text"] == "Go to the spot I clicked (in hallway 2 near door 2), facing north"
        _wait_idle(client, 30.0)
        yaw = client.get("/api/status").json()["pose"][2]
        assert abs(yaw - 1.5708) < 0.2


def test_a_translator_that_cannot_be_used_is_refused_and_the_one_in_use_stays(make_client: AppFactory) -> None:
    import os

    if os.environ.get("GEMINI_API_KEY") or os.environ.get("GOOGLE_API_KEY"):
        return
    with make_client() as client:
        r = client.post("/api/translator", json={"name": "gemini"})
        assert r.status_code == 400 and "GEMINI_API_KEY" in r.json()["error"]["message"]
        assert client.get("/api/status").json()["translator"] == "offline"


def test_a_map_name_in_a_prompt_is_where_the_plan_goes_or_nothing_moves(make_client: AppFactory) -> None:
    """"go through door 5" never drives through another door (a reading that lost the number)."""
    with make_client() as client:
        msgs = _prompt(client, "go through door 5").json()["messages"]
        last = msgs[-1]
        if last["kind"] == "plan":
            poses = [p for c in last["commands"] for p in c["command"].get("poses", [])]
            assert any(abs(p[0] - 4.0) < 1.5 and abs(p[1] - 5.85) < 1.5 for p in poses), poses
            client.post("/api/stop")
        else:
            assert last["kind"] == "clarification" and "door 5" in last["text"]
            assert client.get("/api/status").json()["plan"]["state"] == "idle"


def test_places_named_from_the_map_are_listed_renamed_and_forgotten(make_client: AppFactory) -> None:
    with make_client() as client:
        r = client.post("/api/places", json={"name": "Front door", "x": 4.0, "y": 5.85, "element_id": "door_5"})
        assert r.status_code == 200
        (front,) = r.json()["places"]
        assert abs(front["x"] - 4.0) < 0.1 and abs(front["y"] - 5.85) < 0.1
        bad = client.post("/api/places", json={"name": "desk", "x": 2.8, "y": 7.5})  # on the table
        assert bad.status_code == 400 and "free floor" in bad.json()["error"]["message"]
        client.post("/api/places", json={"name": "kitchen", "x": 2.0, "y": 3.0})
        names = [p["name"].lower() for p in client.get("/api/places").json()["places"]]
        assert names == ["front door", "kitchen"]
        client.post("/api/places/rename", json={"name": "kitchen", "new_name": "pantry"})
        client.post("/api/places/forget", json={"name": "front door"})
        assert [p["name"].lower() for p in client.get("/api/places").json()["places"]] == ["pantry"]
        missing = client.post("/api/places/forget", json={"name": "garage"})
        assert missing.status_code == 400 and "pantry" in missing.json()["error"]["message"]


def test_places_named_in_words_show_as_pins_and_answers_are_plain(make_client: AppFactory) -> None:
    with make_client() as client:
        r = _prompt(client, "call this spot the kitchen").json()["messages"]
        assert r[-1]["kind"] == "answer"
        assert "kitchen" in r[-1]["text"] and "hallway 2" in r[-1]["text"] and "1.5," not in r[-1]["text"]
        assert [p["name"].lower() for p in client.get("/api/places").json()["places"]] == ["kitchen"]
        known = _prompt(client, "what places do you know?").json()["messages"][-1]
        assert known["kind"] == "answer" and "kitchen" in known["text"]
        _prompt(client, "move forward 1 metre")
        _wait_idle(client, 30.0)
        back = _prompt(client, "go to the kitchen").json()["messages"][-1]
        assert back["kind"] == "plan"
        _wait_idle(client, 30.0)
        x, y, _ = client.get("/api/status").json()["pose"]
        assert abs(x - 1.5) < 0.3 and abs(y - 4.95) < 0.3


def test_named_places_survive_a_restart(make_client: AppFactory) -> None:
    with make_client() as client:
        assert client.post("/api/places", json={"name": "dock", "x": 2.0, "y": 3.0}).status_code == 200
    with make_client() as client:  # the same database directory: the same places file
        assert [p["name"] for p in client.get("/api/places").json()["places"]] == ["dock"]


def test_element_ids_stay_put_as_the_map_grows(make_client: AppFactory) -> None:
    """The session's analyses (the live map's and the planner's) keep each element's id."""
    import math

    with make_client(known_map=False) as client:
        session = client.app.state.session  # type: ignore[attr-defined]
        first = session._current_analysis()
        assert first is not None
        seen = {d.id: d.center for d in first.doors}
        for text in ("move forward 2 metres", "move forward 2 metres", "turn around", "move forward 3 metres"):
            _prompt(client, text)
            _wait_idle(client, 60.0)
            now = session._current_analysis()
            for d in now.doors:
                for old_id, c in seen.items():
                    if math.dist(c, d.center) < 0.3:
                        assert d.id == old_id, (d.id, old_id, d.center)
                seen.setdefault(d.id, d.center)
        assert len(seen) >= 2


def test_errors_shown_to_the_user_are_logged(make_client: AppFactory, caplog: Any) -> None:
    import logging

    with make_client() as client, caplog.at_level(logging.WARNING):
        client.post("/api/goto", json={"x": 2.8, "y": 7.5})       # on the table: refused
        client.post("/api/translator", json={"name": "nope"})     # an HTTP error
    text = caplog.text
    assert "told the user (rejected)" in text and "wall or an obstacle" in text
    assert "/api/translator -> 400" in text
