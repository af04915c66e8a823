"""Composition: amounts attached to places, facing, returning, named places.

The meanings (each a rule a person would state, not fitted to a map):

* **N past / before X** (``Step.offset``): measured along the robot's way. In a hallway, past a
  door or an element of that hallway is down the hallway (its local axis, in the direction of X, or
  of the heading when X is beside the robot); past a door or narrow passage otherwise is through
  it, along its axis; past anything else is along the straight line from the robot to it. "Past"
  counts from X's far edge, "before" from its near edge. The goal is never farther along than asked:
  when the point asked for is not free, a free point up to ``OFFSET_SNAP_M`` short of it is used,
  never one beyond it.
* **a fraction of the way** (``Step.fraction``): along a hallway, a room or a wall, that part of the
  run from the robot to the far end in the direction of travel ("halfway down the corridor");
  towards an element, that part of the straight line to the goal "to X" would have.
* **face X / face north** (a Rotate step with a target or ``heading_deg``): one rotation the shorter
  way from the pose the earlier steps leave, to the bearing of X's point (door centre, corner,
  obstacle centre, the foot of a wall, a space's nearest cell or the door into it), or the heading.
* **back to where you started / were** (``Place.START`` / ``Place.PREVIOUS``): after a move earlier
  in the same prompt, where the prompt began / where that move began; as a prompt's first step,
  the session's first trip start / the start of the latest trip that began elsewhere.
* **the X you just passed** (``ElementRef.passed``): of the elements of that kind the robot's trail
  came within ``PASS_NEAR_M`` of and then left at least ``PASSED_BEYOND_M`` behind, the latest.
* **named places**: a spot is reached within ``NAMED_PLACE_MAX_M`` of its point (facing its heading
  when it has one); a named room or hallway is entered like "go into room 3".
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Final, Literal, Protocol

import numpy as np
from skimage.measure import approximate_polygon

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
    BoolArray,
    FloatArray,
    Point,
    Pose,
    closest_on_segment,
    nearest_point,
    unit,
    wrap_angle,
)
from langnav.grounding.history import SAME_PLACE_M, closest_approach
from langnav.grounding.relations import hall_axis, spaces_joined
from langnav.grounding.selection import (
    describe_ref,
    elements_of_kind,
    select,
    select_wall,
    space_of,
)
from langnav.language.intent import ElementRef, Offset, Place, Step
from langnav.places.store import NamedPlace, place_key
from langnav.plan.commands import ROTATE_STEP_DEG, Rotate, steps_for_angle

#: "N past / before X": when that point is not free, a free point at most this much short of it.
OFFSET_SNAP_M: Final = 0.5
#: ... and at most this far to either side of the robot's line (a hallway's half width).
OFFSET_SIDE_M: Final = 0.6
#: The goal may lie this much beyond the point asked for: half a cell of snapping to cell centres.
ALONG_SLACK_M: Final = 0.03
#: "before X" closer than this to the robot is no move at all.
MIN_OFFSET_RUN_M: Final = 0.1
#: "halfway to X": a free point at most this far short of the point asked for ...
FRACTION_SNAP_M: Final = 0.5
#: A way's straight run ends where it comes within this of its farthest point along the heading it
#: set off in (the wobble of a walked path's middle line is smaller).
LEG_END_TOL_M: Final = 0.3
#: The straight run is looked for at points this far apart along the way.
LEG_STEP_M: Final = 0.1
#: ... searched for within this much more of it: the nearest free cell may lie a little to the side
#: of the straight way (the value the search has used since fractions were added).
FRACTION_SEARCH_EXTRA_M: Final = 0.3
#: A fraction this close to a named one ("halfway", "a third") is said with that name (1/3 is read
#: as 0.333 and 0.3333: a thousandth tells them apart from the next fraction a person says).
FRACTION_NAME_TOL: Final = 1e-3
#: "past / before X" in a hallway: X less than this along the hallway from the robot is beside it,
#: neither ahead nor behind, so the way the robot faces says which way "past" is.
BESIDE_ALONG_M: Final = 0.3
#: Facing: a turn smaller than half a rotate step cannot be made; the robot already faces it.
FACING_DONE_DEG: Final = ROTATE_STEP_DEG / 2
#: "the door you just passed": the trail came within this of it (a hallway's width: a door on the
#: far wall of a corridor is passed too) ...
PASS_NEAR_M: Final = 2.0
#: ... and went on at least this far past that point (standing at it is not having passed it).
PASSED_BEYOND_M: Final = 0.5
#: Two elements passed within this much of the way of each other were passed "at the same time" (a
#: door's width): "the door you just passed" does not tell them apart.
PASSED_TIE_M: Final = 0.75
#: Named places: the goal lies within this distance of the remembered point.
NAMED_PLACE_MAX_M: Final = 0.75
#: An element counts as "of the hallway" when its point is within this of the hallway's cells.
OF_HALL_M: Final = 1.0
#: Compass names for headings in messages.
COMPASS: Final = {0: "east", 45: "north-east", 90: "north", 135: "north-west", 180: "west", 225: "south-west",
                  270: "south", 315: "south-east"}


class SafePointNear(Protocol):
    """The free-space search the goals are snapped with (``FreeSpace.safe_point_near``)."""

    def __call__(self, target: Point, component: int, max_radius_m: float, *, prefer: Point | None = None,
                 where: Callable[[FloatArray, FloatArray], BoolArray] | None = None) -> Point | None: ...


@dataclass(frozen=True)
class Anchor:
    """What an offset is measured from: the direction of travel and the target's near / far edge
    along it, as distances from ``origin`` (the robot's place on the line of the way); ``space_id``
    is the space the way runs through at the goal (the hallway, the room a door leads into), where
    the goal is looked for first."""

    origin: Point
    direction: Point
    near_t: float
    far_t: float
    space_id: str | None = None


#: A vectorised predicate on world x, y arrays (the cells a goal may be on).
Where = Callable[[FloatArray, FloatArray], BoolArray]


# ------------------------------------------------------------------------------ facing
def compass_word(heading_deg: float) -> str:
    h = heading_deg % 360.0
    for k, w in COMPASS.items():
        if abs(wrap_angle(math.radians(h - k))) < math.radians(1.0):
            return w
    return f"heading {h:g}°"


def facing_turn(pose: Pose, target_yaw_rad: float, what: str) -> tuple[Rotate | None, Pose, str]:
    """The one Rotate, the shorter way, that leaves the robot facing ``target_yaw_rad`` (None when
    it already does), the pose after it and a note. A half turn goes left (either way is right)."""
    diff = math.degrees(wrap_angle(target_yaw_rad - pose.yaw_rad))
    if abs(diff) < FACING_DONE_DEG:
        return None, pose, f"I am already facing {what}"
    direction: Literal["left", "right"] = "left" if diff > 0 else "right"
    n = steps_for_angle(abs(diff))
    sign = 1.0 if direction == "left" else -1.0
    end = Pose(pose.x_m, pose.y_m, pose.yaw_rad + sign * math.radians(n * ROTATE_STEP_DEG))
    note = f"turn {direction} {n * ROTATE_STEP_DEG:g}° to face {what}"
    return Rotate(direction=direction, repeat=n, note=note), end, note


def facing_point(e: Element, pose: Pose, analysis_here: Room | None, doors: tuple[Door, ...]) -> Point:
    """The point of an element the robot turns to face."""
    if isinstance(e, Room):
        if analysis_here is e:
            return e.centroid
        if analysis_here is not None:
            into = [d for d in doors if {e.id, analysis_here.id} <= set(d.connects)]
            if into:  # "face the hallway" from a room: the door that leads into it
                return min(into, key=lambda d: math.dist(d.center, pose.xy)).center
        return nearest_point(pose.xy, e.cells_xy)[1] if len(e.cells_xy) else e.centroid
    if isinstance(e, UnexploredArea) and len(e.frontier):
        return nearest_point(pose.xy, e.frontier)[1]
    if isinstance(e, Wall):
        return closest_on_segment(pose.xy, e.start, e.end)
    return reference_point(e)


# ------------------------------------------------------------------------------ offsets
def element_extent(e: Element | Point) -> FloatArray:
    """The points whose span along the way is the element's extent (one point for a door centre, a
    corner or a named spot; a passage's two mouths; an obstacle's cells)."""
    if isinstance(e, tuple):
        return np.asarray([e], float)
    if isinstance(e, Obstacle) and len(e.cells_xy):
        return np.asarray(e.cells_xy, float).reshape(-1, 2)
    if isinstance(e, NarrowPassage):
        return np.asarray(e.ends, float).reshape(-1, 2)
    if isinstance(e, Room) and len(e.cells_xy):
        return np.asarray(e.cells_xy, float).reshape(-1, 2)
    if isinstance(e, UnexploredArea) and len(e.frontier):
        return np.asarray(e.frontier, float).reshape(-1, 2)
    return np.asarray([reference_point(e)], float)


def _door_axis(e: Door | NarrowPassage, pose: Pose) -> tuple[Point, Point]:
    """(centre, unit direction away from the robot) across a door / along a passage."""
    if isinstance(e, NarrowPassage):
        a, b = e.ends
        near, far = (a, b) if math.dist(a, pose.xy) <= math.dist(b, pose.xy) else (b, a)
        return e.center, unit((far[0] - near[0], far[1] - near[1]))
    (ax, ay), (bx, by) = e.jambs
    n = unit((-(by - ay), bx - ax)) if math.hypot(bx - ax, by - ay) > 1e-6 else unit(e.normal)
    s = (e.center[0] - pose.x_m) * n[0] + (e.center[1] - pose.y_m) * n[1]
    if abs(s) < 0.1:  # standing in the doorway: onward is the heading's side
        s = math.cos(pose.yaw_rad) * n[0] + math.sin(pose.yaw_rad) * n[1]
    return e.center, n if s >= 0 else (-n[0], -n[1])


def _of_hallway(e: Element | Point, hall: Room) -> bool:
    if isinstance(e, Door | NarrowPassage) and hall.id in e.connects:
        return True
    p = e if isinstance(e, tuple) else reference_point(e) if not isinstance(e, Wall) else e.midpoint
    return len(hall.cells_xy) > 0 and nearest_point(p, hall.cells_xy)[0] <= OF_HALL_M


def _way_space(e: Door | NarrowPassage, here: Room | None, past: bool) -> str | None:
    """The space the way runs through at an offset from an opening: the one on its far side from the
    robot (``past``) or the robot's own (``before``); None when the robot is in neither."""
    if here is None or here.id not in e.connects:
        return None
    if not past:
        return here.id
    others = [c for c in e.connects if c != here.id]
    return others[0] if len(others) == 1 else None


