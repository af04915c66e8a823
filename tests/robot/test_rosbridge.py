"""End to end on loopback: the rosbridge v2 server (backed by the simulator) driven by the
``rosbridge`` backend through roslibpy, plus the faults: a dropped link, malformed messages from
the robot, and timeouts.

roslibpy's transport loop (twisted reactor) starts once per process and is never terminated here:
each backend closes only its own connection, so any number of them can come and go.
"""

from __future__ import annotations

import json
import logging
import math
import threading
import time
from collections.abc import Callable, Iterator
from typing import Any

import pytest
from fake_rosbridge import RawRosbridge
from websockets.asyncio.server import ServerConnection
from websockets.sync.client import connect

from langnav.maps.draw import MapBuilder
from langnav.maps.grid import OccupancyGrid
from langnav.robot.errors import RobotError, RobotTimeout
from langnav.robot.protocol import (
    Pose2D,
    RobotBackend,
    RobotState,
    TaskHandle,
    TaskStatus,
    create_backend,
)
from langnav.robot.ros import messages as rm
from langnav.robot.ros.rosbridge_backend import RosbridgeBackend
from langnav.robot.ros.rosbridge_server import RosbridgeServer, RosbridgeServerConfig

#: The simulated clock runs this many times faster than the wall clock in these tests.
SIM_SPEED = 4.0
START = (1.5, 3.0, 0.0)
GOAL = (6.0, 3.0)


def _world() -> OccupancyGrid:
    return MapBuilder(8, 6).room(0.5, 0.5, 7.5, 5.5).box(3.5, 2.0, 4.0, 4.0).build("test room")


def _until(cond: Callable[[], bool], timeout_s: float, what: str) -> None:
    deadline = time.monotonic() + timeout_s
    while not cond():
        if time.monotonic() > deadline:
            raise AssertionError(f"timed out after {timeout_s} s waiting for {what}")
        time.sleep(0.02)


class Served:
    def __init__(self, backend: RobotBackend, **server_options: Any) -> None:
        self.robot = backend
        self.server = RosbridgeServer(backend, RosbridgeServerConfig(**server_options))
        self.port = self.server.start("127.0.0.1", 0)

    def client(self, **options: Any) -> RosbridgeBackend:
        options.setdefault("connect_timeout_s", 5.0)
        return RosbridgeBackend(host="127.0.0.1", port=self.port, **options)

    def close(self) -> None:
        self.server.close()
        self.robot.close()


def _sim() -> Any:
    sim = create_backend("sim", world=_world(), pose=START, known_map=True)
    sim.start(realtime=True, speed=SIM_SPEED)  # type: ignore[attr-defined]
    return sim


@pytest.fixture(scope="module")
def sim_served() -> Iterator[tuple[Served, RosbridgeBackend]]:
    served = Served(_sim())
    robot = served.client()
    yield served, robot
    robot.close()
    served.close()


@pytest.fixture
def fresh_served() -> Iterator[Served]:
    served = Served(_sim())
    yield served
    served.close()


# -- the happy path ----------------------------------------------------------------------------
def test_pose_map_and_navigation_with_feedback_and_plan(sim_served: tuple[Served, RosbridgeBackend]) -> None:
    served, robot = sim_served
    pose = robot.get_robot_pose(timeout_s=3.0)
    truth = served.robot.get_robot_pose()
    assert (pose.x_m, pose.y_m) == (pytest.approx(truth.x_m, abs=0.05), pytest.approx(truth.y_m, abs=0.05))

    grid = robot.get_map(timeout_s=3.0)
    sim_grid = served.robot.get_map()
    assert grid.cells.shape == sim_grid.cells.shape
    assert (grid.cells == sim_grid.cells).mean() > 0.99
    assert (grid.origin_x_m, grid.resolution_m) == (sim_grid.origin_x_m, sim_grid.resolution_m)

    handle = robot.navigate_through_poses([GOAL])
    distances: list[float] = []
    paths: list[list[tuple[float, float]]] = []
    deadline = time.monotonic() + 20.0
    while handle.status() is TaskStatus.RUNNING and time.monotonic() < deadline:
        fb = handle.feedback()
        if fb is not None and fb.distance_remaining_m is not None:
            distances.append(fb.distance_remaining_m)
        paths.append(robot.get_current_path())
        time.sleep(0.1)
    result = handle.wait(timeout_s=5.0)
    assert result.status is TaskStatus.SUCCEEDED, result.message
    end = robot.get_robot_pose()
    assert math.hypot(end.x_m - GOAL[0], end.y_m - GOAL[1]) < 0.3
    # feedback streamed and the distance shrank; the planned path led to the goal around the box
    assert len(distances) >= 3 and distances[-1] < distances[0] - 2.0
    longest = max(paths, key=len)
    assert len(longest) >= 2
    assert math.hypot(longest[-1][0] - GOAL[0], longest[-1][1] - GOAL[1]) < 0.3
    assert any(not (2.0 <= y <= 4.0) for x, y in longest if 3.3 <= x <= 4.2)  # it goes around the box


