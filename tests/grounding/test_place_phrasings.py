"""How people say places in buildings, read into one intent step each (the offline translator), and
where "towards an unexplored area" ends when the area is seen through an opening.

The readings are the ones grounding needs: "between the first and second doors on your left" is two
doors sharing one noun; "the room on the other side of the hall" is the room across it (one place, not
a walk to the hallway's far end and then a room); "the unexplored bit at end of this corridor" is the
unexplored area at the hallway's end; chat abbreviations of place words ("btwn", "rm") are the words.
"""

from __future__ import annotations

import math

import pytest

from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.pipeline import analyze
from langnav.language.intent import Detail, Element, Movement, Relation, Side, Superlative
from langnav.language.offline import translate_offline
from langnav.language.translator import get_translator
from langnav.maps.draw import MapBuilder
from langnav.pipeline import Planner
from langnav.plan.commands import NavigateThroughPoses


@pytest.mark.parametrize(("prompt", "side"), [
    ("Stop between the first and second doors on your left.", Side.LEFT),
    ("stop btwn the 1st and 2nd doors on the right", Side.RIGHT),
    ("go between the first and the second door on your left", Side.LEFT),
])
def test_two_ordinals_share_the_noun_and_the_side(prompt: str, side: Side) -> None:
    intent = translate_offline(prompt)
    assert intent.clarification is None and len(intent.steps) == 1
    step = intent.steps[0]
    assert step.detail == Detail.BETWEEN
    assert step.target is not None and step.second_target is not None
    assert (step.target.kind, step.target.ordinal, step.target.side) == (Element.DOOR, 1, side)
    assert (step.second_target.kind, step.second_target.ordinal, step.second_target.side) == (Element.DOOR, 2, side)


def test_btwn_is_between() -> None:
    step, = translate_offline("go btwn the 2 obstacles").steps
    assert step.detail == Detail.BETWEEN and step.target is not None and step.target.kind == Element.OBSTACLE


@pytest.mark.parametrize("prompt", [
    "Would you go to the room on the other side of the hall, dear?",
    "room on the other side of the corridor",
    "go into the rm across the hall",
])
def test_the_room_on_the_other_side_of_the_hall_is_the_room_across(prompt: str) -> None:
    step, = translate_offline(prompt).steps
    assert step.target is not None
    assert (step.target.kind, step.target.relation) == (Element.ROOM, Relation.ACROSS)


def test_the_other_side_of_the_hall_alone_is_still_its_far_side() -> None:
    step, = translate_offline("go to the other side of the hall").steps
    assert step.detail == Detail.OPPOSITE_SIDE_OF and step.target is not None
    assert step.target.kind == Element.HALLWAY


@pytest.mark.parametrize("prompt", [
    "go towards unexplored bit at end of this corridor",
    "go towards unexplored area at end of hall",
    "go down the hall to the unexplored area at the end",
])
def test_the_unexplored_bit_at_the_end_of_the_corridor_is_one_place(prompt: str) -> None:
    step, = translate_offline(prompt).steps
    assert step.detail == Detail.TOWARDS and step.target is not None
    assert (step.target.kind, step.target.superlative) == (Element.UNEXPLORED_AREA, Superlative.FARTHEST)


def test_back_out_the_door_is_leaving_through_it() -> None:
    out, turn = translate_offline("back out the door and turn left").steps
    assert (out.detail, out.target.kind if out.target else None) == (Detail.THROUGH, Element.DOOR)
    assert turn.movement == Movement.ROTATE


# ------------------------------------------------------------------------------ towards the unknown
def test_towards_an_area_seen_through_an_opening_stops_in_front_of_its_middle() -> None:
    """A room (x 1-9, y 1-7) with a 1.6 m opening in its south wall at x 5 onto unknown: the robot, in
    the north-west, goes towards it and stops inside the room, a step short of the opening's middle,
    not in the opening by its west jamb (the nearest end of the unknown's edge)."""
    b = MapBuilder(10.0, 8.0)
    b.room(1.0, 1.0, 9.0, 7.0)
    b.unknown(0.0, 0.0, 10.0, 0.9)
    b.door_h(5.0, 1.0, 1.6)
    b.unknown(4.2, 0.0, 5.8, 0.95)
    a = analyze(b.build("opening_onto_unknown"), DEFAULT_PARAMS)
    r = Planner(get_translator("offline")).plan("go towards the nearest unexplored area", a, (2.0, 6.0, 0.0))
    assert r.ok, r.clarification
    nav = [c for c in r.commands if isinstance(c, NavigateThroughPoses)]
    x, y = nav[-1].poses[-1][:2]
    assert y > 1.1  # in the room, not in the opening
    assert abs(x - 5.0) <= 0.5  # in front of its middle
    assert math.dist((x, y), (5.0, 1.0)) <= 1.0  # still "towards": within about 1 m of the edge


# ------------------------------------------------------------------------------ landmarks the map cannot know
@pytest.mark.parametrize(("prompt", "name"), [
    ("go into the room next to the kitchen", "kitchen"),
    ("Would you please go into the room across the hall from the bathroom?", "bathroom"),
    ("go to the door next to the fridge", "fridge"),
])
def test_an_element_placed_by_a_place_the_map_cannot_know_is_asked_about(prompt: str, name: str) -> None:
    # which room is "next to the kitchen" cannot be told from the grid: going to any room is a guess
    intent = translate_offline(prompt)
    assert not intent.steps and intent.clarification is not None and name in intent.clarification


