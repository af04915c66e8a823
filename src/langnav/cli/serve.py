"""``langnav serve``: the web app (chat + live map) with a robot backend, on one port.

The robot options (``--backend``, ``--rosbridge-url``, ``--namespace``, frames, cmd_vel topic and
type, action names, timeouts; or their ``LANGNAV_*`` variables) are the ones ``langnav run``
takes (:mod:`langnav.cli.robot_options`)."""

from __future__ import annotations

import argparse
import logging
from pathlib import Path

from langnav.cli.options import pose_arg
from langnav.cli.places import add_places_option, places_path
from langnav.cli.robot_options import add_robot_arguments, robot_options
from langnav.web.settings import DEFAULT_HOST, DEFAULT_PORT, WebSettings, make_token

log = logging.getLogger(__name__)


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--world", type=Path, default=None,
                   help="map of the simulated world (map_server YAML or image); default: the bundled demo world")
    p.add_argument("--translator", default="offline",
                   help="who reads prompts: offline (default), auto, gemini, openai, local")
    p.add_argument("--host", default=DEFAULT_HOST,
                   help="address to listen on (default 127.0.0.1; any other needs the printed token)")
    p.add_argument("--port", type=int, default=DEFAULT_PORT, help=f"port (default {DEFAULT_PORT})")
    p.add_argument("--known-map", action="store_true", help="the robot starts with the whole world map as its own")
    p.add_argument("--pose", type=pose_arg, default=None, help="start pose X,Y,YAW_DEG (default: the world's open spot)")
    p.add_argument("--db", type=Path, default=Path("langnav.db"), help="SQLite file of the conversation")
    add_places_option(p)  # the same places file as `langnav run` / `langnav places`
    add_robot_arguments(p)


def settings_from_args(args: argparse.Namespace) -> WebSettings:
    """The options (over LANGNAV_* variables); a token is made when the bind is not loopback."""
    backend, options = robot_options(args)  # flags, then LANGNAV_* variables (one definition with `run`)
    settings = WebSettings.from_env(world=args.world, backend=backend, translator=args.translator,
                                    host=args.host, port=args.port, known_map=args.known_map or None,
                                    start_pose=args.pose, db_path=args.db, backend_options=options or None,
                                    places_path=places_path(getattr(args, "places", None)))
    if settings.requires_token and not settings.token:
        settings = settings.model_copy(update={"token": make_token()})
    return settings.checked()


def run(args: argparse.Namespace) -> int:
    import uvicorn

    from langnav.web.app import create_app
    from langnav.web.session import RobotSession

    settings = settings_from_args(args)
    # Built before the server starts, so a bad world, start pose, database or robot address is a
    # one-line error (exit 2) instead of a traceback from inside the server's start-up.
    session = RobotSession(settings)
    shown_host = f"[{settings.host}]" if ":" in settings.host else settings.host
    url = f"http://{shown_host}:{settings.port}/"
    if settings.requires_token:
        print(f"langnav is reachable from other machines on {settings.host}: moving the robot needs this token "
              f"(shown once):\n  {settings.token}\nopen {url}?token={settings.token}", flush=True)
    else:
        print(f"langnav: open {url}", flush=True)
    app = create_app(settings, session_factory=lambda _settings: session)
    try:
        uvicorn.run(app, host=settings.host, port=settings.port, log_level="warning", ws_ping_interval=20.0,
                    # Frames are small and mostly numbers; compressing each one for every viewer
                    # costs more CPU than the bytes it saves on a local network.
                    ws_per_message_deflate=False)
    finally:
        session.close()  # idempotent: the app's shutdown closed it already unless start-up failed
    return 0
