"""Which element of the map the words mean: kind, side, order, superlatives, "this room", "of the hallway".

The meanings follow ``../shared/bench/README.md``:

* left / right: the element's reference point has a positive / negative lateral offset;
  ahead: within +-60 deg of the heading; behind: beyond +-120 deg;
* nearest / farthest and first, second ...: straight-line distance from the robot to the element's
  reference point (door: centre; room: nearest cell; obstacle: nearest cell; unexplored area: nearest
  frontier cell), among the elements the other words select; "the X on your left" = the nearest;
* biggest / smallest: by area (a room's counting its unscanned part, ``floor_area_m2``); "this room":
  the room holding the robot; a corner with no room named is a corner of the robot's room; "the
  left corner": of the room's corners ahead, the farthest left.

Doors and passages of the space the robot is in are counted before the others: "the third door on
your left" in a hallway means the hallway's doors, not one seen through a wall.
"""

from __future__ import annotations

import collections
import itertools
import math
import re
import weakref
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Final

import numpy as np
import numpy.typing as npt
from scipy import ndimage
from scipy.spatial import cKDTree

from langnav.analysis.elements import (
    Corner,
    Door,
    Element,
    ElementKind,
    MapAnalysis,
    NarrowPassage,
    Obstacle,
    Room,
    UnexploredArea,
    Wall,
    reference_point,
)
from langnav.grounding.errors import GroundingError
from langnav.grounding.geometry import (
    AHEAD_HALF_ANGLE_DEG,
    BoolArray,
    Point,
    Pose,
    bearing_rad,
    closest_on_segment,
    is_ahead,
    is_behind,
    is_left,
    is_right,
    lateral_offset,
    nearest_point,
    to_robot_frame,
    unit,
)
from langnav.language.intent import Element as Kind
from langnav.language.intent import ElementRef, Landmark, Place, Relation, Side, Superlative
from langnav.maps.grid import FREE, UNKNOWN, OccupancyGrid

#: A robot standing in a doorway belongs to the nearest space within this distance.
SPACE_SNAP_M: Final = 0.6
#: Walls whose lines are within this angle / offset of each other are one wall (split by doors).
WALL_MERGE_ANGLE_DEG: Final = 10.0
WALL_MERGE_OFFSET_M: Final = 0.3
#: A wall runs "along" the robot (left / right wall) within this angle of the heading.
WALL_PARALLEL_DEG: Final = 45.0
#: Wall pieces shorter than this are jambs and stubs, not "the left wall".
WALL_MIN_CHAIN_M: Final = 1.0
#: Corners whose lateral offsets differ by less than this are equally far left / right.
CORNER_SIDE_TIE_M: Final = 0.3
#: An element counts as inside a space when its point is within this distance of the space's cells.
IN_SPACE_M: Final = 0.5
#: "the door next to the box": the element's reference point lies within this distance of the
#: landmark (its cells for rooms and obstacles): about the width of a room, so "the door next to
#: the box" finds a door across a small room from the box but not one in another part of the floor.
NEAR_MAX_M: Final = 4.0

#: "The obstacle on your right" is a thing the robot can see: one whose cells a straight line from the
#: robot reaches without crossing a wall. A line stops this short of the cell it looks at (the thing's own
#: face and a cell of scan noise in front of it are not walls in the way).
SIGHT_END_SLACK_M: Final = 0.15
#: Cells of a thing tried for a line of sight, nearest first (its face towards the robot). A cap for
#: speed (each try walks a line over the grid): the nearest cells are the face the robot would see, so
#: a thing whose nearest 24 cells are all hidden is taken as out of sight (the robot then asks).
SIGHT_CELLS_TRIED: Final = 24

#: A block this thick between two doorways is a piece of furniture (a counter, a desk block: 0.6-0.9 m
#: deep), not a wall: inner walls are 0.1-0.3 m thick, and even a thick one with two doors in it stays
#: under 0.5 m.
FURNITURE_MIN_THICKNESS_M: Final = 0.5
#: The line between the jambs is read this close to the thing (a cell of scan noise either side).
FURNITURE_LINE_SLACK_M: Final = 0.1
#: A thing standing free has floor round it: a window this much bigger than the way between its two
#: doorways holds it whole (a wall runs on out of it).
FURNITURE_FREE_MARGIN_M: Final = 1.0

#: Building codes ask at least 0.8 m of clear width of a door people walk through (ADA 32 in =
#: 0.81 m; most European codes 0.8 m). An opening measured narrower than that less one map cell of
#: error at a jamb is no door anyone builds: it is a gap between pieces of furniture, shelves or a
#: partition (a 0.7 m gap between two benches). A person calls it "the narrow gap" or "the narrow
#: passage", and does not count it among "the doors" of a room.
NARROW_GAP_MAX_M: Final = 0.75

#: "The narrow gap" between two things standing free (two acoustic screens end to end, two parked cars)
#: is a narrow passage: the analysis's are constrictions longer than a door is deep, but a person calls any way
#: between two things that is wider than the robot and narrower than a passage (the analysis's
#: ``passage_max_width_m``) a narrow gap, however thin the things are. Its sides are the faces of the two
#: things within GAP_FACE_M of their nearest points; a gap with no depth gets GAP_MIN_HALF_DEPTH_M a side.
GAP_FACE_M: Final = 0.15
GAP_MIN_HALF_DEPTH_M: Final = 0.1

#: A thing standing free has scanned floor all round it: at least this share of the cells round it
#: free (a speck of scan noise may touch it; a wall runs into unscanned space or other walls).
THING_RING_FREE_MIN: Final = 0.95
#: Its inside is never scanned (a lidar sees its faces): more free cells inside it than a speck of scan
#: noise are a floor, and it is walls round a room, not a thing.
THING_FLOOR_INSIDE_MAX: Final = 4
#: The share of a thing that is furniture-thick (``FURNITURE_MIN_THICKNESS_M``) all through.
THING_THICK_SHARE: Final = 0.8

#: Nouns for obstacles of a compact footprint ("the box") and of a long one ("the shelf"). When the
#: words use one, obstacles of that shape are chosen before the others.
COMPACT_NOUNS: Final = ("box", "boxes", "crate", "crates", "pillar", "pillars", "column", "columns", "post",
                        "posts", "bin", "bins", "chair", "chairs", "stool", "stools", "cube", "cubes",
                        "barrel", "barrels", "plant", "plants", "pot", "pots")
LONG_NOUNS: Final = ("shelf", "shelves", "bench", "benches", "sofa", "sofas", "couch", "couches", "bookcase",
                     "bookcases", "shelving", "rack", "racks", "counter", "counters")
#: Footprint aspect ratios (long side / short side) of a compact and of a long obstacle.
COMPACT_MAX_ASPECT: Final = 1.6
LONG_MIN_ASPECT: Final = 2.0
_COMPACT_RE: Final = re.compile(r"\b(?:" + "|".join(COMPACT_NOUNS) + r")\b", re.IGNORECASE)
#: "The gap" names an opening; where the map has gaps narrower than any door, a person who says
#: "gap" rather than "door" means one of those (``NARROW_GAP_MAX_M``).
_GAP_RE: Final = re.compile(r"\bgaps?\b", re.IGNORECASE)
_DOOR_RE: Final = re.compile(r"\bdoor", re.IGNORECASE)
#: A question about which door is meant names at most this many doors (nearest first): more is a list
#: nobody reads out, and the user can name any door by its label on the map.
MAX_DOORS_NAMED: Final = 3
#: Facing within ~78 deg of across a hallway (cos 0.2), the robot faces neither of its ends.
FACING_ALONG_MIN: Final = 0.2
#: "The door at the end of the corridor" (``_at_the_end``).
_END_RE: Final = re.compile(r"\bend\b", re.IGNORECASE)
_LONG_RE: Final = re.compile(r"\b(?:" + "|".join(LONG_NOUNS) + r")\b", re.IGNORECASE)

ORDINAL_WORDS: Final = {1: "first", 2: "second", 3: "third", 4: "fourth", 5: "fifth", 6: "sixth",
                        7: "seventh", 8: "eighth", 9: "ninth", 10: "tenth"}
NUMBER_WORDS: Final = {0: "no", 1: "one", 2: "two", 3: "three", 4: "four", 5: "five", 6: "six",
                       7: "seven", 8: "eight", 9: "nine", 10: "ten"}
KIND_NOUN: Final = {Kind.DOOR: ("door", "doors"), Kind.WALL: ("wall", "walls"), Kind.ROOM: ("room", "rooms"),
                    Kind.HALLWAY: ("hallway", "hallways"),
                    Kind.NARROW_PASSAGE: ("narrow passage", "narrow passages"),
                    Kind.OBSTACLE: ("obstacle", "obstacles"), Kind.CORNER: ("corner", "corners"),
                    Kind.UNEXPLORED_AREA: ("unexplored area", "unexplored areas"),
                    Kind.NONE: ("place", "places")}
#: The word the map picture shows before an element's number ("door 2", "passage 1").
LABEL_NOUN: Final = {Kind.DOOR: "door", Kind.WALL: "wall", Kind.ROOM: "room", Kind.HALLWAY: "hallway",
                     Kind.NARROW_PASSAGE: "passage", Kind.OBSTACLE: "obstacle", Kind.CORNER: "corner",
                     Kind.UNEXPLORED_AREA: "unexplored"}
SIDE_WORDS: Final = {Side.LEFT: "on your left", Side.RIGHT: "on your right", Side.AHEAD: "in front of you",
                     Side.BEHIND: "behind you"}


@dataclass(frozen=True)
class WallLine:
    """One wall as a person sees it: collinear wall segments of a space joined across doorways."""

    ids: tuple[str, ...]
    start: Point
    end: Point
    inward: Point
    room: str | None

    @property
    def length_m(self) -> float:
        return math.dist(self.start, self.end)

    @property
    def direction(self) -> Point:
        n = self.length_m or 1.0
        return ((self.end[0] - self.start[0]) / n, (self.end[1] - self.start[1]) / n)


