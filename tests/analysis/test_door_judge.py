"""Golden buildings for door judgement (issue 8): an opening is a door only where it is cut in a
wall between two places (langnav.analysis.door_judge), drawn here with exactly known doors."""

from __future__ import annotations

import math

import numpy as np
import pytest
from analysis_maps import POS_TOL_M, door_near, space_at
from scipy import ndimage as ndi

from langnav.analysis.door_judge import (
    BEYOND_MIN_FLOOR_SHARE,
    JAMB_ALONG_MIN_SHARE,
    SEEN_FLOOR_MIN_M,
    STRIP_WALLED_MAX_SHARE,
    constriction_depth,
    evidence,
    floor_beyond,
    free_widths,
    is_door,
    is_furniture,
    judge_doors,
    line_turn_deg,
    on_wall_line,
)
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.seg_doors import RawDoor
from langnav.analysis.segmentation import UNKNOWN_ID, Segmentation, segment_spaces
from langnav.analysis.wall_lines import GAP_MIN_FLOOR_SHARE
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN, OccupancyGrid


def label_at(seg: Segmentation, grid: OccupancyGrid, x: float, y: float) -> int:
    r, c = grid.world_to_index(x, y)
    return int(seg.labels[int(r), int(c)])


def two_halls_and_a_passage() -> OccupancyGrid:
    """Two 5 m x 5 m halls joined by a wall-bounded passage 0.9 m wide and 2.5 m long (a
    corridor between two wings), and a 0.9 m door from the west hall to a 3 m x 3 m office
    through a wall 0.1 m thick."""
    b = MapBuilder(16.0, 10.0)
    b.room(0.5, 0.5, 5.5, 5.5).room(8.0, 0.5, 13.0, 5.5)
    b.wall(5.5, 1.95, 8.0, 1.95).wall(5.5, 2.95, 8.0, 2.95)  # the passage's walls
    b.free(5.45, 2.0, 8.05, 2.9)
    b.room(0.5, 5.6, 3.5, 8.6).door_h(2.0, 5.55, 0.9)
    return b.build("two halls and a passage")


def test_the_mouths_of_a_passage_are_no_doors_the_door_in_a_wall_is() -> None:
    """The passage is as narrow as its mouths for 2.5 m (longer than any wall is thick): its
    mouths are no doors, the halls stay joined by a way between them; the office door is one."""
    grid = two_halls_and_a_passage()
    seg = segment_spaces(grid)
    west, east, office = (label_at(seg, grid, x, y) for x, y in ((3.0, 2.5), (10.5, 2.5), (2.0, 7.0)))
    assert len({west, east, office}) == 3 and 0 not in (west, east, office)
    assert len(seg.doors) == 1
    door = seg.doors[0]
    assert math.dist(door.center, (2.0, 5.55)) <= POS_TOL_M
    assert door.width_m == pytest.approx(0.9, abs=POS_TOL_M)
    ids = {r.label: r.id for r in seg.rooms}
    assert set(door.connects) == {ids[west], ids[office]}
    # The halls are still joined: by the passage, as a way between them (not a door).
    ways = [set(o.connects) for o in seg.openings]
    assert {ids[west], ids[east]} in ways or any(
        {ids[west], x} in ways and {x, ids[east]} in ways for x in ids.values())


def test_constriction_depth_is_the_wall_thickness_for_a_door_and_the_length_of_a_passage() -> None:
    grid = two_halls_and_a_passage()
    free, occ = grid.cells == FREE, grid.cells == OCCUPIED
    res = grid.resolution_m
    # The office door: normal along y (rows), centre on the wall line.
    r, c = grid.world_to_cell(2.0, 5.55)
    ev = evidence(free, occ, (float(r), float(c)), (1.0, 0.0), 0.9, res, DEFAULT_PARAMS)
    assert ev.constriction_m <= 0.2
    # The passage's west mouth: normal along x (cols).
    r, c = grid.world_to_cell(5.5, 2.45)
    t, w = free_widths(free, (float(r), float(c)), (0.0, 1.0), res, 1.5)
    assert constriction_depth(t, w, 0.9) >= 1.4  # followed to the end of the look (1.5 m)
    assert np.all(w[(t > 0.2) & (t < 1.5)] == pytest.approx(0.9, abs=0.06))


