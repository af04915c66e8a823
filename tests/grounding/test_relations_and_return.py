"""Relational references ("the door next to the box", "the corner of the biggest room"), the
prompt's start ("come back"), corners by their approach point, and whole prompts read by the offline
translator, on the hand-built two-room world (see conftest.py)."""

from __future__ import annotations

import math

import pytest

from langnav.analysis.elements import MapAnalysis
from langnav.grounding import GroundingError, ground
from langnav.grounding.geometry import Pose
from langnav.grounding.selection import describe_ref, select
from langnav.language.intent import ElementRef, Intent
from langnav.language.offline import translate_offline
from langnav.language.translator import get_translator
from langnav.pipeline import Planner
from langnav.plan.commands import NavigateThroughPoses

AT_A = (3.0, 2.0, 0.0)     # room A, facing east towards door_1
IN_B = (8.0, 2.0, 180.0)   # room B, facing west towards door_1


def ref(**kw: object) -> ElementRef:
    return ElementRef.model_validate(kw)


def last_goal(prompt: str, analysis: MapAnalysis, pose: tuple[float, float, float]) -> tuple[float, float]:
    commands = ground(translate_offline(prompt), analysis, pose).commands
    nav = [c for c in commands if isinstance(c, NavigateThroughPoses)]
    x, y = nav[-1].poses[-1][:2]
    return (x, y)


@pytest.mark.parametrize(("words", "pose", "expected"), [
    # door_2 is the door within reach of the box; door_1 is nearer the robot
    ({"kind": "door", "near": {"kind": "obstacle"}}, AT_A, "door_2"),
    ({"kind": "corner", "near": {"kind": "obstacle"}}, AT_A, "c_a_nw"),
    ({"kind": "obstacle", "near": {"kind": "door", "side": "left"}}, AT_A, "obstacle_1"),
    # from room B, "the nearest corner of the biggest room" is one of room A's, not the nearer one of B
    ({"kind": "corner", "within": "room", "near": {"kind": "room", "superlative": "biggest"}}, IN_B, "c_a_se"),
    ({"kind": "corner", "within": "room"}, IN_B, "c_b_sw"),
    ({"kind": "obstacle", "within": "room", "near": {"kind": "room", "superlative": "biggest"}}, IN_B, "obstacle_1"),
])
def test_landmarks_pick_the_element(two_rooms: MapAnalysis, words: dict[str, object],
                                    pose: tuple[float, float, float], expected: str) -> None:
    assert select(ref(**words), two_rooms, Pose.from_deg(*pose)).id == expected


def test_a_landmark_with_nothing_near_it_is_refused(two_rooms: MapAnalysis) -> None:
    with pytest.raises(GroundingError, match="no obstacle near the unexplored area"):
        select(ref(kind="obstacle", near={"kind": "unexplored_area"}), two_rooms, Pose.from_deg(*AT_A))


def test_landmarks_are_described() -> None:
    assert describe_ref(ref(kind="door", near={"kind": "obstacle"})) == "the door near the obstacle"
    assert describe_ref(ref(kind="corner", within="room", near={"kind": "room", "superlative": "biggest"})) \
        == "the corner of the biggest room"
    assert describe_ref(ref(kind="none", place="start")) == "where I started"


def test_the_door_next_to_the_box_end_to_end(two_rooms: MapAnalysis) -> None:
    x, y = last_goal("go to the door next to the box", two_rooms, AT_A)
    assert math.dist((x, y), (6.075, 5.0)) <= 0.75 and x < 6.075


def test_the_corner_of_the_biggest_room_uses_its_approach_point(two_rooms: MapAnalysis) -> None:
    # c_a_se is at (6.0, 1.0) with its approach at (5.6, 1.4): the goal is the approach point
    x, y = last_goal("Go to the nearest corner of the biggest room.", two_rooms, IN_B)
    assert (x, y) == pytest.approx((5.6, 1.4), abs=0.05)


def test_the_left_side_of_the_room_is_along_its_left_wall(two_rooms: MapAnalysis) -> None:
    x, y = last_goal("move to the left side of this room", two_rooms, AT_A)  # facing east: the north wall
    assert 6.0 <= y <= 7.0 - 0.15 and 1.0 < x < 6.0


@pytest.mark.parametrize("prompt", [
    "go through the nearest door, then come back", "Go to the box and return to where you started.",
    "drive to the far corner, then go back to your starting point"])
def test_coming_back_ends_where_the_prompt_started(two_rooms: MapAnalysis, prompt: str) -> None:
    assert math.dist(last_goal(prompt, two_rooms, AT_A), AT_A[:2]) <= 0.75


def test_coming_back_without_a_known_start_is_refused(two_rooms: MapAnalysis) -> None:
    from langnav.analysis.params import DEFAULT_PARAMS
    from langnav.grounding.geometry import free_space_for
    from langnav.grounding.ground import GroundingContext, ground_step

    step = translate_offline("go to the box, then come back").steps[1]
    ctx = GroundingContext(two_rooms, free_space_for(two_rooms.grid, DEFAULT_PARAMS), DEFAULT_PARAMS, {})
    with pytest.raises(GroundingError, match="don't know where I started"):
        ground_step(step, ctx, Pose.from_deg(*AT_A))


def test_issue_5_prompt_end_to_end(two_rooms: MapAnalysis) -> None:
    """'go to the nearest unexplored area, then come back to the nearest door', planned and validated;
    with 'the door' alone room B's two doors are both meant, so the robot asks which."""
    planner = Planner(get_translator("offline"))
    asked = planner.plan("go to the nearest unexplored area, then come back to the door", two_rooms, (8.0, 3.0, 90.0))
    assert not asked.ok and asked.clarification is not None
    assert "door 1" in asked.clarification and "door 2" in asked.clarification
    result = planner.plan("go to the nearest unexplored area, then come back to the nearest door", two_rooms,
                          (8.0, 3.0, 90.0))
    assert result.ok, result.clarification
    first, second = result.items
    fx, fy = first.commands[0].poses[-1][:2]  # type: ignore[attr-defined]
    assert fy >= 5.5 - 1.0 and fx >= 9.0 - 1.0  # by the unexplored pocket's frontier
    sx, sy = second.commands[0].poses[-1][:2]  # type: ignore[attr-defined]
    assert math.dist((sx, sy), (6.075, 5.0)) <= 0.75  # the door nearest to where the first step ends


def test_regrounding_keeps_the_prompts_start(two_rooms: MapAnalysis) -> None:
    planner = Planner(get_translator("offline"))
    result = planner.plan("go through the nearest door, then come back", two_rooms, AT_A)
    assert result.ok, result.clarification
    back = result.items[1]
    later = back.reground((8.0, 2.5, 0.0), two_rooms)  # from wherever the robot really is then
    x, y = later[-1].poses[-1][:2]  # type: ignore[attr-defined]
    assert math.dist((x, y), AT_A[:2]) <= 0.75


def test_the_question_then_it_is_one_trip(two_rooms: MapAnalysis) -> None:
    intent = translate_offline("Which is the smallest room? Drive into it.")
    assert isinstance(intent, Intent) and len(intent.steps) == 1
    x, _ = last_goal("Which is the smallest room? Drive into it.", two_rooms, AT_A)
    assert x > 6.15  # room B is the smaller one
