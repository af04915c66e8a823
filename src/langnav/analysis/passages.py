"""Narrow passages: tight ways through between two free areas that are not doors.

On the skeleton of the navigable space, the clear width at a skeleton cell is twice its distance to
the nearest blocking cell (occupied, or unknown beyond a noise speck; isolated occupied scan specks
do not block). Skeleton cells whose width is between the robot's diameter and
``params.passage_max_width_m`` form candidate chains. A chain's *core* is where the width stays
close to its typical width (the stretch over which the way stays tight, between two near-parallel
sides, without the flaring mouths; one pinch point does not shorten it, nor, on coarse cells, a jog
of its middle line where a side's outline steps a cell, ``JOG_WIDTH_CELLS``). A core is a passage
when it is longer than a doorway could be deep in this building (``params.door_max_depth_m`` and
``WALL_LENGTHS`` of its typical wall thickness, :func:`typical_wall_thickness_m`; up to
``params.passage_min_length_m``), wide enough for the robot with a margin
(``PASSAGE_MIN_MARGIN_M``: 0.1 m a side, across its axis and by the distance to its sides), has
sides along most of its length (or a wall along one side and a single doorway in the other: a
passage with a door off it), solid ones (walls, furniture, a shelf's unscanned inside: not
laser-ray stripes of unknown, nor the unscanned world beyond a sliver outside a wall, nor an
unexplored area), leads somewhere (both mouths open into free space wider than any passage, or, for
an aisle, into another narrow way that reaches such space within ``MOUTH_LEADS_ON_M`` (the way round a
thing standing in a room, in at one side and out at the other): a dead-end
slot does not), is not a door's own gap (a door across its middle; a door at one of its mouths is
how it is entered; a door found in a squeeze between two things with parallel faces, deeper than
any wall, or across an aisle as long as a corridor between two such things, is no door), and is

* clearly longer than wide (``PASSAGE_MIN_ELONGATION``: an aisle, a checkout lane, a corridor),
  except a strip between a wall and a thing one can walk round (a pallet), which is one only when
  as elongated as a corridor (an aisle along a shelf) or tight, as below; or
* a short squeeze, longer than a wall is thick, between a wall and a thing deeper than any wall
  (a sofa, a bench row's end, a buffet counter: not a door leaf) or between two such things (a
  parked bed and a trolley in a corridor, a column and a planter): its sides are no wall with a
  doorway in it. It is a passage however one could go round when it is tight for a person
  (``TIGHT_WIDTH_M``), except beside a lone thing by a wall that open floor leads round nearby
  (a pallet: one walks round it), or where the ways round it near it are as tight and none
  clearly roomier (one of the equal lanes of a grid of bikes or desks); a roomier one only when
  it is the only way past.

A gap no deeper than a doorway is a door's business, except a gap in a line of free-standing
things (a line of screens, a rail, a detector arch between two machines): neither side is joined
to the building's walls (so no doorway: doorways are in walls), both go on along the line away
from the gap, no door was found there and no scan specks lie across it (a glass front's sparse
returns); it is then judged as a squeeze between two things (tight, or the only way). Its middle
line may be too short for a core (a line a cell or two thick): such throats are judged too, the
way through square to the line between the things either side of the narrowest cell.

A passage along a wall (between the wall and a long shelf) shares its skeleton line with the
one-sided strip along the rest of the room's walls: a core without sides along most of its length
is split into its two-sided stretches, and each is judged on its own. An aisle goes on past an
opening in one of its sides no wider than a door (a cross-over gap in a rack row, a door off a
corridor-like squeeze): the two stretches either side of it, in line, as wide as each other and
each with two sides, are one way, judged whole (its middle line breaks there, where the opening
widens the floor beyond any passage).
"""

from __future__ import annotations

import logging
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from functools import cached_property
from typing import Final

import numpy as np
import numpy.typing as npt
from scipy import ndimage as ndi
from skimage.morphology import skeletonize

from langnav.analysis.elements import Door, NarrowPassage
from langnav.analysis.params import AnalysisParams
from langnav.analysis.passages_lines import (
    JOG_WIDTH_CELLS,
    across_ridge,
    crest,
    jogs,
    joined,
    long_pieces,
    two_sided,
    typical_wall_thickness_m,
)
from langnav.analysis.passages_probe import (
    DOORWAY_WALL_FRACTION,
    MIN_BOUNDED_FRACTION,
    WALL_RUNS_ON_SHARE,
    beside_a_wall,
    deep,
    leads_on,
    opens_into_space,
    parallel,
    past_mouths,
    side_distances,
    side_distances_each,
    sides_hold,
    solid_sides,
    space_beyond,
    way_round,
)
from langnav.analysis.precompute import (
    GridLayers,
    component_boxes,
    cov2,
    dilate8,
    divmod_int,
    label8_cells,
    median,
    truncated_sq_edt,
)
from langnav.maps.grid import OCCUPIED, OccupancyGrid

