"""The clear width of a labelled IPA doorway is measured in the map, from jamb to jamb, not from
the blob painted over it (langnav.eval.segmentation.doorway_clear_width_m)."""

from __future__ import annotations

import numpy as np
import pytest

from langnav.eval.segmentation import doorway_clear_width_m

RES_M = 0.05


def wall_with_gap(gap_px: int) -> np.ndarray:
    """A 60 x 60 px map with a vertical wall 5 px thick down its middle and a ``gap_px`` gap in
    it centred on row 30 (image orientation)."""
    occ = np.zeros((60, 60), dtype=bool)
    occ[:, 28:33] = True
    top = 30 - gap_px // 2
    occ[top:top + gap_px, 28:33] = False
    return occ


def blob_around(r0: int, r1: int, c0: int, c1: int) -> np.ndarray:
    rr, cc = np.mgrid[r0:r1, c0:c1]
    return np.column_stack([rr.ravel(), cc.ravel()]).astype(np.int64)


@pytest.mark.parametrize("gap_px", [6, 7, 18])
def test_the_clear_width_is_the_gap_between_the_jambs_not_the_painted_blob(gap_px: int) -> None:
    occ = wall_with_gap(gap_px)
    # A blob painted well past the jambs (as the IPA labels are): 22 x 16 px, 1.1 m long.
    blob = blob_around(19, 41, 23, 39)
    assert doorway_clear_width_m(blob, occ, RES_M) == pytest.approx(gap_px * RES_M)


def test_furniture_beside_a_doorway_is_no_jamb() -> None:
    """A round table standing in the room beside the door is nearer than the far jamb, and as
    big as a wall stub within the blob: the jambs are the walls the doorway is cut in."""
    occ = wall_with_gap(20)  # 1.0 m
    yy, xx = np.mgrid[0:60, 0:60]
    occ |= (yy - 22) ** 2 + (xx - 38) ** 2 <= 16  # a table 0.4 m across, 1 px from the blob
    blob = blob_around(19, 41, 25, 35)
    assert doorway_clear_width_m(blob, occ, RES_M) == pytest.approx(1.0)


def test_an_opening_with_one_jamb_has_no_clear_width() -> None:
    occ = np.zeros((60, 60), dtype=bool)
    occ[:20, 28:33] = True  # a wall ending in open floor
    assert doorway_clear_width_m(blob_around(18, 40, 24, 37), occ, RES_M) is None
