"""The ros2 backend on a machine without ROS 2: a clear, actionable error, and the parts that need
no rclpy (the goal shape read from the action's own definition, the message conversion). The
backend itself runs against real ROS 2 in the tier: tests/ros2 (`make test-ros2`)."""

from __future__ import annotations

import importlib.util
import math
from typing import Any, ClassVar

import pytest

from langnav.robot.errors import RobotError
from langnav.robot.protocol import backend_names, create_backend
from langnav.robot.ros.backend import INSTALL_HINT, Ros2Backend, goal_format
from langnav.robot.ros.convert import from_msg, to_msg

no_ros = pytest.mark.skipif(importlib.util.find_spec("rclpy") is not None,
                            reason="ROS 2 is installed here; this tests the machine without it")


@no_ros
def test_registered_and_import_is_lazy() -> None:
    assert "ros2" in backend_names()  # importing the module needs no ROS 2


@no_ros
def test_without_ros2_creation_says_how_to_install_and_source_it() -> None:
    with pytest.raises(RobotError) as info:
        create_backend("ros2", namespace="robot1")
    text = str(info.value)
    assert INSTALL_HINT in text
    assert "source /opt/ros/jazzy/setup.bash" in text and "--backend rosbridge" in text
    assert "No module named 'rclpy'" in text
    with pytest.raises(RobotError, match="rclpy"):
        Ros2Backend()


class _Goal:
    """A stand-in for a generated NavigateThroughPoses Goal class: only its field list matters."""

    fields: ClassVar[dict[str, str]] = {}

    @classmethod
    def get_fields_and_field_types(cls) -> dict[str, str]:
        return cls.fields


class _JazzyGoal(_Goal):
    fields: ClassVar[dict[str, str]] = {"poses": "sequence<geometry_msgs/PoseStamped>", "behavior_tree": "string"}


class _KiltedGoal(_Goal):
    fields: ClassVar[dict[str, str]] = {"poses": "nav_msgs/Goals", "behavior_tree": "string"}


class _OtherGoal(_Goal):
    fields: ClassVar[dict[str, str]] = {"poses": "geometry_msgs/PoseArray", "behavior_tree": "string"}


def test_the_goal_shape_comes_from_the_actions_definition_not_the_distro() -> None:
    # Jazzy's nav_msgs has Goals too: only the action's own field says which shape it takes
    assert goal_format(_JazzyGoal) == "pose_array"
    assert goal_format(_KiltedGoal) == "goals"
    with pytest.raises(RobotError, match="geometry_msgs/PoseArray"):
        goal_format(_OtherGoal)


class _Vec:
    fields: ClassVar[dict[str, str]] = {"x": "double", "y": "double", "z": "double"}

    def __init__(self) -> None:
        self.x = self.y = self.z = 0.0

    @classmethod
    def get_fields_and_field_types(cls) -> dict[str, str]:
        return cls.fields


class _Scanish:
    fields: ClassVar[dict[str, str]] = {"name": "string", "count": "int32", "ranges": "sequence<float>",
                                        "ok": "boolean", "offset": "double"}

    def __init__(self) -> None:
        self.name, self.count, self.ranges, self.ok, self.offset = "", 0, [], False, 0.0

    @classmethod
    def get_fields_and_field_types(cls) -> dict[str, str]:
        return cls.fields


def test_dicts_become_messages_and_back() -> None:
    msg = to_msg(_Scanish, {"name": "front", "count": 3, "ranges": [1.0, None, 2.5], "ok": True,
                            "offset": None, "unknown_in_this_distro": 1})
    assert (msg.name, msg.count, msg.ok) == ("front", 3, True)
    assert msg.ranges[0] == 1.0 and math.isinf(msg.ranges[1]) and math.isinf(msg.offset)  # JSON null = no return
    back: dict[str, Any] = from_msg(msg)
    assert back["ranges"][2] == 2.5 and back["name"] == "front"
    assert from_msg(to_msg(_Vec, {"x": 1, "y": 2})) == {"x": 1.0, "y": 2.0, "z": 0.0}


def test_a_field_that_does_not_fit_is_named() -> None:
    with pytest.raises(RobotError, match=r"_Scanish.count"):
        to_msg(_Scanish, {"count": "three"})