def test_cancel_mid_goal_stops_the_robot(sim_served: tuple[Served, RosbridgeBackend]) -> None:
    served, robot = sim_served
    handle = robot.navigate_through_poses([(1.5, 1.5), (6.5, 1.2)])
    _until(lambda: handle.feedback() is not None, 5.0, "first feedback")
    handle.cancel()
    result = handle.wait(timeout_s=5.0)
    assert result.status is TaskStatus.CANCELED
    _until(lambda: not served.robot.state().busy, 3.0, "the simulated robot to idle")
    time.sleep(0.3)
    state = served.robot.state()
    assert abs(state.linear_mps) < 1e-9 and abs(state.angular_radps) < 1e-9


# -- faults ------------------------------------------------------------------------------------
def test_connection_dropped_mid_goal_fails_the_handle_and_stops_the_robot(fresh_served: Served) -> None:
    robot = fresh_served.client()
    try:
        handle = robot.navigate_through_poses([GOAL])
        _until(lambda: handle.feedback() is not None, 5.0, "first feedback")
        fresh_served.server.stop()
        result = handle.wait(timeout_s=5.0)
        assert result.status is TaskStatus.FAILED
        assert "lost the rosbridge connection" in result.message
        assert not fresh_served.robot.state().busy  # the server cancelled the dropped client's goal
        with pytest.raises(RobotError, match="not connected"):
            robot.navigate_through_poses([START[:2]])
    finally:
        robot.close()


def test_unreachable_rosbridge_is_a_clear_error_within_the_timeout() -> None:
    server = RosbridgeServer(_DummyRobot())
    port = server.start()
    server.close()  # the port is now closed
    t0 = time.monotonic()
    with pytest.raises(RobotError, match=r"cannot reach rosbridge .*rosbridge_websocket_launch\.xml"):
        RosbridgeBackend(port=port, connect_timeout_s=1.0)
    assert time.monotonic() - t0 < 5.0


def test_server_answers_malformed_input_with_status_and_keeps_serving(sim_served: tuple[Served, RosbridgeBackend]) -> None:
    served, _ = sim_served
    with connect(f"ws://127.0.0.1:{served.port}", open_timeout=5) as ws:
        def ask(payload: str) -> dict[str, Any]:
            ws.send(payload)
            return json.loads(ws.recv(timeout=5))

        assert ask("{not json")["level"] == "error"
        assert "must be a JSON object" in ask("[1, 2]")["msg"]
        bogus = ask(json.dumps({"op": "bogus", "id": "b1"}))
        assert (bogus["op"], bogus["id"]) == ("status", "b1") and "unknown operation 'bogus'" in bogus["msg"]
        assert "no topic '/nope'" in ask(json.dumps({"op": "subscribe", "topic": "/nope"}))["msg"]
        wrong = ask(json.dumps({"op": "subscribe", "topic": "/map", "type": "sensor_msgs/msg/Image"}))
        assert "has type nav_msgs/msg/OccupancyGrid" in wrong["msg"]
        # topics the robot publishes cannot be written to; cmd_vel takes only Twist / TwistStamped
        refused = ask(json.dumps({"op": "publish", "topic": "/map", "msg": {}}))
        assert "/map is published by the robot" in refused["msg"]
        wrong_type = ask(json.dumps({"op": "advertise", "topic": "/cmd_vel", "type": "std_msgs/msg/String"}))
        assert "takes geometry_msgs/msg/Twist or geometry_msgs/msg/TwistStamped" in wrong_type["msg"]
        bad_goal = json.dumps({"op": "send_action_goal", "id": "g1", "action": "/navigate_through_poses",
                               "action_type": rm.NAVIGATE_THROUGH_POSES, "args": {"poses": []}})
        ws.send(bad_goal)
        replies = [json.loads(ws.recv(timeout=5)) for _ in range(2)]
        result = next(r for r in replies if r["op"] == "action_result")
        assert (result["result"], result["status"], result["id"]) == (False, rm.GOAL_STATUS_UNKNOWN, "g1")
        # still serving: a service call answers with the pose
        reply = ask(json.dumps({"op": "call_service", "id": "s1", "service": "/langnav/get_robot_pose"}))
        assert reply["op"] == "service_response" and reply["result"] is True
        pose, frame = rm.parse_pose_stamped(reply["values"]["pose"])
        assert frame == "map" and math.isfinite(pose.x_m)


