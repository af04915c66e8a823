"""Doors picked by order, side or alone in a space with no door of its own are doors in sight
(``selection._doors_in_sight``).

A corridor whose ways out are all wide openings (as the analysis gives a panel front or an arch) has
no door of its own. "The door" or "the second door on your left" said there means a door both the
person and the robot can see; the only doors of the map below are between two rooms, behind the
corridor's wall, so the robot asks instead of driving into a room it cannot see to reach one. Found
on a real map (a 70 m corridor whose doorways became openings: "go to the third doorway behind you"
drove 68 m to a door between two other rooms).

    y=9 +-----------+-----------+-----------+
        |  room     D4  room    D5  room    |
    y=3 +---O1------+---O2------+---O3------+
        |  hallway    robot ->              |
    y=1 +-----------------------------------+
       x=1         x=5         x=9        x=13
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

#: in the corridor's west end facing east: the rooms are on the robot's left
WEST_END_EAST = (1.6, 2.0, 0.0)


@pytest.fixture(scope="module")
def corridor() -> MapAnalysis:
    """The corridor's three doorways handed to the grounding as openings (each room is also entered
    from the next, so none is a room's only way in); the rooms' doors D4, D5 between two rooms."""
    b = MapBuilder(14.0, 10.0).room(1.0, 1.0, 13.0, 9.0).wall(1.0, 3.0, 13.0, 3.0)
    b.wall(5.0, 3.0, 5.0, 9.0).wall(9.0, 3.0, 9.0, 9.0)
    for x in (3.0, 7.0, 11.0):
        b.door_h(x, 3.0, 0.9)
    b.door_v(5.0, 8.0, 0.9).door_v(9.0, 8.0, 0.9)
    a = analyze(b.build("doors_in_sight"), DEFAULT_PARAMS)
    along = [d for d in a.doors if d.center[1] == 3.0]
    assert len(along) == 3 and len(a.doors) == 5
    return dataclasses.replace(
        a, doors=tuple(d for d in a.doors if d not in along),
        openings=tuple(dataclasses.replace(d, id=f"opening_{i}") for i, d in enumerate(along, 1)))


def _plan(a: MapAnalysis, prompt: str) -> PlanResult:
    return Planner(get_translator("offline")).plan(prompt, a, WEST_END_EAST)


@pytest.mark.parametrize("prompt", ["go to the door", "go through the door", "go to the second door on your left",
                                    "go to the last door on your left", "go to the first door"])
def test_no_door_in_sight_asks(corridor: MapAnalysis, prompt: str) -> None:
    result = _plan(corridor, prompt)
    assert not result.commands
    assert result.clarification is not None and "I see no door" in result.clarification


def test_a_door_named_or_the_nearest_still_goes(corridor: MapAnalysis) -> None:
    # a label or "the nearest" says which door it is, wherever it is
    label = next(d.id for d in corridor.doors if d.center == (5.0, 8.0)).replace("_", " ")
    for prompt in (f"go to {label}", "go to the nearest door"):
        navs = [c for c in _plan(corridor, prompt).commands if isinstance(c, NavigateThroughPoses)]
        assert navs, prompt
        x, y = navs[-1].poses[-1][:2]
        assert abs(x - 5.0) < 1.0 and abs(y - 8.0) < 1.0, prompt
