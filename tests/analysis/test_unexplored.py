"""Unexplored areas are the places a person would send the robot to look at: unscanned parts of
the building it can reach, not the unknown insides of furniture, shelves or walls."""

from __future__ import annotations

import numpy as np
import pytest

from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.pipeline import analyze
from langnav.analysis.unexplored import find_unexplored
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN, OccupancyGrid

P = DEFAULT_PARAMS


def furnished_room() -> OccupancyGrid:
    """A closed 8 x 6 m room with furniture the scan never saw into: a 2 x 1 m cabinet (its
    outline scanned, a 0.3 m gap in it, unknown inside), a 3 x 0.8 m shelf whose outline has
    three 0.2 m gaps, and a 0.6 x 0.6 m table top seen only as unknown."""
    b = MapBuilder(10.0, 8.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 8.0, 6.0)
    b.box(1.0, 1.0, 3.0, 2.0).unknown(1.05, 1.05, 2.95, 1.95).free(1.8, 1.0, 2.1, 1.05)
    b.box(4.0, 3.5, 7.0, 4.3).unknown(4.05, 3.55, 6.95, 4.25)
    for x in (4.5, 5.4, 6.3):
        b.free(x, 3.5, x + 0.2, 3.55)
    b.unknown(1.5, 4.0, 2.1, 4.6)
    return b.build(source="furnished_room")


def test_unknown_inside_furniture_is_no_unexplored_area() -> None:
    assert find_unexplored(furnished_room(), P).areas == ()
    assert analyze(furnished_room()).unexplored == ()


def unscanned_corner() -> OccupancyGrid:
    """A closed 6 x 5 m room whose north-east 2 x 1.5 m corner was never scanned."""
    b = MapBuilder(8.0, 7.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 6.0, 5.0)
    b.unknown(4.0, 3.5, 6.0, 5.0)
    return b.build(source="unscanned_corner")


def test_unscanned_corner_of_a_room_is_an_unexplored_area() -> None:
    (u,) = find_unexplored(unscanned_corner(), P).areas
    assert u.interior
    assert u.area_m2 == pytest.approx(3.0, abs=0.01)
    assert u.centroid == pytest.approx((5.0, 4.25), abs=0.03)
    # Its frontier: the free cells along its west and south edges, 1.5 + 2 m.
    assert len(u.frontier) * 0.05 == pytest.approx(3.5, abs=0.1)


def closet_behind(opening: str) -> OccupancyGrid:
    """A 6 x 4 m room; north of it, behind its wall, an unscanned 6 x 2 m closet. The scan saw
    into it only through ``opening``: "holes" (four 5 cm laser holes, each with a ray of free
    cells 1.5 m long beyond) or "door" (a 1 m doorway)."""
    b = MapBuilder(8.0, 8.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 6.0, 4.0)
    b.rect(-0.15, 4.0, 6.15, 6.15, OCCUPIED).unknown(0.0, 4.15, 6.0, 6.0)
    if opening == "holes":
        for x in (1.0, 2.0, 3.0, 4.0):
            b.rect(x, 4.0, x + 0.05, 5.65, FREE)
    else:
        b.door_h(3.0, 4.075, 1.0)
    return b.build(source=f"closet_behind_{opening}")


def test_unknown_seen_only_through_laser_holes_is_out_of_reach() -> None:
    assert find_unexplored(closet_behind("holes"), P).areas == ()


def test_unknown_behind_a_doorway_is_an_unexplored_area() -> None:
    (u,) = find_unexplored(closet_behind("door"), P).areas
    assert u.interior
    # The closet, less the doorway cut 0.125 m into it (a door is 0.4 m deep, its wall 0.15 m).
    assert u.area_m2 == pytest.approx(6.0 * 1.85 - 1.0 * 0.125, abs=0.05)


def test_outside_world_reached_only_through_a_laser_hole_is_not_an_area() -> None:
    # A closed room with one 5 cm hole through its east wall onto the unknown outside.
    b = MapBuilder(6.0, 5.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 4.0, 3.0)
    b.free(4.0, 1.5, 4.15, 1.55)
    assert find_unexplored(b.build(source="hole"), P).areas == ()
    # With a door there instead, the outside is one (exterior) area.
    b.door_v(4.075, 1.5, 0.9)
    (u,) = find_unexplored(b.build(source="door"), P).areas
    assert not u.interior


