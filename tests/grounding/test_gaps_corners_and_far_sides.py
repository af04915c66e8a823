"""Session 9's place rules, on golden maps built here and read by the real analysis where it matters.

* a door cut in something deeper than a wall (a gap between two parked cars) is passed past its far end;
* a narrow gap between two things standing free (two screens end to end) is "the narrow gap", however
  thin the things are, when the analysis has no passage there;
* "the left corner" is never a corner on the robot's right;
* "the opposite side of this room" ends in the third of the room farthest from the robot (README).
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np
import pytest

from langnav.analysis.elements import Door, MapAnalysis
from langnav.analysis.pipeline import analyze
from langnav.grounding import GroundingError, ground
from langnav.grounding.geometry import Pose
from langnav.grounding.ground import THROUGH_MIN_PAST_M
from langnav.grounding.selection import gaps_between_things, select, things_standing_free
from langnav.language.intent import ElementRef, Intent, Step
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import FREE


def ref(**kw: Any) -> ElementRef:
    return ElementRef.model_validate(kw)


def last_pose(analysis: MapAnalysis, pose: tuple[float, float, float], **step: Any) -> tuple[float, float]:
    plan = ground(Intent(steps=[Step.model_validate(step)]), analysis, pose)
    x, y = plan.commands[-1].poses[-1][:2]  # type: ignore[attr-defined]
    return x, y


@pytest.fixture(scope="module")
def deep_gap() -> MapAnalysis:
    """A 10 x 10 m room parted at y 5.0-6.8 by two blocks 1.8 m deep (two cars nose to the walls)
    with a 0.8 m gap between them at x 5.6-6.4."""
    b = MapBuilder(12.0, 12.0)
    b.room(1.0, 1.0, 11.0, 11.0)
    b.box(1.0, 5.0, 5.6, 6.8)
    b.box(6.4, 5.0, 11.0, 6.8)
    return analyze(b.build("deep_gap"))


def test_through_a_door_cut_in_something_deep_ends_past_its_far_end(deep_gap: MapAnalysis) -> None:
    # the door as an analysis may place it: in the middle of the gap, with no passage found along it
    door = Door("door_1", (6.0, 5.9), 0.8, ((5.6, 5.9), (6.4, 5.9)), (0.0, 1.0), deep_gap.doors[0].connects)
    a = dataclasses.replace(deep_gap, doors=(door,), narrow_passages=())
    x, y = last_pose(a, (6.0, 3.0, 90.0), movement="navigate", detail="through", target={"kind": "door"})
    assert y >= 6.8 + THROUGH_MIN_PAST_M - 0.05 and math.dist((x, y), door.center) <= 2.0
    assert abs(x - 6.0) <= 0.5
    # from the far side the other way
    x, y = last_pose(a, (6.0, 9.0, 270.0), movement="navigate", detail="through", target={"kind": "door"})
    assert y <= 5.0 - THROUGH_MIN_PAST_M + 0.05 and math.dist((x, y), door.center) <= 2.0


def test_a_door_in_a_wall_is_passed_as_before(two_rooms: MapAnalysis) -> None:
    # door_1 of the two-room world is cut in a 0.15 m wall: the goal is 0.8 m past its centre line
    x, y = last_pose(two_rooms, (3.0, 2.0, 0.0), movement="navigate", detail="through", target={"kind": "door"})
    assert 6.075 + 0.6 <= x <= 6.075 + 1.0 and abs(y - 2.0) <= 0.3


@pytest.fixture(scope="module")
def screens() -> MapAnalysis:
    """A 10 x 8 m room with two acoustic screens 0.2 m thick end to end at y 5.0-5.2, a 0.7 m gap
    between them at x 5.3-6.0 and 2 m of floor between each screen and the side walls."""
    b = MapBuilder(12.0, 10.0)
    b.room(1.0, 1.0, 11.0, 9.0)
    b.box(3.3, 5.0, 5.3, 5.2)
    b.box(6.0, 5.0, 8.0, 5.2)
    return analyze(b.build("screens"))


def test_the_gap_between_two_thin_things_is_a_narrow_gap(screens: MapAnalysis) -> None:
    assert len(screens.obstacles) == 2
    gaps = gaps_between_things(screens)
    assert len(gaps) == 1
    gap = gaps[0]
    assert abs(gap.width_m - 0.7) <= 0.1
    assert abs(gap.center[0] - 5.65) <= 0.1 and abs(gap.center[1] - 5.1) <= 0.15
    # the analysis finds it too (a gap in a line of free-standing things), one passage, no double
    (passage,) = [p for p in screens.narrow_passages if math.dist(p.center, gap.center) < 1.0]
    assert abs(passage.width_m - 0.7) <= 0.1
    pose = Pose.from_deg(5.65, 3.0, 90.0)
    assert select(ref(kind="narrow_passage", side="ahead"), screens, pose).id == passage.id
    x, y = last_pose(screens, (5.65, 3.0, 90.0), movement="navigate", detail="through",
                     target={"kind": "narrow_passage", "side": "ahead"})
    assert abs(x - 5.65) <= 0.3 and 5.2 + THROUGH_MIN_PAST_M - 0.05 <= y <= 5.1 + 2.0


def test_no_gap_where_things_stand_far_apart_or_a_thing_is_in_the_way() -> None:
    b = MapBuilder(12.0, 10.0)
    b.room(1.0, 1.0, 11.0, 9.0)
    b.box(2.0, 5.0, 4.0, 5.2)
    b.box(5.5, 5.0, 8.0, 5.2)  # 1.5 m apart: wider than a narrow passage
    assert gaps_between_things(analyze(b.build("apart"))) == []
    b = MapBuilder(12.0, 10.0)
    b.room(1.0, 1.0, 11.0, 9.0)
    b.box(2.0, 5.0, 4.0, 5.2)
    b.box(4.2, 5.0, 6.0, 5.2)  # 0.2 m apart: narrower than the robot
    assert gaps_between_things(analyze(b.build("tight"))) == []


def test_the_left_corner_is_never_on_the_right(two_rooms: MapAnalysis) -> None:
    pose = Pose.from_deg(3.0, 3.0, 90.0)  # room A facing north: c_a_nw ahead-left, c_a_ne ahead-right
    assert select(ref(kind="corner", side="left"), two_rooms, pose).id == "c_a_nw"
    assert select(ref(kind="corner", side="right"), two_rooms, pose).id == "c_a_ne"
    # the room's north-west corner not found (a stub of wall missing): the one corner ahead is on the
    # right, and no corner in front of the robot is on its left: it asks
    no_nw = dataclasses.replace(two_rooms, corners=tuple(c for c in two_rooms.corners if c.id != "c_a_nw"))
    assert select(ref(kind="corner", side="right"), no_nw, pose).id == "c_a_ne"
    with pytest.raises(GroundingError, match="on your left"):
        select(ref(kind="corner", side="left"), no_nw, pose)


@pytest.mark.parametrize("pose", [(5.5, 1.5, 90.0), (5.0, 1.5, 180.0), (1.5, 3.0, 90.0), (1.5, 1.5, 45.0),
                                  (5.5, 6.5, 200.0), (3.5, 4.0, 0.0)])
def test_the_opposite_side_is_in_the_third_of_the_room_farthest_away(two_rooms: MapAnalysis,
                                                                       pose: tuple[float, float, float]) -> None:
    x, y = last_pose(two_rooms, pose, movement="navigate", detail="opposite_side_of",
                     target={"kind": "room", "in_current_room": True})
    cells = np.asarray(two_rooms.rooms[0].cells_xy, dtype=float)
    r = np.hypot(cells[:, 0] - pose[0], cells[:, 1] - pose[1])
    assert math.dist((x, y), pose[:2]) >= float(np.quantile(r, 2 / 3)) - 0.1
    assert 1.0 < x < 6.0 and 1.0 < y < 7.0  # in room A


@pytest.fixture(scope="module")
def parked_cars() -> MapAnalysis:
    """A 12 x 10 m room with two cars 1.8 m deep across it at y 5.0-6.8: one nose to the west wall
    (x 1.0-5.6), one standing free (x 6.4-11.5) with 0.8 m and 1.5 m of floor at its ends. The
    analysis parts the room along the cars and counts both as wall structure."""
    b = MapBuilder(14.0, 12.0)
    b.room(1.0, 1.0, 13.0, 11.0)
    b.box(1.0, 5.0, 5.6, 6.8)
    b.box(6.4, 5.0, 11.5, 6.8)
    return analyze(b.build("parked_cars"))


def test_a_thing_standing_free_is_an_obstacle_whatever_line_the_analysis_draws(parked_cars: MapAnalysis) -> None:
    assert len(parked_cars.rooms) == 2 and not parked_cars.obstacles  # the analysis: a partition
    things = things_standing_free(parked_cars)
    assert len(things) == 1  # the car against the wall is the wall's, to this rule as to the analysis
    car = things[0]
    assert abs(car.centroid[0] - 8.95) <= 0.1 and abs(car.centroid[1] - 5.9) <= 0.1
    assert abs(car.extent_m[0] - 5.1) <= 0.15 and abs(car.extent_m[1] - 1.8) <= 0.15
    pose = Pose.from_deg(9.0, 3.0, 90.0)
    assert select(ref(kind="obstacle", side="ahead"), parked_cars, pose).id == car.id
    x, y = last_pose(parked_cars, (9.0, 3.0, 90.0), movement="navigate", detail="next_to",
                     target={"kind": "obstacle", "side": "ahead"})
    assert 6.4 <= x <= 11.5 and 5.0 - 1.0 <= y < 5.0


def test_a_wall_stub_is_no_thing_standing_free(two_rooms: MapAnalysis) -> None:
    # the two-room world's partition runs into the outer walls, and its box is the analysis's obstacle
    assert things_standing_free(two_rooms) == []


def test_the_two_nearest_obstacles_are_those_in_sight_not_one_behind_a_wall() -> None:
    """Two rooms parted by a wall at x 7 (door at y 7). The robot in the east room at (8, 3) facing
    east: a box 1 m ahead, a second box 3 m ahead beyond it, and in the west room a box 2 m away by a
    straight line through the wall."""
    b = MapBuilder(14.0, 10.0)
    b.room(1.0, 1.0, 13.0, 9.0)
    b.wall(7.0, 1.0, 7.0, 9.0, 0.15)
    b.door_v(7.0, 7.0, 0.9)
    b.box(9.0, 2.7, 9.6, 3.3)
    b.box(11.0, 2.7, 11.6, 3.3)
    b.box(5.0, 2.7, 6.0, 3.3)
    a = analyze(b.build("behind_a_wall"))
    assert len(a.obstacles) == 3
    x, y = last_pose(a, (8.0, 3.0, 0.0), movement="navigate", detail="between",
                     target={"kind": "obstacle", "superlative": "nearest"})
    assert math.dist((x, y), (10.3, 3.0)) <= 0.75


def test_the_gap_between_a_thing_standing_free_and_a_box_is_a_narrow_passage() -> None:
    """The parked car standing free of ``parked_cars`` with a box 0.7 m past its east end (the box
    0.2 m from the east wall: no way there): the narrow passage ahead of a robot south of it is that gap,
    whatever spaces the analysis cut round the car."""
    b = MapBuilder(14.0, 12.0)
    b.room(1.0, 1.0, 13.0, 11.0)
    b.box(1.0, 5.0, 5.6, 6.8)
    b.box(6.4, 5.0, 11.5, 6.8)
    b.box(12.2, 5.5, 12.8, 6.3)
    a = analyze(b.build("car_and_box"))
    gaps = [g for g in gaps_between_things(a) if abs(g.center[0] - 11.85) <= 0.15]
    assert len(gaps) == 1 and abs(gaps[0].width_m - 0.7) <= 0.1
    x, y = last_pose(a, (11.85, 3.0, 90.0), movement="navigate", detail="through",
                     target={"kind": "narrow_passage", "side": "ahead"})
    assert abs(x - 11.85) <= 0.3 and 6.3 + THROUGH_MIN_PAST_M - 0.05 <= y <= 5.9 + 2.0


@pytest.fixture(scope="module")
def gap_far() -> MapAnalysis:
    """Two rooms joined by a 0.9 m doorway at x 6, y 4; in the right-hand room two thin screens end to
    end with a 0.6 m gap between them (x 10-10.6, y 2.5-2.7). (The session-9 review's map.)"""
    b = MapBuilder(14.0, 8.0)
    b.room(1.0, 1.0, 13.0, 7.0)
    b.wall(6.0, 1.0, 6.0, 7.0)
    b.door_v(6.0, 4.0, 0.9)
    b.box(8.0, 2.5, 10.0, 2.7)
    b.box(10.6, 2.5, 12.0, 2.7)
    return analyze(b.build("gap_far"))


def test_a_gap_between_things_behind_a_wall_is_not_the_gap_in_front(gap_far: MapAnalysis) -> None:
    # the robot in the left room facing the doorway: "the gap" is the doorway, not the screens' gap 7 m
    # away in the other room; "the narrow passage" sees none from here
    assert gaps_between_things(gap_far), "the screens' gap exists"
    x, _ = last_pose(gap_far, (3.0, 4.0, 0.0), movement="navigate", detail="through", target={"kind": "door"},
                     text="go through the gap")
    assert 6.0 < x < 8.0
    with pytest.raises(GroundingError):
        ground(Intent(steps=[Step.model_validate({"movement": "navigate", "detail": "through",
                                                  "target": {"kind": "narrow_passage"}})]), gap_far, (3.0, 4.0, 0.0))
    # from the right-hand room, in sight, the screens' gap is the narrow passage
    x, y = last_pose(gap_far, (9.0, 4.0, 270.0), movement="navigate", detail="through",
                     target={"kind": "narrow_passage"})
    assert 10.0 <= x <= 10.6 and y < 2.5


def test_a_thing_on_your_side_beyond_another_thing_is_seen_a_thing_behind_a_wall_is_not() -> None:
    """Only walls hide a thing one places by side: a plant beyond a bench row in the same room is seen
    over the benches. One room (x 1-13, y 1-9) with a wall at x 10 (door at y 8): the robot at (4, 1.8)
    facing north; a bench row (x 2-6, y 3-3.5) ahead-left; a plant (x 6.6-7.2, y 6-6.6) on the right,
    the line to its nearest cell crossing the bench row; beyond the wall a box on the right, nearer."""
    b = MapBuilder(14.0, 10.0)
    b.room(1.0, 1.0, 13.0, 9.0)
    b.wall(10.0, 1.0, 10.0, 9.0, 0.15)
    b.door_v(10.0, 8.0, 0.9)
    b.box(2.0, 3.0, 6.0, 3.5)
    b.box(6.6, 6.0, 7.2, 6.6)
    b.box(10.6, 2.0, 11.2, 2.6)
    a = analyze(b.build("plant_beyond_benches"))
    assert len(a.obstacles) == 3
    x, y = last_pose(a, (4.0, 1.8, 90.0), movement="navigate", detail="next_to",
                     target={"kind": "obstacle", "side": "right"})
    # next to the plant (within 1.0 m of its edge), not the box beyond the wall
    assert (round(x, 3), round(y, 3)) == (6.875, 5.575)
    # with the plant gone, the box beyond the wall is no thing on the robot's right: ask
    b.rect(6.6, 6.0, 7.2, 6.6, FREE)
    a = analyze(b.build("box_behind_a_wall"))
    with pytest.raises(GroundingError, match="behind a wall"):
        last_pose(a, (4.0, 1.8, 90.0), movement="navigate", detail="next_to", target={"kind": "obstacle", "side": "right"})
