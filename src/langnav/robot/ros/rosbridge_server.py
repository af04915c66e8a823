"""Serve any :class:`RobotBackend` as a ROS 2 robot over the rosbridge v2 JSON protocol.

One asyncio WebSocket server (``websockets``), one task per client, no fragments. Requests are
JSON text; topics are sent as JSON, or, when a subscription asks for ``compression: "cbor"`` or
``"cbor-raw"``, as binary CBOR frames (``cbor-raw``: the message's CDR bytes, as rosbridge_suite
sends them, which is what Foxglove's rosbridge connection asks for and decodes with the
definitions from ``/rosapi/topics_and_raw_types``). Shapes follow the ROS 2 message definitions
(:mod:`langnav.robot.ros.interfaces`), so Foxglove, roslibjs pages and roslibpy scripts
(langnav's own ``rosbridge`` backend among them) can watch and drive the robot as if it were a
TurtleBot running Nav2 behind rosbridge_suite.

What it offers (names configurable in :class:`RosbridgeServerConfig`):

=====================  ==========================================  ==============================
name                   type                                        notes
=====================  ==========================================  ==============================
/map                   nav_msgs/msg/OccupancyGrid                  latched: sent on subscribe,
                                                                   then whenever it changes
/scan                  sensor_msgs/msg/LaserScan                   no return -> null
/plan                  nav_msgs/msg/Path                           when the path changes
/tf                    tf2_msgs/msg/TFMessage                      odom -> base_link
/tf_static             tf2_msgs/msg/TFMessage                      map -> odom (identity), latched
/odom                  nav_msgs/msg/Odometry                       pose and body twist
/amcl_pose             geometry_msgs/msg/PoseWithCovarianceStamped pose in map
/rosout                rcl_interfaces/msg/Log                      langnav's log records (what the
                                                                   logging setup lets through)
/cmd_vel (subscribed)  geometry_msgs/msg/Twist or TwistStamped     only for backends with
                                                                   ``set_velocity``; zeroed when
                                                                   commands stop for 0.5 s
/navigate_through_poses nav2_msgs/action/NavigateThroughPoses      feedback, result, cancel
/langnav/get_robot_pose langnav_interfaces/srv/GetRobotPose        response ``{"pose": PoseStamped}``
/map_server/map        nav_msgs/srv/GetMap                         response ``{"map": ...}``
/langnav/stop          std_srvs/srv/Trigger                        stops the robot
/rosapi/topics         rosapi_msgs/srv/Topics                      ``{"topics", "types"}``
/rosapi/topics_and_raw_types rosapi_msgs/srv/TopicsAndRawTypes     ``{"topics", "types",
                                                                   "typedefs_full_text"}``
=====================  ==========================================  ==============================

Anything malformed (bad JSON, no ``op``, an unknown op, a topic or service it does not have, a
message that does not match its type) is answered with a rosbridge ``status`` message of level
``error`` carrying the request's ``id``; the server never crashes on input. Goals follow Nav2's
action server: a new goal preempts (aborts) the running one; ``action_result`` carries
``status`` as in ``action_msgs/msg/GoalStatus`` (4 succeeded, 5 canceled, 6 aborted) and
``result: true``, or ``status: 0, result: false`` with a reason string when the goal could not
be run at all (as rosbridge_suite does). When a client disconnects, the goals it sent are
cancelled and a velocity it commanded is zeroed: a dropped link leaves a stopped robot.
"""

from __future__ import annotations

import asyncio
import collections
import contextlib
import hashlib
import itertools
import json
import logging
import math
import threading
import time
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from typing import Any, Final, Protocol, TypeVar, runtime_checkable

import cbor2
from pydantic import BaseModel, ConfigDict, Field
from websockets.asyncio.server import Server, ServerConnection, serve
from websockets.exceptions import ConnectionClosed

from langnav.errors import LangnavError
from langnav.robot.errors import RobotError, RobotTimeout
from langnav.robot.protocol import Pose2D, RobotBackend, TaskHandle, TaskStatus
from langnav.robot.ros import interfaces as ri
from langnav.robot.ros import messages as rm

log = logging.getLogger(__name__)

#: Nav2's generic error code (NavigateToPose's UNKNOWN=9000) for a goal that failed for a reason.
NAV2_ERROR_UNKNOWN: Final = 9000
#: Waiting for the server thread to come up or shut down.
DEFAULT_START_TIMEOUT_S: Final = 10.0
#: A mapping robot's map grows; comparing a digest of the cells avoids resending an unchanged one.
_DIGEST: Final = hashlib.blake2b

