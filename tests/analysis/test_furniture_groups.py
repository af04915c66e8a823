"""A group of furniture standing free in a room (desks pushed together with their chairs) is no
wall, however large: the gaps between it and the walls are no doorways and the room stays one
room (ROSE² freiburg_building79's lab, strands g4s_y2's open-plan office, b9_town_hall's council
chamber were cut in two or three at such gaps). A stretch of wall between two doorways stays a
wall, with a cupboard built against it, at its end, or a partition's cabinets along it."""

from __future__ import annotations

import pytest
from analysis_maps import POS_TOL_M, door_near, space_at, turned

from langnav.analysis.elements import ElementKind
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.seg_core import JambJudge, clean_floor
from langnav.analysis.segmentation import segment_spaces
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import OccupancyGrid


def office_with_desks() -> OccupancyGrid:
    """A 12 m x 7 m office under a 2 m corridor (one 0.9 m door at x = 3), with a group of desks
    in its middle: a 4.8 m column of 0.7 m desks and a 3 m row across it, two chairs against
    them; 1.1 m of floor between the group and the office's south and north walls."""
    b = MapBuilder(15.0, 12.0)
    b.room(1.0, 1.0, 13.0, 8.0)
    b.room(1.0, 8.15, 13.0, 10.15)
    b.door_h(3.0, 8.075, 0.9)
    b.box(6.65, 2.1, 7.35, 6.9).box(5.5, 4.15, 8.5, 4.85)
    b.box(6.0, 3.0, 6.65, 3.5).box(7.35, 5.5, 7.9, 6.0)
    return b.build("office")


def council_chamber() -> OccupancyGrid:
    """A 12 m x 10 m council chamber under a corridor (a 1.6 m double door), with a horseshoe
    of council desks 0.6 m deep in its middle: 5.4 m across, its arms 5.8 m long and open to the
    south, their ends 1.2 m from the south wall (b9_town_hall's chamber was cut in three)."""
    b = MapBuilder(14.0, 15.0)
    b.room(1.0, 1.0, 13.0, 11.0)
    b.room(1.0, 11.15, 13.0, 13.15)
    b.door_h(7.0, 11.075, 1.6)
    b.box(4.3, 2.2, 4.9, 8.0).box(9.1, 2.2, 9.7, 8.0).box(4.3, 7.4, 9.7, 8.0)
    return b.build("council chamber")


def parted_office() -> OccupancyGrid:
    """The same office parted at x = 7 by a partition from 2.1 m to 6.9 m (a 1.1 m doorway at
    each end) with cabinets 0.6 m deep along its west side."""
    b = MapBuilder(15.0, 12.0)
    b.room(1.0, 1.0, 13.0, 8.0)
    b.room(1.0, 8.15, 13.0, 10.15)
    b.door_h(3.0, 8.075, 0.9)
    b.wall(7.0, 2.1, 7.0, 6.9).box(6.32, 2.5, 6.925, 6.5)
    return b.build("parted office")


def partition_with_cupboard() -> OccupancyGrid:
    """A 12 m x 5.4 m office under a corridor, parted at x = 7 by a 1.2 m partition with a
    1.05 m x 1.9 m cupboard at its north end (as deep as a desk group, spread as much), a
    1.2 m doorway between the partition and the south wall and 1.1 m between the cupboard and
    the north wall."""
    b = MapBuilder(15.0, 10.0)
    b.room(1.0, 1.0, 13.0, 6.4)
    b.room(1.0, 6.55, 13.0, 8.55)
    b.door_h(3.0, 6.475, 0.9)
    b.wall(7.0, 2.2, 7.0, 3.4).box(6.5, 3.4, 7.55, 5.3)
    return b.build("partition with a cupboard")


def ward_under_corridor() -> OccupancyGrid:
    """A 2 m corridor over a ward; the wall between them has a door-wide gap each side of a
    3.5 m stretch (x 6-9.5) with a 1.8 m x 0.9 m cupboard built against its ward side."""
    b = MapBuilder(16.0, 9.0)
    b.room(1.0, 1.0, 15.0, 8.15)
    b.wall(1.0, 6.075, 5.0, 6.075).wall(6.0, 6.075, 9.5, 6.075).wall(10.5, 6.075, 15.0, 6.075)
    b.box(6.0, 5.1, 7.8, 6.0)
    return b.build("ward")