# ------------------------------------------------------------------------------ descriptions
def describe_ref(ref: ElementRef) -> str:
    """"the second door on your left", "the biggest room", "the left corner of this room"."""
    if ref.name:
        return f"'{ref.name}'"
    if ref.place == Place.START:
        return "where I started"
    if ref.place == Place.PREVIOUS:
        return "where I was before"
    if ref.label is not None:
        return f"{LABEL_NOUN.get(ref.kind, KIND_NOUN[ref.kind][0])} {ref.label}"
    if ref.passed:
        return f"the {KIND_NOUN[ref.kind][0]} I just passed"
    if ref.relation is not None and ref.kind in (Kind.ROOM, Kind.HALLWAY):
        noun = KIND_NOUN[ref.kind][0]
        other = "this one" if ref.near is None or ref.near.in_current_room else describe_ref(landmark_ref(ref.near))
        if ref.relation == Relation.ACROSS:
            if ref.near is not None and ref.near.kind == Kind.ROOM and not ref.near.in_current_room:
                return f"the {noun} across from {other}"
            hall = "the hallway" if ref.near is None or ref.near.kind != Kind.HALLWAY else other
            return f"the {noun} across {hall}"
        if ref.relation == Relation.DOORS_ALONG:
            n = ref.ordinal or 1
            way = "back" if ref.side == Side.BEHIND else "down" + (f" {SIDE_WORDS[ref.side]}" if ref.side else "")
            return f"the {noun} {n} door{'s' if n != 1 else ''} {way}"
        words = ["the"]
        if ref.ordinal is not None:
            words.append(ORDINAL_WORDS.get(ref.ordinal, f"{ref.ordinal}th"))
        if ref.superlative is not None:
            words.append(ref.superlative.value)
        words.append(noun)
        if ref.side is not None:
            words.append(SIDE_WORDS[ref.side])
        return " ".join(words) + f" next to {other}"
    noun = KIND_NOUN[ref.kind][0]
    plain = ref.ordinal is None and ref.superlative is None and ref.side is None and ref.within is None
    if ref.kind in (Kind.ROOM, Kind.HALLWAY) and ref.in_current_room and plain:
        return f"this {noun}"
    words = ["the"]
    if ref.ordinal is not None:
        words.append(ORDINAL_WORDS.get(ref.ordinal, f"{ref.ordinal}th"))
    if ref.superlative is not None:
        words.append(ref.superlative.value)
    if ref.side is not None and ref.kind in (Kind.CORNER, Kind.WALL) and ref.side in (Side.LEFT, Side.RIGHT):
        words.append(ref.side.value)
        words.append(noun)
    else:
        words.append(noun)
        if ref.side is not None:
            words.append(SIDE_WORDS[ref.side])
        if ref.also_side is not None:
            words.append(SIDE_WORDS[ref.also_side])
    if ref.near is not None and ref.near.kind in (Kind.ROOM, Kind.HALLWAY):
        words.append(f"of {describe_ref(landmark_ref(ref.near))}")
    elif ref.within is not None:
        words.append(f"of the {KIND_NOUN[ref.within][0]}")
    elif ref.in_current_room:
        words.append("in this room")
    if ref.near is not None and ref.near.kind not in (Kind.ROOM, Kind.HALLWAY):
        words.append(f"near {describe_ref(landmark_ref(ref.near))}")
    return " ".join(words)


def landmark_ref(landmark: Landmark) -> ElementRef:
    """A landmark as an element reference of its own."""
    return ElementRef(**landmark.model_dump())


def _count_phrase(n: int, ref: ElementRef) -> str:
    singular, plural = KIND_NOUN[ref.kind]
    noun = singular if n == 1 else plural
    where = ""
    if ref.side is not None and not (ref.kind in (Kind.CORNER, Kind.WALL) and ref.side in (Side.LEFT, Side.RIGHT)):
        where = " " + SIDE_WORDS[ref.side]
    if ref.within is not None:
        where += f" in the {KIND_NOUN[ref.within][0]}"
    elif ref.in_current_room:
        where += " in this room"
    return f"{NUMBER_WORDS.get(n, str(n))} {noun}{where}"


# ------------------------------------------------------------------------------ spaces
def space_of(analysis: MapAnalysis, xy: Point) -> Room | None:
    """The room or hallway holding a point (or, in a doorway, the nearest one within SPACE_SNAP_M)."""
    room = analysis.room_at(*xy)
    if room is not None:
        return room
    best: tuple[float, Room] | None = None
    for r in analysis.rooms:
        if len(r.cells_xy) == 0:
            continue
        d, _ = nearest_point(xy, r.cells_xy)
        if d <= SPACE_SNAP_M and (best is None or d < best[0]):
            best = (d, r)
    return None if best is None else best[1]


def gap_joined(analysis: MapAnalysis, space: Room) -> list[Room]:
    """The space with the spaces narrow gaps join to it (``is_gap``), one after the other. A gap
    narrower than any door does not end a room: a corridor narrowed by a cart goes on past it, and a
    room parted by a row of shelves with a gap in it is one room, whose doors are the doors of both
    parts. Nor do two wide openings between the same two spaces (``round_a_thing``): a long table
    parting a room leaves a way round each of its ends, and a person walks round it in one room."""
    round_ends = round_a_thing(analysis)
    # (A gap the analysis reads as no door at all, an opening, parts no more: the way past a cart
    # standing against a corridor's wall is the way round its end.)
    gaps = [d for d in (*analysis.doors, *analysis.openings)
            if is_gap(d, analysis) and d not in round_ends and not _between_two_rooms(d, analysis)] + round_ends
    by_id = {r.id: r for r in analysis.rooms}
    group = [space]
    seen = {space.id}
    k = 0
    while k < len(group):
        cur = group[k].id
        for g in gaps:
            if cur in g.connects:
                for other in g.connects:
                    if other not in seen and other in by_id:
                        seen.add(other)
                        group.append(by_id[other])
        k += 1
    return group


def _between_two_rooms(gap: Door, analysis: MapAnalysis) -> bool:
    """A narrow way between two rooms that each have a way in of their own (a door or an opening wider
    than a gap, from a third space) is a door between two rooms, not a gap parting one: a kennel room and a treatment room,
    each with its door on the corridor, joined by a 0.8 m connecting door that the scan measures 0.7 m.
    The part behind a gap in a bench row or a shelf line is reached through that gap only (or it is a
    strip, a corridor's part: hallways still join), and that part is the same room."""
    by_id = {r.id: r for r in analysis.rooms}
    sides = [by_id.get(c) for c in gap.connects]
    if len(set(gap.connects)) != 2 or any(r is None or r.kind != ElementKind.ROOM for r in sides):
        return False
    if _jamb_depth_m(gap, analysis) >= FURNITURE_MIN_THICKNESS_M:
        return False  # cut in something as deep as furniture (a shelf line, a bench row): a gap in one room
    # a way in of its own: from a third space (not another way between the same two), wider than a gap
    pair = set(gap.connects)
    ways = [w for w in (*analysis.doors, *analysis.openings) if len(set(w.connects)) == 2
            and set(w.connects) != pair and w.width_m >= NARROW_GAP_MAX_M]
    return all(any(c in w.connects for w in ways) for c in pair)


def _jamb_depth_m(way: Door, analysis: MapAnalysis) -> float:
    """How deep the thing a way is cut in is: the run of occupied cells along the way's normal through a
    point just inside each jamb (``FURNITURE_LINE_SLACK_M`` along the opening's line), the deeper of the
    two. A wall is 0.1-0.3 m; a shelf or a bench row 0.5 m and more (``FURNITURE_MIN_THICKNESS_M``)."""
    grid = analysis.grid
    occupied = grid.occupied
    nx, ny = way.normal
    reach = np.arange(-2.0, 2.0, grid.resolution_m / 2)
    deepest = 0.0
    for jamb, other in (way.jambs, way.jambs[::-1]):
        along = unit((jamb[0] - other[0], jamb[1] - other[1]))
        px, py = jamb[0] + along[0] * FURNITURE_LINE_SLACK_M, jamb[1] + along[1] * FURNITURE_LINE_SLACK_M
        rr, cc = grid.world_to_index(px + reach * nx, py + reach * ny)
        ok = grid.in_bounds(rr, cc)
        hit = np.zeros(len(reach), dtype=bool)
        hit[ok] = occupied[rr[ok], cc[ok]]
        mid = len(reach) // 2
        if not hit[mid]:
            continue
        lo, hi = mid, mid
        while lo > 0 and hit[lo - 1]:
            lo -= 1
        while hi < len(hit) - 1 and hit[hi + 1]:
            hi += 1
        deepest = max(deepest, float(reach[hi] - reach[lo]) + grid.resolution_m)
    return deepest


def round_a_thing(analysis: MapAnalysis) -> list[Door]:
    """The ways between two spaces that a thing standing free between them leaves round its ends: all
    the openings, narrow gaps and doors joining two spaces that are joined by at least one of the
    analysis's openings (an open way in a wall line, no door in it) and one more way, or by two doorways with a thick
    block standing free between them (``_block_between``). A wall has doors in it; an open way and a
    second way between the same two spaces, or two ways round a counter, are the two ends of a long
    table, a desk block, a shelf block or a counter, which a person walks round within one room, not
    a wall between two rooms. Found
    once per analysis (the analysis is immutable; the blocks are looked at in the grid)."""
    known = _ROUND_A_THING.get(analysis)
    if known is None:
        known = _round_a_thing(analysis)
        _ROUND_A_THING[analysis] = known
    return list(known)


#: round_a_thing's answer for each analysis still in use (a memo, dropped with the analysis).
_ROUND_A_THING: weakref.WeakKeyDictionary[MapAnalysis, tuple[Door, ...]] = weakref.WeakKeyDictionary()


def _round_a_thing(analysis: MapAnalysis) -> tuple[Door, ...]:
    links: list[Door] = [*analysis.openings, *analysis.doors]
    spaces = {r.id for r in analysis.rooms}
    pairs: dict[frozenset[str], list[Door]] = {}
    for o in links:
        # (two doors out to the unscanned world are two ways out, whatever stands between them)
        if len(set(o.connects)) == 2 and set(o.connects) <= spaces:
            pairs.setdefault(frozenset(o.connects), []).append(o)
    wide = {id(o) for o in analysis.openings}
    return tuple(o for ways in pairs.values() if len(ways) >= 2 and (
        any(id(w) in wide for w in ways) or any(_block_between(analysis, a, b) for a, b in itertools.combinations(ways, 2)))
        for o in ways)


def _block_between(analysis: MapAnalysis, a: Door, b: Door) -> bool:
    """Whether what stands between two doorways joining the same two spaces is a thing, not a wall: a
    solid block (``FURNITURE_MIN_THICKNESS_M`` thick or more, as a counter or a desk block is, and no
    inner wall) standing free, no longer than the way between the two doorways. A room with two doors
    onto a corridor has a thin wall between them."""
    grid = analysis.grid
    res = grid.resolution_m
    # the thing's two ends are the doorways' jambs nearest each other; the line between them runs
    # along it (through it or along its face)
    (ax, ay), (bx, by) = min(((p, q) for p in a.jambs for q in b.jambs), key=lambda pq: math.dist(*pq))
    length = math.hypot(bx - ax, by - ay)
    if length < res:
        return False
    n = max(2, int(length / (res / 2)))
    xs, ys = np.linspace(ax, bx, n), np.linspace(ay, by, n)
    r_line, c_line = grid.world_to_index(xs, ys)
    reach = math.ceil(FURNITURE_LINE_SLACK_M / res)
    offsets = np.arange(-reach, reach + 1)
    rr = (r_line[:, None, None] + offsets[None, :, None]).repeat(len(offsets), axis=2).reshape(-1)
    cc = (c_line[:, None, None] + offsets[None, None, :]).repeat(len(offsets), axis=1).reshape(-1)
    ok = grid.in_bounds(rr, cc)
    occupied = grid.occupied
    hit = ok.copy()
    hit[ok] = occupied[rr[ok], cc[ok]]
    if not hit.any():
        return False
    # the block: the occupied cells joined to those on the line, in a window a little bigger than the way
    pad = math.ceil(FURNITURE_FREE_MARGIN_M / res)
    r0, r1 = max(int(rr[ok].min()) - pad, 0), min(int(rr[ok].max()) + pad + 1, grid.height)
    c0, c1 = max(int(cc[ok].min()) - pad, 0), min(int(cc[ok].max()) + pad + 1, grid.width)
    window = occupied[r0:r1, c0:c1]
    labels, _ = ndimage.label(window, structure=np.ones((3, 3), dtype=bool))
    on_line = set(np.unique(labels[rr[hit] - r0, cc[hit] - c0]).tolist()) - {0}
    # a lidar sees only a solid thing's faces: its inside, never scanned, is part of it
    block = ndimage.binary_fill_holes(np.isin(labels, list(on_line)))
    edge = np.zeros_like(block)
    edge[0, :] = edge[-1, :] = edge[:, 0] = edge[:, -1] = True
    if (block & edge).any():
        return False  # it runs on out of the window: part of the walls, not a thing standing free
    thickness_m = 2.0 * float(ndimage.distance_transform_edt(block).max()) * res
    return thickness_m >= FURNITURE_MIN_THICKNESS_M


