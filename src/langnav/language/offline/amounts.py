"""An amount said on its own right after a move or a turn ("turn left 45 degrees ... 20 more"; "go
forward two feet ... three"; "move forward four metres, er, four feet"):

* said to be more of the same ("two more", "another ninety") with no unit, its unit is the unit of
  the amount just said: people do not repeat the unit they are counting in ("two feet, then two
  more" is four feet, "turn ninety, then another ninety" two right angles); a number alone with no
  such word ("then 2") leaves its unit to be asked;
* with a word asking for more ("more", "another", "again", "further") or a word that puts
  instructions in a sequence ("then"), it is a further move or turn the same way;
* with neither, it is the amount said again or put right: the last one said counts ("go forward
  seven feet, my bad, six feet" is six feet). Adding the two would take the robot farther than
  anyone asked; doing the last one never does, and the user can ask for more.

A clause that only asks for the same again ("and again", "do it again", "repeat that", "once more")
does the move or turn before it once more, with its amount.
"""

from __future__ import annotations

import re
from typing import Final

from langnav.language.intent import Movement, Step
from langnav.language.offline.normalize import normalize
from langnav.language.offline.numbers import Quantity, QuantityKind, find_quantities

#: The word for each length unit's size in metres (a unit carried to an amount said without one).
_LENGTH_UNIT_WORDS: Final[dict[float, str]] = {1.0: "metres", 0.01: "centimetres", 0.001: "millimetres",
                                               0.1: "decimetres", 0.3048: "feet", 0.0254: "inches",
                                               0.9144: "yards"}
#: Words that give a way or a side: a fragment with one is an instruction of its own, not an amount alone.
_SIDE_RE: Final = re.compile(r"\b(?:left|right|forwards?|backwards?|back|ahead|straight|clockwise|counter\s*clockwise|"
                             r"anti\s*clockwise|cw|ccw|around|round|north|south|east|west|sideways)\b")
#: Words that say an amount is more of what was just done ("two more", "another ninety", "20 further").
_MORE_RE: Final = re.compile(r"\b(?:more|another|further|additional|extra|again)\b")
#: Two unit sizes closer than this are the same unit.
_UNIT_TOL: Final = 1e-9


def unit_word(q: Quantity) -> str | None:
    """The unit ``q`` was said in, as a word ("feet", "degrees"), or None (a compound or no unit)."""
    if q.kind == QuantityKind.ANGLE and q.unit > 0:
        return "degrees"
    if q.kind != QuantityKind.LENGTH:
        return None
    return next((w for size, w in _LENGTH_UNIT_WORDS.items() if abs(size - q.unit) < _UNIT_TOL), None)


def with_unit(fragment: str, unit: str | None) -> str:
    """``fragment`` (normalised) with ``unit`` after each of its numbers, when every number in it was
    said without a unit; else ``fragment``."""
    quantities = find_quantities(fragment)
    if unit is None or not quantities or any(q.kind != QuantityKind.BARE for q in quantities):
        return fragment
    for q in reversed(quantities):
        fragment = f"{fragment[:q.end]} {unit}{fragment[q.end:]}"
    return fragment


def _unit_word(previous: Step) -> str | None:
    """The unit the amount of ``previous`` was said in, as a word, or None."""
    if previous.target is not None or previous.heading_deg is not None:
        return None
    if previous.movement == Movement.ROTATE:
        return "degrees"  # a turn's bare number is degrees ("turn left ninety"; "keep turning right, another twenty")
    if previous.movement != Movement.MOVE or previous.distance_m is None:
        return None
    lengths = [q for q in find_quantities(normalize(previous.text)) if q.kind == QuantityKind.LENGTH and q.unit > 0]
    return unit_word(lengths[-1]) if lengths else None


def with_unit_said_before(clause: str, previous: Step | None, is_fragment: bool) -> str:
    """``clause`` with the unit of the amount before it put after its numbers, when the clause is a
    fragment (no verb of its own) whose every number was said without a unit; else ``clause``."""
    norm = normalize(clause)
    if previous is None or not is_fragment or _SIDE_RE.search(norm) or not _MORE_RE.search(norm):
        # "then left 90": a number with a side of its own is read as that side's (a turn); "then 2" says
        # nothing of being more of the same, so its unit is asked, never guessed
        return clause
    unit = _unit_word(previous)
    carried = with_unit(norm, unit)
    return clause if carried == norm else carried


def same_way_again(previous: Step, step: Step) -> bool:
    """``step`` is a plain move or turn the same way as ``previous``, both with an amount."""
    if step.movement not in (Movement.MOVE, Movement.ROTATE) or step.movement != previous.movement:
        return False
    if step.target is not None or previous.target is not None or step.heading_deg is not None \
            or previous.heading_deg is not None or step.direction != previous.direction:
        return False
    if step.movement == Movement.MOVE:
        return previous.distance_m is not None and step.distance_m is not None
    return previous.angle_deg is not None and step.angle_deg is not None


#: A clause that only asks for what was just done once more.
_AGAIN_RE: Final = re.compile(
    r"^(?:(?:and|now|then|ok(?:ay)?|please|so)\s+)*(?:(?:do|repeat)\s+(?:it|that|this|the\s+same)\s*)?"
    r"(?:again|once\s+more|one\s+more\s+time|(?:a\s+)?second\s+time)?(?:\s+please)?$"
    # "repeat" alone is the radio's "I repeat" (what follows is said again), not "do it again"
    r"|^(?:(?:and|now|then|ok(?:ay)?|please|so)\s+)*repeat\s+(?:it|that|this)(?:\s+please)?$")
#: Words that must be in such a clause (so that "and", "please" alone are not read as asking for more).
_AGAIN_WORD_RE: Final = re.compile(r"\b(?:again|once\s+more|one\s+more\s+time|second\s+time|repeat)\b")


def said_again(clause: str, previous: Step | None) -> Step | None:
    """The step to do once more when ``clause`` only asks for the move or turn before it again ("turn
    left ninety, and again"; "go forward three feet and then do it again"), else None. Only a plain
    move or turn is done again: a place reached is reached, and a facing is faced."""
    if previous is None or previous.movement not in (Movement.MOVE, Movement.ROTATE):
        return None
    if previous.target is not None or previous.heading_deg is not None:
        return None
    norm = normalize(clause)
    if not _AGAIN_WORD_RE.search(norm) or _AGAIN_RE.match(norm) is None:
        return None
    return previous.model_copy(update={"text": f"{previous.text}, {clause}"[:500]})
