"""The ros2 backend against a real ROS 2 graph: rclpy action clients on langnav's Nav2-shaped robot
(the simulator behind RobotNode), prompts end to end, and every way a run can end."""

from __future__ import annotations

import math
import os
import subprocess
import sys
import time
from collections.abc import Callable
from typing import Any

import pytest

from langnav.plan.events import EventKind, PlanStatus
from langnav.plan.executor import PlanExecutor
from langnav.robot.errors import RobotError, RobotTimeout
from langnav.robot.protocol import TaskStatus

#: the langnav command of this venv
LANGNAV = os.path.join(os.path.dirname(sys.executable), "langnav")
#: Nav2's default xy goal tolerance: a navigation ends this close to its goal.
GOAL_TOLERANCE_M = 0.3
#: A Move ends this close to where its 3 cm steps lead (the drive tolerance is millimetres; the
#: slack covers the step rounding of "1 metre" = 33 steps and tf's lag of one period).
MOVE_TOLERANCE_M = 0.1

#: Prompts on the bundled demo world from (12.2, 1.8) facing west (180°), and where a person reading
#: the map says the robot must end: doors at (11.5, 4.1) (north wall of the east room) and (6.05,
#: 1.0) (between the two south rooms), the hallway y 4.2..5.8.
DEMO_CASES: list[tuple[str, dict[str, Any]]] = [
    ("go to the door on your right", {"circle": (11.5, 4.1, 0.75)}),
    ("go to the nearest door", {"circle": (11.5, 4.1, 0.75)}),
    ("move forward 1 meter", {"circle": (11.2, 1.8, MOVE_TOLERANCE_M)}),
    ("turn left 90 degrees, then move forward half a meter", {"circle": (12.2, 1.3, MOVE_TOLERANCE_M)}),
    ("go to the hallway", {"box": (0.2, 4.2, 14.0, 5.8)}),
    ("go through the door in front of you", {"box": (4.3, 0.2, 5.95, 1.8)}),
]


def inside(region: dict[str, Any], x: float, y: float) -> bool:
    if "circle" in region:
        cx, cy, r = region["circle"]
        return math.hypot(x - cx, y - cy) <= r
    x0, y0, x1, y1 = region["box"]
    return x0 <= x <= x1 and y0 <= y <= y1


def plan_on_robot(robot: Any, prompt: str) -> Any:
    from langnav.language.translator import get_translator
    from langnav.pipeline import Planner
    from langnav.plan.events import pose_tuple

    result = Planner(get_translator("offline")).plan(prompt, robot.get_map(), pose_tuple(robot.get_robot_pose()))
    assert result.clarification is None, result.clarification
    return result


@pytest.mark.parametrize(("prompt", "region"), DEMO_CASES, ids=[p for p, _ in DEMO_CASES])
def test_demo_prompts_move_the_robot_into_the_goal_region(prompt: str, region: dict[str, Any],
                                                           demo_robot: Callable[..., Any],
                                                           ros2_backend: Callable[..., Any]) -> None:
    sim, _node = demo_robot(speed=3.0)
    robot = ros2_backend()
    result = plan_on_robot(robot, prompt)  # grounded on the map and pose that came over ROS 2
    status = PlanExecutor(robot).run(result.items, timeout_s=240)
    p = sim.get_robot_pose()
    assert status is PlanStatus.SUCCEEDED
    assert inside(region, p.x_m, p.y_m), (p, region)
    assert sim.collisions == 0
    seen = robot.get_robot_pose(1.0)  # tf composed by langnav: map -> odom -> base_link
    assert math.hypot(seen.x_m - p.x_m, seen.y_m - p.y_m) < 0.05


def test_bench_dev_prompts_end_to_end(shared_dir: Any, closer: Callable[[Any], Any]) -> None:
    """Every dev prompt of the bench that moves the robot, through the ros2 backend (needs ../shared)."""
    import importlib.util
    from pathlib import Path

    spec = importlib.util.spec_from_file_location("bench_ros2", Path(__file__).resolve().parents[2] / "benchmarks" / "ros2.py")
    assert spec is not None and spec.loader is not None
    bench = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench)
    ok, total, misses = bench.run_bench_prompts(shared_dir / "bench", speed=4.0)
    assert total >= 20
    assert ok / total >= 0.95, misses


