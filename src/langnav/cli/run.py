"""``langnav run``: translate, validate and execute one prompt on a robot, printing every event.

    langnav run --world MAP.yaml --pose X,Y,YAW_DEG [--known-map] [--backend sim|rosbridge|ros2]
                [--rosbridge-url ws://HOST:PORT] [--json] [--translator NAME] "prompt"

With the simulator (the default) the robot starts at ``--pose`` in the world ``--world`` and knows
only what its lidar sees, unless ``--known-map`` gives it the world map as its own (a floor
already mapped). The simulator runs headless, faster than real time. With ``--backend rosbridge``
the robot, its map (``/map``) and its pose (tf) come from a ROS 2 robot behind rosbridge
(``--rosbridge-url ws://HOST:PORT``, or ``langnav sim --rosbridge-port``); ``--world``, ``--pose``
and ``--known-map`` are then ignored: the prompt is grounded on the robot's own map. ``--backend
ros2`` drives Nav2 through rclpy and needs ROS 2 on this machine. ``--robot-option KEY=VALUE``
sets any other field of the backend's config; the robot options (``--namespace``, frames,
``--cmd-vel-type``, action names, timeouts) are shared with ``langnav serve`` and can come from
``LANGNAV_*`` environment variables (:mod:`langnav.cli.robot_options`).

The prompt is read against the robot's own map and pose; exploration prompts ("explore", "map
this floor") run frontier exploration. With ``--json`` every event is one JSON object per line;
the last is ``{"event": "finished", "status": "succeeded"|"failed"|"cancelled"|"rejected",
"pose": [x, y, yaw_deg]}``. Exit status: 0 succeeded, 1 failed or cancelled, 2 rejected.
"""

from __future__ import annotations

import argparse
import json
import logging
from typing import Any, Final

from langnav.cli.options import pose_arg, seconds_arg, seed_arg
from langnav.cli.places import add_places_option, places_path
from langnav.cli.robot_options import (
    BACKENDS,
    add_robot_arguments,
    robot_options,
    rosbridge_address,
)
from langnav.errors import LangnavError
from langnav.plan.events import EventKind, ExecEvent, PlanStatus, pose_tuple
from langnav.plan.executor import DEFAULT_EXPLORE_TIMEOUT_S, PlanExecutor
from langnav.robot.errors import RobotError, RobotTimeout
from langnav.robot.protocol import RobotBackend, StopConfirmable, create_backend

log = logging.getLogger(__name__)

EXIT_CODES: Final = {PlanStatus.SUCCEEDED: 0, PlanStatus.FAILED: 1, PlanStatus.CANCELLED: 1, PlanStatus.REJECTED: 2}
#: Time to let a cancelled plan stop the robot on Ctrl-C.
CANCEL_GRACE_S: Final = 10.0
def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("prompt", help="what the robot should do, in plain words")
    p.add_argument("--world", help="the simulated world: map_server YAML or image, or 'demo' (sim only; default demo)")
    p.add_argument("--pose", type=pose_arg, default=None,
                   help="start pose X,Y,YAW_DEG (sim; default the most open spot; use --pose=-1,2,0 for negatives)")
    p.add_argument("--known-map", action="store_true", help="start the simulated robot with the world map as its own")
    p.add_argument("--rosbridge", default=None, metavar="HOST:PORT", help="rosbridge server as HOST:PORT (older form)")
    p.add_argument("--translator", default="offline", help="offline (default), gemini, openai, local, auto")
    p.add_argument("--seed", type=seed_arg, default=0, help="random seed of the simulated lidar noise")
    p.add_argument("--timeout", type=seconds_arg, default=DEFAULT_EXPLORE_TIMEOUT_S,
                   help="give up on the whole plan after this many seconds (robot time in the simulator)")
    p.add_argument("--json", action="store_true", help="one JSON object per line")
    add_robot_arguments(p)
    add_places_option(p)


def _make_robot(args: argparse.Namespace) -> RobotBackend:
    if args.rosbridge and args.rosbridge_url:
        raise RobotError("give --rosbridge-url or --rosbridge, not both")
    if args.rosbridge:  # the older HOST:PORT form
        host, _, port_text = args.rosbridge.rpartition(":")
        if not host or not port_text.isdigit():
            raise RobotError(f"--rosbridge is HOST:PORT, got {args.rosbridge!r}")
        args.rosbridge_url = f"ws://{host}:{port_text}"
    backend, options = robot_options(args)
    if backend == "sim":
        options.setdefault("world", args.world if args.world is not None else "demo")
        options.setdefault("pose", args.pose)
        options.setdefault("known_map", args.known_map)
        options.setdefault("seed", args.seed)
    elif args.world is not None or args.pose is not None or args.known_map:
        log.warning("--world, --pose and --known-map are for the simulator; the robot gives its own")
    return create_backend(backend, **options)


