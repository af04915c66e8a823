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

*A door opens onto places wider than itself.* Beyond a door, on each side, lies a room or a
corridor running along the wall, wider along the door's line than the door. Where the place on
one side keeps the opening's own width for a corridor's length (its typical width there: a
niche, a side door or a ray hole near the mouth does not make a corridor a room), the opening
is the mouth of that corridor or passage: where a corridor runs into a hall, where a corridor is
cut across at a jog, not a door.

*Beyond a door into the unexplored lie rays, not walls.* Through a door onto territory the
robot never entered, the lidar saw a fan of rays bounded by the unknown (past, at most, the
short returns of a door frame). Where the strip seen beyond an opening stays as narrow as the
opening with scanned wall along its side for half of what was seen of it, the opening is the
mouth of a passage running on (an aisle between two shelf blocks, a slot between lockers, a
corridor whose far part was not scanned), not a door.

*A door may open onto an entry lobby.* A room's door in a corridor's or a hall's wall often
opens onto a short lobby about as wide as the door (beside an en-suite bathroom or a wardrobe)
before the room itself: through the door the free width stays the door's for a wall's thickness
and a lobby's length. The door is the one in the wall of the place it is cut in: the opening is
flush with that wall's face (the constriction starts at it, on that side the place is wider than
the door at once) and the constriction ends within a lobby's length in a place wider than the
door. A longer narrow way is a passage (a corridor running on), and a way as narrow on both
sides of its middle is the mouth of one.

*A door lies along its wall.* Walls run along a few directions (the building's, or a wing's
at an angle), and a door is a gap in one: the line from jamb to jamb runs along a direction of
the walls around it, give or take the tilt of ragged jambs. A slanted gap, from the end of one
wall to the corner of another (a wall's end beside an unscanned corner, a ray leaking past a
wall's end into the next room), is in no wall.

*A door's jambs are wall.* Each end of the opening is the end of a wall that carries on along
the opening's line (scanned, occupied cells for a wall's length, allowing for the holes a scan
leaves in walls), or, beside a room's corner, the return of wall a door frame needs between it
and the wall across (the return and the crossing wall's own thickness fill the look along the
line). The tip of a laser ray, a speck of clutter, the corner where a corridor's wall turns
away into a hall, are not: a gap beside them is no door. Nor is the face of a wall crossing
the opening's line with no return along it: a gap that runs right up to a crossing wall is
the way round the end of a partition, a bench row, a shelf or a parking bay's wall, not a door
(builders leave a return beside a door frame at a corner, so that the frame has a wall to
stand in and the door leaf can open past the corner). However thick the crossing wall, the
look along the opening's line from its face reads only its thickness and, beyond it, the floor
of the place behind: an inner wall passing straight by the jamb on both sides is no return.
The building's outer wall is the exception: a partition stopping short of the facade leaves the
door between the two rooms it parts (the frame stands on the outer wall, with the unknown
outside beyond), as a person reads a house's plan.

*A door's jambs are walls, not furniture.* A jamb on a compact body standing free in the floor
(all of it within a few metres, its inside never scanned: a cabinet, a desk block, a counter
seen only from around it), deeper than a wall is thick and shallower than a room, is a piece of
furniture: the gap beside it is a way past the furniture, not a door.

*A door is judged on its wall line.* The flood puts the boundary between two spaces where
their clearance basins meet, which beside a door is often off the wall: pulled into a room by
its unscanned shadow, or slanted from a jamb to the corner of the room beyond. A person looks at
the opening where the wall is, the narrowest crossing next to that boundary: the cells there are
judged.

*A doorway is clear across.* From jamb to jamb, through its centre, the floor is open for at
least the robot's width: the robot drives through a door. A "gap" whose line through its
centre is blocked by a speck of clutter a few centimetres from its middle is a gap between
pieces of clutter (chairs, table legs, boxes standing about a room), not a door; the clearance
flood, which measures an opening by its widest point, cannot tell.

*A doorway was scanned.* The robot saw through an opening: across it, from jamb to jamb, the
cells are scanned (free floor, or a post or a door leaf standing in it; a few unscanned specks
aside). A notch of unknown between two walls' ends (the shadow a wall's corner casts, a wedge
the scan never reached) is no opening, however door-wide the saddle the flood finds there.

A candidate between two spaces that is no door is still a way between them (an opening); one
into unexplored territory is nothing a person would point at.

Pure functions over the grid's masks; thresholds in metres with their reasons.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Final

import numpy as np
import numpy.typing as npt
from scipy import ndimage as ndi

from langnav.analysis.params import AnalysisParams
from langnav.analysis.precompute import EIGHT, far_from_outside, median, take2
from langnav.analysis.seg_doors import SEEN_FLOOR_MIN_M, RawDoor
from langnav.analysis.wall_lines import (
    GAP_MIN_FLOOR_SHARE,
    WALL_MAX_THICKNESS_M,
    dominant_directions,
)

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
#: The place beyond an opening, on each side, is looked at from a wall's thickness
#: (``door_max_depth_m``) to this far (m): a corridor's length (two door widths and more).
MOUTH_LOOK_M: Final = 2.0
#: ... where at least this share of the samples is free (a closet or a wall straight behind the
#: opening leaves no corridor to judge).
MOUTH_MIN_FREE_SHARE: Final = 0.5
#: Free runs across a candidate are first followed this many samples each way (most end within
#: a wall's thickness of it); only the longer ones are followed across the whole look.
FIRST_LOOK_SAMPLES: Final = 16

