"""Corners: where two walls of a space meet, on the space's side.

Two walls of the same space are a corner when they are roughly perpendicular, their lines
cross near an end of each, and the space lies inside the angle (a concave corner a person can
stand in; the outside of an L's elbow is not one). ``Corner.point`` is where the lines cross;
the walls' ends are moved onto it (a fitted wall stops a cell or two short of the corner).

A wall may also stop well short of the crossing and still meet the other there: when a doorway
opens beside the corner, or an unscanned patch covers it. Its line is then followed from its end
to the crossing (at most ``CORNER_MAX_BRIDGE_M``): on the space's side every cell must be the
space's own floor (free, or unknown inside it; at most a door's depth of clutter), and on the
wall's side every cell wall, unknown, or an opening no wider than a door. A line that runs on
across open floor, or into another space or the world outside, does not meet the other wall
there (the outside of an L's elbow, a wall that turns before the crossing). Those walls keep
their observed ends.
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
from langnav.analysis.precompute import GridLayers, truncated_sq_edt
from langnav.maps.grid import OccupancyGrid

#: Walls meet in a corner when the angle between them is within this of 90 degrees.
CORNER_MAX_SKEW_DEG: Final = 30.0
#: The crossing must lie within this of an end of each wall: fitted walls stop short of the
#: corner by the corner's rounding and scan noise; less than a narrow door, so a wall that ends
#: at a doorway is not taken for one that turns.
CORNER_END_TOL_M: Final = 0.5
#: A wall that stops short of the crossing is followed to it over at most this: a door beside
#: the corner plus its jamb, or an unscanned patch over a room's corner a few metres across.
CORNER_MAX_BRIDGE_M: Final = 5.0
#: Following a wall's line: samples this far (in cells) either side of the face line are the
#: centres of the first cell on the space's side and on the wall's side.
_FACE_OFFSET_CELLS: Final = 0.5
#: Two corners of one space closer than this are the same corner (duplicate wall pieces).
CORNER_MERGE_M: Final = 0.3
#: The approach point lies within this of the corner when a clear cell is there (the bench: "at
#: a corner" is within 1.0 m).
APPROACH_MAX_M: Final = 0.9
#: ... and otherwise is the nearest clear cell within this: a corner under an unscanned patch
#: has none close by, and the nearest reachable spot is the best a robot can do.
APPROACH_SEARCH_M: Final = 2.0
#: Up to this many cells, the approach points read one truncated clearance table of the grid
#: (a few ns a cell) rather than a distance transform per corner window (about 0.15 ms each): a
#: building's worth of corners covers at least this much. Both give the same points.
APPROACH_TABLE_MAX_CELLS: Final = 500_000


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
    the skew of perpendicular (|u_i . u_j| <= cos_max, each term as plain float arithmetic) and
    whose lines may meet in a corner."""
    lengths = [w.length_m for w in ws]
    ok_len = np.array([length != 0 for length in lengths])
    ux = np.array([(w.end[0] - w.start[0]) / length if length != 0 else 0.0 for w, length in zip(ws, lengths, strict=True)])
    uy = np.array([(w.end[1] - w.start[1]) / length if length != 0 else 0.0 for w, length in zip(ws, lengths, strict=True)])
    square = np.abs(ux[:, None] * ux[None, :] + uy[:, None] * uy[None, :]) <= cos_max
    square &= ok_len[:, None] & ok_len[None, :]
    ii, jj = np.nonzero(np.triu(square, k=1))
    if len(ii) == 0:
        return []
    # Keep the pairs whose lines may cross near an end of each or past both (``_intersect`` and
    # the tests in ``find_corners`` decide, exactly; a margin keeps borderline pairs for them).
    sx = np.array([w.start[0] for w in ws])
    sy = np.array([w.start[1] for w in ws])
    dx = np.array([w.end[0] for w in ws]) - sx
    dy = np.array([w.end[1] for w in ws]) - sy
    den = dx[ii] * dy[jj] - dy[ii] * dx[jj]
    safe = np.where(np.abs(den) < 1e-12, 1.0, den)
    t = ((sx[jj] - sx[ii]) * dy[jj] - (sy[jj] - sy[ii]) * dx[jj]) / safe
    px, py = sx[ii] + t * dx[ii], sy[ii] + t * dy[ii]
    length = np.hypot(dx, dy)
    margin = 1e-6

    def past_end(k: npt.NDArray[np.intp]) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
        """Distance to the nearer end, and how far past an end the crossing lies (< 0: inside)."""
        along = ((px - sx[k]) * dx[k] + (py - sy[k]) * dy[k]) / np.where(length[k] == 0, 1.0, length[k])
        to_end = np.minimum(np.hypot(px - sx[k], py - sy[k]), np.hypot(px - sx[k] - dx[k], py - sy[k] - dy[k]))
        return to_end, np.maximum(-along, along - length[k])

    end_a, past_a = past_end(ii)
    end_b, past_b = past_end(jj)
    tol = CORNER_END_TOL_M + margin
    near = (end_a <= tol) & (end_b <= tol)
    beyond = ((past_a >= -tol) & (past_a <= CORNER_MAX_BRIDGE_M + margin)
              & (past_b >= -tol) & (past_b <= CORNER_MAX_BRIDGE_M + margin))
    keep = (np.abs(den) >= 1e-12) & (near | beyond)
    return list(zip(ii[keep].tolist(), jj[keep].tolist(), strict=True))


