"""The walk from the robot (langnav.grounding.walking): lengths through doors, never through walls,
and the way back shut when the walk must go on the way the robot faces."""

from __future__ import annotations

import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from langnav.analysis.params import DEFAULT_PARAMS
from langnav.grounding.geometry import FreeSpace, free_space_for
from langnav.grounding.walking import lattice_stride, walk_from
from langnav.maps.draw import MapBuilder

#: The walk's error: a lattice cell's diagonal at each end (0.2 m lattice at 5 cm cells).
LATTICE_SLACK_M = 2 * 4 * 0.05 * math.sqrt(2)


@pytest.fixture(scope="module")
def two_rooms() -> FreeSpace:
    """Two 5 x 4 m rooms side by side (x 1-6 and 6-11, y 1-5), one door at (6, 1.8) in the wall."""
    b = MapBuilder(12.0, 6.0)
    b.room(1.0, 1.0, 11.0, 5.0)
    b.wall(6.0, 1.0, 6.0, 5.0)
    b.door_v(6.0, 1.8, 0.9)
    return free_space_for(b.build("walk_two_rooms"), DEFAULT_PARAMS)


@pytest.mark.parametrize(("resolution", "radius", "k"), [(0.05, 0.17, 4), (0.1, 0.17, 2), (0.05, 0.3, 8),
                                                          (0.2, 0.1, 1)])
def test_the_lattice_step_is_shorter_than_the_robots_diameter(resolution: float, radius: float, k: int) -> None:
    assert lattice_stride(resolution, radius) == k
    assert k == 1 or k * resolution * math.sqrt(2) < 2 * radius


def test_the_walk_to_the_next_room_goes_through_the_door(two_rooms: FreeSpace) -> None:
    walk = walk_from(two_rooms, (4.0, 4.0))
    assert walk is not None
    behind_the_wall = (8.0, 4.0)
    by_the_door = math.dist((4.0, 4.0), (6.0, 1.8)) + math.dist((6.0, 1.8), behind_the_wall)
    got = walk.to([behind_the_wall])
    assert by_the_door - 0.3 <= got <= by_the_door + LATTICE_SLACK_M
    assert got > math.dist((4.0, 4.0), behind_the_wall) + 1.5  # not through the wall (4 m)


def test_no_walk_from_outside_the_building(two_rooms: FreeSpace) -> None:
    assert walk_from(two_rooms, (11.8, 5.8)) is None  # outside the building, in the unknown


@settings(max_examples=40, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(x0=st.floats(1.5, 10.5), y0=st.floats(1.5, 4.5), x1=st.floats(1.2, 10.8), y1=st.floats(1.2, 4.8))
def test_a_walk_is_never_shorter_than_the_straight_line(two_rooms: FreeSpace, x0: float, y0: float, x1: float,
                                                         y1: float) -> None:
    walk = walk_from(two_rooms, (x0, y0))
    if walk is None:
        return
    assert walk.to([(x1, y1)]) >= math.dist((x0, y0), (x1, y1)) - LATTICE_SLACK_M


def test_with_the_way_back_shut_the_walk_goes_round(two_rooms: FreeSpace) -> None:
    # from (4, 2) facing west, the door (east, at 6) is behind: with the way east shut within 4 m
    # the next room cannot be reached, and the walk to it is no shorter than the open one
    open_walk = walk_from(two_rooms, (4.0, 2.0))
    shut = walk_from(two_rooms, (4.0, 2.0), onward=(-1.0, 0.0), onward_m=4.0)
    assert open_walk is not None and shut is not None
    assert shut.to([(8.0, 2.0)]) >= open_walk.to([(8.0, 2.0)])
    assert not shut.reached([8.0], [2.0])[0] and open_walk.reached([8.0], [2.0])[0]
    path = open_walk.path_to((8.0, 2.0))
    assert path[0] == (4.0, 2.0) and path[-1] == (8.0, 2.0)
    assert all(two_rooms.clearance_at(*p) >= two_rooms.robot_radius_m - 1e-9 for p in path[1:-1])
