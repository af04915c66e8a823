"""The shared precomputations and the fast stand-ins give exactly what numpy / scipy give."""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt
from analysis_maps import room_with_door
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from scipy import ndimage as ndi
from skimage import measure

from langnav.analysis import precompute
from langnav.analysis.precompute import (
    EIGHT,
    GridLayers,
    approximate_polygon,
    approximate_polygons,
    border_labels,
    component_boxes,
    count_labels,
    cov2,
    dilate4,
    dilate8,
    dilate_box,
    disc,
    divmod_int,
    edt_scaled,
    extreme_at,
    far_from_outside,
    fill_holes,
    grow_by_disc,
    label8_cells,
    longest_contour,
    maximum3,
    median,
    nonzero2,
    take2,
    truncated_sq_edt,
    unique_values,
)
from langnav.analysis.unexplored import NEIGHBOURS_8, adjacent_pairs
from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN, OccupancyGrid

SHAPES = st.tuples(st.integers(1, 24), st.integers(1, 24))


def masks() -> st.SearchStrategy[npt.NDArray[np.bool_]]:
    return SHAPES.flatmap(lambda s: arrays(np.bool_, s))


@settings(max_examples=150, deadline=None)
@given(masks())
def test_dilations_match_binary_dilation(m: npt.NDArray[np.bool_]) -> None:
    assert np.array_equal(dilate8(m), ndi.binary_dilation(m, structure=EIGHT))
    assert np.array_equal(dilate4(m), ndi.binary_dilation(m))


@settings(max_examples=100, deadline=None)
@given(SHAPES.flatmap(lambda s: arrays(np.int32, s, elements=st.integers(-5, 9))))
def test_maximum3_matches_maximum_filter(a: npt.NDArray[np.int32]) -> None:
    assert np.array_equal(maximum3(a), ndi.maximum_filter(a, size=3))
    f = a.astype(np.float64) / 7.0
    assert np.array_equal(maximum3(f), ndi.maximum_filter(f, size=3))


@settings(max_examples=150, deadline=None)
@given(arrays(np.int64, st.integers(0, 60), elements=st.integers(-5, 2**40)))
def test_unique_values_matches_numpy(a: npt.NDArray[np.int64]) -> None:
    got = unique_values(a)
    assert got.dtype == np.unique(a).dtype and np.array_equal(got, np.unique(a))
    runs = np.concatenate([np.sort(a), np.sort(a[::2])])  # keys gathered run by run
    assert np.array_equal(unique_values(runs), np.unique(runs))


@settings(max_examples=100, deadline=None)
@given(masks())
def test_nonzero2_matches_nonzero(m: npt.NDArray[np.bool_]) -> None:
    r, c = nonzero2(m)
    er, ec = np.nonzero(m)
    assert np.array_equal(r, er) and np.array_equal(c, ec)


@settings(max_examples=150, deadline=None)
@given(arrays(np.int64, st.integers(0, 60), elements=st.integers(-(2**40), 2**40)),
       st.integers(1, 5000) | st.integers(-5000, -1), st.sampled_from([np.int64, np.int32]))
def test_divmod_int_matches_divmod(a: npt.NDArray[np.int64], n: int, dtype: type[np.integer]) -> None:
    a = (a % (2**31 - 1)).astype(dtype) if dtype is np.int32 else a
    q, r = divmod_int(a, n)
    eq, er = np.divmod(a, n)
    assert q.dtype == eq.dtype and r.dtype == er.dtype
    assert np.array_equal(q, eq) and np.array_equal(r, er)


def test_divmod_int_known_values() -> None:
    q, r = divmod_int(np.array([0, 5, 419, 420, 421, 113399, -1, -421]), 420)
    assert q.tolist() == [0, 0, 0, 1, 1, 269, -1, -2]
    assert r.tolist() == [0, 5, 419, 0, 1, 419, 419, 419]


@settings(max_examples=150, deadline=None)
@given(SHAPES.flatmap(lambda s: arrays(np.int32, s, elements=st.integers(0, 6))), st.integers(0, 12))
def test_count_labels_matches_bincount(lab: npt.NDArray[np.int32], minlength: int) -> None:
    for a in (lab, np.sort(lab, axis=None).reshape(lab.shape), lab[:0]):  # runs long and short; none
        got, expected = count_labels(a, minlength), np.bincount(a.ravel(), minlength=minlength)
        assert got.dtype == expected.dtype and np.array_equal(got, expected)
    comp, _n = ndi.label(lab > 2, structure=EIGHT)
    assert np.array_equal(count_labels(comp), np.bincount(comp.ravel()))