#: A jamb's wall carries on along the opening's line with occupied cells on at least this share
#: of a wall's length (scanned walls have holes: glass, dark surfaces, grazing rays) ...
JAMB_ALONG_MIN_SHARE: Final = 0.45
#: A scanned wall's cells lie within this distance (m) of its line (three cells of a 5 cm map:
#: scan noise and a thin wall's thickness); farther is another wall or clutter beside it.
JAMB_BAND_M: Final = 0.1
#: A jamb's wall may leave the jamb-to-jamb line by up to this angle (degrees): ragged wall
#: ends over a door's width tilt that short baseline; a corner (90 degrees) is no run-on wall.
ALONG_MAX_TURN_DEG: Final = 25
#: Beyond an opening, the place it opens onto is looked at from a wall's thickness ...
BEYOND_FROM_M: Final = 0.3
#: ... to this far (m) ...
BEYOND_LOOK_M: Final = 2.0
#: ... and this far (m) either side of the opening's centre line (about a door's width each way).
BEYOND_HALF_WIDTH_M: Final = 1.0
#: A place was seen beyond an opening when at least this share of its free cells there is seen
#: floor; a fan of rays through a gap in a wall has next to none.
BEYOND_MIN_FLOOR_SHARE: Final = 0.3
#: A jamb lies at most this far (m) beyond the end of the opening as measured (the opening's
#: width is its clearance at one crossing; a ragged jamb stands back from it).
JAMB_REACH_M: Final = 0.3
#: A jamb's wall turns across the opening's line (a corner beside the door, whose return along
#: the line is shorter than a wall's length) when it is occupied on at least this share of a
#: wall's length along the normal.
JAMB_ACROSS_MIN_SHARE: Final = 0.8
#: Behind a jamb on the face of a wall crossing the opening's line, the other side of that wall
#: is looked for this far (m): a wall's thickness, thick walls included.
CROSSING_LOOK_M: Final = 0.6
#: ... and the place behind it is floor clear for at least this far (m) along the line: room for
#: the robot (0.34 m) to stand; a hole in a wall, or the slit between two walls, is narrower.
PLACE_BEHIND_MIN_M: Final = 0.35
#: A jamb's body is looked at within this distance (m) of it: a piece of furniture lies
#: wholly inside it, a wall runs on beyond it (to other walls, or along the unknown outside).
BODY_LOOK_M: Final = 3.0
#: A body standing free is furniture when at least this share of it was never scanned (its
#: inside: a scanned wall is occupied cells, a cabinet an outline around the unknown) ...
BODY_MIN_UNKNOWN_SHARE: Final = 0.45
#: ... and it is deeper than a wall is thick (m, WALL_MAX_THICKNESS of the wall lines) and at
#: most this deep (m): cabinets, desks and counters are 0.4-0.8 m deep; a closet or a small
#: room never entered, walled in the same way, is deeper.
BODY_MAX_DEPTH_M: Final = 0.8
#: A body standing free in the floor, scanned solid, is a column or a post up to this footprint
#: (m2: as wide as a cabinet is deep, each way); a pier between two doors stands there too.
COLUMN_MAX_AREA_M2: Final = BODY_MAX_DEPTH_M ** 2
#: The walls around a door, whose directions its line must follow: those within this distance
#: (m) of it (the room or corridor it opens from; a wing at an angle has its own directions).
LOCAL_WALLS_M: Final = 3.0
#: The strip seen beyond an opening into the unexplored is a passage running on (see module
#: doc) when, over what was seen of it from a wall's thickness to MOUTH_LOOK_M, it is as
#: narrow as the opening with scanned wall beside it for more than this share (half: a door
#: frame's returns are short, a passage's walls run on as far as it was seen).
STRIP_WALLED_MAX_SHARE: Final = 0.5
#: The wall line of an opening between two spaces (its narrowest crossing) is looked for within
#: this distance (m) of the boundary the flood found, along its normal: a wall's thickness and
#: a door's depth (a room's unscanned shadow beside the door pulls the boundary that far).
WALL_LINE_SEARCH_M: Final = 0.5
#: An entry lobby behind a door is at most this long (m) past the wall: room for the door leaf
#: to swing (a door's width) and a person to stand clear of it; longer is a corridor.
LOBBY_MAX_M: Final = 1.5
#: Whether an opening was scanned is read over this share of its width about its centre (its
#: ends are the ragged jambs).
OPENING_MIDDLE_SHARE: Final = 0.6


@dataclass(frozen=True)
class DoorEvidence:
    """What the cells around one candidate say (see module doc)."""

    #: Along the normal, the longest stretch (m) through the opening where the free width stays
    #: within the door's width (the constriction's depth) ...
    constriction_m: float
    #: ... and its part on the side the normal comes from (space ``a``'s side).
    constriction_back_m: float
    #: For each jamb: the share of a wall's length beyond it, along the opening's line, that is
    #: occupied; and the smaller of the same shares along the normal's two directions.
    along: tuple[float, float]
    across: tuple[float, float]
    #: The angle (degrees) between the line from jamb to jamb and the nearest direction of the
    #: walls around the opening (0 where there are no jambs or no walls to tell).
    line_turn_deg: float = 0.0
    #: The typical (median) free width (m) along the opening's line of the place beyond it on
    #: space ``a``'s side and on the other, from a wall's thickness to MOUTH_LOOK_M (infinite
    #: where too little of that look is free to tell).
    beyond_width_m: tuple[float, float] = (math.inf, math.inf)
    #: The same typical width past the constriction's end on each side (where a door onto an
    #: entry lobby opens into the room: see module doc).
    past_width_m: tuple[float, float] = (math.inf, math.inf)
    #: Whether either jamb is on a piece of furniture (see module doc; False where the unknown
    #: cells were not given).
    furniture_jamb: bool = False
    #: The share of the opening's middle (OPENING_MIDDLE_SHARE of its width, across the normal
    #: through its centre) that was scanned (free or occupied, not unknown).
    scanned_share: float = 1.0
    #: The clear width (m) along the opening's line through its centre: the narrowest free run
    #: across it within CENTRE_SLACK_M of its centre along the normal, on space ``a``'s side and
    #: on the other (each from the centre; infinite where not measured).
    clear_width_m: tuple[float, float] = (math.inf, math.inf)
    #: Beyond the opening on the side the normal points to: the share of the strip seen there
    #: that is as narrow as the opening with scanned wall beside it (:func:`walled_strip_share`;
    #: 0 where not measured).
    walled_beyond_share: float = 0.0
    #: Whether both jambs are columns or posts standing free in the floor (False where the
    #: unknown cells were not given).
    column_jambs: bool = False


def _sample(mask: BoolArray, rows: npt.NDArray[np.float64], cols: npt.NDArray[np.float64],
            outside: bool) -> BoolArray:
    """``mask`` at continuous (row, col) positions in cell-corner coordinates (cell i spans
    [i, i + 1)); ``outside`` where they leave the grid."""
    r, c, inside = _cells(mask.shape, rows, cols)
    got = np.asarray(take2(mask, r, c), dtype=bool)
    if inside is None:
        return got
    return got | ~inside if outside else got & inside


