"""Intent + map analysis + robot pose -> robot commands, coordinates computed here, step by step.

Each step is read from where the earlier steps leave the robot: a NavigateThroughPoses ends at its
last pose, heading along its last segment; Move and Rotate update the pose. The meanings of the
words are those of ``../shared/bench/README.md``; every goal is a free cell at least
``params.goal_clearance_m`` from occupied and unknown cells and reachable from the robot.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import Final, Literal

import numpy as np
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
    reference_point,
)
from langnav.analysis.params import AnalysisParams
from langnav.grounding import compose
from langnav.grounding.errors import GroundingError
from langnav.grounding.geometry import (
    BoolArray,
    FloatArray,
    FreeSpace,
    Point,
    Pose,
    free_space_for,
    nearest_point,
    room_mask,
    segment_distances,
    unit,
)
from langnav.grounding.history import EMPTY_HISTORY, HistoryView
from langnav.grounding.relations import hall_axis
from langnav.grounding.selection import (
    WallLine,
    came_through_doors,
    describe_ref,
    doors_of,
    gap_joined,
    hallway_parts,
    label_of,
    mostly_hallway,
    select,
    select_pair,
    select_wall,
    space_of,
)
from langnav.grounding.walking import walk_from
from langnav.language.intent import (
    Amount,
    Detail,
    Direction,
    ElementRef,
    Intent,
    Movement,
    Offset,
    Place,
    Query,
    Step,
    Superlative,
)
from langnav.language.intent import Element as Kind
from langnav.places.store import NamedPlace, place_key
from langnav.plan.commands import (
    MAX_MOVE_STEPS,
    MOVE_STEP_M,
    ROTATE_STEP_DEG,
    Command,
    GetCurrentPath,
    GetMap,
    GetRobotPoseLast,
    Move,
    NavigateThroughPoses,
    Rotate,
    Stop,
    steps_for_angle,
    steps_for_distance,
)

# -- distances of the goals, each inside the README's tolerance with room to snap to a free cell ---
#: "to the door": stand this far before the door centre, on the robot's side (README: within 0.75 m).
DOOR_STANDOFF_M: Final = 0.4
DOOR_GOAL_MAX_M: Final = 0.65
#: "through": a pose this far before the opening, then one this far past it (README: within 2 m).
THROUGH_BEFORE_M: Final = 0.5
THROUGH_BEYOND_M: Final = 0.8
THROUGH_MIN_PAST_M: Final = 0.3
THROUGH_MAX_M: Final = 1.8
#: A door's opening is as deep as the thing it is cut in: a wall is at most WALL_DEEP_M thick, so an
#: opening whose sides run on farther (a gap between two parked cars, a cupboard row, a deep reveal)
#: is passed only past their far end. Its sides are looked for REVEAL_PROBE_M beside the opening's
#: edges, along the door's normal up to REVEAL_MAX_M from its centre (deeper is a passage, not a door);
#: a side is there when something blocks within REVEAL_SIDE_M of the probe (a measured width is a
#: cell or two off on a noisy map, and a thin wall's face is within that of a probe just past it).
WALL_DEEP_M: Final = 0.35
REVEAL_PROBE_M: Final = 0.1
REVEAL_SIDE_M: Final = 0.15
REVEAL_MAX_M: Final = 1.0
#: "to the corner": README 1.0 m from the meeting point of the walls.
CORNER_GOAL_MAX_M: Final = 0.9
#: "next to X": stand this far from X's edge, never farther than NEXT_TO_MAX_M (README: 1.0 m).
NEXT_TO_STANDOFF_M: Final = 0.45
NEXT_TO_MAX_M: Final = 0.9
#: The straight run of a hallway sets off along the hallway's axis this many hallway widths along the
#: walk: past a junction the robot may stand in, on the middle line the walk reaches within a width.
RUN_HEAD_WIDTHS: Final = 2.0
#: Stepping into a hallway, the robot passes a point of its walk this far before the spot where it
#: stops: it ends facing the way it came in (across the hallway from a room's door), so "then the
#: first door on your left" is read as a person stepping out of the room would.
INTO_HALL_LEAD_M: Final = 1.0
#: Beside a side of a thing, at least this far in from the side's ends (about the robot's radius:
#: level with the side, not off the corner).
NEXT_TO_FACE_INSET_M: Final = 0.25
#: "towards an unexplored area": README about 1.0 m from its frontier.
FRONTIER_GOAL_MAX_M: Final = 0.9
#: The piece of an unexplored area's edge one goes towards: its cells within this of the nearest one
#: (about a wide doorway's width: the opening it is seen through, or the end of a hallway).
FRONTIER_PIECE_M: Final = 1.5
#: A person going towards the unknown stops about this short of its edge, on the side they came from.
FRONTIER_STANDOFF_M: Final = 0.5
#: A piece of edge whose cells all lie within this of one line is a straight edge (an opening, a
#: hallway's end), which a person stops square in front of: three map cells, for the staircase of a
#: line drawn at an angle and a cell of scan noise on either side; a corner's two faces are not.
FRONTIER_STRAIGHT_TOL_M: Final = 0.15
#: A side of an unscanned block is one a person stops in front of when at least this long (m: about
#: the robot's width).
FRONTIER_FACE_MIN_M: Final = 0.5
#: A piece of edge goes round a block's corner when its two sides facing the robot hold this share
#: of its cells (a ragged edge between laser rays does not).
FRONTIER_CORNER_MIN_SHARE: Final = 0.9
#: ... unless they come at it nearly in its line (within ~78 deg of along it, cos 0.2): then towards them.
FRONTIER_IN_LINE_MAX_COS: Final = 0.2
#: frontier cells tried (nearest first) before giving up on an area.
FRONTIER_TRIES: Final = 400
#: "middle of the room", "between A and B": README 0.75 m.
MIDDLE_GOAL_MAX_M: Final = 0.65
#: "along the wall": README within 1.0 m of the wall; poses every ALONG_SPACING_M, the last one
#: ALONG_END_MARGIN_M before the wall's end.
ALONG_OFFSET_M: Final = 0.5
ALONG_MAX_M: Final = 0.9
ALONG_SPACING_M: Final = 2.5
ALONG_END_MARGIN_M: Final = 0.5
ALONG_MIN_RUN_M: Final = 1.0
ALONG_BACKOFF_M: Final = 0.2
#: "follow the hallway": facing within ~78 deg of across it (cos 0.2), the robot faces neither way
#: along it, and the longer way is taken.
FACING_ALONG_MIN: Final = 0.2
#: ... the way back is shut within the hallway's width and this much more of the robot, so the walk
#: sets off the way the robot faces.
FOLLOW_CLOSE_MARGIN_M: Final = 0.5
#: ... each pose within this much along the way of its point (half a hallway's width) ...
FOLLOW_BAND_M: Final = 0.5
#: ... and within this distance of it, in the hallway.
FOLLOW_SNAP_M: Final = 1.0
#: A point is moved onto the hallway's middle line only where the hallway runs along the way (within
#: ~25 deg): at a bend the local direction of the hallway is no direction of the way.
MIDDLE_LINE_MIN_COS: Final = 0.9
#: "a little": README 0.15-0.5 m and 10-40 deg.
LITTLE_MOVE_M: Final = 0.3
LITTLE_TURN_DEG: Final = 20.0
#: "turn left" alone is a quarter turn; "move forward" alone is one metre.
DEFAULT_TURN_DEG: Final = 90.0
DEFAULT_MOVE_M: Final = 1.0
#: Named places: the goal lies within this distance of the remembered point.
NAMED_PLACE_MAX_M: Final = compose.NAMED_PLACE_MAX_M
#: "opposite side of a room": the far third (README).
OPPOSITE_FRACTION: Final = 2.0 / 3.0
#: "The opposite side of the room" is by its far wall: this far from it (clear of the wall, and
#: deep in the far third of any room wider than a corridor).
OPPOSITE_WALL_STANDOFF_M: Final = 0.6
#: A room's walls run in one direction (modulo a quarter turn) when their length-weighted
#: directions agree this much (1: all square to each other; a round or many-sided room: near 0).
WALL_RUN_MIN_AGREEMENT: Final = 0.5
#: Two points of the robot's way closer than this are the same point: a millimetre, far below a
#: cell, and above the error of the poses' rounding to 3 decimals (at most 0.7 mm).
SAME_POINT_M: Final = 1e-3


@dataclass(frozen=True)
class GroundedStep:
    """One intent step made concrete. ``explore`` marks frontier exploration: the executor keeps
    choosing frontiers after the first goal until none is left."""

    index: int
    step: Step
    commands: tuple[Command, ...]
    start_pose: Pose
    end_pose: Pose
    note: str
    element_ids: tuple[str, ...] = ()
    explore: bool = False
    messages: tuple[str, ...] = ()
    #: "call this spot the kitchen": the place to remember once the plan is accepted
    name_place: NamedPlace | None = None
    #: ... and what that name is given to, in words ("this spot (3.0, 3.0)", "door 2")
    named_what: str = ""
    #: "forget the kitchen": the name to drop once the plan is accepted
    forget_place: str | None = None
    #: "what places do you know?": the answer is the store's list
    list_places: bool = False

    @property
    def moves(self) -> bool:
        return any(isinstance(c, NavigateThroughPoses | Move | Rotate) for c in self.commands)


@dataclass(frozen=True)
class GroundedPlan:
    steps: tuple[GroundedStep, ...]
    start_pose: Pose
    messages: tuple[str, ...] = field(default=())

    @property
    def commands(self) -> list[Command]:
        return [c for s in self.steps for c in s.commands]

    @property
    def end_pose(self) -> Pose:
        return self.steps[-1].end_pose if self.steps else self.start_pose


def as_pose(pose: Pose | Sequence[float]) -> Pose:
    """A Pose, or (x_m, y_m, yaw_deg) as the bench and the CLI give it."""
    if isinstance(pose, Pose):
        return pose
    x, y, yaw = (float(v) for v in pose)
    if not all(math.isfinite(v) for v in (x, y, yaw)):
        raise GroundingError(f"the robot pose {tuple(pose)} is not a finite (x, y, yaw) triple")
    return Pose.from_deg(x, y, yaw)


def named_place_table(named_places: Mapping[str, Point | NamedPlace] | None) -> dict[str, NamedPlace]:
    """Named places by key; bare points (x, y) are spots."""
    out: dict[str, NamedPlace] = {}
    for name, v in (named_places or {}).items():
        place = v if isinstance(v, NamedPlace) else NamedPlace(" ".join(name.split()), float(v[0]), float(v[1]))
        out[place_key(name)] = place
    return out


def ground(intent: Intent, analysis: MapAnalysis, pose: Pose | Sequence[float], *,
           params: AnalysisParams | None = None,
           named_places: Mapping[str, Point | NamedPlace] | None = None,
           history: HistoryView | None = None) -> GroundedPlan:
    """Every step of ``intent`` as commands, each read from where the previous ones leave the robot.
    ``pose`` is also the prompt's start ("go back to where you started"); ``history`` is where the
    robot drove before this prompt ("the door you just passed", "back to where you were").

    Raises GroundingError with a sentence for the user when a step names something the map
    does not have, or asks for something unsafe (a move into a wall).
    """
    if intent.clarification and not intent.steps:
        raise GroundingError(intent.clarification)
    if not intent.steps:
        raise GroundingError("I did not find an instruction in that; tell me where to go, e.g. "
                             "'go to the nearest door'.")
    p = params or analysis.params
    start = as_pose(pose)
    ctx = GroundingContext(analysis, free_space_for(analysis.grid, p), p, named_place_table(named_places),
                           origin=start, history=history or EMPTY_HISTORY, route=[start.xy])
    steps: list[GroundedStep] = []
    cur = start
    for i, step in enumerate(intent.steps):
        prev = steps[-1] if steps else None
        gs = ground_step(_room_entered(_same_element_as_before(step, prev), prev, analysis), ctx, cur, i)
        steps.append(gs)
        ctx.advance(gs)
        cur = gs.end_pose
    return GroundedPlan(tuple(steps), start)


@dataclass
class GroundingContext:
    """What every step is grounded against: the analysis, its free space, thresholds, named places."""

    analysis: MapAnalysis
    space: FreeSpace
    params: AnalysisParams
    named: dict[str, NamedPlace]
    #: where the robot stood when the prompt began (``Place.START``); None when not known
    origin: Pose | None = None
    #: where the robot drove before this prompt, and the trips it made
    history: HistoryView = EMPTY_HISTORY
    #: this prompt's way so far: the start, then every pose the earlier steps drive through
    route: list[Point] = field(default_factory=list)
    #: where each earlier step of this prompt that moved the robot began
    moved_from: list[Pose] = field(default_factory=list)

    def advance(self, gs: GroundedStep) -> None:
        """Take a grounded step's way into account for the steps after it."""
        advance_way(self.route, self.moved_from, gs)

    def trail(self, pose: Pose) -> list[Point]:
        """The whole way driven up to ``pose``, oldest first."""
        pts = [*self.history.trail, *self.route]
        if not pts or math.dist(pts[-1], pose.xy) > SAME_POINT_M:
            pts.append(pose.xy)
        return pts


