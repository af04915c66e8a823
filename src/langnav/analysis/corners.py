"""Corners: where two walls of a space meet, on the space's side.

Two walls of the same space are a corner when they are roughly perpendicular, their lines
cross near an end of each, and the space lies inside the angle (a concave corner a person can
stand in; the outside of an L's elbow is not one). ``Corner.point`` is where the lines cross;
the walls' ends are moved onto it (a fitted wall stops a cell or two short of the corner).
``Corner.approach`` is a free cell of the space near the corner with ``params.goal_clearance_m``
from every occupied or unknown cell: a goal a robot can reach "in the corner".
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from typing import Final

import numpy as np
import numpy.typing as npt
from scipy import ndimage as ndi

from langnav.analysis.elements import Corner, Wall
from langnav.analysis.params import AnalysisParams
from langnav.analysis.precompute import GridLayers
from langnav.maps.grid import OccupancyGrid

#: Walls meet in a corner when the angle between them is within this of 90 degrees.
CORNER_MAX_SKEW_DEG: Final = 30.0
#: The crossing must lie within this of an end of each wall: fitted walls stop short of the
#: corner by the corner's rounding and scan noise; less than a narrow door, so a wall that ends
#: at a doorway is not taken for one that turns.
CORNER_END_TOL_M: Final = 0.5
#: Two corners of one space closer than this are the same corner (duplicate wall pieces).
CORNER_MERGE_M: Final = 0.3
#: The approach point lies within this of the corner (the bench: "at a corner" is within 1.0 m).
APPROACH_MAX_M: Final = 0.9


def _dist(a: tuple[float, float], b: tuple[float, float]) -> float:
    return math.hypot(a[0] - b[0], a[1] - b[1])


def _intersect(a: Wall, b: Wall) -> tuple[float, float] | None:
    ax, ay = a.start
    dax, day = a.end[0] - ax, a.end[1] - ay
    bx, by = b.start
    dbx, dby = b.end[0] - bx, b.end[1] - by
    den = dax * dby - day * dbx
    if abs(den) < 1e-12:
        return None
    t = ((bx - ax) * dby - (by - ay) * dbx) / den
    # Rounded to the nanometre (+ 0.0 turns -0.0 into 0.0): no floating-point dust in outputs.
    return (round(ax + t * dax, 9) + 0.0, round(ay + t * day, 9) + 0.0)


def _square_pairs(ws: list[Wall], cos_max: float) -> list[tuple[int, int]]:
    """Index pairs (i < j, in loop order) of walls of non-zero length whose directions are within
    the skew of perpendicular: |u_i . u_j| <= cos_max, each term as plain float arithmetic."""
    lengths = [w.length_m for w in ws]
    ok_len = np.array([length != 0 for length in lengths])
    ux = np.array([(w.end[0] - w.start[0]) / length if length != 0 else 0.0 for w, length in zip(ws, lengths, strict=True)])
    uy = np.array([(w.end[1] - w.start[1]) / length if length != 0 else 0.0 for w, length in zip(ws, lengths, strict=True)])
    square = np.abs(ux[:, None] * ux[None, :] + uy[:, None] * uy[None, :]) <= cos_max
    square &= ok_len[:, None] & ok_len[None, :]
    ii, jj = np.nonzero(np.triu(square, k=1))
    return list(zip(ii.tolist(), jj.tolist(), strict=True))


def find_corners(grid: OccupancyGrid, params: AnalysisParams, walls: tuple[Wall, ...],
                 labels: npt.NDArray[np.int32], room_labels: Mapping[str, int],
                 layers: GridLayers | None = None) -> tuple[tuple[Corner, ...], tuple[Wall, ...]]:
    """Corners of every space, and the walls with their ends moved onto the corners.

    ``room_labels`` maps a space id to its label; ``layers`` are the grid's shared masks (built
    when not given).
    """
    layers = layers or GridLayers(grid)
    cos_max = math.sin(math.radians(CORNER_MAX_SKEW_DEG))
    ends: dict[str, list[tuple[float, float]]] = {w.id: [w.start, w.end] for w in walls}
    by_room: dict[str | None, list[Wall]] = {}
    for w in walls:
        by_room.setdefault(w.room, []).append(w)
    found: list[tuple[str | None, tuple[float, float], Wall, Wall]] = []
    for room, ws in by_room.items():
        room_found: list[tuple[float, float]] = []
        for i, j in _square_pairs(ws, cos_max):
            a, b = ws[i], ws[j]
            x = _intersect(a, b)
            if x is None:
                continue
            da = min(_dist(x, a.start), _dist(x, a.end))
            db = min(_dist(x, b.start), _dist(x, b.end))
            if da > CORNER_END_TOL_M or db > CORNER_END_TOL_M:
                continue
            # Directions from the corner along each wall (towards its far end).
            fa = a.end if _dist(x, a.end) > _dist(x, a.start) else a.start
            fb = b.end if _dist(x, b.end) > _dist(x, b.start) else b.start
            va = (fa[0] - x[0], fa[1] - x[1])
            vb = (fb[0] - x[0], fb[1] - x[1])
            concave = (vb[0] * a.inward[0] + vb[1] * a.inward[1] > 0
                       and va[0] * b.inward[0] + va[1] * b.inward[1] > 0)
            # Either way the two walls meet there: move their ends onto the meeting point.
            if concave and not any(_dist(x, p) < CORNER_MERGE_M for p in room_found):
                room_found.append(x)
                found.append((room, x, a, b))
            for w in (a, b):
                e = ends[w.id]
                near_end = 0 if _dist(x, e[0]) < _dist(x, e[1]) else 1
                e[near_end] = x
    corners: list[Corner] = []
    for k, (room, x, a, b) in enumerate(found, start=1):
        label = room_labels.get(room, 0) if room is not None else 0
        corners.append(Corner(id=f"corner_{k}", point=x, room=room, walls=(a.id, b.id),
                              approach=approach_point(grid, params, x, labels, label, free=layers.free)))
    new_walls = tuple(dataclasses.replace(w, start=ends[w.id][0], end=ends[w.id][1]) for w in walls)
    return tuple(corners), new_walls


def approach_point(grid: OccupancyGrid, params: AnalysisParams, point: tuple[float, float],
                   labels: npt.NDArray[np.int32], label: int,
                   free: npt.NDArray[np.bool_] | None = None) -> tuple[float, float]:
    """The free cell of space ``label`` nearest ``point`` with the goal clearance (world metres):
    its centre is at least ``params.goal_clearance_m`` from every occupied or unknown cell's edge.
    ``free`` is ``grid.free`` when the caller has it.

    Falls back to the clearest cell of the space within reach when none has the full clearance.
    """
    r, c = grid.world_to_index(point[0], point[1])
    res = grid.resolution_m
    rad = math.ceil(APPROACH_MAX_M / res)
    r0, r1 = max(0, int(r) - rad), min(grid.height, int(r) + rad + 1)
    c0, c1 = max(0, int(c) - rad), min(grid.width, int(c) + rad + 1)
    if r0 >= r1 or c0 >= c1:
        return point
    win_lab = labels[r0:r1, c0:c1]
    # Clearance in a window grown by the clearance itself: exact up to that distance, which is
    # all the test needs (cells beyond the grid count as unknown).
    m = math.ceil(params.goal_clearance_m / res) + 2
    padded = np.zeros((r1 - r0 + 2 * m, c1 - c0 + 2 * m), dtype=bool)
    pr0, pc0 = max(0, r0 - m), max(0, c0 - m)
    pr1, pc1 = min(grid.height, r1 + m), min(grid.width, c1 + m)
    padded[pr0 - (r0 - m):pr1 - (r0 - m), pc0 - (c0 - m):pc1 - (c0 - m)] = (grid.free if free is None else free)[pr0:pr1, pc0:pc1]
    edt = np.asarray(ndi.distance_transform_edt(padded), dtype=np.float64)[m:-m, m:-m]
    win_clear = np.maximum(edt * res - res / 2, 0.0)
    xs, ys = grid.cell_to_world(np.arange(r0, r1)[:, None], np.arange(c0, c1)[None, :])
    d = np.hypot(xs - point[0], ys - point[1])
    inside = (win_lab == label) if label > 0 else (win_clear > 0)
    inside &= d <= APPROACH_MAX_M
    ok = inside & (win_clear >= params.goal_clearance_m)
    if ok.any():
        i = np.argmin(np.where(ok, d, np.inf))
    elif inside.any():
        i = np.argmax(np.where(inside, win_clear, -np.inf))
    else:
        return point
    return (float(xs.flat[i]), float(ys.flat[i]))