def _cells(shape: tuple[int, ...], rows: npt.NDArray[np.float64], cols: npt.NDArray[np.float64]
           ) -> tuple[npt.NDArray[np.intp], npt.NDArray[np.intp], BoolArray | None]:
    """The cells :func:`_sample` reads at (row, col) positions, clamped onto a grid of ``shape``,
    and whether each position is on the grid (None: all are; several masks are read at the same
    positions)."""
    h, w = shape[0], shape[1]
    if rows.size and rows.min() >= 0 and rows.max() < h and cols.min() >= 0 and cols.max() < w:
        # Every position on the grid (a candidate away from the map's edge): no clamping, and
        # truncation is the floor of a non-negative position.
        return rows.astype(np.intp), cols.astype(np.intp), None
    r = np.floor(rows).astype(np.intp)
    c = np.floor(cols).astype(np.intp)
    # On the grid: 0 <= r < h and 0 <= c < w (a negative index read unsigned is past the end).
    inside = (r.view(np.uintp) < h) & (c.view(np.uintp) < w)
    # Read every sample (clamped onto the grid), then set those off it: no masked indexing.
    # (np.maximum / np.minimum: np.clip's checks of its bounds cost more than clamping small arrays.)
    np.maximum(r, 0, out=r)
    np.minimum(r, h - 1, out=r)
    np.maximum(c, 0, out=c)
    np.minimum(c, w - 1, out=c)
    return r, c, inside


def free_widths(free: BoolArray, center_rc: tuple[float, float], normal_rc: tuple[float, float],
                resolution_m: float, look_m: float) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """Offsets t (m) along the normal through ``center_rc`` and, at each, the free width (m)
    along the tangent of the run of ``free`` cells through that point (0 where it is not free)."""
    t_m, widths = free_widths_each(free, [center_rc], [normal_rc], resolution_m, look_m)
    return t_m, widths[0]


def free_widths_each(free: BoolArray, centers_rc: Sequence[tuple[float, float]],
                     normals_rc: Sequence[tuple[float, float]], resolution_m: float, look_m: float
                     ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """:func:`free_widths` of several candidates at once (one look ``look_m`` for all): the
    offsets t (m) and, per candidate (a row each), the free width (m) at each of them."""
    k = math.ceil(look_m / resolution_m / _STEP_CELLS)
    t = np.arange(-k, k + 1) * _STEP_CELLS
    s_max = math.ceil(2.0 * look_m / resolution_m / _STEP_CELLS)
    s = np.arange(-s_max, s_max + 1) * _STEP_CELLS
    rays = _Rays.of(centers_rc, normals_rc, t)
    # The run through s = 0: up to the first blocked sample on each side. Most runs end near the
    # line (in a wall's thickness); only the rows whose run leaves a first, narrow strip of
    # samples are sampled across the whole look.
    near = min(s_max, FIRST_LOOK_SAMPLES)
    n_right, n_left, on = _runs_through_zero(free, rays, s[s_max - near:s_max + near + 1])
    # A half that ran through that strip runs on: it is looked along further, in stretches that
    # double, for its rows only (the samples a look across the whole width reads, up to the first
    # blocked one).
    _run_on(free, rays, s[s_max:], n_right, n_left, near + 1)
    width = np.where(on, (n_right + n_left - 1) * _STEP_CELLS * resolution_m, 0.0)
    return (np.asarray(t * resolution_m, dtype=np.float64),
            np.asarray(width, dtype=np.float64).reshape(len(centers_rc), t.size))


@dataclass(frozen=True)
class _Rays:
    """Lines across candidates, one per (candidate, offset t along its normal), candidates one
    after the other: each line's candidate centre (row, col), its offset t (cells) and the
    candidate's unit normal (row, col). A line's samples lie at ``centre + t * normal + s *
    tangent`` (the tangent is the normal turned a right angle: (-normal col, normal row))."""

    center_r: npt.NDArray[np.float64]
    center_c: npt.NDArray[np.float64]
    t: npt.NDArray[np.float64]
    normal_r: npt.NDArray[np.float64]
    normal_c: npt.NDArray[np.float64]

    @staticmethod
    def of(centers_rc: Sequence[tuple[float, float]], normals_rc: Sequence[tuple[float, float]],
           t: npt.NDArray[np.floating]) -> _Rays:
        c = np.asarray(centers_rc, dtype=np.float64).reshape(-1, 2)
        n = np.asarray(normals_rc, dtype=np.float64).reshape(-1, 2)
        k = t.size
        return _Rays(np.repeat(c[:, 0], k), np.repeat(c[:, 1], k), np.tile(np.asarray(t, dtype=np.float64), len(c)),
                     np.repeat(n[:, 0], k), np.repeat(n[:, 1], k))

    def at(self, lines: npt.NDArray[np.intp] | slice, s: npt.NDArray[np.floating]
           ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
        """The (row, col) positions of the samples at tangent offsets ``s`` (one row of offsets per
        line, or one for all) on ``lines``."""
        tt, nr, nc = self.t[lines], self.normal_r[lines], self.normal_c[lines]
        # The tangent (tr, tc) = (-nc, nr); each position is (centre + t * normal) + s * tangent.
        rows = self.center_r[lines][:, None] + (tt * nr)[:, None] + s * (-nc)[:, None]
        cols = self.center_c[lines][:, None] + (tt * nc)[:, None] + s * nr[:, None]
        return rows, cols


def _run_on(free: BoolArray, rays: _Rays, half: npt.NDArray[np.floating], n_right: npt.NDArray[np.int64],
            n_left: npt.NDArray[np.int64], looked: int) -> None:
    """Carry on the free runs that reached ``looked`` samples along the tangent (``half``: its
    offsets from 0 outwards; the left half's are their negatives): ``n_right`` / ``n_left`` (per
    line of ``rays``) become the index of the first blocked sample, or the length of ``half`` when
    there is none (as :func:`_runs_through_zero` counts over the whole of each half). Both halves
    are looked along together."""
    right, left = np.flatnonzero(n_right >= looked), np.flatnonzero(n_left >= looked)
    rows_on = np.concatenate([right, left])
    sign = np.concatenate([np.ones(right.size), -np.ones(left.size)])
    is_left = np.concatenate([np.zeros(right.size, dtype=bool), np.ones(left.size, dtype=bool)])
    a = looked
    while rows_on.size and a < half.size:
        b = min(half.size, 2 * a)
        rows, cols = rays.at(rows_on, sign[:, None] * half[None, a:b])
        ok = _sample(free, rows, cols, outside=False)
        through = ok.all(axis=1)
        got = np.where(through, b, a + np.argmin(ok, axis=1))
        n_right[rows_on[~is_left]] = got[~is_left]
        n_left[rows_on[is_left]] = got[is_left]
        rows_on, sign, is_left = rows_on[through], sign[through], is_left[through]
        a = b


def _runs_through_zero(free: BoolArray, rays: _Rays, s: npt.NDArray[np.floating]
                       ) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.int64], BoolArray]:
    """For each line of ``rays``: the free samples from s = 0 (the middle of the symmetric
    ``s``) on along the tangent and back (the free run's two halves, each counting s = 0; a half
    that reaches the end of ``s`` counts one more than its samples), and whether s = 0 is free."""
    rows, cols = rays.at(slice(None), s[None, :])
    ok = _sample(free, rows, cols, outside=False)
    mid = (s.size - 1) // 2
    right = ok[:, mid:]
    left = ok[:, mid::-1]
    n_right = np.where(right.all(axis=1), right.shape[1], np.argmin(right, axis=1))
    n_left = np.where(left.all(axis=1), left.shape[1], np.argmin(left, axis=1))
    return n_right.astype(np.int64), n_left.astype(np.int64), np.asarray(ok[:, mid], dtype=bool)