def test_long_thin_unknown_inside_a_rack_is_no_unexplored_area() -> None:
    # A 9 x 7 m hall with a 5 x 0.5 m rack the laser never saw into (2.5 m2 of unknown, open to
    # the hall all along): no room for the robot to drive in and turn.
    b = MapBuilder(11.0, 9.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 9.0, 7.0)
    b.unknown(2.0, 3.0, 7.0, 3.5)
    assert find_unexplored(b.build(source="rack"), P).areas == ()
    # The same hall with a 5 x 1 m unscanned bay along its north wall instead: one area.
    b.free(2.0, 3.0, 7.0, 3.5).unknown(2.0, 6.0, 7.0, 7.0)
    (u,) = find_unexplored(b.build(source="bay"), P).areas
    assert u.area_m2 == pytest.approx(5.0, abs=0.05)


def test_room_seen_through_a_fan_of_laser_rays_is_an_unexplored_area() -> None:
    # A 6 x 4 m room; north of it, through a 1 m doorway, an unscanned 6 x 2 m closet crossed by
    # free laser rays (two cells wide, 0.3 m apart): every unknown stripe between two rays is
    # thin, but the robot fits in none of the rays, and the closet is a place to look at.
    grid = closet_behind("door")
    cells = grid.cells.copy()
    for x in np.arange(0.2, 5.8, 0.3):
        r0, c = (int(v) for v in grid.world_to_index(float(x), 4.6))
        r1, _ = (int(v) for v in grid.world_to_index(float(x), 5.9))
        cells[r0:r1, c:c + 2] = FREE
    fan = OccupancyGrid(cells, grid.resolution_m, grid.origin_x_m, grid.origin_y_m, 0.0, "fan")
    areas = find_unexplored(fan, P).areas
    assert len(areas) >= 1 and all(a.interior for a in areas)
    assert sum(a.area_m2 for a in areas) > 5.0


def test_unknown_thing_the_robot_saw_all_round_is_no_unexplored_area() -> None:
    # A 20 x 14 m hall: a round glass table 0.9 m across seen only as unknown, a 1.2 x 1.0 m
    # cabinet (its outline scanned, its inside unknown), and a 3 x 2 m group of desks (unknown,
    # a few legs scanned at its edge), all with free floor all round: the scans went all round
    # them, they are things.
    b = MapBuilder(22.0, 16.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 20.0, 14.0)
    b.disc(2.5, 2.5, 0.45, UNKNOWN)
    b.box(6.0, 2.0, 7.2, 3.0).unknown(6.05, 2.05, 7.15, 2.95)
    b.unknown(12.0, 2.0, 15.0, 4.0)
    for x in (12.0, 13.45, 14.9):
        b.rect(x, 1.95, x + 0.1, 2.05, OCCUPIED)
    assert find_unexplored(b.build(source="things"), P).areas == ()
    # The middle of the hall unscanned, 8 m across: wider than a short-ranged lidar sees over
    # from the floor around it, worth a look.
    b.unknown(6.0, 5.0, 14.0, 13.0)
    (u,) = find_unexplored(b.build(source="patch"), P).areas
    assert u.area_m2 == pytest.approx(64.0, abs=0.1)
    assert u.centroid == pytest.approx((10.0, 9.0), abs=0.03)


def hall_with_pocket(legs: bool) -> OccupancyGrid:
    """A 10 x 8 m hall with a 1.6 x 1.4 m unknown pocket in its middle, free floor all round it;
    with ``legs``, the scan hit the four corners of whatever stands there."""
    b = MapBuilder(12.0, 10.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 10.0, 8.0)
    b.unknown(4.0, 3.0, 5.6, 4.4)
    if legs:
        for x, y in ((3.95, 2.95), (5.55, 2.95), (3.95, 4.35), (5.55, 4.35)):
            b.rect(x, y, x + 0.1, y + 0.1, OCCUPIED)
    return b.build(source=f"pocket_{legs}")


def test_a_pocket_larger_than_furniture_with_no_scan_hit_is_unexplored() -> None:
    # Nothing was seen standing there (not one hit on its edge), and it is larger than one piece
    # of furniture (seg_island_max_area_m2): unscanned floor, worth a look.
    (u,) = find_unexplored(hall_with_pocket(legs=False), P).areas
    assert u.interior
    assert u.area_m2 == pytest.approx(2.24, abs=0.05)
    assert u.centroid == pytest.approx((4.8, 3.7), abs=0.03)
    assert len(u.frontier) > 0


def test_the_same_pocket_with_its_legs_scanned_is_a_thing() -> None:
    # The scan hit its corners: a table or a desk group stands there, seen all round.
    assert find_unexplored(hall_with_pocket(legs=True), P).areas == ()


