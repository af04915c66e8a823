"""The middle line of narrow floor, and the building's wall thickness, for
:mod:`langnav.analysis.passages`.

The middle line of a strip between two sides is the crest of the distance to them
(:func:`crest`); a ridge across it (:func:`across_ridge`) is where a cell has sides on both
sides, not a plateau beside one wall. On coarse cells the line jogs sideways where a side's
outline steps a cell (:func:`jogs`). Pieces of it are its 8-connected parts long enough to be a
passage (:func:`long_pieces`), and its two-sided cells (:func:`two_sided`) the ones with blocking
cells close on two opposite sides. :func:`typical_wall_thickness_m` reads how thick this
building's walls are, against which a squeeze's length is judged.
"""

from __future__ import annotations

import math
from typing import Final

import numpy as np
import numpy.typing as npt

from langnav.analysis.passages_probe import side_distances
from langnav.analysis.precompute import divmod_int, label8_cells, median

BoolArray = npt.NDArray[np.bool_]

#: A middle-line cell's width is read from its whole cells of distance to a side: where a side
#: jogs by a cell (a scanned outline a cell off), the line steps sideways and the width read
#: there jumps by up to two cells (one a side; 0.2 m on a 0.1 m map, more than the tolerance).
#: A stretch of the line no more than that jump over the tolerance and a few cells long
#: (JOG_MAX_CELLS: the line steps a cell sideways over about as many cells as the way is wide in
#: cells at 0.1 m, never over the length of a thing beside it), between two stretches of one core, is
#: such a jog, not a flaring mouth nor the open side of a gap between things: the way goes on
#: across it.
JOG_WIDTH_CELLS: Final = 2.0
JOG_MAX_CELLS: Final = 4
#: ... when the stretches on either side of it run in line: their axes within this (degrees). A
#: cell's step sideways over a few cells turns a line's direction by at most atan(1/3) ~ 18 deg; a
#: way that really bends (an aisle turning a corner) turns by far more.
JOG_MAX_TURN_DEG: Final = 20.0
#: The middle line of a strip: the distance to its sides falls by at least this (cells) two
#: steps away on both sides (about two across it; half a cell along a stair-stepped wall).
CREST_DROP_CELLS: Final = 1.0
#: A core that is not bounded along most of its length is split into its two-sided stretches,
#: each cell tried across this many directions over 180 degrees (22.5 degrees apart: the side
#: of a passage at any angle is within 11.25 degrees, 2 % farther, of one of them).
TWO_SIDED_DIRECTIONS: Final = 8
#: The thickest wall: occupied runs thicker than this, scanned from both sides, are furniture or
#: solid things, not walls (as ``door_max_depth_m`` is the deepest doorway).
WALL_MAX_THICKNESS_M: Final = 0.45


def typical_wall_thickness_m(occupied: BoolArray, free: BoolArray, res: float) -> float:
    """The building's typical wall thickness (m): the median, over occupied cells, of the thinnest
    run of occupied cells through each along the four grid directions (rows, columns, both
    diagonals: within 22.5 degrees of across any wall) that has free floor at both of its ends (a
    wall scanned from both sides; an outer wall's skin with the unknown world behind it is no
    measure), up to ``WALL_MAX_THICKNESS_M`` (thicker runs are furniture). One cell when nothing
    is measured."""
    h, w = occupied.shape
    rr, cc = np.nonzero(occupied)
    if len(rr) == 0:
        return res
    best = np.full(len(rr), np.inf)
    span = np.int64(h + w + 1)
    for dr, dc in ((0, 1), (1, 0), (1, 1), (1, -1)):
        # Each line of the direction (key) and the position along it; a run is a stretch of
        # consecutive positions on one line. (np.nonzero lists the cells row by row: already in
        # line order for rows.)
        key = rr if dr == 0 else cc if dc == 0 else rr - cc if dc == 1 else rr + cc
        pos = cc if dr == 0 else rr
        order = (np.arange(len(rr)) if dr == 0
                 else np.argsort(key.astype(np.int64) * span + pos, kind="stable"))
        k, p = key[order], pos[order]
        brk = np.ones(len(order), dtype=bool)
        brk[1:] = (k[1:] != k[:-1]) | (p[1:] != p[:-1] + 1)
        run = np.cumsum(brk) - 1
        starts = np.flatnonzero(brk)
        ends = np.append(starts[1:], len(order)) - 1
        # The cells just before and after each run.
        r0, c0 = rr[order[starts]] - dr, cc[order[starts]] - dc
        r1, c1 = rr[order[ends]] + dr, cc[order[ends]] + dc
        bounded = np.ones(len(starts), dtype=bool)
        for r, c in ((r0, c0), (r1, c1)):
            ok = (r >= 0) & (r < h) & (c >= 0) & (c < w)
            bounded &= ok
            bounded[ok] &= free[r[ok], c[ok]]
        step = math.sqrt(2.0) if dr and dc else 1.0
        thick = np.where(bounded, (ends - starts + 1) * step * res, np.inf)
        best[order] = np.minimum(best[order], thick[run])  # (order visits each cell once)
    walls = best[best <= WALL_MAX_THICKNESS_M]
    return median(walls) if len(walls) else res