def _beyond_end(w: Wall, x: tuple[float, float]) -> bool:
    """Does ``x`` (on the wall's line) lie past an end of the wall, or within the end tolerance of
    one, and no farther than ``CORNER_MAX_BRIDGE_M``? (Not somewhere along the wall itself.)"""
    length = w.length_m
    if length == 0:
        return False
    t = ((x[0] - w.start[0]) * (w.end[0] - w.start[0]) + (x[1] - w.start[1]) * (w.end[1] - w.start[1])) / length
    past = max(-t, t - length)
    return -CORNER_END_TOL_M <= past <= CORNER_MAX_BRIDGE_M


def _bridged(grid: OccupancyGrid, params: AnalysisParams, w: Wall, x: tuple[float, float],
             labels: npt.NDArray[np.int32], label: int, layers: GridLayers) -> bool:
    """Does the wall's line run on from its nearer end to ``x`` along the space (module docstring)?

    Samples every half cell: on the space's side, cells of the space (``label``; or unknown and
    not the world outside, for an unlabelled space), with at most ``params.door_max_depth_m`` of
    occupied cells; on the wall's side, anything but a free stretch wider than
    ``params.door_max_width_m``.
    """
    res = grid.resolution_m
    end = w.start if _dist(x, w.start) < _dist(x, w.end) else w.end
    gap = _dist(x, end)
    if gap <= CORNER_END_TOL_M:
        return True
    t = np.arange(0.0, gap + 1e-9, res / 2)
    ux, uy = (x[0] - end[0]) / gap, (x[1] - end[1]) / gap
    px, py = end[0] + t * ux, end[1] + t * uy
    off = _FACE_OFFSET_CELLS * res
    nx, ny = w.inward

    def cells_at(sign: float) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.int64], npt.NDArray[np.bool_]]:
        r, c = grid.world_to_index(px + sign * off * nx, py + sign * off * ny)
        ok = grid.in_bounds(r, c)
        return np.where(ok, r, 0), np.where(ok, c, 0), ok

    r_in, c_in, ok_in = cells_at(1.0)
    lab_in = labels[r_in, c_in]
    occupied_in = layers.occupied[r_in, c_in] & ok_in
    own = (lab_in == label) if label > 0 else np.zeros(len(t), dtype=bool)
    own |= (lab_in == 0) & layers.unknown[r_in, c_in] & ~layers.exterior[r_in, c_in]
    own &= ok_in
    if not np.all(own | occupied_in) or np.count_nonzero(occupied_in) * res / 2 > params.door_max_depth_m:
        return False
    r_out, c_out, ok_out = cells_at(-1.0)
    free_out = layers.free[r_out, c_out] & ok_out
    return _longest_run(free_out) * res / 2 <= params.door_max_width_m