def wall_with_gaps() -> OccupancyGrid:
    """A free 10 m x 6 m floor cut by a wall along y = 3 (0.1 m thick) with: a 0.9 m door at
    x = 2 (wall on both sides); a 0.9 m gap at x = 5 whose east end is the tip of a laser ray
    (the wall stops; beyond, a free streak into unknown); a 0.9 m gap at x = 8 between the
    wall's end and a lone speck."""
    b = MapBuilder(10.0, 6.0)
    b.free(0.0, 0.0, 10.0, 6.0)
    b.wall(0.0, 3.0, 1.55, 3.0).wall(2.45, 3.0, 4.55, 3.0)  # the door at x = 2
    b.unknown(5.45, 2.9, 7.55, 3.1).free(5.45, 2.95, 7.55, 3.0)  # ray streak in unknown
    b.wall(7.55, 3.0, 7.55, 3.0).rect(8.45, 2.95, 8.5, 3.05, OCCUPIED)  # the speck
    return b.build("wall with gaps")


@pytest.mark.parametrize(("x", "door"), [(2.0, True), (5.0, False), (8.0, False)])
def test_a_door_has_wall_at_both_jambs(x: float, door: bool) -> None:
    """Both jambs of a door are wall running on along its line; the end of a ray streak or a
    lone speck is no jamb."""
    grid = wall_with_gaps()
    walls = grid.cells == OCCUPIED
    r, c = grid.world_to_cell(x, 3.0)
    ev = evidence(grid.cells == FREE, walls, (float(r), float(c)), (1.0, 0.0), 0.9, grid.resolution_m,
                  DEFAULT_PARAMS)
    assert is_door(ev, DEFAULT_PARAMS, into_unknown=False) is door
    if door:
        assert min(ev.along) >= 0.9


def room_with_a_door_to_a_ray_fan() -> OccupancyGrid:
    """A 6 m x 4 m room with a 0.7 m gap in its east wall (0.1 m thick); beyond it the lidar saw
    a fan of rays spreading 60 degrees for 0.8 m into unknown, with unscanned notches between
    them, and the outside stays unknown."""
    b = MapBuilder(12.0, 6.0)
    b.room(0.5, 1.0, 6.5, 5.0, wall_m=0.1).door_v(6.55, 3.0, 0.7, depth_m=0.1)
    grid = b.build("door to a ray fan")
    cells = grid.cells.copy()
    res = grid.resolution_m
    for deg in range(-30, 31, 4):
        a = math.radians(deg)
        for i in range(int(0.8 / res) * 2):
            x = 6.6 + math.cos(a) * i * res / 2
            y = 3.0 + math.sin(a) * i * res / 2 * 1.0
            r, c = grid.world_to_index(x, y)
            cells[int(r), int(c)] = FREE
    return OccupancyGrid(cells, res, grid.origin_x_m, grid.origin_y_m, source="door to a ray fan")


def test_a_door_into_unexplored_beyond_a_ray_fan_is_found() -> None:
    """The gap in the wall is the one door, from the room into unexplored territory; the fan of
    rays beyond it (its notches taken into the room as unscanned wedges) hides no other."""
    grid = room_with_a_door_to_a_ray_fan()
    seg = segment_spaces(grid)
    assert len(seg.rooms) == 1
    assert len(seg.doors) == 1
    door = seg.doors[0]
    assert math.dist(door.center, (6.55, 3.0)) <= POS_TOL_M
    assert door.width_m == pytest.approx(0.7, abs=POS_TOL_M)
    assert door.connects == (seg.rooms[0].id, UNKNOWN_ID)


