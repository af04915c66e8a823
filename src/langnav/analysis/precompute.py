"""What several analysis steps need from one grid, computed once, and exact fast stand-ins.

:class:`GridLayers` holds the free / occupied / unknown masks of a grid, the occupied cells and
the 8-connected component labellings (with sizes) of the occupied and of the unknown cells, and
the outside-world unknown mask, each computed on first use and then cached. ``analyze()`` builds
one per grid and hands it to every detector; the segmentation can adopt it too (it labels the
occupied and the unknown cells with the same 8-connectivity).

The stand-ins give *exactly* what the numpy / scipy call they replace gives (property-tested in
``tests/analysis/test_precompute.py``), several times faster on large maps:

- :func:`dilate8`, :func:`dilate4`: ``ndi.binary_dilation`` with a 3x3 / cross structure;
- :func:`maximum3`: ``ndi.maximum_filter(a, size=3)``; :func:`dilate_box`: the same of a mask
  with any size;
- :func:`nonzero2`: ``np.nonzero`` of a 2-D array; :func:`divmod_int`: ``np.divmod`` of integer
  indices by a number (a flat index into its row and column);
- :func:`label8_cells`: ``ndi.label(..., EIGHT)`` of a sparse set of cells (a skeleton);
- :func:`component_boxes`: ``ndi.find_objects`` for chosen components, from their cells;
- :func:`truncated_sq_edt`: ``distance_transform_edt`` squared, exact up to a bound (what a
  test of short clearances needs), in small integers; :func:`far_from_outside`: its test
  against a distance, as the outside grown by the disc of the offsets that fail it
  (:func:`grow_by_disc`, the binary dilation by a disc, :func:`disc`);
- :func:`count_labels`: ``np.bincount`` of a label image, by its runs of equal labels;
  :func:`extreme_at`: ``np.maximum.at`` / ``np.minimum.at`` by labels, a run at a time;
- :func:`median`, :func:`cov2`: ``np.median`` and ``np.cov`` without their overhead;
- :func:`unique_values`: ``np.unique`` of integer keys, by a stable sort;
- :func:`edt_scaled`: ``ndi.distance_transform_edt(mask, sampling=step)`` for a 2-D mask and one
  step for both axes, the distances read from a table of the few (|drow|, |dcol|) offsets;
- :func:`fill_holes`: ``ndi.binary_fill_holes`` of a 2-D mask, by one labelling of the rest;
- :func:`take2`: ``a[rows, cols]`` (a gather by two index arrays), as one flat take;
- :func:`longest_contour`: the longest of ``skimage.measure.find_contours`` of a binary mask
  (padded with a ring of 0) at level 0.5, from the marching-squares segments of all squares at
  once instead of a dictionary walk over them;
- :func:`approximate_polygon`: ``skimage.measure.approximate_polygon`` (Douglas-Peucker), all
  the segments of a level of its recursion at once (:func:`approximate_polygons`: of several
  chains at once).

The cached arrays are shared: they are marked read-only so that no caller changes them for the
others by mistake.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from functools import cached_property
from typing import Any, Final, TypeVar

import numpy as np
import numpy.typing as npt
from scipy import ndimage as ndi
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN, OccupancyGrid

#: 8-connectivity: cells that touch at a corner are one component (scan shadows and wall
#: fragments are rarely 4-clean).
EIGHT: Final = np.ones((3, 3), dtype=bool)

BoolArray = npt.NDArray[np.bool_]
IntArray = npt.NDArray[np.int32]
_S = TypeVar("_S", bound=np.generic)


def dilate8(mask: BoolArray) -> BoolArray:
    """``ndi.binary_dilation(mask, structure=EIGHT)`` for a 2-D mask, as two separable passes of
    shifted ORs (an order of magnitude faster; the result is identical)."""
    m = np.asarray(mask, dtype=bool)
    rows = m.copy()
    rows[1:] |= m[:-1]
    rows[:-1] |= m[1:]
    out = rows.copy()
    out[:, 1:] |= rows[:, :-1]
    out[:, :-1] |= rows[:, 1:]
    return out


def dilate4(mask: BoolArray) -> BoolArray:
    """``ndi.binary_dilation(mask)`` (the cross, 4-neighbour structure) for a 2-D mask, exact."""
    m = np.asarray(mask, dtype=bool)
    out = m.copy()
    out[1:] |= m[:-1]
    out[:-1] |= m[1:]
    out[:, 1:] |= m[:, :-1]
    out[:, :-1] |= m[:, 1:]
    return out


def dilate_box(mask: BoolArray, size: int) -> BoolArray:
    """``ndi.maximum_filter(mask, size=size)`` for a 2-D boolean mask (its default "reflect"
    edges, or "constant" ones with ``cval=False``: the same result, as the cells mirrored in
    from beyond the edge lie in the window already), several times faster: along each axis the
    OR of each window (cells i - size // 2 to i + (size - 1) // 2, as scipy places an even
    window) is the OR of two runs of the largest power of two within it, and those runs are
    made by doubling (a few shifted ORs) instead of scipy's pass over every window."""
    m = np.asarray(mask, dtype=bool)
    if size <= 1:
        return m.copy()
    lo = size // 2
    p = 1 << (size.bit_length() - 1)  # the largest power of two <= size
    out = m
    for axis in (0, 1):
        x = np.moveaxis(out, axis, 0)
        n = x.shape[0]
        # The cells beyond the edges as False, so that every window lies inside.
        run = np.zeros((n + size - 1, *x.shape[1:]), dtype=bool)
        run[lo:lo + n] = x
        k = 1
        while k < p:  # run[j]: the OR of the k cells from j on
            run[:-k] |= run[k:]
            k *= 2
        out = np.moveaxis(run[:n] | run[size - p:size - p + n], 0, axis)
    return np.ascontiguousarray(out)


