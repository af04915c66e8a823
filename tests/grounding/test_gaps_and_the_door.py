"""Gaps narrower than any door, and "the door" of a room with one door or several (the two-room world).

* an opening narrower than ``NARROW_GAP_MAX_M`` is "the narrow gap", not one of "the doors";
* spaces a gap joins are one room for counting its doors;
* "the door" of a room with one door is that door; the one the robot looks straight through; else ask.
"""

from __future__ import annotations

import dataclasses
from typing import Any

import pytest

from langnav.analysis.elements import Door, MapAnalysis
from langnav.grounding import GroundingError, ground
from langnav.grounding.geometry import Pose
from langnav.grounding.selection import NARROW_GAP_MAX_M, doors_of, gap_joined, select
from langnav.language.intent import ElementRef, Intent, Step

#: in room A facing north: door_1 (y 2) and door_2 (y 5) are both on its right, neither straight ahead
A_NORTH = (3.0, 3.0, 90.0)


def ref(**kw: Any) -> ElementRef:
    return ElementRef.model_validate(kw)


def with_gap(two_rooms: MapAnalysis) -> MapAnalysis:
    """The two-room world with door_2 narrowed to a 0.68 m gap (a gap between two shelves)."""
    d1, d2 = two_rooms.doors
    assert d2.width_m > NARROW_GAP_MAX_M
    gap = dataclasses.replace(d2, width_m=0.68, jambs=((6.075, 4.66), (6.075, 5.34)))
    return dataclasses.replace(two_rooms, doors=(d1, gap))


def test_a_gap_is_no_door_but_a_narrow_passage(two_rooms: MapAnalysis) -> None:
    a = with_gap(two_rooms)
    assert [d.id for d in doors_of(a)] == ["door_1"]
    pose = Pose.from_deg(*A_NORTH)
    assert select(ref(kind="narrow_passage"), a, pose).id == "door_2"
    assert select(ref(kind="door"), a, pose).id == "door_1"  # room A's one door
    assert select(ref(kind="door", label=2), a, pose).id == "door_2"  # the label drawn on the map still names it
    # without a gap the map has no narrow passage at all
    with pytest.raises(GroundingError, match="no narrow passages"):
        select(ref(kind="narrow_passage"), two_rooms, pose)


def test_the_gap_in_words_means_the_gap_when_there_is_one(two_rooms: MapAnalysis) -> None:
    a = with_gap(two_rooms)
    pose = Pose.from_deg(*A_NORTH)
    assert select(ref(kind="door"), a, pose, "go through the gap").id == "door_2"
    # with no gap on the map, "the gap" is a doorway
    assert select(ref(kind="door", side="right", ordinal=1), two_rooms, pose, "the first gap on your right").id == "door_1"


def test_through_the_gap_ends_past_it(two_rooms: MapAnalysis) -> None:
    a = with_gap(two_rooms)
    plan = ground(Intent(steps=[Step(movement="navigate", detail="through", target=ref(kind="narrow_passage"))]),
                  a, A_NORTH)
    x, y = plan.commands[0].poses[-1][:2]  # type: ignore[attr-defined]
    assert x > 6.15 and abs(y - 5.0) <= 2.0  # in room B, past the gap


def test_spaces_joined_by_a_gap_are_one_room(two_rooms: MapAnalysis) -> None:
    a = with_gap(two_rooms)
    room_a = a.rooms[0]
    assert [r.id for r in gap_joined(a, room_a)] == ["room_a", "room_b"]
    assert [r.id for r in gap_joined(two_rooms, room_a)] == ["room_a"]


def test_the_door_of_a_room_with_several_asks(two_rooms: MapAnalysis) -> None:
    with pytest.raises(GroundingError) as exc:
        select(ref(kind="door"), two_rooms, Pose.from_deg(*A_NORTH))
    assert "two doors" in str(exc.value) and "door 1" in str(exc.value) and "door 2" in str(exc.value)
    # facing door_1 squarely (the heading line passes through its opening): that one
    assert select(ref(kind="door"), two_rooms, Pose.from_deg(3.0, 2.0, 0.0)).id == "door_1"
    assert select(ref(kind="door"), two_rooms, Pose.from_deg(3.0, 5.1, 0.0)).id == "door_2"
    # words that pick one are read as before
    assert select(ref(kind="door", superlative="nearest"), two_rooms, Pose.from_deg(*A_NORTH)).id == "door_1"


