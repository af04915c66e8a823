"""The bench contract's words about rooms, corners and gaps (../shared/bench/README.md), grounded on one
drawn building: the biggest room (by floor area) and its middle (its free space's centroid), the
nearest corner (of the room the robot is in), the centre of this room, and the narrow gap ahead (through
it: past it on the far side; to it: at it). Round 10's developer typed these as pseudo-code
("goto(room=biggest, where=middle)", "go_through(narrow_gap, ahead)"); the parser turns code into these
words, and this is what the words must give.

    y=9 +------------------+-----------+
        |                  D1          |
        |  room_1 (63 m2)  |  room_2   |
        |                  | [##] [##] |  two cabinets, a 0.6 m gap between them
        |                  |   robot ^ |
    y=1 +------------------+-----------+
       x=1               x=9         x=15
"""

from __future__ import annotations

import pytest

from langnav.analysis.elements import MapAnalysis
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.pipeline import analyze
from langnav.language.translator import get_translator
from langnav.maps.draw import MapBuilder
from langnav.pipeline import Planner
from langnav.plan.commands import NavigateThroughPoses

#: in room_2, below the gap between the cabinets, facing north
BELOW_THE_GAP = (12.8, 1.8, 90.0)


@pytest.fixture(scope="module")
def two_rooms() -> MapAnalysis:
    b = MapBuilder(16.0, 10.0).room(1.0, 1.0, 15.0, 9.0).wall(9.0, 1.0, 9.0, 9.0).door_v(9.0, 7.0, 0.9)
    b.box(9.5, 3.0, 11.7, 4.0).box(12.3, 3.0, 14.5, 4.0)
    return analyze(b.build("contract_building_words"), DEFAULT_PARAMS)


def test_the_drawn_building(two_rooms: MapAnalysis) -> None:
    assert [(r.id, round(r.area_m2, 1)) for r in two_rooms.rooms] == [("room_1", 63.3), ("room_2", 43.2)]
    (gap,) = two_rooms.narrow_passages
    assert (round(gap.center[0], 2), gap.center[1], round(gap.width_m, 2)) == (11.98, 3.5, 0.6)


@pytest.mark.parametrize(("prompt", "poses"), [
    # inside the biggest room: its middle
    ("go to the biggest room", [(4.975, 5.025)]),
    # within 0.75 m of the centroid of its free space (4.96, 5.00)
    ("go to the middle of the biggest room", [(4.975, 5.025)]),
    # within 1.0 m of the nearest corner of this room, (15, 1)
    ("go to the nearest corner", [(14.775, 1.225)]),
    # within 0.75 m of this room's free-space centroid (12.02, 5.15: the cabinets take floor below it)
    ("go to the centre of this room", [(12.025, 5.175)]),
    # through: in front of the gap, in it, and past it on the far side (within 2 m)
    ("go through the narrow gap ahead", [(11.975, 2.525), (11.975, 3.475), (11.975, 4.775)]),
    ("go through the gap ahead", [(11.975, 2.525), (11.975, 3.475), (11.975, 4.775)]),
    # to it: at its near mouth
    ("go to the gap ahead", [(11.975, 3.025)]),
])
def test_the_contract_words(two_rooms: MapAnalysis, prompt: str, poses: list[tuple[float, float]]) -> None:
    result = Planner(get_translator("offline")).plan(prompt, two_rooms, BELOW_THE_GAP)
    navs = [c for c in result.commands if isinstance(c, NavigateThroughPoses)]
    assert len(navs) == 1 and len(result.commands) == 1, result.clarification
    assert [(round(p[0], 3), round(p[1], 3)) for p in navs[0].poses] == poses
