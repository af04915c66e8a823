"""rclpy messages <-> the plain dicts of :mod:`langnav.robot.ros.messages` (rosbridge's JSON shape).

langnav builds and parses ROS messages once, as dicts validated by pydantic models; these two
functions carry them across to rclpy's generated classes and back, driven by each class's own
field list (``get_fields_and_field_types``), so they follow whatever definition the robot's
packages have (a Kilted field that Jazzy lacks is simply not there). No ROS import here: the
classes come from the caller.
"""

from __future__ import annotations

import array
import importlib
import math
import re
from typing import Any, Final

import numpy as np

from langnav.robot.errors import RobotError

_SEQUENCE: Final = re.compile(r"^sequence<(?P<inner>[^,>]+)(?:,\s*\d+)?>$")
_ARRAY: Final = re.compile(r"^(?P<inner>.+)\[(?P<n>\d+)\]$")
_BOUNDED_STRING: Final = re.compile(r"^w?string<=\d+$")


def _message_class(type_name: str) -> Any:
    """'geometry_msgs/PoseStamped' (rclpy's field type spelling) -> the class."""
    pkg, name = type_name.split("/")
    return getattr(importlib.import_module(f"{pkg}.msg"), name)


def _is_message(value: Any) -> bool:
    return hasattr(type(value), "get_fields_and_field_types")


def to_msg(cls: Any, data: dict[str, Any], where: str = "") -> Any:
    """A dict -> an instance of the rclpy message class ``cls``. Fields missing from ``data`` keep
    their defaults; keys the class does not have are ignored (another distro's extra field).
    Raises RobotError naming the field that does not fit."""
    msg = cls()
    where = where or cls.__name__
    for name, kind in cls.get_fields_and_field_types().items():
        if name not in data:
            continue
        try:
            setattr(msg, name, _value(kind, data[name], f"{where}.{name}"))
        except (TypeError, ValueError, AssertionError) as exc:
            raise RobotError(f"{where}.{name}: {exc}") from None
    return msg


def _value(kind: str, value: Any, where: str) -> Any:
    m = _SEQUENCE.match(kind) or _ARRAY.match(kind)
    if m is not None:
        inner = m["inner"]
        if "/" in inner:
            return [to_msg(_message_class(inner), item, f"{where}[{i}]") for i, item in enumerate(value)]
        if isinstance(value, np.ndarray):
            return value.tolist()
        if inner in ("float", "double"):  # JSON's null for a non-finite float (a scan's "no return")
            return [math.inf if v is None else float(v) for v in value]
        return list(value)
    if "/" in kind:
        if _is_message(value):
            return value
        if not isinstance(value, dict):
            raise TypeError(f"expected an object for {kind}, got {type(value).__name__}")
        return to_msg(_message_class(kind), value, where)
    if kind in ("float", "double"):
        return math.inf if value is None else float(value)
    if kind == "boolean":
        return bool(value)
    if kind in ("string", "wstring") or _BOUNDED_STRING.match(kind):
        return str(value)
    if kind in ("octet", "char", "uint8") and isinstance(value, bytes):
        return value
    return int(value)


def from_msg(msg: Any) -> dict[str, Any]:
    """An rclpy message -> a dict of plain Python values (lists for arrays, dicts for messages)."""
    out: dict[str, Any] = {}
    for name in type(msg).get_fields_and_field_types():
        out[name] = _plain(getattr(msg, name))
    return out


def _plain(value: Any) -> Any:
    if _is_message(value):
        return from_msg(value)
    if isinstance(value, array.array | np.ndarray):
        return value.tolist()
    if isinstance(value, list | tuple):
        return [_plain(v) for v in value]
    if isinstance(value, bytes) and len(value) == 1:
        return value[0]
    return value
