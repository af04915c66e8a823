"""Is a doorway candidate a door a person would point at? Judged by the structure around it.

The segmentation proposes a doorway wherever two spaces touch through a door-wide opening, or a
space meets unexplored territory at a door-wide saddle. A person calls an opening a door only
when it is cut in a wall between two places. What the cells around a candidate tell, whatever
the building:

*A door is as deep as a wall is thick.* Step through it along its normal: within a wall's
thickness the free width along the wall widens into the space beyond. The mouth of a passage
(a corridor running on at the width of the opening, a slot between two walls, the wall-bounded
way between two wings) stays as narrow for longer than any wall is thick: a narrow passage or a
corridor continuing, not a door.

A candidate between two spaces that is no door is still a way between them (an opening); one
into unexplored territory is nothing a person would point at.

Pure functions over the grid's masks; thresholds in metres with their reasons.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Final

import numpy as np
import numpy.typing as npt

from langnav.analysis.params import AnalysisParams
from langnav.analysis.seg_doors import RawDoor

BoolArray = npt.NDArray[np.bool_]

#: Sampling step along a candidate's normal and tangent (in cells): fine enough for walls one
#: cell thick.
_STEP_CELLS: Final = 0.5
#: A door's free width widens beyond it by at least this factor (jambs, a frame, a door leaf
#: standing open narrow a doorway; the room behind is wider than the door).
WIDEN_FACTOR: Final = 1.25
#: ... or by this much (m): two cells of scan noise on a narrow opening are no widening.
WIDEN_MIN_M: Final = 0.15
#: The narrowest crossing of a candidate lies within this distance (m) of its centre along
#: its normal (half a thick wall).
CENTRE_SLACK_M: Final = 0.25
#: How far through a candidate (m, each side) its free width is followed: beyond a wall's
#: thickness plus a passage's length, a constriction is a passage whatever follows.
THROUGH_LOOK_M: Final = 1.5

@dataclass(frozen=True)
class DoorEvidence:
    """What the cells around one candidate say (see module doc)."""

    #: Along the normal, the longest stretch (m) through the opening where the free width stays
    #: within the door's width (the constriction's depth).
    constriction_m: float


def _sample(mask: BoolArray, rows: npt.NDArray[np.float64], cols: npt.NDArray[np.float64],
            outside: bool) -> BoolArray:
    """``mask`` at continuous (row, col) positions in cell-corner coordinates (cell i spans
    [i, i + 1)); ``outside`` where they leave the grid."""
    r = np.floor(rows).astype(np.int64)
    c = np.floor(cols).astype(np.int64)
    h, w = mask.shape
    inside = (r >= 0) & (r < h) & (c >= 0) & (c < w)
    out = np.full(rows.shape, outside, dtype=bool)
    out[inside] = mask[r[inside], c[inside]]
    return out


def free_widths(free: BoolArray, center_rc: tuple[float, float], normal_rc: tuple[float, float],
                resolution_m: float, look_m: float) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """Offsets t (m) along the normal through ``center_rc`` and, at each, the free width (m)
    along the tangent of the run of ``free`` cells through that point (0 where it is not free)."""
    nr, nc = normal_rc
    tr, tc = -nc, nr
    k = math.ceil(look_m / resolution_m / _STEP_CELLS)
    t = np.arange(-k, k + 1) * _STEP_CELLS
    s_max = math.ceil(2.0 * look_m / resolution_m / _STEP_CELLS)
    s = np.arange(-s_max, s_max + 1) * _STEP_CELLS
    rows = center_rc[0] + t[:, None] * nr + s[None, :] * tr
    cols = center_rc[1] + t[:, None] * nc + s[None, :] * tc
    ok = _sample(free, rows, cols, outside=False)
    mid = s_max
    # The run through s = 0: up to the first blocked sample on each side.
    right = ok[:, mid:]
    left = ok[:, mid::-1]
    n_right = np.where(right.all(axis=1), right.shape[1], np.argmin(right, axis=1))
    n_left = np.where(left.all(axis=1), left.shape[1], np.argmin(left, axis=1))
    width = np.where(ok[:, mid], (n_right + n_left - 1) * _STEP_CELLS * resolution_m, 0.0)
    return np.asarray(t * resolution_m, dtype=np.float64), np.asarray(width, dtype=np.float64)


def constriction_depth(t_m: npt.NDArray[np.float64], width_m: npt.NDArray[np.float64],
                       door_width_m: float) -> float:
    """The length (m) of the stretch around t = 0 where the free width stays within the door's
    width (widening by less than WIDEN_FACTOR / WIDEN_MIN_M); a blocked sample ends it too."""
    limit = max(door_width_m * WIDEN_FACTOR, door_width_m + WIDEN_MIN_M)
    narrow = (width_m > 0) & (width_m <= limit)
    # The candidate's centre is its widest crossing, and a slanted crossing reads wider: start
    # from the narrow sample nearest to it, within a wall's half thickness.
    near = np.flatnonzero(narrow & (np.abs(t_m) <= CENTRE_SLACK_M))
    if near.size == 0:
        return 0.0
    mid = int(near[np.argmin(np.abs(t_m[near]))])
    hi = mid
    while hi + 1 < narrow.size and narrow[hi + 1]:
        hi += 1
    lo = mid
    while lo - 1 >= 0 and narrow[lo - 1]:
        lo -= 1
    return float(t_m[hi] - t_m[lo])


def evidence(free: BoolArray, occupied: BoolArray, center_rc: tuple[float, float],
             normal_rc: tuple[float, float], width_m: float, resolution_m: float) -> DoorEvidence:
    """The evidence of one candidate (``center_rc`` in cell-corner coordinates, unit normal)."""
    t, w = free_widths(free, center_rc, normal_rc, resolution_m, THROUGH_LOOK_M)
    depth = constriction_depth(t, w, width_m)
    return DoorEvidence(constriction_m=depth)


def is_door(ev: DoorEvidence, params: AnalysisParams, into_unknown: bool) -> bool:
    """The rules of the module doc on one candidate's evidence (``into_unknown``: it opens onto
    unexplored territory, where only its own side was seen)."""
    # As deep as a wall (plus the shortest passage): a longer constriction is a passage or a
    # corridor running on.
    return ev.constriction_m <= params.door_max_depth_m + params.passage_min_length_m


def judge_doors(candidates: list[RawDoor], free: BoolArray, occupied: BoolArray, resolution_m: float,
                params: AnalysisParams) -> tuple[list[RawDoor], list[RawDoor]]:
    """Split ``candidates`` into (doors, the rest) by the rules of the module doc."""
    doors: list[RawDoor] = []
    rest: list[RawDoor] = []
    for d in candidates:
        ev = evidence(free, occupied, d.center_rc, d.normal_rc, d.width_m, resolution_m)
        (doors if is_door(ev, params, into_unknown=d.b == 0) else rest).append(d)
    return doors, rest


__all__ = ["DoorEvidence", "constriction_depth", "evidence", "free_widths", "is_door", "judge_doors"]
