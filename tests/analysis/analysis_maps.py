"""Maps the analysis tests build, with their elements known exactly (world metres)."""

from __future__ import annotations

import math

import numpy as np
from scipy import ndimage as ndi

from langnav.analysis.elements import Door, Room
from langnav.analysis.segmentation import Segmentation
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import OCCUPIED, UNKNOWN, OccupancyGrid

#: Door positions within two cells plus the half-cell of a door's centre.
POS_TOL_M = 0.15


def space_at(seg: Segmentation, grid: OccupancyGrid, x: float, y: float) -> Room:
    """The space holding the world point (x, y) (the test fails if none does)."""
    r, c = grid.world_to_index(x, y)
    room = seg.room_by_label(int(seg.labels[int(r), int(c)]))
    assert room is not None, f"no space at ({x}, {y})"
    return room


def door_near(doors: tuple[Door, ...], x: float, y: float, tol: float = POS_TOL_M) -> Door:
    """The one door within ``tol`` of (x, y) (the test fails if there are none or several)."""
    near = [d for d in doors if math.dist(d.center, (x, y)) <= tol]
    assert len(near) == 1, f"{len(near)} doors near ({x}, {y}): {[d.center for d in doors]}"
    return near[0]



def turned(grid: OccupancyGrid, degrees: float) -> OccupancyGrid:
    """The grid turned by ``degrees`` about its centre, cell by cell (nearest cell; the corners
    it uncovers are unknown): walls become stair-stepped lines, as in a real map at an angle."""
    cells = ndi.rotate(grid.cells.astype(np.int16) + 1, degrees, order=0, reshape=True, cval=0) - 1
    return OccupancyGrid(cells.astype(np.int8), grid.resolution_m, source=f"{grid.source}_turned")


def scan_noise(grid: OccupancyGrid, seed: int = 0) -> OccupancyGrid:
    """Lidar noise: occupied specks on 3 % of the free cells within two cells of a wall, unknown
    specks on 0.2 % of the free cells, and 5 % of the wall cells dropped out (free)."""
    rng = np.random.default_rng(seed)
    c = grid.cells.copy()
    free, occ = c == 0, c == OCCUPIED
    near_wall = ndi.binary_dilation(occ, iterations=2) & free
    c[near_wall & (rng.random(c.shape) < 0.03)] = OCCUPIED
    c[free & (rng.random(c.shape) < 0.002)] = UNKNOWN
    c[occ & (rng.random(c.shape) < 0.05)] = 0
    return OccupancyGrid(c, grid.resolution_m, source=f"{grid.source}_noisy")


def room_with_door() -> OccupancyGrid:
    """A 4 x 3 m room, door 0.9 m wide in the east wall at y = 1.5 onto the unknown outside,
    a 0.5 x 0.4 m box, a 1 x 1 m unscanned patch in the north-west corner and a noise speck."""
    b = MapBuilder(6.0, 5.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 4.0, 3.0)
    b.door_v(4.075, 1.5, 0.9)
    b.box(1.0, 1.0, 1.5, 1.4)
    b.unknown(0.0, 2.0, 1.0, 3.0)
    b.unknown(2.5, 0.5, 2.55, 0.55)  # one unknown cell: a speck, not an area
    return b.build(source="room_with_door")


def l_room() -> OccupancyGrid:
    """An L-shaped room: (0..4, 0..2) and (0..2, 2..4), closed, walls 0.15 m."""
    b = MapBuilder(6.0, 6.0, origin=(-1.0, -1.0))
    b.rect(-0.15, -0.15, 4.15, 2.15, OCCUPIED).rect(-0.15, -0.15, 2.15, 4.15, OCCUPIED)
    b.free(0.0, 0.0, 4.0, 2.0).free(0.0, 0.0, 2.0, 4.0)
    return b.build(source="l_room")


