"""Relations between spaces: "the room next to this one", "the room across the hall", "the room two
doors down".

* **next to** (``Relation.ADJACENT``): a space joined to the reference space by a door or narrow
  passage, or separated from it only by a wall (their free cells come within ``WALL_APART_MAX_M``).
  The reference is ``ref.near`` or, without one, the space the robot is in. When several spaces
  fit and no other word picks one, the robot asks which (it does not guess).
* **N doors down** (``Relation.DOORS_ALONG``, ``ordinal`` N): from the robot's own place on the hallway
  (its room's door, or the robot in the hallway), the doors of the hallway are counted the way the robot
  faces along it ("back": the other way); the room behind the Nth is meant. From a room, the doors on its
  own side of the hallway are counted (as "two doors down the street" counts one side); a side said
  ("on the left") picks that side of the hallway. Facing across the hallway, "down" names no way: a side
  said gives it ("two doors down on your right"), else the robot asks.
* **across the hall** (``Relation.ACROSS``): a space whose door opens onto the same hallway on the
  other side of it (in the hallway's wall there, not off another leg of an L or T), straight across from the door of the room named ("the room across from the
  first room on your left", ``ref.near``), of the robot's room (the robot in a room) or from the
  robot (the robot in the hallway: the side it faces, or, standing by one wall, the other side).
  Straight across: the room's own extent along the hallway comes within ``ACROSS_ALONG_MAX_M`` of
  that point (rooms are wider than their doors and staggered); the nearest such room, or a question
  when two are about as near (``ACROSS_TIE_M``).
"""

from __future__ import annotations

import math
from typing import Final

import numpy as np
from scipy.spatial import cKDTree

from langnav.analysis.elements import Door, Element, ElementKind, MapAnalysis, NarrowPassage, Room
from langnav.grounding.errors import GroundingError
from langnav.grounding.geometry import Point, Pose, nearest_point
from langnav.grounding.selection import (
    KIND_NOUN,
    SIDE_WORDS,
    describe_ref,
    distance_to,
    doors_of,
    elements_of_kind,
    floor_area_m2,
    label_of,
    landmark_ref,
    matches_side,
    select,
    size_of,
    space_of,
)
from langnav.language.intent import Element as Kind
from langnav.language.intent import ElementRef, Relation, Side, Superlative

#: Two spaces whose free cells come this close have only a wall between them (interior walls are
#: 0.1-0.3 m thick; the free cells stop a cell or two short of them).
WALL_APART_MAX_M: Final = 0.6
#: "Straight across": the room's side on the hallway comes within this distance, along the
#: hallway, of the robot's place (or its room's door): rooms along a hall are staggered, and a room
#: a door's width and a half further along is still the one across.
ACROSS_ALONG_MAX_M: Final = 2.0
#: Two rooms on the other side whose distances along the hallway differ by less than this (half a
#: door's width) are equally "across": the robot asks which one.
ACROSS_TIE_M: Final = 0.5
#: Standing this share of the hallway's width or more off its middle line, the robot stands by one
#: wall: across is the other side, whichever way it faces; nearer the middle, the side it faces.
BY_A_WALL_SHARE: Final = 0.25
#: The hallway's local direction is taken from its cells within this distance of the reference.
HALL_AXIS_RADIUS_M: Final = 3.0
#: Windows taken for the hallway's direction: the first finds the middle of the hallway near the
#: point, the second is centred there (see ``hall_axis``).
AXIS_PASSES: Final = 2
#: A hallway's cells near a point spread at least this many times more (variance) along it than across
#: it (a straight stretch 3 m either way of a hallway 2 m wide: 9; 2.5 m wide: 5.8); less, and the window
#: holds an alcove, a lobby or a bend as much as the hallway: a wider window is tried (an L's two legs
#: together spread about 3-4 times more along its diagonal: not enough, so a bend keeps the near window).
AXIS_MIN_ELONGATION: Final = 5.0
#: Times the window is doubled looking for the hallway's run past an alcove or a lobby.
AXIS_WIDENINGS: Final = 2
#: Fewer cells than this near the point (a stub of a hallway) say nothing of its direction: all of
#: the hallway's cells are used.
AXIS_MIN_CELLS: Final = 10
#: A point this close to the hallway's centre line is on neither side of it.
CENTRE_LINE_EPS_M: Final = 0.1
#: A door on the far side of the hallway lies in its wall there: its centre within the hallway's width and
#: this much more of the hallway's middle line as found near here (half a width for the wall itself, the
#: rest for a middle line pulled aside by an alcove or a lobby, and noise). A door farther out opens onto
#: another leg of the hallway (round the corner of an L or T), so its room is not "across" from here.
DOOR_IN_WALL_MARGIN_M: Final = 1.0
#: In the middle of a hallway, the robot faces one side when its heading is within ~70 deg of that
#: side's normal (cos 70 deg); facing along the hallway names no side.
FACING_ACROSS_MIN: Final = 0.34


