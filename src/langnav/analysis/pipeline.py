"""The whole analysis of one grid: spaces and doors, then every other element.

:func:`analyze` runs the space segmentation, then the detectors (unexplored areas, obstacles,
walls, corners, narrow passages), resolves doors that open onto unexplored territory to the
area they open onto, and assigns walls, corners and obstacles to spaces. :class:`AnalysisCache`
keeps recent analyses keyed by the grid's content and the parameters, so the translator and the
web app analyse a map once.
"""

from __future__ import annotations

import dataclasses
import hashlib
import logging
import math
import threading
from collections import OrderedDict
from typing import Final

import numpy as np
import numpy.typing as npt
from scipy import ndimage as ndi

from langnav.analysis.allocator import keep_freed_arrays
from langnav.analysis.corners import find_corners
from langnav.analysis.elements import Door, MapAnalysis, UnexploredArea
from langnav.analysis.obstacles import find_obstacles
from langnav.analysis.params import DEFAULT_PARAMS, AnalysisParams
from langnav.analysis.passages import find_passages
from langnav.analysis.precompute import GridLayers
from langnav.analysis.segmentation import segment_spaces
from langnav.analysis.unexplored import UnexploredResult, find_unexplored
from langnav.analysis.walls import find_walls
from langnav.maps.grid import OccupancyGrid

log = logging.getLogger(__name__)

#: What a door's ``connects`` holds for an opening into unexplored territory (segmentation's word).
UNKNOWN_SIDE: Final = "unknown"
#: Walk this far through a door into unexplored territory to find the area it opens onto
#: (past a strip of free space beyond the wall, as where a scan just peeked out of a door).
DOOR_SIDE_SEARCH_M: Final = 3.0
#: How many analyses the cache keeps (a web session rarely switches between more maps).
DEFAULT_CACHE_SIZE: Final = 8


def analyze(grid: OccupancyGrid, params: AnalysisParams = DEFAULT_PARAMS) -> MapAnalysis:
    """Find every element of ``grid`` (see :mod:`langnav.analysis.elements`)."""
    # Freed grid-sized arrays stay in the process for the next ones (glibc; see the module).
    keep_freed_arrays()
    # Masks and components the segmentation and every detector need, computed once.
    layers = GridLayers(grid)
    seg = segment_spaces(grid, params, layers)
    labels = np.asarray(seg.labels, dtype=np.int32)
    rooms = tuple(seg.rooms)
    room_ids = {r.label: r.id for r in rooms}
    room_labels = {r.id: r.label for r in rooms}
    unx = find_unexplored(grid, params, layers)
    obst = find_obstacles(grid, params, labels, room_ids, exterior=unx.exterior, layers=layers)
    walls = find_walls(grid, params, labels, room_ids, wall=layers.occupied & ~obst.mask, layers=layers)

    corners, walls = find_corners(grid, params, walls, labels, room_labels, layers=layers)

    # Passages: unknown noise specks do not narrow a passage; everything else unknown does.
    blocking = layers.occupied | (layers.unknown & ~unx.specks)
    passages = find_passages(grid, params, labels, room_ids, seg.doors, blocking, layers=layers,
                             unexplored=unx.area_labels > 0)
    doors = tuple(_resolve_door(d, grid, unx) for d in seg.doors)
    return MapAnalysis(grid=grid, params=params, rooms=rooms, doors=doors, walls=walls,
                       corners=corners, obstacles=obst.obstacles, narrow_passages=passages,
                       unexplored=unx.areas, labels=labels, openings=seg.openings)


def _resolve_door(door: Door, grid: OccupancyGrid, unx: UnexploredResult) -> Door:
    """Replace ``"unknown"`` in a door's ``connects`` by the unexplored area it opens onto."""
    if UNKNOWN_SIDE not in door.connects or not unx.areas:
        return door
    side = 1.0 if door.connects[-1] == UNKNOWN_SIDE else -1.0
    area = area_beyond(door, side, grid, unx) or nearest_area(door.center, unx.areas)
    if area is None:
        return door
    connects = tuple(area.id if c == UNKNOWN_SIDE else c for c in door.connects)
    return dataclasses.replace(door, connects=connects)


def area_beyond(door: Door, side: float, grid: OccupancyGrid, unx: UnexploredResult) -> UnexploredArea | None:
    """The first unexplored area met walking from the door's centre along ``side * normal``."""
    step = grid.resolution_m / 2
    for i in range(int(DOOR_SIDE_SEARCH_M / step) + 1):
        x = door.center[0] + side * door.normal[0] * i * step
        y = door.center[1] + side * door.normal[1] * i * step
        r, c = grid.world_to_index(x, y)
        if not grid.in_bounds(r, c):
            break
        k = int(unx.area_labels[int(r), int(c)])
        if k > 0:
            return unx.areas[k - 1]
    return None


def nearest_area(point: tuple[float, float], areas: tuple[UnexploredArea, ...]) -> UnexploredArea | None:
    """The unexplored area whose frontier passes nearest ``point``."""
    best: UnexploredArea | None = None
    best_d = math.inf
    for a in areas:
        if len(a.frontier) == 0:
            continue
        d = float(np.min(np.hypot(a.frontier[:, 0] - point[0], a.frontier[:, 1] - point[1])))
        if d < best_d:
            best, best_d = a, d
    return best


def grid_key(grid: OccupancyGrid) -> str:
    """A content hash of a grid: cells, shape, resolution and origin."""
    h = hashlib.sha1(usedforsecurity=False)
    h.update(np.ascontiguousarray(grid.cells).tobytes())
    h.update(repr((grid.cells.shape, grid.resolution_m, grid.origin_x_m, grid.origin_y_m,
                   grid.origin_yaw_rad)).encode())
    return h.hexdigest()


class AnalysisCache:
    """A small thread-safe LRU of analyses keyed by (grid content hash, params)."""

    def __init__(self, max_entries: int = DEFAULT_CACHE_SIZE) -> None:
        if max_entries < 1:
            raise ValueError(f"max_entries must be at least 1, got {max_entries}")
        self.max_entries = max_entries
        self._items: OrderedDict[tuple[str, AnalysisParams], MapAnalysis] = OrderedDict()
        self._lock = threading.Lock()
        self.hits = 0
        self.misses = 0

    def get(self, grid: OccupancyGrid, params: AnalysisParams = DEFAULT_PARAMS) -> MapAnalysis:
        """The analysis of ``grid`` with ``params``, computed once and then reused."""
        key = (grid_key(grid), params)
        with self._lock:
            hit = self._items.get(key)
            if hit is not None:
                self._items.move_to_end(key)
                self.hits += 1
                return hit
        result = analyze(grid, params)
        with self._lock:
            self.misses += 1
            self._items[key] = result
            self._items.move_to_end(key)
            while len(self._items) > self.max_entries:
                self._items.popitem(last=False)
        return result

    def clear(self) -> None:
        with self._lock:
            self._items.clear()

    def __len__(self) -> int:
        with self._lock:
            return len(self._items)


def labels_for_free_components(grid: OccupancyGrid) -> tuple[npt.NDArray[np.int32], int]:
    """Each 4-connected free region as one space (a stand-in segmentation for detector tests)."""
    lab, n = ndi.label(grid.free)
    return lab.astype(np.int32), int(n)
