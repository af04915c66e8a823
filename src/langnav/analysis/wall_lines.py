"""The building's wall lines, and the door-wide gaps in them that part two spaces.

A building is laid out along a few wall directions (nearly always two at right angles, whatever
the map's rotation), and its walls run on as straight lines across it: a corridor's side wall
with the office doors in it, a glass front broken by laser gaps and open door leaves, a house's
wall between its living room and the bedroom wing. A person sees such a wall line as one wall,
and a door-wide gap in it as a doorway between the spaces on its two sides, however little
those spaces narrow at the gap (an office front as wide as the corridor it opens onto). The
clearance flood of :mod:`langnav.analysis.seg_core` cannot see that (two spaces that do not rise
above an opening look like one), so the gaps are found here, from the walls themselves, and
closed before the flood (ROSE², RA-L 2022, bounds rooms by the building's wall lines the same way).

1. *Directions*: the wall cells' edge directions, folded modulo 90 degrees (a right-angled plan),
   give the dominant direction as the peak of their histogram; other peaks nearly as strong
   (a wing at 45 degrees) are directions too, each with its right angle.
2. *Lines*: along each direction, the wall cells are binned by their offset across it (a band
   of a cell either side: scanned walls are not ruled), and each line's occupied stretches are
   read in order along it.
3. *Gaps*: a gap between two stretches of a line is a doorway between two spaces when
   - it is door-wide (``door_min_width_m`` to ``seg_wall_line_gap_max_m``);
   - the wall line runs on past both of its ends, solid on at least ``seg_wall_line_side_share``
     of ``seg_wall_line_side_m`` (a wall, not the corner of a piece of furniture);
   - or it is wider than a door, an arch (up to ``seg_wall_line_arch_max_m``: the wide opening
     between a home's living room and its bedroom wing or dining room), and the wall runs on
     solid (``seg_wall_line_min_share``: beside an opening that wide, a dashed line is a row of
     furniture) past each end for at least half the arch's width: the wall line is at least as
     long as the opening in it (a wall with an arch cut in it; an open plan's short stubs at
     the ends of a wide opening are no wall), and both of its ends belong to the walls joined
     to the building's shell (desk screens and shelf units stand free on the floor);
   - its floor is scanned (a gap into unknown is an opening into unexplored territory, left to
     :mod:`langnav.analysis.seg_doors`);
   - on both sides the space it opens onto runs on along the wall past one of its ends: a
     doorway is narrower than the rooms it joins, whereas where a corridor meets another one
     (a T or a crossing) the opening is the whole width of the branch, and there is no door.
4. *Doors onto the unexplored* (:func:`outer_gaps`): a door-wide gap in a wall line with seen
   floor on one side and, on the other, only the rays the lidar sent out through it (a door in
   an outer wall, or into a room never entered). The fan of rays joins the space's floor, so
   the flood sees no door-wide saddle there; the wall line does.
"""

from __future__ import annotations

import math
import threading
from dataclasses import dataclass
from typing import Final, Generic, TypeVar

import numpy as np
import numpy.typing as npt
from scipy import ndimage as ndi

from langnav.analysis.params import AnalysisParams
from langnav.analysis.precompute import EIGHT, divmod_int, nonzero2, take2

BoolArray = npt.NDArray[np.bool_]
FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
_Cell = TypeVar("_Cell", np.bool_, np.uint8)

#: Candidate wall directions are tried every this many degrees (then refined to a tenth).
DIRECTION_BIN_DEG: Final = 1.0
#: At most this many wall cells (an even sample) are used to find the directions.
DIRECTION_MAX_CELLS: Final = 20_000
#: Candidate gaps judged together (their samples across the line in one array: bounded memory).
CANDIDATE_BLOCK: Final = 256
#: Directions are scored together up to this many cells times directions (arrays in cache).
SCORE_BLOCK_ELEMENTS: Final = 32_768
#: Adding 1.5 * 2**52 to a float64 below 2**51 in size rounds it to an integer, half to even (the
#: spacing of float64 there is 1, and the sum is rounded to nearest, ties to even, as
#: ``np.rint`` does); adding an even integer too keeps the ties' parity, so the sum's bits less
#: those of the rounder are ``rint(x)`` plus that integer.
_ROUNDER: Final = 1.5 * 2.0**52
_ROUNDER_BITS: Final = int(np.array(_ROUNDER, dtype=np.float64).view(np.int64))
#: Bits of the cell code that reads the wall and the floor masks with one lookup.
WALL_BIT: Final = 1
FLOOR_BIT: Final = 2
#: A second direction (a wing at an angle) counts when its peak rises this share of the main
#: one's height above the worst direction's score.
SECOND_DIRECTION_MIN_SHARE: Final = 0.5
#: ... and lies at least this many degrees (modulo 90) from every direction already taken.
DIRECTION_MIN_SEPARATION_DEG: Final = 10.0
#: Wall cells within this many cells across a line belong to it (scanned walls wobble a cell).
LINE_BAND_CELLS: Final = 1
#: Floor share of a gap's own cells: a doorway's floor is scanned (a few unknown specks aside).
GAP_MIN_FLOOR_SHARE: Final = 0.8
#: An interior wall is 0.1-0.3 m thick (a stud partition to a block wall): a doorway in it is no
#: deeper; a slot between two cabinets, desks or shelf units standing in a row is as deep as
#: they are (0.4 m and more).
WALL_MAX_THICKNESS_M: Final = 0.3
#: A front (a glass front, a row of windows between piers: see :func:`_line_candidates`) runs
#: from solid wall to solid wall over at most this length (m): the fronts of a row of offices,
#: wards' bays or shops (five 4 m bays) between two stretches of wall.
FRONT_MAX_LENGTH_M: Final = 20.0
#: ... each of those walls solid (``seg_wall_line_side_share``) over at least this length (m)
#: along the line: a wall the front continues, not a door frame or a stub.
FRONT_ANCHOR_M: Final = 2.0
#: ... and its pieces are pieces of wall at least this long (m, the longer side of their
#: bounding box): a pier, a mullion, a door frame, a stretch of glass seen square on; not the
#: specks of chair or table legs, or a row of thin posts.
FRONT_PIECE_MIN_M: Final = 0.25
#: ... and its gaps are open floor across the line's band and this far (m) beyond it either
#: side (a wobbly wall a cell or two out of the line runs beside it there) ...
FRONT_BESIDE_M: Final = 0.1
#: ... and no wall crosses the line at either end of a gap, within this distance (m) of the
#: line's band on both sides: a wall's end or a pier stands in the line, a wall crossing it
#: (a corridor's side wall, for a line across the corridor) belongs to another line ...
FRONT_CROSSING_M: Final = 0.3
#: ... but for wall cells along at most this share of a gap's length (a pier a cell or two out
#: of line at its end; a wobbly wall running beside the line covers the whole gap).
FRONT_BESIDE_MAX_SHARE: Final = 0.5
#: Share of the wall line past each end of a gap that must be a partition (thin, with floor on
#: both sides); the rest may be a pillar, a cupboard against it, a perpendicular wall's end.
PARTITION_MIN_SHARE: Final = 0.5
#: Depths (m, from the line) at which the space beyond a gap is looked at: just past the wall's
#: far face (walls are up to ``door_max_depth_m`` thick) and a little further in (a desk or a
#: cupboard may stand against the wall beside the door).
SIDE_DEPTHS_M: Final = (0.3, 0.5, 0.7)
#: The space beyond a gap runs on along the wall at least this far (m) past one of the gap's ends
#: (a corridor branch's side walls start at the gap's ends, a scanned wall a cell or two off).
SIDE_PAST_JAMB_M: Final = 0.5
#: A gap opens from seen floor onto the unseen (:func:`outer_gaps`) when, looking straight
#: through it from a wall's thickness (m) ...
OUTER_LOOK_FROM_M: Final = 0.3
#: ... to a door's width past the wall (m), at least this share of one side is seen floor
#: (the space it opens from) ...
OUTER_NEAR_M: Final = 1.0
OUTER_INSIDE_MIN_SHARE: Final = 0.5
#: ... and on the other, rays reach on through it up to this far (m; what a scan through a door
#: shows of the place beyond) ...
OUTER_FAR_M: Final = 2.0
#: ... while behind the wall beside it (from this far past the wall, m, to OUTER_NEAR_M, and as
#: far along the wall past each jamb) at least this share is unknown: an opaque wall ...
OUTER_BESIDE_FROM_M: Final = 0.2
OUTER_BEHIND_MIN_UNKNOWN: Final = 0.5
#: ... and wall stands in line with both jambs over less than this share of the look beyond
#: (a corridor or a room running on from the gap has its walls there).
OUTER_WALLED_MAX_SHARE: Final = 0.5


