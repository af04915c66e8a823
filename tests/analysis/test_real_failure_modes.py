"""Golden buildings for the ways real maps went wrong (issue 8), drawn here with exactly known
spaces and doors: a corridor widened by a junction, a long room entered through one door, a
laser-ray fan outside a wall, a row of shelves in a hall, a building rotated 23 degrees with
lidar noise and broken walls."""

from __future__ import annotations

import math

import numpy as np
import pytest
from analysis_maps import POS_TOL_M, door_near, space_at
from scipy import ndimage as ndi

from langnav.analysis.elements import ElementKind
from langnav.analysis.params import AnalysisParams
from langnav.analysis.pipeline import analyze
from langnav.analysis.segmentation import UNKNOWN_ID, segment_spaces
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN, OccupancyGrid


def corridor_with_wide_junction() -> OccupancyGrid:
    """A 1.8 m corridor, 30 m long, widened to a 5 m x 5 m lobby in its middle (a junction with
    an alcove opposite), with two offices off it through 0.9 m doors and a 2 m x 6 m store
    room at its east end entered through one door."""
    b = MapBuilder(33.0, 14.0)
    b.room(0.5, 5.0, 30.5, 6.8)  # the corridor
    b.free(13.0, 3.0, 18.0, 8.0)  # the lobby: the corridor widened to 5 m
    b.room(3.0, 7.0, 7.0, 11.0).door_h(5.0, 6.9, 0.9)  # office, north side
    b.room(22.0, 0.5, 26.0, 4.8).door_h(24.0, 4.9, 0.9)  # office, south side
    b.room(24.0, 7.0, 30.0, 9.0).door_h(27.0, 6.9, 0.9)  # the store room: 6 m x 2 m, one door
    # The lobby's walls (the free rectangle cut into the corridor's walls).
    b.wall(12.95, 2.95, 18.05, 2.95).wall(12.95, 8.05, 18.05, 8.05)
    b.wall(12.95, 2.95, 12.95, 4.95).wall(18.05, 2.95, 18.05, 4.95)
    b.wall(12.95, 6.85, 12.95, 8.05).wall(18.05, 6.85, 18.05, 8.05)
    return b.build("corridor with a wide junction")


def test_a_corridor_widened_by_a_junction_is_one_hallway() -> None:
    """Judged by its typical width (1.8 m), not its widest point (the 5 m lobby), the corridor
    is one hallway; the offices and the store room entered through one door are rooms."""
    grid = corridor_with_wide_junction()
    seg = segment_spaces(grid)
    corridor = space_at(seg, grid, 2.0, 6.0)
    assert space_at(seg, grid, 15.5, 5.5) is corridor  # the lobby is part of it
    assert space_at(seg, grid, 29.0, 6.0) is corridor
    assert corridor.kind == ElementKind.HALLWAY
    assert corridor.width_m == pytest.approx(1.8, abs=0.15)  # its typical width
    rooms = [space_at(seg, grid, x, y) for x, y in ((5.0, 9.0), (24.0, 2.5), (27.0, 8.0))]
    assert len({r.id for r in rooms}) == 3
    assert [r.kind for r in rooms] == [ElementKind.ROOM] * 3
    assert len(seg.rooms) == 4
    assert len(seg.doors) == 3
    for (x, y), room in zip(((5.0, 6.9), (24.0, 4.9), (27.0, 6.9)), rooms, strict=True):
        d = door_near(seg.doors, x, y)
        assert set(d.connects) == {corridor.id, room.id}
        assert d.width_m == pytest.approx(0.9, abs=POS_TOL_M)


def test_a_long_narrow_room_with_one_door_is_a_room_and_a_closed_corridor_a_hallway() -> None:
    """A 6 m x 2 m room entered through one door (elongation 3) is a room; judged on its
    shape alone, with no door seen, the same space is a hallway."""
    grid = corridor_with_wide_junction()
    store = space_at(segment_spaces(grid), grid, 27.0, 8.0)
    assert store.kind == ElementKind.ROOM
    b = MapBuilder(8.0, 4.0)
    b.room(1.0, 1.0, 7.0, 3.0)
    closed = segment_spaces(b.build())
    assert [r.kind for r in closed.rooms] == [ElementKind.HALLWAY]


