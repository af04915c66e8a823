"""Serve a langnav robot (the simulator) as a Nav2-shaped robot on a real ROS 2 graph (rclpy).

What a TurtleBot running slam_toolbox and Nav2 offers, names relative to the namespace:

===========================  ============================================  =========================
name                         type                                          notes
===========================  ============================================  =========================
map                          nav_msgs/msg/OccupancyGrid                    transient local; again
                                                                           when the map changes
tf                           tf2_msgs/msg/TFMessage                        map -> odom (odom's origin
                                                                           is the start pose),
                                                                           odom -> base_link
tf_static                    tf2_msgs/msg/TFMessage                        base_link -> base_scan
odom                         nav_msgs/msg/Odometry                         pose and body twist
scan                         sensor_msgs/msg/LaserScan                     best effort
plan                         nav_msgs/msg/Path                             when the path changes
cmd_vel (subscribed)         geometry_msgs/msg/Twist or TwistStamped       teleop; a zero does not
                                                                           stop a goal (as Nav2's
                                                                           controller overrides it)
navigate_through_poses       nav2_msgs/action/NavigateThroughPoses         a new goal preempts
                                                                           (aborts) the running one
spin, backup,                nav2_msgs/action/Spin, BackUp,                Nav2's behavior server
drive_on_heading             DriveOnHeading
===========================  ============================================  =========================

Test switches (:class:`RobotNodeConfig`): ``behaviors=False`` leaves the behavior server out,
``confirm_cancel=False`` rejects cancel requests (a robot whose cancel is never confirmed),
``map_delay_s`` publishes the map only after that long; ``static_map`` serves a saved map (as
map_server) instead of the robot's growing one (as slam_toolbox). ``langnav sim --ros2`` runs it for people
who want to try RViz or Foxglove without a robot.
"""

from __future__ import annotations

import array
import contextlib
import hashlib
import logging
import math
import threading
import time
from collections.abc import Callable
from typing import Any, Final

from pydantic import BaseModel, ConfigDict, Field

from langnav.maps.grid import OccupancyGrid
from langnav.robot.errors import RobotError
from langnav.robot.protocol import Pose2D, RobotBackend, TaskHandle, TaskStatus
from langnav.robot.ros import messages as rm
from langnav.robot.ros.convert import from_msg, to_msg
from langnav.robot.ros.runtime import RosRuntime, import_module, interface

log = logging.getLogger(__name__)

#: How often an action's execute loop looks at the robot's task.
_POLL_S: Final = 0.05
#: Nav2's generic "unknown" error codes: navigation (NavigateToPose's UNKNOWN) and behaviors.
NAV_ERROR_UNKNOWN: Final = 9000
SPIN_ERROR_UNKNOWN: Final = 700
BACKUP_ERROR_UNKNOWN: Final = 710
DRIVE_ERROR_UNKNOWN: Final = 720
#: close(): waiting for the running goals to be answered, and for rclpy to shut down.
CLOSE_TIMEOUT_S: Final = 5.0
#: Timeout error codes of the behaviors (their UNKNOWN + 1).
BEHAVIOR_TIMEOUT_OFFSET: Final = 1


class RobotNodeConfig(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)

    namespace: str = ""
    node_name: str = "langnav_robot"
    map_frame: str = "map"
    odom_frame: str = "odom"
    base_frame: str = "base_link"
    scan_frame: str = "base_scan"
    map_topic: str = "map"
    tf_topic: str = "tf"
    tf_static_topic: str = "tf_static"
    odom_topic: str = "odom"
    scan_topic: str = "scan"
    plan_topic: str = "plan"
    cmd_vel_topic: str = "cmd_vel"
    cmd_vel_stamped: bool = False
    nav_action: str = "navigate_through_poses"
    spin_action: str = "spin"
    backup_action: str = "backup"
    drive_on_heading_action: str = "drive_on_heading"
    #: tf and odom rate (Hz), scan rate (Hz), how often the map is checked for changes (s).
    tf_hz: float = Field(default=20.0, gt=0, le=200)
    scan_hz: float = Field(default=5.0, gt=0, le=50)
    map_check_s: float = Field(default=1.0, gt=0)
    #: serve the behavior server's actions (spin, backup, drive_on_heading)
    behaviors: bool = True
    #: accept cancel requests (False: reject them, as a robot whose cancel is not confirmed)
    confirm_cancel: bool = True
    #: publish the map only after this long (a robot whose SLAM starts late)
    map_delay_s: float = Field(default=0.0, ge=0)