@pytest.mark.parametrize("prompt", ["go to the door next to the box", "go past the first door on your left",
                                    "go to the room next to the one you are in", "go next to the door on your left"])
def test_landmarks_the_map_shows_are_read(prompt: str) -> None:
    intent = translate_offline(prompt)
    assert intent.clarification is None and len(intent.steps) == 1


def test_a_landmark_the_user_named_is_not_asked_about() -> None:
    intent = translate_offline("go into the room next to the kitchen", known_names=("kitchen",))
    assert intent.clarification is None or "don't know" not in intent.clarification


def test_a_sentence_saying_where_a_compass_point_lies_is_no_instruction() -> None:
    intent = translate_offline("Let us try something new. Face south. South is behind the whiteboard.")
    assert intent.clarification is None
    step, = intent.steps
    assert step.movement == Movement.ROTATE and step.heading_deg == 270.0


@pytest.mark.parametrize("prompt", ["go halfway between the first door on the left and the second one",
                                    "wait in between the first two doors on your left"])
def test_the_second_one_and_the_first_two_name_two_doors(prompt: str) -> None:
    step, = translate_offline(prompt).steps
    assert step.detail == Detail.BETWEEN and step.target is not None and step.second_target is not None
    assert (step.target.ordinal, step.second_target.ordinal) == (1, 2)
    assert step.target.side == step.second_target.side == Side.LEFT


@pytest.mark.parametrize("prompt", ["go in the room across the hallway", "go into the room across the hallway from here",
                                    "go in the room on the opposite side of the hallway"])
def test_across_the_hallway_is_read_whole(prompt: str) -> None:
    # "hallway" is not "hall" followed by an unknown place "way"
    step, = translate_offline(prompt).steps
    assert step.target is not None and (step.target.kind, step.target.relation) == (Element.ROOM, Relation.ACROSS)


@pytest.mark.parametrize("prompt", ["go out and turn right", "step out, please"])
def test_go_out_alone_is_out_of_this_room(prompt: str) -> None:
    # no place called "out": the way out of the room the robot is in
    out = translate_offline(prompt).steps[0]
    assert out.detail == Detail.THROUGH and out.target is not None
    assert (out.target.kind, out.target.in_current_room) == (Element.DOOR, True)


@pytest.mark.parametrize(("prompt", "sup"), [
    ("Go to the room which is the smallest.", Superlative.SMALLEST),
    ("go to whichever room is smallest", Superlative.SMALLEST),
    ("head for the room that is the biggest one", Superlative.BIGGEST),
    ("go to the door which is closest", Superlative.NEAREST),
])
def test_a_superlative_in_a_relative_clause_picks_the_element(prompt: str, sup: Superlative) -> None:
    step, = translate_offline(prompt).steps
    assert step.target is not None and step.target.superlative == sup


def test_an_unread_superlative_asks() -> None:
    from langnav.language.offline.ask import spatial

    assert spatial("smallest") == ["smallest"] and spatial("the biggest one") == ["biggest"]
    assert spatial("a little") == []  # "little" is a size word only as a superlative's stem, not an amount's


@pytest.mark.parametrize("prompt", [
    "leave the room through the door",
    "Drive out of this room through the door",
    "exit this room through the doorway",
])
def test_leaving_a_room_through_the_door_is_one_step_through_its_door(prompt: str) -> None:
    step, = translate_offline(prompt).steps
    assert step.detail == Detail.THROUGH and step.target is not None
    assert (step.target.kind, step.target.in_current_room) == (Element.DOOR, True)


@pytest.mark.parametrize("prompt", [
    "through the door on your right, then come back through it",
    "go through the first door on your left and then come back out through it",
])
def test_coming_back_through_a_door_is_through_it_again(prompt: str) -> None:
    first, back = translate_offline(prompt).steps
    assert first.detail == back.detail == Detail.THROUGH
    assert back.target is not None and back.target.kind == Element.DOOR


def test_towards_a_straight_edge_of_the_unknown_steps_back_square_to_it() -> None:
    import numpy as np

    from langnav.grounding.ground import _square_to_the_edge

    # an opening's edge along a line at 23 deg (a rotated map's staircase of cells), the robot off to its side
    t = np.linspace(0.0, 1.5, 31)
    line = np.stack([9.0 + t * np.cos(0.4), 4.3 + t * np.sin(0.4)], axis=1)
    line = np.round(line / 0.05) * 0.05
    towards_robot = (-0.995, -0.1)  # nearly along the edge: the robot came at it from the side
    nx, ny = _square_to_the_edge(line, towards_robot)
    assert abs(nx * np.cos(0.4) + ny * np.sin(0.4)) < 0.05  # square to the edge ...
    assert nx * towards_robot[0] + ny * towards_robot[1] > 0  # ... on the robot's side
    # a corner of an unscanned block (two faces) is no straight edge: towards the robot
    corner = np.array([[x, 8.0] for x in np.arange(8.0, 9.5, 0.05)] + [[8.0, y] for y in np.arange(6.5, 8.0, 0.05)])
    assert _square_to_the_edge(corner, towards_robot) == towards_robot
    # in line with a straight edge: towards the robot too
    assert _square_to_the_edge(line, (float(np.cos(0.4)), float(np.sin(0.4)))) == (float(np.cos(0.4)), float(np.sin(0.4)))
