"""Rooms and hallways: golden buildings for the ways spaces and their kind went wrong on real
and drawn maps (issue 8). A hallway is judged by its typical width wall to wall and by how it
connects: a short hall that many rooms open onto is a hallway, however a bay widens it; a shop
whose counter leaves two corridor-wide aisles is a room; a lounge open onto a corridor is a room
apart from it; a small bathroom behind its door is a room of its own."""

from __future__ import annotations

import dataclasses

import pytest
from analysis_maps import POS_TOL_M, door_near, space_at

from langnav.analysis.elements import ElementKind
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.segmentation import UNKNOWN_ID, segment_spaces
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import OccupancyGrid


def hall_with_a_bay() -> OccupancyGrid:
    """A 2 m x 9 m hall with a 1.4 m x 3 m bay in its east wall (a nurse station, a coat niche)
    and five doorways: four 0.9 m doors into 4 m deep rooms, two a side, and the front door."""
    b = MapBuilder(16.0, 12.0)
    b.room(6.0, 1.0, 8.0, 10.0)  # the hall
    b.room(2.0, 1.0, 6.0, 5.0).door_v(6.0, 3.0, 0.9)
    b.room(2.0, 5.0, 6.0, 10.0).door_v(6.0, 8.0, 0.9)
    b.room(8.0, 1.0, 12.0, 3.95).door_v(8.0, 2.4, 0.9)
    b.room(8.0, 7.05, 12.0, 10.0).door_v(8.0, 8.6, 0.9)
    b.free(8.0, 4.0, 9.4, 7.0)  # the bay, cut into the east wall between the two east rooms
    b.wall(9.45, 3.95, 9.45, 7.05)
    b.door_h(7.0, 1.0, 0.9)  # the front door, onto the unknown outside
    return b.build("hall with a bay")


def test_a_short_hall_many_rooms_open_onto_is_a_hallway_despite_its_bay() -> None:
    """The bay widens the hall to 3.4 m at one point and the hall is only 4.5 times longer than
    wide: judged by its widest point or its length alone it would be a room. Five doorways open
    off it: a space that serves that many others is walked through."""
    grid = hall_with_a_bay()
    seg = segment_spaces(grid)
    hall = space_at(seg, grid, 7.0, 5.0)
    assert space_at(seg, grid, 8.7, 5.5) is hall  # the bay is part of it
    assert space_at(seg, grid, 7.0, 9.5) is hall
    assert hall.kind == ElementKind.HALLWAY
    assert 1.6 <= hall.width_m <= 2.1  # its typical width, not the bay's
    rooms = [space_at(seg, grid, x, y) for x, y in ((4.0, 3.0), (4.0, 7.5), (10.0, 2.4), (10.0, 8.6))]
    assert len({r.id for r in rooms}) == 4
    assert [r.kind for r in rooms] == [ElementKind.ROOM] * 4
    assert len(seg.rooms) == 5
    assert len(seg.doors) == 5
    for (x, y), room in zip(((6.05, 3.0), (6.05, 8.0), (7.95, 2.4), (7.95, 8.6)), rooms, strict=True):
        d = door_near(seg.doors, x, y)
        assert set(d.connects) == {hall.id, room.id}
        assert d.width_m == pytest.approx(0.9, abs=POS_TOL_M)
    assert door_near(seg.doors, 7.0, 0.95).connects == (hall.id, UNKNOWN_ID)


def shop_with_a_counter() -> OccupancyGrid:
    """A 16 m x 6 m shop with a 10 m x 1.2 m display counter down its middle (two 2.4 m aisles
    beside it) and a door at each end."""
    b = MapBuilder(20.0, 10.0)
    b.room(1.0, 1.0, 17.0, 7.0)
    b.box(4.0, 3.4, 14.0, 4.6)
    b.door_v(1.0, 2.0, 0.9).door_v(17.0, 6.0, 0.9)
    return b.build("shop with a counter")


def test_a_shop_whose_counter_leaves_corridor_wide_aisles_is_a_room() -> None:
    """Its aisles are as narrow as a corridor and it has two doors, but wall to wall (the counter
    stands on its floor) it is 6 m wide: a room, as a person sees it."""
    grid = shop_with_a_counter()
    seg = segment_spaces(grid)
    assert len(seg.rooms) == 1
    shop = seg.rooms[0]
    assert space_at(seg, grid, 9.0, 2.2) is shop
    assert space_at(seg, grid, 9.0, 5.8) is shop
    assert shop.kind == ElementKind.ROOM
    assert len(seg.doors) == 2
    assert {d.connects for d in seg.doors} == {(shop.id, UNKNOWN_ID)}


