"""The metamorphic map transforms: turned, resampled and noisy maps are the same building."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import ndimage

from langnav.eval.transforms import (
    PointsAnnotation,
    add_scan_noise,
    free_area_m2,
    max_point_shift_m,
    points_of,
    resample,
    rotate,
)
from langnav.maps.draw import MapBuilder
from langnav.maps.errors import MapError
from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN, OccupancyGrid

FOUR = np.array([[0, 1, 0], [1, 1, 1], [0, 1, 0]], dtype=bool)


def two_rooms() -> OccupancyGrid:
    """Two rooms 4 x 3 m side by side, a 0.9 m door between them, unknown around."""
    b = MapBuilder(10.0, 5.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 4.0, 3.0).room(4.15, 0.0, 8.15, 3.0).door_v(4.075, 1.5, 0.9)
    return b.build("two rooms")


def annotation() -> PointsAnnotation:
    return PointsAnnotation.model_validate({
        "map": "two_rooms.yaml",
        "spaces": [{"point": [2.0, 1.5], "kind": "room", "group": None},
                   {"point": [6.0, 1.5], "kind": "room", "group": None, "note": "east"}],
        "doors": [{"center": [4.075, 1.5], "width_m": 0.9, "optional": False}],
        "narrow_passages": [],
        "ignore": [{"polygon": [[8.5, 0.0], [8.9, 0.0], [8.9, 3.0]], "note": "fan"}],
    })


def free_label_count(cells: np.ndarray) -> int:
    _, n = ndimage.label(cells == FREE, structure=FOUR)
    return int(n)


@settings(max_examples=40, deadline=None)
@given(st.floats(min_value=-360.0, max_value=360.0, allow_nan=False))
def test_rotating_back_returns_every_point(angle_deg: float) -> None:
    grid, ann = two_rooms(), annotation()
    turned, ann1 = rotate(grid, ann, angle_deg)
    _, ann2 = rotate(turned, ann1, -angle_deg)
    # the turned grid's centre is the original's, so turning back about it restores the points
    assert max_point_shift_m(points_of(ann), points_of(ann2)) < 1e-6
    assert ann2.spaces[1].model_extra == {"note": "east"}


@settings(max_examples=25, deadline=None)
@given(st.floats(min_value=0.0, max_value=360.0, allow_nan=False))
def test_rotation_keeps_free_area_and_closed_rooms(angle_deg: float) -> None:
    grid = two_rooms()
    turned, _ = rotate(grid, annotation(), angle_deg)
    # walls may thicken by under a cell on each side (a mapper marks every cell a wall crosses)
    assert free_area_m2(turned) == pytest.approx(free_area_m2(grid), rel=0.12)
    # the two rooms stay one free region joined by the door; no free cell leaks out to the unknown
    assert free_label_count(turned.cells) == 1
    assert turned.origin_yaw_rad == 0.0
    assert turned.resolution_m == grid.resolution_m


def test_rotation_moves_points_with_the_map() -> None:
    grid, ann = two_rooms(), annotation()
    turned, ann90 = rotate(grid, ann, 90.0)
    # each annotated space point still lies on free floor of the turned map
    for s in ann90.spaces:
        r, c = turned.world_to_index(*s.point)
        assert turned.cells[int(r), int(c)] == FREE
    # the map is 10 x 5 m: turned by 90 degrees it is 5 x 10 m, padded with nothing cut
    assert (turned.width, turned.height) == (grid.height, grid.width)
    # the corner cells of a 17-degree turn lie outside the original: unknown
    t17, _ = rotate(grid, ann, 17.0)
    assert t17.cells[0, 0] == UNKNOWN and t17.width > grid.width and t17.height > grid.height


def test_rotation_refuses_a_non_finite_angle() -> None:
    with pytest.raises(MapError, match="finite"):
        rotate(two_rooms(), annotation(), math.nan)


@pytest.mark.parametrize(("res", "rel"), [(0.025, 0.01), (0.1, 0.12)])
def test_resampling_keeps_free_area(res: float, rel: float) -> None:
    grid = two_rooms()
    out = resample(grid, res)
    assert out.resolution_m == res
    assert out.width * res == pytest.approx(grid.width * grid.resolution_m, abs=res)
    assert free_area_m2(out) == pytest.approx(free_area_m2(grid), rel=rel)
    assert free_label_count(out.cells) == 1


def test_coarse_cells_are_walls_when_any_part_is_wall() -> None:
    cells = np.full((4, 4), FREE, dtype=np.int8)
    cells[0, 0] = OCCUPIED           # one wall cell in the lower-left 2x2 block
    cells[2:4, 0:2] = UNKNOWN        # an unknown block
    cells[2, 2] = UNKNOWN            # upper-right block: 3 free, 1 unknown
    cells[0:2, 2] = UNKNOWN          # lower-right block: 2 free, 2 unknown (a tie stays unknown)
    out = resample(OccupancyGrid(cells, 0.05), 0.1)
    assert out.cells.tolist() == [[OCCUPIED, UNKNOWN], [UNKNOWN, FREE]]
    fine = resample(OccupancyGrid(cells, 0.05), 0.025)
    assert fine.cells.shape == (8, 8)
    assert fine.cells[0:2, 0:2].tolist() == [[OCCUPIED, OCCUPIED], [OCCUPIED, OCCUPIED]]
    assert np.array_equal(fine.cells[::2, ::2], cells)


def test_resampling_refuses_a_bad_cell_size() -> None:
    with pytest.raises(MapError, match="positive"):
        resample(two_rooms(), 0.0)


def test_noise_is_fixed_by_its_seed_and_stays_near_walls() -> None:
    grid = two_rooms()
    a, b, c = add_scan_noise(grid, 0), add_scan_noise(grid, 0), add_scan_noise(grid, 1)
    assert np.array_equal(a.cells, b.cells)
    assert not np.array_equal(a.cells, c.cells)
    changed = a.cells != grid.cells
    assert changed.any()
    # every change is free <-> occupied (unknown is never touched) and near a wall
    assert not (changed & (grid.cells == UNKNOWN)).any()
    near_wall = (ndimage.distance_transform_edt(grid.cells != OCCUPIED) - 0.5) * grid.resolution_m <= 0.3 + 1e-9
    assert not (changed & ~near_wall).any()
    assert free_area_m2(a) == pytest.approx(free_area_m2(grid), rel=0.1)
    # no hole opens through a wall: free floor stays one region (bar a few cells cut off in corners
    # by speckle) and no free cell touches the unknown outside
    labels, _ = ndimage.label(a.cells == FREE, structure=FOUR)
    sizes = np.bincount(labels.ravel())[1:]
    assert sizes.max() >= 0.99 * sizes.sum()
    assert not (ndimage.binary_dilation(a.cells == FREE, structure=FOUR) & (grid.cells == UNKNOWN)).any()


def test_noise_refuses_a_probability_out_of_range() -> None:
    with pytest.raises(MapError, match="speckle_per_m2"):
        add_scan_noise(two_rooms(), 0, speckle_per_m2=1000.0)


def test_speckle_is_per_square_metre_whatever_the_cell_size() -> None:
    grid = two_rooms()
    fine = resample(grid, 0.025)

    def hits_per_m2(g: OccupancyGrid) -> float:
        hits = [np.count_nonzero(add_scan_noise(g, seed, wobble_probability=0.0).cells != g.cells)
                for seed in range(6)]
        return float(np.mean(hits)) / free_area_m2(g)

    # speckle only (no wobble): the same density per square metre at 0.05 and 0.025 m cells
    assert hits_per_m2(fine) == pytest.approx(hits_per_m2(grid), rel=0.25)


def test_annotation_round_trips_its_unknown_keys() -> None:
    ann = annotation()
    data = ann.to_json()
    assert data["ignore"][0]["note"] == "fan"
    assert PointsAnnotation.model_validate(data) == ann