#: Words that point back at the element of the step before ("the middle of it", "go in there").
_BACK_REF_RE: Final = re.compile(r"\b(?:it|there|that|that one|this one|that room|this room|them)\b", re.IGNORECASE)
#: "The next room" (``_room_entered``).
_NEXT_RE: Final = re.compile(r"\bnext\b", re.IGNORECASE)
#: The id prefixes that the label words of each kind name (``select_by_label``).
_LABEL_PREFIXES: Final = {Kind.ROOM: ("room", "hallway"), Kind.HALLWAY: ("room", "hallway"), Kind.DOOR: ("door",),
                          Kind.OBSTACLE: ("obstacle",), Kind.CORNER: ("corner",)}


def _same_element_as_before(step: Step, prev: GroundedStep | None) -> Step:
    """"Go into the first room on your left and then go to the middle of it": the reader gives "it"
    the words of the element before, but from inside that room they would pick another one; the
    words point back at the element the step before went to, so it is named by its label (which
    also holds when the step is grounded again later, from wherever the robot is then)."""
    ref = step.target
    if prev is None or ref is None or prev.step.target != ref or len(prev.element_ids) != 1 \
            or not _BACK_REF_RE.search(step.text) or ref.label is not None:
        return step
    element_id = prev.element_ids[0]
    prefix, _, number = element_id.rpartition("_")
    if not number.isdigit() or prefix not in _LABEL_PREFIXES.get(ref.kind, ()):
        return step
    return step.model_copy(update={"target": ElementRef(kind=ref.kind, label=int(number))})


def _room_entered(step: Step, prev: GroundedStep | None, analysis: MapAnalysis) -> Step:
    """"Go through the door in front and stop in the middle of the next room": right after a step
    through a door, "the next room" is the room that door leads into, where the robot now stands (a
    person who has just stepped through a doorway calls the room in front of them the next one).
    Read as "the nearest room other than the one I am in" it would be a third room."""
    ref = step.target
    if prev is None or ref is None or ref.kind != Kind.ROOM or ref.superlative != Superlative.NEAREST \
            or ref.side is not None or ref.ordinal is not None or ref.label is not None or ref.relation is not None \
            or ref.near is not None or not _NEXT_RE.search(step.text):
        return step
    before = prev.step.target
    if prev.step.detail != Detail.THROUGH or before is None or before.kind not in (Kind.DOOR, Kind.NARROW_PASSAGE) \
            or len(prev.element_ids) != 1 or not prev.moves:
        return step
    ways: list[Door | NarrowPassage] = [*analysis.doors, *analysis.narrow_passages]
    door = next((d for d in ways if d.id == prev.element_ids[0]), None)
    room = space_of(analysis, prev.end_pose.xy)
    if door is None or room is None or room.id not in door.connects:
        return step
    number = room.id.rpartition("_")[2]
    if not number.isdigit():
        return step
    return step.model_copy(update={"target": ElementRef(kind=Kind.ROOM, label=int(number))})


def advance_way(route: list[Point], moved_from: list[Pose], gs: GroundedStep) -> None:
    """Add a grounded step's way to a prompt's ``route`` (the start, then every pose driven through)
    and, when it moved the robot, its start to ``moved_from``. The planner keeps these per step for
    re-grounding; ``GroundingContext`` keeps them while grounding: one bookkeeping for both."""
    if not gs.moves:
        return
    if math.dist(gs.start_pose.xy, gs.end_pose.xy) > SAME_POINT_M:
        moved_from.append(gs.start_pose)
    if not route:
        route.append(gs.start_pose.xy)
    for c in gs.commands:
        if isinstance(c, NavigateThroughPoses):
            route.extend((float(q[0]), float(q[1])) for q in c.poses)
    if math.dist(route[-1], gs.end_pose.xy) > SAME_POINT_M:
        route.append(gs.end_pose.xy)


def ground_step(step: Step, ctx: GroundingContext, pose: Pose, index: int = 0) -> GroundedStep:
    """One step from ``pose``."""
    m = step.movement
    if m in (Movement.NAME_PLACE, Movement.FORGET_PLACE) or (m == Movement.QUERY and step.query == Query.PLACES):
        return _place_step(step, ctx, pose, index)
    step = _resolved(step, ctx, pose)
    if m == Movement.ROTATE and step.target is not None and step.heading_deg is None:
        return _face(step, ctx, pose, index)
    if m == Movement.STOP:
        return GroundedStep(index, step, (Stop(note="stop now"),), pose, pose, "stop now")
    if m == Movement.QUERY:
        cmd: Command
        if step.query == Query.PATH:
            cmd = GetCurrentPath(note="report the path I am following")
        elif step.query == Query.MAP:
            cmd = GetMap(note="show the map")
        else:
            cmd = GetRobotPoseLast(note="report where I am")
        return GroundedStep(index, step, (cmd,), pose, pose, cmd.note)
    if m == Movement.ROTATE or (m == Movement.MOVE and step.direction == Direction.AROUND):
        return _rotate(step, pose, index)
    if m == Movement.MOVE or (m == Movement.NAVIGATE and step.target is None and step.direction is not None):
        return _move(step, ctx, pose, index)
    if m == Movement.EXPLORE:
        return _explore(step, ctx, pose, index)
    return _navigate(step, ctx, pose, index)


# ------------------------------------------------------------------------------ rotate / move
def _rotate(step: Step, pose: Pose, index: int) -> GroundedStep:
    if step.heading_deg is not None:
        return _face_heading(step, pose, index)
    d = step.direction
    direction: Literal["left", "right"]
    if d == Direction.AROUND:
        angle = step.angle_deg if step.angle_deg else 180.0
        direction = "left"
    elif d in (Direction.LEFT, Direction.RIGHT):
        direction = "left" if d == Direction.LEFT else "right"
        if step.angle_deg is not None:
            angle = step.angle_deg
        elif step.amount == Amount.LITTLE:
            angle = LITTLE_TURN_DEG
        else:
            angle = DEFAULT_TURN_DEG
    else:
        raise GroundingError("Which way should I turn, left or right?")
    if angle <= 0:
        raise GroundingError("A turn of 0 degrees does nothing; say how far to turn, e.g. 'turn left 45 degrees'.")
    n = steps_for_angle(angle)
    sign = 1.0 if direction == "left" else -1.0
    end = Pose(pose.x_m, pose.y_m, pose.yaw_rad + sign * math.radians(n * ROTATE_STEP_DEG))
    note = "turn around" if d == Direction.AROUND else f"turn {direction} {angle:g}°"
    return GroundedStep(index, step, (Rotate(direction=direction, repeat=n, note=note),), pose, end, note)


def _face_heading(step: Step, pose: Pose, index: int) -> GroundedStep:
    """'face north': one turn the shorter way from the heading the robot has now (README "Compass"),
    as 'face the door' turns (``compose.facing_turn``); nothing when it already faces that way."""
    heading = float(step.heading_deg or 0.0)
    cmd, end, note = compose.facing_turn(pose, math.radians(heading), compose.compass_word(heading))
    if cmd is None:
        return GroundedStep(index, step, (), pose, pose, note, messages=(note + ".",))
    return GroundedStep(index, step, (cmd,), pose, end, note)


MoveDir = Literal["forward", "backward", "left", "right"]
_MOVE_HEADING: Final[dict[Direction, tuple[MoveDir, float]]] = {
    Direction.FORWARD: ("forward", 0.0), Direction.BACKWARD: ("backward", math.pi),
    Direction.LEFT: ("left", math.pi / 2), Direction.RIGHT: ("right", -math.pi / 2)}


