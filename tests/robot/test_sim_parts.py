"""The simulator's pure parts: lidar, log-odds mapping, costmap inflation, planner, controller."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from langnav.maps.draw import MapBuilder
from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN, OccupancyGrid
from langnav.robot.sim.controller import Limits, pure_pursuit, ramp, stopping_speed, wrap_angle
from langnav.robot.sim.costmap import INSCRIBED, LETHAL, MAX_NON_OBSTACLE, NO_INFORMATION, inflate
from langnav.robot.sim.lidar import Lidar, LidarSpec
from langnav.robot.sim.mapping import LogOddsMap
from langnav.robot.sim.planner import NoPathError, path_length_m, plan
from langnav.robot.sim.world import ROBOT_RADIUS_M, World

RES = 0.05


def box_room() -> OccupancyGrid:
    """Free [0, 4] x [0, 3], walls 0.15 m thick, unknown outside."""
    b = MapBuilder(6.0, 5.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 4.0, 3.0)
    return b.build("box room")


ROOM = box_room()


def test_lidar_ranges_are_the_distances_to_the_walls() -> None:
    lidar = Lidar(World(ROOM), LidarSpec(noise_std_m=0.0))
    r = lidar.true_ranges(1.0, 1.5, 0.0)
    ang = lidar.angles_rad
    east, north, west, south = (int(np.argmin(np.abs(ang - a))) for a in (0.0, math.pi / 2, math.pi, -math.pi / 2))
    assert r[east] == pytest.approx(3.0, abs=RES / 2)
    assert r[north] == pytest.approx(1.5, abs=RES / 2)
    assert r[west] == pytest.approx(1.0, abs=RES / 2)
    assert r[south] == pytest.approx(1.5, abs=RES / 2)
    assert np.isfinite(r).all()
    assert len(r) == 360


def test_lidar_beyond_range_is_inf_and_noise_has_the_set_spread() -> None:
    lidar = Lidar(World(ROOM), LidarSpec(range_max_m=2.0, noise_std_m=0.01))
    r = lidar.true_ranges(1.0, 1.5, 0.0)
    assert np.isinf(r[int(np.argmin(np.abs(lidar.angles_rad)))])  # the east wall is 3 m away
    rng = np.random.default_rng(1)
    west = int(np.argmin(np.abs(lidar.angles_rad - math.pi)))
    samples = np.array([lidar.scan(1.0, 1.5, 0.0, rng)[west] for _ in range(300)])
    assert samples.std() == pytest.approx(0.01, rel=0.25)
    assert samples.mean() == pytest.approx(1.0, abs=RES / 2)


@settings(max_examples=40, deadline=None)
@given(x=st.floats(0.3, 3.7), y=st.floats(0.3, 2.7), yaw=st.floats(-math.pi, math.pi))
def test_every_return_lies_on_matter_and_the_way_to_it_is_free(x: float, y: float, yaw: float) -> None:
    world = World(ROOM)
    lidar = Lidar(world)
    r = lidar.true_ranges(x, y, yaw)
    a = lidar.angles_rad + yaw
    hit_x, hit_y = x + (r + RES * 0.6) * np.cos(a), y + (r + RES * 0.6) * np.sin(a)
    rows, cols = ROOM.world_to_index(hit_x, hit_y)
    assert world.solid[rows, cols].all()
    before_x, before_y = x + (r - RES * 0.6) * np.cos(a), y + (r - RES * 0.6) * np.sin(a)
    rows, cols = ROOM.world_to_index(before_x, before_y)
    assert not world.solid[rows, cols].any()


def test_mapping_one_scan_frees_the_room_and_marks_the_walls() -> None:
    lidar = Lidar(World(ROOM), LidarSpec(noise_std_m=0.0))
    m = LogOddsMap(ROOM)
    assert (m.cells() == UNKNOWN).all()
    r = lidar.true_ranges(2.0, 1.5, 0.0)
    m.integrate(2.0, 1.5, 0.0, lidar.angles_rad, r, 10.0)
    cells = m.cells()
    assert not ((cells == FREE) & (ROOM.cells != FREE)).any()
    assert ((cells == OCCUPIED) & (ROOM.cells == OCCUPIED)).sum() > 150
    near = ROOM.free.copy()
    rr, cc = np.indices(near.shape)
    xs, ys = ROOM.cell_to_world(rr, cc)
    near &= np.hypot(xs - 2.0, ys - 1.5) < 1.2
    assert (cells[near] == FREE).all()  # the inner part of the room is seen by many beams
    grid = m.grid()
    assert set(np.unique(grid.to_image()).tolist()) <= {0, 205, 254}


def test_known_map_start_and_a_new_obstacle_turns_occupied_after_a_few_hits() -> None:
    world = World(ROOM)
    lidar = Lidar(world, LidarSpec(noise_std_m=0.0))
    m = LogOddsMap(ROOM, known=ROOM)
    assert (m.cells() == ROOM.cells).all()
    world.add_obstacle(3.0, 1.5, 0.2)
    rows, cols = ROOM.world_to_index(2.82, 1.5)  # the obstacle's west face
    states = []
    for _ in range(4):
        m.integrate(1.0, 1.5, 0.0, lidar.angles_rad, lidar.true_ranges(1.0, 1.5, 0.0), 10.0)
        states.append(int(m.cells()[rows, cols]))
    assert states[0] != OCCUPIED and states[-1] == OCCUPIED


def test_costmap_lethal_inscribed_and_decay() -> None:
    cm = inflate(ROOM)
    assert (cm.costs[ROOM.occupied] == LETHAL).all()
    unknown = cm.costs[ROOM.unknown & ~ROOM.occupied]
    assert np.isin(unknown, (INSCRIBED, NO_INFORMATION)).all() and (unknown == NO_INFORMATION).mean() > 0.5
    row = int(ROOM.world_to_index(0.0, 1.5)[0])
    _, c0 = ROOM.world_to_index(0.0, 1.5)  # the first free column, next to the west wall
    profile = cm.costs[row, int(c0):int(c0) + 16].astype(int)
    assert profile[0] == INSCRIBED
    free_part = profile[profile < INSCRIBED]
    assert free_part.size and free_part[0] <= MAX_NON_OBSTACLE
    assert (np.diff(profile) <= 0).all()  # cost falls with distance from the wall
    assert profile[-1] == 0  # beyond the inflation radius (0.55 m)


def test_planner_keeps_clear_of_walls_and_fails_with_reasons() -> None:
    b = MapBuilder(6.0, 5.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 4.0, 3.0)
    b.wall(2.0, 0.0, 2.0, 2.2)  # a partition with a gap at the top
    grid = b.build("partition")
    cm = inflate(grid)
    path = plan(cm, (1.0, 0.5), (3.0, 0.5))
    world = World(grid)
    assert path[0] == (1.0, 0.5) and path[-1] == (3.0, 0.5)
    assert all(world.clearance_m(x, y) >= ROBOT_RADIUS_M for x, y in path)
    assert max(y for _, y in path) > 2.2  # around the partition's end
    assert path_length_m(path) > 2 * 2.0
    with pytest.raises(NoPathError, match="obstacle"):
        plan(cm, (1.0, 0.5), (2.0, 1.0))  # inside the partition
    with pytest.raises(NoPathError, match="outside the map"):
        plan(cm, (1.0, 0.5), (30.0, 1.0))
    closed = b.wall(2.0, 2.2, 2.0, 3.0).build()
    with pytest.raises(NoPathError, match="walled off"):
        plan(inflate(closed), (1.0, 0.5), (3.0, 0.5))


@settings(max_examples=25, deadline=None)
@given(sx=st.floats(0.3, 3.7), sy=st.floats(0.3, 2.7), gx=st.floats(0.3, 3.7), gy=st.floats(0.3, 2.7))
def test_planned_paths_join_start_to_goal_no_shorter_than_the_straight_line(sx: float, sy: float, gx: float,
                                                                            gy: float) -> None:
    cm = inflate(ROOM)
    path = plan(cm, (sx, sy), (gx, gy))
    assert path[0] == (sx, sy)
    assert math.dist(path[-1], (gx, gy)) < 0.3
    assert path_length_m(path) >= math.dist((sx, sy), path[-1]) - 1e-9


@settings(max_examples=50, deadline=None)
@given(cur=st.floats(-1, 1), target=st.floats(-1, 1), step=st.floats(0.001, 0.5))
def test_ramp_never_jumps_more_than_the_limit(cur: float, target: float, step: float) -> None:
    out = ramp(cur, target, step)
    assert abs(out - cur) <= step + 1e-12
    assert min(cur, target) - 1e-12 <= out <= max(cur, target) + 1e-12


def test_stopping_speed_and_wrap() -> None:
    assert stopping_speed(0.0, 0.3, 0.5) == 0.0
    assert stopping_speed(10.0, 0.3, 0.5) == 0.3
    assert stopping_speed(0.04, 1.0, 0.5) == pytest.approx(0.2)
    assert wrap_angle(3 * math.pi / 2) == pytest.approx(-math.pi / 2)


def test_pure_pursuit_turns_in_place_for_a_carrot_behind_and_drives_for_one_ahead() -> None:
    path = np.column_stack([np.linspace(0, 3, 61), np.zeros(61)])
    ahead = pure_pursuit((0.0, 0.0, 0.0), path, 0, 0.0, Limits())
    assert ahead.linear_mps > 0 and abs(ahead.angular_radps) < 1e-6
    behind = pure_pursuit((0.0, 0.0, math.pi), path, 0, 0.0, Limits())
    assert behind.linear_mps == 0.0 and behind.angular_radps != 0.0
    left = pure_pursuit((0.0, -0.3, 0.0), path, 0, 0.2, Limits())
    assert left.angular_radps > 0  # the path is to the robot's left


def test_world_unknown_specks_are_floor_and_unknown_regions_are_solid() -> None:
    b = MapBuilder(6.0, 5.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 4.0, 3.0)
    b.unknown(1.0, 1.0, 1.1, 1.1)   # a 0.01 m2 speck: unobserved floor
    b.unknown(2.5, 1.0, 3.5, 2.0)   # a 1 m2 unknown region: matter, as far as the sim knows
    world = World(b.build("specks"))
    assert not world.collides(1.05, 1.05)
    assert world.collides(3.0, 1.5)
    assert world.grid.value_at(1.05, 1.05) == FREE
    assert world.grid.value_at(3.0, 1.5) == UNKNOWN
