"""Rooms, hallways and doorways of an occupancy grid.

:func:`segment_spaces` splits the free space of a grid into spaces at its doorways (see
:mod:`langnav.analysis.seg_core` for the method), tells hallways from rooms, and finds the
doorways between spaces and into unexplored territory (:mod:`langnav.analysis.seg_doors`).

After the split, each space takes the rest of its floor: the scanned cells too thin to flood
(laser rays across an unscanned part of a room, broken into dashes: they join the space they
reach without crossing a wall), then the unknown those rays and its walls enclose, its small
enclosed pockets, and the unscanned notches between its rays. Openings between two spaces that
are too narrow for the robot are reported apart (``Segmentation.narrow_doors``), and so are
openings wider than a door that still bound two spaces (``Segmentation.openings``).
Every threshold is a named parameter in metres (:class:`AnalysisParams`), so the result does
not depend on the grid's resolution.
"""

from __future__ import annotations

import dataclasses
import functools
import logging
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Final

import numpy as np
import numpy.typing as npt
from scipy import ndimage as ndi
from skimage.segmentation import watershed

from langnav.analysis.door_judge import hallways_meet, judge_doors
from langnav.analysis.door_posts import wide_with_posts
from langnav.analysis.elements import Door, ElementKind, Room
from langnav.analysis.errors import AnalysisError
from langnav.analysis.params import DEFAULT_PARAMS, AnalysisParams
from langnav.analysis.precompute import (
    GridLayers,
    approximate_polygons,
    border_labels,
    count_labels,
    dilate8,
    dilate_box,
    divmod_int,
    edt_scaled,
    fill_holes,
    longest_contour,
    maximum3,
    median,
    nonzero2,
    unique_values,
)
from langnav.analysis.seg_core import (
    EIGHT,
    Floor,
    JambJudge,
    adjacent_pairs,
    basins,
    clean_floor,
    merge_basins,
)
from langnav.analysis.seg_doors import RawDoor, doors_between, label_max, openings_to_unknown
from langnav.analysis.wall_lines import (
    WallGap,
    closure_mask,
    dominant_directions,
    leaf_mask,
    wall_gaps,
)
from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN, OccupancyGrid

log = logging.getLogger(__name__)

#: An enclosed unknown region belongs to a room when at least this share of the cells around it
#: are that room's floor (an unscanned corner); a region walled in on all sides (a courtyard, a
#: closed room never entered) does not.
ENCLOSED_UNKNOWN_MIN_FLOOR_SHARE: Final = 0.25
#: Outlines of larger bounding boxes (cells) are traced on a subsampled mask (for drawing).
OUTLINE_MAX_CELLS: Final = 60_000
#: Outlines are thinned to about this many points before simplification (they are for drawing).
OUTLINE_MAX_POINTS: Final = 400
#: The grid is cropped to the free space plus this margin (m) before segmenting: enough for the
#: walls and the unknown that openings lead into.
CROP_MARGIN_M: Final = 3.0
#: Widths of spaces with larger bounding boxes (cells) are measured on a subsampled mask.
WIDTH_MAX_CELLS: Final = 250_000
#: A cell is on a space's centre line when its clearance is at least this share of the largest
#: within half a hallway's width (a wall's bumps add spurs to the medial axis, lower than it).
CENTRE_LINE_MIN_SHARE: Final = 0.8
#: A closed wall gap is given back to the spaces found within this many cells of it.
REOPEN_MARGIN_CELLS: Final = 4
#: Two spaces parted by more closed wall gaps than a wall has doors into one room are one space
#: when the gaps take at least this share of the line they lie on: a row of shelf units,
#: counters or desks is open for about as much of its length as it is solid, a wall with a
#: few doors into the same room is mostly wall.
ROW_OF_CLUTTER_MIN_OPEN_SHARE: Final = 0.4
#: ... and when there are at least this many: a room may have a door at each end and one in
#: the middle onto the same corridor; a row of racks or desks has a gap every few metres.
ROW_OF_CLUTTER_MIN_GAPS: Final = 4
#: ... and when the gaps lie on one line: their centres within this distance (m, rms) of it,
#: half an interior wall's thickness.
ROW_OF_CLUTTER_MAX_OFF_LINE_M: Final = 0.15
#: A space with at least this many doorways and openings, corridor-narrow wall to wall, is a
#: hallway even when it is short for its width (an entrance hall, a flat's hallway, a ward
#: corridor with a nurse station bay): a space that serves that many others is walked through;
#: a room has a door or two (an en-suite, a second way out), rarely four.
HALLWAY_MIN_DOORWAYS: Final = 4
#: Pockets a space encloses count as its floor, when its width is measured wall to wall, up to
#: this share of its area: furniture takes a small part of a room (a bed, a counter, a row of
#: shelves); the block a corridor runs around (a stair or lift core) is a large part of it.
FURNITURE_MAX_SHARE: Final = 0.2
#: A hall (a lounge, a dining hall, an open lobby) is at least this many times as wide as the
#: widest corridor (``hallway_max_width_m``): where a disc that wide fits in a space, the space
#: is a hall there, however a corridor runs into it with no wall between.
HALL_MIN_WIDTH_SHARE: Final = 2.0
#: ... along a stretch at least this long both ways (m): the centres of the discs that fit
#: cover a square this wide, so a hall is at least 8 m across; a room just wide enough for
#: the disc (a large office joined to its corridor through a doorway) is no hall.
HALL_CORE_MIN_SIDE_M: Final = 2.0
#: ... a corridor leaves the hall through a mouth at most this many times its own width long
#: (a cut across it, slanted or curved); a bay of the hall meets it along a longer curve.
CORRIDOR_MOUTH_MAX_SHARE: Final = 2.0
#: A space is walled: at least this share of the cells round its outline are wall, even for a
#: room seen only through its door (the laser's rays end on its far walls: a seventh of its
#: outline and more on the maps we have). A space whose outline is nearly all unknown is a view
#: out of the building (a fan of laser rays through a door or a window, ending in the open or at
#: the sensor's range), not a room or a hallway a person would name.
SPACE_MIN_WALL_SHARE: Final = 0.1
#: The spaces an arch joins are read this far (m) either side of its wall line: past the
#: half-thickness of the wall it is cut in.
ARCH_SIDE_LOOK_M: Final = 0.3
#: Id used in ``Door.connects`` for unexplored territory.
UNKNOWN_ID: Final = "unknown"
#: Openings between two spaces narrower than the robot can pass (``door_min_width_m``) but at
#: least this wide (m) are reported apart, as narrow doors: a doorway drawn narrow in a floor
#: plan, a door left ajar. Narrower gaps are cracks in a wall (missed scan points).
NARROW_DOOR_MIN_WIDTH_M: Final = 0.25


@dataclass(frozen=True, eq=False)
class Segmentation:
    """Spaces and doorways of a grid. ``labels`` is int32 in grid orientation (row 0 = bottom):
    0 = no space, k = the room or hallway whose ``label`` is k."""

    labels: npt.NDArray[np.int32] = field(repr=False)
    rooms: tuple[Room, ...]
    doors: tuple[Door, ...]
    #: Openings between two spaces too narrow for the robot (see NARROW_DOOR_MIN_WIDTH_M): doors
    #: to a person, never a way through for the robot; not in ``doors``.
    narrow_doors: tuple[Door, ...] = ()
    #: Openings between two spaces wider than a door (``door_max_width_m``) that still bound them
    #: (a gap in a wall line: an arch, an open front): ways between the spaces, not doors.
    openings: tuple[Door, ...] = ()

    def room_by_label(self, label: int) -> Room | None:
        for r in self.rooms:
            if r.label == label:
                return r
        return None