def _move(step: Step, ctx: GroundingContext, pose: Pose, index: int) -> GroundedStep:
    d = step.direction or Direction.FORWARD
    if d not in _MOVE_HEADING:
        raise GroundingError(f"I can move forward, backward, left or right, not {d.value}.")
    if step.distance_m is not None:
        dist = step.distance_m
    elif step.amount == Amount.LITTLE:
        dist = LITTLE_MOVE_M
    else:
        dist = DEFAULT_MOVE_M
    if dist <= 0:
        raise GroundingError("A move of 0 m does nothing; say how far, e.g. 'move forward 1 meter'.")
    n = steps_for_distance(dist)
    if n > MAX_MOVE_STEPS:
        # One Move goes at most 30 m (plan.commands): farther is a trip to a place, which the
        # robot plans round obstacles, not a straight blind drive.
        raise GroundingError(
            f"Moving {d.value} {dist:g} m is farther than I drive straight in one go "
            f"({MAX_MOVE_STEPS * MOVE_STEP_M:g} m at most); name a place to go to, or say a shorter "
            "distance. Nothing was run.")
    real = n * MOVE_STEP_M
    word, offset = _MOVE_HEADING[d]
    a = pose.yaw_rad + offset
    end_xy = (pose.x_m + real * math.cos(a), pose.y_m + real * math.sin(a))
    clear, free_run = ctx.space.segment_clear(pose.xy, end_xy, ctx.params.robot_radius_m)
    if not clear:
        here = ctx.space.standing_problem(pose.x_m, pose.y_m)
        if here is not None:
            raise GroundingError(
                f"I can't move from ({pose.x_m:.2f}, {pose.y_m:.2f}): that position is {here}. Check that "
                "my pose on the map is right; nothing was run.")
        safe = max(0.0, free_run - 0.05)
        raise GroundingError(
            f"Moving {d.value} {dist:g} m would take me into a wall or an obstacle after about "
            f"{free_run:.1f} m; I can safely move {d.value} at most {safe:.1f} m here. Nothing was run.")
    note = f"move {d.value} {dist:g} m"
    return GroundedStep(index, step, (Move(direction=word, repeat=n, note=note),), pose,
                        Pose(end_xy[0], end_xy[1], pose.yaw_rad), note)


# ------------------------------------------------------------------------------ navigation
def _component(ctx: GroundingContext, pose: Pose) -> int:
    comp = ctx.space.component_at(pose.x_m, pose.y_m)
    if comp == 0:
        where = ctx.space.standing_problem(pose.x_m, pose.y_m)
        raise GroundingError(
            f"I find no free space around my position ({pose.x_m:.2f}, {pose.y_m:.2f})"
            + (f", which is {where}" if where else "")
            + "; check that my pose on the map is right before sending me anywhere.")
    return comp


def _nav_step(step: Step, pose: Pose, index: int, poses: list[Point], note: str,
              ids: tuple[str, ...] = (), explore: bool = False, messages: tuple[str, ...] = ()) -> GroundedStep:
    cmd = NavigateThroughPoses(poses=[[round(x, 3), round(y, 3)] for x, y in poses], note=note)
    prev = pose.xy if len(poses) == 1 else poses[-2]
    last = poses[-1]
    yaw = math.atan2(last[1] - prev[1], last[0] - prev[0]) if math.dist(prev, last) > 1e-6 else pose.yaw_rad
    return GroundedStep(index, step, (cmd,), pose, Pose(last[0], last[1], yaw), note, ids, explore, messages)


def _navigate(step: Step, ctx: GroundingContext, pose: Pose, index: int) -> GroundedStep:
    """A trip to, through, along ... a place; with an offset ("2 m past the door") or a fraction of the
    way ("halfway to the door") when the words give one."""
    if step.offset is not None:
        return _offset_step(step, ctx, pose, index)
    along = step.movement == Movement.FOLLOW or step.detail == Detail.ALONG
    if step.fraction is not None and not along:
        full = _navigate_full(step.model_copy(update={"fraction": None}), ctx, pose, index)
        last = _last_goal(full)
        if last is None:
            return full
        desc = full.note.split(" ", 1)[1] if " " in full.note else full.note
        goal = compose.fraction_goal(last, step.fraction, pose, ctx.space.safe_point_near, _component(ctx, pose), desc)
        return _nav_step(step, pose, index, [goal], f"{compose.fraction_words(step.fraction)} {full.note}",
                         full.element_ids)
    return _navigate_full(step, ctx, pose, index)


def _last_goal(gs: GroundedStep) -> Point | None:
    navs = [c for c in gs.commands if isinstance(c, NavigateThroughPoses)]
    return (float(navs[-1].poses[-1][0]), float(navs[-1].poses[-1][1])) if navs else None


def _navigate_full(step: Step, ctx: GroundingContext, pose: Pose, index: int) -> GroundedStep:
    ref = step.target
    detail = step.detail or Detail.TO
    if ref is None and step.movement == Movement.FOLLOW:
        here = space_of(ctx.analysis, pose.xy)
        hall = here is not None and here.kind == ElementKind.HALLWAY
        ref = ElementRef(kind=Kind.HALLWAY if hall else Kind.ROOM, in_current_room=True)
    if ref is None:
        if detail in (Detail.MIDDLE, Detail.OPPOSITE_SIDE_OF):
            ref = ElementRef(kind=Kind.ROOM, in_current_room=True)
        else:
            raise GroundingError("Where should I go? Name a place on the map, e.g. 'the door on your left'.")
    if ref.place in (Place.START, Place.PREVIOUS):
        return _to_return(step, ref.place, ctx, pose, index)
    comp = _component(ctx, pose)
    if ref.name and detail != Detail.BETWEEN:
        return _to_named(step, ref.name, detail, ctx, pose, comp, index)
    if detail == Detail.BETWEEN:
        return _between(step, ref, ctx, pose, comp, index)
    if step.movement == Movement.FOLLOW or detail == Detail.ALONG:
        if ref.kind == Kind.WALL:
            return _along_wall(step, ref, ctx, pose, comp, index)
        if ref.kind in (Kind.HALLWAY, Kind.ROOM):
            return _follow_space(step, ref, ctx, pose, comp, index)
        raise GroundingError(f"I can follow a wall or a hallway, not {describe_ref(ref)}.")
    if ref.kind == Kind.WALL:
        wall = select_wall(ref, ctx.analysis, pose)
        goal = _next_to_wall(wall, ctx, pose, comp)
        return _nav_step(step, pose, index, [goal], f"next to {describe_ref(ref)}", wall.ids)
    if ref.kind in (Kind.ROOM, Kind.HALLWAY) and detail in (Detail.MIDDLE, Detail.OPPOSITE_SIDE_OF, Detail.TO,
                                                          Detail.STOP_AT, Detail.TOWARDS, Detail.NEXT_TO,
                                                          Detail.THROUGH):
        room = select(ref, ctx.analysis, pose)
        assert isinstance(room, Room)
        return _room_goal(step, ref, room, detail, ctx, pose, comp, index)
    if ref.kind == Kind.UNEXPLORED_AREA and detail == Detail.MIDDLE:
        detail = Detail.TOWARDS
    last_leg = (ctx.route[-2], ctx.route[-1]) if len(ctx.route) >= 2 else None
    e = select(ref, ctx.analysis, pose, step.text, came_through_doors(ctx.analysis, pose, last_leg))
    desc = describe_ref(ref)
    if detail == Detail.THROUGH and isinstance(e, Door | NarrowPassage):
        poses = _through(e, ctx, pose, comp, desc)
        return _nav_step(step, pose, index, poses, f"through {desc}", (e.id,))
    goal = _goal_at(e, detail, ctx, pose, comp, desc)
    verb = {Detail.NEXT_TO: "next to", Detail.TOWARDS: "towards"}.get(detail, "to")
    return _nav_step(step, pose, index, [goal], f"{verb} {desc}", (e.id,))


def _to_return(step: Step, place: Place, ctx: GroundingContext, pose: Pose, index: int) -> GroundedStep:
    """'Go back', 'return to where you started', 'back to where you were' (see grounding.compose)."""
    h = ctx.history
    target, words = compose.return_point(place, pose, ctx.origin, tuple(ctx.moved_from), h.session_start,
                                         h.last_trip_start_away_from(pose.xy))
    if target is None:
        note = f"I am already {words}"
        return GroundedStep(index, step, (), pose, pose, note, messages=(note + ".",))
    comp = _component(ctx, pose)
    goal = ctx.space.safe_point_near(target.xy, comp, NAMED_PLACE_MAX_M)
    if goal is None:
        raise GroundingError(f"I cannot get back to {words} ({target.x_m:.1f}, {target.y_m:.1f}): "
                             "no free space I can reach is near it.")
    return _nav_step(step, pose, index, [goal], f"back to {words}")


def _to_named(step: Step, name: str, detail: Detail, ctx: GroundingContext, pose: Pose, comp: int,
              index: int) -> GroundedStep:
    """A place the user named: a spot (reached facing its heading when it has one) or a room."""
    place = compose.find_named(name, ctx.named)
    element = compose.named_element(place, ctx.analysis)
    if element is not None and place.kind not in ("room", "hallway", "spot"):
        # "go through the front door": the element the name was given to, read like its label
        as_label = ElementRef(kind=Kind(place.kind), label=_label_number(element.id))
        gs = _navigate_full(step.model_copy(update={"target": as_label}), ctx, pose, index)
        return GroundedStep(gs.index, step, gs.commands, gs.start_pose, gs.end_pose,
                            gs.note.replace(describe_ref(as_label), f"'{place.name}' ({label_of(element)})"),
                            gs.element_ids, gs.explore, gs.messages)
    room = compose.named_space(place, ctx.analysis)
    if room is not None:
        ref = ElementRef(kind=Kind.HALLWAY if room.kind == ElementKind.HALLWAY else Kind.ROOM,
                         label=_label_number(room.id))
        gs = _room_goal(step, ref, room, detail if detail in (Detail.MIDDLE, Detail.OPPOSITE_SIDE_OF) else Detail.TO,
                        ctx, pose, comp, index)
        return GroundedStep(gs.index, gs.step, gs.commands, gs.start_pose, gs.end_pose,
                            gs.note.replace(describe_ref(ref), f"'{place.name}' ({label_of(room)})"),
                            gs.element_ids, gs.explore, gs.messages)
    if place.kind != "spot" and detail == Detail.NEXT_TO:
        goal = ctx.space.safe_point_near(place.xy, comp, NEXT_TO_MAX_M)
    else:
        goal = ctx.space.safe_point_near(place.xy, comp, NAMED_PLACE_MAX_M)
    if goal is None:
        raise GroundingError(f"I cannot reach '{place.name}' from here: no free space I can get to near it "
                             f"({place.x_m:.1f}, {place.y_m:.1f}).")
    gs = _nav_step(step, pose, index, [goal], f"to '{place.name}'")
    if place.yaw_deg is None or place.kind != "spot":
        return gs
    cmd = NavigateThroughPoses(poses=[[round(goal[0], 3), round(goal[1], 3), round(place.yaw_deg, 1)]],
                               note=gs.note)
    end = Pose(goal[0], goal[1], math.radians(place.yaw_deg))
    return GroundedStep(index, step, (cmd,), pose, end, gs.note)


