"""The ``rosbridge`` backend: drive a ROS 2 robot running Nav2 through rosbridge_suite, with roslibpy.

* NavigateThroughPoses: Nav2's ``nav2_msgs/action/NavigateThroughPoses`` via rosbridge's action
  ops (rosbridge_suite >= 2.0). Start rosbridge with ``send_action_goals_in_new_thread:=true``:
  otherwise rosbridge reads nothing from the socket while a goal runs and a cancel is never seen
  (langnav then reports the cancel as unconfirmed after ``cancel_timeout_s`` and zeroes cmd_vel).
* Move / Rotate: ``cmd_vel`` at ``cmd_rate_hz``, as Twist (Jazzy) or TwistStamped (Kilted; Nav2's
  ``enable_stamped_cmd_vel``), closed-loop on odometry: it stops when the distance or angle is
  covered, slowing down over the last few centimetres / degrees. Move left / right on a
  differential base is rotate 90°, drive, rotate back.
* /map (slam_toolbox and map_server publish it transient local; rosbridge_suite matches a
  transient-local publisher's durability on subscribe, so the latched map arrives at once),
  /plan, /scan, and the pose from tf (``map -> base_link`` composed from /tf and /tf_static) or
  from a pose topic (/amcl_pose, /pose or an Odometry topic).

Faults: a lost connection fails every running task with a reason (and the stop is queued for
when the robot is reachable again); a malformed message from the robot raises a RobotError (for
feedback: fails the task and stops the robot); every wait has a timeout from
:class:`RosbridgeConfig`.

roslibpy runs its transport (twisted reactor, or an asyncio loop) in a background thread that
can start only once per process; :meth:`RosbridgeBackend.close` closes the connection and stops
reconnecting but never terminates that loop, so any number of backends can come and go.

Closing is ordered so that nothing is sent on a closed socket: first langnav's own loops (the
Move/Rotate cmd_vel loops and the navigation watchdogs) are stopped and joined, then the last
words go out (zero velocity, unsubscribe, unadvertise), then the WebSocket close handshake, queued
behind them on the transport's thread, and only once the link is down is reconnecting switched
off. (Dropping the TCP connection from the caller's thread, as an earlier version did, raced the
queued messages and made twisted log "Attempt to send on a closed protocol" for each of them.)

rosbridge answers a bad request with a ``status`` message; roslibpy registers no handler for that
op (it logs a "No handler registered" traceback per message), so the backend installs one that
logs the robot's message as a warning.
"""

from __future__ import annotations

import logging
import math
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Final, Literal

import roslibpy
from pydantic import BaseModel, ConfigDict, Field, ValidationError

from langnav.maps.grid import OccupancyGrid
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
from langnav.robot.task_state import ReportedTask

log = logging.getLogger(__name__)

#: How often a waiting loop re-checks its condition.
_POLL_S: Final = 0.02
#: rosbridge's per-subscription queue (see RosbridgeBackend._subscribe for why it is 0).
SUBSCRIBE_QUEUE_LENGTH: Final = 0
#: Zero velocity is re-sent at this rate while a cancelled goal is not yet confirmed. A base obeys
#: the latest cmd_vel, and Nav2's controller keeps publishing at its controller_frequency (20 Hz by
#: default) until the goal really ends, so one zero message is overwritten within 50 ms (the robot
#: was measured moving 0.5 m in the second after one). Sending as often as the controller makes
#: at least every other command the base sees a zero one; only the confirmed cancel truly stops
#: Nav2, hence the bounded wait and the error after it (``cancel_timeout_s``).
STOP_HOLD_RATE_HZ: Final = 20.0
#: Opening the stop line (see RosbridgeBackend._open_stop_line) on a link that already works
#: takes milliseconds; waiting longer would only delay the zero velocity on the main connection.
STOP_LINE_CONNECT_TIMEOUT_S: Final = 1.0
#: A cancel through a rosbridge that runs goals in their own thread is confirmed within tens of
#: milliseconds (measured 0.02 s); Nav2's bt_navigator halts its tree within one tick. Two seconds
#: is ample, and short enough that a person learns quickly when the robot may still be moving.
DEFAULT_CANCEL_TIMEOUT_S: Final = 2.0
#: get_map: re-subscribe to the map this often until it arrives. rosbridge picks a subscription's
#: durability from the publishers it knows when the subscription is made, and a fresh rosbridge
#: took about a second to discover a transient-local /map publisher (measured: connecting within
#: ~1 s of rosbridge starting missed the map 1 time in 3); a subscription made in that second is
#: volatile and never receives the latched map, so a new one is made every second.
MAP_RESUBSCRIBE_S: Final = 1.0


