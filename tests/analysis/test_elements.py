"""The element detectors on built maps, with exactly known answers.

Spaces are given as free connected components (or hand labels) so these tests exercise the
detectors alone, independent of the room segmentation.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from analysis_maps import (
    corridor_with_side_passage,
    door_beside_corner,
    l_room,
    l_room_and_closed_room,
    room_beside_corridor,
    room_with_door,
    shelf_off_wall,
    two_rooms_partition,
)

from langnav.analysis.corners import find_corners
from langnav.analysis.obstacles import find_obstacles
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.passages import find_passages
from langnav.analysis.pipeline import labels_for_free_components
from langnav.analysis.unexplored import find_unexplored
from langnav.analysis.walls import find_walls
from langnav.maps.grid import OccupancyGrid

P = DEFAULT_PARAMS


def spaces(grid: OccupancyGrid) -> tuple[np.ndarray, dict[int, str]]:
    labels, n = labels_for_free_components(grid)
    return labels, {k: f"space_{k}" for k in range(1, n + 1)}


def seg(a: tuple[float, float], b: tuple[float, float]) -> tuple[tuple[float, float], tuple[float, float]]:
    """A segment with its ends in a canonical order (for comparing undirected segments)."""
    return (a, b) if a <= b else (b, a)


def rounded(p: tuple[float, float], nd: int = 2) -> tuple[float, float]:
    return (round(p[0], nd) + 0.0, round(p[1], nd) + 0.0)


def walls_and_corners(grid: OccupancyGrid):
    labels, ids = spaces(grid)
    walls = find_walls(grid, P, labels, ids)
    corners, walls = find_corners(grid, P, walls, labels, {v: k for k, v in ids.items()})
    return labels, walls, corners


def test_room_walls_are_its_four_sides_door_included() -> None:
    grid = room_with_door()
    labels, ids = spaces(grid)
    obst = find_obstacles(grid, P, labels, ids)
    walls = find_walls(grid, P, labels, ids, wall=grid.occupied & ~obst.mask)
    corners, walls = find_corners(grid, P, walls, labels, {v: k for k, v in ids.items()})
    got = sorted(seg(rounded(w.start), rounded(w.end)) for w in walls)
    # West wall stops where the unscanned patch begins; north wall likewise (walls are what was
    # seen). The east wall runs across the door (a door does not break a wall).
    assert got == sorted([
        seg((0.0, 0.0), (4.0, 0.0)), seg((4.0, 0.0), (4.0, 3.0)),
        seg((1.0, 3.0), (4.0, 3.0)), seg((0.0, 0.0), (0.0, 2.0)),
    ])
    inward = {seg(rounded(w.start), rounded(w.end)): rounded(w.inward) for w in walls}
    assert inward[seg((0.0, 0.0), (4.0, 0.0))] == (0.0, 1.0)
    assert inward[seg((4.0, 0.0), (4.0, 3.0))] == (-1.0, 0.0)
    # The north-west corner is under the unscanned patch: the west and north walls, followed
    # across it, still meet there.
    assert sorted(rounded(c.point) for c in corners) == [(0.0, 0.0), (0.0, 3.0), (4.0, 0.0), (4.0, 3.0)]
    assert all(w.room == "space_1" for w in walls)


def test_l_room_has_six_walls_and_five_inner_corners() -> None:
    _labels, walls, corners = walls_and_corners(l_room())
    got = sorted(seg(rounded(w.start), rounded(w.end)) for w in walls)
    assert got == sorted([
        seg((0.0, 0.0), (4.0, 0.0)), seg((4.0, 0.0), (4.0, 2.0)), seg((2.0, 2.0), (4.0, 2.0)),
        seg((2.0, 2.0), (2.0, 4.0)), seg((0.0, 4.0), (2.0, 4.0)), seg((0.0, 0.0), (0.0, 4.0)),
    ])
    # The elbow (2, 2) is convex seen from inside: not a corner a person can stand in.
    assert sorted(rounded(c.point) for c in corners) == [(0.0, 0.0), (0.0, 4.0), (2.0, 4.0), (4.0, 0.0), (4.0, 2.0)]


def snap(p: tuple[float, float]) -> tuple[float, float]:
    """A point to the nearest 5 cm (fitted walls sit within a cell of the drawn ones)."""
    return (round(round(p[0] / 0.05) * 0.05, 2) + 0.0, round(round(p[1] / 0.05) * 0.05, 2) + 0.0)


def split_labels(grid: OccupancyGrid, axis: int, at_m: float) -> np.ndarray:
    """Hand labels for two spaces: free cells below ``at_m`` along x (axis 0) or y (axis 1) are
    space 1, the others space 2 (as a segmentation would cut at the doorway)."""
    rows, cols = np.nonzero(grid.free)
    xy = grid.cell_to_world(rows, cols)
    hand = np.zeros(grid.cells.shape, dtype=np.int32)
    hand[rows, cols] = np.where(xy[axis] < at_m, 1, 2)
    return hand


def walls_and_corners_of(grid: OccupancyGrid, labels: np.ndarray, ids: dict[int, str]):
    walls = find_walls(grid, P, labels, ids)
    return find_corners(grid, P, walls, labels, {v: k for k, v in ids.items()})


def test_every_side_of_a_room_and_its_corridor_is_a_wall() -> None:
    # A door jamb in a side wall faces the same way as the end wall beyond it: the end wall's
    # line must still be found wherever its face falls within a cell.
    grid = room_beside_corridor(exit_door=False)
    ids = {1: "room", 2: "corridor"}
    corners, walls = walls_and_corners_of(grid, split_labels(grid, 0, 5.075), ids)
    got = sorted((w.room, seg(snap(w.start), snap(w.end))) for w in walls)
    assert got == sorted([
        ("room", seg((0.0, 0.0), (5.0, 0.0))), ("room", seg((5.0, 0.0), (5.0, 4.5))),
        ("room", seg((0.0, 4.5), (5.0, 4.5))), ("room", seg((0.0, 0.0), (0.0, 4.5))),
        ("corridor", seg((5.15, 0.0), (6.45, 0.0))), ("corridor", seg((6.45, 0.0), (6.45, 4.5))),
        ("corridor", seg((5.15, 4.5), (6.45, 4.5))), ("corridor", seg((5.15, 0.0), (5.15, 4.5))),
    ])
    assert sorted((c.room, snap(c.point)) for c in corners) == sorted(
        [("room", p) for p in ((0.0, 0.0), (5.0, 0.0), (0.0, 4.5), (5.0, 4.5))]
        + [("corridor", p) for p in ((5.15, 0.0), (6.45, 0.0), (5.15, 4.5), (6.45, 4.5))])


def test_corner_beside_a_door_and_under_an_unscanned_patch() -> None:
    # The north door is flush with the west wall; an unscanned patch covers the south-east corner.
    grid = door_beside_corner()
    ids = {1: "south", 2: "north"}
    corners, walls = walls_and_corners_of(grid, split_labels(grid, 1, 4.075), ids)
    south = sorted(snap(c.point) for c in corners if c.room == "south")
    assert south == [(0.0, 0.0), (0.0, 4.0), (5.0, 0.0), (5.0, 4.0)]
    north = sorted(snap(c.point) for c in corners if c.room == "north")
    assert north == [(0.0, 4.15), (0.0, 6.15), (5.0, 4.15), (5.0, 6.15)]
    # Walls keep the ends that were seen: the north wall of the south room starts at the door.
    north_wall = [w for w in walls if w.room == "south" and abs(w.start[1] - 4.0) < 0.05 and abs(w.end[1] - 4.0) < 0.05]
    assert len(north_wall) == 1
    assert min(north_wall[0].start[0], north_wall[0].end[0]) == pytest.approx(0.95, abs=0.06)


def test_wall_lines_crossing_in_another_room_are_no_corner() -> None:
    # The L's north and east walls, prolonged, cross at (4, 4): inside the closed room in its notch.
    grid = l_room_and_closed_room()
    labels, ids = spaces(grid)
    corners, _walls = walls_and_corners_of(grid, labels, ids)
    assert sorted(rounded(c.point) for c in corners if c.room == "space_1") == [
        (0.0, 0.0), (0.0, 4.0), (2.0, 4.0), (4.0, 0.0), (4.0, 2.0)]
    assert sorted(rounded(c.point) for c in corners if c.room == "space_2") == [
        (2.15, 2.15), (2.15, 4.0), (4.0, 2.15), (4.0, 4.0)]


def test_corner_approach_is_clear_inside_and_near() -> None:
    grid = l_room()
    labels, _walls, corners = walls_and_corners(grid)
    assert corners
    for c in corners:
        ax, ay = c.approach
        assert math.dist(c.approach, c.point) <= 0.9
        r, col = grid.world_to_index(ax, ay)
        assert labels[int(r), int(col)] == 1
        # Clear of the walls by the goal clearance (walls are the lines x, y in {0, 2, 4}).
        assert min(abs(ax - v) for v in (0.0, 2.0, 4.0)) >= P.goal_clearance_m - 1e-9 or \
            min(abs(ay - v) for v in (0.0, 2.0, 4.0)) >= P.goal_clearance_m - 1e-9
        assert abs(ax - c.point[0]) >= P.goal_clearance_m - 1e-9
        assert abs(ay - c.point[1]) >= P.goal_clearance_m - 1e-9


def test_obstacle_box_found_speck_and_walls_ignored() -> None:
    grid = room_with_door()
    labels, ids = spaces(grid)
    res = find_obstacles(grid, P, labels, ids)
    assert len(res.obstacles) == 1
    o = res.obstacles[0]
    assert o.centroid == pytest.approx((1.25, 1.2), abs=1e-9)
    assert o.area_m2 == pytest.approx(0.2, abs=1e-9)
    assert o.extent_m == pytest.approx((0.5, 0.4), abs=1e-9)
    assert o.room == "space_1"
    assert int(res.mask.sum()) == 80


def test_partition_between_two_spaces_is_wall_not_obstacle() -> None:
    grid = two_rooms_partition()
    labels, _ = spaces(grid)
    # Hand labels: west of the partition is space 1, east space 2 (as a segmentation would).
    rows, cols = np.nonzero(labels)
    xs, _ys = grid.cell_to_world(rows, cols)
    hand = np.zeros_like(labels)
    hand[rows, cols] = np.where(xs < 3.075, 1, 2)
    res = find_obstacles(grid, P, hand, {1: "west", 2: "east"})
    assert [(o.room, rounded(o.centroid)) for o in res.obstacles] == [("west", (1.3, 1.5))]


def test_unexplored_interior_patch_and_outside_world() -> None:
    grid = room_with_door()
    res = find_unexplored(grid, P)
    interior = [a for a in res.areas if a.interior]
    outside = [a for a in res.areas if not a.interior]
    assert len(interior) == 1 and len(outside) == 1
    a = interior[0]
    assert a.area_m2 == pytest.approx(1.0, abs=1e-9)
    assert a.centroid == pytest.approx((0.5, 2.5), abs=1e-9)
    # Frontier: free cells 8-adjacent to the patch: along its east side (x = 1.025, y in 2..3)
    # and its south side (y = 1.975, x in 0..1), with the shared diagonal cell once: 20 + 20 + 1.
    assert len(a.frontier) == 41
    assert np.allclose(a.frontier.max(axis=0), (1.025, 2.975))
    assert np.allclose(a.frontier.min(axis=0), (0.025, 1.975))
    # The outside is reached only through the door: its frontier lies in the doorway.
    f = outside[0].frontier
    assert f[:, 0].min() > 4.0 - 1e-9
    assert f[:, 1].min() >= 1.05 - 1e-9 and f[:, 1].max() <= 1.95 + 1e-9
    # The single unknown cell is a speck, not an area.
    assert int(res.specks.sum()) == 1


def test_no_outside_area_when_the_building_is_closed() -> None:
    res = find_unexplored(l_room(), P)
    assert res.areas == ()


def test_side_passage_found_with_width_length_and_spaces() -> None:
    grid = corridor_with_side_passage()
    labels, _ids = spaces(grid)
    # Hand labels: the corridor (y < 1.6), the room (y > 3.6); the passage itself unlabelled.
    rows, cols = np.nonzero(labels)
    _xs, ys = grid.cell_to_world(rows, cols)
    hand = np.zeros_like(labels)
    hand[rows, cols] = np.where(ys < 1.6, 1, np.where(ys > 3.6, 2, 0))
    blocking = grid.occupied | grid.unknown
    passages = find_passages(grid, P, hand, {1: "corridor", 2: "room"}, [], blocking)
    assert len(passages) == 1
    p = passages[0]
    assert p.width_m == pytest.approx(0.7, abs=1e-6)
    assert p.center == pytest.approx((5.0, 2.6), abs=0.1)
    assert 1.9 <= p.length_m <= 2.6
    assert sorted(p.connects) == ["corridor", "room"]
    (x0, y0), (x1, y1) = sorted(p.ends, key=lambda e: e[1])
    assert x0 == pytest.approx(5.0, abs=0.05) and x1 == pytest.approx(5.0, abs=0.05)
    assert y0 <= 1.75 and y1 >= 3.45


def test_doorway_and_wide_gaps_are_not_passages() -> None:
    # The room's door (0.9 m wide, a wall deep) and the 1.0+ m gaps around the box are not passages.
    grid = room_with_door()
    labels, ids = spaces(grid)
    blocking = grid.occupied | grid.unknown
    assert find_passages(grid, P, labels, ids, [], blocking) == ()


def passages_of(grid: OccupancyGrid):
    labels, ids = spaces(grid)
    return find_passages(grid, P, labels, ids, [], grid.occupied | grid.unknown)


def test_passage_between_a_wall_and_a_long_shelf() -> None:
    # Its skeleton line runs on along the room's walls (one-sided there): the two-sided stretch
    # between the wall and the shelf is the passage.
    (p,) = passages_of(shelf_off_wall(0.7, 3.0))
    assert p.width_m == pytest.approx(0.7, abs=1e-6)
    assert p.center == pytest.approx((0.35, 2.5), abs=0.05)
    # Its two-sided stretch stops short of the flaring mouths (by up to about a width at each).
    assert 2.4 <= p.length_m <= 3.1
    assert p.connects == ("space_1",)


@pytest.mark.parametrize(("gap_m", "shelf_m"), [(1.3, 3.0), (0.7, 1.0)])
def test_wide_or_short_gap_beside_a_shelf_is_no_passage(gap_m: float, shelf_m: float) -> None:
    # Wider than a passage, or not clearly longer than wide.
    assert passages_of(shelf_off_wall(gap_m, shelf_m)) == ()