def _label_number(element_id: str) -> int | None:
    tail = element_id.rsplit("_", 1)[-1]
    return int(tail) if tail.isdigit() else None


def _point_of(ref: ElementRef, ctx: GroundingContext, pose: Pose, words: str) -> tuple[Point, str, tuple[str, ...]]:
    """A reference's point (named places, returns and elements alike), its words and element ids."""
    if ref.name:
        place = compose.find_named(ref.name, ctx.named)
        return place.xy, f"'{place.name}'", ()
    if ref.place in (Place.START, Place.PREVIOUS):
        h = ctx.history
        target, said = compose.return_point(ref.place, pose, ctx.origin, tuple(ctx.moved_from), h.session_start,
                                            h.last_trip_start_away_from(pose.xy))
        return (target or pose).xy, said, ()
    if ref.kind == Kind.WALL:
        line = select_wall(ref, ctx.analysis, pose)
        return compose.closest_on_segment(pose.xy, line.start, line.end), describe_ref(ref), line.ids
    e = select(ref, ctx.analysis, pose, words)
    return reference_point(e), describe_ref(ref), (e.id,)


def _resolved(step: Step, ctx: GroundingContext, pose: Pose) -> Step:
    """'The door you just passed' as the element it is, by label, from the trail driven so far."""
    update: dict[str, ElementRef] = {}
    for key in ("target", "second_target"):
        ref = getattr(step, key)
        if ref is not None and ref.passed:
            update[key] = compose.resolve_passed(ref, ctx.trail(pose), ctx.analysis)
    return step.model_copy(update=update) if update else step


def _face(step: Step, ctx: GroundingContext, pose: Pose, index: int) -> GroundedStep:
    """'Turn to face the door': one rotation the shorter way ('face north' is ``_face_heading``)."""
    ids: tuple[str, ...] = ()
    ref = step.target
    assert ref is not None
    if ref.name or ref.place is not None or ref.kind == Kind.WALL:
        point, what, ids = _point_of(ref, ctx, pose, step.text)
    elif ref.kind == Kind.NONE:
        raise GroundingError("Which way should I face? Name a place, e.g. 'face the door' or 'face north'.")
    else:
        e = select(ref, ctx.analysis, pose, step.text)
        here = space_of(ctx.analysis, pose.xy)
        if e is here:
            raise GroundingError(f"I am in {label_of(e)} already, so I cannot turn to face it; tell me what to face "
                                 "in it, e.g. 'face the door' or 'face north'.")
        point = compose.facing_point(e, pose, here, tuple(doors_of(ctx.analysis)))
        what, ids = describe_ref(ref), (e.id,)
    if math.dist(point, pose.xy) < compose.MIN_OFFSET_RUN_M:
        raise GroundingError(f"I am at {what}, so there is no way to turn to face it.")
    yaw = math.atan2(point[1] - pose.y_m, point[0] - pose.x_m)
    cmd, end, note = compose.facing_turn(pose, yaw, what)
    if cmd is None:
        return GroundedStep(index, step, (), pose, pose, note, ids, messages=(note + ".",))
    return GroundedStep(index, step, (cmd,), pose, end, note, ids)


def _offset_step(step: Step, ctx: GroundingContext, pose: Pose, index: int) -> GroundedStep:
    """'Go 2 m past the door on your right', 'stop 1 m before the corner'."""
    ref = step.target
    if ref is None:
        raise GroundingError("Past or before what? Name the place, e.g. 'stop 1 m before the door'.")
    comp = _component(ctx, pose)
    here = space_of(ctx.analysis, pose.xy)
    anchor: Element | Point
    ids: tuple[str, ...] = ()
    if ref.name or ref.place is not None or ref.kind == Kind.WALL:
        if ref.name and compose.named_space(compose.find_named(ref.name, ctx.named), ctx.analysis) is not None:
            raise GroundingError(f"'{ref.name}' is a room; I can stop past or before a door, a passage, a corner, "
                                 "an obstacle, a wall or a named spot, not a room.")
        anchor, desc, ids = _point_of(ref, ctx, pose, step.text)
    elif ref.kind in (Kind.ROOM, Kind.HALLWAY, Kind.UNEXPLORED_AREA, Kind.NONE):
        raise GroundingError(f"I can stop a distance past or before a door, a passage, a corner, an obstacle, a "
                             f"wall or a named spot, not {describe_ref(ref)}; say e.g. '2 m past the door'.")
    else:
        e = select(ref, ctx.analysis, pose, step.text)
        anchor, desc, ids = e, describe_ref(ref), (e.id,)
    goal, _ = compose.offset_goal(anchor, step, pose, here, desc, ctx.space.safe_point_near, comp,
                                 lambda space_id: _in_space_id(ctx, space_id))
    word = "past" if step.offset == Offset.PAST else "before"
    return _nav_step(step, pose, index, [goal], f"{step.offset_m:g} m {word} {desc}", ids)


def _place_step(step: Step, ctx: GroundingContext, pose: Pose, index: int) -> GroundedStep:
    """'Call this spot the kitchen', 'forget the kitchen', 'what places do you know?': no motion; the
    planner applies the change once the whole plan is accepted."""
    from langnav.places.errors import PlaceError

    if step.movement == Movement.QUERY:
        known = sorted(ctx.named.values(), key=lambda p: p.key)
        note = ("the places I know: " + ", ".join(f"'{p.name}'" for p in known)) if known else \
            "I know no named places yet; name one with e.g. 'call this spot the kitchen'"
        return GroundedStep(index, step, (), pose, pose, note, list_places=True)
    name = step.place_name or ""
    if step.movement == Movement.FORGET_PLACE:
        place = compose.find_named(name, ctx.named)
        return GroundedStep(index, step, (), pose, pose, f"forget '{place.name}'", forget_place=place.name)
    ref = step.target
    try:
        if ref is None or ref.kind == Kind.NONE:
            new = NamedPlace.spot(name, pose.x_m, pose.y_m, pose.yaw_deg % 360.0)
            what = f"this spot ({pose.x_m:.1f}, {pose.y_m:.1f})"
            ids: tuple[str, ...] = ()
        elif ref.kind == Kind.WALL:
            line = select_wall(ref, ctx.analysis, pose)
            mid = ((line.start[0] + line.end[0]) / 2, (line.start[1] + line.end[1]) / 2)
            new = NamedPlace.element(name, "wall", line.ids[0], *mid)
            what, ids = describe_ref(ref), line.ids
        else:
            e = select(ref, ctx.analysis, pose, step.text)
            new = compose.place_for_element(name, e)
            what = describe_ref(ref) if ref.label is not None else f"{describe_ref(ref)} ({label_of(e)})"
            ids = (e.id,)
    except PlaceError as exc:
        raise GroundingError(f"I can't use that name: {exc}.") from exc
    old = ctx.named.get(new.key)
    note = f"remember {what} as '{new.name}'" + (f" (it was ({old.x_m:.1f}, {old.y_m:.1f}) before)" if old else "")
    return GroundedStep(index, step, (), pose, pose, note, ids, name_place=new, named_what=what)


def _goal_at(e: Element, detail: Detail, ctx: GroundingContext, pose: Pose, comp: int, desc: str) -> Point:
    """The goal for 'to / at / next to / towards' an element (not rooms, walls)."""
    goal: Point | None
    if isinstance(e, Door):
        goal = _door_near_side(e, ctx, pose, comp)
    elif isinstance(e, Corner):
        goal = None
        if ctx.space.is_goal_ok(*e.approach, component=comp) and math.dist(e.approach, e.point) <= CORNER_GOAL_MAX_M:
            goal = ctx.space.cell_centre(*e.approach)
            if not ctx.space.is_goal_ok(*goal, component=comp):
                goal = None
        if goal is None:
            # in the corner's own room: a free spot as near behind its wall, in the next room, is
            # no corner of this one
            own = [r.label for r in ctx.analysis.rooms if r.id == e.room]
            goal = ctx.space.safe_point_near(e.point, comp, CORNER_GOAL_MAX_M, prefer=e.approach,
                                             where=_in_labels(ctx, tuple(own)) if own else None)
        if goal is None and ctx.space.is_goal_ok(*e.approach, component=comp):
            # furniture fills the corner: the nearest spot of the room the robot can stand on
            goal = e.approach
    elif isinstance(e, Obstacle):
        goal = _next_to_cells(e.cells_xy if len(e.cells_xy) else np.array([e.centroid]), ctx, pose, comp)
    elif isinstance(e, UnexploredArea):
        goal = _towards_frontier(e, ctx, pose, comp)
    elif isinstance(e, NarrowPassage):
        near = min(e.ends, key=lambda p: math.dist(p, pose.xy))
        goal = ctx.space.safe_point_near(near, comp, DOOR_GOAL_MAX_M, prefer=near)
    else:
        goal = ctx.space.safe_point_near(reference_point(e), comp, NEXT_TO_MAX_M)
    if goal is None:
        raise GroundingError(f"I cannot get to {desc}: there is no free space I can reach next to it.")
    return goal


def _door_normal(d: Door) -> Point:
    (ax, ay), (bx, by) = d.jambs
    if math.hypot(bx - ax, by - ay) > 1e-6:
        return unit((-(by - ay), bx - ax))
    if math.hypot(*d.normal) > 1e-6:
        return unit(d.normal)
    raise GroundingError(f"door {d.id} has no direction; the map analysis gave it neither jambs nor a normal")