@settings(max_examples=150, deadline=None)
@given(arrays(np.int32, st.integers(0, 80), elements=st.integers(0, 6)), st.integers(0, 2**31))
def test_extreme_at_matches_ufunc_at(index: npt.NDArray[np.int32], seed: int) -> None:
    values = np.random.default_rng(seed).normal(size=index.size).round(1)  # ties between runs
    for idx in (index, np.sort(index)):  # short runs and long ones
        for ufunc in (np.maximum, np.minimum):
            got, expected = np.zeros(8), np.zeros(8)
            extreme_at(ufunc, got, idx, values)
            ufunc.at(expected, idx, values)
            assert np.array_equal(got, expected)


def test_count_labels_known_values() -> None:
    lab = np.array([[0, 0, 2, 2], [2, 0, 0, 5]], dtype=np.int32)
    assert count_labels(lab).tolist() == [4, 0, 3, 0, 0, 1]
    assert count_labels(lab, 8).tolist() == [4, 0, 3, 0, 0, 1, 0, 0]


@settings(max_examples=200, deadline=None)
@given(masks(), st.integers(0, 12))
def test_truncated_sq_edt_is_exact_up_to_its_bound(m: npt.NDArray[np.bool_], bound: int) -> None:
    d2 = truncated_sq_edt(m, bound)
    assert (d2[~m] == 0).all()
    beyond = d2[m] > bound * bound
    if (~m).any():
        ref = ndi.distance_transform_edt(m)
        near = ref <= bound
        # Bit for bit the same distances where exact, and above the bound exactly where the
        # true distance is.
        assert np.array_equal(np.sqrt(d2.astype(np.float64))[near], ref[near])
        assert np.array_equal(beyond, ~near[m])
    else:
        assert beyond.all()


@settings(max_examples=150, deadline=None)
@given(masks(), st.sampled_from([0.05, 0.1, 0.3, 0.5]), st.sampled_from([0.025, 0.05, 0.07]))
def test_far_from_outside_matches_its_formula(m: npt.NDArray[np.bool_], min_m: float, res: float) -> None:
    bound = math.ceil(min_m / res) + 1
    expected = np.sqrt(truncated_sq_edt(m, bound).astype(np.float64)) * res >= min_m
    assert np.array_equal(far_from_outside(m, min_m, res), expected)


@settings(max_examples=150, deadline=None)
@given(masks(), st.floats(0.0, 60.0))
def test_grow_by_disc_is_a_binary_dilation_by_the_disc(m: npt.NDArray[np.bool_], r2: float) -> None:
    reach = math.isqrt(int(r2)) + 1
    a = np.arange(reach + 1)
    near = a[:, None] ** 2 + a[None, :] ** 2 <= r2
    full = np.arange(-reach, reach + 1)
    disc = full[:, None] ** 2 + full[None, :] ** 2 <= r2
    assert np.array_equal(grow_by_disc(m, near), ndi.binary_dilation(m, structure=disc))


@settings(max_examples=200, deadline=None)
@given(masks(), st.integers(1, 70))
def test_dilate_box_is_the_maximum_filter(m: npt.NDArray[np.bool_], size: int) -> None:
    got = dilate_box(m, size)
    assert got.dtype == np.bool_ and np.array_equal(got, ndi.maximum_filter(m, size=size))
    assert np.array_equal(got, ndi.maximum_filter(m, size=size, mode="constant", cval=False))


@settings(max_examples=150, deadline=None)
@given(st.floats(0.0, 25.0), st.sampled_from([0.025, 0.05, 0.1]))
def test_disc_holds_the_offsets_within_its_radius(radius_m: float, res: float) -> None:
    # A robot's body in cells of a map: radius in metres over the resolution, as the callers make it.
    r = radius_m / 10.0 / res
    near = disc(r)
    top = near.shape[0] - 1
    dy, dx = np.meshgrid(np.arange(top + 2), np.arange(top + 2), indexing="ij")
    inside = dx * dx + dy * dy <= r * r + 1e-9
    assert not inside[top + 1].any() and not inside[:, top + 1].any()  # the table holds the whole disc
    assert np.array_equal(near, inside[:top + 1, :top + 1])