#: A passage is at least this many times longer than wide: a corridor, not a gap beside an
#: object (a 0.9 m gap along a 0.7 m table is where you walk round it, not a passage).
PASSAGE_MIN_ELONGATION: Final = 2.0
#: The core of a chain: cells no wider than its typical width (this quantile of its widths along
#: it) plus CORE_WIDTH_TOL_M, i.e. the stretch with near-parallel sides. Typical, not the
#: narrowest: a passage is the stretch over which the way stays tight, and one pinch point
#: (a door leaf, a bump of clutter) does not shorten it to the pinch.
CORE_REF_QUANTILE: Final = 0.5
CORE_WIDTH_TOL_M: Final = 0.15
#: The two stretches of one aisle either side of an opening in one of its sides run in line: their
#: axes, and the way across the opening, within this (degrees) of each other. A straight way's
#: stretches, each fitted over a metre or more, agree within a few degrees; an aisle that turns a
#: corner, or two aisles meeting at a cross-over, turn by far more.
SIDE_OPENING_MAX_TURN_DEG: Final = 20.0
#: ... and the side runs on either side of the opening for at least this many times its width
#: (a wall or a rack row with one gap in it), where a row of separate things spaced about as far
#: apart as they are long (bikes, desks) is no side with an opening but a row of gaps: an aisle
#: has one such opening (as a passage may have one doorway in a side wall, DOORWAY_WALL_FRACTION).
SIDE_OPENING_MIN_RUN: Final = 2.0
#: "Close" for a side: within the half-width plus this.
SIDE_TOL_M: Final = 0.15
#: A passage axis within this (degrees) of a grid axis is taken as that axis: pixel noise tilts
#: the fitted axis of a straight passage by a degree or two.
AXIS_SNAP_DEG: Final = 3.0
#: A wall beside a short squeeze runs on past both its mouths (WALL_RUNS_ON_SHARE of the samples
#: blocked), sampled this far past each (m): a wall, not the corner of a jamb.
WALL_RUN_M: Final = 0.6
#: A door lies across a passage when its normal (the way through it) is within 45 degrees of
#: the passage's axis; farther round, it is in a side wall.
DOOR_ACROSS_COS: Final = math.cos(math.radians(45.0))
#: A way round a squeeze between two things is one within this distance of it (m): round a
#: thing standing in a room (a pallet, a pillar), what a person takes instead of squeezing
#: past. A way through other rooms, round a ring corridor or a long machine line, is a detour:
#: the squeeze is still the way.
WAY_ROUND_M: Final = 4.0
#: A short gap with a way round near it as tight as itself is one of equal gaps (the lanes of a
#: grid of bikes or desks) unless a way round is clearly roomier: wider by this (m; scan noise on
#: two faces, as PARALLEL_SPREAD_M), as the open floor round a column and a planter.
EQUAL_GAP_ROOMIER_M: Final = 0.15
#: A squeeze one could go round is a narrow passage only when it is tight for a person: narrower
#: than the narrowest point of an accessible route (0.815 m, 32 in: ADA 403.5.1 lets a 0.915 m
#: route narrow to that for at most 0.61 m), where two people cannot pass and one turns sideways.
#: A roomier gap beside a thing one can walk round is the floor beside it (a pallet by a wall).
TIGHT_WIDTH_M: Final = 0.815
#: A doorway is as long (along the way through) as its wall is thick, give or take scan noise on
#: its jambs; a squeeze past things is no doorway when longer than this many wall thicknesses
#: (plus a cell of that noise) and than the deepest doorway (``door_max_depth_m``). Walls are
#: judged on each map: thin partitions in one building, thick block walls in another.
WALL_LENGTHS: Final = 2.0
#: Where the robot's centre fits with its localisation error (about this much room on each
#: side): the floor of a way round a squeeze.
PASSAGE_SIDE_MARGIN_M: Final = 0.05
#: A narrow passage leaves the robot at least this much room on each side as the map reads it:
#: its localisation error (PASSAGE_SIDE_MARGIN_M) and as much again for the map itself, whose
#: lidar clears a cell or two off a thing's grazed edges (a row of pews 0.35 m apart maps with
#: 0.45-0.5 m gaps). A 0.5 m gap is no way to send a 0.35 m robot through, and no person calls
#: the slot between two pews, seats or bikes a passage.
PASSAGE_MIN_MARGIN_M: Final = 0.1
#: A side is solid when nothing open lies within this depth past where it starts (a shelf's
#: unscanned inside, a wall); laser-ray stripes of unknown are thinner, with free space behind.
SOLID_UNKNOWN_DEPTH_M: Final = 0.3
#: A throat of the middle line (a gap in a thin line: a rail, a line of screens) spans at least
#: this many cells: a line, not a speck of the skeleton.
THROAT_MIN_CELLS: Final = 3
#: The things either side of a throat are read over this much (m) past their nearest cell: the
#: first stretch of a rail or a screen line, enough to set its direction through its pixel steps.
THROAT_SIDE_M: Final = 0.3
#: A thin line beside a gap, drawn askew, steps this many cells off the gap's own band.
THROAT_BAND_CELLS: Final = 2
#: A mouth that opens into another narrow way (the next aisle round a shelving island, the strip
#: round the end of a locker block between two rows of bunks) leads somewhere when that way
#: reaches open floor within this distance of the mouth (m): the way round a thing standing in a
#: room (WAY_ROUND_M), in at one side and out at the other; a dead-end slot's far end leads
#: nowhere however far one looks.
MOUTH_LEADS_ON_M: Final = WAY_ROUND_M

BoolArray = npt.NDArray[np.bool_]

log = logging.getLogger(__name__)


def clearance_m(grid: OccupancyGrid, blocking: BoolArray) -> npt.NDArray[np.float64]:
    """Per cell: distance (m) from its centre to the nearest blocking cell centre (0 on those)."""
    return np.asarray(ndi.distance_transform_edt(~blocking), dtype=np.float64) * grid.resolution_m


@dataclass(frozen=True)
class _Floor:
    """The open floor in a window round the map's open cells (one blocking cell of margin:
    distances inside it are the same as on the whole grid), and what every candidate is judged
    against there."""

    grid: OccupancyGrid
    params: AnalysisParams
    #: The window's first row and column in the grid.
    r0: int
    c0: int
    #: Open cells (neither blocking nor occupied), the occupied cells (scan specks taken out) and
    #: the unscanned world that is no side of a passage (outside the map, unexplored areas).
    open_: BoolArray
    occupied: BoolArray
    outside: BoolArray
    #: Squared distance (cells) to the nearest blocking cell, exact up to a narrow passage's half
    #: width; ``dist_of[d2]`` is that distance in metres, ``width_of[d2]`` the width across a
    #: middle-line cell there.
    d2: npt.NDArray[np.int32]
    dist_of: npt.NDArray[np.float64]
    width_of: npt.NDArray[np.float64]
    #: Where the robot's centre fits with its margin; floor wider than any narrow passage.
    fits: BoolArray
    wide: BoolArray
    #: A piece of middle line spanning fewer cells than this is too short to be a passage, mouths
    #: included; a two-sided stretch shorter than ``min_len_m`` is no longer than a doorway is deep.
    min_cells: float
    min_len_m: float

    def reject(self, reason: str, centre_g: npt.NDArray[np.float64], width_m: float = math.nan,
               length_m: float = math.nan) -> None:
        """Log (debug) why a candidate (its centre in window cells) is no passage: what a reader
        of a map asks when a passage they point at is not found."""
        if log.isEnabledFor(logging.DEBUG):
            x, y = self.grid.grid_to_world(centre_g[1] + self.r0, centre_g[0] + self.c0)
            log.debug("no passage at (%.2f, %.2f), width %.2f m, length %.2f m: %s", float(x), float(y), width_m,
                      length_m, reason)

    @cached_property
    def structure(self) -> tuple[BoolArray, npt.NDArray[np.int32]]:
        """The building's structure and its things: per window cell, whether it is blocking
        joined (8-connected) to the window's edge (walls run into each other and into the
        unscanned world beyond the outer ones), and the label of the blocking component it is in
        (0 on open floor). A component that does not reach the edge stands free in the floor:
        a piece of furniture, a screen, a rail."""
        lab, _n = ndi.label(~self.open_, structure=np.ones((3, 3), dtype=bool))
        lab = np.asarray(lab, dtype=np.int32)
        edge = np.unique(np.concatenate([lab[0], lab[-1], lab[:, 0], lab[:, -1]]))
        return np.isin(lab, edge[edge > 0]), lab

    def to_world(self, g: npt.NDArray[np.float64]) -> tuple[float, float]:
        """A point in window cells (x, y) in world metres."""
        x, y = self.grid.grid_to_world(g[1] + self.r0, g[0] + self.c0)
        return float(x), float(y)


@dataclass(frozen=True)
class _Piece:
    """A piece of middle line: its cells (window rows, cols), whether each is a ridge across (a
    whole core's cells; None for a two-sided stretch split off one), its points (x, y at cell
    centres), their mean, the unit axis fitted through them and each point's position along it."""

    rr: npt.NDArray[np.intp]
    cc: npt.NDArray[np.intp]
    across: BoolArray | None
    pts: npt.NDArray[np.float64]
    mean: npt.NDArray[np.float64]
    axis: npt.NDArray[np.float64]
    proj: npt.NDArray[np.float64]
    #: A throat shorter than a passage's core (:func:`_core_pieces`): a passage only between
    #: free-standing things.
    short: bool = False

    @property
    def normal(self) -> npt.NDArray[np.float64]:
        """The axis turned a quarter anticlockwise."""
        return np.array([-self.axis[1], self.axis[0]])


@dataclass(frozen=True)
class _Stretch:
    """Where a piece has two sides: per point, the distances (cells) to either side (``inf``
    where open), which points have both, its width (m) across them, its extent ``lo``..``hi``
    along the axis (cells from the piece's mean), its length (m) and its middle (window cells)."""

    sides: npt.NDArray[np.float64]
    bounded: BoolArray
    width_m: float
    lo: float
    hi: float
    length_m: float
    mid: npt.NDArray[np.float64]

    @property
    def half_len(self) -> float:
        """Half its length, in cells."""
        return (self.hi - self.lo + 1.0) / 2.0