def _robot_side_normal(centre: Point, normal: Point, pose: Pose) -> Point:
    """The door normal pointing to the robot's side of the opening."""
    s = (pose.x_m - centre[0]) * normal[0] + (pose.y_m - centre[1]) * normal[1]
    if abs(s) < 0.1:  # standing in the opening: the side it came from is behind its heading
        hx, hy = pose.heading()
        s = -(hx * normal[0] + hy * normal[1])
    return normal if s >= 0 else (-normal[0], -normal[1])


def _side_filter(centre: Point, n: Point, min_dot: float):  # type: ignore[no-untyped-def]
    def where(xs: FloatArray, ys: FloatArray) -> BoolArray:
        return np.asarray((xs - centre[0]) * n[0] + (ys - centre[1]) * n[1] >= min_dot, dtype=bool)
    return where


def _door_near_side(d: Door, ctx: GroundingContext, pose: Pose, comp: int) -> Point | None:
    n = _robot_side_normal(d.center, _door_normal(d), pose)
    prefer = (d.center[0] + n[0] * DOOR_STANDOFF_M, d.center[1] + n[1] * DOOR_STANDOFF_M)
    goal = ctx.space.safe_point_near(d.center, comp, DOOR_GOAL_MAX_M, prefer=prefer,
                                     where=_side_filter(d.center, n, 0.0))
    return goal or ctx.space.safe_point_near(d.center, comp, DOOR_GOAL_MAX_M, prefer=prefer)


def _through(e: Door | NarrowPassage, ctx: GroundingContext, pose: Pose, comp: int, desc: str) -> list[Point]:
    if isinstance(e, Door):
        n_near = _robot_side_normal(e.center, _door_normal(e), pose)
        n_out = (-n_near[0], -n_near[1])
        near_mouth = _mouth(e, n_near, ctx)
        far_mouth = _mouth(e, n_out, ctx)
    else:
        a, b = e.ends
        if math.dist(a, b) < 1e-6:
            raise GroundingError(f"{desc} has no length in the map analysis; I cannot tell its two ends apart")
        near_mouth, far_mouth = (a, b) if math.dist(a, pose.xy) <= math.dist(b, pose.xy) else (b, a)
        axis = unit((far_mouth[0] - near_mouth[0], far_mouth[1] - near_mouth[1]))
        n_near = (-axis[0], -axis[1])
    n_far = (-n_near[0], -n_near[1])
    beyond_t = (far_mouth[0] + n_far[0] * THROUGH_BEYOND_M, far_mouth[1] + n_far[1] * THROUGH_BEYOND_M)
    beyond = ctx.space.safe_point_near(far_mouth, comp, THROUGH_MAX_M, prefer=beyond_t,
                                       where=_side_filter(far_mouth, n_far, THROUGH_MIN_PAST_M))
    if beyond is None:
        raise GroundingError(f"I cannot go through {desc}: there is no free space I can reach on its far side.")
    poses: list[Point] = []
    before_t = (near_mouth[0] + n_near[0] * THROUGH_BEFORE_M, near_mouth[1] + n_near[1] * THROUGH_BEFORE_M)
    if math.dist(pose.xy, near_mouth) > THROUGH_BEFORE_M + 0.2:
        before = ctx.space.safe_point_near(before_t, comp, 0.4, where=_side_filter(near_mouth, n_near, 0.1))
        if before is not None:
            poses.append(before)
    if isinstance(e, NarrowPassage):
        mid = ctx.space.safe_point_near(e.center, comp, min(0.3, e.length_m / 2))
        if mid is not None:
            poses.append(mid)
    poses.append(beyond)
    return poses


def _mouth(d: Door, n: Point, ctx: GroundingContext) -> Point:
    """Where the opening of door ``d`` ends on the side ``n`` points to: its centre when it is cut in a
    wall (its sides end within WALL_DEEP_M), else the end of its sides (``WALL_DEEP_M``): one is through
    a gap between two cars only past the cars, not halfway along them."""
    u = _door_normal(d)
    along = (-u[1], u[0])
    half = d.width_m / 2 + REVEAL_PROBE_M
    step = ctx.space.grid.resolution_m / 2
    depth = 0.0
    s = 0.0
    while s <= REVEAL_MAX_M:
        cx, cy = d.center[0] + n[0] * s, d.center[1] + n[1] * s
        # both sides: a door flush with a wall running on beside it is no deeper for that wall
        if all(_occupied_near(ctx, (cx + k * along[0] * half, cy + k * along[1] * half), REVEAL_SIDE_M)
               for k in (-1, 1)):
            depth = s
        elif s > depth + 2 * step:
            break
        s += step
    if depth <= WALL_DEEP_M:
        return d.center
    return (d.center[0] + n[0] * depth, d.center[1] + n[1] * depth)


def _occupied_near(ctx: GroundingContext, p: Point, r_m: float) -> bool:
    """An occupied cell (a wall, a thing; not unscanned space, which a doorway to the unexplored
    opens onto) within ``r_m`` of ``p``."""
    grid = ctx.analysis.grid
    r, c = grid.world_to_index(p[0], p[1])
    k = math.ceil(r_m / grid.resolution_m)
    rows, cols = grid.cells.shape
    r0, r1, c0, c1 = max(int(r) - k, 0), min(int(r) + k + 1, rows), max(int(c) - k, 0), min(int(c) + k + 1, cols)
    return r0 < r1 and c0 < c1 and bool(grid.occupied[r0:r1, c0:c1].any())


def _kdtree_where(cells: FloatArray, max_m: float):  # type: ignore[no-untyped-def]
    tree = cKDTree(np.asarray(cells, dtype=float).reshape(-1, 2))

    def where(xs: FloatArray, ys: FloatArray) -> BoolArray:
        d, _ = tree.query(np.column_stack([xs.ravel(), ys.ravel()]), distance_upper_bound=max_m + 1e-6)
        return np.asarray(np.isfinite(d).reshape(xs.shape), dtype=bool)
    return where


def _next_to_cells(cells: FloatArray, ctx: GroundingContext, pose: Pose, comp: int) -> Point | None:
    """A free point within NEXT_TO_MAX_M of ``cells``, on the robot's side: beside the side of the
    thing that faces the robot (``_beside_face``), or off its nearest cell when it has no sides."""
    _, q = nearest_point(pose.xy, cells)
    prefer = _beside_face(np.asarray(cells, dtype=float).reshape(-1, 2), pose)
    if prefer is None:
        dx, dy = pose.x_m - q[0], pose.y_m - q[1]
        n = unit((dx, dy)) if math.hypot(dx, dy) > 1e-6 else (-pose.heading()[0], -pose.heading()[1])
        prefer = (q[0] + n[0] * NEXT_TO_STANDOFF_M, q[1] + n[1] * NEXT_TO_STANDOFF_M)
    return ctx.space.safe_point_near(q, comp, NEXT_TO_MAX_M + 0.5, prefer=prefer,
                                     where=_kdtree_where(cells, NEXT_TO_MAX_M))


def _beside_face(cells: FloatArray, pose: Pose) -> Point | None:
    """"Next to the cabinet" is beside one of its sides, not off a corner: of the four sides of the
    thing's footprint (along its own axes), the one facing the robot; the point is
    NEXT_TO_STANDOFF_M out from that side, level with the robot along it but at least
    NEXT_TO_FACE_INSET_M in from the side's ends. None for fewer than three cells."""
    if len(cells) < 3:
        return None
    c = cells.mean(axis=0)
    _, vec = np.linalg.eigh(np.cov((cells - c).T))
    axes = [np.asarray(vec[:, k], dtype=float) for k in range(2)]
    to_robot = np.array([pose.x_m, pose.y_m]) - c
    spans = [((cells - c) @ a).min() for a in axes], [((cells - c) @ a).max() for a in axes]
    best: tuple[float, Point] | None = None
    for k in range(2):
        a, other = axes[k], axes[1 - k]
        for sgn in (1.0, -1.0):
            facing = float(sgn * (to_robot @ a))
            out = spans[1][k] if sgn > 0 else -spans[0][k]
            lo, hi = spans[0][1 - k], spans[1][1 - k]
            inset = min(NEXT_TO_FACE_INSET_M, (hi - lo) / 2)
            level = min(max(float(to_robot @ other), lo + inset), hi - inset)
            p = c + a * sgn * (out + NEXT_TO_STANDOFF_M) + other * level
            if best is None or facing > best[0]:
                best = (facing, (float(p[0]), float(p[1])))
    return None if best is None else best[1]