def corridor_open_onto_a_lounge() -> OccupancyGrid:
    """A 2.4 m corridor, 40 m long, with a 12 m x 8 m lounge open onto its south side along the
    lounge's whole length (no wall between: a care home's day room, a lobby), armchairs and a
    table in the lounge, and an office off the corridor through a 0.9 m door."""
    b = MapBuilder(44.0, 18.0)
    b.room(1.0, 10.0, 41.0, 12.4)
    b.room(15.0, 2.0, 27.0, 10.0)
    b.free(15.05, 9.8, 26.95, 10.2)  # the open side
    b.room(5.0, 12.4, 9.0, 16.4).door_h(7.0, 12.4, 0.9)
    b.box(18.0, 5.0, 19.0, 6.0).box(22.0, 5.0, 23.5, 6.0)
    return b.build("corridor open onto a lounge")


def test_a_lounge_open_onto_a_corridor_is_a_room_apart_from_the_corridor() -> None:
    """Nothing narrows where the corridor meets the lounge, so the flood sees one space; but
    the lounge is far wider than any corridor (a 6 m disc fits in it over a stretch): it is a
    hall of its own, a room, and the corridor runs on either side of it as hallways."""
    grid = corridor_open_onto_a_lounge()
    seg = segment_spaces(grid)
    lounge = space_at(seg, grid, 21.0, 5.0)
    west = space_at(seg, grid, 5.0, 11.2)
    east = space_at(seg, grid, 37.0, 11.2)
    office = space_at(seg, grid, 7.0, 14.4)
    assert len({lounge.id, west.id, east.id, office.id}) == 4
    assert len(seg.rooms) == 4
    assert lounge.kind == ElementKind.ROOM
    assert west.kind == ElementKind.HALLWAY
    assert east.kind == ElementKind.HALLWAY
    assert office.kind == ElementKind.ROOM
    assert lounge.area_m2 == pytest.approx(12 * 8 + 12 * 2.4, rel=0.1)  # with the corridor beside it
    assert west.width_m == pytest.approx(2.4, abs=0.15)
    d = door_near(seg.doors, 7.0, 12.4)
    assert set(d.connects) == {west.id, office.id}
    # The corridor and the lounge meet through openings as wide as the corridor, not doors.
    assert {frozenset(o.connects) for o in seg.openings} == {frozenset((lounge.id, west.id)),
                                                             frozenset((lounge.id, east.id))}
    assert all(o.width_m == pytest.approx(2.4, abs=0.15) for o in seg.openings)


def bedroom_with_an_en_suite() -> OccupancyGrid:
    """A 4 m x 4 m bedroom with a 1.4 m x 1.8 m en-suite bathroom behind a 0.75 m door in its
    east wall, and a 2.2 m corridor north of it through a 0.9 m door."""
    b = MapBuilder(10.0, 9.0)
    b.room(1.0, 1.0, 5.0, 5.0)
    b.room(5.0, 1.0, 6.4, 2.8).door_v(5.0, 1.9, 0.75)
    b.room(1.0, 5.0, 7.0, 7.2).door_h(3.0, 5.0, 0.9)
    return b.build("bedroom with an en-suite")


def test_a_small_bathroom_behind_its_door_is_a_room_of_its_own() -> None:
    """Its door is wide for its size (0.75 m for 2.5 m2), as a bay's mouth is; but a bay is
    open across its whole width, and the door takes less than half of the bathroom's wall.
    With the wall-line closure off (a noisy scan whose wall lines are broken), the flood
    alone must keep it apart."""
    grid = bedroom_with_an_en_suite()
    params = dataclasses.replace(DEFAULT_PARAMS, seg_wall_line_gap_max_m=0.0)
    seg = segment_spaces(grid, params)
    bedroom = space_at(seg, grid, 3.0, 3.0)
    bathroom = space_at(seg, grid, 5.7, 1.9)
    corridor = space_at(seg, grid, 4.0, 6.1)
    assert len({bedroom.id, bathroom.id, corridor.id}) == 3
    assert len(seg.rooms) == 3
    assert bathroom.kind == ElementKind.ROOM
    assert bathroom.area_m2 == pytest.approx(1.4 * 1.8, rel=0.15)
    d = door_near(seg.doors, 4.95, 1.9)
    assert set(d.connects) == {bedroom.id, bathroom.id}
    assert d.width_m == pytest.approx(0.75, abs=POS_TOL_M)