def spaces_joined(a: Room, b: Room, analysis: MapAnalysis) -> bool:
    """A door or narrow passage joins the two spaces."""
    openings: list[Door | NarrowPassage] = [*analysis.doors, *analysis.narrow_passages]
    return any({a.id, b.id} <= set(o.connects) for o in openings)


def wall_apart(a: Room, b: Room) -> bool:
    """The two spaces' free cells come within WALL_APART_MAX_M: only a wall is between them."""
    if len(a.cells_xy) == 0 or len(b.cells_xy) == 0:
        return False
    pa, pb = np.asarray(a.cells_xy, float).reshape(-1, 2), np.asarray(b.cells_xy, float).reshape(-1, 2)
    if len(pa) > len(pb):
        pa, pb = pb, pa
    d, _ = cKDTree(pb).query(pa, k=1, distance_upper_bound=WALL_APART_MAX_M + 1e-6)
    return bool(np.isfinite(d).any())


def _reference_space(ref: ElementRef, analysis: MapAnalysis, pose: Pose) -> Room:
    if ref.near is not None and not ref.near.in_current_room:
        mark = select(landmark_ref(ref.near), analysis, pose)
        if not isinstance(mark, Room):
            raise GroundingError(f"'{describe_ref(ref)}' relates rooms and hallways, not "
                                 f"{KIND_NOUN[ref.near.kind][1]}.")
        return mark
    here = space_of(analysis, pose.xy)
    if here is None:
        raise GroundingError("I cannot tell which room I am in: I seem to be outside every room, so I "
                             "cannot tell which one is next to it.")
    return here


def _kind_pool(ref: ElementRef, analysis: MapAnalysis) -> list[Room]:
    return [e for e in elements_of_kind(analysis, ref.kind) if isinstance(e, Room)]


def select_related_spaces(ref: ElementRef, analysis: MapAnalysis, pose: Pose, count: int = 1) -> list[Element]:
    """The spaces "next to" or "across" the reference space, as the words pick them."""
    if ref.relation == Relation.ACROSS:
        return [_across(ref, analysis, pose)]
    if ref.relation == Relation.DOORS_ALONG:
        return [_doors_along(ref, analysis, pose)]
    mark = _reference_space(ref, analysis, pose)
    pool: list[Room] = [r for r in _kind_pool(ref, analysis)
                        if r is not mark and (spaces_joined(r, mark, analysis) or wall_apart(r, mark))]
    where = "this one" if ref.near is None or ref.near.in_current_room else label_of(mark)
    noun, nouns = KIND_NOUN[ref.kind]
    if not pool:
        raise GroundingError(f"I see no {noun} next to {where}.")
    if ref.side is not None:
        pool = [r for r in pool if matches_side(r, pose, ref.side)]
        if not pool:
            raise GroundingError(f"I see no {noun} next to {where} {SIDE_WORDS[ref.side]}.")
    picked = ref.ordinal is not None or ref.superlative is not None
    if not picked and len(pool) > count:
        options = sorted(pool, key=lambda r: distance_to(r, pose.xy))
        listed = "; ".join(f"{label_of(r)} ({_where_is(r, pose)})" for r in options[:6])
        raise GroundingError(f"There are {len(pool)} {nouns} next to {where}: {listed}. Which one do you mean? "
                             f"Say e.g. 'go to {label_of(options[0])}'.")
    sup = ref.superlative
    if sup in (Superlative.BIGGEST, Superlative.SMALLEST, Superlative.WIDEST, Superlative.NARROWEST):
        ordered = sorted(pool, key=lambda r: floor_area_m2(r, analysis) if sup in (Superlative.BIGGEST,
                         Superlative.SMALLEST) else size_of(r), reverse=sup in (Superlative.BIGGEST, Superlative.WIDEST))
    else:
        ordered = sorted(pool, key=lambda r: distance_to(r, pose.xy), reverse=sup == Superlative.FARTHEST)
    k = (ref.ordinal or 1) - 1
    if len(ordered) < k + count:
        raise GroundingError(f"I see only {len(ordered)} {nouns if len(ordered) != 1 else noun} next to {where}, "
                             f"so I cannot find {describe_ref(ref)}.")
    return list(ordered[k:k + count])


