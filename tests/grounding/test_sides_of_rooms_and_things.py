"""The opposite side of a room and the side of a thing, on the hand-built two-room world.

Room A is x 1-6, y 1-7 (free cells from about x 1.05 to 5.95); the box is x 2.0-2.6, y 5.0-5.6.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

from langnav.analysis.elements import MapAnalysis
from langnav.grounding import ground
from langnav.grounding.ground import MIDDLE_GOAL_MAX_M, OPPOSITE_WALL_STANDOFF_M
from langnav.language.intent import Intent, Step


def goal(analysis: MapAnalysis, pose: tuple[float, float, float], **kw: Any) -> tuple[float, float]:
    plan = ground(Intent(steps=[Step.model_validate(kw)]), analysis, pose)
    x, y = plan.commands[-1].poses[-1][:2]  # type: ignore[attr-defined]
    return x, y


def test_the_opposite_side_is_across_the_room_along_its_walls(two_rooms: MapAnalysis) -> None:
    # near the south wall, off to the east: the way to the middle is up and to the west, but the
    # side facing the robot's is the north side, straight across
    x, y = goal(two_rooms, (5.0, 1.5, 180.0), movement="navigate", detail="opposite_side_of",
                target={"kind": "room", "in_current_room": True})
    assert abs(x - 5.0) <= 0.3
    assert 7.0 - OPPOSITE_WALL_STANDOFF_M - 0.3 <= y <= 7.0 - 0.2  # by the far wall, clear of it
    # by the west wall: the east side
    x, y = goal(two_rooms, (1.5, 3.0, 90.0), movement="navigate", detail="opposite_side_of",
                target={"kind": "room", "in_current_room": True})
    assert x >= 6.0 - OPPOSITE_WALL_STANDOFF_M - 0.3 and abs(y - 3.0) <= 0.3


def test_next_to_a_box_is_beside_its_side_facing_the_robot(two_rooms: MapAnalysis) -> None:
    # from the south-east the box's south side faces the robot most: level with it, not its corner
    x, y = goal(two_rooms, (3.0, 2.0, 0.0), movement="navigate", detail="next_to", target={"kind": "obstacle"})
    assert 2.0 + 0.2 <= x <= 2.6 - 0.2 and 4.3 <= y < 5.0
    # from the east, level with the box: its east side
    x, y = goal(two_rooms, (5.0, 5.3, 180.0), movement="navigate", detail="next_to", target={"kind": "obstacle"})
    assert 2.6 < x <= 3.3 and 5.0 + 0.2 <= y <= 5.6 - 0.2


def test_the_middle_of_a_room_parted_by_a_thing_is_the_middle_of_the_whole(two_rooms: MapAnalysis) -> None:
    # the wall between the doors read as a thing standing in one room (a wide opening and a way round it)
    d1, d2 = two_rooms.doors
    one_room = replace(two_rooms, doors=(d2,), openings=(d1,))
    a, b = (len(r.cells_xy) for r in two_rooms.rooms)
    cx = (a * two_rooms.rooms[0].centroid[0] + b * two_rooms.rooms[1].centroid[0]) / (a + b)
    cy = (a * two_rooms.rooms[0].centroid[1] + b * two_rooms.rooms[1].centroid[1]) / (a + b)
    x, y = goal(one_room, (3.0, 3.0, 0.0), movement="navigate", detail="middle",
                target={"kind": "room", "in_current_room": True})
    assert math.dist((x, y), (cx, cy)) <= MIDDLE_GOAL_MAX_M
    # two rooms a wall with two doors parts: the middle of the robot's room
    x, y = goal(two_rooms, (3.0, 3.0, 0.0), movement="navigate", detail="middle",
                target={"kind": "room", "in_current_room": True})
    assert math.dist((x, y), two_rooms.rooms[0].centroid) <= MIDDLE_GOAL_MAX_M