def find_passages(grid: OccupancyGrid, params: AnalysisParams, labels: npt.NDArray[np.int32],
                  room_ids: Mapping[int, str], doors: Sequence[Door], blocking: BoolArray,
                  dist_m: npt.NDArray[np.float64] | None = None,
                  layers: GridLayers | None = None,
                  unexplored: BoolArray | None = None) -> tuple[NarrowPassage, ...]:
    """Narrow passages of the navigable space ``~blocking`` (see the module docstring).

    ``dist_m`` is :func:`clearance_m` of ``blocking`` when the caller already has it; ``layers``
    the grid's shared masks (built when not given); ``unexplored`` the unknown cells of the
    unexplored areas worth a look (:mod:`langnav.analysis.unexplored`): like the world outside the
    map, unscanned floor that is no side of a passage (nothing is known to stand there).

    The stages: the open floor and its clearances (:func:`_open_floor`); the cores of the middle
    line where it is narrow (:func:`_core_pieces`), those either side of an opening in one side
    of an aisle joined (:func:`_joined_across_side_openings`); each piece's axis and sides
    (:func:`_measured`); then each is judged (:func:`_judged`). Cores without sides along most of
    their length are split into their two-sided stretches (:func:`_two_sided_pieces`), which are
    judged in a second round.
    """
    floor = _open_floor(grid, params, blocking, dist_m, layers or GridLayers(grid), unexplored)
    if floor is None:
        return ()
    passages: list[NarrowPassage] = []
    cores, throats = _core_pieces(floor)
    pieces = _joined_across_side_openings(floor, cores)
    measured = _measured(floor, pieces) + _measured(floor, throats, short=True)
    while measured:
        retry: list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp]]] = []
        for piece, sides in measured:
            found = _judged(floor, piece, sides, doors, labels, room_ids, f"passage_{len(passages) + 1}", retry)
            if found is not None:
                passages.append(found)
        measured = _measured(floor, _two_sided_pieces(floor, retry))
    return tuple(passages)


def _open_floor(grid: OccupancyGrid, params: AnalysisParams, blocking: BoolArray,
                dist_m: npt.NDArray[np.float64] | None, layers: GridLayers,
                unexplored: BoolArray | None) -> _Floor | None:
    """The open floor round the map's open cells and its clearances (:class:`_Floor`); None when
    nothing is open."""
    res = grid.resolution_m
    exterior = layers.exterior if unexplored is None else layers.exterior | unexplored
    # Scan-noise specks (isolated occupied clusters no bigger than the segmentation's specks,
    # which it reads as floor) neither narrow a passage nor make one of its sides: a person
    # reading the map looks past the dots a lidar leaves in an aisle.
    occ = layers.occupied_components
    speck_max = params.seg_speck_max_area_m2 / grid.cell_area_m2
    specks = (occ.sizes <= speck_max)[occ.labels] & layers.occupied
    occupied = layers.occupied & ~specks
    blocking = blocking & ~specks
    open_ = ~blocking & ~occupied
    rows_any = np.flatnonzero(open_.any(axis=1))
    cols_any = np.flatnonzero(open_.any(axis=0))
    if len(rows_any) == 0:
        return None
    # Work in the window around the open cells, one blocking cell of margin: distances inside
    # it are the same as on the whole grid (the margin ring separates it from the rest).
    r0, r1 = max(0, int(rows_any[0]) - 1), min(open_.shape[0], int(rows_any[-1]) + 2)
    c0, c1 = max(0, int(cols_any[0]) - 1), min(open_.shape[1], int(cols_any[-1]) + 2)
    sub = open_[r0:r1, c0:c1]
    # Only short clearances matter (up to a narrow passage's half width): squared distances in
    # cells, exact up to that, from a truncated transform; tables give each one's distance and width.
    reach = math.floor((params.passage_max_width_m + res) / (2.0 * res)) + 1
    if dist_m is None:
        d2 = truncated_sq_edt(sub, reach)
    else:
        d_cells = np.minimum(dist_m[r0:r1, c0:c1] / res, reach + 1)
        d2 = np.rint(d_cells * d_cells).astype(np.int32)
    dist_of = np.sqrt(np.arange(int(d2.max()) + 1, dtype=np.float64)) * res
    # Width across the medial axis: the centre-to-centre distance to a side, minus half a cell, twice.
    width_of = 2.0 * dist_of - res
    # A chain, its flaring mouths included (about a width more than where it has two sides), is
    # at least passage_min_length_m long; where it has two sides, longer than a doorway could be
    # deep: deeper than the deepest doorway (door_max_depth_m) and than this building's own walls
    # (a doorway's way through is as long as its wall is thick), up to passage_min_length_m.
    min_len_m = min(params.passage_min_length_m, max(params.door_max_depth_m,
                    WALL_LENGTHS * typical_wall_thickness_m(layers.occupied, layers.free, res) + res))
    return _Floor(grid=grid, params=params, r0=r0, c0=c0, open_=sub, occupied=occupied[r0:r1, c0:c1],
                  outside=exterior[r0:r1, c0:c1], d2=d2, dist_of=dist_of, width_of=width_of,
                  # Where the robot's centre fits with its margin (the distance table is exact that far).
                  fits=dist_of[d2] > params.robot_radius_m + PASSAGE_SIDE_MARGIN_M,
                  wide=dist_of[d2] > params.passage_max_width_m / 2.0,
                  min_cells=params.passage_min_length_m / res - 1.0, min_len_m=min_len_m)


