"""The line-number tables of wall_lines (the coarse directions, and the refinements about a peak)
give exactly the scores they stand in for."""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from langnav.analysis import wall_lines
from langnav.analysis.wall_lines import LINE_TABLE_SIDE, dominant_directions

SHAPES = st.tuples(st.integers(2, LINE_TABLE_SIDE), st.integers(2, LINE_TABLE_SIDE))


@settings(max_examples=60, deadline=None)
@given(SHAPES.flatmap(lambda s: arrays(np.bool_, s, elements=st.booleans())), st.integers(1, 12))
def test_table_scores_match_line_scores(m: npt.NDArray[np.bool_], keep_one_in: int) -> None:
    # Sparse masks, as walls are: every keep_one_in-th cell of a random mask.
    m = m & (np.arange(m.size).reshape(m.shape) % keep_one_in == 0)
    rr, cc = np.nonzero(m)
    if rr.size < 2:
        return
    expected = wall_lines._line_scores(rr.astype(np.float64), -cc.astype(np.float64),
                                       np.arange(0.0, 90.0, wall_lines.DIRECTION_BIN_DEG))
    got = wall_lines._coarse_scores(rr, cc)
    assert got.dtype == expected.dtype and np.array_equal(got, expected)


@settings(max_examples=60, deadline=None)
@given(SHAPES.flatmap(lambda s: arrays(np.bool_, s, elements=st.booleans())), st.integers(1, 12),
       st.lists(st.integers(0, 89), min_size=1, max_size=2 * wall_lines.FINE_TABLES_KEPT))
def test_fine_table_scores_match_line_scores(m: npt.NDArray[np.bool_], keep_one_in: int, peaks: list[int]) -> None:
    # More peaks than tables are kept: tables are dropped and made again on the way.
    m = m & (np.arange(m.size).reshape(m.shape) % keep_one_in == 0)
    rr, cc = np.nonzero(m)
    if rr.size < 2:
        return
    for p in peaks:
        fine = np.arange(0.0, 90.0, wall_lines.DIRECTION_BIN_DEG)[p] + np.linspace(
            -wall_lines.DIRECTION_BIN_DEG, wall_lines.DIRECTION_BIN_DEG, 21)
        expected = wall_lines._line_scores(rr.astype(np.float64), -cc.astype(np.float64), fine)
        got = wall_lines._fine_scores(p, rr, cc)
        assert got.dtype == expected.dtype and np.array_equal(got, expected)
    assert len(wall_lines._fine_tables) <= wall_lines.FINE_TABLES_KEPT


def test_directions_of_a_rotated_room_match_with_and_without_the_table() -> None:
    # A square room's walls drawn at 20 degrees, in a window the table covers.
    side = 100
    m = np.zeros((side, side), dtype=bool)
    t = math.radians(20.0)
    for s in np.linspace(-30.0, 30.0, 400).tolist():
        for a, b in ((s, -30.0), (s, 30.0), (-30.0, s), (30.0, s)):
            m[round(50 + a * math.sin(t) + b * math.cos(t)), round(50 + a * math.cos(t) - b * math.sin(t))] = True
    with_table = dominant_directions(m)
    old = wall_lines.LINE_TABLE_SIDE
    wall_lines.LINE_TABLE_SIDE = 0  # type: ignore[misc]
    try:
        without = dominant_directions(m)
    finally:
        wall_lines.LINE_TABLE_SIDE = old  # type: ignore[misc]
    assert with_table == without
    assert abs(np.degrees(with_table[0]) % 90.0 - 70.0) < 1.0 or abs(np.degrees(with_table[0]) % 90.0 - 20.0) < 1.0