def mostly_hallway(group: Sequence[Room]) -> bool:
    """Whether spaces a narrow gap joins (``gap_joined``) are one hallway to a person: a group is of the
    kind of its biggest part. A corridor's end cut off past a cart or a bin that narrows it is that
    corridor's part; a stage joined by a gap to the strip behind its flats stays a room."""
    return max(group, key=lambda r: r.area_m2).kind == ElementKind.HALLWAY


def hallway_parts(analysis: MapAnalysis, hall: Room) -> list[Room]:
    """The hallway as a person sees it: with the spaces narrow gaps join to it when the group is mostly
    hallway (``mostly_hallway``), else the hallway alone. Its first part is ``hall``."""
    group = gap_joined(analysis, hall)
    return group if mostly_hallway(group) else [hall]


def _space_for_ref(ref: ElementRef, analysis: MapAnalysis, pose: Pose) -> Room | None:
    """The space the words restrict to: 'of the biggest room', 'of the hallway', 'in this room', or None."""
    if ref.near is not None and ref.near.kind in (Kind.ROOM, Kind.HALLWAY) and ref.kind not in (Kind.ROOM, Kind.HALLWAY):
        space = select(landmark_ref(ref.near), analysis, pose)
        assert isinstance(space, Room)
        return space
    here = space_of(analysis, pose.xy)
    if ref.within is not None and ref.within in (Kind.ROOM, Kind.HALLWAY):
        want = ElementKind.HALLWAY if ref.within == Kind.HALLWAY else ElementKind.ROOM
        if here is not None and here.kind == want:
            return here
        spaces = [r for r in analysis.rooms if r.kind == want and len(r.cells_xy)]
        if not spaces:
            raise GroundingError(f"I see no {KIND_NOUN[ref.within][0]} in this map.")
        return min(spaces, key=lambda r: nearest_point(pose.xy, r.cells_xy)[0])
    if ref.in_current_room or (ref.kind == Kind.CORNER) or (ref.kind == Kind.WALL):
        if here is None:
            raise GroundingError("I cannot tell which room I am in: I seem to be outside every room of the map.")
        return here
    return None


def _in_space(e: Element, space: Room, analysis: MapAnalysis) -> bool:
    if isinstance(e, Door | NarrowPassage):
        if space.id in e.connects:
            return True
        return not e.connects and _near_space(e.center, space)
    if isinstance(e, Obstacle):
        if e.room is not None:
            return e.room == space.id
        return _near_space(e.centroid, space)
    if isinstance(e, Corner | Wall):
        if e.room is not None:
            return e.room == space.id
        return _near_space(reference_point(e), space)
    if isinstance(e, UnexploredArea):
        if len(e.frontier) == 0:
            return False
        rr, cc = analysis.grid.world_to_index(e.frontier[:, 0], e.frontier[:, 1])
        inside = analysis.grid.in_bounds(rr, cc)
        return bool(np.any(analysis.labels[rr[inside], cc[inside]] == space.label))
    if isinstance(e, Room):
        return e.id == space.id
    return False


def _near_space(p: Point, space: Room) -> bool:
    return len(space.cells_xy) > 0 and nearest_point(p, space.cells_xy)[0] <= IN_SPACE_M


# ------------------------------------------------------------------------------ measures
def distance_to(e: Element, xy: Point) -> float:
    """The README's distance from a point to an element's reference point."""
    if isinstance(e, Room):
        return nearest_point(xy, e.cells_xy)[0] if len(e.cells_xy) else math.dist(xy, e.centroid)
    if isinstance(e, Obstacle):
        return nearest_point(xy, e.cells_xy)[0] if len(e.cells_xy) else math.dist(xy, e.centroid)
    if isinstance(e, UnexploredArea):
        return nearest_point(xy, e.frontier)[0] if len(e.frontier) else math.dist(xy, e.centroid)
    if isinstance(e, Wall):
        return math.dist(xy, closest_on_segment(xy, e.start, e.end))
    return math.dist(xy, reference_point(e))


def side_point(e: Element, pose: Pose) -> Point:
    """The point whose side of the robot decides 'on your left' (the reference point)."""
    if isinstance(e, UnexploredArea) and len(e.frontier):
        return nearest_point(pose.xy, e.frontier)[1]
    if isinstance(e, Wall):
        return closest_on_segment(pose.xy, e.start, e.end)
    return reference_point(e)


def unscanned_part_m2(room: Room, analysis: MapAnalysis) -> float:
    """The floor of a room the map has not seen yet: the unexplored areas inside the building that
    open onto this room only, along more than a doorway's width (``params.door_max_width_m``). A
    room half scanned shows its unknown half across the whole room; an unscanned room behind a
    door shows it through the doorway only, and is a room of its own, not part of this one."""
    total = 0.0
    for u in analysis.unexplored:
        if not u.interior or len(u.frontier) == 0:
            continue
        f = np.asarray(u.frontier, dtype=float).reshape(-1, 2)
        rr, cc = analysis.grid.world_to_index(f[:, 0], f[:, 1])
        ok = analysis.grid.in_bounds(rr, cc)
        labels = analysis.labels[rr[ok], cc[ok]]
        labels = labels[labels > 0]
        if labels.size == 0 or bool(np.any(labels != room.label)):
            continue
        span = math.hypot(float(np.ptp(f[:, 0])), float(np.ptp(f[:, 1])))
        if span > analysis.params.door_max_width_m and not _counted_in(u, room, analysis):
            total += u.area_m2
    return total


def _counted_in(u: UnexploredArea, room: Room, analysis: MapAnalysis) -> bool:
    """The analysis already gave the area's unknown cells to the room (its ``area_m2`` counts them):
    most unknown cells next to the area's frontier carry the room's label."""
    grid = analysis.grid
    f = np.asarray(u.frontier, dtype=float).reshape(-1, 2)
    rr, cc = grid.world_to_index(f[:, 0], f[:, 1])
    near_r = (rr[:, None] + np.array([-1, -1, -1, 0, 0, 1, 1, 1])[None, :]).ravel()
    near_c = (cc[:, None] + np.array([-1, 0, 1, -1, 1, -1, 0, 1])[None, :]).ravel()
    ok = grid.in_bounds(near_r, near_c)
    near_r, near_c = near_r[ok], near_c[ok]
    unknown = grid.cells[near_r, near_c] == UNKNOWN
    if not np.any(unknown):
        return False
    return bool(np.mean(analysis.labels[near_r[unknown], near_c[unknown]] == room.label) > 0.5)


def floor_area_m2(e: Element, analysis: MapAnalysis) -> float:
    """"The biggest room": a room's floor area counting its unexplored cells (README), including the
    part not scanned yet (``unscanned_part_m2``); other elements by ``size_of``."""
    if isinstance(e, Room):
        return e.area_m2 + unscanned_part_m2(e, analysis)
    return size_of(e)


def size_of(e: Element) -> float:
    if isinstance(e, Room | Obstacle | UnexploredArea):
        return e.area_m2
    if isinstance(e, Door | NarrowPassage):
        return e.width_m
    if isinstance(e, Wall):
        return e.length_m
    return 0.0


def width_of(e: Element) -> float:
    if isinstance(e, Room | Door | NarrowPassage):
        return e.width_m
    if isinstance(e, Obstacle):
        return min(e.extent_m)
    return size_of(e)


def matches_side(e: Element, pose: Pose, side: Side) -> bool:
    p = side_point(e, pose)
    if side == Side.LEFT:
        return is_left(pose, p)
    if side == Side.RIGHT:
        return is_right(pose, p)
    if side == Side.AHEAD:
        return is_ahead(pose, p)
    return is_behind(pose, p)


def is_gap(d: Door, analysis: MapAnalysis) -> bool:
    """An opening narrower than any door (``NARROW_GAP_MAX_M``): a narrow gap, not a door; unless
    it is the only way into a room (``only_way_in``), which makes it that room's door."""
    return d.width_m < NARROW_GAP_MAX_M and not only_way_in(d, analysis)


def only_way_in(d: Door, analysis: MapAnalysis) -> bool:
    """A room that has no other opening is entered through this one: whatever its width, it is the
    room's door (a dressing room, a booth or a WC behind a 0.7 m door, narrower than today's codes
    ask but common in older and back-of-house buildings). A gap between shelves or in a partition
    parts a space that is entered some other way too."""
    rooms = {r.id for r in analysis.rooms}
    openings: list[Door | NarrowPassage] = [*analysis.doors, *analysis.narrow_passages]
    return any(space in rooms and sum(space in o.connects for o in openings) == 1 for space in d.connects)


def doors_of(analysis: MapAnalysis) -> list[Door]:
    """The doors a person counts: the analysis's doors without the narrow gaps and the ways round a
    thing standing in a room (``round_a_thing``), and the openings that are a room's only way in
    (``entrance_opening``)."""
    round_ends = {id(d) for d in round_a_thing(analysis)}
    return [*(d for d in analysis.doors if not is_gap(d, analysis) and id(d) not in round_ends),
            *(o for o in analysis.openings if entrance_opening(o, analysis))]


def entrance_opening(o: Door, analysis: MapAnalysis) -> bool:
    """An opening of a door's width that is the only way into a room is that room's door. The map
    analysis calls an opening a door only where the places on both sides are wider than it; a room
    whose floor narrows at once behind its doorway (an archive with its shelf aisle facing the door, a
    store with a rack row) fails that, yet a person enters the room through it and counts it with the
    corridor's doors. An opening into a room that has other ways in stays a way between two parts of
    a space (the end of a partition, the way past a cart): no door."""
    if not NARROW_GAP_MAX_M <= o.width_m <= analysis.params.door_max_width_m:
        return False
    everything: list[Door | NarrowPassage] = [*analysis.doors, *analysis.openings, *analysis.narrow_passages]
    ways = [w for w in everything if len(set(w.connects)) > 1]
    rooms = {r.id for r in analysis.rooms if r.kind == ElementKind.ROOM}
    return any(space in rooms and sum(space in w.connects for w in ways) == 1 for space in o.connects)