def maximum3(a: npt.NDArray[_S]) -> npt.NDArray[_S]:
    """``ndi.maximum_filter(a, size=3)`` for a 2-D array of finite values: the same result (its
    "reflect" edges repeat the edge cell, which cannot raise a maximum), as two separable passes
    of shifted maxima, several times faster."""
    rows = a.copy()
    np.maximum(rows[1:], a[:-1], out=rows[1:])
    np.maximum(rows[:-1], a[1:], out=rows[:-1])
    out = rows.copy()
    np.maximum(out[:, 1:], rows[:, :-1], out=out[:, 1:])
    np.maximum(out[:, :-1], rows[:, 1:], out=out[:, :-1])
    return out


def border_labels(lab: npt.NDArray[np.integer]) -> npt.NDArray[np.int64]:
    """Labels (> 0) of the components touching the border of a label image."""
    edge = np.concatenate([lab[0, :], lab[-1, :], lab[:, 0], lab[:, -1]])
    return unique_values(edge[edge > 0]).astype(np.int64)


_A = TypeVar("_A", bound=npt.NDArray[Any])


def _frozen(a: _A) -> _A:
    a.flags.writeable = False
    return a


@dataclass(frozen=True, eq=False)
class Components:
    """An 8-connected labelling: ``labels`` (int32, 0 = background), ``n`` components and the
    cell count of each (``sizes[k]`` for label k, ``sizes[0] = 0``)."""

    labels: IntArray
    n: int
    sizes: npt.NDArray[np.int64]


def count_labels(labels: npt.NDArray[np.integer[Any]], minlength: int = 0) -> npt.NDArray[np.intp]:
    """``np.bincount(labels.ravel(), minlength=minlength)`` of non-negative integer labels: the
    same counts, of the same type and length, counted by runs of equal labels. A label image
    holds long runs of one label (the background, a room), and ``np.bincount`` adds one to the
    same counter cell after cell, each addition waiting for the one before (several times
    slower than a pass that finds where the label changes); here each run is added once, its
    length as a weight (float64: exact for every count below 2**53)."""
    v = labels.ravel()
    if v.size == 0:
        return np.bincount(v, minlength=minlength)
    starts = _run_starts(v)
    lengths = np.empty_like(starts)
    lengths[:-1] = starts[1:]
    lengths[-1] = v.size
    lengths -= starts
    return np.bincount(v[starts], weights=lengths, minlength=minlength).astype(np.intp)


def _run_starts(v: npt.NDArray[np.generic]) -> npt.NDArray[np.intp]:
    """Where each run of equal values of a non-empty 1-D array starts."""
    starts = np.empty(1, dtype=np.intp)
    starts[0] = 0
    return np.concatenate([starts, np.flatnonzero(v[1:] != v[:-1]) + 1])


def extreme_at(ufunc: np.ufunc, out: npt.NDArray[Any], index: npt.NDArray[np.integer[Any]],
               values: npt.NDArray[Any]) -> None:
    """``ufunc.at(out, index, values)`` for ``np.maximum`` or ``np.minimum`` and 1-D ``index``
    and ``values``: the same result. ``ufunc.at`` is slow per element (several times a plain
    ufunc); a label image's cells in raster order come in runs of one label, so each run's
    extreme is taken first (``ufunc.reduceat``) and ``ufunc.at`` sees one value per run. A
    maximum or a minimum rounds nothing: grouping the values differently cannot change it."""
    if index.size == 0:
        return
    starts = _run_starts(index)
    ufunc.at(out, index[starts], ufunc.reduceat(values, starts))


def label8(mask: BoolArray) -> Components:
    """The 8-connected components of ``mask`` with their sizes."""
    lab, n = ndi.label(mask, structure=EIGHT)
    sizes = count_labels(lab, n + 1)
    sizes[0] = 0
    return Components(_frozen(lab.astype(np.int32, copy=False)), int(n), _frozen(sizes))