def offset_anchor(e: Element | Point, pose: Pose, here: Room | None, *, past: bool = True) -> Anchor:
    """How "past / before X" is measured from this pose (see the module docstring); ``e`` is an
    element or a point (a named spot, the foot of a wall)."""
    pts = element_extent(e)
    if isinstance(e, tuple):
        ref = e
    else:
        ref = reference_point(e) if not isinstance(e, Wall) else closest_on_segment(pose.xy, e.start, e.end)
    space_id: str | None = None
    if here is not None and here.kind == ElementKind.HALLWAY and _of_hallway(e, here):
        # down the hallway as it runs where X is (an L-shaped corridor turns), along its middle
        centre, axis = hall_axis(here, ref)
        along = (ref[0] - pose.x_m) * axis[0] + (ref[1] - pose.y_m) * axis[1]
        heading = math.cos(pose.yaw_rad) * axis[0] + math.sin(pose.yaw_rad) * axis[1]
        sign = (1.0 if along > 0 else -1.0) if abs(along) > BESIDE_ALONG_M else (1.0 if heading >= 0 else -1.0)
        d = (axis[0] * sign, axis[1] * sign)
        t_robot = (pose.x_m - centre[0]) * d[0] + (pose.y_m - centre[1]) * d[1]
        origin = (centre[0] + d[0] * t_robot, centre[1] + d[1] * t_robot)
        space_id = here.id
    elif isinstance(e, Door | NarrowPassage):
        centre, d = _door_axis(e, pose)
        # measured from the robot's line through the opening's centre
        t_robot = (pose.x_m - centre[0]) * d[0] + (pose.y_m - centre[1]) * d[1]
        origin = (centre[0] + d[0] * t_robot, centre[1] + d[1] * t_robot)
        space_id = _way_space(e, here, past)
    else:
        v = (ref[0] - pose.x_m, ref[1] - pose.y_m)
        d = unit(v) if math.hypot(*v) > 1e-6 else (math.cos(pose.yaw_rad), math.sin(pose.yaw_rad))
        origin = pose.xy
    t = (pts[:, 0] - origin[0]) * d[0] + (pts[:, 1] - origin[1]) * d[1]
    return Anchor(origin, d, float(t.min()), float(t.max()), space_id)


