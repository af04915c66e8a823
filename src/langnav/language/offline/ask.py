"""Ask, don't guess (issue 9 item 6): when a word that could change where or how far the robot goes
was not read, or a reading would have to guess a side or a unit, nothing runs. The reply says what
was understood (the plan it would run) and asks about the rest.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import Final

from langnav.language.intent import Amount, Direction, Movement, Step
from langnav.language.offline import lexicon as lx
from langnav.language.offline.compass import HEADINGS_DEG
from langnav.language.offline.numbers import ANGLE_UNITS_DEG, FRACTIONS, LENGTH_UNITS_M, ONES, TENS
from langnav.language.offline.reading import ASK_SIDE

#: Words that say where or how far: sides, directions, places, amounts, units, compass points.
#: One of them left unread means the plan may not be what was asked.
SPATIAL_WORDS: Final = frozenset(
    {w for phrase in (*lx.MOVE_DIRECTIONS, *lx.ROTATE_DIRECTIONS, *lx.ELEMENT_NOUNS, *lx.ORDINALS,
                      *lx.SIDE_ADJECTIVES, *LENGTH_UNITS_M, *ANGLE_UNITS_DEG, *ONES, *TENS, *FRACTIONS)
     for w in phrase.split()}
    | set(HEADINGS_DEG) | {"hundred", "thousand", "halfway", "past", "beyond", "behind", "until", "till", "before",
                           "after", "across", "between", "along", "through", "around", "clockwise", "counterclockwise",
                           "anticlockwise", "sideways", "far", "farther", "further", "closer", "nearer", "back",
                           # amounts said relative to another one ("two more", "the same distance", "twice")
                           "more", "less", "same", "distance", "amount", "longer", "shorter", "twice", "double",
                           "triple",
                           # the map's axes ("move +x 2 m", "along the y axis"): a way in the map's frame
                           "x", "y", "+x", "-x", "+y", "-y", "axis"}
    # a superlative picks which place ("the smallest room"): one left unread may pick another
    | {w for w in lx.SUPERLATIVES if w.endswith("est") and " " not in w}
    # the ways said in another language ("izquierda", "links"): one left unread may be the way meant
    | lx.FOREIGN_WAY_WORDS
) - lx.STOPWORDS - {"a", "an", "the", "of", "to", "in", "on", "at", "up", "one", "way", "port", "positive",
                    "negative", "wall", "turn", "u", "face", "about", "other", "opposite", "direction", "came",
                    "we", "you", "your", "side", "hand", "closer", "nearer"} | {"wall", "walls", "door", "doors"}
UNDERSTOOD_NONE: Final = "I understood no motion I could run"


def spatial(words: str) -> list[str]:
    """The words of ``words`` that could change where or how far the robot goes."""
    return [w for w in words.lower().split() if w.strip(",.;:!?'\"") in SPATIAL_WORDS]


#: A verb of going and the word that says a destination follows ("go to", "head towards", "drive into").
_GOING_TO_RE: Final = re.compile(
    r"\b(?:" + "|".join(sorted((re.escape(v).replace(r"\ ", r"\s+") for v in lx.GO_VERBS), key=len, reverse=True))
    + r")\s+(?:(?:up|over|on|back|down|right|straight)\s+)?(?:to|towards?|into|onto|up\s+to|as\s+far\s+as)\s+"
    r"(?P<place>[^,.;!?]+)", re.IGNORECASE)
#: Words after "to" that say a way, not a place ("step to the side", "go to your left"): no destination.
_WAY_OBJECTS: Final = frozenset({"the", "your", "my", "a", "one", "other", "side", "sides", "left", "right", "front",
                                 "back", "rear", "hand"})


def names_destination(words: str) -> bool:
    """Whether ``words`` send the robot to a place (a verb of going, then "to", "towards", "into" and what follows):
    left unread, they name a destination the reading could not ground ("go to the robot and turn left"; "go to my
    friend"), so the plan may not be what was asked: the rest of the request must not run without it (the words
    after the verb are a place, never an address to the robot, which is spoken to, not gone to)."""
    m = _GOING_TO_RE.search(words)
    return m is not None and not set(m.group("place").lower().split()) <= _WAY_OBJECTS


def only_stops(steps: Sequence[Step]) -> bool:
    """A plan that only stops ("nee nee, stop"; "dur, stop!"): a word left unread next to it cannot make the robot
    go farther or turn more than stopping does, so it is no reason to hold the stop back and ask."""
    return bool(steps) and all(s.movement == Movement.STOP for s in steps)


def ask_message(steps: Sequence[Step], unread: Sequence[str], questions: Sequence[str], *,
                plan: str | None = None) -> str:
    """What was understood, what was not, and the question: nothing runs until the user answers.
    ``plan`` is the understood plan in words when the caller has better ones than the steps' (the
    grounded plan's notes: "to the second door on your left")."""
    if plan is None:
        # a turn whose side is asked about carries a placeholder side: say "which way?", not the placeholder
        sideless = ASK_SIDE in questions
        plan = ", then ".join(_describe(s, sideless and s.movement == Movement.ROTATE and not _SIDE_SAID_RE.search(s.text))
                              for s in steps)
    understood = f"I understood: {plan}." if plan else f"{UNDERSTOOD_NONE}."
    parts = [understood]
    if unread:
        shown = "; ".join(f"'{u}'" for u in unread)
        parts.append(f"I did not understand {shown}, which could change where I go or how far.")
    parts.extend(dict.fromkeys(questions))
    parts.append("Nothing was run: tell me again with that made clear.")
    return " ".join(parts)


