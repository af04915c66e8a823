"""STOP on a backend that can tell whether the stop took (the rosbridge backend's wait_stopped):
when the robot does not confirm, the chat says so; the user must know it may still be moving."""

from __future__ import annotations

import time
from pathlib import Path

from langnav.robot.errors import RobotError
from langnav.web.session import RobotSession, _make_robot
from langnav.web.settings import WebSettings

HALLWAY_POSE = (1.5, 4.95, 0.0)
UNCONFIRMED = "the goal was not confirmed cancelled: THE ROBOT MAY STILL BE MOVING"


def _session(tmp_path: Path, wait_stopped: object) -> RobotSession:
    settings = WebSettings(db_path=tmp_path / "chat.db", known_map=True, start_pose=HALLWAY_POSE)
    robot = _make_robot(settings)
    robot.wait_stopped = wait_stopped  # type: ignore[attr-defined]
    return RobotSession(settings, robot=robot)


def _texts(session: RobotSession, kind: str, timeout_s: float = 5.0) -> list[str]:
    end = time.monotonic() + timeout_s
    while True:
        found = [m.payload.get("text", "") for m in session.store.history() if m.kind == kind]
        if found or time.monotonic() > end:
            return found
        time.sleep(0.05)


def test_an_unconfirmed_stop_is_told_as_an_error(tmp_path: Path) -> None:
    def never_confirmed(timeout_s: float | None = None) -> None:
        raise RobotError(UNCONFIRMED)

    session = _session(tmp_path, never_confirmed)
    try:
        assert session.stop()["ok"] is True
        errors = _texts(session, "error")
        assert len(errors) == 1 and "MAY STILL BE MOVING" in errors[0]
    finally:
        session.close()


def test_a_confirmed_stop_says_nothing_more(tmp_path: Path) -> None:
    calls: list[float | None] = []
    session = _session(tmp_path, lambda timeout_s=None: calls.append(timeout_s))
    try:
        session.stop()
        assert _texts(session, "error", timeout_s=0.5) == []
        assert calls == [None]  # the backend's own bound
    finally:
        session.close()