def guest_room_with_an_en_suite() -> OccupancyGrid:
    """A 2 m x 7 m hotel guest room entered from a corridor through a 0.9 m door at its north
    end, with a 2.5 m x 2.5 m en-suite bathroom behind a 0.8 m door in its east wall."""
    b = MapBuilder(12.0, 12.0)
    b.room(1.0, 1.0, 3.0, 8.0)
    b.room(3.0, 1.0, 5.5, 3.5).door_v(3.0, 2.5, 0.8)
    b.room(1.0, 8.0, 11.0, 10.2).door_h(2.0, 8.0, 0.9)
    return b.build("guest room with an en-suite")


def test_a_narrow_room_with_an_en_suite_is_a_room_not_a_hallway() -> None:
    """The guest room is as narrow and long as a corridor and has two doors, but its second
    door leads only into its own bathroom (a smaller dead end): no one walks through it."""
    grid = guest_room_with_an_en_suite()
    seg = segment_spaces(grid)
    guest = space_at(seg, grid, 2.0, 5.0)
    bathroom = space_at(seg, grid, 4.2, 2.2)
    assert guest.id != bathroom.id
    assert len(seg.rooms) == 3
    assert guest.kind == ElementKind.ROOM
    assert bathroom.kind == ElementKind.ROOM
    assert set(door_near(seg.doors, 2.95, 2.5).connects) == {guest.id, bathroom.id}
    assert guest.id in door_near(seg.doors, 2.0, 7.95).connects



def store_round_a_shelf_block() -> OccupancyGrid:
    """A 6 m x 5 m dispensary (a store room, a kennel room) whose 2.2 m x 3.2 m shelf block
    stands against its back wall, leaving a walk 1.8-1.9 m wide round it, entered from a 2 m
    corridor through a 0.9 m door; and, for contrast, a 2 m corridor looping round a 6 m x
    10 m core (a lift and stair block) with four offices off it."""
    b = MapBuilder(30.0, 16.0)
    b.room(1.0, 1.0, 7.0, 6.0)
    b.box(2.9, 1.0, 5.1, 4.2)  # the shelf block, against the back wall
    b.room(1.0, 6.0, 12.0, 8.0).door_h(4.0, 6.0, 0.9)
    b.room(14.0, 1.0, 24.0, 15.0)  # the loop's outer walls
    b.box(16.0, 3.0, 22.0, 13.0)  # the core
    b.room(24.0, 1.0, 28.0, 5.0).door_v(24.0, 2.0, 0.9)
    b.room(24.0, 5.0, 28.0, 9.0).door_v(24.0, 7.0, 0.9)
    b.room(24.0, 9.0, 28.0, 13.0).door_v(24.0, 11.0, 0.9)
    b.room(12.0, 9.0, 14.0, 13.0).door_v(14.0, 11.0, 0.9)
    b.door_v(12.0, 7.0, 0.9).door_v(14.0, 7.0, 0.9)  # the corridor into the loop
    return b.build("store round a shelf block")


def test_a_room_round_a_shelf_block_is_a_room_a_loop_round_a_core_a_hallway() -> None:
    """Walking round the block, the store's floor is 1.9 m wide and 12 m long: by its area for
    its width a dead-end corridor. But it reaches no farther than a room (its far corners under
    8 m apart, four times its width) and is entered through one door. The corridor round the
    core reaches as far as it is long."""
    grid = store_round_a_shelf_block()
    seg = segment_spaces(grid)
    store = space_at(seg, grid, 2.0, 2.5)
    assert space_at(seg, grid, 6.0, 2.5) is store
    assert space_at(seg, grid, 4.0, 5.0) is store
    assert store.kind == ElementKind.ROOM
    loop = space_at(seg, grid, 15.0, 8.0)
    assert space_at(seg, grid, 23.0, 8.0) is loop
    assert space_at(seg, grid, 19.0, 14.0) is loop
    assert loop.kind == ElementKind.HALLWAY
    corridor = space_at(seg, grid, 9.0, 7.0)
    assert len({store.id, loop.id, corridor.id}) == 3
    assert set(door_near(seg.doors, 4.0, 6.0).connects) == {store.id, corridor.id}