def things_standing_free(analysis: MapAnalysis) -> list[Obstacle]:
    """Things standing free on the floor that the analysis counted as wall structure because spaces
    meet round them (a desk block or a parked car between two parts of an open room): an occupied
    cluster that no wall runs into (scanned free floor all round it, THING_RING_FREE_MIN of its ring),
    solid (no floor inside it), as thick as furniture all through (``FURNITURE_MIN_THICKNESS_M``,
    ``THING_THICK_SHARE``; an inner wall is thinner) and not one of
    the analysis's obstacles. To a person in the room it is a thing in it, "the obstacle on the left",
    whatever line the analysis drew through it. Ids are ``thing_N``; the room is the one most of its
    ring lies in. Found once per analysis."""
    known = _THINGS.get(analysis)
    if known is not None:
        return list(known)
    grid = analysis.grid
    occupied = grid.occupied
    comp, n = ndimage.label(occupied, structure=np.ones((3, 3), dtype=bool))
    taken = np.zeros(n + 1, dtype=bool)
    for o in analysis.obstacles:
        pts = np.asarray(o.cells_xy, dtype=float).reshape(-1, 2)
        rr, cc = grid.world_to_index(pts[:, 0], pts[:, 1])
        ok = grid.in_bounds(rr, cc)
        taken[comp[rr[ok], cc[ok]]] = True
    sizes = np.bincount(comp.ravel(), minlength=n + 1)
    sizes[0] = 0
    if n:
        taken[int(np.argmax(sizes))] = True  # the building's walls
    by_label = {r.label: r.id for r in analysis.rooms}
    res = grid.resolution_m
    out: list[Obstacle] = []
    for k, sl in enumerate(ndimage.find_objects(comp), start=1):
        if sl is None or taken[k] or sizes[k] * grid.cell_area_m2 < analysis.params.obstacle_min_area_m2:
            continue
        r0, r1 = max(sl[0].start - 2, 0), min(sl[0].stop + 2, grid.height)
        c0, c1 = max(sl[1].start - 2, 0), min(sl[1].stop + 2, grid.width)
        if r0 == 0 or c0 == 0 or r1 == grid.height or c1 == grid.width:
            continue
        own = comp[r0:r1, c0:c1] == k
        block = ndimage.binary_fill_holes(own)
        if np.count_nonzero(block & ~own & (grid.cells[r0:r1, c0:c1] == FREE)) > THING_FLOOR_INSIDE_MAX:
            continue  # walls round a floor (a room inside a room, its door gaps parting it from the rest)
        ring = ndimage.binary_dilation(block, structure=np.ones((3, 3), dtype=bool)) & ~block
        free_ring = grid.cells[r0:r1, c0:c1][ring] == FREE
        if free_ring.mean() < THING_RING_FREE_MIN:
            continue
        # thick all through, as a desk or a car is: most of it stays when a disc as wide as furniture
        # is thick is rolled inside it (a run of thin walls, even with the unscanned inside of a thick
        # junction or two, does not)
        k_cells = max(1, round(FURNITURE_MIN_THICKNESS_M / 2 / res))
        yy, xx = np.ogrid[-k_cells:k_cells + 1, -k_cells:k_cells + 1]
        disc = xx * xx + yy * yy <= k_cells * k_cells
        thick = ndimage.binary_opening(np.pad(block, k_cells + 1), structure=disc)
        if np.count_nonzero(thick) < THING_THICK_SHARE * np.count_nonzero(block):
            continue
        rr, cc = np.nonzero(own)
        oxs, oys = grid.cell_to_world(rr + r0, cc + c0)
        br, bc = np.nonzero(block)
        bxs, bys = grid.cell_to_world(br + r0, bc + c0)
        ring_labels = analysis.labels[r0:r1, c0:c1][ring]
        ring_labels = ring_labels[ring_labels > 0]
        room = by_label.get(int(np.bincount(ring_labels).argmax())) if ring_labels.size else None
        out.append(Obstacle(f"thing_{len(out) + 1}", (float(bxs.mean()), float(bys.mean())),
                            float(len(bxs) * grid.cell_area_m2),
                            (float(bxs.max() - bxs.min()) + res, float(bys.max() - bys.min()) + res), room,
                            np.stack([oxs, oys], axis=1)))
    _THINGS[analysis] = tuple(out)
    return out


_THINGS: weakref.WeakKeyDictionary[MapAnalysis, tuple[Obstacle, ...]] = weakref.WeakKeyDictionary()


def elements_of_kind(analysis: MapAnalysis, kind: Kind) -> list[Element]:
    """The elements the noun of ``kind`` names: "doors" are the doors without the gaps narrower than
    any door, which are "narrow passages" (gaps) with the analysis's passages. A room's only way in
    narrower than that is both: its door, and a narrow gap one squeezes through."""
    if kind == Kind.DOOR:
        return list(doors_of(analysis))
    if kind == Kind.NARROW_PASSAGE:
        passages = list(analysis.narrow_passages)
        # a gap inside a passage the analysis found is that passage's pinch, not a second one;
        # a gap the analysis reads as no door (an opening: the way past a partition's end or a
        # cart) is squeezed through all the same
        gaps = [d for d in (*analysis.doors, *analysis.openings) if d.width_m < NARROW_GAP_MAX_M and not any(
            math.dist(d.center, closest_on_segment(d.center, p.ends[0], p.ends[1])) <= p.width_m for p in passages)]
        # and the gaps between two things standing free, where the analysis has none of its own
        between = [g for g in gaps_between_things(analysis) if not any(
            math.dist(g.center, closest_on_segment(g.center, p.ends[0], p.ends[1])) <= max(p.width_m, g.width_m)
            for p in passages) and not any(math.dist(g.center, d.center) <= max(d.width_m, g.width_m) for d in gaps)]
        return [*passages, *gaps, *between]
    if kind == Kind.ROOM:
        # a room parted by a gap narrower than any door is one room (``gap_joined``), whatever the
        # shape of its parts: a lab's strip between the door and a bench row is that lab's part, not a
        # hallway, when the lab is mostly room (``mostly_hallway``)
        return [r for r in analysis.rooms if r.kind == ElementKind.ROOM
                or not mostly_hallway(gap_joined(analysis, r))]
    if kind == Kind.HALLWAY:
        return [r for r in analysis.rooms if r.kind == ElementKind.HALLWAY]
    if kind == Kind.OBSTACLE:
        return [*analysis.obstacles, *things_standing_free(analysis)]
    if kind == Kind.CORNER:
        return list(analysis.corners)
    if kind == Kind.UNEXPLORED_AREA:
        return list(analysis.unexplored)
    if kind == Kind.WALL:
        return list(analysis.walls)
    return []


# ------------------------------------------------------------------------------ selection
def select(ref: ElementRef, analysis: MapAnalysis, pose: Pose, words: str = "",
           came_through: frozenset[str] = frozenset()) -> Element:
    """The one element the words mean. Raises GroundingError saying what the map has instead.
    ``words`` is the step's text, read only for the shape of an obstacle ("the box") and "gap".
    ``came_through``: the doors the robot has just walked through (``came_through_doors``), which
    are behind it, where it came from, not "the first door on your left"."""
    return select_many(ref, analysis, pose, 1, words, came_through)[0]


def in_sight(analysis: MapAnalysis, xy: Point, o: Obstacle, *, past_things: bool = False) -> bool:
    """Whether a straight line from ``xy`` reaches one of the thing's cells (``SIGHT_CELLS_TRIED``
    nearest) without crossing an occupied cell of the map before it (``SIGHT_END_SLACK_M``);
    ``past_things``: only walls hide it (a person sees a thing beyond another thing in the same room:
    over it, round it as they step aside), ``walls_only``."""
    cells = np.asarray(o.cells_xy, dtype=float).reshape(-1, 2)
    if not len(cells):
        return False
    grid = analysis.grid
    d = np.hypot(cells[:, 0] - xy[0], cells[:, 1] - xy[1])
    occupied = walls_only(analysis) if past_things else grid.occupied
    step_m = grid.resolution_m / 2
    for k in np.argsort(d)[:SIGHT_CELLS_TRIED]:
        length = float(d[k]) - SIGHT_END_SLACK_M
        if length <= 0:
            return True
        t = np.arange(0.0, length, step_m) / float(d[k])
        xs = xy[0] + t * (cells[k, 0] - xy[0])
        ys = xy[1] + t * (cells[k, 1] - xy[1])
        r, c = grid.world_to_index(xs, ys)
        inside = grid.in_bounds(r, c)
        if not occupied[r[inside], c[inside]].any():
            return True
    return False


def walls_only(analysis: MapAnalysis) -> BoolArray:
    """The occupied cells of the map without those of the obstacles and the things standing free
    (``things_standing_free``): what hides a thing from a person in a room. Once per analysis."""
    known = _WALLS_ONLY.get(analysis)
    if known is None:
        grid = analysis.grid
        known = grid.occupied.copy()
        for o in [*analysis.obstacles, *things_standing_free(analysis)]:
            pts = np.asarray(o.cells_xy, dtype=float).reshape(-1, 2)
            rr, cc = grid.world_to_index(pts[:, 0], pts[:, 1])
            ok = grid.in_bounds(rr, cc)
            known[rr[ok], cc[ok]] = False
        _WALLS_ONLY[analysis] = known
    return known


_WALLS_ONLY: weakref.WeakKeyDictionary[MapAnalysis, BoolArray] = weakref.WeakKeyDictionary()


def aspect_ratio(o: Obstacle) -> float:
    lo, hi = sorted(o.extent_m)
    return hi / lo if lo > 0 else math.inf


def shape_filter(pool: list[Element], words: str) -> list[Element]:
    """Obstacles of the shape a noun in ``words`` implies, when there are any; else ``pool``."""
    keep: list[Element]
    if _COMPACT_RE.search(words):
        keep = [e for e in pool if isinstance(e, Obstacle) and aspect_ratio(e) <= COMPACT_MAX_ASPECT]
    elif _LONG_RE.search(words):
        keep = [e for e in pool if isinstance(e, Obstacle) and aspect_ratio(e) >= LONG_MIN_ASPECT]
    else:
        return pool
    return keep or pool


def select_many(ref: ElementRef, analysis: MapAnalysis, pose: Pose, count: int, words: str = "",
                came_through: frozenset[str] = frozenset()) -> list[Element]:
    """``count`` elements the words mean, best first ("the two obstacles in this room").

    In steps, each a rule about what the words pick: an answer the words give directly (a label, a
    relation between spaces, a corner, "this room", "the gap"); the elements of the kind; those the
    words place by space (``_placed_by_space``), by side (``_placed_by_side``), by sight for things
    (``_things_in_sight``), by a landmark; the ones of the space the robot is in (``_of_this_space``);
    then ordered by the superlative or by distance (``_ordered``) and counted off (``_counted_off``)."""
    direct = _selected_directly(ref, analysis, pose, count, words)
    if direct is not None:
        return direct
    pool = _candidates(ref, analysis, pose)
    space = _space_for_ref(ref, analysis, pose)
    pool = _placed_by_space(ref, pool, analysis, pose, space)
    pool = _placed_by_side(ref, pool, pose, came_through)
    if ref.kind == Kind.OBSTACLE:
        pool = _things_in_sight(ref, pool, analysis, pose, count, words, space)
    by_landmark: dict[int, float] | None = None
    if ref.near is not None and not (ref.near.kind in (Kind.ROOM, Kind.HALLWAY) and space is not None):
        pool, by_landmark = _near_landmark(ref, pool, analysis, pose)
    rank = _local_rank(analysis, pose, space)
    pool = _of_this_space(ref, pool, analysis, pose, count, space, rank)
    ordered = _ordered(ref, pool, analysis, pose, rank, by_landmark)
    ordered = _at_the_end_if_said(ref, ordered, pose, space, words)
    return _counted_off(ref, ordered, count)


