"""One definition of the robot options for `langnav run` and `langnav serve`: flags, or LANGNAV_*
environment variables (the flag wins), all shown in --help."""

from __future__ import annotations

import argparse
from collections.abc import Iterator
from typing import Any

import pytest

from langnav.cli import build_parser, main
from langnav.cli.robot_options import ROBOT_OPTIONS, add_robot_arguments, robot_options
from langnav.robot.errors import RobotError
from langnav.robot.protocol import create_backend
from langnav.robot.ros.rosbridge_server import RosbridgeServer


def _parse(*argv: str) -> argparse.Namespace:
    p = argparse.ArgumentParser()
    add_robot_arguments(p)
    return p.parse_args(list(argv))


def test_flags_set_the_backend_config_fields() -> None:
    backend, options = robot_options(_parse(
        "--backend", "rosbridge", "--rosbridge-url", "wss://robot.local:9443", "--namespace", "/robot1",
        "--map-frame", "map2", "--odom-frame", "odom2", "--base-frame", "base_footprint",
        "--cmd-vel-topic", "/cmd_vel_nav", "--cmd-vel-type", "geometry_msgs/msg/TwistStamped",
        "--nav-action", "/nav/through", "--map-topic", "/slam/map", "--connect-timeout", "3",
        "--cancel-timeout", "1.5", "--feedback-timeout", "20", "--robot-option", "goal_format=goals"), {})
    assert backend == "rosbridge"
    assert options == {"host": "robot.local", "port": 9443, "secure": True, "namespace": "/robot1",
                       "map_frame": "map2", "odom_frame": "odom2", "base_frame": "base_footprint",
                       "cmd_vel_topic": "/cmd_vel_nav", "cmd_vel_stamped": True, "nav_action": "/nav/through",
                       "map_topic": "/slam/map", "connect_timeout_s": 3.0, "cancel_timeout_s": 1.5,
                       "feedback_timeout_s": 20.0, "goal_format": "goals"}


def test_environment_variables_set_them_too_and_a_flag_wins() -> None:
    env = {"LANGNAV_BACKEND": "rosbridge", "LANGNAV_ROSBRIDGE_URL": "ws://10.0.0.7", "LANGNAV_ROBOT_NAMESPACE": "/r2",
           "LANGNAV_CMD_VEL_TYPE": "Twist", "LANGNAV_BASE_FRAME": "base_footprint",
           "LANGNAV_CANCEL_TIMEOUT_S": "3", "LANGNAV_ROBOT_OPTIONS": "goal_format=goals linear_speed_mps=0.1"}
    backend, options = robot_options(_parse("--base-frame", "base_link"), env)
    assert backend == "rosbridge"
    assert options == {"host": "10.0.0.7", "port": 9090, "secure": False, "namespace": "/r2", "cmd_vel_stamped": False,
                       "base_frame": "base_link", "cancel_timeout_s": 3.0, "goal_format": "goals",
                       "linear_speed_mps": 0.1}


def test_bad_values_and_misplaced_options_are_clear_errors() -> None:
    with pytest.raises(SystemExit):
        _parse("--cmd-vel-type", "Twist3D")
    with pytest.raises(RobotError, match="LANGNAV_CMD_VEL_TYPE: the cmd_vel type is Twist or TwistStamped"):
        robot_options(_parse("--backend", "rosbridge"), {"LANGNAV_CMD_VEL_TYPE": "twisty"})
    with pytest.raises(RobotError, match="--namespace: these robot options are for --backend rosbridge or ros2"):
        robot_options(_parse("--namespace", "/r1"), {})
    with pytest.raises(RobotError, match="is for --backend rosbridge, not ros2"):
        robot_options(_parse("--backend", "ros2"), {"LANGNAV_ROSBRIDGE_URL": "ws://x:9090"})
    with pytest.raises(RobotError, match="LANGNAV_BACKEND='rosbrige' is not a backend"):
        robot_options(_parse(), {"LANGNAV_BACKEND": "rosbrige"})
    # set in the environment for a real robot, while someone tries the simulator: ignored
    assert robot_options(_parse(), {"LANGNAV_ROBOT_NAMESPACE": "/r1"}) == ("sim", {})


@pytest.mark.parametrize("command", ["run", "serve"])
def test_run_and_serve_take_and_document_every_robot_option(command: str) -> None:
    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    text = sub.choices[command].format_help()
    for flag, env in [("--backend", "LANGNAV_BACKEND"), ("--rosbridge-url", "LANGNAV_ROSBRIDGE_URL"),
                      ("--robot-option", "LANGNAV_ROBOT_OPTIONS"), *((o.flag, o.env) for o in ROBOT_OPTIONS)]:
        assert flag in text and env in text, (flag, env)


def test_serve_passes_the_robot_options_to_the_web_app(monkeypatch: pytest.MonkeyPatch) -> None:
    from langnav.cli.serve import settings_from_args

    monkeypatch.setenv("LANGNAV_ROBOT_NAMESPACE", "/robot1")
    args = build_parser().parse_args(["serve", "--backend", "rosbridge", "--rosbridge-url", "ws://192.168.1.42:9091",
                                      "--cmd-vel-type", "TwistStamped"])
    settings = settings_from_args(args)
    assert settings.backend == "rosbridge"
    assert settings.backend_options == {"host": "192.168.1.42", "port": 9091, "secure": False,
                                        "namespace": "/robot1", "cmd_vel_stamped": True}


@pytest.fixture
def served_sim() -> Iterator[int]:
    sim: Any = create_backend("sim", world="demo", pose=(12.2, 1.8, 0.0), known_map=True)
    server = RosbridgeServer(sim)
    sim.start(realtime=True, speed=4.0)
    yield server.start("127.0.0.1", 0)
    server.close()
    sim.close()


def test_run_reaches_the_robot_named_by_the_environment(served_sim: int, monkeypatch: pytest.MonkeyPatch,
                                                        capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.setenv("LANGNAV_BACKEND", "rosbridge")
    monkeypatch.setenv("LANGNAV_ROSBRIDGE_URL", f"ws://127.0.0.1:{served_sim}")
    assert main(["run", "--json", "--timeout", "60", "where am I"]) == 0
    assert '"status": "succeeded"' in capsys.readouterr().out
    # an option the backend does not have is a one-line error, not a traceback
    monkeypatch.setenv("LANGNAV_ROBOT_OPTIONS", "odom_frme=odom")
    assert main(["run", "where am I"]) == 2
    assert "invalid rosbridge option(s): odom_frme: Extra inputs are not permitted" in capsys.readouterr().err


def test_run_says_loudly_when_a_stop_was_not_confirmed(capsys: pytest.CaptureFixture[str]) -> None:
    from langnav.cli.run import _confirm_stop, _Printer
    from langnav.robot.protocol import StopConfirmable

    class Unconfirmed:
        def wait_stopped(self, timeout_s: float | None = None) -> None:
            raise RobotError("THE ROBOT MAY STILL BE MOVING: stop it at the robot")

    robot: Any = Unconfirmed()
    assert isinstance(robot, StopConfirmable)
    _confirm_stop(_Printer(as_json=False), robot)
    assert capsys.readouterr().out == "WARNING: THE ROBOT MAY STILL BE MOVING: stop it at the robot\n"
    _confirm_stop(_Printer(as_json=True), robot)
    assert '"event": "stop_unconfirmed"' in capsys.readouterr().out
