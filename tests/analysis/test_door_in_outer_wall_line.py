"""An entrance in the building's outer wall is judged in the wall line (issue 8): the lidar saw
out through it, the fan of rays beyond was flooded as a space of its own (a view out), and the
flood parted the two across the rays, off the wall and slanted to it, where the door's leaves
standing open outwards make the opening read as deep as a slot. A person reads the door where
the wall is, as wide as the gap in it: the gap the wall lines find there (seen floor inside,
only the rays through it outside) stands in for the flood's doorway. Golden buildings drawn
here with the door known exactly, turned (a rule about buildings holds whatever the map's
angle), and the look-alike that stays no door: a gap whose clear way is narrower than the
wall-line gap read beside it."""

from __future__ import annotations

import math

import numpy as np
import pytest
from analysis_maps import POS_TOL_M, door_near
from test_views_out import _rays

from langnav.analysis.door_judge import DoorEvidence, is_door
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.pipeline import analyze
from langnav.eval.transforms import PointsAnnotation, map_centre, rotate, rotate_point
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import OCCUPIED, OccupancyGrid

#: The entrance's centre (world metres) in :func:`lobby_with_entrance`: in the east wall's line.
DOOR_XY = (8.075, 3.5)
#: A door leaf is drawn this thick (m): a panel of a few centimetres, one cell of a 5 cm map.
LEAF_M = 0.05


def lobby_with_entrance(width_m: float) -> OccupancyGrid:
    """A 7 m x 5 m lobby (x 1-8, y 1-6) with an entrance ``width_m`` wide centred at DOOR_XY in
    its east wall, a double door whose two leaves stand open outwards at 90 degrees (half the
    opening long each), and beyond it the open outside, seen only as a fan of rays 80 degrees
    wide and 9 m long sent out through the entrance from inside the lobby."""
    b = MapBuilder(18.0, 11.0)
    b.room(1.0, 1.0, 8.0, 6.0).door_v(DOOR_XY[0], DOOR_XY[1], width_m)
    grid = b.build(f"lobby with a {width_m} m entrance")
    cells = grid.cells.copy()
    ys, xs = np.mgrid[0:cells.shape[0], 0:cells.shape[1]]
    wx, wy = grid.cell_to_world(ys, xs)
    half = width_m / 2
    for y_jamb, inward in ((DOOR_XY[1] - half, 1.0), (DOOR_XY[1] + half, -1.0)):
        leaf = (wx > 8.15) & (wx < 8.15 + half) & (np.abs(wy - (y_jamb + inward * LEAF_M / 2)) < 0.03)
        cells[leaf] = OCCUPIED
    _rays(cells, grid, 6.5, DOOR_XY[1], np.arange(-40.0, 40.5, 0.5), 9.0)
    return OccupancyGrid(cells, grid.resolution_m, grid.origin_x_m, grid.origin_y_m, source=grid.source)


@pytest.mark.parametrize("width_m", [1.2, 1.7])
@pytest.mark.parametrize("angle_deg", [0.0, 33.0, 62.0])
def test_an_entrance_with_its_leaves_open_outwards_is_the_door_in_the_outer_wall(width_m: float,
                                                                               angle_deg: float) -> None:
    """One door, in the east wall's line, from the lobby onto the unexplored outside (the view
    out is no space), as wide as the opening between the leaves; the lobby is the one space."""
    grid0 = lobby_with_entrance(width_m)
    grid, centre = grid0, DOOR_XY
    if angle_deg:
        grid, _ = rotate(grid0, PointsAnnotation(), angle_deg)
        centre = rotate_point(DOOR_XY, map_centre(grid0), math.radians(angle_deg))
    result = analyze(grid)
    assert len(result.rooms) == 1
    assert result.openings == ()
    assert len(result.doors) == 1
    door = door_near(result.doors, *centre)
    assert door.connects[0] == result.rooms[0].id
    assert door.connects[1].startswith("unexplored_")
    assert door.width_m == pytest.approx(width_m - 2 * LEAF_M, abs=2 * POS_TOL_M)


def _evidence(clear_m: float) -> DoorEvidence:
    """A gap's evidence: jambs of wall running on, along the walls, scanned, clear ``clear_m``."""
    return DoorEvidence(constriction_m=0.2, constriction_back_m=0.1, along=(1.0, 1.0), across=(0.1, 0.1),
                        clear_width_m=(clear_m, clear_m))


def test_a_wall_line_gap_between_two_spaces_is_as_wide_as_its_clear_way() -> None:
    """A ragged wall's band shows a gap on each of its lines; on an outer one, where the wall's
    cells stray from it, the gap reads wider than the floor is clear across the doorway (1.75 m
    read, 1.05 m clear): no door there. Read as clear as it is wide, give or take a frame's
    narrowing, it is one."""
    params = DEFAULT_PARAMS
    assert not is_door(_evidence(1.05), params, into_unknown=False, in_wall_line=True, width_m=1.75)
    assert is_door(_evidence(1.6), params, into_unknown=False, in_wall_line=True, width_m=1.75)
    # The flood's own doorways are measured where they are clear: the rule is the gap's.
    assert is_door(_evidence(1.05), params, into_unknown=True, in_wall_line=True, width_m=1.75)