#: An open door leaf (:func:`_jamb_leaves`) is at most this long (m): the widest single leaf
#: (a wide accessible door; a double door's leaves are half of its opening each) ...
LEAF_MAX_LENGTH_M: Final = 1.25
#: ... and no longer than the opening it closes, give or take this much (m: a ragged jamb, the
#: leaf's hinge standing off the wall's end).
LEAF_SLACK_M: Final = 0.15
#: A leaf is a panel a few centimetres thick: across it, its scanned cells span at most this
#: (m), and a cell of scan spread more.
LEAF_MAX_THICKNESS_M: Final = 0.1
#: ... thin with floor on both faces over at least this share of its length (a few cells of
#: scan noise along it aside) ...
LEAF_MIN_SHARE: Final = 0.8
#: ... and floor just past its free edge over this many cells, on at least this share of them.
LEAF_TIP_CELLS: Final = 2
LEAF_TIP_MIN_FLOOR_SHARE: Final = 0.6


@dataclass(frozen=True)
class WallGap:
    """A door-wide gap in a wall line, in grid coordinates (row, col; continuous): its two ends
    on the line and its width."""

    end_a_rc: tuple[float, float]
    end_b_rc: tuple[float, float]
    width_m: float
    #: A gap of a front (a glass front, a row of windows between piers), not a gap between two
    #: solid stretches of wall: glass the lidar saw through, or the front's door.
    in_front: bool = False
    #: The (row, col) cells of the open door leaves standing at its jambs (a double door's).
    leaf_cells: tuple[tuple[int, int], ...] = ()