def test_beyond_a_door_lies_seen_floor_beyond_a_gap_to_a_ray_fan_only_streaks() -> None:
    """The room side of the ray-fan door is seen floor; the fan beyond is free streaks with
    unknown between them, next to no floor 0.25 m from the unknown."""
    grid = room_with_a_door_to_a_ray_fan()
    free = grid.cells == FREE
    far = ndi.distance_transform_edt(grid.cells != UNKNOWN) * grid.resolution_m >= SEEN_FLOOR_MIN_M
    r, c = grid.world_to_cell(6.55, 3.0)
    centre, normal = (float(r), float(c)), (0.0, 1.0)  # normal along +x: room -> fan
    assert floor_beyond(free, far, centre, normal, -1.0, grid.resolution_m) >= 0.9
    assert floor_beyond(free, far, centre, normal, 1.0, grid.resolution_m) < BEYOND_MIN_FLOOR_SHARE


def double_doors() -> OccupancyGrid:
    """Two 5 m x 4 m rooms side by side, a wall 0.1 m thick between them with a 1.8 m double
    door at y = 2, and a 1.8 m double door at y = 2 in the east room's outer wall onto the
    unscanned outside."""
    b = MapBuilder(14.0, 6.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 5.0, 4.0).room(5.1, 0.0, 10.0, 4.0)
    b.door_v(5.05, 2.0, 1.8, depth_m=0.2).door_v(10.05, 2.0, 1.8, depth_m=0.2)
    return b.build("double doors")


def test_a_double_door_cut_in_a_wall_is_a_door() -> None:
    """A double door (1.8 m: wider than a single door, within door_wide_max_width_m) in a wall
    is a door a person points at, between the two rooms and from the east room to the outside."""
    grid = double_doors()
    seg = segment_spaces(grid)
    west, east = space_at(seg, grid, 2.5, 2.0), space_at(seg, grid, 7.5, 2.0)
    assert west.id != east.id
    assert len(seg.doors) == 2 and not seg.openings
    inner, outer = door_near(seg.doors, 5.05, 2.0), door_near(seg.doors, 10.05, 2.0)
    assert set(inner.connects) == {west.id, east.id}
    assert outer.connects == (east.id, UNKNOWN_ID)
    for d in (inner, outer):
        assert d.width_m == pytest.approx(1.8, abs=POS_TOL_M)


def slanted_gap() -> OccupancyGrid:
    """An 8 m x 4 m floor parted by a partition along x = 4 from its north wall down to y = 2; the
    east room's south-west corner holds a closet (1 m x 1.4 m, never scanned inside: its faces are
    wall) whose corner stands 0.6 m east and 0.6 m south of the partition's end. The way between
    the rooms is the slanted gap from the partition's end to the closet's corner."""
    b = MapBuilder(10.0, 6.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 8.0, 4.0)
    b.wall(4.0, 4.0, 4.0, 2.0)
    b.rect(4.55, -0.05, 5.65, 1.45, OCCUPIED).unknown(4.6, 0.0, 5.6, 1.4)
    return b.build("slanted gap")


def test_a_slanted_gap_between_a_walls_end_and_a_corner_is_no_door() -> None:
    """The gap runs at 45 degrees to every wall around it: it is cut in no wall, so it is a way
    between the two rooms (an opening), not a door."""
    grid = slanted_gap()
    seg = segment_spaces(grid)
    west, east = space_at(seg, grid, 2.0, 3.0), space_at(seg, grid, 6.5, 3.0)
    assert west.id != east.id
    assert seg.doors == ()
    gap = door_near(seg.openings, 4.3, 1.7, tol=0.2)
    assert set(gap.connects) == {west.id, east.id}
    # The evidence says why: the line from jamb to jamb turns 45 degrees from the walls'.
    r, c = grid.world_to_cell(4.3, 1.7)
    assert line_turn_deg(grid.cells == OCCUPIED, (float(r), float(c)), math.radians(45.0),
                         grid.resolution_m) == pytest.approx(45.0, abs=3.0)


