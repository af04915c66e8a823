from __future__ import annotations

import math

import pytest

from langnav.language.intent import (
    Detail,
    Direction,
    Element,
    ElementRef,
    Intent,
    Movement,
    Query,
    Side,
    Step,
    Superlative,
)
from langnav.maps.draw import MapBuilder
from langnav.robot.protocol import Pose2D
from langnav.web.feedback import (
    describe_intent,
    describe_map,
    describe_path,
    describe_ref,
    heading_word,
    where_am_i,
)


@pytest.mark.parametrize(("deg", "word"), [(0, "east"), (90, "north"), (180, "west"), (-90, "south"),
                                           (270, "south"), (44, "north-east"), (-135, "south-west"),
                                           (359, "east"), (-22, "east"), (-23, "south-east")])
def test_heading_word(deg: float, word: str) -> None:
    assert heading_word(math.radians(deg)) == word


def test_where_am_i_without_map() -> None:
    assert where_am_i(Pose2D(3.14, 6.04, 0.0)) == "I'm at x 3.1, y 6.0, facing east."


def test_describe_ref_second_door_on_left() -> None:
    ref = ElementRef(kind=Element.DOOR, ordinal=2, side=Side.LEFT)
    assert describe_ref(ref) == "the second door on your left"
    assert describe_ref(ElementRef(kind=Element.CORNER, superlative=Superlative.NEAREST,
                                   within=Element.HALLWAY)) == "the nearest corner of the hallway"
    assert describe_ref(ElementRef(kind=Element.ROOM, name="kitchen")) == "the kitchen"


def test_describe_intent_in_order() -> None:
    intent = Intent(steps=[
        Step(movement=Movement.NAVIGATE, detail=Detail.TO,
             target=ElementRef(kind=Element.UNEXPLORED_AREA, superlative=Superlative.NEAREST)),
        Step(movement=Movement.ROTATE, direction=Direction.LEFT, angle_deg=90),
        Step(movement=Movement.MOVE, direction=Direction.FORWARD, distance_m=0.5),
        Step(movement=Movement.QUERY, query=Query.POSE),
    ])
    assert describe_intent(intent) == ("I'll go to the nearest unexplored area, then turn left, then "
                                       "move forward 0.50 m, then tell you where I am.")


def test_describe_intent_clarification() -> None:
    assert describe_intent(Intent(clarification="Which door?")) == "Which door?"


def test_describe_path() -> None:
    assert describe_path([]) == "I have no path right now: I'm not driving anywhere."
    assert describe_path([(0, 0), (3, 4), (3, 5)]) == "My path is 6.0 m long and ends at x 3.0, y 5.0."


def test_describe_map_counts_known_area() -> None:
    grid = MapBuilder(4.0, 2.0).free(0.0, 0.0, 2.0, 2.0).build()
    assert describe_map(grid) == "My map is 4.0 m by 2.0 m; I know 4 m² of it, 4 m² free."
