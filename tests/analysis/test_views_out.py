"""A view out of the building is no space: the fan of laser rays the lidar sent out through a door
or a window ends in the open, its outline nearly all unknown. A room seen only through its door
is still a room: its rays end on its far walls."""

from __future__ import annotations

import math

import numpy as np
import pytest
from analysis_maps import space_at

from langnav.analysis.elements import ElementKind
from langnav.analysis.pipeline import analyze
from langnav.analysis.segmentation import UNKNOWN_ID, segment_spaces
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN, OccupancyGrid


def _rays(cells: np.ndarray, grid: OccupancyGrid, x0: float, y0: float, bearings_deg: np.ndarray,
          length_m: float, stop: np.ndarray | None = None) -> None:
    """Free cells along rays from (x0, y0); a ray ending on a cell of ``stop`` marks it a wall hit."""
    res = grid.resolution_m
    for b in np.radians(bearings_deg):
        for t in np.arange(0.0, length_m, res / 2):
            ri, ci = grid.world_to_index(x0 + t * math.cos(b), y0 + t * math.sin(b))
            r, c = int(ri), int(ci)
            if not (0 <= r < cells.shape[0] and 0 <= c < cells.shape[1]):
                break
            if stop is not None and stop[r, c]:
                cells[r, c] = OCCUPIED
                break
            if cells[r, c] == OCCUPIED:
                break
            cells[r, c] = FREE


def office_with_views() -> OccupancyGrid:
    """A 6 m x 4 m office (x 1-7, y 1-5) with a 1.2 m door in its east wall onto the outside,
    where the lidar saw a fan of rays 60 degrees wide and 7 m long into the open; a 1 m door in
    its north wall into a 5 m x 4 m store (x 1.5-6.5, y 5.2-9.2) never entered: seen only by the
    rays sent through that door, which end on its far walls."""
    b = MapBuilder(16.0, 11.0)
    b.room(1.0, 1.0, 7.0, 5.0).door_v(7.075, 3.0, 1.2)
    b.room(1.5, 5.2, 6.5, 9.2).door_h(4.0, 5.1, 1.0)
    grid = b.build("office with views")
    cells = grid.cells.copy()
    store_walls = np.zeros(cells.shape, dtype=bool)
    ys, xs = np.mgrid[0:cells.shape[0], 0:cells.shape[1]]
    wx, wy = grid.cell_to_world(ys, xs)
    inside_store = (wx > 1.4) & (wx < 6.6) & (wy > 5.15) & (wy < 9.3)
    store_walls[inside_store & (cells == OCCUPIED)] = True
    store_walls[(wy < 5.25)] = False  # the wall with the door in it stays as scanned
    # The store: unknown but for the rays through its door, ending on its walls.
    cells[inside_store & (wy >= 5.25)] = UNKNOWN
    _rays(cells, grid, 4.0, 5.0, np.arange(20.0, 161.0, 1.0), 6.0, stop=store_walls)
    # The open outside, seen through the east door.
    _rays(cells, grid, 7.0, 3.0, np.arange(-30.0, 30.5, 0.5), 7.0)
    return OccupancyGrid(cells, grid.resolution_m, grid.origin_x_m, grid.origin_y_m, source=grid.source)


def test_a_fan_of_rays_out_through_a_door_is_no_space() -> None:
    grid = office_with_views()
    seg = segment_spaces(grid)
    office = space_at(seg, grid, 3.0, 2.0)
    store = space_at(seg, grid, 4.0, 7.5)
    assert office is not store
    assert office.kind == ElementKind.ROOM and store.kind == ElementKind.ROOM
    assert len(seg.rooms) == 2
    for x, y in ((9.0, 3.0), (11.0, 4.0), (12.5, 2.0)):  # the fan outside
        r, c = grid.world_to_index(x, y)
        assert seg.labels[int(r), int(c)] == 0
    # The doors are found as before: the store's; the fan's opening, which the flood did not
    # take for a door, is still none (a door into a view would lead into the unexplored).
    assert len(seg.doors) == 1
    assert set(seg.doors[0].connects) == {office.id, store.id}
    assert math.dist(seg.doors[0].center, (4.0, 5.1)) < 0.3
    assert all(UNKNOWN_ID not in d.connects for d in seg.doors)


def test_the_whole_analysis_names_the_office_and_the_store_only() -> None:
    a = analyze(office_with_views())
    assert [r.kind for r in a.rooms] == [ElementKind.ROOM, ElementKind.ROOM]
    office, store = sorted(a.rooms, key=lambda r: r.centroid[1])
    assert math.dist(office.centroid, (4.0, 3.0)) < 0.2
    assert 4.5 < store.centroid[1] < 9.2 and abs(store.centroid[0] - 4.0) < 0.2
    assert office.area_m2 == pytest.approx(24.0, abs=1.5)


def test_without_the_rule_the_fan_was_a_room_of_its_own(monkeypatch: pytest.MonkeyPatch) -> None:
    """The map is the failure mode: the fan rises above its door and floods as a space."""
    import langnav.analysis.segmentation as seg_mod

    grid = office_with_views()
    monkeypatch.setattr(seg_mod, "SPACE_MIN_WALL_SHARE", 0.0)
    seg = segment_spaces(grid)
    r, c = grid.world_to_index(11.0, 3.0)
    assert seg.labels[int(r), int(c)] > 0
    assert len(seg.rooms) == 3


def test_a_map_whose_walls_read_as_unknown_keeps_every_space() -> None:
    """Where most of the floor has little wall round it (an image whose walls were read as
    unknown), the share of wall tells a view from a room no more: every space stays."""
    grid = office_with_views()
    cells = grid.cells.copy()
    cells[cells == OCCUPIED] = UNKNOWN
    unwalled = OccupancyGrid(cells, grid.resolution_m, grid.origin_x_m, grid.origin_y_m, source="unwalled")
    seg = segment_spaces(unwalled)
    fan = space_at(seg, unwalled, 11.0, 3.0)
    assert fan is not space_at(seg, unwalled, 3.0, 2.0)


def test_a_door_into_a_view_leads_into_the_unexplored() -> None:
    from langnav.analysis.seg_doors import RawDoor
    from langnav.analysis.segmentation import _into_unexplored

    view = np.array([False, False, True, False, True])  # spaces 2 and 4 are views out
    doors = [RawDoor(1, 2, (5.0, 5.0), (0.0, 1.0), 0.9),  # room 1 into view 2
             RawDoor(2, 3, (8.0, 5.0), (1.0, 0.0), 1.0),  # view 2 into room 3
             RawDoor(2, 4, (9.0, 5.0), (1.0, 0.0), 1.0),  # between two views: none
             RawDoor(4, 0, (9.0, 9.0), (1.0, 0.0), 1.0),  # from a view into the unexplored: none
             RawDoor(1, 3, (3.0, 3.0), (0.0, 1.0), 0.8)]  # between two rooms: as it was
    out = _into_unexplored(doors, view)
    assert [(d.a, d.b) for d in out] == [(1, 0), (3, 0), (1, 3)]
    assert out[1].normal_rc == (-1.0, -0.0)
    assert out[2] is doors[4]