def test_tf_composition_and_map_come_from_the_graph(demo_robot: Callable[..., Any],
                                                    ros2_backend: Callable[..., Any]) -> None:
    sim, _ = demo_robot()
    robot = ros2_backend()
    pose = robot.get_robot_pose(2.0)
    truth = sim.get_robot_pose()
    assert (pose.x_m, pose.y_m) == pytest.approx((truth.x_m, truth.y_m), abs=0.02)
    assert math.cos(pose.yaw_rad - truth.yaw_rad) > 0.999
    grid = robot.get_map(2.0)
    world = sim.get_map()
    assert (grid.width, grid.height) == (world.width, world.height)
    assert grid.resolution_m == pytest.approx(world.resolution_m, rel=1e-6)  # float32 on the wire
    # the same cells (the simulator's map keeps learning from its scans: a few may have changed)
    assert (grid.to_ros_data() == world.to_ros_data()).mean() > 0.99
    deadline = time.monotonic() + 3.0
    while (st := robot.state()).scan is None and time.monotonic() < deadline:
        time.sleep(0.05)
    assert st.connected and st.extra["pose_known"] and st.scan is not None and len(st.scan.ranges_m) > 100


def test_cancel_ends_the_goal_canceled_and_the_robot_stops(demo_robot: Callable[..., Any],
                                                          ros2_backend: Callable[..., Any]) -> None:
    sim, _ = demo_robot(speed=1.0)
    robot = ros2_backend()
    handle = robot.navigate_through_poses([(6.5, 4.9)])
    _wait_moving(sim)
    t0 = time.monotonic()
    handle.cancel()
    result = handle.wait(5.0)
    stopped_after = _wait_stopped(sim)
    assert result.status is TaskStatus.CANCELED and "stopped" in result.message
    assert time.monotonic() - t0 < 2.0
    assert stopped_after < 1.0


def test_stop_brings_the_robot_to_zero_speed_within_a_second(demo_robot: Callable[..., Any],
                                                            ros2_backend: Callable[..., Any]) -> None:
    sim, _node = demo_robot(speed=1.0)
    robot = ros2_backend()
    handle = robot.navigate_through_poses([(6.5, 4.9)])
    _wait_moving(sim)
    t0 = time.monotonic()
    robot.stop()
    to_zero = _wait_stopped(sim)
    result = handle.wait(5.0)
    print(f"STOP -> zero speed: {to_zero:.3f} s; outcome {result.status.value} after {time.monotonic() - t0:.3f} s")
    assert to_zero < 1.0
    assert result.status is TaskStatus.CANCELED
    # it stays stopped: the goal is gone and nothing drives it
    p = sim.get_robot_pose()
    time.sleep(1.0)
    q = sim.get_robot_pose()
    assert math.hypot(q.x_m - p.x_m, q.y_m - p.y_m) < 0.01


def test_an_unconfirmed_cancel_holds_zero_velocity_then_says_so(demo_robot: Callable[..., Any],
                                                               ros2_backend: Callable[..., Any]) -> None:
    sim, _ = demo_robot(confirm_cancel=False)
    robot = ros2_backend(cancel_timeout_s=1.5)
    handle = robot.navigate_through_poses([(6.5, 4.9)])
    _wait_moving(sim)
    t0 = time.monotonic()
    robot.stop()
    result = handle.wait(5.0)
    waited = time.monotonic() - t0
    assert result.status is TaskStatus.FAILED
    assert "did not confirm the cancel within 1.5 s" in result.message and "zero velocity was held" in result.message
    assert 1.4 < waited < 3.0


def test_pause_stops_and_resume_finishes(demo_robot: Callable[..., Any], ros2_backend: Callable[..., Any]) -> None:
    sim, _ = demo_robot(speed=2.0)
    robot = ros2_backend()
    result = plan_on_robot(robot, "go to the hallway")
    run = PlanExecutor(robot).start(result.items)
    _wait_moving(sim)
    run.pause()
    assert _wait_stopped(sim) < 1.0
    time.sleep(0.5)
    assert any(e.kind is EventKind.PAUSED for e in run.events)
    run.resume()
    assert run.wait(120) is PlanStatus.SUCCEEDED
    p = sim.get_robot_pose()
    assert 4.2 <= p.y_m <= 5.8


