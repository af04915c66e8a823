"""Readings that go by a room's walls, on a floor drawn at a slant (turned 21.7 degrees): "the
opposite side of this room" is straight across, square to the walls, in a room about as wide as it
is long with tables in it (the spread of its floor points elsewhere); "the unexplored part of this
room", an unscanned block in a corner seen on two sides, is looked at from in front of the side
facing the robot, not from off its corner; of the hand-built two rooms' unscanned block, the side the
robot's walk arrives at.

The floor, drawn (metres; the map is this drawing turned about the origin):

  y=7.4 +---------------------------+
        |                     [?]   |      classroom: x 0-7, y 0-7.4
        |  [t]                      |      [?] unscanned block x 5-7, y 5.2-7.4
        |                           |      tables [t] (a big one in the south-west)
        |   [ t ]      [t]          |
    y=0 +---------------------------+
       x=0                         x=7
"""

from __future__ import annotations

import math

import numpy as np

from langnav.analysis.elements import MapAnalysis
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.pipeline import analyze
from langnav.grounding import ground
from langnav.language.intent import Intent, Step
from langnav.language.translator import get_translator
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import UNKNOWN, OccupancyGrid
from langnav.pipeline import Planner
from langnav.plan.commands import NavigateThroughPoses

TURN_DEG = 21.7
MARGIN_M = 3.0
#: In front of a side, not off its corner: at least this far in from the corner along the side.
IN_FRONT_M = 0.4


def turned(p: tuple[float, float]) -> tuple[float, float]:
    t = math.radians(TURN_DEG)
    return (MARGIN_M + p[0] * math.cos(t) - p[1] * math.sin(t), MARGIN_M + p[0] * math.sin(t) + p[1] * math.cos(t))


def drawn(p: tuple[float, float]) -> tuple[float, float]:
    t = math.radians(TURN_DEG)
    x, y = p[0] - MARGIN_M, p[1] - MARGIN_M
    return (x * math.cos(t) + y * math.sin(t), -x * math.sin(t) + y * math.cos(t))


def classroom() -> OccupancyGrid:
    res = 0.05
    b = MapBuilder(9.0, 10.0, res, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 7.0, 7.4)
    for t in ((1.0, 1.0, 3.0, 2.4), (3.6, 1.0, 5.0, 2.0), (1.0, 3.6, 2.0, 5.0)):
        b.box(*t)
    b.unknown(5.0, 5.2, 7.0, 7.4)
    src = b.build("classroom")
    # the map: the drawing turned about its origin, read back cell by cell (nearest cell)
    n = 300
    rr, cc = np.indices((n, n))
    x, y = (cc + 0.5) * res, (rr + 0.5) * res
    dx, dy = np.vectorize(lambda a, b_: drawn((a, b_)))(x, y)
    sc = np.floor((dx + 1.0) / res).astype(int)
    sr = np.floor((dy + 1.0) / res).astype(int)
    inside = (sr >= 0) & (sr < src.cells.shape[0]) & (sc >= 0) & (sc < src.cells.shape[1])
    cells = np.full((n, n), UNKNOWN, dtype=np.int8)
    cells[inside] = src.cells[sr[inside], sc[inside]]
    return OccupancyGrid(cells, res, 0.0, 0.0, 0.0, "classroom turned")


_ANALYSIS: list[MapAnalysis] = []


def analysis() -> MapAnalysis:
    if not _ANALYSIS:
        _ANALYSIS.append(analyze(classroom(), DEFAULT_PARAMS))
    return _ANALYSIS[0]


def drawn_goal(prompt: str, x: float, y: float, yaw_deg: float) -> tuple[float, float]:
    px, py = turned((x, y))
    r = Planner(get_translator("offline")).plan(prompt, analysis(), (px, py, yaw_deg + TURN_DEG))
    assert r.ok, r.clarification
    navs = [c for c in r.commands if isinstance(c, NavigateThroughPoses)]
    assert navs
    return drawn((navs[-1].poses[-1][0], navs[-1].poses[-1][1]))