def glass_front(door: bool) -> OccupancyGrid:
    """A closed 6 x 4 m room whose east wall is a glass front: the laser went through it (5 cm
    holes every 0.5 m) and mapped a 3 x 3 m patch of the courtyard beyond, the unknown outside
    round it. With ``door``, a 1 m doorway in the glass front leads out."""
    b = MapBuilder(12.0, 6.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 6.0, 4.0)
    b.free(6.15, 0.5, 9.15, 3.5)
    for y in np.arange(0.25, 4.0, 0.5):
        b.free(5.85, float(y), 6.15, float(y) + 0.05)
    if door:
        b.door_v(6.0, 2.0, 1.0)
    return b.build(source=f"glass_front_{door}")


def test_courtyard_seen_through_glass_is_no_unexplored_area() -> None:
    # The courtyard's floor is wide enough for the robot, but it cannot drive there from the
    # room: nothing to send it to look at.
    assert find_unexplored(glass_front(door=False), P).areas == ()
    assert analyze(glass_front(door=False)).unexplored == ()


def test_courtyard_reached_through_a_door_is_the_outside_area() -> None:
    (u,) = find_unexplored(glass_front(door=True), P).areas
    assert not u.interior
    # Its frontier is the courtyard's edge, where the robot can drive up to the unknown (the
    # patch's north, east and south edges: 3 + 3 + 3 m, bar the corners); none of it is in the room.
    assert np.all(u.frontier[:, 0] > 6.1)
    assert len(u.frontier) * 0.05 == pytest.approx(9.0, abs=0.4)


def doubled_wall() -> OccupancyGrid:
    """A 3 x 4 m room and, east of it, the 5 x 4 m room the robot mapped from; a loop-closure
    error drew the wall between them twice, 0.45 m apart, with unknown between the copies. The
    east room's north-west corner, 1.2 m square, was in a scan shadow, and its wall copy stops
    there: the cavity and the shadow are one unknown region."""
    b = MapBuilder(12.5, 6.0, origin=(-1.0, -1.0))
    b.room(2.0, 0.0, 5.0, 4.0)
    b.room(5.6, 0.0, 10.6, 4.0)
    b.unknown(5.075, 0.0, 5.525, 4.0)
    b.rect(5.0, -0.075, 5.6, 0.075, OCCUPIED).rect(5.0, 3.925, 5.6, 4.075, OCCUPIED)
    b.unknown(5.525, 2.8, 6.8, 3.925)
    return b.build(source="doubled_wall")


def test_cavity_of_a_doubled_wall_is_cut_off_the_shadow_it_joins() -> None:
    (u,) = find_unexplored(doubled_wall(), P).areas
    assert u.interior
    # The shadow (1.275 x 1.125 m) with at most the strip of cavity beside it (0.45 m more),
    # not the 2.8 m of cavity below it (1.26 m2 more, centroid 1 m lower).
    assert 1.275 * 1.125 <= u.area_m2 <= 1.725 * 1.125 + 0.01
    assert u.centroid[1] > 3.2
    assert np.all(u.frontier[:, 0] > 5.6)


def test_unscanned_wing_behind_a_door_is_kept_whole() -> None:
    # A 6 x 4 m room; through a 1 m door in its east wall, a 1.2 m wide, 4 m long corridor (never
    # scanned) leading to a 3 x 3 m room: one area, all of it.
    b = MapBuilder(15.0, 6.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 6.0, 4.0)
    b.rect(6.0, 1.25, 10.3, 2.75, OCCUPIED).rect(10.15, 0.35, 13.3, 3.65, OCCUPIED)
    b.unknown(6.075, 1.4, 10.3, 2.6).unknown(10.3, 0.5, 13.15, 3.5)
    b.door_v(6.075, 2.0, 1.0)
    (u,) = find_unexplored(b.build(source="wing"), P).areas
    assert u.interior
    # Corridor (4.225 x 1.2 m) and room (2.85 x 3 m), less the doorway cut 0.2 m into the corridor.
    assert u.area_m2 == pytest.approx(4.225 * 1.2 + 2.85 * 3.0 - 1.0 * 0.2, abs=0.05)


def test_outside_frontier_is_its_openings_not_the_gaps_in_a_wall() -> None:
    # A room with a door out east and a glass north wall (one cell thin) with a 10 cm gap: the
    # outside area's frontier is at the door, none of it at the gap (x = 2 m, y = 3 m).
    b = MapBuilder(6.0, 5.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 4.0, 3.0)
    b.free(0.0, 2.925, 4.0, 3.0).unknown(-0.075, 3.01, 4.075, 3.2)
    b.rect(-0.075, 2.99, 4.075, 3.01, OCCUPIED).free(2.0, 2.99, 2.1, 3.01)
    b.door_v(4.075, 1.5, 0.9)
    (u,) = find_unexplored(b.build(source="door_and_gap"), P).areas
    assert not u.interior
    assert len(u.frontier) > 0
    assert np.all(u.frontier[:, 0] > 3.9)
