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
an aisle, into another narrow way that reaches such space within ``MOUTH_LEADS_ON_M``: a dead-end
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

A passage along a wall (between the wall and a long shelf) shares its skeleton line with the
one-sided strip along the rest of the room's walls: a core without sides along most of its length
is split into its two-sided stretches, and each is judged on its own.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Final

import numpy as np
import numpy.typing as npt
from scipy import ndimage as ndi
from skimage.morphology import skeletonize

from langnav.analysis.elements import Door, NarrowPassage
from langnav.analysis.params import AnalysisParams
from langnav.analysis.precompute import (
    GridLayers,
    component_boxes,
    cov2,
    dilate8,
    label8_cells,
    median,
    truncated_sq_edt,
)
from langnav.maps.grid import OccupancyGrid

#: A passage is at least this many times longer than wide: a corridor, not a gap beside an
#: object (a 0.9 m gap along a 0.7 m table is where you walk round it, not a passage).
PASSAGE_MIN_ELONGATION: Final = 2.0
#: The core of a chain: cells no wider than its typical width (this quantile of its widths along
#: it) plus CORE_WIDTH_TOL_M, i.e. the stretch with near-parallel sides. Typical, not the
#: narrowest: a passage is the stretch over which the way stays tight, and one pinch point
#: (a door leaf, a bump of clutter) does not shorten it to the pinch.
CORE_REF_QUANTILE: Final = 0.5
CORE_WIDTH_TOL_M: Final = 0.15
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
#: A passage has sides: at this share of its core, blocking cells lie close on both sides (a
#: strip along a wall whose other side is a row of separate objects is not a passage).
MIN_BOUNDED_FRACTION: Final = 0.7
#: ... or, walled on one side along this share, with one doorway in the other side.
DOORWAY_WALL_FRACTION: Final = 0.9
#: Open stretches of a side up to this long (cells) are scan noise, not a doorway.
DOORWAY_MIN_GAP_CELLS: Final = 3
#: "Close" for a side: within the half-width plus this.
SIDE_TOL_M: Final = 0.15
#: The middle line of a strip: the distance to its sides falls by at least this (cells) two
#: steps away on both sides (about two across it; half a cell along a stair-stepped wall).
CREST_DROP_CELLS: Final = 1.0
#: A passage axis within this (degrees) of a grid axis is taken as that axis: pixel noise tilts
#: the fitted axis of a straight passage by a degree or two.
AXIS_SNAP_DEG: Final = 3.0
#: A core that is not bounded along most of its length is split into its two-sided stretches,
#: each cell tried across this many directions over 180 degrees (22.5 degrees apart: the side
#: of a passage at any angle is within 11.25 degrees, 2 % farther, of one of them).
TWO_SIDED_DIRECTIONS: Final = 8
#: A short squeeze beside a wall: the wall runs on past both mouths, blocked (within the
#: squeeze's width) along this share of the samples there, and the thing beside it ends (open
#: along as much).
WALL_RUNS_ON_SHARE: Final = 0.7
#: A squeeze between two things runs between their faces: parallel, its width varying along it by
#: no more than this (m; scan noise on the two faces), not a pinch between a corner and a slanted
#: wall, as where a room narrows to its door.
PARALLEL_SPREAD_M: Final = 0.15
#: ... sampled this far past each mouth (m): a wall, not the corner of a jamb.
WALL_RUN_M: Final = 0.6
#: A free crack along a thing's depth up to this wide (m; two cells of a common 0.05 m map) is
#: scan noise: the sliver between the two copies of its outline a pose error drew twice.
OUTLINE_CRACK_M: Final = 0.1
#: ... and the thing is deeper than a wall is thick (door_max_depth_m): blocked along this share
#: of that depth past its face (its outline may have a scan dropout).
DEEP_SHARE: Final = 0.8
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
#: The thickest wall: occupied runs thicker than this, scanned from both sides, are furniture or
#: solid things, not walls (as ``door_max_depth_m`` is the deepest doorway).
WALL_MAX_THICKNESS_M: Final = 0.45
#: Look this far beyond a mouth for the space the passage opens into.
MOUTH_SEARCH_M: Final = 1.0
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
#: A mouth opens into a free area when one is found within this distance beyond it (the core
#: stops where the sides start to flare, up to about a width before the space itself).
MOUTH_OPEN_SEARCH_M: Final = 1.5
#: A mouth that opens into another narrow way (the next aisle round a shelving island) leads
#: somewhere when that way reaches open floor within this distance of the mouth (m): about a
#: shelf's length; a dead-end slot's far end leads nowhere however far one looks.
MOUTH_LEADS_ON_M: Final = 3.0
#: Side distances of many pieces are sampled together, about this many samples at a time
#: (bounded memory on a large map; fewer numpy calls on a small one).
SIDE_BATCH_SAMPLES: Final = 400_000

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
    line where it is narrow (:func:`_core_pieces`); each piece's axis and sides
    (:func:`_measured`); then each is judged (:func:`_judged`). Cores without sides along most of
    their length are split into their two-sided stretches (:func:`_two_sided_pieces`), which are
    judged in a second round.
    """
    floor = _open_floor(grid, params, blocking, dist_m, layers or GridLayers(grid), unexplored)
    if floor is None:
        return ()
    passages: list[NarrowPassage] = []
    pieces = _core_pieces(floor)
    while pieces:
        retry: list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp]]] = []
        for piece, sides in _measured(floor, pieces):
            found = _judged(floor, piece, sides, doors, labels, room_ids, f"passage_{len(passages) + 1}", retry)
            if found is not None:
                passages.append(found)
        pieces = _two_sided_pieces(floor, retry)
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


def _core_pieces(floor: _Floor) -> list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp], BoolArray | None]]:
    """The cores of the narrow middle line long enough to be passages: per core its cells (window
    rows, cols) and which of them are a ridge across (:func:`_across_ridge`)."""
    params, res, d2, width_of = floor.params, floor.grid.resolution_m, floor.d2, floor.width_of
    band_of = (width_of > 2.0 * params.robot_radius_m) & (width_of <= params.passage_max_width_m)
    band = floor.open_ & band_of[d2]
    # The medial axis within the band: crest cells of the distance map (clearly higher than the
    # cells two steps away on both sides, across some direction), a cell thicker (to bridge the
    # sideways step of the crest where a side has a bump), thinned to one cell. Cheaper than
    # skeletonising all free space.
    skel = skeletonize(band & dilate8(_crest(d2)))
    # Chains of the skeleton (8-connected), labelled from its few cells, not the whole window.
    idx = np.flatnonzero(skel)
    cid, n = label8_cells(idx, skel.shape)
    if n == 0:
        return []
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
        in_core |= _jogs(idx, in_core, w <= ref[cid - 1] + CORE_WIDTH_TOL_M + JOG_WIDTH_CELLS * res,
                         ref[cid - 1] / res, skel.shape)
    core_idx = idx[in_core]
    core_id, m = label8_cells(core_idx, skel.shape)
    # Necessary conditions, vectorised, before the per-core work: a chain of n cells spans at
    # most n * sqrt(2) cells and at most its bounding box's diagonal.
    n_cells = np.bincount(core_id, minlength=m + 1)
    long_enough = np.flatnonzero(n_cells * math.sqrt(2) >= floor.min_cells)
    long_enough = long_enough[long_enough > 0]
    core_r, core_c = np.divmod(core_idx, floor.open_.shape[1])
    boxes = component_boxes(core_id, core_r, core_c, long_enough)
    # Each core's cells, in raster order.
    by_core = np.argsort(core_id, kind="stable")
    core_start = np.searchsorted(core_id[by_core], np.arange(m + 2))
    # Which cells are a ridge across: a per-cell test, made for all the core cells at once.
    across_core = _across_ridge(d2, core_r, core_c)
    pieces: list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp], BoolArray | None]] = []
    for k in long_enough.tolist():
        sl = boxes[k]
        if math.hypot(sl[0].stop - sl[0].start, sl[1].stop - sl[1].start) < floor.min_cells:
            continue
        cells = by_core[core_start[k]:core_start[k + 1]]
        pieces.append((core_r[cells], core_c[cells], across_core[cells]))
    return pieces


def _measured(floor: _Floor, pieces: list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp], BoolArray | None]]
              ) -> list[tuple[_Piece, npt.NDArray[np.float64]]]:
    """Each piece's axis and length, and the cheap test first (with the skeleton's width, at most
    a cell narrower than the true one); then the distances to the sides of all that pass, at
    once: the pieces at least ``passage_min_length_m`` long, with their sides."""
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
        # Snap a nearly axis-aligned passage onto the grid axis (cleaner width sampling).
        if abs(axis[0]) >= math.cos(math.radians(AXIS_SNAP_DEG)):
            axis = np.array([math.copysign(1.0, axis[0]), 0.0])
        elif abs(axis[1]) >= math.cos(math.radians(AXIS_SNAP_DEG)):
            axis = np.array([0.0, math.copysign(1.0, axis[1])])
        proj = (pts - mean) @ axis
        # Short ones too (a squeeze past furniture beside a wall is as deep as the furniture,
        # its mouths flaring on either side).
        if (float(proj.max() - proj.min()) + 1.0) * res < floor.params.passage_min_length_m:
            continue
        measured.append(_Piece(rr=rr, cc=cc, across=across, pts=pts, mean=mean, axis=axis, proj=proj))
    side_sets = _side_distances_each(floor.open_, [p.pts for p in measured],
                                     [floor.dist_of[floor.d2[p.rr, p.cc]] / res for p in measured],
                                     [p.normal for p in measured], SIDE_TOL_M / res)
    return list(zip(measured, side_sets, strict=True))


def _judged(floor: _Floor, piece: _Piece, sides: npt.NDArray[np.float64], doors: Sequence[Door],
            labels: npt.NDArray[np.int32], room_ids: Mapping[int, str], passage_id: str,
            retry: list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp]]]) -> NarrowPassage | None:
    """The narrow passage a piece is, or None (the reason logged). A whole core without sides
    along most of its length adds its ridge cells to ``retry``, to be split into its two-sided
    stretches."""
    if not _sides_hold(sides, piece.proj, floor.params.door_max_width_m / floor.grid.resolution_m):
        if piece.across is not None and len(piece.rr) * math.sqrt(2) >= floor.min_cells:
            retry.append((piece.rr[piece.across], piece.cc[piece.across]))
        floor.reject('no two sides along it', piece.pts.mean(axis=0))
        return None
    stretch = _two_sided_stretch(floor, piece, sides)
    if stretch is None:
        return None
    if not _leads_somewhere(floor, piece, stretch):
        floor.reject('a mouth leads nowhere', stretch.mid, stretch.width_m, stretch.length_m)
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
    # It runs where it has two sides: not on into its flaring mouths.
    lo, hi = float(piece.proj[bounded].min()), float(piece.proj[bounded].max())
    length_m = (hi - lo + 1.0) * res
    mid = piece.mean + 0.5 * (lo + hi) * piece.axis
    if length_m < floor.min_len_m:
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
    solid = _solid_sides(floor.open_, floor.occupied, floor.outside, piece.pts, piece.normal, sides,
                         SOLID_UNKNOWN_DEPTH_M / res)
    if np.count_nonzero(solid) < MIN_BOUNDED_FRACTION * np.count_nonzero(bounded):
        floor.reject('sides not solid', mid, width_m, length_m)
        return None
    return _Stretch(sides=sides, bounded=bounded, width_m=width_m, lo=lo, hi=hi, length_m=length_m, mid=mid)


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
    return all(_opens_into_space(floor.open_, e, sign * axis, res, params, last)
               or (aisle and _leads_on(floor.fits, floor.wide, e, piece.rr[own], piece.cc[own], stretch.width_m / res,
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
    past = _past_mouths(floor.open_, mid, axis, half_len, width_m / res, WALL_RUN_M / res)
    thing = _beside_a_wall(past, both_mouths=not elongated)
    if not elongated:
        depth = params.door_max_depth_m / res
        sides_deep = [_deep(floor.open_, piece.pts[bounded], piece.normal * (2 * j - 1), sides[bounded, j], depth, res)
                      for j in (0, 1)]
        # A squeeze past a thing deeper than a wall beside a wall that runs on, or
        # between two such things (a parked bed and a trolley in a corridor, a
        # wardrobe and a desk across a room): longer than a wall is thick
        # (passage_min_length_m) with both sides solid, it is no doorway.
        # (Between two things, neither side runs on past a mouth in line, as a wall
        # does, along WALL_RUNS_ON_SHARE of seg_wall_line_side_m: a wall's corner is
        # no thing.)
        squeeze = (sides_deep[thing] if thing is not None else all(sides_deep) and bool(
            _past_mouths(floor.open_, mid, axis, half_len, width_m / res,
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
    door_at = not (squeeze and thing is None and _parallel(sides[bounded], res)) and any(
        math.dist(d.center, cw) <= length_m / 2 + params.door_max_depth_m for d in doors)
    round_reach = WAY_ROUND_M / res if thing is None and not door_at else math.inf
    fits, wide = floor.fits, floor.wide
    if (thing is not None or squeeze) and (door_at or width_m > TIGHT_WIDTH_M) and _way_round(
            fits, fits, mid, axis, half_len, width_m / res, round_reach):
        floor.reject('a way round it', mid, width_m, length_m)
        return None
    if thing is not None and not door_at and _way_round(wide, fits, mid, axis, half_len,
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
        if (_way_round(as_wide, fits, mid, axis, half_len, width_m / res, WAY_ROUND_M / res)
                and not _way_round(roomier, fits, mid, axis, half_len, width_m / res,
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
    no_door = squeeze and _parallel(sides[bounded], res) and (thing is None or length_m >= width_m)
    # So is one across an aisle as elongated as a corridor between two things deeper than
    # any wall with parallel faces (lockers and a locker island, two shelf rows): no wall
    # stands there for a door to be in (on a turned map the stair-stepped faces read as
    # jambs). A short way through a wall mass between two rooms keeps its door.
    corridor_like = length_m >= params.hallway_min_elongation * width_m
    if not no_door and corridor_like and any(_is_the_door(d, centre, axis_w, length_m, width_m, params)
                                             for d in doors):
        no_door = _parallel(sides[bounded], res) and all(
            _deep(floor.open_, piece.pts[bounded], piece.normal * (2 * j - 1), sides[bounded, j],
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
        sid = _space_beyond(labels, e + np.array([floor.c0, floor.r0]), sign * piece.axis, res, room_ids)
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
    long_r, long_c = _join(_pieces(ar, ac, floor.open_.shape, floor.min_cells))
    two_r, two_c = _two_sided(floor.open_, long_r, long_c, floor.dist_of[floor.d2[long_r, long_c]] / res,
                              SIDE_TOL_M / res)
    return [(pr, pc, None) for pr, pc in _pieces(two_r, two_c, floor.open_.shape, floor.min_cells)]


def _jogs(idx: npt.NDArray[np.intp], core: BoolArray, near: BoolArray,
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
    r, c = np.divmod(run_flat, w)
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
    sr, sc = np.divmod(core_flat, w)
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
    return float(np.median(walls)) if len(walls) else res


def _parallel(sides: npt.NDArray[np.float64], res: float) -> bool:
    """Do the two sides of a stretch (per point, the distances in cells to either side, both
    finite) run parallel: its width varies along it by no more than ``PARALLEL_SPREAD_M`` (or two
    cells: a cell of scan noise on each face) between the 10th and 90th percentiles?"""
    w = sides.sum(axis=1) * res
    lo, hi = np.quantile(w, [0.1, 0.9])
    return bool(hi - lo <= max(PARALLEL_SPREAD_M, 2.0 * res))


def _past_mouths(open_: BoolArray, centre_g: npt.NDArray[np.float64], axis: npt.NDArray[np.float64],
                 half_len: float, width: float, run: float, tol: float | None = None) -> npt.NDArray[np.float64]:
    """Past each mouth of the stretch (``centre_g``, unit ``axis``, ``half_len`` cells either way,
    ``width`` cells wide), from a quarter of its width to ``run`` cells on: per side (0: along
    -normal, 1: along +normal, the normal being the axis turned a quarter anticlockwise) and per
    mouth (0: ahead along +axis, 1: behind), the share of samples blocked within its half width
    plus ``tol`` cells (default: its whole width)."""
    normal = np.array([-axis[1], axis[0]])
    t = np.arange(width / 4.0, run + 0.5, 0.5)
    starts = np.concatenate([centre_g + (half_len + t)[:, None] * axis, centre_g - (half_len + t)[:, None] * axis])
    sides = _side_distances(open_, starts, np.full(len(starts), width / 2.0), normal,
                            width / 2.0 if tol is None else tol)
    blocked = np.isfinite(sides)
    n = len(t)
    return np.array([[blocked[:n, j].mean(), blocked[n:, j].mean()] for j in (0, 1)])


def _beside_a_wall(past: npt.NDArray[np.float64], both_mouths: bool = True) -> int | None:
    """Is a stretch (``past``: :func:`_past_mouths`) a squeeze between a wall and a thing beside
    it: one side stays blocked (the wall runs on) along ``WALL_RUNS_ON_SHARE`` of the samples
    past both mouths (or one, ``both_mouths=False``: a wall that ends at a doorway), and the other
    is open along as much past both (the thing ends)? The thing's side, or None."""
    on = past.min(axis=1) if both_mouths else past.max(axis=1)
    off = past.max(axis=1)
    for j in (0, 1):
        if on[j] >= WALL_RUNS_ON_SHARE and off[1 - j] <= 1.0 - WALL_RUNS_ON_SHARE:
            return 1 - j
    return None


