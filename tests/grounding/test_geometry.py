"""Property tests of the robot-frame transforms and of the free-space searches."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from langnav.analysis.elements import MapAnalysis
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.grounding.geometry import (
    Pose,
    bearing_rad,
    blocking_mask,
    closest_on_segment,
    free_space_for,
    is_ahead,
    is_behind,
    is_left,
    is_right,
    segment_distance,
    segment_distances,
    to_robot_frame,
    wrap_angle,
)
from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN, OccupancyGrid

coord = st.floats(-50, 50, allow_nan=False)
yaw = st.floats(-720, 720, allow_nan=False)


@given(coord, coord, yaw, st.floats(-10, 10), st.floats(-10, 10))
def test_robot_frame_inverts_the_pose_transform(x: float, y: float, yaw_deg: float, f: float, lat: float) -> None:
    pose = Pose.from_deg(x, y, yaw_deg)
    c, s = math.cos(pose.yaw_rad), math.sin(pose.yaw_rad)
    p = (x + c * f - s * lat, y + s * f + c * lat)
    f2, lat2 = to_robot_frame(pose, p)
    assert math.isclose(f2, f, abs_tol=1e-6)
    assert math.isclose(lat2, lat, abs_tol=1e-6)


@given(coord, coord, yaw, st.floats(0.2, 10), st.floats(-10, 10))
def test_left_and_right_swap_when_the_robot_turns_around(x: float, y: float, yaw_deg: float, lat: float,
                                                          f: float) -> None:
    pose = Pose.from_deg(x, y, yaw_deg)
    c, s = math.cos(pose.yaw_rad), math.sin(pose.yaw_rad)
    p = (x + c * f - s * lat, y + s * f + c * lat)
    assert is_left(pose, p) and not is_right(pose, p)
    turned = Pose.from_deg(x, y, yaw_deg + 180)
    assert is_right(turned, p) and not is_left(turned, p)


@given(coord, coord, yaw, st.floats(0, 359.9), st.floats(0.5, 20))
def test_ahead_and_behind_follow_the_bearing(x: float, y: float, yaw_deg: float, rel_deg: float, r: float) -> None:
    pose = Pose.from_deg(x, y, yaw_deg)
    a = pose.yaw_rad + math.radians(rel_deg)
    p = (x + r * math.cos(a), y + r * math.sin(a))
    rel = abs(math.degrees(wrap_angle(math.radians(rel_deg))))
    assert math.isclose(abs(math.degrees(bearing_rad(pose, p))), rel, abs_tol=1e-4)
    if rel < 59.9:
        assert is_ahead(pose, p) and not is_behind(pose, p)
    if rel > 120.1:
        assert is_behind(pose, p) and not is_ahead(pose, p)
    if 60.1 < rel < 119.9:
        assert not is_ahead(pose, p) and not is_behind(pose, p)


@given(st.floats(-100, 100, allow_nan=False))
def test_wrap_angle_range(a: float) -> None:
    w = wrap_angle(a)
    assert -math.pi < w <= math.pi
    assert math.isclose(math.cos(w), math.cos(a), abs_tol=1e-9)


@given(st.lists(st.tuples(coord, coord), min_size=1, max_size=20), st.tuples(coord, coord), st.tuples(coord, coord))
def test_vectorised_segment_distance_matches_scalar(pts: list[tuple[float, float]], a: tuple[float, float],
                                                    b: tuple[float, float]) -> None:
    xs = np.array([p[0] for p in pts])
    ys = np.array([p[1] for p in pts])
    d = segment_distances(xs, ys, a, b)
    for i, p in enumerate(pts):
        assert math.isclose(d[i], segment_distance(p, a, b), abs_tol=1e-6)
        q = closest_on_segment(p, a, b)
        assert math.dist(p, q) <= math.dist(p, a) + 1e-9 and math.dist(p, q) <= math.dist(p, b) + 1e-9


@settings(max_examples=60, deadline=None)
@given(st.floats(1.0, 11.0), st.floats(1.0, 7.0), st.floats(0.1, 1.5))
def test_safe_point_near_is_free_clear_reachable_and_close(two_rooms: MapAnalysis, x: float, y: float,
                                                           radius: float) -> None:
    fs = free_space_for(two_rooms.grid, DEFAULT_PARAMS)
    comp = fs.component_at(3.0, 2.0)
    p = fs.safe_point_near((x, y), comp, radius)
    if p is None:
        return
    assert math.dist(p, (x, y)) <= radius + 1e-9
    assert two_rooms.grid.value_at(*p) == FREE
    assert fs.clearance_at(*p) >= DEFAULT_PARAMS.goal_clearance_m
    assert fs.is_reachable(p[0], p[1], comp)


def test_speckle_unknown_does_not_block_but_areas_do() -> None:
    cells = np.full((40, 40), FREE, np.int8)
    cells[10, 10] = UNKNOWN                 # one cell of speckle
    cells[20:25, 20:25] = UNKNOWN           # 25 cells: an unexplored area
    cells[0, :] = OCCUPIED
    blocking = blocking_mask(OccupancyGrid(cells, 0.05))
    assert not blocking[10, 10]
    assert blocking[22, 22] and blocking[0, 5]
    assert blocking.sum() == 25 + 40


def test_components_split_by_a_gap_narrower_than_the_robot() -> None:
    cells = np.full((40, 80), FREE, np.int8)
    cells[:, 39:41] = OCCUPIED
    cells[18:22, 39:41] = FREE  # a 0.2 m gap: free, but a 0.17 m robot cannot pass
    fs = free_space_for(OccupancyGrid(cells, 0.05), DEFAULT_PARAMS)
    left, right = fs.component_at(0.5, 1.0), fs.component_at(3.5, 1.0)
    assert left > 0 and right > 0 and left != right