def offset_goal(e: Element | Point, step: Step, pose: Pose, here: Room | None, desc: str,
                safe_point: SafePointNear, comp: int,
                in_space: Callable[[str], Where | None] | None = None) -> tuple[Point, float]:
    """The goal N metres past / before ``e`` and the along-way distance asked for (from the anchor's
    origin). The goal is looked for first in the space the way runs through there (``in_space``
    gives a space's cells by id, None for an id that is no space): never sideways into a doorway
    or a room beside the way. Raises GroundingError when that point is behind the robot or not
    reachable."""
    if step.offset is None or step.offset_m is None:
        raise GroundingError(f"How far past or before {desc} should I stop? Say e.g. 'stop 1 m before {desc}' "
                             f"or 'go 2 m past {desc}'; nothing was run.")
    past = step.offset == Offset.PAST
    a = offset_anchor(e, pose, here, past=past)
    n = step.offset_m
    t_goal = a.far_t + n if past else a.near_t - n
    t_robot = (pose.x_m - a.origin[0]) * a.direction[0] + (pose.y_m - a.origin[1]) * a.direction[1]
    word = "past" if past else "before"
    if t_goal - t_robot < MIN_OFFSET_RUN_M:
        if not past:
            raise GroundingError(f"I am already less than {n:g} m from {desc}, so I cannot stop {n:g} m before it; "
                                 "nothing was run.")
        raise GroundingError(f"{n:g} m past {desc} is behind me; turn towards it first or name where to go.")
    target = (a.origin[0] + a.direction[0] * t_goal, a.origin[1] + a.direction[1] * t_goal)
    d = a.direction
    o = a.origin

    def on_the_way(xs: FloatArray, ys: FloatArray) -> BoolArray:
        t = (xs - o[0]) * d[0] + (ys - o[1]) * d[1]
        side = np.abs(-(xs - target[0]) * d[1] + (ys - target[1]) * d[0])
        return np.asarray((t <= t_goal + ALONG_SLACK_M) & (t >= t_goal - OFFSET_SNAP_M) & (side <= OFFSET_SIDE_M),
                          dtype=bool)

    radius = math.hypot(OFFSET_SNAP_M, OFFSET_SIDE_M)
    goal: Point | None = None
    space = in_space(a.space_id) if a.space_id is not None and in_space is not None else None
    if space is not None:
        inside = space

        def on_the_way_in_space(xs: FloatArray, ys: FloatArray) -> BoolArray:
            return np.asarray(on_the_way(xs, ys) & inside(xs, ys), dtype=bool)

        goal = safe_point(target, comp, radius, prefer=target, where=on_the_way_in_space)
    if goal is None:  # the way leaves that space there (the hallway ends in a room): straight on
        goal = safe_point(target, comp, radius, prefer=target, where=on_the_way)
    if goal is None:
        raise GroundingError(f"I cannot stop {n:g} m {word} {desc}: there is no free space I can reach there "
                             "(a wall or an obstacle is in the way, or it is off the map). Nothing was run.")
    return goal, t_goal