def _selected_directly(ref: ElementRef, analysis: MapAnalysis, pose: Pose, count: int,
                       words: str) -> list[Element] | None:
    """What the words name without a choice among the elements of a kind (None: choose): a name the
    user gave (here unknown: ask), a label on the map ("door 2"), a space by its relation to another
    ("the room across the hall"), a corner, "this room"; and "the gap" said of a door, which is a narrow
    passage when the map has one that matches the words."""
    if ref.name:
        raise GroundingError(
            f"I don't know a place called '{ref.name}'; name it first: stand there and say 'call this spot the "
            f"{ref.name}'. Or tell me where it is by what the map shows (e.g. 'the second door on your left').")
    if ref.kind == Kind.NONE:
        raise GroundingError("I don't know which place you mean; name a door, room, corner, wall or obstacle.")
    if ref.kind == Kind.WALL:
        raise GroundingError("internal: walls are selected with select_wall")  # pragma: no cover
    if ref.label is not None:
        if count != 1:
            raise GroundingError(f"{describe_ref(ref)} is one element; I cannot pick {count} of it.")
        return [select_by_label(ref.kind, ref.label, analysis)]
    if ref.relation is not None and ref.kind in (Kind.ROOM, Kind.HALLWAY):
        # relations imports this module
        from langnav.grounding.relations import select_related_spaces

        return select_related_spaces(ref, analysis, pose, count)
    if ref.kind == Kind.CORNER:
        return _corners(ref, analysis, pose, count)
    if ref.kind in (Kind.ROOM, Kind.HALLWAY) and ref.in_current_room and ref.superlative is None \
            and ref.ordinal is None and count == 1:
        here = space_of(analysis, pose.xy)
        if here is None:
            raise GroundingError("I cannot tell which room I am in: I seem to be outside every room.")
        return [here]
    if ref.kind == Kind.DOOR and words and _GAP_RE.search(words) and not _DOOR_RE.search(words):
        try:
            return select_many(ref.model_copy(update={"kind": Kind.NARROW_PASSAGE}), analysis, pose, count, words)
        except GroundingError:
            pass  # no gap matches the words: "the gap" is a doorway
    return None


def _corners(ref: ElementRef, analysis: MapAnalysis, pose: Pose, count: int) -> list[Element]:
    """The corner the words mean (``_select_corner``) and, for more than one, the nearest others of its
    space."""
    first = _select_corner(ref, analysis, pose)
    if count == 1:
        return [first]
    space = _space_for_ref(ref, analysis, pose)
    assert space is not None
    rest = sorted((c for c in analysis.corners if c is not first and _in_space(c, space, analysis)),
                  key=lambda c: math.dist(pose.xy, c.point))
    if len(rest) < count - 1:
        raise GroundingError(f"I see only {1 + len(rest)} corners here, so I cannot pick {count} of them.")
    return [first, *rest[:count - 1]]


def _candidates(ref: ElementRef, analysis: MapAnalysis, pose: Pose) -> list[Element]:
    """The elements of the kind the noun names; raises when the map has none."""
    pool = elements_of_kind(analysis, ref.kind)
    if ref.kind == Kind.NARROW_PASSAGE:
        # a gap between two things is the robot's to name only where it sees it: noise and furniture
        # leave hundreds such gaps on a real map, and one in another room is no "gap" a person in this
        # one points at (the doorway in front is) -- see _gap_in_sight. So is a passage the analysis
        # found no deeper than a doorway: a gap in a line of things (a rail, a line of screens)
        between = {id(g) for g in gaps_between_things(analysis)}
        between |= {id(p) for p in analysis.narrow_passages if p.length_m < analysis.params.door_max_depth_m}
        pool = [e for e in pool if id(e) not in between or _gap_in_sight(analysis, pose.xy, e)]
    if not pool:
        raise GroundingError(f"I see no {KIND_NOUN[ref.kind][1]} in this map.")
    return pool


def _placed_by_space(ref: ElementRef, pool: list[Element], analysis: MapAnalysis, pose: Pose,
                     space: Room | None) -> list[Element]:
    """The elements in the space the words name ("the door of this room"); for a space placed relative
    to the robot, another space than the one it stands in; for "the second room on your left" said in a
    hallway, the rooms that open onto it."""
    if space is not None and ref.kind not in (Kind.ROOM, Kind.HALLWAY):
        pool = [e for e in pool if _in_space(e, space, analysis)]
    if ref.kind in (Kind.ROOM, Kind.HALLWAY) and not ref.in_current_room and _relative_to_robot(ref):
        # "the room on the right", "the nearest room", "the second room on your left": words that place
        # a space relative to the robot mean another space than the one it stands in
        here_space = space_of(analysis, pose.xy)
        # (the parts of the room it stands in are that room: a gap narrower than a door does not end it)
        here_parts = {id(r) for r in gap_joined(analysis, here_space)} if here_space is not None else set()
        others = [e for e in pool if id(e) not in here_parts]
        if here_space is not None and len(others) < len(pool):
            pool = others
            if not pool:
                raise GroundingError(f"I see no {KIND_NOUN[ref.kind][0]} other than the one I am in.")
    if ref.kind == Kind.ROOM and ref.ordinal is not None and isinstance(here_space := space_of(analysis, pose.xy), Room) \
            and here_space.kind == ElementKind.HALLWAY:
        # "the second room on your left", said in a hallway, counts the rooms one passes along it: those
        # that open onto it (as its doors are counted), not a room behind one of them (reached through it)
        ways_out: list[Door | NarrowPassage] = [*analysis.doors, *analysis.narrow_passages]
        opening = {i for o in ways_out if here_space.id in o.connects for i in o.connects}
        if any(e.id in opening for e in pool):
            pool = [e for e in pool if e.id in opening]
    if ref.kind == Kind.ROOM and ref.superlative not in (Superlative.BIGGEST, Superlative.SMALLEST):
        pool = _one_part_each(pool, analysis, pose)
    return pool


def _one_part_each(pool: list[Element], analysis: MapAnalysis, pose: Pose) -> list[Element]:
    """Rooms once each: of the parts a gap narrower than any door joins into one room (``gap_joined``),
    the part one enters from here (``entered_part_key``; by size, ``_rooms_by_size`` counts them whole)."""
    best: dict[str, Element] = {}
    order = entered_part_key(analysis, pose)
    for e in pool:
        key = min(r.id for r in gap_joined(analysis, e)) if isinstance(e, Room) else e.id
        if key not in best or order(e) < order(best[key]):
            best[key] = e
    keep = {id(e) for e in best.values()}
    return [e for e in pool if id(e) in keep]


def doorways_from(analysis: MapAnalysis, xy: Point) -> dict[str, int]:
    """How many doorways (doors and wide openings, the analysis's ``graph``) one passes walking from the
    space holding ``xy`` into each space it can reach; the spaces it cannot reach are left out."""
    here = space_of(analysis, xy)
    if here is None:
        return {}
    graph = analysis.graph()
    hops = {here.id: 0}
    queue = collections.deque([here.id])
    while queue:
        cur = queue.popleft()
        for _, other in graph.get(cur, []):
            if other not in hops:
                hops[other] = hops[cur] + 1
                queue.append(other)
    return hops


def entered_part_key(analysis: MapAnalysis, pose: Pose) -> Callable[[Element], tuple[float, float]]:
    """Which part of a room a person means, smallest first: the part one enters from here, before the
    part nearest by a straight line. A room parted by a gap narrower than a door (``gap_joined``) is
    entered through one of its parts' doors: the library's shelf room, whose door is on the robot's
    corridor, is entered there, not at the strip behind it that lies nearer through a wall (that strip
    opens onto another room). So the part fewest doorways away (``doorways_from``), then the nearest."""
    hops = doorways_from(analysis, pose.xy)

    def key(e: Element) -> tuple[float, float]:
        return (float(hops.get(e.id, math.inf)), distance_to(e, pose.xy))
    return key


def _placed_by_side(ref: ElementRef, pool: list[Element], pose: Pose,
                    came_through: frozenset[str]) -> list[Element]:
    """The elements on the side the words say; "on your left / right" never the door just come through
    (``came_through_doors``); "behind you on the left": both sides hold."""
    if ref.side is not None:
        pool = [e for e in pool if matches_side(e, pose, ref.side)]
        if came_through and ref.side in (Side.LEFT, Side.RIGHT):
            pool = [e for e in pool if e.id not in came_through]
    if ref.also_side is not None:
        pool = [e for e in pool if matches_side(e, pose, ref.also_side)]
    return pool


def _things_in_sight(ref: ElementRef, pool: list[Element], analysis: MapAnalysis, pose: Pose, count: int,
                     words: str, space: Room | None) -> list[Element]:
    """Obstacles of the shape the noun implies, and, where no space is named, the ones the robot sees:
    the nearest ones and the ones on a side are things a person standing there sees."""
    if words:
        pool = shape_filter(pool, words)
    if ref.side is None and ref.superlative == Superlative.NEAREST and space is None and ref.near is None:
        # "the two nearest obstacles" are things the robot sees from where it stands, not one nearer
        # by a straight line through a wall in the next room (when too few are in sight: all of them)
        wanted = (ref.ordinal or 1) + count - 1
        seen_near: list[Element] = []
        for e in sorted(pool, key=lambda e: distance_to(e, pose.xy)):
            if len(seen_near) >= wanted:
                break
            if isinstance(e, Obstacle) and in_sight(analysis, pose.xy, e, past_things=True):
                seen_near.append(e)
        if len(seen_near) >= wanted:
            pool = seen_near
    if ref.side is not None and space is None and ref.near is None:
        # "the obstacle on your right" places a thing by where the robot sees it: one behind a wall, in
        # another room, is not on its right to a person standing there (ask rather than drive to it).
        # Only walls hide it: a plant beyond a bench row in the same room is seen over the benches, or
        # round them as one steps aside (as for "the nearest obstacles")
        seen: list[Element] = []
        # nearest first; when only the nearest ones can be meant, the farther ones need no look
        wanted = ((ref.ordinal or 1) + count - 1 if ref.superlative in (None, Superlative.NEAREST)
                  else len(pool))
        for e in sorted(pool, key=lambda e: distance_to(e, pose.xy)):
            if len(seen) >= wanted:
                break
            if isinstance(e, Obstacle) and in_sight(analysis, pose.xy, e, past_things=True):
                seen.append(e)
        if not seen and pool:
            raise GroundingError(f"I see no {KIND_NOUN[ref.kind][0]}{_where(ref)} from here: the nearest such "
                                 "thing is behind a wall. Which one do you mean?")
        pool = seen
    return pool


