"""Two hallways meeting (issue 8, langnav.analysis.door_judge.hallways_meet): an opening between
two corridors as wide as one of them is where they meet, not a door (a care home's corridor
running into another at its full width, next to a room's wide opening that made the place
beyond it read wide, was a door); a door between two corridors stands in a frame narrower than
both. Exact cases, in metres: the opening's width and the two hallways' typical widths."""

from __future__ import annotations

import pytest

from langnav.analysis.door_judge import WIDEN_FACTOR, WIDEN_MIN_M, hallways_meet


@pytest.mark.parametrize(
    ("width_m", "hallways_m"),
    [
        (1.75, (1.9, 1.9)),  # a corridor's mouth, a speck at one side of it
        (1.95, (2.1, 1.9)),  # a corridor running into another at a T
        (1.9, (1.9, 3.0)),  # a corridor's mouth at exactly its width
        (1.2, (1.35, 4.0)),  # a narrow corridor's mouth on a wide one: within scan noise of its width
    ],
)
def test_an_opening_as_wide_as_a_corridor_is_where_it_meets_the_other(width_m: float,
                                                                      hallways_m: tuple[float, float]) -> None:
    assert hallways_meet(width_m, hallways_m)


@pytest.mark.parametrize(
    ("width_m", "hallways_m"),
    [
        (0.97, (2.45, 1.35)),  # a ward corridor's door onto the stem corridor
        (0.78, (1.63, 1.72)),  # a hotel's corridor door
        (1.15, (2.3, 2.9)),  # a police station's corridor door
        (1.6, (2.2, 2.4)),  # a fire door's double leaves across a corridor, in their frame
    ],
)
def test_a_door_between_two_corridors_is_narrower_than_both(width_m: float, hallways_m: tuple[float, float]) -> None:
    assert not hallways_meet(width_m, hallways_m)


def test_the_bound_is_a_doors_own_widening() -> None:
    """Narrower than the narrower hallway by exactly a door's widening: still where they meet;
    a centimetre more: a door."""
    w = 1.0
    limit = max(w * WIDEN_FACTOR, w + WIDEN_MIN_M)
    assert hallways_meet(w, (limit, 3.0))
    assert not hallways_meet(w, (limit + 0.01, 3.0))