def test_many_openings_into_one_place_do_not_make_a_room_a_hallway() -> None:
    """A 31 m2 meeting room 3 m wide whose glass front onto an open floor was scanned as three
    pane gaps, with a door into its own store: four openings, but they lead on to one place
    only (the floor), so no one walks through it: a room. The same room with its openings into
    four places is walked through: a hallway."""
    from langnav.analysis.segmentation import _kind_and_size

    def kind(served: int | None) -> ElementKind:
        return _kind_and_size(31.0, 1.58, 2.33, 0.0, 4, lambda: 3.1, 0.05, DEFAULT_PARAMS,
                              whole_wide_share=lambda: 0.0, whole_typical=lambda: 2.33, ways_on=3,
                              extent_m=9.4, served=served)[0]

    assert kind(1) == ElementKind.ROOM
    assert kind(4) == ElementKind.HALLWAY
    assert kind(None) == ElementKind.HALLWAY  # counted by openings alone


def store_with_a_shelf_row() -> OccupancyGrid:
    """A 2.6 m x 10 m store room (an evidence store, an archive) entered through a 0.9 m door
    from a 1.8 m corridor, with two 0.6 m x 4 m shelf units in a row 0.5 m off its west wall;
    and, for contrast, a dead-end corridor 1.6 m wide and 12 m long off the same corridor."""
    b = MapBuilder(14.0, 17.0)
    b.room(1.0, 1.0, 13.0, 2.8)  # the corridor
    b.room(2.0, 2.8, 4.6, 12.8).door_h(3.3, 2.8, 0.9)  # the store
    b.box(2.5, 3.55, 3.1, 7.55).box(2.5, 8.15, 3.1, 12.15)  # the shelf row
    b.room(8.0, 2.8, 9.6, 14.8).door_h(8.8, 2.8, 0.9)  # the dead-end corridor
    return b.build("store with a shelf row")


def test_a_dead_end_store_narrowed_by_its_shelves_is_a_room() -> None:
    """Beside its shelves the store's aisle is 1.5 m wide, and its floor is long for that
    width: a dead-end corridor by its clearance. Wall to wall it is 2.6 m wide, long for that
    width (nearly four times) but not five times as long, and it is entered through one door:
    a room. The dead-end corridor, as
    narrow wall to wall, is longer than a room is."""
    grid = store_with_a_shelf_row()
    seg = segment_spaces(grid)
    store = space_at(seg, grid, 4.0, 7.0)
    assert store.kind == ElementKind.ROOM
    assert store.width_m == pytest.approx(2.6, abs=0.2)  # wall to wall
    corridor = space_at(seg, grid, 5.0, 1.9)
    dead_end = space_at(seg, grid, 8.8, 9.0)
    assert len({store.id, corridor.id, dead_end.id}) == 3
    assert dead_end.kind == ElementKind.HALLWAY
    assert set(door_near(seg.doors, 3.3, 2.8).connects) == {store.id, corridor.id}


@pytest.mark.parametrize(("peak_m", "whole_width_m", "kind"), [
    (0.8, 2.6, ElementKind.ROOM),  # shelves narrow it to 1.55 m; 2.6 m wall to wall, 9.4 m long
    (0.8, 1.6, ElementKind.HALLWAY),  # 1.6 m wall to wall and 9.4 m long: a dead-end corridor
])
def test_a_dead_end_is_judged_on_its_width_wall_to_wall(peak_m: float, whole_width_m: float,
                                                        kind: ElementKind) -> None:
    from langnav.analysis.segmentation import _kind_and_size

    got = _kind_and_size(24.0, peak_m, 1.5, 0.0, 1, lambda: whole_width_m, 0.05, DEFAULT_PARAMS,
                         whole_wide_share=lambda: 0.0, whole_typical=lambda: whole_width_m,
                         ways_on=1, extent_m=9.4, served=1)[0]
    assert got == kind


