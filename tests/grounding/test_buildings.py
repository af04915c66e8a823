"""Grounding on buildings other than the bench's, analysed by the real analysis and read by the
offline translator end to end: an L-shaped corridor with rooms on both sides, the same floor turned
a quarter turn (north-south becomes east-west: no rule may lean on the map's axes) and a floor
with one room half unscanned. Each test asserts the region the goal lies in.

The L (``build_l``), metres; hallway = leg A (y 5-7, x 1-12) + leg B (x 10-12, y 7-17):

    y=17 +   unknown   +---------+--+---------+
         |             | room 5  |  | room 3  |
    y=11 +-------------+   D(10,14) D(12,13)  |
         |   room 2 (x 1-10, y 7-11) |B |     |
    y=7  +----D(4,7)-------------+  |  +------+ y=9
         |          leg A           D(12,6)   |
    y=5  +--D(3,5)----D(7,5)---D(10.5,5)------+ room 4 (x 12-16, y 1-9)
         | room 6  | room 7  | room 8  |      |
    y=1  +---------+---------+---------+------+
        x=1       x=5       x=9       x=12   x=16
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import pytest

from langnav.analysis.elements import ElementKind, MapAnalysis, Room
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.pipeline import analyze
from langnav.grounding.selection import unscanned_part_m2
from langnav.language.translator import get_translator
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import OccupancyGrid
from langnav.pipeline import Planner, PlanResult
from langnav.plan.commands import NavigateThroughPoses

Point = tuple[float, float]
#: A frame change of the floor: world point of the drawn floor -> world point of the map.
Frame = Callable[[Point], Point]


def build_l_grid() -> OccupancyGrid:
    b = MapBuilder(18.0, 18.0)
    b.room(1.0, 1.0, 16.0, 17.0)
    b.unknown(1.0, 11.0, 6.0, 17.0)  # the north-west block is not part of the building
    b.wall(1.0, 11.0, 6.0, 11.0, 0.3)
    b.wall(6.0, 11.0, 6.0, 17.0, 0.3)
    b.wall(1.0, 5.0, 12.0, 5.0)
    b.wall(1.0, 7.0, 10.0, 7.0)
    b.wall(10.0, 7.0, 10.0, 17.0)
    b.wall(12.0, 1.0, 12.0, 17.0)
    b.wall(5.0, 1.0, 5.0, 5.0)
    b.wall(9.0, 1.0, 9.0, 5.0)
    b.wall(6.0, 11.0, 10.0, 11.0)
    b.wall(12.0, 9.0, 16.0, 9.0)
    for x in (3.0, 7.0, 10.5):
        b.door_h(x, 5.0, 0.9)
    b.door_h(4.0, 7.0, 0.9)
    b.door_v(10.0, 14.0, 0.9)
    b.door_v(12.0, 6.0, 0.9)
    b.door_v(12.0, 13.0, 0.9)
    return b.build("l_corridor")


def quarter_turn(grid: OccupancyGrid) -> tuple[OccupancyGrid, Frame]:
    """The floor turned a quarter turn clockwise, as a map of its own (exact: cells map to cells;
    headings turn by -90 degrees), and where a point of the drawn floor is on it."""
    width_m = grid.cells.shape[1] * grid.resolution_m
    cells = np.rot90(grid.cells).copy()  # row 0 is the bottom: (x, y) -> (y, width - x)
    turned = OccupancyGrid(cells, grid.resolution_m, 0.0, 0.0, 0.0, f"{grid.source}_turned")
    return turned, lambda p: (p[1], width_m - p[0])


def identity(p: Point) -> Point:
    return p


FLOORS: dict[str, tuple[MapAnalysis, Frame]] = {}


def floor(name: str) -> tuple[MapAnalysis, Frame]:
    if name not in FLOORS:
        grid = build_l_grid()
        frame: Frame = identity
        if name == "turned":
            grid, frame = quarter_turn(grid)
        FLOORS[name] = (analyze(grid, DEFAULT_PARAMS), frame)
    return FLOORS[name]


def pose_in(frame: Frame, x: float, y: float, yaw_deg: float, turn_deg: float) -> tuple[float, float, float]:
    fx, fy = frame((x, y))
    return (fx, fy, (yaw_deg + turn_deg) % 360.0)


def plan(prompt: str, a: MapAnalysis, pose: tuple[float, float, float]) -> PlanResult:
    return Planner(get_translator("offline")).plan(prompt, a, pose)


def last_goal(r: PlanResult) -> Point:
    assert r.ok, r.clarification
    navs = [c for c in r.commands if isinstance(c, NavigateThroughPoses)]
    assert navs, r.commands
    return (navs[-1].poses[-1][0], navs[-1].poses[-1][1])


def room_holding(a: MapAnalysis, frame: Frame, x: float, y: float) -> Room:
    r = a.room_at(*frame((x, y)))
    assert r is not None, f"the analysis has no space at ({x}, {y})"
    return r


CASES = [("drawn", 0.0), ("turned", -90.0)]


@pytest.mark.parametrize(("name", "turn"), CASES)
def test_the_l_floor_is_what_the_tests_expect(name: str, turn: float) -> None:
    a, frame = floor(name)
    assert sorted(r.kind.value for r in a.rooms) == ["hallway"] + ["room"] * 7
    assert len(a.doors) == 7
    hall = room_holding(a, frame, 6.0, 6.0)
    assert hall.kind == ElementKind.HALLWAY and room_holding(a, frame, 11.0, 15.0) is hall


@pytest.mark.parametrize(("name", "turn"), CASES)
@pytest.mark.parametrize("words", ["first", "nearest"])
def test_the_first_room_on_your_left_is_by_straight_line(name: str, turn: float, words: str) -> None:
    # the contract's order: straight-line distance to the room's nearest cell (room 2's wall runs
    # beside the robot in leg B, though its door is back in leg A)
    a, frame = floor(name)
    r = plan(f"go into the {words} room on your left", a, pose_in(frame, 11.0, 10.0, 90.0, turn))
    assert a.room_at(*last_goal(r)) is room_holding(a, frame, 5.0, 9.0)


@pytest.mark.parametrize(("name", "turn"), CASES)
def test_the_last_door_on_your_right_down_leg_a(name: str, turn: float) -> None:
    a, frame = floor(name)
    r = plan("go to the last door on your right", a, pose_in(frame, 2.0, 6.0, 0.0, turn))
    assert math.dist(last_goal(r), frame((10.5, 5.0))) <= 0.75


@pytest.mark.parametrize(("name", "turn"), CASES)
def test_a_metre_past_a_door_stays_in_the_hallway(name: str, turn: float) -> None:
    # 1 m past the door of room 8 (x 10.5) runs down leg A to the bend, in the hallway's middle
    a, frame = floor(name)
    start = (3.0, 6.0)
    r = plan("go 1 metre past the third door on your right", a, pose_in(frame, *start, 0.0, turn))
    goal = last_goal(r)
    hall = room_holding(a, frame, 6.0, 6.0)
    assert a.room_at(*goal) is hall
    door = frame((10.5, 5.0))
    along = math.dist(frame(start), goal) if turn else goal[0] - start[0]
    assert along <= (10.5 - start[0]) + 1.0 + 0.06  # never farther than asked
    assert math.dist(goal, door) >= 0.9


# ------------------------------------------------------------------------------ a room half scanned
def build_half_scanned() -> MapAnalysis:
    """A hallway (y 10-12) with room A (x 1-8, y 6-10) and room B (x 8-17, y 1-10) south of it; B's
    south part (y 1-7.5) is not scanned yet, and behind A's south door is room G (y 1-6), never
    entered: unknown seen through a doorway only."""
    b = MapBuilder(18.0, 13.0)
    b.room(1.0, 1.0, 17.0, 12.0)
    b.wall(1.0, 10.0, 17.0, 10.0)
    b.wall(8.0, 1.0, 8.0, 10.0)
    b.wall(1.0, 6.0, 8.0, 6.0)
    b.door_h(4.0, 10.0, 0.9)
    b.door_h(12.0, 10.0, 0.9)
    b.door_h(4.0, 6.0, 0.9)
    b.unknown(1.0, 1.0, 7.9, 5.9)
    b.unknown(8.1, 1.0, 17.0, 7.5)
    return analyze(b.build("half_scanned"), DEFAULT_PARAMS)


@pytest.fixture(scope="module")
def half() -> MapAnalysis:
    return build_half_scanned()


def test_the_biggest_room_counts_its_unscanned_part(half: MapAnalysis) -> None:
    a_room, b_room = half.room_at(4.0, 8.0), half.room_at(12.0, 9.0)
    assert a_room is not None and b_room is not None
    assert b_room.area_m2 < a_room.area_m2  # scanned so far, B is the smaller
    x, y = last_goal(plan("go into the biggest room", half, (2.0, 11.0, 0.0)))
    assert half.room_at(x, y) is b_room
    x, y = last_goal(plan("go into the smallest room", half, (2.0, 11.0, 0.0)))
    assert half.room_at(x, y) is a_room


def test_a_room_seen_through_a_doorway_is_not_part_of_the_room(half: MapAnalysis) -> None:
    a_room, b_room = half.room_at(4.0, 8.0), half.room_at(12.0, 9.0)
    assert a_room is not None and b_room is not None
    assert unscanned_part_m2(a_room, half) == 0.0  # room G, behind A's door
    assert unscanned_part_m2(b_room, half) == pytest.approx(8.9 * 6.5, rel=0.05)


# ------------------------------------------------------------------------------ following the L
#: The walk's lattice may make the way a little longer than the shortest one (a lattice step).
WAY_SLACK_M = 0.3


def drawn_point(name: str, p: Point) -> Point:
    """A point of the map back on the drawn floor (the quarter turn undone)."""
    return p if name == "drawn" else (18.0 - p[1], p[0])


@pytest.mark.parametrize(("name", "turn"), CASES)
@pytest.mark.parametrize("fraction", [("a quarter of the way", 0.25), ("halfway", 0.5),
                                      ("three quarters of the way", 0.75)])
def test_a_fraction_down_the_l_corridor_is_of_its_straight_run(name: str, turn: float,
                                                               fraction: tuple[str, float]) -> None:
    # "down this corridor" is the straight run ahead: at the L's bend this corridor ends (leg B is
    # the corridor one turns into), so halfway down leg A is halfway to the bend, in leg A
    a, frame = floor(name)
    hall = room_holding(a, frame, 6.0, 6.0)
    words, f = fraction
    r = plan(f"go {words} down the corridor", a, pose_in(frame, 2.0, 6.0, 0.0, turn))
    goal = drawn_point(name, last_goal(r))
    assert a.room_at(*last_goal(r)) is hall
    assert 5.0 < goal[1] < 7.0  # in leg A
    run = 11.0 - 2.0  # from the robot to leg B's middle line, where the run turns
    assert goal[0] - 2.0 <= f * run + WAY_SLACK_M  # never farther than asked
    assert goal[0] - 2.0 >= f * run - 1.0


@pytest.mark.parametrize(("name", "turn"), CASES)
def test_the_end_of_the_l_corridor_is_its_bend(name: str, turn: float) -> None:
    a, frame = floor(name)
    x, y = drawn_point(name, last_goal(plan("go to the end of the corridor", a, pose_in(frame, 2.0, 6.0, 0.0, turn))))
    assert 9.0 < x < 12.0 and 5.0 < y < 7.5  # at the bend, not up leg B


@pytest.mark.parametrize(("name", "turn"), CASES)
def test_following_the_l_corridor_ends_at_its_far_end_in_the_hallway(name: str, turn: float) -> None:
    a, frame = floor(name)
    hall = room_holding(a, frame, 6.0, 6.0)
    r = plan("follow the corridor", a, pose_in(frame, 2.0, 6.0, 0.0, turn))
    assert r.ok, r.clarification
    (c,) = r.commands
    assert isinstance(c, NavigateThroughPoses) and len(c.poses) >= 3
    for p in c.poses:
        assert a.room_at(p[0], p[1]) is hall
    x, y = drawn_point(name, last_goal(r))
    assert 10.0 < x < 12.0 and y >= 15.5
    # and back the other way from leg B, facing down it
    back = plan("follow the corridor", a, pose_in(frame, 11.0, 12.0, 270.0, turn))
    x, y = drawn_point(name, last_goal(back))
    assert x <= 2.5 and 5.0 < y < 7.0


def test_doors_are_counted_among_those_of_the_space_the_robot_is_in(half: MapAnalysis) -> None:
    # in the hallway facing east: its two doors are on the right; the door between room A and the
    # unscanned room G is no door of the hallway, so there is no third door on the right
    second = plan("go to the second door on your right", half, (2.0, 11.0, 0.0))
    assert math.dist(last_goal(second), (12.0, 10.0)) <= 0.75
    third = plan("go to the third door on your right", half, (2.0, 11.0, 0.0))
    assert not third.ok and third.commands == ()
    assert "only two doors on your right" in (third.clarification or "")


# ------------------------------------------------------------------------------ staggered rooms
def build_staggered() -> MapAnalysis:
    """A hallway (y 5-7, x 1-17); rooms south (x 1-6, 6-11, 11-17; doors at their west ends) and
    north (x 1-4, 4-9, 9-17; doors at their east ends): rooms wider than their doors, doors far from
    straight across each other."""
    b = MapBuilder(18.0, 12.0)
    b.room(1.0, 1.0, 17.0, 11.0)
    b.wall(1.0, 5.0, 17.0, 5.0)
    b.wall(1.0, 7.0, 17.0, 7.0)
    for x in (6.0, 11.0):
        b.wall(x, 1.0, x, 5.0)
    for x in (4.0, 9.0):
        b.wall(x, 7.0, x, 11.0)
    for x in (2.0, 7.0, 12.0):
        b.door_h(x, 5.0, 0.9)
    for x in (3.5, 8.5, 16.0):
        b.door_h(x, 7.0, 0.9)
    return analyze(b.build("staggered"), DEFAULT_PARAMS)


@pytest.fixture(scope="module")
def staggered() -> MapAnalysis:
    return build_staggered()


@pytest.mark.parametrize(("prompt", "pose"), [
    ("go into the room across the hall", (5.0, 5.6, 90.0)),     # near the middle, facing north
    ("go into the room across the hall", (5.0, 5.3, 270.0)),    # by the south wall, facing it
    ("turn around, then go into the room across the hall", (5.0, 6.0, 270.0)),
])
def test_the_room_across_the_hall_is_judged_by_its_extent(staggered: MapAnalysis, prompt: str,
                                                          pose: tuple[float, float, float]) -> None:
    # the north room x 4-9 spans the robot's place along the hallway, though its door is 3.5 m on
    x, y = last_goal(plan(prompt, staggered, pose))
    assert staggered.room_at(x, y) is staggered.room_at(6.5, 9.0)


def test_two_rooms_equally_across_are_asked_about(staggered: MapAnalysis) -> None:
    # at x 9 the wall between the north rooms x 4-9 and 9-17 is straight across
    r = plan("go into the room across the hall", staggered, (9.0, 6.0, 90.0))
    assert not r.ok and r.commands == () and "which one" in (r.clarification or "")


@pytest.mark.parametrize(("yaw", "end_x"), [(0.0, 17.0), (180.0, 1.0)])
@pytest.mark.parametrize("words", ["go to the end of the hall", "go to the end of the corridor"])
def test_the_end_of_the_hall_is_the_end_ahead(staggered: MapAnalysis, yaw: float, end_x: float, words: str) -> None:
    # the last metre before the end wall ahead, in the hallway
    x, y = last_goal(plan(words, staggered, (5.0, 6.0, yaw)))
    assert staggered.room_at(x, y) is staggered.room_at(5.0, 6.0)
    assert 0.2 <= abs(end_x - x) <= 1.0 and 5.0 < y < 7.0


# ------------------------------------------------------------------------------ stepping into the hallway
@pytest.mark.parametrize(("name", "turn"), CASES)
def test_out_into_the_hallway_stops_outside_the_door_facing_across(name: str, turn: float) -> None:
    # from room 7 (door at (7, 5)): just outside its door in leg A, not the hallway's middle far up
    # leg B; then the first door on the left is the next one along, not the door it came out of
    a, frame = floor(name)
    r = plan("go out into the hallway, then go to the first door on your left", a, pose_in(frame, 7.0, 3.0, 90.0, turn))
    assert r.ok, r.clarification
    out = r.items[0].commands[-1].poses[-1]  # type: ignore[attr-defined]
    x, y = drawn_point(name, (out[0], out[1]))
    assert abs(x - 7.0) <= 0.75 and 5.2 <= y <= 7.0
    assert math.dist(drawn_point(name, last_goal(r)), (4.0, 7.0)) <= 0.75


@pytest.mark.parametrize(("name", "turn"), CASES)
def test_into_the_hallway_when_in_it_is_no_move(name: str, turn: float) -> None:
    a, frame = floor(name)
    r = plan("go in the corridor to the second door on your right", a, pose_in(frame, 2.0, 6.0, 0.0, turn))
    assert r.ok, r.clarification
    assert not r.items[0].commands  # in the hallway already
    assert math.dist(drawn_point(name, last_goal(r)), (7.0, 5.0)) <= 0.75  # D(3,5), then D(7,5)


@pytest.mark.parametrize(("name", "turn"), CASES)
def test_it_is_the_element_of_the_step_before(name: str, turn: float) -> None:
    # "it" is read with the words of the room before; from inside that room those words would pick
    # another room, so "it" is that room, by its label (kept when the step is grounded again)
    a, frame = floor(name)
    r = plan("go into the first room on your left and then go to the middle of it", a, pose_in(frame, 2.0, 6.0, 0.0, turn))
    assert r.ok, r.clarification
    room2 = room_holding(a, frame, 5.0, 9.0)
    assert a.room_at(*last_goal(r)) is room2 and math.dist(last_goal(r), room2.centroid) <= 0.75
    assert r.items[1].step.target is not None and r.items[1].step.target.label is not None


# ------------------------------------------------------------------------------ across the hall by the bend
@pytest.mark.parametrize(("name", "turn"), CASES)
@pytest.mark.parametrize("words", ["go into the room across the hall", "go to the room on the other side of the hall"])
def test_across_from_a_door_by_the_bend_is_straight_through_it(name: str, turn: float, words: str) -> None:
    # room 8's door (10.5, 5) is by the bend of the L: the hallway's cells round it run two ways, so
    # across is taken from the door itself: room 2 (x 1-10, y 7-11) straight over leg A, not room 5,
    # whose door opens onto leg B round the corner, nor room 7 beside room 8 on the same side
    a, frame = floor(name)
    r = plan(words, a, pose_in(frame, 10.5, 3.0, 90.0, turn))
    assert a.room_at(*last_goal(r)) is room_holding(a, frame, 5.0, 9.0)


@pytest.mark.parametrize(("name", "turn"), CASES)
@pytest.mark.parametrize("words", ["stop between the first and second doors on your right",
                                   "stop btwn the 1st and 2nd doors on the right"])
def test_between_two_doors_said_with_one_noun(name: str, turn: float, words: str) -> None:
    # leg A, facing east: the doors on the right are room 6's (3, 5) and room 7's (7, 5)
    a, frame = floor(name)
    r = plan(words, a, pose_in(frame, 2.0, 6.0, 0.0, turn))
    assert math.dist(last_goal(r), frame((5.0, 5.0))) <= 0.75


# ------------------------------------------------------------------------------ across from an alcove
def build_alcove() -> MapAnalysis:
    """A hallway (y 5-7, x 1-17) with a lift lobby open to it on the north (x 7-11, y 7-10.5), rooms north
    either side of the lobby and three rooms south, room 2 (x 6-12) straight across from the lobby."""
    b = MapBuilder(18.0, 12.0)
    b.room(1.0, 1.0, 17.0, 10.5)
    b.wall(1.0, 5.0, 17.0, 5.0)
    b.wall(1.0, 7.0, 7.0, 7.0)
    b.wall(11.0, 7.0, 17.0, 7.0)
    b.wall(7.0, 7.0, 7.0, 10.5)
    b.wall(11.0, 7.0, 11.0, 10.5)
    b.wall(6.0, 1.0, 6.0, 5.0)
    b.wall(12.0, 1.0, 12.0, 5.0)
    for x in (3.5, 9.0, 14.5):
        b.door_h(x, 5.0, 0.9)
    b.door_h(4.0, 7.0, 0.9)
    b.door_h(14.0, 7.0, 0.9)
    return analyze(b.build("alcove"), DEFAULT_PARAMS)


@pytest.mark.parametrize(("prompt", "yaw"), [("turn around, then go into the room across the hall", 90.0),
                                             ("go into the room across the hall", 270.0)])
def test_across_the_hall_from_a_lobby_off_it(prompt: str, yaw: float) -> None:
    # the lobby's cells near the robot run north-south as much as the hallway's run east-west: the
    # hallway's way is read past the lobby, and across is the side faced (south), not a question
    a = build_alcove()
    assert sorted(r.kind.value for r in a.rooms) == ["hallway"] + ["room"] * 5
    goal = last_goal(plan(prompt, a, (9.0, 9.5, yaw)))
    assert a.room_at(*goal) is a.room_at(9.0, 3.0)


# ------------------------------------------------------------------------------ rooms counted along a hallway
def build_inner_room() -> MapAnalysis:
    """A hallway (y 5-7, x 1-17) with three rooms north (x 1-6, 6-11, 11-17; y 7-10), each with a door
    onto it, and an inner room (x 1-6, y 10-14) behind the first, reached only through it: from the
    hallway's west end its nearest cell is nearer than the second room's."""
    b = MapBuilder(18.0, 15.0)
    b.room(1.0, 5.0, 17.0, 14.0)
    b.wall(1.0, 7.0, 17.0, 7.0)
    b.wall(6.0, 7.0, 6.0, 14.0)
    b.wall(11.0, 7.0, 11.0, 14.0)
    b.wall(1.0, 10.0, 6.0, 10.0)
    b.unknown(6.1, 10.1, 17.0, 14.0)
    b.wall(6.0, 10.0, 17.0, 10.0)
    for x in (3.5, 9.5, 14.0):
        b.door_h(x, 7.0, 0.9)
    b.door_h(3.5, 10.0, 0.9)
    return analyze(b.build("inner_room"), DEFAULT_PARAMS)


@pytest.mark.parametrize(("words", "room_point"), [("second", (8.5, 8.5)), ("third", (14.0, 8.5))])
def test_rooms_counted_from_a_hallway_are_the_rooms_along_it(words: str, room_point: Point) -> None:
    a = build_inner_room()
    inner = a.room_at(3.5, 12.0)
    assert inner is not None and inner.kind == ElementKind.ROOM
    goal = last_goal(plan(f"go into the {words} room on your left", a, (1.8, 6.0, 0.0)))
    assert a.room_at(*goal) is a.room_at(*room_point)


# ------------------------------------------------------------------------------ no short cut through a room
def build_corner_room() -> MapAnalysis:
    """An L corridor: leg A (y 1-3, x 1-15) then leg B (x 13-15, y 3-15); a room in the bend's inner corner
    (x 8-13, y 3-8) has a door onto each leg, (10.5, 3) and (13, 5.5): the shortest walk up the corridor
    cuts through it."""
    b = MapBuilder(16.0, 16.0)
    b.room(1.0, 1.0, 15.0, 15.0)
    b.wall(1.0, 3.0, 13.0, 3.0)
    b.wall(13.0, 3.0, 13.0, 15.0)
    b.wall(8.0, 3.0, 8.0, 8.0)
    b.wall(8.0, 8.0, 13.0, 8.0)
    b.unknown(1.2, 3.2, 7.8, 14.8)
    b.unknown(8.2, 8.2, 12.8, 14.8)
    b.door_h(10.5, 3.0, 0.9)
    b.door_v(13.0, 5.5, 0.9)
    return analyze(b.build("corner_room"), DEFAULT_PARAMS)


@pytest.mark.parametrize(("prompt", "box"), [
    ("go to the end of the corridor", (11.5, 15.0, 1.0, 3.5)),       # at the bend
    ("go halfway down the corridor", (6.0, 9.5, 1.0, 3.0)),          # half of leg A, not through the room
])
def test_down_the_corridor_walks_the_corridor(prompt: str, box: tuple[float, float, float, float]) -> None:
    a = build_corner_room()
    hall = a.room_at(4.0, 2.0)
    assert hall is not None and hall.kind == ElementKind.HALLWAY and a.room_at(14.0, 10.0) is hall
    r = plan(prompt, a, (2.0, 2.0, 0.0))
    x, y = last_goal(r)
    assert box[0] <= x <= box[1] and box[2] <= y <= box[3]
    navs = [c for c in r.commands if isinstance(c, NavigateThroughPoses)]
    assert all(a.room_at(p[0], p[1]) is hall for c in navs for p in c.poses)