@dataclass(frozen=True, eq=False)
class GridLayers:
    """Masks and component labellings of one grid, each computed once, on first use.

    Build one per grid (``GridLayers(grid)``) and pass it to every step that analyses that grid.
    """

    grid: OccupancyGrid

    @cached_property
    def free(self) -> BoolArray:
        return _frozen(self.grid.cells == FREE)

    @cached_property
    def occupied(self) -> BoolArray:
        return _frozen(self.grid.cells == OCCUPIED)

    @cached_property
    def unknown(self) -> BoolArray:
        return _frozen(self.grid.cells == UNKNOWN)

    @cached_property
    def occupied_flat(self) -> npt.NDArray[np.intp]:
        """Flat indices of the occupied cells, ascending (a real map has few)."""
        return _frozen(np.flatnonzero(self.occupied))

    @cached_property
    def occupied_components(self) -> Components:
        """8-connected components of the occupied cells."""
        return label8(self.occupied)

    @cached_property
    def unknown_components(self) -> Components:
        """8-connected components of the unknown cells."""
        return label8(self.unknown)

    @cached_property
    def unknown_outside(self) -> npt.NDArray[np.bool_]:
        """Per unknown component label: does it touch the grid border (the world outside)?"""
        comp = self.unknown_components
        outside = np.zeros(comp.n + 1, dtype=bool)
        outside[border_labels(comp.labels)] = True
        outside[0] = False
        return _frozen(outside)

    @cached_property
    def exterior(self) -> BoolArray:
        """Unknown cells connected (8-neighbours) to the grid border: the world outside the map."""
        return _frozen(self.unknown_outside[self.unknown_components.labels])


def fill_holes(mask: BoolArray) -> BoolArray:
    """``ndi.binary_fill_holes(mask)`` for a 2-D mask, exactly: the mask plus the rest of the
    array that is not 4-connected to its edge (what that call's dilation from the edge reaches),
    found by one labelling instead of a dilation run to convergence."""
    m = np.asarray(mask, dtype=bool)
    rest, n = ndi.label(~m)
    # Per label of the rest: enclosed (not background, not touching the edge); read by label.
    enclosed = np.ones(n + 1, dtype=bool)
    enclosed[0] = False
    enclosed[border_labels(rest)] = False
    return m | enclosed[rest]


def truncated_sq_edt(mask: BoolArray, max_cells: int) -> npt.NDArray[np.signedinteger[Any]]:
    """Squared Euclidean distance (in cells², integers) from each cell of ``mask`` to the nearest
    cell outside it, exact wherever it is at most ``max_cells ** 2``; elsewhere some value above
    ``max_cells ** 2``; 0 off the mask. As in ``ndi.distance_transform_edt(mask)``, cells beyond
    the array's edge do not count as outside.

    For steps that only need short distances (how wide a narrow passage is): a column pass
    (distance to the nearest outside cell in the same column, capped) and a min-plus pass over
    the ``2 * max_cells + 1`` nearest columns, in small integers. ``np.sqrt`` of the result
    (as float64) is bit for bit what ``distance_transform_edt`` returns where it is exact.
    """
    m = np.asarray(mask, dtype=bool)
    h, w = m.shape
    cap = int(max_cells) + 1
    # The smallest integer type that holds every value of the row pass (a capped square plus a
    # square): fewer bytes per cell for its passes over the whole array.
    top = cap * cap + max_cells * max_cells
    dtype: type[np.signedinteger[Any]] = (np.int8 if top < np.iinfo(np.int8).max
                                          else np.int16 if top < np.iinfo(np.int16).max else np.int32)
    # Column pass: rows to the nearest outside cell above / below ("far" when there is none),
    # in place, in the smallest integer type that holds the row numbers.
    far = h + cap + 1
    it: type[np.signedinteger[Any]] = np.int16 if 2 * h + cap + 2 < np.iinfo(np.int16).max else np.int32
    idx = np.arange(h, dtype=it)[:, None]
    up = np.where(m, it(-far), idx)
    np.maximum.accumulate(up, axis=0, out=up)
    np.subtract(idx, up, out=up)
    down = np.where(m, it(far + h), idx)
    np.minimum.accumulate(down[::-1], axis=0, out=down[::-1])
    np.subtract(down, idx, out=down)
    np.minimum(up, down, out=up)
    np.minimum(up, cap, out=up)
    col = up
    g2: npt.NDArray[np.signedinteger[Any]] = col.astype(dtype)
    np.multiply(g2, g2, out=g2)
    out = g2.copy()
    tmp = np.empty_like(g2)
    # Row pass: the nearest outside cell dc columns away is at least dc away; past max_cells
    # it cannot make a distance within the bound. Inner columns take the nearer of their two
    # columns dc away at once; the dc columns at each edge have only one of them.
    for dc in range(1, min(int(max_cells), w - 1) + 1):
        k = dtype(dc * dc)
        if 2 * dc < w:
            t = tmp[:, dc:w - dc]
            np.minimum(g2[:, :w - 2 * dc], g2[:, 2 * dc:], out=t)
            t += k
            np.minimum(out[:, dc:w - dc], t, out=out[:, dc:w - dc])
        e = min(dc, w - dc)
        np.minimum(out[:, :e], g2[:, dc:dc + e] + k, out=out[:, :e])
        np.minimum(out[:, w - e:], g2[:, w - e - dc:w - dc] + k, out=out[:, w - e:])
    return out