# -- a robot that speaks nonsense -------------------------------------------------------------------
class _BadRobot(RawRosbridge):
    """A raw rosbridge server whose /map and NavigateThroughPoses feedback are malformed and
    which never publishes tf: the robot side of the 'malformed message' fault."""

    def __init__(self) -> None:
        self.cmd_vel: list[dict[str, Any]] = []
        super().__init__()

    async def serve_one(self, ws: ServerConnection) -> None:
        async for raw in ws:
            msg = json.loads(raw)
            if msg["op"] == "subscribe" and msg["topic"] == "/map":
                await ws.send(json.dumps({"op": "publish", "topic": "/map",
                                          "msg": {"info": {"resolution": -1, "width": 2}, "data": "oops"}}))
            elif msg["op"] == "send_action_goal":
                await ws.send(json.dumps({"op": "action_feedback", "id": msg["id"], "action": msg["action"],
                                          "values": {"current_pose": {"pose": "nowhere"}}}))
            elif msg["op"] == "publish" and msg["topic"] == "/cmd_vel":
                self.cmd_vel.append(msg["msg"])


def test_malformed_messages_from_the_robot_give_clear_errors() -> None:
    bad = _BadRobot()
    robot = RosbridgeBackend(port=bad.port, connect_timeout_s=5.0)
    try:
        with pytest.raises(RobotError, match=r"malformed /map \(nav_msgs/msg/OccupancyGrid\)"):
            robot.get_map(timeout_s=3.0)
        handle = robot.navigate_through_poses([(1.0, 2.0, 90.0)])
        result = handle.wait(timeout_s=5.0)
        assert result.status is TaskStatus.FAILED
        assert "malformed /navigate_through_poses feedback" in result.message
        assert "robot stopped" in result.message
        _until(lambda: any(m["linear"]["x"] == 0.0 for m in bad.cmd_vel), 3.0, "a zero cmd_vel")
        t0 = time.monotonic()
        with pytest.raises(RobotTimeout, match=r"no transform map -> base_link within 0\.3 s"):
            robot.get_robot_pose(timeout_s=0.3)
        assert time.monotonic() - t0 < 2.0
        assert robot.state().connected  # the backend is still usable
    finally:
        robot.close()
        bad.close()


