"""ROS 2 messages as rosbridge JSON dicts <-> langnav types.

Pure converters, no I/O. Outgoing builders return plain dicts shaped as the ROS 2 message
definitions (``builtin_interfaces/Time`` is ``{"sec", "nanosec"}``); incoming parsers validate
with pydantic first, so a malformed message from a robot raises a :class:`RobotError` that says
which message, which field and what was wrong, never a ``KeyError`` deep inside a callback.

Incoming models ignore extra fields (a newer distro may add some) but require every field
langnav reads. The robot is planar: poses and transforms are projected to (x, y, yaw).

JSON has no inf/NaN; rosbridge and this module send ``null`` for a non-finite float, and the
parsers read ``null`` in a ``LaserScan`` range as "no return" (``inf``).
"""

from __future__ import annotations

import math
import time
from collections.abc import Iterable, Sequence
from typing import Any, Final, TypeVar

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, ValidationError

from langnav.maps.errors import MapError
from langnav.maps.grid import OccupancyGrid, from_ros_data
from langnav.robot.errors import RobotError
from langnav.robot.protocol import LaserScan, Pose2D, TaskFeedback

# -- ROS type names (ROS 2 "pkg/msg/Name" spelling, which rosbridge_suite >= 2.0 accepts) --------
POSE_STAMPED: Final = "geometry_msgs/msg/PoseStamped"
POSE_WITH_COV_STAMPED: Final = "geometry_msgs/msg/PoseWithCovarianceStamped"
TWIST: Final = "geometry_msgs/msg/Twist"
TWIST_STAMPED: Final = "geometry_msgs/msg/TwistStamped"
OCCUPANCY_GRID: Final = "nav_msgs/msg/OccupancyGrid"
PATH: Final = "nav_msgs/msg/Path"
ODOMETRY: Final = "nav_msgs/msg/Odometry"
LASER_SCAN: Final = "sensor_msgs/msg/LaserScan"
TF_MESSAGE: Final = "tf2_msgs/msg/TFMessage"
NAVIGATE_THROUGH_POSES: Final = "nav2_msgs/action/NavigateThroughPoses"
GET_MAP_SRV: Final = "nav_msgs/srv/GetMap"
TRIGGER_SRV: Final = "std_srvs/srv/Trigger"

#: action_msgs/msg/GoalStatus values, as rosbridge puts them in ``action_result.status``.
GOAL_STATUS_UNKNOWN: Final = 0
GOAL_STATUS_ACCEPTED: Final = 1
GOAL_STATUS_EXECUTING: Final = 2
GOAL_STATUS_CANCELING: Final = 3
GOAL_STATUS_SUCCEEDED: Final = 4
GOAL_STATUS_CANCELED: Final = 5
GOAL_STATUS_ABORTED: Final = 6

#: A quaternion shorter than this is no rotation at all (a zeroed message), not a yaw.
MIN_QUATERNION_NORM: Final = 1e-6
#: Show at most this many characters of a bad message in an error.
_MAX_ERROR_CHARS: Final = 300

M = TypeVar("M", bound=BaseModel)


class _Msg(BaseModel):
    model_config = ConfigDict(extra="ignore", frozen=True)


class TimeMsg(_Msg):
    sec: int = 0
    nanosec: int = Field(default=0, ge=0, lt=1_000_000_000)


class HeaderMsg(_Msg):
    stamp: TimeMsg = TimeMsg()
    frame_id: str = ""


class Vector3Msg(_Msg):
    x: float = 0.0
    y: float = 0.0
    z: float = 0.0


class QuaternionMsg(_Msg):
    x: float = 0.0
    y: float = 0.0
    z: float = 0.0
    w: float = 1.0


class PoseMsg(_Msg):
    position: Vector3Msg
    orientation: QuaternionMsg


class PoseStampedMsg(_Msg):
    header: HeaderMsg = HeaderMsg()
    pose: PoseMsg


class PoseWithCovarianceMsg(_Msg):
    pose: PoseMsg


class PoseWithCovarianceStampedMsg(_Msg):
    header: HeaderMsg = HeaderMsg()
    pose: PoseWithCovarianceMsg


class TwistMsg(_Msg):
    linear: Vector3Msg
    angular: Vector3Msg