def far_from_outside(mask: BoolArray, min_m: float, resolution_m: float) -> BoolArray:
    """The cells of ``mask`` at least ``min_m`` from the nearest cell outside it (cell centre to
    cell centre, ``resolution_m`` a cell), as ``np.sqrt(truncated_sq_edt(mask, bound)
    .astype(np.float64)) * resolution_m >= min_m`` gives them with ``bound = ceil(min_m /
    resolution_m) + 1``, exactly.

    That test rises with the distance, so a cell passes it when every outside cell passes it:
    when no outside cell lies at an offset that fails it; the others are the outside grown by
    those offsets (:func:`grow_by_disc`).
    """
    bound = math.ceil(min_m / resolution_m) + 1
    a = np.arange(bound + 1)
    near = ~(np.sqrt((a[:, None] ** 2 + a[None, :] ** 2).astype(np.float64)) * resolution_m >= min_m)
    return ~grow_by_disc(~np.asarray(mask, dtype=bool), near)


def disc(radius_cells: float) -> BoolArray:
    """The disc of this radius (cells, centre to centre) as :func:`grow_by_disc` takes it: the
    offsets (|rows|, |columns|) = (dy, dx) with dx² + dy² ≤ radius², a square table of
    ``floor(radius) + 1`` each way (each row's run: the largest dx for its dy, worked out as a
    square root)."""
    r2 = radius_cells * radius_cells + 1e-9  # a cell exactly on the circle is inside
    top = math.floor(math.sqrt(r2))
    near = np.zeros((top + 1, top + 1), dtype=bool)
    for dy in range(top + 1):
        near[dy, :math.floor(math.sqrt(r2 - dy * dy)) + 1] = True
    return near


def grow_by_disc(mask: BoolArray, near: BoolArray) -> BoolArray:
    """The cells a cell of ``mask`` reaches at an offset (rows, columns) with ``near[|rows|,
    |columns|]`` (cells beyond the array reach nothing): a binary dilation by that disc, exactly.

    ``near`` must be a disc: in each row of it the offsets that reach form one run from column 0
    (as any test that rises with the distance gives). The mask is grown along its rows by each
    run's length, then those copies across rows: a few dozen passes over a boolean array, in
    place of a distance transform for a test against one distance.
    """
    m = np.asarray(mask, dtype=bool)
    h, w = m.shape
    half = [int(np.flatnonzero(row).max()) if row.any() else -1 for row in np.asarray(near, dtype=bool)]
    out = np.zeros(m.shape, dtype=bool)
    if half[0] < 0:
        return out  # the disc is empty
    grown: dict[int, BoolArray] = {}
    cur = m.copy()
    done = 0
    for width in sorted({x for x in half if x >= 0}):
        for d in range(done + 1, min(width, w - 1) + 1):
            cur[:, d:] |= m[:, :-d]
            cur[:, :-d] |= m[:, d:]
        done = width
        grown[width] = cur.copy()
    out |= grown[half[0]]
    for dr in range(1, min(len(half) - 1, h - 1) + 1):
        if half[dr] >= 0:
            row = grown[half[dr]]
            out[dr:] |= row[:-dr]
            out[:-dr] |= row[dr:]
    return out


def component_boxes(ids: npt.NDArray[np.integer], rows: npt.NDArray[np.integer], cols: npt.NDArray[np.integer],
                    wanted: npt.NDArray[np.integer]) -> dict[int, tuple[slice, slice]]:
    """Bounding boxes (as ``ndi.find_objects`` gives them) of the components ``wanted``, from
    their cells (``ids[i]`` is the label of the cell at ``rows[i], cols[i]``): a pass over those
    cells only, instead of over the whole label image."""
    if len(wanted) == 0:
        return {}
    n = int(max(int(np.max(wanted)), int(np.max(ids)) if len(ids) else 0)) + 1
    big = np.iinfo(np.int64).max
    r0 = np.full(n, big, dtype=np.int64)
    c0 = np.full(n, big, dtype=np.int64)
    r1 = np.full(n, -1, dtype=np.int64)
    c1 = np.full(n, -1, dtype=np.int64)
    ids = np.asarray(ids).ravel()
    extreme_at(np.minimum, r0, ids, np.asarray(rows).ravel())
    extreme_at(np.minimum, c0, ids, np.asarray(cols).ravel())
    extreme_at(np.maximum, r1, ids, np.asarray(rows).ravel())
    extreme_at(np.maximum, c1, ids, np.asarray(cols).ravel())
    return {int(k): (slice(int(r0[k]), int(r1[k]) + 1), slice(int(c0[k]), int(c1[k]) + 1))
            for k in np.asarray(wanted).tolist()}