GET_ROBOT_POSE_SRV: Final = "langnav_interfaces/srv/GetRobotPose"
TOPICS_SRV: Final = "rosapi_msgs/srv/Topics"
TOPICS_AND_RAW_TYPES_SRV: Final = "rosapi_msgs/srv/TopicsAndRawTypes"
LOG: Final = "rcl_interfaces/msg/Log"
#: Subscription encodings: rosbridge's "none" (JSON), "cbor" (the JSON values as CBOR) and
#: "cbor-raw" (the CDR bytes in a CBOR envelope). rosbridge's "png" is not offered.
COMPRESSIONS: Final = ("none", "cbor", "cbor-raw")
#: /rosout keeps at most this many records waiting for the next publish (a burst drops the oldest).
ROSOUT_BACKLOG: Final = 200
#: rcl_interfaces/msg/Log levels (rcutils' severities are Python's logging levels).
_LOG_LEVELS: Final = ((logging.CRITICAL, 50), (logging.ERROR, 40), (logging.WARNING, 30), (logging.INFO, 20))

T = TypeVar("T")


@runtime_checkable
class VelocityCommandable(Protocol):
    """A backend that can be driven by velocity (teleop, ``/cmd_vel``); optional."""

    def set_velocity(self, linear_mps: float, angular_radps: float) -> None: ...


