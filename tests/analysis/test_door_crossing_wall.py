"""Golden buildings for a gap that runs up to the face of a wall crossing its line (issue 8,
langnav.analysis.door_judge): the way round a partition's end past an inner wall with a place
behind it is no door; a return of wall beside the gap (a door frame's jamb) makes it one, and so
does the building's outer wall, where partitions stop short of the facade for a room's door."""

from __future__ import annotations

import math

import pytest
from analysis_maps import POS_TOL_M, door_near, space_at

from langnav.analysis.door_judge import JAMB_ALONG_MIN_SHARE, evidence
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.segmentation import segment_spaces
from langnav.eval.transforms import PointsAnnotation, map_centre, rotate, rotate_point
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import FREE, OCCUPIED, OccupancyGrid

#: The thick wall along the north floor's south side (a wall with a service duct, a party wall).
THICK_M = 0.3
#: The partition along x = 4 ends this high (m) above that wall's face: a 1 m gap.
PARTITION_END_Y = 1.3
#: The door from the north floor's east half to the south room, through the thick wall.
SOUTH_DOOR_XY = (6.5, -THICK_M / 2)


def floor_with_a_partition(behind: str, return_m: float = 0.0) -> OccupancyGrid:
    """An 8 m x 4 m floor (y from 0 to 4) parted by a partition along x = 4 from its north wall
    down to y = 1.3, 1 m short of the 0.3 m wall along its south side. ``behind`` that wall:
    "room", a 3 m deep room entered through a 0.9 m door at x = 6.5 (the wall is an inner wall
    crossing the gap's line), or "outside", the unknown (the building's outer wall).
    ``return_m``: a return of wall along x = 4 at the gap's foot (a door frame's jamb)."""
    b = MapBuilder(10.0, 9.0, origin=(-1.0, -4.0))
    b.room(0.0, -3.0 - THICK_M, 8.0, 4.0)  # the building, its outer walls 0.1 m thick
    b.rect(0.0, -THICK_M, 8.0, 0.0, OCCUPIED)  # the thick wall
    if behind == "room":
        b.door_h(*SOUTH_DOOR_XY, 0.9)
    else:
        b.unknown(-0.2, -3.5, 8.2, -THICK_M)
    b.wall(4.0, 4.0, 4.0, PARTITION_END_Y)
    if return_m > 0:
        b.rect(3.95, 0.0, 4.05, return_m, OCCUPIED)
    return b.build(f"partition short of a wall with a {behind} behind it")


@pytest.mark.parametrize(("behind", "return_m", "door"), [
    ("room", 0.0, False),  # the way round the partition's end: an opening, no door
    ("room", 0.15, True),  # a door frame's return beside the inner wall: a door
    ("outside", 0.0, True),  # a partition stopping short of the outer wall: a room's door
])
def test_a_gap_up_to_a_crossing_wall_is_a_door_only_with_a_return_or_at_the_outer_wall(
        behind: str, return_m: float, door: bool) -> None:
    grid = floor_with_a_partition(behind, return_m)
    seg = segment_spaces(grid)
    west, east = space_at(seg, grid, 2.0, 2.5), space_at(seg, grid, 6.0, 2.5)
    assert west.id != east.id
    y = (return_m + PARTITION_END_Y) / 2
    gap_doors = [d for d in seg.doors if math.dist(d.center, (4.0, y)) <= 0.4]
    if door:
        assert len(gap_doors) == 1
        assert set(gap_doors[0].connects) == {west.id, east.id}
        assert gap_doors[0].width_m == pytest.approx(PARTITION_END_Y - return_m, abs=POS_TOL_M)
    else:
        assert gap_doors == []
        assert any(set(o.connects) == {west.id, east.id} for o in seg.openings)
    if behind == "room":
        south = space_at(seg, grid, 2.0, -1.5)
        assert set(door_near(seg.doors, *SOUTH_DOOR_XY).connects) == {east.id, south.id}
        assert len(seg.doors) == 1 + door
    else:
        assert len(seg.doors) == 1
    # The evidence says why: the jamb on the thick wall's face runs on along the gap's line only
    # with the return or against the outer wall.
    r, c = grid.world_to_cell(4.0, y)
    ev = evidence(grid.cells == FREE, grid.cells == OCCUPIED, (float(r), float(c)), (0.0, 1.0),
                  PARTITION_END_Y - return_m, grid.resolution_m, DEFAULT_PARAMS)
    assert (min(ev.along) >= JAMB_ALONG_MIN_SHARE) is door


@pytest.mark.parametrize("angle_deg", [21.0, 58.0])
def test_the_way_round_a_partition_is_no_door_whatever_the_maps_rotation(angle_deg: float) -> None:
    """Turned about the map's centre: still no door at the gap, still the door to the south room."""
    grid0 = floor_with_a_partition("room")
    grid, _ = rotate(grid0, PointsAnnotation(), angle_deg)
    turn = math.radians(angle_deg)
    centre = map_centre(grid0)
    seg = segment_spaces(grid)
    east = space_at(seg, grid, *rotate_point((6.0, 2.5), centre, turn))
    south = space_at(seg, grid, *rotate_point((2.0, -1.5), centre, turn))
    gap = rotate_point((4.0, PARTITION_END_Y / 2), centre, turn)
    assert not [d for d in seg.doors if math.dist(d.center, gap) <= 0.4]
    door = door_near(seg.doors, *rotate_point(SOUTH_DOOR_XY, centre, turn), tol=2 * POS_TOL_M)
    assert set(door.connects) == {east.id, south.id}