def constriction_depth(t_m: npt.NDArray[np.float64], width_m: npt.NDArray[np.float64],
                       door_width_m: float, back_only: bool = False) -> float:
    """The length (m) of the stretch around t = 0 where the free width stays within the door's
    width (widening by less than WIDEN_FACTOR / WIDEN_MIN_M); a blocked sample ends it too.
    ``back_only``: only its part at t <= 0 (behind the opening's centre)."""
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
    if back_only:
        return float(max(0.0, -t_m[lo]))
    return float(t_m[hi] - t_m[lo])


def jamb_cells(occupied: BoolArray, center_rc: tuple[float, float], width_m: float,
               resolution_m: float) -> tuple[tuple[float, float], tuple[float, float]] | None:
    """The centres of the two jamb cells of a candidate: the occupied cell nearest to its
    centre, and the nearest one on the opposite side of the centre; both within half the
    opening plus JAMB_REACH_M. None when there is no such pair (an end of the opening is
    unknown or free: no wall)."""
    reach = (width_m / 2 + JAMB_REACH_M) / resolution_m
    rad = math.ceil(reach) + 1
    r0 = max(0, math.floor(center_rc[0]) - rad)
    c0 = max(0, math.floor(center_rc[1]) - rad)
    win = occupied[r0:math.floor(center_rc[0]) + rad + 1, c0:math.floor(center_rc[1]) + rad + 1]
    rr, cc = np.nonzero(win)
    if rr.size == 0:
        return None
    dr = rr + r0 + 0.5 - center_rc[0]
    dc = cc + c0 + 0.5 - center_rc[1]
    d2 = dr * dr + dc * dc
    i = int(np.argmin(d2))
    # Opposite: more than 90 degrees away from the first jamb, seen from the centre.
    opposite = (dr * dr[i] + dc * dc[i] < 0) & (d2 <= reach * reach)
    if d2[i] > reach * reach or not opposite.any():
        return None
    j = int(np.flatnonzero(opposite)[np.argmin(d2[opposite])])
    return ((float(rr[i] + r0 + 0.5), float(cc[i] + c0 + 0.5)),
            (float(rr[j] + r0 + 0.5), float(cc[j] + c0 + 0.5)))


def wall_share(occupied: BoolArray, start_rc: tuple[float, float], direction_rc: tuple[float, float],
               resolution_m: float, length_m: float, band_m: float) -> float:
    """Share of the steps along ``direction_rc`` from ``start_rc`` (up to ``length_m``) with an
    occupied cell within ``band_m`` either side of the line (walls are not ruled lines)."""
    return float(wall_shares(occupied, start_rc, [direction_rc], resolution_m, length_m, band_m)[0])


def wall_shares(occupied: BoolArray, start_rc: tuple[float, float], directions_rc: list[tuple[float, float]],
                resolution_m: float, length_m: float, band_m: float) -> npt.NDArray[np.float64]:
    """:func:`wall_share` along each of ``directions_rc``, all at once."""
    return np.asarray(wall_hits(occupied, start_rc, directions_rc, resolution_m, length_m, band_m).mean(axis=1),
                      dtype=np.float64)


def wall_hits(occupied: BoolArray, start_rc: tuple[float, float], directions_rc: list[tuple[float, float]],
              resolution_m: float, length_m: float, band_m: float) -> BoolArray:
    """Per direction of ``directions_rc`` and step along it from ``start_rc`` (up to
    ``length_m``): whether an occupied cell lies within ``band_m`` either side of the line."""
    dr = np.array([d[0] for d in directions_rc])[:, None, None]
    dc = np.array([d[1] for d in directions_rc])[:, None, None]
    s = np.arange(_STEP_CELLS, length_m / resolution_m + 1e-9, _STEP_CELLS)[None, :, None]
    b = np.arange(-band_m / resolution_m, band_m / resolution_m + 1e-9, _STEP_CELLS)[None, None, :]
    rows = start_rc[0] + s * dr - b * dc
    cols = start_rc[1] + s * dc + b * dr
    return np.asarray(_sample(occupied, rows, cols, outside=False).any(axis=2), dtype=bool)


def evidence_look_m() -> float:
    """How far (m, each side) :func:`evidence` follows the free width along a candidate's normal."""
    return max(THROUGH_LOOK_M, MOUTH_LOOK_M)


def _turned(dr: float, dc: float, angle: float) -> tuple[float, float]:
    """(dr, dc) turned by ``angle`` radians."""
    ca, sa = math.cos(angle), math.sin(angle)
    return dr * ca - dc * sa, dr * sa + dc * ca


