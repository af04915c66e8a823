"""A hand-built world for grounding tests: a built grid and a MapAnalysis written by hand,
so grounding is tested apart from the map analysis.

    y=7 +---------------------+---------------------+
        |  A (room_a)         |           ?unknown? |
        |  [box]              D2 (6.075,5.0)         |
        |                     |                     |
        |  robot starts here  D1 (6.075,2.0)   B    |
    y=1 +---------------------+---------------------+
       x=1                   x=6.075               x=11
"""

from __future__ import annotations

import numpy as np
import pytest

from langnav.analysis.elements import (
    Corner,
    Door,
    ElementKind,
    MapAnalysis,
    Obstacle,
    Room,
    UnexploredArea,
    Wall,
)
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import FREE, OccupancyGrid


def _cells_xy(grid: OccupancyGrid, mask: np.ndarray) -> np.ndarray:
    rr, cc = np.nonzero(mask)
    xs, ys = grid.cell_to_world(rr, cc)
    return np.column_stack([xs, ys])


def build_two_rooms() -> MapAnalysis:
    b = MapBuilder(12.0, 8.0)
    b.room(1.0, 1.0, 11.0, 7.0)
    b.wall(6.075, 1.0, 6.075, 7.0)
    b.door_v(6.075, 2.0, 0.9)
    b.door_v(6.075, 5.0, 0.9)
    b.box(2.0, 5.0, 2.6, 5.6)
    b.unknown(9.0, 5.5, 11.0, 7.0)
    grid = b.build("two_rooms")
    rows, cols = np.indices(grid.cells.shape)
    xs, ys = grid.cell_to_world(rows, cols)
    inside = (ys > 1.0) & (ys < 7.0)
    labels = np.zeros(grid.cells.shape, np.int32)
    labels[(grid.cells == FREE) & inside & (xs > 1.0) & (xs < 6.0)] = 1
    labels[(grid.cells != 100) & inside & (xs > 6.15) & (xs < 11.0)] = 2
    room_a = Room("room_a", 1, ElementKind.ROOM, 30.0, 29.6, (3.5, 4.0), 6.0, 5.0,
                  _cells_xy(grid, (labels == 1) & (grid.cells == FREE)), np.zeros((0, 2)))
    room_b = Room("room_b", 2, ElementKind.ROOM, 29.1, 26.1, (8.3, 3.7), 6.0, 4.85,
                  _cells_xy(grid, (labels == 2) & (grid.cells == FREE)), np.zeros((0, 2)))
    d1 = Door("door_1", (6.075, 2.0), 0.9, ((6.075, 1.55), (6.075, 2.45)), (1.0, 0.0), ("room_a", "room_b"))
    d2 = Door("door_2", (6.075, 5.0), 0.9, ((6.075, 4.55), (6.075, 5.45)), (1.0, 0.0), ("room_a", "room_b"))
    walls = (
        Wall("w_a_s", (1.0, 1.0), (6.0, 1.0), "room_a", (0.0, 1.0)),
        Wall("w_a_n", (1.0, 7.0), (6.0, 7.0), "room_a", (0.0, -1.0)),
        Wall("w_a_w", (1.0, 1.0), (1.0, 7.0), "room_a", (1.0, 0.0)),
        Wall("w_a_e1", (6.0, 1.0), (6.0, 1.55), "room_a", (-1.0, 0.0)),
        Wall("w_a_e2", (6.0, 2.45), (6.0, 4.55), "room_a", (-1.0, 0.0)),
        Wall("w_a_e3", (6.0, 5.45), (6.0, 7.0), "room_a", (-1.0, 0.0)),
        Wall("w_b_s", (6.15, 1.0), (11.0, 1.0), "room_b", (0.0, 1.0)),
        Wall("w_b_e", (11.0, 1.0), (11.0, 5.5), "room_b", (-1.0, 0.0)),
    )
    corners = (
        Corner("c_a_sw", (1.0, 1.0), "room_a", ("w_a_s", "w_a_w"), (1.4, 1.4)),
        Corner("c_a_se", (6.0, 1.0), "room_a", ("w_a_s", "w_a_e1"), (5.6, 1.4)),
        Corner("c_a_ne", (6.0, 7.0), "room_a", ("w_a_n", "w_a_e3"), (5.6, 6.6)),
        Corner("c_a_nw", (1.0, 7.0), "room_a", ("w_a_n", "w_a_w"), (1.4, 6.6)),
        Corner("c_b_sw", (6.15, 1.0), "room_b", ("w_b_s", "w_b_w"), (6.55, 1.4)),
        Corner("c_b_se", (11.0, 1.0), "room_b", ("w_b_s", "w_b_e"), (10.6, 1.4)),
    )
    box_mask = (xs > 2.0) & (xs < 2.6) & (ys > 5.0) & (ys < 5.6)
    box = Obstacle("obstacle_1", (2.3, 5.3), 0.36, (0.6, 0.6), "room_a", _cells_xy(grid, box_mask))
    unk_mask = (xs > 9.0) & (xs < 11.0) & (ys > 5.5) & (ys < 7.0)
    frontier = _cells_xy(grid, (grid.cells == FREE) & (
        ((xs > 9.0) & (xs < 11.0) & (ys > 5.45) & (ys < 5.5)) | ((xs > 8.95) & (xs < 9.0) & (ys > 5.5) & (ys < 7.0))))
    unexplored = UnexploredArea("unexplored_1", (10.0, 6.25), 3.0, frontier, True)
    assert unk_mask.any() and len(frontier) > 10
    return MapAnalysis(grid, DEFAULT_PARAMS, (room_a, room_b), (d1, d2), walls, corners, (box,), (),
                       (unexplored,), labels)


@pytest.fixture(scope="session")
def two_rooms() -> MapAnalysis:
    return build_two_rooms()