def corridor_with_side_passage() -> OccupancyGrid:
    """A 10 x 1.6 m corridor; from its middle a 0.7 m wide, 2 m long passage leads north into
    a 3 x 2.4 m room."""
    b = MapBuilder(12.0, 8.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 10.0, 1.6)
    b.room(3.5, 3.6, 6.5, 6.0)
    b.rect(4.3, 1.6, 5.7, 3.6, OCCUPIED)
    b.free(4.65, 1.5, 5.35, 3.7)
    return b.build(source="corridor_with_side_passage")


def two_rooms_partition() -> OccupancyGrid:
    """Two 3 x 3 m rooms side by side; the partition between them is a free-standing wall piece
    (doors at both of its ends), plus a 0.6 x 0.6 m box in the west room."""
    b = MapBuilder(8.0, 5.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 6.15, 3.0)
    b.wall(3.075, 0.0, 3.075, 3.0)
    b.door_v(3.075, 0.45, 0.9, depth_m=0.2).door_v(3.075, 2.55, 0.9, depth_m=0.2)
    b.box(1.0, 1.2, 1.6, 1.8)
    b.rect(5.0, 2.0, 5.05, 2.05, OCCUPIED)  # one occupied cell: noise, not an obstacle
    return b.build(source="two_rooms_partition")


def room_beside_corridor(exit_door: bool = True) -> OccupancyGrid:
    """A 5 x 4.5 m room and, east of it across one wall, a 1.3 m wide corridor of the same length:
    a 1.0 m door between them at y = 1.5, and (``exit_door``) a 0.8 m door in the corridor's
    short south wall onto the unknown outside (that wall is then mostly doorway)."""
    b = MapBuilder(9.0, 7.0, origin=(-1.0, -1.5))
    b.room(0.0, 0.0, 5.0, 4.5)
    b.room(5.15, 0.0, 6.45, 4.5)
    b.door_v(5.075, 1.5, 1.0)
    if exit_door:
        b.door_h(5.8, -0.075, 0.8)
    return b.build(source="room_beside_corridor")


def door_beside_corner() -> OccupancyGrid:
    """A 5 x 4 m room whose 0.9 m north door is flush with its west wall (no jamb between them),
    opening into a 5 x 2 m room north of it; a 1.2 x 1.0 m unscanned patch covers the south-east
    corner of the first room."""
    b = MapBuilder(7.0, 8.5, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 5.0, 4.0)
    b.room(0.0, 4.15, 5.0, 6.15)
    b.door_h(0.45, 4.075, 0.9)
    b.unknown(3.8, 0.0, 5.0, 1.0)
    return b.build(source="door_beside_corner")


def l_room_and_closed_room() -> OccupancyGrid:
    """The L-shaped room of :func:`l_room` with its notch (2.15..4, 2.15..4) a closed room of its
    own: the L's walls lines cross in that room, which is no corner of the L."""
    b = MapBuilder(6.0, 6.0, origin=(-1.0, -1.0))
    b.rect(-0.15, -0.15, 4.15, 4.15, OCCUPIED)
    b.free(0.0, 0.0, 4.0, 2.0).free(0.0, 0.0, 2.0, 4.0)
    b.free(2.15, 2.15, 4.0, 4.0)
    return b.build(source="l_room_and_closed_room")


def shelf_off_wall(gap_m: float = 0.7, shelf_length_m: float = 3.0) -> OccupancyGrid:
    """A 6 x 5 m room with a door; a 0.3 m deep shelf ``shelf_length_m`` long stands ``gap_m`` off
    its west wall (x = 0), from y = 1.0: the strip between them is a narrow passage when it is
    narrow and long enough."""
    b = MapBuilder(8.0, 7.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 6.0, 5.0)
    b.door_v(6.075, 2.5, 0.9)
    b.box(gap_m, 1.0, gap_m + 0.3, 1.0 + shelf_length_m)
    return b.build(source="shelf_off_wall")