class TwistStampedMsg(_Msg):
    header: HeaderMsg = HeaderMsg()
    twist: TwistMsg


class TwistWithCovarianceMsg(_Msg):
    twist: TwistMsg


class OdometryMsg(_Msg):
    header: HeaderMsg = HeaderMsg()
    child_frame_id: str = ""
    pose: PoseWithCovarianceMsg
    twist: TwistWithCovarianceMsg | None = None


class MapMetaDataMsg(_Msg):
    resolution: float = Field(gt=0)
    width: int = Field(gt=0)
    height: int = Field(gt=0)
    origin: PoseMsg


class OccupancyGridMsg(_Msg):
    header: HeaderMsg = HeaderMsg()
    info: MapMetaDataMsg
    data: list[int]


class PathMsg(_Msg):
    header: HeaderMsg = HeaderMsg()
    poses: list[PoseStampedMsg]


class LaserScanMsg(_Msg):
    header: HeaderMsg = HeaderMsg()
    angle_min: float
    angle_max: float
    angle_increment: float
    range_min: float = 0.0
    range_max: float
    ranges: list[float | None]


class TransformMsg(_Msg):
    translation: Vector3Msg
    rotation: QuaternionMsg


class TransformStampedMsg(_Msg):
    header: HeaderMsg
    child_frame_id: str = Field(min_length=1)
    transform: TransformMsg


class TFMessageMsg(_Msg):
    transforms: list[TransformStampedMsg]


class DurationMsg(_Msg):
    sec: int = 0
    nanosec: int = 0


class NavigateThroughPosesFeedbackMsg(_Msg):
    current_pose: PoseStampedMsg
    navigation_time: DurationMsg = DurationMsg()
    estimated_time_remaining: DurationMsg = DurationMsg()
    number_of_recoveries: int = 0
    distance_remaining: float | None = None
    number_of_poses_remaining: int | None = None


def validate(model: type[M], msg: Any, what: str) -> M:
    """Validate one incoming message; a malformed one raises RobotError naming ``what``."""
    if not isinstance(msg, dict):
        raise RobotError(f"malformed {what}: expected a JSON object, got {type(msg).__name__} "
                         f"{_preview(msg)}")
    try:
        return model.model_validate(msg)
    except ValidationError as exc:
        problems = "; ".join(
            f"{'.'.join(str(p) for p in err['loc']) or '<message>'}: {err['msg']}"
            for err in exc.errors()[:5]
        )
        raise RobotError(f"malformed {what}: {problems} (message: {_preview(msg)}); check that the "
                         f"robot publishes the ROS 2 message type langnav expects") from None


def _preview(msg: Any) -> str:
    text = repr(msg)
    return text if len(text) <= _MAX_ERROR_CHARS else text[:_MAX_ERROR_CHARS] + "..."


def _finite(value: float) -> float | None:
    return value if math.isfinite(value) else None


# -- time ----------------------------------------------------------------------------------------
def stamp(t_s: float | None = None) -> dict[str, int]:
    """A ``builtin_interfaces/Time`` for ``t_s`` seconds (now when None)."""
    t = time.time() if t_s is None else t_s
    sec = math.floor(t)
    return {"sec": int(sec), "nanosec": min(999_999_999, round((t - sec) * 1e9))}


def duration(seconds: float) -> dict[str, int]:
    """A ``builtin_interfaces/Duration``."""
    return stamp(max(0.0, seconds))


def duration_s(msg: DurationMsg | TimeMsg) -> float:
    return msg.sec + msg.nanosec * 1e-9


def header(frame_id: str, t_s: float | None = None) -> dict[str, Any]:
    return {"stamp": stamp(t_s), "frame_id": frame_id}


# -- rotations -----------------------------------------------------------------------------------
def yaw_to_quaternion(yaw_rad: float) -> dict[str, float]:
    """A rotation about z as a ``geometry_msgs/Quaternion``."""
    half = 0.5 * yaw_rad
    return {"x": 0.0, "y": 0.0, "z": math.sin(half), "w": math.cos(half)}