def _core_pieces(floor: _Floor) -> tuple[list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp], BoolArray | None]],
                                          list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp], BoolArray | None]]]:
    """The cores of the narrow middle line long enough to be passages: per core its cells (window
    rows, cols) and which of them are a ridge across (:func:`across_ridge`); and the throats, whole
    chains too short for such a core (``THROAT_MIN_CELLS`` or more): a gap in a thin line (a rail,
    a line of screens), whose middle line is no longer than the line is thick plus a cell or two,
    a passage only in a line of free-standing things (:func:`_in_a_line`)."""
    params, res, d2, width_of = floor.params, floor.grid.resolution_m, floor.d2, floor.width_of
    band_of = (width_of > 2.0 * params.robot_radius_m) & (width_of <= params.passage_max_width_m)
    band = floor.open_ & band_of[d2]
    # The medial axis within the band: crest cells of the distance map (clearly higher than the
    # cells two steps away on both sides, across some direction), a cell thicker (to bridge the
    # sideways step of the crest where a side has a bump), thinned to one cell. Cheaper than
    # skeletonising all free space.
    skel = skeletonize(band & dilate8(crest(d2)))
    # Chains of the skeleton (8-connected), labelled from its few cells, not the whole window.
    idx = np.flatnonzero(skel)
    cid, n = label8_cells(idx, skel.shape)
    if n == 0:
        return [], []
    w = width_of[d2.ravel()[idx]]
    # Per chain: its typical width (sort by (chain, width), pick the rank).
    order = np.lexsort((w, cid))
    cid_s, w_s = cid[order], w[order]
    starts = np.searchsorted(cid_s, np.arange(1, n + 1))
    counts = np.bincount(cid, minlength=n + 1)[1:]
    ref = w_s[starts + (counts * CORE_REF_QUANTILE).astype(int)]
    in_core = w <= ref[cid - 1] + CORE_WIDTH_TOL_M
    if JOG_WIDTH_CELLS * res > CORE_WIDTH_TOL_M:
        # (On finer cells the tolerance already spans a jog's jump.)
        in_core |= jogs(idx, in_core, w <= ref[cid - 1] + CORE_WIDTH_TOL_M + JOG_WIDTH_CELLS * res,
                        ref[cid - 1] / res, skel.shape)
    core_idx = idx[in_core]
    core_id, m = label8_cells(core_idx, skel.shape)
    # Necessary conditions, vectorised, before the per-core work: a chain of n cells spans at
    # most n * sqrt(2) cells and at most its bounding box's diagonal.
    n_cells = np.bincount(core_id, minlength=m + 1)
    long_enough = np.flatnonzero(n_cells * math.sqrt(2) >= floor.min_cells)
    long_enough = long_enough[long_enough > 0]
    core_r, core_c = divmod_int(core_idx, floor.open_.shape[1])
    boxes = component_boxes(core_id, core_r, core_c, long_enough)
    # Each core's cells, in raster order.
    by_core = np.argsort(core_id, kind="stable")
    core_start = np.searchsorted(core_id[by_core], np.arange(m + 2))
    # Which cells are a ridge across: a per-cell test, made for all the core cells at once.
    across_core = across_ridge(d2, core_r, core_c)
    pieces: list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp], BoolArray | None]] = []
    has_core = np.zeros(n + 1, dtype=bool)
    core_chain = cid[in_core]
    for k in long_enough.tolist():
        sl = boxes[k]
        if math.hypot(sl[0].stop - sl[0].start, sl[1].stop - sl[1].start) < floor.min_cells:
            continue
        cells = by_core[core_start[k]:core_start[k + 1]]
        pieces.append((core_r[cells], core_c[cells], across_core[cells]))
        has_core[core_chain[cells[0]]] = True
    # The throats: the whole chains too short to hold a core that long (a gap in a thin line: its
    # middle line runs only through the gap, as long as the line is thick, a cell or two more:
    # the sides flare at once), of THROAT_MIN_CELLS or more (fewer is a speck of the skeleton).
    gap_cells = float(THROAT_MIN_CELLS)
    short = np.flatnonzero((counts * math.sqrt(2) >= gap_cells) & ~has_core[1:]) + 1
    throats: list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp], BoolArray | None]] = []
    if len(short):
        chain_r, chain_c = divmod_int(idx, floor.open_.shape[1])
        chain_boxes = component_boxes(cid, chain_r, chain_c, short)
        by_chain = np.argsort(cid, kind="stable")
        chain_start = np.searchsorted(cid[by_chain], np.arange(n + 2))
        for k in short.tolist():
            sl = chain_boxes[k]
            if not gap_cells <= math.hypot(sl[0].stop - sl[0].start, sl[1].stop - sl[1].start) < floor.min_cells:
                continue
            cells = by_chain[chain_start[k]:chain_start[k + 1]]
            throats.append((chain_r[cells], chain_c[cells], None))
    return pieces, throats


def _joined_across_side_openings(
        floor: _Floor, pieces: list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp], BoolArray | None]]
) -> list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp], BoolArray | None]]:
    """The pieces, those that are stretches of one aisle either side of an opening in one of its
    sides joined into one: each with two sides along most of it (``MIN_BOUNDED_FRACTION``), as
    wide as each other (within ``CORE_WIDTH_TOL_M`` and a cell a side), in line
    (``SIDE_OPENING_MAX_TURN_DEG``), their facing ends no farther apart than a door is wide
    (``door_max_width_m``), and across the gap one side going on (blocked along
    ``DOORWAY_WALL_FRACTION`` of it) while the other opens (along half of it or more) and runs on
    beside the opening for ``SIDE_OPENING_MIN_RUN`` times its width either side: a rack row
    with a cross-over gap beside the aisle, a door in a corridor's side wall. Where both sides
    open across the gap (a cross aisle between two aisles in line) they stay two; one opening
    per aisle (a row of separate things beside a strip is a row of gaps)."""
    res = floor.grid.resolution_m
    # Each piece's points, axis, extent along it and half width (cells); its sides.
    pts_of, fits_of = [], []
    for rr, cc, _across in pieces:
        pts = np.stack([cc + 0.5, rr + 0.5], axis=1).astype(float)
        pts_of.append(pts)
        fits_of.append(len(rr) >= 2)
    shape: list[tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], float, float, float]] = []
    for (rr, cc, _across), pts, ok in zip(pieces, pts_of, fits_of, strict=True):
        if not ok:
            shape.append((np.zeros(2), np.zeros(2), 0.0, 0.0, 0.0))
            continue
        mean = pts.mean(axis=0)
        evals, evecs = np.linalg.eigh(cov2((pts - mean).T))
        axis = evecs[:, int(np.argmax(evals))]
        proj = (pts - mean) @ axis
        shape.append((mean, axis, float(proj.min()), float(proj.max()),
                      median(floor.dist_of[floor.d2[rr, cc]]) / res))
    idx = [k for k, ok in enumerate(fits_of) if ok]
    side_sets = side_distances_each(floor.open_, [pts_of[k] for k in idx],
                                    [floor.dist_of[floor.d2[pieces[k][0], pieces[k][1]]] / res for k in idx],
                                    [np.array([-shape[k][1][1], shape[k][1][0]]) for k in idx], SIDE_TOL_M / res)
    two_sided = {k for k, sides in zip(idx, side_sets, strict=True)
                 if np.isfinite(sides).all(axis=1).mean() >= MIN_BOUNDED_FRACTION}
    cos_in_line = math.cos(math.radians(SIDE_OPENING_MAX_TURN_DEG))
    max_gap = floor.params.door_max_width_m / res
    cand = sorted(two_sided)
    ends = {k: (shape[k][0] + shape[k][2] * shape[k][1], shape[k][0] + shape[k][3] * shape[k][1]) for k in cand}
    pairs: list[tuple[float, int, int]] = []
    for n, i in enumerate(cand):
        mean_i, axis_i, _lo, _hi, half_i = shape[i]
        for j in cand[n + 1:]:
            axis_j, half_j = shape[j][1], shape[j][4]
            if (abs(float(axis_i @ axis_j)) < cos_in_line
                    or abs(half_i - half_j) > CORE_WIDTH_TOL_M / res / 2.0 + 1.0):
                continue
            gap, a, b = min(((float(np.hypot(*(x - y))), x, y) for x in ends[i] for y in ends[j]),
                            key=lambda t: t[0])
            if not 0.5 < gap <= max_gap:
                continue
            way = (b - a) / gap
            # Across the gap in line, and beyond piece i's end (not back over it).
            if (abs(float(way @ axis_i)) < cos_in_line
                    or abs(float((b - mean_i) @ axis_i)) <= abs(float((a - mean_i) @ axis_i))):
                continue
            # Along the whole way, from the far end of one stretch to the far end of the other.
            far_a = ends[i][0] if float(np.hypot(*(ends[i][0] - a))) > float(np.hypot(*(ends[i][1] - a))) else ends[i][1]
            far_b = ends[j][0] if float(np.hypot(*(ends[j][0] - b))) > float(np.hypot(*(ends[j][1] - b))) else ends[j][1]
            span = float(np.hypot(*(far_b - far_a)))
            pos = np.arange(0.0, span + 0.25, 0.5)
            line = far_a[None, :] + (pos / max(span, 1e-9))[:, None] * (far_b - far_a)[None, :]
            sides = np.isfinite(side_distances(floor.open_, line, np.full(len(pos), max(half_i, half_j)),
                                               np.array([-axis_i[1], axis_i[0]]), SIDE_TOL_M / res))
            in_gap = ((pos >= float(np.hypot(*(a - far_a))) + 0.5) & (pos <= float(np.hypot(*(b - far_a))) - 0.5))
            if not in_gap.any():
                continue
            held = sides[in_gap].mean(axis=0)
            if held.max() < DOORWAY_WALL_FRACTION or held.min() > 0.5:
                continue
            # The opening: the open run of the other side round the gap's middle; the side runs on
            # beside it, blocked along SIDE_OPENING_MIN_RUN times its width before and after it.
            other = sides[:, int(np.argmin(held))]
            mid_k = int(np.flatnonzero(in_gap)[len(np.flatnonzero(in_gap)) // 2])
            lo_k = mid_k
            while lo_k > 0 and not other[lo_k - 1]:
                lo_k -= 1
            hi_k = mid_k
            while hi_k < len(other) - 1 and not other[hi_k + 1]:
                hi_k += 1
            opening = (hi_k - lo_k + 1) * 0.5
            if min(other[:lo_k].sum(), other[hi_k + 1:].sum()) * 0.5 >= SIDE_OPENING_MIN_RUN * opening:
                pairs.append((gap, i, j))
    # Join them in pairs, the nearest first: an aisle with one opening in a side.
    partner: dict[int, int] = {}
    for _gap, i, j in sorted(pairs):
        if i not in partner and j not in partner:
            partner[i], partner[j] = j, i
    out: list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp], BoolArray | None]] = []
    for k in range(len(pieces)):
        if k not in partner:
            out.append(pieces[k])
            continue
        if partner[k] < k:
            continue
        group = [k, partner[k]]
        across_cells = [pieces[g][2] for g in group]
        joined_across = (None if any(a_ is None for a_ in across_cells)
                         else np.concatenate([a_ for a_ in across_cells if a_ is not None]))
        out.append((np.concatenate([pieces[g][0] for g in group]), np.concatenate([pieces[g][1] for g in group]),
                    joined_across))
    return out