# -- Move / Rotate by cmd_vel, closed loop on odometry ------------------------------------------
class _DummyRobot:
    """A unicycle driven only by velocity (a base without Nav2): a test double of the Protocol."""

    name = "velocity-double"

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._pose = Pose2D(0.0, 0.0, 0.0)
        self._v = self._w = 0.0
        self._halt = threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def _run(self) -> None:
        dt = 0.01
        while not self._halt.wait(dt):
            with self._lock:
                p = self._pose
                self._pose = Pose2D(p.x_m + self._v * dt * math.cos(p.yaw_rad),
                                    p.y_m + self._v * dt * math.sin(p.yaw_rad),
                                    rm.wrap_angle(p.yaw_rad + self._w * dt))

    def set_velocity(self, linear_mps: float, angular_radps: float) -> None:
        with self._lock:
            self._v, self._w = linear_mps, angular_radps

    def navigate_through_poses(self, poses: Any) -> TaskHandle:
        raise RobotError("this base has no navigation stack")

    def move(self, direction: str, steps: int) -> TaskHandle:
        raise RobotError("drive me by velocity")

    def rotate(self, direction: str, steps: int) -> TaskHandle:
        raise RobotError("drive me by velocity")

    def stop(self) -> None:
        self.set_velocity(0.0, 0.0)

    def get_current_path(self, timeout_s: float = 5.0) -> list[tuple[float, float]]:
        return []

    def get_map(self, timeout_s: float = 5.0) -> OccupancyGrid:
        return _world()

    def get_robot_pose(self, timeout_s: float = 5.0) -> Pose2D:
        with self._lock:
            return self._pose

    def state(self) -> RobotState:
        with self._lock:
            return RobotState(pose=self._pose, linear_mps=self._v, angular_radps=self._w)

    def close(self) -> None:
        self._halt.set()
        self._thread.join(2)


@pytest.mark.parametrize("stamped", [False, True], ids=["Twist", "TwistStamped"])
def test_move_and_rotate_by_cmd_vel_closed_loop(stamped: bool) -> None:
    served = Served(_DummyRobot(), state_rate_hz=50.0)
    robot = served.client(cmd_vel_stamped=stamped, linear_speed_mps=0.3, angular_speed_radps=1.5,
                          slowdown_gain_per_s=5.0)
    try:
        start = robot.get_robot_pose(timeout_s=3.0)
        turn = robot.rotate("left", 9)
        assert turn.wait(timeout_s=10.0).status is TaskStatus.SUCCEEDED
        time.sleep(0.2)
        after_turn = served.robot.get_robot_pose()
        assert math.degrees(rm.wrap_angle(after_turn.yaw_rad - start.yaw_rad)) == pytest.approx(90.0, abs=3.0)
        move = robot.move("forward", 10)
        assert move.wait(timeout_s=10.0).status is TaskStatus.SUCCEEDED
        time.sleep(0.2)
        end = served.robot.get_robot_pose()
        assert math.hypot(end.x_m - after_turn.x_m, end.y_m - after_turn.y_m) == pytest.approx(0.30, abs=0.02)
        assert end.y_m > after_turn.y_m + 0.25  # forward after turning left is +y
        assert served.robot.state().linear_mps == 0.0
    finally:
        robot.close()
        served.close()


# -- teleop: /cmd_vel drives the simulator (Foxglove's teleop panel, roslibjs pages) -----------------
def _ask(ws: Any, payload: dict[str, Any], op: str) -> dict[str, Any]:
    """Send, then read until a reply with this ``op`` (a status error before it fails the test)."""
    ws.send(json.dumps(payload))
    deadline = time.monotonic() + 5.0
    while time.monotonic() < deadline:
        reply = json.loads(ws.recv(timeout=5))
        if reply["op"] == op:
            return reply
        assert reply["op"] != "status", reply
    raise AssertionError(f"no {op} within 5 s")


@pytest.mark.parametrize("stamped", [False, True], ids=["Twist", "TwistStamped"])
def test_cmd_vel_drives_the_simulator_then_its_timeout_stops_it(fresh_served: Served, stamped: bool) -> None:
    sim = fresh_served.robot
    msg_type = rm.TWIST_STAMPED if stamped else rm.TWIST
    start = sim.get_robot_pose()
    with connect(f"ws://127.0.0.1:{fresh_served.port}", open_timeout=5) as ws:
        ws.send(json.dumps({"op": "advertise", "topic": "/cmd_vel", "type": msg_type}))
        speeds: list[float] = []
        t_end = time.monotonic() + 1.0  # 4 s of robot time
        while time.monotonic() < t_end:  # a teleop panel publishes at 10-20 Hz while a key is held
            ws.send(json.dumps({"op": "publish", "topic": "/cmd_vel",
                                "msg": rm.cmd_vel(0.2, 0.05, stamped, "base_link")}))
            speeds.append(sim.state().linear_mps)
            time.sleep(0.05)
        # nothing refused: the next reply on the socket is the answer to this call
        reply = _ask(ws, {"op": "call_service", "id": "p", "service": "/langnav/get_robot_pose"}, "service_response")
        assert reply["result"] is True
        _until(lambda: sim.state().linear_mps == 0.0, 3.0, "the cmd_vel timeout to stop the robot")
    end = sim.get_robot_pose()
    assert max(speeds) == pytest.approx(0.2, abs=1e-6)
    assert 0.4 < end.x_m - start.x_m < 1.2  # about 0.2 m/s for 4 s of robot time, and a curve left
    assert end.y_m > start.y_m and 0.05 < end.yaw_rad - start.yaw_rad < 0.4
    assert sim.collisions == 0  # type: ignore[attr-defined]