def quaternion_to_yaw(q: QuaternionMsg | dict[str, Any]) -> float:
    """The yaw (rotation about z) of a quaternion, in (-pi, pi]; normalises it first."""
    qm = q if isinstance(q, QuaternionMsg) else validate(QuaternionMsg, q, "geometry_msgs/Quaternion")
    norm = math.sqrt(qm.x ** 2 + qm.y ** 2 + qm.z ** 2 + qm.w ** 2)
    if not math.isfinite(norm) or norm < MIN_QUATERNION_NORM:
        raise RobotError(f"malformed quaternion {qm.model_dump()}: its norm is {norm}, not 1")
    x, y, z, w = qm.x / norm, qm.y / norm, qm.z / norm, qm.w / norm
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def wrap_angle(angle_rad: float) -> float:
    """An angle in (-pi, pi]."""
    a = math.fmod(angle_rad + math.pi, 2.0 * math.pi)
    if a <= 0.0:
        a += 2.0 * math.pi
    return a - math.pi


# -- poses ---------------------------------------------------------------------------------------
def pose(x_m: float, y_m: float, yaw_rad: float) -> dict[str, Any]:
    """A ``geometry_msgs/Pose`` on the floor."""
    return {"position": {"x": float(x_m), "y": float(y_m), "z": 0.0},
            "orientation": yaw_to_quaternion(yaw_rad)}


def pose_stamped(p: Pose2D, frame_id: str, t_s: float | None = None) -> dict[str, Any]:
    return {"header": header(frame_id, t_s), "pose": pose(p.x_m, p.y_m, p.yaw_rad)}


def pose2d_from_pose(msg: PoseMsg) -> Pose2D:
    x, y = msg.position.x, msg.position.y
    if not (math.isfinite(x) and math.isfinite(y)):
        raise RobotError(f"malformed pose: position ({x}, {y}) is not finite")
    return Pose2D(x, y, quaternion_to_yaw(msg.orientation))


def parse_pose_stamped(msg: Any) -> tuple[Pose2D, str]:
    """A ``geometry_msgs/PoseStamped`` -> (pose, frame_id)."""
    m = validate(PoseStampedMsg, msg, POSE_STAMPED)
    return pose2d_from_pose(m.pose), m.header.frame_id


def pose_with_covariance_stamped(p: Pose2D, frame_id: str, t_s: float | None = None,
                                 variance_m2: float = 0.0) -> dict[str, Any]:
    cov = [0.0] * 36
    cov[0] = cov[7] = variance_m2
    return {"header": header(frame_id, t_s),
            "pose": {"pose": pose(p.x_m, p.y_m, p.yaw_rad), "covariance": cov}}


def parse_robot_pose(msg: Any, what: str) -> tuple[Pose2D, str]:
    """A pose topic message -> (pose, frame_id): accepts PoseWithCovarianceStamped (amcl_pose),
    PoseStamped and Odometry, told apart by their fields."""
    if isinstance(msg, dict) and "child_frame_id" in msg:
        odom = validate(OdometryMsg, msg, f"{what} ({ODOMETRY})")
        return pose2d_from_pose(odom.pose.pose), odom.header.frame_id
    if isinstance(msg, dict) and isinstance(msg.get("pose"), dict) and "pose" in msg["pose"]:
        pwc = validate(PoseWithCovarianceStampedMsg, msg, f"{what} ({POSE_WITH_COV_STAMPED})")
        return pose2d_from_pose(pwc.pose.pose), pwc.header.frame_id
    ps = validate(PoseStampedMsg, msg, f"{what} ({POSE_STAMPED})")
    return pose2d_from_pose(ps.pose), ps.header.frame_id


def odometry(p: Pose2D, linear_mps: float, angular_radps: float, frame_id: str, child_frame_id: str,
             t_s: float | None = None) -> dict[str, Any]:
    """A ``nav_msgs/Odometry``: pose in ``frame_id``, twist in the body frame."""
    return {
        "header": header(frame_id, t_s),
        "child_frame_id": child_frame_id,
        "pose": {"pose": pose(p.x_m, p.y_m, p.yaw_rad), "covariance": [0.0] * 36},
        "twist": {"twist": twist(linear_mps, angular_radps), "covariance": [0.0] * 36},
    }


# -- velocity ------------------------------------------------------------------------------------
def twist(linear_mps: float, angular_radps: float) -> dict[str, Any]:
    """A ``geometry_msgs/Twist`` for a planar base."""
    return {"linear": {"x": float(linear_mps), "y": 0.0, "z": 0.0},
            "angular": {"x": 0.0, "y": 0.0, "z": float(angular_radps)}}


