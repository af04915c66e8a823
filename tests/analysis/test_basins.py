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
from langnav.analysis.seg_core import basins, distinct_openings, wall_with_doors


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


def test_one_doorway_met_as_several_saddles_is_one_opening() -> None:
    """The flood meets a 1.8 m door as three saddles a few cells apart (more basins touch it on
    a fine grid): one opening; a door 3 m along the same wall is another."""
    width, res = 1000, 0.025
    def at(r: int, c: int) -> int:
        return r * width + c

    seen = [(0.9, at(100, 200)), (0.6, at(103, 204)), (0.4, at(98, 197)), (0.45, at(100, 320))]
    got = distinct_openings(seen, width, res)
    assert sorted(got) == [(0.45, at(100, 320)), (0.9, at(100, 200))]


def test_doors_in_a_mostly_solid_wall_are_no_row_of_clutter() -> None:
    width, res = 1000, 0.05
    def at(r: int, c: int) -> int:
        return r * width + c

    # Three doors (0.9, 1.8, 0.9 m) along a 12 m wall: open for 3.6 m of about 11 m.
    doors = [(0.45, at(30, 100)), (0.9, at(130, 100)), (0.45, at(230, 100))]
    assert wall_with_doors(doors, width, res)
    # A row of shelf units 1.2 m long with 1 m gaps between them: open about as much as solid.
    gaps = [(0.5, at(20, 100 + 44 * k)) for k in range(5)]
    assert not wall_with_doors(gaps, width, res)
    # Openings scattered over the floor (around desks) lie on no line.
    scattered = [(0.45, at(30, 100)), (0.45, at(130, 160)), (0.45, at(60, 260))]
    assert not wall_with_doors(scattered, width, res)
    assert not wall_with_doors(doors[:1], width, res)
