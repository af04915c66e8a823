"""Narrow passages on layouts written for this check before running them: rack aisles of several
widths, a dead-end aisle, a line of screens with a gap in it (a rail, a detector arch), the same
rotated and with lidar noise, with the exact passages a person would point at."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import ndimage as ndi

from langnav.analysis.elements import NarrowPassage
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.passages import find_passages
from langnav.analysis.pipeline import analyze, labels_for_free_components
from langnav.analysis.precompute import GridLayers
from langnav.analysis.unexplored import find_unexplored
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import OCCUPIED, UNKNOWN, OccupancyGrid

P = DEFAULT_PARAMS
#: The rack hall: racks 0.6 m deep from x 2 to 8 (scanned outline, unknown inside).
RACK_X = (2.0, 8.0)
RACK_DEPTH_M = 0.6


def passages_of(grid: OccupancyGrid) -> tuple[NarrowPassage, ...]:
    """The passages of ``grid`` with its free components as spaces and no doors (as the pipeline
    reads unknown specks and unexplored areas)."""
    labels, n = labels_for_free_components(grid)
    layers = GridLayers(grid)
    unx = find_unexplored(grid, P, layers)
    return find_passages(grid, P, labels, {k: f"space_{k}" for k in range(1, n + 1)}, [],
                         layers.occupied | (layers.unknown & ~unx.specks), layers=layers,
                         unexplored=unx.area_labels > 0)


def rack_hall(aisles_m: tuple[float, ...], dead_end: bool = False) -> OccupancyGrid:
    """A 10 x 8 m hall (x 0..10, y 0..8); rack rows run east-west from x 2 to 8 (to the west wall
    with ``dead_end``), the first at y 1.5, with aisles ``aisles_m`` wide between them: each aisle
    opens at both ends into 2 m cross aisles (only at its east end with ``dead_end``)."""
    b = MapBuilder(12.0, 10.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 10.0, 8.0)
    x0 = 0.05 if dead_end else RACK_X[0]
    y = 1.5
    for gap in (*aisles_m, None):
        b.box(x0, y, RACK_X[1], y + RACK_DEPTH_M).unknown(x0 + 0.05, y + 0.05, RACK_X[1] - 0.05,
                                                          y + RACK_DEPTH_M - 0.05)
        if gap is not None:
            y += RACK_DEPTH_M + gap
    return b.build(source=f"rack_hall_{aisles_m}_{dead_end}")


def aisle_ys(aisles_m: tuple[float, ...]) -> list[float]:
    out, y = [], 1.5 + RACK_DEPTH_M
    for gap in aisles_m:
        out.append(y + gap / 2)
        y += gap + RACK_DEPTH_M
    return out


def rotated(grid: OccupancyGrid, degrees: float) -> OccupancyGrid:
    """The grid turned by ``degrees`` about its centre, cell by cell (uncovered corners unknown)."""
    cells = ndi.rotate(grid.cells.astype(np.int16) + 1, degrees, order=0, reshape=True, cval=0) - 1
    return OccupancyGrid(cells.astype(np.int8), grid.resolution_m, source=f"{grid.source}_rotated")


def with_lidar_noise(grid: OccupancyGrid, seed: int = 0) -> OccupancyGrid:
    """Occupied specks on 3 % of the free cells within two cells of a wall, unknown specks on 0.2 %
    of the free cells, 5 % of the wall cells dropped out (free)."""
    rng = np.random.default_rng(seed)
    c = grid.cells.copy()
    free, occ = c == 0, c == 100
    near_wall = ndi.binary_dilation(occ, iterations=2) & free
    c[near_wall & (rng.random(c.shape) < 0.03)] = 100
    c[free & (rng.random(c.shape) < 0.002)] = UNKNOWN
    c[occ & (rng.random(c.shape) < 0.05)] = 0
    return OccupancyGrid(c, grid.resolution_m, source=f"{grid.source}_noisy")


AISLES = (0.6, 0.75, 0.9)


def test_rack_aisles_of_06_to_09_m_are_passages_the_length_of_the_racks() -> None:
    found = sorted(passages_of(rack_hall(AISLES)), key=lambda p: p.center[1])
    assert len(found) == 3
    for p, y, w in zip(found, aisle_ys(AISLES), AISLES, strict=True):
        assert p.center == pytest.approx((5.0, y), abs=0.05)
        assert p.width_m == pytest.approx(w, abs=0.051)
        assert p.length_m == pytest.approx(RACK_X[1] - RACK_X[0], abs=0.3)


def test_rack_aisles_closed_at_one_end_by_the_wall_are_no_passages() -> None:
    # The same racks run on to the west wall: each aisle is a dead end (one goes in to reach the
    # racks and comes back out), no way through between two free areas.
    assert passages_of(rack_hall(AISLES, dead_end=True)) == ()


@pytest.mark.parametrize("degrees", [17.0, 41.0])
def test_rack_aisles_rotated_with_lidar_noise_keep_their_widths(degrees: float) -> None:
    found = passages_of(with_lidar_noise(rotated(rack_hall(AISLES), degrees)))
    assert sorted(round(p.width_m / 0.05) * 0.05 for p in found) == pytest.approx(list(AISLES), abs=0.051)
    assert all(p.length_m == pytest.approx(6.0, abs=0.4) for p in found)


@pytest.mark.parametrize("degrees", [17.0, 41.0])
def test_rotated_noisy_dead_end_aisles_stay_no_passages(degrees: float) -> None:
    assert passages_of(with_lidar_noise(rotated(rack_hall(AISLES, dead_end=True), degrees))) == ()


def screen_line(gap_m: float = 0.7, to_walls: bool = False, depth_m: float = 0.1) -> OccupancyGrid:
    """A 10 x 6 m room (x 0..10, y 0..6) of 0.1 m walls with a line of screens ``depth_m`` deep
    (thinner than the deepest doorway) centred on y 3: from x 2 to 5 and from 5 + ``gap_m`` to 8,
    open floor round both ends (with ``to_walls``, the line runs from wall to wall: a partition
    with a doorway in it)."""
    b = MapBuilder(12.0, 8.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 10.0, 6.0, wall_m=0.1)
    x0, x1 = (0.0, 10.0) if to_walls else (2.0, 8.0)
    b.rect(x0, 3.0 - depth_m / 2, 5.0, 3.0 + depth_m / 2, OCCUPIED)
    b.rect(5.0 + gap_m, 3.0 - depth_m / 2, x1, 3.0 + depth_m / 2, OCCUPIED)
    return b.build(source=f"screen_line_{gap_m}_{to_walls}_{depth_m}")


@pytest.mark.parametrize(("depth_m", "degrees"), [(0.1, 0.0), (0.1, 10.0), (0.1, 23.0), (0.1, 41.0),
                                              (0.3, 0.0), (0.3, 23.0), (0.3, 67.0)])
def test_a_tight_gap_in_a_free_standing_line_of_screens_is_a_passage(depth_m: float, degrees: float) -> None:
    # A line of screens, a rail, a detector arch between two machines: no wall (it stands free,
    # open floor round its ends), so its gap is no doorway however thin the line; 0.7 m is tight
    # for a person, so it is a passage although one could walk round the line's ends. As long as
    # the line is thick, give or take the steps of a line drawn askew.
    grid = screen_line(0.7, depth_m=depth_m)
    (p,) = passages_of(rotated(grid, degrees) if degrees else grid)
    assert p.width_m == pytest.approx(0.7, abs=0.051)
    assert p.length_m == pytest.approx(depth_m, abs=0.07)
    if not degrees:
        assert p.center == pytest.approx((5.35, 3.0), abs=0.06)


@pytest.mark.parametrize("depth_m", [0.1, 0.3])
def test_the_same_gap_in_a_line_from_wall_to_wall_is_a_doorway(depth_m: float) -> None:
    # Joined to the walls at both ends the line is a partition: its gap is a doorway (a door's
    # business), not a passage.
    assert passages_of(screen_line(0.7, to_walls=True, depth_m=depth_m)) == ()
    assert passages_of(rotated(screen_line(0.7, to_walls=True, depth_m=depth_m), 23.0)) == ()


@pytest.mark.parametrize("depth_m", [0.1, 0.3])
def test_a_roomy_gap_in_a_free_standing_line_is_walked_round(depth_m: float) -> None:
    # 0.95 m: roomy for a person, with open floor round the line's ends: no passage.
    assert passages_of(screen_line(0.95, depth_m=depth_m)) == ()


def test_a_gap_between_a_rack_row_end_and_a_rack_beside_a_cross_aisle_is_no_gap_in_a_line() -> None:
    # Rotated, the cross aisle between a free-standing rack and the rack rows' ends reads as a
    # short gap between two free-standing things at each row's end; the rack runs along the
    # way there, no line going on away from the gap: no passage (the rows' four aisles are).
    b = MapBuilder(11.0, 10.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 9.0, 8.0)
    b.box(0.8, 0.3, 1.2, 7.7)
    for k in range(5):
        b.box(2.0, 1.2 + 1.2 * k, 6.0, 1.6 + 1.2 * k)
    found = passages_of(rotated(b.build(source="cross_aisle"), 23.0))
    assert len(found) == 4
    assert all(p.length_m == pytest.approx(4.0, abs=0.15) for p in found)


def test_specks_across_a_gap_are_the_line_going_on() -> None:
    # A glass front: its returns are sparse, single specks between longer pieces; a 0.7 m stretch
    # with specks on it is no gap in the line.
    b = MapBuilder(12.0, 8.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 10.0, 6.0, wall_m=0.1)
    b.rect(2.0, 2.95, 5.0, 3.05, OCCUPIED).rect(5.7, 2.95, 8.0, 3.05, OCCUPIED)
    b.rect(5.2, 2.95, 5.25, 3.0, OCCUPIED).rect(5.45, 3.0, 5.5, 3.05, OCCUPIED)
    assert passages_of(b.build(source="glass_front")) == ()


@pytest.mark.parametrize("degrees", [0.0, 23.0, 41.0])
def test_a_gap_in_a_free_standing_line_in_the_whole_analysis(degrees: float) -> None:
    # The whole analysis (a line of 0.3 m cabinets): one room, the gap a passage and no door
    # (the line is in no wall).
    grid = screen_line(0.7, depth_m=0.3)
    a = analyze(rotated(grid, degrees) if degrees else grid)
    assert len(a.rooms) == 1
    assert a.doors == ()
    (p,) = a.narrow_passages
    assert p.width_m == pytest.approx(0.7, abs=0.051)


def long_cross_aisle() -> OccupancyGrid:
    """A 9 x 10 m store room (y 0..10): a 0.4 m rack stands 0.8 m off its west wall (x 0.8-1.2,
    0.3 m from the north and south walls: too tight to pass), and seven 4 m rack rows run east
    from x = 2 (0.4 m deep, from y = 1.2 every 1.2 m): their 0.8 m aisles open east into the room
    and west into the 0.8 m cross aisle, which meets the room's floor only past the first and last
    rows, 3.6 m from the middle aisle's west mouth."""
    b = MapBuilder(11.0, 12.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 9.0, 10.0)
    b.box(0.8, 0.3, 1.2, 9.7)
    for k in range(7):
        b.box(2.0, 1.2 + 1.2 * k, 6.0, 1.6 + 1.2 * k)
    return b.build(source="long_cross_aisle")


@pytest.mark.parametrize("degrees", [0.0, 23.0])
def test_aisles_leading_round_a_rack_into_a_long_cross_aisle_lead_somewhere(degrees: float) -> None:
    # The west mouths open into the cross aisle, which reaches open floor within the way round a
    # thing standing in a room (WAY_ROUND_M): all six aisles lead somewhere.
    grid = long_cross_aisle()
    found = sorted(passages_of(rotated(grid, degrees) if degrees else grid), key=lambda p: p.center[1])
    assert len(found) == 6
    assert all(p.width_m == pytest.approx(0.8, abs=0.06) for p in found)
    assert all(p.length_m == pytest.approx(4.0, abs=0.15) for p in found)
    if not degrees:
        assert [p.center for p in found] == [pytest.approx((4.0, 2.0 + 1.2 * k), abs=0.06) for k in range(6)]
