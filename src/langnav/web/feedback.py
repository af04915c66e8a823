"""The user feedback manager: robot answers and plan events in plain words.

"I'm in the hallway at x 3.1, y 6.0, facing east." Pure functions of poses, paths, maps and
intents; :class:`FeedbackManager` adds the current map analysis (to name the room or hallway).
Map frame: +x is east, +y is north, yaw counter-clockwise from east.
"""

from __future__ import annotations

import functools
import math
import re
from collections.abc import Callable, Sequence
from typing import Final

import numpy as np

from langnav.analysis.elements import Element as MapElement
from langnav.analysis.elements import ElementKind, MapAnalysis, reference_point
from langnav.analysis.identity import label
from langnav.language.intent import Amount, Detail, Direction, ElementRef, Intent, Movement, Step
from langnav.maps.grid import OccupancyGrid
from langnav.plan.commands import (
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
)
from langnav.robot.protocol import Pose2D

#: Eight compass words, counter-clockwise from east (yaw 0) in 45-degree sectors.
COMPASS: Final = ("east", "north-east", "north", "north-west", "west", "south-west", "south", "south-east")
#: "Near" a landmark: within a couple of strides (a person points someone to "near door 2" when it
#: is that close; farther, the room alone says where).
NEAR_M: Final = 2.0
_ORDINALS: Final = ("first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth",
                    "ninth", "tenth")
_ELEMENT_WORDS: Final = {"narrow_passage": "narrow passage", "unexplored_area": "unexplored area",
                         "none": "place"}
_DETAIL_WORDS: Final = {Detail.TO: "to", Detail.NEXT_TO: "next to", Detail.TOWARDS: "towards",
                        Detail.THROUGH: "through", Detail.OPPOSITE_SIDE_OF: "to the opposite side of",
                        Detail.ALONG: "along", Detail.BETWEEN: "between", Detail.STOP_AT: "and stop at",
                        Detail.MIDDLE: "to the middle of"}


def heading_word(yaw_rad: float) -> str:
    """The compass direction nearest a map-frame yaw: 0 -> east, pi/2 -> north."""
    sector = round(math.degrees(yaw_rad) / 45.0) % len(COMPASS)
    return COMPASS[sector]


def place_name(analysis: MapAnalysis | None, x_m: float, y_m: float) -> str | None:
    """ "hallway 2", "room 3" (the names on the map) or None when the point is in no known space."""
    if analysis is None:
        return None
    space = analysis.room_at(x_m, y_m)
    return None if space is None else label(space.id)


def nearest_landmark(analysis: MapAnalysis | None, x_m: float, y_m: float,
                     within_m: float = NEAR_M) -> str | None:
    """The name of the doorway (else passage, else piece of furniture) nearest a point, if one is
    within ``within_m``: what a person says to place someone ("near door 2")."""
    if analysis is None:
        return None
    groups: tuple[Sequence[MapElement], ...] = (analysis.doors, analysis.narrow_passages, analysis.obstacles)
    for group in groups:
        best = min(group, key=lambda e: math.dist(reference_point(e), (x_m, y_m)), default=None)
        if best is not None and math.dist(reference_point(best), (x_m, y_m)) <= within_m:
            return label(best.id)
    return None


def where_words(analysis: MapAnalysis | None, x_m: float, y_m: float) -> str:
    """ "in room 3 near door 2", "in hallway 2", "near door 4", or "" when nothing names the spot."""
    place = place_name(analysis, x_m, y_m)
    near = nearest_landmark(analysis, x_m, y_m)
    parts = ([f"in {place}"] if place else []) + ([f"near {near}"] if near else [])
    return " ".join(parts)


def where_am_i(pose: Pose2D, analysis: MapAnalysis | None = None, *, exact: bool = False) -> str:
    """ "I'm in room 3 near door 2, facing east." Coordinates only when asked for (``exact``) or
    when nothing on the map names the spot."""
    where = where_words(analysis, pose.x_m, pose.y_m)
    facing = heading_word(pose.yaw_rad)
    coords = f"x {pose.x_m:.1f}, y {pose.y_m:.1f}"
    if not where:
        return f"I'm at {coords}, facing {facing}."
    if exact:
        return f"I'm {where}, at {coords} (metres on the map), facing {facing}."
    return f"I'm {where}, facing {facing}."


def describe_path(path: Sequence[tuple[float, float]], analysis: MapAnalysis | None = None) -> str:
    if len(path) < 2:
        return "I have no path right now: I'm not driving anywhere."
    pts = np.asarray(path, dtype=float)
    length = float(np.linalg.norm(np.diff(pts, axis=0), axis=1).sum())
    end = pts[-1]
    where = where_words(analysis, float(end[0]), float(end[1]))
    if where:
        return f"My path is {length:.1f} m long and ends {where}."
    return f"My path is {length:.1f} m long and ends at x {end[0]:.1f}, y {end[1]:.1f}."