# ------------------------------------------------------------------------------ ways
@dataclass(frozen=True)
class Way:
    """A way the robot walks, as a polyline from the robot: its corners and the length walked to
    each. "Halfway down the corridor" and "along the hallway" are measured along it, so an L-shaped
    corridor is followed round its bend."""

    points: tuple[Point, ...]
    lengths: tuple[float, ...]

    @classmethod
    def through(cls, pts: list[Point], tolerance_m: float) -> Way:
        """The way through ``pts`` (first the robot), its small wiggles (under ``tolerance_m``, the
        walk's lattice step) straightened."""
        a = np.asarray(pts, dtype=float).reshape(-1, 2)
        if len(a) > 2:
            a = approximate_polygon(a, tolerance_m)
        keep = [tuple(map(float, a[0]))]
        for q in a[1:]:
            if math.dist(keep[-1], (float(q[0]), float(q[1]))) > 1e-6:
                keep.append((float(q[0]), float(q[1])))
        lengths = [0.0]
        for p0, p1 in itertools.pairwise(keep):
            lengths.append(lengths[-1] + math.dist(p0, p1))
        return cls(tuple((p[0], p[1]) for p in keep), tuple(lengths))

    @property
    def length_m(self) -> float:
        return self.lengths[-1]

    def point_at(self, s_m: float) -> Point:
        """The point ``s_m`` along the way (clamped to its ends)."""
        if len(self.points) == 1 or s_m <= 0:
            return self.points[0]
        for i in range(1, len(self.points)):
            if s_m <= self.lengths[i] or i == len(self.points) - 1:
                seg = self.lengths[i] - self.lengths[i - 1]
                f = 1.0 if seg <= 0 else min(1.0, (s_m - self.lengths[i - 1]) / seg)
                (x0, y0), (x1, y1) = self.points[i - 1], self.points[i]
                return (x0 + (x1 - x0) * f, y0 + (y1 - y0) * f)
        return self.points[-1]

    def direction_at(self, s_m: float) -> Point:
        """The unit direction of the way at ``s_m``."""
        for i in range(1, len(self.points)):
            if s_m <= self.lengths[i] or i == len(self.points) - 1:
                return unit((self.points[i][0] - self.points[i - 1][0], self.points[i][1] - self.points[i - 1][1]))
        return (1.0, 0.0)

    def straight_leg(self, heading: Point, bend_m: float) -> Way:
        """The way up to where it turns a corner: "down this corridor" and "the end of the corridor"
        mean the straight run ahead, and at an L's bend the run ends (the other leg is another
        corridor, "at the end of the corridor, turn left"). A way turns a corner where it has gone
        sideways of ``heading`` by more than ``bend_m`` (the corridor's width: round a corner, not a
        wiggle of the middle line); the run ends, before that, where the way comes within
        ``LEG_END_TOL_M`` of its farthest point along ``heading``. A way with no bend is whole."""
        if self.length_m <= LEG_END_TOL_M:
            return self
        ss = np.append(np.arange(0.0, self.length_m, LEG_STEP_M), self.length_m)
        pts = np.array([self.point_at(float(s)) for s in ss])
        rel = pts - np.asarray(self.points[0])
        proj = rel[:, 0] * heading[0] + rel[:, 1] * heading[1]
        lat = rel[:, 0] * heading[1] - rel[:, 1] * heading[0]
        sideways = np.nonzero(np.abs(lat) > bend_m)[0]
        if sideways.size == 0:
            return self
        head = proj[: int(sideways[0]) + 1]
        k = int(np.argmax(head >= head.max() - LEG_END_TOL_M))
        if k == 0:
            return self  # the way sets off sideways: no straight run ahead to measure
        s_end = float(ss[k])
        keep = [p for p, length in zip(self.points, self.lengths, strict=True) if length < s_end]
        end = self.point_at(s_end)
        if math.dist(keep[-1], end) > 1e-6:
            keep.append(end)
        lengths = [0.0]
        for p0, p1 in itertools.pairwise(keep):
            lengths.append(lengths[-1] + math.dist(p0, p1))
        return Way(tuple(keep), tuple(lengths))

    def along(self, xs: FloatArray, ys: FloatArray) -> FloatArray:
        """How far along the way each point is: on the segment nearest to it, the length to the
        segment's start plus the point's projection on it."""
        best_d = np.full(np.shape(xs), np.inf)
        best_s = np.zeros(np.shape(xs))
        for i in range(1, len(self.points)):
            (x0, y0), (x1, y1) = self.points[i - 1], self.points[i]
            seg = self.lengths[i] - self.lengths[i - 1]
            if seg <= 0:
                continue
            ux, uy = (x1 - x0) / seg, (y1 - y0) / seg
            t = (xs - x0) * ux + (ys - y0) * uy
            last = i == len(self.points) - 1
            tc = np.clip(t, 0.0, np.inf if last else seg)  # beyond the end, along its last segment
            d = np.hypot(xs - (x0 + ux * tc), ys - (y0 + uy * tc))
            closer = d < best_d
            best_d = np.where(closer, d, best_d)
            best_s = np.where(closer, self.lengths[i - 1] + np.clip(t, 0.0 if i > 1 else -np.inf,
                                                                   np.inf if last else seg), best_s)
        return np.asarray(best_s, dtype=np.float64)