def cmd_vel(linear_mps: float, angular_radps: float, stamped: bool, frame_id: str = "base_link",
            t_s: float | None = None) -> dict[str, Any]:
    """A velocity command as Twist (Jazzy) or TwistStamped (Kilted, Nav2 enable_stamped_cmd_vel)."""
    t = twist(linear_mps, angular_radps)
    return {"header": header(frame_id, t_s), "twist": t} if stamped else t


def parse_cmd_vel(msg: Any) -> tuple[float, float]:
    """A Twist or TwistStamped -> (linear x m/s, angular z rad/s)."""
    if isinstance(msg, dict) and "twist" in msg:
        t = validate(TwistStampedMsg, msg, TWIST_STAMPED).twist
    else:
        t = validate(TwistMsg, msg, TWIST)
    lin, ang = t.linear.x, t.angular.z
    if not (math.isfinite(lin) and math.isfinite(ang)):
        raise RobotError(f"malformed cmd_vel: linear.x={lin}, angular.z={ang} must be finite")
    return lin, ang


# -- maps ----------------------------------------------------------------------------------------
def occupancy_grid(grid: OccupancyGrid, frame_id: str = "map", t_s: float | None = None) -> dict[str, Any]:
    """A ``nav_msgs/OccupancyGrid`` (data row-major from the bottom row; -1 / 0 / 100)."""
    return {
        "header": header(frame_id, t_s),
        "info": {
            "map_load_time": stamp(t_s),
            "resolution": float(grid.resolution_m),
            "width": grid.width,
            "height": grid.height,
            "origin": pose(grid.origin_x_m, grid.origin_y_m, grid.origin_yaw_rad),
        },
        "data": grid.to_ros_data().tolist(),
    }


def parse_occupancy_grid(msg: Any, source: str = "/map") -> OccupancyGrid:
    """A ``nav_msgs/OccupancyGrid`` -> OccupancyGrid (ROS thresholds applied)."""
    m = validate(OccupancyGridMsg, msg, f"{source} ({OCCUPANCY_GRID})")
    origin = pose2d_from_pose(m.info.origin)
    try:
        return from_ros_data(np.asarray(m.data, dtype=np.int64), m.info.width, m.info.height,
                             m.info.resolution, origin.x_m, origin.y_m, origin.yaw_rad, source=source)
    except MapError as exc:
        raise RobotError(f"malformed {source} ({OCCUPANCY_GRID}): {exc}") from None


def path(points: Iterable[tuple[float, float]], frame_id: str = "map", t_s: float | None = None) -> dict[str, Any]:
    """A ``nav_msgs/Path``; each pose faces the next point."""
    pts = [(float(x), float(y)) for x, y in points]
    poses = []
    for i, (x, y) in enumerate(pts):
        if i + 1 < len(pts):
            yaw = math.atan2(pts[i + 1][1] - y, pts[i + 1][0] - x)
        elif i > 0:
            yaw = math.atan2(y - pts[i - 1][1], x - pts[i - 1][0])
        else:
            yaw = 0.0
        poses.append({"header": header(frame_id, t_s), "pose": pose(x, y, yaw)})
    return {"header": header(frame_id, t_s), "poses": poses}


def parse_path(msg: Any, source: str = "/plan") -> tuple[list[tuple[float, float]], str]:
    """A ``nav_msgs/Path`` -> ([(x, y)], frame_id)."""
    m = validate(PathMsg, msg, f"{source} ({PATH})")
    pts = [(p.pose.position.x, p.pose.position.y) for p in m.poses]
    if not all(math.isfinite(x) and math.isfinite(y) for x, y in pts):
        raise RobotError(f"malformed {source} ({PATH}): a pose is not finite")
    return pts, m.header.frame_id


# -- laser ---------------------------------------------------------------------------------------
def laser_scan(scan: LaserScan, frame_id: str = "base_scan", t_s: float | None = None,
               range_min_m: float = 0.0) -> dict[str, Any]:
    """A ``sensor_msgs/LaserScan`` (no return -> null, as JSON has no inf)."""
    n = len(scan.ranges_m)
    return {
        "header": header(frame_id, t_s),
        "angle_min": scan.angle_min_rad,
        "angle_max": scan.angle_min_rad + scan.angle_increment_rad * max(0, n - 1),
        "angle_increment": scan.angle_increment_rad,
        "time_increment": 0.0,
        "scan_time": 0.0,
        "range_min": range_min_m,
        "range_max": scan.range_max_m,
        "ranges": [_finite(r) for r in scan.ranges_m],
        "intensities": [],
    }


