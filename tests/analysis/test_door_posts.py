"""Gaps either side of a post (issue 8, langnav.analysis.door_posts): a hall's open front with a
column standing in it is one opening wider than a door, not two doors (a care home's lobby
opening onto its corridor read as two doors beside its column); two doors into one office a
stretch of wall apart stay two doors. Golden building drawn here with the doors known exactly,
turned as a slam_toolbox map may be."""

from __future__ import annotations

import math

import pytest
from analysis_maps import POS_TOL_M, door_near, space_at

from langnav.analysis.door_posts import POST_MAX_WIDTH_M
from langnav.analysis.segmentation import segment_spaces
from langnav.eval.transforms import PointsAnnotation, map_centre, rotate, rotate_point
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import OccupancyGrid

#: The hall's open front in the corridor's north wall: x 3.0-5.4 (2.4 m, wider than any door),
#: a 0.4 m column standing in it at x 4.0-4.4.
FRONT_X = (3.0, 5.4)
COLUMN_X = (4.0, 4.4)
#: The office's two doors (centres, world metres; 0.9 m each, 0.7 m of wall between them).
OFFICE_DOORS_XY = ((9.0, 2.575), (10.6, 2.575))


def hall_with_column(speck: bool = False, partition_m: float = 0.0) -> OccupancyGrid:
    """A 2 m x 15 m corridor (y 0.5-2.5); north of it a hall (x 1-7.5) open onto it through
    FRONT_X with a column in the opening, and an office (x 7.65-14) with two doors onto the
    corridor. ``speck``: a 0.1 m speck of clutter in the front's east half (scan noise);
    ``partition_m``: a partition this long running north into the hall from the column."""
    b = MapBuilder(16.0, 9.0)
    b.room(0.5, 0.5, 15.5, 2.5)  # the corridor
    b.room(1.0, 2.65, 7.5, 7.5)  # the hall
    b.room(7.65, 2.65, 14.0, 7.5)  # the office
    b.door_h((FRONT_X[0] + FRONT_X[1]) / 2, 2.575, FRONT_X[1] - FRONT_X[0])
    b.box(COLUMN_X[0], 2.5, COLUMN_X[1], 2.65)
    if speck:
        b.box(4.9, 2.55, 5.0, 2.6)
    if partition_m:
        b.wall(sum(COLUMN_X) / 2, 2.65, sum(COLUMN_X) / 2, 2.65 + partition_m)
    for x, y in OFFICE_DOORS_XY:
        b.door_h(x, y, 0.9)
    return b.build("a hall open onto a corridor past a column, an office with two doors")


@pytest.mark.parametrize("speck", [False, True])
def test_the_gaps_beside_a_column_in_an_open_front_are_no_doors(speck: bool) -> None:
    """The front is 2.4 m from wall to wall, the column 0.4 m: one opening wider than a door.
    Its two halves are ways between the corridor and the hall (openings), no door."""
    grid = hall_with_column(speck)
    seg = segment_spaces(grid)
    corridor = space_at(seg, grid, 2.0, 1.5)
    hall = space_at(seg, grid, 3.0, 5.0)
    assert [d for d in seg.doors if hall.id in d.connects] == []
    halves = [o for o in seg.openings if set(o.connects) == {corridor.id, hall.id}]
    assert len(halves) == 2
    assert all(FRONT_X[0] < o.center[0] < FRONT_X[1] for o in halves)


def test_a_partition_meeting_the_front_is_no_post() -> None:
    """A partition running 3 m into the hall from the column: a wall meeting the front's line,
    deeper than a post; the gaps either side of it are two doors (into the hall's two parts)."""
    grid = hall_with_column(partition_m=3.0)
    seg = segment_spaces(grid)
    corridor = space_at(seg, grid, 2.0, 1.5)
    hall = space_at(seg, grid, 3.0, 5.0)
    doors = [d for d in seg.doors if hall.id in d.connects]
    assert [round(d.center[0], 1) for d in sorted(doors, key=lambda d: d.center[0])] == [3.5, 4.9]
    assert all(set(d.connects) == {corridor.id, hall.id} for d in doors)
    assert all(d.width_m == pytest.approx(1.0, abs=POS_TOL_M) for d in doors)


def test_two_doors_a_stretch_of_wall_apart_stay_two_doors() -> None:
    """0.7 m of wall between the office's doors is wider than a post: each is a door."""
    assert POST_MAX_WIDTH_M < 0.7
    grid = hall_with_column()
    seg = segment_spaces(grid)
    corridor = space_at(seg, grid, 2.0, 1.5)
    office = space_at(seg, grid, 11.0, 5.0)
    doors = [door_near(seg.doors, x, y) for x, y in OFFICE_DOORS_XY]
    assert all(set(d.connects) == {corridor.id, office.id} for d in doors)
    assert all(d.width_m == pytest.approx(0.9, abs=POS_TOL_M) for d in doors)
    assert len(seg.doors) == 2


@pytest.mark.parametrize("angle_deg", [17.0, 33.0])
def test_the_column_front_is_no_door_whatever_the_maps_rotation(angle_deg: float) -> None:
    """Turned about the map's centre: still the office's two doors and no door into the hall."""
    grid0 = hall_with_column()
    grid, _ = rotate(grid0, PointsAnnotation(), angle_deg)
    turn = math.radians(angle_deg)
    seg = segment_spaces(grid)
    hall = space_at(seg, grid, *rotate_point((3.0, 5.0), map_centre(grid0), turn))
    assert [d for d in seg.doors if hall.id in d.connects] == []
    for xy in OFFICE_DOORS_XY:
        door_near(seg.doors, *rotate_point(xy, map_centre(grid0), turn), tol=2 * POS_TOL_M)
    assert len(seg.doors) == 2
