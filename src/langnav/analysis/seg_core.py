"""The numeric core of room segmentation: clean the grid, flood the clearance map, merge basins.

Pure array functions; :mod:`langnav.analysis.segmentation` turns their output into elements.

Method (after Bormann et al., ICRA 2016, "distance" and "Voronoi" methods, and the decluttering
and merging steps of ROSE², RA-L 2022):

1. *Floor*: free cells, plus occupied specks (scan noise), small unknown holes enclosed by free
   space, and free-standing clutter (furniture islands up to ``seg_island_max_area_m2`` that
   are not thin wall stubs): furniture must not split a room.
2. *Clearance*: the Euclidean distance of every floor cell to the nearest non-floor cell, in
   metres. Its ridges are the Voronoi skeleton of the free space; a doorway is a *saddle* of it
   (a local minimum of clearance along the skeleton), a room is a hill.
3. *Basins*: a watershed of -clearance from its local maxima gives one basin per hill.
4. *Merge tree*: basins are merged across their saddles from the widest saddle down (a
   persistence simplification). Two basins stay apart only where the saddle is as narrow as a
   door and both hills rise clearly above it; otherwise the "saddle" is just a bulge of one space.
   Two narrow spaces meeting through an opening nearly as wide as they are stay one corridor;
   so do two pieces of a corridor, judged on their typical width (twice the mean clearance)
   rather than their peak, which junctions and door recesses raise.
   An opening wider than a door (up to ``seg_wall_gap_max_width_m``) still separates two
   spaces that rise above it when it is a gap in a wall line: the wall runs on straight past
   both of its jambs (ROSE²'s rooms bounded by the building's wall lines, in local form).
5. *Jambs*: the widest opening left between two spaces must be cut in a wall: both of its jambs
   belong to the wall network or to a wall stub running along the gap (:class:`JambJudge`), or
   one of them is the door itself standing open (a thin leaf hinged there): an open door
   marks its doorway, which then parts a small room behind it (an en-suite) from its room.
   A large piece standing free in a room that spreads both ways at the depth of furniture
   (desks pushed together with their chairs), with no wall running on in line with it, is no
   wall: the gaps between it and the walls are ways round the furniture, not doorways.
   A crack narrower than a door (a slit beside a cabinet, a pane of a glass front) is no way
   through: failing the test, it does not join the spaces; their wider openings decide.
6. A space whose opening is wide for its size (``seg_merge_gap_ratio``: a bay) and pieces
   smaller than ``room_min_area_m2`` join their neighbour; isolated fragments below that size
   are dropped. A single door's width cut in a wall across a part of a small room's side (a
   bathroom, a store behind its door) is no bay's mouth: that room stays apart.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Final

import numpy as np
import numpy.typing as npt
from scipy import ndimage as ndi
from skimage.segmentation import watershed

from langnav.analysis.params import AnalysisParams
from langnav.analysis.precompute import (
    Components,
    GridLayers,
    border_labels,
    count_labels,
    dilate8,
    dilate_box,
    divmod_int,
    edt_scaled,
    extreme_at,
    maximum3,
    nonzero2,
)
from langnav.analysis.wall_lines import WALL_MAX_THICKNESS_M, WallDirections, dominant_directions
from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN

BoolArray = npt.NDArray[np.bool_]
IntArray = npt.NDArray[np.int32]
FloatArray = npt.NDArray[np.float64]

#: A doorway runs along its wall; an elongated piece that meets the gap at more than about 60
#: degrees (a shelf end, a bench standing out into the room) is furniture, not a jamb.
STUB_ACROSS_MAX_COS: Final = 0.5
#: A wall piece this long (m) flanks a doorway whatever its overall direction.
WALL_MIN_LENGTH_ANY_DIRECTION_M: Final = 2.0
#: A wall stub is at least this many times longer than thick (a cabinet or a box is not); it
#: then also has a direction.
STUB_MIN_ELONGATION: Final = 1.8
#: A single door leaf is at most this wide (m; 0.6-0.9 m doors, a 1 m accessible one).
SINGLE_DOOR_MAX_M: Final = 1.0
#: A door leaf is at most this thick as scanned (m; a 40-60 mm leaf, blurred to a few cells);
#: a shelf unit, a bench or a cabinet standing out into a room is deeper.
LEAF_MAX_THICKNESS_M: Final = 0.15
#: A leaf standing open is hinged at the doorway's jamb: the jamb is its end, its far end at
#: least this share of its length away (a point along a piece's side is nearer to all of it).
LEAF_HINGE_END_SHARE: Final = 0.85
#: A bay is open across at least this share of its width along the opening; a doorway into a
#: small room (a bathroom, a store) takes a smaller part of the wall it is cut in.
BAY_MIN_OPEN_SHARE: Final = 0.6
#: A piece of a wall line is no thicker than a wall (m; the thickest interior wall).
WALL_LINE_PIECE_MAX_THICKNESS_M: Final = 0.3
#: Wall cells within this many cells across a piece's own line are in line with it (scanned
#: walls wobble a cell, and a rotated wall's staircase another half).
WALL_LINE_BAND_CELLS: Final = 1.5
#: A group of furniture standing free in a room (desks pushed together with their chairs, a
#: meeting table, a council chamber's horseshoe of desks, a counter with its stools) is at most
#: this long end to end (m): it stands in one room with room to walk round it; a free-standing
#: block longer than that is a wing of walls.
FURNITURE_GROUP_MAX_EXTENT_M: Final = 6.0
#: ... and at most this deep (m, twice its largest inner clearance): desks and cabinets are
#: 0.4-0.8 m deep, and where two meet at a corner the piece is as deep as their diagonal
#: (0.8 m x sqrt 2); a closed room or a core seen from outside (its inside never scanned, at
#: least 1.5 m across) is deeper. It is deeper than a wall is thick (WALL_MAX_THICKNESS_M).
FURNITURE_GROUP_MAX_DEPTH_M: Final = 1.2
#: A piece of wall, even broken off between two doorways and with cabinets standing against it,
#: runs along a line: at least this many times longer than the band it takes across (a 2 m
#: piece of wall with 0.6 m of furniture against it); a group of furniture spreads both ways.
WALL_RUN_MIN_ELONGATION: Final = 3.0
#: A wall running on along a line beyond a piece takes at most this share of the band the
#: piece spans across that line (a wall's thickness); a wall crossing the line fills the band
#: but for the doors in it.
IN_LINE_MAX_BAND_SHARE: Final = 0.5
#: Two wall directions less than this apart (radians, one degree) are one.
SAME_LINE_MAX_RAD: Final = math.radians(1.0)
#: 3x3 neighbourhood: 8-connectivity for components of cells.
EIGHT: Final = np.ones((3, 3), dtype=bool)


@dataclass(frozen=True)
class Floor:
    """The cleaned grid: what counts as floor for segmentation, and the unknown left around it."""

    floor: BoolArray  # free + specks + small enclosed unknown holes
    free: BoolArray  # the free cells of the grid (after speck removal)
    exterior: BoolArray  # unknown cells that are not small holes (unexplored territory)
    clearance_m: FloatArray  # Euclidean distance of floor cells to the nearest non-floor cell
    #: small pieces of non-floor that stand in a wall line (piers between windows, door frames):
    #: walls, however short (see :func:`_on_wall_lines`)
    wall_pieces: BoolArray | None = None
    #: the wall directions found while telling wall pieces from furniture, with the walls they
    #: were found on (the segmentation's own walls, unless some pieces were kept as walls)
    wall_directions: WallDirections | None = None


def _small_components(mask: BoolArray, max_cells: float, *, exclude_border: bool = False,
                      components: Components | None = None) -> BoolArray:
    """Cells of the 8-connected components of ``mask`` with at most ``max_cells`` cells
    (``components``: that labelling of ``mask``, when it is at hand)."""
    if components is None:
        lab, n = ndi.label(mask, structure=EIGHT)
        sizes = count_labels(lab) if n else np.zeros(1, dtype=np.int64)
    else:
        lab, n, sizes = components.labels, components.n, components.sizes
    if n == 0:
        return np.zeros_like(mask)
    keep = sizes <= max_cells
    keep[0] = False
    if exclude_border:
        keep[border_labels(lab)] = False
    return keep[lab]


def clean_floor(cells: npt.NDArray[np.int8], resolution_m: float, params: AnalysisParams,
                layers: GridLayers | None = None) -> Floor:
    """Floor mask and clearance map of a trinary grid (see module doc, step 1-2). ``layers``:
    the masks and components of these very cells, when they are at hand."""
    cell_area = resolution_m * resolution_m
    if layers is None:
        occupied, unknown, free = cells == OCCUPIED, cells == UNKNOWN, cells == FREE
        occ_comp = unk_comp = None
    else:
        occupied, unknown, free = layers.occupied, layers.unknown, layers.free
        occ_comp, unk_comp = layers.occupied_components, layers.unknown_components
    # Occupied specks: isolated noise hits, chair legs. Only those touching free space count.
    specks = _small_components(occupied, params.seg_speck_max_area_m2 / cell_area, components=occ_comp)
    specks &= dilate8(free)
    free = free | specks
    # Unknown holes enclosed by free space (unscanned spots behind furniture, sensor dropouts).
    holes = _small_components(unknown, params.seg_hole_max_area_m2 / cell_area, exclude_border=True,
                              components=unk_comp)
    floor = free | holes
    exterior = unknown & ~holes
    islands, pieces, directions = _furniture(floor, resolution_m, params, occupied)
    floor = floor | islands
    exterior &= ~islands
    clearance = edt_scaled(floor, resolution_m)
    return Floor(floor=floor, free=free, exterior=exterior, clearance_m=clearance, wall_pieces=pieces,
                 wall_directions=directions)


def wall_stub_length(mask: BoolArray, resolution_m: float, params: AnalysisParams) -> float:
    """The length (m) of this piece of non-floor if it is a wall stub (thin, elongated, long
    enough), else 0 (furniture)."""
    thick = 2.0 * float(ndi.distance_transform_edt(np.pad(mask, 1), sampling=resolution_m).max())
    thick = max(thick, resolution_m)
    length = float(mask.sum()) * resolution_m**2 / thick
    stub = (thick <= 2 * params.door_max_depth_m and length >= params.seg_wall_min_length_m
            and length >= STUB_MIN_ELONGATION * thick)
    return length if stub else 0.0


def _furniture(floor: BoolArray, resolution_m: float, params: AnalysisParams,
               occupied: BoolArray | None = None) -> tuple[BoolArray, BoolArray, WallDirections | None]:
    """Free-standing clutter: small pieces of non-floor apart from the walls (tables with their
    chairs, cabinets, columns, unscanned wedges between laser rays), but not thin wall stubs.

    Pieces closer than ``seg_jamb_join_m`` are one piece. Rooms are segmented as if these were
    floor (ROSE² "decluttering"): furniture must not split a room. Returns the furniture and
    the small pieces kept as walls because they stand in a wall line (``occupied`` given), and
    the wall directions found to tell them (None when there were none to tell).
    """
    cell_area = resolution_m * resolution_m
    # Chessboard distance: a square neighbourhood is as good as a disc for grouping, and cheap.
    # Floor cells within half the join distance of two pieces bridge a gap up to the join distance.
    join_cells = int(params.seg_jamb_join_m / 2 / resolution_m + 1e-9)
    solid = ~floor
    none = np.zeros_like(floor)
    if not solid.any():
        return none, none, None
    # The non-floor grown by join_cells (a square): the cells within that chessboard distance.
    grouped = dilate8(solid) if join_cells == 1 else dilate_box(solid, 2 * join_cells + 1)
    comp, n = ndi.label(grouped, structure=EIGHT)
    if n == 0:
        return none, none, None
    area = np.bincount(comp[solid], minlength=n + 1) * cell_area
    small = area <= params.seg_island_max_area_m2
    small[0] = False
    small[border_labels(comp)] = False
    # Thin, long pieces are wall stubs (between two doorways), not furniture.
    objs = ndi.find_objects(comp)
    min_cells = params.seg_wall_min_length_m / resolution_m
    for k in np.flatnonzero(small & (area >= params.seg_wall_min_length_m * resolution_m)):
        sl = objs[k - 1]
        # A stub at least seg_wall_min_length_m long spans that much of its bounding box.
        if sl is None or max(sl[0].stop - sl[0].start, sl[1].stop - sl[1].start) < min_cells:
            continue
        if wall_stub_length((comp[sl] == k) & solid[sl], resolution_m, params) > 0:
            small[k] = False
    pieces = none
    directions = None
    if occupied is not None and small.any():
        in_line, directions = _on_wall_lines(comp, small, objs, occupied & solid, resolution_m, params)
        small &= ~in_line
        pieces = in_line[comp] & solid
    return small[comp] & solid, pieces, directions


def _on_wall_lines(comp: IntArray, small: BoolArray, objs: list[tuple[slice, slice] | None],
                   wall: BoolArray, resolution_m: float, params: AnalysisParams
                   ) -> tuple[BoolArray, WallDirections]:
    """Which small pieces of ``comp`` (``small``) are short pieces of a wall line: as thin as a
    wall, and in line with wall on both sides within a double door's width (the piers between
    windows, a door frame beside a glass panel, a short wall between a door and a window). A
    person sees them as the wall they stand in, not as furniture: the wall line runs on through
    them, whatever the laser saw of the glass beside them. Pieces in line with others of their
    kind count when the row reaches the wall network on one side (a row of piers). Also returns
    the wall directions it used, with the walls they were found on (the wall network)."""
    res = resolution_m
    network = wall & ~small[comp]
    dirs = dominant_directions(network)
    found = np.zeros_like(small)
    if not dirs:
        return found, WallDirections(network, dirs)
    thin = WALL_LINE_PIECE_MAX_THICKNESS_M / res + 1.0
    reach = params.door_wide_max_width_m / res
    pad = math.ceil(reach) + 2
    h, w = wall.shape
    # Per piece: the pieces in line with it on either side ('network' or small ones).
    sides: dict[int, tuple[set[int], set[int]]] = {}
    for k in np.flatnonzero(small).tolist():
        sl = objs[k - 1]
        if sl is None:
            continue
        rr, cc = np.nonzero((comp[sl] == k) & wall[sl])
        if rr.size == 0:
            continue
        rr, cc = rr + (sl[0].start - max(sl[0].start - pad, 0)), cc + (sl[1].start - max(sl[1].start - pad, 0))
        win = (slice(max(sl[0].start - pad, 0), min(sl[0].stop + pad, h)),
               slice(max(sl[1].start - pad, 0), min(sl[1].stop + pad, w)))
        sub: IntArray | None = None
        for theta in dirs:
            ct, st = math.cos(theta), math.sin(theta)
            u, v = cc * ct + rr * st, -cc * st + rr * ct
            thick = float(v.max() - v.min())
            if thick > thin or u.max() - u.min() + 1 < STUB_MIN_ELONGATION * (thick + 1):
                continue  # not a thin piece along this direction (a compact one: a post, a box)
            if sub is None:
                sub = comp[win]
                orr, occ = np.nonzero(wall[win] & (sub != k))
            ou, ov = occ * ct + orr * st, -occ * st + orr * ct
            on = np.abs(ov - (v.max() + v.min()) / 2) <= thick / 2 + WALL_LINE_BAND_CELLS
            left = on & (ou < u.min()) & (ou >= u.min() - reach)
            right = on & (ou > u.max()) & (ou <= u.max() + reach)
            if left.any() and right.any():
                sides[k] = (set(sub[orr[left], occ[left]].tolist()), set(sub[orr[right], occ[right]].tolist()))
                break
    changed = True
    while changed:
        changed = False
        for k, (lk, rk) in sides.items():
            if not found[k] and any(not small[j] or found[j] for j in lk | rk):
                found[k] = True
                changed = True
    return found, WallDirections(network, dirs)


# -- basins and their adjacency ----------------------------------------------------------------

def basins(clearance_m: FloatArray, floor: BoolArray, min_peak_m: float) -> IntArray:
    """Watershed of -clearance from its local maxima (plateaus are one marker each)."""
    peaks = (clearance_m >= maximum3(clearance_m)) & floor & (clearance_m >= min_peak_m)
    markers, _ = ndi.label(peaks, structure=EIGHT)
    out = np.zeros(floor.shape, dtype=np.int32)
    rows, cols = np.flatnonzero(floor.any(axis=1)), np.flatnonzero(floor.any(axis=0))
    if rows.size == 0:
        return out
    # Flooded in the floor's bounding box only: the same flood (nothing outside the mask is
    # flooded; inside, the markers are met in the same raster order and every cell's neighbours
    # in the same order), on fewer cells where a margin of wall and unknown surrounds the floor.
    box = (slice(int(rows[0]), int(rows[-1]) + 1), slice(int(cols[0]), int(cols[-1]) + 1))
    out[box] = watershed(-clearance_m[box], markers[box], mask=floor[box])
    return out


def adjacent_pairs(labels: IntArray, value: FloatArray) -> tuple[
        npt.NDArray[np.int64], npt.NDArray[np.int64], FloatArray, npt.NDArray[np.int64]]:
    """Every pair of different non-zero labels that touch (4-neighbours), with the *saddle*:
    the largest ``min(value[p], value[q])`` over the touching cell pairs (the widest crossing).

    Returns (a, b, saddle, flat index of the saddle cell) with a < b, one row per pair of labels.
    """
    keys_l: list[npt.NDArray[np.int64]] = []
    vals_l: list[FloatArray] = []
    locs_l: list[npt.NDArray[np.int64]] = []
    _h, w = labels.shape
    for sl_p, sl_q in (((slice(None), slice(None, -1)), (slice(None), slice(1, None))),
                       ((slice(None, -1), slice(None)), (slice(1, None), slice(None)))):
        lp, lq = labels[sl_p], labels[sl_q]
        m = (lp != lq) & (lp > 0) & (lq > 0)
        rr, cc = nonzero2(m)
        locs_l.append(rr.astype(np.int64) * w + cc)
        a = np.minimum(lp[m], lq[m]).astype(np.int64)
        b = np.maximum(lp[m], lq[m]).astype(np.int64)
        keys_l.append(a * (int(labels.max()) + 1) + b)
        vals_l.append(np.minimum(value[sl_p][m], value[sl_q][m]))
    keys = np.concatenate(keys_l)
    vals = np.concatenate(vals_l)
    locs = np.concatenate(locs_l)
    if keys.size == 0:
        empty = np.zeros(0, dtype=np.int64)
        return empty, empty, np.zeros(0), empty
    order = np.lexsort((vals, keys))
    keys, vals, locs = keys[order], vals[order], locs[order]
    last = np.r_[keys[1:] != keys[:-1], True]
    k = keys[last]
    n = int(labels.max()) + 1
    return k // n, k % n, vals[last], locs[last]


class JambJudge:
    """Tells a doorway from a gap around furniture: a doorway's two jambs are walls.

    The jambs of a crossing are the nearest non-floor cell and the nearest one on the opposite
    side. Each belongs to a connected piece of non-floor; a piece is *structural* (a wall) when it
    is large (the wall network, the unknown outside) or thin and long (a wall stub); compact
    islands (a column, a cabinet, a table) are furniture.
    """

    def __init__(self, floor: BoolArray, clearance_m: FloatArray, resolution_m: float,
                 params: AnalysisParams, wall_pieces: BoolArray | None = None,
                 directions: Sequence[float] | None = None) -> None:
        self.res = resolution_m
        #: The building's wall directions (radians in the (col, row) plane), when known.
        self.directions = list(directions or ())
        self.params = params
        self.obstacle = ~floor
        # Pieces closer than seg_jamb_join_m are one piece: a door frame scanned as fragments is
        # still part of its wall, a chair's legs one chair.
        self.join_m = params.seg_jamb_join_m
        bridge = clearance_m <= self.join_m / 2 + 1e-9  # bridges gaps up to join_m
        self.comp, _ = ndi.label(self.obstacle | bridge, structure=EIGHT)
        # Sizes count the non-floor cells themselves, not the joining margin.
        self.sizes = np.bincount(self.comp[self.obstacle], minlength=int(self.comp.max()) + 1) * resolution_m**2
        self.objs = ndi.find_objects(self.comp)
        self._cache: dict[int, float] = {}
        self._axes: dict[int, tuple[float, float]] = {}
        self._groups: dict[int, bool] = {}
        # The pieces reaching the grid's edge: the building's walls with the unknown outside.
        self.outer = np.zeros(int(self.comp.max()) + 1, dtype=bool)
        self.outer[border_labels(self.comp)] = True
        self.outer[0] = False
        # Pieces holding a piece of a wall line are walls, however short.
        self.in_wall_line = np.zeros(int(self.comp.max()) + 1, dtype=bool)
        if wall_pieces is not None and wall_pieces.any():
            self.in_wall_line[self.comp[wall_pieces & self.obstacle]] = True
            self.in_wall_line[0] = False

    def _stub(self, k: int) -> float:
        """The length of the small piece ``k`` if it is a wall stub, else 0."""
        if k not in self._cache:
            sl = self.objs[k - 1]
            self._cache[k] = 0.0 if sl is None else wall_stub_length(
                (self.comp[sl] == k) & self.obstacle[sl], self.res, self.params)
        return self._cache[k]

    def _axis(self, k: int) -> tuple[float, float]:
        """Principal direction (drow, dcol) of the small piece ``k``; (0, 0) for a compact one."""
        if k in self._axes:
            return self._axes[k]
        out = (0.0, 0.0)
        sl = self.objs[k - 1]
        if sl is not None:
            rr, cc = np.nonzero(self.comp[sl] == k)
            if rr.size >= 3:
                evals, evecs = np.linalg.eigh(np.cov(np.vstack([rr, cc]).astype(float)))
                if evals[1] > STUB_MIN_ELONGATION**2 * max(evals[0], 1e-9):
                    out = (float(evecs[0, 1]), float(evecs[1, 1]))
        self._axes[k] = out
        return out

    def structural(self, jamb: tuple[int, int], tangent: tuple[float, float]) -> bool:
        """Is the non-floor at ``jamb`` a wall that a doorway along ``tangent`` can be cut in?"""
        k = int(self.comp[jamb])
        if self.in_wall_line[k]:
            return True
        if self.sizes[k] >= self.params.seg_wall_network_min_area_m2:
            return not self._furniture_group(k)
        length = self._stub(k)
        if length <= 0:
            return False
        if length >= WALL_MIN_LENGTH_ANY_DIRECTION_M:
            return True  # a long wall may turn a corner at the jamb
        ar, ac = self._axis(k)
        if ar == 0.0 and ac == 0.0:
            return True  # a compact stub: no direction to contradict the doorway
        return abs(ar * tangent[0] + ac * tangent[1]) >= STUB_ACROSS_MAX_COS or self._leaf_at(k, jamb, length)

    def _furniture_group(self, k: int) -> bool:
        """Is the large piece ``k`` a group of furniture standing free in a room (desks pushed
        together with their chairs, a meeting table, a counter with its stools), not a wall? It
        stands free (off the grid's edge, which the walls and the unknown outside reach), at
        most FURNITURE_GROUP_MAX_EXTENT_M long end to end, deeper than a wall and no deeper than
        furniture (FURNITURE_GROUP_MAX_DEPTH_M), and spread both ways rather than running along
        a line (WALL_RUN_MIN_ELONGATION): a piece of wall broken off between two doorways, with
        cabinets against it, is still a line; a closed room or a core seen from outside is
        deeper."""
        if k in self._groups:
            return self._groups[k]
        out = False
        sl = self.objs[k - 1]
        h, w = self.obstacle.shape
        if sl is not None and sl[0].start > 0 and sl[1].start > 0 and sl[0].stop < h and sl[1].stop < w:
            mine = (self.comp[sl] == k) & self.obstacle[sl]
            rr, cc = np.nonzero(mine)
            if rr.size >= 3:
                spread, axes = np.linalg.eigh(np.cov(np.vstack([rr, cc]).astype(float)))
                # The length of a uniform strip with that spread along each principal axis.
                long_m, short_m = (math.sqrt(12.0 * max(float(v), 0.0)) * self.res for v in spread[::-1])
                # ... and its length end to end along the long one.
                along = rr * float(axes[0, 1]) + cc * float(axes[1, 1])
                length_m = (float(along.max() - along.min()) + 1.0) * self.res
                # Its depth with the specks of scan noise inside it filled (a solid block's laser
                # hits are dotted with free cells; the floor between desks is larger).
                holes = _small_components(~np.pad(mine, 1), self.params.seg_speck_max_area_m2 / self.res**2,
                                          exclude_border=True)
                depth_m = 2.0 * float(ndi.distance_transform_edt(np.pad(mine, 1) | holes, sampling=self.res).max())
                out = (length_m <= FURNITURE_GROUP_MAX_EXTENT_M and long_m < WALL_RUN_MIN_ELONGATION * short_m
                       and WALL_MAX_THICKNESS_M < depth_m <= FURNITURE_GROUP_MAX_DEPTH_M
                       and not self._holds_wall_run(mine)
                       and not any(self._in_line_with_walls(rr + sl[0].start, cc + sl[1].start, axis)
                                   for axis in self._line_axes((float(axes[0, 1]), float(axes[1, 1])))))
        self._groups[k] = out
        return out

    def _holds_wall_run(self, mine: BoolArray) -> bool:
        """Does the piece ``mine`` hold a stretch of wall: a part no thicker than a wall
        (WALL_MAX_THICKNESS_M) running straight for a wall's length (``seg_wall_line_side_m``,
        WALL_RUN_MIN_ELONGATION times longer than wide)? Then it is a wall with furniture
        against it (a partition with a cabinet at its end); desks and cabinets are deeper than
        a wall, and their thin bits (a chair's back, a shelf's edge) are short."""
        r = max(1, round(WALL_MAX_THICKNESS_M / 2 / self.res))
        yy, xx = np.ogrid[-r:r + 1, -r:r + 1]
        body = np.pad(mine, r + 1)
        # The parts a disc as wide as a wall does not fit in (and not the fringe of the others).
        thick = ndi.binary_dilation(ndi.binary_opening(body, structure=xx * xx + yy * yy <= r * r), structure=EIGHT)
        runs, _ = ndi.label(body & ~thick, structure=EIGHT)
        for i, sl in enumerate(ndi.find_objects(runs), start=1):
            if sl is None or max(sl[0].stop - sl[0].start, sl[1].stop - sl[1].start) * self.res \
                    < self.params.seg_wall_line_side_m / math.sqrt(2.0):
                continue  # too short along any direction to be a wall's length
            rr, cc = np.nonzero(runs[sl] == i)
            if rr.size < 3:
                continue
            spread = np.linalg.eigvalsh(np.cov(np.vstack([rr, cc]).astype(float)))
            long_m, short_m = (math.sqrt(12.0 * max(float(v), 0.0)) * self.res for v in spread[::-1])
            if long_m >= self.params.seg_wall_line_side_m and long_m >= WALL_RUN_MIN_ELONGATION * short_m:
                return True
        return False

    def _line_axes(self, own: tuple[float, float]) -> list[tuple[float, float]]:
        """The directions (unit, row/col) a wall may run along: the building's wall directions
        and their right angles, or, when none were found, ``own`` (a piece's long axis) and
        its right angle."""
        if not self.directions:
            return [own, (-own[1], own[0])]
        # A line read one way or the other is the same line (both its ends are looked at).
        angles: list[float] = []
        for a in ((t + q) % math.pi for t in self.directions for q in (0.0, math.pi / 2)):
            if all(abs((a - b + math.pi / 2) % math.pi - math.pi / 2) > SAME_LINE_MAX_RAD for b in angles):
                angles.append(a)
        return [(math.sin(a), math.cos(a)) for a in angles]

    def _in_line_with_walls(self, rows: npt.NDArray[np.intp], cols: npt.NDArray[np.intp],
                            axis: tuple[float, float]) -> bool:
        """Does a wall of the building (the wall network reaching the grid's edge) run on in
        line with the piece at ``rows``, ``cols`` beyond one of its ends along ``axis`` (unit,
        row/col), past a gap up to a double door's width, for a wall's length
        (``seg_wall_line_side_m``)? Then the piece is a stretch of that wall, thickened by what
        stands against it, not a group of furniture. A wall crossing the line (the wall the
        group stands off) fills only its thickness of it."""
        ar, ac = axis
        u = rows * ar + cols * ac
        v = cols * ar - rows * ac
        reach = (self.params.door_wide_max_width_m + self.params.seg_wall_line_side_m) / self.res
        pad = math.ceil(reach) + 1
        h, w = self.obstacle.shape
        r0, r1 = max(int(rows.min()) - pad, 0), min(int(rows.max()) + pad + 1, h)
        c0, c1 = max(int(cols.min()) - pad, 0), min(int(cols.max()) + pad + 1, w)
        wall = self.obstacle[r0:r1, c0:c1] & self.outer[self.comp[r0:r1, c0:c1]]
        gr, gc = np.mgrid[r0:r1, c0:c1]
        gu = gr * ar + gc * ac
        gv = gc * ar - gr * ac
        band = (gv >= v.min()) & (gv <= v.max())
        for near in (band & (gu < u.min()) & (gu >= u.min() - reach), band & (gu > u.max()) & (gu <= u.max() + reach)):
            # Steps along the line where wall takes a thin part of the band across: a wall
            # running along the line (a wall crossing it fills the band but for its doors, and
            # the unknown behind it all of it).
            step = np.floor(gu[near]).astype(np.int64)
            step -= step.min(initial=0)
            on_wall = np.bincount(step, weights=wall[near], minlength=1)
            across = np.bincount(step, minlength=1)
            along = (on_wall > 0) & (on_wall <= IN_LINE_MAX_BAND_SHARE * across)
            if np.count_nonzero(along) * self.res >= self.params.seg_wall_line_side_m:
                return True
        return False

    def _leaf_at(self, k: int, jamb: tuple[int, int], length_m: float) -> bool:
        """Is the stub ``k`` (``length_m`` long) a door leaf standing open, hinged at ``jamb``?
        A leaf is no longer than a single door is wide, as thin as a door, and the doorway's
        jamb is its end (the hinge), not a point along its side (a shelf end or a bench
        standing out into the room meets the gap with its side or its thick end)."""
        if length_m > SINGLE_DOOR_MAX_M + self.res:
            return False
        sl = self.objs[k - 1]
        if sl is None:
            return False
        rr, cc = np.nonzero((self.comp[sl] == k) & self.obstacle[sl])
        if rr.size == 0:
            return False
        thick = float(rr.size) * self.res**2 / max(length_m, self.res)
        if thick > max(LEAF_MAX_THICKNESS_M, 2.0 * self.res):
            return False
        far = float(np.hypot(rr + sl[0].start - jamb[0], cc + sl[1].start - jamb[1]).max()) * self.res
        return far >= LEAF_HINGE_END_SHARE * length_m

    def jambs(self, row: int, col: int, clearance_m: float) -> tuple[tuple[int, int], tuple[int, int]] | None:
        """The two jamb cells of the crossing at (row, col), or None if there is no opposite one."""
        rad = math.ceil(clearance_m / self.res) + 3
        h, w = self.obstacle.shape
        r0, r1 = max(0, row - rad), min(h, row + rad + 1)
        c0, c1 = max(0, col - rad), min(w, col + rad + 1)
        rr, cc = np.nonzero(self.obstacle[r0:r1, c0:c1])
        if rr.size == 0:
            return None
        dr = rr + r0 - row
        dc = cc + c0 - col
        d2 = dr * dr + dc * dc
        i = int(np.argmin(d2))
        opposite = (dr * dr[i] + dc * dc[i]) < 0
        if not opposite.any():
            return None
        j = int(np.flatnonzero(opposite)[np.argmin(d2[opposite])])
        return (int(rr[i] + r0), int(cc[i] + c0)), (int(rr[j] + r0), int(cc[j] + c0))

    def on_wall_line(self, row: int, col: int, clearance_m: float, length_m: float,
                     min_share: float) -> bool:
        """Does the wall run on straight past both jambs of the crossing at (row, col), for
        ``length_m`` with non-floor on at least ``min_share`` of it (a gap in a wall line)?"""
        jj = self.jambs(row, col, clearance_m)
        if jj is None:
            return False
        (r1, c1), (r2, c2) = jj
        n = math.hypot(r2 - r1, c2 - c1) or 1.0
        tr, tc = (r2 - r1) / n, (c2 - c1) / n
        steps = np.arange(1, max(2, round(length_m / self.res)) + 1, dtype=float)
        h, w = self.obstacle.shape
        for (jr, jc), sign in (((r1, c1), -1.0), ((r2, c2), 1.0)):
            hit = np.zeros(steps.size, dtype=bool)
            for off in (-1.0, 0.0, 1.0):  # a cell either side of the line: walls are not ruled
                rr = np.rint(jr + sign * tr * steps - tc * off).astype(np.int64)
                cc = np.rint(jc + sign * tc * steps + tr * off).astype(np.int64)
                inside = (rr >= 0) & (rr < h) & (cc >= 0) & (cc < w)
                hit[inside] |= self.obstacle[rr[inside], cc[inside]]
                hit[~inside] = True
            if hit.mean() < min_share:
                return False
        return True

    def leaf_doorway(self, row: int, col: int, clearance_m: float) -> bool:
        """Is the crossing at (row, col) a doorway with its door standing open at a jamb (a
        leaf hinged there, :meth:`_leaf_at`)? An open leaf is a door's own mark."""
        jj = self.jambs(row, col, clearance_m)
        if jj is None or not self.is_doorway(row, col, clearance_m):
            return False
        for j in jj:
            k = int(self.comp[j])
            if self.sizes[k] >= self.params.seg_wall_network_min_area_m2 or self.in_wall_line[k]:
                continue
            length = self._stub(k)
            if 0 < length < WALL_MIN_LENGTH_ANY_DIRECTION_M and self._leaf_at(k, j, length):
                return True
        return False

    def is_doorway(self, row: int, col: int, clearance_m: float) -> bool:
        jj = self.jambs(row, col, clearance_m)
        if jj is None:
            return False
        (r1, c1), (r2, c2) = jj
        n = math.hypot(r2 - r1, c2 - c1) or 1.0
        tangent = ((r2 - r1) / n, (c2 - c1) / n)
        return all(self.structural(j, tangent) for j in jj)


#: An opening whose jambs lie within 30 degrees of a corridor piece's long axis is in its side
#: wall (a door off the corridor); one across the axis continues the corridor.
_SIDE_OPENING_MIN_COS: Final = math.cos(math.radians(30.0))


class _UnionFind:
    def __init__(self, n: int) -> None:
        self.parent = list(range(n))

    def find(self, i: int) -> int:
        p = self.parent
        while p[i] != i:
            p[i] = p[p[i]]
            i = p[i]
        return i


def merge_basins(labels: IntArray, clearance_m: FloatArray, resolution_m: float,
                 params: AnalysisParams, judge: JambJudge | None = None) -> IntArray:
    """Steps 4-5 of the module doc: merge basins into spaces; returns labels 1..K (0 = none)."""
    n = int(labels.max()) + 1
    if n <= 1:
        return labels
    flat = labels.ravel()
    cells = count_labels(flat, n).astype(float)
    area = cells * resolution_m**2
    # The cells of the pieces (label 0 is never measured below), in raster order.
    on_flat = np.flatnonzero(flat)
    lab_on = flat[on_flat]
    clear_on = clearance_m.ravel()[on_flat]
    peak = np.zeros(n)
    extreme_at(np.maximum, peak, lab_on, clear_on)
    # Summed clearance (m x cells): twice the mean clearance of a space is about its half-width
    # where it is long and narrow, whatever bulges (junctions, door recesses) raise its peak.
    clear_sum = np.bincount(lab_on, weights=clear_on, minlength=n)
    # First and second moments of each piece's cells (row, col): its long axis, to tell an
    # opening across a corridor (it continues) from one in its side wall (a door off it).
    # Rarely needed: worked out on first use, replaying the joins made until then in order.
    mom: list[list[float]] = []
    joins_before_mom: list[tuple[int, int]] = []

    def moments() -> list[list[float]]:
        if not mom:
            rows_i, cols_i = divmod_int(on_flat, labels.shape[1])
            rf, cf = rows_i.astype(float), cols_i.astype(float)
            mom.extend(np.bincount(lab_on, weights=w, minlength=n).tolist()
                       for w in (rf, cf, rf * rf, cf * cf, rf * cf))
            for ra, rb in joins_before_mom:
                for m in mom:
                    m[ra] += m[rb]
        return mom
    a_arr, b_arr, s_arr, loc_arr = adjacent_pairs(labels, clearance_m)
    width = labels.shape[1]
    # A doorway's saddle clearance is about half its width (cell centres: + half a cell).
    door_clear_max = (params.door_max_width_m + resolution_m) / 2
    hallway_peak_max = params.hallway_max_width_m / 2
    wall_gap_clear_max = (params.seg_wall_gap_max_width_m + resolution_m) / 2
    uf = _UnionFind(n)
    peak_l = peak.tolist()
    area_l = area.tolist()
    csum_l = clear_sum.tolist()
    cells_l = cells.tolist()

    def half_width(r: int) -> float:
        return 2.0 * csum_l[r] / max(cells_l[r], 1.0)

    def join(ra: int, rb: int) -> None:
        uf.parent[rb] = ra
        peak_l[ra] = max(peak_l[ra], peak_l[rb])
        area_l[ra] += area_l[rb]
        csum_l[ra] += csum_l[rb]
        cells_l[ra] += cells_l[rb]
        if mom:
            for m in mom:
                m[ra] += m[rb]
        else:
            joins_before_mom.append((ra, rb))

    def axis_cos(r: int, tangent: tuple[float, float]) -> float:
        """|cos| of the angle between ``tangent`` (unit, row/col) and piece ``r``'s long axis:
        near 1 for an opening in its side wall, near 0 for a cut across it."""
        k = max(cells_l[r], 1.0)
        mo = moments()
        mr, mc = mo[0][r] / k, mo[1][r] / k
        vrr, vcc = mo[2][r] / k - mr * mr, mo[3][r] / k - mc * mc
        vrc = mo[4][r] / k - mr * mc
        # Long axis: the covariance's main eigenvector (angle from the row axis).
        theta = 0.5 * math.atan2(2.0 * vrc, vrr - vcc)
        return abs(math.cos(theta) * tangent[0] + math.sin(theta) * tangent[1])

    def extent_along(r: int, tangent: tuple[float, float]) -> float:
        """The extent (cells) of piece ``r`` along ``tangent`` (unit, row/col): sqrt(12 x the
        variance of its cells along it), the length of a uniform strip with that spread."""
        k = max(cells_l[r], 1.0)
        mo = moments()
        mr, mc = mo[0][r] / k, mo[1][r] / k
        vrr, vcc = mo[2][r] / k - mr * mr, mo[3][r] / k - mc * mc
        vrc = mo[4][r] / k - mr * mc
        tr, tc = tangent
        return math.sqrt(12.0 * max(tr * tr * vrr + 2.0 * tr * tc * vrc + tc * tc * vcc, 0.0))

    def side_door(loc: int, s: float, pieces: tuple[int, ...]) -> bool:
        """Is the crossing at ``loc`` a doorway cut in walls along the side of one of the
        corridor ``pieces`` (a room off a hallway: never a corridor narrowing)?"""
        if judge is None or not pieces:
            return False
        row, col = loc // width, loc % width
        jj = judge.jambs(row, col, s)
        if jj is None or not judge.is_doorway(row, col, s):
            return False
        (r1, c1), (r2, c2) = jj
        d = math.hypot(r2 - r1, c2 - c1) or 1.0
        cos = [axis_cos(r, ((r2 - r1) / d, (c2 - c1) / d)) for r in pieces]
        # Across one piece's axis: that piece ends there (a corridor's branch at a junction).
        return max(cos) > _SIDE_OPENING_MIN_COS and min(cos) > _SIDE_OPENING_MIN_COS

    kept: list[tuple[int, int, float, int]] = []
    for i in np.argsort(-s_arr, kind="stable"):
        a, b, s = int(a_arr[i]), int(b_arr[i]), float(s_arr[i])
        ra, rb = uf.find(a), uf.find(b)
        if ra == rb:
            continue
        low = min(peak_l[ra], peak_l[rb])
        # Two narrow spaces meeting through an opening nearly as wide as they are: one corridor
        # narrowed by clutter, not two spaces and a door.
        corridor = max(peak_l[ra], peak_l[rb]) <= hallway_peak_max and \
            low < s * params.seg_hallway_saddle_ratio
        # ... but a door standing open in the opening (its leaf hinged at a jamb) makes it a
        # doorway between two spaces (a room and its en-suite), unless it is a door across a
        # corridor (a piece on either side long for its width: the corridor runs on).
        if corridor and judge is not None and s <= door_clear_max and \
                not any(area_l[r] >= params.hallway_min_elongation * (2.0 * peak_l[r]) ** 2 for r in (ra, rb)) and \
                judge.leaf_doorway(int(loc_arr[i]) // width, int(loc_arr[i]) % width, s):
            corridor = False
        if params.seg_corridor_saddle_ratio > 0 and not corridor:
            wa, wb = half_width(ra), half_width(rb)
            # At least one of them is long for its width (a corridor piece, not a room whose
            # furniture lowers its mean clearance).
            long_pieces = tuple(r for r, w in ((ra, wa), (rb, wb))
                                if area_l[r] >= params.hallway_min_elongation * (2.0 * w) ** 2)
            corridor = bool(long_pieces) and max(wa, wb) <= hallway_peak_max and \
                max(wa, wb) < s * params.seg_corridor_saddle_ratio and \
                not side_door(int(loc_arr[i]), s, long_pieces)
        # An opening wider than a door is still a boundary where it is a gap in a wall line
        # (an open front, a glass wall): the wall runs on straight past both of its ends.
        if judge is not None and not corridor and door_clear_max < s <= wall_gap_clear_max \
                and low - s >= params.seg_persistence_m and \
                judge.on_wall_line(int(loc_arr[i]) // width, int(loc_arr[i]) % width, s,
                                   params.seg_wall_line_min_length_m, params.seg_wall_line_min_share):
            kept.append((a, b, s, int(loc_arr[i])))
            continue
        if s > door_clear_max or low - s < params.seg_persistence_m or \
                low < s * params.seg_peak_saddle_ratio or corridor:
            join(ra, rb)
        else:
            kept.append((a, b, s, int(loc_arr[i])))
    # A crossing whose jambs are not both walls is a gap around furniture: one space.
    # Two spaces are judged on their widest opening: a wall with several gaps (a dashed wall
    # in a drawing, a doorway beside a broken wall) keeps them apart if that one is a doorway.
    # A crack too narrow to walk through (narrower than the narrowest door) is no way between
    # two spaces whatever stands at its sides: beside furniture it is a slit behind a cabinet,
    # in a glass front a pane the laser saw through; it neither joins them nor settles that
    # they are apart (their wider openings are judged on their own).
    crack_clear = (params.door_min_width_m - resolution_m) / 2
    if judge is not None:
        judged: set[tuple[int, int]] = set()
        for a, b, s, loc in sorted(kept, key=lambda e: -e[2]):
            ra, rb = uf.find(a), uf.find(b)
            if ra == rb or (not params.seg_jamb_all_openings and (min(ra, rb), max(ra, rb)) in judged):
                continue
            if judge.is_doorway(loc // width, loc % width, s):
                judged.add((min(ra, rb), max(ra, rb)))
            elif s >= crack_clear:
                join(ra, rb)
    # Spaces joined through many door-wide openings are one space with a row of clutter.
    if params.seg_max_openings_between > 0:
        min_clear = (params.door_min_width_m - resolution_m) / 2
        count: dict[tuple[int, int], int] = {}
        for a, b, s, _ in kept:
            ra, rb = uf.find(a), uf.find(b)
            if ra != rb and s >= min_clear:
                key = (min(ra, rb), max(ra, rb))
                count[key] = count.get(key, 0) + 1
        for (ra, rb), c in count.items():
            ra, rb = uf.find(ra), uf.find(rb)
            if ra != rb and c > params.seg_max_openings_between:
                join(ra, rb)
    # A piece whose opening is wide for its size (a bay of a room behind a desk) is part of
    # the neighbour: a doorway is narrow next to the room it leads into.
    if params.seg_merge_gap_ratio > 0:
        for a, b, s, loc in sorted(kept, key=lambda e: -e[2]):
            ra, rb = uf.find(a), uf.find(b)
            if ra == rb or 2 * s < params.seg_merge_gap_ratio * math.sqrt(min(area_l[ra], area_l[rb])):
                continue
            # A single door's width cut in a wall across a small room (a bathroom, a store
            # behind its door) parts it from its neighbour: a bay is open across about its
            # whole width, a doorway across a part of the wall it is cut in.
            if judge is not None and 2 * s <= SINGLE_DOOR_MAX_M and \
                    judge.leaf_doorway(loc // width, loc % width, s):
                continue  # its door stands open in it: a doorway, however small the room
            if judge is not None and 2 * s <= SINGLE_DOOR_MAX_M and \
                    judge.is_doorway(loc // width, loc % width, s):
                small = ra if area_l[ra] <= area_l[rb] else rb
                jj = judge.jambs(loc // width, loc % width, s)
                if jj is not None:
                    (r1, c1), (r2, c2) = jj
                    dd = math.hypot(r2 - r1, c2 - c1) or 1.0
                    if 2 * s < BAY_MIN_OPEN_SHARE * extent_along(small, ((r2 - r1) / dd, (c2 - c1) / dd)) * resolution_m:
                        continue
            join(ra, rb)
    # Small pieces join the neighbour they share the widest opening with.
    best: dict[int, tuple[float, int]] = {}
    changed = True
    while changed:
        changed = False
        best.clear()
        for a, b, s, _ in kept:
            ra, rb = uf.find(a), uf.find(b)
            if ra == rb:
                continue
            for x, y in ((ra, rb), (rb, ra)):
                if area_l[x] < params.room_min_area_m2 and (x not in best or s > best[x][0]):
                    best[x] = (s, y)
        for x, (_, y) in sorted(best.items(), key=lambda kv: area_l[kv[0]]):
            rx, ry = uf.find(x), uf.find(y)
            if rx == ry or area_l[rx] >= params.room_min_area_m2:
                continue
            join(ry, rx)
            changed = True
    roots = np.array([uf.find(i) for i in range(n)], dtype=np.int64)
    roots[0] = 0
    # Pieces still too small to be a room have no neighbour to join: scan fragments, not spaces.
    tiny = np.array([area_l[r] < params.room_min_area_m2 for r in roots.tolist()])
    roots[tiny] = 0
    uniq, inv = np.unique(roots, return_inverse=True)
    # Keep 0 as 0; renumber roots by descending area so that label 1 is the biggest space.
    new_area = np.bincount(inv, weights=area, minlength=uniq.size)
    order = np.argsort(-new_area, kind="stable")
    rank = np.empty_like(order)
    rank[order] = np.arange(1, uniq.size + 1)
    zero_idx = int(np.searchsorted(uniq, 0))
    rank = rank - (rank > rank[zero_idx]).astype(rank.dtype)
    rank[zero_idx] = 0
    mapping = rank[inv].astype(np.int32)
    return mapping[labels]


__all__ = ["Floor", "JambJudge", "adjacent_pairs", "basins", "clean_floor", "merge_basins"]
