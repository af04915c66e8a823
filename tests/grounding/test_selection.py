"""Which element the words mean, on the hand-built two-room world (see conftest.py)."""

from __future__ import annotations

from dataclasses import replace

import pytest

from langnav.analysis.elements import Door, MapAnalysis
from langnav.grounding.errors import GroundingError
from langnav.grounding.geometry import Pose
from langnav.grounding.selection import (
    describe_ref,
    doors_of,
    gap_joined,
    round_a_thing,
    select,
    select_wall,
    wall_lines,
)
from langnav.language.intent import Element, ElementRef, Side, Superlative
from langnav.maps.draw import MapBuilder

AT_A = Pose.from_deg(3.0, 2.0, 0.0)  # in room A, facing east (towards door_1)


def ref(**kw: object) -> ElementRef:
    return ElementRef.model_validate(kw)


@pytest.mark.parametrize(("words", "expected"), [
    ({"kind": "door"}, "door_1"),
    ({"kind": "door", "side": "ahead"}, "door_1"),
    ({"kind": "door", "side": "left"}, "door_2"),
    ({"kind": "door", "ordinal": 2}, "door_2"),
    ({"kind": "door", "superlative": "farthest"}, "door_2"),
    ({"kind": "corner", "side": "left"}, "c_a_ne"),
    ({"kind": "corner", "side": "right"}, "c_a_se"),
    ({"kind": "corner", "superlative": "farthest"}, "c_a_ne"),
    ({"kind": "corner"}, "c_a_sw"),
    ({"kind": "room", "superlative": "biggest"}, "room_a"),
    ({"kind": "room", "superlative": "smallest"}, "room_b"),
    ({"kind": "room", "in_current_room": True}, "room_a"),
    ({"kind": "obstacle", "in_current_room": True}, "obstacle_1"),
    ({"kind": "unexplored_area", "superlative": "nearest"}, "unexplored_1"),
])
def test_select(two_rooms: MapAnalysis, words: dict[str, object], expected: str) -> None:
    assert select(ref(**words), two_rooms, AT_A).id == expected


def test_turning_changes_left_and_right(two_rooms: MapAnalysis) -> None:
    facing_west = Pose.from_deg(3.0, 2.0, 180.0)
    assert select(ref(kind="door", side="right"), two_rooms, facing_west).id == "door_2"
    with pytest.raises(GroundingError, match="no door on your left"):
        select(ref(kind="door", side="left"), two_rooms, facing_west)


def test_ordinal_too_large_says_how_many_there_are(two_rooms: MapAnalysis) -> None:
    with pytest.raises(GroundingError, match="I see only two doors, so I cannot find the third door"):
        select(ref(kind="door", ordinal=3), two_rooms, AT_A)
    with pytest.raises(GroundingError, match="only one door on your left"):
        select(ref(kind="door", side="left", ordinal=2), two_rooms, AT_A)


def test_named_places_the_map_cannot_know(two_rooms: MapAnalysis) -> None:
    with pytest.raises(GroundingError, match=r"a place called 'kitchen'; name it first"):
        select(ref(kind="room", name="kitchen"), two_rooms, AT_A)


def test_missing_kind_is_reported(two_rooms: MapAnalysis) -> None:
    with pytest.raises(GroundingError, match="no narrow passages"):
        select(ref(kind="narrow_passage"), two_rooms, AT_A)


def test_walls_split_by_doors_are_one_wall(two_rooms: MapAnalysis) -> None:
    lines = wall_lines([w for w in two_rooms.walls if w.room == "room_a"])
    east = [ln for ln in lines if set(ln.ids) == {"w_a_e1", "w_a_e2", "w_a_e3"}]
    assert len(lines) == 4 and len(east) == 1
    assert east[0].length_m == pytest.approx(6.0)


def test_left_and_right_walls(two_rooms: MapAnalysis) -> None:
    north = Pose.from_deg(3.0, 2.0, 90.0)
    assert set(select_wall(ref(kind="wall", side="right"), two_rooms, north).ids) == {"w_a_e1", "w_a_e2", "w_a_e3"}
    assert select_wall(ref(kind="wall", side="left"), two_rooms, north).ids == ("w_a_w",)
    assert select_wall(ref(kind="wall", side="ahead"), two_rooms, north).ids == ("w_a_n",)
    assert select_wall(ref(kind="wall"), two_rooms, north).ids == ("w_a_s",)


def test_compact_noun_picks_a_compact_obstacle(two_rooms: MapAnalysis) -> None:
    box = select(ref(kind="obstacle"), two_rooms, AT_A, "go next to the box")
    assert box.id == "obstacle_1"
    # a long noun with no long obstacle falls back to every obstacle
    assert select(ref(kind="obstacle"), two_rooms, AT_A, "go to the shelf").id == "obstacle_1"