# ------------------------------------------------------------------------------ fractions
def fraction_goal(full_goal: Point, fraction: float, pose: Pose,
                  safe_point: SafePointNear, comp: int, desc: str) -> Point:
    """That part of the straight way from the robot to ``full_goal`` (never beyond it)."""
    v = (full_goal[0] - pose.x_m, full_goal[1] - pose.y_m)
    length = math.hypot(*v)
    if length < 1e-6:
        raise GroundingError(f"I am already at {desc}.")
    d = (v[0] / length, v[1] / length)
    want = length * fraction
    target = (pose.x_m + d[0] * want, pose.y_m + d[1] * want)

    def not_beyond(xs: FloatArray, ys: FloatArray) -> BoolArray:
        t = (xs - pose.x_m) * d[0] + (ys - pose.y_m) * d[1]
        return np.asarray((t <= want + ALONG_SLACK_M) & (t >= want - FRACTION_SNAP_M), dtype=bool)

    goal = safe_point(target, comp, FRACTION_SNAP_M + FRACTION_SEARCH_EXTRA_M, prefer=target, where=not_beyond)
    if goal is None:
        raise GroundingError(f"I cannot stop {fraction_words(fraction)} to {desc}: there is no free space I can "
                             "reach at that point of the way. Nothing was run.")
    return goal