def room_with_ray_fan() -> OccupancyGrid:
    """A 6 m x 4 m room with a 0.6 m gap in its east wall; beyond it, outside, the lidar saw a
    fan of free rays through the gap into unknown, dense enough to scan as a solid wedge
    widening from the gap to 0.95 m, 2.5 m long."""
    b = MapBuilder(14.0, 6.0)
    b.room(0.5, 1.0, 6.5, 5.0).door_v(6.575, 3.0, 0.6)
    grid = b.build("ray fan")
    cells = grid.cells.copy()
    res = grid.resolution_m
    for i in range(int(5.0 / res)):
        x = 6.8 + (i + 0.5) * res  # cell centres
        half = min(0.3 + 0.1 * i * res, 0.475) if x < 9.3 else 0.0
        for y in np.arange(3.0 - half + res / 2, 3.0 + half, res):
            r, c = grid.world_to_index(x, y)
            cells[int(r), int(c)] = FREE
    return OccupancyGrid(cells, res, grid.origin_x_m, grid.origin_y_m, source="ray fan")


def test_a_laser_ray_fan_outside_a_wall_is_no_space() -> None:
    grid = room_with_ray_fan()
    seg = segment_spaces(grid)
    assert len(seg.rooms) == 1
    room = seg.rooms[0]
    assert room.kind == ElementKind.ROOM
    r, c = grid.world_to_index(10.5, 3.0)
    assert seg.labels[int(r), int(c)] in (0, room.label)  # never a space of its own
    # The only door is the gap in the wall, leading outside; none from the fan into unknown.
    assert len(seg.doors) <= 1
    for d in seg.doors:
        assert d.center == pytest.approx((6.575, 3.0), abs=0.4)
        assert UNKNOWN_ID in d.connects


def test_a_sliver_behind_a_corridor_wall_is_no_space() -> None:
    """A 0.6 m strip of free floor behind a corridor's wall (scanned through a crack) is no
    room or hallway of its own; the corridor and the room off it are the only spaces."""
    b = MapBuilder(14.0, 8.0)
    b.room(0.5, 3.0, 13.5, 4.8).room(2.0, 5.0, 8.0, 7.5).door_h(5.0, 4.9, 0.9)
    b.room(4.0, 1.0, 10.0, 1.6)  # the sliver, behind the corridor's south wall
    b.free(7.0, 1.6, 7.2, 3.0)  # a crack through the wall joins it to the corridor
    grid = b.build()
    seg = segment_spaces(grid)
    assert len(seg.rooms) == 2
    r, c = grid.world_to_index(5.0, 1.3)
    corridor = space_at(seg, grid, 2.0, 4.0)
    # Never a space of its own: a sliver touching a space joins it (a bay of it).
    assert seg.labels[int(r), int(c)] in (0, corridor.label)
    # Without the minimum width of a space, the strip was a space of its own.
    assert len(segment_spaces(grid, AnalysisParams(space_min_width_m=0.0)).rooms) == 3
    assert corridor.kind == ElementKind.HALLWAY
    assert len(seg.doors) == 1
    door_near(seg.doors, 5.0, 4.9)


def hall_with_shelf_rows() -> OccupancyGrid:
    """A 24 m x 14 m warehouse hall with two rows of shelving (1 m deep racks, 4 m long, with
    1.2 m gaps between racks) and a 1.0 m door to an office in the north-east corner."""
    b = MapBuilder(27.0, 17.0)
    b.room(1.0, 1.0, 25.0, 15.0)
    for y0 in (5.0, 9.5):
        x = 4.0
        while x + 4.0 <= 22.0:
            b.box(x, y0, x + 4.0, y0 + 1.0)
            x += 5.2
    b.wall(20.0, 12.0, 25.0, 12.0).wall(20.0, 12.0, 20.0, 15.0)  # the office walls
    b.door_v(20.0, 13.5, 1.0)
    return b.build("warehouse")


