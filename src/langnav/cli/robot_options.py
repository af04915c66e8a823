"""The robot options ``langnav run`` and ``langnav serve`` share: one definition, each option a
flag or a ``LANGNAV_*`` environment variable (the flag wins), shown in ``--help``.

    --backend sim|rosbridge|ros2            LANGNAV_BACKEND
    --rosbridge-url ws://HOST:PORT          LANGNAV_ROSBRIDGE_URL
    --namespace /robot1                     LANGNAV_ROBOT_NAMESPACE
    --map-frame / --odom-frame / --base-frame   LANGNAV_MAP_FRAME / _ODOM_FRAME / _BASE_FRAME
    --cmd-vel-topic, --cmd-vel-type Twist|TwistStamped   LANGNAV_CMD_VEL_TOPIC / _CMD_VEL_TYPE
    --nav-action, --map-topic               LANGNAV_NAV_ACTION / _MAP_TOPIC
    --connect-timeout / --cancel-timeout / --feedback-timeout (s)   LANGNAV_*_TIMEOUT_S
    --robot-option KEY=VALUE (repeatable)   LANGNAV_ROBOT_OPTIONS="KEY=VALUE KEY=VALUE"

Each named option sets one field of the backend's configuration (``RosbridgeConfig`` for
rosbridge; the ros2 backend's config for ros2, which refuses a field it does not have);
``--robot-option`` sets any other field. The simulator takes none of the named ones
(``--robot-option`` reaches its own options).
"""

from __future__ import annotations

import argparse
import logging
import os
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any, Final
from urllib.parse import urlsplit

import yaml

from langnav.cli.options import seconds_arg
from langnav.robot.errors import RobotError

log = logging.getLogger(__name__)

#: sim runs anywhere; rosbridge reaches a robot over WebSocket; ros2 needs ROS 2 (rclpy) on this machine.
BACKENDS: Final = ("sim", "rosbridge", "ros2")
DEFAULT_BACKEND: Final = "sim"
ENV_BACKEND: Final = "LANGNAV_BACKEND"
ENV_ROSBRIDGE_URL: Final = "LANGNAV_ROSBRIDGE_URL"
ENV_ROBOT_OPTIONS: Final = "LANGNAV_ROBOT_OPTIONS"
#: rosbridge_server's default port, for a URL without one.
ROSBRIDGE_DEFAULT_PORT: Final = 9090
#: The cmd_vel message types a base takes (Nav2's enable_stamped_cmd_vel chooses between them).
CMD_VEL_TYPES: Final = {"twist": False, "twiststamped": True}


def cmd_vel_type_arg(text: str) -> bool:
    """``Twist`` or ``TwistStamped`` (also ``geometry_msgs/msg/...``) -> stamped?"""
    key = text.strip().rsplit("/", 1)[-1].lower()
    if key not in CMD_VEL_TYPES:
        raise argparse.ArgumentTypeError(f"the cmd_vel type is Twist or TwistStamped, got {text!r}")
    return CMD_VEL_TYPES[key]


def robot_option_arg(text: str) -> tuple[str, Any]:
    """``KEY=VALUE``; the value is read as YAML (``true``, ``0.5``, ``/robot1``)."""
    key, sep, value = text.partition("=")
    if not sep or not key.strip():
        raise argparse.ArgumentTypeError(f"a robot option is KEY=VALUE, got {text!r}")
    return key.strip(), yaml.safe_load(value)


@dataclass(frozen=True)
class RobotOption:
    """One option: its flag, its environment variable, the backend config field it sets."""

    flag: str
    env: str
    key: str
    help: str
    parse: Callable[[str], Any] = str
    metavar: str | None = None

    @property
    def dest(self) -> str:
        return "robot_" + self.flag.lstrip("-").replace("-", "_")


ROBOT_OPTIONS: Final = (
    RobotOption("--namespace", "LANGNAV_ROBOT_NAMESPACE", "namespace",
                "prefix of every topic, action and service (a namespaced TurtleBot 4: /robot1)", metavar="NS"),
    RobotOption("--map-frame", "LANGNAV_MAP_FRAME", "map_frame", "the map frame (default map)", metavar="FRAME"),
    RobotOption("--odom-frame", "LANGNAV_ODOM_FRAME", "odom_frame", "the odometry frame (default odom)",
                metavar="FRAME"),
    RobotOption("--base-frame", "LANGNAV_BASE_FRAME", "base_frame",
                "the robot's base frame (default base_link; base_footprint on some robots)", metavar="FRAME"),
    RobotOption("--cmd-vel-topic", "LANGNAV_CMD_VEL_TOPIC", "cmd_vel_topic",
                "where Move/Rotate and the stop publish velocity (default /cmd_vel)", metavar="TOPIC"),
    RobotOption("--cmd-vel-type", "LANGNAV_CMD_VEL_TYPE", "cmd_vel_stamped",
                "Twist (Jazzy's Nav2 default, Create 3) or TwistStamped (Kilted; check with "
                "`ros2 topic info -v /cmd_vel`)", parse=cmd_vel_type_arg, metavar="Twist|TwistStamped"),
    RobotOption("--nav-action", "LANGNAV_NAV_ACTION", "nav_action",
                "Nav2's NavigateThroughPoses action (default /navigate_through_poses)", metavar="ACTION"),
    RobotOption("--map-topic", "LANGNAV_MAP_TOPIC", "map_topic", "the map topic (default /map)", metavar="TOPIC"),
    RobotOption("--connect-timeout", "LANGNAV_CONNECT_TIMEOUT_S", "connect_timeout_s",
                "give up connecting after this many seconds (default 10)", parse=seconds_arg, metavar="S"),
    RobotOption("--cancel-timeout", "LANGNAV_CANCEL_TIMEOUT_S", "cancel_timeout_s",
                "after STOP, hold zero velocity this long at most while waiting for the robot to confirm "
                "the cancel, then report that it may still be moving (default 2)", parse=seconds_arg, metavar="S"),
    RobotOption("--feedback-timeout", "LANGNAV_FEEDBACK_TIMEOUT_S", "feedback_timeout_s",
                "fail a navigation that sent no feedback for this long (default 10)", parse=seconds_arg,
                metavar="S"),
)