def _deep(open_: BoolArray, pts: npt.NDArray[np.float64], outward: npt.NDArray[np.float64],
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


def _way_round(floor: BoolArray, fits: BoolArray, centre_g: npt.NDArray[np.float64], axis: npt.NDArray[np.float64],
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


def _crest(d2: npt.NDArray[np.integer]) -> BoolArray:
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


def _ridge(d: npt.NDArray[np.integer] | npt.NDArray[np.floating]) -> BoolArray:
    """Cells whose value is >= both neighbours along at least one of the four directions (the
    same cells for a distance map and for its square)."""
    p = np.pad(d, 1, mode="constant", constant_values=0)
    # c >= both of a pair <=> c >= the larger; for some pair <=> c >= the smallest of those.
    h, w = d.shape
    lowest = np.maximum(p[0:h, 1:w + 1], p[2:h + 2, 1:w + 1])  # up / down
    for (r_a, c_a), (r_b, c_b) in (((1, 0), (1, 2)), ((0, 0), (2, 2)), ((0, 2), (2, 0))):
        np.minimum(lowest, np.maximum(p[r_a:r_a + h, c_a:c_a + w], p[r_b:r_b + h, c_b:c_b + w]), out=lowest)
    return (d >= lowest) & (d > 0)


def _across_ridge(d: npt.NDArray[np.integer], rr: npt.NDArray[np.intp], cc: npt.NDArray[np.intp]) -> BoolArray:
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


def _pieces(rr: npt.NDArray[np.intp], cc: npt.NDArray[np.intp], shape: tuple[int, int], min_cells: float
            ) -> list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp]]]:
    """The 8-connected pieces of a set of cells that may span ``min_cells`` (n cells span at most
    n * sqrt(2), and at most their bounding box's diagonal)."""
    if len(rr) == 0:
        return []
    flat = np.sort(rr * shape[1] + cc)
    ids, n = label8_cells(flat, shape)
    rows, cols = np.divmod(flat, shape[1])
    out = []
    for i in np.flatnonzero(np.bincount(ids, minlength=n + 1) * math.sqrt(2) >= min_cells).tolist():
        if i == 0:
            continue
        sel = ids == i
        pr, pc = rows[sel], cols[sel]
        if math.hypot(int(pr.max()) - int(pr.min()) + 1, int(pc.max()) - int(pc.min()) + 1) >= min_cells:
            out.append((pr, pc))
    return out