@dataclass(frozen=True)
class _LocalRank:
    """Doors and passages of the space the robot is in (``here``, with the parts a gap narrower than any
    door joins to it: ``here_group``) come before the others (0, else 1), unless the words name a space
    (``space``); every other element ranks 0."""

    analysis: MapAnalysis
    here: Room | None
    here_group: tuple[Room, ...]
    space: Room | None

    def __call__(self, e: Element) -> int:
        if self.here is None or self.space is not None or not isinstance(e, Door | NarrowPassage):
            return 0
        return 0 if any(_in_space(e, s, self.analysis) for s in self.here_group) else 1


def _doors_in_sight(ref: ElementRef, pool: list[Element], analysis: MapAnalysis, pose: Pose) -> list[Element]:
    """Doors picked by side or alone ("the last doorway on your left", "the door") in a space with no
    door of its own (a corridor whose ways out are all wide openings): a person means a door both can
    see, never one between two other rooms tens of metres away; ask when none is in sight (an ordinal
    counts only the space's own doors, so it asks there already: ``_of_this_space``). A door picked
    by name, by a landmark, as passed or as the nearest one says itself which it is. With none in
    sight, ``_counted_off`` says so and asks."""
    if ref.label is not None or ref.relation is not None or ref.near is not None or ref.passed \
            or ref.superlative not in (None, Superlative.FARTHEST):
        return pool
    return [e for e in pool if _gap_in_sight(analysis, pose.xy, e)]


def _local_rank(analysis: MapAnalysis, pose: Pose, space: Room | None) -> _LocalRank:
    here = space_of(analysis, pose.xy)
    return _LocalRank(analysis, here, tuple(gap_joined(analysis, here)) if here is not None else (), space)


def _of_this_space(ref: ElementRef, pool: list[Element], analysis: MapAnalysis, pose: Pose, count: int,
                   space: Room | None, rank: _LocalRank) -> list[Element]:
    """"The door" of the space the robot is in (one, the one it faces, or ask: ``_one_door_or_ask``);
    "the obstacle" of a room with one; "the fourth door on your left" counted among the doors of the
    space the robot is in."""
    here_group = list(rank.here_group)
    if ref.kind == Kind.DOOR and ref.ordinal is None and space is None and rank.here is not None \
            and not any(rank(e) == 0 for e in elements_of_kind(analysis, Kind.DOOR)):
        pool = _doors_in_sight(ref, pool, analysis, pose)
    if ref.kind == Kind.DOOR and count == 1 and _plain(ref):
        _one_door_or_ask(pool, [space] if space is not None else here_group, analysis, pose)
    if ref.kind == Kind.OBSTACLE and count == 1 and _plain(ref) and space is None and here_group:
        # "the obstacle" said in a room with one obstacle is that one (the one thing of that kind both
        # can see), even when another room's obstacle through a door is nearer
        own = [e for e in pool if any(_in_space(e, s, analysis) for s in here_group)]
        if len(own) == 1:
            pool = own
    if ref.ordinal is not None and ref.kind in (Kind.DOOR, Kind.NARROW_PASSAGE) and rank.here is not None \
            and space is None and (ref.kind == Kind.DOOR
                                   or any(rank(e) == 0 for e in elements_of_kind(analysis, ref.kind))):
        # "the fourth door on your left" counts the doors of the space the robot is in (README): with
        # three of them on that side there is no fourth, whatever doors of other rooms it could see. A
        # space with no door of its own has no first, second or third door either: counting the doors
        # between two other rooms instead sends the robot to a door anywhere in the building (a corridor
        # whose ways out are all open fronts: "the third doorway behind you" 68 m away), so the count comes
        # up short and the robot asks. (Passages are not a space's own in that way: the first narrow
        # passage ahead may be in the next space.)
        pool = [e for e in pool if rank(e) == 0]
    return pool


def _ordered(ref: ElementRef, pool: list[Element], analysis: MapAnalysis, pose: Pose, rank: _LocalRank,
             by_landmark: dict[int, float] | None) -> list[Element]:
    """The elements best first: by size or width for those superlatives, farthest first, nearest the
    landmark ("the door next to the box"), else nearest first (the space's own doors first, ``rank``)."""
    sup = ref.superlative
    if sup in (Superlative.BIGGEST, Superlative.SMALLEST) and ref.kind == Kind.ROOM:
        return _rooms_by_size(pool, analysis, pose, biggest=sup == Superlative.BIGGEST)
    if sup in (Superlative.BIGGEST, Superlative.SMALLEST):
        return sorted(pool, key=lambda e: floor_area_m2(e, analysis), reverse=sup == Superlative.BIGGEST)
    if sup in (Superlative.WIDEST, Superlative.NARROWEST):
        return sorted(pool, key=width_of, reverse=sup == Superlative.WIDEST)
    if sup == Superlative.FARTHEST:
        return sorted(pool, key=lambda e: (rank(e), -distance_to(e, pose.xy)))
    if by_landmark is not None and sup is None and ref.ordinal is None:
        return sorted(pool, key=lambda e: by_landmark[id(e)])  # "the door next to the box": nearest to it
    return sorted(pool, key=lambda e: (rank(e), distance_to(e, pose.xy)))


def _at_the_end_if_said(ref: ElementRef, ordered: list[Element], pose: Pose, space: Room | None,
                        words: str) -> list[Element]:
    """"The last door at the end of the corridor": only the doors at its end (``_at_the_end``); ask when
    there is none there."""
    if ref.kind == Kind.DOOR and ref.superlative == Superlative.FARTHEST and space is not None \
            and space.kind == ElementKind.HALLWAY and words and _END_RE.search(words):
        ordered = [e for e in ordered if _at_the_end(e, space, pose)]
        if not ordered:
            raise GroundingError(f"I see no door at the end of {label_of(space)}: its doors are along its sides. "
                                 "Which door do you mean? Say e.g. 'the last door on your left'.")
    return ordered


def _counted_off(ref: ElementRef, ordered: list[Element], count: int) -> list[Element]:
    """The ``count`` elements from the ordinal on ("the second and third"); says how many there are
    when there are too few."""
    k = (ref.ordinal or 1) - 1
    if len(ordered) < k + count:
        if not ordered:
            raise GroundingError(f"I see no {KIND_NOUN[ref.kind][0]}{_where(ref)}, so I cannot find "
                                 f"{describe_ref(ref)}.")
        raise GroundingError(f"I see only {_count_phrase(len(ordered), ref)}, so I cannot find "
                             f"{describe_ref(ref) if count == 1 else f'{count} of them'}.")
    return ordered[k:k + count]


def gaps_between_things(analysis: MapAnalysis) -> list[NarrowPassage]:
    """The narrow gaps between two things standing free (``GAP_FACE_M``), as passages: the way between
    the nearest points of the two things, wider than the robot and narrower than a passage, with no
    occupied or unknown cell on it (so no wall between them, whatever spaces the analysis put them
    in); its ends are where the two things' facing sides end."""
    cached = _GAPS.get(analysis)
    if cached is not None:
        return list(cached)
    params = analysis.params
    lo, hi = 2 * params.robot_radius_m, params.passage_max_width_m
    things = [o for o in [*analysis.obstacles, *things_standing_free(analysis)] if len(o.cells_xy)]
    trees = [cKDTree(np.asarray(o.cells_xy, dtype=float).reshape(-1, 2)) for o in things]
    # only pairs whose bounding boxes come within a passage's width can have a gap between them (a
    # real map has hundreds of things: the boxes keep the look-up to the few that stand close)
    boxes = np.array([[*t.mins, *t.maxes] for t in trees]).reshape(-1, 4)
    gx = np.maximum(0.0, np.maximum(boxes[:, None, 0] - boxes[None, :, 2], boxes[None, :, 0] - boxes[:, None, 2]))
    gy = np.maximum(0.0, np.maximum(boxes[:, None, 1] - boxes[None, :, 3], boxes[None, :, 1] - boxes[:, None, 3]))
    near = np.hypot(gx, gy) <= hi + analysis.grid.resolution_m
    out: list[NarrowPassage] = []
    for (i, a), (j, b) in itertools.combinations(enumerate(things), 2):
        if not near[i, j]:
            continue
        ca = np.asarray(a.cells_xy, dtype=float).reshape(-1, 2)
        d, k = trees[j].query(ca, distance_upper_bound=hi + analysis.grid.resolution_m)
        if not np.isfinite(d).any():
            continue
        ia = int(np.argmin(d))
        p, q = ca[ia], np.asarray(b.cells_xy, dtype=float).reshape(-1, 2)[int(k[ia])]
        # cell centres: the clear width is one cell less than the distance between them
        width = float(d[ia]) - analysis.grid.resolution_m
        if not lo <= width <= hi or not _open_between(analysis, (float(p[0]), float(p[1])), (float(q[0]), float(q[1]))):
            continue
        across = unit((float(q[0] - p[0]), float(q[1] - p[1])))
        axis = (-across[1], across[0])
        centre = ((float(p[0]) + float(q[0])) / 2, (float(p[1]) + float(q[1])) / 2)
        spans = []
        for cells, end in ((ca, p), (np.asarray(b.cells_xy, dtype=float).reshape(-1, 2), q)):
            face = cells[np.abs((cells - end) @ np.asarray(across)) <= GAP_FACE_M]
            t = (face - np.asarray(centre)) @ np.asarray(axis)
            spans.append((float(t.min()), float(t.max())))
        t0, t1 = max(spans[0][0], spans[1][0]), min(spans[0][1], spans[1][1])
        if t1 - t0 < 2 * GAP_MIN_HALF_DEPTH_M:
            mid = (t0 + t1) / 2 if t1 >= t0 else 0.0
            t0, t1 = mid - GAP_MIN_HALF_DEPTH_M, mid + GAP_MIN_HALF_DEPTH_M
        ends = ((centre[0] + axis[0] * t0, centre[1] + axis[1] * t0), (centre[0] + axis[0] * t1, centre[1] + axis[1] * t1))
        centre = ((ends[0][0] + ends[1][0]) / 2, (ends[0][1] + ends[1][1]) / 2)
        rooms = tuple(dict.fromkeys(r for r in (a.room, b.room) if r is not None))
        out.append(NarrowPassage(f"the gap between {a.id} and {b.id}", centre, width, t1 - t0, ends, rooms))
    _GAPS[analysis] = tuple(out)
    return out


_GAPS: weakref.WeakKeyDictionary[MapAnalysis, tuple[NarrowPassage, ...]] = weakref.WeakKeyDictionary()


def _line_cells(grid: OccupancyGrid, p: Point, q: Point) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.int64]]:
    """The cells under the straight line from ``p`` to ``q``, both ends included, sampled every half cell
    (so no cell the line crosses is skipped); row and column indices, not checked against the bounds."""
    n = max(2, math.ceil(math.dist(p, q) / (grid.resolution_m / 2)))
    ts = np.linspace(0.0, 1.0, n + 1)
    return grid.world_to_index(p[0] + (q[0] - p[0]) * ts, p[1] + (q[1] - p[1]) * ts)


