"""The segmentation's basins are flooded in the floor's bounding box: exactly the flood of the
whole grid (the same labels cell for cell), ties and plateaus included."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from scipy import ndimage as ndi
from skimage.segmentation import watershed

from langnav.analysis.precompute import EIGHT, edt_scaled, maximum3
from langnav.analysis.seg_core import basins


def _whole_grid_flood(clearance_m: npt.NDArray[np.float64], floor: npt.NDArray[np.bool_],
                      min_peak_m: float) -> npt.NDArray[np.int32]:
    peaks = (clearance_m >= maximum3(clearance_m)) & floor & (clearance_m >= min_peak_m)
    markers, _ = ndi.label(peaks, structure=EIGHT)
    return np.asarray(watershed(-clearance_m, markers, mask=floor), dtype=np.int32)


@settings(max_examples=150, deadline=None)
@given(arrays(np.bool_, st.tuples(st.integers(1, 20), st.integers(1, 20))),
       st.tuples(st.integers(0, 6), st.integers(0, 6), st.integers(0, 6), st.integers(0, 6)),
       st.sampled_from([0.0, 0.05, 0.1]))
def test_basins_in_the_floors_box_are_the_whole_grids(inner: npt.NDArray[np.bool_],
                                                       margins: tuple[int, int, int, int],
                                                       min_peak_m: float) -> None:
    top, bottom, left, right = margins
    floor = np.pad(inner, ((top, bottom), (left, right)))
    clearance = edt_scaled(floor, 0.05)
    got = basins(clearance, floor, min_peak_m)
    assert got.dtype == np.int32
    np.testing.assert_array_equal(got, _whole_grid_flood(clearance, floor, min_peak_m))


def test_basins_of_a_grid_without_floor_are_empty() -> None:
    floor = np.zeros((5, 7), dtype=bool)
    np.testing.assert_array_equal(basins(np.zeros((5, 7)), floor, 0.1), np.zeros((5, 7), dtype=np.int32))


def test_two_rooms_joined_by_a_doorway_are_two_basins() -> None:
    floor = np.zeros((14, 24), dtype=bool)
    floor[2:12, 2:11] = True  # a room 9 cells wide ...
    floor[2:12, 13:22] = True  # ... another beside it ...
    floor[6:8, 11:13] = True  # ... and a doorway 2 cells wide between them
    got = basins(edt_scaled(floor, 0.05), floor, 0.1)
    assert set(np.unique(got[2:12, 2:11])) == {1}
    assert set(np.unique(got[2:12, 13:22])) == {2}
    assert not got[~floor].any()