def test_gaps_between_shelves_are_no_doors_and_the_hall_is_one_room() -> None:
    grid = hall_with_shelf_rows()
    seg = segment_spaces(grid)
    hall = space_at(seg, grid, 2.0, 2.0)
    assert hall.kind == ElementKind.ROOM
    for x, y in ((10.0, 7.5), (10.0, 12.5), (5.0, 14.0), (23.0, 3.0), (8.6, 5.5), (13.8, 10.0)):
        assert space_at(seg, grid, x, y) is hall  # aisles and the gaps between racks
    office = space_at(seg, grid, 22.5, 13.5)
    assert office is not hall
    assert len(seg.rooms) == 2
    assert len(seg.doors) == 1
    d = door_near(seg.doors, 20.0, 13.5)
    assert set(d.connects) == {hall.id, office.id}


def rotated_noisy_flat(angle_deg: float = 23.0, seed: int = 7) -> tuple[OccupancyGrid, dict[str, tuple[float, float]]]:
    """A flat (a 1.5 m hallway, three rooms off it through 0.9 m doors) drawn axis-aligned,
    rotated by ``angle_deg`` about the map centre, with lidar noise: salt specks on the floor,
    walls broken by missed scan cells. Returns the grid and the world positions of the room
    centres and door centres (rotated the same way)."""
    b = MapBuilder(20.0, 16.0)
    b.room(3.0, 7.5, 17.0, 9.0)  # hallway
    b.room(3.0, 9.15, 8.0, 13.0).door_h(5.5, 9.075, 0.9)
    b.room(8.15, 9.15, 17.0, 13.0).door_h(12.0, 9.075, 0.9)
    b.room(3.0, 3.0, 10.0, 7.35).door_h(7.0, 7.425, 0.9)
    flat = b.build()
    points = {"hallway": (10.0, 8.25), "nw": (5.5, 11.0), "ne": (12.5, 11.0), "s": (6.5, 5.0),
              "door_nw": (5.5, 9.075), "door_ne": (12.0, 9.075), "door_s": (7.0, 7.425)}
    a = math.radians(angle_deg)
    h, w = flat.cells.shape
    cy, cx = (h - 1) / 2, (w - 1) / 2
    # Nearest-neighbour rotation of the cells (rotating the array turns the world the same way
    # about the map's centre).
    rr, cc = np.mgrid[0:h, 0:w]
    sr = cy + (rr - cy) * math.cos(a) - (cc - cx) * math.sin(a)
    sc = cx + (rr - cy) * math.sin(a) + (cc - cx) * math.cos(a)
    src_r, src_c = np.rint(sr).astype(int), np.rint(sc).astype(int)
    ok = (src_r >= 0) & (src_r < h) & (src_c >= 0) & (src_c < w)
    cells = np.full((h, w), UNKNOWN, dtype=np.int8)
    cells[ok] = flat.cells[src_r[ok], src_c[ok]]
    rng = np.random.default_rng(seed)
    free = cells == FREE
    salt = free & (rng.random(cells.shape) < 0.004) & ~ndi.binary_dilation(~free, iterations=3)
    cells[salt] = OCCUPIED
    wall = cells == OCCUPIED
    broken = wall & ~salt & (rng.random(cells.shape) < 0.03)
    cells[broken] = FREE
    grid = OccupancyGrid(cells, flat.resolution_m, source=f"flat rotated {angle_deg}")
    res = flat.resolution_m

    def turned(p: tuple[float, float]) -> tuple[float, float]:
        # Cell of p in the drawn flat, then the cell it moved to (the inverse of the sampling).
        r, c = p[1] / res - 0.5, p[0] / res - 0.5
        nr = cy + (r - cy) * math.cos(a) + (c - cx) * math.sin(a)
        nc = cx - (r - cy) * math.sin(a) + (c - cx) * math.cos(a)
        return (nc + 0.5) * res, (nr + 0.5) * res

    return grid, {k: turned(p) for k, p in points.items()}