def _join(pieces: list[tuple[npt.NDArray[np.intp], npt.NDArray[np.intp]]]
          ) -> tuple[npt.NDArray[np.intp], npt.NDArray[np.intp]]:
    """All the cells of some pieces, as one (rows, cols) pair."""
    if not pieces:
        empty = np.zeros(0, dtype=np.intp)
        return empty, empty
    return np.concatenate([p[0] for p in pieces]), np.concatenate([p[1] for p in pieces])


def _two_sided(open_: BoolArray, rr: npt.NDArray[np.intp], cc: npt.NDArray[np.intp],
               reach: npt.NDArray[np.float64], tol_cells: float) -> tuple[npt.NDArray[np.intp], npt.NDArray[np.intp]]:
    """The skeleton cells (rows ``rr``, cols ``cc``) with blocking cells within their half-width
    ``reach`` + ``tol_cells`` on two opposite sides, along one of ``TWO_SIDED_DIRECTIONS``
    directions (a cell beside one wall has a single side)."""
    if len(rr) == 0:
        return rr, cc
    pts = np.stack([cc + 0.5, rr + 0.5], axis=1).astype(float)
    two_sided = np.zeros(len(pts), dtype=bool)
    for k in range(TWO_SIDED_DIRECTIONS):
        a = math.pi * k / TWO_SIDED_DIRECTIONS
        sides = _side_distances(open_, pts, reach, np.array([math.cos(a), math.sin(a)]), tol_cells)
        two_sided |= np.isfinite(sides).all(axis=1)
    return rr[two_sided], cc[two_sided]


