"""ROS 2 message definitions (``.msg`` text) of the types langnav's rosbridge server speaks, and a
CDR encoder driven by them.

Foxglove's rosbridge connection asks ``/rosapi/topics_and_raw_types`` for every topic's full
definition -- the root type's ``.msg`` text, then each type it uses after a line of 80 ``=`` and
``MSG: pkg/Name``, as rosapi's ``stringify_field_types`` writes it -- and then subscribes with
``compression: "cbor-raw"``: each message arrives as its serialized CDR bytes, which it decodes
with that definition. So these definitions must match the wire format exactly. They are the ROS 2
(Jazzy) ones without the comments, with every type written ``pkg/Name`` (valid in any package);
the tests compare them field by field with an independent store of ROS 2 types and decode the
CDR written here with an independent decoder.

Pure functions and constant data; no I/O.
"""

from __future__ import annotations

import math
import re
import struct
from dataclasses import dataclass
from functools import cache
from typing import Any, Final

import numpy as np

from langnav.robot.errors import RobotError

#: type name ("pkg/msg/Name") -> .msg text
MSG_DEFINITIONS: Final[dict[str, str]] = {
    "builtin_interfaces/msg/Time": "int32 sec\nuint32 nanosec\n",
    "std_msgs/msg/Header": "builtin_interfaces/Time stamp\nstring frame_id\n",
    "geometry_msgs/msg/Point": "float64 x\nfloat64 y\nfloat64 z\n",
    "geometry_msgs/msg/Vector3": "float64 x\nfloat64 y\nfloat64 z\n",
    "geometry_msgs/msg/Quaternion": "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n",
    "geometry_msgs/msg/Pose": "geometry_msgs/Point position\ngeometry_msgs/Quaternion orientation\n",
    "geometry_msgs/msg/PoseStamped": "std_msgs/Header header\ngeometry_msgs/Pose pose\n",
    "geometry_msgs/msg/PoseWithCovariance": "geometry_msgs/Pose pose\nfloat64[36] covariance\n",
    "geometry_msgs/msg/PoseWithCovarianceStamped": "std_msgs/Header header\ngeometry_msgs/PoseWithCovariance pose\n",
    "geometry_msgs/msg/Twist": "geometry_msgs/Vector3 linear\ngeometry_msgs/Vector3 angular\n",
    "geometry_msgs/msg/TwistStamped": "std_msgs/Header header\ngeometry_msgs/Twist twist\n",
    "geometry_msgs/msg/TwistWithCovariance": "geometry_msgs/Twist twist\nfloat64[36] covariance\n",
    "geometry_msgs/msg/Transform": "geometry_msgs/Vector3 translation\ngeometry_msgs/Quaternion rotation\n",
    "geometry_msgs/msg/TransformStamped": (
        "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/Transform transform\n"),
    "tf2_msgs/msg/TFMessage": "geometry_msgs/TransformStamped[] transforms\n",
    "nav_msgs/msg/MapMetaData": (
        "builtin_interfaces/Time map_load_time\nfloat32 resolution\nuint32 width\nuint32 height\n"
        "geometry_msgs/Pose origin\n"),
    "nav_msgs/msg/OccupancyGrid": "std_msgs/Header header\nnav_msgs/MapMetaData info\nint8[] data\n",
    "nav_msgs/msg/Path": "std_msgs/Header header\ngeometry_msgs/PoseStamped[] poses\n",
    "nav_msgs/msg/Odometry": (
        "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/PoseWithCovariance pose\n"
        "geometry_msgs/TwistWithCovariance twist\n"),
    "sensor_msgs/msg/LaserScan": (
        "std_msgs/Header header\nfloat32 angle_min\nfloat32 angle_max\nfloat32 angle_increment\n"
        "float32 time_increment\nfloat32 scan_time\nfloat32 range_min\nfloat32 range_max\n"
        "float32[] ranges\nfloat32[] intensities\n"),
    "rcl_interfaces/msg/Log": (
        "uint8 DEBUG=10\nuint8 INFO=20\nuint8 WARN=30\nuint8 ERROR=40\nuint8 FATAL=50\n"
        "builtin_interfaces/Time stamp\nuint8 level\nstring name\nstring msg\nstring file\n"
        "string function\nuint32 line\n"),
}

