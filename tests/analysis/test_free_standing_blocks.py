"""A solid thing standing free in a room (a vehicle, a counter, a table with its chairs) is no wall,
however big: the gaps between it and the walls are no doorways, and the room stays one room. A thin
wall standing free between two doorways still parts two rooms."""

from __future__ import annotations

import pytest
from analysis_maps import space_at

from langnav.analysis.elements import ElementKind
from langnav.analysis.pipeline import analyze
from langnav.analysis.segmentation import segment_spaces
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import UNKNOWN, OccupancyGrid

#: Why the engine-bay maps fail on the current rules (kept as the target, strict: if they pass,
#: the marker must go).
KNOWN_FAILURE = (
    "issue 8, known failure: a solid thing standing free in a room (a fire engine) is still read as "
    "a wall a doorway is cut beside. The rule tried in session 7 (a free-standing piece deeper than "
    "a wall and filling its convex hull is no wall) also merged blocks of rooms seen only from outside "
    "into their corridor (dev folders maps-3, maps-5, maps-6 lost recall), so it was taken out."
)


def bay_with_engines() -> OccupancyGrid:
    """A 20 m x 12 m vehicle bay with two fire engines (2.5 m x 8 m, seen only by their outline),
    a locker block 0.7 m beside the second engine, and a day room (4 m x 6.3 m) through a door in
    its north wall with a 1.8 m x 1.5 m table 1.0-1.2 m from its side walls."""
    b = MapBuilder(23.0, 22.0)
    b.room(1.0, 1.0, 21.0, 13.0)
    b.room(7.0, 13.2, 11.0, 19.5)
    b.door_h(9.0, 13.1, 0.9)
    for x0 in (5.3, 11.5):  # the engines: an outline 0.15 m thick round an unscanned inside
        b.box(x0, 2.5, x0 + 2.5, 10.5).rect(x0 + 0.15, 2.65, x0 + 2.35, 10.35, UNKNOWN)
    b.box(14.7, 5.0, 15.4, 7.0)  # lockers
    b.box(8.2, 15.5, 10.0, 17.0)  # the day room's table
    return b.build("bay")


@pytest.mark.xfail(strict=True, reason=KNOWN_FAILURE)
def test_a_vehicle_bay_with_engines_is_one_room() -> None:
    grid = bay_with_engines()
    seg = segment_spaces(grid)
    bay = space_at(seg, grid, 2.0, 6.0)
    assert bay.kind == ElementKind.ROOM
    # beside, between, before and behind the engines, and through the locker gap
    for x, y in ((10.0, 6.0), (19.0, 6.0), (10.0, 1.7), (10.0, 12.0), (15.05, 8.0), (14.4, 6.0)):
        assert space_at(seg, grid, x, y) is bay
    day = space_at(seg, grid, 7.5, 16.0)
    assert day is not bay
    for x, y in ((10.5, 16.0), (9.0, 18.5), (9.0, 14.0)):  # all round the table
        assert space_at(seg, grid, x, y) is day
    assert len(seg.rooms) == 2
    assert len(seg.doors) == 1


@pytest.mark.xfail(strict=True, reason=KNOWN_FAILURE)
def test_the_engines_and_the_table_are_obstacles_and_the_bay_middle_is_its_own() -> None:
    a = analyze(bay_with_engines())
    assert len(a.rooms) == 2
    bay = max(a.rooms, key=lambda r: r.area_m2)
    assert abs(bay.centroid[0] - 11.0) < 0.8 and abs(bay.centroid[1] - 7.0) < 0.8
    assert len(a.obstacles) == 4  # two engines, the lockers, the table
    engines = sorted((o for o in a.obstacles if o.area_m2 > 10.0), key=lambda o: o.centroid[0])
    assert len(engines) == 2
    assert abs(engines[0].centroid[0] - 6.55) < 0.1 and abs(engines[1].centroid[0] - 12.75) < 0.1
    assert all(o.room == bay.id for o in engines)


def l_shaped_lab(bench_y: float) -> OccupancyGrid:
    """An L-shaped lab (4.8 m x 7.8 m, and a 2.8 m x 6 m wing to the north) entered from a corridor
    along its west side, with a 2 m x 0.8 m bench standing free across its wide part (1.3 m from
    its west wall, 1.5 m from its east wall), its south edge at ``bench_y``."""
    b = MapBuilder(12.0, 18.0)
    b.room(3.0, 1.0, 7.8, 8.8)
    b.free(3.0, 8.8, 5.8, 14.8)
    b.wall(5.8, 8.8, 5.8, 14.8).wall(5.8, 8.8, 7.8, 8.8).wall(3.0, 14.8, 5.8, 14.8)
    b.wall(3.0 - 0.075, 8.8, 3.0 - 0.075, 14.8)
    b.room(0.8, 1.0, 2.8, 16.0)
    b.door_v(2.9, 5.3, 0.9)
    b.box(4.3, bench_y, 6.3, bench_y + 0.8)
    return b.build("lab")


@pytest.mark.xfail(strict=True, reason=KNOWN_FAILURE)
@pytest.mark.parametrize("bench_y", [3.8, 5.0, 6.0])
def test_a_lab_bench_across_a_room_leaves_it_one_room(bench_y: float) -> None:
    grid = l_shaped_lab(bench_y)
    seg = segment_spaces(grid)
    lab = space_at(seg, grid, 4.0, 2.0)
    for x, y in ((3.6, bench_y + 0.4), (7.2, bench_y + 0.4), (6.5, 8.0), (4.4, 14.0)):
        assert space_at(seg, grid, x, y) is lab
    assert len(seg.rooms) == 2  # the lab and the corridor


def test_a_thin_wall_standing_free_between_two_doorways_still_parts_two_rooms() -> None:
    # a 10 m x 6 m hall parted at x = 6 by a partition with a 0.9 m doorway at each end (to the wall face)
    b = MapBuilder(13.0, 8.0)
    b.room(1.0, 1.0, 11.0, 7.0)
    b.wall(6.0, 1.975, 6.0, 6.025)
    grid = b.build("parted")
    seg = segment_spaces(grid)
    west, east = space_at(seg, grid, 3.0, 4.0), space_at(seg, grid, 9.0, 4.0)
    assert west is not east
    assert len(seg.rooms) == 2