def parse_laser_scan(msg: Any, sensor_pose: Pose2D, source: str = "/scan") -> LaserScan:
    """A ``sensor_msgs/LaserScan`` -> LaserScan taken at ``sensor_pose``."""
    m = validate(LaserScanMsg, msg, f"{source} ({LASER_SCAN})")
    if not (math.isfinite(m.angle_min) and math.isfinite(m.angle_increment) and math.isfinite(m.range_max)):
        raise RobotError(f"malformed {source} ({LASER_SCAN}): angles and range_max must be finite")
    ranges = tuple(math.inf if r is None or not math.isfinite(r) else float(r) for r in m.ranges)
    return LaserScan(m.angle_min, m.angle_increment, m.range_max, ranges, sensor_pose)


# -- tf ------------------------------------------------------------------------------------------
def transform_stamped(parent: str, child: str, p: Pose2D, t_s: float | None = None) -> dict[str, Any]:
    """A ``geometry_msgs/TransformStamped`` placing ``child`` at ``p`` in ``parent``."""
    return {
        "header": header(parent, t_s),
        "child_frame_id": child,
        "transform": {"translation": {"x": p.x_m, "y": p.y_m, "z": 0.0},
                      "rotation": yaw_to_quaternion(p.yaw_rad)},
    }


def tf_message(transforms: Sequence[dict[str, Any]]) -> dict[str, Any]:
    return {"transforms": list(transforms)}


def compose(a: Pose2D, b: Pose2D) -> Pose2D:
    """``a`` then ``b``: the pose b (given in a's frame) expressed in a's parent frame."""
    c, s = math.cos(a.yaw_rad), math.sin(a.yaw_rad)
    return Pose2D(a.x_m + c * b.x_m - s * b.y_m, a.y_m + s * b.x_m + c * b.y_m,
                  wrap_angle(a.yaw_rad + b.yaw_rad))


def _strip(frame: str) -> str:
    return frame.lstrip("/")


class TransformTree:
    """The latest planar transforms from /tf and /tf_static, composed on lookup.

    Not a tf2 buffer: no history, no interpolation. Langnav asks only "where is base_link in map
    now", which the latest map->odom and odom->base_link answer.
    """

    #: Longest frame chain followed before giving up (a loop in a malformed tree).
    MAX_DEPTH: Final = 32

    def __init__(self) -> None:
        self._parent: dict[str, tuple[str, Pose2D]] = {}

    def update(self, msg: Any, source: str = "/tf") -> int:
        """Add the transforms of a ``tf2_msgs/TFMessage``; returns how many."""
        m = validate(TFMessageMsg, msg, f"{source} ({TF_MESSAGE})")
        for t in m.transforms:
            tr = t.transform.translation
            if not (math.isfinite(tr.x) and math.isfinite(tr.y)):
                raise RobotError(f"malformed {source} ({TF_MESSAGE}): translation of "
                                 f"{t.child_frame_id} is not finite")
            p = Pose2D(tr.x, tr.y, quaternion_to_yaw(t.transform.rotation))
            self._parent[_strip(t.child_frame_id)] = (_strip(t.header.frame_id), p)
        return len(m.transforms)

    def frames(self) -> list[str]:
        return sorted(set(self._parent) | {parent for parent, _ in self._parent.values()})

    def _to_root(self, frame: str) -> list[tuple[str, Pose2D]]:
        chain: list[tuple[str, Pose2D]] = []
        cur = frame
        while cur in self._parent and len(chain) < self.MAX_DEPTH:
            parent, p = self._parent[cur]
            chain.append((parent, p))
            cur = parent
        return chain

    def lookup(self, target: str, source: str) -> Pose2D | None:
        """The pose of frame ``source`` in frame ``target``, or None when they are not connected."""
        target, source = _strip(target), _strip(source)
        # Pose of each frame in the root of its chain.
        def in_root(frame: str) -> tuple[str, Pose2D]:
            p = Pose2D(0.0, 0.0, 0.0)
            root = frame
            for parent, step in self._to_root(frame):
                p = compose(step, p)
                root = parent
            return root, p

        root_s, pose_s = in_root(source)
        root_t, pose_t = in_root(target)
        if root_s != root_t:
            return None
        return compose(invert(pose_t), pose_s)