#: Directions tried for a jamb's wall, about the opening's line (radians).
_ALONG_ANGLES: Final = tuple(math.radians(a) for a in
                             np.linspace(-ALONG_MAX_TURN_DEG, ALONG_MAX_TURN_DEG, 2 * ALONG_MAX_TURN_DEG // 5 + 1))


def evidence(free: BoolArray, occupied: BoolArray, center_rc: tuple[float, float],
             normal_rc: tuple[float, float], width_m: float, resolution_m: float,
             params: AnalysisParams, unknown: BoolArray | None = None, into_unknown: bool = False,
             widths: tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]] | None = None) -> DoorEvidence:
    """The evidence of one candidate (``center_rc`` in cell-corner coordinates, unit normal;
    ``unknown``: the unscanned cells, to tell furniture at a jamb; ``into_unknown``: the
    normal points into unexplored territory, whose seen strip is judged; ``widths``: its
    :func:`free_widths` over :func:`evidence_look_m`, when the caller has them)."""
    # A wall's length: the shortest wall stub that is a jamb; a scanned wall's cells scatter
    # about its line by a few cells (JAMB_BAND_M).
    wall_m = params.seg_wall_min_length_m
    band_m = JAMB_BAND_M
    t_all, w_all = free_widths(free, center_rc, normal_rc, resolution_m, evidence_look_m()) if widths is None else widths
    through = np.abs(t_all) <= THROUGH_LOOK_M + 1e-9
    t, w = t_all[through], w_all[through]
    depth = constriction_depth(t, w, width_m)
    back = constriction_depth(t, w, width_m, back_only=True)
    clear = (clear_width(t_all, w_all, -1.0), clear_width(t_all, w_all, 1.0))
    beyond = (typical_width(t_all, w_all, -1.0, params.door_max_depth_m),
              typical_width(t_all, w_all, 1.0, params.door_max_depth_m))
    past = (typical_width(t_all, w_all, -1.0, back + resolution_m),
            typical_width(t_all, w_all, 1.0, depth - back + resolution_m))
    scanned = scanned_across(free, occupied, center_rc, normal_rc, width_m, resolution_m, unknown)
    walled = (walled_strip_share(free, occupied, center_rc, normal_rc, width_m, resolution_m, params)
              if into_unknown else 0.0)
    jj = jamb_cells(occupied, center_rc, width_m, resolution_m)
    if jj is None:
        return DoorEvidence(constriction_m=depth, constriction_back_m=back, along=(0.0, 0.0), across=(0.0, 0.0),
                            beyond_width_m=beyond, past_width_m=past, scanned_share=scanned,
                            clear_width_m=clear, walled_beyond_share=walled)
    (r1, c1), (r2, c2) = jj
    # The opening's line runs from jamb to jamb (the candidate's own normal is the mean step
    # across a ragged boundary, often slanted).
    n = math.hypot(r2 - r1, c2 - c1) or 1.0
    tr, tc = (r2 - r1) / n, (c2 - c1) / n
    turn = line_turn_deg(occupied, center_rc, math.atan2(tr, tc), resolution_m)
    nr, nc = tc, -tr
    along: list[float] = []
    across: list[float] = []
    for jamb, sign in (((r1, c1), -1.0), ((r2, c2), 1.0)):
        # The wall runs on along (nearly) the opening's line: jamb to jamb is a short baseline
        # across ragged wall ends, so the wall may leave it at a small angle.
        fan = [_turned(sign * tr, sign * tc, a) for a in _ALONG_ANGLES]
        hits = wall_hits(occupied, jamb, [*fan, (nr, nc), (-nr, -nc)], resolution_m, wall_m, band_m)
        shares = hits.mean(axis=1)
        # A wall runs on for a wall's length: one that stops short of its last third is a post,
        # a pillar or a speck of clutter, whatever share of the look it fills.
        runs_on = hits[:, -max(1, hits.shape[1] // 3):].any(axis=1)
        # ... unless the wall turns there (a door beside a corner: the short return along the
        # opening's line, the wall running on across it).
        turns = shares[-2:].max() >= JAMB_ACROSS_MIN_SHARE
        # An inner wall running on across the line to both sides, with a place behind it
        # whichever way near the line one looks, passes straight by the jamb: the look along the
        # line reads only its thickness (and, slanted, its length), no return; the opening runs
        # up to its face (see the module doc).
        crossing = (shares[-2:].min() >= JAMB_ACROSS_MIN_SHARE
                    and _floor_behind(free, occupied, jamb, fan, resolution_m))
        along.append(0.0 if crossing else float(np.where(runs_on | turns, shares, 0.0)[:-2].max()))
        across.append(float(shares[-2:].min()))
    bodies = [_free_body(free, unknown, j, resolution_m) for j in jj] if unknown is not None else []
    return DoorEvidence(constriction_m=depth, constriction_back_m=back, along=(along[0], along[1]),
                        across=(across[0], across[1]), line_turn_deg=turn, beyond_width_m=beyond, past_width_m=past,
                        furniture_jamb="furniture" in bodies, scanned_share=scanned, clear_width_m=clear,
                        walled_beyond_share=walled, column_jambs=bodies == ["column", "column"])


def _floor_behind(free: BoolArray, occupied: BoolArray, start_rc: tuple[float, float],
                  directions_rc: list[tuple[float, float]], resolution_m: float) -> bool:
    """Whether, along each of ``directions_rc`` from ``start_rc``, the wall ends within
    CROSSING_LOOK_M (no occupied cell within JAMB_BAND_M of the line: a wall's cells scatter
    about it) in free floor clear for PLACE_BEHIND_MIN_M: the wall there is an inner wall with a
    place behind it, not a wall running on near the line (a T-junction, a partition meeting it,
    a wall seen again past a hole) nor the building's outer wall with the unknown beyond."""
    hits = wall_hits(occupied, start_rc, directions_rc, resolution_m, CROSSING_LOOK_M + PLACE_BEHIND_MIN_M,
                     JAMB_BAND_M)
    n_wall = math.ceil(CROSSING_LOOK_M / resolution_m / _STEP_CELLS)
    n_place = math.ceil(PLACE_BEHIND_MIN_M / resolution_m / _STEP_CELLS)
    ends = np.argmin(hits, axis=1)
    if (hits[:, :n_wall].all(axis=1)).any():
        return False
    steps = np.arange(hits.shape[1])[None, :]
    after = (steps >= ends[:, None]) & (steps < ends[:, None] + n_place)
    if (hits & after).any():
        return False
    s = (ends + 1) * _STEP_CELLS
    rows = start_rc[0] + s * np.array([d[0] for d in directions_rc])
    cols = start_rc[1] + s * np.array([d[1] for d in directions_rc])
    return bool(_sample(free, rows, cols, outside=False).all())


def walled_strip_share(free: BoolArray, occupied: BoolArray, center_rc: tuple[float, float],
                       normal_rc: tuple[float, float], width_m: float, resolution_m: float,
                       params: AnalysisParams) -> float:
    """Of the samples along the normal (its + side, from ``door_max_depth_m`` to MOUTH_LOOK_M)
    where the floor through the opening's centre line is free, the share where the free run
    across is as narrow as the opening (within WIDEN_FACTOR / WIDEN_MIN_M of ``width_m``) and
    ends, on at least one side, at an occupied cell within JAMB_BAND_M (a wall beside the
    strip, not the unknown beside a ray)."""
    limit = max(width_m * WIDEN_FACTOR, width_m + WIDEN_MIN_M)
    t = np.arange(params.door_max_depth_m, MOUTH_LOOK_M + 1e-9, resolution_m * _STEP_CELLS) / resolution_m
    s_max = math.ceil(limit / resolution_m / _STEP_CELLS) + 1
    s = np.arange(-s_max, s_max + 1) * _STEP_CELLS
    n_right, n_left, on = _runs_through_zero(free, _Rays.of([center_rc], [normal_rc], t), s)
    if not on.any():
        return 0.0
    narrow = on & ((n_right + n_left - 1) * _STEP_CELLS * resolution_m <= limit)
    nr, nc = normal_rc
    tr, tc = -nc, nr
    band = np.arange(0.0, JAMB_BAND_M / resolution_m + 1e-9, _STEP_CELLS)

    def wall_at(offset: npt.NDArray[np.floating], sign: float) -> BoolArray:
        # An occupied cell within the band just past the run's end (offset, in cells).
        o = offset[:, None] + sign * band[None, :]
        rows = center_rc[0] + t[:, None] * nr + o * tr
        cols = center_rc[1] + t[:, None] * nc + o * tc
        return np.asarray(_sample(occupied, rows, cols, outside=False).any(axis=1), dtype=bool)

    walled = wall_at(n_right * _STEP_CELLS, 1.0) | wall_at(-n_left * _STEP_CELLS, -1.0)
    return float((narrow & walled).sum() / on.sum())


def clear_width(t_m: npt.NDArray[np.float64], width_m: npt.NDArray[np.float64], side: float) -> float:
    """The narrowest free run (m) across an opening through its centre, over the free samples
    from it to CENTRE_SLACK_M on ``side`` (+1: along the normal) (0 when none is free)."""
    near = (side * t_m >= -1e-9) & (side * t_m <= CENTRE_SLACK_M + 1e-9) & (width_m > 0)
    return float(width_m[near].min()) if near.any() else 0.0


def scanned_across(free: BoolArray, occupied: BoolArray, center_rc: tuple[float, float],
                   normal_rc: tuple[float, float], width_m: float, resolution_m: float,
                   unknown: BoolArray | None = None) -> float:
    """The share of scanned samples (not ``unknown``; without it, ``free`` or ``occupied``)
    along the tangent through ``center_rc`` over the middle OPENING_MIDDLE_SHARE of an opening
    ``width_m`` wide."""
    half = OPENING_MIDDLE_SHARE * width_m / 2 / resolution_m
    s = np.arange(-half, half + 1e-9, _STEP_CELLS)
    nr, nc = normal_rc
    rows, cols = center_rc[0] - s * nc, center_rc[1] + s * nr
    if unknown is not None:
        got = ~_sample(unknown, rows, cols, outside=True)
    else:
        got = _sample(free, rows, cols, outside=False) | _sample(occupied, rows, cols, outside=False)
    return float(got.mean()) if got.size else 0.0


def is_furniture(free: BoolArray, unknown: BoolArray, cell_rc: tuple[float, float], resolution_m: float) -> bool:
    """Whether the occupied cell at ``cell_rc`` is on a piece of furniture: the body of
    not-free cells holding it lies within BODY_LOOK_M of it, at least BODY_MIN_UNKNOWN_SHARE of
    it unscanned, and it is deeper than a wall and at most BODY_MAX_DEPTH_M deep (twice its
    largest inner clearance)."""
    return _free_body(free, unknown, cell_rc, resolution_m) == "furniture"


def is_column(free: BoolArray, unknown: BoolArray, cell_rc: tuple[float, float], resolution_m: float) -> bool:
    """Whether the occupied cell at ``cell_rc`` is on a column or a post standing free: a body
    as :func:`is_furniture`'s, but scanned solid, and no larger than COLUMN_MAX_AREA_M2."""
    return _free_body(free, unknown, cell_rc, resolution_m) == "column"


def _free_body(free: BoolArray, unknown: BoolArray, cell_rc: tuple[float, float], resolution_m: float) -> str:
    """What the body of not-free cells holding ``cell_rc`` is: "furniture", "column" or "wall"."""
    rad = math.ceil(BODY_LOOK_M / resolution_m)
    r, c = math.floor(cell_rc[0]), math.floor(cell_rc[1])
    h, w = free.shape
    body = np.ones((2 * rad + 1, 2 * rad + 1), dtype=bool)  # off the grid: not free
    unk = np.zeros(body.shape, dtype=bool)
    r0, r1, c0, c1 = max(r - rad, 0), min(r + rad + 1, h), max(c - rad, 0), min(c + rad + 1, w)
    body[r0 - r + rad:r1 - r + rad, c0 - c + rad:c1 - c + rad] = ~free[r0:r1, c0:c1]
    unk[r0 - r + rad:r1 - r + rad, c0 - c + rad:c1 - c + rad] = unknown[r0:r1, c0:c1]
    pieces, _ = ndi.label(body, structure=EIGHT)
    mine = pieces == pieces[rad, rad]
    if mine[0].any() or mine[-1].any() or mine[:, 0].any() or mine[:, -1].any():
        return "wall"  # it runs on beyond the look
    depth_m = 2.0 * float(ndi.distance_transform_edt(mine).max()) * resolution_m
    if not WALL_MAX_THICKNESS_M < depth_m <= BODY_MAX_DEPTH_M:
        return "wall"
    if (unk & mine).sum() >= BODY_MIN_UNKNOWN_SHARE * mine.sum():
        return "furniture"
    return "column" if mine.sum() * resolution_m ** 2 <= COLUMN_MAX_AREA_M2 else "wall"


def typical_width(t_m: npt.NDArray[np.float64], width_m: npt.NDArray[np.float64], side: float,
                  from_m: float) -> float:
    """The median free width (m) at the offsets ``t_m`` on ``side`` (+1: along the normal) from
    ``from_m`` to MOUTH_LOOK_M, over the free samples; infinite when fewer than
    MOUTH_MIN_FREE_SHARE of them are free."""
    sel = (side * t_m >= from_m) & (side * t_m <= MOUTH_LOOK_M + 1e-9)
    got = width_m[sel]
    free = got[got > 0]
    if got.size == 0 or free.size < MOUTH_MIN_FREE_SHARE * got.size:
        return math.inf
    return median(free)


def opens_wider(ev: DoorEvidence, width_m: float, sides: tuple[int, ...] = (0, 1)) -> bool:
    """Whether the places beyond an opening ``width_m`` wide are wider than it on ``sides`` (0:
    space ``a``'s side, 1: the other), by WIDEN_FACTOR or WIDEN_MIN_M (see module doc)."""
    limit = max(width_m * WIDEN_FACTOR, width_m + WIDEN_MIN_M)
    return all(ev.beyond_width_m[i] > limit for i in sides)


def hallways_meet(width_m: float, hallway_widths_m: tuple[float, float]) -> bool:
    """Whether an opening ``width_m`` wide between two hallways ``hallway_widths_m`` wide (each
    its typical width, judged along its length) is where they meet, not a door: a door between
    two corridors (a fire door, a door across a corridor) stands in a frame narrower than both by
    a door's widening (WIDEN_FACTOR / WIDEN_MIN_M); an opening as wide as one of them is that
    corridor running into the other (a junction, a corridor's mouth), however a side opening near
    it widens the place beyond it locally."""
    limit = max(width_m * WIDEN_FACTOR, width_m + WIDEN_MIN_M)
    return min(hallway_widths_m) <= limit


def line_turn_deg(occupied: BoolArray, center_rc: tuple[float, float], line_rad: float,
                  resolution_m: float) -> float:
    """The angle (degrees, 0-45) between a line through ``center_rc`` at ``line_rad`` (in the
    (col, row) plane) and the nearest direction of the walls within LOCAL_WALLS_M of it (0 when
    there are too few to tell)."""
    rad = math.ceil(LOCAL_WALLS_M / resolution_m)
    r, c = math.floor(center_rc[0]), math.floor(center_rc[1])
    dirs = dominant_directions(occupied[max(0, r - rad):r + rad + 1, max(0, c - rad):c + rad + 1])
    if not dirs:
        return 0.0
    return math.degrees(min(abs((line_rad - q + math.pi / 2) % math.pi - math.pi / 2) for q in dirs))


def lobby_side(ev: DoorEvidence, params: AnalysisParams, width_m: float) -> int | None:
    """The side (0: space ``a``'s, 1: the other) of an entry lobby behind an opening ``width_m``
    wide between two spaces, deeper than a wall (see module doc), or None: the constriction
    starts within half a wall's thickness of the opening's line on the other side, where the
    place is wider than the door, and runs on no longer than a wall's thickness and LOBBY_MAX_M
    into a place wider than the door."""
    front = ev.constriction_m - ev.constriction_back_m
    for flush, side, lobby in ((ev.constriction_back_m, 1, front), (front, 0, ev.constriction_back_m)):
        past = dataclasses.replace(ev, beyond_width_m=ev.past_width_m)
        if (flush <= params.door_max_depth_m / 2 and opens_wider(ev, width_m, (1 - side,))
                and lobby <= params.door_max_depth_m + LOBBY_MAX_M and opens_wider(past, width_m, (side,))):
            return side
    return None


def is_door(ev: DoorEvidence, params: AnalysisParams, into_unknown: bool, in_wall_line: bool = False,
            width_m: float | None = None) -> bool:
    """The rules of the module doc on one candidate's evidence (``into_unknown``: it opens onto
    unexplored territory, where only its own side was seen; ``in_wall_line``: it is a gap in a
    wall line, as deep as the wall, found so: its depth was judged there; ``width_m``: the
    opening's width, for the places beyond it)."""
    # As deep as a wall (plus the shortest passage): a longer constriction is a passage or a
    # corridor running on. A gap in an outer wall line that deep is an exit at the end of
    # whatever leads to it, a corridor as wide as the door included.
    if in_wall_line:
        pass
    elif into_unknown:
        # Beyond an opening into unexplored territory only rays through it were seen (a strip
        # as narrow as the opening, walled by unknown, not by walls): judge its depth on the
        # side of the space it opens from, half a wall's thickness and a passage.
        if ev.constriction_back_m > params.door_max_depth_m / 2 + params.passage_min_length_m:
            return False
    elif ev.constriction_m > params.door_max_depth_m + params.passage_min_length_m:
        # ... unless it is a door flush with a wall's face onto an entry lobby: the room lies
        # past the lobby (see module doc).
        lobby = None if width_m is None else lobby_side(ev, params, width_m)
        if lobby is None:
            return False
        past, beyond = ev.past_width_m, ev.beyond_width_m
        ev = dataclasses.replace(ev, beyond_width_m=(past[0] if lobby == 0 else beyond[0],
                                                     past[1] if lobby == 1 else beyond[1]))
    # Between two spaces, it opens onto places wider than itself on both sides: the mouth of a
    # corridor running on at its width is no door. (Into the unexplored only rays through it
    # were seen beyond; a gap in a wall line is an exit whatever leads to it.)
    if width_m is not None and not into_unknown and not in_wall_line and not opens_wider(ev, width_m):
        return False
    # Along a wall: the opening's line follows the walls' direction.
    if ev.line_turn_deg > ALONG_MAX_TURN_DEG:
        return False
    # Clear across: the robot fits through it along its line (a speck of clutter in the middle
    # of a "gap" makes it a gap between pieces of clutter). Into the unexplored, only the
    # space's own side: beyond lie the rays through it, a streak each.
    clear = ev.clear_width_m[0] if into_unknown else min(ev.clear_width_m)
    if clear < 2.0 * params.robot_radius_m:
        return False
    # A gap read in a wall line between two spaces is as wide as the floor is clear along its
    # line through its centre (a ragged wall's band shows wider gaps on its outer lines, where
    # the wall's cells stray from them), give or take a door's widening (its frame, a leaf).
    if in_wall_line and not into_unknown and width_m is not None and clear * WIDEN_FACTOR < width_m:
        return False
    # Into the unexplored: beyond lie rays, not a passage running on between walls.
    if into_unknown and ev.walled_beyond_share > STRIP_WALLED_MAX_SHARE:
        return False
    # It was scanned: the robot saw through it.
    if ev.scanned_share < GAP_MIN_FLOOR_SHARE:
        return False
    # Its jambs are walls, not furniture; and not two columns standing free in the floor (a
    # pier between two doors stands beside a wall's end at their other jambs).
    if ev.furniture_jamb or ev.column_jambs:
        return False
    # Both jambs are wall running on along the opening's line (a return beside a corner counts,
    # the bare face of a wall across the line does not: see the module doc).
    return all(a >= JAMB_ALONG_MIN_SHARE for a in ev.along)


def floor_beyond(free: BoolArray, far_from_unknown: BoolArray, center_rc: tuple[float, float],
                 normal_rc: tuple[float, float], side: float, resolution_m: float) -> float:
    """Share of the free cells beyond the opening on ``side`` (+1: along the normal; from a
    wall's thickness to BEYOND_LOOK_M, BEYOND_HALF_WIDTH_M either side of its centre line) that
    lie in ``far_from_unknown`` (seen floor, not a ray with unknown beside it)."""
    nr, nc = normal_rc
    tr, tc = -nc, nr
    t = np.arange(BEYOND_FROM_M, BEYOND_LOOK_M, resolution_m) / resolution_m
    sv = np.arange(-BEYOND_HALF_WIDTH_M, BEYOND_HALF_WIDTH_M + 1e-9, resolution_m) / resolution_m
    rows = center_rc[0] + side * t[:, None] * nr + sv[None, :] * tr
    cols = center_rc[1] + side * t[:, None] * nc + sv[None, :] * tc
    r, c, inside = _cells(free.shape, rows, cols)
    f = np.asarray(take2(free, r, c), dtype=bool)
    if inside is not None:
        f &= inside
    if not f.any():
        return 0.0
    return float(np.asarray(take2(far_from_unknown, r, c), dtype=bool)[f].mean())


def on_wall_line(free: BoolArray, door: RawDoor, resolution_m: float) -> RawDoor:
    """``door`` moved along its normal onto its narrowest free crossing within
    WALL_LINE_SEARCH_M (the nearest such crossing to where it was; unchanged when no crossing
    there is free)."""
    return on_wall_lines(free, [door], resolution_m)[0]


def on_wall_lines(free: BoolArray, doors: Sequence[RawDoor], resolution_m: float) -> list[RawDoor]:
    """:func:`on_wall_line` of each of ``doors``, their free widths read all at once."""
    if not doors:
        return []
    t_m, widths = free_widths_each(free, [d.center_rc for d in doors], [d.normal_rc for d in doors],
                                   resolution_m, WALL_LINE_SEARCH_M)
    out: list[RawDoor] = []
    for door, w_m in zip(doors, widths, strict=True):
        ok = (np.abs(t_m) <= WALL_LINE_SEARCH_M + 1e-9) & (w_m > 0)
        if not ok.any():
            out.append(door)
            continue
        narrowest = np.flatnonzero(ok & (w_m <= w_m[ok].min() + 1e-9))
        step = float(t_m[narrowest[np.argmin(np.abs(t_m[narrowest]))]]) / resolution_m
        nr, nc = door.normal_rc
        out.append(dataclasses.replace(door, center_rc=(door.center_rc[0] + step * nr,
                                                        door.center_rc[1] + step * nc)))
    return out


def judge_doors(candidates: list[RawDoor], free: BoolArray, occupied: BoolArray, resolution_m: float,
                params: AnalysisParams, unknown: BoolArray | None = None) -> tuple[list[RawDoor], list[RawDoor]]:
    """Split ``candidates`` into (doors, the rest) by the rules of the module doc (``unknown``:
    the unscanned cells, for the place beyond each side)."""
    doors: list[RawDoor] = []
    rest: list[RawDoor] = []
    far: BoolArray | None = None
    if unknown is not None and unknown.any() and candidates:
        # Only distances up to SEEN_FLOOR_MIN_M matter: the exact truncated transform (bit for
        # bit the full one's distances up to its bound; farther cells read farther).
        far = far_from_outside(~unknown, SEEN_FLOOR_MIN_M, resolution_m)
    # Between two spaces, judged on the wall line (into the unexplored, the rays beyond would
    # read as the narrowest crossing). The free widths of all candidates are read at once.
    # (A gap found in a wall line is on it already.)
    between = [d for d in candidates if d.b != 0 and not d.in_wall_line]
    moved = iter(on_wall_lines(free, between, resolution_m))
    at_line = [d if d.b == 0 or d.in_wall_line else next(moved) for d in candidates]
    t_m, widths = free_widths_each(free, [a.center_rc for a in at_line], [a.normal_rc for a in at_line],
                                   resolution_m, evidence_look_m())
    for d, at, w_m in zip(candidates, at_line, widths, strict=True):
        ev = evidence(free, occupied, at.center_rc, at.normal_rc, d.width_m, resolution_m, params, unknown,
                      into_unknown=d.b == 0, widths=(t_m, w_m))
        ok = is_door(ev, params, into_unknown=d.b == 0, in_wall_line=d.in_wall_line, width_m=d.width_m)
        if ok and far is not None:
            # A place on each side that is a space: its floor was seen, not only rays through
            # the opening (into unexplored territory: the space's own side).
            # (A gap read in a wall line between two spaces opens from seen floor onto the rays
            # through it, judged so there: seen floor on one side.)
            sides = (-1.0,) if d.b == 0 else (-1.0, 1.0)
            seen = [floor_beyond(free, far, d.center_rc, d.normal_rc, sd, resolution_m) >= BEYOND_MIN_FLOOR_SHARE
                    for sd in sides]
            ok = any(seen) if d.in_wall_line and d.b != 0 else all(seen)
            # ... and a door onto the unexplored has the unexplored beyond it, not seen floor: a
            # line from a wall to the scanned face of a wardrobe whose inside is unknown runs
            # across a room, with the room's floor on both sides. (A gap in a wall line found
            # so has had what lies beyond it judged there.)
            if ok and d.b == 0 and not d.in_wall_line:
                ok = floor_beyond(free, far, d.center_rc, d.normal_rc, 1.0, resolution_m) < BEYOND_MIN_FLOOR_SHARE
        (doors if ok else rest).append(d)
    return doors, rest


__all__ = [
    "SEEN_FLOOR_MIN_M",
    "DoorEvidence",
    "clear_width",
    "constriction_depth",
    "evidence",
    "evidence_look_m",
    "floor_beyond",
    "free_widths",
    "free_widths_each",
    "hallways_meet",
    "is_column",
    "is_door",
    "is_furniture",
    "judge_doors",
    "line_turn_deg",
    "lobby_side",
    "on_wall_line",
    "on_wall_lines",
    "opens_wider",
    "scanned_across",
    "typical_width",
    "walled_strip_share",
]