#: The line rosapi puts between the definitions of one full text.
SEPARATOR: Final = "=" * 80
#: CDR encapsulation header: plain CDR, little endian (what rclpy's serialize_message writes).
CDR_LE_HEADER: Final = b"\x00\x01\x00\x00"

#: primitive -> (numpy dtype, size in bytes); char and byte are 8 bits in ROS 2.
_PRIMITIVES: Final[dict[str, tuple[str, int]]] = {
    "bool": ("?", 1), "byte": ("u1", 1), "char": ("u1", 1), "int8": ("i1", 1), "uint8": ("u1", 1),
    "int16": ("<i2", 2), "uint16": ("<u2", 2), "int32": ("<i4", 4), "uint32": ("<u4", 4),
    "int64": ("<i8", 8), "uint64": ("<u8", 8), "float32": ("<f4", 4), "float64": ("<f8", 8),
}
_FIELD_RE: Final = re.compile(r"^(?P<type>[A-Za-z0-9_/]+)(?P<array>\[(?P<bound><=)?(?P<n>\d*)\])?$")


@dataclass(frozen=True)
class Field:
    name: str
    type: str  # a primitive, "string", or "pkg/msg/Name"
    sequence: bool = False  # T[] (or T[<=N])
    length: int | None = None  # T[N]


def full_name(type_name: str) -> str:
    """'nav_msgs/OccupancyGrid' or 'nav_msgs/msg/OccupancyGrid' -> 'nav_msgs/msg/OccupancyGrid'."""
    parts = type_name.strip("/").split("/")
    if len(parts) == 2:
        return f"{parts[0]}/msg/{parts[1]}"
    if len(parts) == 3:
        return "/".join(parts)
    raise RobotError(f"{type_name!r} is not a ROS message type name (pkg/msg/Name)")


def short_name(type_name: str) -> str:
    """'nav_msgs/msg/OccupancyGrid' -> 'nav_msgs/OccupancyGrid' (how .msg files and rosapi name it)."""
    pkg, _, name = full_name(type_name).split("/")
    return f"{pkg}/{name}"


def definition(type_name: str) -> str:
    try:
        return MSG_DEFINITIONS[full_name(type_name)]
    except KeyError:
        raise RobotError(f"no message definition for {type_name}; known: {', '.join(sorted(MSG_DEFINITIONS))}") from None


@cache
def fields(type_name: str) -> tuple[Field, ...]:
    """The fields of a message type (constants skipped), parsed from its definition."""
    out: list[Field] = []
    for raw in definition(type_name).splitlines():
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        tokens = line.split()
        if len(tokens) > 1 and "=" in tokens[1]:
            continue  # a constant: TYPE NAME=VALUE
        m = _FIELD_RE.match(tokens[0])
        if m is None or len(tokens) not in (2, 3):
            raise RobotError(f"{type_name}: cannot read the field line {raw!r}")
        base = m["type"]
        if base not in _PRIMITIVES and base != "string":
            base = full_name(base)
        sequence = m["array"] is not None and (m["bound"] is not None or not m["n"])
        length = int(m["n"]) if m["array"] is not None and not sequence else None
        out.append(Field(tokens[1], base, sequence, length))
    return tuple(out)


def dependencies(type_name: str) -> list[str]:
    """Every message type ``type_name`` uses, directly or not, each once, depth first."""
    seen: list[str] = []
    stack = [full_name(type_name)]
    while stack:
        for f in fields(stack.pop()):
            if f.type not in _PRIMITIVES and f.type != "string" and f.type not in seen:
                seen.append(f.type)
                stack.append(f.type)
    return seen


def full_text(type_name: str) -> str:
    """The definition with all it uses, in rosapi's ``typedefs_full_text`` (``gendeps --cat``) form."""
    text = definition(type_name)
    for dep in dependencies(type_name):
        text += f"\n{SEPARATOR}\nMSG: {short_name(dep)}\n{definition(dep)}"
    return text


