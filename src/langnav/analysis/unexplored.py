"""Unexplored areas: connected unknown regions that border free space, with their frontier.

The unknown world outside the building (every unknown region touching the grid border) is one
area, ``interior=False``, and counts only where an opening leads into it (it borders free space).
Unknown specks smaller than ``params.unexplored_min_area_m2`` are scanner noise, not areas, and
unknown cells inside a wall (touching no free cell) are not areas either.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Final

import numpy as np
import numpy.typing as npt

from langnav.analysis.elements import UnexploredArea
from langnav.analysis.params import AnalysisParams
from langnav.analysis.precompute import EIGHT, GridLayers, border_labels, dilate8, nonzero2
from langnav.maps.grid import OccupancyGrid

__all__ = ["EIGHT", "NEIGHBOURS_8", "UnexploredResult", "adjacent_pairs", "border_labels",
           "exterior_unknown_mask", "find_unexplored"]

#: The eight neighbour offsets (d_row, d_col).
NEIGHBOURS_8: Final = ((-1, -1), (-1, 0), (-1, 1), (0, -1), (0, 1), (1, -1), (1, 0), (1, 1))

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

    # Map component label -> area index (1-based); all outside components share one index.
    area_of = np.zeros(n + 1, dtype=np.int32)
    interior_ids = np.flatnonzero(touches & ~outside & (sizes >= min_cells))
    interior_ids = interior_ids[interior_ids > 0]
    area_of[interior_ids] = np.arange(1, len(interior_ids) + 1, dtype=np.int32)
    has_outside = bool((touches & outside).any())
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