def test_disc_of_a_robot_body() -> None:
    # 0.2 m at 5 cm: four cells each way, the corner cells (3, 3) outside (18 > 16).
    assert disc(0.2 / 0.05).astype(int).tolist() == [[1, 1, 1, 1, 1], [1, 1, 1, 1, 0], [1, 1, 1, 1, 0],
                                                      [1, 1, 1, 0, 0], [1, 0, 0, 0, 0]]


def test_truncated_sq_edt_known_values() -> None:
    m = np.ones((5, 9), dtype=bool)
    m[2, 0] = False
    d2 = truncated_sq_edt(m, 3)
    assert d2[2, 0] == 0
    assert d2[2, 3] == 9
    assert d2[0, 1] == 5
    assert d2[2, 8] > 9  # 8 cells away: only known to be beyond the bound


@settings(max_examples=150, deadline=None)
@given(arrays(np.float64, st.integers(1, 40), elements=st.floats(-1e6, 1e6)))
def test_median_and_cov2_match_numpy(v: npt.NDArray[np.float64]) -> None:
    assert median(v) == float(np.median(v))
    if len(v) >= 2:
        pts = np.stack([v, v[::-1] * 0.5 + 1.0])
        assert np.array_equal(cov2(pts), np.cov(pts))


@settings(max_examples=100, deadline=None)
@given(masks())
def test_component_boxes_match_find_objects(m: npt.NDArray[np.bool_]) -> None:
    lab, n = ndi.label(m, structure=EIGHT)
    rr, cc = np.nonzero(lab)
    wanted = np.arange(1, n + 1)
    boxes = component_boxes(lab[rr, cc], rr, cc, wanted)
    assert boxes == {k: sl for k, sl in enumerate(ndi.find_objects(lab), start=1)}


@settings(max_examples=150, deadline=None)
@given(masks(), st.sampled_from(["dense", "few", "sparse"]))
def test_label8_cells_matches_ndi_label(m: npt.NDArray[np.bool_], way: str) -> None:
    lab, n = ndi.label(m, structure=EIGHT)
    flat = np.flatnonzero(m)
    # Each of the three ways: a labelling of the cells' box, union-find, a sparse graph.
    old = (precompute.LABEL8_DENSE_CELLS_PER_CELL, precompute.LABEL8_DENSE_MIN_CELLS, precompute.LABEL8_SMALL_CELLS)
    if way != "dense":
        precompute.LABEL8_DENSE_CELLS_PER_CELL, precompute.LABEL8_DENSE_MIN_CELLS = -1, -1  # type: ignore[misc]
        precompute.LABEL8_SMALL_CELLS = 10**9 if way == "few" else 0  # type: ignore[misc]
    try:
        got, got_n = label8_cells(flat, m.shape)
    finally:
        (precompute.LABEL8_DENSE_CELLS_PER_CELL, precompute.LABEL8_DENSE_MIN_CELLS,  # type: ignore[misc]
         precompute.LABEL8_SMALL_CELLS) = old
    assert got_n == n
    assert np.array_equal(got, lab.ravel()[flat])


@settings(max_examples=100, deadline=None)
@given(SHAPES.flatmap(lambda s: st.tuples(arrays(np.bool_, s), arrays(np.int32, s, elements=st.integers(0, 4)))))
def test_adjacent_pairs_match_brute_force(ab: tuple[npt.NDArray[np.bool_], npt.NDArray[np.int32]]) -> None:
    a, b = ab
    h, w = a.shape
    expected = sorted({(r * w + c, int(b[r + dr, c + dc]))
                       for r, c in zip(*np.nonzero(a), strict=True)
                       for dr, dc in NEIGHBOURS_8
                       if 0 <= r + dr < h and 0 <= c + dc < w and b[r + dr, c + dc] > 0})
    assert [tuple(p) for p in adjacent_pairs(a, b).tolist()] == expected


