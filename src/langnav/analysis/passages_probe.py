"""Probes of the floor round a narrow-passage candidate, for :mod:`langnav.analysis.passages`.

Each samples the open floor (a boolean window: True where the robot may be) along lines from a
candidate's middle line, in grid cells (x, y): how far its sides are (:func:`side_distances`),
whether they hold along it (:func:`sides_hold`) and are solid (:func:`solid_sides`), what lies
past its mouths (:func:`past_mouths`, :func:`beside_a_wall`), whether a thing beside it is
deeper than a wall (:func:`deep`) and its faces parallel (:func:`parallel`), whether there is a
way round it (:func:`way_round`), and whether its mouths lead somewhere
(:func:`opens_into_space`, :func:`leads_on`) and into which space (:func:`space_beyond`).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Final

import numpy as np
import numpy.typing as npt
from scipy import ndimage as ndi

from langnav.analysis.params import AnalysisParams

BoolArray = npt.NDArray[np.bool_]

#: A passage has sides: at this share of its core, blocking cells lie close on both sides (a
#: strip along a wall whose other side is a row of separate objects is not a passage).
MIN_BOUNDED_FRACTION: Final = 0.7
#: ... or, walled on one side along this share, with one doorway in the other side.
DOORWAY_WALL_FRACTION: Final = 0.9
#: Open stretches of a side up to this long (cells) are scan noise, not a doorway.
DOORWAY_MIN_GAP_CELLS: Final = 3
#: A short squeeze beside a wall: the wall runs on past both mouths, blocked (within the
#: squeeze's width) along this share of the samples there, and the thing beside it ends (open
#: along as much).
WALL_RUNS_ON_SHARE: Final = 0.7
#: A squeeze between two things runs between their faces: parallel, its width varying along it by
#: no more than this (m; scan noise on the two faces), not a pinch between a corner and a slanted
#: wall, as where a room narrows to its door.
PARALLEL_SPREAD_M: Final = 0.15
#: A free crack along a thing's depth up to this wide (m; two cells of a common 0.05 m map) is
#: scan noise: the sliver between the two copies of its outline a pose error drew twice.
OUTLINE_CRACK_M: Final = 0.1
#: ... and the thing is deeper than a wall is thick (door_max_depth_m): blocked along this share
#: of that depth past its face (its outline may have a scan dropout).
DEEP_SHARE: Final = 0.8
#: Look this far beyond a mouth for the space the passage opens into.
MOUTH_SEARCH_M: Final = 1.0
#: A mouth opens into a free area when one is found within this distance beyond it (the core
#: stops where the sides start to flare, up to about a width before the space itself).
MOUTH_OPEN_SEARCH_M: Final = 1.5
#: Side distances of many pieces are sampled together, about this many samples at a time
#: (bounded memory on a large map; fewer numpy calls on a small one).
SIDE_BATCH_SAMPLES: Final = 400_000


def side_distances(open_: BoolArray, pts: npt.NDArray[np.float64], reach: npt.NDArray[np.float64],
                   normal: npt.NDArray[np.float64], tol_cells: float,
                   stop: float | None = None) -> npt.NDArray[np.float64]:
    """Per point (x, y in grid cells): distance (cells) to the first non-open cell along -normal
    and +normal, within reach + tol; ``inf`` where that side is open. Shape (N, 2). ``normal``
    is one (2,) vector, or one per point (N, 2); ``stop`` is where the samples end (default:
    past the longest reach).

    Sampling every half cell from a cell centre, the first blocked sample is 0 to 0.5 cell past
    the side's edge: the two sides summed, minus half a cell, is the width.
    """
    if stop is None:
        stop = float(reach.max()) + tol_cells + 0.5
    steps = np.arange(0.0, stop, 0.5)
    limit = reach + tol_cells
    out = np.full((len(pts), 2), np.inf)
    h, w = open_.shape
    nrm = np.asarray(normal, dtype=np.float64)
    for j, sign in enumerate((-1.0, 1.0)):
        # All samples of all points at once: (N, steps), the same arithmetic as one by one.
        t = sign * steps
        if nrm.ndim == 1:
            x = pts[:, 0:1] + (t * nrm[0])[None, :]
            y = pts[:, 1:2] + (t * nrm[1])[None, :]
        else:
            x = pts[:, 0:1] + t[None, :] * nrm[:, 0:1]
            y = pts[:, 1:2] + t[None, :] * nrm[:, 1:2]
        r = np.floor(y).astype(int)
        c = np.floor(x).astype(int)
        inside = (r >= 0) & (r < h) & (c >= 0) & (c < w)
        blocked = ~inside
        blocked[inside] = ~open_[r[inside], c[inside]]
        hit = blocked & (steps[None, :] <= limit[:, None])
        first = np.argmax(hit, axis=1)
        found = hit[np.arange(len(pts)), first]
        out[found, j] = steps[first[found]]
    return out


def side_distances_each(open_: BoolArray, pts: Sequence[npt.NDArray[np.float64]],
                        reach: Sequence[npt.NDArray[np.float64]], normal: Sequence[npt.NDArray[np.float64]],
                        tol_cells: float) -> list[npt.NDArray[np.float64]]:
    """:func:`side_distances` of several point sets (each with its own normal), the same values,
    worked out together in batches of about ``SIDE_BATCH_SAMPLES`` samples: one sample step
    list for all (the longest; a sample past a point's reach never counts)."""
    out: list[npt.NDArray[np.float64]] = []
    i = 0
    while i < len(pts):
        # Take sets while the batch stays small.
        j, n_pts, stop = i, 0, 0.0
        while j < len(pts):
            s = max(stop, float(reach[j].max()) + tol_cells + 0.5)
            if j > i and (n_pts + len(pts[j])) * (2.0 * s + 1.0) > SIDE_BATCH_SAMPLES:
                break
            stop, n_pts, j = s, n_pts + len(pts[j]), j + 1
        sizes = [len(p) for p in pts[i:j]]
        normals = np.repeat(np.array(normal[i:j]).reshape(-1, 2), sizes, axis=0)
        sides = side_distances(open_, np.concatenate(pts[i:j]), np.concatenate(reach[i:j]),
                               normals, tol_cells, stop=stop)
        out.extend(np.split(sides, np.cumsum(sizes)[:-1]))
        i = j
    return out


def sides_hold(sides: npt.NDArray[np.float64], proj: npt.NDArray[np.float64], door_cells: float) -> bool:
    """Has a piece sides along it (``sides``: per point, the distances to either side, ``inf``
    where open; ``proj``: the points' positions along the axis, cells)? Between its first and
    last two-sided points (not in its flaring mouths): two-sided along ``MIN_BOUNDED_FRACTION``
    of it, or walled on one side along ``DOORWAY_WALL_FRACTION`` with the other side open in a
    single doorway (at most ``door_cells`` long; a passage with a door off it), not in a row of
    gaps (a strip along a wall beside separate objects)."""
    both = np.isfinite(sides).all(axis=1)
    if not both.any():
        return False
    inside = (proj >= proj[both].min()) & (proj <= proj[both].max())
    s, p = sides[inside], proj[inside]
    if np.isfinite(s).all(axis=1).mean() >= MIN_BOUNDED_FRACTION:
        return True
    order = np.argsort(p, kind="stable")
    p = p[order]
    for j in (0, 1):
        wall, other = np.isfinite(s[order, j]), np.isfinite(s[order, 1 - j])
        if wall.mean() < DOORWAY_WALL_FRACTION or other.mean() < 0.5:
            continue
        # The open stretches of the other side, by their extent along the axis.
        edges = np.flatnonzero(np.diff(np.concatenate(([1], other.astype(np.int8), [1]))))
        gaps = [float(p[b - 1] - p[a]) + 1.0 for a, b in zip(edges[::2], edges[1::2], strict=True)]
        real = [g for g in gaps if g > DOORWAY_MIN_GAP_CELLS]
        if len(real) == 1 and real[0] <= door_cells:
            return True
    return False


def solid_sides(open_: BoolArray, occupied: BoolArray, outside: BoolArray, pts: npt.NDArray[np.float64],
                normal: npt.NDArray[np.float64], sides: npt.NDArray[np.float64], depth_cells: float) -> BoolArray:
    """Per point: are both its sides (distances ``sides`` from :func:`side_distances` along
    -/+``normal``) solid: an occupied cell where the side starts (a wall, a thin shelf), or
    unknown that is not the unexplored world ``outside`` with no open cell within
    ``depth_cells`` past it (a shelf's unscanned inside)? A thin unknown stripe between two
    laser rays, with free space just behind it, is not; nor is the unscanned world beyond a
    sliver of free space outside a wall (nothing is known to stand there)."""
    out: BoolArray = np.asarray(np.isfinite(sides).all(axis=1), dtype=bool)
    steps = np.arange(0.0, depth_cells + 0.5, 0.5)
    h, w = open_.shape
    for j, sign in enumerate((-1.0, 1.0)):
        idx = np.flatnonzero(out)
        t = sign * (sides[idx, j][:, None] + steps[None, :])
        r = np.floor(pts[idx, 1:2] + t * normal[1]).astype(int)
        c = np.floor(pts[idx, 0:1] + t * normal[0]).astype(int)
        inside = (r >= 0) & (r < h) & (c >= 0) & (c < w)
        see = np.zeros(r.shape, dtype=bool)
        see[inside] = open_[r[inside], c[inside]]
        hit = np.zeros(r.shape, dtype=bool)
        hit[inside] = occupied[r[inside], c[inside]]
        beyond = np.ones(r.shape, dtype=bool)
        beyond[inside] = outside[r[inside], c[inside]]
        out[idx[(see.any(axis=1) | beyond[:, 0]) & ~hit[:, 0]]] = False
    return out


def past_mouths(open_: BoolArray, centre_g: npt.NDArray[np.float64], axis: npt.NDArray[np.float64],
                half_len: float, width: float, run: float, tol: float | None = None) -> npt.NDArray[np.float64]:
    """Past each mouth of the stretch (``centre_g``, unit ``axis``, ``half_len`` cells either way,
    ``width`` cells wide), from a quarter of its width to ``run`` cells on: per side (0: along
    -normal, 1: along +normal, the normal being the axis turned a quarter anticlockwise) and per
    mouth (0: ahead along +axis, 1: behind), the share of samples blocked within its half width
    plus ``tol`` cells (default: its whole width)."""
    normal = np.array([-axis[1], axis[0]])
    t = np.arange(width / 4.0, run + 0.5, 0.5)
    starts = np.concatenate([centre_g + (half_len + t)[:, None] * axis, centre_g - (half_len + t)[:, None] * axis])
    sides = side_distances(open_, starts, np.full(len(starts), width / 2.0), normal,
                           width / 2.0 if tol is None else tol)
    blocked = np.isfinite(sides)
    n = len(t)
    return np.array([[blocked[:n, j].mean(), blocked[n:, j].mean()] for j in (0, 1)])


def beside_a_wall(past: npt.NDArray[np.float64], both_mouths: bool = True) -> int | None:
    """Is a stretch (``past``: :func:`past_mouths`) a squeeze between a wall and a thing beside
    it: one side stays blocked (the wall runs on) along ``WALL_RUNS_ON_SHARE`` of the samples
    past both mouths (or one, ``both_mouths=False``: a wall that ends at a doorway), and the other
    is open along as much past both (the thing ends)? The thing's side, or None."""
    on = past.min(axis=1) if both_mouths else past.max(axis=1)
    off = past.max(axis=1)
    for j in (0, 1):
        if on[j] >= WALL_RUNS_ON_SHARE and off[1 - j] <= 1.0 - WALL_RUNS_ON_SHARE:
            return 1 - j
    return None


def deep(open_: BoolArray, pts: npt.NDArray[np.float64], outward: npt.NDArray[np.float64],
         side: npt.NDArray[np.float64], depth: float, res: float) -> bool:
    """Is the thing on one side of a squeeze (its points ``pts``, the side ``side`` cells away
    along the unit ``outward``) deeper than ``depth`` cells: blocked along ``DEEP_SHARE`` of the
    samples that far past where it starts (a scan dropout in its outline is no way into it),
    at ``MIN_BOUNDED_FRACTION`` of the points?"""
    h, w = open_.shape
    t = side[:, None] + np.arange(0.0, depth + 0.5, 0.5)[None, :]
    r = np.floor(pts[:, 1:2] + t * outward[1]).astype(int)
    c = np.floor(pts[:, 0:1] + t * outward[0]).astype(int)
    inside = (r >= 0) & (r < h) & (c >= 0) & (c < w)
    blocked = ~inside
    blocked[inside] = ~open_[r[inside], c[inside]]
    # A crack no wider than scan noise inside the thing (the sliver between the two copies of its
    # outline that a pose error drew twice) is no way into it: closed across.
    k = math.ceil(OUTLINE_CRACK_M / res / 0.5)
    if k > 0 and blocked.shape[1] > k + 1:
        blocked |= ndi.binary_closing(blocked, structure=np.ones((1, k + 1), dtype=bool))
    return bool((blocked.mean(axis=1) >= DEEP_SHARE).mean() >= MIN_BOUNDED_FRACTION)


def parallel(sides: npt.NDArray[np.float64], res: float) -> bool:
    """Do the two sides of a stretch (per point, the distances in cells to either side, both
    finite) run parallel: its width varies along it by no more than ``PARALLEL_SPREAD_M`` (or two
    cells: a cell of scan noise on each face) between the 10th and 90th percentiles?"""
    w = sides.sum(axis=1) * res
    lo, hi = np.quantile(w, [0.1, 0.9])
    return bool(hi - lo <= max(PARALLEL_SPREAD_M, 2.0 * res))


def way_round(floor: BoolArray, fits: BoolArray, centre_g: npt.NDArray[np.float64], axis: npt.NDArray[np.float64],
              half_len: float, width: float, reach: float) -> bool:
    """Can the robot get from one mouth of a squeeze (``centre_g``, unit ``axis``, ``half_len`` and
    ``width`` in cells) to the other without going through it, within ``reach`` cells of it
    (``WAY_ROUND_M``)? Over the ``floor`` cells (where its centre ``fits``, or only open floor
    wider than any passage), and where it fits just beyond each mouth."""
    h, w = fits.shape
    # The squeeze's box (with a cell of slack at its ends) and the floor just beyond each mouth
    # (within a width of its end, ahead of it), in a window around it that holds the way round.
    pad = half_len + max(2.0 * width + 2.0, min(reach, float(h + w)))
    r0, r1 = max(0, math.floor(centre_g[1] - pad)), min(h, math.ceil(centre_g[1] + pad) + 1)
    c0, c1 = max(0, math.floor(centre_g[0] - pad)), min(w, math.ceil(centre_g[0] + pad) + 1)
    rr, cc = np.mgrid[r0:r1, c0:c1]
    dx, dy = cc + 0.5 - centre_g[0], rr + 0.5 - centre_g[1]
    along = dx * axis[0] + dy * axis[1]
    across = np.abs(-dx * axis[1] + dy * axis[0])
    cut = (np.abs(along) <= half_len + 1.0) & (across <= width / 2.0 + 1.0)
    ahead = (across <= width) & (np.abs(along) <= half_len + 1.0 + width) & ~cut
    win, _n = ndi.label((floor[r0:r1, c0:c1] | (fits[r0:r1, c0:c1] & ahead)) & ~cut, structure=np.ones((3, 3), dtype=bool))
    first = np.unique(win[ahead & (along > half_len + 1.0) & (win > 0)])
    second = np.unique(win[ahead & (along < -half_len - 1.0) & (win > 0)])
    return bool(np.intersect1d(first, second).size)


def opens_into_space(open_: BoolArray, end_g: npt.NDArray[np.float64], direction: npt.NDArray[np.float64],
                     res: float, params: AnalysisParams, last_g: npt.NDArray[np.float64] | None = None) -> bool:
    """Does the free space beyond a mouth (``end_g``, x, y in grid cells; ``direction`` outwards
    along the axis) open into a free area: within ``MOUTH_OPEN_SEARCH_M`` of the mouth, reached
    through free cells ahead of it, a cell whose clearance exceeds half the widest passage
    (somewhere wider than any narrow passage: a room, a hall, a corridor)? A dead-end slot's
    far end, a sliver outside a wall and a laser ray's tip do not. Where the mouth's own cell is
    no free cell, the way is followed from ``last_g``, the passage's last middle-line cell there
    (a bent passage's straight axis ends in its side)."""
    h, w = open_.shape
    reach = MOUTH_OPEN_SEARCH_M / res
    need = params.passage_max_width_m / 2.0 / res
    x, y = float(end_g[0]), float(end_g[1])
    # The window: the search disc plus the clearance to measure, so that a cell of the disc that
    # is clear enough is so within the window (the window's edge counts as blocked).
    pad = math.ceil(reach + need) + 1
    r0, r1 = max(0, math.floor(y) - pad), min(h, math.floor(y) + pad + 1)
    c0, c1 = max(0, math.floor(x) - pad), min(w, math.floor(x) + pad + 1)
    win = open_[r0:r1, c0:c1]
    rr, cc = np.mgrid[r0:r1, c0:c1]
    dx, dy = cc + 0.5 - x, rr + 0.5 - y
    # Ahead of the mouth (half a cell of slack: the end lies on a cell centre's line).
    ahead = win & (dx * direction[0] + dy * direction[1] >= -0.5) & (dx * dx + dy * dy <= reach * reach)
    lab, _n = ndi.label(ahead)
    start = lab[min(max(math.floor(y), r0), r1 - 1) - r0, min(max(math.floor(x), c0), c1 - 1) - c0]
    if start == 0 and last_g is not None:
        lr, lc = math.floor(float(last_g[1])), math.floor(float(last_g[0]))
        if r0 <= lr < r1 and c0 <= lc < c1:
            start = lab[lr - r0, lc - c0]
    if start == 0:
        return False
    clear = ndi.distance_transform_edt(np.pad(win, 1))[1:-1, 1:-1]
    return bool(clear[lab == start].max() > need)


def leads_on(fits: BoolArray, wide: BoolArray, end_g: npt.NDArray[np.float64], rr: npt.NDArray[np.intp],
             cc: npt.NDArray[np.intp], width: float, reach: float) -> bool:
    """Does the way beyond a mouth (``end_g``, x, y in grid cells) lead on to open floor: from the
    mouth, over cells where the robot fits (``fits``) and not back along the passage itself (its
    middle line ``rr``, ``cc`` and the floor within its half width ``width / 2`` of it), a cell of
    ``wide`` floor (wider than any passage) within ``reach`` cells of the mouth? A dead-end slot's
    far end does not, nor a strip past a gap the robot cannot take; a mouth opening into the next
    aisle round an island or into a narrow cross aisle does, where that aisle meets the room."""
    h, w = fits.shape
    x, y = float(end_g[0]), float(end_g[1])
    pad = math.ceil(reach) + 1
    r0, r1 = max(0, math.floor(y) - pad), min(h, math.floor(y) + pad + 1)
    c0, c1 = max(0, math.floor(x) - pad), min(w, math.floor(x) + pad + 1)
    own = np.zeros((r1 - r0, c1 - c0), dtype=bool)
    keep = (rr >= r0) & (rr < r1) & (cc >= c0) & (cc < c1)
    own[rr[keep] - r0, cc[keep] - c0] = True
    if not own.any():
        return False
    # The passage's own floor: within its half width (and a cell) of its middle line.
    cut = ndi.distance_transform_edt(~own) <= width / 2.0 + 1.0
    gy, gx = np.mgrid[r0:r1, c0:c1]
    dx, dy = gx + 0.5 - x, gy + 0.5 - y
    # From the mouth (its end of the passage's floor, within its half width), over floor where
    # the robot fits, not back along the passage.
    at_mouth = dx * dx + dy * dy <= (width / 2.0 + 1.0) ** 2
    floor = fits[r0:r1, c0:c1] & (~cut | at_mouth) & (dx * dx + dy * dy <= reach * reach)
    lab, _n = ndi.label(floor, structure=np.ones((3, 3), dtype=bool))
    first = np.unique(lab[at_mouth & (lab > 0)])
    if len(first) == 0:
        return False
    return bool((wide[r0:r1, c0:c1] & ~cut & np.isin(lab, first)).any())


def space_beyond(labels: npt.NDArray[np.int32], end_g: npt.NDArray[np.float64],
                 direction: npt.NDArray[np.float64], res: float, room_ids: Mapping[int, str]) -> str | None:
    """The first labelled space met walking from a mouth outwards along the axis (grid coords)."""
    steps = int(MOUTH_SEARCH_M / res)
    for t in range(0, steps + 1):
        x, y = end_g + t * direction
        r, c = math.floor(y), math.floor(x)
        if not (0 <= r < labels.shape[0] and 0 <= c < labels.shape[1]):
            return None
        lab = int(labels[r, c])
        if lab > 0 and lab in room_ids:
            return room_ids[lab]
    return None