def fraction_words(fraction: float) -> str:
    named = {0.5: "halfway", 0.25: "a quarter of the way", 0.75: "three quarters of the way",
             1 / 3: "a third of the way", 2 / 3: "two thirds of the way"}
    for v, w in named.items():
        if abs(fraction - v) < FRACTION_NAME_TOL:
            return w
    return f"{fraction * 100:.0f}% of the way"


# ------------------------------------------------------------------------------ returns
def return_point(place: Place, now: Pose, origin: Pose | None, moved_from: tuple[Pose, ...],
                 session_start: Pose | None, last_trip_elsewhere: Pose | None) -> tuple[Pose | None, str]:
    """Where "back to where you started / were" leads from ``now``, and its words (see the docstring).
    None when the robot is already there."""
    if place == Place.PREVIOUS:
        target = moved_from[-1] if moved_from else last_trip_elsewhere
        words = "where I was before"
        if target is None:
            raise GroundingError("I don't remember being anywhere else yet in this session, so I can't go back "
                                 "to where I was; name the place instead, e.g. 'go back to door 2'.")
    else:
        target = origin if moved_from else session_start
        words = "where I started"
        if target is None:
            raise GroundingError("I don't know where I started: I have not moved since I was switched on; "
                                 "name the place instead, e.g. 'go to door 2'.")
    if math.dist(target.xy, now.xy) <= SAME_PLACE_M:
        return None, words
    return target, words


# ------------------------------------------------------------------------------ passed elements
def passed_element(ref: ElementRef, trail: list[Point], analysis_elements: list[Element]) -> Element:
    """The element of ``ref``'s kind that the robot passed last along ``trail`` (oldest first, ending
    at the robot)."""
    noun = describe_ref(ref.model_copy(update={"passed": False, "label": None})).removeprefix("the ")
    if len(trail) < 2:
        raise GroundingError(f"I have not driven anywhere yet that I remember, so I don't know which {noun} "
                             "I passed; name it instead, e.g. by the label on the map ('door 2').")
    passed: list[tuple[float, Element]] = []
    for e in analysis_elements:
        pts = element_extent(e)
        p = nearest_point(trail[-1], pts)[1] if len(pts) > 1 else (float(pts[0, 0]), float(pts[0, 1]))
        d, s, total = closest_approach(trail, p)
        if d <= PASS_NEAR_M and total - s >= PASSED_BEYOND_M:
            passed.append((s, e))
    if not passed:
        raise GroundingError(f"I don't remember passing any {noun} on the way I drove; name it instead, "
                             "e.g. by the label on the map ('door 2').")
    last = max(s for s, _ in passed)
    tied = [e for s, e in passed if s >= last - PASSED_TIE_M]
    if len(tied) > 1:
        # two passed at about the same point of the way (facing doors of a corridor): ask which
        names = " and ".join(e.id.replace("_", " ") for e in tied[:4])
        raise GroundingError(f"I passed {names} at about the same point; which one do you mean? Say e.g. "
                             f"'go back to {tied[0].id.replace('_', ' ')}'.")
    return tied[0]