def test_grid_layers_match_direct_computation() -> None:
    grid = room_with_door()
    cells = grid.cells.copy()
    cells[0, :] = UNKNOWN  # an unknown strip on the border: the outside world
    # An unknown speck in the middle of the floor.
    inner = ndi.binary_erosion(cells == FREE, structure=EIGHT, iterations=2)
    r, c = (int(v[0]) for v in np.nonzero(inner))
    cells[r, c] = UNKNOWN
    grid = OccupancyGrid(cells=cells, resolution_m=grid.resolution_m)
    layers = GridLayers(grid)
    assert np.array_equal(layers.free, cells == FREE)
    assert np.array_equal(layers.occupied, cells == OCCUPIED)
    assert np.array_equal(layers.unknown, cells == UNKNOWN)
    lab, n = ndi.label(cells == UNKNOWN, structure=EIGHT)
    comps = layers.unknown_components
    assert comps.n == n and np.array_equal(comps.labels, lab)
    assert comps.sizes[0] == 0 and comps.sizes[1:].tolist() == np.bincount(lab.ravel())[1:].tolist()
    assert np.array_equal(layers.exterior, np.isin(lab, border_labels(lab)) & (lab > 0))
    assert layers.exterior[0].all() and not layers.exterior[r, c] and layers.unknown[r, c]
    # Computed once, and shared read-only.
    assert layers.occupied_components is layers.occupied_components
    assert not layers.free.flags.writeable


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 2**32 - 1), st.sampled_from([0, 10**12]), st.sampled_from([8, 16, 256]))
def test_wall_gradient_is_ndi_sobel_of_the_smoothed_mask(seed: int, tiled_from: int, tile: int) -> None:
    """Tiled or not, the gradient at the face cells is bit for bit the whole-grid filters'."""
    import langnav.analysis.walls as walls

    rng = np.random.default_rng(seed)
    h, w = (int(v) for v in rng.integers(1, 60, size=2))
    wall = rng.random((h, w)) < rng.uniform(0.05, 0.5)
    rows, cols = np.nonzero(rng.random((h, w)) < 0.3)
    if len(rows) == 0:
        return
    sm = ndi.gaussian_filter(wall.astype(np.float32), walls.GRADIENT_SIGMA_CELLS)
    old = (walls.TILED_MIN_WINDOW_CELLS, walls.GRADIENT_TILE_CELLS)
    walls.TILED_MIN_WINDOW_CELLS, walls.GRADIENT_TILE_CELLS = tiled_from, tile
    try:
        gy, gx = walls._wall_gradient(wall, rows, cols)
    finally:
        walls.TILED_MIN_WINDOW_CELLS, walls.GRADIENT_TILE_CELLS = old
    assert np.array_equal(gy, ndi.sobel(sm, axis=0)[rows, cols].astype(float))
    assert np.array_equal(gx, ndi.sobel(sm, axis=1)[rows, cols].astype(float))


@settings(max_examples=150, deadline=None)
@given(st.integers(2, 120).flatmap(lambda n: arrays(np.float64, (n, 2), elements=st.integers(-40, 40).map(lambda v: v / 2))),
       st.sampled_from([0.3, 1.0, 2.5]), st.booleans())
def test_approximate_polygon_matches_skimage(pts: npt.NDArray[np.float64], tolerance: float, walk: bool) -> None:
    coords = np.cumsum(pts, axis=0) / 3.0 if walk else pts  # a random walk, or scattered points
    expected = measure.approximate_polygon(coords, tolerance)
    got = approximate_polygon(coords, tolerance)
    assert got.shape == expected.shape and np.array_equal(got, expected)


@settings(max_examples=200, deadline=None)
@given(SHAPES.flatmap(lambda s: arrays(np.bool_, s)), st.integers(0, 3))
def test_longest_contour_matches_find_contours(m: npt.NDArray[np.bool_], thin: int) -> None:
    # Sparse masks too (saddles, single cells, several loops of one length).
    if thin:
        m = m & (np.arange(m.size).reshape(m.shape) % (thin + 1) == 0)
    contours = measure.find_contours(np.pad(m, 1).astype(np.uint8), 0.5)
    got = longest_contour(m)
    if not contours:
        assert got is None
        return
    expected = max(contours, key=len)
    assert got is not None and got.shape == expected.shape and np.array_equal(got, expected)


def test_longest_contour_of_a_square_and_a_speck() -> None:
    m = np.zeros((6, 6), dtype=bool)
    m[0, 5] = True  # a speck, met first in raster order but shorter
    m[2:5, 1:4] = True
    got = longest_contour(m)
    assert got is not None and len(got) == 13  # 12 edge midpoints round a 3 x 3 block, closed
    assert got[0].tolist() == got[-1].tolist()
    # In the padded image the block spans rows 3-5 and columns 2-4: its outline runs half a
    # cell outside them.
    assert (got[:, 0].min(), got[:, 0].max(), got[:, 1].min(), got[:, 1].max()) == (2.5, 5.5, 1.5, 4.5)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.integers(0, 60).flatmap(lambda n: arrays(np.float64, (n, 2), elements=st.integers(-40, 40).map(
    lambda v: v / 2))), min_size=1, max_size=5), st.sampled_from([0.3, 1.0, 2.5]))