@pytest.mark.parametrize("degrees", [0.0, 30.0])
def test_a_group_of_desks_standing_free_leaves_the_office_one_room(degrees: float) -> None:
    grid = office_with_desks()
    if degrees:
        grid = turned(grid, degrees)
    seg = segment_spaces(grid)
    assert len(seg.rooms) == 2
    assert seg.openings == ()
    assert len(seg.doors) == 1
    if degrees:
        return  # the points below are in the unturned map's frame
    office = space_at(seg, grid, 2.0, 4.5)
    assert office.kind == ElementKind.ROOM
    # west, east, north and south of the desks, and in the gaps between them and the walls
    for x, y in ((12.0, 4.5), (7.0, 7.45), (7.0, 1.55), (5.0, 2.0), (9.0, 7.0)):
        assert space_at(seg, grid, x, y) is office
    corridor = space_at(seg, grid, 7.0, 9.15)
    assert corridor.kind == ElementKind.HALLWAY
    assert office.area_m2 == pytest.approx(78.5, abs=0.5)
    assert corridor.area_m2 == pytest.approx(24.0, abs=0.2)
    door = door_near(seg.doors, 3.0, 8.075)
    assert set(door.connects) == {office.id, corridor.id}


def test_a_horseshoe_of_desks_leaves_the_chamber_one_room() -> None:
    grid = council_chamber()
    seg = segment_spaces(grid)
    chamber = space_at(seg, grid, 2.0, 6.0)
    assert chamber.kind == ElementKind.ROOM
    # inside the horseshoe, east of it, north of it, and between its ends and the south wall
    for x, y in ((7.0, 4.0), (12.0, 6.0), (7.0, 9.5), (4.6, 1.6), (9.4, 1.6)):
        assert space_at(seg, grid, x, y) is chamber
    assert len(seg.rooms) == 2
    assert seg.openings == ()
    door = door_near(seg.doors, 7.0, 11.075)
    assert set(door.connects) == {chamber.id, space_at(seg, grid, 7.0, 12.1).id}


def test_a_partition_with_cabinets_along_it_still_parts_two_rooms() -> None:
    grid = parted_office()
    seg = segment_spaces(grid)
    west, east = space_at(seg, grid, 3.8, 4.5), space_at(seg, grid, 10.0, 4.5)
    assert west is not east
    assert {west.kind, east.kind} == {ElementKind.ROOM}
    assert len(seg.rooms) == 3
    # the two doorways at the partition's ends are openings between the two halves
    assert sorted(o.center[1] for o in seg.openings) == pytest.approx([1.55, 7.45], abs=POS_TOL_M)
    assert all(set(o.connects) == {west.id, east.id} for o in seg.openings)


def test_a_partition_with_a_cupboard_at_its_end_still_parts_two_rooms() -> None:
    grid = partition_with_cupboard()
    seg = segment_spaces(grid)
    west, east = space_at(seg, grid, 4.0, 3.7), space_at(seg, grid, 10.0, 3.7)
    assert west is not east
    assert len(seg.rooms) == 3
    # the doorway south of the partition, and the one north of the cupboard
    south, north = sorted(seg.openings, key=lambda o: o.center[1])
    assert south.center == pytest.approx((7.08, 1.55), abs=POS_TOL_M)
    assert north.center == pytest.approx((7.53, 5.85), abs=POS_TOL_M)
    assert all(set(o.connects) == {west.id, east.id} for o in seg.openings)


def test_a_stretch_of_wall_with_a_cupboard_against_it_is_wall() -> None:
    grid = ward_under_corridor()
    seg = segment_spaces(grid)
    ward, corridor = space_at(seg, grid, 8.0, 3.5), space_at(seg, grid, 8.0, 7.1)
    assert ward is not corridor
    assert len(seg.rooms) == 2
    assert sorted(d.center[0] for d in seg.doors) == pytest.approx([5.5, 10.0], abs=POS_TOL_M)
    assert all(set(d.connects) == {ward.id, corridor.id} for d in seg.doors)


def _judge(grid: OccupancyGrid, directions: list[float]) -> JambJudge:
    fl = clean_floor(grid.cells, grid.resolution_m, DEFAULT_PARAMS)
    return JambJudge(fl.floor, fl.clearance_m, grid.resolution_m, DEFAULT_PARAMS, fl.wall_pieces, directions)


def test_the_jambs_a_desk_group_and_a_walls_stretch_make() -> None:
    # The desk group (5 m2, spread both ways, 1 m deep where its desks cross) is no jamb; the
    # ward's stretch of wall, as deep and as spread with its cupboard, is: the corridor's wall
    # runs on in line with it beyond both gaps.
    office = office_with_desks()
    judge = _judge(office, [0.0])
    r, c = office.world_to_index(7.0, 6.85)
    assert not judge.structural((int(r), int(c)), (0.0, 1.0))
    r, c = office.world_to_index(7.0, 8.0)  # the office's north wall across the gap
    assert judge.structural((int(r), int(c)), (0.0, 1.0))
    ward = ward_under_corridor()
    judge = _judge(ward, [0.0])
    r, c = ward.world_to_index(9.45, 6.075)
    assert judge.structural((int(r), int(c)), (0.0, 1.0))
