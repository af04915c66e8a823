"""Unexplored areas: the unknown regions a person would send the robot to look at, with their frontier.

Where the robot can reach is judged from the floor it drove on (:func:`reachable_floor`): the
largest connected region where its disc fits, not any spot it would fit in (the floor seen
through a glass front is out of its reach). An area's frontier is the part of its edge the robot
can come up to from there, so a goal computed for it is a drivable one.

The unknown world outside the building (every unknown region touching the grid border) is one
area, ``interior=False``, and counts only where an opening the robot can reach leads into it.
An unknown region inside the map is an area when it is worth a trip: at least
``params.unexplored_worth_area_m2`` large, ``params.unexplored_min_width_m`` wide (room to drive in
and turn: not a shelf's or a rack's unknown inside, however long), not a thing the robot scanned
all round (free floor on every side and narrower than ``params.unexplored_enclosed_max_width_m``:
a group of desks, a glass table), with at least ``params.unexplored_min_frontier_m`` of
frontier the robot can come up to in one opening (a door, a room's open side: not the gaps in the
scanned outline of a shelf, a cabinet or a pallet whose inside is unknown, nor laser holes).
A region's thin parts as large as ``params.unexplored_worth_area_m2`` (the cavity between the two
copies of a wall a loop-closure error drew twice) are cut off it first (:func:`_cut_thin_parts`).
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
    count_labels,
    dilate8,
    disc,
    divmod_int,
    grow_by_disc,
    label8,
    label8_cells,
    nonzero2,
    truncated_sq_edt,
)
from langnav.maps.grid import OccupancyGrid

__all__ = ["EIGHT", "NEIGHBOURS_8", "UnexploredResult", "adjacent_pairs", "border_labels",
           "exterior_unknown_mask", "find_unexplored", "reachable_floor"]

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
    rr, cc = divmod_int(flat, w)
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
    lab, n, sizes, outside = _cut_thin_parts(grid, params, layers, lab, n, sizes, outside)
    min_cells = params.unexplored_min_area_m2 / grid.cell_area_m2
    speck_ids = ~outside & (sizes < min_cells)
    speck_ids[0] = False
    specks = speck_ids[lab]
    # (free cell, unknown label) pairs: which regions border free space, and their frontier cells.
    pairs = adjacent_pairs(layers.free, lab)
    touches = np.zeros(n + 1, dtype=bool)
    touches[pairs[:, 1]] = True
    # Where the robot can come up to from the floor it drove on: an area's frontier is the part
    # of its edge there, and only an area with enough of it is worth a trip.
    pairs = pairs[reachable_floor(grid, params, layers, specks, pairs[:, 0])]
    worth = _worth_a_trip(grid, params, layers, lab, n, sizes, outside, pairs)

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
    fr_r, fr_c = divmod_int(fr[:, 1], grid.width)
    fx, fy = grid.cell_to_world(fr_r, fr_c)
    order = np.argsort(fr[:, 0], kind="stable")
    splits = np.searchsorted(fr[order, 0], np.arange(1, n_areas + 2))

    areas: list[UnexploredArea] = []
    for k in range(1, n_areas + 1):
        sel = order[splits[k - 1]:splits[k]]
        # Its openings only: the runs of frontier as long as unexplored_min_frontier_m, not the
        # single cells seen through the gaps of a glass front or a wall's laser holes.
        sel = sel[_in_openings(grid, params, fr[sel, 1])]
        frontier = np.stack([fx[sel], fy[sel]], axis=1) if len(sel) else np.zeros((0, 2))
        areas.append(UnexploredArea(
            id=f"unexplored_{k}",
            centroid=(float(cx[k]), float(cy[k])),
            area_m2=float(counts[k] * grid.cell_area_m2),
            frontier=frontier,
            interior=not (has_outside and k == n_areas),
        ))
    return UnexploredResult(tuple(areas), area_labels, exterior, specks)


def _in_openings(grid: OccupancyGrid, params: AnalysisParams, cells: npt.NDArray[np.int64]) -> BoolArray:
    """Per frontier cell (sorted unique flat indices): is it in an opening, a run of frontier (an
    8-connected piece of ``cells``) at least ``params.unexplored_min_frontier_m`` long, rather than
    a cell seen through the gaps of a glass front, a wall's laser holes or a shelf's outline?"""
    need = math.ceil(params.unexplored_min_frontier_m / grid.resolution_m - 1e-9)
    run, n_runs = label8_cells(cells, (grid.height, grid.width))
    return np.asarray((np.bincount(run, minlength=n_runs + 1) >= need)[run], dtype=bool)


def _worth_a_trip(grid: OccupancyGrid, params: AnalysisParams, layers: GridLayers, lab: IntArray, n: int,
                  sizes: npt.NDArray[np.int64], outside: BoolArray, pairs: npt.NDArray[np.int64]) -> BoolArray:
    """Per unknown component (index = label): would a person send the robot to look at it? For
    the outside world (all its components together): does the robot reach enough of its
    frontier? For a region inside the map: big enough, and seen through an opening the robot
    can reach rather than through gaps in a scanned outline (see the module docstring)."""
    inside = ~outside
    inside[0] = False
    candidate = np.zeros(n + 1, dtype=bool)
    candidate[inside] = sizes[inside] * grid.cell_area_m2 >= params.unexplored_worth_area_m2
    candidate &= _wide_enough(grid, params, layers, lab, candidate)
    candidate &= ~_seen_all_round(grid, params, layers, lab, sizes, candidate)
    worth = np.zeros(n + 1, dtype=bool)
    # (``pairs`` hold only the frontier cells the robot comes up to from the main free space.)
    # The outside world: enough of its frontier within reach.
    # Frontier cells that see the region across an edge (4-neighbours), not only through the
    # corner between two occupied cells of a diagonal outline, which no scan passes.
    pairs = pairs[_edge_adjacent(lab, pairs)]
    out_cells = np.unique(pairs[outside[pairs[:, 1]], 0])
    # ... in one opening (a connected run), as for a region inside the map: not the cells seen
    # through the gaps of a glass front.
    if _in_openings(grid, params, out_cells).any():
        worth[outside] = True
    # A region inside the map: one opening (a connected run of its frontier) the robot can come
    # up to along at least unexplored_min_frontier_m (a door, a room's open side; not the gaps
    # in a shelf's scanned outline, nor laser holes).
    sel = candidate[pairs[:, 1]]
    if sel.any():
        cells, regions = pairs[sel, 0], pairs[sel, 1]
        uniq, inverse = np.unique(cells, return_inverse=True)
        opening = np.zeros(n + 1, dtype=bool)
        opening[regions[_in_openings(grid, params, uniq)[inverse]]] = True
        worth |= candidate & opening
    return worth


def _cut_thin_parts(grid: OccupancyGrid, params: AnalysisParams, layers: GridLayers, lab: IntArray, n: int,
                    sizes: npt.NDArray[np.int64], outside: BoolArray
                    ) -> tuple[IntArray, int, npt.NDArray[np.int64], BoolArray]:
    """The unknown regions inside the map without their thin parts: the labelling, count, sizes
    and outside flags again, the cut cells unlabelled (0) and the pieces left apart.

    A region's part with room for the robot to drive in and turn is what a disc
    ``params.unexplored_min_width_m`` wide covers inside it (counting, as :func:`_wide_enough`
    does, the free laser rays the robot does not fit in as part of it). A thin part beyond that
    which is itself as large as ``params.unexplored_worth_area_m2`` is no place to look at: the
    cavity between the two copies of a wall that a loop-closure error drew twice, a sliver
    behind a row of furniture. It is cut off, so that it neither makes a scan shadow it joins
    look large nor carries the shadow's frontier along the wall. Smaller thin bits (the corners
    a disc does not reach, a doorway's reveal) stay with the region.
    """
    inside = np.flatnonzero(~outside & (sizes * grid.cell_area_m2 >= params.unexplored_worth_area_m2))
    inside = inside[inside > 0]
    if len(inside) == 0:
        return lab, n, sizes, outside
    res = grid.resolution_m
    need = (params.unexplored_min_width_m / res + 1.0) / 2.0  # disc centre to outside, cells
    cover2 = (need - 0.5) ** 2  # the disc's cells, centre to centre (its width over two)
    reach = math.ceil(need) + 1
    a = np.arange(reach + 1)
    d2 = a[:, None] ** 2 + a[None, :] ** 2
    near_need, near_cover = d2 < need * need, d2 <= cover2 + 1e-9  # the offsets (cells) within each
    half = max(1, math.ceil(params.robot_radius_m / res))
    pad = reach + 2 * half + 1
    worth_cells = params.unexplored_worth_area_m2 / grid.cell_area_m2
    rows, cols = nonzero2(np.isin(lab, inside))
    boxes = component_boxes(lab[rows, cols], rows, cols, inside)
    out: IntArray | None = None
    n_new = n
    for k in inside.tolist():
        sr, sc = boxes[k]
        r0, r1 = max(0, sr.start - pad), min(grid.height, sr.stop + pad)
        c0, c1 = max(0, sc.start - pad), min(grid.width, sc.stop + pad)
        own = lab[r0:r1, c0:c1] == k
        region = _unknown_or_too_tight(layers, r0, r1, c0, c1, half)
        # truncated_sq_edt(region, reach) >= need * need and truncated_sq_edt(~centres, reach) <=
        # cover2 + 1e-9, exactly (both within the reach), as the outside and the centres grown.
        centres = ~grow_by_disc(~region, near_need)
        covered = grow_by_disc(centres, near_cover)
        thin = own & ~covered
        if not thin.any():
            continue
        parts = label8(thin)
        big = parts.sizes >= worth_cells
        big[0] = False
        if not big.any():
            continue
        keep = own & ~big[parts.labels]
        pieces = label8(keep)
        if out is None:
            out = lab.copy()
        window = out[r0:r1, c0:c1]
        window[own] = 0
        if pieces.n:
            # The first piece keeps the region's label, the others take new ones.
            ids = np.concatenate([[0, k], np.arange(n_new + 1, n_new + pieces.n, dtype=np.int64)])
            window[keep] = ids[pieces.labels[keep]]
            n_new += pieces.n - 1
    if out is None:
        return lab, n, sizes, outside
    new_sizes = count_labels(out, n_new + 1).astype(np.int64)
    new_sizes[0] = 0
    new_outside = np.zeros(n_new + 1, dtype=bool)
    new_outside[:n + 1] = outside
    return out, n_new, new_sizes, new_outside


def _seen_all_round(grid: OccupancyGrid, params: AnalysisParams, layers: GridLayers, lab: IntArray,
                    sizes: npt.NDArray[np.int64], candidate: BoolArray) -> BoolArray:
    """Per unknown component (index = label, ``sizes`` its cells; only ``candidate`` ones tested):
    did the robot's scans go all round it? It touches no wall (every occupied piece beside it is
    no bigger than a piece of furniture, ``params.seg_island_max_area_m2``: scanned legs and
    edges), so free floor surrounds it, and it is narrower than
    ``params.unexplored_enclosed_max_width_m``, so a lidar on that floor would have seen into it
    had nothing stood in the way: it is a thing (a group of desks, a glass table, a plant), and
    sending the robot there shows nothing more. A thing shows where it stands by the scan hits
    on its outline (legs, edges, faces); only one piece of furniture's size (up to
    ``params.seg_island_max_area_m2``: a glass table the laser passes through) may show none. A
    larger pocket with no hit at all on its edge shows nothing standing there: floor the map
    holds no scan of, worth a look."""
    out = np.zeros(len(candidate), dtype=bool)
    if not candidate.any():
        return out
    occ = layers.occupied_components
    island = params.seg_island_max_area_m2 / grid.cell_area_m2
    # (unknown cell of a candidate, occupied piece beside it): a candidate beside a bigger piece
    # touches a wall.
    pairs = adjacent_pairs(candidate[lab], occ.labels)
    walled = np.zeros(len(candidate), dtype=bool)
    hit = np.zeros(len(candidate), dtype=bool)
    if len(pairs):
        walled[lab.ravel()[pairs[occ.sizes[pairs[:, 1]] > island, 0]]] = True
        hit[lab.ravel()[pairs[:, 0]]] = True
    unseen = ~hit & (sizes > island)
    ids = np.flatnonzero(candidate & ~walled & ~unseen)
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
        # A square that holds the disc, else the disc itself.
        out[k] = not (_holds_square(own, side) or float(ndi.distance_transform_edt(own).max()) >= need)
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
        # the disc (cheap on a large region), else the disc itself; then with the free cells
        # about it that the robot's footprint (a free square of its diameter) never covers.
        if _holds_square(own, 2 * math.ceil(need) + 1) or int(truncated_sq_edt(own, reach)[own].max()) >= need * need:
            out[k] = True
            continue
        region = _unknown_or_too_tight(layers, r0, r1, c0, c1, half)
        out[k] = int(truncated_sq_edt(region, reach)[own].max()) >= need * need
    return out


def _holds_square(mask: BoolArray, side: int) -> bool:
    """Whether ``mask`` holds a square of ``side`` cells: its erosion by that square (two
    separable passes of a minimum filter; cells beyond the array are outside) is not empty."""
    square = mask
    for axis in (0, 1):
        square = ndi.minimum_filter1d(square, side, axis=axis, mode="constant", cval=False)
    return bool(square.any())


def _edge_adjacent(lab: IntArray, pairs: npt.NDArray[np.int64]) -> BoolArray:
    """Per (cell, label) pair: has the cell a 4-neighbour of that label?"""
    h, w = lab.shape
    flat = lab.ravel()
    rr, cc = divmod_int(pairs[:, 0], w)
    out = np.zeros(len(pairs), dtype=bool)
    for dr, dc in ((-1, 0), (1, 0), (0, -1), (0, 1)):
        r2, c2 = rr + dr, cc + dc
        ok = (r2 >= 0) & (r2 < h) & (c2 >= 0) & (c2 < w)
        out[ok] |= flat[r2[ok] * w + c2[ok]] == pairs[ok, 1]
    return out


def _unknown_or_too_tight(layers: GridLayers, r0: int, r1: int, c0: int, c1: int, half: int) -> BoolArray:
    """In the window rows r0:r1, cols c0:c1: the unknown cells and the free cells no square of
    side 2 * half + 1 cells that is all free covers (floor too tight for the robot to stand on)."""
    free = layers.free[r0:r1, c0:c1]
    fits = free
    for axis in (0, 1):
        fits = ndi.minimum_filter1d(fits, 2 * half + 1, axis=axis, mode="constant", cval=False)
    for axis in (0, 1):
        fits = ndi.maximum_filter1d(fits, 2 * half + 1, axis=axis, mode="constant", cval=False)
    return np.asarray(layers.unknown[r0:r1, c0:c1] | (free & ~fits))


def reachable_floor(grid: OccupancyGrid, params: AnalysisParams, layers: GridLayers, specks: BoolArray,
                    cells: npt.NDArray[np.int64]) -> BoolArray:
    """Per cell (flat index): can the robot come up to it from the main free space, i.e. is it
    a cell its body (a disc of ``params.robot_radius_m``) covers somewhere in the largest
    connected region where its centre fits, or an 8-neighbour of one?

    The robot's centre fits where every blocking cell (occupied, or unknown other than a noise
    speck; the grid's edge too) is at least its radius away, as the planner that drives it to a
    goal counts clearance. The map was built by the robot driving through it, so the floor it
    drove on is one connected region, by far the largest: free cells it does not connect to
    are the laser-ray fans seen through glass fronts and windows, the floor beyond a closed door
    seen through its gaps, or a pocket too tight to enter. A place seen only from there is not
    one a person would send the robot to look at: it cannot drive there, and a goal for it would
    be a spot beside the glass.
    """
    out = np.zeros(len(cells), dtype=bool)
    rows, cols = nonzero2(layers.free)
    if len(rows) == 0 or len(cells) == 0:
        return out
    body = disc(params.robot_radius_m / grid.resolution_m)
    reach = body.shape[0] - 1  # the body's reach (cells) from its centre
    # Over the free cells' bounding box (a real map's unknown margin is most of it), with room
    # for the body's reach and its neighbours beyond the free cells.
    pad = reach + 2
    r0, r1 = max(0, int(rows.min()) - pad), min(grid.height, int(rows.max()) + pad + 1)
    c0, c1 = max(0, int(cols.min()) - pad), min(grid.width, int(cols.max()) + pad + 1)
    blocking = layers.occupied[r0:r1, c0:c1] | (layers.unknown[r0:r1, c0:c1] & ~specks[r0:r1, c0:c1])
    # The disc's centre fits where the disc round it holds no blocking cell: outside the blocking
    # cells grown by the disc; the grid's edge blocks too (the cells beyond it, padded as blocking,
    # grow in). The body covers the cells the disc round a centre of the main region reaches.
    h, w = blocking.shape
    centre = ~grow_by_disc(np.pad(blocking, reach, constant_values=True), body)[reach:reach + h, reach:reach + w]
    comps = label8(centre)
    if comps.n == 0:
        return out
    # A cell is come up to when a centre of the main region lies within the disc round it or
    # round one of its neighbours: looked up at those offsets, on the region padded so that
    # none falls off it.
    main = np.pad(comps.labels == 1 + int(np.argmax(comps.sizes[1:])), pad, constant_values=False)
    rr, cc = divmod_int(cells, grid.width)
    inside = (rr >= r0) & (rr < r1) & (cc >= c0) & (cc < c1)
    flat = (rr[inside] - r0 + pad) * main.shape[1] + (cc[inside] - c0 + pad)
    main_flat = main.ravel()
    hit = np.zeros(len(flat), dtype=bool)
    for dr, dc in _disc_and_neighbours(body):
        hit |= main_flat[flat + (dr * main.shape[1] + dc)]
    out[inside] = hit
    return out


def _disc_and_neighbours(near: BoolArray) -> list[tuple[int, int]]:
    """The offsets (rows, columns) of the disc ``near`` (as :func:`~langnav.analysis.precompute.disc`
    gives it), grown by one cell all round (its cells and their 8-neighbours)."""
    reach = near.shape[0] - 1
    cells = [(dy, dx) for dy in range(-reach, reach + 1) for dx in range(-reach, reach + 1)
             if near[abs(dy), abs(dx)]]
    return sorted({(dy + a, dx + b) for dy, dx in cells for a in (-1, 0, 1) for b in (-1, 0, 1)})
