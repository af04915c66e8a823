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
from scipy import ndimage as ndi

from langnav.analysis.elements import UnexploredArea
from langnav.analysis.params import AnalysisParams
from langnav.maps.grid import OccupancyGrid

#: 8-connectivity: unknown regions joined at a corner are one region (a scan shadow is rarely 4-clean).
EIGHT: Final = np.ones((3, 3), dtype=bool)
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


def border_labels(lab: npt.NDArray[np.integer]) -> npt.NDArray[np.int64]:
    """Labels (> 0) of the components touching the border of a label image."""
    edge = np.concatenate([lab[0, :], lab[-1, :], lab[:, 0], lab[:, -1]])
    return np.unique(edge[edge > 0]).astype(np.int64)


def exterior_unknown_mask(grid: OccupancyGrid) -> BoolArray:
    """Unknown cells connected (8-neighbours) to the grid border: the world outside the map."""
    lab, _ = ndi.label(grid.unknown, structure=EIGHT)
    return np.isin(lab, border_labels(lab)) & (lab > 0)


def adjacent_pairs(a: npt.NDArray[np.integer], b: npt.NDArray[np.integer]) -> npt.NDArray[np.int64]:
    """Unique (flat index of a cell with a > 0, label b > 0 of one of its 8 neighbours) pairs.

    Returned as an (N, 2) int64 array sorted by cell; vectorised (eight shifted views of the
    window holding both masks' overlap).
    """
    h, w = a.shape
    near = ndi.binary_dilation(b > 0, structure=EIGHT) & (a > 0)
    rows = np.flatnonzero(near.any(axis=1))
    if len(rows) == 0:
        return np.zeros((0, 2), dtype=np.int64)
    cols = np.flatnonzero(near.any(axis=0))
    r0, r1 = max(0, int(rows[0]) - 1), min(h, int(rows[-1]) + 2)
    c0, c1 = max(0, int(cols[0]) - 1), min(w, int(cols[-1]) + 2)
    sub_near = near[r0:r1, c0:c1]
    sub_b = b[r0:r1, c0:c1]
    rr, cc = np.nonzero(sub_near)
    hh, ww = sub_b.shape
    base = int(b.max()) + 1
    codes: list[npt.NDArray[np.int64]] = []
    flat = (rr + r0).astype(np.int64) * w + (cc + c0)
    for dr, dc in NEIGHBOURS_8:
        r2, c2 = rr + dr, cc + dc
        ok = (r2 >= 0) & (r2 < hh) & (c2 >= 0) & (c2 < ww)
        lab = np.zeros(len(rr), dtype=np.int64)
        lab[ok] = sub_b[r2[ok], c2[ok]]
        sel = lab > 0
        codes.append(flat[sel] * base + lab[sel])
    uniq = np.unique(np.concatenate(codes))
    return np.stack([uniq // base, uniq % base], axis=1)


def find_unexplored(grid: OccupancyGrid, params: AnalysisParams) -> UnexploredResult:
    """Every unknown region bordering free space; the outside world (if reached) is one area."""
    unknown = grid.unknown
    free = grid.free
    lab, n = ndi.label(unknown, structure=EIGHT)
    if n == 0:
        none = np.zeros(grid.cells.shape, dtype=bool)
        return UnexploredResult((), np.zeros(grid.cells.shape, dtype=np.int32), none, none)
    sizes = np.bincount(lab.ravel(), minlength=n + 1)
    outside = np.zeros(n + 1, dtype=bool)
    outside[border_labels(lab)] = True
    outside[0] = False
    exterior = outside[lab]
    min_cells = params.unexplored_min_area_m2 / grid.cell_area_m2
    speck_ids = ~outside & (sizes < min_cells)
    speck_ids[0] = False
    specks = speck_ids[lab]
    # (free cell, unknown label) pairs: which regions border free space, and their frontier cells.
    pairs = adjacent_pairs(free.astype(np.int8), lab)
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
    area_labels = area_of[lab]
    area_labels[lab == 0] = 0
    if n_areas == 0:
        return UnexploredResult((), area_labels.astype(np.int32), exterior, specks)

    # Cell statistics per area, vectorised.
    rows, cols = np.nonzero(area_labels)
    ids = area_labels[rows, cols]
    counts = np.bincount(ids, minlength=n_areas + 1).astype(float)
    mean_r = np.bincount(ids, weights=rows, minlength=n_areas + 1) / np.maximum(counts, 1)
    mean_c = np.bincount(ids, weights=cols, minlength=n_areas + 1) / np.maximum(counts, 1)
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
    return UnexploredResult(tuple(areas), area_labels.astype(np.int32), exterior, specks)