def unique_values(a: npt.NDArray[np.integer]) -> npt.NDArray[np.integer]:
    """``np.unique`` of a 1-D integer array: the same sorted distinct values, from one stable
    sort (timsort, which keys gathered run by run, each run in order, take several times faster
    than the sort ``np.unique`` uses)."""
    s = np.sort(a, kind="stable")
    if s.size < 2:
        return s
    first = np.empty(s.size, dtype=bool)
    first[0] = True
    np.not_equal(s[1:], s[:-1], out=first[1:])
    return s[first]


def median(v: npt.NDArray[np.floating]) -> float:
    """``np.median`` of a non-empty 1-D array: the same value (a partition, then the middle one or
    the mean of the middle two), without the generic machinery that dominates on short arrays."""
    h = len(v) // 2
    if len(v) % 2:
        return float(np.partition(v, h)[h])
    p = np.partition(v, (h - 1, h))
    return float((p[h - 1] + p[h]) / 2)


def cov2(centred: npt.NDArray[np.floating]) -> npt.NDArray[np.float64]:
    """``np.cov(centred)`` for a (2, n) array of float64 rows, n >= 2: the same arithmetic (copy,
    remove the row means, product, divide by n - 1) without its argument handling."""
    x = np.array(centred, dtype=np.float64)
    x -= x.mean(axis=1)[:, None]
    c = np.dot(x, x.T.conj())
    c *= np.true_divide(1, x.shape[1] - 1)
    return c


_I = TypeVar("_I", bound=np.integer[Any])


def divmod_int(a: npt.NDArray[_I], n: int) -> tuple[npt.NDArray[_I], npt.NDArray[_I]]:
    """``np.divmod(a, n)`` of an integer array by a non-zero Python int (a flat index by the row
    length: its row and column): the same quotients and remainders, of the same type. numpy's
    floor division by one number multiplies and shifts (libdivide) where ``np.divmod`` divides
    each element in hardware; the remainder is then ``a - q * n`` (floor division's, as
    ``np.divmod``'s: the sign of ``n``), about half the time in all."""
    q = np.floor_divide(a, n)
    r = np.multiply(q, n)
    np.subtract(a, r, out=r)
    return q, r


def nonzero2(mask: npt.NDArray[np.generic]) -> tuple[npt.NDArray[np.intp], npt.NDArray[np.intp]]:
    """``np.nonzero`` of a 2-D array: the same (rows, cols) in the same row-major order, through
    the flat indices (about three times faster on a large, sparse mask)."""
    return divmod_int(np.flatnonzero(mask), mask.shape[1])


#: Up to this many cells, :func:`label8_cells` joins them in plain Python (a sparse graph's
#: set-up costs more than the whole job).
LABEL8_SMALL_CELLS: Final = 200
#: ... unless their bounding box holds at most this many cells per cell plus
#: LABEL8_DENSE_MIN_CELLS: then ``ndi.label`` of the box is cheaper (a few nanoseconds a cell of
#: the box, against about a microsecond per cell joined in Python or in a sparse graph).
LABEL8_DENSE_CELLS_PER_CELL: Final = 32
LABEL8_DENSE_MIN_CELLS: Final = 4096