def room_with_a_wardrobe() -> OccupancyGrid:
    """A 4.3 m x 5 m room with a wardrobe (1 m wide, 2.5 m deep) against its north wall: only
    its front face was scanned, its inside is unknown and runs out through a laser gap in the
    wall behind it into the unscanned outside. Gaps of 1.9 m and 1.4 m lie between the wardrobe
    and the room's side walls, with the room's floor on both sides of them."""
    b = MapBuilder(8.0, 8.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 4.3, 5.0)
    b.unknown(1.9, 2.5, 2.9, 5.2).rect(1.9, 2.45, 2.9, 2.5, OCCUPIED)
    return b.build("room with a wardrobe")


def test_no_door_onto_the_unexplored_has_seen_floor_beyond_it() -> None:
    """A line from a side wall to the wardrobe's scanned face runs across the room, not into
    unexplored territory (its floor lies beyond it): the room is one space with no door."""
    grid = room_with_a_wardrobe()
    seg = segment_spaces(grid)
    assert len(seg.rooms) == 1
    assert seg.doors == ()


def corridor_mouth_beside_a_door() -> OccupancyGrid:
    """A 6 m x 6 m hall; a corridor 1.5 m wide runs 6 m east from its east wall (y 1.05-2.55);
    an office north of the corridor has its 0.8 m door in the corridor's north wall right beside
    the mouth (x 6.3-7.1), so the corridor widens into the office just past its mouth."""
    b = MapBuilder(14.0, 9.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 6.0, 6.0)
    b.wall(6.0, 1.0, 12.0, 1.0).wall(6.0, 2.6, 12.0, 2.6).wall(12.0, 1.0, 12.0, 2.6)
    b.free(5.95, 1.05, 11.95, 2.55)
    b.room(6.0, 2.6, 9.0, 5.0).door_h(6.7, 2.6, 0.8)
    return b.build("corridor mouth beside a door")


def test_the_mouth_of_a_corridor_is_no_door_the_door_beside_it_is() -> None:
    """Where the corridor runs into the hall, the hall's wall runs on past both of its walls and
    the office door beside the mouth breaks the corridor's narrowness just behind it: a
    candidate there looks like a door in the hall's wall. But the corridor behind it keeps the
    opening's width along most of its length: it is the corridor's mouth, not a door."""
    grid = corridor_mouth_beside_a_door()
    free, occ = grid.cells == FREE, grid.cells == OCCUPIED
    res = grid.resolution_m
    r, c = grid.world_to_cell(6.0, 1.8)
    mouth = RawDoor(1, 2, (float(r), float(c)), (0.0, 1.0), 1.5)
    r, c = grid.world_to_cell(6.7, 2.6)
    office = RawDoor(2, 3, (float(r), float(c)), (1.0, 0.0), 0.8)
    ev = evidence(free, occ, mouth.center_rc, mouth.normal_rc, mouth.width_m, res, DEFAULT_PARAMS)
    # Behind the mouth: the hall (6 m along the opening's line), the corridor (its 1.5 m width).
    assert ev.beyond_width_m[0] >= 5.0
    assert ev.beyond_width_m[1] == pytest.approx(1.5, abs=0.15)
    # The corridor's narrowness is broken just past the mouth: depth alone cannot tell.
    assert ev.constriction_m < DEFAULT_PARAMS.door_max_depth_m + DEFAULT_PARAMS.passage_min_length_m
    doors, rest = judge_doors([mouth, office], free, occ, res, DEFAULT_PARAMS, unknown=grid.cells == UNKNOWN)
    assert doors == [office] and rest == [mouth]
    # The whole analysis: the office door, and no door where the corridor meets the hall.
    seg = segment_spaces(grid)
    assert len(seg.doors) == 1
    assert math.dist(seg.doors[0].center, (6.7, 2.6)) <= POS_TOL_M


def corridor_into_hall() -> OccupancyGrid:
    """A 6 m x 5 m hall; a corridor 1.4 m wide runs 6 m south from its south-west corner (its
    west wall runs on as the hall's west wall: a wide junction, no wall between them); an office
    east of the corridor through a 0.9 m door."""
    b = MapBuilder(12.0, 14.0, origin=(-1.0, -1.0))
    b.room(0.0, 6.0, 6.0, 11.0)
    b.room(0.0, 0.0, 1.4, 6.0)
    b.free(0.0, 5.8, 1.4, 6.3)
    b.room(1.5, 1.0, 4.5, 4.0).door_v(1.45, 2.5, 0.9)
    return b.build("corridor into a hall")


