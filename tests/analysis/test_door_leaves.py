"""Open door leaves (issue 8): a double door whose two leaves stand open across the wall, into
the room they swing into, is still a door in its wall line; golden buildings drawn here with the
door known exactly, turned and resampled (a rule about buildings holds whatever the map's angle
and cell size), and the look-alikes that are no door: a slot between two shelf units, and a gap
between two desk dividers that cross the line."""

from __future__ import annotations

import math

import numpy as np
import pytest
from analysis_maps import POS_TOL_M, door_near, space_at

from langnav.analysis.elements import ElementKind
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.pipeline import analyze
from langnav.analysis.segmentation import segment_spaces
from langnav.analysis.wall_lines import leaf_mask, wall_gaps
from langnav.eval.transforms import PointsAnnotation, map_centre, resample, rotate, rotate_point
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import FREE, OCCUPIED, OccupancyGrid

#: The door's centre (world metres) in :func:`hall_off_corridor`.
DOOR_XY = (8.0, 2.6)
#: A door leaf is drawn this thick (m): a panel of a few centimetres, one cell of a 5 cm map.
LEAF_M = 0.05


def hall_off_corridor(width_m: float, jambs: str) -> OccupancyGrid:
    """A 2 m x 15 m corridor (y 0.5-2.5) with a 10 m x 6.8 m hall north of it, entered through a
    ``width_m`` opening centred at DOOR_XY in their 0.15 m wall. ``jambs``: what stands at the
    opening's two ends on the hall's side: "leaves" (a double door's two leaves, open at 90
    degrees into the hall, half the opening long each), "shelves" (two 0.6 m shelf units as
    deep as the leaves, against the wall), "dividers" (two thin panels crossing the wall line,
    standing out 1 m into the corridor as well), or "none"."""
    b = MapBuilder(16.0, 11.0)
    b.room(0.5, 0.5, 15.5, 2.5)  # the corridor
    b.room(3.0, 2.65, 13.0, 9.5)  # the hall
    b.door_h(DOOR_XY[0], 2.575, width_m)
    x0, x1 = DOOR_XY[0] - width_m / 2, DOOR_XY[0] + width_m / 2
    reach = width_m / 2
    if jambs == "leaves":
        b.wall(x0 + LEAF_M / 2, 2.65, x0 + LEAF_M / 2, 2.65 + reach, LEAF_M)
        b.wall(x1 - LEAF_M / 2, 2.65, x1 - LEAF_M / 2, 2.65 + reach, LEAF_M)
    elif jambs == "shelves":
        b.box(x0 - 0.6, 2.65, x0, 2.65 + reach)
        b.box(x1, 2.65, x1 + 0.6, 2.65 + reach)
    elif jambs == "dividers":
        b.wall(x0 + LEAF_M / 2, 1.5, x0 + LEAF_M / 2, 2.65 + reach, LEAF_M)
        b.wall(x1 - LEAF_M / 2, 1.5, x1 - LEAF_M / 2, 2.65 + reach, LEAF_M)
    elif jambs != "none":
        raise ValueError(f"jambs: none, leaves, shelves or dividers, not {jambs!r}")
    return b.build(f"hall off a corridor, {width_m} m opening, {jambs}")


@pytest.mark.parametrize("width_m", [1.6, 1.8])
def test_a_double_door_with_its_leaves_open_is_the_door_between_corridor_and_hall(width_m: float) -> None:
    """The leaves stand across the wall at both jambs: the opening reads as deep as a slot
    between two cabinets, and the hall's floor along the wall is cut by them. They are thin,
    free-ended panels no longer than half the opening: leaves, not wall. One door, in the wall
    line, between the hallway and the hall, as wide as the clear way between the leaves."""
    grid = hall_off_corridor(width_m, "leaves")
    seg = segment_spaces(grid)
    corridor = space_at(seg, grid, 2.0, 1.5)
    hall = space_at(seg, grid, 8.0, 6.0)
    assert corridor.kind == ElementKind.HALLWAY
    assert hall.kind == ElementKind.ROOM
    assert len(seg.rooms) == 2
    assert seg.openings == ()
    assert len(seg.doors) == 1
    door = door_near(seg.doors, *DOOR_XY)
    assert set(door.connects) == {corridor.id, hall.id}
    assert door.width_m == pytest.approx(width_m - 2 * LEAF_M, abs=POS_TOL_M)


def test_the_leaves_are_found_and_only_their_cells_leave_the_wall() -> None:
    """The leaf cells the wall lines report are the two panels beyond the wall's face: the jambs
    stay wall (a door is judged on them)."""
    grid = hall_off_corridor(1.6, "leaves")
    occupied = grid.cells == OCCUPIED
    gaps = wall_gaps(occupied, grid.cells == FREE, grid.resolution_m, DEFAULT_PARAMS)
    leaves = leaf_mask(gaps, occupied.shape)
    rr, cc = np.nonzero(leaves)
    xs, ys = grid.cell_to_world(rr, cc)
    assert leaves.sum() > 0
    assert set(np.round(xs, 3)) <= {7.225, 8.775}  # the two panels' cells (5 cm cells, centres)
    assert ys.min() > 2.65 and ys.max() <= 2.65 + 0.8 + 0.05
    assert (occupied & leaves).sum() == leaves.sum()


@pytest.mark.parametrize("jambs", ["shelves", "dividers"])
def test_shelf_units_and_crossing_dividers_are_no_leaves(jambs: str) -> None:
    """Shelf units have their bodies behind their sides; dividers cross the wall line and stand
    out on both sides of it: neither is a door's leaf, and the 1.8 m gap between them is no
    door."""
    grid = hall_off_corridor(1.8, jambs)
    seg = segment_spaces(grid)
    assert not [d for d in seg.doors if math.dist(d.center, DOOR_XY) <= 0.5]


@pytest.mark.parametrize("angle_deg", [17.0, 33.0, 62.0])
def test_the_double_door_is_found_whatever_the_maps_rotation(angle_deg: float) -> None:
    """Turned about the map's centre (a slam_toolbox map's frame is at any angle to the
    building), the leaves are staircases of cells a cell or two wide: still leaves, and the door
    is still the one way between the two spaces."""
    grid0 = hall_off_corridor(1.8, "leaves")
    grid, _ = rotate(grid0, PointsAnnotation(), angle_deg)
    centre = rotate_point(DOOR_XY, map_centre(grid0), math.radians(angle_deg))
    result = analyze(grid)
    assert len(result.rooms) == 2
    assert result.openings == ()
    assert len(result.doors) == 1
    door = door_near(result.doors, *centre)
    assert door.width_m == pytest.approx(1.8 - 2 * LEAF_M, abs=2 * POS_TOL_M)


@pytest.mark.parametrize("resolution_m", [0.025, 0.1])
def test_the_double_door_is_found_whatever_the_cell_size(resolution_m: float) -> None:
    grid = resample(hall_off_corridor(1.8, "leaves"), resolution_m)
    result = analyze(grid)
    assert len(result.rooms) == 2
    assert len(result.doors) == 1
    door = door_near(result.doors, *DOOR_XY, tol=POS_TOL_M + resolution_m)
    assert door.width_m == pytest.approx(1.8 - 2 * LEAF_M, abs=POS_TOL_M + resolution_m)