def _longest_run(mask: npt.NDArray[np.bool_]) -> int:
    """The length of the longest run of True in a 1-D mask."""
    if not mask.any():
        return 0
    edges = np.flatnonzero(np.diff(np.concatenate([[0], mask.astype(np.int8), [0]])))
    return int(np.max(edges[1::2] - edges[0::2]))


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
            near = da <= CORNER_END_TOL_M and db <= CORNER_END_TOL_M
            if not near and not (_beyond_end(a, x) and _beyond_end(b, x)):
                continue
            # Directions from the corner along each wall (towards its far end).
            fa = a.end if _dist(x, a.end) > _dist(x, a.start) else a.start
            fb = b.end if _dist(x, b.end) > _dist(x, b.start) else b.start
            va = (fa[0] - x[0], fa[1] - x[1])
            vb = (fb[0] - x[0], fb[1] - x[1])
            concave = (vb[0] * a.inward[0] + vb[1] * a.inward[1] > 0
                       and va[0] * b.inward[0] + va[1] * b.inward[1] > 0)
            if not near:
                # Walls that stop short: a corner only where both lines reach it along the space.
                label = room_labels.get(room, 0) if room is not None else 0
                if not (concave and not any(_dist(x, p) < CORNER_MERGE_M for p in room_found)
                        and all(_bridged(grid, params, w, x, labels, label, layers) for w in (a, b))):
                    continue
                room_found.append(x)
                found.append((room, x, a, b))
                continue
            # Either way the two walls meet there: move their ends onto the meeting point.
            if concave and not any(_dist(x, p) < CORNER_MERGE_M for p in room_found):
                room_found.append(x)
                found.append((room, x, a, b))
            for w in (a, b):
                e = ends[w.id]
                near_end = 0 if _dist(x, e[0]) < _dist(x, e[1]) else 1
                e[near_end] = x
    corners: list[Corner] = []
    # One clearance table of the whole grid for all the approach windows on a small grid; on a
    # large one a transform per window costs less.
    use_table = bool(found) and grid.cells.size <= APPROACH_TABLE_MAX_CELLS
    clear_sq = free_clearance_sq(grid, params, layers.free) if use_table else None
    for k, (room, x, a, b) in enumerate(found, start=1):
        label = room_labels.get(room, 0) if room is not None else 0
        corners.append(Corner(id=f"corner_{k}", point=x, room=room, walls=(a.id, b.id),
                              approach=approach_point(grid, params, x, labels, label, free=layers.free,
                                                      clear_sq=clear_sq)))
    # Walls with an end moved to a corner are new walls; the others are kept as they are.
    new_walls = tuple(w if ends[w.id][0] is w.start and ends[w.id][1] is w.end
                      else dataclasses.replace(w, start=ends[w.id][0], end=ends[w.id][1]) for w in walls)
    return tuple(corners), new_walls


def _approach_margin_cells(grid: OccupancyGrid, params: AnalysisParams) -> int:
    """How far (cells) clearances must be exact for the approach test: the goal clearance and
    two cells more."""
    return math.ceil(params.goal_clearance_m / grid.resolution_m) + 2


def free_clearance_sq(grid: OccupancyGrid, params: AnalysisParams,
                      free: npt.NDArray[np.bool_] | None = None) -> npt.NDArray[np.signedinteger]:
    """Squared distance (cells²) of every cell to the nearest non-free cell (cells beyond the
    grid count as unknown), exact up to what :func:`approach_point` tests (see
    :func:`truncated_sq_edt`); one table for all the corners of a grid."""
    m = _approach_margin_cells(grid, params)
    f = grid.free if free is None else free
    return truncated_sq_edt(np.pad(f, 1), m)[1:-1, 1:-1]


