"""Numbers and units in prompts: "1.5 m", "sixty centimetres", "half a meter", "a quarter turn", "90°".

:func:`find_quantities` returns every distance (in metres), angle (in degrees) and bare number in a
normalised (lower-case) clause, with its character span so the caller can mark the words as read.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace
from enum import StrEnum
from typing import Final

from langnav.language.offline.lexicon import phrase_regex

# ------------------------------------------------------------------------------ number words
ONES: Final[dict[str, int]] = {
    "zero": 0, "nought": 0, "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7,
    "eight": 8, "nine": 9, "ten": 10, "eleven": 11, "twelve": 12, "thirteen": 13, "fourteen": 14,
    "fifteen": 15, "sixteen": 16, "seventeen": 17, "eighteen": 18, "nineteen": 19,
}
TENS: Final[dict[str, int]] = {
    "twenty": 20, "thirty": 30, "forty": 40, "fourty": 40, "fifty": 50, "sixty": 60, "seventy": 70,
    "eighty": 80, "ninety": 90,
}
#: Every number word said as one word ("seven", "fifteen", "ninety"), longest first: the one pattern
#: that every stage looking for a number said in words uses (restarts, corrections, the splitter's
#: "and", durations, turn counts, labels), so that each knows the same words as the number reading.
NUMBER_WORDS: Final = "|".join(sorted((w for w in (*ONES, *TENS) if (ONES | TENS)[w] > 0), key=len, reverse=True))
#: The same words as a tuple, with "hundred": the words a cut-off word ("fi-", "hun-") may start.
NUMBER_WORD_LIST: Final = (*sorted((w for w in (*ONES, *TENS) if (ONES | TENS)[w] > 0), key=len, reverse=True),
                           "hundred")
#: "and a half", "one half", "a quarter of a": the fraction each word names.
FRACTIONS: Final[dict[str, float]] = {"half": 0.5, "quarter": 0.25, "third": 1 / 3,
                                      "three quarters": 0.75, "three quarter": 0.75,
                                      "two thirds": 2 / 3}
#: Vague counts: "a couple of metres" is two; "a few metres" about three (flagged approximate).
VAGUE_COUNTS: Final[dict[str, tuple[float, bool]]] = {
    "a couple of": (2.0, False), "a couple": (2.0, False), "couple of": (2.0, False),
    "a pair of": (2.0, False), "a few": (3.0, True), "few": (3.0, True), "several": (3.0, True),
    "some": (2.0, True),
}

#: Length units in metres.
LENGTH_UNITS_M: Final[dict[str, float]] = {
    **dict.fromkeys(("m", "meter", "meters", "metre", "metres", "mtr", "mtrs", "meter's", "metres's",
                     "mt", "mts", "ms"), 1.0),
    **dict.fromkeys(("cm", "cms", "centimeter", "centimeters", "centimetre", "centimetres", "centi meters"),
                    0.01),
    **dict.fromkeys(("mm", "millimeter", "millimeters", "millimetre", "millimetres"), 0.001),
    **dict.fromkeys(("dm", "decimeter", "decimeters", "decimetre", "decimetres"), 0.1),
    # the plurals learners and fast typists write ("5 feets", "two inchs") are the same units
    **dict.fromkeys(("ft", "foot", "feet", "'", "feets", "foots", "fts"), 0.3048),
    **dict.fromkeys(("inch", "inches", '"', "ins", "inchs", "inche"), 0.0254),
    **dict.fromkeys(("yard", "yards", "yd", "yds", "yardss"), 0.9144),
}
#: A number said after feet without a unit is inches when it is below this ("5 foot 6").
INCHES_PER_FOOT: Final = 12
#: A number said after metres without a unit is centimetres when it is below this ("1 m 20").
CENTIMETRES_PER_METRE: Final = 100

#: Angle units in degrees.
ANGLE_UNITS_DEG: Final[dict[str, float]] = {
    **dict.fromkeys(("degree", "degrees", "deg", "degs", "°", "º", "dgr", "degreess"), 1.0),
    **dict.fromkeys(("rad", "rads", "radian", "radians"), math.degrees(1.0)),
}
#: Nouns of a whole rotation: "a quarter turn", "two full turns".
TURN_NOUNS: Final = ("turn", "turns", "rotation", "rotations", "revolution", "revolutions", "circle",
                     "circles", "spin", "spins", "twirl", "pirouette")
WHOLE_TURN_WORDS: Final = ("full", "complete", "whole", "entire", "360", "360 degree", "360-degree")

_ONE_TO_NINE: Final = "one|two|three|four|five|six|seven|eight|nine"
_TENS_WORDS: Final = "|".join(t for t in TENS if t != "fourty") + "|fourty"
_TEENS_WORDS: Final = "ten|eleven|twelve|thirteen|fourteen|fifteen|sixteen|seventeen|eighteen|nineteen"
#: "one eighty", "two twenty five", "three sixty", "three fifteen", "one oh five": spoken hundreds, a
#: digit word then a two-digit number said as tens, as a teen, or as "oh" and a digit.
_SPOKEN_HUNDREDS: Final = (rf"(?:{_ONE_TO_NINE})[\s-]+(?:(?:{_TENS_WORDS})(?:[\s-]+(?:{_ONE_TO_NINE}))?|(?:{_TEENS_WORDS})"
                           rf"|(?:oh|o|zero)[\s-]+(?:{_ONE_TO_NINE}))")
_WORD_INT: Final = (rf"(?:{_SPOKEN_HUNDREDS}|(?:{_TENS_WORDS})(?:[\s-]+(?:{_ONE_TO_NINE}))?"
                    rf"|{'|'.join(sorted(ONES, key=len, reverse=True))})")
_HUNDREDS: Final = (rf"(?:(?:a|one|two|three|four|five|six|seven|eight|nine)\s+)?hundred"
                    rf"(?:\s+(?:and\s+)?{_WORD_INT})?")
_DIGIT_WORD: Final = "zero|oh|one|two|three|four|five|six|seven|eight|nine"
#: "point seven five" (the "nought" / "zero" before the point left unsaid, as people say a decimal below one)
#: is 0.75, never 75 or 5: the words after "point" are the decimals whether or not a whole part was said.
_WORD_NUM: Final = (rf"(?:(?:{_HUNDREDS}|{_WORD_INT})(?:\s+point(?:\s+(?:{_DIGIT_WORD}))+)?"
                    rf"|(?<![\w-])point(?:\s+(?:{_DIGIT_WORD}))+)")
_DIGIT_NUM: Final = r"(?:\d+\s+\d+\s*/\s*\d+|\d+\s*/\s*\d+|\d+(?:\.\d+)?|\.\d+)"
_AND_FRACTION: Final = r"(?:\s+and\s+(?:a\s+|one\s+)?(?:half|quarter|third|three\s+quarters?))"
#: One number, in digits or words, with an optional "and a half".
NUMBER: Final = rf"(?:{_DIGIT_NUM}|{_WORD_NUM}){_AND_FRACTION}?"
_VAGUE: Final = phrase_regex(VAGUE_COUNTS)
_LEAD_FRACTION: Final = (r"(?:(?:a|one)\s+)?(?:half|quarter|third|three\s+quarters?|two\s+thirds)"
                         r"(?:\s+of)?(?:\s+(?:a|an|one))?")


#: Words between an amount and its unit that only say it adds to what was done ("two more feet",
#: "forty five further degrees"): the amount is the same.
_MORE: Final = r"(?:more|further|additional|extra|other|another)"
#: Words before an amount that say it adds to what was done, or that it is roughly said ("another
#: two feet", "a further three metres", "an extra 20 cm", "around five feet", "about another
#: foot"): the amount is the number said.
_AMOUNT_LEAD: Final = (r"(?:(?:another|a\s+further|an?\s+additional|an?\s+extra|further|additional|extra|"
                       r"around|about|roughly|approximately|approx|circa|some|nearly|almost|like)\s+){0,2}")
#: Words after an amount that say it adds to what was done ("five feet more", "ten degrees further").
_AMOUNT_TAIL: Final = r"(?:\s+(?:more|further|extra|again))?"


#: "N turns" with N at least this is N degrees ("a one eighty turn"); nobody asks for 30 whole turns.
DEGREES_NOT_TURNS_MIN: Final = 30.0


class QuantityKind(StrEnum):
    LENGTH = "length"   # value in metres
    ANGLE = "angle"     # value in degrees
    BARE = "bare"       # a number with no unit: its meaning depends on the verb


@dataclass(frozen=True)
class Quantity:
    kind: QuantityKind
    value: float
    start: int
    end: int
    approximate: bool = False
    #: the size of the unit it was said in (metres or degrees; 0 for a compound, a turn or a bare
    #: number): "two feet and six inches" is one amount because inches are smaller than feet
    unit: float = 0.0
    #: said as more than what came before ("two more metres", "another foot"): it adds to it
    adds: bool = False
    #: said as another way of giving the amount before it ("2 metres or 6 feet"): one of the two
    alternative: bool = False


#: Between two amounts: the second is another way of saying the first ("2 metres or 6 feet").
_OR_BEFORE: Final = re.compile(r"^\s*,?\s*(?:or|maybe|perhaps|possibly|or\s+(?:about|around|roughly|maybe|perhaps|like|so))"
                               r"(?:\s+(?:about|around|roughly|like))?\s*,?\s*$")
_ADDS_RE: Final = re.compile(r"\b(?:more|another|further|additional|extra)\b")

#: Two amounts closer than this are the same amount (a millimetre, a hundredth of a degree).
SAME_AMOUNT_TOL: Final = 1e-3


def one_amount(quantities: list[Quantity]) -> float | None:
    """The one amount several quantities of a kind in one instruction say, or None when they disagree.

    English says a compound measure largest unit first ("two feet and six inches", "one metre twenty
    centimetres", "a yard and a foot"): each part in a smaller unit than the one before adds to it.
    The same amount said again, in any unit ("a full spin, three sixty"; "two hundred centimetres,
    that's two metres") is that amount once: adding it would take the robot farther than asked.
    An amount said to be more ("4 feet, then two more metres") adds to the one before; one said as
    another way of giving it ("2 metres or 6 feet") is the smaller of the two.
    Anything else (two different amounts in the same unit, or a larger unit after a smaller one)
    is no reading of one amount: the caller asks which one was meant."""
    if not quantities:
        return None
    total = quantities[0].value
    unit = quantities[0].unit
    for q in quantities[1:]:
        if q.alternative:
            total = min(total, q.value)  # "2 metres or 6 feet": never farther than either
            unit = q.unit
            continue
        if q.adds:
            total += q.value  # "go 4 feet, two more metres"
            continue
        if abs(q.value - total) <= SAME_AMOUNT_TOL or abs(q.value - quantities[0].value) <= SAME_AMOUNT_TOL:
            continue  # said again
        if unit > 0 and 0 < q.unit < unit and q.value < unit - SAME_AMOUNT_TOL:
            # (a part of a compound is less than one of the unit before it: "two feet twelve inches" is none)
            total += q.value
            unit = q.unit
            continue
        return None
    return total


def _unit_regex(units: dict[str, float]) -> str:
    ordered = sorted(units, key=len, reverse=True)
    alts = []
    for u in ordered:
        esc = r"\s+".join(re.escape(w) for w in u.split())
        alts.append(esc + (r"(?![\w'])" if u[-1].isalnum() else ""))
    return "(?:" + "|".join(alts) + ")"


_LENGTH_UNIT: Final = _unit_regex(LENGTH_UNITS_M)
_ANGLE_UNIT: Final = _unit_regex(ANGLE_UNITS_DEG)
_TURN_NOUN: Final = rf"(?:{'|'.join(TURN_NOUNS)})(?![\w])"
_B: Final = r"(?<![\w.])"  # a number starts at a word boundary, not inside "1.5" or "x2"
_E: Final = r"(?![\w.]*\w)"

_UNIT_PATTERNS: Final[tuple[tuple[QuantityKind, re.Pattern[str]], ...]] = (
    # "a metre and a half", "a meter", "an inch", "another metre", "one more foot"
    *((kind, re.compile(rf"{_B}{_AMOUNT_LEAD}(?P<lead>a|an|one|another)\s+(?:(?:single|{_MORE})\s+)?(?P<unit>{unit})"
                        rf"(?P<tail>\s+and\s+(?:a\s+)?(?:half|quarter))?{_AMOUNT_TAIL}"))
      for kind, unit in ((QuantityKind.LENGTH, _LENGTH_UNIT), (QuantityKind.ANGLE, _ANGLE_UNIT))),
    # "half a meter", "a quarter of a metre", "three quarters of a meter"
    *((kind, re.compile(rf"{_B}{_AMOUNT_LEAD}(?P<frac>{_LEAD_FRACTION})\s*(?P<unit>{unit}){_AMOUNT_TAIL}"))
      for kind, unit in ((QuantityKind.LENGTH, _LENGTH_UNIT), (QuantityKind.ANGLE, _ANGLE_UNIT))),
    # "2 metres", "1.5m", "sixty centimetres", "two and a half meters", "a couple of meters",
    # "two more feet", "forty five more degrees"; "three or four feet" (a range: the smaller counts)
    *((kind, re.compile(rf"{_B}{_AMOUNT_LEAD}(?:(?P<low>{NUMBER})\s+(?:or|to)\s+|(?P<low_digits>\d+(?:\.\d+)?)\s*-\s*(?=\d))?"
                        rf"(?P<num>{NUMBER}|{_VAGUE})"
                        rf"(?:\s+{_MORE})?\s*-?\s*(?P<unit>{unit})"
                        rf"(?P<tail>\s+and\s+(?:a\s+)?(?:half|quarter))?{_AMOUNT_TAIL}"))
      for kind, unit in ((QuantityKind.LENGTH, _LENGTH_UNIT), (QuantityKind.ANGLE, _ANGLE_UNIT))),
)
#: "pi/2 radians", "pi radians", "half pi"
_PI_PATTERN: Final = re.compile(
    r"(?<!\w)(?:(?P<mul>\d+(?:\.\d+)?|half(?:\s+of)?|a\s+half|quarter)\s*(?:\*\s*)?)?(?:pi|π)"
    r"(?:\s*/\s*(?P<div>\d+(?:\.\d+)?))?(?:\s*(?:rad|rads|radians?))?(?!\w)")
#: "a quarter turn", "half a turn", "a full turn", "two full turns", "one and a half turns"
_TURN_PATTERN: Final = re.compile(
    rf"(?<!\w)(?:(?P<ratio>\d+\s*/\s*\d+)(?:\s+of)?(?:\s+an?)?|(?P<frac>(?:a|one)\s+quarter|quarter|a\s+half|half\s+(?:a|an|of\s+a)|half|"
    rf"(?:a\s+)?three[\s-]+quarters?(?:\s+of\s+a)?|three[\s-]+quarter"
    # "an eighth of a turn", "a third of a turn", "a quarter of a turn": any share of a whole turn
    rf"|(?:(?:a|an|one)\s+)?(?:eighth|sixth|third|quarter)(?=\s+of\s+(?:a|an|one)\b))(?:\s+of\s+(?:a|an|one))?"
    rf"|(?:(?P<num>{NUMBER})\s+|(?:a|an)\s+)?(?P<whole>(?:{'|'.join(WHOLE_TURN_WORDS)}))"
    rf"|(?P<count>{NUMBER}))"
    rf"[\s-]*(?:full\s+|complete\s+|whole\s+)?(?P<noun>{_TURN_NOUN})")
#: Words after a number that make it no distance or angle ("5 seconds", "3 times").
_NOT_UNITS: Final = (r"(?:seconds?|secs?|minutes?|mins?|hours?|times|steps?|percent|%|x|people|persons?|doors?|"
                     r"o\s*'?\s*clock|oclock)")
_BARE_PATTERN: Final = re.compile(rf"{_B}{_AMOUNT_LEAD}(?P<num>{NUMBER})(?!\s*(?:st|nd|rd|th)\b)(?![\w])(?!\s*{_NOT_UNITS}\b)")
#: "1 m 50", "2 metres 30": metres and centimetres.
_METRES_CENTIMETRES: Final = re.compile(
    rf"(?<![\w.])(?P<m>\d+|{_WORD_INT})\s*(?:m|meters?|metres?)\s+(?:and\s+)?(?P<cm>\d{{1,2}}|{_WORD_INT})"
    rf"(?!\s*(?:cm|mm|m|centimet(?:er|re)s?|millimet(?:er|re)s?|degrees?|deg|inch(?:es|s)?|ins?|feets?|foot|ft|yards?|"
    rf"yds?|\.|\d|{_NOT_UNITS}\b))(?![\w.])")


#: "2 foot 6", "five feet three", "six foot and two": feet and then inches, the inch unit left unsaid.
_FEET_INCHES: Final = re.compile(
    rf"(?<![\w.])(?P<ft>\d+|{_WORD_INT})\s*(?:feet|foot|ft|')\s*(?:and\s+)?(?P<inch>\d{{1,2}}|{_WORD_INT})"
    # the inches' unit may be said too ("5 ft 10 in", "5'10\""); "in" followed by a place is no unit
    r"(?:\s*(?:inch(?:es)?|inchs|\"|ins?(?!\s+(?:the|a|an|front|this|that|your|my|here|there)\b)))?"
    rf"(?!\s*(?:cm|mm|m|meters?|metres?|feet|foot|ft|inch(?:es|s)?|ins?|yards?|yds?|degrees?|deg|\.|\d|"
    rf"{_NOT_UNITS}\b))(?![\w.])")


#: "1e3", "2.5E-1": scientific notation, written out before anything else reads the digits.
_SCIENTIFIC: Final = re.compile(r"(?<![\w.])(?P<mant>\d+(?:\.\d+)?|\.\d+)[eE](?P<exp>[+-]?\d{1,6})(?![\d.])")
#: "1,000", "12,500,000": thousands separated by commas (a decimal comma has one or two digits).
_THOUSANDS: Final = re.compile(r"(?<![\d.,])\d{1,3}(?:,\d{3})+(?![\d,])")
#: Written-out values beyond this are shown as this (they are out of every range anyway).
_HUGE: Final = 1e15
#: "-5 m", "−90 degrees": a minus sign right before a number (not a range such as "2-3 m").
NEGATIVE_NUMBER: Final = re.compile(r"(?<![\w.])[-−–](?=\.?\d)")


#: Digit words as radio operators say numbers, one digit at a time ("one five feet", "rotate left one
#: three five", "two zero feet"); "niner" is the radio's nine, "oh" a zero after another digit.
_DIGIT_VALUES: Final[dict[str, int]] = {**{w: v for w, v in ONES.items() if v <= 9}, "niner": 9}
_DIGIT_RUN_WORD: Final = "|".join(sorted(_DIGIT_VALUES, key=len, reverse=True))
DIGIT_RUN: Final = re.compile(
    rf"(?<!point\s)(?<![\w.,-])(?P<run>(?:{_DIGIT_RUN_WORD})(?:\s+(?:{_DIGIT_RUN_WORD}|oh)){{1,3}})"
    r"(?!\s+(?:point|hundred|thousand|and\s+(?:a\s+)?(?:half|quarter))\b)(?![\w-])", re.IGNORECASE)


#: "door no. 2", "room No.3", "gate nr. 4": "no." / "nr." / "num." before a numeral abbreviates "number"
#: (its dot ends no sentence, and "2 on the right" after it is no turn). Only right after a word
#: naming a thing: after an amount ("80 degrees no. 85") "no" corrects it, and after a comma or a
#: full stop it is the word "no".
_NUMBER_ABBREVIATION: Final = re.compile(r"\b(?P<noun>[a-z]+)\s+(?:no|nr|num)\.\s*(?=\d)", re.IGNORECASE)


def _abbreviation_read(m: re.Match[str]) -> str:
    noun = m.group("noun").lower()
    if noun in LENGTH_UNITS_M or noun in ANGLE_UNITS_DEG or noun in ONES or noun in TENS:
        return m.group(0)
    return f"{m.group('noun')} number "


#: "five-ish feet", "90ish degrees": about that number.
_ISH: Final = re.compile(rf"\b(?P<num>\d+(?:\.\d+)?|{NUMBER_WORDS})[\s-]?ish\b", re.IGNORECASE)


def _digits(m: re.Match[str], said: frozenset[int] = frozenset()) -> str:
    """A run of digit words as the number it spells, when it can only be that number: its digits are
    not one digit said again ("four four": a restart, read there), and two digits one apart ("two
    three feet") may be a range ("two or three feet"), so those stay words (and the reading asks) unless
    the number they spell was said whole in the same prompt ("left turn forty five, that's four five
    degrees left": the radio restatement of 45, no range)."""
    words = m.group("run").lower().split()
    if words[0] in ("oh",) or len(set(words)) == 1:
        return m.group(0)
    if words[0] == words[1]:
        words = words[1:]  # "one one five": a stutter on the first digit, then the number
    values = [0 if w == "oh" else _DIGIT_VALUES[w] for w in words]
    spelled = int("".join(map(str, values))) if values else 0
    if len(values) < 2 or (len(values) == 2 and abs(values[1] - values[0]) == 1 and 0 not in values
                           and spelled not in said):
        return m.group(0)
    return str(spelled)


#: A whole number said in words of two or more ("forty five", "one hundred and twenty") or in digits.
_WHOLE_SAID: Final = re.compile(rf"\b(?:{_TENS_WORDS})[\s-]+(?:{_ONE_TO_NINE})\b|\b(?:{_TENS_WORDS}|{_TEENS_WORDS})\b|\b\d+\b",
                                re.IGNORECASE)


def _numbers_said(text: str) -> frozenset[int]:
    """The whole numbers a prompt says in tens words or digits (what a digit-by-digit restatement may spell)."""
    found: set[int] = set()
    for m in _WHOLE_SAID.finditer(text):
        try:
            found.add(int(number_value(m.group(0))))
        except ValueError:
            continue
    return frozenset(found)


def canonical_numbers(text: str) -> str:
    """Digits in one form before a prompt is split and read: scientific notation written out
    ("1e3" -> "1000", "1e309" -> a huge number, "1e-400" -> "0"), thousands separators
    dropped ("1,000,000" -> "1000000") and numbers said digit by digit written as the number
    ("one three five" -> "135"); "no." before a numeral after a noun is "number" ("door no. 2")."""
    text = _NUMBER_ABBREVIATION.sub(_abbreviation_read, text)
    text = _THOUSANDS.sub(lambda m: m.group(0).replace(",", ""), text)
    text = _ISH.sub(r"about \g<num>", text)
    text = _SCIENTIFIC.sub(_write_out, text)
    said = _numbers_said(text)
    return DIGIT_RUN.sub(lambda m: _digits(m, said), text)


def _write_out(m: re.Match[str]) -> str:
    try:
        value = float(f"{m.group('mant')}e{m.group('exp')}")
    except OverflowError:  # pragma: no cover - float() gives inf rather than raising
        value = math.inf
    if not math.isfinite(value) or value >= _HUGE:
        return f"{_HUGE:.0f}"
    return f"{value:.6f}".rstrip("0").rstrip(".") or "0"


def number_value(text: str) -> float:
    """The value of a number written in digits or words: '1.5', '3/4', 'twenty-five',
    'one hundred and eighty', 'two point five', 'one and a half', 'a couple of'.

    Raises ValueError when the text is not a number."""
    t = " ".join(text.lower().replace("-", " ").split())
    if not t:
        raise ValueError("empty number")
    if t in VAGUE_COUNTS:
        return VAGUE_COUNTS[t][0]
    extra = 0.0
    m = re.fullmatch(r"(?P<head>.+?)\s+and\s+(?:a\s+|one\s+)?(?P<frac>half|quarter|third|three quarters?)", t)
    if m:
        t = m.group("head")
        extra = FRACTIONS[m.group("frac")]
    return _plain_number(t) + extra


def _plain_number(t: str) -> float:
    mixed = re.fullmatch(r"(\d+)\s+(\d+)\s*/\s*(\d+)", t)
    if mixed:
        return int(mixed.group(1)) + _ratio(mixed.group(2), mixed.group(3))
    frac = re.fullmatch(r"(\d+)\s*/\s*(\d+)", t)
    if frac:
        return _ratio(frac.group(1), frac.group(2))
    if re.fullmatch(r"\d+(?:\.\d+)?|\.\d+", t):
        return float(t)
    whole, _, decimals = t.partition(" point ")
    if whole.startswith("point "):  # "point five": no whole part said
        whole, decimals = "zero", whole[len("point "):]
    value = float(_word_integer(whole))
    if decimals:
        digits = "".join(str(ONES.get(w, 0)) for w in decimals.split())
        value += float("0." + digits)
    return value


def _ratio(num: str, den: str) -> float:
    if int(den) == 0:
        raise ValueError(f"'{num}/{den}' divides by zero")
    return int(num) / int(den)


def _word_integer(t: str) -> int:
    words = [w for w in t.split() if w != "and"]
    if not words:
        raise ValueError(f"{t!r} is not a number")
    if len(words) >= 2 and words[0] in ONES and 1 <= ONES[words[0]] <= 9 and (
            words[1] in TENS or 10 <= ONES.get(words[1], 0) <= 19):
        # "one eighty" is 180, "two twenty five" 225, "three fifteen" 315 (spoken hundreds)
        return 100 * ONES[words[0]] + _word_integer(" ".join(words[1:]))
    if len(words) == 3 and words[0] in ONES and 1 <= ONES[words[0]] <= 9 and words[1] in ("oh", "o", "zero") \
            and 1 <= ONES.get(words[2], 0) <= 9:
        return 100 * ONES[words[0]] + ONES[words[2]]  # "one oh five" is 105
    total = 0
    current = 0
    for w in words:
        if w in ("a",):
            current = max(current, 1)
        elif w in ONES:
            current += ONES[w]
        elif w in TENS:
            current += TENS[w]
        elif w == "hundred":
            current = max(current, 1) * 100
            total += current
            current = 0
        else:
            raise ValueError(f"{w!r} is not a number word")
    return total + current


def _fraction_value(frac: str) -> float:
    f = " ".join(frac.split())
    for words, value in (("three quarter", 0.75), ("two thirds", 2 / 3), ("quarter", 0.25),
                         ("half", 0.5), ("third", 1 / 3), ("eighth", 1 / 8), ("sixth", 1 / 6)):
        if words in f:
            return value
    raise ValueError(f"{frac!r} is not a fraction")


def _unit_factor(unit: str, kind: QuantityKind) -> float:
    table = LENGTH_UNITS_M if kind == QuantityKind.LENGTH else ANGLE_UNITS_DEG
    return table[" ".join(unit.split())]


def find_quantities(text: str) -> list[Quantity]:
    """Every quantity in ``text`` (lower-case), left to right, non-overlapping.

    Distances come in metres, angles in degrees; a number without a unit is ``BARE``."""
    found: list[Quantity] = []
    taken = [False] * len(text)

    def free(a: int, b: int) -> bool:
        return not any(taken[a:b])

    def add(q: Quantity) -> None:
        found.append(q)
        for i in range(q.start, q.end):
            taken[i] = True

    candidates: list[Quantity] = []
    candidates += [Quantity(QuantityKind.ANGLE, _turn_degrees(m), m.start(), m.end())
                   for m in _TURN_PATTERN.finditer(text)]
    candidates += [Quantity(QuantityKind.ANGLE, _pi_degrees(m), m.start(), m.end())
                   for m in _PI_PATTERN.finditer(text)]
    for m in _METRES_CENTIMETRES.finditer(text):
        try:
            metres, centimetres = number_value(m.group("m")), number_value(m.group("cm"))
        except ValueError:
            continue
        if centimetres < CENTIMETRES_PER_METRE:  # "one metre twenty" is 1.20 m
            candidates.append(Quantity(QuantityKind.LENGTH, metres + centimetres / CENTIMETRES_PER_METRE,
                                       m.start(), m.end()))
    for m in _FEET_INCHES.finditer(text):
        try:
            inches = number_value(m.group("inch"))
            if inches < INCHES_PER_FOOT:
                candidates.append(Quantity(QuantityKind.LENGTH, number_value(m.group("ft")) * LENGTH_UNITS_M["ft"]
                                           + inches * LENGTH_UNITS_M["inch"], m.start(), m.end()))
        except ValueError:
            continue
    for kind, pattern in _UNIT_PATTERNS:
        for m in pattern.finditer(text):
            q = _unit_quantity(kind, m)
            if q is not None:
                candidates.append(q)
    # leftmost-longest: "half a meter" beats "a meter", "one and a half m" beats "a half m"
    for q in sorted(candidates, key=lambda q: (q.start - q.end, q.start)):
        if free(q.start, q.end):
            add(q)
    for m in _BARE_PATTERN.finditer(text):
        if free(m.start(), m.end()):
            try:
                value = number_value(m.group("num"))
            except ValueError:
                continue
            add(Quantity(QuantityKind.BARE, value, m.start(), m.end()))
    found.sort(key=lambda q: q.start)
    return [replace(q, alternative=True) if i and _OR_BEFORE.search(text[found[i - 1].end:q.start]) else q
            for i, q in enumerate(found)]


def _unit_quantity(kind: QuantityKind, m: re.Match[str]) -> Quantity | None:
    groups = m.groupdict()
    approximate = False
    if groups.get("lead"):
        value = 1.0
    elif groups.get("frac"):
        value = _fraction_value(groups["frac"])
    else:
        num = " ".join(groups["num"].split())
        if num in VAGUE_COUNTS:
            value, approximate = VAGUE_COUNTS[num]
        else:
            try:
                value = number_value(num)
                low = groups.get("low") or groups.get("low_digits")
                if low:
                    # "three or four feet", "3-4 m": never more than the speaker allowed
                    value = min(value, number_value(low))
            except ValueError:
                return None
    if groups.get("tail"):
        value += 0.5 if "half" in groups["tail"] else 0.25
    factor = _unit_factor(groups["unit"], kind)
    return Quantity(kind, value * factor, m.start(), m.end(), approximate, unit=factor,
                    adds=_ADDS_RE.search(m.group(0)) is not None)


def _turn_degrees(m: re.Match[str]) -> float:
    if m.group("ratio"):
        return 360.0 * _plain_number(" ".join(m.group("ratio").split()))
    if m.group("frac"):
        return 360.0 * _fraction_value(m.group("frac"))
    if m.group("whole"):
        count = number_value(m.group("num")) if m.group("num") else 1.0
        # "three sixty full circle": a number this large is the degrees of the full turn said again
        return count if count >= DEGREES_NOT_TURNS_MIN else 360.0 * count
    count = number_value(m.group("count"))
    # "a one eighty turn", "do a ninety turn": a count this large is the angle of one turn in degrees
    return count if count >= DEGREES_NOT_TURNS_MIN else 360.0 * count


def _pi_degrees(m: re.Match[str]) -> float:
    mul_text = m.group("mul")
    mul = 1.0
    if mul_text:
        mul = 0.5 if "half" in mul_text else 0.25 if "quarter" in mul_text else float(mul_text)
    div = float(m.group("div")) if m.group("div") else 1.0
    if div == 0:
        raise ValueError("division by zero in an angle")
    return 180.0 * mul / div