class RosbridgeServerConfig(BaseModel):
    """Names, frames and rates of the served robot."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    map_topic: str = "/map"
    scan_topic: str = "/scan"
    plan_topic: str = "/plan"
    tf_topic: str = "/tf"
    tf_static_topic: str = "/tf_static"
    odom_topic: str = "/odom"
    pose_topic: str = "/amcl_pose"
    cmd_vel_topic: str = "/cmd_vel"
    nav_action: str = "/navigate_through_poses"
    get_pose_service: str = "/langnav/get_robot_pose"
    get_map_service: str = "/map_server/map"
    stop_service: str = "/langnav/stop"
    topics_service: str = "/rosapi/topics"
    topics_and_raw_types_service: str = "/rosapi/topics_and_raw_types"
    rosout_topic: str = "/rosout"
    #: /rosout carries the records of this logger and its children at this level and above.
    rosout_logger: str = "langnav"
    rosout_level: int = Field(default=logging.INFO, ge=0)
    map_frame: str = "map"
    odom_frame: str = "odom"
    base_frame: str = "base_link"
    scan_frame: str = "base_link"
    #: tf, odom and pose: Create 3 publishes odometry at 20 Hz; 10 Hz is plenty for a display.
    state_rate_hz: float = Field(default=10.0, gt=0, le=100)
    #: RPLIDAR A1 on a TurtleBot 4 spins at ~7 Hz.
    scan_rate_hz: float = Field(default=5.0, gt=0, le=50)
    plan_rate_hz: float = Field(default=2.0, gt=0, le=50)
    #: slam_toolbox's default map_update_interval is 5 s; checking every second is prompt enough.
    map_rate_hz: float = Field(default=1.0, gt=0, le=20)
    #: Nav2's bt_navigator sends feedback every BT tick (10-100 Hz); 5 Hz is enough over a WebSocket.
    feedback_rate_hz: float = Field(default=5.0, gt=0, le=50)
    #: Zero the velocity when no cmd_vel came for this long (Create 3 uses 0.5 s too).
    cmd_vel_timeout_s: float = Field(default=0.5, gt=0)
    #: Limit on one backend call made for a client (pose, map, starting a goal).
    backend_call_timeout_s: float = Field(default=10.0, gt=0)

    # -- behaving like the real servers robots run (for testing clients against them) --------------
    #: rosbridge_suite before PR #996 (Jan 2025; launch argument send_action_goals_in_new_thread
    #: false) runs a goal on the thread that reads the client's socket: nothing else that client
    #: sends, a cancel among it, is read until the goal has ended.
    goals_on_main_thread: bool = False
    #: rosbridge-server-rs answers a goal that did not succeed (5 canceled, 6 aborted) with
    #: ``result: false`` next to its status code; rosbridge_suite says ``result: true``.
    result_false_unless_succeeded: bool = False
    #: A subscription to a latched topic made this soon after the server started gets no latched
    #: message, as with a fresh rosbridge that has not yet discovered the transient-local publisher
    #: (its subscription is then volatile); the map counts as published once before the start.
    latched_discovery_s: float = Field(default=0.0, ge=0)


@dataclass
class _Goal:
    goal_id: str
    action: str
    task: asyncio.Task[None] | None = None
    handle: TaskHandle | None = None
    cancel_requested: bool = False
    preempted: bool = False


@dataclass(eq=False)
class _Client:
    ws: ServerConnection
    number: int
    subscriptions: dict[str, set[str]] = field(default_factory=dict)
    #: topic -> how this client wants it encoded (one of COMPRESSIONS)
    compression: dict[str, str] = field(default_factory=dict)
    advertised: dict[str, str] = field(default_factory=dict)
    goals: dict[str, _Goal] = field(default_factory=dict)
    drove_velocity: bool = False


@dataclass(frozen=True)
class _TopicSpec:
    msg_type: str
    latched: bool = False


class RosbridgeServer:
    """A rosbridge v2 server for one backend. Use :meth:`start` / :meth:`stop` from sync code
    (a thread with its own event loop) or ``await serve(...)`` inside a running loop."""

    def __init__(self, backend: RobotBackend, config: RosbridgeServerConfig | None = None) -> None:
        self.backend = backend
        self.config = config or RosbridgeServerConfig()
        c = self.config
        self._topics: dict[str, _TopicSpec] = {
            c.map_topic: _TopicSpec(rm.OCCUPANCY_GRID, latched=True),
            c.scan_topic: _TopicSpec(rm.LASER_SCAN),
            c.plan_topic: _TopicSpec(rm.PATH),
            c.tf_topic: _TopicSpec(rm.TF_MESSAGE),
            c.tf_static_topic: _TopicSpec(rm.TF_MESSAGE, latched=True),
            c.odom_topic: _TopicSpec(rm.ODOMETRY),
            c.pose_topic: _TopicSpec(rm.POSE_WITH_COV_STAMPED),
            c.rosout_topic: _TopicSpec(LOG),
        }
        self._services: dict[str, str] = {
            c.get_pose_service: GET_ROBOT_POSE_SRV,
            c.get_map_service: rm.GET_MAP_SRV,
            c.stop_service: rm.TRIGGER_SRV,
            c.topics_service: TOPICS_SRV,
            c.topics_and_raw_types_service: TOPICS_AND_RAW_TYPES_SRV,
        }
        self._rosout = _RosoutHandler(c.rosout_level)
        self._clients: set[_Client] = set()
        self._numbers = itertools.count(1)
        self._latched: dict[str, dict[str, Any]] = {}
        self._map_digest: bytes | None = None
        self._last_path: tuple[tuple[float, float], ...] | None = None
        self._active_goal: _Goal | None = None
        self._last_cmd_vel_s: float | None = None
        self._executor = ThreadPoolExecutor(max_workers=4, thread_name_prefix="rosbridge-backend")
        self._thread: threading.Thread | None = None
        self._loop: asyncio.AbstractEventLoop | None = None
        self._stop_event: asyncio.Event | None = None
        self._ready = threading.Event()
        self._start_error: BaseException | None = None
        self._started_s = 0.0
        self.port: int | None = None

    # -- lifecycle -------------------------------------------------------------------------------
    def start(self, host: str = "127.0.0.1", port: int = 0, timeout_s: float = DEFAULT_START_TIMEOUT_S) -> int:
        """Serve in a background thread; returns the bound port (``port=0`` picks a free one)."""
        if self._thread is not None:
            raise RobotError("the rosbridge server is already running; stop() it first")
        self._ready.clear()
        self._start_error = None
        self._thread = threading.Thread(target=self._thread_main, args=(host, port), daemon=True,
                                        name=f"rosbridge-server-{port}")
        self._thread.start()
        if not self._ready.wait(timeout_s):
            raise RobotTimeout(f"the rosbridge server did not start on {host}:{port} within {timeout_s} s")
        if self._start_error is not None:
            self._thread = None
            raise RobotError(f"cannot serve rosbridge on {host}:{port}: {self._start_error}") from self._start_error
        assert self.port is not None
        return self.port

    def stop(self, timeout_s: float = DEFAULT_START_TIMEOUT_S) -> None:
        """Close every connection (clients see the link drop) and stop serving."""
        loop, thread = self._loop, self._thread
        if loop is not None and self._stop_event is not None and not loop.is_closed():
            with contextlib.suppress(RuntimeError):
                loop.call_soon_threadsafe(self._stop_event.set)
        if thread is not None:
            thread.join(timeout_s)
            if thread.is_alive():
                raise RobotTimeout(f"the rosbridge server did not stop within {timeout_s} s")
        self._thread = None

    def close(self) -> None:
        self.stop()
        self._executor.shutdown(wait=False, cancel_futures=True)

    def _thread_main(self, host: str, port: int) -> None:
        try:
            asyncio.run(self.serve(host, port))
        except BaseException as exc:  # surfaced by start(); the thread must not die silently
            if not self._ready.is_set():
                self._start_error = exc
                self._ready.set()
            else:
                log.exception("rosbridge server stopped with an error")

    async def serve(self, host: str, port: int, on_ready: Callable[[int], None] | None = None) -> None:
        """Serve until :meth:`stop` (or cancellation)."""
        self._loop = asyncio.get_running_loop()
        self._stop_event = asyncio.Event()
        self._started_s = time.monotonic()
        if self.config.latched_discovery_s > 0:
            await self._publish_map(force=True)  # published before anyone could receive it
        async with serve(self._connection, host, port, max_size=None, compression=None) as server:
            self.port = _bound_port(server)
            log.info("rosbridge server for %s listening on ws://%s:%d", self.backend.name, host, self.port)
            streams = [asyncio.create_task(coro) for coro in (
                self._stream(self.config.state_rate_hz, self._publish_state),
                self._stream(self.config.scan_rate_hz, self._publish_scan),
                self._stream(self.config.plan_rate_hz, self._publish_plan),
                self._stream(self.config.map_rate_hz, self._publish_map),
                self._stream(1.0 / self.config.cmd_vel_timeout_s, self._cmd_vel_watchdog),
                self._stream(self.config.state_rate_hz, self._publish_rosout),
            )]
            rosout_logger = logging.getLogger(self.config.rosout_logger)
            rosout_logger.addHandler(self._rosout)
            self._ready.set()
            if on_ready is not None:
                on_ready(self.port)
            try:
                await self._stop_event.wait()
            finally:
                rosout_logger.removeHandler(self._rosout)
                for t in streams:
                    t.cancel()
                for client in list(self._clients):
                    await self._drop_client(client)
                    await client.ws.close(1001, "langnav rosbridge server shutting down")
                server.close()
        log.info("rosbridge server stopped")

    # -- helpers -----------------------------------------------------------------------------------
    async def _call(self, fn: Callable[..., T], *args: Any) -> T:
        loop = asyncio.get_running_loop()
        try:
            return await asyncio.wait_for(loop.run_in_executor(self._executor, fn, *args),
                                          self.config.backend_call_timeout_s)
        except TimeoutError:
            raise RobotTimeout(f"the {self.backend.name} backend did not answer "
                               f"{getattr(fn, '__name__', fn)} within {self.config.backend_call_timeout_s} s") from None

    async def _send(self, client: _Client, message: dict[str, Any] | bytes) -> None:
        """Send a JSON message, or an already encoded binary (CBOR) frame."""
        data: str | bytes
        if isinstance(message, bytes):
            data = message
        else:
            try:
                data = json.dumps(message, allow_nan=False)
            except (TypeError, ValueError) as exc:
                log.error("cannot encode %s for client %d: %s", message.get("op"), client.number, exc)
                data = json.dumps({"op": "status", "level": "error", "msg": f"server could not encode a "
                                   f"{message.get('op')} message: {exc}"})
        with contextlib.suppress(ConnectionClosed):
            await client.ws.send(data)

    async def _status(self, client: _Client, level: str, msg: str, mid: Any = None) -> None:
        log.info("client %d: %s: %s", client.number, level, msg)
        out: dict[str, Any] = {"op": "status", "level": level, "msg": msg}
        if mid is not None:
            out["id"] = mid
        await self._send(client, out)

    def _subscribers(self, topic: str) -> list[_Client]:
        return [c for c in self._clients if c.subscriptions.get(topic)]

    async def _publish(self, topic: str, msg: dict[str, Any]) -> None:
        spec = self._topics[topic]
        if spec.latched:
            self._latched[topic] = msg
        frames = _Frames(topic, spec.msg_type, msg)
        for client in self._subscribers(topic):
            await self._send_frame(client, frames)

    async def _send_frame(self, client: _Client, frames: _Frames) -> None:
        mode = client.compression.get(frames.topic, "none")
        try:
            await self._send(client, frames.encoded(mode))
        except LangnavError as exc:  # a message that does not fit its own definition: a bug, say so
            log.error("cannot encode %s as %s for client %d: %s", frames.topic, mode, client.number, exc)
            await self._status(client, "error", f"server could not encode {frames.topic} as {mode}: {exc}")

    # -- periodic streams ----------------------------------------------------------------------
    async def _stream(self, rate_hz: float, step: Callable[[], Any]) -> None:
        period = 1.0 / rate_hz
        while True:
            try:
                await step()
            except asyncio.CancelledError:
                raise
            except (LangnavError, OSError) as exc:
                log.warning("rosbridge stream %s: %s", getattr(step, "__name__", step), exc)
            await asyncio.sleep(period)

    async def _publish_state(self) -> None:
        c = self.config
        wanted = [t for t in (c.tf_topic, c.odom_topic, c.pose_topic) if self._subscribers(t)]
        if not wanted:
            return
        st = await self._call(self.backend.state)
        now = time.time()
        if c.tf_topic in wanted:
            await self._publish(c.tf_topic, rm.tf_message(
                [rm.transform_stamped(c.odom_frame, c.base_frame, st.pose, now)]))
        if c.odom_topic in wanted:
            await self._publish(c.odom_topic, rm.odometry(st.pose, st.linear_mps, st.angular_radps,
                                                          c.odom_frame, c.base_frame, now))
        if c.pose_topic in wanted:
            await self._publish(c.pose_topic, rm.pose_with_covariance_stamped(st.pose, c.map_frame, now))

    async def _publish_scan(self) -> None:
        if not self._subscribers(self.config.scan_topic):
            return
        st = await self._call(self.backend.state)
        if st.scan is not None:
            await self._publish(self.config.scan_topic, rm.laser_scan(st.scan, self.config.scan_frame))

    async def _publish_plan(self) -> None:
        if not self._subscribers(self.config.plan_topic):
            self._last_path = None
            return
        pts = tuple(await self._call(self.backend.get_current_path))
        if pts != self._last_path:
            self._last_path = pts
            await self._publish(self.config.plan_topic, rm.path(pts, self.config.map_frame))

    async def _publish_map(self, force: bool = False) -> None:
        if not force and not self._subscribers(self.config.map_topic):
            return
        grid = await self._call(self.backend.get_map)
        digest = _DIGEST(grid.cells.tobytes() + repr((grid.resolution_m, grid.origin_x_m, grid.origin_y_m,
                                                     grid.origin_yaw_rad, grid.cells.shape)).encode()).digest()
        if force or digest != self._map_digest or self.config.map_topic not in self._latched:
            self._map_digest = digest
            await self._publish(self.config.map_topic, rm.occupancy_grid(grid, self.config.map_frame))

    async def _publish_rosout(self) -> None:
        records = self._rosout.drain()
        if not self._subscribers(self.config.rosout_topic):
            return
        for record in records:
            await self._publish(self.config.rosout_topic, _log_message(record))

    async def _cmd_vel_watchdog(self) -> None:
        last = self._last_cmd_vel_s
        if last is not None and time.monotonic() - last > self.config.cmd_vel_timeout_s:
            self._last_cmd_vel_s = None
            if isinstance(self.backend, VelocityCommandable):
                log.info("no %s for %.1f s: stopping", self.config.cmd_vel_topic, self.config.cmd_vel_timeout_s)
                await self._call(self.backend.set_velocity, 0.0, 0.0)

    # -- connections -----------------------------------------------------------------------------
    async def _connection(self, ws: ServerConnection) -> None:
        client = _Client(ws, next(self._numbers))
        self._clients.add(client)
        log.info("rosbridge client %d connected from %s", client.number, ws.remote_address)
        try:
            async for raw in ws:
                await self._handle_raw(client, raw)
        except ConnectionClosed:
            pass
        finally:
            await self._drop_client(client)
            log.info("rosbridge client %d disconnected (close code %s)", client.number, ws.close_code)

    async def _drop_client(self, client: _Client) -> None:
        if client not in self._clients:
            return
        self._clients.discard(client)
        for goal in list(client.goals.values()):
            goal.cancel_requested = True
            if goal.handle is not None:
                with contextlib.suppress(LangnavError):
                    await self._call(goal.handle.cancel)
            if goal.task is not None:
                goal.task.cancel()
        if client.drove_velocity and isinstance(self.backend, VelocityCommandable):
            with contextlib.suppress(LangnavError):
                await self._call(self.backend.set_velocity, 0.0, 0.0)

    async def _handle_raw(self, client: _Client, raw: str | bytes) -> None:
        if isinstance(raw, bytes):
            await self._status(client, "error", "binary (CBOR/BSON) messages are not supported; send JSON text")
            return
        try:
            msg = json.loads(raw)
        except json.JSONDecodeError as exc:
            await self._status(client, "error", f"malformed JSON: {exc}")
            return
        if not isinstance(msg, dict):
            await self._status(client, "error", f"a rosbridge message must be a JSON object, got {type(msg).__name__}")
            return
        mid = msg.get("id")
        op = msg.get("op")
        handler = self._ops.get(op) if isinstance(op, str) else None
        if handler is None:
            what = "a message without an 'op'" if op is None else f"unknown operation {op!r}"
            await self._status(client, "error", f"{what}; supported: {', '.join(sorted(self._ops))}", mid)
            return
        try:
            await handler(self, client, msg)
        except (LangnavError, KeyError, TypeError, ValueError) as exc:
            await self._status(client, "error", f"{op}: {exc}", mid)

    # -- topic ops -------------------------------------------------------------------------------
    def _topic_name(self, msg: dict[str, Any]) -> str:
        topic = msg.get("topic")
        if not isinstance(topic, str) or not topic:
            raise RobotError("missing 'topic' (a string)")
        return topic

    async def _op_subscribe(self, client: _Client, msg: dict[str, Any]) -> None:
        topic = self._topic_name(msg)
        spec = self._topics.get(topic)
        if spec is None:
            raise RobotError(f"no topic {topic!r}; available: {', '.join(sorted(self._topics))}")
        wanted = msg.get("type")
        if wanted and _normal_type(wanted) != _normal_type(spec.msg_type):
            raise RobotError(f"topic {topic} has type {spec.msg_type}, not {wanted}")
        compression = msg.get("compression") or "none"
        if compression not in COMPRESSIONS:
            await self._status(client, "warning", f"compression {compression!r} is not supported "
                               f"(only {', '.join(COMPRESSIONS)}); sending {topic} as JSON", msg.get("id"))
            compression = "none"
        sub_id = str(msg.get("id") or f"subscribe:{topic}")
        first = not client.subscriptions.get(topic)
        client.subscriptions.setdefault(topic, set()).add(sub_id)
        if first or compression == "cbor-raw":  # as rosbridge: cbor-raw wins over the others
            client.compression[topic] = compression
        discovering = time.monotonic() - self._started_s < self.config.latched_discovery_s
        if spec.latched and first and not discovering:
            await self._send_latched(client, topic)

    async def _send_latched(self, client: _Client, topic: str) -> None:
        if topic == self.config.tf_static_topic:
            self._latched[topic] = rm.tf_message([rm.transform_stamped(
                self.config.map_frame, self.config.odom_frame, Pose2D(0.0, 0.0, 0.0))])
        elif topic == self.config.map_topic and topic not in self._latched:
            await self._publish_map(force=True)
            return  # _publish sent it to every subscriber, this client included
        latched = self._latched.get(topic)
        if latched is not None:
            await self._send_frame(client, _Frames(topic, self._topics[topic].msg_type, latched))

    async def _op_unsubscribe(self, client: _Client, msg: dict[str, Any]) -> None:
        topic = self._topic_name(msg)
        subs = client.subscriptions.get(topic)
        if not subs:
            await self._status(client, "warning", f"not subscribed to {topic}", msg.get("id"))
            return
        if msg.get("id") is None:
            subs.clear()
        else:
            subs.discard(str(msg["id"]))

    async def _op_advertise(self, client: _Client, msg: dict[str, Any]) -> None:
        topic = self._topic_name(msg)
        msg_type = msg.get("type")
        if not isinstance(msg_type, str):
            raise RobotError("advertise needs a 'type'")
        if topic != self.config.cmd_vel_topic:
            raise RobotError(f"this robot takes commands on {self.config.cmd_vel_topic} only, not {topic}")
        if _normal_type(msg_type) not in (_normal_type(rm.TWIST), _normal_type(rm.TWIST_STAMPED)):
            raise RobotError(f"{topic} takes {rm.TWIST} or {rm.TWIST_STAMPED}, not {msg_type}")
        client.advertised[topic] = msg_type

    async def _op_unadvertise(self, client: _Client, msg: dict[str, Any]) -> None:
        topic = self._topic_name(msg)
        if client.advertised.pop(topic, None) is None:
            await self._status(client, "warning", f"{topic} was not advertised", msg.get("id"))

    async def _op_publish(self, client: _Client, msg: dict[str, Any]) -> None:
        topic = self._topic_name(msg)
        if topic != self.config.cmd_vel_topic:
            if topic in self._topics:
                raise RobotError(f"{topic} is published by the robot; it cannot be written to")
            raise RobotError(f"no topic {topic!r} to publish to; this robot takes {self.config.cmd_vel_topic}")
        if not isinstance(self.backend, VelocityCommandable):
            raise RobotError(f"the {self.backend.name} backend cannot be driven by velocity; "
                             f"use the {self.config.nav_action} action instead")
        linear, angular = rm.parse_cmd_vel(msg.get("msg"))
        self._last_cmd_vel_s = time.monotonic()
        client.drove_velocity = True
        await self._call(self.backend.set_velocity, linear, angular)

    # -- services --------------------------------------------------------------------------------
    async def _op_call_service(self, client: _Client, msg: dict[str, Any]) -> None:
        service = msg.get("service")
        mid = msg.get("id")
        c = self.config
        if not isinstance(service, str) or service not in self._services:
            reason = (f"Service {service} does not exist; available: {', '.join(sorted(self._services))}")
            await self._status(client, "error", reason, mid)
            await self._service_response(client, str(service), mid, reason, ok=False)
            return
        try:
            values: dict[str, Any] | str
            if service == c.get_pose_service:
                p = await self._call(self.backend.get_robot_pose)
                values = {"pose": rm.pose_stamped(p, c.map_frame)}
            elif service == c.get_map_service:
                grid = await self._call(self.backend.get_map)
                values = {"map": rm.occupancy_grid(grid, c.map_frame)}
            elif service == c.stop_service:
                await self._stop_everything()
                values = {"success": True, "message": "stopped"}
            else:  # rosapi: topics, topics_and_raw_types
                names = [*sorted(self._topics), c.cmd_vel_topic]
                types = [*(self._topics[n].msg_type for n in names[:-1]), rm.TWIST]
                values = {"topics": names, "types": types}
                if service == c.topics_and_raw_types_service:
                    values["typedefs_full_text"] = [ri.full_text(t) for t in types]
            await self._service_response(client, service, mid, values, ok=True)
        except LangnavError as exc:
            await self._service_response(client, service, mid, f"{service}: {exc}", ok=False)

    async def _service_response(self, client: _Client, service: str, mid: Any, values: Any, ok: bool) -> None:
        out: dict[str, Any] = {"op": "service_response", "service": service, "values": values, "result": ok}
        if mid is not None:
            out["id"] = mid
        await self._send(client, out)

    async def _stop_everything(self) -> None:
        goal = self._active_goal
        if goal is not None:
            goal.cancel_requested = True
        await self._call(self.backend.stop)
        if isinstance(self.backend, VelocityCommandable):
            await self._call(self.backend.set_velocity, 0.0, 0.0)

    # -- actions ---------------------------------------------------------------------------------
    async def _op_send_action_goal(self, client: _Client, msg: dict[str, Any]) -> None:
        action = msg.get("action")
        goal_id = str(msg.get("id") or f"send_action_goal:{action}:{next(self._numbers)}")
        if action != self.config.nav_action:
            await self._action_failure(client, str(action), goal_id,
                                       f"No action server available for {action!r}; this robot serves "
                                       f"{self.config.nav_action} ({rm.NAVIGATE_THROUGH_POSES})")
            return
        action_type = msg.get("action_type")
        if action_type and _normal_type(action_type) != _normal_type(rm.NAVIGATE_THROUGH_POSES):
            await self._action_failure(client, action, goal_id,
                                       f"{action} has type {rm.NAVIGATE_THROUGH_POSES}, not {action_type}")
            return
        try:
            poses, frame = rm.parse_navigate_through_poses_goal(msg.get("args"))
        except RobotError as exc:
            await self._action_failure(client, action, goal_id, f"Action goal was rejected: {exc}")
            return
        if frame and frame.lstrip("/") != self.config.map_frame:
            await self._action_failure(client, action, goal_id,
                                       f"Action goal was rejected: poses are in frame {frame!r}; "
                                       f"this robot takes goals in {self.config.map_frame!r}")
            return
        goal = _Goal(goal_id, action)
        previous = self._active_goal
        if previous is not None:
            previous.preempted = True
        self._active_goal = goal
        client.goals[goal_id] = goal
        goal.task = asyncio.create_task(self._run_goal(client, goal, poses, bool(msg.get("feedback", False))))
        if self.config.goals_on_main_thread:
            await asyncio.wait([goal.task])  # read nothing more from this client until the goal ends

    async def _run_goal(self, client: _Client, goal: _Goal, poses: list[Pose2D], feedback: bool) -> None:
        c = self.config
        targets = [(p.x_m, p.y_m, math.degrees(p.yaw_rad)) for p in poses]
        status, values = rm.GOAL_STATUS_ABORTED, {"error_code": NAV2_ERROR_UNKNOWN, "error_msg": ""}
        try:
            handle = await self._call(self.backend.navigate_through_poses, targets)
            goal.handle = handle
            period = 1.0 / c.feedback_rate_hz
            cancel_sent = False
            while True:
                st = handle.status()
                if st is not TaskStatus.RUNNING:
                    break
                if (goal.cancel_requested or goal.preempted) and not cancel_sent:
                    cancel_sent = True
                    await self._call(handle.cancel)
                if feedback and not cancel_sent:
                    fb = handle.feedback()
                    if fb is not None:
                        await self._send(client, {"op": "action_feedback", "id": goal.goal_id, "action": goal.action,
                                                  "values": rm.navigate_through_poses_feedback(
                                                      fb.pose, c.map_frame, fb.elapsed_s, fb.distance_remaining_m,
                                                      fb.poses_remaining, fb.recoveries)})
                await asyncio.sleep(period)
            result = await self._call(handle.wait, c.backend_call_timeout_s)
            if result.status is TaskStatus.SUCCEEDED:
                status, values = rm.GOAL_STATUS_SUCCEEDED, {"error_code": 0, "error_msg": ""}
            elif result.status is TaskStatus.CANCELED and goal.preempted and not goal.cancel_requested:
                values["error_msg"] = "preempted by a newer goal"
            elif result.status is TaskStatus.CANCELED:
                status, values = rm.GOAL_STATUS_CANCELED, {"error_code": 0, "error_msg": result.message or "canceled"}
            else:
                values["error_msg"] = result.message or "navigation failed"
        except asyncio.CancelledError:
            if goal.handle is not None:
                with contextlib.suppress(LangnavError):
                    goal.handle.cancel()
            raise
        except LangnavError as exc:
            await self._action_failure(client, goal.action, goal.goal_id, f"{type(exc).__name__}: {exc}")
            return
        finally:
            client.goals.pop(goal.goal_id, None)
            if self._active_goal is goal:
                self._active_goal = None
        ok = status == rm.GOAL_STATUS_SUCCEEDED or not c.result_false_unless_succeeded
        await self._send(client, {"op": "action_result", "id": goal.goal_id, "action": goal.action,
                                  "values": values, "status": status, "result": ok})

    async def _action_failure(self, client: _Client, action: str, goal_id: str, reason: str) -> None:
        await self._status(client, "error", f"send_action_goal {reason}", goal_id)
        await self._send(client, {"op": "action_result", "id": goal_id, "action": action, "values": reason,
                                  "status": rm.GOAL_STATUS_UNKNOWN, "result": False})

    async def _op_cancel_action_goal(self, client: _Client, msg: dict[str, Any]) -> None:
        goal_id = msg.get("id")
        goal = client.goals.get(str(goal_id)) if goal_id is not None else None
        if goal is None:
            await self._status(client, "warning", f"cancel_action_goal: no goal {goal_id!r} in progress "
                               f"on {msg.get('action')}", goal_id)
            return
        goal.cancel_requested = True
        if goal.handle is not None:
            await self._call(goal.handle.cancel)

    async def _op_unsupported(self, client: _Client, msg: dict[str, Any]) -> None:
        await self._status(client, "error", f"{msg.get('op')} is not supported by langnav's rosbridge server: "
                           "it serves a robot, it does not host client-side services or actions", msg.get("id"))

    _ops: Final[dict[str, Callable[[RosbridgeServer, _Client, dict[str, Any]], Any]]] = {
        "subscribe": _op_subscribe,
        "unsubscribe": _op_unsubscribe,
        "advertise": _op_advertise,
        "unadvertise": _op_unadvertise,
        "publish": _op_publish,
        "call_service": _op_call_service,
        "send_action_goal": _op_send_action_goal,
        "cancel_action_goal": _op_cancel_action_goal,
        "advertise_service": _op_unsupported,
        "unadvertise_service": _op_unsupported,
        "service_response": _op_unsupported,
        "advertise_action": _op_unsupported,
        "unadvertise_action": _op_unsupported,
        "action_feedback": _op_unsupported,
        "action_result": _op_unsupported,
        "fragment": _op_unsupported,
    }


class _Frames:
    """One published message, encoded once per compression that a subscriber asked for."""

    def __init__(self, topic: str, msg_type: str, msg: dict[str, Any]) -> None:
        self.topic = topic
        self.msg_type = msg_type
        self.msg = msg
        self._cache: dict[str, dict[str, Any] | bytes] = {}

    def encoded(self, mode: str) -> dict[str, Any] | bytes:
        if mode not in self._cache:
            out: dict[str, Any] = {"op": "publish", "topic": self.topic, "msg": self.msg}
            if mode == "none":
                self._cache[mode] = out
            elif mode == "cbor":
                self._cache[mode] = cbor2.dumps(out)
            else:  # cbor-raw: the CDR bytes and the time they were sent, as rosbridge_suite does
                secs, nsecs = divmod(time.time_ns(), 1_000_000_000)
                out["msg"] = {"secs": secs, "nsecs": nsecs, "bytes": ri.serialize_cdr(self.msg_type, self.msg)}
                self._cache[mode] = cbor2.dumps(out)
        return self._cache[mode]


class _RosoutHandler(logging.Handler):
    """Keeps langnav's log records (from any thread) until the /rosout stream publishes them."""

    def __init__(self, level: int) -> None:
        super().__init__(level)
        self._records: collections.deque[logging.LogRecord] = collections.deque(maxlen=ROSOUT_BACKLOG)

    def emit(self, record: logging.LogRecord) -> None:
        self._records.append(record)

    def drain(self) -> list[logging.LogRecord]:
        out = []
        while self._records:
            out.append(self._records.popleft())
        return out


def _log_message(record: logging.LogRecord) -> dict[str, Any]:
    """A log record as an ``rcl_interfaces/msg/Log``."""
    level = next((ros for py, ros in _LOG_LEVELS if record.levelno >= py), 10)
    try:
        text = record.getMessage()
    except (TypeError, ValueError) as exc:  # a bad format string in someone's log call
        text = f"{record.msg!r} (unformattable: {exc})"
    return {"stamp": rm.stamp(record.created), "level": level, "name": record.name, "msg": text,
            "file": record.pathname, "function": record.funcName or "", "line": max(0, record.lineno)}


def _normal_type(name: str) -> str:
    """'nav_msgs/OccupancyGrid' and 'nav_msgs/msg/OccupancyGrid' are the same type."""
    parts = name.strip("/").split("/")
    return f"{parts[0]}/{parts[-1]}" if len(parts) >= 2 else name


def _bound_port(server: Server) -> int:
    for sock in server.sockets:
        return int(sock.getsockname()[1])
    raise RobotError("the rosbridge server has no listening socket")
