"""The ``ros2`` backend: rclpy and nav2_simple_commander's BasicNavigator, on a machine with ROS 2.

ROS 2 is imported only when the backend is created; without it (or without
``nav2_simple_commander``) creation raises a :class:`RobotError` that says how to install and
source it, and that ``--backend rosbridge`` works from anywhere.

* NavigateThroughPoses -> ``BasicNavigator.goThroughPoses`` (a ``nav_msgs/Goals`` on Kilted+,
  a list of PoseStamped before), feedback from ``getFeedback()``, cancel -> ``cancelTask()``.
* Move forward -> ``driveOnHeading``, backward -> ``backUp``, left / right -> spin 90°, drive,
  spin back; Rotate -> ``spin``. These are Nav2's behavior server actions (collision-checked).
* Pose from tf (``map -> base_link``), /map (transient local) and /plan from subscriptions on
  a second node spun by a background executor.

BasicNavigator is not thread-safe and spins itself inside its calls, so every call to it goes
through one lock, and a task's watcher thread polls ``isTaskComplete()``; every wait has a
timeout (the commander's own loops have none, so langnav never calls ``waitUntilNav2Active``).
"""

from __future__ import annotations

import logging
import math
import threading
import time
from typing import Any, Final

import numpy as np
from pydantic import BaseModel, ConfigDict, Field

from langnav.maps.errors import MapError
from langnav.maps.grid import OccupancyGrid, from_ros_data
from langnav.plan.commands import MOVE_STEP_M, ROTATE_STEP_DEG
from langnav.robot import ros_messages as rm
from langnav.robot.errors import RobotError, RobotTimeout
from langnav.robot.protocol import (
    DEFAULT_REQUEST_TIMEOUT_S,
    Pose2D,
    RobotState,
    TaskFeedback,
    TaskHandle,
    TaskStatus,
    register_backend,
)
from langnav.robot.task_state import ReportedTask

log = logging.getLogger(__name__)

INSTALL_HINT: Final = (
    "the ros2 backend needs ROS 2 (rclpy) and nav2_simple_commander on this machine: install ROS 2 "
    "Jazzy (https://docs.ros.org/en/jazzy/Installation.html) and `sudo apt install "
    "ros-jazzy-nav2-simple-commander ros-jazzy-tf2-ros`, then `source /opt/ros/jazzy/setup.bash` "
    "in this shell and run langnav with the Python ROS was built for (python3 of that Ubuntu, "
    "with langnav installed next to it). Or drive the robot from anywhere with --backend rosbridge "
    "(see docs/ros2.md)"
)
_POLL_S: Final = 0.05


class Ros2Config(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)

    namespace: str = ""
    node_name: str = "langnav_navigator"
    map_frame: str = "map"
    base_frame: str = "base_link"
    map_topic: str = "map"
    plan_topic: str = "plan"
    behavior_tree: str = ""
    #: Nav2 behavior pace for Move: DriveOnHeading / BackUp speed (m/s).
    drive_speed_mps: float = Field(default=0.15, gt=0, le=1.0)
    #: Behaviour time allowance = nominal duration x this + slack.
    time_allowance_factor: float = Field(default=3.0, ge=1.0)
    time_allowance_slack_s: float = Field(default=5.0, ge=0.0)
    #: Waiting for Nav2's action servers when the backend is created.
    server_timeout_s: float = Field(default=10.0, gt=0)


def _import_ros() -> dict[str, Any]:
    try:
        import rclpy
        from geometry_msgs.msg import PoseStamped
        from nav2_simple_commander.robot_navigator import BasicNavigator
        from nav2_simple_commander.robot_navigator import TaskResult as NavResult
        from nav_msgs.msg import OccupancyGrid as RosGrid
        from nav_msgs.msg import Path as RosPath
        from rclpy.executors import SingleThreadedExecutor
        from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
        from tf2_ros import Buffer, TransformListener
    except ImportError as exc:
        raise RobotError(f"{INSTALL_HINT} (import failed: {exc})") from None
    return {"rclpy": rclpy, "PoseStamped": PoseStamped, "BasicNavigator": BasicNavigator, "NavResult": NavResult,
            "RosGrid": RosGrid, "RosPath": RosPath, "Executor": SingleThreadedExecutor, "QoSProfile": QoSProfile,
            "Durability": DurabilityPolicy, "Reliability": ReliabilityPolicy, "Buffer": Buffer,
            "TransformListener": TransformListener}