def bedroom_with_an_en_suite_door_open(leaf: bool = True) -> OccupancyGrid:
    """A 3 m x 5.5 m bedroom with a 1.3 m x 2.2 m en-suite in its north-west corner, as a scan
    of a care home's room draws it: the en-suite's south wall is scanned only as a short stub
    beside its east wall, and its door stands open into the bedroom, the leaf (0.85 m, 0.1 m as
    scanned) hinged 0.3 m from the outer wall; a room east of the bedroom leads on."""
    b = MapBuilder(10.0, 9.0)
    b.room(1.0, 1.0, 4.0, 6.5)  # the bedroom
    b.room(4.0, 1.0, 8.0, 6.5).door_v(4.0, 2.0, 0.9)
    b.wall(2.3, 4.3, 2.3, 6.5)  # the en-suite's east wall
    b.wall(2.15, 4.3, 2.3, 4.3)  # the stub of its south wall
    if leaf:
        b.wall(1.35, 3.45, 1.35, 4.3, thickness_m=0.1)  # the door, standing open
    return b.build("bedroom with an en-suite, its door open")


def test_an_en_suite_whose_door_stands_open_is_a_room_of_its_own() -> None:
    """The en-suite is as narrow as its doorway is wide, and its south wall was hardly scanned:
    by clearance alone it is a bay of the bedroom. Its open door, a thin leaf as long as a door
    is wide hinged at the doorway's end, marks the doorway: two rooms and a door between them.
    Without the leaf the 1.15 m gap is an open bay."""
    grid = bedroom_with_an_en_suite_door_open()
    seg = segment_spaces(grid)
    bedroom = space_at(seg, grid, 2.5, 2.5)
    en_suite = space_at(seg, grid, 1.65, 5.4)
    assert bedroom.id != en_suite.id
    assert len(seg.rooms) == 3
    assert en_suite.area_m2 == pytest.approx(1.3 * 2.2, abs=0.5)
    door = door_near(seg.doors, 1.75, 4.3)
    assert set(door.connects) == {bedroom.id, en_suite.id}
    assert door.width_m == pytest.approx(0.75, abs=0.15)  # from the leaf to the stub
    grid = bedroom_with_an_en_suite_door_open(leaf=False)
    seg = segment_spaces(grid)
    assert space_at(seg, grid, 2.5, 2.5) is space_at(seg, grid, 1.65, 5.4)
    assert len(seg.rooms) == 2


def test_a_small_hall_many_doors_open_onto_is_judged_on_its_width_within_its_walls() -> None:
    """A 6.7 m2 hall and the 0.8 m corridor leading off it, with four doorways into four
    places: within its walls its typical width is 0.8 m, but the floor's clearance reaches out
    through the doorways lining it and reads 1.6 m. Judged on its own width it is walked
    through: a hallway. Were it 1.6 m wide within its walls too, it would be a room (a small
    lobby no longer than wide)."""
    from langnav.analysis.segmentation import _kind_and_size

    def kind(own_typical_m: float) -> ElementKind:
        return _kind_and_size(6.7, 0.94, 1.61, 0.0, 4, lambda: 1.83, 0.05, DEFAULT_PARAMS,
                              whole_wide_share=lambda: 0.0, whole_typical=lambda: own_typical_m,
                              ways_on=4, extent_m=5.4, served=4)[0]

    assert kind(0.8) == ElementKind.HALLWAY
    assert kind(1.61) == ElementKind.ROOM


@pytest.mark.parametrize("degrees", [7.0, 24.0, 45.0, 66.0])
def test_an_en_suite_whose_door_stands_open_is_apart_at_any_angle(degrees: float) -> None:
    """The same rooms turned on the grid (stair-stepped walls, a leaf scanned two or three
    cells thick): the open leaf still parts the en-suite, and without it the bay stays open."""
    from test_passages import rotated

    def areas(grid: OccupancyGrid) -> list[float]:
        return sorted(round(r.area_m2, 1) for r in segment_spaces(grid).rooms)

    with_leaf = areas(rotated(bedroom_with_an_en_suite_door_open(), degrees))
    assert len(with_leaf) == 3
    assert with_leaf[0] == pytest.approx(2.6, abs=0.3)  # the en-suite
    assert with_leaf[1] == pytest.approx(12.6, abs=0.3)  # the bedroom
    assert len(areas(rotated(bedroom_with_an_en_suite_door_open(leaf=False), degrees))) == 2