def test_a_corridor_running_into_a_hall_has_no_door_there() -> None:
    """The exact doors: the office's, and none where the corridor widens into the hall."""
    grid = corridor_into_hall()
    seg = segment_spaces(grid)
    office, hall = space_at(seg, grid, 3.0, 2.5), space_at(seg, grid, 3.0, 8.5)
    assert office.id != hall.id
    assert len(seg.doors) == 1
    door = door_near(seg.doors, 1.45, 2.5)
    assert door.width_m == pytest.approx(0.9, abs=POS_TOL_M)
    assert set(door.connects) == {office.id, space_at(seg, grid, 0.7, 2.5).id}


def cabinet_row() -> OccupancyGrid:
    """A 10 m x 6 m open-plan floor with a row of three cabinets (1.5 m long, 0.6 m deep, seen
    only from around: an outline with the unknown inside) standing free across it at y 3.0-3.6,
    with 1 m gaps between them; an office east of the floor through a 0.9 m door."""
    b = MapBuilder(15.0, 8.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 10.0, 6.0).room(10.1, 0.0, 13.0, 3.0).door_v(10.05, 1.5, 0.9)
    for x0 in (1.0, 3.5, 6.0):
        b.rect(x0, 3.0, x0 + 1.5, 3.6, OCCUPIED).unknown(x0 + 0.05, 3.05, x0 + 1.45, 3.55)
    return b.build("cabinet row")


def test_a_gap_between_cabinets_is_no_door_the_door_in_the_wall_is() -> None:
    """The gap between two cabinets has wall-like jambs along its line (the cabinets' faces),
    but each jamb is a body standing free, unscanned inside, as deep as a cabinet: furniture.
    The office door's jambs are the building's walls."""
    grid = cabinet_row()
    free, occ, unknown = grid.cells == FREE, grid.cells == OCCUPIED, grid.cells == UNKNOWN
    res = grid.resolution_m
    r, c = grid.world_to_cell(3.0, 3.3)
    gap = RawDoor(1, 2, (float(r), float(c)), (1.0, 0.0), 1.0)
    r, c = grid.world_to_cell(10.05, 1.5)
    office = RawDoor(1, 3, (float(r), float(c)), (0.0, 1.0), 0.9)
    assert evidence(free, occ, gap.center_rc, gap.normal_rc, 1.0, res, DEFAULT_PARAMS, unknown).furniture_jamb
    assert not evidence(free, occ, office.center_rc, office.normal_rc, 0.9, res, DEFAULT_PARAMS, unknown).furniture_jamb
    doors, rest = judge_doors([gap, office], free, occ, res, DEFAULT_PARAMS, unknown=unknown)
    assert doors == [office] and rest == [gap]
    # A closet never entered (1.2 m deep) is walled the same way, but deeper than furniture.
    r, c = grid.world_to_cell(1.0, 3.3)
    assert is_furniture(free, unknown, (float(r), float(c)), res)
    b = MapBuilder(8.0, 8.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 6.0, 6.0).rect(1.0, 3.0, 3.0, 4.2, OCCUPIED).unknown(1.05, 3.05, 2.95, 4.15)
    closet = b.build("closet")
    r, c = closet.world_to_cell(1.0, 3.5)
    assert not is_furniture(closet.cells == FREE, closet.cells == UNKNOWN, (float(r), float(c)), res)
    # The whole analysis: one floor, the office, and the office door only.
    seg = segment_spaces(grid)
    assert len(seg.doors) == 1
    assert math.dist(seg.doors[0].center, (10.05, 1.5)) <= POS_TOL_M


def wall_stub_and_pillar() -> OccupancyGrid:
    """A 9 m x 6 m room; a wall stub runs 3 m south from its north wall at x = 4 and ends in
    open floor at y = 3; a pillar 0.3 m square stands 0.75 m south of the stub's end."""
    b = MapBuilder(12.0, 9.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 9.0, 6.0)
    b.wall(4.0, 6.0, 4.0, 3.0)
    b.box(3.85, 1.95, 4.15, 2.25)
    return b.build("wall stub and pillar")


