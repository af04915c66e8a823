"""Robot backends: the embedded simulator (default), rosbridge (roslibpy) and ROS 2 (rclpy)."""

# Importing the simulator registers the default backend, "sim".
import langnav.robot.sim  # noqa: F401  (registers "sim")
from langnav.robot.errors import RobotError, RobotTimeout
from langnav.robot.protocol import (
    LaserScan,
    Pose2D,
    RobotBackend,
    RobotState,
    TaskFeedback,
    TaskHandle,
    TaskResult,
    TaskStatus,
    create_backend,
)

__all__ = ["LaserScan", "Pose2D", "RobotBackend", "RobotError", "RobotState", "RobotTimeout",
           "TaskFeedback", "TaskHandle", "TaskResult", "TaskStatus", "create_backend"]