def test_an_unreachable_goal_is_aborted_with_nav2s_reason(demo_robot: Callable[..., Any],
                                                         ros2_backend: Callable[..., Any]) -> None:
    _sim, _ = demo_robot()
    robot = ros2_backend()
    handle = robot.navigate_through_poses([(3.0, 9.9)])  # outside the building's north wall
    result = handle.wait(60.0)
    assert result.status is TaskStatus.FAILED
    assert "aborted" in result.message and "navigate_through_poses" in result.message


def test_a_new_goal_preempts_the_running_one(demo_robot: Callable[..., Any],
                                             ros2_backend: Callable[..., Any]) -> None:
    sim, _ = demo_robot(speed=3.0)
    robot = ros2_backend()
    first = robot.navigate_through_poses([(6.5, 4.9)])
    _wait_moving(sim)
    second = robot.navigate_through_poses([(11.5, 3.5)])
    r1 = first.wait(5.0)
    assert r1.status is TaskStatus.CANCELED and "preempted" in r1.message
    r2 = second.wait(120.0)
    assert r2.status is TaskStatus.SUCCEEDED
    p = sim.get_robot_pose()
    assert math.hypot(p.x_m - 11.5, p.y_m - 3.5) < GOAL_TOLERANCE_M


def test_a_robot_whose_nav2_shuts_down_ends_the_task_aborted(demo_robot: Callable[..., Any],
                                                              ros2_backend: Callable[..., Any]) -> None:
    sim, node = demo_robot()
    robot = ros2_backend()
    handle = robot.navigate_through_poses([(6.5, 4.9)])
    _wait_moving(sim)
    t0 = time.monotonic()
    node.close()  # Nav2 shuts down: it aborts its goal and leaves the graph
    result = handle.wait(10.0)
    assert result.status is TaskStatus.FAILED
    # Two right reports race here: the abort result, when it reaches the client before the server is
    # gone, or else the graph watch seeing the action server leave (the result lost with the node).
    # Either way the task fails, names the server, and does so within the watch's time.
    assert "/navigate_through_poses" in result.message
    assert "aborted" in result.message or "left the ROS graph" in result.message
    assert time.monotonic() - t0 < 5.0
    deadline = time.monotonic() + 5.0
    while robot.state().connected and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not robot.state().connected
    t1 = time.monotonic()
    robot.close()
    assert time.monotonic() - t1 < 8.0


def test_a_missing_behavior_server_is_an_error_that_names_it(demo_robot: Callable[..., Any],
                                                             ros2_backend: Callable[..., Any]) -> None:
    demo_robot(behaviors=False)
    robot = ros2_backend(behavior_server_timeout_s=1.0)
    t0 = time.monotonic()
    result = robot.rotate("left", 3).wait(10.0)
    assert result.status is TaskStatus.FAILED
    assert "/spin action server" in result.message and "behavior_server" in result.message
    assert time.monotonic() - t0 < 3.0
    t1 = time.monotonic()
    robot.close()
    assert time.monotonic() - t1 < 3.0


def test_without_nav2_creation_fails_naming_the_server_and_returns(ros2_backend: Callable[..., Any]) -> None:
    t0 = time.monotonic()
    with pytest.raises(RobotError, match=r"/navigate_through_poses action server did not appear within 1.0 s"):
        ros2_backend(connect_timeout_s=1.0)
    assert time.monotonic() - t0 < 4.0


def test_a_map_that_arrives_late_is_picked_up(demo_robot: Callable[..., Any],
                                              ros2_backend: Callable[..., Any]) -> None:
    demo_robot(map_delay_s=3.0)
    robot = ros2_backend()
    with pytest.raises(RobotTimeout, match=r"no map on /map within 0\.5 s"):
        robot.get_map(0.5)
    grid = robot.get_map(10.0)
    assert grid.width > 100