def crest(d2: npt.NDArray[np.integer]) -> BoolArray:
    """Cells whose distance (square root of ``d2``, in cells) exceeds that of both cells two
    steps away along one of the four directions by ``CREST_DROP_CELLS``: the middle line of a
    strip between two sides (the distance falls by about a cell a step on both sides of it),
    not a plateau along one wall, nor the ripples of a stair-stepped slanted wall (half a cell)."""
    d = np.sqrt(d2.astype(np.float32))
    h, w = d.shape
    p = np.pad(d, 2, mode="constant", constant_values=0)
    # Two steps along each direction: rows (dr), columns (dc).
    highest = np.full(d.shape, np.inf, dtype=np.float32)
    for dr, dc in ((2, 0), (0, 2), (2, 2), (2, -2)):
        a = p[2 + dr:2 + dr + h, 2 + dc:2 + dc + w]
        b = p[2 - dr:2 - dr + h, 2 - dc:2 - dc + w]
        np.minimum(highest, np.maximum(a, b), out=highest)
    return (d - highest >= CREST_DROP_CELLS) & (d > 0)


def across_ridge(d: npt.NDArray[np.integer], rr: npt.NDArray[np.intp], cc: npt.NDArray[np.intp]) -> BoolArray:
    """Per cell: is its value >= both neighbours along one of the four directions, and > one of
    them? A ridge across, not a plateau along a wall (the strip beside a single wall is level
    along the wall and rises away from it). A cheap necessary test for a cell with two sides."""
    h, w = d.shape
    v = d[rr, cc]
    near_r = {k: np.clip(rr + k, 0, h - 1) for k in (-1, 0, 1)}
    near_c = {k: np.clip(cc + k, 0, w - 1) for k in (-1, 0, 1)}
    out = np.zeros(len(rr), dtype=bool)
    for dr, dc in ((0, 1), (1, 0), (1, 1), (1, -1)):
        a = d[near_r[dr], near_c[dc]]
        b = d[near_r[-dr], near_c[-dc]]
        out |= (v >= a) & (v >= b) & ((v > a) | (v > b))
    return out