#: Words with which a person asks for numbers rather than a place's name.
_NUMBER_WORDS: Final = re.compile(r"\b(coordinates?|exact(ly)?|precise(ly)?|x\s*(and|,)\s*y|numbers?)\b", re.I)


_COORDS: Final = re.compile(r"\((-?\d+(?:\.\d+)?),\s*(-?\d+(?:\.\d+)?)\)")


#: Robotics words users do not use, and the words they do (every reply goes through this).
_JARGON: Final = ((re.compile(r"\bposes\b", re.I), "positions"), (re.compile(r"\bpose\b", re.I), "position"),
                  (re.compile(r"\bfrontiers\b( of the map)?", re.I), "edges of the map"),
                  (re.compile(r"\bfrontier\b( of the map)?", re.I), "edge of the map"))


def _same_case(found: re.Match[str], words: str) -> str:
    return words[:1].upper() + words[1:] if found.group(0)[:1].isupper() else words


def asks_for_numbers(prompt: str) -> bool:
    """Whether a question asks for coordinates ("where exactly are you?", "your coordinates?")."""
    return bool(_NUMBER_WORDS.search(prompt))


def turn_words(direction: str, angle_deg: float) -> str:
    """ "turn around", "turn left", "turn right 30°", "turn a full circle left"."""
    a = round(angle_deg)
    if a % 360 == 0 and a:
        return f"turn {a // 360} full circle{'s' if a >= 720 else ''} {direction}"
    if a == 180:
        return "turn around"
    if a == 90:
        return f"turn {direction}"
    return f"turn {direction} {a}°"


def plain_command(cmd: Command, analysis: MapAnalysis | None = None) -> str:
    """A robot command in words a person uses: where it goes by name, turns as turns, no steps.
    (The exact command, with its coordinates, stays available as :func:`langnav.plan.commands.describe`.)"""
    note = (cmd.note or "").strip()
    if isinstance(cmd, NavigateThroughPoses):
        end = cmd.poses[-1]
        where = where_words(analysis, float(end[0]), float(end[1]))
        lead = f"Go {note}" if note and not note.lower().startswith(("go ", "the point")) else (
            "Go to the point you clicked" if note.startswith("the point") else (note.capitalize() or "Go"))
        return f"{lead} ({where})" if where else lead
    if isinstance(cmd, Move):
        return f"Move {cmd.direction} {cmd.repeat * MOVE_STEP_M:.2f} m"
    if isinstance(cmd, Rotate):
        words = turn_words(cmd.direction, cmd.repeat * ROTATE_STEP_DEG)
        return words[:1].upper() + words[1:]
    if isinstance(cmd, Stop):
        return "Stop"
    if isinstance(cmd, GetCurrentPath):
        return "Tell you my path"
    if isinstance(cmd, GetMap):
        return "Tell you what is on my map"
    if isinstance(cmd, GetRobotPoseLast):
        return "Tell you where I am"
    return type(cmd).__name__


def describe_map(grid: OccupancyGrid, analysis: MapAnalysis | None = None) -> str:
    known = float((grid.cells != -1).sum()) * grid.cell_area_m2
    free = float(grid.free.sum()) * grid.cell_area_m2
    text = (f"My map is {grid.width * grid.resolution_m:.1f} m by {grid.height * grid.resolution_m:.1f} m; "
            f"I know {known:.0f} m² of it, {free:.0f} m² free.")
    if analysis is not None:
        rooms = sum(1 for r in analysis.rooms if r.kind != ElementKind.HALLWAY)
        halls = len(analysis.rooms) - rooms
        text += (f" I see {_count(rooms, 'room')}, {_count(halls, 'hallway')}, "
                 f"{_count(len(analysis.doors), 'door')} and "
                 f"{_count(len(analysis.unexplored), 'unexplored area')}.")
    return text


def _count(n: int, word: str) -> str:
    return f"{n} {word}" if n == 1 else f"{n} {word}s"


def describe_ref(ref: ElementRef) -> str:
    """ "the second door on your left", "the nearest corner of the hallway", "the kitchen"."""
    if ref.name:
        return f"the {ref.name}" if not ref.name.lower().startswith("the ") else ref.name
    noun = _ELEMENT_WORDS.get(ref.kind.value, ref.kind.value)
    words = ["the"]
    if ref.ordinal is not None:
        words.append(_ORDINALS[ref.ordinal - 1] if ref.ordinal <= len(_ORDINALS) else f"#{ref.ordinal}")
    if ref.superlative is not None:
        words.append(ref.superlative.value)
    words.append(noun)
    if ref.side is not None:
        words.append({"ahead": "ahead of you", "behind": "behind you"}.get(ref.side.value,
                                                                          f"on your {ref.side.value}"))
    if ref.in_current_room:
        words.append("in this room")
    if ref.within is not None:
        words.append(f"of the {_ELEMENT_WORDS.get(ref.within.value, ref.within.value)}")
    return " ".join(words)


