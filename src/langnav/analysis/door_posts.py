"""Gaps either side of a post: one opening, judged by its whole width.

A post, a column or the mullion of a double door standing in an opening splits the boundary
between two spaces into two gaps side by side, and the segmentation proposes a doorway in each.
A person sees one opening, as wide as both gaps and the post: a lobby's open front with a column
in it, an arch with a pillar. Where that whole opening is wider than the widest door, neither gap
is a door, however door-wide each reads: they are the two halves of a wide opening (still a way
between the two spaces). A post stands alone in the line of the wall, no deeper than it is wide;
a wall meeting that line (a partition between two rooms behind a glass front) is none, and so is
a pier in a row of them (a glass front seen only at its piers: each gap is a way in). Two doors
into the same room are farther apart than a post is wide: each needs its frame and a stretch of
wall beside it.

Pure functions over the grid's masks; thresholds in metres with their reasons.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Final

import numpy as np
import numpy.typing as npt

from langnav.analysis.params import AnalysisParams
from langnav.analysis.seg_doors import RawDoor

BoolArray = npt.NDArray[np.bool_]

#: A post, a column or a double door's mullion is at most this wide (m) along the opening; a
#: stretch of wall between two doors into the same room is wider (two frames and the wall
#: between them).
POST_MAX_WIDTH_M: Final = 0.5
#: The two gaps beside a post lie on one wall line: their centres are at most this far apart
#: (m) across it (a wall's thickness: each centre is where its gap is narrowest, somewhere in
#: the wall's depth) ...
SAME_LINE_MAX_OFFSET_M: Final = 0.45
#: ... and their normals at most this far apart (degrees): ragged gaps in one wall.
SAME_LINE_MAX_TURN_DEG: Final = 25.0
#: A speck of clutter or scan noise in a gap (m): a cell or two of a coarse map.
SPECK_MAX_M: Final = 0.2
#: Sampling step along the line through the two gaps (cells).
_STEP_CELLS: Final = 0.5


def _free_at(free: BoolArray, rows: npt.NDArray[np.float64], cols: npt.NDArray[np.float64]) -> BoolArray:
    """``free`` at continuous (row, col) positions (cell i spans [i, i + 1)); off the grid: not free."""
    r = np.floor(rows).astype(np.intp)
    c = np.floor(cols).astype(np.intp)
    inside = (r >= 0) & (r < free.shape[0]) & (c >= 0) & (c < free.shape[1])
    out = np.zeros(r.shape, dtype=bool)
    out[inside] = free[r[inside], c[inside]]
    return out


def _run_m(free: BoolArray, start_rc: tuple[float, float], step_rc: tuple[float, float], look_cells: float,
           resolution_m: float) -> float:
    """How far (m) the floor stays free from ``start_rc`` along the unit ``step_rc``, up to ``look_cells``."""
    s = np.arange(_STEP_CELLS, look_cells + 1e-9, _STEP_CELLS)
    ok = _free_at(free, start_rc[0] + s * step_rc[0], start_rc[1] + s * step_rc[1])
    n = int(np.argmin(ok)) if not ok.all() else ok.size
    return n * _STEP_CELLS * resolution_m


def post_span_m(free: BoolArray, a: RawDoor, b: RawDoor, resolution_m: float) -> float | None:
    """The width (m) of the opening that gaps ``a`` and ``b`` make with a post between them
    (both gaps' widths and the post's), or None when they are no such pair: not between the same
    two spaces, not in one wall line, or with anything but one post (at most POST_MAX_WIDTH_M of
    non-floor, as deep as it is wide, besides specks) on the line from one's centre to the
    other's."""
    if a is b or {a.a, a.b} != {b.a, b.b} or 0 in (a.a, a.b):
        return None
    if abs(a.normal_rc[0] * b.normal_rc[0] + a.normal_rc[1] * b.normal_rc[1]) < math.cos(
            math.radians(SAME_LINE_MAX_TURN_DEG)):
        return None
    dr, dc = b.center_rc[0] - a.center_rc[0], b.center_rc[1] - a.center_rc[1]
    dist = math.hypot(dr, dc)
    if dist == 0.0:
        return None
    across = abs(dr * a.normal_rc[0] + dc * a.normal_rc[1]) * resolution_m
    if across > SAME_LINE_MAX_OFFSET_M:
        return None
    # Each centre lies somewhere in its gap (where it is widest), so the line between them is
    # at most both gaps and the post long.
    if dist * resolution_m > a.width_m + b.width_m + POST_MAX_WIDTH_M:
        return None
    ur, uc = dr / dist, dc / dist
    s = np.arange(0.0, dist + 1e-9, _STEP_CELLS)
    ok = _free_at(free, a.center_rc[0] + s * ur, a.center_rc[1] + s * uc)
    # One post: a run of non-floor between the two gaps no wider than a post; any other run is a
    # speck of clutter or scan noise in a gap.
    edges = np.flatnonzero(np.diff(np.r_[0, (~ok).astype(np.int8), 0]))
    runs_m = (edges[1::2] - edges[::2]) * _STEP_CELLS * resolution_m
    if runs_m.size == 0:
        return None
    runs_m = np.sort(runs_m)
    if runs_m[-1] > POST_MAX_WIDTH_M or (runs_m.size > 1 and runs_m[-2] > SPECK_MAX_M):
        return None
    # A post stands alone in the opening, no deeper than it is wide: a wall meeting the line there
    # (a partition between two rooms behind a glass front) runs on across it.
    longest = int(np.argmax(edges[1::2] - edges[::2]))
    mid = (edges[2 * longest] + edges[2 * longest + 1] - 1) / 2 * _STEP_CELLS
    mid_rc = (a.center_rc[0] + mid * ur, a.center_rc[1] + mid * uc)
    reach = POST_MAX_WIDTH_M / resolution_m
    nr, nc = a.normal_rc
    depth_m = sum(_run_m(~free, mid_rc, (sg * nr, sg * nc), reach, resolution_m) for sg in (-1.0, 1.0))
    if depth_m >= POST_MAX_WIDTH_M:
        return None
    # The opening, wall to wall: both gaps as wide as they read as doors, and the post.
    return a.width_m + b.width_m + float(runs_m[-1])


