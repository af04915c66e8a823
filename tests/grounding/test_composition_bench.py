"""Composition on the bench buildings (../shared/bench/maps; skipped when absent): labels, amounts,
facing, returning, relations between spaces and named places, asserting goal values. Elements are
found by where they are, not by their numbers, so the tests hold while the analysis renumbers."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from langnav.analysis.elements import Door, ElementKind, MapAnalysis, Room
from langnav.grounding.selection import label_of
from langnav.language.translator import get_translator
from langnav.maps.io import load_map
from langnav.pipeline import Planner, PlanResult
from langnav.plan.commands import NavigateThroughPoses, Rotate

SLACK_M = 0.06
HALL_START = (1.5, 5.75, 0.0)  # env2: the west end of the hallway, facing east


@pytest.fixture(scope="module")
def planner() -> Planner:
    return Planner(get_translator("offline"))


def _analysis(shared_dir: Path, name: str, planner: Planner) -> MapAnalysis:
    path = shared_dir / "bench" / "maps" / f"{name}.yaml"
    if not path.is_file():
        pytest.skip(f"{path} is not on this machine")
    return planner.analysis_for(load_map(path))


@pytest.fixture(scope="module")
def env2(shared_dir: Path, planner: Planner) -> MapAnalysis:
    return _analysis(shared_dir, "env2", planner)


@pytest.fixture(scope="module")
def env1(shared_dir: Path, planner: Planner) -> MapAnalysis:
    return _analysis(shared_dir, "env1", planner)


def goals(r: PlanResult) -> list[tuple[float, float]]:
    assert r.ok, r.clarification
    return [(p[0], p[1]) for c in r.commands if isinstance(c, NavigateThroughPoses) for p in c.poses]


def hallway(a: MapAnalysis) -> Room:
    return next(r for r in a.rooms if r.kind == ElementKind.HALLWAY)


def door_near(a: MapAnalysis, x: float, y: float) -> Door:
    return min(a.doors, key=lambda d: math.dist(d.center, (x, y)))


@pytest.mark.parametrize("name", ["env1", "env2"])
def test_every_label_on_the_map_means_that_element(name: str, shared_dir: Path, planner: Planner) -> None:
    a = _analysis(shared_dir, name, planner)
    start = HALL_START if name == "env2" else (3.0, 3.0, 0.0)
    for d in a.doors:
        r = planner.plan(f"go to {label_of(d)}", a, start)
        if r.ok:
            assert math.dist(goals(r)[-1], d.center) <= 0.75, label_of(d)
        else:  # a door to the unknown outside may be out of reach; never another door
            assert "cannot" in (r.clarification or ""), r.clarification
    for room in a.rooms:
        x, y = goals(planner.plan(f"go to {label_of(room)}", a, start))[-1]
        assert a.room_at(x, y) is room, label_of(room)


def test_halfway_down_the_hallway(env2: MapAnalysis, planner: Planner) -> None:
    far_x = float(hallway(env2).cells_xy[:, 0].max())
    half = HALL_START[0] + (far_x - HALL_START[0]) / 2
    g = goals(planner.plan("go halfway down the corridor", env2, HALL_START))
    assert half - 0.6 <= g[-1][0] <= half + SLACK_M
    assert all(x <= half + SLACK_M for x, _ in g)


def test_two_metres_past_the_door_on_your_right(env2: MapAnalysis, planner: Planner) -> None:
    door = door_near(env2, 2.5, 4.9)  # the first door on the right, into the south-west room
    x, y = goals(planner.plan("go 2 metres past the door on your right", env2, HALL_START))[-1]
    assert door.center[0] + 1.5 <= x <= door.center[0] + 2.0 + SLACK_M
    assert env2.room_at(x, y) is hallway(env2)


def test_one_metre_before_and_past_a_door_from_a_room(env2: MapAnalysis, planner: Planner) -> None:
    door = door_near(env2, 2.5, 4.9)
    x, y = goals(planner.plan("stop 1 m before the door", env2, (3.0, 3.0, 90.0)))[-1]
    assert door.center[1] - 1.5 <= y <= door.center[1] - 1.0 + SLACK_M and abs(x - door.center[0]) <= 0.6
    x, y = goals(planner.plan("go 1 m past the door", env2, (3.0, 3.0, 90.0)))[-1]
    assert door.center[1] + 0.5 <= y <= door.center[1] + 1.0 + SLACK_M and abs(x - door.center[0]) <= 0.6


def test_face_north_and_face_a_door(env2: MapAnalysis, planner: Planner) -> None:
    (c,) = planner.plan("face north", env2, HALL_START).commands
    assert isinstance(c, Rotate) and (c.direction, c.repeat) == ("left", 9)
    door = door_near(env2, 8.7, 4.9)
    pose = (8.7, 5.9, 0.0)
    (c,) = planner.plan(f"turn to face {label_of(door)}", env2, pose).commands
    assert isinstance(c, Rotate) and (c.direction, c.repeat) == ("right", 9)


def test_come_back_here_and_where_you_started(env2: MapAnalysis) -> None:
    planner = Planner(get_translator("offline"))
    g = goals(planner.plan("go to the nearest corner, then come back here", env2, HALL_START))
    assert math.dist(g[-1], HALL_START[:2]) <= 0.75
    end = goals(planner.plan("go to the farthest door on your left", env2, HALL_START))[-1]
    back = goals(planner.plan("go back to where you started", env2, (end[0], end[1], 0.0)))[-1]
    assert math.dist(back, HALL_START[:2]) <= 0.75


def test_the_room_across_the_hall_and_next_to_this_one(env2: MapAnalysis, planner: Planner) -> None:
    here = env2.room_at(3.0, 3.0)
    assert here is not None
    x, y = goals(planner.plan("head into the room across the hall", env2, (3.0, 3.0, 90.0)))[-1]
    across = env2.room_at(x, y)
    hall_y = hallway(env2).centroid[1]
    assert across is not None and across.kind == ElementKind.ROOM and across.centroid[1] > hall_y > here.centroid[1]
    x, y = goals(planner.plan("go to the room next to this one", env2, (3.0, 3.0, 90.0)))[-1]
    beside = env2.room_at(x, y)
    assert beside is not None and beside is not here and beside.kind == ElementKind.ROOM
    assert beside.centroid[1] < hall_y  # on the same side of the hallway


def test_the_room_on_the_right_is_another_room(env2: MapAnalysis, planner: Planner) -> None:
    here = env2.room_at(3.0, 3.0)
    x, y = goals(planner.plan("go to the room on the right", env2, (3.0, 3.0, 90.0)))[-1]
    assert env2.room_at(x, y) is not here


def test_named_places_on_env2(env2: MapAnalysis) -> None:
    planner = Planner(get_translator("offline"))
    assert planner.plan("this is the charging dock", env2, (15.0, 2.5, 180.0)).ok
    (c,) = planner.plan("go to the charging dock", env2, HALL_START).commands
    assert isinstance(c, NavigateThroughPoses)
    assert math.dist(c.poses[-1][:2], (15.0, 2.5)) <= 0.75 and c.poses[-1][2] == pytest.approx(180.0)


def test_env1_labels_and_offsets(env1: MapAnalysis, planner: Planner) -> None:
    for o in env1.obstacles:
        r = planner.plan(f"go next to {label_of(o)}", env1, (3.0, 3.0, 0.0))
        if r.ok:
            x, y = goals(r)[-1]
            assert min(math.dist((x, y), tuple(p)) for p in o.cells_xy) <= 1.0 + SLACK_M
    corner = env1.corners[0]
    g = goals(planner.plan(f"go to {label_of(corner)}", env1, (3.0, 3.0, 0.0)))[-1]
    assert math.dist(g, corner.point) <= 1.0
