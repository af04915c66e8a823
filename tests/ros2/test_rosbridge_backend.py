"""The rosbridge backend through a real rosbridge (rosbridge-server-rs on the same ROS 2 graph as
langnav's Nav2-shaped robot): the dev prompts that move the robot, cancel, STOP, pause, abort,
preempt, a lost connection, a map that arrives late and 40 connect / disconnect cycles.

Printed figures (``make test-ros2`` with ``-s``): STOP -> zero speed, reconnects, prompts in the
goal region.
"""

from __future__ import annotations

import math
import os
import signal
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from langnav.plan.events import PlanStatus
from langnav.plan.executor import PlanExecutor
from langnav.robot.protocol import TaskStatus

#: A far goal on the demo floor from the east room: the robot is still driving when it is stopped.
FAR = [(6.5, 4.9)]
#: Connect / disconnect cycles (issue 10: the old queue_length wedged rosbridge within 18).
CYCLES = 40


def _backend(port: int, closer: Callable[[Any], Any], **options: Any) -> Any:
    from langnav.robot.ros.rosbridge_backend import RosbridgeBackend

    options.setdefault("connect_timeout_s", 20.0)
    robot = closer(RosbridgeBackend(host="127.0.0.1", port=port, **options))
    robot.get_robot_pose(20.0)  # the robot is on the graph and rosbridge sees it
    return robot


def _wait_moving(sim: Any, handle: Any = None, timeout_s: float = 20.0) -> None:
    deadline = time.monotonic() + timeout_s
    while abs(sim.state().linear_mps) < 0.05:
        assert handle is None or handle.status() is TaskStatus.RUNNING, handle.wait(0.0)
        assert time.monotonic() < deadline, "the robot did not start moving"
        time.sleep(0.02)


def _time_to_still(sim: Any, t0: float, timeout_s: float = 5.0) -> float:
    while abs(sim.state().linear_mps) > 1e-6 or abs(sim.state().angular_radps) > 1e-6:
        assert time.monotonic() - t0 < timeout_s, "the robot did not stop"
        time.sleep(0.005)
    return time.monotonic() - t0


def _rosbridge_pid(port: int) -> int:
    """The rosbridge-server-rs process serving ``port`` (a child of this test run)."""
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            cmd = (entry / "cmdline").read_bytes().split(b"\0")
        except OSError:
            continue
        if any(b"rosbridge_server_rs" in c for c in cmd[:1]) and f"127.0.0.1:{port}".encode() in cmd:
            return int(entry.name)
    raise AssertionError(f"no rosbridge-server-rs process on port {port}")


def test_cancel_is_read_as_canceled_and_the_robot_stops(demo_robot: Callable[..., Any], rosbridge_rs: int,
                                                        closer: Callable[[Any], Any]) -> None:
    sim, _ = demo_robot(speed=1.0)
    robot = _backend(rosbridge_rs, closer)
    handle = robot.navigate_through_poses(FAR)
    _wait_moving(sim, handle)
    t0 = time.monotonic()
    handle.cancel()
    result = handle.wait(5.0)
    still = _time_to_still(sim, t0)
    print(f"\nrosbridge-server-rs: cancel -> {result.status.value} in {time.monotonic() - t0:.3f} s, "
          f"zero speed after {still:.3f} s")
    # rosbridge-server-rs answers "status 5, result false": a cancel, not a failure
    assert result.status is TaskStatus.CANCELED, result.message
    robot.wait_stopped()  # confirmed


@pytest.mark.parametrize("trial", range(3))
def test_stop_brings_the_robot_to_zero_speed(trial: int, demo_robot: Callable[..., Any], rosbridge_rs: int,
                                             closer: Callable[[Any], Any]) -> None:
    sim, _ = demo_robot(speed=1.0)  # real time: the figure is in seconds of robot time
    robot = _backend(rosbridge_rs, closer)
    handle = robot.navigate_through_poses(FAR)
    _wait_moving(sim, handle)
    t0 = time.monotonic()
    robot.stop()
    still = _time_to_still(sim, t0)
    robot.wait_stopped()
    print(f"\nrosbridge-server-rs: STOP -> zero speed {still:.3f} s (trial {trial + 1})")
    assert still < 1.0
    assert handle.wait(2.0).status is TaskStatus.CANCELED
    p = sim.get_robot_pose()
    time.sleep(1.0)  # and it stays put: nothing drives it on
    q = sim.get_robot_pose()
    assert math.hypot(q.x_m - p.x_m, q.y_m - p.y_m) < 0.01


def test_pause_stops_the_robot_and_resume_reaches_the_goal(demo_robot: Callable[..., Any], rosbridge_rs: int,
                                                           closer: Callable[[Any], Any]) -> None:
    from langnav.plan.commands import NavigateThroughPoses

    sim, _ = demo_robot(speed=2.0)
    robot = _backend(rosbridge_rs, closer)
    run = PlanExecutor(robot).start([NavigateThroughPoses(poses=[list(FAR[0])])])
    _wait_moving(sim)
    t0 = time.monotonic()
    run.pause()
    still = _time_to_still(sim, t0)
    robot.wait_stopped()
    print(f"\nrosbridge-server-rs: pause -> zero speed {still:.3f} s")
    p = sim.get_robot_pose()
    time.sleep(1.0)
    q = sim.get_robot_pose()
    assert math.hypot(q.x_m - p.x_m, q.y_m - p.y_m) < 0.01
    run.resume()
    assert run.wait(180.0) is PlanStatus.SUCCEEDED
    end = sim.get_robot_pose()
    assert math.hypot(end.x_m - FAR[0][0], end.y_m - FAR[0][1]) < 0.3


