"""Doors onto an entry lobby (issue 8): a resident room's door in a corridor's wall opens onto a
short lobby about as wide as the door (between the en-suite bathroom and a wardrobe) before the
room itself. Golden building drawn here with the doors known exactly: the lobby's door is the
door between the corridor and the room, however deep the narrow way through it reads; the look-
alike that is no door, a narrow way running on for a corridor's length, stays a passage."""

from __future__ import annotations

import math

import pytest
from analysis_maps import POS_TOL_M, door_near, space_at

from langnav.analysis.segmentation import segment_spaces
from langnav.eval.transforms import PointsAnnotation, map_centre, rotate, rotate_point
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import OccupancyGrid

#: The lobby's door (centre, world metres) in the corridor's north wall, and its width (m).
LOBBY_DOOR_XY = (4.05, 2.575)
LOBBY_DOOR_M = 1.0
#: The narrow way's mouth on the corridor's wall.
WAY_XY = (9.5, 2.575)


def rooms_off_corridor() -> OccupancyGrid:
    """A 2 m x 15 m corridor (y 0.5-2.5). North of it, a resident room (x 1-5.5, y 2.65-7.5)
    entered through a 1 m door at LOBBY_DOOR_XY onto a 1.2 m x 1.2 m lobby (x 3.45-4.65): the
    en-suite bathroom west of it (never entered: its inside unknown), a wardrobe east of it.
    Further east, a room (x 7-12, y 5-9) reached from the corridor by a 1 m wide way 2.2 m long
    (x 9-10)."""
    b = MapBuilder(16.0, 10.0)
    b.room(0.5, 0.5, 15.5, 2.5)  # the corridor
    b.room(1.0, 2.65, 5.5, 7.5)  # the resident room
    b.door_h(*LOBBY_DOOR_XY, LOBBY_DOOR_M)
    b.wall(3.375, 2.65, 3.375, 4.2)  # the bathroom's wall along the lobby
    b.wall(1.0, 4.275, 3.45, 4.275)  # ... and its north wall
    b.unknown(1.0, 2.65, 3.3, 4.2)  # the bathroom, never entered
    b.box(4.65, 2.65, 5.5, 3.85)  # the wardrobe beside the lobby
    b.room(9.0, 2.65, 10.0, 4.85)  # the narrow way
    b.room(7.0, 5.0, 12.0, 9.0)  # the room it leads to
    b.door_h(*WAY_XY, 1.0)
    b.door_h(9.5, 4.925, 1.0)
    return b.build("rooms off a corridor: a door onto a lobby, a narrow way")


def test_a_door_onto_an_entry_lobby_is_the_door_between_corridor_and_room() -> None:
    """The free width through the door stays within the door's for the wall and the lobby
    (1.35 m): deeper than a wall, but flush with the corridor's wall and opening into the room
    within a lobby's length: the one door between them, at the corridor's wall, as wide as it
    was drawn."""
    grid = rooms_off_corridor()
    seg = segment_spaces(grid)
    corridor = space_at(seg, grid, 2.0, 1.5)
    room = space_at(seg, grid, 3.0, 6.0)
    door = door_near(seg.doors, *LOBBY_DOOR_XY, tol=2 * POS_TOL_M)
    assert set(door.connects) == {corridor.id, room.id}
    assert door.width_m == pytest.approx(LOBBY_DOOR_M, abs=POS_TOL_M)
    assert [d for d in seg.doors if room.id in d.connects] == [door]


def test_a_narrow_way_a_corridor_long_is_no_door() -> None:
    """The 1 m way runs on for 2.2 m past the corridor's wall: longer than a lobby, a passage;
    no door anywhere along it."""
    grid = rooms_off_corridor()
    seg = segment_spaces(grid)
    far_room = space_at(seg, grid, 9.5, 7.0)
    assert not [d for d in seg.doors if far_room.id in d.connects]
    assert all(abs(d.center[0] - WAY_XY[0]) > 1.0 for d in seg.doors)


@pytest.mark.parametrize("angle_deg", [17.0, 33.0])
def test_the_lobby_door_is_found_whatever_the_maps_rotation(angle_deg: float) -> None:
    """Turned about the map's centre (a slam_toolbox map's frame is at any angle to the
    building): still the one door between the corridor and the room, at the corridor's wall."""
    grid0 = rooms_off_corridor()
    grid, _ = rotate(grid0, PointsAnnotation(), angle_deg)
    turn = math.radians(angle_deg)
    seg = segment_spaces(grid)
    corridor = space_at(seg, grid, *rotate_point((2.0, 1.5), map_centre(grid0), turn))
    room = space_at(seg, grid, *rotate_point((3.0, 6.0), map_centre(grid0), turn))
    door = door_near(seg.doors, *rotate_point(LOBBY_DOOR_XY, map_centre(grid0), turn), tol=2 * POS_TOL_M)
    assert set(door.connects) == {corridor.id, room.id}
    assert [d for d in seg.doors if room.id in d.connects] == [door]