def describe_steps(steps: Sequence[Step]) -> str:
    """The steps in plain words ("turn right 90 degrees, then move forward 0.91 m")."""
    return ", then ".join(_describe(s) for s in steps)


#: A side said in a turn's words (its placeholder side is not said).
_SIDE_SAID_RE: Final = re.compile(r"\b(?:left|right|clockwise|counter\s*clockwise|anti\s*clockwise|cw|ccw|port|starboard)\b",
                                  re.IGNORECASE)


def _describe(step: Step, side_asked: bool = False) -> str:
    if step.movement == Movement.ROTATE and side_asked and step.heading_deg is None \
            and step.direction in (Direction.LEFT, Direction.RIGHT):
        return f"turn {_amount(step, 'degrees')} (which way?)"
    if step.movement == Movement.ROTATE:
        if step.heading_deg is not None:
            name = next((k for k, v in HEADINGS_DEG.items() if abs(v - step.heading_deg) < 1e-6),
                        f"heading {step.heading_deg:g} degrees")
            return f"turn to face {name}"
        if step.direction == Direction.AROUND:
            return "turn around"
        side = step.direction.value if step.direction is not None else "(which way?)"
        return f"turn {side} {_amount(step, 'degrees')}"
    if step.movement == Movement.MOVE:
        side = step.direction.value if step.direction is not None else "forward"
        return f"move {side} {_amount(step, 'm')}"
    if step.movement == Movement.STOP:
        return "stop"
    if step.movement == Movement.QUERY and step.query is not None:
        return f"report my {step.query.value}"
    if step.movement == Movement.EXPLORE:
        return "explore"
    target = step.target.kind.value.replace("_", " ") if step.target is not None else "there"
    detail = step.detail.value.replace("_", " ") if step.detail is not None else "to"
    return f"go {detail} the {target}"


def _amount(step: Step, unit: str) -> str:
    value = step.angle_deg if step.movement == Movement.ROTATE else step.distance_m
    if value is not None:
        return f"{value:.3g} {unit}"
    if step.amount == Amount.LITTLE:
        return "a little"
    return "90 degrees" if step.movement == Movement.ROTATE else "(how far?)"