def _towards_frontier(u: UnexploredArea, ctx: GroundingContext, pose: Pose, comp: int) -> Point | None:
    if len(u.frontier) == 0:
        return None
    f = np.asarray(u.frontier, dtype=float).reshape(-1, 2)
    facing = _facing_the_frontier(f, ctx, pose, comp)
    if facing is not None:
        return facing
    order = np.argsort(np.hypot(f[:, 0] - pose.x_m, f[:, 1] - pose.y_m))
    stride = max(1, len(order) // FRONTIER_TRIES)
    for i in order[::stride]:
        p = (float(f[i, 0]), float(f[i, 1]))
        g = ctx.space.safe_point_near(p, comp, FRONTIER_GOAL_MAX_M)
        if g is not None:
            return g
    return None


def _facing_the_frontier(f: FloatArray, ctx: GroundingContext, pose: Pose, comp: int) -> Point | None:
    """Where a person stops "going towards" an unexplored area: in front of the middle of the piece of
    its edge that is nearest (not at the end of it by a door jamb), a step short of it on the side they
    came from (not in the doorway it is seen through), still within FRONTIER_GOAL_MAX_M of the edge and
    with nothing but free floor between the spot and the edge. None when no such spot is free."""
    near = f[np.argmin(np.hypot(f[:, 0] - pose.x_m, f[:, 1] - pose.y_m))]
    piece = f[np.hypot(f[:, 0] - near[0], f[:, 1] - near[1]) <= FRONTIER_PIECE_M]
    piece = _face_towards(piece, (float(near[0]), float(near[1])), ctx, pose)
    centre = piece.mean(axis=0)
    edge = piece[np.argmin(np.hypot(piece[:, 0] - centre[0], piece[:, 1] - centre[1]))]
    p = (float(edge[0]), float(edge[1]))
    if math.dist(p, pose.xy) <= FRONTIER_STANDOFF_M:
        return None
    back = _square_to_the_edge(piece, unit((pose.x_m - p[0], pose.y_m - p[1])))
    short = (p[0] + back[0] * FRONTIER_STANDOFF_M, p[1] + back[1] * FRONTIER_STANDOFF_M)
    g = ctx.space.safe_point_near(p, comp, FRONTIER_GOAL_MAX_M, prefer=short)
    if g is None or not ctx.space.segment_clear(p, g, 0.0)[0]:
        return None
    return g


def _face_towards(piece: FloatArray, near: Point, ctx: GroundingContext, pose: Pose) -> FloatArray:
    """Of a piece of an unexplored area's edge that goes round a corner (an unscanned block in a
    room's corner, seen on two sides), the side that faces the robot most squarely from where it
    stands: a person sent to look at it stops in front of that side, not off its corner. The sides run with the
    walls of the room the edge is in. The piece itself when it is no such corner (a straight edge, a
    ragged one, a room with no wall direction)."""
    if len(piece) < 3:
        return piece
    room = space_of(ctx.analysis, near)
    theta = None if room is None else _wall_run(room, ctx)
    if theta is None:
        return piece
    back = unit((pose.x_m - near[0], pose.y_m - near[1]))
    rel = piece - piece.mean(axis=0)
    faces: list[tuple[float, BoolArray]] = []
    for k in range(4):
        n = (math.cos(theta + k * math.pi / 2), math.sin(theta + k * math.pi / 2))
        proj = rel @ np.asarray(n)
        on = proj >= proj.max() - FRONTIER_STRAIGHT_TOL_M
        along = rel[on] @ np.asarray((-n[1], n[0]))
        if float(along.max() - along.min()) >= FRONTIER_FACE_MIN_M:
            faces.append((n[0] * back[0] + n[1] * back[1], on))
    if len(faces) < 2:
        return piece
    faces.sort(key=lambda fo: -fo[0])
    # a corner: its two sides nearest to facing the robot hold nearly all of the piece (a ragged
    # edge does not); the robot sees the first of them
    if faces[0][0] <= 0.0 or float(np.mean(faces[0][1] | faces[1][1])) < FRONTIER_CORNER_MIN_SHARE:
        return piece
    return piece[faces[0][1]]


def _square_to_the_edge(piece: FloatArray, back: Point) -> Point:
    """The way a person steps back from a straight piece of an unexplored area's edge (an opening, a
    hallway's end): square to it, on the side they came from, so they stop in front of it and not
    beside it along the edge when they came at it from the side. A piece that is no straight line (a
    corner of an unscanned block) or that the robot is in line with keeps ``back`` (towards the robot)."""
    if len(piece) < 3:
        return back
    rel = piece - piece.mean(axis=0)
    w, v = np.linalg.eigh(np.cov(rel.T))
    along = v[:, int(np.argmax(w))]
    normal = (-float(along[1]), float(along[0]))
    if float(np.abs(rel @ np.asarray(normal)).max()) > FRONTIER_STRAIGHT_TOL_M:
        return back
    dot = normal[0] * back[0] + normal[1] * back[1]
    if abs(dot) < FRONTIER_IN_LINE_MAX_COS:
        return back
    return (normal[0], normal[1]) if dot > 0 else (-normal[0], -normal[1])


def _room_cells_mask(ctx: GroundingContext, room: Room) -> BoolArray:
    return room_mask(ctx.analysis.labels, room.label)


def _in_label(ctx: GroundingContext, label: int) -> compose.Where:
    """The cells of the room or hallway whose label is ``label``, as a predicate on world x, y."""
    return _in_labels(ctx, (label,))


def _in_labels(ctx: GroundingContext, parts: tuple[int, ...]) -> compose.Where:
    """The cells of the spaces whose labels are ``parts``, as a predicate on world x, y."""
    labels = ctx.analysis.labels
    grid = ctx.analysis.grid

    def inside(xs: FloatArray, ys: FloatArray) -> BoolArray:
        rr, cc = grid.world_to_index(xs, ys)
        ok = grid.in_bounds(rr, cc)
        out = np.zeros(xs.shape, dtype=bool)
        out[ok] = np.isin(labels[rr[ok], cc[ok]], parts)
        return out
    return inside


def _in_space_id(ctx: GroundingContext, space_id: str) -> compose.Where | None:
    """The cells of the room or hallway ``space_id``; None when no space has that id (unexplored)."""
    room = next((r for r in ctx.analysis.rooms if r.id == space_id), None)
    return None if room is None else _in_label(ctx, room.label)


def _room_goal(step: Step, ref: ElementRef, room: Room, detail: Detail, ctx: GroundingContext, pose: Pose, comp: int,
               index: int) -> GroundedStep:
    desc = describe_ref(ref)
    mask = _room_cells_mask(ctx, room)
    in_room = _in_label(ctx, room.label)
    messages: tuple[str, ...] = ()
    if detail in (Detail.TO, Detail.STOP_AT) and _plain_space(ref):
        if room is space_of(ctx.analysis, pose.xy):
            # "go in the corridor to the second door": the robot is in it already; nothing to drive
            note = f"I am in {label_of(room)} already"
            return GroundedStep(index, step, (), pose, pose, note, (room.id,), messages=(note + ".",))
        if room.kind == ElementKind.HALLWAY and len(room.cells_xy) >= 3:
            stepped = _step_into_hallway(room, ctx, pose, comp)
            if stepped is not None:
                return _nav_step(step, pose, index, stepped, f"into {desc}", (room.id,))
    if detail == Detail.OPPOSITE_SIDE_OF and room.kind == ElementKind.HALLWAY and ref.kind != Kind.ROOM \
            and len(room.cells_xy) >= 3:
        # (a space the user calls a room has an opposite side, even when it is long enough for a hall)
        # "the end of the hall": the end ahead along the way the hallway leads, before its end wall
        hall, parts = _whole_hallway(ctx, room)
        way = _down_the_run(_hallway_way(hall, parts, ctx, pose, desc), hall, pose)
        s_end = way.length_m - ALONG_END_MARGIN_M
        if s_end < ALONG_MIN_RUN_M:
            raise GroundingError(f"I am already at the end of {desc}; turn around to go to its other end.")
        goal = _on_the_way(hall, parts, way, s_end, s_end, ctx, comp)
        if goal is None:
            raise GroundingError(f"I cannot reach the end of {desc}: no free space I can get to there.")
        return _nav_step(step, pose, index, [goal], f"to the end of {desc}", (room.id,))
    if detail == Detail.OPPOSITE_SIDE_OF:
        goal = _opposite_side(room, mask, ctx, pose, comp)
        if goal is None:
            raise GroundingError(f"I cannot reach the far side of {desc}.")
        return _nav_step(step, pose, index, [goal], f"to the opposite side of {desc}", (room.id,))
    centre = room.centroid
    if detail == Detail.MIDDLE:
        # the middle of a room parted by a thing standing in it (a gap or a way round each end of it,
        # ``gap_joined``) is the middle of the whole room a person sees, not of the part the robot is in
        group = gap_joined(ctx.analysis, room)
        if len(group) > 1 and not mostly_hallway(group):
            weights = [len(r.cells_xy) for r in group]
            centre = (sum(w * r.centroid[0] for w, r in zip(weights, group, strict=True)) / sum(weights),
                      sum(w * r.centroid[1] for w, r in zip(weights, group, strict=True)) / sum(weights))
            in_room = _in_labels(ctx, tuple(r.label for r in group))
            mask = np.logical_or.reduce([_room_cells_mask(ctx, r) for r in group])
    goal = ctx.space.safe_point_near(centre, comp, MIDDLE_GOAL_MAX_M, where=in_room)
    if goal is None:
        goal = ctx.space.best_in_mask(mask, comp, centre)
        if goal is None:
            raise GroundingError(f"I cannot get into {desc}: none of its free space is reachable from here.")
        if detail == Detail.MIDDLE:
            messages = (f"The middle of {desc} is taken up; I will stop at the nearest free spot, "
                        f"{math.dist(goal, centre):.1f} m from it.",)
    verb = "to the middle of" if detail == Detail.MIDDLE else "into"
    return _nav_step(step, pose, index, [goal], f"{verb} {desc}", (room.id,), messages=messages)


def _plain_space(ref: ElementRef) -> bool:
    """A space named by its kind alone ("the hallway", "the corridor"), no word picking one of several."""
    return (ref.ordinal is None and ref.superlative is None and ref.side is None and ref.label is None
            and ref.relation is None and ref.near is None and ref.name is None and not ref.passed)


def _step_into_hallway(hall: Room, ctx: GroundingContext, pose: Pose, comp: int) -> list[Point] | None:
    """"Go out into the hallway": a hallway is entered where the walk from here first reaches it (out
    of the room's door), onto its middle line; not at its middle, which may be far along it. The
    poses are a point of the walk INTO_HALL_LEAD_M before that spot and the spot itself, so the robot
    ends facing the way it walked in. None when the walk does not reach the hallway."""
    walk = walk_from(ctx.space, pose.xy)
    if walk is None:
        return None
    cells = np.asarray(hall.cells_xy, dtype=float).reshape(-1, 2)
    reached = walk.reached(cells[:, 0], cells[:, 1])
    if not reached.any():
        return None
    metres = np.where(reached, walk.each(cells[:, 0], cells[:, 1]), np.inf)
    entry = (float(cells[int(np.argmin(metres)), 0]), float(cells[int(np.argmin(metres)), 1]))
    target = _on_middle_line(hall, entry, None)
    goal = ctx.space.safe_point_near(target, comp, FOLLOW_SNAP_M, prefer=target, where=_in_label(ctx, hall.label))
    if goal is None:
        return None
    path = walk.path_to(goal)
    lengths = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff([p[0] for p in path]), np.diff([p[1] for p in path])))])
    lead = [p for p, d in zip(path[1:-1], lengths[1:-1], strict=True)
            if lengths[-1] - d >= INTO_HALL_LEAD_M and ctx.space.is_goal_ok(*p, component=comp)]
    return [lead[-1], goal] if lead else [goal]


