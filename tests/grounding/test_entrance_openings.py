"""An opening that is a room's only way in is that room's door (``selection.entrance_opening``).

The map analysis calls an opening a door only where the places on both sides are wider than it; a
room whose floor narrows at once behind the doorway (an archive whose shelf aisle faces the door)
fails that, yet a person enters the room through it and counts it with the corridor's doors. The
corridor below is analysed from a drawn map; the middle room's doorway is then handed to the
grounding as an opening (as the analysis gives such a doorway), so the rule is tested apart from the
door judge.

    y=9 +-----------+-----------+-----------+
        |  room_2   |  room_4   |  room_1   |
        |           D4 (side door, 2nd map) |
    y=3 +---D1------+---D2------+---D3------+
        |  hallway_3      robot ->          |
    y=1 +-----------------------------------+
       x=1         x=5         x=9        x=13
"""

from __future__ import annotations

import dataclasses

import pytest

from langnav.analysis.elements import MapAnalysis
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.pipeline import analyze
from langnav.grounding.selection import doors_of, entrance_opening
from langnav.language.translator import get_translator
from langnav.maps.draw import MapBuilder
from langnav.pipeline import Planner
from langnav.plan.commands import NavigateThroughPoses

#: in the corridor's west end facing east: the rooms' doorways are on the robot's left
WEST_END_EAST = (1.6, 2.0, 0.0)


def _corridor(side_door: bool) -> MapAnalysis:
    """The corridor with the middle room's doorway (x 7) as an opening; ``side_door``: that room is
    also entered from the room west of it (D4)."""
    b = MapBuilder(14.0, 10.0).room(1.0, 1.0, 13.0, 9.0).wall(1.0, 3.0, 13.0, 3.0)
    b.wall(5.0, 3.0, 5.0, 9.0).wall(9.0, 3.0, 9.0, 9.0)
    for x in (3.0, 7.0, 11.0):
        b.door_h(x, 3.0, 0.9)
    if side_door:
        b.door_v(5.0, 6.0, 0.9)
    a = analyze(b.build("entrance_openings"), DEFAULT_PARAMS)
    middle = next(d for d in a.doors if d.center == (7.0, 3.0))
    return dataclasses.replace(a, doors=tuple(d for d in a.doors if d is not middle),
                               openings=(dataclasses.replace(middle, id="opening_1"),))


@pytest.fixture(scope="module")
def only_way_in() -> MapAnalysis:
    return _corridor(side_door=False)


@pytest.fixture(scope="module")
def two_ways_in() -> MapAnalysis:
    return _corridor(side_door=True)


def _goal(a: MapAnalysis, prompt: str) -> tuple[float, float] | None:
    result = Planner(get_translator("offline")).plan(prompt, a, WEST_END_EAST)
    navs = [c for c in result.commands if isinstance(c, NavigateThroughPoses)]
    if not navs:
        return None
    x, y = navs[-1].poses[-1][:2]
    return (round(x, 3), round(y, 3))


def test_the_only_way_into_a_room_is_its_door(only_way_in: MapAnalysis) -> None:
    opening = only_way_in.openings[0]
    assert entrance_opening(opening, only_way_in)
    assert "opening_1" in [d.id for d in doors_of(only_way_in)]
    # counted with the corridor's doors: the second on the left is the middle room's doorway, the
    # goal on the corridor's side of it (DOOR_STANDOFF_M before its centre, snapped to a cell centre)
    assert _goal(only_way_in, "go to the second door on your left") == (6.975, 2.575)
    assert _goal(only_way_in, "go to the third door on your left") == (10.975, 2.575)


def test_an_opening_into_a_room_entered_another_way_is_no_door(two_ways_in: MapAnalysis) -> None:
    opening = two_ways_in.openings[0]
    assert not entrance_opening(opening, two_ways_in)
    assert "opening_1" not in [d.id for d in doors_of(two_ways_in)]
    assert _goal(two_ways_in, "go to the second door on your left") == (10.975, 2.575)


def test_an_opening_wider_than_any_door_is_no_door(only_way_in: MapAnalysis) -> None:
    wide = dataclasses.replace(only_way_in.openings[0], width_m=DEFAULT_PARAMS.door_max_width_m + 0.2)
    assert not entrance_opening(wide, dataclasses.replace(only_way_in, openings=(wide,)))