class RobotNode:
    """A Nav2-shaped ROS 2 robot over a :class:`RobotBackend` (see the module docstring)."""

    def __init__(self, robot: RobotBackend, config: RobotNodeConfig | None = None,
                 static_map: OccupancyGrid | None = None, **options: Any) -> None:
        """``static_map``: serve this map (as map_server does with a saved floor plan, beside AMCL)
        instead of the robot's own, growing one (as slam_toolbox does)."""
        self.robot = robot
        self._static_map = static_map
        self.config = c = config or RobotNodeConfig(**options)
        self._types = {n: interface(n) for n in (
            "nav_msgs/msg/OccupancyGrid", "nav_msgs/msg/Odometry", "nav_msgs/msg/Path", "sensor_msgs/msg/LaserScan",
            "tf2_msgs/msg/TFMessage", "geometry_msgs/msg/Twist", "geometry_msgs/msg/TwistStamped")}
        action = import_module("rclpy.action")
        qos = import_module("rclpy.qos")
        groups = import_module("rclpy.callback_groups")
        self._action = action
        self._start_pose = robot.get_robot_pose()
        self._t0 = time.monotonic()
        self._map_digest = b""
        self._plan: tuple[tuple[float, float], ...] = ()
        self._closed = False
        #: goals under way: goal id -> the robot's task handle (for cancel and preemption)
        self._goals: dict[bytes, TaskHandle] = {}
        self._nav_lock = threading.Lock()
        self._nav_current: Any = None
        self._rt = RosRuntime(c.node_name, c.namespace, threads=8)
        node = self._rt.node
        try:
            latched = qos.QoSProfile(depth=1, durability=qos.DurabilityPolicy.TRANSIENT_LOCAL,
                                     reliability=qos.ReliabilityPolicy.RELIABLE)
            static = qos.QoSProfile(depth=1, durability=qos.DurabilityPolicy.TRANSIENT_LOCAL,
                                    reliability=qos.ReliabilityPolicy.RELIABLE)
            sensor = qos.QoSProfile(depth=5, reliability=qos.ReliabilityPolicy.BEST_EFFORT)
            tf_cls = self._types["tf2_msgs/msg/TFMessage"]
            self._pub_map = node.create_publisher(self._types["nav_msgs/msg/OccupancyGrid"], c.map_topic, latched)
            self._pub_tf = node.create_publisher(tf_cls, c.tf_topic, 100)
            self._pub_tf_static = node.create_publisher(tf_cls, c.tf_static_topic, static)
            self._pub_odom = node.create_publisher(self._types["nav_msgs/msg/Odometry"], c.odom_topic, 10)
            self._pub_scan = node.create_publisher(self._types["sensor_msgs/msg/LaserScan"], c.scan_topic, sensor)
            self._pub_plan = node.create_publisher(self._types["nav_msgs/msg/Path"], c.plan_topic, 10)
            twist = self._types["geometry_msgs/msg/TwistStamped" if c.cmd_vel_stamped else "geometry_msgs/msg/Twist"]
            node.create_subscription(twist, c.cmd_vel_topic, self._on_cmd_vel, 10)
            self._pub_tf_static.publish(to_msg(tf_cls, rm.tf_message(
                [rm.transform_stamped(c.base_frame, c.scan_frame, Pose2D(0.0, 0.0, 0.0), self._rt.now_s())])))
            reentrant = groups.ReentrantCallbackGroup()
            self._servers = [action.ActionServer(
                node, interface("nav2_msgs/action/NavigateThroughPoses"), c.nav_action, self._execute_nav,
                goal_callback=self._on_goal, cancel_callback=self._on_cancel,
                handle_accepted_callback=self._on_nav_accepted, callback_group=reentrant)]
            if c.behaviors:
                for name, type_name, fn in (
                        (c.spin_action, "nav2_msgs/action/Spin", self._execute_spin),
                        (c.backup_action, "nav2_msgs/action/BackUp", self._execute_backup),
                        (c.drive_on_heading_action, "nav2_msgs/action/DriveOnHeading", self._execute_drive)):
                    self._servers.append(action.ActionServer(
                        node, interface(type_name), name, fn, goal_callback=self._on_goal,
                        cancel_callback=self._on_cancel, callback_group=reentrant))
            self._timers = [node.create_timer(1.0 / c.tf_hz, self._publish_state),
                            node.create_timer(1.0 / c.scan_hz, self._publish_scan),
                            node.create_timer(c.map_check_s, self._publish_map)]
        except BaseException:
            self._rt.close()
            raise
        self._publish_map()

    # -- publishing ------------------------------------------------------------------------------
    def _odom_pose(self, p: Pose2D) -> Pose2D:
        """The robot's pose in odom, whose origin is where it started (as wheel odometry)."""
        return rm.compose(rm.invert(self._start_pose), p)

    def _publish_state(self) -> None:
        c = self.config
        st = self.robot.state()
        t = self._rt.now_s()
        odom_pose = self._odom_pose(st.pose)
        self._pub_tf.publish(to_msg(self._types["tf2_msgs/msg/TFMessage"], rm.tf_message([
            rm.transform_stamped(c.map_frame, c.odom_frame, self._start_pose, t),
            rm.transform_stamped(c.odom_frame, c.base_frame, odom_pose, t)])))
        self._pub_odom.publish(to_msg(self._types["nav_msgs/msg/Odometry"], rm.odometry(
            odom_pose, st.linear_mps, st.angular_radps, c.odom_frame, c.base_frame, t)))
        if st.path != self._plan:
            self._plan = st.path
            self._pub_plan.publish(to_msg(self._types["nav_msgs/msg/Path"], rm.path(st.path, c.map_frame, t)))

    def _publish_scan(self) -> None:
        scan = self.robot.state().scan
        if scan is not None:
            self._pub_scan.publish(to_msg(self._types["sensor_msgs/msg/LaserScan"], rm.laser_scan(
                scan, self.config.scan_frame, self._rt.now_s())))

    def _publish_map(self) -> None:
        if time.monotonic() - self._t0 < self.config.map_delay_s:
            return
        grid = self._static_map if self._static_map is not None else self.robot.get_map()
        cells = grid.to_ros_data().astype("int8").tobytes()
        digest = hashlib.blake2b(cells, digest_size=16).digest()
        if digest == self._map_digest:
            return
        self._map_digest = digest
        data = rm.occupancy_grid(grid, self.config.map_frame, self._rt.now_s())
        data.pop("data")
        msg = to_msg(self._types["nav_msgs/msg/OccupancyGrid"], data)
        msg.data = array.array("b", cells)
        self._pub_map.publish(msg)

    def _on_cmd_vel(self, msg: Any) -> None:
        try:
            v, w = rm.parse_cmd_vel(from_msg(msg))
            setter = getattr(self.robot, "set_velocity", None)
            if setter is not None:
                setter(v, w)
        except RobotError as exc:
            log.warning("ignored a cmd_vel: %s", exc)

    # -- actions ---------------------------------------------------------------------------------
    def _on_goal(self, _goal: Any) -> Any:
        return self._action.GoalResponse.ACCEPT

    def _on_cancel(self, _handle: Any) -> Any:
        return self._action.CancelResponse.ACCEPT if self.config.confirm_cancel else self._action.CancelResponse.REJECT

    def _on_nav_accepted(self, handle: Any) -> None:
        """Nav2 runs one navigation at a time: a new goal preempts (aborts) the running one."""
        with self._nav_lock:
            previous, self._nav_current = self._nav_current, handle
        if previous is not None and previous.is_active:
            task = self._goals.get(bytes(previous.goal_id.uuid))
            if task is not None:
                task.cancel()
        handle.execute()

    def _execute_nav(self, handle: Any) -> Any:
        goal = from_msg(handle.request)
        types = interface("nav2_msgs/action/NavigateThroughPoses")
        result_cls, fb_cls = types.Result, types.Feedback
        try:
            poses, _frame = rm.parse_navigate_through_poses_goal(goal)
            task = self.robot.navigate_through_poses([(p.x_m, p.y_m, math.degrees(p.yaw_rad)) for p in poses])
        except RobotError as exc:
            handle.abort()
            return to_msg(result_cls, {"error_code": NAV_ERROR_UNKNOWN, "error_msg": str(exc)})
        n = len(poses)
        t0 = time.monotonic()

        def feedback() -> None:
            fb = task.feedback()
            if fb is None:
                return
            handle.publish_feedback(to_msg(fb_cls, rm.navigate_through_poses_feedback(
                fb.pose, self.config.map_frame, time.monotonic() - t0, fb.distance_remaining_m,
                fb.poses_remaining if fb.poses_remaining is not None else n, fb.recoveries,
                t_s=self._rt.now_s())))

        return self._follow(handle, task, feedback, result_cls, NAV_ERROR_UNKNOWN, None)

    def _behavior(self, handle: Any, type_name: str, start: Callable[[Any], TaskHandle], code: int,
                  traveled: Callable[[Pose2D, Pose2D], float], fb_field: str) -> Any:
        types = interface(type_name)
        goal = handle.request
        allowance = goal.time_allowance.sec + goal.time_allowance.nanosec * 1e-9
        try:
            task = start(goal)
        except RobotError as exc:
            handle.abort()
            return to_msg(types.Result, {"error_code": code, "error_msg": str(exc)})
        p0 = self.robot.get_robot_pose()

        def feedback() -> None:
            handle.publish_feedback(to_msg(types.Feedback, {fb_field: traveled(p0, self.robot.get_robot_pose())}))

        return self._follow(handle, task, feedback, types.Result, code, allowance if allowance > 0 else None)

    def _execute_spin(self, handle: Any) -> Any:
        def traveled(p0: Pose2D, p: Pose2D) -> float:
            return abs(rm.wrap_angle(p.yaw_rad - p0.yaw_rad))

        return self._behavior(handle, "nav2_msgs/action/Spin", lambda g: self._turn(float(g.target_yaw)),
                              SPIN_ERROR_UNKNOWN, traveled, "angular_distance_traveled")

    def _execute_backup(self, handle: Any) -> Any:
        return self._behavior(handle, "nav2_msgs/action/BackUp", lambda g: self._drive(-abs(float(g.target.x))),
                              BACKUP_ERROR_UNKNOWN, _distance, "distance_traveled")

    def _execute_drive(self, handle: Any) -> Any:
        return self._behavior(handle, "nav2_msgs/action/DriveOnHeading", lambda g: self._drive(float(g.target.x)),
                              DRIVE_ERROR_UNKNOWN, _distance, "distance_traveled")

    def _drive(self, distance_m: float) -> TaskHandle:
        drive = getattr(self.robot, "drive", None)
        if drive is None:
            raise RobotError(f"{self.robot.name} cannot drive an arbitrary distance")
        handle: TaskHandle = drive(distance_m)
        return handle

    def _turn(self, angle_rad: float) -> TaskHandle:
        turn = getattr(self.robot, "turn", None)
        if turn is None:
            raise RobotError(f"{self.robot.name} cannot turn an arbitrary angle")
        handle: TaskHandle = turn(angle_rad)
        return handle

    def _follow(self, handle: Any, task: TaskHandle, feedback: Callable[[], None], result_cls: Any, code: int,
                limit_s: float | None) -> Any:
        """Run an accepted goal on the robot's task until it ends, is cancelled or is preempted."""
        gid = bytes(handle.goal_id.uuid)
        self._goals[gid] = task
        t0 = time.monotonic()
        try:
            while task.status() is TaskStatus.RUNNING and not self._closed:
                if handle.is_cancel_requested:
                    task.cancel()
                    _wait_quietly(task)
                    handle.canceled()
                    return result_cls()
                if limit_s is not None and time.monotonic() - t0 > limit_s:
                    task.cancel()
                    _wait_quietly(task)
                    handle.abort()
                    return to_msg(result_cls, {"error_code": code + BEHAVIOR_TIMEOUT_OFFSET,
                                               "error_msg": f"time allowance of {limit_s:.1f} s exceeded"})
                try:
                    feedback()
                except RobotError as exc:
                    log.debug("feedback: %s", exc)
                time.sleep(_POLL_S)
            result = task.wait(0.0) if task.status() is not TaskStatus.RUNNING else None
            if result is not None and result.status is TaskStatus.SUCCEEDED:
                handle.succeed()
                return result_cls()
            if handle.is_cancel_requested and self.config.confirm_cancel:
                handle.canceled()
                return result_cls()
            handle.abort()
            message = result.message if result is not None else "the robot node was shut down"
            return to_msg(result_cls, {"error_code": code, "error_msg": message})
        finally:
            self._goals.pop(gid, None)

    def close(self, timeout_s: float = CLOSE_TIMEOUT_S) -> None:
        """Stop the robot's goals (aborted: the robot's navigation went away), leave the graph."""
        if self._closed:
            return
        self._closed = True
        for task in list(self._goals.values()):
            task.cancel()
        deadline = time.monotonic() + timeout_s
        while self._goals and time.monotonic() < deadline:  # the execute loops answer their goals
            time.sleep(_POLL_S)
        self._rt.close(timeout_s)


def _distance(p0: Pose2D, p: Pose2D) -> float:
    return math.hypot(p.x_m - p0.x_m, p.y_m - p0.y_m)


def _wait_quietly(task: TaskHandle, timeout_s: float = 2.0) -> None:
    with contextlib.suppress(RobotError):
        task.wait(timeout_s)
