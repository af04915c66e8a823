"""The ros2 backend without ROS 2: a clear, actionable error (rclpy is not installable here)."""

from __future__ import annotations

import importlib.util

import pytest

from langnav.robot.errors import RobotError
from langnav.robot.protocol import backend_names, create_backend
from langnav.robot.ros2_backend import INSTALL_HINT, Ros2Backend

pytestmark = pytest.mark.skipif(importlib.util.find_spec("rclpy") is not None,
                                reason="ROS 2 is installed here; this tests the machine without it")


def test_registered_and_import_is_lazy() -> None:
    assert "ros2" in backend_names()  # importing the module needs no ROS 2


def test_without_ros2_creation_says_how_to_install_and_source_it() -> None:
    with pytest.raises(RobotError) as info:
        create_backend("ros2", namespace="/robot1")
    text = str(info.value)
    assert INSTALL_HINT in text
    assert "source /opt/ros/jazzy/setup.bash" in text and "--backend rosbridge" in text
    assert "import failed: No module named 'rclpy'" in text
    with pytest.raises(RobotError, match="rclpy"):
        Ros2Backend()
