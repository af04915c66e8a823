"""The rosbridge backend through a real rosbridge (rosbridge-server-rs, on the same ROS 2 graph as
the Nav2-shaped robot): what travels over it, end to end."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from langnav.plan.events import PlanStatus
from langnav.plan.executor import PlanExecutor
from langnav.robot.protocol import TaskStatus


def _backend(port: int, closer: Callable[[Any], Any]) -> Any:
    from langnav.robot.ros.rosbridge_backend import RosbridgeBackend, RosbridgeConfig

    return closer(RosbridgeBackend(RosbridgeConfig(host="127.0.0.1", port=port, connect_timeout_s=20.0)))


def test_a_prompt_runs_end_to_end_through_rosbridge_rs(demo_robot: Callable[..., Any], rosbridge_rs: int,
                                                       closer: Callable[[Any], Any]) -> None:
    from langnav.language.translator import get_translator
    from langnav.pipeline import Planner
    from langnav.plan.events import pose_tuple

    sim, _ = demo_robot(speed=2.0)
    robot = _backend(rosbridge_rs, closer)
    grid = robot.get_map(20.0)
    pose = robot.get_robot_pose(10.0)
    truth = sim.get_robot_pose()
    assert math.hypot(pose.x_m - truth.x_m, pose.y_m - truth.y_m) < 0.05
    plan = Planner(get_translator("offline")).plan("go to the nearest door", grid, pose_tuple(pose))
    assert plan.clarification is None
    assert PlanExecutor(robot).run(plan.items, timeout_s=180) is PlanStatus.SUCCEEDED
    p = sim.get_robot_pose()
    assert math.hypot(p.x_m - 11.5, p.y_m - 4.1) <= 0.75


def test_rotate_by_cmd_vel_through_rosbridge_rs(demo_robot: Callable[..., Any], rosbridge_rs: int,
                                                closer: Callable[[Any], Any]) -> None:
    sim, _ = demo_robot(speed=1.0)
    robot = _backend(rosbridge_rs, closer)
    robot.get_robot_pose(10.0)
    result = robot.rotate("left", 9).wait(60.0)
    assert result.status is TaskStatus.SUCCEEDED
    assert math.cos(sim.get_robot_pose().yaw_rad - math.radians(270)) > 0.995
