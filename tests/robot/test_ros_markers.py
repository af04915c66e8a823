"""The map analysis as a visualization_msgs/MarkerArray (plain dicts; no ROS needed)."""

from __future__ import annotations

import math

import pytest

from langnav.analysis.pipeline import analyze
from langnav.maps.demo import build_demo_grid
from langnav.robot.ros.markers import (
    CUBE_LIST,
    DELETEALL,
    LINE_LIST,
    POINTS,
    ROOM_CELL_M,
    TEXT_VIEW_FACING,
    analysis_markers,
    display_name,
)


@pytest.fixture(scope="module")
def demo_markers() -> tuple[object, list[dict[str, object]]]:
    a = analyze(build_demo_grid())
    return a, analysis_markers(a, "map", 12.5)["markers"]


def test_names_are_written_as_in_the_web_app() -> None:
    assert display_name("door_2") == "door 2"
    assert display_name("unexplored_10") == "unexplored 10"


def test_every_room_door_passage_and_unexplored_area_is_labelled(demo_markers) -> None:  # type: ignore[no-untyped-def]
    a, markers = demo_markers
    labels = {m["text"]: m for m in markers if m["type"] == TEXT_VIEW_FACING}
    expected = ([r.id for r in a.rooms] + [d.id for d in a.doors] + [p.id for p in a.narrow_passages]
                + [u.id for u in a.unexplored])
    assert sorted(labels) == sorted(display_name(e) for e in expected)
    assert {"room 1", "hallway 2", "door 1", "passage 1", "unexplored 1"} <= set(labels)
    door = a.doors[0]
    pos = labels[display_name(door.id)]["pose"]["position"]  # type: ignore[index]
    assert (pos["x"], pos["y"]) == pytest.approx(door.center)


def test_first_marker_clears_the_previous_array_and_ids_are_unique_per_namespace(demo_markers) -> None:  # type: ignore[no-untyped-def]
    _, markers = demo_markers
    assert markers[0]["action"] == DELETEALL
    keys = [(m["ns"], m["id"]) for m in markers[1:]]
    assert len(keys) == len(set(keys))
    assert all(m["header"]["frame_id"] == "map" and m["header"]["stamp"] == {"sec": 12, "nanosec": 500_000_000}
               for m in markers)


def test_shapes_follow_the_elements(demo_markers) -> None:  # type: ignore[no-untyped-def]
    a, markers = demo_markers
    rooms = [m for m in markers if m["ns"] == "rooms" and m["type"] == CUBE_LIST]
    assert len(rooms) == len(a.rooms)
    for room, m in zip(a.rooms, rooms, strict=True):
        area = len(m["points"]) * ROOM_CELL_M ** 2  # type: ignore[arg-type]
        assert area == pytest.approx(room.area_m2, rel=0.35)  # squares of 0.2 m cover the room's cells
    doors = [m for m in markers if m["ns"] == "doors" and m["type"] == LINE_LIST]
    for door, m in zip(a.doors, doors, strict=True):
        p, q = m["points"]  # type: ignore[misc]
        assert math.hypot(p["x"] - q["x"], p["y"] - q["y"]) == pytest.approx(door.width_m, abs=0.1)
    frontier = [m for m in markers if m["ns"] == "unexplored" and m["type"] == POINTS]
    assert [len(m["points"]) for m in frontier] == [len(u.frontier) for u in a.unexplored]  # type: ignore[arg-type]
