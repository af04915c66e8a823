"""Unexplored areas: the unknown regions a person would send the robot to look at, with their frontier.

The unknown world outside the building (every unknown region touching the grid border) is one
area, ``interior=False``, and counts only where an opening the robot can reach leads into it.
An unknown region inside the map is an area when it is worth a trip: at least
``params.unexplored_worth_area_m2`` large, ``params.unexplored_min_width_m`` wide (room to drive in
and turn: not a shelf's or a rack's unknown inside, however long), not a thing the robot scanned
all round (free floor on every side and narrower than ``params.unexplored_enclosed_max_width_m``:
a group of desks, a glass table), with at least ``params.unexplored_min_frontier_m`` of
frontier the robot can come up to in one opening (a door, a room's open side: not the gaps in the
scanned outline of a shelf, a cabinet or a pallet whose inside is unknown, nor laser holes).
Unknown specks smaller than
``params.unexplored_min_area_m2`` are scanner noise (navigable for clearance purposes); unknown
cells inside a wall (touching no free cell) and the other pockets are no areas.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Final

import numpy as np
import numpy.typing as npt
from scipy import ndimage as ndi

from langnav.analysis.elements import UnexploredArea
from langnav.analysis.params import AnalysisParams
from langnav.analysis.precompute import (
    EIGHT,
    GridLayers,
    border_labels,
    component_boxes,
    dilate8,
    label8_cells,
    nonzero2,
    truncated_sq_edt,
)
from langnav.maps.grid import OccupancyGrid

__all__ = ["EIGHT", "NEIGHBOURS_8", "UnexploredResult", "adjacent_pairs", "border_labels",
           "exterior_unknown_mask", "find_unexplored"]

#: The eight neighbour offsets (d_row, d_col).
NEIGHBOURS_8: Final = ((-1, -1), (-1, 0), (-1, 1), (0, -1), (0, 1), (1, -1), (1, 0), (1, 1))

#: The outside world's frontier is tested this many cells at a time (consecutive cells: a band
#: of rows, a small window) until enough of it is within the robot's reach.
OUTSIDE_CHUNK_CELLS: Final = 2000

BoolArray = npt.NDArray[np.bool_]
IntArray = npt.NDArray[np.int32]


@dataclass(frozen=True, eq=False)
class UnexploredResult:
    """The areas found and an int32 grid (grid orientation): k = ``areas[k - 1]``, 0 = none.

    ``exterior`` marks the unknown world outside the map (unknown connected to the grid border);
    ``specks`` the unknown noise specks that are not areas (navigable for clearance purposes).
    """

    areas: tuple[UnexploredArea, ...]
    area_labels: IntArray
    exterior: BoolArray
    specks: BoolArray


def exterior_unknown_mask(grid: OccupancyGrid, layers: GridLayers | None = None) -> BoolArray:
    """Unknown cells connected (8-neighbours) to the grid border: the world outside the map."""
    return (layers or GridLayers(grid)).exterior


def adjacent_pairs(a: npt.NDArray[np.integer] | BoolArray, b: npt.NDArray[np.integer]) -> npt.NDArray[np.int64]:
    """Unique (flat index of a cell with a > 0, label b > 0 of one of its 8 neighbours) pairs.

    Returned as an (N, 2) int64 array sorted by cell, then by label; vectorised: the eight
    neighbour labels of each candidate cell are gathered at once and deduplicated per cell by
    sorting the eight.
    """
    h, w = a.shape
    near = dilate8(b > 0)
    near &= a.astype(bool, copy=False) if a.dtype == np.bool_ else (a > 0)
    flat = np.flatnonzero(near).astype(np.int64, copy=False)
    if len(flat) == 0:
        return np.zeros((0, 2), dtype=np.int64)
    rr, cc = np.divmod(flat, w)
    b_flat = b.ravel()
    # Neighbour labels by flat offset; "clip" keeps the index in the array, and the cells on the
    # grid's edge, whose offsets wrap round or fall off, are put right below.
    nb = np.stack([b_flat.take(flat + (dr * w + dc), mode="clip") for dr, dc in NEIGHBOURS_8], axis=1)
    edge = np.flatnonzero((rr == 0) | (rr == h - 1) | (cc == 0) | (cc == w - 1))
    if len(edge):
        for j, (dr, dc) in enumerate(NEIGHBOURS_8):
            r2, c2 = rr[edge] + dr, cc[edge] + dc
            nb[edge[(r2 < 0) | (r2 >= h) | (c2 < 0) | (c2 >= w)], j] = 0
    nb.sort(axis=1)
    keep = nb > 0
    keep[:, 1:] &= nb[:, 1:] != nb[:, :-1]
    cells = np.broadcast_to(flat[:, None], nb.shape)[keep]
    return np.stack([cells, nb[keep].astype(np.int64)], axis=1)


def find_unexplored(grid: OccupancyGrid, params: AnalysisParams, layers: GridLayers | None = None
                     ) -> UnexploredResult:
    """Every unknown region bordering free space; the outside world (if reached) is one area.

    ``layers`` are the grid's shared masks and components (built when not given).
    """
    layers = layers or GridLayers(grid)
    comps = layers.unknown_components
    lab, n, sizes = comps.labels, comps.n, comps.sizes
    if n == 0:
        none = np.zeros(grid.cells.shape, dtype=bool)
        return UnexploredResult((), np.zeros(grid.cells.shape, dtype=np.int32), none, none)
    outside = layers.unknown_outside
    exterior = layers.exterior
    min_cells = params.unexplored_min_area_m2 / grid.cell_area_m2
    speck_ids = ~outside & (sizes < min_cells)
    speck_ids[0] = False
    specks = speck_ids[lab]
    # (free cell, unknown label) pairs: which regions border free space, and their frontier cells.
    pairs = adjacent_pairs(layers.free, lab)
    touches = np.zeros(n + 1, dtype=bool)
    touches[pairs[:, 1]] = True
    worth = _worth_a_trip(grid, params, layers, lab, n, sizes, pairs)

    # Map component label -> area index (1-based); all outside components share one index.
    area_of = np.zeros(n + 1, dtype=np.int32)
    interior_ids = np.flatnonzero(touches & ~outside & (sizes >= min_cells) & worth)
    interior_ids = interior_ids[interior_ids > 0]
    area_of[interior_ids] = np.arange(1, len(interior_ids) + 1, dtype=np.int32)
    has_outside = bool((touches & outside & worth).any())
    if has_outside:
        area_of[outside] = len(interior_ids) + 1
    n_areas = len(interior_ids) + int(has_outside)
    area_labels = area_of[lab]  # area_of[0] == 0: no area off the unknown cells
    if n_areas == 0:
        return UnexploredResult((), area_labels, exterior, specks)

    # Cell statistics per area: counts and row / column sums, as exact integers. Interior areas
    # from their own cells; the outside one (most of a real map's unknown margin) from the
    # exterior mask's row and column counts, without listing its cells.
    counts_i = np.bincount(area_of, weights=sizes, minlength=n_areas + 1)
    rows, cols = nonzero2((area_labels > 0) & ~exterior)
    ids = area_labels[rows, cols]
    sum_r = np.bincount(ids, weights=rows, minlength=n_areas + 1)
    sum_c = np.bincount(ids, weights=cols, minlength=n_areas + 1)
    if has_outside:
        sum_r[n_areas] = float(np.count_nonzero(exterior, axis=1) @ np.arange(grid.height, dtype=np.int64))
        sum_c[n_areas] = float(np.count_nonzero(exterior, axis=0) @ np.arange(grid.width, dtype=np.int64))
    counts = counts_i.astype(float)
    mean_r = sum_r / np.maximum(counts, 1)
    mean_c = sum_c / np.maximum(counts, 1)
    cx, cy = grid.cell_to_world(mean_r, mean_c)

    fr_area = area_of[pairs[:, 1]]
    keep = fr_area > 0
    fr_cells = pairs[keep, 0]
    fr_area = fr_area[keep]
    # One frontier cell may touch an area through several neighbours: unique (area, cell).
    fr_codes = np.unique(fr_area.astype(np.int64) * (grid.width * grid.height) + fr_cells)
    fr = np.stack([fr_codes // (grid.width * grid.height), fr_codes % (grid.width * grid.height)], axis=1)
    fr_r, fr_c = np.divmod(fr[:, 1], grid.width)
    fx, fy = grid.cell_to_world(fr_r, fr_c)
    order = np.argsort(fr[:, 0], kind="stable")
    splits = np.searchsorted(fr[order, 0], np.arange(1, n_areas + 2))

    areas: list[UnexploredArea] = []
    for k in range(1, n_areas + 1):
        sel = order[splits[k - 1]:splits[k]]
        frontier = np.stack([fx[sel], fy[sel]], axis=1) if len(sel) else np.zeros((0, 2))
        areas.append(UnexploredArea(
            id=f"unexplored_{k}",
            centroid=(float(cx[k]), float(cy[k])),
            area_m2=float(counts[k] * grid.cell_area_m2),
            frontier=frontier,
            interior=not (has_outside and k == n_areas),
        ))
    return UnexploredResult(tuple(areas), area_labels, exterior, specks)


def _worth_a_trip(grid: OccupancyGrid, params: AnalysisParams, layers: GridLayers, lab: IntArray, n: int,
                  sizes: npt.NDArray[np.int64], pairs: npt.NDArray[np.int64]) -> BoolArray:
    """Per unknown component (index = label): would a person send the robot to look at it? For
    the outside world (all its components together): does the robot reach enough of its
    frontier? For a region inside the map: big enough, and seen through an opening the robot
    can reach rather than through gaps in a scanned outline (see the module docstring)."""
    outside = layers.unknown_outside
    inside = ~outside
    inside[0] = False
    candidate = np.zeros(n + 1, dtype=bool)
    candidate[inside] = sizes[inside] * grid.cell_area_m2 >= params.unexplored_worth_area_m2
    candidate &= _wide_enough(grid, params, layers, lab, candidate)
    candidate &= ~_seen_all_round(grid, params, layers, lab, candidate)
    res = grid.resolution_m
    need = math.ceil(params.unexplored_min_frontier_m / res - 1e-9)
    worth = np.zeros(n + 1, dtype=bool)
    # The outside world: enough of its frontier (all its pieces together) within reach, tested
    # in chunks of consecutive cells (a band of rows each, a small window) until enough.
    # Frontier cells that see the region across an edge (4-neighbours), not only through the
    # corner between two occupied cells of a diagonal outline, which no scan passes.
    pairs = pairs[_edge_adjacent(lab, pairs)]
    out_cells = pairs[outside[pairs[:, 1]], 0]
    found = 0
    for k in range(0, len(out_cells), OUTSIDE_CHUNK_CELLS):
        found += int(np.count_nonzero(_robot_reaches(grid, params, layers, out_cells[k:k + OUTSIDE_CHUNK_CELLS])))
        if found >= need:
            worth[outside] = True
            break
    # A region inside the map: one opening (a connected run of its frontier) the robot can come
    # up to along at least unexplored_min_frontier_m (a door, a room's open side; not the gaps
    # in a shelf's scanned outline, nor laser holes).
    sel = candidate[pairs[:, 1]]
    if sel.any():
        cells, regions = pairs[sel, 0], pairs[sel, 1]
        reach = _robot_reaches(grid, params, layers, cells)
        uniq, inverse = np.unique(cells, return_inverse=True)
        run, n_runs = label8_cells(uniq, (grid.height, grid.width))
        per_run = np.bincount(run[inverse], weights=reach, minlength=n_runs + 1)
        best = np.zeros(n + 1)
        np.maximum.at(best, regions, per_run[run[inverse]])
        worth |= candidate & (best >= need)
    return worth


def _seen_all_round(grid: OccupancyGrid, params: AnalysisParams, layers: GridLayers, lab: IntArray,
                    candidate: BoolArray) -> BoolArray:
    """Per unknown component (index = label; only ``candidate`` ones tested): did the robot's scans
    go all round it? It touches no wall (every occupied piece beside it is no bigger than a piece
    of furniture, ``params.seg_island_max_area_m2``: scanned legs and edges), so free floor
    surrounds it, and it is narrower than ``params.unexplored_enclosed_max_width_m``, so a lidar
    on that floor would have seen into it had nothing stood in the way: it is a thing (a group of
    desks, a glass table, a plant), and sending the robot there shows nothing more."""
    out = np.zeros(len(candidate), dtype=bool)
    if not candidate.any():
        return out
    occ = layers.occupied_components
    island = params.seg_island_max_area_m2 / grid.cell_area_m2
    # (unknown cell of a candidate, occupied piece beside it): a candidate beside a bigger piece
    # touches a wall.
    pairs = adjacent_pairs(candidate[lab], occ.labels)
    walled = np.zeros(len(candidate), dtype=bool)
    if len(pairs):
        walled[lab.ravel()[pairs[occ.sizes[pairs[:, 1]] > island, 0]]] = True
    ids = np.flatnonzero(candidate & ~walled)
    if len(ids) == 0:
        return out
    rows, cols = nonzero2(np.isin(lab, ids))
    boxes = component_boxes(lab[rows, cols], rows, cols, ids)
    res = grid.resolution_m
    # The disc's centre this far (cells, centre to centre) from every cell outside the region.
    need = (params.unexplored_enclosed_max_width_m / res + 1.0) / 2.0
    side = 2 * math.ceil(need) + 1
    for k in ids.tolist():
        sr, sc = boxes[k]
        if min(sr.stop - sr.start, sc.stop - sc.start) < 2.0 * need - 1.0:
            out[k] = True  # too narrow a box to hold the disc
            continue
        own = np.pad(lab[sr, sc] == k, 1)
        # A square that holds the disc (two separable passes), else the disc itself.
        square = own
        for axis in (0, 1):
            square = ndi.minimum_filter1d(square, side, axis=axis, mode="constant", cval=False)
        out[k] = not (square.any() or float(ndi.distance_transform_edt(own).max()) >= need)
    return out


def _wide_enough(grid: OccupancyGrid, params: AnalysisParams, layers: GridLayers, lab: IntArray,
                 candidate: BoolArray) -> BoolArray:
    """Per unknown component (index = label; only ``candidate`` ones tested, others False): does
    it hold a disc ``params.unexplored_min_width_m`` wide, within the unknown cells and the free
    cells around them that the robot does not fit in (laser rays across an unscanned room, the
    specks of free in a shelf's outline): room for the robot to drive in and turn?"""
    out = np.zeros(len(candidate), dtype=bool)
    ids = np.flatnonzero(candidate)
    if len(ids) == 0:
        return out
    rows, cols = nonzero2(np.isin(lab, ids))
    boxes = component_boxes(lab[rows, cols], rows, cols, ids)
    res = grid.resolution_m
    # The disc's centre lies this far (cells, centre to centre) from everything else: half its
    # width plus half a cell (a width counts whole cells, distances run between centres).
    need = (params.unexplored_min_width_m / res + 1.0) / 2.0
    reach = math.ceil(need) + 1
    half = max(1, math.ceil(params.robot_radius_m / res))
    pad = reach + 2 * half + 1
    for k in ids.tolist():
        sr, sc = boxes[k]
        r0, r1 = max(0, sr.start - pad), min(grid.height, sr.stop + pad)
        c0, c1 = max(0, sc.start - pad), min(grid.width, sc.stop + pad)
        own = lab[r0:r1, c0:c1] == k
        # The region alone first (a room behind a door is wide by itself): a square that holds
        # the disc (two separable passes, cheap on a large region), else the disc itself; then
        # with the free cells about it that the robot's footprint (a free square of its
        # diameter) never covers.
        square = own
        for axis in (0, 1):
            square = ndi.minimum_filter1d(square, 2 * math.ceil(need) + 1, axis=axis, mode="constant", cval=False)
        if square.any() or int(truncated_sq_edt(own, reach)[own].max()) >= need * need:
            out[k] = True
            continue
        free = layers.free[r0:r1, c0:c1]
        fits = free
        for axis in (0, 1):
            fits = ndi.minimum_filter1d(fits, 2 * half + 1, axis=axis, mode="constant", cval=False)
        for axis in (0, 1):
            fits = ndi.maximum_filter1d(fits, 2 * half + 1, axis=axis, mode="constant", cval=False)
        region = layers.unknown[r0:r1, c0:c1] | (free & ~fits)
        out[k] = int(truncated_sq_edt(region, reach)[own].max()) >= need * need
    return out


def _edge_adjacent(lab: IntArray, pairs: npt.NDArray[np.int64]) -> BoolArray:
    """Per (cell, label) pair: has the cell a 4-neighbour of that label?"""
    h, w = lab.shape
    flat = lab.ravel()
    rr, cc = np.divmod(pairs[:, 0], w)
    out = np.zeros(len(pairs), dtype=bool)
    for dr, dc in ((-1, 0), (1, 0), (0, -1), (0, 1)):
        r2, c2 = rr + dr, cc + dc
        ok = (r2 >= 0) & (r2 < h) & (c2 >= 0) & (c2 < w)
        out[ok] |= flat[r2[ok] * w + c2[ok]] == pairs[ok, 1]
    return out


def _robot_reaches(grid: OccupancyGrid, params: AnalysisParams, layers: GridLayers,
                   cells: npt.NDArray[np.int64]) -> BoolArray:
    """Per free cell (flat index): can the robot come up to it, i.e. does it touch (8-neighbours)
    a cell that the robot's footprint covers somewhere, the footprint a free square of a robot's
    diameter (it holds the robot's disc: a slightly strict test)?"""
    out = np.zeros(len(cells), dtype=bool)
    if len(cells) == 0:
        return out
    half = max(1, math.ceil(params.robot_radius_m / grid.resolution_m))
    near = half + 1
    rr, cc = np.divmod(cells, grid.width)
    # Over the window that the tests read (its edge blocks): where the robot's centre fits (the
    # free cells eroded by the square), then the cells within ``near`` of those (the footprint
    # and its neighbours), by separable minimum and maximum filters.
    pad = near + half
    r0, r1 = max(0, int(rr.min()) - pad), min(grid.height, int(rr.max()) + pad + 1)
    c0, c1 = max(0, int(cc.min()) - pad), min(grid.width, int(cc.max()) + pad + 1)
    m = layers.free[r0:r1, c0:c1]
    for axis in (0, 1):
        m = ndi.minimum_filter1d(m, 2 * half + 1, axis=axis, mode="constant", cval=False)
    for axis in (0, 1):
        m = ndi.maximum_filter1d(m, 2 * near + 1, axis=axis, mode="constant", cval=False)
    return np.asarray(m[rr - r0, cc - c0], dtype=bool)