def test_the_opposite_side_of_a_square_room_with_tables_is_straight_across() -> None:
    # by the south wall, facing north: the north side, level with the robot
    x, y = drawn_goal("go to the opposite side of this room", 3.5, 0.6, 90.0)
    assert 7.4 * 2 / 3 <= y <= 7.4 - 0.2
    assert abs(x - 3.5) <= 1.0
    # by the west wall, facing east: the east side, level with the robot
    x, y = drawn_goal("go to the opposite side of this room", 0.6, 3.0, 0.0)
    assert 7.0 * 2 / 3 <= x <= 7.0 - 0.2
    assert abs(y - 3.0) <= 1.0


def test_the_unexplored_part_of_the_room_is_looked_at_from_the_side_facing_the_robot() -> None:
    # from the west-south-west of the block's corner: in front of its west side, level with it
    x, y = drawn_goal("go to the unexplored part of this room", 2.6, 4.4, 0.0)
    assert 5.0 - 0.95 <= x <= 5.0 - 0.15
    assert 5.2 + IN_FRONT_M <= y <= 7.4
    # from the south-south-west, and from straight below the corner (its west side edge-on): in
    # front of its south side
    for x0, y0 in ((4.2, 2.8), (4.9, 1.2)):
        x, y = drawn_goal("go to the unexplored part of this room", x0, y0, 90.0)
        assert 5.0 + IN_FRONT_M <= x <= 7.0
        assert 5.2 - 0.95 <= y <= 5.2 - 0.15


def test_the_side_of_the_block_is_the_one_the_robot_arrives_at(two_rooms: MapAnalysis) -> None:
    def towards(pose: tuple[float, float, float]) -> tuple[float, float]:
        plan = ground(Intent(steps=[Step.model_validate(
            {"movement": "navigate", "detail": "towards", "target": {"kind": "unexplored_area"}})]), two_rooms, pose)
        x, y = plan.commands[-1].poses[-1][:2]  # type: ignore[attr-defined]
        return x, y

    # the unscanned block x 9-11, y 5.5-7 in room B's north-east corner; from room B's south-west,
    # by door_1, the robot walks up to its south side
    x, y = towards((7.0, 2.0, 0.0))
    assert 9.0 + IN_FRONT_M <= x <= 11.0 and 5.5 - 0.95 <= y <= 5.5 - 0.15
    # from room A the walk goes through door_2 (6.075, 5.0): it arrives from the west
    x, y = towards((3.0, 2.0, 0.0))
    assert 9.0 - 0.95 <= x <= 9.0 - 0.15 and 5.5 + IN_FRONT_M <= y <= 7.0


def test_a_corner_filled_by_furniture_is_reached_from_its_own_room() -> None:
    # two rooms parted by a wall at x = 5; in the west room a cabinet fills its north-east corner
    # but for 0.2 m slits: no spot near the corner is free on its side, while the east room's floor
    # lies just behind the wall
    b = MapBuilder(11.0, 7.0)
    b.room(1.0, 1.0, 10.0, 6.0)
    b.wall(5.0, 1.0, 5.0, 6.0)
    b.door_v(5.0, 2.0, 0.9)
    b.box(3.6, 4.6, 4.8, 5.8)
    a = analyze(b.build("cabinet"), DEFAULT_PARAMS)
    pose = (3.2, 4.0, 45.0)  # the north-east corner is the nearest (2.7 m; the north-west 3.0 m)
    room = a.room_at(3.2, 4.0)
    assert room is not None
    r = Planner(get_translator("offline")).plan("go to the nearest corner", a, pose)
    assert r.ok, r.clarification
    navs = [c for c in r.commands if isinstance(c, NavigateThroughPoses)]
    x, y = navs[-1].poses[-1][0], navs[-1].poses[-1][1]
    assert a.room_at(x, y) is room  # not behind the wall in the east room
    assert math.dist((x, y), (4.925, 5.925)) <= 2.0