def _label8_few(flat: list[int], shape: tuple[int, int]) -> tuple[npt.NDArray[np.int32], int]:
    """:func:`label8_cells` for a few cells (sorted flat indices, as a list): union-find."""
    h, w = shape
    where = {f: i for i, f in enumerate(flat)}
    parent = list(range(len(flat)))

    def root(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for i, f in enumerate(flat):
        r, c = divmod(f, w)
        for dr, dc in ((0, 1), (1, -1), (1, 0), (1, 1)):
            if 0 <= c + dc < w and r + dr < h:
                j = where.get(f + dr * w + dc)
                if j is not None:
                    a, b = root(i), root(j)
                    if a != b:
                        parent[max(a, b)] = min(a, b)
    # Number the components by their first cell (the cells are in raster order).
    number: dict[int, int] = {}
    out = np.empty(len(flat), dtype=np.int32)
    for i in range(len(flat)):
        out[i] = number.setdefault(root(i), len(number) + 1)
    return out, len(number)


def label8_cells(flat: npt.NDArray[np.integer], shape: tuple[int, int]) -> tuple[npt.NDArray[np.int32], int]:
    """8-connected components of a sparse set of cells, given by their sorted flat indices in an
    array of ``shape``: the label of each cell (1..n) and n, numbered as ``ndi.label`` numbers
    them (in the raster order of each component's first cell). For thin sets (a skeleton) this
    costs a pass over the cells, not over the whole array."""
    n_cells = len(flat)
    if n_cells == 0:
        return np.zeros(0, dtype=np.int32), 0
    f = np.asarray(flat, dtype=np.int64)
    r, c = divmod_int(f, shape[1])
    r0, c0 = int(r[0]), int(c.min())  # the cells are sorted: the first is in the top row
    box_h, box_w = int(r[-1]) - r0 + 1, int(c.max()) - c0 + 1
    if box_h * box_w <= LABEL8_DENSE_CELLS_PER_CELL * n_cells + LABEL8_DENSE_MIN_CELLS:
        # Few cells in a small box: one labelling of the box (its raster order is the grid's,
        # so the components are numbered alike).
        box = np.zeros((box_h, box_w), dtype=bool)
        box[r - r0, c - c0] = True
        lab, n = ndi.label(box, structure=EIGHT)
        return lab[r - r0, c - c0].astype(np.int32, copy=False), int(n)
    if n_cells <= LABEL8_SMALL_CELLS:
        return _label8_few(np.asarray(flat).tolist(), shape)
    h, w = shape
    src: list[npt.NDArray[np.intp]] = []
    dst: list[npt.NDArray[np.intp]] = []
    # Each neighbour pair once: east, south-west, south, south-east.
    for dr, dc in ((0, 1), (1, -1), (1, 0), (1, 1)):
        nb = f + (dr * w + dc)
        pos = np.minimum(np.searchsorted(f, nb), n_cells - 1)
        hit = (f[pos] == nb) & (c + dc >= 0) & (c + dc < w) & (r + dr < h)
        src.append(np.flatnonzero(hit))
        dst.append(pos[hit])
    i = np.concatenate(src)
    j = np.concatenate(dst)
    graph = coo_matrix((np.ones(len(i), dtype=np.int8), (i, j)), shape=(n_cells, n_cells))
    n, comp = connected_components(graph, directed=False)
    # Renumber by first appearance (the cells are in raster order).
    _, first = np.unique(comp, return_index=True)
    relabel = np.empty(n, dtype=np.int32)
    relabel[np.argsort(first)] = np.arange(1, n + 1, dtype=np.int32)
    return relabel[comp], int(n)


def approximate_polygon(coords: npt.NDArray[np.float64], tolerance: float) -> npt.NDArray[np.float64]:
    """``skimage.measure.approximate_polygon(coords, tolerance)`` for a (K, 2) float64 chain and
    ``tolerance > 0``: the same points, bit for bit (see :func:`approximate_polygons`)."""
    return approximate_polygons([coords], tolerance)[0]


def approximate_polygons(chains: list[npt.NDArray[np.float64]], tolerance: float) -> list[npt.NDArray[np.float64]]:
    """:func:`approximate_polygon` of each of ``chains``, all at once.

    Douglas-Peucker keeps a point where it splits a segment, and whether and where a segment
    splits depends on that segment alone, so the segments of one level of the recursion are
    measured together, of every chain (a segment never leaves its chain), with skimage's
    arithmetic element by element (numpy's sine, cosine and arctangent give an array the values
    they give its elements one by one).
    """
    if tolerance <= 0:
        raise ValueError(f"approximate_polygon needs a positive tolerance, got {tolerance}")
    if not chains:
        return []
    parts = [np.asarray(c, dtype=np.float64).reshape(-1, 2) for c in chains]
    sizes = np.array([len(c) for c in parts], dtype=np.intp)
    xy = np.concatenate(parts)
    n = xy.shape[0]
    bounds = np.concatenate([[0], np.cumsum(sizes)])
    chain = np.zeros(n, dtype=bool)
    some = sizes > 0
    starts = bounds[:-1][some]
    ends = bounds[1:][some] - 1
    chain[starts] = True
    chain[ends] = True
    rows, cols = xy[:, 0], xy[:, 1]
    while True:
        inner = ends - starts > 1  # a segment with no point between its ends never splits
        starts, ends = starts[inner], ends[inner]
        if starts.size == 0:
            break
        r0, c0, r1, c1 = rows[starts], cols[starts], rows[ends], cols[ends]
        dr, dc = r1 - r0, c1 - c0
        angle = -np.arctan2(dr, dc)
        sin, cos = np.sin(angle), np.cos(angle)
        dist = c0 * sin + r0 * cos
        # The points between the ends of every segment, segment by segment.
        counts = ends - starts - 1
        first = np.cumsum(counts) - counts
        seg = np.repeat(np.arange(starts.size), counts)
        idx = np.arange(int(counts.sum())) + np.repeat(starts + 1 - first, counts)
        pr, pc = rows[idx], cols[idx]
        dr0, dc0 = pr - r0[seg], pc - c0[seg]
        dr1, dc1 = pr - r1[seg], pc - c1[seg]
        sdr, sdc = dr[seg], dc[seg]
        perp = ((dr0 * sdr + dc0 * sdc) > 0) & ((-dr1 * sdr - dc1 * sdc) > 0)
        d = np.where(perp, np.abs(pr * cos[seg] + pc * sin[seg] - dist[seg]),
                     np.minimum(np.sqrt(dc0**2 + dr0**2), np.sqrt(dc1**2 + dr1**2)))
        top = np.maximum.reduceat(d, first)
        split = top > tolerance
        if not split.any():
            break
        # The first point at the maximum of each segment that splits.
        at_top = np.flatnonzero((d == top[seg]) & split[seg])
        first_hit = np.concatenate(([True], seg[at_top[1:]] != seg[at_top[:-1]]))
        new = idx[at_top[first_hit]]
        chain[new] = True
        starts = np.concatenate([starts[split], new])
        ends = np.concatenate([new, ends[split]])
    return [xy[a:b][chain[a:b]] for a, b in zip(bounds[:-1].tolist(), bounds[1:].tolist(), strict=True)]


def edt_scaled(mask: BoolArray, step: float) -> npt.NDArray[np.float64]:
    """``ndi.distance_transform_edt(mask, sampling=step)`` for a 2-D mask: the same values, bit
    for bit. scipy's feature transform picks the nearest outside cell of each cell (with the
    same sampling, so the same one); its distance, ``sqrt((dr * step)² + (dc * step)²)`` in
    float64, depends only on (|dr|, |dc|), so it is read from a table of those offsets instead
    of being worked out on whole-grid float arrays.

    The transform runs on the mask's bounding box and a ring of one cell around it (0 outside):
    every cell of the mask has its nearest outside cell in there (the ring lies between it and
    any farther one), and scipy's passes along each row and column meet the cells beyond the
    ring only as candidates strictly farther than the ring's, which neither displace a nearer
    one nor change which of two equally near ones is kept."""
    m = np.asarray(mask)
    rows, cols = np.flatnonzero(m.any(axis=1)), np.flatnonzero(m.any(axis=0))
    if rows.size == 0:
        return np.zeros(m.shape)
    r0, r1 = max(int(rows[0]) - 1, 0), min(int(rows[-1]) + 2, m.shape[0])
    c0, c1 = max(int(cols[0]) - 1, 0), min(int(cols[-1]) + 2, m.shape[1])
    if (r1 - r0) * (c1 - c0) < m.size:
        out = np.zeros(m.shape)
        out[r0:r1, c0:c1] = edt_scaled(m[r0:r1, c0:c1], step)
        return out
    h, w = m.shape
    ft = ndi.distance_transform_edt(m, sampling=(step, step), return_distances=False, return_indices=True)
    dr = ft[0]
    dr -= np.arange(h, dtype=np.int32)[:, None]
    np.abs(dr, out=dr)
    dc = ft[1]
    dc -= np.arange(w, dtype=np.int32)[None, :]
    np.abs(dc, out=dc)
    s = np.float64(step)
    a = np.arange(int(dr.max()) + 1, dtype=np.float64) * s
    b = np.arange(int(dc.max()) + 1, dtype=np.float64) * s
    table = np.sqrt((a * a)[:, None] + (b * b)[None, :])
    return take2(table, dr, dc)


def take2(a: npt.NDArray[_S], rows: npt.NDArray[np.integer], cols: npt.NDArray[np.integer]) -> npt.NDArray[_S]:
    """``a[rows, cols]`` for a 2-D array and index arrays of one shape, every index inside the
    array: the same values, read by one flat ``np.take`` (numpy's indexing by two arrays walks a
    general multi-index iterator, several times slower per element)."""
    if not a.flags.c_contiguous:
        return a[rows, cols]
    flat = np.multiply(rows, a.shape[1], dtype=np.intp)
    flat += cols
    return np.take(a.reshape(-1), flat)


#: Marching squares on a binary image at level 0.5, as ``skimage.measure.find_contours`` draws
#: them (``fully_connected="low"``): for each square's code (upper-left * 8 + upper-right * 4 +
#: lower-left * 2 + lower-right, 1 where the image is above the level), the segments it adds, in
#: the order it adds them, each from one edge's midpoint to another's: T(op), B(ottom), L(eft),
#: R(ight). The two saddles (6, 9) add two; codes 0 and 15 none.
_MS_SEGMENTS: Final = {1: (("B", "R"),), 2: (("L", "B"),), 3: (("L", "R"),), 4: (("R", "T"),),
                       5: (("B", "T"),), 6: (("R", "T"), ("L", "B")), 7: (("L", "T"),),
                       8: (("T", "L"),), 9: (("T", "L"), ("B", "R")), 10: (("T", "B"),),
                       11: (("T", "R"),), 12: (("R", "L"),), 13: (("B", "L"),), 14: (("R", "B"),)}


@functools.lru_cache(maxsize=64)
def _ms_offsets(width: int) -> tuple[npt.NDArray[np.int64], ...]:
    """Per square code: the ids of its first and second segments' ends, less twice the square's
    flat index (its upper-left vertex, ``row * width + col``). An edge midpoint's id is twice the
    flat index of the vertex it starts from, plus 1 when the edge runs down (a column's edge)."""
    edge = {"T": 0, "B": 2 * width, "L": 1, "R": 3}
    out = [np.full(16, -1, dtype=np.int64) for _ in range(4)]
    for code, segs in _MS_SEGMENTS.items():
        for k, (a, b) in enumerate(segs):
            out[2 * k][code] = edge[a]
            out[2 * k + 1][code] = edge[b]
    return tuple(_frozen(a) for a in out)


def _doublings(n: int) -> int:
    """How many times a stride doubles from 1 to at least ``n`` (ceil(log2(n)), at least 1)."""
    return max(1, (n - 1).bit_length())


def _loop_ranks(nxt: npt.NDArray[np.intp], members: npt.NDArray[np.intp], start: int) -> npt.NDArray[np.intp]:
    """For the segments ``members`` of one loop of the successor map ``nxt`` (``start`` among
    them): how many steps along the successors each lies from ``start`` (list ranking: the loop
    is cut before ``start``, and each segment's distance to the cut is summed over strides that
    double)."""
    size = members.size
    local = np.empty(nxt.size, dtype=np.intp)
    local[members] = np.arange(size)
    step = local[nxt[members]]
    tail = int(np.flatnonzero(step == local[start])[0])  # the segment the loop ends with
    step[tail] = tail
    dist = np.ones(size, dtype=np.intp)
    dist[tail] = 0
    for _ in range(_doublings(size)):
        dist += dist[step]
        step = step[step]
    return (size - 1) - dist


def longest_contour(mask: BoolArray) -> npt.NDArray[np.float64] | None:
    """``max(skimage.measure.find_contours(np.pad(mask, 1).astype(np.uint8), 0.5), key=len)``
    (None where there is no contour): the same points, in the same order, bit for bit.

    skimage adds each square's segments in raster order and chains them in a dictionary walk;
    in a binary image every edge midpoint is on exactly one closed loop (the padding closes them
    all), so the chaining is a permutation of the segments (each one's successor starts where it
    ends) and what it returns follows from it: the loops in the order of their first segment,
    each starting (and ending again) at the end of its last segment, then along the segments.
    """
    h, w = mask.shape[0] + 2, mask.shape[1] + 2
    m = np.zeros((h, w), dtype=bool)
    m[1:-1, 1:-1] = mask
    code = (m[:-1, :-1].astype(np.uint8) << 3) | (m[:-1, 1:].astype(np.uint8) << 2) \
        | (m[1:, :-1].astype(np.uint8) << 1) | m[1:, 1:].astype(np.uint8)
    cells = np.flatnonzero((code != 0) & (code != 15))
    if cells.size == 0:
        return None
    c = code.reshape(-1)[cells]
    q2 = 2 * (cells // (w - 1) * w + cells % (w - 1))  # twice the squares' flat vertex index
    f1, t1, f2, t2 = _ms_offsets(w)
    two = (c == 6) | (c == 9)
    count = 1 + two.astype(np.int64)
    first = np.cumsum(count) - count  # each square's first segment, in skimage's order
    n = int(count.sum())
    frm = np.empty(n, dtype=np.int64)
    to = np.empty(n, dtype=np.int64)
    frm[first] = q2 + f1[c]
    to[first] = q2 + t1[c]
    frm[first[two] + 1] = q2[two] + f2[c[two]]
    to[first[two] + 1] = q2[two] + t2[c[two]]
    # The successor of each segment: the one that starts where it ends.
    by_start = np.argsort(frm)
    nxt = by_start[np.searchsorted(frm[by_start], to)]
    # Each loop's first segment, by pointer jumping: after step k every segment holds the
    # smallest index among the 2**k segments from it on; once 2**k reaches the loop's length,
    # its loop's smallest. No loop is longer than all n segments: ceil(log2(n)) steps.
    loop = np.arange(n, dtype=np.intp)
    jump = nxt
    for _ in range(_doublings(n)):
        loop = np.minimum(loop, loop[jump])
        jump = jump[jump]
    sizes = np.bincount(loop, minlength=n)
    # The longest loop; of equal ones the first (skimage's list is in the order of their first
    # segments, and ``max`` keeps the first of equals).
    best = int(np.argmax(sizes))
    members = np.flatnonzero(loop == best)
    last = int(members[-1])
    # From the end of the loop's last segment round along the successors, back to it.
    order = np.empty(members.size + 1, dtype=np.intp)
    order[_loop_ranks(nxt, members, last)] = members
    order[-1] = last
    ids = to[order]
    # An id back to its point: a row's edge (even) is (row, col + 0.5), a column's (odd) is
    # (row + 0.5, col).
    vertex, down = divmod_int(ids, 2)
    rows, cols = divmod_int(vertex, w)
    out = np.empty((ids.size, 2), dtype=np.float64)
    out[:, 0] = rows + 0.5 * down
    out[:, 1] = cols + 0.5 * (1 - down)
    return out
