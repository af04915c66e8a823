"""The ``ros2`` backend: Nav2 through plain rclpy action clients, on a machine with ROS 2.

The shape of nav2_simple_commander's API (start a task, get a handle, read feedback, cancel, a
result of succeeded / failed / canceled), not its code: every wait here is bounded by a named
default, a missing action server is an error that names it, and ``close()`` always returns.

* NavigateThroughPoses -> Nav2's ``navigate_through_poses`` action. The goal is built from the
  action type's own field list: ``geometry_msgs/PoseStamped[] poses`` on Humble / Jazzy, a
  ``nav_msgs/Goals`` on Kilted and later (whether ``nav_msgs.msg.Goals`` imports says nothing:
  Jazzy's nav_msgs has it too).
* Move forward -> ``drive_on_heading``, backward -> ``backup``, left / right -> ``spin`` 90°,
  drive, spin back; Rotate -> ``spin``: Nav2's behavior server actions, collision-checked by Nav2.
* Pose: langnav's own composition of the latest ``map -> odom -> base_link`` transforms from
  ``tf`` and ``tf_static`` (no tf2_ros needed); ``map`` (transient local), ``plan``, ``odom`` and
  ``scan`` from subscriptions.
* STOP and cancel hold: the goal is cancelled and zero velocity is published on ``cmd_vel`` at
  ``cmd_rate_hz`` until the action server confirms the cancel (and at least ``stop_hold_min_s``),
  or ``cancel_timeout_s`` passes: then the task ends FAILED with a message that says the robot
  did not confirm and may still be moving.

One private rclpy context and executor per backend (:mod:`langnav.robot.ros.runtime`); a task's
phases run in a watcher thread that polls futures with bounded waits, and any exception there
ends the task FAILED with the reason, never a hang.
"""

from __future__ import annotations

import logging
import math
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Final

import numpy as np
from pydantic import BaseModel, ConfigDict, Field

from langnav.maps.errors import MapError
from langnav.maps.grid import OccupancyGrid, from_ros_data
from langnav.plan.commands import MOVE_STEP_M, ROTATE_STEP_DEG
from langnav.robot.errors import RobotError, RobotTimeout
from langnav.robot.protocol import (
    DEFAULT_REQUEST_TIMEOUT_S,
    LaserScan,
    Pose2D,
    RobotState,
    TaskFeedback,
    TaskHandle,
    TaskStatus,
    register_backend,
)
from langnav.robot.ros import messages as rm
from langnav.robot.ros.convert import from_msg, to_msg
from langnav.robot.ros.runtime import INSTALL_HINT, RosRuntime, import_module, interface
from langnav.robot.task_state import ReportedTask

log = logging.getLogger(__name__)

__all__ = ["INSTALL_HINT", "Ros2Backend", "Ros2Config"]

#: How often a watcher looks at its goal's futures, the server's presence and the clock.
_POLL_S: Final = 0.02
#: action_msgs/msg/GoalStatus values.
GOAL_SUCCEEDED: Final = 4
GOAL_CANCELED: Final = 5
GOAL_ABORTED: Final = 6
#: Nav2's Spin turns at up to 1 rad/s by default; the time allowance assumes half of that.
NOMINAL_SPIN_RADPS: Final = 0.5

NAVIGATE_THROUGH_POSES: Final = "nav2_msgs/action/NavigateThroughPoses"
SPIN: Final = "nav2_msgs/action/Spin"
BACK_UP: Final = "nav2_msgs/action/BackUp"
DRIVE_ON_HEADING: Final = "nav2_msgs/action/DriveOnHeading"