def test_a_rotated_flat_with_lidar_noise_keeps_its_rooms_doors_and_hallway() -> None:
    grid, at = rotated_noisy_flat()
    seg = segment_spaces(grid)
    hallway = space_at(seg, grid, *at["hallway"])
    rooms = [space_at(seg, grid, *at[k]) for k in ("nw", "ne", "s")]
    assert hallway.kind == ElementKind.HALLWAY
    assert [r.kind for r in rooms] == [ElementKind.ROOM] * 3
    assert len({hallway.id, *(r.id for r in rooms)}) == 4
    assert len(seg.rooms) == 4
    assert len(seg.doors) == 3
    for key, room in zip(("door_nw", "door_ne", "door_s"), rooms, strict=True):
        d = door_near(seg.doors, *at[key], tol=0.3)
        assert set(d.connects) == {hallway.id, room.id}


def test_the_whole_analysis_of_the_ray_fan_map_names_one_room() -> None:
    a = analyze(room_with_ray_fan())
    assert [r.kind for r in a.rooms] == [ElementKind.ROOM]


def store_behind_a_cabinet() -> OccupancyGrid:
    """A 12 x 6 m hall and a 12 x 4 m store north of it, parted by a wall whose one doorway
    (1.0 m) is blocked by a 0.4 m cabinet standing in it: a 0.3 m slit either side."""
    b = MapBuilder(14.0, 12.0)
    b.room(1.0, 1.0, 13.0, 11.0)
    b.wall(1.0, 7.0, 13.0, 7.0)
    b.door_h(4.0, 7.0, 1.0)
    b.box(3.8, 6.5, 4.2, 7.5)
    return b.build("store behind a cabinet")


def test_a_slit_beside_furniture_too_narrow_to_pass_does_not_join_two_rooms() -> None:
    grid = store_behind_a_cabinet()
    seg = segment_spaces(grid)
    hall, store = space_at(seg, grid, 6.0, 4.0), space_at(seg, grid, 6.0, 9.0)
    assert hall is not store
    assert len(seg.rooms) == 2
    assert seg.doors == ()
    # The slits are openings to a person (narrow doors), never a way through for the robot.
    assert sorted(round(d.center[0], 2) for d in seg.narrow_doors) == [3.65, 4.35]
    assert all(set(d.connects) == {hall.id, store.id} for d in seg.narrow_doors)


def ward_with_windowed_bays() -> OccupancyGrid:
    """A 2.2 m corridor (y 5.0-7.2) with four 4.5 m bays south of it (y 1-5). Each bay's front
    is a wall with a 1.8 m sliding door between two 0.45 m windows the laser saw through: short
    piers of wall (0.4 m) stand between each window and the door."""
    b = MapBuilder(21.0, 9.0)
    b.room(1.0, 1.0, 19.0, 7.2)
    for i in range(4):
        x0 = 1.0 + 4.5 * i
        if i:
            b.wall(x0, 1.0, x0, 5.0)  # the side wall between two bays
        b.wall(x0, 5.0, x0 + 4.5, 5.0)  # the front, then its openings
        b.free(x0 + 0.45, 4.8, x0 + 0.9, 5.2)  # a window
        b.free(x0 + 1.3, 4.8, x0 + 3.1, 5.2)  # the sliding door
        b.free(x0 + 3.5, 4.8, x0 + 3.95, 5.2)  # a window
    return b.build("ward with windowed bays")


def test_short_piers_between_windows_and_a_door_are_wall_and_each_bay_is_a_room() -> None:
    grid = ward_with_windowed_bays()
    seg = segment_spaces(grid)
    corridor = space_at(seg, grid, 9.0, 6.1)
    assert corridor.kind == ElementKind.HALLWAY
    bays = [space_at(seg, grid, x, 3.0) for x in (3.0, 7.5, 12.0, 16.5)]
    assert len({b.id for b in bays} | {corridor.id}) == 5
    assert all(b.kind == ElementKind.ROOM for b in bays)
    assert len(seg.rooms) == 5
    assert len(seg.doors) == 4
    for x, bay in zip((3.2, 7.7, 12.2, 16.7), bays, strict=True):
        d = door_near(seg.doors, x, 5.0)
        assert set(d.connects) == {corridor.id, bay.id}
        assert d.width_m == pytest.approx(1.8, abs=0.05)