def _side_distances(open_: BoolArray, pts: npt.NDArray[np.float64], reach: npt.NDArray[np.float64],
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


def _side_distances_each(open_: BoolArray, pts: Sequence[npt.NDArray[np.float64]],
                         reach: Sequence[npt.NDArray[np.float64]], normal: Sequence[npt.NDArray[np.float64]],
                         tol_cells: float) -> list[npt.NDArray[np.float64]]:
    """:func:`_side_distances` of several point sets (each with its own normal), the same values,
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
        sides = _side_distances(open_, np.concatenate(pts[i:j]), np.concatenate(reach[i:j]),
                                normals, tol_cells, stop=stop)
        out.extend(np.split(sides, np.cumsum(sizes)[:-1]))
        i = j
    return out


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


def _sides_hold(sides: npt.NDArray[np.float64], proj: npt.NDArray[np.float64], door_cells: float) -> bool:
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


def _solid_sides(open_: BoolArray, occupied: BoolArray, outside: BoolArray, pts: npt.NDArray[np.float64],
                 normal: npt.NDArray[np.float64], sides: npt.NDArray[np.float64], depth_cells: float) -> BoolArray:
    """Per point: are both its sides (distances ``sides`` from :func:`_side_distances` along
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


def _opens_into_space(open_: BoolArray, end_g: npt.NDArray[np.float64], direction: npt.NDArray[np.float64],
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


def _leads_on(fits: BoolArray, wide: BoolArray, end_g: npt.NDArray[np.float64], rr: npt.NDArray[np.intp],
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


def _space_beyond(labels: npt.NDArray[np.int32], end_g: npt.NDArray[np.float64],
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