class Ros2Config(BaseModel):
    """Names, frames, speeds and every time limit of the ros2 backend."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    #: The robot's namespace ("robot1" for a namespaced TurtleBot 4): applies to every relative
    #: name below, as ROS resolves names.
    namespace: str = ""
    node_name: str = "langnav"
    map_frame: str = "map"
    #: named in errors only: the pose is map -> base_link through whatever frames tf holds
    odom_frame: str = "odom"
    base_frame: str = "base_link"
    map_topic: str = "map"
    plan_topic: str = "plan"
    odom_topic: str = "odom"
    scan_topic: str = "scan"
    #: Relative, so a namespaced robot that remaps tf into its namespace (TurtleBot 4) works; set
    #: "/tf" and "/tf_static" for a namespaced robot that keeps the global ones.
    tf_topic: str = "tf"
    tf_static_topic: str = "tf_static"
    cmd_vel_topic: str = "cmd_vel"
    #: TwistStamped (True) or Twist (False) on cmd_vel for STOP's zero velocity; None: what the
    #: robot's cmd_vel subscribers take (Twist when none is seen).
    cmd_vel_stamped: bool | None = None
    nav_action: str = "navigate_through_poses"
    spin_action: str = "spin"
    backup_action: str = "backup"
    drive_on_heading_action: str = "drive_on_heading"
    behavior_tree: str = ""
    #: Nav2 behavior pace for Move: DriveOnHeading / BackUp speed (m/s).
    drive_speed_mps: float = Field(default=0.15, gt=0, le=1.0)
    #: Behavior time allowance = nominal duration x this + slack.
    time_allowance_factor: float = Field(default=3.0, ge=1.0)
    time_allowance_slack_s: float = Field(default=5.0, ge=0.0)
    #: Waiting for the navigate_through_poses server when the backend is created (the shared robot
    #: option --connect-timeout).
    connect_timeout_s: float = Field(default=10.0, gt=0)
    #: Waiting for a behavior server (spin, backup, drive_on_heading) when a Move/Rotate needs it.
    behavior_server_timeout_s: float = Field(default=3.0, gt=0)
    #: Waiting for a server to accept or reject a goal.
    goal_response_timeout_s: float = Field(default=5.0, gt=0)
    #: A running goal's action server gone from the graph this long: the robot is lost.
    server_lost_s: float = Field(default=2.0, gt=0)
    #: No navigation feedback for this long: the robot is lost (a robot that vanishes without
    #: leaving the graph -- powered off, out of Wi-Fi range -- is dropped by DDS only after its
    #: lease, 20 s by default; Nav2's bt_navigator sends feedback on every tree tick, recoveries
    #: included).
    feedback_timeout_s: float = Field(default=10.0, gt=0)
    #: STOP / cancel: hold zero velocity until the cancel is confirmed, at most this long.
    cancel_timeout_s: float = Field(default=5.0, gt=0)
    #: STOP: hold zero velocity at least this long (a base that missed one message still stops).
    stop_hold_min_s: float = Field(default=0.5, ge=0)
    cmd_rate_hz: float = Field(default=20.0, gt=0, le=100)
    #: close(): the running goal's cancel and the executor's shutdown, each at most this long.
    close_timeout_s: float = Field(default=5.0, gt=0)


@dataclass(frozen=True)
class _Phase:
    """One action goal of a task."""

    action: str  # config field name of the action, e.g. "spin_action"
    type_name: str
    goal: Callable[[Any], dict[str, Any]]  # the action's Goal class -> the goal dict
    #: the phase's own limit (a behavior's time allowance + slack); None: navigation (no limit
    #: but the feedback and server watchdogs).
    limit_s: float | None
    #: metres or radians the phase covers, for "remaining" in the feedback
    amount: float = 0.0


class _Ros2Task(ReportedTask):
    """A TaskHandle over a sequence of Nav2 action goals."""

    wait_hint = " (cancel it, or call stop())"

    def __init__(self, kind: str, backend: Ros2Backend) -> None:
        super().__init__(kind)
        self._backend = backend
        self.cancel_requested = threading.Event()
        self.goal_handle: Any = None
        self.result_future: Any = None

    def cancel(self) -> None:
        if self.done:
            return
        self._backend._stop_task(self)

    def set_feedback(self, fb: TaskFeedback) -> None:
        with self._cond:
            self._feedback = fb

    def finish(self, status: TaskStatus, message: str, pose: Pose2D | None) -> bool:
        return self._set_result(status, message, pose)


class Ros2Backend:
    """A :class:`RobotBackend` on plain rclpy (see the module docstring)."""

    name = "ros2"

    def __init__(self, config: Ros2Config | None = None, **options: Any) -> None:
        self.config = c = config or Ros2Config(**options)
        self._closed = False
        self._lock = threading.Lock()
        self._task: _Ros2Task | None = None
        self._holds: list[threading.Thread] = []
        self._map_msg: Any = None
        self._plan: list[tuple[float, float]] = []
        self._odom: tuple[float, float] = (0.0, 0.0)
        self._scan_msg: Any = None
        self._tf = rm.TransformTree()
        self._tf_lock = threading.Lock()
        qos = import_module("rclpy.qos")
        self._types = {name: interface(name) for name in (
            "nav_msgs/msg/OccupancyGrid", "nav_msgs/msg/Path", "nav_msgs/msg/Odometry",
            "sensor_msgs/msg/LaserScan", "tf2_msgs/msg/TFMessage", "geometry_msgs/msg/Twist",
            "geometry_msgs/msg/TwistStamped", NAVIGATE_THROUGH_POSES)}
        self._action_mod = import_module("rclpy.action")
        self._rt = RosRuntime(c.node_name, c.namespace)
        node = self._rt.node
        try:
            latched = qos.QoSProfile(depth=1, durability=qos.DurabilityPolicy.TRANSIENT_LOCAL,
                                     reliability=qos.ReliabilityPolicy.RELIABLE)
            static = qos.QoSProfile(depth=100, durability=qos.DurabilityPolicy.TRANSIENT_LOCAL,
                                    reliability=qos.ReliabilityPolicy.RELIABLE)
            sensor = qos.QoSProfile(depth=5, reliability=qos.ReliabilityPolicy.BEST_EFFORT)
            node.create_subscription(self._types["nav_msgs/msg/OccupancyGrid"], c.map_topic, self._on_map, latched)
            node.create_subscription(self._types["nav_msgs/msg/Path"], c.plan_topic, self._on_plan, 10)
            node.create_subscription(self._types["nav_msgs/msg/Odometry"], c.odom_topic, self._on_odom, 10)
            node.create_subscription(self._types["sensor_msgs/msg/LaserScan"], c.scan_topic, self._on_scan, sensor)
            node.create_subscription(self._types["tf2_msgs/msg/TFMessage"], c.tf_topic, self._on_tf, 100)
            node.create_subscription(self._types["tf2_msgs/msg/TFMessage"], c.tf_static_topic, self._on_tf, static)
            self._cmd_pubs: dict[bool, Any] = {}
            self._clients: dict[str, tuple[Any, Any]] = {}
            nav, _ = self._client("nav_action", NAVIGATE_THROUGH_POSES)
            if not self._wait_for_server(nav, c.connect_timeout_s):
                raise RobotError(f"Nav2's {self._resolved(c.nav_action)} action server did not appear within "
                                 f"{c.connect_timeout_s} s (namespace {c.namespace!r}, ROS_DOMAIN_ID "
                                 f"{_domain_id()}): is Nav2 running and active, on this ROS domain?")
        except BaseException:
            self._rt.close(c.close_timeout_s)
            raise

    # -- subscriptions (executor thread) ---------------------------------------------------------
    def _on_map(self, msg: Any) -> None:
        self._map_msg = msg

    def _on_plan(self, msg: Any) -> None:
        self._plan = [(p.pose.position.x, p.pose.position.y) for p in msg.poses]

    def _on_odom(self, msg: Any) -> None:
        t = msg.twist.twist
        self._odom = (t.linear.x, t.angular.z)

    def _on_scan(self, msg: Any) -> None:
        self._scan_msg = msg

    def _on_tf(self, msg: Any) -> None:
        try:
            data = from_msg(msg)
            with self._tf_lock:
                self._tf.update(data, self.config.tf_topic)
        except RobotError as exc:
            log.warning("ignored a malformed transform: %s", exc)

    # -- names and servers -------------------------------------------------------------------------
    def _resolved(self, name: str) -> str:
        if name.startswith("/"):
            return name
        ns = self.config.namespace.strip("/")
        return f"/{ns}/{name}" if ns else f"/{name}"

    def _client(self, action_field: str, type_name: str) -> tuple[Any, Any]:
        """(the rclpy ActionClient, the action type) for an action field of the config."""
        with self._lock:
            entry = self._clients.get(action_field)
            if entry is None:
                cls = self._types.get(type_name) or interface(type_name)
                entry = (self._action_mod.ActionClient(self._rt.node, cls, getattr(self.config, action_field)), cls)
                self._clients[action_field] = entry
            return entry

    def _wait_for_server(self, client: Any, timeout_s: float) -> bool:
        deadline = time.monotonic() + timeout_s
        while not client.server_is_ready():
            if time.monotonic() >= deadline or self._closed:
                return False
            time.sleep(_POLL_S)
        return True

    @property
    def connected(self) -> bool:
        """Whether Nav2's navigate_through_poses server is on the graph now."""
        if self._closed:
            return False
        try:
            return bool(self._clients["nav_action"][0].server_is_ready())
        except Exception:
            return False

    # -- reading ---------------------------------------------------------------------------------
    def get_robot_pose(self, timeout_s: float = DEFAULT_REQUEST_TIMEOUT_S) -> Pose2D:
        c = self.config
        deadline = time.monotonic() + timeout_s
        while True:
            with self._tf_lock:
                pose = self._tf.lookup(c.map_frame, c.base_frame)
                frames = self._tf.frames()
            if pose is not None:
                return pose
            if time.monotonic() >= deadline:
                raise RobotTimeout(f"no transform {c.map_frame} -> {c.base_frame} on {self._resolved(c.tf_topic)} "
                                   f"within {timeout_s} s (frames seen: {', '.join(frames) or 'none'}); is "
                                   f"slam_toolbox or AMCL publishing {c.map_frame} -> {c.odom_frame}?")
            time.sleep(_POLL_S)

    def get_map(self, timeout_s: float = DEFAULT_REQUEST_TIMEOUT_S) -> OccupancyGrid:
        deadline = time.monotonic() + timeout_s
        while self._map_msg is None:
            if time.monotonic() >= deadline:
                raise RobotTimeout(f"no map on {self._resolved(self.config.map_topic)} within {timeout_s} s; is "
                                   f"slam_toolbox or map_server running?")
            time.sleep(_POLL_S)
        m = self._map_msg
        q = m.info.origin.orientation
        try:
            return from_ros_data(np.asarray(m.data, dtype=np.int64), m.info.width, m.info.height, m.info.resolution,
                                 m.info.origin.position.x, m.info.origin.position.y,
                                 rm.quaternion_to_yaw({"x": q.x, "y": q.y, "z": q.z, "w": q.w}),
                                 source=self._resolved(self.config.map_topic))
        except MapError as exc:
            raise RobotError(f"malformed map on {self._resolved(self.config.map_topic)}: {exc}") from None

    def get_current_path(self, timeout_s: float = DEFAULT_REQUEST_TIMEOUT_S) -> list[tuple[float, float]]:
        return list(self._plan)

    def _scan(self, pose: Pose2D | None) -> LaserScan | None:
        msg = self._scan_msg
        if msg is None or pose is None:
            return None
        try:
            return rm.parse_laser_scan(from_msg(msg), pose, self._resolved(self.config.scan_topic))
        except RobotError:
            return None

    def state(self) -> RobotState:
        try:
            pose: Pose2D | None = self.get_robot_pose(timeout_s=0.0)
        except RobotError:
            pose = None
        task = self._task
        v, w = self._odom
        return RobotState(pose=pose or Pose2D(0.0, 0.0, 0.0), connected=self.connected, linear_mps=v,
                          angular_radps=w, scan=self._scan(pose), path=tuple(self._plan),
                          busy=task is not None and not task.done, extra={"pose_known": pose is not None})

    # -- commanding ------------------------------------------------------------------------------
    def navigate_through_poses(self, poses: list[tuple[float, float] | tuple[float, float, float]]) -> TaskHandle:
        if not poses:
            raise RobotError("navigate_through_poses needs at least one pose (x, y[, yaw_deg])")
        try:
            prev = self.get_robot_pose(timeout_s=0.0)
        except RobotError:
            prev = Pose2D(float(poses[0][0]), float(poses[0][1]), 0.0)
        targets: list[Pose2D] = []
        for p in poses:
            if len(p) not in (2, 3) or not all(math.isfinite(float(v)) for v in p):
                raise RobotError(f"a pose is (x, y) or (x, y, yaw_deg) with finite numbers, got {p!r}")
            x, y = float(p[0]), float(p[1])
            yaw = math.radians(float(p[2])) if len(p) == 3 else math.atan2(y - prev.y_m, x - prev.x_m)  # type: ignore[misc]
            prev = Pose2D(x, y, yaw)
            targets.append(prev)
        c = self.config

        def goal(goal_cls: Any) -> dict[str, Any]:
            return rm.navigate_through_poses_goal(targets, c.map_frame, goal_format(goal_cls), c.behavior_tree,
                                                  self._rt.now_s())

        return self._run("navigate through poses",
                         [_Phase("nav_action", NAVIGATE_THROUGH_POSES, goal, None, float(len(targets)))])

    def _allowance(self, nominal_s: float) -> float:
        return nominal_s * self.config.time_allowance_factor + self.config.time_allowance_slack_s

    def _spin_phase(self, angle: float) -> _Phase:
        allow = self._allowance(abs(angle) / NOMINAL_SPIN_RADPS)
        return _Phase("spin_action", SPIN, lambda _cls: {"target_yaw": angle, "time_allowance": rm.duration(allow)},
                      allow + self.config.time_allowance_slack_s, abs(angle))

    def _drive_phase(self, dist: float, backward: bool) -> _Phase:
        c = self.config
        allow = self._allowance(dist / c.drive_speed_mps)

        def goal(_cls: Any) -> dict[str, Any]:
            return {"target": {"x": dist, "y": 0.0, "z": 0.0}, "speed": c.drive_speed_mps,
                    "time_allowance": rm.duration(allow)}

        if backward:
            return _Phase("backup_action", BACK_UP, goal, allow + c.time_allowance_slack_s, dist)
        return _Phase("drive_on_heading_action", DRIVE_ON_HEADING, goal, allow + c.time_allowance_slack_s, dist)

    def move(self, direction: str, steps: int) -> TaskHandle:
        if direction not in ("forward", "backward", "left", "right") or steps < 1:
            raise RobotError(f"move takes forward/backward/left/right and >= 1 step, got {direction!r} x {steps}")
        dist = steps * MOVE_STEP_M
        if direction in ("forward", "backward"):
            phases = [self._drive_phase(dist, backward=direction == "backward")]
        else:
            side = math.pi / 2 if direction == "left" else -math.pi / 2
            phases = [self._spin_phase(side), self._drive_phase(dist, backward=False), self._spin_phase(-side)]
        return self._run(f"move {direction} {dist:.2f} m", phases)

    def rotate(self, direction: str, steps: int) -> TaskHandle:
        if direction not in ("left", "right") or steps < 1:
            raise RobotError(f"rotate takes left/right and >= 1 step, got {direction!r} x {steps}")
        angle = math.radians(steps * ROTATE_STEP_DEG) * (1 if direction == "left" else -1)
        return self._run(f"rotate {direction} {math.degrees(abs(angle)):.0f} deg", [self._spin_phase(angle)])

    def _run(self, kind: str, phases: list[_Phase]) -> TaskHandle:
        if self._closed:
            raise RobotError("the ros2 backend is closed; create a new one")
        previous = self._task
        task = _Ros2Task(kind, self)
        self._task = task
        if previous is not None and not previous.done:
            # Nav2 preempts a running navigation with the next goal of the same action; a goal of
            # another action would run beside it, so the previous one is cancelled first.
            previous.cancel_requested.set()
            self._cancel_goal(previous)
            previous.finish(TaskStatus.CANCELED, f"{previous.kind}: preempted by {kind}", self._pose_or_none())
        threading.Thread(target=self._watch, args=(task, phases), daemon=True, name=f"langnav-ros2-{kind}").start()
        return task

    # -- the watcher -------------------------------------------------------------------------------
    def _watch(self, task: _Ros2Task, phases: list[_Phase]) -> None:
        try:
            t0 = time.monotonic()
            for phase in phases:
                if not self._run_phase(task, phase, t0):
                    return
            task.finish(TaskStatus.SUCCEEDED, f"{task.kind} done", self._pose_or_none())
        except Exception as exc:  # never leave a task without an outcome
            log.exception("the ros2 backend's %s watcher failed", task.kind)
            self._cancel_goal(task)
            task.finish(TaskStatus.FAILED, f"{task.kind} failed inside langnav's ros2 backend: "
                        f"{type(exc).__name__}: {exc}", self._pose_or_none())

    def _run_phase(self, task: _Ros2Task, phase: _Phase, t0: float) -> bool:
        """Run one goal to its end; False when the task ended (its outcome is set)."""
        c = self.config
        name = self._resolved(getattr(c, phase.action))
        if task.cancel_requested.is_set() or task.done:
            task.finish(TaskStatus.CANCELED, f"{task.kind} canceled", self._pose_or_none())
            return False
        client, action_type = self._client(phase.action, phase.type_name)
        wait_s = c.connect_timeout_s if phase.action == "nav_action" else c.behavior_server_timeout_s
        if not self._wait_for_server(client, wait_s):
            task.finish(TaskStatus.FAILED, f"{task.kind}: the {name} action server ({phase.type_name}) is not "
                        f"available (waited {wait_s} s); is Nav2's "
                        f"{'bt_navigator' if phase.action == 'nav_action' else 'behavior_server'} running?",
                        self._pose_or_none())
            return False
        goal_msg = to_msg(action_type.Goal, phase.goal(action_type.Goal), f"{name} goal")
        start_pose = self._pose_or_none()
        progress: dict[str, Any] = {"fb": None, "t": time.monotonic()}

        def on_feedback(msg: Any) -> None:
            progress["fb"] = msg.feedback
            progress["t"] = time.monotonic()

        send = client.send_goal_async(goal_msg, feedback_callback=on_feedback)
        deadline = time.monotonic() + c.goal_response_timeout_s
        while not send.done():
            if task.done:
                return False
            if time.monotonic() >= deadline:
                task.finish(TaskStatus.FAILED, f"{task.kind}: {name} did not answer the goal within "
                            f"{c.goal_response_timeout_s} s", self._pose_or_none())
                return False
            time.sleep(_POLL_S)
        handle = send.result()
        if handle is None or not handle.accepted:
            task.finish(TaskStatus.FAILED, f"{task.kind}: {name} rejected the goal", self._pose_or_none())
            return False
        task.goal_handle = handle
        task.result_future = result = handle.get_result_async()
        if task.cancel_requested.is_set():
            handle.cancel_goal_async()
        started = time.monotonic()
        lost_since: float | None = None
        while not result.done():
            if task.done:
                return False
            now = time.monotonic()
            self._publish_feedback(task, phase, progress["fb"], start_pose, now - t0)
            if client.server_is_ready():
                lost_since = None
            elif lost_since is None:
                lost_since = now
            elif now - lost_since >= c.server_lost_s:
                task.finish(TaskStatus.FAILED, f"{task.kind}: lost the robot: the {name} action server left the "
                            f"ROS graph {c.server_lost_s} s ago while the goal ran (robot off, out of range, "
                            f"or Nav2 stopped)", self._pose_or_none())
                return False
            if not task.cancel_requested.is_set():
                if phase.limit_s is not None and now - started > phase.limit_s:
                    handle.cancel_goal_async()
                    task.finish(TaskStatus.FAILED, f"{task.kind}: {name} did not finish within {phase.limit_s:.1f} s "
                                f"(its time allowance and slack); the goal was cancelled", self._pose_or_none())
                    return False
                if phase.limit_s is None and now - progress["t"] > c.feedback_timeout_s:
                    handle.cancel_goal_async()
                    task.finish(TaskStatus.FAILED, f"{task.kind}: no feedback from {name} for "
                                f"{c.feedback_timeout_s} s: lost the robot, or Nav2 is stuck; a cancel was sent "
                                f"and zero velocity published", self._pose_or_none())
                    self._stop_task(None)
                    return False
            time.sleep(_POLL_S)
        response = result.result()
        status = int(response.status)
        if status == GOAL_SUCCEEDED:
            return True
        if status == GOAL_CANCELED:
            why = "stopped" if task.cancel_requested.is_set() else f"cancelled by the robot ({name})"
            task.finish(TaskStatus.CANCELED, f"{task.kind} {why}", self._pose_or_none())
            return False
        detail = _error_detail(response.result)
        what = "aborted" if status == GOAL_ABORTED else f"ended with goal status {status}"
        task.finish(TaskStatus.FAILED, f"{task.kind}: Nav2 {what} the goal ({name}{detail})", self._pose_or_none())
        return False

    def _publish_feedback(self, task: _Ros2Task, phase: _Phase, fb: Any, start: Pose2D | None, elapsed: float) -> None:
        pose = self._pose_or_none()
        if fb is not None and hasattr(fb, "current_pose"):
            p = fb.current_pose.pose
            q = p.orientation
            task.set_feedback(TaskFeedback(
                pose=Pose2D(p.position.x, p.position.y, rm.quaternion_to_yaw({"x": q.x, "y": q.y, "z": q.z, "w": q.w})),
                distance_remaining_m=float(fb.distance_remaining), elapsed_s=elapsed,
                poses_remaining=int(fb.number_of_poses_remaining), recoveries=int(fb.number_of_recoveries)))
            return
        if pose is None:
            return
        done = getattr(fb, "distance_traveled", None)
        turned = getattr(fb, "angular_distance_traveled", None)
        dist_left = max(phase.amount - float(done), 0.0) if done is not None else None
        ang_left = max(phase.amount - float(turned), 0.0) if turned is not None else None
        task.set_feedback(TaskFeedback(pose=pose, distance_remaining_m=dist_left, elapsed_s=elapsed,
                                       angle_remaining_rad=ang_left, message=phase.type_name.rsplit("/", 1)[-1]))

    def _pose_or_none(self) -> Pose2D | None:
        try:
            return self.get_robot_pose(timeout_s=0.0)
        except RobotError:
            return None

    # -- STOP --------------------------------------------------------------------------------------
    def _cmd_vel_stamped(self) -> bool:
        c = self.config
        if c.cmd_vel_stamped is not None:
            return c.cmd_vel_stamped
        try:
            infos = self._rt.node.get_subscriptions_info_by_topic(self._resolved(c.cmd_vel_topic))
        except Exception:
            return False
        return any(i.topic_type == "geometry_msgs/msg/TwistStamped" for i in infos)

    def _publish_zero(self) -> None:
        stamped = self._cmd_vel_stamped()
        with self._lock:
            pub = self._cmd_pubs.get(stamped)
            if pub is None:
                cls = self._types["geometry_msgs/msg/TwistStamped" if stamped else "geometry_msgs/msg/Twist"]
                pub = self._cmd_pubs[stamped] = self._rt.node.create_publisher(cls, self.config.cmd_vel_topic, 10)
        msg = to_msg(pub.msg_type, rm.cmd_vel(0.0, 0.0, stamped, self.config.base_frame, self._rt.now_s()))
        pub.publish(msg)

    def _cancel_goal(self, task: _Ros2Task) -> None:
        handle = task.goal_handle
        if handle is not None:
            try:
                handle.cancel_goal_async()
            except Exception as exc:
                log.warning("cancelling %s: %s", task.kind, exc)

    def _stop_task(self, task: _Ros2Task | None) -> None:
        """Cancel ``task`` (if any) and hold zero velocity until the cancel is confirmed."""
        if self._closed:
            return
        if task is not None and not task.done:
            task.cancel_requested.set()
            self._cancel_goal(task)
        hold = threading.Thread(target=self._hold, args=(task,), daemon=True, name="langnav-ros2-stop")
        with self._lock:
            self._holds = [h for h in self._holds if h.is_alive()] + [hold]
        hold.start()

    def _hold(self, task: _Ros2Task | None) -> None:
        c = self.config
        t0 = time.monotonic()
        period = 1.0 / c.cmd_rate_hz
        try:
            while not self._rt.closed:
                self._publish_zero()
                elapsed = time.monotonic() - t0
                confirmed = task is None or task.done or (
                    task.result_future is not None and task.result_future.done())
                if confirmed and elapsed >= c.stop_hold_min_s:
                    break
                if elapsed >= c.cancel_timeout_s:
                    if task is not None:
                        task.finish(TaskStatus.FAILED, (
                            f"{task.kind}: the robot did not confirm the cancel within {c.cancel_timeout_s} s; zero "
                            f"velocity was held on {self._resolved(c.cmd_vel_topic)} meanwhile, but Nav2 may still "
                            f"be driving: check the robot and stop it by hand if it moves"), self._pose_or_none())
                    break
                time.sleep(period)
        except Exception as exc:
            log.error("holding zero velocity failed: %s", exc)
            if task is not None:
                task.finish(TaskStatus.FAILED, f"{task.kind}: could not hold the robot stopped: {exc}",
                            self._pose_or_none())
        if task is not None and not task.done and task.result_future is None:
            task.finish(TaskStatus.CANCELED, f"{task.kind} stopped before Nav2 took the goal", self._pose_or_none())

    def stop(self) -> None:
        """Cancel whatever runs and hold the robot stopped (see the module docstring)."""
        self._stop_task(self._task)

    def close(self) -> None:
        """Stop, wait (bounded) for the hold, shut rclpy down. Always returns."""
        if self._closed:
            return
        try:
            task = self._task
            if task is not None and not task.done:
                self.stop()
            deadline = time.monotonic() + self.config.cancel_timeout_s + 1.0
            for hold in list(self._holds):
                hold.join(max(deadline - time.monotonic(), 0.0))
        except Exception as exc:
            log.warning("stopping the robot while closing: %s", exc)
        finally:
            self._closed = True
            task = self._task
            if task is not None:
                task.finish(TaskStatus.CANCELED, f"{task.kind}: the ros2 backend was closed", None)
            self._rt.close(self.config.close_timeout_s)


def goal_format(goal_cls: Any) -> str:
    """'pose_array' or 'goals': how this NavigateThroughPoses definition takes its poses."""
    kind = goal_cls.get_fields_and_field_types().get("poses", "")
    if kind.startswith("sequence<geometry_msgs/PoseStamped"):
        return "pose_array"
    if kind == "nav_msgs/Goals":
        return "goals"
    raise RobotError(f"this nav2_msgs NavigateThroughPoses has poses of type {kind!r}, which langnav does not know "
                     f"(it knows geometry_msgs/PoseStamped[] and nav_msgs/Goals)")


def _error_detail(result: Any) -> str:
    code = getattr(result, "error_code", None)
    msg = getattr(result, "error_msg", "")
    parts = [f"error code {code}"] if code else []
    if msg:
        parts.append(str(msg))
    return f": {', '.join(parts)}" if parts else ""


def _domain_id() -> str:
    import os

    return os.environ.get("ROS_DOMAIN_ID", "0 (unset)")


def _factory(**options: Any) -> Ros2Backend:
    return Ros2Backend(**options)


register_backend("ros2", _factory)
