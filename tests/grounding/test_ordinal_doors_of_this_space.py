"""'The first / second / third door' counts the doors of the space the robot is in (bench README: "Doors are
counted among those one passes in the space the robot is in ..., not doors between two other rooms"), also
when that space has none: then there is no first door, and the robot asks instead of counting the doors
between two other rooms (a real corridor whose ways out are all open fronts sent the robot to a door 68 m
away in another wing for "the third doorway behind you").

The corridor below is analysed from a drawn map; its two doorways are then handed to the grounding as
openings (as the analysis gives a wide open front), so the rule is tested apart from the door judge. Each
room is entered two ways (from the corridor and through D3), so neither opening is a room's only way in
(``entrance_opening``) and the corridor has no door of its own; D3 is a door between two other rooms.

    y=9 +-----------+-----------+
        |  room A   D3  room B  |
        |           |           |
    y=3 +---O1------+-----O2----+
        |  hallway     robot -> |
    y=1 +-----------------------+
       x=1         x=7         x=13
"""

from __future__ import annotations

import dataclasses

import pytest

from langnav.analysis.elements import MapAnalysis
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.pipeline import analyze
from langnav.grounding.selection import doors_of
from langnav.language.translator import get_translator
from langnav.maps.draw import MapBuilder
from langnav.pipeline import Planner
from langnav.plan.commands import NavigateThroughPoses

#: in the corridor's west end facing east: the rooms are on the robot's left
WEST_END_EAST = (1.6, 2.0, 0.0)


@pytest.fixture(scope="module")
def open_fronts() -> MapAnalysis:
    b = MapBuilder(14.0, 10.0).room(1.0, 1.0, 13.0, 9.0).wall(1.0, 3.0, 13.0, 3.0).wall(7.0, 3.0, 7.0, 9.0)
    b.door_h(3.0, 3.0, 0.9).door_h(11.0, 3.0, 0.9).door_v(7.0, 6.0, 0.9)
    a = analyze(b.build("ordinal_doors_of_this_space"), DEFAULT_PARAMS)
    fronts = [d for d in a.doors if d.center[1] == 3.0]
    assert len(fronts) == 2
    return dataclasses.replace(a, doors=tuple(d for d in a.doors if d not in fronts),
                               openings=tuple(dataclasses.replace(d, id=f"opening_{i + 1}")
                                              for i, d in enumerate(fronts)))


def _plan(a: MapAnalysis, prompt: str) -> tuple[tuple[float, float] | None, str | None]:
    result = Planner(get_translator("offline")).plan(prompt, a, WEST_END_EAST)
    navs = [c for c in result.commands if isinstance(c, NavigateThroughPoses)]
    goal = (round(navs[-1].poses[-1][0], 3), round(navs[-1].poses[-1][1], 3)) if navs else None
    return goal, result.clarification


def test_the_corridor_has_no_door_of_its_own(open_fronts: MapAnalysis) -> None:
    # the only door a person counts is D3, between room A and room B
    assert [d.center for d in doors_of(open_fronts)] == [(7.0, 6.0)]


@pytest.mark.parametrize("prompt", ["go to the first door on your left", "go through the second door on your left",
                                    "go to the first door", "take the third door on the left"])
def test_an_ordinal_door_with_none_in_this_space_asks(open_fronts: MapAnalysis, prompt: str) -> None:
    goal, said = _plan(open_fronts, prompt)
    assert goal is None
    assert said is not None and "cannot find the" in said


def test_the_nearest_door_is_still_the_nearest_anywhere(open_fronts: MapAnalysis) -> None:
    # "nearest" is straight-line distance (README), not an ordinal: D3, beside whichever room it opens
    goal, said = _plan(open_fronts, "go to the nearest door")
    assert said is None and goal is not None
    assert abs(goal[0] - 7.0) < 0.8 and abs(goal[1] - 6.0) < 0.8