def test_an_aborted_goal_is_read_as_nav2s_abort(demo_robot: Callable[..., Any], rosbridge_rs: int,
                                                 closer: Callable[[Any], Any]) -> None:
    demo_robot(speed=2.0)
    robot = _backend(rosbridge_rs, closer)
    result = robot.navigate_through_poses([(500.0, 500.0)]).wait(30.0)  # far outside the map
    # rosbridge-server-rs: "status 6, result false", values {"error_code": 9000} (the tier's Jazzy
    # NavigateThroughPoses result has no error_msg): read as Nav2's abort, with its code
    assert result.status is TaskStatus.FAILED
    assert result.message.startswith("Nav2 aborted the goal (status 6, error_code 9000)"), result.message


def test_a_new_goal_preempts_the_running_one(demo_robot: Callable[..., Any], rosbridge_rs: int,
                                             closer: Callable[[Any], Any]) -> None:
    sim, _ = demo_robot(speed=2.0)
    robot = _backend(rosbridge_rs, closer)
    first = robot.navigate_through_poses(FAR)
    _wait_moving(sim, first)
    second = robot.navigate_through_poses([(11.5, 4.1)])
    ended = first.wait(10.0)
    assert ended.status in (TaskStatus.FAILED, TaskStatus.CANCELED), ended
    assert second.wait(120.0).status is TaskStatus.SUCCEEDED
    p = sim.get_robot_pose()
    assert math.hypot(p.x_m - 11.5, p.y_m - 4.1) < 0.3


def test_a_lost_connection_fails_the_task_with_a_reason(demo_robot: Callable[..., Any], rosbridge_rs: int,
                                                        closer: Callable[[Any], Any]) -> None:
    sim, _ = demo_robot(speed=1.0)
    robot = _backend(rosbridge_rs, closer, close_timeout_s=2.0)
    handle = robot.navigate_through_poses(FAR)
    _wait_moving(sim, handle)
    os.kill(_rosbridge_pid(rosbridge_rs), signal.SIGKILL)
    result = handle.wait(10.0)
    assert result.status is TaskStatus.FAILED and "lost the rosbridge connection" in result.message
    assert not robot.state().connected


def test_a_map_that_arrives_after_langnav_subscribed_is_still_received(
        demo_robot: Callable[..., Any], rosbridge_rs: int, closer: Callable[[Any], Any]) -> None:
    from langnav.robot.ros.rosbridge_backend import RosbridgeBackend

    # subscribed before there is any /map publisher
    robot = closer(RosbridgeBackend(host="127.0.0.1", port=rosbridge_rs, connect_timeout_s=20.0))
    time.sleep(1.0)
    sim, _ = demo_robot(speed=1.0)  # the robot (and its transient-local /map) comes up now
    t0 = time.monotonic()
    grid = robot.get_map(20.0)
    print(f"\nrosbridge-server-rs: map arrived {time.monotonic() - t0:.2f} s after the robot came up")
    world = sim.get_map()
    assert (grid.width, grid.height) == (world.width, world.height)


def test_forty_connect_disconnect_cycles(demo_robot: Callable[..., Any], rosbridge_rs: int) -> None:
    from langnav.robot.ros.rosbridge_backend import RosbridgeBackend

    sim, _ = demo_robot(speed=1.0)
    truth = sim.get_robot_pose()
    ok = 0
    t0 = time.monotonic()
    for _ in range(CYCLES):
        robot = RosbridgeBackend(host="127.0.0.1", port=rosbridge_rs, connect_timeout_s=10.0)
        try:
            pose = robot.get_robot_pose(10.0)
            robot.get_map(10.0)
            ok += math.hypot(pose.x_m - truth.x_m, pose.y_m - truth.y_m) < 0.05
        finally:
            robot.close()
    print(f"\nrosbridge-server-rs: {ok}/{CYCLES} connect / pose / map / disconnect cycles in "
          f"{time.monotonic() - t0:.1f} s")
    assert ok == CYCLES


def test_bench_dev_prompts_through_rosbridge(shared_dir: Path, rosbridge_rs: int) -> None:
    """Every dev prompt of the bench that moves the robot, through rosbridge-server-rs (../shared)."""
    import importlib.util

    from langnav.robot.ros.rosbridge_backend import RosbridgeBackend

    spec = importlib.util.spec_from_file_location("bench_ros2", Path(__file__).resolve().parents[2] / "benchmarks" / "ros2.py")
    assert spec is not None and spec.loader is not None
    bench = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench)
    ok, total, misses = bench.run_bench_prompts(
        shared_dir / "bench", speed=4.0,
        connect=lambda: RosbridgeBackend(host="127.0.0.1", port=rosbridge_rs, connect_timeout_s=20.0))
    print(f"\nrosbridge-server-rs: {ok}/{total} dev prompts that move the robot ended in the goal region")
    assert total >= 20
    assert ok / total >= 0.95, misses