def wide_with_posts(doors: Sequence[RawDoor], free: BoolArray, resolution_m: float,
                    params: AnalysisParams) -> tuple[list[RawDoor], list[RawDoor]]:
    """Split ``doors`` into (doors, halves of a wide opening): pairs of them side by side across
    a post that make an opening wider than the widest door (see module doc). Only gaps that each
    read as a door are paired: a slit or a glass pane's gap beside a door is a hole in its wall,
    not the other half of its opening. Three gaps and more in a row across posts are a front of
    panes between piers (a glass front the lidar saw only at its piers), each gap a way in: they
    stay as they are."""
    widest = params.door_wide_max_width_m + resolution_m
    n = len(doors)
    span: dict[tuple[int, int], float] = {}
    for i in range(n):
        for j in range(i + 1, n):
            s = post_span_m(free, doors[i], doors[j], resolution_m)
            if s is not None:
                span[i, j] = s
    beside = [[j for j in range(n) if (min(i, j), max(i, j)) in span] for i in range(n)]
    halves_at: set[int] = set()
    for (i, j), s in span.items():
        # One post between two gaps, neither with another gap across a post beside it.
        if s > widest and beside[i] == [j] and beside[j] == [i]:
            halves_at.update((i, j))
    kept = [d for k, d in enumerate(doors) if k not in halves_at]
    return kept, [d for k, d in enumerate(doors) if k in halves_at]


__all__ = ["POST_MAX_WIDTH_M", "post_span_m", "wide_with_posts"]