def approach_point(grid: OccupancyGrid, params: AnalysisParams, point: tuple[float, float],
                   labels: npt.NDArray[np.int32], label: int,
                   free: npt.NDArray[np.bool_] | None = None,
                   clear_sq: npt.NDArray[np.signedinteger] | None = None) -> tuple[float, float]:
    """The free cell of space ``label`` nearest ``point`` with the goal clearance (world metres):
    its centre is at least ``params.goal_clearance_m`` from every occupied or unknown cell's edge.
    ``free`` is ``grid.free`` and ``clear_sq`` :func:`free_clearance_sq` when the caller has them.

    Within ``APPROACH_MAX_M`` when such a cell is there, or the clearest cell there when the
    robot fits in it; else the nearest with the clearance within ``APPROACH_SEARCH_M``; else the
    clearest free cell of the space within ``APPROACH_MAX_M``.
    """
    near = _window(grid, params, point, labels, label, free, APPROACH_MAX_M, clear_sq)
    if near is None:
        return point
    xs, ys, d, inside, clear = near
    ok = inside & (clear >= params.goal_clearance_m)
    if ok.any():
        i = np.argmin(np.where(ok, d, np.inf))
        return (float(xs.flat[i]), float(ys.flat[i]))
    if inside.any() and np.where(inside, clear, -np.inf).max() >= params.robot_radius_m:
        i = np.argmax(np.where(inside, clear, -np.inf))  # close to the corner, and the robot fits
        return (float(xs.flat[i]), float(ys.flat[i]))
    far = _window(grid, params, point, labels, label, free, APPROACH_SEARCH_M, clear_sq)
    if far is not None:
        fxs, fys, fd, finside, fclear = far
        fok = finside & (fclear >= params.goal_clearance_m)
        if fok.any():
            i = np.argmin(np.where(fok, fd, np.inf))
            return (float(fxs.flat[i]), float(fys.flat[i]))
    if inside.any():
        i = np.argmax(np.where(inside, clear, -np.inf))
        return (float(xs.flat[i]), float(ys.flat[i]))
    return point


def _window(grid: OccupancyGrid, params: AnalysisParams, point: tuple[float, float],
            labels: npt.NDArray[np.int32], label: int, free: npt.NDArray[np.bool_] | None, reach_m: float,
            clear_sq: npt.NDArray[np.signedinteger] | None = None) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.float64],
                       npt.NDArray[np.bool_], npt.NDArray[np.float64]] | None:
    """Around ``point``, out to ``reach_m``: cell centres (x, y), their distance to the point,
    which are free cells of space ``label`` within reach, and their clearance (m); ``None`` off
    the grid. ``clear_sq``: :func:`free_clearance_sq` of the grid, when the caller has it."""
    r, c = grid.world_to_index(point[0], point[1])
    res = grid.resolution_m
    rad = math.ceil(reach_m / res)
    r0, r1 = max(0, int(r) - rad), min(grid.height, int(r) + rad + 1)
    c0, c1 = max(0, int(c) - rad), min(grid.width, int(c) + rad + 1)
    if r0 >= r1 or c0 >= c1:
        return None
    win_lab = labels[r0:r1, c0:c1]
    # Clearance in a window grown by the clearance itself: exact up to that distance, which is
    # all the test needs (cells beyond the grid count as unknown).
    m = _approach_margin_cells(grid, params)
    pr0, pc0 = max(0, r0 - m), max(0, c0 - m)
    pr1, pc1 = min(grid.height, r1 + m), min(grid.width, c1 + m)
    seen = (grid.free if free is None else free)[pr0:pr1, pc0:pc1]
    # The window grown by m is all free only when the grid's edge does not cut it.
    all_free = (pr0, pc0, pr1, pc1) == (r0 - m, c0 - m, r1 + m, c1 + m) and bool(seen.all())
    if clear_sq is not None and not all_free:
        # The same values up to m cells (what the tests below compare exactly), and above m
        # beyond that, as in the window (sqrt of integer squares: bit for bit the transform's).
        edt = np.sqrt(clear_sq[r0:r1, c0:c1].astype(np.float64))
    else:
        padded = np.zeros((r1 - r0 + 2 * m, c1 - c0 + 2 * m), dtype=bool)
        padded[pr0 - (r0 - m):pr1 - (r0 - m), pc0 - (c0 - m):pc1 - (c0 - m)] = seen
        edt = np.asarray(ndi.distance_transform_edt(padded), dtype=np.float64)[m:-m, m:-m]
    clear = np.maximum(edt * res - res / 2, 0.0)
    xs, ys = grid.cell_to_world(np.arange(r0, r1)[:, None], np.arange(c0, c1)[None, :])
    d = np.hypot(xs - point[0], ys - point[1])
    inside = (clear > 0) & (win_lab == label) if label > 0 else (clear > 0)
    inside &= d <= reach_m
    return xs, ys, d, inside, clear