def resolve_passed(ref: ElementRef, trail: list[Point], analysis: MapAnalysis) -> ElementRef:
    """'the door you just passed' as a reference by label (the element it turned out to be)."""
    e = passed_element(ref, trail, elements_of_kind(analysis, ref.kind))
    number = int(e.id.rsplit("_", 1)[1])
    return ref.model_copy(update={"passed": False, "label": number, "side": None, "also_side": None, "ordinal": None,
                                  "superlative": None})


# ------------------------------------------------------------------------------ named places
def find_named(name: str, named: dict[str, NamedPlace]) -> NamedPlace:
    place = named.get(place_key(name))
    if place is None:
        known = ", ".join(f"'{p.name}'" for p in sorted(named.values(), key=lambda p: p.key))
        raise GroundingError(f"I don't know a place called '{name}'; name it first: 'call this spot the "
                             f"{place_key(name)}'." + (f" The places I know: {known}." if known else ""))
    return place


def named_space(place: NamedPlace, analysis: MapAnalysis) -> Room | None:
    """The room or hallway a named room / hallway is (the space holding its point now)."""
    if place.kind not in ("room", "hallway"):
        return None
    if place.element_id is not None:
        for r in analysis.rooms:
            if r.id == place.element_id and (len(r.cells_xy) == 0 or nearest_point(place.xy, r.cells_xy)[0] < 1.0):
                return r
    return space_of(analysis, place.xy)


#: A named element is still that element when it lies within this distance of where it was named
#: (element ids stay while the map grows; this guards against an id given to something else).
NAMED_ELEMENT_MOVED_MAX_M: Final = 1.0


def named_element(place: NamedPlace, analysis: MapAnalysis) -> Element | None:
    """The element a named place was given to, when the map still has it where it was."""
    if place.element_id is None:
        return None
    try:
        e = analysis.by_id(place.element_id)
    except KeyError:
        return None
    if isinstance(e, Room):
        near = nearest_point(place.xy, e.cells_xy)[0] if len(e.cells_xy) else math.dist(place.xy, e.centroid)
    elif isinstance(e, Wall):
        near = math.dist(place.xy, closest_on_segment(place.xy, e.start, e.end))
    else:
        near = math.dist(place.xy, element_point(e))
    return e if near <= NAMED_ELEMENT_MOVED_MAX_M else None


def place_for_element(name: str, e: Element) -> NamedPlace:
    """A named place for an element of the map ("name it" on a door in the web app): its kind, id and
    point. Raises BadPlaceName for a name that cannot be a place's name."""
    if isinstance(e, Room):
        kind = "hallway" if e.kind == ElementKind.HALLWAY else "room"
    else:
        kind = {Door: "door", Wall: "wall", Corner: "corner", Obstacle: "obstacle", NarrowPassage: "narrow_passage",
                UnexploredArea: "unexplored_area"}[type(e)]
    x, y = element_point(e)
    return NamedPlace.element(name, kind, e.id, x, y)


def element_point(e: Element) -> Point:
    """The point stored for a named element: its reference point; for a room, a free cell near its
    centroid (the centroid of an L-shaped room may lie outside it)."""
    if isinstance(e, Room) and len(e.cells_xy):
        return nearest_point(e.centroid, e.cells_xy)[1]
    if isinstance(e, Corner):
        return e.approach
    return reference_point(e)


__all__ = [
    "Anchor",
    "Way",
    "compass_word",
    "element_extent",
    "element_point",
    "facing_point",
    "facing_turn",
    "find_named",
    "fraction_goal",
    "fraction_words",
    "named_space",
    "offset_anchor",
    "offset_goal",
    "passed_element",
    "resolve_passed",
    "return_point",
    "select",
    "select_wall",
    "spaces_joined",
]
