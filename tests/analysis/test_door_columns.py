"""Columns standing free in the floor are no door's jambs (issue 8): the gap between two of them
is a way between them, not a door cut in a wall (the turtlebot3 world's pillars, turned with the
map, read as a row of doorways). A pier between two doors stands beside a wall's end at their
other jambs: those doors keep it. Golden grids drawn here, the jambs known exactly, turned."""

from __future__ import annotations

import math

import numpy as np
import pytest

from langnav.analysis.door_judge import evidence, is_column, is_door, is_furniture
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.eval.transforms import PointsAnnotation, map_centre, rotate, rotate_point
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN, OccupancyGrid

#: The gap's centre (world metres) in :func:`floor_with_bodies`.
GAP_XY = (5.0, 4.0)
#: A column's radius (m): a 0.35 m round pillar.
COLUMN_R_M = 0.175


def floor_with_bodies(left: str) -> OccupancyGrid:
    """A 10 m x 8 m hall (x 0-10, y 0-8) with a 0.35 m column at x = 5.525 east of GAP_XY and,
    0.7 m of floor west of it, ``left``: another such column ("column"), or the end of a wall
    running 3 m west from there ("wall")."""
    b = MapBuilder(10.0, 8.0)
    b.room(0.0, 0.0, 10.0, 8.0)
    b.disc(GAP_XY[0] + 0.35 + COLUMN_R_M, GAP_XY[1], COLUMN_R_M)
    if left == "column":
        b.disc(GAP_XY[0] - 0.35 - COLUMN_R_M, GAP_XY[1], COLUMN_R_M)
    else:
        b.wall(GAP_XY[0] - 3.35, GAP_XY[1], GAP_XY[0] - 0.35, GAP_XY[1], 0.15)
    return b.build(f"hall, a column and a {left}")


def _judged(grid: OccupancyGrid, centre: tuple[float, float], normal_xy: tuple[float, float]) -> tuple[bool, bool]:
    """(both jambs are columns, the gap is a door) for the gap at ``centre``, 0.7 m wide."""
    res = grid.resolution_m
    r, c = grid.world_to_cell(*centre)
    normal_rc = (normal_xy[1], normal_xy[0])  # rows run with y, columns with x
    free, occupied, unknown = grid.cells == FREE, grid.cells == OCCUPIED, grid.cells == UNKNOWN
    ev = evidence(free, occupied, (float(r), float(c)), normal_rc, 0.7, res, DEFAULT_PARAMS, unknown)
    return ev.column_jambs, is_door(ev, DEFAULT_PARAMS, into_unknown=False, width_m=0.7)


@pytest.mark.parametrize("angle_deg", [0.0, 17.0, 62.0])
def test_the_gap_between_two_columns_is_no_door(angle_deg: float) -> None:
    grid, centre, normal = floor_with_bodies("column"), GAP_XY, (0.0, 1.0)
    if angle_deg:
        turned, _ = rotate(grid, PointsAnnotation(), angle_deg)
        centre = rotate_point(GAP_XY, map_centre(grid), math.radians(angle_deg))
        a = math.radians(angle_deg)
        grid, normal = turned, (-math.sin(a), math.cos(a))
    columns, door = _judged(grid, centre, normal)
    assert columns
    assert not door


@pytest.mark.parametrize("angle_deg", [0.0, 17.0, 62.0])
def test_a_column_beside_a_walls_end_is_not_two_columns(angle_deg: float) -> None:
    grid, centre, normal = floor_with_bodies("wall"), GAP_XY, (0.0, 1.0)
    if angle_deg:
        turned, _ = rotate(grid, PointsAnnotation(), angle_deg)
        centre = rotate_point(GAP_XY, map_centre(grid), math.radians(angle_deg))
        a = math.radians(angle_deg)
        grid, normal = turned, (-math.sin(a), math.cos(a))
    columns, _door = _judged(grid, centre, normal)
    assert not columns


def test_a_column_is_scanned_solid_and_furniture_is_not() -> None:
    """A solid body standing free is a column; the same body with its inside unscanned (a
    cabinet seen from around it) is furniture; a wall running on is neither."""
    grid = floor_with_bodies("wall")
    free, unknown = grid.cells == FREE, grid.cells == UNKNOWN
    r, c = grid.world_to_cell(GAP_XY[0] + 0.35 + COLUMN_R_M, GAP_XY[1])
    assert is_column(free, unknown, (float(r), float(c)), grid.resolution_m)
    assert not is_furniture(free, unknown, (float(r), float(c)), grid.resolution_m)
    inside = np.zeros_like(free)
    inside[int(r) - 2:int(r) + 3, int(c) - 2:int(c) + 3] = True
    assert is_furniture(free, unknown | inside, (float(r), float(c)), grid.resolution_m)
    rw, cw = grid.world_to_cell(GAP_XY[0] - 1.0, GAP_XY[1])
    assert not is_column(free, unknown, (float(rw), float(cw)), grid.resolution_m)
