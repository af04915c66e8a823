"""Narrow passages on built maps whose answer is known: what leads somewhere between two solid
sides is a passage; dead-end slots, slivers outside walls and laser-ray stripes are not."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import ndimage as ndi

from langnav.analysis.elements import Door
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.passages import find_passages, typical_wall_thickness_m
from langnav.analysis.pipeline import analyze, labels_for_free_components
from langnav.analysis.precompute import GridLayers
from langnav.analysis.unexplored import find_unexplored
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import OCCUPIED, UNKNOWN, OccupancyGrid

P = DEFAULT_PARAMS
#: Shelf-row warehouse: rows of shelves 0.4 m deep and 4 m long, 0.8 m apart, x from 2 to 6.
AISLE_M = 0.8
SHELF_DEPTH_M = 0.4
SHELF_X = (2.0, 6.0)


def passages_of(grid: OccupancyGrid):
    """The passages of ``grid``, its free components as spaces, no doors; unknown noise specks
    do not block and unexplored areas are no sides (as in the pipeline)."""
    labels, n = labels_for_free_components(grid)
    layers = GridLayers(grid)
    unx = find_unexplored(grid, P, layers)
    return find_passages(grid, P, labels, {k: f"space_{k}" for k in range(1, n + 1)}, [],
                         layers.occupied | (layers.unknown & ~unx.specks), layers=layers,
                         unexplored=unx.area_labels > 0)


def warehouse(n_shelves: int = 4, unknown_racks: bool = False) -> OccupancyGrid:
    """A 9 x 7 m hall; ``n_shelves`` shelf rows run east-west from x = 2 to 6, the first at
    y = 1.5, each 0.4 m deep, 0.8 m apart: the aisles between them open at both ends into the
    hall's 2 m wide cross aisles (and the hall is 1.5 m wide or more beside the outer rows). ``unknown_racks``: the shelves are scanned only as their
    unknown insides (racks the laser does not see into), not as occupied cells."""
    b = MapBuilder(11.0, 9.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 9.0, 7.0)
    y = 1.5
    for _ in range(n_shelves):
        if unknown_racks:
            b.unknown(SHELF_X[0], y, SHELF_X[1], y + SHELF_DEPTH_M)
        else:
            b.box(SHELF_X[0], y, SHELF_X[1], y + SHELF_DEPTH_M)
        y += SHELF_DEPTH_M + AISLE_M
    return b.build(source="warehouse")


def aisle_centres(n_shelves: int) -> list[tuple[float, float]]:
    first = 1.5 + SHELF_DEPTH_M + AISLE_M / 2
    return [(4.0, first + k * (SHELF_DEPTH_M + AISLE_M)) for k in range(n_shelves - 1)]


@pytest.mark.parametrize("unknown_racks", [False, True])
def test_aisles_between_shelf_rows_are_passages(unknown_racks: bool) -> None:
    found = sorted(passages_of(warehouse(4, unknown_racks)), key=lambda p: p.center[1])
    assert len(found) == 3
    for p, (x, y) in zip(found, aisle_centres(4), strict=True):
        assert p.center == pytest.approx((x, y), abs=0.05)
        assert p.width_m == pytest.approx(AISLE_M, abs=0.051)
        # The aisle's length is the shelves' (4 m), give or take its flaring mouths.
        (x0, y0), (x1, y1) = sorted(p.ends)
        assert y0 == pytest.approx(y, abs=0.05) and y1 == pytest.approx(y, abs=0.05)
        assert x0 == pytest.approx(SHELF_X[0], abs=0.3) and x1 == pytest.approx(SHELF_X[1], abs=0.3)
        assert p.length_m == pytest.approx(x1 - x0, abs=0.06)


def rotated(grid: OccupancyGrid, degrees: float) -> OccupancyGrid:
    """The grid turned by ``degrees`` about its centre, cell by cell (nearest cell; the corners
    it uncovers are unknown): walls become stair-stepped lines, as in a real map at an angle."""
    cells = ndi.rotate(grid.cells.astype(np.int16) + 1, degrees, order=0, reshape=True, cval=0) - 1
    return OccupancyGrid(cells.astype(np.int8), grid.resolution_m, source=f"{grid.source}_rotated")


@pytest.mark.parametrize("degrees", [5.0, 10.0, 23.0, 45.0, 80.0])
def test_aisles_of_a_rotated_warehouse_are_passages(degrees: float) -> None:
    # The same three aisles, whatever the angle: stair-stepped walls leave no comb of false
    # crests that would cut an aisle's line short.
    found = passages_of(rotated(warehouse(4), degrees))
    assert len(found) == 3
    for p in found:
        assert p.width_m == pytest.approx(AISLE_M, abs=0.051)
        assert p.length_m == pytest.approx(SHELF_X[1] - SHELF_X[0], abs=0.15)


def test_an_aisle_on_coarse_cells_whose_side_steps_a_cell_is_found_whole() -> None:
    """0.1 m cells (a large floor's map): a 4 m aisle, 0.8 m wide, between two shelf rows whose
    scanned outlines are a cell off for their last metre (both a cell north). Its middle line
    steps a cell sideways there, where the width read from whole cells jumps by 0.2 m: that is
    no flaring mouth, and the aisle is one passage the length of the shelves."""
    b = MapBuilder(11.0, 9.0, resolution_m=0.1, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 9.0, 7.0)
    b.box(2.0, 1.4, 5.0, 2.0).box(5.0, 1.5, 6.0, 2.1)
    b.box(2.0, 2.8, 5.0, 3.4).box(5.0, 2.9, 6.0, 3.5)
    (p,) = passages_of(b.build(source="stepped_aisle_coarse"))
    assert p.center == pytest.approx((4.0, 2.42), abs=0.06)
    assert p.length_m == pytest.approx(4.0, abs=0.1)
    assert p.width_m == pytest.approx(0.8, abs=0.051)


def test_warehouse_end_to_end_aisles_are_passages_not_doors() -> None:
    a = analyze(warehouse(4))
    centres = sorted(p.center for p in a.narrow_passages)
    assert len(centres) == 3
    for got, want in zip(sorted(centres, key=lambda c: c[1]), aisle_centres(4), strict=True):
        assert got == pytest.approx(want, abs=0.05)
    # One hall: the gaps between shelves are no doors.
    assert a.doors == ()


def dead_end_slot() -> OccupancyGrid:
    """A 6 x 5 m room; two 0.4 m deep, 2 m long cabinets stand out from its north wall, 0.7 m
    apart: the slot between them is closed at the wall (it leads nowhere)."""
    b = MapBuilder(8.0, 7.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 6.0, 5.0)
    b.box(2.0, 3.0, 2.4, 5.0)
    b.box(3.1, 3.0, 3.5, 5.0)
    return b.build(source="dead_end_slot")


def test_dead_end_slot_is_no_passage() -> None:
    assert passages_of(dead_end_slot()) == ()


def test_the_same_slot_open_at_both_ends_is_a_passage() -> None:
    # Control: the cabinets 1.5 m off the wall, so the slot opens into the room at both ends.
    b = MapBuilder(8.0, 7.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 6.0, 5.0)
    b.box(2.0, 1.5, 2.4, 3.5)
    b.box(3.1, 1.5, 3.5, 3.5)
    (p,) = passages_of(b.build(source="open_slot"))
    assert p.center == pytest.approx((2.75, 2.5), abs=0.05)
    assert p.width_m == pytest.approx(0.7, abs=0.051)


@pytest.mark.parametrize("sliver_m", [0.25, 0.6])
def test_sliver_outside_a_wall_is_no_passage(sliver_m: float) -> None:
    """A 6 x 4 m room whose scan leaked through a window in the south wall: a free strip
    ``sliver_m`` wide runs along the outside of that wall, bounded by the unscanned world. Below
    the robot's width it is no way through; wider, one side is nothing known (the outside)."""
    b = MapBuilder(8.0, 7.0, origin=(-1.0, -2.0))
    b.room(0.0, 0.0, 6.0, 4.0)
    b.free(0.5, -0.15 - sliver_m, 5.5, -0.15)
    b.free(2.5, -0.15, 3.5, 0.0)  # the window the scan leaked through
    grid = b.build(source="sliver_outside")
    assert passages_of(grid) == ()


def test_strip_between_laser_ray_stripes_is_no_passage() -> None:
    """A 5 x 5 m room; east of it, beyond a doorway, a fan of free rays 0.6 m wide separated by
    unknown stripes 0.1 m thick (the laser's view into an unscanned space)."""
    b = MapBuilder(12.0, 7.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 5.0, 5.0)
    b.door_v(5.075, 2.5, 3.0)
    b.free(5.2, 0.5, 9.0, 4.5)
    for y in (1.2, 1.9, 2.6, 3.3):
        b.unknown(5.6, y, 9.0, y + 0.1)
    assert passages_of(b.build(source="ray_stripes")) == ()


def test_gap_narrower_than_robot_plus_margin_is_no_passage() -> None:
    # Shelves 0.4 m apart: wider than the 0.34 m robot, but with no room to pass.
    b = MapBuilder(8.0, 7.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 6.0, 5.0)
    b.box(2.0, 1.5, 2.4, 3.5)
    b.box(2.8, 1.5, 3.2, 3.5)
    assert passages_of(b.build(source="tight_slot")) == ()


def test_unknown_inside_furniture_bounds_a_passage_but_the_outside_does_not() -> None:
    grid = warehouse(2, unknown_racks=True)
    cells = grid.cells.copy()
    (p,) = passages_of(grid)
    assert p.width_m == pytest.approx(AISLE_M, abs=0.051)
    # Open the north rack's unknown to the grid edge (it is then the unscanned world, not a rack).
    r0, c0 = (int(v) for v in grid.world_to_index(4.0, 3.1))
    cells[r0:, c0] = UNKNOWN
    opened = OccupancyGrid(cells, grid.resolution_m, grid.origin_x_m, grid.origin_y_m, 0.0, "opened")
    assert passages_of(opened) == ()


def passage_with_doorway() -> OccupancyGrid:
    """Two 3 x 4 m halls joined by a wall-bounded passage 0.9 m wide and 2.5 m long (x 3 to 5.5,
    y 1.0 to 1.9); its south wall has a 1 m doorway (x 3.75 to 4.75) into a closet."""
    b = MapBuilder(11.0, 8.0, origin=(-1.0, -2.5))
    b.rect(-0.15, -1.65, 8.65, 4.15, OCCUPIED)
    b.free(0.0, 0.0, 3.0, 4.0).free(5.5, 0.0, 8.5, 4.0)
    b.free(2.9, 1.0, 5.6, 1.9)
    b.free(3.5, -1.5, 5.0, 0.85).free(3.75, 0.8, 4.75, 1.05)
    return b.build(source="passage_with_doorway")


def test_passage_with_a_doorway_in_its_side_wall() -> None:
    (p,) = passages_of(passage_with_doorway())
    assert p.center == pytest.approx((4.25, 1.45), abs=0.06)
    assert p.width_m == pytest.approx(0.9, abs=0.051)
    assert p.length_m == pytest.approx(2.5, abs=0.15)


def test_strip_beside_a_row_of_separate_boxes_is_no_passage() -> None:
    # A 0.8 m strip between a room's north wall and a row of 0.5 m boxes 0.5 m apart: the
    # strip's south side is a row of gaps, no wall with a doorway.
    b = MapBuilder(10.0, 7.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 8.0, 5.0)
    for x in np.arange(1.0, 7.0, 1.0):
        b.box(float(x), 3.7, float(x) + 0.5, 4.2)
    assert passages_of(b.build(source="box_row")) == ()


def with_lidar_noise(grid: OccupancyGrid, seed: int = 0) -> OccupancyGrid:
    """Scan noise: occupied specks on 3 % of the free cells within two cells of a wall, unknown
    specks on 0.2 % of the free cells, and 5 % of the wall cells dropped out (free)."""
    rng = np.random.default_rng(seed)
    c = grid.cells.copy()
    free, occ = c == 0, c == 100
    near_wall = ndi.binary_dilation(occ, iterations=2) & free
    c[near_wall & (rng.random(c.shape) < 0.03)] = 100
    c[free & (rng.random(c.shape) < 0.002)] = UNKNOWN
    c[occ & (rng.random(c.shape) < 0.05)] = 0
    return OccupancyGrid(c, grid.resolution_m, source=f"{grid.source}_noisy")


@pytest.mark.parametrize("degrees", [0.0, 23.0, 37.0])
def test_rotated_noisy_warehouse_keeps_its_aisles_and_nothing_else(degrees: float) -> None:
    found = passages_of(with_lidar_noise(rotated(warehouse(4), degrees)))
    assert len(found) == 3
    for p in found:
        assert p.width_m == pytest.approx(AISLE_M, abs=0.1)


def two_rooms_joined_by_a_corridor() -> OccupancyGrid:
    """Two rooms, x 0 to 3.15 and 4.85 to 8 (y 0 to 3), joined by a corridor 0.8 m wide and
    1.7 m long (x 3.15 to 4.85, y 1.1 to 1.9)."""
    b = MapBuilder(10.0, 5.0, origin=(-1.0, -1.0))
    b.rect(-0.15, -0.15, 8.15, 3.15, OCCUPIED)
    b.free(0.0, 0.0, 3.15, 3.0).free(4.85, 0.0, 8.0, 3.0).free(3.1, 1.1, 4.9, 1.9)
    return b.build(source="corridor_between_rooms")


def door_across(x: float) -> Door:
    return Door(id="door_1", center=(x, 1.5), width_m=0.8, jambs=((x, 1.1), (x, 1.9)), normal=(1.0, 0.0),
                connects=("space_1", "space_2"))


@pytest.mark.parametrize(("door_x", "is_passage"), [(None, True), (4.8, True), (3.2, True), (4.0, False)])
def test_a_door_at_a_mouth_leaves_the_passage_one_in_its_middle_is_it(door_x: float | None,
                                                                      is_passage: bool) -> None:
    grid = two_rooms_joined_by_a_corridor()
    labels, n = labels_for_free_components(grid)
    layers = GridLayers(grid)
    doors = [] if door_x is None else [door_across(door_x)]
    found = find_passages(grid, P, labels, {k: f"space_{k}" for k in range(1, n + 1)}, doors,
                          layers.occupied | layers.unknown, layers=layers)
    assert len(found) == int(is_passage)
    if is_passage:
        assert found[0].center == pytest.approx((4.0, 1.5), abs=0.06)
        assert found[0].width_m == pytest.approx(0.8, abs=0.051)


def test_scan_specks_in_an_aisle_neither_cut_nor_narrow_it() -> None:
    # Lidar dots (single occupied cells) every 0.7 m along each aisle, off its middle line: the
    # aisles stay whole, 0.8 m wide and as long as the shelves.
    grid = warehouse(3)
    cells = grid.cells.copy()
    for _x, y in aisle_centres(3):
        for k, xs in enumerate(np.arange(SHELF_X[0] + 0.3, SHELF_X[1] - 0.2, 0.7)):
            r, c = (int(v) for v in grid.world_to_index(float(xs), y + (0.15 if k % 2 else -0.2)))
            cells[r, c] = OCCUPIED
    found = passages_of(OccupancyGrid(cells, grid.resolution_m, grid.origin_x_m, grid.origin_y_m, 0.0, "dotted"))
    assert len(found) == 2
    for p, (x, y) in zip(sorted(found, key=lambda p: p.center[1]), aisle_centres(3), strict=True):
        assert p.center == pytest.approx((x, y), abs=0.06)
        assert p.width_m == pytest.approx(AISLE_M, abs=0.051)
        assert p.length_m == pytest.approx(SHELF_X[1] - SHELF_X[0], abs=0.15)


def test_a_pinch_at_one_end_does_not_shorten_the_passage() -> None:
    # Two rooms joined by a corridor 0.8 m wide and 2.5 m long (x 3 to 5.5, y 1.1 to 1.9), a
    # door leaf or a cabinet narrowing its west end to 0.55 m over 0.3 m: the passage is still
    # the whole tight stretch, its width the typical one (not the pinch's).
    b = MapBuilder(11.0, 5.0, origin=(-1.0, -1.0))
    b.rect(-0.15, -0.15, 8.65, 3.15, OCCUPIED)
    b.free(0.0, 0.0, 3.0, 3.0).free(5.5, 0.0, 8.5, 3.0).free(2.95, 1.1, 5.55, 1.9)
    b.rect(3.0, 1.65, 3.3, 1.9, OCCUPIED)
    (p,) = passages_of(b.build(source="pinched_corridor"))
    assert p.center == pytest.approx((4.25, 1.5), abs=0.1)
    assert p.length_m == pytest.approx(2.5, abs=0.15)
    assert p.width_m == pytest.approx(0.8, abs=0.051)


def test_strip_between_a_shelf_and_an_unexplored_area_is_no_passage() -> None:
    # A 9 x 7 m hall; a 4 x 0.4 m shelf and, 0.8 m north of it, a 4 x 4.3 m part of the hall
    # the scan never reached, up to its north wall (an unexplored area, open to the hall on
    # three sides). Nothing is known to stand along the strip's north side: no passage.
    # Control: the same strip with a second shelf in place of the unscanned part is an aisle.
    def hall(unscanned: bool) -> OccupancyGrid:
        b = MapBuilder(11.0, 9.0, origin=(-1.0, -1.0))
        b.room(0.0, 0.0, 9.0, 7.0)
        b.box(2.0, 1.5, 6.0, 1.9)
        if unscanned:
            b.unknown(2.0, 2.7, 6.0, 7.0)
        else:
            b.box(2.0, 2.7, 6.0, 3.1)
        return b.build(source=f"hall_unscanned_{unscanned}")

    assert passages_of(hall(unscanned=True)) == ()
    (p,) = passages_of(hall(unscanned=False))
    assert p.center == pytest.approx((4.0, 2.3), abs=0.05)


def sofa_squeeze(shelf_to_x: float | None = 8.0, gap_m: float = 0.6) -> OccupancyGrid:
    """An 8 x 6 m room split by furniture: a 2.4 x 0.7 m sofa (outline scanned, inside unknown)
    ``gap_m`` from the west wall (y 3.0 to 3.7), and a 0.3 m deep shelf from the sofa's east end
    to x = ``shelf_to_x`` (8: the east wall; None: no shelf, the sofa stands free). The squeeze
    between the sofa and the west wall is the way into the north part of the room."""
    b = MapBuilder(10.0, 8.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 8.0, 6.0)
    b.box(gap_m, 3.0, gap_m + 2.4, 3.7).unknown(gap_m + 0.05, 3.05, gap_m + 2.35, 3.65)
    if shelf_to_x is not None:
        b.box(gap_m + 2.4, 3.2, shelf_to_x, 3.5)
    return b.build(source=f"sofa_squeeze_{shelf_to_x}_{gap_m}")


def test_squeeze_between_furniture_and_a_wall_that_is_the_only_way_is_a_passage() -> None:
    # Shorter than twice its width (0.7 x 0.6 m), but the only way past the sofa and the shelf.
    (p,) = passages_of(sofa_squeeze())
    assert p.center == pytest.approx((0.3, 3.35), abs=0.06)
    assert p.width_m == pytest.approx(0.6, abs=0.051)
    assert p.length_m == pytest.approx(0.7, abs=0.15)


def test_a_tight_squeeze_with_a_way_round_is_still_a_passage() -> None:
    # The shelf stops short of the east wall: one could walk round the other end, but a 0.6 m
    # squeeze between a sofa and a wall is what a person calls a narrow passage (tighter than
    # any accessible route), as the squeeze between a buffet counter and a wall.
    (p,) = passages_of(sofa_squeeze(shelf_to_x=6.5))
    assert p.center == pytest.approx((0.3, 3.35), abs=0.06)
    assert p.width_m == pytest.approx(0.6, abs=0.051)


def test_a_roomy_gap_beside_a_sofa_with_a_way_round_is_no_passage() -> None:
    # The same sofa 0.95 m from the wall, the shelf short of the east wall: room for two to pass
    # sideways, and a way round the other end; the gap is the floor beside the sofa.
    assert passages_of(sofa_squeeze(shelf_to_x=6.5, gap_m=0.95)) == ()
    # ... but the only way past the sofa and the shelf, it is a passage.
    (p,) = passages_of(sofa_squeeze(gap_m=0.95))
    assert p.width_m == pytest.approx(0.95, abs=0.051)


def test_a_squeeze_in_a_ring_corridor_is_the_way_past() -> None:
    # A 2 m ring corridor round a 12 x 5 m core (x 2..14, y 2..7); a bed and a trolley narrow its
    # south side to 0.9 m (x 7..8). The robot could go the other way round the ring (some 30 m),
    # but that is a detour, not a way round the things: the squeeze is a passage.
    b = MapBuilder(18.0, 11.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 16.0, 9.0)
    b.box(2.0, 2.0, 14.0, 7.0).unknown(2.1, 2.1, 13.9, 6.9)
    b.box(6.5, 0.0, 8.5, 0.6).unknown(6.55, 0.05, 8.45, 0.55)
    b.box(7.0, 1.5, 8.0, 2.0)
    (p,) = passages_of(b.build(source="ring_squeeze"))
    assert p.center == pytest.approx((7.5, 1.05), abs=0.06)
    assert p.width_m == pytest.approx(0.9, abs=0.051)


@pytest.mark.parametrize("degrees", [8.0, 23.0])
def test_rotated_noisy_squeeze_is_still_the_only_way(degrees: float) -> None:
    found = passages_of(with_lidar_noise(rotated(sofa_squeeze(), degrees)))
    assert len(found) == 1
    assert found[0].width_m == pytest.approx(0.6, abs=0.1)


def test_door_open_along_the_way_beside_a_wall_is_no_squeeze() -> None:
    # A partition wall across an 8 x 6 m room leaves a 0.7 m doorway at the west wall, its
    # door leaf (0.05 m thick) open northwards along the way: the only way north, and the west
    # wall runs on past it, but what stands beside the way is a jamb and a door leaf, no deeper
    # than a wall: a door, not a squeeze past furniture.
    b = MapBuilder(10.0, 8.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 8.0, 6.0)
    b.rect(0.7, 3.0, 8.0, 3.15, OCCUPIED)
    b.rect(0.7, 3.15, 0.75, 3.85, OCCUPIED)
    assert passages_of(b.build(source="door_leaf")) == ()


def beside_east_wall(x0: float, y0: float, x1: float, y1: float) -> OccupancyGrid:
    """An 8 x 6 m room with one box (x0..x1, y0..y1) standing free near its east wall (x = 8)."""
    b = MapBuilder(10.0, 8.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 8.0, 6.0)
    b.box(x0, y0, x1, y1)
    return b.build(source="beside_east_wall")


def test_gap_between_a_pallet_and_the_wall_is_walked_round() -> None:
    # A 1.0 x 1.2 m pallet 0.5 m from the wall: the 0.5 x 1.2 m gap is longer than twice its
    # width, but one walks round the pallet.
    assert passages_of(beside_east_wall(6.5, 2.0, 7.5, 3.2)) == ()


def test_aisle_between_a_long_shelf_and_the_wall_is_a_passage() -> None:
    # A 0.4 x 4 m shelf 0.7 m from the wall: as elongated as a corridor, an aisle along the shelf
    # (though one could walk round the shelf too).
    (p,) = passages_of(beside_east_wall(6.9, 1.0, 7.3, 5.0))
    assert p.center == pytest.approx((7.65, 3.0), abs=0.06)
    assert p.width_m == pytest.approx(0.7, abs=0.051)
    assert p.length_m == pytest.approx(4.0, abs=0.15)


def test_a_door_in_a_side_wall_leads_off_the_passage() -> None:
    # The passage with a doorway in its south wall, that doorway read as a door (its normal
    # across the passage's axis): the passage stays; the same door turned across the way is the
    # passage's own gap.
    grid = passage_with_doorway()
    labels, n = labels_for_free_components(grid)
    layers = GridLayers(grid)

    def door(normal: tuple[float, float]) -> Door:
        return Door(id="door_1", center=(4.25, 0.925), width_m=1.0, jambs=((3.75, 0.925), (4.75, 0.925)),
                    normal=normal, connects=("space_1", "space_2"))

    def found(d: Door) -> tuple:
        return find_passages(grid, P, labels, {k: f"space_{k}" for k in range(1, n + 1)}, [d],
                             layers.occupied | layers.unknown, layers=layers)

    (p,) = found(door((0.0, 1.0)))
    assert p.center == pytest.approx((4.25, 1.45), abs=0.06)
    assert found(door((1.0, 0.0))) == ()


def corridor_squeeze(bed_to_wall: bool = True) -> OccupancyGrid:
    """A 12 x 2.4 m corridor (x 0..12, y 0..2.4) between two 3 x 3 m rooms at its ends, joined
    to them over its whole width; a 2.0 x 0.75 m parked bed against its south wall (x 5.0..7.0,
    y 0..0.75; outline scanned, inside unknown) and a 1.0 x 0.75 m trolley against its north wall
    (x 5.5..6.5, y 1.65..2.4) leave a 0.9 m squeeze between them (x 5.5..6.5). ``bed_to_wall``
    False: the bed stands 0.9 m off the south wall (y 0.9..1.65), so one walks round it."""
    b = MapBuilder(14.0, 4.4, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 12.0, 2.4)
    y0 = 0.0 if bed_to_wall else 0.9
    b.box(5.0, y0, 7.0, y0 + 0.75).unknown(5.05, y0 + 0.05, 6.95, y0 + 0.7)
    if bed_to_wall:
        b.box(5.5, 1.65, 6.5, 2.4).unknown(5.55, 1.7, 6.45, 2.35)
    return b.build(source=f"corridor_squeeze_{bed_to_wall}")


def test_squeeze_between_two_things_in_a_corridor_is_a_passage() -> None:
    # Shorter than twice its width (1.0 x 0.9 m), between two things deeper than any wall (no
    # doorway), and the only way along the corridor: a person points at it.
    (p,) = passages_of(corridor_squeeze())
    assert p.center == pytest.approx((6.0, 1.2), abs=0.06)
    assert p.width_m == pytest.approx(0.9, abs=0.051)
    assert p.length_m == pytest.approx(1.0, abs=0.15)


def test_a_bed_standing_off_the_wall_leaves_its_tight_side_a_passage() -> None:
    # The bed stands off the south wall (0.9 m, y 0.9..1.65), 0.75 m from the north wall: there is
    # a way round it on either side. The 0.9 m gap beside it is roomy floor with a way round; the
    # 0.75 m strip along the north wall is tight for a person (a squeeze between a bed and a
    # wall, as a person would point at it) and stays a passage, for all the way round.
    (p,) = passages_of(corridor_squeeze(bed_to_wall=False))
    assert p.center == pytest.approx((6.0, 2.02), abs=0.06)
    assert p.width_m == pytest.approx(0.75, abs=0.051)


def furniture_row(depth_m: float) -> OccupancyGrid:
    """A 7 x 5 m room split by a row of furniture ``depth_m`` deep across it (y 2.0..2.0+depth),
    from the west wall to x 3.0 and from x 3.7 to the east wall: a 0.7 m gap between a wardrobe
    and a desk (``depth_m`` 0.7), or a doorway in a partition wall (0.15)."""
    b = MapBuilder(9.0, 7.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 7.0, 5.0)
    b.rect(0.0, 2.0, 3.0, 2.0 + depth_m, OCCUPIED)
    b.rect(3.7, 2.0, 7.0, 2.0 + depth_m, OCCUPIED)
    return b.build(source=f"furniture_row_{depth_m}")


def test_gap_in_a_row_of_furniture_across_a_room_is_a_passage() -> None:
    # A wardrobe and a desk, 0.7 m deep, with a 0.7 m gap: the way between the room's two parts,
    # between things deeper than any wall.
    (p,) = passages_of(furniture_row(0.7))
    assert p.center == pytest.approx((3.35, 2.35), abs=0.06)
    assert p.width_m == pytest.approx(0.7, abs=0.051)


def test_doorway_in_a_partition_is_no_passage() -> None:
    # The same gap in a 0.15 m partition wall is a doorway (a door's business), not a passage.
    assert passages_of(furniture_row(0.15)) == ()


def test_cart_narrowing_a_corridor_is_a_passage() -> None:
    # A 1.8 m corridor narrowed to 0.85 m by a 1.5 m long housekeeping cart against its north
    # wall: wider than a standard door's clear width, yet a squeeze a person points at (the way
    # it narrows is twice as wide).
    b = MapBuilder(14.0, 3.8, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 12.0, 1.8)
    b.box(5.0, 0.85, 6.5, 1.8).unknown(5.05, 0.9, 6.45, 1.75)
    (p,) = passages_of(b.build(source="corridor_cart"))
    assert p.center == pytest.approx((5.75, 0.425), abs=0.06)
    assert p.width_m == pytest.approx(0.85, abs=0.051)


def passages_with_door(grid: OccupancyGrid, door: Door) -> tuple:
    """The passages of ``grid`` (free components as spaces) with one door found in it."""
    labels, n = labels_for_free_components(grid)
    layers = GridLayers(grid)
    return find_passages(grid, P, labels, {k: f"space_{k}" for k in range(1, n + 1)}, [door],
                         layers.occupied | layers.unknown, layers=layers)


def test_a_door_found_in_a_gap_between_furniture_leaves_the_passage() -> None:
    # The segmentation may read the wardrobe-desk gap as a door (at its north mouth): between two
    # things with parallel faces, deeper than any wall, it is no door; the passage stays.
    door = Door(id="door_1", center=(3.35, 2.7), width_m=0.7, jambs=((3.0, 2.7), (3.7, 2.7)),
                normal=(0.0, 1.0), connects=("space_1", "space_2"))
    (p,) = passages_with_door(furniture_row(0.7), door)
    assert p.center == pytest.approx((3.35, 2.35), abs=0.06)


def test_a_room_narrowing_to_its_door_is_the_doors_approach() -> None:
    # A 4 x 4 m room whose walls close in on its 0.7 m east door: a thick wall piece north of
    # the door (x 3-4, y 2.4-4) and a slanted wall south of it (its face rising from y 1.4 at
    # x 3 to 1.7 at the door): a pinch from 1.0 m to the door's 0.7 m, deep on both sides but
    # no squeeze between parallel faces. With the door found there, it is the door's approach.
    b = MapBuilder(10.0, 6.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 8.0, 4.0)
    b.rect(3.85, 0.0, 4.0, 1.7, OCCUPIED).rect(3.0, 2.4, 4.0, 4.0, OCCUPIED)
    for k in range(17):
        x = 3.0 + 0.05 * k
        b.rect(x, 0.0, x + 0.05, 1.4 + (x - 3.0) * 0.3 / 0.85, OCCUPIED)
    grid = b.build(source="room_to_door")
    door = Door(id="door_1", center=(3.925, 2.05), width_m=0.7, jambs=((3.925, 1.7), (3.925, 2.4)),
                normal=(1.0, 0.0), connects=("space_1", "space_2"))
    assert passages_with_door(grid, door) == ()
    # Control: the same squeeze with no door found is a way between the two rooms.
    assert len(passages_of(grid)) == 1


def test_a_door_found_along_a_cart_in_a_corridor_leaves_the_passage() -> None:
    # The 1.5 m cart narrowing the corridor, with a door found at the squeeze's east mouth: a
    # doorway is shorter than it is wide; a squeeze along a thing, longer than wide, is none.
    b = MapBuilder(14.0, 3.8, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 12.0, 1.8)
    b.box(5.0, 0.85, 6.5, 1.8).unknown(5.05, 0.9, 6.45, 1.75)
    door = Door(id="door_1", center=(6.5, 0.425), width_m=0.85, jambs=((6.5, 0.0), (6.5, 0.85)),
                normal=(1.0, 0.0), connects=("space_1", "space_2"))
    (p,) = passages_with_door(b.build(source="corridor_cart"), door)
    assert p.center == pytest.approx((5.75, 0.425), abs=0.06)


def test_a_door_found_at_the_end_of_a_thick_partition_is_that_door() -> None:
    # A 0.6 m thick partition across an 8 x 6 m room stops 0.9 m short of the south wall: the
    # opening is shorter than it is wide. With a door found there it is that door, no passage
    # (unfound, it is the only way past the partition: a squeeze).
    b = MapBuilder(10.0, 8.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 8.0, 6.0)
    b.rect(3.0, 0.9, 3.6, 6.0, OCCUPIED)
    grid = b.build(source="thick_partition")
    door = Door(id="door_1", center=(3.3, 0.45), width_m=0.9, jambs=((3.3, 0.0), (3.3, 0.9)),
                normal=(1.0, 0.0), connects=("space_1", "space_2"))
    assert passages_with_door(grid, door) == ()
    (p,) = passages_of(grid)
    assert p.center == pytest.approx((3.3, 0.45), abs=0.06)



def bench_rows(wall_m: float, depth_m: float = 0.55) -> OccupancyGrid:
    """A 10 x 8.5 m waiting room (x 0..10, y 0..8.5) with a partition ``wall_m`` thick across it
    at y 6.9 (a 0.9 m doorway at x 8) and three fixed bench rows ``depth_m`` deep (outline
    scanned, inside unknown) from x 0.75 to 5.0 at y 1.2, 3.15 and 5.1: each row's end leaves a
    0.75 m gap to the west wall, as long as the bench is deep, between 1.4 m aisles."""
    b = MapBuilder(12.0, 10.5, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 10.0, 8.5)
    b.wall(0.0, 6.9, 10.0, 6.9, thickness_m=wall_m)
    b.door_h(8.0, 6.9, 0.9, depth_m=wall_m + 0.1)
    for y0 in (1.2, 3.15, 5.1):
        b.box(0.75, y0, 5.0, y0 + depth_m).unknown(0.8, y0 + 0.05, 4.95, y0 + depth_m - 0.05)
    return b.build(source=f"bench_rows_{wall_m}_{depth_m}")


def test_typical_wall_thickness_is_read_from_walls_scanned_on_both_sides() -> None:
    # The partition (scanned from both sides) sets it; the outer walls (unknown behind them) and
    # the benches (deeper than any wall) do not.
    for wall_m in (0.1, 0.2, 0.35):
        layers = GridLayers(bench_rows(wall_m))
        assert typical_wall_thickness_m(layers.occupied, layers.free, 0.05) == pytest.approx(wall_m, abs=0.026)


def test_gaps_between_bench_ends_and_a_wall_are_passages_when_longer_than_two_walls() -> None:
    # 0.55 m long, under passage_min_length_m: in a building of 0.1 m partitions a 0.55 m deep
    # gap is no doorway (a doorway is as long as its wall is thick), so the three 0.75 m gaps
    # between the bench ends and the west wall are narrow passages, although one could walk
    # round the 4.25 m benches at their east ends.
    found = sorted(passages_of(bench_rows(0.1)), key=lambda p: p.center[1])
    assert [p.center for p in found] == [pytest.approx((0.375, y + 0.275), abs=0.06) for y in (1.2, 3.15, 5.1)]
    assert all(p.width_m == pytest.approx(0.75, abs=0.051) for p in found)
    assert all(p.length_m == pytest.approx(0.55, abs=0.1) for p in found)
    # The whole analysis (doors found first) reads them the same.
    assert len(analyze(bench_rows(0.1)).narrow_passages) == 3


def test_the_same_gaps_in_a_building_of_thick_walls_are_no_passages() -> None:
    # With 0.35 m walls a 0.55 m deep gap is as long as a doorway in one of them.
    assert passages_of(bench_rows(0.35)) == ()


def test_a_gap_no_deeper_than_a_doorway_is_no_passage_however_thin_the_walls() -> None:
    # 0.4 m deep bench ends: within the deepest doorway (door_max_depth_m), even where the
    # building's partitions are 0.1 m.
    assert passages_of(bench_rows(0.1, depth_m=0.4)) == ()


def laundry(island_x1: float = 7.3, door: bool = True, resolution_m: float = 0.05) -> OccupancyGrid:
    """An 8 x 6 m laundry (x 0-8) beside a 4 x 6 m drying room (x 8-12), a 0.85 m door between
    them at the north-east corner (y 5.0-5.85). A 6.3 m folding island (x 1.0 to ``island_x1``,
    y 4.4-5.25) leaves a 0.75 m aisle along the north wall, which bends at its east end: round
    the island's end (0.7 m from the east wall) into the laundry, and on through the door."""
    b = MapBuilder(15.0, 9.0, resolution_m=resolution_m, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 8.0, 6.0)
    b.room(8.0, 0.0, 12.0, 6.0)
    if door:
        b.free(7.9, 5.0, 8.1, 5.85)
    b.box(1.0, 4.4, island_x1, 5.25)
    return b.build(source=f"laundry_{island_x1}_{door}")


def test_an_aisle_that_bends_at_its_end_into_a_door_leads_somewhere() -> None:
    # The aisle's straight axis ends in its side at the bend; the way leaves through the last
    # cell of its middle line, into the drying room and round the island.
    (p,) = passages_of(laundry())
    assert p.center == pytest.approx((4.19, 5.52), abs=0.1)
    assert p.width_m == pytest.approx(0.775, abs=0.051)
    assert p.length_m == pytest.approx(6.28, abs=0.2)


def test_the_same_aisle_closed_at_its_end_leads_nowhere() -> None:
    # Control: the island runs on to the east wall and no door: a dead end.
    assert passages_of(laundry(island_x1=8.0, door=False)) == ()


def conveyor_line(crack_m: float | None) -> OccupancyGrid:
    """A 17 x 9 m hall crossed by a conveyor line (0.8 m deep, unknown inside its scanned
    outline) with a 0.95 m walk-through gap at x 7.6-8.55. With ``crack_m``, the east conveyor's
    end face was drawn twice: a one-cell line at x 8.45-8.5, then a free crack ``crack_m`` wide
    before the conveyor's inside (a pose error between two passes)."""
    b = MapBuilder(19.0, 11.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 17.0, 9.0)
    b.box(1.5, 4.0, 7.6, 4.8).unknown(1.55, 4.05, 7.55, 4.75)
    b.box(8.5, 4.0, 15.5, 4.8).unknown(8.55, 4.05, 15.45, 4.75)
    if crack_m is not None:
        b.free(8.5, 4.0, 8.5 + crack_m, 4.8)
        b.rect(8.45, 4.0, 8.5, 4.8, OCCUPIED)
    return b.build(source=f"conveyor_{crack_m}")


@pytest.mark.parametrize("crack_m", [None, 0.1])
def test_a_gap_in_a_conveyor_line_is_a_passage_its_doubled_end_face_too(crack_m: float | None) -> None:
    # A crack no wider than scan noise (OUTLINE_CRACK_M) between the two copies of the end face
    # is no way into the conveyor: it is as deep as before, and the gap between the ends is a
    # squeeze between two things.
    (p,) = passages_of(conveyor_line(crack_m))
    assert p.center == pytest.approx((8.03, 4.4), abs=0.05)
    assert p.width_m == pytest.approx(0.9 if crack_m is None else 0.85, abs=0.051)
    assert p.length_m == pytest.approx(0.8, abs=0.1)


def test_a_thin_panel_before_the_conveyor_end_is_no_thing_to_squeeze_past() -> None:
    # Control: 0.3 m of floor behind the line: a thin panel standing before the conveyor, no
    # deeper than a wall; the gap beside it is no squeeze between two things.
    assert passages_of(conveyor_line(0.3)) == ()


def slot_and_conveyor(resolution_m: float) -> OccupancyGrid:
    """A 17 x 9 m hall: two 0.4 x 2 m cabinets 0.7 m apart (a slot open at both ends, x 2.4-3.1),
    and a conveyor line (0.8 m deep, its outline 0.1 m, unknown inside) with a 0.9 m gap at
    x 7.6-8.5; every edge on a 0.1 m grid, so that the same building is drawn at any resolution."""
    b = MapBuilder(19.0, 11.0, resolution_m=resolution_m, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 17.0, 9.0)
    b.box(2.0, 1.5, 2.4, 3.5)
    b.box(3.1, 1.5, 3.5, 3.5)
    b.box(1.5, 5.0, 7.6, 5.8).unknown(1.6, 5.1, 7.5, 5.7)
    b.box(8.5, 5.0, 15.5, 5.8).unknown(8.6, 5.1, 15.4, 5.7)
    return b.build(source=f"slot_and_conveyor_{resolution_m}")


@pytest.mark.parametrize("resolution_m", [0.025, 0.1])
@pytest.mark.parametrize("building", ["laundry", "slot_and_conveyor"])
def test_passages_do_not_depend_on_the_maps_resolution(building: str, resolution_m: float) -> None:
    # The rules are in metres: the same building drawn at 0.025 m or 0.1 m has the passages it
    # has at 0.05 m, each where it was (within a cell) and as wide (within a cell).
    draw = {"laundry": lambda res: laundry(resolution_m=res), "slot_and_conveyor": slot_and_conveyor}[building]
    at_005 = sorted(passages_of(draw(0.05)), key=lambda p: p.center)
    found = sorted(passages_of(draw(resolution_m)), key=lambda p: p.center)
    assert len(at_005) == {"laundry": 1, "slot_and_conveyor": 2}[building]
    assert len(found) == len(at_005)
    for p, q in zip(found, at_005, strict=True):
        assert p.center == pytest.approx(q.center, abs=max(resolution_m, 0.05) + 0.01)
        assert p.width_m == pytest.approx(q.width_m, abs=max(resolution_m, 0.05) + 0.01)
        assert p.length_m == pytest.approx(q.length_m, abs=2 * max(resolution_m, 0.05) + 0.01)


def pews(gap_m: float, resolution_m: float = 0.05) -> OccupancyGrid:
    """A 10 x 8 m nave: two blocks of five 3 m pews (0.4 m deep) either side of a 1 m centre
    aisle, ``gap_m`` between one pew and the next, the rows from y = 2 m."""
    b = MapBuilder(12.0, 10.0, resolution_m=resolution_m, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 10.0, 8.0)
    for k in range(5):
        y = 2.0 + k * (0.4 + gap_m)
        b.box(2.0, y, 5.0, y + 0.4)
        b.box(6.0, y, 9.0, y + 0.4)
    return b.build(source=f"pews_{gap_m}")


@pytest.mark.parametrize("resolution_m", [0.025, 0.05, 0.1])
def test_the_slots_between_pews_are_no_passages(resolution_m: float) -> None:
    # 0.5 m as the map reads it (pews 0.35 m apart, their edges cleared by the lidar): no way
    # to send a 0.35 m robot, and no person calls the slot one sits in a passage.
    assert passages_of(pews(0.5, resolution_m)) == ()


@pytest.mark.parametrize("resolution_m", [0.025, 0.05, 0.1])
def test_aisles_between_rows_wide_enough_for_the_robot_are_passages(resolution_m: float) -> None:
    # The same nave with 0.6 m between the rows: each of the eight slots is a short aisle the
    # robot can take (0.125 m a side), from the side aisle to the centre aisle.
    found = sorted(passages_of(pews(0.6, resolution_m)), key=lambda p: (p.center[1], p.center[0]))
    want = [(x, 2.4 + k * 1.0 + 0.3) for k in range(4) for x in (3.5, 7.5)]
    assert len(found) == len(want)
    for p, centre in zip(found, want, strict=True):
        assert p.center == pytest.approx(centre, abs=0.06)
        assert p.width_m == pytest.approx(0.6, abs=0.051)
        assert p.length_m == pytest.approx(3.0, abs=0.15)


def cross_aisle(resolution_m: float = 0.05) -> OccupancyGrid:
    """A 9 x 8 m store room: a 0.4 m rack stands 0.8 m off its west wall (x 0.8-1.2, y 0.3-7.7,
    0.3 m from the north and south walls: too tight to pass), and five 4 m rack rows run east
    from x = 2 (0.4 m deep, from y = 1.2 every 1.2 m): their 0.8 m aisles open east into the
    room and west into the 0.8 m cross aisle between the rack and the rows' ends, which meets
    the room's floor only past the first and last rows."""
    b = MapBuilder(11.0, 10.0, resolution_m=resolution_m, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 9.0, 8.0)
    b.box(0.8, 0.3, 1.2, 7.7)
    for k in range(5):
        y = 1.2 + 1.2 * k
        b.box(2.0, y, 6.0, y + 0.4)
    return b.build(source="cross_aisle")


@pytest.mark.parametrize("resolution_m", [0.025, 0.05, 0.1])
def test_aisles_ending_in_a_narrow_cross_aisle_lead_somewhere(resolution_m: float) -> None:
    # The middle aisles' west mouths open into the cross aisle, 2.5 m from open floor: they lead
    # somewhere (the robot drives on down the cross aisle). The strip behind the rack leads
    # nowhere: 0.3 m gaps at both of its ends.
    found = sorted(passages_of(cross_aisle(resolution_m)), key=lambda p: p.center[1])
    assert len(found) == 4
    for k, p in enumerate(found):
        assert p.center == pytest.approx((4.0, 1.2 + 1.2 * k + 0.4 + 0.4), abs=0.06)
        assert p.width_m == pytest.approx(0.8, abs=0.051)
        assert p.length_m == pytest.approx(4.0, abs=0.15)


@pytest.mark.parametrize("degrees", [10.0, 23.0, 45.0])
def test_pews_and_cross_aisles_read_the_same_rotated(degrees: float) -> None:
    # Stair-stepped at any angle: no slot between pews 0.5 m apart, the eight 0.6 m aisles, and
    # the four rack aisles that end in a narrow cross aisle.
    assert passages_of(rotated(pews(0.5), degrees)) == ()
    wide = passages_of(rotated(pews(0.6), degrees))
    assert len(wide) == 8 and all(p.width_m == pytest.approx(0.6, abs=0.06) for p in wide)
    racks = passages_of(rotated(cross_aisle(), degrees))
    assert len(racks) == 4 and all(p.width_m == pytest.approx(0.8, abs=0.06) for p in racks)


def bike_grid(resolution_m: float = 0.05, gap_m: float = 0.75) -> OccupancyGrid:
    """A spin studio: a 4 x 3 grid of bikes (0.5 x 1.1 m) with ``gap_m`` between them and to the
    walls, its door a 0.9 m gap in the south wall."""
    nx, ny, bike_w, bike_l = 4, 3, 0.5, 1.1
    w, h = gap_m + nx * (bike_w + gap_m), gap_m + ny * (bike_l + gap_m)
    b = MapBuilder(w + 2.0, h + 2.0, resolution_m=resolution_m, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, w, h)
    b.free(w / 2 - 0.45, -0.2, w / 2 + 0.45, 0.0)
    for i in range(nx):
        for j in range(ny):
            x, y = gap_m + i * (bike_w + gap_m), gap_m + j * (bike_l + gap_m)
            b.box(x, y, x + bike_w, y + bike_l)
    return b.build(source=f"bike_grid_{gap_m}")


@pytest.mark.parametrize("resolution_m", [0.025, 0.05, 0.1])
def test_the_lanes_of_a_grid_of_bikes_are_no_passages(resolution_m: float) -> None:
    # Every gap between two bikes, or a bike and a wall, is as tight as the ways round it (0.75
    # m): none is the narrow passage a person points at (eight to ten were reported).
    assert passages_of(bike_grid(resolution_m)) == ()


def test_the_lanes_of_a_rotated_grid_of_bikes_are_no_passages() -> None:
    assert passages_of(rotated(bike_grid(), 23.0)) == ()


def test_a_door_read_in_a_gap_between_two_deep_things_keeps_the_gap_a_passage() -> None:
    """A 10 x 7 m lounge: a 2.6 x 0.8 m sofa and a 1.6 x 0.8 m block of armchairs stand end to
    end in its middle (outlines scanned, insides unknown), 0.8 m apart; open floor leads round
    both. A door read in that gap (the segmentation's, as on a real map) is no door: its sides
    are things with parallel faces deeper than any wall, so the gap is judged as a squeeze (tight
    for a person: a passage) and not as a doorway one could go round."""
    b = MapBuilder(12.0, 9.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 10.0, 7.0)
    b.box(2.0, 3.0, 4.6, 3.8).unknown(2.05, 3.05, 4.55, 3.75)
    b.box(5.4, 3.0, 7.0, 3.8).unknown(5.45, 3.05, 6.95, 3.75)
    grid = b.build(source="lounge_gap")
    labels, n = labels_for_free_components(grid)
    layers = GridLayers(grid)
    door = Door(id="door_1", center=(5.0, 3.4), width_m=0.8, jambs=((4.6, 3.4), (5.4, 3.4)), normal=(0.0, 1.0),
                connects=("space_1", "space_1"))
    for doors in ([], [door]):
        (p,) = find_passages(grid, P, labels, {k: f"space_{k}" for k in range(1, n + 1)}, doors,
                             layers.occupied | layers.unknown, layers=layers)
        assert p.center == pytest.approx((5.0, 3.4), abs=0.05)
        assert p.width_m == pytest.approx(0.8, abs=0.051)
        assert p.length_m == pytest.approx(0.8, abs=0.1)


#: A 0.1 m map's locker room (a crop of a simulated-SLAM map, '#' occupied, '?' unknown, '.'
#: free): an 0.85 m aisle between a row of wall lockers and a locker island, both scanned as
#: outlines with unknown insides. Each side's outline steps a cell at a different place, so the
#: aisle is a cell wider for a few cells, where its middle line jogs sideways.
LOCKER_AISLE_0_1 = (
    ".##................................................................................",
    ".##................................................................................",
    ".##................................................................................",
    ".##..............##################################################................",
    ".##..............#????????????????????#############################................",
    ".##..............#????????????????????????????????????????????????#................",
    ".##.............##????????????????????????????????????????????????#................",
    ".##..............#????????????????????????????????????????????????#................",
    ".##..............##################################################................",
    ".##...............######??.#?#?#.###.##.##?#####...................................",
    ".##................................................................................",
    ".##................................................................................",
    ".##................................................................................",
    ".##................................................................................",
    ".##................................................................................",
    ".##................................................................................",
    ".##................................................................................",
    ".##.....................................................#?.################........",
    ".##....######################################################################......",
    ".##....?????????????????????????????????????????????????????????????????????#......",
    ".##....?????????????????????????????????????????????????????????????????????#......",
    ".##...??????????????????????????????????????????????????????????????????????#......",
    ".##...??????????????????????????????????????????????????????????????????????#......",
    ".#####?????????????????##?#?#?????????#?#?#??##?#####?#?#####??####################",
    ".##################################################################################",
    ".##................................................................................",
    ".##................................................................................",
    ".##................................................................................",
)


def test_an_aisle_whose_middle_line_jogs_on_coarse_cells_is_one_passage() -> None:
    # The jog (the width read there 0.2 m over the aisle's) cut the aisle at 3.3 m, its centre
    # off the lockers' middle; it is one 5 m passage (the island's length).
    cells = np.array([[{"#": OCCUPIED, "?": UNKNOWN}.get(ch, 0) for ch in row] for row in LOCKER_AISLE_0_1],
                     dtype=np.int8)
    (p,) = passages_of(OccupancyGrid(cells, 0.1, source="locker_aisle_0.1"))
    assert p.length_m == pytest.approx(5.0, abs=0.15)
    assert p.width_m == pytest.approx(0.8, abs=0.051)
    assert p.center == pytest.approx((4.2, 1.32), abs=0.1)


def test_a_door_read_across_a_long_aisle_between_lockers_is_no_door() -> None:
    """A 10 x 5 m locker room: wall lockers 0.5 m deep along its north wall (x 1 to 8) and a
    0.6 m deep locker island (x 2 to 7) 0.85 m south of them, outlines scanned, insides unknown.
    A door read across the aisle's middle (as on a turned map, where the stair-stepped faces
    read as jambs) is no door: no wall stands between two things deeper than any wall along a
    way as long as a corridor. The aisle is one passage, the island's length."""
    b = MapBuilder(12.0, 7.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 10.0, 5.0)
    b.box(1.0, 4.5, 8.0, 5.0).unknown(1.05, 4.55, 7.95, 4.95)
    b.box(2.0, 3.05, 7.0, 3.65).unknown(2.05, 3.1, 6.95, 3.6)
    grid = b.build(source="locker_room")
    labels, n = labels_for_free_components(grid)
    layers = GridLayers(grid)
    door = Door(id="door_1", center=(4.5, 4.075), width_m=0.85, jambs=((4.5, 3.65), (4.5, 4.5)),
                normal=(1.0, 0.0), connects=("space_1", "space_1"))
    (p,) = find_passages(grid, P, labels, {k: f"space_{k}" for k in range(1, n + 1)}, [door],
                         layers.occupied | layers.unknown, layers=layers)
    assert p.center == pytest.approx((4.5, 4.075), abs=0.06)
    assert p.width_m == pytest.approx(0.85, abs=0.051)
    assert p.length_m == pytest.approx(5.0, abs=0.2)


@settings(max_examples=16, deadline=None, derandomize=True)
@given(width_m=st.floats(0.6, 0.85), length_m=st.floats(2.5, 6.0), depth_m=st.floats(0.4, 1.0),
       degrees=st.one_of(st.just(0.0), st.floats(0.0, 90.0)), resolution_m=st.sampled_from([0.025, 0.05, 0.1]))
def test_an_aisle_between_two_shelf_rows_is_one_passage_of_its_width(width_m: float, length_m: float, depth_m: float,
                                                                      degrees: float, resolution_m: float) -> None:
    """Two shelf rows standing free in a hall, whatever their length, depth and the map's angle
    and cells: the aisle between them is one passage, as wide as it is (up to a cell and a half:
    drawn on cells its width is rounded to whole cells, and a turned map's stair-stepped faces
    add one), and nothing else is. (Aisles up to 0.85 m: within that cell and a half of
    passage_max_width_m, 1.0 m, on 0.1 m cells an aisle may read as wider than a passage.)"""
    b = MapBuilder(length_m + 6.0, 2 * depth_m + width_m + 6.0, resolution_m=resolution_m, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, length_m + 4.0, 2 * depth_m + width_m + 4.0)
    b.box(2.0, 2.0, 2.0 + length_m, 2.0 + depth_m)
    b.box(2.0, 2.0 + depth_m + width_m, 2.0 + length_m, 2.0 + 2 * depth_m + width_m)
    grid = b.build(source="two shelf rows")
    found = passages_of(rotated(grid, degrees) if degrees else grid)
    assert len(found) == 1
    assert found[0].width_m == pytest.approx(width_m, abs=1.5 * resolution_m + 0.01)
    assert found[0].length_m == pytest.approx(length_m, abs=0.1 * length_m + 2 * resolution_m)


def rack_rows(cross_aisle: bool) -> OccupancyGrid:
    """A 12 x 8 m hall with three rack rows, 0.6 m deep and 8 m long (x from 2 to 10), 0.8 m
    apart: the middle row has a 0.8 m cross-over gap (x from 5.6 to 6.4); ``cross_aisle``: the
    outer rows have it too, a cross aisle through all three."""
    b = MapBuilder(14.0, 10.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 12.0, 8.0)
    for k, y in enumerate((2.0, 3.4, 4.8)):
        if k == 1 or cross_aisle:
            b.box(2.0, y, 5.6, y + 0.6)
            b.box(6.4, y, 10.0, y + 0.6)
        else:
            b.box(2.0, y, 10.0, y + 0.6)
    return b.build(source="rack_rows")


def test_an_aisle_goes_on_past_a_cross_over_gap_in_one_of_its_rows() -> None:
    """Each aisle runs the racks' whole length: the gap in the middle row beside it is a way off it
    (as a door off a corridor), not its end; one passage each, not two halves."""
    found = sorted(passages_of(rack_rows(cross_aisle=False)), key=lambda p: p.center[1])
    assert len(found) == 2
    for p, y in zip(found, (3.0, 4.4), strict=True):
        assert p.center == pytest.approx((6.0, y), abs=0.1)
        assert p.width_m == pytest.approx(0.8, abs=0.051)
        assert p.length_m == pytest.approx(8.0, abs=0.3)


def test_aisles_either_side_of_a_cross_aisle_stay_two() -> None:
    """Where the cross-over runs through every row, both sides of each aisle open there: a cross
    aisle, and the aisle's halves either side of it are two ways."""
    found = sorted(passages_of(rack_rows(cross_aisle=True)), key=lambda p: (p.center[1], p.center[0]))
    assert len(found) == 4
    for p, (x, y) in zip(found, ((3.8, 3.0), (8.2, 3.0), (3.8, 4.4), (8.2, 4.4)), strict=True):
        assert p.center == pytest.approx((x, y), abs=0.15)
        assert p.length_m == pytest.approx(3.6, abs=0.3)
