"""``langnav node``: langnav as a ROS 2 node (needs rclpy; see docs/ros2.md).

    langnav node [--node-namespace NS] [--translator offline] [robot options] [--duration S]

Offers the action ``/langnav/instruct`` (langnav_interfaces/action/Instruct: goal the prompt,
feedback each step in plain words, result outcome and reply), the service ``/langnav/stop``
(std_srvs/srv/Trigger) and the map analysis on ``/langnav/map_analysis``
(visualization_msgs/msg/MarkerArray) for RViz and Foxglove. It drives the robot through the
``ros2`` backend (Nav2 on the same ROS graph) by default; the robot options are those of
``langnav run`` (``--namespace /robot1``, ``--base-frame base_footprint``, ``--robot-option``, or
their LANGNAV_* variables).

    ros2 action send_goal --feedback /langnav/instruct langnav_interfaces/action/Instruct "{prompt: 'go to the nearest door'}"
    ros2 service call /langnav/stop std_srvs/srv/Trigger
"""

from __future__ import annotations

import argparse
import os
import time

from langnav.cli.robot_options import ENV_BACKEND, add_robot_arguments, robot_options
from langnav.robot.protocol import create_backend

#: How often the console line is refreshed.
STATUS_PERIOD_S = 5.0


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--node-namespace", default="", help="ROS 2 namespace of langnav's own node (default: none)")
    p.add_argument("--translator", default="offline", help="offline (default), gemini, openai, local, auto")
    p.add_argument("--duration", type=float, default=None, help="stop after this many seconds (default: until Ctrl-C)")
    add_robot_arguments(p)


def run(args: argparse.Namespace) -> int:
    from langnav.robot.ros.node import LangnavNode

    if getattr(args, "backend", None) is None and ENV_BACKEND not in os.environ:
        args.backend = "ros2"  # a ROS 2 node drives the robot on its own graph unless told otherwise
    backend, options = robot_options(args)
    robot = create_backend(backend, **options)
    node = None
    try:
        node = LangnavNode(robot, translator=args.translator, namespace=args.node_namespace)
        ns = "/" + args.node_namespace.strip("/") if args.node_namespace.strip("/") else ""
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