def _measured(floor: _Floor, pieces: list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp], BoolArray | None]],
              short: bool = False) -> list[tuple[_Piece, npt.NDArray[np.float64]]]:
    """Each piece's axis and length, and the cheap test first (with the skeleton's width, at most
    a cell narrower than the true one); then the distances to the sides of all that pass, at
    once: the pieces at least ``passage_min_length_m`` long (``THROAT_MIN_CELLS`` for the
    ``short`` throats of :func:`_core_pieces`), with their sides."""
    res = floor.grid.resolution_m
    measured: list[_Piece] = []
    for rr, cc, across in pieces:
        if len(rr) < 2:
            continue
        pts = np.stack([cc + 0.5, rr + 0.5], axis=1).astype(float)
        mean = pts.mean(axis=0)
        cov = cov2((pts - mean).T)
        evals, evecs = np.linalg.eigh(cov)
        axis = evecs[:, int(np.argmax(evals))]
        if short:
            # A throat's few cells fit no axis: the way through runs across the line between
            # the nearest blocking cells on either side of its narrowest cell.
            axis = _throat_axis(floor, rr, cc, axis)
        # Snap a nearly axis-aligned passage onto the grid axis (cleaner width sampling).
        if abs(axis[0]) >= math.cos(math.radians(AXIS_SNAP_DEG)):
            axis = np.array([math.copysign(1.0, axis[0]), 0.0])
        elif abs(axis[1]) >= math.cos(math.radians(AXIS_SNAP_DEG)):
            axis = np.array([0.0, math.copysign(1.0, axis[1])])
        proj = (pts - mean) @ axis
        # Short ones too (a squeeze past furniture beside a wall is as deep as the furniture,
        # its mouths flaring on either side).
        if (float(proj.max() - proj.min()) + 1.0) < (
                THROAT_MIN_CELLS if short else floor.params.passage_min_length_m / res):
            continue
        measured.append(_Piece(rr=rr, cc=cc, across=across, pts=pts, mean=mean, axis=axis, proj=proj, short=short))
    side_sets = side_distances_each(floor.open_, [p.pts for p in measured],
                                    [floor.dist_of[floor.d2[p.rr, p.cc]] / res for p in measured],
                                    [p.normal for p in measured], SIDE_TOL_M / res)
    return list(zip(measured, side_sets, strict=True))


def _throat_axis(floor: _Floor, rr: npt.NDArray[np.intp], cc: npt.NDArray[np.intp],
                 fallback: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
    """The way through a throat (unit x, y in cells): square to the line between the two things
    either side of its narrowest cell, each taken as its blocking cells within ``THROAT_SIDE_M``
    past the nearest one (their middle: one cell's pixel steps do not tilt it), the far one on
    the other side of that cell from the nearest (``fallback`` when there is none within a
    passage's width)."""
    k = int(np.argmin(floor.d2[rr, cc]))
    r, c = int(rr[k]), int(cc[k])
    res = floor.grid.resolution_m
    reach = math.ceil((floor.params.passage_max_width_m + THROAT_SIDE_M) / res)
    h, w = floor.open_.shape
    r0, c0 = max(0, r - reach), max(0, c - reach)
    br, bc = np.nonzero(~floor.open_[r0:min(h, r + reach + 1), c0:min(w, c + reach + 1)])
    if len(br) == 0:
        return fallback
    v = np.stack([bc + c0 - c, br + r0 - r], axis=1).astype(float)
    n = np.sqrt((v * v).sum(axis=1))
    first = v[int(np.argmin(n))]
    far = v @ first < 0
    if not far.any():
        return fallback
    near_d, far_d = float(n.min()), float(n[far].min())
    side_a = v[~far & (n <= near_d + THROAT_SIDE_M / res)].mean(axis=0)
    side_b = v[far & (n <= far_d + THROAT_SIDE_M / res)].mean(axis=0)
    across = side_b - side_a
    norm = float(np.hypot(*across))
    if norm == 0.0:
        return fallback
    return np.array([across[1], -across[0]]) / norm


def _judged(floor: _Floor, piece: _Piece, sides: npt.NDArray[np.float64], doors: Sequence[Door],
            labels: npt.NDArray[np.int32], room_ids: Mapping[int, str], passage_id: str,
            retry: list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp]]]) -> NarrowPassage | None:
    """The narrow passage a piece is, or None (the reason logged). A whole core without sides
    along most of its length adds its ridge cells to ``retry``, to be split into its two-sided
    stretches."""
    if not sides_hold(sides, piece.proj, floor.params.door_max_width_m / floor.grid.resolution_m):
        if piece.across is not None and len(piece.rr) * math.sqrt(2) >= floor.min_cells:
            retry.append((piece.rr[piece.across], piece.cc[piece.across]))
        floor.reject('no two sides along it', piece.pts.mean(axis=0))
        return None
    stretch = _two_sided_stretch(floor, piece, sides)
    if stretch is None:
        return None
    if stretch.length_m < floor.min_len_m and not piece.short:
        # A gap between free-standing things, shorter than a doorway: its sides are where it is
        # narrowest, and the way through runs square to them (_throat_axis), not along the chain
        # with its flaring mouths (askew across a thin line, the probes miss the line).
        again = _measured(floor, [(piece.rr, piece.cc, None)], short=True)
        return _judged(floor, *again[0], doors, labels, room_ids, passage_id, retry) if again else None
    if not _leads_somewhere(floor, piece, stretch):
        floor.reject('a mouth leads nowhere', stretch.mid, stretch.width_m, stretch.length_m)
        return None
    # A gap no deeper than a doorway between free-standing things (_two_sided_stretch) where a
    # door was found is that door: the things may be the pieces of a wall broken by laser gaps.
    # Nor is it a gap where scan specks lie across it: the sparse returns of a glass front or a
    # thin rail, the line goes on there.
    if stretch.length_m < floor.min_len_m:
        if any(math.dist(d.center, floor.to_world(stretch.mid)) <= stretch.length_m / 2 + floor.params.door_max_depth_m
               for d in doors):
            floor.reject('a door', stretch.mid, stretch.width_m, stretch.length_m)
            return None
        if not _in_a_line(floor, piece, stretch):
            floor.reject('shorter than a doorway is deep', stretch.mid, stretch.width_m, stretch.length_m)
            return None
        if _specks_across(floor, piece, stretch):
            floor.reject('scan specks across it: the line goes on', stretch.mid, stretch.width_m, stretch.length_m)
            return None
    squeeze = False
    if stretch.length_m < floor.params.hallway_min_elongation * stretch.width_m:
        gap = _short_way(floor, piece, stretch, doors)
        if gap is None:
            return None
        squeeze, thing = gap
    else:
        thing = None
    if _is_a_door(floor, piece, stretch, doors, squeeze, thing):
        floor.reject('a door', stretch.mid, stretch.width_m, stretch.length_m)
        return None
    return _passage(floor, piece, stretch, labels, room_ids, passage_id)