def _where_is(e: Element, pose: Pose) -> str:
    for side in (Side.AHEAD, Side.BEHIND, Side.LEFT, Side.RIGHT):
        if matches_side(e, pose, side):
            return SIDE_WORDS[side]
    return "beside me"


def hall_axis(hall: Room, around: Point, *, past_alcoves: bool = False) -> tuple[Point, Point]:
    """(centre, unit direction) of the hallway near a point: the principal axis of its cells within
    HALL_AXIS_RADIUS_M (all of them when too few are near). ``past_alcoves``: when those cells spread
    about as much both ways, wider windows are tried (see AXIS_MIN_ELONGATION)."""
    cells = np.asarray(hall.cells_xy, float).reshape(-1, 2)
    if len(cells) < 3:
        raise GroundingError(f"{label_of(hall)} has too little free space to tell its direction.")
    first: tuple[Point, Point] | None = None
    for k in range(AXIS_WIDENINGS + 1 if past_alcoves else 1):
        c = np.asarray(around, float)
        pts = cells
        # Twice: a window round a point off the centre line (near a wall, at the hallway's end) holds
        # more of one side of the hallway than of the other and tilts the axis; the second window is
        # centred on the middle of the hallway found by the first.
        for _ in range(AXIS_PASSES):
            near = cells[np.hypot(cells[:, 0] - c[0], cells[:, 1] - c[1]) <= HALL_AXIS_RADIUS_M * 2 ** k]
            pts = near if len(near) >= AXIS_MIN_CELLS else cells
            c = pts.mean(axis=0)
        w, v = np.linalg.eigh(np.cov((pts - c).T))
        axis = v[:, int(np.argmax(w))]
        found = (float(c[0]), float(c[1])), (float(axis[0]), float(axis[1]))
        first = first or found
        # A window whose cells spread about as much both ways says nothing of which way the hallway runs:
        # an alcove or a lobby off it (a wider window is the hallway itself, long and narrow: taken), or a
        # bend or junction (a wider window holds both legs, no narrower: the nearest window is kept).
        if len(pts) == len(cells) or w.min() * AXIS_MIN_ELONGATION <= w.max():
            return found
    assert first is not None
    return first


#: A door this close along the hallway to where the counting starts is the robot's own (its room's door,
#: or the door it stands by): it is not counted.
OWN_DOOR_ALONG_M: Final = 0.5


def _hall_and_origin(analysis: MapAnalysis, pose: Pose, what: str) -> tuple[Room, Room | None, Point]:
    """The hallway the robot is in or its room opens onto, its room (None in the hallway), and the point
    relations along the hallway start from (the robot in the hallway, else its room's door onto it)."""
    here = space_of(analysis, pose.xy)
    if here is not None and here.kind == ElementKind.HALLWAY:
        return here, None, pose.xy
    halls = [r for r in analysis.rooms if r.kind == ElementKind.HALLWAY]
    joined = [h for h in halls if here is not None and spaces_joined(h, here, analysis)]
    if here is None or not joined:
        raise GroundingError(f"I see no hallway next to the room I am in, so I cannot tell {what}.")
    hall = min(joined, key=lambda h: nearest_point(pose.xy, h.cells_xy)[0])
    doors = [d for d in doors_of(analysis) if {hall.id, here.id} <= set(d.connects)]
    if not doors:
        raise GroundingError(f"I see no door from this room onto {label_of(hall)}.")
    return hall, here, min(doors, key=lambda d: math.dist(d.center, pose.xy)).center


