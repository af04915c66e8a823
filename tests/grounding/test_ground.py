"""Grounding of whole intents on the hand-built two-room world: exact commands, and refusals."""

from __future__ import annotations

import math
from typing import Any

import pytest

from langnav.analysis.elements import MapAnalysis
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.grounding import GroundingError, ground
from langnav.grounding.geometry import free_space_for
from langnav.language.intent import Intent, Step
from langnav.plan.commands import to_bench

AT_A = (3.0, 2.0, 0.0)  # room A, facing east towards door_1


def step(**kw: Any) -> Step:
    return Step.model_validate(kw)


def bench(analysis: MapAnalysis, pose: tuple[float, float, float], *steps: Step) -> list[dict[str, Any]]:
    return [to_bench(c) for c in ground(Intent(steps=list(steps)), analysis, pose).commands]


def ntp(*poses: list[float]) -> list[dict[str, Any]]:
    return [{"command": "NavigateThroughPoses", "poses": list(poses)}]


CASES = [
    ("door ahead: before its centre, on my side",
     AT_A, [step(movement="navigate", detail="to", target={"kind": "door", "side": "ahead"})],
     ntp([5.675, 1.975])),
    ("door on the left",
     AT_A, [step(movement="navigate", detail="to", target={"kind": "door", "side": "left"})],
     ntp([5.675, 4.975])),
    ("through the first door: before it, then past it",
     AT_A, [step(movement="navigate", detail="through", target={"kind": "door", "ordinal": 1})],
     ntp([5.575, 1.975], [6.875, 1.975])),
    ("through the same door from the other side",
     (8.0, 2.0, 180.0), [step(movement="navigate", detail="through", target={"kind": "door", "ordinal": 1})],
     ntp([6.575, 1.975], [5.275, 1.975])),
    ("next to the obstacle, on my side of it: beside its side facing me, not off its corner",
     AT_A, [step(movement="navigate", detail="next_to", target={"kind": "obstacle"})],
     ntp([2.325, 4.575])),
    ("left corner: of the corners ahead, the farthest left",
     AT_A, [step(movement="navigate", detail="to", target={"kind": "corner", "side": "left"})],
     ntp([5.575, 6.575])),
    ("right corner",
     AT_A, [step(movement="navigate", detail="to", target={"kind": "corner", "side": "right"})],
     ntp([5.575, 1.375])),
    ("along the right wall, joined across both doors, to its end",
     (3.0, 2.0, 90.0), [step(movement="follow", detail="along", target={"kind": "wall", "side": "right"})],
     ntp([5.475, 4.225], [5.475, 6.475])),
    ("middle of this room",
     AT_A, [step(movement="navigate", detail="middle")],
     ntp([3.475, 3.975])),
    ("towards the unexplored area",
     AT_A, [step(movement="navigate", detail="towards", target={"kind": "unexplored_area"})],
     # a step short of the middle of the side of the unscanned block the robot arrives at (through
     # door_2, from the west): in front of its west side, not off its corner
     ntp([8.475, 6.225])),
    ("between the two doors",
     AT_A, [step(movement="navigate", detail="between", target={"kind": "door"})],
     ntp([5.825, 3.475])),
    ("turn left, then the left corner is read from the new heading",
     AT_A, [step(movement="rotate", direction="left"),
            step(movement="navigate", detail="to", target={"kind": "corner", "side": "left"})],
     [{"command": "Rotate", "direction": "left", "repeat": 9}, *ntp([1.375, 6.575])]),
    ("turn around is 18 steps; move forward 1 m is 33",
     AT_A, [step(movement="rotate", direction="around"), step(movement="move", direction="forward", distance_m=1)],
     [{"command": "Rotate", "direction": "left", "repeat": 18},
      {"command": "Move", "direction": "forward", "repeat": 33}]),
    ("a little: 0.3 m and 20 degrees",
     AT_A, [step(movement="move", direction="backward", amount="little"),
            step(movement="rotate", direction="right", amount="little")],
     [{"command": "Move", "direction": "backward", "repeat": 10},
      {"command": "Rotate", "direction": "right", "repeat": 2}]),
    ("stop and queries",
     AT_A, [step(movement="stop"), step(movement="query", query="pose"), step(movement="query", query="path"),
            step(movement="query", query="map")],
     [{"command": "Stop"}, {"command": "GetRobotPoseLast"}, {"command": "GetCurrentPath"}, {"command": "GetMap"}]),
]


@pytest.mark.parametrize(("why", "pose", "steps", "expected"), CASES, ids=[c[0] for c in CASES])
def test_exact_commands(two_rooms: MapAnalysis, why: str, pose: tuple[float, float, float], steps: list[Step],
                        expected: list[dict[str, Any]]) -> None:
    assert bench(two_rooms, pose, *steps) == expected