def _opposite_side(room: Room, mask: BoolArray, ctx: GroundingContext, pose: Pose, comp: int) -> Point | None:
    """"The opposite side of the room": the side of the room facing the robot's across it. The way
    across is the room's axis (the run of its walls) nearest to the way from the robot to the room's
    middle; the goal is in the third of the room farthest along it, straight across from the robot,
    ``OPPOSITE_WALL_STANDOFF_M`` short of the far wall (the far side itself, not the middle of the
    room's far third), and among the room's cells farthest from the robot (the third of them farthest)."""
    xs, ys = ctx.space.xs[mask], ctx.space.ys[mask]
    if xs.size == 0:
        return None
    v = (room.centroid[0] - pose.x_m, room.centroid[1] - pose.y_m)
    d = unit(v) if math.hypot(*v) > 0.5 else pose.heading()
    theta = _wall_run(room, ctx)
    if theta is not None:
        axes = [(math.cos(theta + k * math.pi / 2), math.sin(theta + k * math.pi / 2)) for k in range(4)]
        d = max(axes, key=lambda a: a[0] * d[0] + a[1] * d[1])
    elif xs.size >= 3:
        _, vec = np.linalg.eigh(np.cov(np.vstack([xs - xs.mean(), ys - ys.mean()])))
        axes = [(float(vec[0, k]) * sgn, float(vec[1, k]) * sgn) for k in range(2) for sgn in (1.0, -1.0)]
        d = max(axes, key=lambda a: a[0] * d[0] + a[1] * d[1])
    t = (xs - pose.x_m) * d[0] + (ys - pose.y_m) * d[1]
    cut = t.min() + OPPOSITE_FRACTION * (t.max() - t.min())
    # the README's "third of the room farthest from the robot" by distance: with the robot off to one
    # side, straight across can be nearer than a third of the room (a room seen from near its corner)
    r = np.hypot(xs - pose.x_m, ys - pose.y_m)
    far_off = r >= float(np.quantile(r, OPPOSITE_FRACTION))
    far = mask.copy()
    far[mask] = (t >= cut) & far_off
    if not far.any():
        far[mask] = far_off
    depth = max(float(t.max()) - OPPOSITE_WALL_STANDOFF_M, float(cut))
    prefer = (pose.x_m + d[0] * depth, pose.y_m + d[1] * depth)
    return ctx.space.best_in_mask(far, comp, prefer)


def _wall_run(room: Room, ctx: GroundingContext) -> float | None:
    """The direction (rad, modulo a quarter turn) the room's walls run in: the length-weighted
    mean of its walls' directions, read modulo 90 degrees (walls meet square). A person's "across
    the room" is square to its walls; the spread of its floor (its principal axes) is no guide in
    a room about as wide as long or with furniture in it. None when the room has no walls of its
    own, or they agree on no direction (a round room)."""
    sx = sy = total_m = 0.0
    for wall in ctx.analysis.walls:
        if wall.room != room.id:
            continue
        dx, dy = wall.end[0] - wall.start[0], wall.end[1] - wall.start[1]
        length = math.hypot(dx, dy)
        angle = 4.0 * math.atan2(dy, dx)
        sx += length * math.cos(angle)
        sy += length * math.sin(angle)
        total_m += length
    if total_m == 0.0 or math.hypot(sx, sy) < WALL_RUN_MIN_AGREEMENT * total_m:
        return None
    return math.atan2(sy, sx) / 4.0


