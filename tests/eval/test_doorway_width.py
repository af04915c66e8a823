"""The clear width of a labelled IPA doorway is measured in the map, from jamb to jamb, not from
the blob painted over it (langnav.eval.segmentation.doorway_clear_width_m)."""

from __future__ import annotations

import numpy as np
import pytest

from langnav.eval.segmentation import doorway_clear_width_m, ipa_doorways

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


def test_a_blob_over_two_doors_side_by_side_is_two_doorways() -> None:
    """office_h paints one blob over two office doors parted by the wall between the offices:
    each opening is a doorway of its own, with its own clear width and the blob's pixels
    nearest to it."""
    occ = np.zeros((60, 80), dtype=bool)
    occ[28:33, :] = True  # the corridor's wall, 5 px thick, along row 30
    occ[28:33, 20:38] = False  # a 0.9 m door ...
    occ[28:33, 42:60] = False  # ... and another, 4 px of wall between them
    occ[33:, 38:42] = True  # the wall parting the two offices
    blob = blob_around(22, 38, 16, 64)
    doors = ipa_doorways([blob], occ, RES_M)
    assert [d.clear_width_m for d in doors] == [pytest.approx(0.9), pytest.approx(0.9)]
    assert sum(len(d.pixels) for d in doors) == len(blob)
    assert doors[0].pixels[:, 1].max() < doors[1].pixels[:, 1].min()


def test_a_door_with_a_broken_jamb_is_one_doorway() -> None:
    """A jamb scanned in two pieces (a crack across the wall) leaves one opening: the crossings
    of it have floor between them, not wall."""
    occ = wall_with_gap(18)
    occ[10, 28:33] = False  # a crack through the wall well above the door, inside the window
    occ[38, 28:33] = False  # ... and one below
    doors = ipa_doorways([blob_around(8, 52, 22, 38)], occ, RES_M)
    assert len(doors) == 1
    assert doors[0].clear_width_m == pytest.approx(0.9)