# -- CDR -------------------------------------------------------------------------------------------
class _Writer:
    """XCDR1 little endian; alignment is counted from the end of the encapsulation header."""

    def __init__(self) -> None:
        self.buf = bytearray()

    def align(self, size: int) -> None:
        self.buf.extend(b"\x00" * (-len(self.buf) % size))

    def primitive(self, kind: str, value: Any) -> None:
        dtype, size = _PRIMITIVES[kind]
        self.align(size)
        self.buf.extend(np.asarray(_number(kind, value), dtype=dtype).tobytes())

    def primitives(self, kind: str, values: list[Any]) -> None:
        """An array of one primitive type, converted in one go (a map has ~10^5 cells)."""
        if not values:
            return  # no alignment for an empty array (as Fast-CDR)
        dtype, size = _PRIMITIVES[kind]
        if kind.startswith("float"):
            try:
                arr = np.asarray([math.inf if v is None else v for v in values], dtype=np.float64)
            except (TypeError, ValueError):
                raise TypeError(f"numbers for {kind}[]") from None
        else:
            arr = np.asarray(values)
            want = "b" if kind == "bool" else "iu"
            if arr.dtype.kind not in want:
                raise TypeError(f"{'bools' if kind == 'bool' else 'integers'} for {kind}[]")
            if kind != "bool":
                info = np.iinfo(dtype)
                if arr.min() < info.min or arr.max() > info.max:
                    raise TypeError(f"integers in [{info.min}, {info.max}] for {kind}[]")
        self.align(size)
        self.buf.extend(arr.astype(dtype).tobytes())

    def string(self, value: Any) -> None:
        if not isinstance(value, str):
            raise TypeError(f"a string, not {type(value).__name__}")
        data = value.encode("utf-8")
        self.align(4)
        self.buf.extend(struct.pack("<I", len(data) + 1))
        self.buf.extend(data + b"\x00")


def _number(kind: str, value: Any) -> Any:
    if value is None and kind.startswith("float"):
        return math.inf  # JSON has no inf: rosbridge and ros.messages send null (a LaserScan "no return")
    if kind == "bool":
        if not isinstance(value, bool):
            raise TypeError(f"a bool, not {value!r}")
        return value
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise TypeError(f"a number, not {value!r}")
    if not kind.startswith("float"):
        info = np.iinfo(_PRIMITIVES[kind][0])
        if not (isinstance(value, int) and info.min <= value <= info.max):
            raise TypeError(f"an integer in [{info.min}, {info.max}] for {kind}, not {value!r}")
    return value


def _write(w: _Writer, type_name: str, msg: Any, where: str) -> None:
    if not isinstance(msg, dict):
        raise RobotError(f"{where}: a {short_name(type_name)} must be an object, got {type(msg).__name__}")
    for f in fields(type_name):
        here = f"{where}.{f.name}"
        if f.name not in msg:
            raise RobotError(f"{here}: missing (a {short_name(type_name)} has "
                             f"{', '.join(x.name for x in fields(type_name))})")
        value = msg[f.name]
        try:
            if f.sequence or f.length is not None:
                if not isinstance(value, list | tuple):
                    raise TypeError(f"a list, not {type(value).__name__}")
                if f.length is not None and len(value) != f.length:
                    raise TypeError(f"exactly {f.length} items, not {len(value)}")
                if f.sequence:
                    w.align(4)
                    w.buf.extend(struct.pack("<I", len(value)))
                if f.type in _PRIMITIVES:
                    w.primitives(f.type, list(value))
                else:
                    for i, item in enumerate(value):
                        _write_one(w, f.type, item, f"{here}[{i}]")
            else:
                _write_one(w, f.type, value, here)
        except TypeError as exc:
            raise RobotError(f"{here}: expected {exc}") from None


def _write_one(w: _Writer, kind: str, value: Any, where: str) -> None:
    if kind in _PRIMITIVES:
        w.primitive(kind, value)
    elif kind == "string":
        w.string(value)
    else:
        _write(w, kind, value, where)


def serialize_cdr(type_name: str, msg: dict[str, Any]) -> bytes:
    """A message (rosbridge JSON dict) -> its CDR bytes, with the encapsulation header, as rclpy's
    ``serialize_message`` gives them (what rosbridge sends for ``compression: "cbor-raw"``).
    Raises RobotError naming the field when the message does not match the definition."""
    w = _Writer()
    _write(w, full_name(type_name), msg, short_name(type_name))
    return CDR_LE_HEADER + bytes(w.buf)