def _between(step: Step, ref: ElementRef, ctx: GroundingContext, pose: Pose, comp: int, index: int) -> GroundedStep:
    second_ref = step.second_target
    if second_ref is not None and any(r.name or r.place is not None for r in (ref, second_ref)):
        # "between the kitchen and door 2": a named place's point with an element's reference point
        pa, da, ia = _point_of(ref, ctx, pose, step.text)
        pb, db, ib = _point_of(second_ref, ctx, pose, step.text)
        mid = ((pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2)
        goal = ctx.space.safe_point_near(mid, comp, MIDDLE_GOAL_MAX_M)
        if goal is None:
            raise GroundingError(f"There is no free space I can reach between {da} and {db}.")
        return _nav_step(step, pose, index, [goal], f"between {da} and {db}", ia + ib)
    a, b = select_pair(ref, step.second_target, ctx.analysis, pose, step.text)
    pa, pb = reference_point(a), reference_point(b)
    mid = ((pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2)
    goal = ctx.space.safe_point_near(mid, comp, MIDDLE_GOAL_MAX_M)
    second = describe_ref(step.second_target) if step.second_target else "the other"
    if goal is None:
        raise GroundingError(f"There is no free space I can reach between {describe_ref(ref)} and {second}.")
    note = f"between {describe_ref(ref)} and {second}" if step.second_target else \
        f"between the two {describe_ref(ref).removeprefix('the ')}s"
    return _nav_step(step, pose, index, [goal], note, (a.id, b.id))


# ------------------------------------------------------------------------------ walls, hallways
def _oriented(wall: WallLine, pose: Pose) -> tuple[Point, Point, Point]:
    """(start, direction of travel, inward normal toward the robot) of a wall line."""
    d = wall.direction
    hx, hy = pose.heading()
    start, end = wall.start, wall.end
    dot = d[0] * hx + d[1] * hy
    t_robot = (pose.x_m - start[0]) * d[0] + (pose.y_m - start[1]) * d[1]
    # facing the wall: go towards its farther end
    forward = (wall.length_m - t_robot) >= t_robot if abs(dot) < 0.2 else dot > 0
    if not forward:
        start, d = end, (-d[0], -d[1])
    n = wall.inward
    if (pose.x_m - start[0]) * n[0] + (pose.y_m - start[1]) * n[1] < 0:
        n = (-n[0], -n[1])
    return start, d, n


def _next_to_wall(wall: WallLine, ctx: GroundingContext, pose: Pose, comp: int) -> Point:
    start, d, n = _oriented(wall, pose)
    t = min(max((pose.x_m - start[0]) * d[0] + (pose.y_m - start[1]) * d[1], 0.0), wall.length_m)
    base = (start[0] + d[0] * t, start[1] + d[1] * t)
    prefer = (base[0] + n[0] * NEXT_TO_STANDOFF_M, base[1] + n[1] * NEXT_TO_STANDOFF_M)
    goal = ctx.space.safe_point_near(prefer, comp, NEXT_TO_MAX_M, where=_wall_band(wall, n, NEXT_TO_MAX_M))
    if goal is None:
        raise GroundingError("I cannot get next to that wall: no free space I can reach beside it.")
    return goal


def _wall_band(wall: WallLine, n: Point, max_m: float):  # type: ignore[no-untyped-def]
    def where(xs: FloatArray, ys: FloatArray) -> BoolArray:
        side = (xs - wall.start[0]) * n[0] + (ys - wall.start[1]) * n[1] > 0
        return np.asarray(side & (segment_distances(xs, ys, wall.start, wall.end) <= max_m), dtype=bool)
    return where


def _along_wall(step: Step, ref: ElementRef, ctx: GroundingContext, pose: Pose, comp: int, index: int) -> GroundedStep:
    wall = select_wall(ref, ctx.analysis, pose)
    desc = describe_ref(ref)
    start, d, n = _oriented(wall, pose)
    length = wall.length_m
    t0 = min(max((pose.x_m - start[0]) * d[0] + (pose.y_m - start[1]) * d[1], 0.0), length)
    t_end = length - ALONG_END_MARGIN_M
    if step.fraction is not None:
        t_end = t0 + (length - t0) * step.fraction  # "halfway along the wall": of the run from here
        if t_end - t0 < compose.MIN_OFFSET_RUN_M:
            raise GroundingError(f"I am already {compose.fraction_words(step.fraction)} along {desc} or past it.")
    elif t_end - t0 < ALONG_MIN_RUN_M:
        raise GroundingError(f"I am already at the end of {desc}; turn around to drive along it the other way.")
    band = _wall_band(wall, n, ALONG_MAX_M)

    limit = t_end + compose.ALONG_SLACK_M if step.fraction is not None else math.inf

    def at(t: float, radius: float) -> Point | None:
        base = (start[0] + d[0] * t, start[1] + d[1] * t)
        target = (base[0] + n[0] * ALONG_OFFSET_M, base[1] + n[1] * ALONG_OFFSET_M)

        def where(xs: FloatArray, ys: FloatArray) -> BoolArray:  # never past the part of the wall asked for
            ok = band(xs, ys)
            return np.asarray(ok & ((xs - start[0]) * d[0] + (ys - start[1]) * d[1] <= limit), dtype=bool)
        return ctx.space.safe_point_near(target, comp, radius, where=where)

    end: Point | None = None
    t = t_end
    shortest = ALONG_MIN_RUN_M / 2 if step.fraction is None else compose.MIN_OFFSET_RUN_M / 2
    while t > t0 + shortest:
        end = at(t, 0.5)
        if end is not None:
            break
        t -= ALONG_BACKOFF_M
    if end is None:
        raise GroundingError(f"I cannot drive along {desc}: there is no free space I can reach beside it.")
    t_last = t
    k = max(2, math.ceil((t_last - t0) / ALONG_SPACING_M))
    poses: list[Point] = []
    for i in range(1, k):
        p = at(t0 + (t_last - t0) * i / k, 0.5)
        if p is not None and (not poses or math.dist(p, poses[-1]) > 0.3):
            poses.append(p)
    poses.append(end)
    return _nav_step(step, pose, index, poses, f"along {desc}", wall.ids)


def _follow_space(step: Step, ref: ElementRef, ctx: GroundingContext, pose: Pose, comp: int, index: int) -> GroundedStep:
    """Follow a hallway (or a room) along its long axis, to its far end in the direction of travel."""
    if ref.ordinal is None and ref.superlative is None and ref.side is None:
        here = space_of(ctx.analysis, pose.xy)
        want = ElementKind.HALLWAY if ref.kind == Kind.HALLWAY else ElementKind.ROOM
        room = here if here is not None and here.kind == want else select(ref, ctx.analysis, pose)
    else:
        room = select(ref, ctx.analysis, pose)
    assert isinstance(room, Room)
    desc = describe_ref(ref)
    if room.kind == ElementKind.HALLWAY and len(room.cells_xy) >= 3:
        return _follow_hallway(step, desc, room, ctx, pose, comp, index)
    mask = _room_cells_mask(ctx, room)
    xs, ys = ctx.space.xs[mask], ctx.space.ys[mask]
    if xs.size < 2:
        raise GroundingError(f"{desc} has no free space to follow.")
    c = (float(xs.mean()), float(ys.mean()))
    cov = np.cov(np.vstack([xs - c[0], ys - c[1]]))
    w, v = np.linalg.eigh(cov)
    axis = (float(v[0, int(np.argmax(w))]), float(v[1, int(np.argmax(w))]))
    t = (xs - c[0]) * axis[0] + (ys - c[1]) * axis[1]
    hx, hy = pose.heading()
    tr = (pose.x_m - c[0]) * axis[0] + (pose.y_m - c[1]) * axis[1]
    dot = axis[0] * hx + axis[1] * hy
    if abs(dot) < 0.2:
        sign = 1.0 if (t.max() - tr) >= (tr - t.min()) else -1.0
    else:
        sign = 1.0 if dot > 0 else -1.0
    t_far = (t.max() if sign > 0 else t.min()) - sign * ALONG_END_MARGIN_M
    if step.fraction is not None:
        # "halfway down the corridor": that part of the run from here (or from where the robot enters
        # it) to the end it is heading for
        t_here = min(max(tr, float(t.min())), float(t.max()))
        t_far = t_here + ((t.max() if sign > 0 else t.min()) - t_here) * step.fraction
    run = (t_far - tr) * sign
    if step.fraction is not None and run < compose.MIN_OFFSET_RUN_M:
        raise GroundingError(f"I am already {compose.fraction_words(step.fraction)} along {desc} or past it.")
    if run < ALONG_MIN_RUN_M and step.fraction is None:
        raise GroundingError(f"I am already at the end of {desc}; turn around to follow it the other way.")
    k = max(2, math.ceil(run / ALONG_SPACING_M))
    poses: list[Point] = []
    for i in range(1, k + 1):
        ti = tr + (t_far - tr) * i / k
        target = (c[0] + axis[0] * ti, c[1] + axis[1] * ti)
        t_cells = (ctx.space.xs - c[0]) * axis[0] + (ctx.space.ys - c[1]) * axis[1]
        band = np.abs(t_cells - ti) <= 0.5
        if step.fraction is not None:  # never past the part of the run asked for
            band &= (t_cells - t_far) * sign <= compose.ALONG_SLACK_M
        p = ctx.space.best_in_mask(mask & band, comp, target)
        if p is not None and (not poses or math.dist(p, poses[-1]) > 0.3):
            poses.append(p)
    if not poses:
        raise GroundingError(f"I cannot follow {desc}: none of it is reachable from here.")
    return _nav_step(step, pose, index, poses, f"follow {desc}", (room.id,))


def _follow_hallway(step: Step, desc: str, hall: Room, ctx: GroundingContext, pose: Pose, comp: int,
                    index: int) -> GroundedStep:
    """'Follow the corridor', 'halfway down the hallway': along the way the hallway leads from here in
    the direction the robot faces (round the bend of an L-shaped corridor), to its far end or that
    part of the way; poses on the hallway's middle line, never past the part asked for. The hallway is
    the one a person sees, its parts past a narrow gap included (``_whole_hallway``)."""
    hall, parts = _whole_hallway(ctx, hall)
    way = _hallway_way(hall, parts, ctx, pose, desc)
    if step.fraction is not None:
        # "halfway down the corridor": of the straight run ahead, from here to where it turns
        way = _down_the_run(way, hall, pose)
        s_goal = way.length_m * step.fraction
        if s_goal < compose.MIN_OFFSET_RUN_M:
            raise GroundingError(f"I am already {compose.fraction_words(step.fraction)} along {desc} or past it.")
    else:
        s_goal = way.length_m - ALONG_END_MARGIN_M
        if s_goal < ALONG_MIN_RUN_M:
            raise GroundingError(f"I am already at the end of {desc}; turn around to follow it the other way.")
    k = max(2, math.ceil(s_goal / ALONG_SPACING_M))
    poses: list[Point] = []
    for i in range(1, k + 1):
        p = _on_the_way(hall, parts, way, s_goal * i / k, s_goal, ctx, comp)
        if p is not None and (not poses or math.dist(p, poses[-1]) > 0.3):
            poses.append(p)
    if not poses:
        raise GroundingError(f"I cannot follow {desc}: none of it is reachable from here.")
    return _nav_step(step, pose, index, poses, f"follow {desc}", (hall.id,))


def _whole_hallway(ctx: GroundingContext, hall: Room) -> tuple[Room, tuple[int, ...]]:
    """The hallway as a person sees it (``hallway_parts``: a corridor a cart narrows to a gap goes on
    past the cart) and the labels of its parts. The hallway is ``hall`` with the free cells of every
    part, from which its axis, its far end and its middle line are read; its width is its own."""
    parts = hallway_parts(ctx.analysis, hall)
    if len(parts) == 1:
        return hall, (hall.label,)
    cells = np.concatenate([np.asarray(r.cells_xy, dtype=float).reshape(-1, 2) for r in parts])
    whole = replace(hall, cells_xy=cells, area_m2=sum(r.area_m2 for r in parts),
                    free_area_m2=sum(r.free_area_m2 for r in parts))
    return whole, tuple(r.label for r in parts)


def _hallway_way(hall: Room, parts: tuple[int, ...], ctx: GroundingContext, pose: Pose, desc: str) -> compose.Way:
    """The way down the hallway (of the labels ``parts``) the robot faces (facing across it: the
    longer way)."""
    _, axis = hall_axis(hall, pose.xy)
    hx, hy = pose.heading()
    dot = axis[0] * hx + axis[1] * hy
    ways = [(axis[0], axis[1]), (-axis[0], -axis[1])] if abs(dot) < FACING_ALONG_MIN else \
        [(axis[0], axis[1]) if dot > 0 else (-axis[0], -axis[1])]
    found = [w for w in (_way_down(hall, parts, d, ctx, pose) for d in ways) if w is not None]
    if not found:
        raise GroundingError(f"I cannot follow {desc}: none of it is reachable from here.")
    return max(found, key=lambda w: w.length_m)


def _down_the_run(way: compose.Way, hall: Room, pose: Pose) -> compose.Way:
    """The way down the hallway as far as its straight run goes (``Way.straight_leg``). The run sets
    off along the hallway's axis where the walk is RUN_HEAD_WIDTHS hallway widths on (not where the
    robot stands, where it tilts at a junction; nor the walk's own first stretch, which slants to the
    middle line from a robot off it), the way the walk goes."""
    head = way.point_at(min(way.length_m, RUN_HEAD_WIDTHS * hall.width_m))
    v = (head[0] - pose.x_m, head[1] - pose.y_m)
    if math.hypot(*v) < compose.MIN_OFFSET_RUN_M:
        return way
    _, axis = hall_axis(hall, head)
    heading = axis if axis[0] * v[0] + axis[1] * v[1] >= 0 else (-axis[0], -axis[1])
    return way.straight_leg(heading, hall.width_m)


def _on_the_way(hall: Room, parts: tuple[int, ...], way: compose.Way, s_m: float, s_max: float,
                ctx: GroundingContext, comp: int) -> Point | None:
    """A goal in the hallway (of the labels ``parts``) ``s_m`` along the way, on its middle line, never
    past ``s_max``."""
    target = _on_middle_line(hall, way.point_at(s_m), way.direction_at(s_m))
    lo, hi = s_m - FOLLOW_BAND_M, min(s_m + FOLLOW_BAND_M, s_max + compose.ALONG_SLACK_M)
    in_hall = _in_labels(ctx, parts)

    def where(xs: FloatArray, ys: FloatArray) -> BoolArray:
        along = way.along(xs, ys)  # never past the part of the way asked for
        return np.asarray(in_hall(xs, ys) & (along >= lo) & (along <= hi), dtype=bool)

    return ctx.space.safe_point_near(target, comp, FOLLOW_SNAP_M, prefer=target, where=where)


def _way_down(hall: Room, parts: tuple[int, ...], direction: Point, ctx: GroundingContext,
              pose: Pose) -> compose.Way | None:
    """The way down the hallway setting off in ``direction``: the walk to the hallway's farthest cell
    with the way back shut, ending on the hallway's middle line."""
    labels = ctx.analysis.labels
    start = ctx.space.start_cell(*pose.xy)
    # down the hallway is along it: a room with two doors onto it is no short cut (from outside the
    # hallway the walk may start anywhere)
    inside = start is not None and labels.shape == ctx.space.components.shape and int(labels[start]) in parts
    walk = walk_from(ctx.space, pose.xy, onward=direction, onward_m=hall.width_m + FOLLOW_CLOSE_MARGIN_M,
                     within=(labels, parts) if inside else None)
    if walk is None:
        return None
    cells = np.asarray(hall.cells_xy, dtype=float).reshape(-1, 2)
    xs, ys = cells[:, 0], cells[:, 1]
    metres = np.where(walk.reached(xs, ys), walk.each(xs, ys), -np.inf)
    i = int(np.argmax(metres))
    if not np.isfinite(metres[i]):
        return None
    far = (float(xs[i]), float(ys[i]))
    end = _on_middle_line(hall, far, None)
    return compose.Way.through(walk.path_to(end), walk.stride * ctx.space.grid.resolution_m)


def _on_middle_line(hall: Room, p: Point, direction: Point | None) -> Point:
    """``p`` moved across the hallway onto its middle line, where the hallway runs along
    ``direction`` there (at a bend it does not: ``p`` stays)."""
    c, a = hall_axis(hall, p)
    if direction is not None and abs(a[0] * direction[0] + a[1] * direction[1]) < MIDDLE_LINE_MIN_COS:
        return p
    t = (p[0] - c[0]) * a[0] + (p[1] - c[1]) * a[1]
    return (c[0] + a[0] * t, c[1] + a[1] * t)


# ------------------------------------------------------------------------------ explore
def _explore(step: Step, ctx: GroundingContext, pose: Pose, index: int) -> GroundedStep:
    comp = _component(ctx, pose)
    areas = list(ctx.analysis.unexplored)
    if step.target is not None and step.target.kind not in (Kind.NONE, Kind.UNEXPLORED_AREA):
        # "explore the hallway": go there first, exploring from there
        inner = _navigate(step.model_copy(update={"movement": Movement.NAVIGATE}), ctx, pose, index)
        return GroundedStep(index, step, inner.commands, pose, inner.end_pose, "explore " + inner.note,
                            inner.element_ids, True)
    areas.sort(key=lambda u: nearest_point(pose.xy, u.frontier)[0] if len(u.frontier) else math.inf)
    for u in areas:
        g = _towards_frontier(u, ctx, pose, comp)
        if g is not None:
            return _nav_step(step, pose, index, [g], "explore, starting at the nearest unexplored area",
                             (u.id,), explore=True)
    raise GroundingError("There is nothing left to explore that I can reach: every frontier of the map is "
                         "mapped or out of reach.")


__all__ = ["GroundedPlan", "GroundedStep", "GroundingContext", "as_pose", "ground", "ground_step"]