def jogs(idx: npt.NDArray[np.intp], core: BoolArray, near: BoolArray,
         width_cells: npt.NDArray[np.float64], shape: tuple[int, int]) -> BoolArray:
    """Per middle-line cell (sorted flat indices ``idx``): is it in a jog between two stretches
    of the ``core`` cells (see ``JOG_WIDTH_CELLS``): not in the core, ``near`` its chain's width,
    in a run of such cells at most ``JOG_MAX_CELLS`` long that touches two stretches of the core
    running in line, each passing within half the way's width (``width_cells``) of the run?"""
    out = np.zeros(len(idx), dtype=bool)
    cand = near & ~core
    if not cand.any() or not core.any():
        return out
    core_flat = idx[core]
    stretch, _n = label8_cells(core_flat, shape)
    run_flat = idx[cand]
    run, n_runs = label8_cells(run_flat, shape)
    h, w = shape
    r, c = divmod_int(run_flat, w)
    # Each run's cells' core neighbours: the stretches each run touches.
    pairs: list[npt.NDArray[np.int64]] = []
    for dr in (-1, 0, 1):
        for dc in (-1, 0, 1):
            if dr == 0 and dc == 0:
                continue
            ok = (r + dr >= 0) & (r + dr < h) & (c + dc >= 0) & (c + dc < w)
            nb = run_flat + dr * w + dc
            pos = np.minimum(np.searchsorted(core_flat, nb), len(core_flat) - 1)
            hit = ok & (core_flat[pos] == nb)
            pairs.append(np.stack([run[hit].astype(np.int64), stretch[pos[hit]].astype(np.int64)], axis=1))
    touch = np.unique(np.concatenate(pairs), axis=0)
    n_touched = np.bincount(touch[:, 0], minlength=n_runs + 1)
    size = np.bincount(run, minlength=n_runs + 1)
    ok = (n_touched == 2) & (size <= JOG_MAX_CELLS)
    if not ok.any():
        return out
    # ... and the two stretches are one way on either side of it: in line (their axes within
    # JOG_MAX_TURN_DEG, each passing within half the way's width of the run), not two ways
    # meeting at a corner (the gaps on either side of a locker block, joined round its end).
    sr, sc = divmod_int(core_flat, w)
    cnt = np.bincount(stretch, minlength=_n + 1).astype(float)
    cnt[0] = 1.0
    mx, my = np.bincount(stretch, weights=sc, minlength=_n + 1) / cnt, np.bincount(stretch, weights=sr, minlength=_n + 1) / cnt
    dx, dy = sc - mx[stretch], sr - my[stretch]
    sxx = np.bincount(stretch, weights=dx * dx, minlength=_n + 1)
    syy = np.bincount(stretch, weights=dy * dy, minlength=_n + 1)
    sxy = np.bincount(stretch, weights=dx * dy, minlength=_n + 1)
    ang = 0.5 * np.arctan2(2.0 * sxy, sxx - syy)
    ux, uy = np.cos(ang), np.sin(ang)
    rx = np.bincount(run, weights=c.astype(float), minlength=n_runs + 1) / np.maximum(size, 1)
    ry = np.bincount(run, weights=r.astype(float), minlength=n_runs + 1) / np.maximum(size, 1)
    half = np.bincount(run, weights=width_cells[cand], minlength=n_runs + 1) / np.maximum(size, 1) / 2.0
    for k in np.flatnonzero(ok).tolist():
        a, b = touch[touch[:, 0] == k, 1].tolist()
        in_line = abs(ux[a] * ux[b] + uy[a] * uy[b]) >= math.cos(math.radians(JOG_MAX_TURN_DEG))
        for s_ in (a, b):
            off = abs(-(rx[k] - mx[s_]) * uy[s_] + (ry[k] - my[s_]) * ux[s_])
            in_line = in_line and off <= max(half[k], 1.0)
        ok[k] = in_line
    out[np.flatnonzero(cand)] = ok[run]
    return out


def long_pieces(rr: npt.NDArray[np.intp], cc: npt.NDArray[np.intp], shape: tuple[int, int], min_cells: float
           ) -> list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp]]]:
    """The 8-connected pieces of a set of cells that may span ``min_cells`` (n cells span at most
    n * sqrt(2), and at most their bounding box's diagonal)."""
    if len(rr) == 0:
        return []
    flat = np.sort(rr * shape[1] + cc)
    ids, n = label8_cells(flat, shape)
    rows, cols = divmod_int(flat, shape[1])
    out = []
    for i in np.flatnonzero(np.bincount(ids, minlength=n + 1) * math.sqrt(2) >= min_cells).tolist():
        if i == 0:
            continue
        sel = ids == i
        pr, pc = rows[sel], cols[sel]
        if math.hypot(int(pr.max()) - int(pr.min()) + 1, int(pc.max()) - int(pc.min()) + 1) >= min_cells:
            out.append((pr, pc))
    return out


def joined(pieces: list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp]]]
         ) -> tuple[npt.NDArray[np.intp], npt.NDArray[np.intp]]:
    """All the cells of some pieces, as one (rows, cols) pair."""
    if not pieces:
        empty = np.zeros(0, dtype=np.intp)
        return empty, empty
    return np.concatenate([p[0] for p in pieces]), np.concatenate([p[1] for p in pieces])


def two_sided(open_: BoolArray, rr: npt.NDArray[np.intp], cc: npt.NDArray[np.intp],
              reach: npt.NDArray[np.float64], tol_cells: float) -> tuple[npt.NDArray[np.intp], npt.NDArray[np.intp]]:
    """The skeleton cells (rows ``rr``, cols ``cc``) with blocking cells within their half-width
    ``reach`` + ``tol_cells`` on two opposite sides, along one of ``TWO_SIDED_DIRECTIONS``
    directions (a cell beside one wall has a single side)."""
    if len(rr) == 0:
        return rr, cc
    pts = np.stack([cc + 0.5, rr + 0.5], axis=1).astype(float)
    both = np.zeros(len(pts), dtype=bool)
    for k in range(TWO_SIDED_DIRECTIONS):
        a = math.pi * k / TWO_SIDED_DIRECTIONS
        sides = side_distances(open_, pts, reach, np.array([math.cos(a), math.sin(a)]), tol_cells)
        both |= np.isfinite(sides).all(axis=1)
    return rr[both], cc[both]