class _Printer:
    def __init__(self, as_json: bool) -> None:
        self.as_json = as_json

    def line(self, obj: dict[str, Any], text: str) -> None:
        print(json.dumps(obj, ensure_ascii=False) if self.as_json else text, flush=True)

    def event(self, ev: ExecEvent) -> None:
        if ev.kind is EventKind.FINISHED:
            return  # the CLI prints its own last line, with the final pose
        if self.as_json:
            self.line(ev.to_json(), "")
            return
        n = "" if ev.index is None else f"{ev.index + 1}. "
        mark = {EventKind.STARTED: "▶", EventKind.PROGRESS: "…", EventKind.SUCCEEDED: "✓", EventKind.FAILED: "✗",
                EventKind.CANCELLED: "■", EventKind.PAUSED: "‖", EventKind.RESUMED: "▶"}[ev.kind]
        what = ev.text if ev.kind is EventKind.STARTED else ev.message
        if ev.kind is EventKind.PROGRESS and ev.fraction is not None:
            what = f"{ev.fraction:4.0%}  {what}"
        print(f"[{ev.time_s:7.1f} s] {mark} {n}{what}", flush=True)


def run(args: argparse.Namespace) -> int:
    from langnav.analysis.identity import StableAnalyzer
    from langnav.language.translator import get_translator
    from langnav.pipeline import Planner, default_analyzer
    from langnav.places import JsonPlaceStore

    out = _Printer(args.json)
    places = JsonPlaceStore(places_path(args.places))  # read before the robot starts: a bad file stops here
    robot = _make_robot(args)
    try:
        grid = robot.get_map()
        pose = robot.get_robot_pose()
        start = pose_tuple(pose)
        # later steps are re-grounded on the grown map: its elements keep the ids the prompt read
        planner = Planner(get_translator(args.translator), places=places,
                          analyzer=StableAnalyzer(default_analyzer))
        result = planner.plan(args.prompt, grid, start)
        if result.clarification is not None:
            out.line({"event": "rejected", "message": result.clarification},
                     f"not run: {result.clarification}")
            return _finish(out, robot, PlanStatus.REJECTED)
        out.line({"event": "plan", "commands": result.to_json()["commands"], "messages": list(result.messages),
                  "pose": list(start)},
                 "plan from ({:.2f}, {:.2f}, {:.0f}°):\n".format(*start)
                 + "\n".join(f"  {i + 1}. {c}" for i, c in enumerate(_described(result)))
                 + "".join(f"\n  note: {m}" for m in result.messages))
        if not result.commands:  # naming a place, answering what places are known: nothing to drive
            return _finish(out, robot, PlanStatus.SUCCEEDED)
        run_ = PlanExecutor(robot).start(result.items, on_event=out.event)
        try:
            status = run_.wait(args.timeout)
        except RobotTimeout:
            run_.cancel()
            run_.wait(CANCEL_GRACE_S)
            _confirm_stop(out, robot)
            status = PlanStatus.FAILED
            out.line({"event": "failed", "message": f"the plan took longer than {args.timeout:.0f} s"},
                     f"gave up: the plan took longer than {args.timeout:.0f} s")
        except KeyboardInterrupt:
            run_.cancel()
            run_.wait(CANCEL_GRACE_S)
            _confirm_stop(out, robot)
            _finish(out, robot, PlanStatus.CANCELLED)
            return 130
        return _finish(out, robot, status)
    finally:
        try:
            robot.close()
        except LangnavError as exc:
            log.warning("closing the robot: %s", exc)


def _confirm_stop(out: _Printer, robot: RobotBackend) -> None:
    """After a cancel: say so loudly when the robot did not confirm that it stopped (a backend
    that can tell: the rosbridge backend's ``wait_stopped``)."""
    if not isinstance(robot, StopConfirmable):
        return
    try:
        robot.wait_stopped()
    except RobotError as exc:
        out.line({"event": "stop_unconfirmed", "message": str(exc)}, f"WARNING: {exc}")


def _described(result: Any) -> list[str]:
    from langnav.plan.commands import describe

    items = list(getattr(result, "items", ()))
    lines: list[str] = []
    for it in items:
        if getattr(it, "explore", False):
            lines.append("Explore until nothing reachable is left to map")
        lines.extend(describe(c) for c in it.commands)
    return lines


def _finish(out: _Printer, robot: RobotBackend, status: PlanStatus) -> int:
    x, y, yaw = pose_tuple(robot.get_robot_pose())
    out.line({"event": "finished", "status": status.value, "pose": [x, y, yaw]},
             f"finished: {status.value} at ({x:.2f}, {y:.2f}, {yaw:.0f}°)")
    return EXIT_CODES[status]


__all__ = ["BACKENDS", "add_arguments", "rosbridge_address", "run"]

