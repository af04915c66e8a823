"""``langnav node``: langnav as a ROS 2 node (needs rclpy; see docs/ros2.md).

    langnav node [--namespace NS] [--translator offline] [--robot-option KEY=VALUE ...] [--duration S]

Offers the action ``/langnav/instruct`` (langnav_interfaces/action/Instruct: goal the prompt,
feedback each step in plain words, result outcome and reply), the service ``/langnav/stop``
(std_srvs/srv/Trigger) and the map analysis on ``/langnav/map_analysis``
(visualization_msgs/msg/MarkerArray) for RViz and Foxglove. It drives the robot through the
``ros2`` backend (Nav2 on the same ROS graph); ``--robot-option`` sets a field of its config
(``namespace=robot1``, ``base_frame=base_footprint``, ...).

    ros2 action send_goal --feedback /langnav/instruct langnav_interfaces/action/Instruct "{prompt: 'go to the nearest door'}"
    ros2 service call /langnav/stop std_srvs/srv/Trigger
"""

from __future__ import annotations

import argparse
import time
from typing import Any

import yaml

from langnav.robot.protocol import create_backend

#: How often the console line is refreshed.
STATUS_PERIOD_S = 5.0


def _option(text: str) -> tuple[str, Any]:
    key, sep, value = text.partition("=")
    if not sep or not key.strip():
        raise argparse.ArgumentTypeError(f"--robot-option is KEY=VALUE, got {text!r}")
    return key.strip(), yaml.safe_load(value)


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--namespace", default="", help="ROS 2 namespace of langnav's node (default: none)")
    p.add_argument("--translator", default="offline", help="offline (default), gemini, openai, local, auto")
    p.add_argument("--robot-option", type=_option, action="append", default=[], metavar="KEY=VALUE",
                   help="a field of the ros2 backend's config (repeatable), e.g. namespace=robot1")
    p.add_argument("--duration", type=float, default=None, help="stop after this many seconds (default: until Ctrl-C)")


def run(args: argparse.Namespace) -> int:
    from langnav.robot.ros.node import LangnavNode

    robot = create_backend("ros2", **dict(args.robot_option))
    node = None
    try:
        node = LangnavNode(robot, translator=args.translator, namespace=args.namespace)
        ns = "/" + args.namespace.strip("/") if args.namespace.strip("/") else ""
        print(f"langnav node: {ns}/langnav/instruct, {ns}/langnav/stop, {ns}/langnav/map_analysis "
              f"(Ctrl-C to stop)", flush=True)
        t_end = None if args.duration is None else time.monotonic() + args.duration
        while t_end is None or time.monotonic() < t_end:
            time.sleep(STATUS_PERIOD_S if t_end is None else max(0.0, min(STATUS_PERIOD_S, t_end - time.monotonic())))
    finally:
        if node is not None:
            node.close()
        robot.close()
    return 0