def test_goals_meet_the_readme_tolerances(two_rooms: MapAnalysis) -> None:
    fs = free_space_for(two_rooms.grid, DEFAULT_PARAMS)
    door = bench(two_rooms, AT_A, step(movement="navigate", target={"kind": "door", "side": "left"}))[0]["poses"][-1]
    assert math.dist(door, (6.075, 5.0)) <= 0.75 and door[0] < 6.0  # on the robot's side
    corner = bench(two_rooms, AT_A, step(movement="navigate", target={"kind": "corner", "side": "left"}))
    assert math.dist(corner[0]["poses"][-1], (6.0, 7.0)) <= 1.0
    through = bench(two_rooms, AT_A, step(movement="navigate", detail="through", target={"kind": "door"}))
    end = through[0]["poses"][-1]
    assert end[0] > 6.15 and math.dist(end, (6.075, 2.0)) <= 2.0
    for p in (door, corner[0]["poses"][-1], *through[0]["poses"]):
        assert fs.clearance_at(*p) >= 0.2


def test_steps_are_read_from_where_the_previous_ones_end(two_rooms: MapAnalysis) -> None:
    plan = ground(Intent(steps=[step(movement="navigate", detail="through", target={"kind": "door"}),
                                step(movement="navigate", target={"kind": "door", "side": "left"})]),
                  two_rooms, AT_A)
    # after going east through door_1 the robot faces east in room B: door_2 is on its left
    assert plan.steps[0].end_pose.x_m > 6.5
    assert math.isclose(plan.steps[0].end_pose.yaw_rad, 0.0, abs_tol=1e-6)
    assert plan.steps[1].element_ids == ("door_2",)
    assert plan.steps[1].commands[0].poses[-1][0] > 6.15  # approached from room B's side


def test_explore_is_marked(two_rooms: MapAnalysis) -> None:
    plan = ground(Intent(steps=[step(movement="explore")]), two_rooms, AT_A)
    assert plan.steps[0].explore and plan.steps[0].element_ids == ("unexplored_1",)


def test_notes_say_why(two_rooms: MapAnalysis) -> None:
    plan = ground(Intent(steps=[step(movement="navigate", target={"kind": "door", "ordinal": 2})]), two_rooms, AT_A)
    assert plan.commands[0].note == "to the second door"


def test_named_place_remembered(two_rooms: MapAnalysis) -> None:
    intent = Intent(steps=[step(movement="navigate", target={"kind": "room", "name": "Kitchen"})])
    plan = ground(intent, two_rooms, AT_A, named_places={"kitchen": (9.0, 3.0)})
    assert math.dist(plan.commands[0].poses[-1], (9.0, 3.0)) <= 0.75


@pytest.mark.parametrize(("steps", "message"), [
    ([step(movement="navigate", target={"kind": "door", "ordinal": 5})], "only two doors"),
    ([step(movement="navigate", target={"kind": "room", "name": "kitchen"})], "don't know a place called 'kitchen'; name it first"),
    ([step(movement="navigate", target={"kind": "narrow_passage"})], "no narrow passages"),
    ([step(movement="move", direction="forward", distance_m=9)], "into a wall.*after about 7.8 m"),
    ([step(movement="move", direction="right", distance_m=1.5)], "into a wall"),
    ([step(movement="rotate", angle_deg=45)], "left or right"),
    ([step(movement="navigate")], "Where should I go"),
    ([step(movement="follow", target={"kind": "door"})], "follow a wall or a hallway"),
    ([], "did not find an instruction"),
])
def test_refusals_are_readable(two_rooms: MapAnalysis, steps: list[Step], message: str) -> None:
    with pytest.raises(GroundingError, match=message):
        ground(Intent(steps=steps), two_rooms, AT_A)


def test_clarification_intent_is_refused_with_its_words(two_rooms: MapAnalysis) -> None:
    with pytest.raises(GroundingError, match="I cannot pick things up"):
        ground(Intent(clarification="I cannot pick things up."), two_rooms, AT_A)


def test_pose_in_a_wall_is_refused(two_rooms: MapAnalysis) -> None:
    with pytest.raises(GroundingError, match="no free space around my position"):
        ground(Intent(steps=[step(movement="navigate", target={"kind": "door"})]), two_rooms, (0.2, 0.2, 0.0))


def test_a_move_longer_than_one_command_goes_is_refused_clearly() -> None:
    """'go forward a hundred feet' in a hall with 40 m of clear floor: one Move goes at most 30 m,
    so the reply says so (it used to fail the command's own validation: 'planning failed')."""
    from langnav.analysis.pipeline import analyze
    from langnav.maps.draw import MapBuilder

    b = MapBuilder(46.0, 8.0, 0.1, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 44.0, 6.0)
    hall = analyze(b.build(source="long hall"))
    with pytest.raises(GroundingError, match="farther than I drive straight in one go"):
        ground(Intent(steps=[step(movement="move", direction="forward", distance_m=30.48)]), hall, (1.0, 3.0, 0.0))
    # 29.9 m is within one command and clear: it runs.
    cmds = ground(Intent(steps=[step(movement="move", direction="forward", distance_m=29.9)]), hall,
                  (1.0, 3.0, 0.0)).commands
    assert [to_bench(c)["command"] for c in cmds] == ["Move"]