def _line_scores(rows: FloatArray, neg_cols: FloatArray, degs: FloatArray) -> FloatArray:
    """How well the cells line up along each direction of ``degs`` and its right angle: the sum
    of squared counts of cells per one-cell line across each direction (a wall along a direction
    puts its cells on few lines), over the number of cells. ``neg_cols``: the cells' columns
    negated. Several directions are scored in one array when the cells are few (a door's
    surroundings), one at a time when they are many (the arrays stay in cache).

    A cell's line is ``rint(-col * sin + row * cos)`` (half to even); it is read as the low bits
    of that sum plus :data:`_ROUNDER` and an even shift per direction (see there): one addition
    instead of rounding, converting to integers and shifting."""
    n = rows.size
    block = min(max(1, SCORE_BLOCK_ELEMENTS // n), len(degs))
    # Every line number lies within +-reach (|-col * sin + row * cos| <= hypot(row, col), and
    # rows and columns are >= 0; a cell more for the rounding): shifted by reach, each direction
    # of a block counts into its own span of bins. Both even, so that every shift is even (see
    # _ROUNDER).
    reach = math.ceil(math.hypot(float(rows.max()), float(neg_cols.min()))) + 2
    reach += reach % 2
    span = 2 * reach + 2
    out = np.empty(len(degs))
    # The rounder plus each direction's shift, for every cell (adding a full array is several
    # times faster than broadcasting a column).
    offset = np.empty((block, n))
    offset[...] = (_ROUNDER + reach + np.arange(block, dtype=np.float64) * span)[:, None]
    x = np.empty((block, n))
    tmp = np.empty((block, n))
    for b0 in range(0, len(degs), block):
        ts = [math.radians(float(d)) for d in degs[b0:b0 + block]]
        k = len(ts)
        xk, tk = x[:k], tmp[:k]
        total = np.zeros(k, dtype=np.int64)
        for c, s in (([math.cos(t) for t in ts], [math.sin(t) for t in ts]),
                     ([-math.sin(t) for t in ts], [math.cos(t) for t in ts])):
            np.multiply.outer(s, neg_cols, out=xk)
            np.multiply.outer(c, rows, out=tk)
            xk += tk
            xk += offset[:k]
            v = xk.view(np.int64)
            v -= _ROUNDER_BITS
            counts = np.bincount(v.ravel(), minlength=k * span).reshape(k, span)
            total += (counts * counts).sum(axis=1)  # exact: integers
        out[b0:b0 + k] = total.astype(np.float64) / n
    return out


#: Wall masks up to this many rows and columns (a door's surroundings, LOCAL_WALLS_M either side
#: at 5 cm cells, fits) have their cells' line numbers along the coarse directions read from a
#: :class:`_LineTable`, a table by each cell's (row, column) in the mask.
LINE_TABLE_SIDE: Final = 128
#: In the table, each line number is stored shifted by this (more than any line number's size:
#: the table's diagonal, 128 * sqrt(2) cells) and each direction's numbers by a span of twice
#: it, so that one count over the table's rows gives every direction's counts apart.
_TABLE_SHIFT: Final = 184
_TABLE_SPAN: Final = 2 * _TABLE_SHIFT + 2


class _LineTable:
    """The line numbers :func:`_line_scores` works out for a cell at (row, column) along each of
    a set of directions and its right angle (a pure function of those), kept for the cells of a
    LINE_TABLE_SIDE square as they are first met: a door's surroundings are scored from numbers
    read, not worked out again for each door (wall cells placed alike in their windows recur).
    One table, of the coarse directions, kept for the process (the refinements around a peak
    differ from building to building: worked out each time)."""

    def __init__(self, degs: FloatArray) -> None:
        self.degs = degs.copy()
        # The smallest integer type that holds every shifted number (fewer bytes to read per
        # cell, and less memory kept): below 2 * len(degs) * _TABLE_SPAN.
        top = 2 * len(degs) * _TABLE_SPAN
        dtype = np.int16 if top <= np.iinfo(np.int16).max else np.int32
        self.numbers = np.empty((LINE_TABLE_SIDE * LINE_TABLE_SIDE, 2 * len(degs)), dtype=dtype)
        self.known = np.zeros(LINE_TABLE_SIDE * LINE_TABLE_SIDE, dtype=bool)

    def scores(self, rr: npt.NDArray[np.intp], cc: npt.NDArray[np.intp]) -> FloatArray:
        """``_line_scores(rr, -cc, self.degs)``, exactly, for cells inside the square (call
        with the table's lock held)."""
        flat = rr * LINE_TABLE_SIDE + cc
        new = flat[~self.known[flat]]
        if new.size:
            self.numbers[new] = self._work_out(new // LINE_TABLE_SIDE, new % LINE_TABLE_SIDE)
            self.known[new] = True
        v = self.numbers[flat]
        k = 2 * len(self.degs)
        counts = np.bincount(v.ravel(), minlength=k * _TABLE_SPAN).reshape(k, _TABLE_SPAN)
        sq = (counts * counts).sum(axis=1)
        return np.asarray((sq[0::2] + sq[1::2]).astype(np.float64) / len(flat), dtype=np.float64)

    def _work_out(self, rr: npt.NDArray[np.intp], cc: npt.NDArray[np.intp]) -> IntArray:
        """The shifted line numbers of cells, with :func:`_line_scores`' arithmetic (see there),
        every direction (and its right angle) at once."""
        ts = [math.radians(float(d)) for d in self.degs]
        sin = [v for t in ts for v in (math.sin(t), math.cos(t))]
        cos = [v for t in ts for v in (math.cos(t), -math.sin(t))]
        x = np.multiply.outer(sin, -cc.astype(np.float64))
        x += np.multiply.outer(cos, rr.astype(np.float64))
        x += (_ROUNDER + _TABLE_SHIFT + np.arange(len(sin), dtype=np.float64) * _TABLE_SPAN)[:, None]
        v = x.view(np.int64)
        v -= _ROUNDER_BITS
        return v.T


_COARSE_DEGS: Final = np.arange(0.0, 90.0, DIRECTION_BIN_DEG)
_COARSE_DEGS.flags.writeable = False
#: The directions a peak at coarse direction p is refined over: p plus these (a tenth of a bin).
_FINE_STEPS: Final = np.linspace(-DIRECTION_BIN_DEG, DIRECTION_BIN_DEG, 21)
_FINE_STEPS.flags.writeable = False
#: Tables of refined directions kept, one per coarse peak (1.4 MB each once filled): a building
#: has a few wall directions, and the doors of one map are refined about the same peaks.
FINE_TABLES_KEPT: Final = 4
#: The coarse directions' table, made on first use (12 MB once filled), the tables of the
#: refinements about the latest coarse peaks (most recent last), and their lock.
_coarse_table: list[_LineTable] = []
_fine_tables: dict[int, _LineTable] = {}
_coarse_lock = threading.Lock()


def _coarse_scores(rr: npt.NDArray[np.intp], cc: npt.NDArray[np.intp]) -> FloatArray:
    """``_line_scores(rr, -cc, _COARSE_DEGS)`` for cells (rr, cc) of a mask within
    LINE_TABLE_SIDE, from the table."""
    with _coarse_lock:
        if not _coarse_table:
            _coarse_table.append(_LineTable(_COARSE_DEGS))
        return _coarse_table[0].scores(rr, cc)


def _fine_scores(peak: int, rr: npt.NDArray[np.intp], cc: npt.NDArray[np.intp]) -> FloatArray:
    """``_line_scores(rr, -cc, _COARSE_DEGS[peak] + _FINE_STEPS)`` for cells (rr, cc) of a mask
    within LINE_TABLE_SIDE, from that peak's table."""
    with _coarse_lock:
        table = _fine_tables.pop(peak, None)
        if table is None:
            table = _LineTable(_COARSE_DEGS[peak] + _FINE_STEPS)
            while len(_fine_tables) >= FINE_TABLES_KEPT:
                del _fine_tables[next(iter(_fine_tables))]  # the least recently used
        _fine_tables[peak] = table
        return table.scores(rr, cc)


def dominant_directions(wall: BoolArray) -> list[float]:
    """The building's wall directions (radians in the (col, row) plane, in [0, pi)), main first.

    Each candidate direction modulo 90 degrees (a right-angled plan: a direction and its right
    angle together) is scored by how many wall cells line up along it (:func:`_line_scores`,
    a Hough transform's peak in short); the best one, refined, is the building's; other
    peaks nearly as strong (a wing at an angle) are directions too. The edge directions of
    the cells themselves would not do: a wall's pixel staircase turns them towards 45 degrees.
    """
    rr, cc = nonzero2(wall)
    if rr.size < 2:
        return []
    if rr.size > DIRECTION_MAX_CELLS:  # a fixed, even sample of the cells is as good
        pick = np.linspace(0, rr.size - 1, DIRECTION_MAX_CELLS).astype(np.int64)
        rr, cc = rr[pick], cc[pick]
    rows, cols = rr.astype(np.float64), cc.astype(np.float64)
    grid_deg = _COARSE_DEGS
    neg_cols = -cols
    # A small mask (a door's surroundings) is scored from the table of line numbers (a fixed
    # sample of the cells would not be the mask's own cells).
    small = max(wall.shape) <= LINE_TABLE_SIDE and rr.size == np.count_nonzero(wall)
    score = _coarse_scores(rr, cc) if small else _line_scores(rows, neg_cols, grid_deg)
    base = float(score.min())
    # Each score against its neighbours round the circle of directions (``np.roll`` by 1 and by
    # -1, without its generic set-up).
    before = np.concatenate((score[-1:], score[:-1]))
    after = np.concatenate((score[1:], score[:1]))
    peaks = np.flatnonzero((score >= before) & (score > after))
    peaks = peaks[np.argsort(-score[peaks])]
    taken: list[float] = []
    for p in peaks.tolist():
        if taken and score[p] - base < SECOND_DIRECTION_MIN_SHARE * (score[peaks[0]] - base):
            break
        # Refined to a tenth of a bin around the peak.
        fine = grid_deg[p] + _FINE_STEPS
        fine_score = _fine_scores(p, rr, cc) if small else _line_scores(rows, neg_cols, fine)
        deg = float(fine[int(np.argmax(fine_score))] % 90.0)
        if all(min(abs(deg - t) % 90.0, 90.0 - abs(deg - t) % 90.0) >= DIRECTION_MIN_SEPARATION_DEG
               for t in taken):
            taken.append(deg)
    out: list[float] = []
    for deg in taken:
        out += [math.radians(deg), math.radians(deg + 90.0)]
    return out


@dataclass(frozen=True)
class WallDirections:
    """The wall directions (:func:`dominant_directions`) of one wall mask, kept with the mask so
    that a later step with the same walls reuses them instead of scoring every direction again."""

    wall: BoolArray
    directions: list[float]

    def of(self, wall: BoolArray) -> list[float]:
        """The directions of ``wall``: these when it is this very mask, else found anew."""
        if self.wall.shape == wall.shape and np.array_equal(self.wall, wall):
            return list(self.directions)
        return dominant_directions(wall)


class _LineSampler(Generic[_Cell]):
    """Reads a mask (or a code per cell) at (u, v): u along the direction (cos_t, sin_t) in the
    (col, row) plane, v across it; off the grid reads False (0)."""

    def __init__(self, mask: npt.NDArray[_Cell], cos_t: float, sin_t: float) -> None:
        self.mask: npt.NDArray[_Cell] = mask
        self.cos_t, self.sin_t = cos_t, sin_t

    def rc(self, u: FloatArray, v: FloatArray) -> tuple[FloatArray, FloatArray]:
        return u * self.sin_t + v * self.cos_t, u * self.cos_t - v * self.sin_t

    def __call__(self, u: FloatArray, v: FloatArray) -> npt.NDArray[_Cell]:
        r, c = self.rc(u, v)
        ri, ci = np.rint(r).astype(np.int64), np.rint(c).astype(np.int64)
        h, w = self.mask.shape
        # On the grid: 0 <= ri < h and 0 <= ci < w (a negative index read unsigned is past the end).
        inside = (ri.view(np.uint64) < h) & (ci.view(np.uint64) < w)
        # Read every sample (clamped onto the grid), then zero those off it. (np.maximum /
        # np.minimum: np.clip's checks of its bounds cost more than clamping small arrays.)
        np.maximum(ri, 0, out=ri)
        np.minimum(ri, h - 1, out=ri)
        np.maximum(ci, 0, out=ci)
        np.minimum(ci, w - 1, out=ci)
        out = take2(self.mask, ri, ci)
        out *= inside
        return out


def _ragged(counts: IntArray) -> tuple[IntArray, IntArray]:
    """For groups of ``counts`` items laid end to end: each item's group and its index in it."""
    group = np.repeat(np.arange(counts.size), counts)
    starts = np.cumsum(counts) - counts
    return group, np.arange(int(counts.sum())) - starts[group]


def _runs_on(floor_at: _LineSampler[np.bool_], u0: FloatArray, u1: FloatArray, v: FloatArray) -> BoolArray:
    """Per candidate: is the floor continuous along the line at offset ``v`` from u0 to u1
    (cells; sampled as ``np.linspace(u0, u1, n)`` with n = the cells spanned, at least 2)?"""
    n = np.maximum(2, np.ceil(np.abs(u1 - u0)).astype(np.int64) + 1)
    group, k = _ragged(n)
    step = (u1 - u0) / (n - 1)
    u = k.astype(np.float64) * step[group] + u0[group]
    last = np.cumsum(n) - 1
    u[last] = u1
    ok = floor_at(u, v[group])
    return np.logical_and.reduceat(ok, last - n + 1)


def _band_runs(on: BoolArray, reach: int) -> tuple[BoolArray, IntArray, IntArray]:
    """Per row of ``on`` (samples across the line, the line at index ``reach``): whether a cell
    of the line's band is set, and the first and last cells of the run of set cells through the
    band's first set cell."""
    band = on[..., reach - LINE_BAND_CELLS:reach + LINE_BAND_CELLS + 1]
    has: BoolArray = np.asarray(band.any(axis=-1))
    s = (reach - LINE_BAND_CELLS + band.argmax(axis=-1))[..., None]
    idx = np.arange(on.shape[-1])
    after = ~on & (idx > s)
    hi: IntArray = np.where(after.any(axis=-1), after.argmax(axis=-1), on.shape[-1]) - 1
    before = (~on & (idx < s))[..., ::-1]
    lo: IntArray = np.where(before.any(axis=-1), on.shape[-1] - 1 - before.argmax(axis=-1), -1) + 1
    return has, lo, hi


def _through_depth(wall_at: _LineSampler[np.bool_], ua: FloatArray, ub: FloatArray, v: FloatArray,
                   reach: int, leaves: FloatArray | None = None) -> FloatArray:
    """Per candidate: how deep (cells, across the line at ``v``) the gap between the wall cells
    at ``ua`` and ``ub`` is: on each side of the line, the shorter of the two jambs' reaches
    across it (the wall's own thickness at a doorway; a slot's length between two pieces
    standing in a row). Each jamb's reach is the longest run of wall across the line through
    its last few cells. ``leaves``: per candidate, jamb and side (-v, +v), an open door leaf's
    length there (:func:`_jamb_leaves`; 0: none): a leaf is no wall, its jamb reaches no way
    across on that side."""
    offs = np.arange(-reach, reach + 1, dtype=np.float64)
    back = np.arange(3, dtype=np.float64)
    u = np.stack([ua[:, None] - back, ub[:, None] + back], axis=1)  # (candidate, jamb, cell)
    col = wall_at(u[..., None], (v[:, None] + offs)[:, None, None, :])
    has, lo, hi = _band_runs(col, reach)
    plus = np.where(has, hi - reach, 0).max(axis=2, initial=0)
    minus = np.where(has, reach - lo, 0).max(axis=2, initial=0)
    if leaves is not None:
        minus = np.where(leaves[:, :, 0] > 0, 0, minus)
        plus = np.where(leaves[:, :, 1] > 0, 0, plus)
    return (plus.min(axis=1) + minus.min(axis=1) + 1).astype(np.float64)


def _jamb_leaves(wall_at: _LineSampler[np.bool_], floor_at: _LineSampler[np.bool_], ua: FloatArray,
                 ub: FloatArray, v: FloatArray, res: float) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Per candidate gap (between the wall cells at ``ua`` and ``ub`` on the line at ``v``), jamb
    (a, b) and side of the line (-v, +v): the length (cells) of the open door leaf standing there
    (0: none), its position along the line, and where the wall's face is on that side (cells
    from the line, beside the jamb: where the leaf begins).

    A door leaf swung open stands across the wall line at a jamb, hinged there: a thin panel
    (LEAF_MAX_THICKNESS_M) with floor on both of its faces, longer than a wall is thick, no
    longer than the opening it closes (a double door's two leaves are half of it each) nor than
    the widest single leaf (LEAF_MAX_LENGTH_M), and its far edge stands free in the floor. The
    side of a cabinet or a shelf unit in a row has the unit's body behind it; a corridor's wall
    at a junction runs on for metres; neither is a leaf."""
    reach = math.ceil(LEAF_MAX_LENGTH_M / res) + LEAF_TIP_CELLS + 1
    offs = np.arange(-reach, reach + 1, dtype=np.float64)
    back = np.arange(3, dtype=np.float64)
    u = np.stack([ua[:, None] - back, ub[:, None] + back], axis=1)  # (candidate, jamb, cell)
    # Across the line from the jamb's last few cells, wall in any of them (a leaf scanned at an
    # angle to the grid is a staircase a cell or two wide).
    col = np.asarray(wall_at(u[..., None], (v[:, None] + offs)[:, None, None, :]).any(axis=2), dtype=bool)
    has, lo, hi = _band_runs(col, reach)
    ext = np.stack([np.where(has, reach - lo, 0), np.where(has, hi - reach, 0)], axis=-1)  # (candidate, jamb, side)
    length = ext.astype(np.float64)
    u_leaf = np.repeat(u[:, :, 1, None], 2, axis=-1)
    width = (ub - ua - 1)[:, None, None]
    # A leaf swings to one side of its wall: on the other, the jamb is the wall's own face (a
    # desk divider or a partition crossing the line stands out on both sides).
    face = math.ceil(WALL_MAX_THICKNESS_M / 2 / res) + 1
    other = ext[:, :, ::-1]
    maybe = ((length * res > WALL_MAX_THICKNESS_M) & (length * res <= LEAF_MAX_LENGTH_M)
             & (length <= width / 2 + LEAF_SLACK_M / res) & (length < reach - LEAF_TIP_CELLS)
             & (other <= face))
    # The two leaves of a double door stand at its two jambs, on the same side.
    maybe &= maybe[:, ::-1, :]
    out = np.zeros(length.shape)
    # The wall's face on each side, beside the jamb (past where a leaf's hinge could stand).
    thick = _leaf_thickness_cells(res)
    u_far = np.stack([ua - (thick + 3), ub + (thick + 3)], axis=1)  # (candidate, jamb)
    beside = np.asarray(wall_at(u_far[..., None], (v[:, None] + offs)[:, None, :]), dtype=bool)
    got, lo_f, hi_f = _band_runs(beside, reach)
    wall_face = np.stack([np.where(got, reach - lo_f, 0), np.where(got, hi_f - reach, 0)], axis=-1) + 1.0
    if not maybe.any():
        return out, u_leaf, wall_face
    i, j, s = np.nonzero(maybe)
    sign = np.where(s == 1, 1.0, -1.0)
    n = length[i, j, s]
    # Thin, with floor on both faces, beyond the wall's own half thickness to the leaf's end.
    t = np.arange(face, reach + 1, dtype=np.float64)[None, :]
    valid = t <= (n - 1)[:, None]
    side = thick + 2
    across = np.arange(-side, side + 1, dtype=np.float64)
    uu = u_leaf[i, j, s][:, None, None] + across[None, None, :]
    vv = (v[i][:, None] + sign[:, None] * t)[:, :, None]
    w_on = wall_at(uu, vv)
    f_on = floor_at(uu, vv)
    got, lo2, hi2 = _band_runs(w_on, side)
    idx = np.arange(across.size)
    thin = got & (hi2 - lo2 + 1 <= thick)
    floor_lo = (f_on & (idx >= (lo2 - 2)[..., None]) & (idx < lo2[..., None])).any(axis=-1)
    floor_hi = (f_on & (idx > hi2[..., None]) & (idx <= (hi2 + 2)[..., None])).any(axis=-1)
    ok_at = thin & floor_lo & floor_hi
    good = (ok_at & valid).sum(axis=1)
    panel = (valid.sum(axis=1) > 0) & (good >= LEAF_MIN_SHARE * valid.sum(axis=1))
    # ... up to its very edge: the side of a box (a shelf unit, a pallet) turns into the box's
    # back face there, a leaf ends on its own.
    last = np.clip(n.astype(np.int64) - face, 0, t.shape[1] - 1)
    rows = np.arange(n.size)
    panel &= ok_at[rows, last] & ok_at[rows, np.maximum(last - 1, 0)]
    # Its far edge stands free: floor just past it.
    tip_t = n[:, None] + np.arange(1, LEAF_TIP_CELLS + 1, dtype=np.float64)[None, :]
    tip_u = u_leaf[i, j, s][:, None, None] + np.arange(-1.0, 2.0)[None, None, :]
    tip = floor_at(tip_u, (v[i][:, None] + sign[:, None] * tip_t)[:, :, None])
    free_tip = tip.mean(axis=(1, 2)) >= LEAF_TIP_MIN_FLOOR_SHARE
    ok = panel & free_tip
    out[i[ok], j[ok], s[ok]] = n[ok]
    pair = (out > 0) & (out[:, ::-1, :] > 0)
    return np.where(pair, out, 0.0), u_leaf, wall_face


def _leaf_thickness_cells(res: float) -> int:
    """The most cells a door leaf spans across it (LEAF_MAX_THICKNESS_M and a cell of spread)."""
    return math.ceil(LEAF_MAX_THICKNESS_M / res - 1e-9) + 1


def _leaf_cells(floor_at: _LineSampler[np.bool_], wall_at: _LineSampler[np.bool_], leaves: FloatArray,
                u_leaf: FloatArray, wall_face: FloatArray, v: FloatArray, res: float) -> list[tuple[IntArray, IntArray]]:
    """Per candidate: the (rows, cols) of the wall cells of its door leaves (:func:`_jamb_leaves`;
    empty where it has none), from the wall's face on (``wall_face``: the jamb stays wall)."""
    thick = _leaf_thickness_cells(res)
    h, w = floor_at.mask.shape
    out: list[tuple[IntArray, IntArray]] = []
    for k in range(leaves.shape[0]):
        rows: list[IntArray] = []
        cols: list[IntArray] = []
        for j, s in zip(*np.nonzero(leaves[k]), strict=True):
            n = float(leaves[k, j, s])
            depth = np.arange(float(wall_face[k, j, s]), n + 1.0)
            uu = np.repeat(u_leaf[k, j, s] + np.arange(-thick, thick + 1.0), depth.size)
            vv = np.tile(v[k] + (1.0 if s == 1 else -1.0) * depth, 2 * thick + 1)
            on = wall_at(uu, vv).astype(bool)
            r, c = floor_at.rc(uu[on], vv[on])
            ri, ci = np.rint(r).astype(np.int64), np.rint(c).astype(np.int64)
            inside = (ri >= 0) & (ri < h) & (ci >= 0) & (ci < w)
            rows.append(ri[inside])
            cols.append(ci[inside])
        empty = np.zeros(0, dtype=np.int64)
        out.append((np.concatenate(rows) if rows else empty, np.concatenate(cols) if cols else empty))
    return out


def _with_floor(floor_at: _LineSampler[np.bool_], cells: list[tuple[IntArray, IntArray]]) -> _LineSampler[np.bool_]:
    """``floor_at`` with ``cells`` read as floor (door leaves: an open leaf stands in the room it
    swings into, whose floor runs on behind it)."""
    if not any(r.size for r, _ in cells):
        return floor_at
    floor = floor_at.mask.copy()
    for r, c in cells:
        floor[r, c] = True
    return _LineSampler(floor, floor_at.cos_t, floor_at.sin_t)


def _partition_share(both_at: _LineSampler[np.uint8], u_end: FloatArray, sign: float, v: FloatArray, side: int,
                     reach: int, thin: int) -> FloatArray:
    """Per candidate: of the wall cells on the line at ``v`` over ``side`` cells from ``u_end``
    on (towards ``sign``), the share where the wall across the line is at most ``thin`` cells
    thick with floor just beyond both of its faces (within two cells); 0 with no wall cell.
    ``both_at`` reads WALL_BIT and FLOOR_BIT of a cell at once."""
    u = (u_end[:, None] + sign * np.arange(side, dtype=np.float64))[..., None]
    vv = (v[:, None] + np.arange(-reach, reach + 1, dtype=np.float64))[:, None, :]
    both = both_at(u, vv)  # (candidate, cell along, cell across)
    w, f = (both & WALL_BIT) > 0, (both & FLOOR_BIT) > 0
    # The wall's thickness is that of what is not floor across it: a wall's two faces with its
    # unscanned inside between them (a thick wall or a block drawn as its outline) are one wall.
    on = _band_runs(w, reach)[0]
    _, lo, hi = _band_runs(~f, reach)
    idx = np.arange(w.shape[-1])
    floor_before = (f & (idx >= (lo - 2)[..., None]) & (idx < lo[..., None])).any(axis=-1)
    floor_after = (f & (idx > hi[..., None]) & (idx <= (hi + 2)[..., None])).any(axis=-1)
    good = (on & (hi - lo + 1 <= thin) & floor_before & floor_after).sum(axis=1)
    n_on = on.sum(axis=1)
    return np.where(n_on > 0, good / np.maximum(n_on, 1), 0.0)


@dataclass(frozen=True)
class _LineCandidates:
    """The door-wide gaps along one wall direction: gap i lies between ``pos[i]`` and
    ``pos[i + 1]`` on ``line[i]`` for i in ``cand`` (positions along and lines across the
    direction, offset by ``umin`` / ``vmin``)."""

    cos_t: float
    sin_t: float
    cand: IntArray
    line: IntArray
    pos: IntArray
    umin: int
    vmin: int
    #: Per candidate: a gap of a front (not between two solid stretches of wall).
    front: BoolArray | None = None


def _line_candidates(wall: BoolArray, dirs: list[float], resolution_m: float, params: AnalysisParams,
                     max_width_m: float, front_max_width_m: float = 0.0,
                     arch_max_width_m: float = 0.0) -> list[_LineCandidates]:
    """Per wall direction, the gaps ``door_min_width_m`` to ``max_width_m`` wide in its wall
    lines where the line runs on past both ends, occupied on ``seg_wall_line_side_share`` of
    ``seg_wall_line_side_m`` (a wall, not the corner of a piece of furniture).

    With ``arch_max_width_m``, also the wider gaps up to that width where the line runs on
    that solid past each end for at least half the gap's width (see the module doc: an arch).

    With ``front_max_width_m``, also the gaps up to that width in a *front*: a stretch of the
    line broken into pieces (piers, mullions, door frames, the glass the lidar saw square on)
    no farther apart than that, which runs from solid wall to solid wall (each solid over
    ``FRONT_ANCHOR_M``) over at most ``FRONT_MAX_LENGTH_M``: a glass front or a row of windows
    between piers stands in the wall line it continues, however little of it the scan shows."""
    res = resolution_m
    gmin = (params.door_min_width_m - res) / res
    gmax = (max_width_m + res) / res
    fmax = (front_max_width_m + res) / res
    amax = (arch_max_width_m + res) / res
    side = max(2, round(params.seg_wall_line_side_m / res))
    share = params.seg_wall_line_side_share * side
    rr, cc = nonzero2(wall)
    rr_f, cc_f = rr.astype(np.float64), cc.astype(np.float64)
    # A front's pieces are pieces of wall, not specks (a chair's or a table's legs, the dots a
    # row of posts leaves): small compact pieces play no part in a front.
    pieces = _not_specks(wall, FRONT_PIECE_MIN_M / res)[rr, cc] if fmax > gmin else None
    out: list[_LineCandidates] = []
    for theta in dirs:
        cos_t, sin_t = math.cos(theta), math.sin(theta)
        u = np.rint(cc_f * cos_t + rr_f * sin_t).astype(np.int64)
        v = np.rint(-cc_f * sin_t + rr_f * cos_t).astype(np.int64)
        umin, vmin = int(u.min()), int(v.min()) - LINE_BAND_CELLS
        span = int(u.max()) - umin + 1
        key, line, pos = _line_keys(u - umin, v - vmin, span)
        cand, walled = _gap_candidates(key, line, pos, span, side, share, gmin, gmax)
        cand = cand[walled]
        if amax > gmax:
            # An arch is cut in a solid wall: beside an opening that wide, only a line drawn
            # solid (``seg_wall_line_min_share``, as the flood's wall lines) tells a wall from a
            # row of furniture or clutter standing in line.
            arch, walled = _gap_candidates(key, line, pos, span, side, params.seg_wall_line_min_share * side,
                                           gmax, amax, arch=True)
            cand = np.union1d(cand, arch[walled])
        if cand.size:
            out.append(_LineCandidates(cos_t, sin_t, cand, line, pos, umin, vmin))
        if pieces is None or not pieces.any():
            continue
        # Fronts: gaps with a pier at one end at least (solid wall at both is a plain gap,
        # judged above: wider than a door, it is an opening between two walls).
        key, line, pos = _line_keys(u[pieces] - umin, v[pieces] - vmin, span)
        cand, walled = _gap_candidates(key, line, pos, span, side, share, gmin, fmax)
        anchor = max(2, round(FRONT_ANCHOR_M / res))
        front = ~walled & _in_front(key, line, pos, cand, span, anchor,
                                    params.seg_wall_line_side_share * anchor, gmin, fmax,
                                    FRONT_MAX_LENGTH_M / res)
        # ... and open floor across the whole gap a wall's thickness either side of the line:
        # where a wobbly wall runs beside the line, the line misses it in places, and those
        # are no gaps.
        if front.any():
            raw = np.unique((v - vmin) * span + (u - umin))
            i = np.flatnonzero(front)
            p0, p1 = pos[cand[i]] + 1, pos[cand[i] + 1]
            li = line[cand[i]]
            beside = np.zeros(i.size, dtype=np.int64)
            clear = LINE_BAND_CELLS + max(1, round(FRONT_BESIDE_M / res))
            for dv in range(-clear, clear + 1):
                beside += _count(raw, (li + dv) * span, p0, p1)
            front[i] = beside <= FRONT_BESIDE_MAX_SHARE * (p1 - p0)
            # ... and its ends stand in the line: a wall crossing it there (a corridor's side
            # walls, for a line drawn across the corridor) is no pier of this line.
            reach = max(1, round(FRONT_CROSSING_M / res))
            crossing = np.zeros(i.size, dtype=bool)
            for a, b in ((p0 - 1 - LINE_BAND_CELLS, p0), (p1, p1 + 1 + LINE_BAND_CELLS)):
                sides = []
                for sign in (-1, 1):
                    n = np.zeros(i.size, dtype=np.int64)
                    for d in range(LINE_BAND_CELLS + 1, LINE_BAND_CELLS + 1 + reach):
                        n += _count(raw, (li + sign * d) * span, a, b)
                    sides.append(n > 0)
                crossing |= sides[0] & sides[1]
            front[i] &= ~crossing
        cand = cand[front]
        if cand.size:
            out.append(_LineCandidates(cos_t, sin_t, cand, line, pos, umin, vmin,
                                       np.ones(cand.size, dtype=bool)))
    return out


def _count(raw: IntArray, row0: IntArray, a: IntArray, b: IntArray) -> IntArray:
    """Per item: how many of the sorted keys ``raw`` lie in [row0 + a, row0 + b)."""
    return np.searchsorted(raw, row0 + b) - np.searchsorted(raw, row0 + a)


def _line_keys(u: IntArray, v: IntArray, span: int) -> tuple[IntArray, IntArray, IntArray]:
    """The distinct (line, position) keys (line x span + position) of the wall cells at
    positions ``u`` along and ``v`` across a direction (``v`` at least LINE_BAND_CELLS), in
    order: each cell is on the lines within the band across it. Returns (key, line, position)."""
    vv = np.concatenate([v + k for k in range(-LINE_BAND_CELLS, LINE_BAND_CELLS + 1)])
    uu = np.tile(u, 2 * LINE_BAND_CELLS + 1)
    # A mark per key, cheaper than np.unique.
    flat = vv * span + uu
    seen = np.zeros(int(flat.max()) + 1, dtype=bool)
    seen[flat] = True
    key = np.flatnonzero(seen)
    line, pos = divmod_int(key, span)
    return key, line, pos


def _gap_candidates(key: IntArray, line: IntArray, pos: IntArray, span: int, side: int, share: float,
                    gmin: float, gmax: float, arch: bool = False) -> tuple[IntArray, BoolArray]:
    """The gaps ``gmin`` to ``gmax`` cells wide between the sorted wall ``key`` cells of a line
    (gap i between key i and i + 1), and whether the line is solid (``share`` of ``side``
    cells) just before and just after each. ``arch``: over at least half the gap's width
    (``share`` of it) instead, when that is longer than ``side``."""
    gap = np.diff(pos) - 1
    cand = np.flatnonzero((line[1:] == line[:-1]) & (gap >= gmin) & (gap <= gmax))
    sides = np.full(cand.size, side, dtype=np.int64)
    if arch:
        sides = np.maximum(sides, np.ceil(gap[cand] / 2).astype(np.int64))
    need = share / side * sides
    lo_before = np.maximum(key[cand] - sides + 1, line[cand] * span)
    before = np.searchsorted(key, key[cand], side="right") - np.searchsorted(key, lo_before, side="left")
    hi_after = np.minimum(key[cand + 1] + sides - 1, line[cand + 1] * span + span - 1)
    after = np.searchsorted(key, hi_after, side="right") - np.searchsorted(key, key[cand + 1], side="left")
    return cand, (before >= need) & (after >= need)


def _not_specks(wall: BoolArray, min_cells: float) -> BoolArray:
    """The cells of ``wall`` in 8-connected pieces whose bounding box reaches at least
    ``min_cells`` along its longer side."""
    lab, n = ndi.label(wall, structure=EIGHT)
    if n == 0:
        return np.zeros_like(wall)
    big = np.zeros(n + 1, dtype=bool)
    for k, sl in enumerate(ndi.find_objects(lab), start=1):
        if sl is not None:
            big[k] = max(sl[0].stop - sl[0].start, sl[1].stop - sl[1].start) >= min_cells
    return big[lab]


def _in_front(key: IntArray, line: IntArray, pos: IntArray, cand: IntArray, span: int, side: int,
              share: float, gmin: float, fmax: float, max_len: float) -> npt.NDArray[np.bool_]:
    """Per candidate gap (between wall cells ``cand`` and ``cand + 1`` of the sorted ``key`` =
    line x span + pos): is it in a front, a run of the line whose gaps are at most ``fmax``
    cells, with solid wall (``share`` of ``side`` cells) ending at or before the gap's first
    end and solid wall starting at or after its second, at most ``max_len`` cells apart, and
    at least one more gap (``gmin`` cells or wider) between them?"""
    n = key.size
    idx = np.arange(n)
    # Solid wall ending at cell j (looking back from it) / starting at cell j (looking on).
    back = np.searchsorted(key, key, side="right") - np.searchsorted(
        key, np.maximum(key - side + 1, line * span), side="left")
    on = np.searchsorted(key, np.minimum(key + side - 1, line * span + span - 1), side="right") - idx
    # Runs: a new one starts where the line changes or a gap is wider than a front's.
    brk = np.ones(n, dtype=bool)
    brk[1:] = (line[1:] != line[:-1]) | (np.diff(pos) - 1 > fmax)
    run = np.cumsum(brk)
    last_back = np.maximum.accumulate(np.where(back >= share, idx, -1))
    next_on = np.minimum.accumulate(np.where(on >= share, idx, n)[::-1])[::-1]
    a, b = last_back[cand], next_on[cand + 1]
    ok = (a >= 0) & (b < n)
    a, b = np.where(ok, a, 0), np.where(ok, b, 0)
    # A front is broken by pieces: between its solid ends it has more than this one gap (a
    # single wide gap between two walls is an opening, an arch, a corridor's branch).
    gaps_before = np.concatenate([[0], np.cumsum(np.diff(pos) - 1 >= gmin)])  # gaps before key j
    return ok & (run[a] == run[cand]) & (run[b] == run[cand + 1]) & (run[cand] == run[cand + 1]) & \
        (pos[b] - pos[a] <= max_len) & \
        (gaps_before[b] - gaps_before[a] >= 2)


def wall_gaps(wall: BoolArray, floor: BoolArray, resolution_m: float, params: AnalysisParams,
              directions: list[float] | None = None) -> list[WallGap]:
    """The door-wide gaps in the wall lines of ``wall`` that part two spaces of ``floor`` (see
    the module doc). ``directions``: the wall directions, when known (else found here)."""
    if params.seg_wall_line_gap_max_m <= 0 or not wall.any():
        return []
    dirs = dominant_directions(wall) if directions is None else directions
    res = resolution_m
    side = max(2, round(params.seg_wall_line_side_m / res))
    past = SIDE_PAST_JAMB_M / res
    depths = [d / res for d in SIDE_DEPTHS_M]
    max_depth = WALL_MAX_THICKNESS_M / res + 1.0  # + the cell the line runs through
    thin = round(WALL_MAX_THICKNESS_M / res) + 1
    reach = math.ceil(2 * params.door_max_depth_m / res) + 2
    both = np.where(wall, WALL_BIT, 0).astype(np.uint8) | np.where(floor, FLOOR_BIT, 0).astype(np.uint8)
    out: list[WallGap] = []
    for lc in _line_candidates(wall, dirs, res, params, params.seg_wall_line_gap_max_m,
                               params.seg_wall_gap_max_width_m, params.seg_wall_line_arch_max_m):
        floor_at = _LineSampler(floor, lc.cos_t, lc.sin_t)
        wall_at = _LineSampler(wall, lc.cos_t, lc.sin_t)
        both_at = _LineSampler(both, lc.cos_t, lc.sin_t)
        for b0 in range(0, lc.cand.size, CANDIDATE_BLOCK):
            front = None if lc.front is None else lc.front[b0:b0 + CANDIDATE_BLOCK]
            out += _gaps_kept(lc.cand[b0:b0 + CANDIDATE_BLOCK], lc.line, lc.pos, lc.umin, lc.vmin, floor_at,
                              wall_at, both_at, _GapScales(past, depths, max_depth, thin, reach, side), res,
                              front)
    widest_door = params.seg_wall_line_gap_max_m + res
    if any(g.width_m > widest_door and not g.in_front for g in out):
        # An arch is cut in one of the building's walls: both of its ends stand in the wall
        # network that reaches the building's shell (the outside, unknown or its outer walls).
        # Free-standing screens, desk pods and shelf units stand on the floor, however solid
        # and long: a wide gap between two of them is an open floor's aisle.
        shell = _shell(floor)
        out = [g for g in out if g.width_m <= widest_door or g.in_front
               or (_touches(shell, g.end_a_rc) and _touches(shell, g.end_b_rc))]
    return out


def _shell(floor: BoolArray) -> BoolArray:
    """The non-floor cells connected (8-connected) to the grid's border: the building's outer
    walls, the unknown outside them and every wall joined to them."""
    lab, n = ndi.label(~floor, structure=EIGHT)
    keep = np.zeros(n + 1, dtype=bool)
    edge = np.concatenate([lab[0, :], lab[-1, :], lab[:, 0], lab[:, -1]])
    keep[edge] = True
    keep[0] = False
    return keep[lab]


def _touches(mask: BoolArray, rc: tuple[float, float]) -> bool:
    """Is a cell of ``mask`` within a cell of the continuous (row, col) ``rc`` (a wall line's
    band is a cell either side of it)?"""
    r, c = round(rc[0]), round(rc[1])
    h, w = mask.shape
    return bool(mask[max(r - 1, 0):min(r + 2, h), max(c - 1, 0):min(c + 2, w)].any())


@dataclass(frozen=True)
class _GapScales:
    """The lengths (cells) a candidate gap is judged with (see :func:`wall_gaps`)."""

    past: float
    depths: list[float]
    max_depth: float
    thin: int
    reach: int
    side: int


def _gaps_kept(cand: IntArray, line: IntArray, pos: IntArray, umin: int, vmin: int,
               floor_at: _LineSampler[np.bool_], wall_at: _LineSampler[np.bool_],
               both_at: _LineSampler[np.uint8], k: _GapScales, res: float,
               front: BoolArray | None = None) -> list[WallGap]:
    """The candidate gaps (between ``pos[i]`` and ``pos[i + 1]`` on ``line[i]``, i in ``cand``)
    that are doorways between two spaces (see the module doc), all candidates at once;
    ``front``: which candidates are gaps of a front."""
    v_line = (line[cand] + vmin).astype(np.float64)
    ua, ub = (pos[cand] + umin).astype(np.float64), (pos[cand + 1] + umin).astype(np.float64)  # the last / next wall cell
    inner = (ub - ua - 1).astype(np.int64)
    group, step = _ragged(inner)
    on_floor = floor_at(ua[group] + 1.0 + step, v_line[group])
    floor_share = np.bincount(group, weights=on_floor, minlength=cand.size) / np.maximum(inner, 1)
    keep = (inner == 0) | (floor_share >= GAP_MIN_FLOOR_SHARE)
    # A doorway is as deep as its wall: the slot between two cabinets or desks standing
    # in a row is as deep as they are.
    # (An open door leaf standing at a jamb is no wall: see :func:`_jamb_leaves`.)
    leaves = np.zeros((cand.size, 2, 2))
    u_leaf = np.zeros((cand.size, 2, 2))
    wall_face = np.zeros((cand.size, 2, 2))
    idx = np.flatnonzero(keep)
    leaves[idx], u_leaf[idx], wall_face[idx] = _jamb_leaves(wall_at, floor_at, ua[idx], ub[idx], v_line[idx], res)
    keep[idx] = _through_depth(wall_at, ua[idx], ub[idx], v_line[idx], k.reach, leaves[idx]) <= k.max_depth
    # The wall runs on past both ends as a partition between two spaces: thin, floor
    # on both sides (an outer wall has unknown outside it, a shelf row or a counter is
    # thick, a wall with cupboards along it has them on one side only).
    idx = np.flatnonzero(keep)
    keep[idx] = np.minimum(
        _partition_share(both_at, ua[idx], -1.0, v_line[idx], k.side, k.reach, k.thin),
        _partition_share(both_at, ub[idx], 1.0, v_line[idx], k.side, k.reach, k.thin)) \
        >= PARTITION_MIN_SHARE
    # On both sides the space runs on along the wall past one of the gap's ends (behind the
    # door leaves standing open in it).
    idx = np.flatnonzero(keep)
    leaf_cells = _leaf_cells(floor_at, wall_at, leaves[idx], u_leaf[idx], wall_face[idx], v_line[idx], res)
    leaf_of = dict(zip(idx.tolist(), leaf_cells, strict=True))
    floor_at = _with_floor(floor_at, leaf_cells)
    # Every (side, end, depth) look of every candidate is read in one pass: (side, end, depth,
    # candidate) in that order.
    mid = (ua[idx] + ub[idx]) / 2
    ends = (ua[idx] - k.past, ub[idx] + k.past)
    looks = [(mid, end, v_line[idx] + sign * d) for sign in (-1.0, 1.0) for end in ends for d in k.depths]
    on = _runs_on(floor_at, *(np.concatenate([look[i] for look in looks]) for i in range(3)))
    on = np.reshape(on, (2, 2, len(k.depths), idx.size))
    keep[idx] &= np.all(np.any(np.all(on, axis=2), axis=1), axis=0)
    out: list[WallGap] = []
    for i in np.flatnonzero(keep).tolist():
        r2, c2 = floor_at.rc(np.array([ua[i], ub[i]]), np.full(2, v_line[i]))
        lr, lc_ = leaf_of[i]
        out.append(WallGap((float(r2[0]), float(c2[0])), (float(r2[1]), float(c2[1])),
                           float((ub[i] - ua[i] - 1) * res), front is not None and bool(front[i]),
                           tuple(zip(lr.tolist(), lc_.tolist(), strict=True))))
    return out


def leaf_mask(gaps: list[WallGap], shape: tuple[int, ...]) -> BoolArray:
    """The cells of the open door leaves standing in ``gaps`` (see :func:`_jamb_leaves`): no
    wall, whatever the scan made of them, for judging the doorways there."""
    out = np.zeros(shape[:2], dtype=bool)
    for g in gaps:
        if g.leaf_cells:
            r, c = np.array(g.leaf_cells, dtype=np.int64).T
            out[r, c] = True
    return out


def _through(at: _LineSampler[np.bool_], v: float, u: FloatArray, depth: FloatArray, sign: float) -> BoolArray:
    """``at`` over the cells at positions ``u`` along the line at ``v`` and ``depth`` across it
    towards ``sign`` (all pairs, position-major)."""
    return at(np.repeat(u, depth.size), v + sign * np.tile(depth, u.size))


@dataclass(frozen=True)
class OuterGap:
    """A door-wide gap in a wall line with seen floor on one side only: its centre (row, col;
    cell-corner coordinates, cell i spans [i, i + 1)), the unit normal (drow, dcol) from the
    seen side out, and its width (m)."""

    center_rc: tuple[float, float]
    normal_rc: tuple[float, float]
    width_m: float


def outer_gaps(wall: BoolArray, floor: BoolArray, seen: BoolArray, unknown: BoolArray, resolution_m: float,
               params: AnalysisParams, directions: list[float] | None = None) -> list[OuterGap]:
    """The door-wide gaps (up to ``door_wide_max_width_m``) in the wall lines of ``wall`` that
    open from seen floor onto what was never seen: a door in an outer wall, or into a room the
    robot did not enter, through which the lidar saw out. ``seen``: floor the scans covered, not
    a streak with unknown beside it; ``unknown``: the unexplored cells.

    The gap is as deep as a wall and its floor is free; its wall runs on past both ends (a wall
    line, not the corner of a piece of furniture or the end of a wall). On one side lies seen
    floor (the space it opens from). On the other, the rays through the gap fill its width just
    past the wall and reach on beyond a door's width (a scan through an open door sees through
    all of it and on for metres; through a window or a hole in a dashed wall, streaks or a
    sliver); the wall beside the gap hides what is behind it (an opaque wall: behind a glass or
    broken wall the scan saw floor all along, and the gap is one more hole in it); and what the
    rays show beyond is not walled in along the gap's sides (a corridor or a room running on
    from a gap as wide as it is a way on, seen, not a door onto the unexplored).
    """
    if not wall.any():
        return []
    dirs = dominant_directions(wall) if directions is None else directions
    res = resolution_m
    max_depth = WALL_MAX_THICKNESS_M / res + 1.0
    reach = math.ceil(2 * params.door_max_depth_m / res) + 2
    near = np.arange(OUTER_LOOK_FROM_M, OUTER_NEAR_M + 1e-9, res) / res
    far = np.arange(OUTER_LOOK_FROM_M, OUTER_FAR_M + 1e-9, res) / res
    ray = far[far >= OUTER_NEAR_M / res]
    beside = np.arange(OUTER_BESIDE_FROM_M, OUTER_NEAR_M + 1e-9, res) / res
    widest = max(params.door_max_width_m, params.door_wide_max_width_m)
    across = np.arange(0.0, (widest / 2 + OUTER_NEAR_M) / res + 1e-9)
    out: list[OuterGap] = []
    for lc in _line_candidates(wall, dirs, res, params, widest):
        floor_at, wall_at, seen_at, unknown_at = (_LineSampler(m, lc.cos_t, lc.sin_t)
                                                  for m in (floor, wall, seen, unknown))
        # A free gap as deep as a wall (all candidates at once; the rest one by one).
        v_all = (lc.line[lc.cand] + lc.vmin).astype(np.float64)
        ua_all = (lc.pos[lc.cand] + lc.umin).astype(np.float64)
        ub_all = (lc.pos[lc.cand + 1] + lc.umin).astype(np.float64)
        n_in = (ub_all - ua_all - 1).astype(np.int64)
        group, step = _ragged(n_in)
        on_floor = floor_at(ua_all[group] + 1.0 + step, v_all[group])
        keep = (n_in > 0) & (np.bincount(group, weights=on_floor, minlength=n_in.size)
                             >= GAP_MIN_FLOOR_SHARE * np.maximum(n_in, 1))
        idx = np.flatnonzero(keep)
        keep[idx] = _through_depth(wall_at, ua_all[idx], ub_all[idx], v_all[idx], reach) <= max_depth
        idx = np.flatnonzero(keep)
        for b0 in range(0, idx.size, CANDIDATE_BLOCK):
            sel = idx[b0:b0 + CANDIDATE_BLOCK]
            out += _outer_kept(v_all[sel], ua_all[sel], ub_all[sel], lc, _OuterSamplers(floor_at, wall_at, seen_at, unknown_at),
                               _OuterLooks(near, far, ray, beside, across), res)
    return out


@dataclass(frozen=True)
class _OuterSamplers:
    """The masks :func:`outer_gaps` reads along one wall direction."""

    floor: _LineSampler[np.bool_]
    wall: _LineSampler[np.bool_]
    seen: _LineSampler[np.bool_]
    unknown: _LineSampler[np.bool_]


@dataclass(frozen=True)
class _OuterLooks:
    """The depths (cells) across the line :func:`outer_gaps` looks at, and the offsets along it."""

    near: FloatArray
    far: FloatArray
    ray: FloatArray
    beside: FloatArray
    across: FloatArray


def _outer_kept(v: FloatArray, ua: FloatArray, ub: FloatArray, lc: _LineCandidates, at: _OuterSamplers,
                looks: _OuterLooks, res: float) -> list[OuterGap]:
    """Of the free gaps as deep as a wall at ``v`` between the wall cells at ``ua`` and ``ub``,
    the outer gaps (the tests of :func:`outer_gaps`, all candidates at once, each test on the
    candidates that passed the ones before)."""

    def share(mask: _LineSampler[np.bool_], depth: FloatArray, sign: FloatArray, sel: IntArray) -> FloatArray:
        """Per candidate of ``sel``: the share of the cells at its inner positions and ``depth``
        across the line towards its ``sign`` that are set in ``mask``."""
        n_in = (ub[sel] - ua[sel] - 1).astype(np.int64)
        group, step = _ragged(n_in)
        hit = mask((ua[sel][group] + 1.0 + step)[:, None], v[sel][group][:, None] + sign[group][:, None] * depth[None, :])
        count = np.bincount(group, weights=hit.sum(axis=1), minlength=sel.size)
        return np.asarray(count / (n_in.astype(np.float64) * depth.size), dtype=np.float64)

    # Seen floor on one side of the gap, straight through it.
    every = np.arange(v.size)
    ones = np.ones(v.size)
    share_minus = share(at.seen, looks.near, -ones, every)
    share_plus = share(at.seen, looks.near, ones, every)
    sign = np.where(share_minus >= share_plus, -1.0, 1.0)
    keep = np.maximum(share_minus, share_plus) >= OUTER_INSIDE_MIN_SHARE
    # On the other (-sign): rays through all of the gap, reaching on.
    idx = np.flatnonzero(keep)
    keep[idx] = share(at.floor, looks.near, -sign[idx], idx) >= GAP_MIN_FLOOR_SHARE
    idx = np.flatnonzero(keep)
    keep[idx] = share(at.floor, looks.ray, -sign[idx], idx) > 0
    # An opaque wall beside it: unknown behind it, along the wall past each jamb.
    idx = np.flatnonzero(keep)
    side_u = np.arange(1.0, OUTER_NEAR_M / res + 1e-9)
    behind = np.zeros(idx.size, dtype=np.int64)
    for u_side in (ua[idx][:, None] - side_u[None, :], ub[idx][:, None] + side_u[None, :]):
        hit = at.unknown(u_side[:, :, None],
                         v[idx][:, None, None] + (-sign[idx])[:, None, None] * looks.beside[None, None, :])
        behind += hit.sum(axis=(1, 2))
    keep[idx] = behind / (2 * side_u.size * looks.beside.size) >= OUTER_BEHIND_MIN_UNKNOWN
    # Not walled in: beyond the wall, what bounds the floor across the way the rays went is
    # wall on both sides over less than OUTER_WALLED_MAX_SHARE of the look.
    idx = np.flatnonzero(keep)
    u_mid = (ua[idx] + ub[idx]) / 2
    v_far = v[idx][:, None] - sign[idx][:, None] * looks.far[None, :]  # (candidate, depth)
    walled = np.ones(v_far.shape, dtype=bool)
    for way in (-1.0, 1.0):
        uu = u_mid[:, None] + way * looks.across[None, :]  # (candidate, offset)
        ff = at.floor(uu[:, None, :], v_far[:, :, None])
        first = np.where(ff.all(axis=2), uu.shape[1] - 1, np.argmin(ff, axis=2))
        walled &= at.wall(np.take_along_axis(uu, first, axis=1), v_far)
    keep[idx] = walled.sum(axis=1) / looks.far.size < OUTER_WALLED_MAX_SHARE
    out: list[OuterGap] = []
    for i in np.flatnonzero(keep).tolist():
        sg = float(sign[i])
        r, c = at.floor.rc(np.array([(ua[i] + ub[i]) / 2]), np.array([v[i]]))
        # d(r, c)/dv = (cos_t, -sin_t): from the seen side (v + sign * depth) out.
        out.append(OuterGap((float(r[0]) + 0.5, float(c[0]) + 0.5), (-sg * lc.cos_t, sg * lc.sin_t),
                            float((ub[i] - ua[i] - 1) * res)))
    return out


def closure_mask(gaps: list[WallGap], floor: BoolArray) -> BoolArray:
    """The floor cells that close ``gaps``: each gap's segment, from one end's wall cell to the
    other's, drawn a band of LINE_BAND_CELLS either side of it (a flood must not slip through
    diagonally), sampled every half cell along and across it; all gaps at once."""
    out = np.zeros(floor.shape, dtype=bool)
    if not gaps:
        return out
    h, w = floor.shape
    ends = np.array([(*g.end_a_rc, *g.end_b_rc) for g in gaps])
    ra, ca, rb, cb = ends[:, 0], ends[:, 1], ends[:, 2], ends[:, 3]
    lengths = [math.hypot(g.end_b_rc[0] - g.end_a_rc[0], g.end_b_rc[1] - g.end_a_rc[1]) for g in gaps]
    n = np.array([max(2, math.ceil(2 * length) + 1) for length in lengths], dtype=np.int64)
    length = np.array(lengths)
    long = length > 0
    safe = np.where(long, length, 1.0)
    nr = np.where(long, (cb - ca) / safe, 0.0)  # across
    nc = np.where(long, -(rb - ra) / safe, 0.0)
    # Along each segment: np.linspace(0, 1, n) of its own n, for all segments at once.
    group, k = _ragged(n)
    t = k.astype(np.float64) * (1.0 / (n - 1))[group]
    t[np.cumsum(n) - 1] = 1.0
    ra_g, ca_g, nr_g, nc_g = ra[group], ca[group], nr[group], nc[group]
    dr_t, dc_t = (rb - ra)[group] * t, (cb - ca)[group] * t
    for off in np.arange(-LINE_BAND_CELLS, LINE_BAND_CELLS + 0.25, 0.5):
        r = np.rint(ra_g + dr_t + nr_g * off).astype(np.int64)
        c = np.rint(ca_g + dc_t + nc_g * off).astype(np.int64)
        inside = (r >= 0) & (r < h) & (c >= 0) & (c < w)
        out[r[inside], c[inside]] = True
    return out & floor


__all__ = ["OuterGap", "WallDirections", "WallGap", "closure_mask", "dominant_directions", "leaf_mask",
           "outer_gaps", "wall_gaps"]