def _two_sided_stretch(floor: _Floor, piece: _Piece, sides: npt.NDArray[np.float64]) -> _Stretch | None:
    """The stretch of a piece that has sides, when it is as long, wide and solid-sided as a
    passage; None (the reason logged) otherwise."""
    params, res, d2 = floor.params, floor.grid.resolution_m, floor.d2
    bounded: BoolArray = np.asarray(np.isfinite(sides).all(axis=1), dtype=bool)
    # Width: across the passage between its two sides (exact for axis-aligned sides).
    width_m = (median(sides[bounded].sum(axis=1)) - 0.5) * res
    if piece.short and bounded.any():
        # A throat is as wide as it is at its narrowest: its few samples across a thin line drawn
        # askew may hit the line a step past its end.
        width_m = (float(sides[bounded].sum(axis=1).min()) - 0.5) * res
    # It runs where it has two sides: not on into its flaring mouths.
    lo, hi = float(piece.proj[bounded].min()), float(piece.proj[bounded].max())
    length_m = (hi - lo + 1.0) * res
    mid = piece.mean + 0.5 * (lo + hi) * piece.axis
    # A doorway is as deep as its wall is thick: a shorter gap is a door's business, except
    # between two things that stand free (a gap in a line of screens, a rail or a detector arch
    # standing in a room, open floor round its ends): a wall runs into the building's other
    # walls, so a gap between two free-standing things is in no wall, however thin they are.
    if ((length_m < floor.min_len_m or piece.short)
            and _free_standing_things(floor, piece, sides, bounded) is None):
        floor.reject('shorter than a doorway is deep', mid, width_m, length_m)
        return None
    # Wide enough for the robot to pass, and narrow (the band's test used the skeleton's
    # width, up to a cell off).
    # Across its axis, and by the distance from its middle line to its sides whatever
    # the direction (twice it, up to a cell over): an axis drawn askew through a strip
    # (round the corner of a box) measures it wider than it is.
    min_width_m = 2.0 * (params.robot_radius_m + PASSAGE_MIN_MARGIN_M)
    if (width_m < min_width_m or width_m > params.passage_max_width_m
            or 2.0 * median(floor.dist_of[d2[piece.rr[bounded], piece.cc[bounded]]]) < min_width_m):
        floor.reject('too narrow or too wide', mid, width_m, length_m)
        return None
    # Between two things: both sides solid along most of its two-sided length, not
    # laser-ray stripes.
    solid = solid_sides(floor.open_, floor.occupied, floor.outside, piece.pts, piece.normal, sides,
                        SOLID_UNKNOWN_DEPTH_M / res)
    if np.count_nonzero(solid) < MIN_BOUNDED_FRACTION * np.count_nonzero(bounded):
        floor.reject('sides not solid', mid, width_m, length_m)
        return None
    return _Stretch(sides=sides, bounded=bounded, width_m=width_m, lo=lo, hi=hi, length_m=length_m, mid=mid)


def _free_standing_things(floor: _Floor, piece: _Piece, sides: npt.NDArray[np.float64],
                          bounded: BoolArray) -> tuple[int, int] | None:
    """The two free-standing things a stretch runs between, when it does: where its two sides
    start (along most of its two-sided points, ``MIN_BOUNDED_FRACTION``), blocking that is no
    part of the building's structure (:attr:`_Floor.structure`: walls joined to each other and to
    the world beyond them), a different thing on each side (not a slot in one thing). Their
    labels (the commonest on each side); None when it does not."""
    if not bounded.any():
        return None
    structure, things = floor.structure
    h, w = structure.shape
    on: list[npt.NDArray[np.int32]] = []
    for j, sign in enumerate((-1.0, 1.0)):
        # The first blocked sample of side_distances, the same arithmetic.
        t = sign * sides[bounded, j]
        r = np.clip(np.floor(piece.pts[bounded, 1] + t * piece.normal[1]).astype(int), 0, h - 1)
        c = np.clip(np.floor(piece.pts[bounded, 0] + t * piece.normal[0]).astype(int), 0, w - 1)
        lab = things[r, c]
        if np.count_nonzero((lab > 0) & ~structure[r, c]) < MIN_BOUNDED_FRACTION * len(lab):
            return None
        on.append(lab[lab > 0])
    if len(np.intersect1d(on[0], on[1])):
        return None
    a, b = (int(np.bincount(o).argmax()) for o in on)
    return a, b


def _in_a_line(floor: _Floor, piece: _Piece, stretch: _Stretch) -> bool:
    """Is a stretch no deeper than a doorway a gap in a line of free-standing things (a line of
    screens, a rail, a detector arch between two machines): between two of them
    (:func:`_free_standing_things`: no wall, so no doorway), each going on away from the gap
    along the line, deeper than any wall is thick (``door_max_depth_m``), not a thing running
    along the way beside it (the end of a rack row beside a cross aisle)?"""
    res = floor.grid.resolution_m
    b = stretch.bounded
    pair = _free_standing_things(floor, piece, stretch.sides, b)
    if pair is None:
        return False
    depth = floor.params.door_max_depth_m / res
    return all(deep(floor.open_, piece.pts[b], piece.normal * (2 * j - 1), stretch.sides[b, j], depth, res)
               or _reaches(floor, pair[j], stretch, piece.normal * (2 * j - 1), depth) for j in (0, 1))


def _reaches(floor: _Floor, thing: int, stretch: _Stretch, outward: npt.NDArray[np.float64],
             depth: float) -> bool:
    """Does a free-standing thing (its label in :attr:`_Floor.structure`) beside a short stretch
    reach ``depth`` cells along ``outward`` (x, y in cells, square to the way), within the band
    the stretch spans along the way (and ``THROAT_BAND_CELLS`` either side: a thin line drawn
    askew in steps): a line that goes on away from the gap, not a thing that runs along the way
    beside it?"""
    _structure, lab = floor.structure
    mid = stretch.mid
    pad = math.ceil(depth + floor.params.passage_max_width_m / floor.grid.resolution_m) + 1
    h, w = lab.shape
    r0, c0 = max(0, math.floor(mid[1]) - pad), max(0, math.floor(mid[0]) - pad)
    rr, cc = np.nonzero(lab[r0:min(h, math.floor(mid[1]) + pad + 1), c0:min(w, math.floor(mid[0]) + pad + 1)] == thing)
    dx, dy = cc + c0 + 0.5 - mid[0], rr + r0 + 0.5 - mid[1]
    way = np.abs(dx * outward[1] - dy * outward[0])
    along = (dx * outward[0] + dy * outward[1])[way <= stretch.half_len + THROAT_BAND_CELLS]
    return bool(len(along) and along.max() - along.min() >= depth)