def segment_spaces(grid: OccupancyGrid, params: AnalysisParams = DEFAULT_PARAMS,
                   layers: GridLayers | None = None) -> Segmentation:
    """Split the free space of ``grid`` into rooms and hallways joined by doorways.

    ``layers``: the masks and components of ``grid`` (:class:`GridLayers`), when the caller has
    them; they are used where the grid is segmented as it is (neither cropped nor coarsened).
    """
    if layers is not None and layers.grid is not grid:
        raise ValueError("segment_spaces: layers were computed for another grid; pass GridLayers(grid)")
    free = grid.free if layers is None else layers.free
    if not free.any():
        raise AnalysisError(f"{grid.source}: the map has no free space to segment")
    # Work on the part of the grid around the free space (maps often have wide margins).
    margin = math.ceil(CROP_MARGIN_M / grid.resolution_m)
    rows = np.flatnonzero(free.any(axis=1))
    cols = np.flatnonzero(free.any(axis=0))
    r0, r1 = max(0, rows[0] - margin), min(grid.height, rows[-1] + margin + 1)
    c0, c1 = max(0, cols[0] - margin), min(grid.width, cols[-1] + margin + 1)
    if (r0, r1, c0, c1) == (0, grid.height, 0, grid.width):
        return _segment_at_working_resolution(grid, params, layers)
    ox, oy = grid.grid_to_world(r0, c0)
    sub = OccupancyGrid(grid.cells[r0:r1, c0:c1], grid.resolution_m, float(ox), float(oy),
                        grid.origin_yaw_rad, grid.source)
    seg = _segment_at_working_resolution(sub, params)
    labels = np.zeros(grid.cells.shape, dtype=np.int32)
    labels[r0:r1, c0:c1] = seg.labels
    return Segmentation(labels=labels, rooms=seg.rooms, doors=seg.doors, narrow_doors=seg.narrow_doors,
                        openings=seg.openings)


