"""Two readings of places along a corridor (``selection.entered_part_key``, ``_one_door_or_ask``).

A room parted by a gap narrower than any door is one room (``gap_joined``); which of its parts a person
means is the part one enters from here, not the part nearest by a straight line. Below, the shelf room
room_2 is entered from the corridor by D4; the strip behind room_1 (entered from room_1 by D1) joins it
only by a 0.65 m gap and lies nearer the robot through the wall. "The last room on your right" is the
shelf room, as "the second room on your right" is (found on the library of prompts-4: the last room went
to the strip).

    y=13 +--------------------------------------------+
         |  hallway      robot ->                     |
    y=10 +----D3-----------------+-----+------D4------+
         |  room_1               |strip|   room_2     |
         |                      D1     gap            |
    y=1  +-----------------------+-----+--------------+
        x=1                    x=12  x=14            x=21

A corridor whose ways out are all open fronts has no door of its own, so "the door" said there names
none: the only door the robot sees is between two other rooms at the corridor's far end, 35 m off. A
person would ask which door; so does the robot (found on a real map: 74 m).
"""

from __future__ import annotations

import dataclasses

import pytest

from langnav.analysis.elements import MapAnalysis
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.pipeline import analyze
from langnav.language.translator import get_translator
from langnav.maps.draw import MapBuilder
from langnav.pipeline import Planner, PlanResult
from langnav.plan.commands import NavigateThroughPoses

#: in the corridor's west end facing east: the rooms are on the robot's right
CORRIDOR_WEST_END = (1.6, 11.5, 0.0)
#: the middle of the shelf room, room_2 (the goal of "go to <a room>")
SHELF_ROOM = (17.525, 5.475)
STRIP = (12.975, 5.425)


@pytest.fixture(scope="module")
def library() -> MapAnalysis:
    b = MapBuilder(22.0, 14.0).room(1.0, 1.0, 21.0, 13.0).wall(1.0, 10.0, 21.0, 10.0)
    b.wall(12.0, 1.0, 12.0, 10.0).wall(14.0, 1.0, 14.0, 10.0)
    b.door_h(4.0, 10.0, 0.9).door_h(17.0, 10.0, 0.9).door_v(12.0, 3.0, 0.9).door_v(14.0, 5.0, 0.65)
    return analyze(b.build("library_with_a_strip"), DEFAULT_PARAMS)


def _plan(a: MapAnalysis, prompt: str, pose: tuple[float, float, float]) -> PlanResult:
    return Planner(get_translator("offline")).plan(prompt, a, pose)


def _goals(a: MapAnalysis, prompt: str, pose: tuple[float, float, float] = CORRIDOR_WEST_END) -> list[tuple[float, float]]:
    return [(round(c.poses[-1][0], 3), round(c.poses[-1][1], 3)) for c in _plan(a, prompt, pose).commands
            if isinstance(c, NavigateThroughPoses)]


def test_the_strip_is_a_part_of_the_shelf_room(library: MapAnalysis) -> None:
    spaces = {r.id: (round(r.centroid[0], 1), round(r.centroid[1], 1)) for r in library.rooms}
    assert spaces == {"room_1": (6.5, 5.5), "room_2": (17.5, 5.5), "hallway_3": (11.0, 11.5), "hallway_4": (13.0, 5.4)}
    gap = next(d for d in library.doors if d.width_m < 0.75)
    assert set(gap.connects) == {"room_2", "hallway_4"}


@pytest.mark.parametrize("prompt", ["go to the last room on your right", "go to the farthest room on your right",
                                    "go to the second room on your right", "go to the smallest room"])
def test_the_room_is_the_part_entered_from_here(library: MapAnalysis, prompt: str) -> None:
    # (the smallest room: the shelf room and its strip, 78.6 m2, counted whole against room_1's 97 m2)
    assert _goals(library, prompt) == [SHELF_ROOM]


def test_the_part_entered_from_the_next_room_is_the_strip(library: MapAnalysis) -> None:
    # standing in room_1, whose door D1 opens onto the strip, the shelf room is entered through the strip
    assert _goals(library, "go to the smallest room", (6.0, 3.0, 0.0)) == [STRIP]
    assert _goals(library, "go to the first room on your right") == [(6.475, 5.475)]


@pytest.fixture(scope="module")
def open_fronts() -> MapAnalysis:
    """A 29 m corridor (y 1-3.4) whose two ways out are handed to the grounding as wide openings: one into
    room_1 along its north side (room_1 is entered from room_3 too, so the opening is not its only way
    in), one at its east end into room_3; room_3's door D2 into room_4 is in line with the corridor."""
    b = MapBuilder(44.0, 10.0).room(1.0, 1.0, 43.0, 9.0)
    b.wall(1.0, 3.4, 30.0, 3.4).wall(30.0, 1.0, 30.0, 9.0).wall(37.0, 1.0, 37.0, 9.0)
    b.door_v(30.0, 2.2, 1.2).door_v(37.0, 2.2, 0.9).door_h(8.0, 3.4, 0.9).door_v(30.0, 7.0, 0.9)
    a = analyze(b.build("corridor_of_open_fronts"), DEFAULT_PARAMS)
    ways = [d for d in a.doors if d.center[0] < 31.0 and d.center[1] < 3.5]
    assert len(ways) == 2 and len(a.doors) == 4
    return dataclasses.replace(a, doors=tuple(d for d in a.doors if d not in ways),
                               openings=tuple(dataclasses.replace(d, id=f"opening_{i}") for i, d in enumerate(ways, 1)))


@pytest.mark.parametrize("prompt", ["go to the door", "go through the door", "go out the door"])
def test_the_door_of_a_space_with_none_asks(open_fronts: MapAnalysis, prompt: str) -> None:
    result = _plan(open_fronts, prompt, (2.0, 2.2, 0.0))
    assert not result.commands
    assert result.clarification == ("Hallway 2 has no door of its own; the door I see from here: door 2 (ahead, "
                                    "35.0 m). Which door do you mean? Say e.g. 'door 2'.")


def test_a_door_said_which_still_goes(open_fronts: MapAnalysis) -> None:
    # a label, a side or "the nearest" says which door it is
    assert _goals(open_fronts, "go to door 2", (2.0, 2.2, 0.0)) == [(36.575, 2.175)]
    assert _goals(open_fronts, "go to the door ahead", (2.0, 2.2, 0.0)) == [(36.575, 2.175)]
    assert _goals(open_fronts, "go to the nearest door", (2.0, 2.2, 0.0)) == [(29.575, 6.975)]