def _specks_across(floor: _Floor, piece: _Piece, stretch: _Stretch) -> bool:
    """Are there scan specks (occupied cells the floor reads past) on the line across a stretch's
    middle, between its two sides: the sparse returns of the line it is a gap in (a glass front,
    a thin rail), which goes on there?"""
    b = stretch.bounded
    lo = -median(stretch.sides[b, 0])
    hi = median(stretch.sides[b, 1])
    t = np.arange(lo + 1.0, hi - 0.5, 0.5)
    if len(t) == 0:
        return False
    pts = stretch.mid[None, :] + t[:, None] * piece.normal[None, :]
    r = np.floor(pts[:, 1]).astype(int) + floor.r0
    c = np.floor(pts[:, 0]).astype(int) + floor.c0
    h, w = floor.grid.cells.shape
    ok = (r >= 0) & (r < h) & (c >= 0) & (c < w)
    return bool((floor.grid.cells[r[ok], c[ok]] == OCCUPIED).any())


def _leads_somewhere(floor: _Floor, piece: _Piece, stretch: _Stretch) -> bool:
    """Does the stretch lead somewhere: both mouths open into free space wider than any passage,
    or, for an aisle, into another narrow way that goes on to open floor nearby?"""
    res, params = floor.grid.resolution_m, floor.params
    pts, proj, axis, bounded = piece.pts, piece.proj, piece.axis, stretch.bounded
    ends_g = [piece.mean + stretch.lo * axis, piece.mean + stretch.hi * axis]
    # A way as elongated as a corridor leaves through the last cell of its middle line at each
    # end (where an aisle bends at its end, the end of its straight axis falls in its side); a
    # short gap's axis across a bend is no way's axis.
    two = pts[bounded]
    lasts = ([two[int(np.argmin(proj[bounded]))], two[int(np.argmax(proj[bounded]))]]
             if stretch.length_m >= params.hallway_min_elongation * stretch.width_m else [None, None])
    # An aisle (at least PASSAGE_MIN_ELONGATION times longer than wide) whose mouth opens
    # into another narrow way leads somewhere when that way goes on to open floor nearby
    # (aisles round a shelving island meet at its corners; rack aisles end in a narrow
    # cross aisle). Its own middle line: its two-sided stretch, not the next aisle's.
    aisle = stretch.length_m >= PASSAGE_MIN_ELONGATION * stretch.width_m
    own = ((proj >= stretch.lo) & (proj <= stretch.hi)
           & (np.abs((pts - piece.mean) @ piece.normal) <= stretch.width_m / res / 2.0 + 1.0))
    return all(opens_into_space(floor.open_, e, sign * axis, res, params, last)
               or (aisle and leads_on(floor.fits, floor.wide, e, piece.rr[own], piece.cc[own], stretch.width_m / res,
                                      MOUTH_LEADS_ON_M / res))
               for sign, e, last in zip((-1.0, 1.0), ends_g, lasts, strict=True))


def _short_way(floor: _Floor, piece: _Piece, stretch: _Stretch, doors: Sequence[Door]
               ) -> tuple[bool, int | None] | None:
    """A way less elongated than a corridor: a gap in a wall line (a door's business), between two
    objects or beside one (walked round), or a squeeze past things. When it is a passage: whether
    it is a squeeze past deep things, and the side of the thing beside a wall (None when it is
    between two things or no wall runs on past it). None (the reason logged) when it is not."""
    params, res, d2 = floor.params, floor.grid.resolution_m, floor.d2
    width_m, length_m, mid = stretch.width_m, stretch.length_m, stretch.mid
    sides, bounded, axis = stretch.sides, stretch.bounded, piece.axis
    # Short (less than PASSAGE_MIN_ELONGATION times longer than wide), it is a gap: in a
    # wall line (a door's business), between two objects or beside one (walked round).
    # Except a squeeze past things deeper than any wall or door leaf (a sofa, a cart, a
    # wardrobe: not a jamb with its door open along the way), beside a wall that runs on
    # past both mouths or between two of them, that is the only way from one side to the
    # other: a person points at that, up to the widest passage (a corridor narrowed to
    # 0.9 m by a parked bed is a squeeze, however wide a door may be).
    # Between a wall and a thing one can walk round (a pallet, a cabinet), a strip is a
    # way of its own only when it is as elongated as a corridor (an aisle along a shelf).
    elongated = length_m >= PASSAGE_MIN_ELONGATION * width_m
    squeeze = False
    # (A short one needs the wall on past both of its mouths: it is a squeeze along a
    # wall, not round the end of one.)
    half_len = stretch.half_len
    past = past_mouths(floor.open_, mid, axis, half_len, width_m / res, WALL_RUN_M / res)
    thing = beside_a_wall(past, both_mouths=not elongated)
    if not elongated:
        depth = params.door_max_depth_m / res
        sides_deep = [deep(floor.open_, piece.pts[bounded], piece.normal * (2 * j - 1), sides[bounded, j], depth, res)
                      for j in (0, 1)]
        # A gap in a line of free-standing things (_in_a_line): both are deep along the line,
        # however thin (the probe above misses a thin line drawn askew in steps).
        if length_m < floor.min_len_m:
            sides_deep = [True, True]
        # A squeeze past a thing deeper than a wall beside a wall that runs on, or
        # between two such things (a parked bed and a trolley in a corridor, a
        # wardrobe and a desk across a room): longer than a wall is thick
        # (passage_min_length_m) with both sides solid, it is no doorway.
        # (Between two things, neither side runs on past a mouth in line, as a wall
        # does, along WALL_RUNS_ON_SHARE of seg_wall_line_side_m: a wall's corner is
        # no thing.)
        squeeze = (sides_deep[thing] if thing is not None else all(sides_deep) and bool(
            past_mouths(floor.open_, mid, axis, half_len, width_m / res,
                        params.seg_wall_line_side_m / res, SIDE_TOL_M / res).max()
            < WALL_RUNS_ON_SHARE))
        if not squeeze:
            floor.reject('no squeeze past deep things', mid, width_m, length_m)
            return None
    # A gap where a door was found parts two spaces, and is a passage only when it is
    # the only way between them (else it is one of their doorways, however thick the
    # wall looks). Otherwise a squeeze one can go round is still a passage when it is
    # tight for a person (TIGHT_WIDTH_M: a gap between a column and a planter, between
    # a bench row's end and a wall, a bed and a wall), and a roomier one is the way
    # past only when there is no way round: between two things, none near
    # (WAY_ROUND_M: a corridor narrowed by a trolley and a cart, with the ring's far
    # side as a detour); between a wall and a thing, none at all (past a row of shelf
    # ends). A tight strip between a wall and a lone thing that open floor, wider
    # than any passage, leads round nearby is walked round too (a pallet by a wall).
    cw = floor.to_world(mid)
    # (A door found in a squeeze between two things with parallel faces is no door:
    # see _is_a_door.)
    door_at = not (squeeze and thing is None and parallel(sides[bounded], res)) and any(
        math.dist(d.center, cw) <= length_m / 2 + params.door_max_depth_m for d in doors)
    round_reach = WAY_ROUND_M / res if thing is None and not door_at else math.inf
    fits, wide = floor.fits, floor.wide
    if (thing is not None or squeeze) and (door_at or width_m > TIGHT_WIDTH_M) and way_round(
            fits, fits, mid, axis, half_len, width_m / res, round_reach):
        floor.reject('a way round it', mid, width_m, length_m)
        return None
    if thing is not None and not door_at and way_round(wide, fits, mid, axis, half_len,
                                                       width_m / res, WAY_ROUND_M / res):
        floor.reject('open floor round the thing', mid, width_m, length_m)
        return None
    # A short gap among equal ones (a grid of bikes, a block of desks, seats) is no
    # narrow passage: a way round near it is as tight (as wide, a cell of slack), and
    # none clearly roomier (EQUAL_GAP_ROOMIER_M) leads round it. A person points at the
    # squeeze that is tighter than the floor around it, not at one of a grid's lanes.
    if not elongated and (thing is not None or squeeze) and not door_at:
        as_wide = d2 >= max(width_m / res / 2.0 - 1.0, 0.0) ** 2
        roomier = wide | (d2 >= ((width_m + EQUAL_GAP_ROOMIER_M) / res / 2.0) ** 2)
        if (way_round(as_wide, fits, mid, axis, half_len, width_m / res, WAY_ROUND_M / res)
                and not way_round(roomier, fits, mid, axis, half_len, width_m / res,
                                  WAY_ROUND_M / res)):
            floor.reject('one of equal gaps', mid, width_m, length_m)
            return None
    return squeeze, thing