def test_cmd_vel_cancels_a_running_navigation_goal(fresh_served: Served) -> None:
    with connect(f"ws://127.0.0.1:{fresh_served.port}", open_timeout=5) as ws:
        goal = rm.navigate_through_poses_goal([Pose2D(*GOAL, 0.0)])
        ws.send(json.dumps({"op": "send_action_goal", "id": "g", "action": "/navigate_through_poses",
                            "action_type": rm.NAVIGATE_THROUGH_POSES, "args": goal}))
        _until(lambda: fresh_served.robot.state().busy, 3.0, "the goal to start")
        ws.send(json.dumps({"op": "publish", "topic": "/cmd_vel", "msg": rm.twist(0.0, 0.5)}))
        result = _ask(ws, {"op": "call_service", "id": "noop", "service": "/rosapi/topics"}, "action_result")
    assert (result["id"], result["status"], result["result"]) == ("g", rm.GOAL_STATUS_CANCELED, True)
    assert "teleop" in result["values"]["error_msg"]


def test_close_mid_motion_stops_the_robot_and_sends_nothing_on_the_closed_socket(
        fresh_served: Served, caplog: pytest.LogCaptureFixture) -> None:
    caplog.set_level(logging.INFO)
    robot = fresh_served.client()
    turn = robot.rotate("left", 36)  # a full turn: the cmd_vel loop is publishing when close() comes
    _until(lambda: abs(fresh_served.robot.state().angular_radps) > 0.1, 5.0, "the turn to start")
    robot.close()
    assert turn.wait(timeout_s=1.0).status is TaskStatus.FAILED
    # the zero velocity was sent before the close frame; the server applies it on its own loop,
    # so wait (bounded) for the robot to be standing still rather than racing that loop
    _until(lambda: fresh_served.robot.state().extra["teleop"] is False
           and abs(fresh_served.robot.state().angular_radps) < 0.05, 2.0, "the robot to stop")
    fresh_served.server.stop()  # the robot goes away right after: nothing may still be queued for it
    time.sleep(0.5)  # anything queued on roslibpy's thread would have run (and failed) by now
    transport = [r for r in caplog.records if r.name.split(".")[0] in ("twisted", "roslibpy", "autobahn")]
    assert not [r for r in transport if r.levelno >= logging.WARNING], [r.getMessage() for r in transport]
    # the server got a close frame (roslibpy sends none with no code: 1005), not a dropped TCP connection (1006)
    assert any(r.getMessage() == "rosbridge client 1 disconnected (close code 1005)" for r in caplog.records)


# -- Foxglove: rosapi discovery, definitions, cbor-raw (CDR) subscriptions, /rosout -------------------
def test_rosapi_topics_and_raw_types_describe_every_topic(sim_served: tuple[Served, RosbridgeBackend]) -> None:
    served, _ = sim_served
    with connect(f"ws://127.0.0.1:{served.port}", open_timeout=5) as ws:
        full = _ask(ws, {"op": "call_service", "id": "t", "service": "/rosapi/topics_and_raw_types",
                         "type": "rosapi/TopicsAndRawTypes"}, "service_response")
        plain = _ask(ws, {"op": "call_service", "id": "u", "service": "/rosapi/topics"}, "service_response")
    values = full["values"]
    assert full["result"] is True and set(values) == {"topics", "types", "typedefs_full_text"}
    assert len(values["topics"]) == len(values["types"]) == len(values["typedefs_full_text"])
    assert plain["values"] == {"topics": values["topics"], "types": values["types"]}
    by_topic = dict(zip(values["topics"], values["types"], strict=True))
    assert by_topic == {"/map": rm.OCCUPANCY_GRID, "/scan": rm.LASER_SCAN, "/plan": rm.PATH, "/tf": rm.TF_MESSAGE,
                        "/tf_static": rm.TF_MESSAGE, "/odom": rm.ODOMETRY, "/amcl_pose": rm.POSE_WITH_COV_STAMPED,
                        "/rosout": "rcl_interfaces/msg/Log", "/cmd_vel": rm.TWIST}
    # Foxglove takes rcl_interfaces/msg/Log among the types as "this is ROS 2", then parses each definition
    rosbags_typesys = pytest.importorskip("rosbags.typesys")
    for type_name, text in zip(values["types"], values["typedefs_full_text"], strict=True):
        assert type_name in rosbags_typesys.get_types_from_msg(text, type_name)


