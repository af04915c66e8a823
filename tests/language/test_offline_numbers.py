"""Numbers and units: digits, words, fractions, metric and imperial lengths, angles and turns."""

from __future__ import annotations

import math

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from langnav.language.offline.numbers import QuantityKind, find_quantities, number_value

ONES = ["zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven",
        "twelve", "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen"]
TENS = ["", "", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety"]
LENGTH_UNITS = {"m": 1.0, "meters": 1.0, "metres": 1.0, "meter": 1.0, "cm": 0.01, "centimetres": 0.01,
                "centimeters": 0.01, "mm": 0.001, "millimetres": 0.001, "ft": 0.3048, "feet": 0.3048,
                "inches": 0.0254}
ANGLE_UNITS = ["degrees", "degree", "deg", "°"]


def to_words(n: int, hyphen: bool = True) -> str:
    """English words for 0..99 ("twenty-five" or "twenty five")."""
    if n < 20:
        return ONES[n]
    tens, ones = divmod(n, 10)
    if ones == 0:
        return TENS[tens]
    return f"{TENS[tens]}{'-' if hyphen else ' '}{ONES[ones]}"


def single(text: str) -> tuple[QuantityKind, float, str]:
    found = find_quantities(text)
    assert len(found) == 1, (text, found)
    q = found[0]
    return q.kind, q.value, text[q.start:q.end]


@given(st.integers(min_value=0, max_value=99), st.booleans())
def test_number_words_up_to_ninety_nine(n: int, hyphen: bool) -> None:
    assert number_value(to_words(n, hyphen)) == n


@given(st.integers(min_value=1, max_value=99), st.sampled_from(sorted(LENGTH_UNITS)), st.booleans())
@example(n=21, unit="centimeters", hyphen=True)  # "twenty-one" is no range "twenty to one"
def test_word_lengths_in_metres(n: int, unit: str, hyphen: bool) -> None:
    kind, value, _ = single(f"move forward {to_words(n, hyphen)} {unit} please")
    assert kind == QuantityKind.LENGTH
    assert value == pytest.approx(n * LENGTH_UNITS[unit])


@given(st.decimals(min_value="0.01", max_value="99.99", places=2), st.sampled_from(sorted(LENGTH_UNITS)),
       st.sampled_from(["", " "]))
def test_decimal_lengths_with_or_without_space(x: object, unit: str, space: str) -> None:
    text = f"go {x}{space}{unit} forward"
    kind, value, span = single(text)
    assert kind == QuantityKind.LENGTH
    assert value == pytest.approx(float(str(x)) * LENGTH_UNITS[unit])
    assert span == f"{x}{space}{unit}"


@given(st.integers(min_value=1, max_value=360), st.sampled_from(ANGLE_UNITS))
def test_angles_in_degrees(n: int, unit: str) -> None:
    kind, value, _ = single(f"turn left {n} {unit}")
    assert (kind, value) == (QuantityKind.ANGLE, n)


@given(st.integers(min_value=1, max_value=9), st.sampled_from(["half", "quarter"]))
def test_and_a_fraction(n: int, frac: str) -> None:
    kind, value, _ = single(f"move {to_words(n)} and a {frac} metres")
    assert kind == QuantityKind.LENGTH
    assert value == pytest.approx(n + (0.5 if frac == "half" else 0.25))


@pytest.mark.parametrize(("text", "kind", "value"), [
    ("half a meter", QuantityKind.LENGTH, 0.5),
    ("half a metre", QuantityKind.LENGTH, 0.5),
    ("a half meter", QuantityKind.LENGTH, 0.5),
    ("a quarter of a metre", QuantityKind.LENGTH, 0.25),
    ("three quarters of a meter", QuantityKind.LENGTH, 0.75),
    ("a meter", QuantityKind.LENGTH, 1.0),
    ("a metre and a half", QuantityKind.LENGTH, 1.5),
    ("one and a half meters", QuantityKind.LENGTH, 1.5),
    ("1 1/2 m", QuantityKind.LENGTH, 1.5),
    ("1/2 m", QuantityKind.LENGTH, 0.5),
    ("two point five meters", QuantityKind.LENGTH, 2.5),
    ("a couple of meters", QuantityKind.LENGTH, 2.0),
    ("60 cm", QuantityKind.LENGTH, 0.6),
    ("600 mm", QuantityKind.LENGTH, 0.6),
    ("3 feet", QuantityKind.LENGTH, 0.9144),
    ("a foot", QuantityKind.LENGTH, 0.3048),
    ("10 inches", QuantityKind.LENGTH, 0.254),
    ("a hundred degrees", QuantityKind.ANGLE, 100.0),
    ("one hundred and eighty degrees", QuantityKind.ANGLE, 180.0),
    ("ninety deg", QuantityKind.ANGLE, 90.0),
    ("a quarter turn", QuantityKind.ANGLE, 90.0),
    ("half a turn", QuantityKind.ANGLE, 180.0),
    ("a half turn", QuantityKind.ANGLE, 180.0),
    ("a full turn", QuantityKind.ANGLE, 360.0),
    ("a complete rotation", QuantityKind.ANGLE, 360.0),
    ("two full turns", QuantityKind.ANGLE, 720.0),
    ("three quarter turn", QuantityKind.ANGLE, 270.0),
    ("3/4 of a turn", QuantityKind.ANGLE, 270.0),
    ("pi/2 radians", QuantityKind.ANGLE, 90.0),
    ("pi radians", QuantityKind.ANGLE, 180.0),
    ("1.5 rad", QuantityKind.ANGLE, math.degrees(1.5)),
    ("45", QuantityKind.BARE, 45.0),
    ("twenty", QuantityKind.BARE, 20.0),
])
def test_quantity_forms(text: str, kind: QuantityKind, value: float) -> None:
    got_kind, got_value, span = single(text)
    assert got_kind == kind
    assert got_value == pytest.approx(value)
    assert span == text


def test_vague_counts_are_flagged_approximate() -> None:
    (q,) = find_quantities("move a few meters forward")
    assert (q.kind, q.value, q.approximate) == (QuantityKind.LENGTH, 3.0, True)


def test_several_quantities_in_order() -> None:
    found = find_quantities("move 2 m then turn 30 degrees and 50 cm")
    assert [(q.kind, round(q.value, 3)) for q in found] == [
        (QuantityKind.LENGTH, 2.0), (QuantityKind.ANGLE, 30.0), (QuantityKind.LENGTH, 0.5)]


@pytest.mark.parametrize("text", ["the 2nd door", "the second one", "go to the door", "turn left"])
def test_ordinals_and_plain_words_are_not_quantities(text: str) -> None:
    kinds = [q.kind for q in find_quantities(text)]
    assert QuantityKind.LENGTH not in kinds and QuantityKind.ANGLE not in kinds
    if text != "the second one":
        assert kinds == []


@pytest.mark.parametrize("text", ["", "meters", "banana", "two bananas"])
def test_number_value_rejects_non_numbers(text: str) -> None:
    with pytest.raises(ValueError):
        number_value(text)


def test_zero_denominator_is_an_error() -> None:
    with pytest.raises(ValueError, match="zero"):
        number_value("1/0")