def _doors_along(ref: ElementRef, analysis: MapAnalysis, pose: Pose) -> Room:
    """'The room two doors down': see the module docstring."""
    n = ref.ordinal or 1
    hall, here, origin = _hall_and_origin(analysis, pose, f"which room is {n} doors down")
    centre, axis = hall_axis(hall, origin)
    heading = (math.cos(pose.yaw_rad), math.sin(pose.yaw_rad))
    facing_along = heading[0] * axis[0] + heading[1] * axis[1]
    side = ref.side
    if abs(facing_along) >= FACING_ACROSS_MIN:
        way = 1.0 if facing_along > 0 else -1.0
        if side == Side.BEHIND:
            way, side = -way, None
    elif side in (Side.LEFT, Side.RIGHT):
        # facing across the hallway: "down on your right" is the way along it to the robot's right
        left = (-heading[1], heading[0])
        to_left = left[0] * axis[0] + left[1] * axis[1]
        way = (1.0 if to_left > 0 else -1.0) * (1.0 if side == Side.LEFT else -1.0)
        side = None
    else:
        raise GroundingError(f"I am facing across {label_of(hall)}, so 'down' could be either way; say e.g. "
                             f"'the room {n} doors down on your left' (or right).")
    d_axis = (axis[0] * way, axis[1] * way)

    def along(p: Point) -> float:
        return (p[0] - origin[0]) * d_axis[0] + (p[1] - origin[1]) * d_axis[1]

    def lateral(p: Point) -> float:  # > 0: left of the way along the hallway
        return d_axis[0] * (p[1] - centre[1]) - d_axis[1] * (p[0] - centre[0])

    doors = [d for d in doors_of(analysis) if hall.id in d.connects and (here is None or here.id not in d.connects)
             and along(d.center) > OWN_DOOR_ALONG_M]
    if side in (Side.LEFT, Side.RIGHT):
        doors = [d for d in doors if (lateral(d.center) > 0) == (side == Side.LEFT)]
    elif here is not None:
        own = lateral(origin)
        doors = [d for d in doors if (lateral(d.center) > 0) == (own > 0)]  # the robot's own side
    doors.sort(key=lambda d: along(d.center))
    if len(doors) < n:
        raise GroundingError(f"I see only {len(doors)} door{'s' if len(doors) != 1 else ''} further along "
                             f"{label_of(hall)} that way, so there is no room {n} doors down.")
    door = doors[n - 1]
    rooms = {r.id: r for r in analysis.rooms}
    behind = [rooms[c] for c in door.connects if c != hall.id and c in rooms]
    if not behind or behind[0].kind != ElementKind.ROOM:
        raise GroundingError(f"{label_of(door)}, {n} doors down, leads to no room I know.")
    return behind[0]