def test_cbor_raw_subscription_sends_cdr_that_the_definitions_decode(sim_served: tuple[Served, RosbridgeBackend]) -> None:
    cbor2 = pytest.importorskip("cbor2")
    rosbags_typesys = pytest.importorskip("rosbags.typesys")
    served, _ = sim_served
    with connect(f"ws://127.0.0.1:{served.port}", open_timeout=5) as ws:
        defs = _ask(ws, {"op": "call_service", "id": "t", "service": "/rosapi/topics_and_raw_types"},
                    "service_response")["values"]
        store = rosbags_typesys.get_typestore(rosbags_typesys.Stores.EMPTY)
        for type_name, text in zip(defs["types"], defs["typedefs_full_text"], strict=True):
            store.register(rosbags_typesys.get_types_from_msg(text, type_name))
        for topic in ("/map", "/odom"):  # as Foxglove subscribes
            ws.send(json.dumps({"op": "subscribe", "topic": topic, "compression": "cbor-raw"}))
        got: dict[str, Any] = {}
        deadline = time.monotonic() + 5.0
        while len(got) < 2 and time.monotonic() < deadline:
            frame = ws.recv(timeout=5)
            assert isinstance(frame, bytes), frame  # binary CBOR, not JSON text
            envelope = cbor2.loads(frame)
            assert envelope["op"] == "publish" and set(envelope["msg"]) == {"secs", "nsecs", "bytes"}
            got[envelope["topic"]] = envelope["msg"]["bytes"]
    grid = store.deserialize_cdr(got["/map"], rm.OCCUPANCY_GRID)
    truth = served.robot.get_map()
    assert (grid.info.width, grid.info.height, grid.header.frame_id) == (truth.width, truth.height, "map")
    assert (grid.data == truth.to_ros_data()).mean() > 0.99  # the map keeps being refined from scans
    odom = store.deserialize_cdr(got["/odom"], rm.ODOMETRY)
    pose = served.robot.get_robot_pose()
    assert (odom.header.frame_id, odom.child_frame_id) == ("odom", "base_link")
    assert math.hypot(odom.pose.pose.position.x - pose.x_m, odom.pose.pose.position.y - pose.y_m) < 0.5


def test_rosout_carries_the_servers_log(sim_served: tuple[Served, RosbridgeBackend],
                                        caplog: pytest.LogCaptureFixture) -> None:
    caplog.set_level(logging.INFO, logger="langnav")
    served, _ = sim_served
    with connect(f"ws://127.0.0.1:{served.port}", open_timeout=5) as ws:
        ws.send(json.dumps({"op": "subscribe", "topic": "/rosout", "type": "rcl_interfaces/msg/Log"}))
        ws.send(json.dumps({"op": "bogus"}))  # the server logs the refusal
        deadline = time.monotonic() + 5.0
        while time.monotonic() < deadline:
            reply = json.loads(ws.recv(timeout=5))
            if reply["op"] == "publish" and "unknown operation 'bogus'" in reply["msg"]["msg"]:
                break
        else:
            raise AssertionError("no /rosout record of the refusal within 5 s")
    log_msg = reply["msg"]
    assert (reply["topic"], log_msg["level"], log_msg["name"]) == ("/rosout", 20, "langnav.robot.ros.rosbridge_server")
    assert log_msg["function"] == "_status" and log_msg["line"] > 0