def test_the_gap_between_a_wall_stubs_end_and_a_pillar_is_no_door() -> None:
    """The stub's end is a jamb (its wall runs on along the gap's line), but the pillar's face
    is no wall: it fills part of a wall's length along the line and stops, a post standing in
    the floor. A door beside a corner keeps its jamb: there the wall turns across the line."""
    grid = wall_stub_and_pillar()
    free, occ, unknown = grid.cells == FREE, grid.cells == OCCUPIED, grid.cells == UNKNOWN
    r, c = grid.world_to_cell(4.0, 2.6)
    gap = RawDoor(1, 2, (float(r), float(c)), (0.0, 1.0), 0.7)
    ev = evidence(free, occ, gap.center_rc, gap.normal_rc, 0.7, grid.resolution_m, DEFAULT_PARAMS, unknown)
    assert max(ev.along) == pytest.approx(1.0) and min(ev.along) == 0.0
    assert judge_doors([gap], free, occ, grid.resolution_m, DEFAULT_PARAMS, unknown=unknown)[0] == []
    seg = segment_spaces(grid)
    assert len(seg.rooms) == 1 and seg.doors == ()


def partition_short_of_a_wall(return_m: float) -> OccupancyGrid:
    """An 8 m x 4 m floor parted by a partition along x = 4 from its north wall down to y = 1.1;
    the south wall has a return of ``return_m`` along x = 4 (0: none), so the way between the two
    halves is a 0.9 m gap from the partition's end to that return (or to the bare south wall's
    face, 1.05 m)."""
    b = MapBuilder(10.0, 6.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 8.0, 4.0)
    b.wall(4.0, 4.0, 4.0, 1.1)
    if return_m > 0:
        b.wall(4.0, 0.0, 4.0, 0.05 + return_m)
    return b.build("partition short of a wall")


def test_a_gap_beside_a_corner_is_a_door_with_a_return_and_a_way_round_without() -> None:
    """With a 0.15 m return of wall beside it at the south wall (a door frame's jamb), the gap is
    a door; where the partition simply stops short of the bare south wall, the gap is the way
    round its end (an opening between the halves), not a door."""
    for return_m, door in ((0.15, True), (0.0, False)):
        grid = partition_short_of_a_wall(return_m)
        seg = segment_spaces(grid)
        west, east = space_at(seg, grid, 2.0, 2.5), space_at(seg, grid, 6.0, 2.5)
        assert west.id != east.id
        y = (1.1 + 0.05 + return_m) / 2
        if door:
            assert len(seg.doors) == 1
            d = door_near(seg.doors, 4.0, y)
            assert set(d.connects) == {west.id, east.id}
            assert d.width_m == pytest.approx(1.1 - 0.05 - return_m, abs=POS_TOL_M)
        else:
            assert seg.doors == ()
            # (The boundary the flood draws there is slanted: its centre lies off the line.)
            assert set(door_near(seg.openings, 4.0, y, tol=0.4).connects) == {west.id, east.id}
        # The evidence says why: the jamb at the south wall runs on along the door's line only
        # with the return.
        r, c = grid.world_to_cell(4.0, y)
        ev = evidence(grid.cells == FREE, grid.cells == OCCUPIED, (float(r), float(c)), (0.0, 1.0),
                      1.1 - 0.05 - return_m, grid.resolution_m, DEFAULT_PARAMS)
        assert (min(ev.along) >= JAMB_ALONG_MIN_SHARE) is door


def room_with_an_unscanned_gap(scanned: bool) -> OccupancyGrid:
    """A 6 m x 4 m room whose north wall has a 0.8 m gap at x = 3, the outside unscanned; the gap
    itself was scanned (free: the lidar saw through it, and 1 m of floor beyond it) or not
    (unknown: a notch the scan never reached, between two walls' ends)."""
    b = MapBuilder(8.0, 7.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 6.0, 4.0).door_h(3.0, 4.0, 0.8, depth_m=0.2)
    if scanned:
        b.free(2.65, 4.0, 3.35, 5.0)
    else:
        b.unknown(2.6, 3.9, 3.4, 4.1)
    return b.build("room with an unscanned gap")