def test_doors_are_the_gap_free_doors(two_rooms: MapAnalysis) -> None:
    assert all(isinstance(d, Door) for d in doors_of(two_rooms))
    assert [d.id for d in doors_of(two_rooms)] == ["door_1", "door_2"]


def test_a_gap_inside_a_passage_is_that_passage(two_rooms: MapAnalysis) -> None:
    from langnav.analysis.elements import NarrowPassage
    from langnav.grounding.selection import elements_of_kind
    from langnav.language.intent import Element as Kind

    a = with_gap(two_rooms)
    passage = NarrowPassage("passage_1", (6.075, 5.0), 0.7, 1.6, ((5.3, 5.0), (6.9, 5.0)), ("room_a", "room_b"))
    both = dataclasses.replace(a, narrow_passages=(passage,))
    assert [e.id for e in elements_of_kind(both, Kind.NARROW_PASSAGE)] == ["passage_1"]
    assert [e.id for e in elements_of_kind(a, Kind.NARROW_PASSAGE)] == ["door_2"]


def test_a_rooms_only_way_in_is_its_door_however_narrow(two_rooms: MapAnalysis) -> None:
    # room B entered only through the 0.68 m opening (door_1 walled up): a booth behind a 0.7 m door
    only = dataclasses.replace(with_gap(two_rooms), doors=(with_gap(two_rooms).doors[1],))
    assert only.doors[0].width_m < NARROW_GAP_MAX_M
    assert [d.id for d in doors_of(only)] == ["door_2"]
    pose = Pose.from_deg(*A_NORTH)
    assert select(ref(kind="door", side="right", ordinal=1), only, pose).id == "door_2"
    # still narrow: "the narrow gap" finds it too, and it does not make room B a part of room A
    assert select(ref(kind="narrow_passage"), only, pose).id == "door_2"
    assert [r.id for r in gap_joined(only, only.rooms[0])] == ["room_a"]
    # with a second way into room B the narrow opening is a gap again, not one of the doors
    assert [d.id for d in doors_of(with_gap(two_rooms))] == ["door_1"]


def test_that_points_back_at_the_door_the_step_before_went_to(two_rooms: MapAnalysis) -> None:
    # "go to the last door on your right, if that's okay": a reader that gives "that" the words of the
    # door before must not pick the last door on the right again from that door (it would be another)
    last = {"kind": "door", "side": "right", "superlative": "farthest"}
    plan = ground(Intent(steps=[
        Step.model_validate({"movement": "navigate", "target": last, "text": "go to the last door on your right"}),
        Step.model_validate({"movement": "navigate", "target": last, "text": "if that's okay"})]), two_rooms, A_NORTH)
    assert [s.element_ids for s in plan.steps] == [("door_2",), ("door_2",)]


def test_the_obstacle_of_a_room_with_one_is_that_one(two_rooms: MapAnalysis) -> None:
    import numpy as np

    from langnav.analysis.elements import Obstacle

    box, = two_rooms.obstacles  # room A's box at (2.3, 5.3)
    # a box in room B just through door_1, nearer to a robot standing by that door than room A's box
    near = Obstacle("obstacle_2", (6.9, 2.0), 0.16, (0.4, 0.4), "room_b", np.array([[6.9, 2.0]]))
    a = dataclasses.replace(two_rooms, obstacles=(box, near))
    pose = Pose.from_deg(5.2, 2.4, 0.0)  # in room A by door_1
    assert select(ref(kind="obstacle"), a, pose).id == "obstacle_1"  # the one in this room
    assert select(ref(kind="obstacle", superlative="nearest"), a, pose).id == "obstacle_2"  # words that pick