def test_descriptions() -> None:
    assert describe_ref(ref(kind="door", ordinal=2, side="left")) == "the second door on your left"
    assert describe_ref(ref(kind="corner", side="right", in_current_room=True)) == "the right corner in this room"
    assert describe_ref(ref(kind="room", superlative="biggest")) == "the biggest room"
    assert describe_ref(ref(kind="room", in_current_room=True)) == "this room"
    assert describe_ref(ref(kind="wall", side="left", within="hallway")) == "the left wall of the hallway"
    assert Side.LEFT.value == "left" and Superlative.BIGGEST.value == "biggest" and Element.DOOR.value == "door"


def test_two_sides_narrow_to_a_quarter(two_rooms: MapAnalysis) -> None:
    """"The door behind you on the left" (session 6, parser): both sides hold; "behind you" alone is the nearer."""
    in_b = Pose.from_deg(8.0, 3.0, 0.0)  # in room B facing east: both doors behind, door_1 right, door_2 left
    assert select(ref(kind="door", side="behind"), two_rooms, in_b).id == "door_1"
    assert select(ref(kind="door", side="behind", also_side="left"), two_rooms, in_b).id == "door_2"
    assert select(ref(kind="door", side="behind", also_side="right"), two_rooms, in_b).id == "door_1"
    assert describe_ref(ref(kind="door", side="behind", also_side="left")) == "the door behind you on your left"


def test_a_thing_on_your_side_is_one_in_sight(two_rooms: MapAnalysis) -> None:
    # from room A the box is ahead and in sight
    assert select(ref(kind="obstacle", side="ahead"), two_rooms, Pose.from_deg(4.0, 5.3, 180.0)).id == "obstacle_1"
    # from room B, with the wall between the doors in the way, "the obstacle ahead" is no thing it sees
    with pytest.raises(GroundingError, match="from here"):
        select(ref(kind="obstacle", side="ahead"), two_rooms, Pose.from_deg(8.0, 3.5, 180.0))
    # seen through a door it is
    assert select(ref(kind="obstacle", side="ahead"), two_rooms, Pose.from_deg(8.0, 5.0, 180.0)).id == "obstacle_1"


def test_two_wide_openings_between_two_spaces_make_one_room(two_rooms: MapAnalysis) -> None:
    d1, d2 = two_rooms.doors
    both = replace(two_rooms, doors=(), openings=(d1, d2))
    assert [r.id for r in gap_joined(both, both.rooms[0])] == ["room_a", "room_b"]
    assert round_a_thing(both) == [d1, d2]
    # a wide opening and a door between the same two spaces: the two ends of one thing, no door of a room
    mixed = replace(two_rooms, doors=(d2,), openings=(d1,))
    assert [r.id for r in gap_joined(mixed, mixed.rooms[0])] == ["room_a", "room_b"]
    assert round_a_thing(mixed) == [d1, d2] and doors_of(mixed) == []
    # one wide opening is a way between two rooms, as before; two doors are two doors
    one = replace(two_rooms, doors=(), openings=(d1,))
    assert [r.id for r in gap_joined(one, one.rooms[0])] == ["room_a"]
    assert round_a_thing(one) == [] and round_a_thing(two_rooms) == []
    assert doors_of(two_rooms) == [d1, d2]


def test_a_thick_block_standing_free_between_two_doorways_is_a_thing(two_rooms: MapAnalysis) -> None:
    # a counter 0.8 m deep standing free across the room, ways round both its ends: one room
    b = MapBuilder(12.0, 8.0)
    b.room(1.0, 1.0, 11.0, 7.0)
    b.box(5.6, 2.2, 6.4, 5.8)
    grid = b.build("counter")
    ends = (Door("door_1", (6.0, 1.6), 1.1, ((6.0, 1.05), (6.0, 2.15)), (1.0, 0.0), ("room_a", "room_b")),
            Door("door_2", (6.0, 6.4), 1.1, ((6.0, 5.85), (6.0, 6.95)), (1.0, 0.0), ("room_a", "room_b")))
    counter = replace(two_rooms, grid=grid, doors=ends)
    assert round_a_thing(counter) == list(ends) and doors_of(counter) == []
    assert [r.id for r in gap_joined(counter, counter.rooms[0])] == ["room_a", "room_b"]
    # the same line as a thin wall with two doors in it (the fixture): two doors of two rooms
    b = MapBuilder(12.0, 8.0)
    b.room(1.0, 1.0, 11.0, 7.0)
    b.box(5.95, 2.2, 6.15, 5.8)
    thin = replace(two_rooms, grid=b.build("thin"), doors=ends)
    assert round_a_thing(thin) == [] and doors_of(thin) == list(ends)
    assert round_a_thing(two_rooms) == []