def _gap_in_sight(analysis: MapAnalysis, xy: Point, gap: Element) -> bool:
    """Whether the straight line from the robot to the middle of a gap between two things crosses no
    wall (``walls_only``: things do not hide it, a person sees past them) and stays on known cells: the
    gap is in the robot's sight, not behind a wall in another room."""
    grid = analysis.grid
    rr, cc = _line_cells(grid, xy, reference_point(gap))
    inside = grid.in_bounds(rr, cc)
    if not inside.all():
        return False
    return not walls_only(analysis)[rr, cc].any() and not np.any(grid.cells[rr, cc] == UNKNOWN)


def _open_between(analysis: MapAnalysis, p: Point, q: Point) -> bool:
    """No occupied or unknown cell on the straight way between two things' nearest cells (their own
    two cells apart): the gap is open floor, not a wall or a third thing."""
    grid = analysis.grid
    rr, cc = _line_cells(grid, p, q)
    rr, cc = rr[1:-1], cc[1:-1]  # the two things' own cells are the ends
    (pr, pc), (qr, qc) = grid.world_to_index(p[0], p[1]), grid.world_to_index(q[0], q[1])
    inside = grid.in_bounds(rr, cc) & ~((rr == pr) & (cc == pc)) & ~((rr == qr) & (cc == qc))
    return bool(inside.any()) and bool(np.all(grid.cells[rr[inside], cc[inside]] == FREE))


def _at_the_end(e: Element, hall: Room, pose: Pose) -> bool:
    """"The door at the end of the corridor": a door in the end wall of the hallway as it runs where
    the robot is, at the end the robot faces (either end when it faces across), or in a side wall
    within one hallway width of that end; not the last of the doors along its sides when the end
    wall is plain, nor a door at the end of another leg of the hallway."""
    from langnav.grounding.relations import hall_axis  # relations imports this module

    centre, axis = hall_axis(hall, pose.xy)
    c, a = np.asarray(centre), np.asarray(axis)
    cells = np.asarray(hall.cells_xy, float).reshape(-1, 2) - c
    across = np.abs(cells[:, 0] * -a[1] + cells[:, 1] * a[0])
    t = (cells @ a)[across <= hall.width_m]
    p = np.asarray(reference_point(e)) - c
    if t.size == 0 or abs(float(p[0] * -a[1] + p[1] * a[0])) > hall.width_m:
        return False
    t_door = float(p @ a)
    facing = math.cos(pose.yaw_rad) * a[0] + math.sin(pose.yaw_rad) * a[1]
    far = t_door >= float(t.max()) - hall.width_m
    near = t_door <= float(t.min()) + hall.width_m
    if abs(facing) < FACING_ALONG_MIN:
        return bool(far or near)
    return bool(far if facing > 0 else near)


def _rooms_by_size(pool: list[Element], analysis: MapAnalysis, pose: Pose, *, biggest: bool) -> list[Element]:
    """Rooms from biggest (or smallest) on, a room parted by a gap narrower than any door counted
    whole (``gap_joined``: a lab split by two benches with a 0.7 m gap between them is one lab, as
    big as both parts). Each room once, by the part of it one enters from here (``entered_part_key``).
    Parts that are mostly hallway (a corridor's end past a cart that narrows it) are no room."""
    order = entered_part_key(analysis, pose)
    area: dict[str, float] = {}
    part: dict[str, Element] = {}
    for e in pool:
        if not isinstance(e, Room):
            continue
        group = gap_joined(analysis, e)
        if mostly_hallway(group):
            continue
        key = min(r.id for r in group)
        area[key] = sum(floor_area_m2(r, analysis) for r in group)
        if key not in part or order(e) < order(part[key]):
            part[key] = e
    keys = sorted(area, key=lambda k: area[k], reverse=biggest)
    return [part[k] for k in keys]


def came_through_doors(analysis: MapAnalysis, pose: Pose, last_leg: tuple[Point, Point] | None) -> frozenset[str]:
    """The doors whose opening the robot's last leg of way crossed and that are now behind it (beyond
    +-120 deg): the door it just stepped out of. One does not call the door one has just come
    through "the first door on your left": it is where one came from."""
    if last_leg is None or math.dist(*last_leg) < 1e-6:
        return frozenset()
    a, b = last_leg
    out: set[str] = set()
    for d in analysis.doors:
        if _segments_cross(a, b, d.jambs[0], d.jambs[1]) and is_behind(pose, d.center):
            out.add(d.id)
    return frozenset(out)


def _segments_cross(a: Point, b: Point, c: Point, d: Point) -> bool:
    def orient(p: Point, q: Point, r: Point) -> float:
        return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])
    o1, o2, o3, o4 = orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b)
    return o1 * o2 < 0 and o3 * o4 < 0


def _plain(ref: ElementRef) -> bool:
    """Words that pick no element among several of a kind: "the door", "the door of this room"."""
    return (ref.ordinal is None and ref.side is None and ref.superlative is None and ref.near is None
            and ref.label is None and ref.relation is None and not ref.passed and ref.name is None)


def _one_door_or_ask(pool: list[Element], spaces: list[Room], analysis: MapAnalysis, pose: Pose) -> None:
    """"The door" of a room with one door is that door; of a room with several it could be any of
    them, so ask (naming them as the map shows them, with where each is) instead of guessing. A
    space with no door of its own has no "the door" either: the words take for granted the door of
    the place where both stand, and any door seen from it (``pool``: the doors in sight) is another
    space's, one of several or far off (a corridor whose ways out are all open fronts, with one door
    in sight at its far end 74 m away). Which one, or whether one of the open ways out was meant, is
    the person's to say: ask, naming the doors in sight nearest first (none in sight: ``_counted_off``
    says so)."""
    if not spaces:
        return
    own = [e for e in pool if any(_in_space(e, s, analysis) for s in spaces)]
    if not own and pool:
        seen = sorted(pool, key=lambda e: distance_to(e, pose.xy))[:MAX_DOORS_NAMED]
        names = ", ".join(f"{label_of(e)} ({_where_is(e, pose)}, {distance_to(e, pose.xy):.1f} m)" for e in seen)
        raise GroundingError(f"{label_of(spaces[0]).capitalize()} has no door of its own; the door"
                             f"{'s' if len(seen) > 1 else ''} I see from here: {names}. Which door do you mean? "
                             f"Say e.g. '{label_of(seen[0])}'.")
    if len(own) <= 1:
        if own:
            pool[:] = own
        return
    faced = [e for e in own if isinstance(e, Door) and _heading_crosses(pose, e.jambs)]
    if len(faced) == 1:
        pool[:] = faced  # the robot looks straight through one of them: "the door" is the one it faces
        return
    own.sort(key=lambda e: distance_to(e, pose.xy))
    where = " ".join(spaces[0].id.split("_"))
    names = ", ".join(f"{label_of(e)} ({_where_is(e, pose)}, {distance_to(e, pose.xy):.1f} m)" for e in own[:-1])
    last = own[-1]
    raise GroundingError(f"{where.capitalize()} has {NUMBER_WORDS.get(len(own), str(len(own)))} doors: {names} and "
                         f"{label_of(last)} ({_where_is(last, pose)}, {distance_to(last, pose.xy):.1f} m). Which "
                         f"one do you mean? Say e.g. 'the door on your left' or '{label_of(own[0])}'.")


def _heading_crosses(pose: Pose, seg: tuple[Point, Point]) -> bool:
    """The robot's heading line, ahead of it, passes through the segment (a door's opening)."""
    (ax, ay), (bx, by) = seg
    hx, hy = pose.heading()
    ex, ey = bx - ax, by - ay
    den = hx * ey - hy * ex
    if abs(den) < 1e-9:
        return False
    wx, wy = ax - pose.x_m, ay - pose.y_m
    t = (wx * ey - wy * ex) / den  # along the heading
    u = (wx * hy - wy * hx) / den  # along the segment
    return t > 0 and 0.0 <= u <= 1.0


def _where_is(e: Element, pose: Pose) -> str:
    p = side_point(e, pose)
    if is_ahead(pose, p):
        return "ahead"
    if is_behind(pose, p):
        return "behind me"
    return "on my left" if is_left(pose, p) else "on my right"


def _relative_to_robot(ref: ElementRef) -> bool:
    """Words that place an element relative to the robot: a side, an order, nearest / farthest."""
    return ref.side is not None or ref.ordinal is not None or ref.superlative in (Superlative.NEAREST,
                                                                                 Superlative.FARTHEST)


def label_of(e: Element | str) -> str:
    """The label the map picture and the web app show: the element id with '_' as a space."""
    return (e if isinstance(e, str) else e.id).replace("_", " ")


def _label_number(element_id: str) -> int | None:
    m = re.fullmatch(r"[a-z_]+?_(\d+)", element_id)
    return int(m.group(1)) if m else None


def select_by_label(kind: Kind, label: int, analysis: MapAnalysis) -> Element:
    """The element whose label (id) is that kind and number: "door 2" is door_2. Rooms and hallways
    are numbered together, so "room 3" may name hallway_3 when no room has that number."""
    kinds = [kind]
    if kind == Kind.ROOM:
        kinds.append(Kind.HALLWAY)
    elif kind == Kind.HALLWAY:
        kinds.append(Kind.ROOM)
    for k in kinds:
        for e in _labelled(analysis, k):
            if _label_number(e.id) == label:
                return e
    pool = _labelled(analysis, kind)
    noun = LABEL_NOUN.get(kind, KIND_NOUN[kind][0])
    if not pool:
        raise GroundingError(f"I see no {noun} {label} on the map: it has no {KIND_NOUN[kind][1]}.")
    shown = sorted(pool, key=lambda e: (_label_number(e.id) or 0))
    names = ", ".join(label_of(e) for e in shown[:12]) + (" ..." if len(shown) > 12 else "")
    raise GroundingError(f"I see no {noun} {label} on the map; its {KIND_NOUN[kind][1]} are {names}.")


def _labelled(analysis: MapAnalysis, kind: Kind) -> list[Element]:
    """The elements the picture labels with the noun of ``kind``: "door 9" is door_9 even when it is
    a gap narrower than any door."""
    if kind == Kind.DOOR:
        return list(analysis.doors)
    if kind == Kind.NARROW_PASSAGE:
        return list(analysis.narrow_passages)
    if kind == Kind.OBSTACLE:
        return list(analysis.obstacles)  # things standing free have no label on the picture
    return elements_of_kind(analysis, kind)


def _near_landmark(ref: ElementRef, pool: list[Element], analysis: MapAnalysis,
                   pose: Pose) -> tuple[list[Element], dict[int, float]]:
    """The elements of ``pool`` next to (or, for spaces, opening onto) the landmark, with their
    distances to it."""
    assert ref.near is not None
    mark = select(landmark_ref(ref.near), analysis, pose)
    dist: dict[int, float] = {}
    keep: list[Element] = []
    for e in pool:
        if e is mark:
            continue
        if isinstance(mark, Room) and isinstance(e, Room):
            # "the room at the end of the hallway": a room a door joins to it
            openings: list[Door | NarrowPassage] = [*analysis.doors, *analysis.narrow_passages]
            joined = any({mark.id, e.id} <= set(d.connects) for d in openings)
            d = 0.0 if joined else _gap(e, mark)
        elif isinstance(mark, Room):
            d = 0.0 if _in_space(e, mark, analysis) else _gap(e, mark)
        else:
            d = _gap(e, mark)
        if d <= NEAR_MAX_M:
            keep.append(e)
            dist[id(e)] = d
    if not keep:
        raise GroundingError(f"I see no {KIND_NOUN[ref.kind][0]} near {describe_ref(landmark_ref(ref.near))}.")
    return keep, dist


