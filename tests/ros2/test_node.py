"""`langnav node` on a real ROS 2 graph: /langnav/instruct, /langnav/stop, /langnav/map_analysis,
used the way a ROS user would (an rclpy action client, a service call, a subscription)."""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Callable
from typing import Any

import pytest

#: How long a goal may wait to be accepted: `langnav node` reads the map and plans the prompt
#: first, which on a loaded 2-core machine took over 10 s.
ACCEPT_TIMEOUT_S = 30.0


class Client:
    """A ROS user's side: an action client for /langnav/instruct, /langnav/stop, the markers."""

    def __init__(self) -> None:
        from langnav.robot.ros.runtime import RosRuntime, import_module, interface

        action = import_module("rclpy.action")
        qos = import_module("rclpy.qos")
        self.rt = RosRuntime("test_client", threads=4)
        self.instruct_type = interface("langnav_interfaces/action/Instruct")
        self.instruct = action.ActionClient(self.rt.node, self.instruct_type, "langnav/instruct")
        self.stop = self.rt.node.create_client(interface("std_srvs/srv/Trigger"), "langnav/stop")
        self.markers: list[Any] = []
        latched = qos.QoSProfile(depth=1, durability=qos.DurabilityPolicy.TRANSIENT_LOCAL,
                                 reliability=qos.ReliabilityPolicy.RELIABLE)
        self.rt.node.create_subscription(interface("visualization_msgs/msg/MarkerArray"), "langnav/map_analysis",
                                         self.markers.append, latched)
        self.steps: list[str] = []
        assert self.instruct.wait_for_server(timeout_sec=10.0)

    def send(self, prompt: str) -> Any:
        goal = self.instruct_type.Goal()
        goal.prompt = prompt
        future = self.instruct.send_goal_async(goal, feedback_callback=lambda m: self.steps.append(m.feedback.step))
        handle = _wait(future, ACCEPT_TIMEOUT_S)
        assert handle.accepted
        return handle

    def call_stop(self) -> Any:
        assert self.stop.wait_for_service(timeout_sec=5.0)
        return _wait(self.stop.call_async(self.stop.srv_type.Request()), 10.0)

    def close(self) -> None:
        self.rt.close()


def _wait(future: Any, timeout_s: float) -> Any:
    done = threading.Event()
    future.add_done_callback(lambda _f: done.set())
    assert done.wait(timeout_s), "no answer in time"
    return future.result()


@pytest.fixture
def langnav_node(demo_robot: Callable[..., Any], ros2_backend: Callable[..., Any],
                 closer: Callable[[Any], Any]) -> tuple[Any, Any, Client]:
    from langnav.robot.ros.node import LangnavNode

    sim, _ = demo_robot(speed=3.0)
    robot = ros2_backend()
    node = closer(LangnavNode(robot, map_check_s=0.5))
    client = closer(Client())
    return sim, node, client


def test_instruct_runs_a_prompt_with_plain_word_feedback(langnav_node: tuple[Any, Any, Client]) -> None:
    sim, _, client = langnav_node
    handle = client.send("go to the nearest door")
    response = _wait(handle.get_result_async(), 180.0)
    assert response.status == 4  # SUCCEEDED
    assert response.result.outcome == "succeeded" and response.result.reply
    p = sim.get_robot_pose()
    assert math.hypot(p.x_m - 11.5, p.y_m - 4.1) <= 0.75  # the door in the east room's north wall
    assert client.steps[0] == "reading 'go to the nearest door' against the map"
    assert any(s.startswith("plan: ") and "door" in s for s in client.steps)
    assert any(s.startswith("step 1: Navigate to") for s in client.steps)
    assert any(s.startswith("step 1: succeeded") for s in client.steps)


def test_a_prompt_langnav_cannot_ground_is_refused_with_the_reason(langnav_node: tuple[Any, Any, Client]) -> None:
    sim, _, client = langnav_node
    start = sim.get_robot_pose()
    response = _wait(client.send("go to the third kitchen on the left").get_result_async(), 60.0)
    assert response.status == 6  # ABORTED: nothing ran
    assert response.result.outcome == "refused" and "kitchen" in response.result.reply.lower()
    p = sim.get_robot_pose()
    assert math.hypot(p.x_m - start.x_m, p.y_m - start.y_m) < 0.01


def test_stop_service_ends_the_instruction_and_stops_the_robot(langnav_node: tuple[Any, Any, Client]) -> None:
    sim, _, client = langnav_node
    handle = client.send("go to the hallway")
    deadline = time.monotonic() + 20.0
    while abs(sim.linear_mps) < 0.05:
        assert time.monotonic() < deadline, "the robot did not start"
        time.sleep(0.02)
    t0 = time.monotonic()
    answer = client.call_stop()
    assert answer.success and answer.message == "stopped"
    response = _wait(handle.get_result_async(), 20.0)
    assert response.result.outcome == "canceled"
    while abs(sim.linear_mps) > 1e-6 or abs(sim.angular_radps) > 1e-6:
        assert time.monotonic() - t0 < 2.0, "the robot did not stop"
        time.sleep(0.005)


def test_cancelling_the_goal_cancels_the_plan(langnav_node: tuple[Any, Any, Client]) -> None:
    sim, _, client = langnav_node
    handle = client.send("go to the hallway")
    deadline = time.monotonic() + 20.0
    while abs(sim.linear_mps) < 0.05:
        assert time.monotonic() < deadline, "the robot did not start"
        time.sleep(0.02)
    _wait(handle.cancel_goal_async(), 10.0)
    response = _wait(handle.get_result_async(), 20.0)
    assert response.status == 5  # CANCELED
    assert response.result.outcome == "canceled"


def test_the_map_analysis_is_published_as_labelled_markers(langnav_node: tuple[Any, Any, Client]) -> None:
    from langnav.robot.ros.markers import TEXT_VIEW_FACING

    _, node, client = langnav_node
    deadline = time.monotonic() + 30.0
    while not client.markers:
        assert time.monotonic() < deadline, "no MarkerArray on /langnav/map_analysis"
        time.sleep(0.1)
    markers = client.markers[-1].markers
    texts = {m.text for m in markers if m.type == TEXT_VIEW_FACING}
    assert {"room 1", "hallway 2", "room 3", "room 4", "door 1", "door 3", "passage 1"} <= texts
    assert all(m.header.frame_id == "map" for m in markers)
    door = next(m for m in markers if m.text == "door 1")
    assert (door.pose.position.x, door.pose.position.y) == pytest.approx((6.05, 1.0), abs=0.1)
    assert node.markers_published >= 1


def test_langnav_node_command_serves_the_action(demo_robot: Callable[..., Any], closer: Callable[[Any], Any]) -> None:
    """`langnav node` in its own process, driving the robot through the ros2 backend."""
    import os
    import subprocess
    import sys

    sim, _ = demo_robot(speed=2.0)
    langnav = os.path.join(os.path.dirname(sys.executable), "langnav")
    proc = subprocess.Popen([langnav, "node", "--duration", "90"], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, env=os.environ)
    try:
        client = closer(Client())
        response = _wait(client.send("turn left 90 degrees").get_result_async(), 60.0)
        assert response.result.outcome == "succeeded", response.result.reply
        assert math.cos(sim.get_robot_pose().yaw_rad - math.radians(270)) > 0.99
    finally:
        proc.terminate()
        _out, err = proc.communicate(timeout=30)
    assert "terminate called" not in err