def _is_a_door(floor: _Floor, piece: _Piece, stretch: _Stretch, doors: Sequence[Door], squeeze: bool,
               thing: int | None) -> bool:
    """Is the stretch a door's own gap: a door across its middle, or, for a short gap, one at it?
    (A door at one of a passage's mouths is how it is entered.) Not where the door was read in a
    squeeze between things with parallel faces (``squeeze``, ``thing``: :func:`_short_way`)."""
    params, res = floor.params, floor.grid.resolution_m
    width_m, length_m = stretch.width_m, stretch.length_m
    sides, bounded = stretch.sides, stretch.bounded
    centre = floor.to_world(stretch.mid)
    ax_w = np.subtract(floor.grid.grid_to_world(floor.r0 + stretch.mid[1] + piece.axis[1],
                                                floor.c0 + stretch.mid[0] + piece.axis[0]), centre)
    axis_w = (float(ax_w[0]), float(ax_w[1]))
    # A door found across or at a squeeze between two things with parallel faces is no door:
    # its sides are deeper than a wall is thick along and across the way (a gap in a row
    # of furniture, between a bed and a trolley: not an opening in a wall, and no room
    # ends there). Otherwise a door across the way is the passage's own gap, and a short
    # gap with a door at it is that door's opening (a door leaf, open along the way,
    # lengthens its jamb; a room narrowing to its door is the door's approach).
    # So is one found along a squeeze past a thing beside a wall, at least as long as it
    # is wide (a housekeeping cart in a corridor): a doorway is shorter than it is wide
    # (walls are thinner than door_max_depth_m, doors wider than door_min_width_m).
    no_door = squeeze and parallel(sides[bounded], res) and (thing is None or length_m >= width_m)
    # So is one across an aisle as elongated as a corridor between two things deeper than
    # any wall with parallel faces (lockers and a locker island, two shelf rows): no wall
    # stands there for a door to be in (on a turned map the stair-stepped faces read as
    # jambs). A short way through a wall mass between two rooms keeps its door.
    corridor_like = length_m >= params.hallway_min_elongation * width_m
    if not no_door and corridor_like and any(_is_the_door(d, centre, axis_w, length_m, width_m, params)
                                             for d in doors):
        no_door = parallel(sides[bounded], res) and all(
            deep(floor.open_, piece.pts[bounded], piece.normal * (2 * j - 1), sides[bounded, j],
                 params.door_max_depth_m / res, res)
            for j in (0, 1))
    elongated = length_m >= PASSAGE_MIN_ELONGATION * width_m
    return not no_door and (
        any(_is_the_door(d, centre, axis_w, length_m, width_m, params) for d in doors)
        or (not elongated and any(math.dist(d.center, centre) <= length_m / 2 + params.door_max_depth_m
                                  for d in doors)))


def _passage(floor: _Floor, piece: _Piece, stretch: _Stretch, labels: npt.NDArray[np.int32],
             room_ids: Mapping[int, str], passage_id: str) -> NarrowPassage:
    """The passage a judged stretch is: its centre, ends and the spaces its mouths open into."""
    res = floor.grid.resolution_m
    ends_w: list[tuple[float, float]] = []
    spaces: list[str] = []
    for sign, lim in ((-1.0, stretch.lo), (1.0, stretch.hi)):
        e = piece.mean + lim * piece.axis
        ends_w.append(floor.to_world(e))
        sid = space_beyond(labels, e + np.array([floor.c0, floor.r0]), sign * piece.axis, res, room_ids)
        if sid is not None and sid not in spaces:
            spaces.append(sid)
    return NarrowPassage(id=passage_id, center=floor.to_world(stretch.mid), width_m=stretch.width_m,
                         length_m=stretch.length_m, ends=(ends_w[0], ends_w[1]), connects=tuple(spaces))


def _two_sided_pieces(floor: _Floor, retry: list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp]]]
                      ) -> list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp], BoolArray | None]]:
    """A passage along a wall shares its skeleton line with the strip along the rest of that wall
    (the same width from the wall): the two-sided stretches of the ridge cells of the cores
    without sides along most of their length (``retry``), each to be judged alone."""
    if not retry:
        return []
    res = floor.grid.resolution_m
    ar, ac = np.concatenate([r for r, _ in retry]), np.concatenate([c for _, c in retry])
    long_r, long_c = joined(long_pieces(ar, ac, floor.open_.shape, floor.min_cells))
    two_r, two_c = two_sided(floor.open_, long_r, long_c, floor.dist_of[floor.d2[long_r, long_c]] / res,
                             SIDE_TOL_M / res)
    return [(pr, pc, None) for pr, pc in long_pieces(two_r, two_c, floor.open_.shape, floor.min_cells)]


def _is_the_door(door: Door, centre: tuple[float, float], axis: tuple[float, float], length_m: float,
                 width_m: float, params: AnalysisParams) -> bool:
    """Is a passage (``centre``, unit ``axis`` in world metres) the gap of ``door``? When the door
    lies across it (one goes through the door going along the passage) away from its mouths: a
    door at one of its mouths is how one enters a passage (a short corridor between two rooms
    with a door at its end), and a door in one of its side walls leads off it; neither is the
    passage itself."""
    n = math.hypot(*axis) or 1.0
    ux, uy = axis[0] / n, axis[1] / n
    dn = math.hypot(*door.normal)
    if dn > 0 and abs(door.normal[0] * ux + door.normal[1] * uy) / dn < DOOR_ACROSS_COS:
        return False
    dx, dy = door.center[0] - centre[0], door.center[1] - centre[1]
    along, across = dx * ux + dy * uy, abs(-dx * uy + dy * ux)
    if across > width_m / 2 + params.door_max_depth_m:
        return False
    return abs(along) < length_m / 2 - params.door_max_depth_m or length_m <= 2 * params.door_max_depth_m