def describe_step(step: Step) -> str:
    """One intent step in plain words: "go to the second door on your left"."""
    m = step.movement
    if m == Movement.STOP:
        return "stop"
    if m == Movement.EXPLORE:
        return "explore until there is nothing left to map"
    if m == Movement.QUERY:
        return {"pose": "tell you where I am", "path": "tell you my current path",
                "map": "show you my map"}.get(step.query.value if step.query else "", "answer a question")
    if m == Movement.ROTATE:
        if step.direction == Direction.AROUND:
            return "turn around"
        if step.angle_deg is not None and step.direction is not None:
            return turn_words(step.direction.value, step.angle_deg)
        how = f"{step.angle_deg:.0f}°" if step.angle_deg is not None else (
            "a little" if step.amount == Amount.LITTLE else "")
        side = step.direction.value if step.direction else ""
        return " ".join(w for w in ("turn", side, how) if w)
    if m == Movement.MOVE:
        how = f"{step.distance_m:.2f} m" if step.distance_m is not None else (
            "a little" if step.amount == Amount.LITTLE else "")
        side = step.direction.value if step.direction else "forward"
        return " ".join(w for w in ("move", side, how) if w)
    target = describe_ref(step.target) if step.target else "there"
    if m == Movement.FOLLOW:
        return f"follow {target}"
    detail = _DETAIL_WORDS.get(step.detail, "to") if step.detail else "to"
    if step.detail == Detail.BETWEEN and step.second_target is not None:
        return f"go between {target} and {describe_ref(step.second_target)}"
    return f"go {detail} {target}"


def describe_intent(intent: Intent) -> str:
    """The whole reading, in order: "I'll go to the nearest door, then turn left 90°."""
    if not intent.steps:
        return intent.clarification or "I did not find anything to do in that."
    parts = [describe_step(s) for s in intent.steps]
    text = parts[0] if len(parts) == 1 else ", then ".join(parts)
    return f"I'll {text}."


class FeedbackManager:
    """Plain-words answers that know the current map analysis (for room and hallway names)."""

    def __init__(self, analysis: Callable[[], MapAnalysis | None]) -> None:
        self._analysis = analysis

    def where_am_i(self, pose: Pose2D, exact: bool = False) -> str:
        return where_am_i(pose, self._analysis(), exact=exact)

    def path(self, path: Sequence[tuple[float, float]]) -> str:
        return describe_path(path, self._analysis())

    def exploration_left(self, message: str) -> str:
        """An exploration's last word, with the unexplored areas the map still shows named."""
        analysis = self._analysis()
        left = [u for u in analysis.unexplored if u.interior] if analysis is not None else []
        if not left:
            return message
        names = ", ".join(label(u.id) + (f" ({where_words(analysis, *u.centroid)})"
                                         if where_words(analysis, *u.centroid) else "") for u in left[:3])
        more = f" and {len(left) - 3} more" if len(left) > 3 else ""
        return f"{message}. Still unexplored on the map: {names}{more}"

    def placed(self, text: str) -> str:
        """A reply with map coordinates "(x, y)" in it, with the place's name in their stead when
        the map names the spot (coordinates only when nothing does)."""
        analysis = self._analysis()

        def name(m: re.Match[str]) -> str:
            where = where_words(analysis, float(m.group(1)), float(m.group(2)))
            return f"({where})" if where else m.group(0)

        return _COORDS.sub(name, text)

    def plain(self, text: str) -> str:
        """Any reply in the words a user knows: map coordinates named by place (see :meth:`placed`),
        "pose" said as "position", a "frontier" as an edge of the map."""
        text = self.placed(text)
        for pattern, words in _JARGON:
            text = pattern.sub(functools.partial(_same_case, words=words), text)
        return text

    def command(self, cmd: Command) -> str:
        return plain_command(cmd, self._analysis())

    def map(self, grid: OccupancyGrid) -> str:
        return describe_map(grid, self._analysis())

    def arrived(self, pose: Pose2D) -> str:
        return "Done. " + self.where_am_i(pose)

    def stopped(self, pose: Pose2D, why: str = "") -> str:
        lead = f"Stopped ({why})." if why else "Stopped."
        return f"{lead} {self.where_am_i(pose)}"

    def cancelled(self, pose: Pose2D) -> str:
        return f"Plan cancelled. {self.where_am_i(pose)}"

    def failed(self, reason: str, pose: Pose2D | None) -> str:
        text = f"I could not do that: {reason.rstrip('.')}."
        return f"{text} {self.where_am_i(pose)}" if pose is not None else text