def _across(ref: ElementRef, analysis: MapAnalysis, pose: Pose) -> Room:
    here = space_of(analysis, pose.xy)
    if ref.near is not None and ref.near.kind == Kind.ROOM and not ref.near.in_current_room:
        # "the room across from the first room on your left": across from that room's door
        mark = select(landmark_ref(ref.near), analysis, pose)
        if not isinstance(mark, Room):
            raise GroundingError(f"'{describe_ref(ref)}' needs a room to look across from.")
        here = mark
    halls = [r for r in analysis.rooms if r.kind == ElementKind.HALLWAY]
    # the room across from which to look: "across from the first room on your left", else the robot's
    base = here
    if ref.near is not None and ref.near.kind == Kind.ROOM and not ref.near.in_current_room:
        mark = select(landmark_ref(ref.near), analysis, pose)
        if not isinstance(mark, Room):
            raise GroundingError(f"I cannot tell which room is across from {describe_ref(landmark_ref(ref.near))}.")
        base = mark
    if ref.near is not None and ref.near.kind == Kind.HALLWAY and not ref.near.in_current_room:
        hall_e = select(landmark_ref(ref.near), analysis, pose)
        assert isinstance(hall_e, Room)
        hall = hall_e
    elif base is here and here is not None and here.kind == ElementKind.HALLWAY:
        hall = here
    else:
        joined = [h for h in halls if base is not None and spaces_joined(h, base, analysis)]
        if not joined:
            what = "the room I am in" if base is here else label_of(base) if base is not None else "me"
            raise GroundingError(f"I see no hallway next to {what}, so I cannot tell which room is across it.")
        hall = min(joined, key=lambda h: nearest_point(pose.xy, h.cells_xy)[0])
    # the point across from which to look: the robot in the hallway, else the room's door onto it
    from_door = base is not None and base is not hall
    if base is None or base is hall:
        origin = pose.xy
        # which side is across depends only on which way the hallway runs here, also for a robot
        # standing in an alcove or a lobby off it
        centre, axis = hall_axis(hall, origin, past_alcoves=True)
        normal = (-axis[1], axis[0])
    else:
        doors = [d for d in doors_of(analysis) if {hall.id, base.id} <= set(d.connects)]
        if not doors:
            raise GroundingError(f"I see no door from {label_of(base)} onto {label_of(hall)}.")
        door = min(doors, key=lambda d: math.dist(d.center, pose.xy))
        origin = door.center
        # Across from a door is straight on through it: the door's own normal is the way across the
        # hallway there, even by a bend or a junction, where the hallway's cells round the door run two
        # ways and their main axis says nothing. The hallway's middle line is half its width in.
        into = 1.0 if door.connects[-1] == hall.id else -1.0  # the normal points from connects[0] to [1]
        normal = (door.normal[0] * into, door.normal[1] * into)
        axis = (normal[1], -normal[0])
        centre = (origin[0] + normal[0] * hall.width_m / 2, origin[1] + normal[1] * hall.width_m / 2)

    def across(p: Point) -> float:
        return (p[0] - centre[0]) * normal[0] + (p[1] - centre[1]) * normal[1]

    def along(p: Point) -> float:
        return (p[0] - centre[0]) * axis[0] + (p[1] - centre[1]) * axis[1]

    facing = math.cos(pose.yaw_rad) * normal[0] + math.sin(pose.yaw_rad) * normal[1]
    by_a_wall = hall.width_m * BY_A_WALL_SHARE
    if ref.side in (Side.LEFT, Side.RIGHT):
        # "the room across the hall on your left": that side of the robot is the far side
        left_is_plus = (-math.sin(pose.yaw_rad)) * normal[0] + math.cos(pose.yaw_rad) * normal[1] > 0
        far_plus = left_is_plus if ref.side == Side.LEFT else not left_is_plus
        own = -1.0 if far_plus else 1.0
    elif from_door or abs(across(origin)) >= max(by_a_wall, CENTRE_LINE_EPS_M):
        own = across(origin)  # from a room's door, or standing by one wall: across is the other side
    elif abs(facing) >= FACING_ACROSS_MIN:
        own = -1.0 if facing > 0 else 1.0  # in the middle of the hallway: across is the side it faces
    elif abs(across(origin)) >= CENTRE_LINE_EPS_M:
        own = across(origin)
    else:
        raise GroundingError(f"I am in the middle of {label_of(hall)}, facing along it, so 'across' could be "
                             "either side; say 'the room across the hall on your left' (or right).")
    here_along = along(origin)
    candidates: dict[str, tuple[float, Room]] = {}
    for d in doors_of(analysis):
        if hall.id not in d.connects:
            continue
        other_id = next((c for c in d.connects if c != hall.id), None)
        if other_id is None or (base is not None and other_id == base.id):
            continue
        other = next((r for r in analysis.rooms if r.id == other_id), None)
        if other is None or (ref.kind == Kind.ROOM and other.kind != ElementKind.ROOM):
            continue
        if across(d.center) * own >= 0:
            continue  # a door on the robot's own side of the hallway
        if abs(across(d.center)) > hall.width_m + DOOR_IN_WALL_MARGIN_M:
            continue  # a door off another leg of the hallway, round a corner
        # how far along the hallway the room is from here: 0 when its side on the hallway spans here
        cells = np.asarray(other.cells_xy, float).reshape(-1, 2)
        if len(cells):
            t = (cells[:, 0] - centre[0]) * axis[0] + (cells[:, 1] - centre[1]) * axis[1]
            gap = max(0.0, float(t.min()) - here_along, here_along - float(t.max()))
        else:
            gap = abs(along(d.center) - here_along)
        if other.id not in candidates or gap < candidates[other.id][0]:
            candidates[other.id] = (gap, other)
    if not candidates:
        raise GroundingError(f"I see no room on the other side of {label_of(hall)}.")
    ranked = sorted(candidates.values(), key=lambda t: t[0])
    gap, best = ranked[0]
    if gap > ACROSS_ALONG_MAX_M:
        raise GroundingError(f"No room is straight across {label_of(hall)} from here: the nearest on the other "
                             f"side, {label_of(best)}, is {gap:.1f} m further along. Say 'go to {label_of(best)}' "
                             "if you mean that one.")
    if len(ranked) > 1 and ranked[1][0] - gap < ACROSS_TIE_M:
        other = ranked[1][1]
        raise GroundingError(f"Two rooms are across {label_of(hall)} from here, {label_of(best)} and "
                             f"{label_of(other)}; which one do you mean? Say e.g. 'go to {label_of(best)}'.")
    return best


__all__ = ["ACROSS_ALONG_MAX_M", "WALL_APART_MAX_M", "hall_axis", "select_related_spaces", "spaces_joined",
           "wall_apart"]
