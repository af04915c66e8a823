"""The embedded 2D simulator: ground-truth world, lidar, log-odds mapping, costmap, planner,
controller, and the :class:`SimBackend` registered as robot backend ``"sim"``."""

from langnav.robot.protocol import register_backend
from langnav.robot.sim.backend import (
    SimBackend,
    SimConfig,
    SimTaskHandle,
    create_sim,
    default_start,
)
from langnav.robot.sim.world import ROBOT_RADIUS_M, World

register_backend("sim", create_sim)

__all__ = ["ROBOT_RADIUS_M", "SimBackend", "SimConfig", "SimTaskHandle", "World", "create_sim", "default_start"]