def _segment_at_working_resolution(grid: OccupancyGrid, params: AnalysisParams,
                                   layers: GridLayers | None = None) -> Segmentation:
    """Segment large fine grids on a coarser copy (every threshold is in metres, so the result
    is the same within a cell), then carry the labels and room measures back to the grid."""
    f = int(params.seg_coarse_resolution_m / grid.resolution_m + 1e-9)
    if grid.cells.size <= params.seg_max_cells_full_resolution or f < 2:
        return _segment(grid, params, layers)
    h, w = grid.cells.shape
    ph, pw = -h % f, -w % f
    cells = np.pad(grid.cells, ((0, ph), (0, pw)), constant_values=UNKNOWN)
    blocks = cells.reshape((h + ph) // f, f, (w + pw) // f, f)
    coarse = np.full(blocks.shape[::2], UNKNOWN, dtype=np.int8)
    coarse[2 * (blocks == FREE).sum(axis=(1, 3)) >= f * f] = FREE
    coarse[(blocks == OCCUPIED).any(axis=(1, 3))] = OCCUPIED  # thin walls survive
    seg = _segment(OccupancyGrid(coarse, grid.resolution_m * f, grid.origin_x_m, grid.origin_y_m,
                                 grid.origin_yaw_rad, grid.source), params)
    labels = np.repeat(np.repeat(seg.labels, f, axis=0), f, axis=1)[:h, :w].copy()
    labels[grid.cells == OCCUPIED] = 0
    # Free cells of coarse blocks that held a wall take a neighbour's label.
    orphan = (grid.cells == FREE) & (labels == 0)
    if orphan.any():
        labels[orphan] = ndi.maximum_filter(labels, size=2 * f + 1)[orphan]
    objs = ndi.find_objects(labels)
    rooms = tuple(_measured_at(grid, labels, r, objs[r.label - 1]) for r in seg.rooms
                  if r.label <= len(objs) and objs[r.label - 1] is not None)
    return Segmentation(labels=labels, rooms=rooms, doors=seg.doors, narrow_doors=seg.narrow_doors,
                        openings=seg.openings)


def _measured_at(grid: OccupancyGrid, labels: npt.NDArray[np.int32], room: Room,
                 sl: tuple[slice, slice]) -> Room:
    """``room`` with its areas, centroid and cells measured on ``grid`` (finer than it was found on)."""
    mask = labels[sl] == room.label
    free = mask & (grid.cells[sl] == FREE)
    rr, cc = nonzero2(free if free.any() else mask)
    xs, ys = grid.cell_to_world(rr + sl[0].start, cc + sl[1].start)
    a = grid.cell_area_m2
    return dataclasses.replace(room, area_m2=float(mask.sum()) * a, free_area_m2=float(free.sum()) * a,
                               centroid=(float(xs.mean()), float(ys.mean())),
                               cells_xy=np.column_stack([xs, ys]))


def _segment(grid: OccupancyGrid, params: AnalysisParams, layers: GridLayers | None = None) -> Segmentation:
    res = grid.resolution_m
    fl = clean_floor(grid.cells, res, params, layers)
    if layers is None:
        occupied, unknown = grid.cells == OCCUPIED, grid.cells == UNKNOWN
    else:
        occupied, unknown = layers.occupied, layers.unknown
    # Door-wide gaps in the building's wall lines part the spaces on their two sides: the flood
    # runs on the floor with them closed, and they are opened again (as doorways) afterwards.
    # The walls are what the cleaning left of the occupied cells (free-standing clutter
    # standing in a row is no wall).
    # The building's wall directions, found once for the wall gaps and the doors in outer walls.
    walls = occupied & ~fl.floor
    directions = fl.wall_directions.of(walls) if fl.wall_directions is not None else dominant_directions(walls)
    gaps = wall_gaps(walls, fl.floor, res, params, directions)
    closed = closure_mask(gaps, fl.floor)
    panes = [g for g in gaps if g.in_front]
    front = closure_mask(panes, fl.floor) if panes else None
    split_floor, split_clear = fl.floor, fl.clearance_m
    if closed.any():
        split_floor = fl.floor & ~closed
        split_clear = edt_scaled(split_floor, res)
    raw_labels = basins(split_clear, split_floor, params.seg_min_peak_m)
    judge = JambJudge(split_floor, split_clear, res, params, fl.wall_pieces, directions) if params.seg_jamb_test \
        else None
    labels = merge_basins(raw_labels, split_clear, res, params, judge)
    if closed.any():
        labels = _reopen(labels, closed, params.seg_max_openings_between, res, front)
    if params.seg_claim_free_m > 0:
        labels = _claim_free(labels, fl.free, ~occupied, params.seg_claim_free_m / res)
    labels, exterior = _attach_enclosed_unknown(labels, fl, grid, params)
    labels = _fill_enclosed(labels, params.seg_island_max_area_m2 / (res * res))
    if params.seg_close_unknown_gaps_m > 0:
        labels = _close_unknown_gaps(labels, unknown, occupied, params.seg_close_unknown_gaps_m / res)
    labels = _drop_slivers(labels, fl.clearance_m, res, params)
    labels = _split_halls_from_corridors(labels, res, params)
    exterior &= labels == 0
    between = doors_between(labels, fl.clearance_m, res, params,
                            min_width_m=min(NARROW_DOOR_MIN_WIDTH_M, params.door_min_width_m))
    passable = params.door_min_width_m - res
    # Wider than a double door: a gap in a wall line that bounds two spaces (an arch, an open
    # front), an opening between them but no door a person would count.
    widest = max(params.door_max_width_m, params.door_wide_max_width_m) + res
    raw_doors = [d for d in between if passable <= d.width_m <= widest]
    raw_narrow = [d for d in between if d.width_m < passable]
    raw_wide = [d for d in between if d.width_m > widest]
    raw_wide += _arches(gaps, labels, fl.clearance_m, res, params)
    peaks = label_max(labels, fl.clearance_m)  # the widest clearance of each space
    view = _views_out(labels, occupied)
    found = openings_to_unknown(labels, fl.floor, exterior, occupied, fl.clearance_m, res, params, peaks,
                                known=between, directions=directions, views_out=view)
    raw_doors += found.doors
    # A doorway between two spaces at a gap in an outer wall line is judged as the flood found
    # it and as that gap (seg_doors.doors_in_outer_walls): the gap stands in for it when only
    # the gap is a door.
    in_line = {id(between[k]): g for k, g in found.at_gaps.items()}
    alternates = list(in_line.values())
    # Only openings cut in a wall are doors (door_judge); the others between two spaces are
    # still ways between them.
    # (The open leaves of double doors found in the wall lines are no wall there.)
    leaves = leaf_mask(gaps, occupied.shape)
    raw_doors, not_doors = judge_doors(raw_doors + alternates, fl.free | leaves, occupied & ~fl.floor & ~leaves,
                                       res, params, unknown=unknown)
    raw_doors, not_doors, raw_wide, raw_narrow = _read_in_wall_lines(in_line, raw_doors, not_doors, raw_wide,
                                                                     raw_narrow)
    # Two door-wide gaps either side of a post are one opening: wider than a door, neither is a door.
    raw_doors, halves = wide_with_posts(raw_doors, fl.free | leaves, res, params)
    not_doors += halves
    raw_wide += [d for d in not_doors if d.b != 0]
    openings = np.bincount(np.array([x for d in raw_doors + raw_wide for x in (d.a, d.b) if x > 0], dtype=np.int64),
                           minlength=int(labels.max()) + 1)
    pairs = [(d.a, d.b) for d in raw_doors + raw_wide]
    rooms = _rooms(grid, labels, fl, params, peaks, openings, _ways_on(openings, pairs, labels),
                   _served(pairs, openings, labels))
    # Two hallways meet through an opening as wide as one of them: a junction, no door (it stays
    # a way between them).
    halls = {r.label: r.width_m for r in rooms if r.kind == ElementKind.HALLWAY}
    junctions = [d for d in raw_doors if d.a in halls and d.b in halls
                 and hallways_meet(d.width_m, (halls[d.a], halls[d.b]))]
    raw_doors = [d for d in raw_doors if d not in junctions]
    raw_wide += junctions
    if view.any():
        # A view out of the building is no space: its cells are no one's, a door into it leads
        # into unexplored territory (found and judged as any other, so the doors stay as they
        # were), and an opening into it wider or narrower than a door is none.
        rooms = [r for r in rooms if not view[r.label]]
        raw_doors = _into_unexplored(raw_doors, view)
        raw_narrow = [d for d in raw_narrow if not (view[d.a] or view[d.b])]
        raw_wide = [d for d in raw_wide if not (view[d.a] or view[d.b])]
        labels = np.where(view[labels], 0, labels).astype(np.int32)
    ids = {r.label: r.id for r in rooms}
    doors = _doors(grid, raw_doors, ids)
    narrow = _doors(grid, raw_narrow, ids, prefix="narrow_door")
    wide = _doors(grid, raw_wide, ids, prefix="opening")
    return Segmentation(labels=labels, rooms=tuple(rooms), doors=tuple(doors), narrow_doors=tuple(narrow),
                        openings=tuple(wide))


def _read_in_wall_lines(in_line: dict[int, RawDoor], doors: list[RawDoor], not_doors: list[RawDoor],
                        wide: list[RawDoor], narrow: list[RawDoor]
                        ) -> tuple[list[RawDoor], list[RawDoor], list[RawDoor], list[RawDoor]]:
    """The judged ``doors`` and ``not_doors`` (flood doorways and their readings at wall-line
    gaps, ``in_line``: id of the doorway -> the gap's reading), and the ``wide`` and ``narrow``
    doorways, with each doorway read one way: as the gap when that is a door (it replaces the
    doorway, whatever its width: the wall shows where and how wide the door is), else as the
    flood found it."""
    alternates = {id(g) for g in in_line.values()}
    door_ids = {id(d) for d in doors}
    replaced = {k for k, g in in_line.items() if id(g) in door_ids}
    kept_alts = {id(in_line[k]) for k in replaced}
    doors = [d for d in doors if (id(d) not in alternates or id(d) in kept_alts) and id(d) not in replaced]
    not_doors = [d for d in not_doors if id(d) not in alternates and id(d) not in replaced]
    wide = [d for d in wide if id(d) not in replaced]
    narrow = [d for d in narrow if id(d) not in replaced]
    return doors, not_doors, wide, narrow


def _arches(gaps: list[WallGap], labels: npt.NDArray[np.int32], clearance_m: npt.NDArray[np.float64],
            res: float, params: AnalysisParams) -> list[RawDoor]:
    """The openings between two spaces through the arches among ``gaps`` wider than
    ``doors_between`` looks (``seg_wall_gap_max_width_m``): a way between the spaces on the
    arch's two sides, found from the wall line itself; one per arch (the lines a cell apart
    find it each: the narrowest, the line through the wall's middle, is kept). Its width is
    the clear width at its middle (twice the clearance there: a line across a stair-stepped
    wall at an angle finds its gap between the steps, a little wider)."""
    out: list[RawDoor] = []
    h, w = labels.shape
    look = ARCH_SIDE_LOOK_M / res
    for g in sorted(gaps, key=lambda g: g.width_m):
        if g.in_front or g.width_m <= params.seg_wall_gap_max_width_m + res:
            continue
        (ra, ca), (rb, cb) = g.end_a_rc, g.end_b_rc
        length = math.hypot(rb - ra, cb - ca)
        if length == 0:
            continue
        nr, nc = (cb - ca) / length, -(rb - ra) / length
        r, c = (ra + rb) / 2, (ca + cb) / 2
        sides = []
        for sign in (-1.0, 1.0):
            ri, ci = round(r + sign * look * nr), round(c + sign * look * nc)
            sides.append(int(labels[ri, ci]) if 0 <= ri < h and 0 <= ci < w else 0)
        a, b = sides
        seen = any({o.a, o.b} == {a, b} and math.hypot(o.center_rc[0] - r - 0.5, o.center_rc[1] - c - 0.5) * res
                   <= o.width_m for o in out)
        if a > 0 and b > 0 and a != b and not seen:
            normal = (nr, nc) if a < b else (-nr, -nc)
            clear = float(clearance_m[round(r), round(c)])
            width = min(g.width_m, 2.0 * clear - 0.5 * res) if clear > 0 else g.width_m
            out.append(RawDoor(min(a, b), max(a, b), (r + 0.5, c + 0.5), normal, width, in_wall_line=True))
    return out


def _reopen(labels: npt.NDArray[np.int32], closed: npt.NDArray[np.bool_],
            max_openings: int, resolution_m: float,
            front: npt.NDArray[np.bool_] | None = None) -> npt.NDArray[np.int32]:
    """Give the cells that closed the wall gaps back to the spaces on either side of them (each
    to the nearest: the two sides meet in the gap's middle): the gap becomes the doorway
    between the two.

    Two spaces parted by more than ``max_openings`` closed gaps (0: no limit) that take a large
    share of the line they lie on are one space: a wall has a door or two into the same room, a
    row of counters, desks or shelf units standing in a line has a gap between every two of
    them (see ``seg_max_openings_between`` for openings found by the flood). The gaps of a
    front (``front``: a glass front, a row of windows between piers) are no such row: it
    stands in a wall line between stretches of solid wall."""
    todo = closed & (labels == 0)
    if not todo.any():
        return labels
    out = labels.copy()
    pieces, _ = ndi.label(todo, structure=EIGHT)
    h, w = labels.shape
    objs = ndi.find_objects(pieces)
    for sl in objs:
        if sl is None:
            continue
        win = (slice(max(sl[0].start - REOPEN_MARGIN_CELLS, 0), min(sl[0].stop + REOPEN_MARGIN_CELLS, h)),
               slice(max(sl[1].start - REOPEN_MARGIN_CELLS, 0), min(sl[1].stop + REOPEN_MARGIN_CELLS, w)))
        lab = labels[win]
        if not (lab > 0).any():
            continue  # a closure with no space beside it (its spaces were too small to keep)
        _, (ri, ci) = ndi.distance_transform_edt(lab == 0, return_indices=True)
        sub = todo[win]
        out[win][sub] = lab[ri[sub], ci[sub]]
    if max_openings <= 0:
        return out
    # Per pair of spaces: the closed gaps' (row, col) extents, to tell a row of clutter (open for
    # a large share of its length) from a wall with several doors (mostly solid); not a front's.
    boxes: dict[tuple[int, int], list[tuple[slice, slice]]] = {}
    for k, sl in enumerate(objs, start=1):
        if sl is None:
            continue
        mine = pieces[sl] == k
        if front is not None and (front[sl] & mine).any():
            continue
        got = np.unique(out[sl][mine])
        got = got[got > 0]
        if got.size == 2:
            boxes.setdefault((int(got[0]), int(got[1])), []).append(sl)
    rows_of_clutter = []
    for ab, sls in boxes.items():
        if len(sls) < max(max_openings + 1, ROW_OF_CLUTTER_MIN_GAPS):
            continue
        # A row stands on one line (a room with doors in two of its walls is no row).
        centres = np.array([((a.start + a.stop) / 2, (b.start + b.stop) / 2) for a, b in sls])
        centred = centres - centres.mean(axis=0)
        off_line = float(np.linalg.svd(centred, compute_uv=False)[-1]) / math.sqrt(len(sls))
        if off_line * resolution_m > ROW_OF_CLUTTER_MAX_OFF_LINE_M:
            continue
        open_cells = sum(math.hypot(a.stop - a.start, b.stop - b.start) for a, b in sls)
        span = math.hypot(max(a.stop for a, _ in sls) - min(a.start for a, _ in sls),
                          max(b.stop for _, b in sls) - min(b.start for _, b in sls))
        if open_cells >= ROW_OF_CLUTTER_MIN_OPEN_SHARE * span:
            rows_of_clutter.append(ab)
    if not rows_of_clutter:
        return out
    target = np.arange(int(out.max()) + 1, dtype=np.int32)
    for a, b in sorted(rows_of_clutter):
        ra, rb = target[a], target[b]
        target[target == max(ra, rb)] = min(ra, rb)
    keep = np.unique(target)
    renum = np.zeros(target.size, dtype=np.int32)
    renum[keep] = np.arange(keep.size, dtype=np.int32)  # keep[0] is 0: no space stays 0
    return renum[target][out].astype(np.int32)


def _views_out(labels: npt.NDArray[np.int32], occupied: npt.NDArray[np.bool_]) -> npt.NDArray[np.bool_]:
    """Per label: is that space a view out of the building (``SPACE_MIN_WALL_SHARE``)?"""
    n = int(labels.max())
    view = np.zeros(n + 1, dtype=bool)
    if n <= 1:
        return view
    h, w = labels.shape
    # The cells round each space's outline: (space, cell) pairs, each once, over the 8 neighbours.
    keys: list[npt.NDArray[np.int64]] = []
    for dr in (-1, 0, 1):
        for dc in (-1, 0, 1):
            if dr == 0 and dc == 0:
                continue
            src = labels[max(dr, 0):h + min(dr, 0), max(dc, 0):w + min(dc, 0)]
            dst = labels[max(-dr, 0):h + min(-dr, 0), max(-dc, 0):w + min(-dc, 0)]
            rr, cc = nonzero2((src > 0) & (dst != src))
            cell = (rr + max(-dr, 0)).astype(np.int64) * w + (cc + max(-dc, 0))
            keys.append(src[rr, cc].astype(np.int64) * (h * w) + cell)
    pairs = unique_values(np.concatenate(keys))
    space, cell = divmod_int(pairs, h * w)
    ring = np.bincount(space, minlength=n + 1)
    wall = np.bincount(space[occupied.ravel()[cell]], minlength=n + 1)
    area = count_labels(labels, n + 1)
    view = (wall < SPACE_MIN_WALL_SHARE * ring) & (area > 0)
    view[0] = False
    # A view out is a small part of a map that draws its walls: where most of the floor has
    # little wall round it, its walls were not drawn as walls (an image whose walls read as
    # unknown, an open yard) and the test tells nothing.
    if area[view].sum() * 2 > area[1:].sum():
        view[:] = False
    return view


def _into_unexplored(doors: list[RawDoor], view: npt.NDArray[np.bool_]) -> list[RawDoor]:
    """``doors`` with the views out (``view``, per label) read as unexplored territory: a door
    into one leads from its space into the unexplored (``b`` = 0); one between two views, or
    from a view into the unexplored, is none."""
    out: list[RawDoor] = []
    for d in doors:
        if not view[d.a]:
            out.append(dataclasses.replace(d, b=0) if d.b > 0 and view[d.b] else d)
        elif d.b > 0 and not view[d.b]:
            out.append(dataclasses.replace(d, a=d.b, b=0, normal_rc=(-d.normal_rc[0], -d.normal_rc[1])))
    return out


def _attach_enclosed_unknown(labels: npt.NDArray[np.int32], fl: Floor, grid: OccupancyGrid,
                             params: AnalysisParams) -> tuple[npt.NDArray[np.int32], npt.NDArray[np.bool_]]:
    """Give unknown regions enclosed by one room (unscanned corners) to that room.

    Returns the new labels and the unknown that remains unexplored territory.
    """
    ext = fl.exterior
    # 4-connected: the unknown between laser rays (one cell wide, often diagonal) is a piece of
    # its own, enclosed by the room those rays belong to.
    lab, n = ndi.label(ext)
    if n == 0:
        return labels, ext
    border = border_labels(lab)
    ring = dilate8(ext) & ~ext
    rr, cc = nonzero2(ring)
    # Which unknown region each ring cell touches (the largest label among its 8 neighbours).
    near = maximum3(lab)[rr, cc]
    ring_room = labels[rr, cc]
    total = np.bincount(near, minlength=n + 1)
    out = labels.copy()
    remaining = ext.copy()
    keyed = near.astype(np.int64) * (int(labels.max()) + 1) + ring_room
    counts = np.bincount(keyed[ring_room > 0], minlength=(n + 1) * (int(labels.max()) + 1))
    counts = counts.reshape(n + 1, int(labels.max()) + 1)
    best_room = counts.argmax(axis=1)
    best_share = counts.max(axis=1) / np.maximum(total, 1)
    # Not larger than an unscanned part of a room can be: a bounded area, and less than the
    # scanned part of the room itself (a courtyard inside a corridor loop is neither).
    cell_area = grid.resolution_m**2
    unknown_area = count_labels(lab, n + 1) * cell_area
    room_area = count_labels(labels, int(labels.max()) + 1) * cell_area
    take = (best_share >= ENCLOSED_UNKNOWN_MIN_FLOOR_SHARE) & (best_room > 0) \
        & (unknown_area <= params.seg_enclosed_unknown_max_area_m2) \
        & (unknown_area <= room_area[best_room])
    take[0] = False
    take[border] = False
    if take.any():
        sel = take[lab]
        out[sel] = best_room[lab[sel]]
        remaining &= ~sel
    return out.astype(np.int32), remaining


def _fill_enclosed(labels: npt.NDArray[np.int32], max_cells: float) -> npt.NDArray[np.int32]:
    """Give each space the small unlabelled pockets it encloses (clutter, unscanned spots up to
    ``max_cells``): they are part of its floor area, as a person sees the room. A large enclosed
    region (a courtyard inside a corridor loop) stays out."""
    out = labels.copy()
    for k, sl in enumerate(ndi.find_objects(labels), start=1):
        if sl is None:
            continue
        sub = labels[sl]
        inside = fill_holes(sub == k) & (sub == 0)
        if not inside.any():
            continue
        pockets, n = ndi.label(inside, structure=EIGHT)
        sizes = count_labels(pockets, n + 1)
        take = sizes <= max_cells
        take[0] = False
        out[sl][take[pockets]] = k
    return out


def _close_unknown_gaps(labels: npt.NDArray[np.int32], unknown: npt.NDArray[np.bool_],
                        occupied: npt.NDArray[np.bool_], radius_cells: float) -> npt.NDArray[np.int32]:
    """Give each space the unknown cells in its narrow notches (the unscanned wedges between
    laser rays in a room): an unknown cell with the same space on both sides, within
    ``radius_cells`` along a row, a column or a diagonal, and no wall in between."""
    r = int(radius_cells)
    if r < 1 or not unknown.any():
        return labels
    todo = unknown & (labels == 0)
    # Only cells with a space within r (in the chessboard metric) can be filled: look out from
    # those alone, through a copy of the labels padded with r cells of wall.
    todo &= dilate_box(labels > 0, 2 * r + 1)
    rows, cols = nonzero2(todo)
    if rows.size == 0:
        return labels
    h, w = labels.shape
    seen = np.full((h + 2 * r, w + 2 * r), -1, dtype=np.int32)  # walls stop the look-out
    seen[r:r + h, r:r + w] = np.where(occupied, -1, labels)
    flat_seen = seen.ravel()
    pw = w + 2 * r
    base = (rows + r) * pw + (cols + r)
    value = np.zeros(rows.size, dtype=np.int32)  # what each cell gets (0: nothing yet)
    steps = np.arange(1, r + 1)

    def first_met(cells: npt.NDArray[np.intp], offsets: npt.NDArray[np.intp]) -> npt.NDArray[np.int32]:
        """Per cell (of ``cells``), the first non-zero value met along its line (a space, or -1:
        a wall, the edge), 0 if none within r."""
        seq = flat_seen[base[cells, None] + offsets[None, :]]
        return seq[np.arange(cells.size), np.argmax(seq != 0, axis=1)]

    # Each cell takes the first line with the same space on both sides: a line is looked along
    # only from the cells still without a space, and behind only where a space lies ahead.
    for dr, dc in ((0, 1), (1, 0), (1, 1), (1, -1)):
        step_off = steps * (dr * pw + dc)
        todo_i = np.flatnonzero(value == 0)
        ahead = first_met(todo_i, step_off)
        some = ahead > 0
        todo_i, ahead = todo_i[some], ahead[some]
        fill = first_met(todo_i, -step_off) == ahead
        value[todo_i[fill]] = ahead[fill]
    out = labels.copy()
    got = value > 0
    out[rows[got], cols[got]] = value[got]
    return out


def _claim_free(labels: npt.NDArray[np.int32], free: npt.NDArray[np.bool_],
                passable: npt.NDArray[np.bool_], max_cells: float) -> npt.NDArray[np.int32]:
    """Give the scanned cells left out of every space (laser rays across an unscanned part of a
    room, broken into dashes; cells joined to a space only diagonally) to the space they reach
    first through ``passable`` cells (free or unknown: no wall in between, 8-connected), if they
    lie within ``max_cells`` of it: a room's scanned floor is all of it, not only the part wide
    enough to flood."""
    todo = free & (labels == 0)
    if not todo.any() or labels.max() == 0:
        return labels
    near = ndi.distance_transform_edt(labels == 0) <= max_cells
    todo &= near
    # Only a window around the cells to claim takes part.
    rows = np.flatnonzero(todo.any(axis=1))
    cols = np.flatnonzero(todo.any(axis=0))
    if rows.size == 0:
        return labels
    r0, r1 = max(0, rows[0] - 1), min(labels.shape[0], rows[-1] + 2)
    c0, c1 = max(0, cols[0] - 1), min(labels.shape[1], cols[-1] + 2)
    win = (slice(r0, r1), slice(c0, c1))
    lab = labels[win]
    grow = todo[win]
    # A flood over a flat image reaches cells in the order of their (8-connected) distance.
    flood = watershed(np.zeros(lab.shape, dtype=np.uint8), lab, connectivity=2,
                      mask=(passable[win] & near[win]) | (lab > 0))
    out = labels.copy()
    out[win] = np.where(grow, flood, lab)
    return out


def _drop_slivers(labels: npt.NDArray[np.int32], clearance_m: npt.NDArray[np.float64], res: float,
                  params: AnalysisParams) -> npt.NDArray[np.int32]:
    """Labels without the spaces narrower than ``params.space_min_width_m`` at their widest point
    (no room or hallway: laser-ray fans, gaps behind furniture, shelf interiors), renumbered in
    order. A sliver touching a wider space is a bay of it and joins the one it shares its
    widest opening with; one alone is no space."""
    if params.space_min_width_m <= 0 or labels.max() == 0:
        return labels
    width = 2.0 * label_max(labels, clearance_m) - res
    keep = width >= params.space_min_width_m - 1e-9
    keep[0] = False
    if keep[1:].all():
        return labels
    # The floor's clearance leaves furniture and unscanned patches out: judge a narrow space on
    # all of it, as a person sees its width.
    objs = ndi.find_objects(labels)
    for k in np.flatnonzero(~keep[1:]) + 1:
        sl = objs[k - 1]
        if sl is not None and _whole_width(labels[sl] == k, res) >= params.space_min_width_m - 1e-9:
            keep[k] = True
    target = np.arange(keep.size, dtype=np.int32)
    target[~keep] = 0
    a_arr, b_arr, s_arr, _ = adjacent_pairs(labels, clearance_m)
    best = np.full(keep.size, -1.0)
    for a, b, s in zip(a_arr.tolist(), b_arr.tolist(), s_arr.tolist(), strict=True):
        for sliver, wide in ((a, b), (b, a)):
            if not keep[sliver] and keep[wide] and s > best[sliver]:
                best[sliver] = s
                target[sliver] = wide
    on = target > 0
    mapping = np.zeros(keep.size, dtype=np.int32)
    mapping[keep] = np.arange(1, int(keep.sum()) + 1, dtype=np.int32)
    return np.where(on, mapping[target], 0).astype(np.int32)[labels]


def _centre_line(clearance_m: npt.NDArray[np.float64], floor: npt.NDArray[np.bool_], res: float,
                 reach_m: float) -> npt.NDArray[np.bool_]:
    """Cells on the centre line of the free space (its medial axis): the clearance is a local
    maximum across a row or a column, as it is midway between two walls, and close to the
    largest clearance within ``reach_m`` (the spurs a noisy wall adds to a medial axis run
    towards the wall, their clearance falling away from the centre's)."""
    c = clearance_m
    across_rows = np.zeros(c.shape, dtype=bool)
    across_rows[1:-1] = (c[1:-1] >= c[:-2]) & (c[1:-1] >= c[2:])
    across_cols = np.zeros(c.shape, dtype=bool)
    across_cols[:, 1:-1] = (c[:, 1:-1] >= c[:, :-2]) & (c[:, 1:-1] >= c[:, 2:])
    line = floor & (c > 0) & (across_rows | across_cols)
    size = 2 * max(1, round(reach_m / res)) + 1
    return line & (c >= CENTRE_LINE_MIN_SHARE * ndi.maximum_filter(c, size=size))


def _typical_widths(labels: npt.NDArray[np.int32], clearance_m: npt.NDArray[np.float64],
                    floor: npt.NDArray[np.bool_], res: float, wide_clearance_m: float
                    ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """Per label: the typical width (twice the median clearance along the space's centre line,
    m: a corridor's width whatever junctions and alcoves widen it here and there) and the share
    of its cells farther than ``wide_clearance_m`` from every wall."""
    n = int(labels.max()) + 1
    line = _centre_line(clearance_m, floor, res, wide_clearance_m) & (labels > 0)
    lab_line = labels[line]
    clear_line = clearance_m[line]
    typical = np.zeros(n)
    if lab_line.size:
        order = np.lexsort((clear_line, lab_line))
        lab_s, clear_s = lab_line[order], clear_line[order]
        starts = np.searchsorted(lab_s, np.arange(n), side="left")
        ends = np.searchsorted(lab_s, np.arange(n), side="right")
        has = ends > starts
        mid = (starts + ends - 1) // 2
        typical[has] = 2.0 * clear_s[np.minimum(mid[has], clear_s.size - 1)] - res
    on = labels > 0
    cells = np.bincount(labels[on], minlength=n)
    wide = np.bincount(labels[on & (clearance_m > wide_clearance_m)], minlength=n)
    return typical, wide / np.maximum(cells, 1)


def _kind_and_size(area_m2: float, peak_m: float, typical_m: float, wide_share: float, openings: int,
                   whole_width: Callable[[], float], res: float, params: AnalysisParams,
                   whole_wide_share: Callable[[], float] = lambda: 0.0,
                   whole_typical: Callable[[], float] = lambda: 0.0,
                   ways_on: int | None = None, extent_m: float = math.inf,
                   served: int | None = None) -> tuple[ElementKind, float, float]:
    """Hallway or room, with (length, width).

    A hallway is walked through (not a dead end entered through one doorway, unless it is
    longer for its width wall to wall than rooms are; ``ways_on``: its openings less those into
    a smaller dead end of its own, an en-suite or a closet) and long and narrow: for its widest
    inscribed circle (furniture was taken out of the floor's clearance already), or, when a
    junction or an alcove widens it here and there, for its typical width (the median width
    along its centre line) if it has two openings or more, is many times longer than that
    typical width and has little floor wider than a corridor; or, with many doorways off it
    (``HALLWAY_MIN_DOORWAYS``, into more than one place: ``served``), longer than wide for
    that typical width. Either way its typical
    width wall to wall (``whole_typical()``, furniture as floor) is a corridor's too. Its width
    is the one it was judged on; length = area / width. Judged on its widest point, it is long
    for that width on that length, but no more than its extent (``extent_m``, how far apart its
    two farthest points are): a room that goes round an island (a laundry's washer row, a
    dispensary's shelf block) has much floor for its width, yet reaches no farther than a room;
    a corridor reaches as far as it is long. (Judged on its typical width, a corridor's alcoves
    and side pockets are floor it has beside its length: there, area / width.)
    ``whole_width()``: the widest inscribed circle of the whole space, its furniture and
    unscanned patches included; ``whole_wide_share()``: the share of the whole space farther
    than half a hallway's width from its edge (an open-plan floor's desk clusters narrow its
    clearance to aisles, but not the floor a person sees: a room).
    """
    # Clearance is measured between cell centres: an opening of n cells has 2 x peak = (n + 1) cells.
    peak_width = max(2.0 * peak_m - res, res)

    def length(w: float) -> float:
        return min(area_m2 / w, extent_m)

    leads_on = openings if ways_on is None else ways_on
    if openings >= 1 and leads_on <= 1:
        # Entered through one doorway and leading nowhere else (but into a smaller dead end
        # of its own: an en-suite, a closet): a room (a dead-end corridor with its doors
        # closed is longer than rooms are). Its width is the one a person sees wall to wall:
        # shelves or a bed along it narrow its floor, not it.
        wall_width = max(peak_width, whole_width())
        if length(wall_width) < params.hallway_dead_end_min_elongation * wall_width:
            return ElementKind.ROOM, area_m2 / wall_width, wall_width
    def narrow(w: float, long: float) -> bool:
        return w <= params.hallway_max_width_m and long >= params.hallway_min_elongation * w

    if narrow(peak_width, area_m2 / peak_width):
        # Part of the space may be unscanned or cluttered (shelves, furniture): its width as a
        # person sees it is that of the whole space.
        peak_width = max(peak_width, whole_width())
        if narrow(peak_width, length(peak_width)):
            return ElementKind.HALLWAY, area_m2 / peak_width, peak_width
    typical = max(min(typical_m, peak_width), res)
    # Judged on its typical width, a space must also be walked through (two openings or more):
    # an open floor's aisles between its desks and shelves are as narrow as a corridor, and a
    # room's bed or table narrows the floor around it; wall to wall (furniture and shelf rows
    # counted as floor), neither is corridor-narrow.
    if typical_m > 0 and openings >= 2 and typical <= params.hallway_max_width_m \
            and wide_share <= params.hallway_max_wide_share:
        long = area_m2 / typical >= params.hallway_long_elongation * typical
        # A space that many others open onto is walked through: it need only be longer than
        # it is wide, as a corridor is (an entrance hall, a ward corridor with a bay).
        # ... into more than one place (``served``): a meeting room's glass front onto an
        # open floor is many openings into one space, and no one walks through it.
        serves = openings >= HALLWAY_MIN_DOORWAYS and (served is None or served >= 2)
        if serves:
            # Its width there is the one within its own walls: the floor's clearance reaches out
            # through the doorways lining it into the rooms beyond, and widens it at each.
            own = min(typical, max(whole_typical(), res))
            serves = area_m2 / own >= params.hallway_min_elongation * own
        if (long or serves) and whole_wide_share() <= params.hallway_max_wide_share \
                and whole_typical() <= params.hallway_max_width_m:
            return ElementKind.HALLWAY, area_m2 / typical, typical
    return ElementKind.ROOM, area_m2 / peak_width, peak_width


def _wall_to_wall(mask: npt.NDArray[np.bool_], res: float, max_pocket_m2: float
                  ) -> tuple[npt.NDArray[np.bool_], float]:
    """A whole space as a person measures it wall to wall, and the cell size it is measured at:
    its mask (on a coarser copy when it is large, padded by a cell) with the pockets it
    encloses filled when they are furniture standing on its floor (a bed, a counter, a row of
    shelves, unscanned spots): up to ``max_pocket_m2`` and ``FURNITURE_MAX_SHARE`` of the
    space. A block a corridor runs around (a stair or lift core, a courtyard) is larger."""
    k = max(1, math.ceil(math.sqrt(mask.size / WIDTH_MAX_CELLS)))
    whole = np.pad(mask[::k, ::k], 1)
    rk = res * k
    holes = fill_holes(whole) & ~whole
    if holes.any() and max_pocket_m2 > 0:
        pockets, n = ndi.label(holes, structure=EIGHT)
        area = count_labels(pockets, n + 1) * rk * rk
        small = area <= min(max_pocket_m2, FURNITURE_MAX_SHARE * float(whole.sum()) * rk * rk)
        small[0] = False
        whole = whole | small[pockets]
    return whole, rk


def _whole_width(mask: npt.NDArray[np.bool_], res: float, max_pocket_m2: float = 0.0) -> float:
    """The widest inscribed circle (m) of a whole space (furniture and unscanned patches in its
    mask included, and the pockets of furniture it encloses: see :func:`_wall_to_wall`), on a
    coarser copy when it is large (a corridor network spans the map)."""
    whole, rk = _wall_to_wall(mask, res, max_pocket_m2)
    return 2.0 * float(ndi.distance_transform_edt(whole, sampling=rk).max()) - rk


def _whole_wide_share(mask: npt.NDArray[np.bool_], res: float, wide_m: float) -> float:
    """The share of a whole space (its mask: furniture and pockets it encloses included) farther
    than ``wide_m`` from its edge, on a coarser copy when it is large."""
    k = max(1, math.ceil(math.sqrt(mask.size / WIDTH_MAX_CELLS)))
    whole = np.pad(mask[::k, ::k], 1)
    if not whole.any():
        return 0.0
    d = ndi.distance_transform_edt(whole, sampling=res * k)
    return float((d[whole] > wide_m).mean())


def _whole_typical_width(mask: npt.NDArray[np.bool_], res: float, reach_m: float,
                         max_pocket_m2: float) -> float:
    """The typical width (m) of a whole space measured wall to wall (:func:`_wall_to_wall`):
    twice the median clearance along its centre line; 0 when it has none."""
    whole, rk = _wall_to_wall(mask, res, max_pocket_m2)
    d = ndi.distance_transform_edt(whole, sampling=rk)
    line = _centre_line(d, whole, rk, reach_m)
    if not line.any():
        return 0.0
    return 2.0 * median(d[line]) - rk


def _split_halls_from_corridors(labels: npt.NDArray[np.int32], res: float,
                                params: AnalysisParams) -> npt.NDArray[np.int32]:
    """Part the spaces that are a corridor run into a hall open onto it (a lounge, a dining
    hall, a lobby with no wall on the corridor's side): the hall is where a disc wider than any
    corridor fits (``HALL_MIN_WIDTH_SHARE`` x ``hallway_max_width_m``); the corridors are the
    narrow runs left over that are longer than wide (``hallway_min_elongation``, judged on
    their typical width) and leave the hall through a mouth about as wide as themselves; what
    else is left (the hall's corners, its bays cut off along the disc's arc, fragments) stays
    with the corridor or hall nearest to it. A corridor widened at a junction or a lobby is no
    hall (nothing that wide fits in it). A hall with a narrow arm (an L-shaped hall) is parted
    too: a person may well name the arm apart."""
    n = int(labels.max())
    if n == 0:
        return labels
    out = labels.copy()
    nxt = n + 1
    r_hall = HALL_MIN_WIDTH_SHARE * params.hallway_max_width_m / 2
    min_area = math.pi * r_hall * r_hall
    cells = count_labels(labels, n + 1) * res * res
    for k, sl in enumerate(ndi.find_objects(labels), start=1):
        if sl is None or cells[k] < 2 * min_area:
            continue
        mask = labels[sl] == k
        whole, rk = _wall_to_wall(mask, res, params.seg_enclosed_unknown_max_area_m2)
        d = ndi.distance_transform_edt(whole, sampling=rk)
        core = d >= r_hall
        if not core.any():
            continue
        # ... over a stretch of floor (HALL_CORE_MIN_SIDE_M).
        cores, nc = ndi.label(core, structure=EIGHT)
        big_core = count_labels(cores, nc + 1) * rk * rk >= HALL_CORE_MIN_SIDE_M ** 2
        big_core[0] = False
        core = big_core[cores]
        if not core.any():
            continue
        wide = whole & (ndi.distance_transform_edt(~core, sampling=rk) <= r_hall)
        rest, m = ndi.label(whole & ~wide, structure=EIGHT)
        if m == 0:
            continue
        line = _centre_line(d, whole, rk, params.hallway_max_width_m / 2)
        near_wide = dilate8(wide)
        area = count_labels(rest, m + 1) * rk * rk
        corridor = np.zeros(m + 1, dtype=bool)
        for j in np.flatnonzero(area[1:] >= params.room_min_area_m2) + 1:
            on = line & (rest == j)
            if not on.any():
                continue
            typical = 2.0 * median(d[on]) - rk
            # A corridor leaves a hall through a mouth as wide as itself; a bay of the hall
            # cut off by the disc's arc meets it along a longer curve.
            mouths, _ = ndi.label(near_wide & (rest == j), structure=EIGHT)
            mouth_len = np.array([math.hypot(a.stop - a.start, b.stop - b.start) * rk
                                  for a, b in ndi.find_objects(mouths) if a is not None])
            corridor[j] = params.space_min_width_m <= typical <= params.hallway_max_width_m and \
                bool((mouth_len <= CORRIDOR_MOUTH_MAX_SHARE * max(typical, rk)).all()) and \
                area[j] >= params.hallway_min_elongation * typical * typical
        if not corridor.any():
            continue
        # The corridors, each a space; the halls with their corners, each a space.
        pieces = np.zeros(whole.shape, dtype=np.int32)
        for j in np.flatnonzero(corridor):
            pieces[rest == j] = int(j)
        halls, h = ndi.label(whole & (pieces == 0), structure=EIGHT)
        big = count_labels(halls, h + 1) * rk * rk >= min_area
        big[0] = False
        pieces[big[halls]] = halls[big[halls]] + m
        # Corners, alcoves and fragments (laser-ray dashes) join the nearest corridor or hall.
        _, (ri, ci) = ndi.distance_transform_edt(pieces == 0, return_indices=True)
        pieces = np.where(whole, pieces[ri, ci], 0).astype(np.int32)
        # Back to the space's own cells (the padding and subsampling undone).
        step = max(1, round(rk / res))
        full = np.repeat(np.repeat(pieces[1:-1, 1:-1], step, axis=0), step, axis=1)[:mask.shape[0], :mask.shape[1]]
        if full.shape != mask.shape or (mask & (full == 0)).any():
            padded = np.zeros(mask.shape, dtype=np.int32)
            padded[:full.shape[0], :full.shape[1]] = full
            _, (ri, ci) = ndi.distance_transform_edt(padded == 0, return_indices=True)
            full = padded[ri, ci]
        ids = np.unique(full[mask])
        ids = ids[ids > 0]
        if ids.size < 2:
            continue
        sub = out[sl]
        biggest = int(ids[np.argmax([np.count_nonzero(mask & (full == i)) for i in ids])])
        for i in ids:
            if int(i) == biggest:
                continue
            sub[mask & (full == i)] = nxt
            nxt += 1
    return out


def _served(pairs: list[tuple[int, int]], openings: npt.NDArray[np.int64],
            labels: npt.NDArray[np.int32]) -> npt.NDArray[np.int64]:
    """Per label, how many places its openings lead on to: each other space once however many
    openings it shares with it (the panes of a glass front, two doors into one room), all but
    one smaller space with no other opening (a room with its own store or en-suite is still a
    dead end, as in :func:`_ways_on`), and each opening into unexplored territory as a place of
    its own."""
    n = openings.size
    area = count_labels(labels, n)
    others: list[set[int]] = [set() for _ in range(n)]
    dead_end = np.zeros(n, dtype=bool)
    unknown = np.zeros(n, dtype=np.int64)
    for a, b in pairs:
        for x, y in ((a, b), (b, a)):
            if not 0 < x < n:
                continue
            if y <= 0:
                unknown[x] += 1
            else:
                others[x].add(y)
                dead_end[x] |= bool(openings[y] == 1 and area[y] < area[x])
    return np.array([len(o) for o in others], dtype=np.int64) - dead_end + unknown


def _ways_on(openings: npt.NDArray[np.int64], pairs: list[tuple[int, int]],
             labels: npt.NDArray[np.int32]) -> npt.NDArray[np.int64]:
    """Per label, its openings that lead on: all of them but one into a smaller space that has
    no other (an en-suite bathroom, a closet, a store behind its door: a room with one is still
    a dead end, not a way through). A corridor serves several such rooms: they all count but
    one, and it stays a way through."""
    area = count_labels(labels, openings.size)
    leaves = np.zeros_like(openings)
    for a, b in pairs:
        if a <= 0 or b <= 0:
            continue
        for x, y in ((a, b), (b, a)):
            if openings[y] == 1 and area[y] < area[x]:
                leaves[x] += 1
    return openings - np.minimum(leaves, 1)


def _rooms(grid: OccupancyGrid, labels: npt.NDArray[np.int32], fl: Floor,
           params: AnalysisParams, peaks: npt.NDArray[np.float64],
           openings: npt.NDArray[np.int64], ways_on: npt.NDArray[np.int64] | None = None,
           served: npt.NDArray[np.int64] | None = None) -> list[Room]:
    """The spaces of ``labels``, measured; ``peaks``: the widest clearance of each (by label);
    ``openings``: how many doorways each has."""
    res = grid.resolution_m
    rooms: list[Room] = []
    objs = ndi.find_objects(labels)
    typical, wide_share = _typical_widths(labels, fl.clearance_m, fl.floor, res,
                                          params.hallway_max_width_m / 2)
    present = [(k, sl, labels[sl] == k) for k, sl in enumerate(objs, start=1) if sl is not None]
    polygons = _outlines(grid, [(sub, sl) for _, sl, sub in present])
    for (k, sl, sub), polygon in zip(present, polygons, strict=True):
        free_sub = sub & fl.free[sl]
        rr, cc = nonzero2(free_sub if free_sub.any() else sub)
        rr = rr + sl[0].start
        cc = cc + sl[1].start
        xs, ys = grid.cell_to_world(rr, cc)
        area = float(sub.sum()) * res * res
        kind, length, width = _kind_and_size(area, float(peaks[k]), float(typical[k]), float(wide_share[k]),
                                             int(openings[k]) if k < openings.size else 0,
                                             functools.partial(_whole_width, sub, res,
                                                               params.seg_enclosed_unknown_max_area_m2),
                                             res, params,
                                             functools.partial(_whole_wide_share, sub, res,
                                                               params.hallway_max_width_m / 2),
                                             functools.partial(_whole_typical_width, sub, res,
                                                               params.hallway_max_width_m / 2,
                                                               params.seg_enclosed_unknown_max_area_m2),
                                             ways_on=int(ways_on[k]) if ways_on is not None and k < ways_on.size else None,
                                             served=int(served[k]) if served is not None and k < served.size else None,
                                             extent_m=_extent(polygon))
        prefix = "hallway" if kind == ElementKind.HALLWAY else "room"
        rooms.append(Room(
            id=f"{prefix}_{k}", label=k, kind=kind, area_m2=area,
            free_area_m2=float(free_sub.sum()) * res * res,
            centroid=(float(xs.mean()), float(ys.mean())), length_m=length, width_m=width,
            cells_xy=np.column_stack([xs, ys]), polygon=polygon))
    return rooms


def _extent(polygon: npt.NDArray[np.float64]) -> float:
    """How far apart (m) the two farthest points of a space's outline are; infinite with no
    outline (nothing to judge its reach by)."""
    if len(polygon) < 2:
        return math.inf
    d = polygon[:, None, :] - polygon[None, :, :]
    return float(np.sqrt((d * d).sum(axis=-1).max()))


def _outlines(grid: OccupancyGrid, spaces: list[tuple[npt.NDArray[np.bool_], tuple[slice, slice]]]
              ) -> list[npt.NDArray[np.float64]]:
    """The outer outline of each space (its mask in the window ``sl`` of the grid) in world
    metres (for drawing), simplified to about a cell; all simplified at once."""
    chains: list[npt.NDArray[np.float64]] = []
    for sub, _ in spaces:
        # Large spaces are outlined on a coarser copy: the outline is for drawing.
        k = max(1, math.ceil(math.sqrt(sub.size / OUTLINE_MAX_CELLS)))
        # The longest of find_contours(np.pad(sub[::k, ::k], 1).astype(np.uint8), 0.5), exactly.
        c = longest_contour(sub[::k, ::k])
        if c is None:
            chains.append(np.zeros((0, 2)))
            continue
        c = (c - 1) * k + 1
        step = max(1, len(c) // OUTLINE_MAX_POINTS)
        chains.append(np.vstack([c[::step], c[:1]]))
    out: list[npt.NDArray[np.float64]] = []
    for (_, sl), c in zip(spaces, approximate_polygons(chains, tolerance=1.0), strict=True):
        if len(c) == 0:
            out.append(np.zeros((0, 2)))
            continue
        r = c[:, 0] - 1 + sl[0].start + 0.5
        col = c[:, 1] - 1 + sl[1].start + 0.5
        xs, ys = grid.grid_to_world(r, col)
        out.append(np.column_stack([xs, ys]))
    return out


def _doors(grid: OccupancyGrid, raw: list[RawDoor], ids: dict[int, str], prefix: str = "door") -> list[Door]:
    doors: list[Door] = []
    c, s = math.cos(grid.origin_yaw_rad), math.sin(grid.origin_yaw_rad)
    # Order doors by position (bottom-left first) so that ids are stable.
    raw = sorted(raw, key=lambda d: (round(d.center_rc[0]), round(d.center_rc[1])))
    for d in raw:
        if d.a not in ids or (d.b != 0 and d.b not in ids):
            continue
        x, y = grid.grid_to_world(d.center_rc[0], d.center_rc[1])
        nr, nc = d.normal_rc
        nx, ny = c * nc - s * nr, s * nc + c * nr
        tx, ty = -ny, nx
        h = d.width_m / 2
        cx, cy = float(x), float(y)
        other = ids[d.b] if d.b != 0 else UNKNOWN_ID
        doors.append(Door(
            id=f"{prefix}_{len(doors) + 1}", center=(cx, cy), width_m=d.width_m,
            jambs=((cx - tx * h, cy - ty * h), (cx + tx * h, cy + ty * h)),
            normal=(float(nx), float(ny)), connects=(ids[d.a], other)))
    return doors


__all__ = ["NARROW_DOOR_MIN_WIDTH_M", "UNKNOWN_ID", "Segmentation", "segment_spaces"]
