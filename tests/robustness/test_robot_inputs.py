"""Robot inputs a user can get wrong: the simulator's start pose (not finite, off the map, a map the
robot does not fit on) and the sim subcommand's --pose parsing."""

from __future__ import annotations

import argparse
import math

import numpy as np
import pytest

from langnav.cli import sim as sim_cli
from langnav.cli.options import pose_arg
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import FREE, OccupancyGrid
from langnav.robot import RobotError
from langnav.robot.protocol import Pose2D
from langnav.robot.sim import SimBackend, create_sim


def room() -> OccupancyGrid:
    b = MapBuilder(4.0, 3.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 2.0, 1.0)
    return b.build("room")


@pytest.mark.parametrize("pose", [(math.nan, 0.5, 0.0), (0.5, math.nan, 0.0), (0.5, 0.5, math.nan),
                                  (math.inf, 0.5, 0.0), (0.5, 0.5, -math.inf)])
def test_start_pose_not_finite_is_refused_with_the_map_extent(pose: tuple[float, float, float]) -> None:
    with pytest.raises(RobotError, match=r"finite.*extent x -1\.00\.\.3\.00 m, y -1\.00\.\.2\.00 m"):
        create_sim(room(), pose)


@pytest.mark.parametrize("pose", [(1e300, 0.5, 0.0), (0.5, -1e300, 0.0), (3.5, 0.5, 0.0), (0.5, -1.2, 90.0)])
def test_start_pose_off_the_map_says_so(pose: tuple[float, float, float]) -> None:
    with pytest.raises(RobotError, match=r"outside the map \(extent x -1\.00\.\.3\.00 m, y -1\.00\.\.2\.00 m\)"):
        create_sim(room(), pose)


def test_a_pose2d_start_is_checked_too() -> None:
    with pytest.raises(RobotError, match="finite"):
        SimBackend(room(), Pose2D(0.5, 0.5, math.nan))


def test_a_start_pose_that_is_not_numbers_is_a_robot_error() -> None:
    with pytest.raises(RobotError, match="numbers"):
        create_sim(room(), ("a", 0.5, 0.0))


@pytest.mark.parametrize("size", [1, 3])
def test_a_map_too_small_for_the_robot_says_so(size: int) -> None:
    grid = OccupancyGrid(np.full((size, size), FREE, dtype=np.int8), 0.05)
    with pytest.raises(RobotError, match=r"no spot wide enough for the robot \(radius 0\.17 m\)"):
        create_sim(grid, (0.025, 0.025, 0.0))


def test_near_a_wall_still_says_obstacle() -> None:
    with pytest.raises(RobotError, match=r"inside an obstacle or closer than 0\.17 m"):
        create_sim(room(), (0.05, 0.5, 0.0))


def test_a_good_start_pose_is_kept() -> None:
    s = create_sim(room(), (1.0, 0.5, 90.0))
    assert (s.pose.x_m, s.pose.y_m) == (1.0, 0.5)
    assert s.pose.yaw_rad == pytest.approx(math.pi / 2)


def test_sim_subcommand_parses_pose_with_the_shared_option() -> None:
    parser = argparse.ArgumentParser()
    sim_cli.add_arguments(parser)
    pose_action = next(a for a in parser._actions if a.dest == "pose")
    assert pose_action.type is pose_arg
    args = parser.parse_args(["--world", "w.yaml", "--pose=-1, 2"])
    assert args.pose == (-1.0, 2.0, 0.0)
