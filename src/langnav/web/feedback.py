"""The user feedback manager: robot answers and plan events in plain words.

"I'm in the hallway at x 3.1, y 6.0, facing east." Pure functions of poses, paths, maps and
intents; :class:`FeedbackManager` adds the current map analysis (to name the room or hallway).
Map frame: +x is east, +y is north, yaw counter-clockwise from east.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Final

import numpy as np

from langnav.analysis.elements import ElementKind, MapAnalysis
from langnav.language.intent import Amount, Detail, Direction, ElementRef, Intent, Movement, Step
from langnav.maps.grid import OccupancyGrid
from langnav.robot.protocol import Pose2D

#: Eight compass words, counter-clockwise from east (yaw 0) in 45-degree sectors.
COMPASS: Final = ("east", "north-east", "north", "north-west", "west", "south-west", "south", "south-east")
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
    """ "the hallway", "room 2" or None when the point is in no known space."""
    if analysis is None:
        return None
    space = analysis.room_at(x_m, y_m)
    if space is None:
        return None
    if space.kind == ElementKind.HALLWAY:
        halls = [r for r in analysis.rooms if r.kind == ElementKind.HALLWAY]
        return "the hallway" if len(halls) == 1 else f"hallway {halls.index(space) + 1}"
    rooms = [r for r in analysis.rooms if r.kind != ElementKind.HALLWAY]
    return f"room {rooms.index(space) + 1}"


def where_am_i(pose: Pose2D, analysis: MapAnalysis | None = None) -> str:
    """ "I'm in the hallway at x 3.1, y 6.0, facing east." """
    place = place_name(analysis, pose.x_m, pose.y_m)
    where = f"in {place} at" if place else "at"
    return f"I'm {where} x {pose.x_m:.1f}, y {pose.y_m:.1f}, facing {heading_word(pose.yaw_rad)}."


def describe_path(path: Sequence[tuple[float, float]]) -> str:
    if len(path) < 2:
        return "I have no path right now: I'm not driving anywhere."
    pts = np.asarray(path, dtype=float)
    length = float(np.linalg.norm(np.diff(pts, axis=0), axis=1).sum())
    end = pts[-1]
    return f"My path is {length:.1f} m long and ends at x {end[0]:.1f}, y {end[1]:.1f}."


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

    def where_am_i(self, pose: Pose2D) -> str:
        return where_am_i(pose, self._analysis())

    def path(self, path: Sequence[tuple[float, float]]) -> str:
        return describe_path(path)

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