class RosbridgeConfig(BaseModel):
    """Where the robot is and what its topics, frames and limits are called."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    host: str = "127.0.0.1"
    port: int = Field(default=9090, ge=1, le=65535)
    secure: bool = False
    #: roslibpy transport: "twisted" (its default) or "asyncio"; one per process (txaio binds one).
    transport: Literal["twisted", "asyncio"] | None = None
    #: Prefix for every topic, action and service name (TurtleBot 4 ``namespace:=/robot1``).
    namespace: str = ""

    nav_action: str = "/navigate_through_poses"
    #: "pose_array" (Humble, Jazzy: PoseStamped[] poses) or "goals" (Kilted+: nav_msgs/Goals).
    goal_format: Literal["pose_array", "goals"] = "pose_array"
    behavior_tree: str = ""
    cmd_vel_topic: str = "/cmd_vel"
    #: TwistStamped (Kilted, Nav2 enable_stamped_cmd_vel) or Twist (Jazzy, Create 3).
    cmd_vel_stamped: bool = False
    map_topic: str = "/map"
    plan_topic: str = "/plan"
    scan_topic: str = "/scan"
    odom_topic: str = "/odom"
    tf_topic: str = "/tf"
    tf_static_topic: str = "/tf_static"
    #: Where the pose comes from: the tf tree, or a pose topic.
    pose_source: Literal["tf", "topic"] = "tf"
    pose_topic: str = "/amcl_pose"
    pose_topic_type: str = rm.POSE_WITH_COV_STAMPED
    #: Optional nav_msgs/srv/GetMap fallback when no /map arrives ("" = none), e.g.
    #: "/slam_toolbox/dynamic_map" or "/map_server/map".
    map_service: str = ""
    map_frame: str = "map"
    odom_frame: str = "odom"
    base_frame: str = "base_link"

    #: Move / Rotate pace: TurtleBot 4's teleop defaults are 0.5 m/s, 1 rad/s; steps of 3 cm and
    #: 10° are small, so a gentler pace keeps the overshoot under a centimetre / a degree.
    linear_speed_mps: float = Field(default=0.15, gt=0, le=1.0)
    angular_speed_radps: float = Field(default=0.6, gt=0, le=3.0)
    #: Slowest commanded speed near the end: slower and a real base stalls on friction.
    min_linear_speed_mps: float = Field(default=0.02, gt=0)
    min_angular_speed_radps: float = Field(default=0.1, gt=0)
    #: Proportional slow-down near the goal (1/s): speed = gain x remaining.
    slowdown_gain_per_s: float = Field(default=2.0, gt=0)
    #: Stop when this close: 5 mm, 1° (a step is 3 cm / 10°).
    distance_tolerance_m: float = Field(default=0.005, gt=0)
    angle_tolerance_rad: float = Field(default=math.radians(1.0), gt=0)
    #: Nav2's controller runs at 20 Hz; so does this loop.
    cmd_rate_hz: float = Field(default=20.0, gt=0, le=100)
    #: A move takes at most its nominal duration x this + motion_slack_s, else it fails.
    motion_timeout_factor: float = Field(default=3.0, ge=1.0)
    motion_slack_s: float = Field(default=5.0, ge=0.0)
    #: Where odometry is read from for Move / Rotate: the odom topic, or the robot pose.
    motion_pose_source: Literal["odom", "pose"] = "odom"

    connect_timeout_s: float = Field(default=10.0, gt=0)
    #: close(): wait this long for the close handshake (autobahn's closeHandshakeTimeout is 5 s)
    #: and for langnav's own Move/Rotate loops and watchdogs to end (they poll every 50 ms).
    close_timeout_s: float = Field(default=5.0, gt=0)
    #: Odometry older than this while moving stops the move (the base or the link stalled).
    odom_stale_s: float = Field(default=1.0, gt=0)
    #: Fail navigation when no feedback came for this long (Nav2 sends it every BT tick).
    feedback_timeout_s: float = Field(default=10.0, gt=0)
    #: After cancel() / stop(), hold zero velocity (at ``stop_hold_rate_hz``) for at most this long
    #: while waiting for the robot to confirm the cancel; then the task fails saying the robot may
    #: still be moving.
    cancel_timeout_s: float = Field(default=DEFAULT_CANCEL_TIMEOUT_S, gt=0)
    stop_hold_rate_hz: float = Field(default=STOP_HOLD_RATE_HZ, gt=0, le=100)
    #: Reconnect backoff cap (roslibpy's default is an hour).
    reconnect_max_delay_s: float = Field(default=10.0, gt=0)

    def name(self, topic: str) -> str:
        """A topic, action or service name with the namespace applied."""
        if not self.namespace or not topic.startswith("/"):
            return topic
        return "/" + self.namespace.strip("/") + topic

    @property
    def url(self) -> str:
        return f"{'wss' if self.secure else 'ws'}://{self.host}:{self.port}"


@dataclass(frozen=True)
class _Stamped:
    msg: Any
    received_s: float


def goal_outcome(status: Any, values: Any, accepted: bool, action: str) -> tuple[TaskStatus, str]:
    """An ``action_result`` read by its status code (``action_msgs/msg/GoalStatus``: 4 succeeded,
    5 canceled, 6 aborted), whatever its ``result`` flag says: rosbridge_suite answers a cancelled
    or aborted goal with ``result: true``, rosbridge-server-rs with ``result: false`` (the flag
    means "the action ran and succeeded" there). ``values`` is Nav2's result (``error_code``,
    ``error_msg``), possibly nested under ``result``, or a reason string; its wording is kept.
    ``accepted`` is the message's ``result`` flag; without a status code, a false one means the
    goal could not be run at all."""
    raw = getattr(status, "value", status)
    code = raw if isinstance(raw, int) and not isinstance(raw, bool) else None
    body = values.get("result") if isinstance(values, dict) and isinstance(values.get("result"), dict) else values
    if code is None and isinstance(body, dict):  # some servers put the status inside the values
        inner = body.get("status")
        code = inner if isinstance(inner, int) and not isinstance(inner, bool) else None
    if isinstance(body, dict):
        reason = str(body.get("error_msg") or "")
        err = body.get("error_code")
    else:
        reason, err = ("" if body in (None, False, True) else str(body)), None
    if code == rm.GOAL_STATUS_SUCCEEDED:
        return TaskStatus.SUCCEEDED, reason or "reached the last pose"
    if code == rm.GOAL_STATUS_CANCELED:
        return TaskStatus.CANCELED, reason or "canceled"
    if code == rm.GOAL_STATUS_ABORTED:
        return TaskStatus.FAILED, (f"Nav2 aborted the goal (status {code}, error_code {err}): "
                                   f"{reason or 'no reason given'}")
    if not accepted:
        return TaskStatus.FAILED, f"{action} could not run the goal: {reason or 'no reason given'}"
    return TaskStatus.FAILED, (f"{action} ended the goal with status {raw!r} (error_code {err}): "
                               f"{reason or 'no reason given'}")


class _Task(ReportedTask):
    """A TaskHandle whose state is set from roslibpy's thread and read from the caller's."""

    wait_hint = " (cancel() it, or wait longer)"

    def __init__(self, kind: str, on_cancel: Callable[[_Task], None], goal: bool = False) -> None:
        super().__init__(kind)
        self._on_cancel = on_cancel
        #: a Nav2 goal (its cancel must be confirmed by the robot), not a Move/Rotate cmd_vel loop
        self.goal = goal
        self.cancel_requested_s: float | None = None
        self.last_news_s = time.monotonic()
        self.goal_id = ""

    def cancel(self) -> None:
        with self._cond:
            if self._status is not TaskStatus.RUNNING or self.cancel_requested_s is not None:
                return
            self.cancel_requested_s = time.monotonic()
        self._on_cancel(self)

    def set_feedback(self, fb: TaskFeedback) -> None:
        with self._cond:
            self.last_news_s = time.monotonic()
            if self._status is TaskStatus.RUNNING:
                self._feedback = fb

    def finish(self, status: TaskStatus, message: str, pose: Pose2D | None = None) -> bool:
        """Set the result once; later calls are ignored (first outcome wins)."""
        if not self._set_result(status, message, pose):
            return False
        log.info("%s %s: %s", self.kind, status.value, message)
        return True


class RosbridgeBackend:
    """A :class:`RobotBackend` over rosbridge (see the module docstring)."""

    name = "rosbridge"

    def __init__(self, config: RosbridgeConfig | None = None, **options: Any) -> None:
        if config is not None and options:
            raise RobotError("give either a RosbridgeConfig or keyword options, not both")
        try:
            self.config = config or RosbridgeConfig(**options)
        except ValidationError as exc:
            problems = "; ".join(f"{'.'.join(map(str, e['loc'])) or 'options'}: {e['msg']}" for e in exc.errors())
            raise RobotError(f"invalid rosbridge option(s): {problems} (the fields are those of RosbridgeConfig, "
                             f"see docs/ros2.md)") from None
        c = self.config
        self._lock = threading.RLock()
        self._closed = False
        self._connected = False
        self._latest: dict[str, _Stamped] = {}
        self._tf = rm.TransformTree()
        self._tf_error: RobotError | None = None
        self._tasks: set[_Task] = set()
        #: langnav's own threads (Move/Rotate loops, navigation watchdogs): joined by close()
        self._workers: set[threading.Thread] = set()
        #: set while the WebSocket is down (set by roslibpy's "close" event, cleared on "ready")
        self._link_down = threading.Event()
        self._map_cache: tuple[Any, OccupancyGrid] | None = None
        #: bumped by every new command: a stop hold ends when the robot is told to move again
        self._command_gen = 0
        self._holding = False
        #: why the last stop was not confirmed (the robot may still be moving), until a new command
        self._stop_unconfirmed: str | None = None
        self._cmd_vel: roslibpy.Topic | None = None
        self._stop_line: tuple[roslibpy.Ros, roslibpy.Topic] | None = None
        self._subs: list[tuple[roslibpy.Topic, Callable[[Any], None]]] = []
        try:
            self._ros = roslibpy.Ros(c.host, c.port, is_secure=c.secure, transport=c.transport)
        except RuntimeError as exc:  # txaio already bound to the other framework
            raise RobotError(f"cannot use roslibpy transport {c.transport!r}: {exc}") from exc
        self._ros.factory.maxDelay = c.reconnect_max_delay_s
        self._ros.on("close", self._on_close)
        self._ros.on("ready", self._on_ready)
        self._ros.factory.on_ready(self._install_status_handler)  # now if connected, else when it is
        try:
            self._ros.run(timeout=c.connect_timeout_s)
        except roslibpy.core.RosTimeoutError:
            self._closed = True  # late transport events of this failed attempt are no faults
            self._stop_reconnecting(force=True)
            raise RobotError(
                f"cannot reach rosbridge at {c.url} within {c.connect_timeout_s} s. Check that rosbridge "
                f"runs on the robot (`ros2 launch rosbridge_server rosbridge_websocket_launch.xml "
                f"port:={c.port} send_action_goals_in_new_thread:=true`, or `langnav sim --rosbridge-port "
                f"{c.port}` for the simulator), that {c.host} is the robot's address and {c.port} the "
                f"rosbridge port (a web server there instead answers the WebSocket upgrade with an HTTP "
                f"error), that this machine reaches it (`ping {c.host}`) and no firewall blocks port "
                f"{c.port}") from None
        self._connected = True
        self._nav = roslibpy.ActionClient(self._ros, c.name(c.nav_action), rm.NAVIGATE_THROUGH_POSES)
        self._cmd_vel = roslibpy.Topic(self._ros, c.name(c.cmd_vel_topic),
                                       rm.TWIST_STAMPED if c.cmd_vel_stamped else rm.TWIST, queue_size=1)
        self._subscribe(c.map_topic, rm.OCCUPANCY_GRID)
        self._subscribe(c.plan_topic, rm.PATH)
        self._subscribe(c.scan_topic, rm.LASER_SCAN)
        self._subscribe(c.odom_topic, rm.ODOMETRY)
        if c.pose_source == "tf":
            self._subscribe(c.tf_topic, rm.TF_MESSAGE, self._on_tf)
            self._subscribe(c.tf_static_topic, rm.TF_MESSAGE, self._on_tf)
        else:
            self._subscribe(c.pose_topic, c.pose_topic_type)
        log.info("rosbridge backend connected to %s", c.url)

    # -- connection ------------------------------------------------------------------------------
    def _subscribe(self, topic: str, msg_type: str, callback: Callable[[str, Any], None] | None = None) -> None:
        name = self.config.name(topic)
        # queue_length=0 (rosbridge keeps no per-subscription queue), not 1: rosbridge_suite <= 2.1.0
        # can wedge, accepting no further connections, when a client that subscribed with a queue
        # length > 0 disconnects (upstream issue #891, fixed by #983); measured here: wedged after 5
        # of 18 `langnav run` connections with queue_length=1, 40 of 40 fine with 0. langnav only ever
        # reads the latest message of each topic, so the queue bought nothing.
        t = roslibpy.Topic(self._ros, name, msg_type, queue_length=SUBSCRIBE_QUEUE_LENGTH)
        handler = callback or self._store

        def on_message(msg: Any) -> None:
            try:
                handler(topic, msg)
            except Exception:  # a callback must never kill roslibpy's thread
                log.exception("handling a message on %s", name)

        t.subscribe(on_message)
        self._subs.append((t, on_message))

    def _resubscribe(self, topic: str) -> None:
        """Drop the subscription to ``topic`` and make it again (rosbridge then makes a new ROS
        subscription, with the durability of the publishers it knows now)."""
        name = self.config.name(topic)
        for t, on_message in self._subs:
            if t.name == name:
                t.unsubscribe()
                t.subscribe(on_message)

    def _store(self, topic: str, msg: Any) -> None:
        self._latest[topic] = _Stamped(msg, time.monotonic())

    def _on_tf(self, topic: str, msg: Any) -> None:
        try:
            with self._lock:
                self._tf.update(msg, self.config.name(topic))
                self._tf_error = None
            self._store(topic, msg)
        except RobotError as exc:
            self._tf_error = exc
            log.warning("%s", exc)

    def _on_ready(self, proto: Any = None, *_: Any) -> None:
        self._connected = True
        self._link_down.clear()
        if proto is not None:
            self._install_status_handler(proto)

    def _install_status_handler(self, proto: Any) -> Any:
        """roslibpy 2.x maps the ``status`` op to no handler (a TODO in its RosBridgeProtocol) and
        logs a traceback for every status message; handle it: log what the robot said."""
        handlers = getattr(proto, "_message_handlers", None)
        if isinstance(handlers, dict) and handlers.get("status") is None:
            handlers["status"] = self._on_status
        return proto

    def _on_status(self, message: Any) -> None:
        level = str(message.get("level", "")) if hasattr(message, "get") else ""
        text = message.get("msg", message) if hasattr(message, "get") else message
        log.log(logging.WARNING if level in ("error", "warning") else logging.INFO,
                "rosbridge at %s reports %s: %s", self.config.url, level or "status", text)

    def _on_close(self, *_: Any) -> None:
        was = self._connected
        self._connected = False
        self._link_down.set()
        if self._closed or self._cmd_vel is None:  # closed, or never connected: nothing to stop
            return
        if was:
            log.warning("lost the rosbridge connection to %s", self.config.url)
        reason = (f"lost the rosbridge connection to {self.config.url} mid-task; the robot was told to "
                  f"stop (sent when it is reachable again); check the network and rosbridge")
        with self._lock:
            tasks = list(self._tasks)
        for task in tasks:
            task.finish(TaskStatus.FAILED, reason, self._cached_pose())
        # This runs inside the transport's "close" event, while (with twisted) the factory still
        # holds the dead protocol: a send now would go to the closed socket. Once the event is
        # over the factory has dropped it, and the stop is queued until the link is back.
        self._ros.call_later(0, self._send_stop)

    def _stop_reconnecting(self, force: bool = False, ros: roslibpy.Ros | None = None) -> None:
        """Switch roslibpy's reconnecting off (of the main connection, or ``ros``), on the
        transport's thread; ``force`` also drops a connection whose close handshake never finished."""
        ros = ros or self._ros
        factory = ros.factory
        stop_trying = getattr(factory, "stopTrying", None)
        if callable(stop_trying):  # twisted ReconnectingClientFactory: not thread-safe, so on its thread
            ros.call_later(0, stop_trying)
            connector = getattr(factory, "connector", None)
            if force and connector is not None:
                ros.call_later(0, connector.disconnect)
        else:  # asyncio transport: its reconnect loop checks this flag
            factory._stop = True
            proto = getattr(factory, "_proto", None)
            if force and proto is not None:
                ros.call_later(0, proto.dropConnection)

    def _require_connection(self) -> None:
        if self._closed:
            raise RobotError("the rosbridge backend is closed; create a new one")
        if not (self._connected and self._ros.is_connected):
            raise RobotError(f"not connected to rosbridge at {self.config.url} (roslibpy keeps "
                             f"reconnecting); check that rosbridge runs and the network is up")

    def close(self) -> None:
        """Stop the robot and disconnect, in an order that sends nothing on a closed socket (see
        the module docstring). Running tasks end FAILED ("closed"). Idempotent."""
        if self._closed:
            return
        c = self.config
        self._closed = True  # no new task starts; the link going down is no longer a fault
        with self._lock:
            tasks = list(self._tasks)
        for task in tasks:
            if self._connected:
                task.cancel()  # navigation: cancel the goal; Move/Rotate: their loop sends zero velocity
            task.finish(TaskStatus.FAILED, "the rosbridge backend was closed")
        self._join_workers(c.close_timeout_s)
        self._close_stop_line()
        if not self._connected:
            for t, _cb in self._subs:  # nothing can be sent: just drop the handlers
                self._ros.off(t.name)
            self._stop_reconnecting()
            return
        self._send_stop()
        for t, _cb in self._subs:
            t.unsubscribe()
        if self._cmd_vel is not None:
            self._cmd_vel.unadvertise()
        try:
            self._ros.close(timeout=c.close_timeout_s)  # queues the close frame behind the messages above
        except roslibpy.core.RosTimeoutError:
            log.warning("rosbridge connection did not start closing within %s s", c.close_timeout_s)
        clean = self._link_down.wait(c.close_timeout_s)
        if not clean:
            log.warning("rosbridge at %s did not finish the close handshake within %s s; dropping the "
                        "connection", c.url, c.close_timeout_s)
        self._stop_reconnecting(force=not clean)

    def _open_stop_line(self) -> tuple[roslibpy.Ros, roslibpy.Topic] | None:
        """The stop line: a second WebSocket to rosbridge that carries only the stop (zero velocity
        and the cancel request), opened on the first stop and kept until close(). rosbridge_suite
        reads each connection's messages on that connection's own thread, and one that runs goals
        on that thread (``send_action_goals_in_new_thread:=false``, the launch default before 2025)
        reads nothing more from the connection that sent the goal until the goal ends: a zero
        velocity sent there arrives too late. None when it cannot be opened (the main connection
        is used then)."""
        with self._lock:
            if self._stop_line is not None or self._closed:
                return self._stop_line
        c = self.config
        ros = roslibpy.Ros(c.host, c.port, is_secure=c.secure, transport=c.transport)
        ros.factory.maxDelay = c.reconnect_max_delay_s
        ros.factory.on_ready(self._install_status_handler)
        try:
            ros.run(timeout=min(c.connect_timeout_s, STOP_LINE_CONNECT_TIMEOUT_S))
        except roslibpy.core.RosTimeoutError:
            self._stop_reconnecting(force=True, ros=ros)
            log.warning("could not open a second connection to %s for the stop; holding zero velocity "
                        "on the main one", c.url)
            return None
        topic = roslibpy.Topic(ros, c.name(c.cmd_vel_topic), rm.TWIST_STAMPED if c.cmd_vel_stamped else rm.TWIST,
                               queue_size=1)
        with self._lock:
            if self._closed:  # close() ran meanwhile
                line_to_close: tuple[roslibpy.Ros, roslibpy.Topic] | None = (ros, topic)
            else:
                self._stop_line, line_to_close = (ros, topic), None
        if line_to_close is not None:
            self._stop_reconnecting(force=True, ros=ros)
            return None
        return self._stop_line

    def _close_stop_line(self) -> None:
        with self._lock:
            line, self._stop_line = self._stop_line, None
        if line is None:
            return
        ros, topic = line
        if ros.is_connected:
            topic.unadvertise()
            try:
                ros.close(timeout=self.config.close_timeout_s)
            except roslibpy.core.RosTimeoutError:
                log.warning("the stop line to %s did not start closing", self.config.url)
        self._stop_reconnecting(force=not ros.is_connected, ros=ros)

    def _join_workers(self, timeout_s: float) -> None:
        deadline = time.monotonic() + timeout_s
        with self._lock:
            workers = [t for t in self._workers if t is not threading.current_thread()]
        for t in workers:
            t.join(max(0.0, deadline - time.monotonic()))
            if t.is_alive():
                log.warning("%s did not stop within %s s", t.name, timeout_s)

    def _spawn(self, name: str, target: Callable[[], None]) -> None:
        """Start one of langnav's own worker threads (joined by close())."""
        def run() -> None:
            try:
                target()
            finally:
                with self._lock:
                    self._workers.discard(threading.current_thread())

        t = threading.Thread(target=run, daemon=True, name=name)
        with self._lock:
            self._workers.add(t)
        t.start()

    # -- reading -------------------------------------------------------------------------------
    def _wait_for(self, topic: str, timeout_s: float, what: str) -> _Stamped:
        deadline = time.monotonic() + timeout_s
        while True:
            got = self._latest.get(topic)
            if got is not None:
                return got
            self._require_connection()
            if time.monotonic() >= deadline:
                raise RobotTimeout(f"no {what} on {self.config.name(topic)} within {timeout_s} s; is it "
                                   f"published (ros2 topic info {self.config.name(topic)})?")
            time.sleep(_POLL_S)

    def _cached_pose(self) -> Pose2D | None:
        try:
            return self._pose_now()
        except RobotError:
            return None

    def _pose_now(self) -> Pose2D | None:
        c = self.config
        if c.pose_source == "tf":
            with self._lock:
                p = self._tf.lookup(c.map_frame, c.base_frame)
                err = self._tf_error
            if p is None and err is not None:
                raise err
            return p
        got = self._latest.get(c.pose_topic)
        if got is None:
            return None
        p, _frame = rm.parse_robot_pose(got.msg, c.name(c.pose_topic))
        return p

    def get_robot_pose(self, timeout_s: float = DEFAULT_REQUEST_TIMEOUT_S) -> Pose2D:
        deadline = time.monotonic() + timeout_s
        c = self.config
        while True:
            p = self._pose_now()
            if p is not None:
                return p
            self._require_connection()
            if time.monotonic() >= deadline:
                if c.pose_source == "tf":
                    with self._lock:
                        frames = self._tf.frames()
                    raise RobotTimeout(f"no transform {c.map_frame} -> {c.base_frame} within {timeout_s} s "
                                       f"(frames seen: {', '.join(frames) or 'none'}); is SLAM or AMCL "
                                       f"running, and are map_frame/base_frame right?")
                raise RobotTimeout(f"no pose on {c.name(c.pose_topic)} within {timeout_s} s")
            time.sleep(_POLL_S)

    def get_map(self, timeout_s: float = DEFAULT_REQUEST_TIMEOUT_S) -> OccupancyGrid:
        """The latest map; until one arrives, re-subscribe every ``MAP_RESUBSCRIBE_S`` (see there
        why) up to ``timeout_s``, then try ``map_service`` if set, else raise a RobotTimeout."""
        c = self.config
        name = c.name(c.map_topic)
        start = time.monotonic()
        next_try = start + MAP_RESUBSCRIBE_S
        tries = 0
        while (got := self._latest.get(c.map_topic)) is None:
            self._require_connection()
            now = time.monotonic()
            if now - start >= timeout_s:
                if c.map_service:
                    return self._map_from_service(max(timeout_s, DEFAULT_REQUEST_TIMEOUT_S))
                raise RobotTimeout(
                    f"no map (nav_msgs/OccupancyGrid) on {name} within {timeout_s} s, subscribed "
                    f"{tries + 1} time(s); is slam_toolbox or map_server running and publishing it "
                    f"transient local (`ros2 topic info -v {name}`: Durability TRANSIENT_LOCAL)? "
                    f"Or set map_service (e.g. /slam_toolbox/dynamic_map) as a fallback")
            if now >= next_try:
                tries += 1
                log.info("no map on %s after %.1f s: subscribing again (%d)", name, now - start, tries)
                self._resubscribe(c.map_topic)
                next_try = now + MAP_RESUBSCRIBE_S
            time.sleep(_POLL_S)
        cached = self._map_cache
        if cached is not None and cached[0] is got.msg:
            return cached[1]
        grid = rm.parse_occupancy_grid(got.msg, name)
        self._map_cache = (got.msg, grid)
        return grid

    def _map_from_service(self, timeout_s: float) -> OccupancyGrid:
        name = self.config.name(self.config.map_service)
        service = roslibpy.Service(self._ros, name, rm.GET_MAP_SRV)
        try:
            response = service.call(roslibpy.ServiceRequest({}), timeout=timeout_s)
        except roslibpy.core.RosTimeoutError:
            raise RobotTimeout(f"{name} did not answer within {timeout_s} s") from None
        except roslibpy.core.ServiceException as exc:
            raise RobotError(f"{name} failed: {exc}") from None
        if not isinstance(response, dict) and not hasattr(response, "get"):
            raise RobotError(f"malformed {name} response: {response!r}")
        return rm.parse_occupancy_grid(dict(response).get("map"), name)

    def get_current_path(self, timeout_s: float = DEFAULT_REQUEST_TIMEOUT_S) -> list[tuple[float, float]]:
        """The last /plan Nav2 published ([] before any): it is published while planning, not on request."""
        got = self._latest.get(self.config.plan_topic)
        if got is None:
            self._require_connection()
            return []
        pts, _frame = rm.parse_path(got.msg, self.config.name(self.config.plan_topic))
        return pts

    def _odom(self) -> tuple[Pose2D, float, float, float] | None:
        """(pose, linear, angular, received_s) from the odom topic, or None."""
        got = self._latest.get(self.config.odom_topic)
        if got is None:
            return None
        m = rm.validate(rm.OdometryMsg, got.msg, f"{self.config.name(self.config.odom_topic)} ({rm.ODOMETRY})")
        lin = m.twist.twist.linear.x if m.twist else 0.0
        ang = m.twist.twist.angular.z if m.twist else 0.0
        return rm.pose2d_from_pose(m.pose.pose), lin, ang, got.received_s

    def state(self) -> RobotState:
        pose = self._cached_pose()
        lin = ang = 0.0
        try:
            odom = self._odom()
            if odom is not None:
                lin, ang = odom[1], odom[2]
        except RobotError as exc:
            log.debug("state: %s", exc)
        scan: LaserScan | None = None
        got = self._latest.get(self.config.scan_topic)
        if got is not None and pose is not None:
            try:
                scan = rm.parse_laser_scan(got.msg, pose, self.config.name(self.config.scan_topic))
            except RobotError as exc:
                log.debug("state: %s", exc)
        try:
            path = tuple(self.get_current_path())
        except RobotError:
            path = ()
        with self._lock:
            busy = any(not t.done for t in self._tasks)
        return RobotState(pose=pose or Pose2D(0.0, 0.0, 0.0), connected=self._connected and not self._closed,
                          linear_mps=lin, angular_radps=ang, scan=scan, path=path, busy=busy,
                          extra={"pose_known": pose is not None, "url": self.config.url,
                                 "stop_holding": self._holding, "stop_unconfirmed": self._stop_unconfirmed})

    # -- commanding ------------------------------------------------------------------------------
    def _publish_cmd(self, linear_mps: float, angular_radps: float) -> None:
        c = self.config
        if self._cmd_vel is None:
            raise RobotError(f"not connected to rosbridge at {c.url}")
        self._cmd_vel.publish(roslibpy.Message(rm.cmd_vel(linear_mps, angular_radps, c.cmd_vel_stamped, c.base_frame)))

    def _send_stop(self) -> None:
        """Zero velocity; queued by roslibpy until the link is back when it is down."""
        try:
            self._publish_cmd(0.0, 0.0)
        except Exception as exc:  # roslibpy may fail in odd ways on a half-closed link
            log.warning("could not send the stop command: %s", exc)

    def stop(self) -> None:
        """Cancel what runs and send zero velocity now; while a cancelled Nav2 goal is not yet
        confirmed ended, zero velocity is held (see :meth:`_hold_stop`). Returns at once:
        :meth:`wait_stopped` tells whether the stop was confirmed."""
        with self._lock:
            tasks = list(self._tasks)
        for task in tasks:
            task.cancel()
        self._send_stop()

    def _pending_cancels(self) -> list[_Task]:
        with self._lock:
            return [t for t in self._tasks if t.goal and t.cancel_requested_s is not None and not t.done]

    def _new_command(self) -> None:
        """The robot is told to move again: a stop hold ends, a past unconfirmed stop is forgotten."""
        with self._lock:
            self._command_gen += 1
            self._stop_unconfirmed = None

    def _hold_stop(self) -> None:
        """Publish zero velocity at ``stop_hold_rate_hz`` until every cancelled goal is confirmed
        ended (its result arrived), or given up after ``cancel_timeout_s`` (the navigation
        watchdog then fails it saying the robot may still be moving), or a new command starts, or
        the backend closes. One holder thread at a time."""
        with self._lock:
            if self._holding or self._closed:
                return
            self._holding = True
            gen = self._command_gen
        self._spawn("rosbridge-stop-hold", lambda: self._run_hold(gen))

    def _run_hold(self, gen: int) -> None:
        c = self.config
        period = 1.0 / c.stop_hold_rate_hz
        try:
            line = self._open_stop_line() if self._connected else None
            if line is not None:  # the cancel again, where a blocked connection cannot hold it up
                nav = roslibpy.ActionClient(line[0], c.name(c.nav_action), rm.NAVIGATE_THROUGH_POSES)
                for task in self._pending_cancels():
                    if task.goal_id:
                        nav.cancel_goal(task.goal_id)
            while not self._closed and self._command_gen == gen and self._pending_cancels():
                if line is not None and line[0].is_connected:
                    line[1].publish(roslibpy.Message(rm.cmd_vel(0.0, 0.0, c.cmd_vel_stamped, c.base_frame)))
                elif self._connected:
                    self._send_stop()
                time.sleep(period)
        finally:
            with self._lock:
                self._holding = False
            # a cancel that came in as this loop was ending still gets its hold
            if not self._closed and self._command_gen == gen and self._pending_cancels():
                self._hold_stop()

    def wait_stopped(self, timeout_s: float | None = None) -> None:
        """Block until every cancelled goal is confirmed ended (default limit: ``cancel_timeout_s``
        and a second); raise :class:`RobotError` when a stop was not confirmed: the robot may still
        be moving, and the message says what to do."""
        limit = self.config.cancel_timeout_s + 1.0 if timeout_s is None else timeout_s
        deadline = time.monotonic() + limit
        while self._pending_cancels() and time.monotonic() < deadline:
            time.sleep(_POLL_S)
        if self._stop_unconfirmed is not None:
            raise RobotError(self._stop_unconfirmed)
        if self._pending_cancels():
            raise RobotTimeout(f"the robot has not confirmed the cancel within {limit} s; zero velocity is "
                               f"still being held on {self.config.name(self.config.cmd_vel_topic)}")

    def _add_task(self, task: _Task) -> None:
        with self._lock:
            self._tasks.add(task)

    def _end_task(self, task: _Task) -> None:
        with self._lock:
            self._tasks.discard(task)

    def navigate_through_poses(self, poses: list[tuple[float, float] | tuple[float, float, float]]) -> TaskHandle:
        self._require_connection()
        if not poses:
            raise RobotError("navigate_through_poses needs at least one pose")
        c = self.config
        targets = self._targets(poses)
        goal = rm.navigate_through_poses_goal(targets, c.map_frame, c.goal_format, c.behavior_tree)
        self._new_command()
        task = _Task(f"navigate through {len(targets)} pose(s)", self._cancel_nav, goal=True)
        goal_id: list[str] = []

        def on_outcome(result: Any, accepted: bool) -> None:
            get = result.get if hasattr(result, "get") else (lambda _k: None)
            status, message = goal_outcome(get("status"), get("values") if hasattr(result, "get") else result,
                                           accepted, c.name(c.nav_action))
            task.finish(status, message, self._cached_pose())

        def on_result(result: Any) -> None:
            on_outcome(result, True)

        def on_error(result: Any) -> None:
            on_outcome(result, False)

        def on_feedback(values: Any) -> None:
            try:
                task.set_feedback(rm.parse_navigate_through_poses_feedback(dict(values), c.name(c.nav_action)))
            except RobotError as exc:
                if task.finish(TaskStatus.FAILED, f"{exc}; the goal was cancelled and the robot stopped",
                               self._cached_pose()):
                    self._cancel_goal_id(goal_id)
                    self._send_stop()

        self._add_task(task)
        goal_id.append(self._nav.send_goal(roslibpy.Goal(goal), on_result, on_feedback, on_error))
        task.goal_id = goal_id[0]
        self._watch(task, self._nav_watchdog)
        return task

    def _targets(self, poses: list[tuple[float, float] | tuple[float, float, float]]) -> list[Pose2D]:
        """(x, y[, yaw_deg]) -> poses; a pose without yaw faces along the leg that reaches it."""
        prev = self._cached_pose()
        out: list[Pose2D] = []
        for p in poses:
            if len(p) not in (2, 3) or not all(math.isfinite(v) for v in p):
                raise RobotError(f"a pose is (x, y) or (x, y, yaw_deg) in metres and degrees, got {p!r}")
            x, y = float(p[0]), float(p[1])
            if len(p) == 3:
                yaw = math.radians(p[2])  # type: ignore[misc]
            elif prev is not None and math.hypot(x - prev.x_m, y - prev.y_m) > 1e-6:
                yaw = math.atan2(y - prev.y_m, x - prev.x_m)
            else:
                yaw = prev.yaw_rad if prev is not None else 0.0
            pose = Pose2D(x, y, yaw)
            out.append(pose)
            prev = pose
        return out

    def _cancel_nav(self, task: _Task) -> None:
        self._cancel_goal_id([task.goal_id])
        self._hold_stop()

    def _cancel_goal_id(self, goal_id: list[str]) -> None:
        if goal_id and goal_id[0]:
            self._nav.cancel_goal(goal_id[0])

    def _watch(self, task: _Task, check: Callable[[_Task], None]) -> None:
        def run() -> None:
            try:
                while not task.done:
                    check(task)
                    time.sleep(0.05)
            finally:
                self._end_task(task)

        self._spawn(f"rosbridge-{task.kind}", run)

    def _nav_watchdog(self, task: _Task) -> None:
        c = self.config
        now = time.monotonic()
        if task.cancel_requested_s is not None and now - task.cancel_requested_s > c.cancel_timeout_s:
            message = (
                f"THE ROBOT MAY STILL BE MOVING: {c.name(c.nav_action)} did not confirm the cancel within "
                f"{c.cancel_timeout_s} s. langnav held zero velocity on {c.name(c.cmd_vel_topic)} at "
                f"{c.stop_hold_rate_hz:g} Hz meanwhile, but Nav2's controller keeps driving until the goal "
                f"really ends. Stop the robot at the robot (its stop button or emergency stop), then restart "
                f"rosbridge with `send_action_goals_in_new_thread:=true`: without it rosbridge reads nothing "
                f"(a cancel neither) while a goal runs")
            if task.finish(TaskStatus.FAILED, message, self._cached_pose()):
                with self._lock:
                    self._stop_unconfirmed = message
                log.error("%s", message)
        elif now - task.last_news_s > c.feedback_timeout_s:
            self._cancel_goal_id([task.goal_id])
            self._send_stop()
            task.finish(TaskStatus.FAILED, f"no feedback from {c.name(c.nav_action)} for {c.feedback_timeout_s} s; "
                        f"the goal was cancelled and the robot stopped", self._cached_pose())

    # -- Move / Rotate by cmd_vel ----------------------------------------------------------------
    def move(self, direction: str, steps: int) -> TaskHandle:
        if direction not in ("forward", "backward", "left", "right"):
            raise RobotError(f"move direction must be forward, backward, left or right, got {direction!r}")
        if steps < 1:
            raise RobotError(f"move needs at least one step, got {steps}")
        dist = steps * MOVE_STEP_M
        phases: list[tuple[str, float]]
        if direction == "forward":
            phases = [("drive", dist)]
        elif direction == "backward":
            phases = [("drive", -dist)]
        else:  # a differential base turns, drives, and turns back
            side = math.pi / 2 if direction == "left" else -math.pi / 2
            phases = [("turn", side), ("drive", dist), ("turn", -side)]
        return self._start_motion(f"move {direction} {dist:.2f} m", phases)

    def rotate(self, direction: str, steps: int) -> TaskHandle:
        if direction not in ("left", "right"):
            raise RobotError(f"rotate direction must be left or right, got {direction!r}")
        if steps < 1:
            raise RobotError(f"rotate needs at least one step, got {steps}")
        angle = math.radians(steps * ROTATE_STEP_DEG)
        return self._start_motion(f"rotate {direction} {math.degrees(angle):.0f}°",
                                  [("turn", angle if direction == "left" else -angle)])

    def _start_motion(self, kind: str, phases: list[tuple[str, float]]) -> TaskHandle:
        self._require_connection()
        with self._lock:
            running = list(self._tasks)
        for t in running:  # one motion at a time: a new command replaces the old
            t.cancel()
        self._new_command()
        task = _Task(kind, lambda _t: None)
        self._add_task(task)
        self._spawn(f"rosbridge-{kind}", lambda: self._run_motion(task, phases))
        return task

    def _motion_pose(self) -> tuple[Pose2D, float] | None:
        if self.config.motion_pose_source == "odom":
            odom = self._odom()
            return None if odom is None else (odom[0], odom[3])
        p = self._pose_now()
        return None if p is None else (p, time.monotonic())

    def _run_motion(self, task: _Task, phases: list[tuple[str, float]]) -> None:
        try:
            for kind, amount in phases:
                if not self._run_phase(task, kind, amount):
                    return
            task.finish(TaskStatus.SUCCEEDED, f"{task.kind} done", self._cached_pose())
        except RobotError as exc:
            self._send_stop()
            task.finish(TaskStatus.FAILED, f"{task.kind}: {exc}; the robot was stopped", self._cached_pose())
        finally:
            self._end_task(task)

    def _run_phase(self, task: _Task, kind: str, amount: float) -> bool:
        """Drive (metres, signed) or turn (radians, signed) closed-loop; False when the task ended."""
        c = self.config
        linear = kind == "drive"
        speed = c.linear_speed_mps if linear else c.angular_speed_radps
        min_speed = c.min_linear_speed_mps if linear else c.min_angular_speed_radps
        tol = c.distance_tolerance_m if linear else c.angle_tolerance_rad
        limit_s = abs(amount) / speed * c.motion_timeout_factor + c.motion_slack_s
        start_s = time.monotonic()
        first = self._motion_pose()
        while first is None:
            self._require_connection()
            if time.monotonic() - start_s > c.odom_stale_s:
                raise RobotError(f"no odometry on {c.name(c.odom_topic)} within {c.odom_stale_s} s; "
                                 f"is the base driver running?")
            time.sleep(_POLL_S)
            first = self._motion_pose()
        start = first[0]
        last_yaw, turned = start.yaw_rad, 0.0
        period = 1.0 / c.cmd_rate_hz
        sign = 1.0 if amount >= 0 else -1.0
        while True:
            if task.done:
                self._send_stop()
                return False
            if task.cancel_requested_s is not None:
                self._send_stop()
                task.finish(TaskStatus.CANCELED, f"{task.kind} canceled", self._cached_pose())
                return False
            self._require_connection()
            now = time.monotonic()
            got = self._motion_pose()
            assert got is not None
            cur, received_s = got
            if now - received_s > c.odom_stale_s:
                raise RobotError(f"odometry stopped arriving (last one {now - received_s:.1f} s ago)")
            if now - start_s > limit_s:
                raise RobotError(f"did not finish within {limit_s:.1f} s (blocked, or the base ignores cmd_vel "
                                 f"on {c.name(c.cmd_vel_topic)}?)")
            if linear:
                dx, dy = cur.x_m - start.x_m, cur.y_m - start.y_m
                done = dx * math.cos(start.yaw_rad) + dy * math.sin(start.yaw_rad)
            else:
                turned += rm.wrap_angle(cur.yaw_rad - last_yaw)
                last_yaw = cur.yaw_rad
                done = turned
            remaining = (amount - done) * sign
            task.set_feedback(TaskFeedback(pose=cur, distance_remaining_m=max(0.0, remaining) if linear else None,
                                           elapsed_s=now - start_s, message=f"{kind} {max(0.0, remaining):.3f} left"))
            if remaining <= tol:
                self._publish_cmd(0.0, 0.0)
                return True
            v = sign * min(speed, max(min_speed, c.slowdown_gain_per_s * remaining))
            self._publish_cmd(v, 0.0) if linear else self._publish_cmd(0.0, v)
            time.sleep(period)


def _factory(**options: Any) -> RosbridgeBackend:
    return RosbridgeBackend(**options)


register_backend("rosbridge", _factory)