def test_a_door_onto_the_unexplored_was_seen_through() -> None:
    """The gap the lidar saw through is a door from the room onto the unexplored; the same gap
    left unscanned (unknown from jamb to jamb) is no opening the robot saw, and no door."""
    for scanned in (True, False):
        grid = room_with_an_unscanned_gap(scanned)
        seg = segment_spaces(grid)
        assert len(seg.rooms) == 1
        if scanned:
            assert len(seg.doors) == 1
            d = door_near(seg.doors, 3.0, 4.0)
            assert d.connects == (seg.rooms[0].id, UNKNOWN_ID)
            assert d.width_m == pytest.approx(0.8, abs=POS_TOL_M)
        else:
            assert seg.doors == ()
        r, c = grid.world_to_cell(3.0, 4.0)
        ev = evidence(grid.cells == FREE, grid.cells == OCCUPIED, (float(r), float(c)), (1.0, 0.0), 0.8,
                      grid.resolution_m, DEFAULT_PARAMS, unknown=grid.cells == UNKNOWN)
        assert (ev.scanned_share >= GAP_MIN_FLOOR_SHARE) is scanned


def wall_with_a_clear_and_a_blocked_gap() -> OccupancyGrid:
    """A 10 m x 6 m room parted at y = 3 by a wall with two 0.9 m gaps, at x = 2.5 and x = 7.5;
    the legs of a chair (5 cm specks, 0.3 m apart) stand in the second gap's line."""
    b = MapBuilder(12.0, 8.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 10.0, 6.0).wall(0.0, 3.0, 10.0, 3.0)
    b.door_h(2.5, 3.0, 0.9).door_h(7.5, 3.0, 0.9)
    b.rect(7.3, 2.975, 7.35, 3.025, OCCUPIED).rect(7.65, 2.975, 7.7, 3.025, OCCUPIED)
    return b.build("a clear and a blocked gap")


def test_a_gap_blocked_in_its_middle_is_no_door() -> None:
    """Both gaps have wall jambs and open onto rooms wider than themselves; across the second
    one, through its centre, the floor is open for less than the robot's width (clutter stands
    in it): the robot cannot drive through it, it is no door."""
    grid = wall_with_a_clear_and_a_blocked_gap()
    free, occ, unknown = grid.cells == FREE, grid.cells == OCCUPIED, grid.cells == UNKNOWN
    res = grid.resolution_m
    cands = []
    for x in (2.5, 7.5):
        r, c = grid.world_to_cell(x, 3.0)
        cands.append(RawDoor(1, 2, (float(r) + 0.5, float(c) + 0.5), (1.0, 0.0), 0.9))
    clear, blocked = cands
    ev_clear = evidence(free, occ, clear.center_rc, clear.normal_rc, 0.9, res, DEFAULT_PARAMS, unknown)
    ev_blocked = evidence(free, occ, blocked.center_rc, blocked.normal_rc, 0.9, res, DEFAULT_PARAMS, unknown)
    assert ev_clear.clear_width_m == pytest.approx((0.9, 0.9), abs=2 * res)
    assert max(ev_blocked.clear_width_m) < 2 * DEFAULT_PARAMS.robot_radius_m
    doors, rest = judge_doors(cands, free, occ, res, DEFAULT_PARAMS, unknown=unknown)
    assert doors == [clear] and rest == [blocked]