def _cells(e: Element) -> np.ndarray:
    if isinstance(e, Room | Obstacle) and len(e.cells_xy):
        return np.asarray(e.cells_xy, dtype=float).reshape(-1, 2)
    if isinstance(e, UnexploredArea) and len(e.frontier):
        return np.asarray(e.frontier, dtype=float).reshape(-1, 2)
    return np.asarray([reference_point(e)], dtype=float)


def _gap(a: Element, b: Element) -> float:
    """Distance between two elements: their nearest cells (reference points for doors, corners)."""
    pa, pb = _cells(a), _cells(b)
    if len(pa) > len(pb):
        pa, pb = pb, pa
    d, _ = cKDTree(pb).query(pa, k=1)
    return float(np.min(d))


def _where(ref: ElementRef) -> str:
    s = ""
    if ref.side is not None:
        s += " " + SIDE_WORDS[ref.side]
    if ref.within is not None:
        s += f" in the {KIND_NOUN[ref.within][0]}"
    elif ref.in_current_room:
        s += " in this room"
    return s


def _select_corner(ref: ElementRef, analysis: MapAnalysis, pose: Pose) -> Corner:
    space = _space_for_ref(ref, analysis, pose)
    assert space is not None
    # the robot's room is the whole of it, parts a narrow gap joins included (``gap_joined``)
    spaces = gap_joined(analysis, space) if space is space_of(analysis, pose.xy) else [space]
    corners = [c for c in analysis.corners if any(_in_space(c, s, analysis) for s in spaces)]
    room_word = "hallway" if space.kind == ElementKind.HALLWAY else "room"
    if not corners:
        raise GroundingError(f"I found no corners in this {room_word}.")
    by_landmark: dict[int, float] | None = None
    if ref.near is not None and ref.near.kind not in (Kind.ROOM, Kind.HALLWAY):
        pool: list[Element] = list(corners)
        _, by_landmark = _near_landmark(ref, pool, analysis, pose)
        corners = [c for c in corners if id(c) in by_landmark]
    side = ref.side
    if side in (Side.LEFT, Side.RIGHT):
        ahead = [c for c in corners if is_ahead(pose, c.point)]
        if not ahead:  # nothing within +-60 deg: take the front half
            ahead = [c for c in corners if abs(math.degrees(bearing_rad(pose, c.point))) < 90.0]
        if not ahead:
            raise GroundingError(f"No corner of this {room_word} is in front of me; turn towards the "
                                 f"corners you mean, or say 'the nearest corner'.")
        sign = 1.0 if side == Side.LEFT else -1.0
        # "the left corner" is on the left: of the corners ahead the one farthest that way, but never
        # one on the other side (a room whose corner that way is not seen, e.g. a wall stub missing)
        sided = [c for c in ahead if sign * lateral_offset(pose, c.point) > 0.0]
        if not sided:
            sided = [c for c in corners if sign * lateral_offset(pose, c.point) > 0.0
                     and abs(math.degrees(bearing_rad(pose, c.point))) < 90.0]
        if not sided:
            raise GroundingError(f"I see no corner of this {room_word} in front of me on your {side.value}; "
                                 f"which corner do you mean?")
        ahead = sided
        best_lat = max(sign * lateral_offset(pose, c.point) for c in ahead)
        tied = [c for c in ahead if sign * lateral_offset(pose, c.point) >= best_lat - CORNER_SIDE_TIE_M]
        # among corners equally far to that side, the room's far corner (not a door jamb on the way)
        return max(tied, key=lambda c: math.dist(pose.xy, c.point))
    if side == Side.AHEAD:
        corners = [c for c in corners if is_ahead(pose, c.point)]
    elif side == Side.BEHIND:
        corners = [c for c in corners if is_behind(pose, c.point)]
    if not corners:
        raise GroundingError(f"I see no corner of this {room_word} {SIDE_WORDS[side] if side else ''}.".strip())
    far = ref.superlative == Superlative.FARTHEST
    if by_landmark is not None and ref.superlative is None and ref.ordinal is None:
        return min(corners, key=lambda c: by_landmark[id(c)])  # "the corner next to the door"
    ordered = sorted(corners, key=lambda c: math.dist(pose.xy, c.point), reverse=far)
    k = (ref.ordinal or 1) - 1
    if k >= len(ordered):
        raise GroundingError(f"This {room_word} has only {NUMBER_WORDS.get(len(ordered), len(ordered))} "
                             f"corners{_where(ref)}.")
    return ordered[k]


def select_pair(first: ElementRef, second: ElementRef | None, analysis: MapAnalysis,
                pose: Pose, words: str = "") -> tuple[Element, Element]:
    """The two elements of 'between A and B' (or 'between the two obstacles')."""
    if second is None:
        a, b = select_many(first, analysis, pose, 2, words)
        return a, b
    a = select(first, analysis, pose, words)
    if second == first or (second.kind == first.kind and second.ordinal is None and second.superlative is None
                           and second.side is None):
        others = [e for e in select_many(second, analysis, pose, 2, words) if e is not a]
        return a, others[0]
    b = select(second, analysis, pose, words)
    if a is b:
        raise GroundingError(f"{describe_ref(first)} and {describe_ref(second)} are the same place; "
                             "'between' needs two different ones.")
    return a, b


# ------------------------------------------------------------------------------ walls
def wall_lines(walls: Sequence[Wall]) -> list[WallLine]:
    """Join collinear wall segments facing the same way (a wall split by doorways is one wall)."""
    groups: list[list[Wall]] = []
    for w in sorted(walls, key=lambda w: -w.length_m):
        if w.length_m == 0:
            continue
        placed = False
        for g in groups:
            if _collinear(g[0], w):
                g.append(w)
                placed = True
                break
        if not placed:
            groups.append([w])
    lines: list[WallLine] = []
    for g in groups:
        base = g[0]
        d = ((base.end[0] - base.start[0]) / base.length_m, (base.end[1] - base.start[1]) / base.length_m)
        ts = [t for w in g for t in (_proj(w.start, base.start, d), _proj(w.end, base.start, d))]
        lo, hi = min(ts), max(ts)
        start = (base.start[0] + d[0] * lo, base.start[1] + d[1] * lo)
        end = (base.start[0] + d[0] * hi, base.start[1] + d[1] * hi)
        lines.append(WallLine(tuple(w.id for w in g), start, end, base.inward, base.room))
    return lines


def _proj(p: Point, o: Point, d: Point) -> float:
    return (p[0] - o[0]) * d[0] + (p[1] - o[1]) * d[1]


def _collinear(a: Wall, b: Wall) -> bool:
    da = math.atan2(a.end[1] - a.start[1], a.end[0] - a.start[0])
    db = math.atan2(b.end[1] - b.start[1], b.end[0] - b.start[0])
    diff = abs(math.degrees(da - db)) % 180.0
    if min(diff, 180.0 - diff) > WALL_MERGE_ANGLE_DEG:
        return False
    if a.inward[0] * b.inward[0] + a.inward[1] * b.inward[1] <= 0:
        return False
    # perpendicular offset of b's midpoint from a's line
    n = a.inward
    off = (b.midpoint[0] - a.start[0]) * n[0] + (b.midpoint[1] - a.start[1]) * n[1]
    return abs(off) <= WALL_MERGE_OFFSET_M


def select_wall(ref: ElementRef, analysis: MapAnalysis, pose: Pose) -> WallLine:
    """'The left wall', 'the right wall of the hallway', 'the wall in front of you', 'the nearest wall'."""
    if ref.label is not None:
        w = select_by_label(Kind.WALL, ref.label, analysis)
        assert isinstance(w, Wall)
        return WallLine((w.id,), w.start, w.end, w.inward, w.room)
    space = _space_for_ref(ref, analysis, pose)
    assert space is not None
    room_word = "hallway" if space.kind == ElementKind.HALLWAY else "room"
    walls = [w for w in analysis.walls if _in_space(w, space, analysis)]
    # a wall bounds the space when its inward normal points at the robot's side of it
    facing = [w for w in walls
              if (pose.x_m - w.start[0]) * w.inward[0] + (pose.y_m - w.start[1]) * w.inward[1] > 0]
    lines = [ln for ln in wall_lines(facing or walls) if ln.length_m >= WALL_MIN_CHAIN_M]
    if not lines:
        raise GroundingError(f"I found no walls in this {room_word}.")
    hx, hy = pose.heading()

    def parallel(ln: WallLine) -> bool:
        dx, dy = ln.direction
        return abs(dx * hx + dy * hy) >= math.cos(math.radians(WALL_PARALLEL_DEG))

    def line_lateral(ln: WallLine) -> float:
        # signed offset of the wall's line from the robot, in the robot frame (left > 0)
        p = _foot_on_line(pose.xy, ln)
        return to_robot_frame(pose, p)[1]

    def line_forward(ln: WallLine) -> float:
        return to_robot_frame(pose, _foot_on_line(pose.xy, ln))[0]

    side = ref.side
    if side in (Side.LEFT, Side.RIGHT):
        sign = 1.0 if side == Side.LEFT else -1.0
        cands = [ln for ln in lines if parallel(ln) and sign * line_lateral(ln) > 0]
        if not cands:
            raise GroundingError(f"I see no wall running along my {side.value} side in this {room_word}; "
                                 "turn so the wall is beside me, or say 'the nearest wall'.")
        return max(cands, key=lambda ln: sign * line_lateral(ln))
    if side in (Side.AHEAD, Side.BEHIND):
        sign = 1.0 if side == Side.AHEAD else -1.0
        cands = [ln for ln in lines if not parallel(ln) and sign * line_forward(ln) > 0]
        if not cands:
            raise GroundingError(f"I see no wall {SIDE_WORDS[side]} in this {room_word}.")
        return min(cands, key=lambda ln: abs(line_forward(ln)))
    far = ref.superlative == Superlative.FARTHEST
    if ref.superlative in (Superlative.BIGGEST, Superlative.WIDEST):
        return max(lines, key=lambda ln: ln.length_m)
    ordered = sorted(lines, key=lambda ln: math.dist(pose.xy, closest_on_segment(pose.xy, ln.start, ln.end)),
                     reverse=far)
    k = (ref.ordinal or 1) - 1
    if k >= len(ordered):
        raise GroundingError(f"This {room_word} has only {NUMBER_WORDS.get(len(ordered), len(ordered))} walls.")
    return ordered[k]


def _foot_on_line(p: Point, ln: WallLine) -> Point:
    d = ln.direction
    t = _proj(p, ln.start, d)
    return (ln.start[0] + d[0] * t, ln.start[1] + d[1] * t)


__all__ = ["AHEAD_HALF_ANGLE_DEG", "LABEL_NOUN", "WallLine", "describe_ref", "distance_to", "hallway_parts", "label_of",
           "matches_side",
           "select", "select_by_label", "select_many", "select_pair", "select_wall", "side_point", "space_of",
           "wall_lines"]