class _Ros2Task(ReportedTask):
    """A TaskHandle over BasicNavigator's single active task."""

    def __init__(self, kind: str, backend: Ros2Backend) -> None:
        super().__init__(kind)
        self._backend = backend
        self.cancel_requested = False

    def cancel(self) -> None:
        with self._cond:
            if self._result is not None:
                return
            self.cancel_requested = True
        self._backend._cancel()

    def set_feedback(self, fb: TaskFeedback) -> None:
        with self._cond:
            self._feedback = fb

    def finish(self, status: TaskStatus, message: str, pose: Pose2D | None) -> None:
        self._set_result(status, message, pose)


class Ros2Backend:
    """A :class:`RobotBackend` on rclpy + nav2_simple_commander (see the module docstring)."""

    name = "ros2"

    def __init__(self, config: Ros2Config | None = None, **options: Any) -> None:
        self.config = config or Ros2Config(**options)
        self._ros = _import_ros()
        c, r = self.config, self._ros
        rclpy = r["rclpy"]
        if not rclpy.ok():
            rclpy.init()
        self._lock = threading.RLock()  # BasicNavigator is not thread-safe
        self._nav = r["BasicNavigator"](node_name=c.node_name, namespace=c.namespace)
        self._task: _Ros2Task | None = None
        self._map_msg: Any = None
        self._plan_msg: Any = None
        self._closed = False
        # a second node for tf, /map and /plan, spun in the background
        self._node = rclpy.create_node(c.node_name + "_observer", namespace=c.namespace)
        self._tf = r["Buffer"]()
        self._tf_listener = r["TransformListener"](self._tf, self._node)
        latched = r["QoSProfile"](depth=1, durability=r["Durability"].TRANSIENT_LOCAL,
                                  reliability=r["Reliability"].RELIABLE)
        self._node.create_subscription(r["RosGrid"], c.map_topic, self._on_map, latched)
        self._node.create_subscription(r["RosPath"], c.plan_topic, self._on_plan, 10)
        self._executor = r["Executor"]()
        self._executor.add_node(self._node)
        self._spin = threading.Thread(target=self._executor.spin, daemon=True, name="langnav-ros2-spin")
        self._spin.start()
        with self._lock:
            ready = self._nav.nav_through_poses_client.wait_for_server(timeout_sec=c.server_timeout_s)
        if not ready:
            self.close()
            raise RobotError(f"Nav2's navigate_through_poses action server did not appear within "
                             f"{c.server_timeout_s} s (namespace {c.namespace!r}); is Nav2 running and active?")

    def _on_map(self, msg: Any) -> None:
        self._map_msg = msg

    def _on_plan(self, msg: Any) -> None:
        self._plan_msg = msg

    # -- reading ---------------------------------------------------------------------------------
    def get_robot_pose(self, timeout_s: float = DEFAULT_REQUEST_TIMEOUT_S) -> Pose2D:
        c = self.config
        deadline = time.monotonic() + timeout_s
        while True:
            try:
                t = self._tf.lookup_transform(c.map_frame, c.base_frame, self._ros["rclpy"].time.Time())
                q = t.transform.rotation
                return Pose2D(t.transform.translation.x, t.transform.translation.y,
                              rm.quaternion_to_yaw({"x": q.x, "y": q.y, "z": q.z, "w": q.w}))
            except Exception as exc:  # tf2 raises LookupException / ExtrapolationException / ...
                if time.monotonic() >= deadline:
                    raise RobotTimeout(f"no transform {c.map_frame} -> {c.base_frame} within {timeout_s} s: "
                                       f"{exc}") from None
            time.sleep(_POLL_S)

    def get_map(self, timeout_s: float = DEFAULT_REQUEST_TIMEOUT_S) -> OccupancyGrid:
        deadline = time.monotonic() + timeout_s
        while self._map_msg is None:
            if time.monotonic() >= deadline:
                raise RobotTimeout(f"no map on {self.config.map_topic} within {timeout_s} s; is slam_toolbox "
                                   f"or map_server running?")
            time.sleep(_POLL_S)
        m = self._map_msg
        q = m.info.origin.orientation
        try:
            return from_ros_data(np.asarray(m.data, dtype=np.int64), m.info.width, m.info.height, m.info.resolution,
                                 m.info.origin.position.x, m.info.origin.position.y,
                                 rm.quaternion_to_yaw({"x": q.x, "y": q.y, "z": q.z, "w": q.w}),
                                 source=self.config.map_topic)
        except MapError as exc:
            raise RobotError(f"malformed map on {self.config.map_topic}: {exc}") from None

    def get_current_path(self, timeout_s: float = DEFAULT_REQUEST_TIMEOUT_S) -> list[tuple[float, float]]:
        msg = self._plan_msg
        return [] if msg is None else [(p.pose.position.x, p.pose.position.y) for p in msg.poses]

    def state(self) -> RobotState:
        try:
            pose: Pose2D | None = self.get_robot_pose(timeout_s=0.0)
        except RobotError:
            pose = None
        task = self._task
        return RobotState(pose=pose or Pose2D(0.0, 0.0, 0.0), connected=not self._closed,
                          path=tuple(self.get_current_path()), busy=task is not None and not task.done,
                          extra={"pose_known": pose is not None})

    # -- commanding ------------------------------------------------------------------------------
    def _pose_stamped(self, p: Pose2D) -> Any:
        ps = self._ros["PoseStamped"]()
        ps.header.frame_id = self.config.map_frame
        ps.header.stamp = self._nav.get_clock().now().to_msg()
        ps.pose.position.x, ps.pose.position.y = p.x_m, p.y_m
        q = rm.yaw_to_quaternion(p.yaw_rad)
        ps.pose.orientation.z, ps.pose.orientation.w = q["z"], q["w"]
        return ps

    def navigate_through_poses(self, poses: list[tuple[float, float] | tuple[float, float, float]]) -> TaskHandle:
        if not poses:
            raise RobotError("navigate_through_poses needs at least one pose")
        prev = self.state().pose
        targets: list[Pose2D] = []
        for p in poses:
            x, y = float(p[0]), float(p[1])
            yaw = math.radians(p[2]) if len(p) == 3 else math.atan2(y - prev.y_m, x - prev.x_m)  # type: ignore[misc]
            prev = Pose2D(x, y, yaw)
            targets.append(prev)
        stamped: Any = [self._pose_stamped(t) for t in targets]
        try:  # Kilted and later: the goal is a nav_msgs/Goals, not a list
            from nav_msgs.msg import Goals
        except ImportError:
            pass
        else:
            goals = Goals()
            goals.header = stamped[0].header
            goals.goals = stamped
            stamped = goals

        def start() -> bool:
            return bool(self._nav.goThroughPoses(stamped, self.config.behavior_tree))

        return self._run("navigate through poses", [start])

    def move(self, direction: str, steps: int) -> TaskHandle:
        if direction not in ("forward", "backward", "left", "right") or steps < 1:
            raise RobotError(f"move takes forward/backward/left/right and >= 1 step, got {direction!r} x {steps}")
        c = self.config
        dist = steps * MOVE_STEP_M
        allow = dist / c.drive_speed_mps * c.time_allowance_factor + c.time_allowance_slack_s
        spin_allow = (math.pi / 2) / 0.5 * c.time_allowance_factor + c.time_allowance_slack_s

        def drive() -> bool:
            return bool(self._nav.driveOnHeading(dist=dist, speed=c.drive_speed_mps, time_allowance=int(allow)))

        def back() -> bool:
            return bool(self._nav.backup(backup_dist=dist, backup_speed=c.drive_speed_mps, time_allowance=int(allow)))

        def spin(angle: float) -> Any:
            return lambda: bool(self._nav.spin(spin_dist=angle, time_allowance=int(spin_allow)))

        if direction == "forward":
            steps_fns = [drive]
        elif direction == "backward":
            steps_fns = [back]
        else:
            side = math.pi / 2 if direction == "left" else -math.pi / 2
            steps_fns = [spin(side), drive, spin(-side)]
        return self._run(f"move {direction} {dist:.2f} m", steps_fns)

    def rotate(self, direction: str, steps: int) -> TaskHandle:
        if direction not in ("left", "right") or steps < 1:
            raise RobotError(f"rotate takes left/right and >= 1 step, got {direction!r} x {steps}")
        angle = math.radians(steps * ROTATE_STEP_DEG) * (1 if direction == "left" else -1)
        allow = abs(angle) / 0.5 * self.config.time_allowance_factor + self.config.time_allowance_slack_s
        return self._run(f"rotate {direction}", [lambda: bool(self._nav.spin(spin_dist=angle,
                                                                             time_allowance=int(allow)))])

    def _run(self, kind: str, phases: list[Any]) -> TaskHandle:
        if self._closed:
            raise RobotError("the ros2 backend is closed; create a new one")
        if self._task is not None and not self._task.done:
            self._task.cancel()
        task = _Ros2Task(kind, self)
        self._task = task
        threading.Thread(target=self._watch, args=(task, phases), daemon=True, name=f"langnav-ros2-{kind}").start()
        return task

    def _watch(self, task: _Ros2Task, phases: list[Any]) -> None:
        nav_result = self._ros["NavResult"]
        t0 = time.monotonic()
        for start in phases:
            if task.cancel_requested:
                task.finish(TaskStatus.CANCELED, f"{task.kind} canceled", self._pose_or_none())
                return
            with self._lock:
                accepted = start()
            if not accepted:
                task.finish(TaskStatus.FAILED, f"Nav2 rejected the {task.kind} goal", self._pose_or_none())
                return
            while True:
                with self._lock:
                    complete = self._nav.isTaskComplete()
                    fb = self._nav.getFeedback()
                if task.cancel_requested and not complete:
                    with self._lock:
                        self._nav.cancelTask()
                if fb is not None and hasattr(fb, "current_pose"):
                    p = fb.current_pose.pose
                    q = p.orientation
                    task.set_feedback(TaskFeedback(
                        pose=Pose2D(p.position.x, p.position.y,
                                    rm.quaternion_to_yaw({"x": q.x, "y": q.y, "z": q.z, "w": q.w})),
                        distance_remaining_m=getattr(fb, "distance_remaining", None),
                        elapsed_s=time.monotonic() - t0,
                        poses_remaining=getattr(fb, "number_of_poses_remaining", None),
                        recoveries=int(getattr(fb, "number_of_recoveries", 0))))
                if complete:
                    break
                time.sleep(_POLL_S)
            with self._lock:
                result = self._nav.getResult()
            if result == nav_result.SUCCEEDED:
                continue
            status = TaskStatus.CANCELED if result == nav_result.CANCELED else TaskStatus.FAILED
            detail = getattr(self._nav, "status", None)
            task.finish(status, f"{task.kind}: Nav2 reported {getattr(result, 'name', result)}"
                        + (f" (goal status {detail})" if detail is not None else ""), self._pose_or_none())
            return
        task.finish(TaskStatus.SUCCEEDED, f"{task.kind} done", self._pose_or_none())

    def _pose_or_none(self) -> Pose2D | None:
        try:
            return self.get_robot_pose(timeout_s=0.0)
        except RobotError:
            return None

    def _cancel(self) -> None:
        with self._lock:
            self._nav.cancelTask()

    def stop(self) -> None:
        task = self._task
        if task is not None:
            task.cancel()

    def close(self) -> None:
        if self._closed:
            return
        self._closed = True
        try:
            self.stop()
        finally:
            self._executor.shutdown(timeout_sec=DEFAULT_REQUEST_TIMEOUT_S)
            self._node.destroy_node()
            self._nav.destroy_node()


def _factory(**options: Any) -> Ros2Backend:
    return Ros2Backend(**options)


register_backend("ros2", _factory)
