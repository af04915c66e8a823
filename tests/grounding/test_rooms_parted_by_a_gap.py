"""A room parted by a gap narrower than any door is one room, whatever the shape of its parts.

A lab whose bench rows leave a 0.7 m gap is split by the analysis into the strip between its door and
the benches (long and narrow: a "hallway" to the analysis) and the part behind the benches. A person
counts the lab once among the rooms along the corridor, enters it by the part at its door, and does
not call its other part "another room" (``selection.elements_of_kind``, ``_one_part_each``).

    y=10 +----------+--------------------+----------+
         |  room_3  |  room_4 (behind)   |  room_2  |
         |          |=====benches==gap===|          |
         |          |  hallway_5 (strip) |          |
    y=3.4+---D1-----+---D2---------------+---D3-----+
         |  hallway_1       robot ->                |
    y=1  +------------------------------------------+
        x=1        x=6                  x=14       x=19
"""

from __future__ import annotations

import pytest

from langnav.analysis.elements import ElementKind, MapAnalysis
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.pipeline import analyze
from langnav.grounding.selection import elements_of_kind, gap_joined
from langnav.language.intent import Element as Kind
from langnav.language.translator import get_translator
from langnav.maps.draw import MapBuilder
from langnav.pipeline import Planner
from langnav.plan.commands import NavigateThroughPoses

#: in the corridor's west end facing east: the rooms are on the robot's left
WEST_END_EAST = (1.6, 2.2, 0.0)


@pytest.fixture(scope="module")
def lab() -> MapAnalysis:
    b = MapBuilder(20.0, 12.0).room(1.0, 1.0, 19.0, 10.0).wall(1.0, 3.4, 19.0, 3.4)
    b.wall(6.0, 3.4, 6.0, 10.0).wall(14.0, 3.4, 14.0, 10.0)
    for x in (3.0, 8.0, 16.0):
        b.door_h(x, 3.4, 0.9)
    b.box(6.0, 5.8, 9.65, 6.6).box(10.35, 5.8, 14.0, 6.6)
    return analyze(b.build("lab_parted_by_benches"), DEFAULT_PARAMS)


def _goals(a: MapAnalysis, prompt: str, pose: tuple[float, float, float] = WEST_END_EAST) -> list[tuple[float, float]]:
    result = Planner(get_translator("offline")).plan(prompt, a, pose)
    return [(round(c.poses[-1][0], 3), round(c.poses[-1][1], 3)) for c in result.commands
            if isinstance(c, NavigateThroughPoses)]


def test_the_analysis_parts_the_lab_into_a_strip_and_a_room(lab: MapAnalysis) -> None:
    kinds = {r.id: r.kind for r in lab.rooms}
    assert kinds == {"hallway_1": ElementKind.HALLWAY, "room_2": ElementKind.ROOM, "room_3": ElementKind.ROOM,
                     "room_4": ElementKind.ROOM, "hallway_5": ElementKind.HALLWAY}
    assert [r.id for r in gap_joined(lab, lab.by_id("hallway_5"))] == ["hallway_5", "room_4"]  # type: ignore[arg-type]
    # the strip is a part of the lab (mostly room); the corridor stays a hallway
    assert {e.id for e in elements_of_kind(lab, Kind.ROOM)} == {"room_2", "room_3", "room_4", "hallway_5"}


def test_the_lab_is_counted_once_and_entered_by_its_door(lab: MapAnalysis) -> None:
    # second room on the left: the lab, its part at the door (in the strip, y 3.5-5.8)
    assert _goals(lab, "go into the second room on your left") == [(9.975, 4.675)]
    assert _goals(lab, "go into the third room on your left") == [(16.525, 6.725)]
    # then through its gap, into the part behind the benches
    assert _goals(lab, "go to the second room on your left, then go through the narrow gap") == [
        (9.975, 4.675), (9.975, 7.375)]


def test_the_other_part_of_the_room_one_is_in_is_no_other_room(lab: MapAnalysis) -> None:
    # behind the benches, facing south: the nearest other room is not the strip at the lab's door
    # (room_2's nearest cell is nearer than room_3's by a cell: its middle is the goal)
    assert _goals(lab, "go to the nearest room", (10.0, 8.0, 270.0)) == [(16.525, 6.725)]