def aisle_between_blocks_and_a_door_to_rays() -> OccupancyGrid:
    """A 10 m x 5 m hall; north of it two shelf blocks (scanned on their faces, unknown inside)
    stand 0.8 m apart, and the aisle between them was seen 1.5 m in; a 0.9 m door in the hall's
    east wall (0.1 m thick) opens onto territory never entered, seen only as the rays through it."""
    b = MapBuilder(14.0, 10.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 10.0, 5.0)
    b.rect(2.0, 5.0, 3.5, 8.0, OCCUPIED).unknown(2.05, 5.05, 3.45, 7.95)
    b.rect(4.3, 5.0, 6.0, 8.0, OCCUPIED).unknown(4.35, 5.05, 5.95, 7.95)
    b.free(3.55, 4.9, 4.25, 6.5)
    b.door_v(10.0, 2.5, 0.9, depth_m=0.1)
    b.free(10.05, 2.2, 11.5, 2.8)
    return b.build("aisle between blocks and a door to rays")


def test_the_mouth_of_an_aisle_running_into_the_unknown_is_no_door() -> None:
    """Both openings lead from the hall into unexplored territory and have wall at both jambs.
    Beyond the door lie only the rays through it, bounded by the unknown; beyond the aisle's
    mouth the strip seen runs on as narrow as the mouth between the blocks' scanned sides: an
    aisle running on, not a door."""
    grid = aisle_between_blocks_and_a_door_to_rays()
    free, occ, unknown = grid.cells == FREE, grid.cells == OCCUPIED, grid.cells == UNKNOWN
    res = grid.resolution_m
    r, c = grid.world_to_cell(3.9, 5.0)
    aisle = RawDoor(1, 0, (float(r) + 0.5, float(c) + 0.5), (1.0, 0.0), 0.75)
    r, c = grid.world_to_cell(10.0, 2.5)
    door = RawDoor(1, 0, (float(r) + 0.5, float(c) + 0.5), (0.0, 1.0), 0.9)
    ev_aisle = evidence(free, occ, aisle.center_rc, aisle.normal_rc, 0.75, res, DEFAULT_PARAMS, unknown,
                        into_unknown=True)
    ev_door = evidence(free, occ, door.center_rc, door.normal_rc, 0.9, res, DEFAULT_PARAMS, unknown,
                       into_unknown=True)
    assert ev_aisle.walled_beyond_share > STRIP_WALLED_MAX_SHARE
    assert ev_door.walled_beyond_share == 0.0
    doors, rest = judge_doors([aisle, door], free, occ, res, DEFAULT_PARAMS, unknown=unknown)
    assert doors == [door] and rest == [aisle]


def door_beside_a_corner_with_a_shadow() -> OccupancyGrid:
    """A 10 m x 4 m hall; north of it a 4.5 m x 4 m room whose east wall meets the hall's north
    wall at x = 5.5, where a 0.9 m door (centre x = 5.0) opens beside that corner; east of the
    room, unscanned."""
    b = MapBuilder(12.0, 10.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 10.0, 4.0).room(1.0, 4.0, 5.5, 8.0)
    b.unknown(5.55, 4.05, 9.95, 8.0)
    b.door_h(5.0, 4.0, 0.9)
    return b.build("door beside a corner")


def test_a_door_is_judged_on_its_wall_line_not_where_the_flood_put_its_boundary() -> None:
    """The flood's boundary between the hall and the room lies 0.3 m into the room: judged
    there, the jamb beside the corner has no wall along that line. On the wall line (the
    narrowest crossing next to it) both jambs are walls: it is a door."""
    grid = door_beside_a_corner_with_a_shadow()
    free, occ, unknown = grid.cells == FREE, grid.cells == OCCUPIED, grid.cells == UNKNOWN
    res = grid.resolution_m
    r, c = grid.world_to_cell(5.0, 4.3)
    off = RawDoor(1, 2, (float(r) + 0.5, float(c) + 0.5), (1.0, 0.0), 0.9)
    ev_off = evidence(free, occ, off.center_rc, off.normal_rc, 0.9, res, DEFAULT_PARAMS, unknown)
    assert not is_door(ev_off, DEFAULT_PARAMS, into_unknown=False, width_m=0.9)
    on = on_wall_line(free, off, res)
    x, y = grid.grid_to_world(*on.center_rc)
    assert math.dist((float(x), float(y)), (5.0, 4.0)) <= 2 * res
    doors, rest = judge_doors([off], free, occ, res, DEFAULT_PARAMS, unknown=unknown)
    assert doors == [off] and rest == []
