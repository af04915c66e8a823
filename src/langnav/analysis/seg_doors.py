"""Doorways from a segmentation: where two spaces touch, and where a space opens into unknown.

A doorway between two spaces is a connected piece of their shared boundary; its width comes
from the clearance at its widest crossing (about half the opening), its centre is that crossing,
its normal the mean step from the first space to the second.

An opening into unexplored territory is found by a second flood, over the floor *and* the
unknown around it (unknown counts as open space here): the spaces flood from their cores, the
unknown from its own interior, and where the two meet at a saddle as narrow as a door, bounded
by walls, there is a doorway into the unknown. Where the lidar saw out through a door, the fan
of rays beyond joins the space's floor and moves that saddle metres out; the door is then found
as a gap in the wall line with seen floor on one side only
(:func:`langnav.analysis.wall_lines.outer_gaps`).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Final

import numpy as np
import numpy.typing as npt
from scipy import ndimage as ndi
from skimage.segmentation import watershed

from langnav.analysis.params import AnalysisParams
from langnav.analysis.precompute import dilate_box, extreme_at, far_from_outside, maximum3, nonzero2
from langnav.analysis.seg_core import EIGHT, BoolArray, FloatArray, IntArray
from langnav.analysis.wall_lines import outer_gaps

#: Label given to the unknown in the second flood (larger than any space label).
_OUTSIDE_OFFSET: Final = 1
#: Unknown farther than this from the floor plays no part in finding openings into it.
OPENING_BAND_M: Final = 2.0
#: A frontier longer than this is a space fading into unexplored territory, not a doorway (with
#: the bit of floor a scan sees beyond an open door, an opening's frontier is shorter).
OPENING_MAX_EXTENT_M: Final = 4.0
#: A space's core for the second flood: cells with at least this share of its peak clearance.
CORE_FRACTION: Final = 0.6
#: The space a door in an outer wall opens from is the one met from this far (m) inside it ...
OUTER_LABEL_FROM_M: Final = 0.1
#: ... to this far (m).
OUTER_LABEL_TO_M: Final = 1.0
#: Seen floor: a free cell at least this far (m) from unscanned cells (a fan of laser rays is
#: free streaks a few cells wide with unknown between them).
SEEN_FLOOR_MIN_M: Final = 0.25


@dataclass(frozen=True)
class RawDoor:
    """A doorway in grid coordinates: continuous (row, col) of its centre, unit normal (drow, dcol)
    pointing from space ``a`` to space ``b`` (``b`` = 0: unexplored territory), and its width."""

    a: int
    b: int
    center_rc: tuple[float, float]
    normal_rc: tuple[float, float]
    width_m: float
    #: Found as a gap in a wall line, as deep as the wall (the line's jambs and depth were
    #: checked there): the end of a corridor at an exit in the outer wall is a door however
    #: wide the corridor behind it.
    in_wall_line: bool = False


@dataclass(frozen=True)
class UnknownOpenings:
    """What :func:`openings_to_unknown` finds: the doorways into unexplored territory, and the
    doorways between two spaces (``known``, by index) that lie at a gap of an outer wall line,
    each read as that gap (see :func:`doors_in_outer_walls`)."""

    doors: list[RawDoor]
    at_gaps: dict[int, RawDoor] = dataclasses.field(default_factory=dict)


def _boundary_pairs(labels: IntArray) -> tuple[npt.NDArray[np.int64], ...]:
    """All 4-neighbour cell pairs (p, q) with different non-zero labels: rows/cols of p and q."""
    out: list[tuple[npt.NDArray[np.int64], ...]] = []
    h, w = labels.shape
    for dr, dc in ((0, 1), (1, 0)):
        lp = labels[: h - dr, : w - dc]
        lq = labels[dr:, dc:]
        rr, cc = nonzero2((lp != lq) & (lp > 0) & (lq > 0))
        out.append((rr, cc, rr + dr, cc + dc))
    return tuple(np.concatenate([o[i] for o in out]).astype(np.int64) for i in range(4))


def doors_between(labels: IntArray, clearance_m: FloatArray, resolution_m: float,
                  params: AnalysisParams, outside_label: int | None = None,
                  min_width_m: float | None = None) -> list[RawDoor]:
    """Doorways along the boundaries of ``labels`` (see module doc), from ``min_width_m``
    (default ``params.door_min_width_m``) to ``params.door_max_width_m`` wide (between two
    spaces: up to ``params.seg_wall_gap_max_width_m``, a wide gap in a wall line).

    With ``outside_label``, only boundaries between a space and that label are examined, and the
    doorway's ``b`` is 0 (unknown).
    """
    pr, pc, qr, qc = _boundary_pairs(labels)
    la, lb = labels[pr, pc], labels[qr, qc]
    if outside_label is not None:
        sel = (la == outside_label) ^ (lb == outside_label)
        pr, pc, qr, qc, la, lb = pr[sel], pc[sel], qr[sel], qc[sel], la[sel], lb[sel]
    if pr.size == 0:
        return []
    # Orient each pair from the lower label to the higher one.
    swap = la > lb
    pr, qr = np.where(swap, qr, pr), np.where(swap, pr, qr)
    pc, qc = np.where(swap, qc, pc), np.where(swap, pc, qc)
    a, b = np.minimum(la, lb), np.maximum(la, lb)
    val = np.minimum(clearance_m[pr, pc], clearance_m[qr, qc])
    n = int(labels.max()) + 1
    key = a.astype(np.int64) * n + b
    order = np.argsort(key, kind="stable")
    key, pr, pc, qr, qc, val = key[order], pr[order], pc[order], qr[order], qc[order], val[order]
    starts = np.flatnonzero(np.r_[True, key[1:] != key[:-1]])
    ends = np.r_[starts[1:], key.size]
    min_w = (params.door_min_width_m if min_width_m is None else min_width_m) - resolution_m
    # Between two spaces, a gap in a wall line wider than a door may separate them too.
    wide = params.seg_wall_gap_max_width_m if outside_label is None else 0.0
    max_w = max(params.door_max_width_m, params.door_wide_max_width_m, wide) + resolution_m
    found: list[RawDoor] = []
    for s0, s1 in zip(starts, ends, strict=True):
        ka, kb = divmod(int(key[s0]), n)
        rows = np.r_[pr[s0:s1], qr[s0:s1]]
        cols = np.r_[pc[s0:s1], qc[s0:s1]]
        r0, c0 = rows.min(), cols.min()
        mask = np.zeros((rows.max() - r0 + 1, cols.max() - c0 + 1), dtype=bool)
        mask[rows - r0, cols - c0] = True
        comp, ncomp = ndi.label(mask, structure=EIGHT)
        pair_comp = comp[pr[s0:s1] - r0, pc[s0:s1] - c0]
        for ci in range(1, ncomp + 1):
            m = pair_comp == ci
            if not m.any():
                continue
            v = val[s0:s1][m]
            s = float(v.max())
            width = 2.0 * s - 0.5 * resolution_m
            if not (min_w <= width <= max_w):
                continue
            top = v >= s - 0.5 * resolution_m
            cr = (pr[s0:s1][m][top] + qr[s0:s1][m][top]).mean() / 2 + 0.5
            cc = (pc[s0:s1][m][top] + qc[s0:s1][m][top]).mean() / 2 + 0.5
            dr = float((qr[s0:s1][m] - pr[s0:s1][m]).sum())
            dc = float((qc[s0:s1][m] - pc[s0:s1][m]).sum())
            norm = float(np.hypot(dr, dc)) or 1.0
            if outside_label is not None and kb == outside_label:
                found.append(RawDoor(ka, 0, (float(cr), float(cc)), (dr / norm, dc / norm), width))
            elif outside_label is not None:
                found.append(RawDoor(kb, 0, (float(cr), float(cc)), (-dr / norm, -dc / norm), width))
            else:
                found.append(RawDoor(ka, kb, (float(cr), float(cc)), (dr / norm, dc / norm), width))
    return found


def label_max(labels: IntArray, values: FloatArray) -> FloatArray:
    """The largest value under each label 0..max (0 where a label is absent; label 0 ignored)."""
    out = np.zeros(int(labels.max()) + 1)
    m = labels > 0
    extreme_at(np.maximum, out, labels[m], values[m])
    return out


def openings_to_unknown(labels: IntArray, floor: BoolArray, exterior: BoolArray,
                        obstacle: BoolArray, clearance_m: FloatArray, resolution_m: float,
                        params: AnalysisParams, peak: FloatArray | None = None,
                        known: list[RawDoor] | None = None,
                        directions: list[float] | None = None,
                        views_out: BoolArray | None = None) -> UnknownOpenings:
    """Doorways from a space into unexplored territory (see module doc). ``peak``:
    ``label_max(labels, clearance_m)``, when the caller has it; ``known``: the doorways between
    spaces found already (a gap in an outer wall that is one of them is not found twice);
    ``directions``: the wall directions of ``obstacle & ~floor``, when the caller has them;
    ``views_out``: per label, whether that space is a view out of the building (no space).

    Only windows around the frontier (floor touching unexplored unknown) are flooded again.
    """
    if not exterior.any() or labels.max() == 0:
        return UnknownOpenings([])
    frontier = floor & (labels > 0) & maximum3(exterior)
    if not frontier.any():
        return UnknownOpenings([])
    # A door to the outside or to an unscanned room may be a double door.
    widest = max(params.door_max_width_m, params.door_wide_max_width_m)
    door_clear_max = (widest + resolution_m) / 2
    # Frontier cells closer than a door width belong to one opening candidate.
    join = max(1, round(widest / resolution_m))
    groups, _ = ndi.label(dilate_box(frontier, join), structure=EIGHT)
    groups[~frontier] = 0
    margin = math.ceil(OPENING_BAND_M / resolution_m)
    if peak is None:
        peak = label_max(labels, clearance_m)
    h, w = labels.shape
    out: list[RawDoor] = []
    max_extent = OPENING_MAX_EXTENT_M / resolution_m
    for sl in ndi.find_objects(groups):
        if sl is None or max(sl[0].stop - sl[0].start, sl[1].stop - sl[1].start) > max_extent:
            continue
        r0, r1 = max(0, sl[0].start - margin), min(h, sl[0].stop + margin)
        c0, c1 = max(0, sl[1].start - margin), min(w, sl[1].stop + margin)
        win = (slice(r0, r1), slice(c0, c1))
        lab = labels[win]
        ext = exterior[win]
        # Every cell but a wall is open here: unknown notches between rays that a space took as
        # its own still open onto what lies beyond them.
        open_ = floor[win] | ~obstacle[win]
        clear2 = ndi.distance_transform_edt(open_, sampling=resolution_m)
        markers = np.where((lab > 0) & (clearance_m[win] >= CORE_FRACTION * peak[lab]), lab, 0)
        rim = np.zeros(lab.shape, dtype=bool)
        rim[[0, -1], :] = True
        rim[:, [0, -1]] = True
        markers[rim & (lab > 0)] = lab[rim & (lab > 0)]
        outside = int(labels.max()) + _OUTSIDE_OFFSET
        markers[ext & ((clear2 > door_clear_max) | rim)] = outside
        if not (markers == outside).any():
            continue
        flood = np.asarray(watershed(-clear2, markers.astype(np.int32), mask=open_), dtype=np.int32)
        for d in doors_between(flood, clear2, resolution_m, params, outside_label=outside):
            r, c = d.center_rc[0] + r0, d.center_rc[1] + c0
            # Keep a door only near this window's own frontier (windows overlap).
            if not (sl[0].start - join <= r <= sl[0].stop + join and sl[1].start - join <= c <= sl[1].stop + join):
                continue
            if any(math.hypot(r - o.center_rc[0], c - o.center_rc[1]) * resolution_m < params.door_min_width_m
                   for o in out):
                continue
            out.append(RawDoor(d.a, 0, (r, c), d.normal_rc, d.width_m))
    return doors_in_outer_walls(labels, floor, exterior, obstacle, resolution_m, params, out, known or [],
                                directions, views_out)


def doors_in_outer_walls(labels: IntArray, floor: BoolArray, exterior: BoolArray, obstacle: BoolArray,
                         resolution_m: float, params: AnalysisParams, found: list[RawDoor],
                         known: list[RawDoor], directions: list[float] | None = None,
                         views_out: BoolArray | None = None) -> UnknownOpenings:
    """``found`` (doorways into unexplored territory found at a saddle) and the doorways from a
    space into unexplored territory through which the lidar saw out: a door-wide gap in a wall
    line with the space's seen floor on one side and, on the other, only the fan of rays that
    went through it (:func:`langnav.analysis.wall_lines.outer_gaps`). The fan joins the space's
    floor, so its frontier lies metres out, too long for a saddle as narrow as a door: the wall
    line shows the door. A gap at a doorway of ``found`` marks that one as in a wall line. A gap
    at a doorway between two spaces (``known``: the view out through the door, or a room seen
    only through it, was flooded as a space) is that doorway read in the wall line (returned in
    ``at_gaps``): the flood parts the two where their basins meet, often off the wall (a line
    across the rays beyond the door, slanted to the wall), and measures it there; a person
    reads the door where the wall is, as wide as the gap in it. Beyond such a gap lie the rays
    through it: no space, the first space's own (flooded past the wall), or a view out of the
    building (``views_out``: per label); a space of its own there was seen otherwise, and the
    gap is no door onto the unseen (the end of a row of hollow benches beside a hall's wall).
    ``directions``: the wall directions of ``obstacle & ~floor``, when the caller has them."""
    walls = obstacle & ~floor
    seen = floor & far_from_outside(~exterior, SEEN_FLOOR_MIN_M, resolution_m)
    out = list(found)
    look = np.arange(OUTER_LABEL_FROM_M, OUTER_LABEL_TO_M + 1e-9, resolution_m) / resolution_m
    h, w = labels.shape

    def near(o: RawDoor, r: float, c: float, width_m: float) -> bool:
        return math.hypot(r - o.center_rc[0], c - o.center_rc[1]) * resolution_m < max(width_m, o.width_m)

    # A doorway between two spaces at a gap: the gap nearest to it (a ragged wall gives a gap on
    # each of the lines in its band).
    in_line: dict[int, tuple[float, RawDoor]] = {}

    def space_at(r: float, c: float, sign: float, nr: float, nc: float) -> int:
        """The space met stepping from (r, c) along ``sign`` x the normal (0: none)."""
        rr = np.floor(r + sign * look * nr).astype(np.int64)
        cc = np.floor(c + sign * look * nc).astype(np.int64)
        ok = (rr >= 0) & (rr < h) & (cc >= 0) & (cc < w)
        lab = labels[rr[ok], cc[ok]]
        lab = lab[lab > 0]
        return int(np.bincount(lab).argmax()) if lab.size else 0

    for g in outer_gaps(walls, floor, seen, exterior, resolution_m, params, directions):
        (r, c), (nr, nc) = g.center_rc, g.normal_rc
        at_known = [k for k, o in enumerate(known) if near(o, r, c, g.width_m)]
        if at_known:
            # The doorway is between the space the gap opens from and one beyond it: the rays
            # just past the gap are no one's, the first space's own (the flood parted the two
            # further out, across the rays) or a view out.
            inner, outer = space_at(r, c, -1.0, nr, nc), space_at(r, c, 1.0, nr, nc)
            rays = outer in (0, inner) or (views_out is not None and bool(views_out[outer]))
            for k in at_known:
                o = known[k]
                if not rays or inner not in (o.a, o.b) or outer not in (o.a, o.b, 0):
                    continue
                d = math.hypot(r - o.center_rc[0], c - o.center_rc[1])
                if k not in in_line or d < in_line[k][0]:
                    sg = 1.0 if inner == o.a else -1.0
                    in_line[k] = (d, dataclasses.replace(o, center_rc=(r, c), normal_rc=(sg * nr, sg * nc),
                                                         width_m=g.width_m, in_wall_line=True))
            continue
        at = [i for i, o in enumerate(out) if near(o, r, c, g.width_m)]
        if at:
            for i in at:
                out[i] = dataclasses.replace(out[i], in_wall_line=True)
            continue
        # The space it opens from: the label met stepping in from the gap.
        inner = space_at(r, c, -1.0, nr, nc)
        if inner == 0:
            continue
        out.append(RawDoor(inner, 0, (r, c), (nr, nc), g.width_m, in_wall_line=True))
    return UnknownOpenings(out, {k: d for k, (_, d) in in_line.items()})


__all__ = ["SEEN_FLOOR_MIN_M", "RawDoor", "doors_between", "doors_in_outer_walls", "label_max", "openings_to_unknown"]
