"""'The room two doors down' (issue 9: a count of doors along the way picks one room), on a hallway
drawn in the test and analysed by the real analysis, read by the offline translator end to end.

    y=11 +---------+---------+---------+
         | upper W | upper M | upper E |
    y=7  +--D--------D---------D-------+      doors at x 3, 7.5, 12
         |           hallway            |
    y=5  +--D--------D---------D-------+      doors at x 3, 7.5, 12
         | lower W | lower M | lower E |
    y=1  +---------+---------+---------+
        x=1       x=5       x=10      x=15
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


@pytest.fixture(scope="module")
def hall() -> MapAnalysis:
    b = MapBuilder(16.0, 12.0)
    b.room(1.0, 1.0, 15.0, 11.0)
    b.wall(1.0, 5.0, 15.0, 5.0)
    b.wall(1.0, 7.0, 15.0, 7.0)
    for x in (5.0, 10.0):
        b.wall(x, 1.0, x, 5.0)
        b.wall(x, 7.0, x, 11.0)
    for x in (3.0, 7.5, 12.0):
        b.door_h(x, 5.0, 0.9)
        b.door_h(x, 7.0, 0.9)
    return analyze(b.build("doors_along"), DEFAULT_PARAMS)


def _end_room(a: MapAnalysis, prompt: str, pose: tuple[float, float, float]) -> str | None:
    result = Planner(get_translator("offline")).plan(prompt, a, pose)
    navs = [c for c in result.commands if isinstance(c, NavigateThroughPoses)]
    if not navs:
        return None
    x, y = navs[-1].poses[-1][:2]
    room = a.room_at(x, y)
    return None if room is None else f"{'lower' if y < 5 else 'upper'} {'W' if x < 5 else 'M' if x < 10 else 'E'}"


@pytest.mark.parametrize(("prompt", "want"), [
    ("go to the room 2 doors down", "lower E"),            # from its room, the doors on its own side
    ("go to the room one door down", "lower M"),
    ("please head into the room that's two doors down the hall", "lower E"),
    ("go to the room two doors down on the left", "upper E"),  # the other side, said
])
def test_counted_from_the_robots_room_the_way_it_faces(hall: MapAnalysis, prompt: str, want: str) -> None:
    assert _end_room(hall, prompt, (3.0, 3.0, 0.0)) == want  # in lower W, facing east (along the hallway)


def test_counted_from_the_hallway_counts_both_sides(hall: MapAnalysis) -> None:
    # in the hallway at x 2, facing east: doors at x 3 (both sides), then 7.5: the second door is one of x 3
    assert _end_room(hall, "go to the room 3 doors down on the right", (2.0, 6.0, 0.0)) == "lower E"
    assert _end_room(hall, "go to the room 1 door down on the left", (2.0, 6.0, 0.0)) == "upper W"


def test_back_counts_the_other_way(hall: MapAnalysis) -> None:
    assert _end_room(hall, "go to the room two doors back", (13.0, 3.0, 0.0)) == "lower W"


def test_facing_across_the_hallway_asks_which_way(hall: MapAnalysis) -> None:
    result = Planner(get_translator("offline")).plan("go to the room 2 doors down", hall, (3.0, 3.0, 90.0))
    assert not result.commands
    assert result.clarification and "either way" in result.clarification
    # a side said gives the way along the hallway
    assert _end_room(hall, "go to the room 2 doors down on your right", (3.0, 3.0, 90.0)) == "lower E"


def test_too_few_doors_is_said(hall: MapAnalysis) -> None:
    result = Planner(get_translator("offline")).plan("go to the room 3 doors down", hall, (3.0, 3.0, 0.0))
    assert not result.commands and result.clarification and "only 2 doors" in result.clarification


def test_across_from_another_room(hall: MapAnalysis) -> None:
    """'The room across from the first room on your left': across the hallway from that room's door."""
    # in the hallway at x 2 facing east: the first room on the left is upper W; across from it, lower W
    assert _end_room(hall, "go into the room across from the first room on your left", (2.0, 6.0, 0.0)) == "lower W"
    assert _end_room(hall, "go to the room across the hall from the room on your right", (11.0, 6.0, 0.0)) \
        == "upper E"