def test_approximate_polygons_match_skimage_one_by_one(chains: list[npt.NDArray[np.float64]], tolerance: float) -> None:
    walks = [np.cumsum(c, axis=0) / 3.0 for c in chains]
    got = approximate_polygons(walks, tolerance)
    assert len(got) == len(walks)
    for g, w in zip(got, walks, strict=True):
        expected = measure.approximate_polygon(w, tolerance) if len(w) else w
        assert g.shape == expected.shape and np.array_equal(g, expected)


def test_approximate_polygon_keeps_corners_of_a_square() -> None:
    side = np.arange(0.0, 10.0)
    square = np.vstack([np.column_stack([side, np.zeros(10)]), np.column_stack([np.full(10, 10.0), side]),
                        np.column_stack([10.0 - side, np.full(10, 10.0)]), np.column_stack([np.zeros(10), 10.0 - side]),
                        [[0.0, 0.0]]])
    got = approximate_polygon(square, 1.0)
    assert got.tolist() == [[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0], [0.0, 0.0]]


@settings(max_examples=150, deadline=None)
@given(masks(), st.sampled_from([0.025, 0.05, 0.07, 0.1, 1.0]))
def test_edt_scaled_matches_distance_transform_edt(m: npt.NDArray[np.bool_], step: float) -> None:
    expected = ndi.distance_transform_edt(m, sampling=step)
    got = edt_scaled(m, step)
    assert got.dtype == np.float64 and np.array_equal(got, expected)


@settings(max_examples=200, deadline=None)
@given(masks(), st.tuples(st.integers(0, 5), st.integers(0, 5), st.integers(0, 5), st.integers(0, 5)),
       st.sampled_from([0.05, 0.1, 0.3, 1.0]))
def test_edt_scaled_of_a_mask_with_margins_matches_distance_transform_edt(
        m: npt.NDArray[np.bool_], margins: tuple[int, int, int, int], step: float) -> None:
    """A mask with empty rows and columns around it (worked on in its bounding box)."""
    top, bottom, left, right = margins
    padded = np.pad(m, ((top, bottom), (left, right)))
    got = edt_scaled(padded, step)
    assert got.dtype == np.float64 and np.array_equal(got, ndi.distance_transform_edt(padded, sampling=step))


@settings(max_examples=150, deadline=None)
@given(masks())
def test_fill_holes_matches_binary_fill_holes(m: npt.NDArray[np.bool_]) -> None:
    assert np.array_equal(fill_holes(m), ndi.binary_fill_holes(m))


def test_fill_holes_fills_a_ring_not_a_notch() -> None:
    ring = np.zeros((5, 6), dtype=bool)
    ring[1:4, 1:4] = True
    ring[2, 2] = False  # a hole
    ring[1:4, 5] = True  # a bar by the edge: the cell between is open to the edge above
    got = fill_holes(ring)
    assert got[2, 2] and not got[2, 4] and got.sum() == ring.sum() + 1


@settings(max_examples=60, deadline=None)
@given(a=arrays(np.float64, st.tuples(st.integers(1, 30), st.integers(1, 30)),
                elements=st.floats(-1e6, 1e6, allow_nan=False)),
       seed=st.integers(0, 2**31 - 1), transposed=st.booleans())
def test_take2_matches_indexing_by_two_arrays(a: npt.NDArray[np.float64], seed: int, transposed: bool) -> None:
    """take2 reads what ``a[rows, cols]`` reads, for index arrays of any shape and dtype, on a
    contiguous array and on a strided view (where it falls back to the indexing itself)."""
    m = a.T if transposed else a
    rng = np.random.default_rng(seed)
    shape = tuple(rng.integers(1, 6, size=int(rng.integers(1, 4))))
    for dtype in (np.int32, np.int64, np.intp):
        rows = rng.integers(0, m.shape[0], size=shape).astype(dtype)
        cols = rng.integers(0, m.shape[1], size=shape).astype(dtype)
        got = take2(m, rows, cols)
        assert got.dtype == m.dtype and got.shape == rows.shape
        assert np.array_equal(got, m[rows, cols])
