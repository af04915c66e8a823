"""The chat's own answers: help, counts, where things are, what a click points at, examples."""

from __future__ import annotations

import math
from functools import cache

import pytest

from langnav.analysis.elements import MapAnalysis
from langnav.analysis.pipeline import analyze
from langnav.maps.demo import DEMO_START, build_demo_grid
from langnav.robot.protocol import Pose2D
from langnav.web import conversation as cv
from langnav.web.feedback import asks_for_numbers, plain_command, turn_words, where_am_i
from langnav.web.mapframes import known_bounds

HALL = Pose2D(DEMO_START[0], DEMO_START[1], 0.0)


@cache
def demo() -> MapAnalysis:
    return analyze(build_demo_grid())


@pytest.mark.parametrize("text", ["help", "Help!", "?", "what can you do?", "What can I say", "how do I use this?"])
def test_help_requests(text: str) -> None:
    assert cv.is_help(text)


@pytest.mark.parametrize("text", ["help me get to the kitchen door", "go to the door", "what is your path?"])
def test_not_help(text: str) -> None:
    assert not cv.is_help(text)


def test_counts_use_the_names_on_the_map() -> None:
    a = demo()
    assert cv.count_answer("how many rooms are there?", a) == "I see 3 rooms: room 1, room 3 and room 4."
    assert cv.count_answer("How many doors do you see", a) == "I see 5 doors: door 1, door 2, door 3, door 4 and door 5."
    assert cv.count_answer("how many hallways?", a) == "I see 1 hallway: hallway 2."
    assert cv.count_answer("how many corners are there", a).startswith("I see ")
    assert cv.count_answer("go to the nearest door", a) is None


@pytest.mark.parametrize(("bearing_deg", "words"), [(0, "ahead of me"), (45, "ahead on my left"), (90, "on my left"),
                                                      (-90, "on my right"), (180, "behind me"),
                                                      (-135, "behind me on my right")])
def test_relative_words(bearing_deg: float, words: str) -> None:
    pose = Pose2D(1.0, 1.0, math.radians(30))
    a = math.radians(30 + bearing_deg)
    text = cv.relative_words(pose, (1.0 + 2.0 * math.cos(a), 1.0 + 2.0 * math.sin(a)))
    assert text.startswith(f"2.0 m {words} (to the ")


def test_where_is_answers_from_the_map() -> None:
    a = demo()
    assert cv.where_answer("where is door 5?", a, HALL) == \
        "Door 5 is 2.7 m ahead of me (to the east), between hallway 2 and room 4."
    assert cv.where_answer("Where's room 3", a, HALL).startswith("Room 3 is ")
    assert cv.where_answer("where is door 9?", a, HALL).startswith("I don't see door 9 on my map. The ones I know:")
    assert cv.where_answer("where is the nearest door?", a, HALL) is None  # for the translator


def test_a_click_points_at_the_thin_things_first() -> None:
    a = demo()
    door = a.by_id("door_5")
    assert cv.element_at(a, *door.center).id == "door_5"  # type: ignore[union-attr]
    table = max(a.obstacles, key=lambda o: o.centroid[1])
    hit = cv.element_at(a, *table.centroid)
    assert hit is table
    card = cv.element_card(hit)
    assert card["kind"] == "obstacle" and card["size"] == "1.6 × 0.8 m"
    room = cv.element_at(a, 3.0, 2.0)
    assert room is not None and room.id == "room_3"
    assert [x["prompt"] for x in cv.element_card(door)["actions"] if "prompt" in x] == ["go to door 5", "go through door 5"]


def test_starter_examples_are_the_ones_that_plan() -> None:
    a = demo()
    refused = {"go through the door on your left, then turn around"}
    out = cv.starter_examples(a, HALL, lambda t: t not in refused)
    assert out[0] == "where are you?" and "go to the nearest door" in out
    assert "go through the door on your right, then turn around" in out  # the other side, once
    assert not any(t in refused for t in out) and len(out) == 5


def test_plain_words() -> None:
    from langnav.plan.commands import Move, NavigateThroughPoses, Rotate

    a = demo()
    assert where_am_i(HALL, a) == "I'm in hallway 2 near door 2, facing east."
    assert where_am_i(HALL, a, exact=True) == "I'm in hallway 2 near door 2, at x 1.5, y 5.0 (metres on the map), facing east."
    assert turn_words("left", 180) == "turn around" and turn_words("right", 90) == "turn right"
    assert turn_words("left", 360) == "turn 1 full circle left" and turn_words("right", 30) == "turn right 30°"
    assert plain_command(Rotate(direction="left", repeat=18)) == "Turn around"
    assert plain_command(Move(direction="forward", repeat=20)) == "Move forward 0.60 m"
    nav = NavigateThroughPoses(poses=[[3.975, 6.625]], note="through the door on your left")
    assert plain_command(nav, a) == "Go through the door on your left (in room 4 near door 5)"
    assert asks_for_numbers("what are your exact coordinates?") and not asks_for_numbers("where are you?")
    for text in (where_am_i(HALL, a), plain_command(nav, a)):
        assert "pose" not in text and "frontier" not in text


def test_known_bounds_frame_the_mapped_cells() -> None:
    from langnav.maps.draw import MapBuilder

    b = MapBuilder(20.0, 20.0, origin=(-10.0, -10.0))
    g = b.build("empty")
    g.cells[:] = -1
    r0, c0 = g.world_to_index(1.0, 2.0)
    g.cells[int(r0):int(r0) + 20, int(c0):int(c0) + 40] = 0
    x0, y0, x1, y1 = known_bounds(g)  # type: ignore[misc]
    assert (x0, y0) == pytest.approx((1.0, 2.0), abs=g.resolution_m)
    assert (x1 - x0, y1 - y0) == pytest.approx((40 * g.resolution_m, 20 * g.resolution_m), abs=1e-6)
    g.cells[:] = -1
    assert known_bounds(g) is None


def test_named_elements_and_plan_reaches() -> None:
    a = demo()
    assert cv.named_elements("go past door 2 into room 3", a) == ["door_2", "room_3"]
    assert cv.named_elements("go to door 42", a) == []
    door5 = a.by_id("door_5")
    near = (door5.center[0], door5.center[1] + 0.6)  # type: ignore[union-attr]
    assert cv.plan_reaches([near], a, "door_5")
    assert not cv.plan_reaches([(3.0, 4.5)], a, "door_5")
    assert cv.plan_reaches([(3.0, 2.0)], a, "room_3") and not cv.plan_reaches([(3.0, 7.0)], a, "room_3")


def test_replies_are_put_in_plain_words() -> None:
    from langnav.web.feedback import FeedbackManager

    fm = FeedbackManager(demo)
    assert fm.plain("There is nothing left to explore that I can reach: every frontier of the map is mapped") == \
        "There is nothing left to explore that I can reach: every edge of the map is mapped"
    assert fm.plain("check that my pose on the map is right") == "check that my position on the map is right"
    assert fm.plain("command 1, pose 1 (4.00, 5.85): inside a wall") == \
        "command 1, position 1 (in hallway 2 near door 5): inside a wall"
    assert fm.plain("Poses far away (40.0, 40.0)") == "Positions far away (40.0, 40.0)"  # nothing names it