def add_robot_arguments(p: argparse.ArgumentParser) -> None:
    """The robot options, in their own ``--help`` section."""
    g = p.add_argument_group("robot", "which robot and how to reach it; every option can also come from the "
                             "environment variable named in brackets (a flag wins)")
    g.add_argument("--backend", default=None, choices=BACKENDS,
                   help=f"robot backend (default {DEFAULT_BACKEND}) [{ENV_BACKEND}]")
    g.add_argument("--rosbridge-url", default=None, metavar="ws://HOST:PORT",
                   help=f"rosbridge server of the robot (rosbridge backend; default ws://127.0.0.1:"
                        f"{ROSBRIDGE_DEFAULT_PORT}) [{ENV_ROSBRIDGE_URL}]")
    for opt in ROBOT_OPTIONS:
        g.add_argument(opt.flag, dest=opt.dest, type=opt.parse, default=None, metavar=opt.metavar,
                       help=f"{opt.help} [{opt.env}]")
    g.add_argument("--robot-option", dest="robot_option", type=robot_option_arg, action="append", default=[],
                   metavar="KEY=VALUE", help=f"any other field of the backend's config (repeatable), e.g. "
                   f"goal_format=goals [{ENV_ROBOT_OPTIONS}, space-separated]")


def rosbridge_address(url: str) -> tuple[str, int, bool]:
    """``ws://HOST[:PORT]`` or ``wss://...`` -> (host, port, secure); the port defaults to 9090."""
    parts = urlsplit(url.strip())
    if parts.scheme not in ("ws", "wss") or not parts.hostname or parts.path not in ("", "/"):
        raise RobotError(f"--rosbridge-url is ws://HOST:PORT (or wss://), e.g. ws://192.168.1.42:9090; got {url!r}")
    try:
        port = parts.port or ROSBRIDGE_DEFAULT_PORT
    except ValueError:
        raise RobotError(f"--rosbridge-url has a bad port: {url!r}") from None
    return parts.hostname, port, parts.scheme == "wss"


def robot_options(args: argparse.Namespace, environ: Mapping[str, str] | None = None) -> tuple[str, dict[str, Any]]:
    """(backend name, its config options) from the flags, then the environment. Options given as
    flags to the simulator are refused; from the environment they are ignored (the variables may
    be set for a real robot while someone tries the simulator)."""
    env = os.environ if environ is None else environ
    # getattr: a Namespace built by hand (a test, another tool) may leave the robot options out
    backend = getattr(args, "backend", None) or env.get(ENV_BACKEND) or DEFAULT_BACKEND
    if backend not in BACKENDS:
        raise RobotError(f"{ENV_BACKEND}={backend!r} is not a backend; choose one of: {', '.join(BACKENDS)}")
    flags: dict[str, Any] = {}
    from_env: dict[str, Any] = {}
    for opt in ROBOT_OPTIONS:
        value = getattr(args, opt.dest, None)
        if value is not None:
            flags[opt.key] = value
        elif (raw := env.get(opt.env)) is not None and raw.strip():
            try:
                from_env[opt.key] = opt.parse(raw.strip())
            except argparse.ArgumentTypeError as exc:
                raise RobotError(f"{opt.env}: {exc}") from None
    extra: dict[str, Any] = dict(getattr(args, "robot_option", None) or [])
    for item in env.get(ENV_ROBOT_OPTIONS, "").split():
        try:
            key, value = robot_option_arg(item)
        except argparse.ArgumentTypeError as exc:
            raise RobotError(f"{ENV_ROBOT_OPTIONS}: {exc}") from None
        from_env.setdefault(key, value)
    url = getattr(args, "rosbridge_url", None)
    if url is not None:
        flags["rosbridge_url"] = url
    elif env.get(ENV_ROSBRIDGE_URL, "").strip():
        from_env["rosbridge_url"] = env[ENV_ROSBRIDGE_URL]
    if backend == "sim":  # --robot-option still reaches the simulator's own options
        if flags:
            named = ", ".join(f"--{k.replace('_', '-')}" for k in sorted(flags))
            raise RobotError(f"{named}: these robot options are for --backend rosbridge or ros2, not the simulator")
        if from_env:
            log.info("ignoring robot options from the environment for the simulator: %s", ", ".join(sorted(from_env)))
        return backend, extra
    options = {**from_env, **extra, **flags}
    url = options.pop("rosbridge_url", None)
    if url is not None:
        if backend != "rosbridge":
            raise RobotError(f"--rosbridge-url ({ENV_ROSBRIDGE_URL}) is for --backend rosbridge, not {backend}")
        host, port, secure = rosbridge_address(str(url))
        options.update(host=host, port=port, secure=secure)
    return backend, options


__all__ = ["BACKENDS", "ROBOT_OPTIONS", "RobotOption", "add_robot_arguments", "cmd_vel_type_arg",
           "robot_option_arg", "robot_options", "rosbridge_address"]