def test_forty_connect_disconnect_cycles(demo_robot: Callable[..., Any]) -> None:
    from langnav.robot.ros.backend import Ros2Backend

    sim, _ = demo_robot()
    ok = 0
    t0 = time.monotonic()
    for _ in range(40):
        robot = Ros2Backend()
        try:
            pose = robot.get_robot_pose(5.0)
            grid = robot.get_map(5.0)
            ok += int(abs(pose.x_m - sim.get_robot_pose().x_m) < 0.05 and grid.width > 100)
        finally:
            robot.close()
    print(f"40 connect/disconnect cycles: {ok}/40 in {time.monotonic() - t0:.1f} s")
    assert ok == 40


def test_an_exception_in_the_watcher_ends_the_task_with_the_reason(demo_robot: Callable[..., Any],
                                                                   ros2_backend: Callable[..., Any],
                                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    demo_robot()
    robot = ros2_backend()

    def broken(*_args: Any) -> None:
        raise ValueError("a feedback the backend cannot read")

    monkeypatch.setattr(robot, "_publish_feedback", broken)
    result = robot.navigate_through_poses([(11.5, 3.5)]).wait(10.0)
    assert result.status is TaskStatus.FAILED
    assert "ValueError: a feedback the backend cannot read" in result.message


def test_langnav_run_on_ros2_exits_cleanly(demo_robot: Callable[..., Any]) -> None:
    """A motion run through the CLI ends with exit 0 and no abort from a C++ thread at exit."""
    sim, _ = demo_robot()
    proc = subprocess.run([LANGNAV, "run", "--backend", "ros2", "--json",
                           "turn left 90 degrees"], capture_output=True, text=True, timeout=120, env=os.environ)
    assert proc.returncode == 0, proc.stderr
    assert "terminate called" not in proc.stderr
    assert '"status": "succeeded"' in proc.stdout.splitlines()[-1]
    assert math.cos(sim.get_robot_pose().yaw_rad - math.radians(270)) > 0.99


def test_langnav_sim_serves_a_ros2_graph_and_a_vanished_robot_is_lost(ros2_backend: Callable[..., Any]) -> None:
    """`langnav sim --ros2` in its own process: the ros2 backend (as RViz or Foxglove would) sees and
    drives it; then the process is killed mid-goal (a robot switched off: no goodbye on the graph)."""
    proc = subprocess.Popen([LANGNAV, "sim", "--world", "demo", "--known-map", "--pose", "12.2,1.8,180",
                             "--ros2", "--no-rosbridge", "--duration", "120"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=os.environ)
    try:
        robot = ros2_backend(connect_timeout_s=30.0, feedback_timeout_s=2.0)
        pose = robot.get_robot_pose(5.0)
        assert (pose.x_m, pose.y_m) == pytest.approx((12.2, 1.8), abs=0.05)
        result = robot.move("forward", 10).wait(30.0)
        assert result.status is TaskStatus.SUCCEEDED
        moved = robot.get_robot_pose(1.0)
        assert moved.x_m == pytest.approx(12.2 - 0.3, abs=0.03)
        handle = robot.navigate_through_poses([(6.5, 4.9)])
        deadline = time.monotonic() + 10.0
        while handle.feedback() is None:
            assert time.monotonic() < deadline, "no navigation feedback"
            time.sleep(0.05)
        t0 = time.monotonic()
        proc.kill()
        result = handle.wait(10.0)
        assert result.status is TaskStatus.FAILED
        assert "no feedback from /navigate_through_poses for 2.0 s: lost the robot" in result.message
        assert time.monotonic() - t0 < 4.0
        t1 = time.monotonic()
        robot.close()
        assert time.monotonic() - t1 < 8.0
    finally:
        proc.kill()
        _out, err = proc.communicate(timeout=20)
    assert "terminate called" not in err


def _wait_moving(sim: Any, timeout_s: float = 10.0) -> None:
    deadline = time.monotonic() + timeout_s
    while abs(sim.linear_mps) < 0.05:
        assert time.monotonic() < deadline, "the robot did not start moving"
        time.sleep(0.02)


def _wait_stopped(sim: Any, timeout_s: float = 5.0) -> float:
    t0 = time.monotonic()
    while abs(sim.linear_mps) > 1e-6 or abs(sim.angular_radps) > 1e-6:
        assert time.monotonic() - t0 < timeout_s, "the robot did not stop"
        time.sleep(0.005)
    return time.monotonic() - t0