def invert(p: Pose2D) -> Pose2D:
    c, s = math.cos(p.yaw_rad), math.sin(p.yaw_rad)
    return Pose2D(-(c * p.x_m + s * p.y_m), s * p.x_m - c * p.y_m, wrap_angle(-p.yaw_rad))


# -- Nav2 NavigateThroughPoses -------------------------------------------------------------------
def navigate_through_poses_goal(poses: Sequence[Pose2D], frame_id: str = "map", goal_format: str = "pose_array",
                                behavior_tree: str = "", t_s: float | None = None) -> dict[str, Any]:
    """The goal of ``nav2_msgs/action/NavigateThroughPoses``.

    ``goal_format``: ``"pose_array"`` for Humble and Jazzy (``geometry_msgs/PoseStamped[] poses``),
    ``"goals"`` for Kilted and later (``nav_msgs/Goals poses``: a header and ``goals[]``).
    """
    stamped = [pose_stamped(p, frame_id, t_s) for p in poses]
    if goal_format == "pose_array":
        return {"poses": stamped, "behavior_tree": behavior_tree}
    if goal_format == "goals":
        return {"poses": {"header": header(frame_id, t_s), "goals": stamped}, "behavior_tree": behavior_tree}
    raise RobotError(f"unknown goal_format {goal_format!r}; choose 'pose_array' (Humble, Jazzy) "
                     f"or 'goals' (Kilted and later)")


def parse_navigate_through_poses_goal(args: Any) -> tuple[list[Pose2D], str]:
    """A NavigateThroughPoses goal in either shape -> (poses, frame_id of the first)."""
    if not isinstance(args, dict) or "poses" not in args:
        raise RobotError(f"malformed {NAVIGATE_THROUGH_POSES} goal: expected an object with 'poses', "
                         f"got {_preview(args)}")
    raw = args["poses"]
    if isinstance(raw, dict):  # nav_msgs/Goals (Kilted) or nav2_msgs/PoseStampedArray
        raw = raw.get("goals", raw.get("poses"))
    if not isinstance(raw, list) or not raw:
        raise RobotError(f"malformed {NAVIGATE_THROUGH_POSES} goal: 'poses' must hold at least one "
                         f"geometry_msgs/PoseStamped, got {_preview(args['poses'])}")
    parsed = [parse_pose_stamped(p) for p in raw]
    return [p for p, _ in parsed], parsed[0][1]


def navigate_through_poses_feedback(current: Pose2D, frame_id: str, elapsed_s: float,
                                    distance_remaining_m: float | None, poses_remaining: int | None,
                                    recoveries: int = 0, speed_mps: float | None = None,
                                    t_s: float | None = None) -> dict[str, Any]:
    """The feedback of ``nav2_msgs/action/NavigateThroughPoses``."""
    dist = distance_remaining_m if distance_remaining_m is not None and math.isfinite(distance_remaining_m) else 0.0
    eta = dist / speed_mps if speed_mps and speed_mps > 0 else 0.0
    return {
        "current_pose": pose_stamped(current, frame_id, t_s),
        "navigation_time": duration(elapsed_s),
        "estimated_time_remaining": duration(eta),
        "number_of_recoveries": int(recoveries),
        "distance_remaining": float(dist),
        "number_of_poses_remaining": int(poses_remaining or 0),
    }


def parse_navigate_through_poses_feedback(values: Any, action: str) -> TaskFeedback:
    m = validate(NavigateThroughPosesFeedbackMsg, values, f"{action} feedback ({NAVIGATE_THROUGH_POSES})")
    dist = m.distance_remaining
    return TaskFeedback(
        pose=pose2d_from_pose(m.current_pose.pose),
        distance_remaining_m=dist if dist is not None and math.isfinite(dist) else None,
        elapsed_s=duration_s(m.navigation_time),
        poses_remaining=m.number_of_poses_remaining,
        recoveries=m.number_of_recoveries,
    )
