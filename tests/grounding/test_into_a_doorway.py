"""Into a doorway is through it (``lexicon.ENTERING_WORDS``): one is inside a room one goes into, but one
goes into a door or a gap only by passing through it, into what lies beyond ("she says go into the first
door on your right": round 10's bank, where the robot stopped at the door).

    y=6 +-----------+
        |  room     |
    y=3 +----D------+
        |  hallway  |  robot at x=2 facing east: the door is on its left
    y=1 +-----------+
       x=1         x=9
"""

from __future__ import annotations

import pytest

from langnav.analysis.elements import MapAnalysis
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.pipeline import analyze
from langnav.language.intent import Detail
from langnav.language.intent import Element as Kind
from langnav.language.translator import Context, get_translator
from langnav.maps.draw import MapBuilder
from langnav.pipeline import Planner
from langnav.plan.commands import NavigateThroughPoses


@pytest.fixture(scope="module")
def one_door() -> MapAnalysis:
    b = MapBuilder(10.0, 7.0).room(1.0, 1.0, 9.0, 6.0).wall(1.0, 3.0, 9.0, 3.0).door_h(5.0, 3.0, 0.9)
    return analyze(b.build("into_a_doorway"), DEFAULT_PARAMS)


@pytest.mark.parametrize(("prompt", "kind", "detail"), [
    ("go into the first door on your left", Kind.DOOR, Detail.THROUGH),
    ("she says go into the first door on your right", Kind.DOOR, Detail.THROUGH),
    ("enter the door on your left", Kind.DOOR, Detail.THROUGH),
    ("walk into the doorway", Kind.DOOR, Detail.THROUGH),
    ("head into the narrow gap", Kind.NARROW_PASSAGE, Detail.THROUGH),
    ("go into the room on your left", Kind.ROOM, Detail.TO),
    ("enter room 3", Kind.ROOM, Detail.TO),
    ("go to the first door on your left", Kind.DOOR, Detail.TO),
])
def test_into_a_doorway_is_through_it(prompt: str, kind: Kind, detail: Detail) -> None:
    step = get_translator("offline").translate(prompt, Context()).steps[0]
    assert step.target is not None and step.target.kind == kind
    assert step.detail == detail


def test_the_robot_ends_beyond_the_door(one_door: MapAnalysis) -> None:
    result = Planner(get_translator("offline")).plan("go into the first door on your left", one_door, (2.0, 2.0, 0.0))
    navs = [c for c in result.commands if isinstance(c, NavigateThroughPoses)]
    assert [[round(v, 3) for v in p[:2]] for p in navs[-1].poses] == [[4.975, 2.475], [4.975, 3.775]]
