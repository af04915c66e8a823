"""``langnav sim``: run the simulated robot in real time and serve it over rosbridge (and, with
``--ros2``, as a Nav2-shaped robot on a real ROS 2 graph).

    langnav sim --world MAP.yaml --pose X,Y,YAW_DEG [--known-map] [--rosbridge-port 9090] [--host 127.0.0.1]
                [--ros2 [--namespace NS]] [--no-rosbridge]

Foxglove (Open connection -> Rosbridge -> ws://HOST:PORT), roslibjs pages and roslibpy scripts
see a ROS 2 robot: /map, /scan, /plan, /tf, /tf_static, /odom, /amcl_pose, /rosout, the
/navigate_through_poses action, /rosapi/topics_and_raw_types (the message definitions Foxglove
decodes with), and /cmd_vel for teleop (Twist or TwistStamped, held 0.5 s).
``langnav run --backend rosbridge --rosbridge-url ws://HOST:PORT`` drives it like a real one.
With ``--ros2`` (needs rclpy and the nav2_msgs / tf2_msgs interfaces; see docs/ros2.md) the same
robot is on the ROS 2 graph of this ROS_DOMAIN_ID (:mod:`langnav.robot.ros.robot_node`): RViz,
Foxglove and ``langnav run --backend ros2`` see map, tf, scan, odom, plan, cmd_vel and Nav2's
navigate_through_poses, spin, backup and drive_on_heading actions.
"""

from __future__ import annotations

import argparse
import math
import time
from typing import Any

from langnav.cli.options import pose_arg
from langnav.robot.errors import RobotError
from langnav.robot.protocol import Pose2D, create_backend
from langnav.robot.ros.rosbridge_server import RosbridgeServer

#: How often the console line with the pose is refreshed.
STATUS_PERIOD_S = 2.0


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--world", required=True, help="ground-truth map (map_server YAML or image)")
    parser.add_argument("--pose", type=pose_arg, default=None, help="start pose X,Y,YAW_DEG (default: the most open spot)")
    parser.add_argument("--known-map", action="store_true", help="start with the whole map known (a floor already mapped)")
    parser.add_argument("--rosbridge-port", type=int, default=9090, help="rosbridge WebSocket port (0: any free port)")
    parser.add_argument("--host", default="127.0.0.1", help="interface to listen on (0.0.0.0 for the LAN)")
    parser.add_argument("--seed", type=int, default=0, help="random seed of the lidar noise")
    parser.add_argument("--ros2", action="store_true", help="also serve the robot on the ROS 2 graph (rclpy)")
    parser.add_argument("--namespace", default="", help="ROS 2 namespace of the served robot (with --ros2)")
    parser.add_argument("--no-rosbridge", action="store_true", help="do not serve rosbridge (with --ros2)")
    parser.add_argument("--duration", type=float, default=None, help="stop after this many seconds (default: run until Ctrl-C)")


def run(args: argparse.Namespace) -> int:
    if not 0 <= args.rosbridge_port <= 65535:
        raise RobotError(f"--rosbridge-port must be 0..65535, got {args.rosbridge_port}")
    if args.no_rosbridge and not args.ros2:
        raise RobotError("--no-rosbridge leaves nothing to serve: add --ros2")
    sim: Any = create_backend("sim", world=args.world, pose=args.pose, known_map=args.known_map, seed=args.seed)
    server = None if args.no_rosbridge else RosbridgeServer(sim)
    node: Any = None
    try:
        sim.start(realtime=True)
        if args.ros2:
            from langnav.robot.ros.robot_node import RobotNode

            # a known map is a floor already mapped: served unchanging, as map_server serves a saved map
            node = RobotNode(sim, static_map=sim.world.frame if args.known_map else None, namespace=args.namespace)
        p: Pose2D = sim.get_robot_pose()
        print(f"langnav sim: {args.world} from ({p.x_m:.2f}, {p.y_m:.2f}, {math.degrees(p.yaw_rad):.0f}°), "
              f"{'known' if args.known_map else 'unknown'} map", flush=True)
        if server is not None:
            port = server.start(args.host, args.rosbridge_port)
            print(f"rosbridge v2 on ws://{args.host}:{port} (Ctrl-C to stop)", flush=True)
        if node is not None:
            print(f"ROS 2: Nav2-shaped robot in namespace {args.namespace or '/'!r} (Ctrl-C to stop)", flush=True)
        t_end = None if args.duration is None else time.monotonic() + args.duration
        while t_end is None or time.monotonic() < t_end:
            time.sleep(STATUS_PERIOD_S if t_end is None else max(0.0, min(STATUS_PERIOD_S, t_end - time.monotonic())))
            st = sim.state()
            print(f"t={st.time_s:7.1f} s  pose=({st.pose.x_m:6.2f}, {st.pose.y_m:6.2f}, "
                  f"{math.degrees(st.pose.yaw_rad):5.0f}°)  {'busy' if st.busy else 'idle'}", flush=True)
    finally:
        if node is not None:
            node.close()
        if server is not None:
            server.close()
        sim.close()
    return 0
