"""Obstacles: occupied clusters apart from the building's wall structure.

Occupied cells are grouped into 8-connected components. A component is *wall structure* when
it is the largest one, touches the grid border or the unknown world outside the building, or
bounds two or more different spaces (a partition between rooms, a wall stub between doors).
Every other component at least ``params.obstacle_min_area_m2`` large is an obstacle: furniture,
a box, a pillar standing in one space. Its area counts unknown cells it encloses (a SLAM map
often sees only the outline of a piece of furniture).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from langnav.analysis.elements import Obstacle
from langnav.analysis.params import AnalysisParams
from langnav.analysis.precompute import (
    GridLayers,
    border_labels,
    component_boxes,
    dilate8,
    divmod_int,
    fill_holes,
)
from langnav.analysis.unexplored import adjacent_pairs
from langnav.maps.grid import OccupancyGrid

BoolArray = npt.NDArray[np.bool_]


@dataclass(frozen=True, eq=False)
class ObstacleResult:
    """The obstacles and a mask (grid orientation) of their occupied cells."""

    obstacles: tuple[Obstacle, ...]
    mask: BoolArray


def find_obstacles(grid: OccupancyGrid, params: AnalysisParams, labels: npt.NDArray[np.int32],
                   room_ids: Mapping[int, str], exterior: BoolArray | None = None,
                   layers: GridLayers | None = None) -> ObstacleResult:
    """Occupied clusters that are not part of the walls, with the space that holds each.

    ``labels`` are space labels (grid orientation, 0 = none); ``room_ids`` maps label -> id.
    ``exterior`` is the outside-world unknown mask (computed when not given); ``layers`` the
    grid's shared masks and components (built when not given).
    """
    layers = layers or GridLayers(grid)
    occ_comps = layers.occupied_components
    comp, n, sizes = occ_comps.labels, occ_comps.n, occ_comps.sizes
    empty = ObstacleResult((), np.zeros(comp.shape, dtype=bool))
    if n == 0:
        return empty
    structural = np.zeros(n + 1, dtype=bool)
    structural[int(np.argmax(sizes))] = True
    structural[border_labels(comp)] = True
    if exterior is None:
        exterior = layers.exterior
    # Components touching the outside world: those with a cell next to (8-neighbours) it.
    occ_flat = layers.occupied_flat
    occ_comp = comp.ravel()[occ_flat]
    structural[occ_comp[dilate8(exterior).ravel()[occ_flat]]] = True
    # Which space labels each component borders: (space cell, component) pairs -> (comp, label).
    lab_pairs = adjacent_pairs(labels, comp)
    space_of_pair = labels.ravel()[lab_pairs[:, 0]].astype(np.int64)
    base = int(labels.max()) + 1
    # Most-bordered space per component (by the number of neighbouring cells), and how many
    # different spaces each borders.
    codes, counts = np.unique(lab_pairs[:, 1] * base + space_of_pair, return_counts=True)
    n_spaces = np.bincount(codes // base, minlength=n + 1)
    structural[n_spaces >= 2] = True
    best_space = np.zeros(n + 1, dtype=np.int64)
    # Sort by count so that, per component, the most frequent space is written last.
    by_count = np.argsort(counts, kind="stable")
    best_space[codes[by_count] // base] = codes[by_count] % base

    min_cells = params.obstacle_min_area_m2 / grid.cell_area_m2
    candidates = np.flatnonzero(~structural & (sizes >= min_cells))
    candidates = candidates[candidates > 0]
    if len(candidates) == 0:
        return empty
    is_candidate = np.zeros(n + 1, dtype=bool)
    is_candidate[candidates] = True
    # The candidates' cells, from the (few) occupied cells: grouped by candidate, each group in
    # raster order, with their world centres computed at once.
    of_candidate = is_candidate[occ_comp]
    cand_flat, cand_comp = occ_flat[of_candidate], occ_comp[of_candidate]
    mask = np.zeros(comp.shape, dtype=bool)
    mask.ravel()[cand_flat] = True
    by_cand = np.argsort(cand_comp, kind="stable")
    cand_flat, cand_comp = cand_flat[by_cand], cand_comp[by_cand]
    cand_r, cand_c = divmod_int(cand_flat, comp.shape[1])
    slices = component_boxes(cand_comp, cand_r, cand_c, candidates)
    cand_x, cand_y = grid.cell_to_world(cand_r, cand_c)
    bounds = np.searchsorted(cand_comp, np.append(candidates, n + 1))
    res = grid.resolution_m
    obstacles: list[Obstacle] = []
    for k, c in enumerate(candidates.tolist(), start=1):
        sl = slices[c]
        oxs, oys = cand_x[bounds[k - 1]:bounds[k]], cand_y[bounds[k - 1]:bounds[k]]
        xs, ys = oxs, oys
        # A hole needs a ring round it: nothing to fill in a box less than 3 cells across.
        if min(sl[0].stop - sl[0].start, sl[1].stop - sl[1].start) >= 3:
            own = comp[sl] == c
            filled = fill_holes(own)
            if np.count_nonzero(filled) > len(oxs):
                rr, cc = np.nonzero(filled)
                xs, ys = grid.cell_to_world(rr + sl[0].start, cc + sl[1].start)
        # Extent: bounding box of the cell squares in the map frame (cells are res wide).
        extent = ((float(xs.max() - xs.min()) + res), (float(ys.max() - ys.min()) + res))
        space = int(best_space[c])
        obstacles.append(Obstacle(
            id=f"obstacle_{k}",
            centroid=(float(xs.mean()), float(ys.mean())),
            area_m2=float(len(xs) * grid.cell_area_m2),
            extent_m=extent,
            room=room_ids.get(space) if space > 0 else None,
            cells_xy=np.stack([oxs, oys], axis=1),
        ))
    return ObstacleResult(tuple(obstacles), mask)

