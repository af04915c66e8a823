"""Unexplored areas are the places a person would send the robot to look at: unscanned parts of
the building it can reach, not the unknown insides of furniture, shelves or walls."""

from __future__ import annotations

import pytest

from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.pipeline import analyze
from langnav.analysis.unexplored import find_unexplored
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import FREE, OCCUPIED, OccupancyGrid

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
