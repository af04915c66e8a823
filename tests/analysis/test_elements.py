"""The element detectors on built maps, with exactly known answers.

Spaces are given as free connected components (or hand labels) so these tests exercise the
detectors alone, independent of the room segmentation.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from analysis_maps import corridor_with_side_passage, l_room, room_with_door, two_rooms_partition

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
    # West wall stops where the unscanned patch begins; north wall likewise. The east wall runs
    # across the door (a door does not break a wall).
    assert got == sorted([
        seg((0.0, 0.0), (4.0, 0.0)), seg((4.0, 0.0), (4.0, 3.0)),
        seg((1.0, 3.0), (4.0, 3.0)), seg((0.0, 0.0), (0.0, 2.0)),
    ])
    inward = {seg(rounded(w.start), rounded(w.end)): rounded(w.inward) for w in walls}
    assert inward[seg((0.0, 0.0), (4.0, 0.0))] == (0.0, 1.0)
    assert inward[seg((4.0, 0.0), (4.0, 3.0))] == (-1.0, 0.0)
    assert sorted(rounded(c.point) for c in corners) == [(0.0, 0.0), (4.0, 0.0), (4.0, 3.0)]
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
