"""What reading one clause yields: its steps, the words left unread, the confidence, a problem.

The confidence factors and the limits of one step live here, with their reasons.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from enum import StrEnum
from typing import Final

from langnav.language.intent import ElementRef, Step

# ------------------------------------------------------------------------------ confidence
#: Confidence factors: each doubt in a reading multiplies the step's confidence.
UNREAD_WORD_FACTOR: Final = 0.7          # per content word left unread
DEFAULT_AMOUNT_FACTOR: Final = 0.75      # "move forward" with no distance: the grounding guesses
GUESSED_DIRECTION_FACTOR: Final = 0.7    # "rotate 90 degrees" with no side: left is a guess
UNITLESS_NUMBER_FACTOR: Final = 0.85     # "move forward 2": metres assumed
VAGUE_NUMBER_FACTOR: Final = 0.75        # "a few metres"
WEAK_WORD_FACTOR: Final = 0.85           # "passage" alone, "the other door", "take the door"
ELLIPSIS_FACTOR: Final = 0.85            # "... then the second one": the verb is borrowed
NOTHING_READ_CONFIDENCE: Final = 0.2     # no instruction recognised at all
OUT_OF_SCOPE_CONFIDENCE: Final = 0.9     # clearly something the robot cannot do
NAME_CONFIDENCE: Final = 0.9             # a place name the map cannot know
ASK_CONFIDENCE: Final = 0.4              # a reading that must ask before it runs (issue 9: ask, don't guess)
MIN_CONFIDENCE: Final = 0.05
#: Longest single move (the intent schema's bound); longer trips should name a place.
MAX_MOVE_M: Final = 100.0
#: Largest single turn (the intent schema's bound: ten full turns).
MAX_TURN_DEG: Final = 3600.0
#: "turn left" alone (README): used only to multiply "turn left twice".
DEFAULT_TURN_DEG: Final = 90.0


#: Questions asked instead of guessing.
ASK_SIDE: Final = "Which way should I turn, left or right?"
ASK_BOTH_SIDES: Final = ("I heard both left and right in one turn (clockwise is right, counter-clockwise is left): "
                         "which way should I turn?")
ASK_DISTANCE: Final = "How far should I move {direction}?"
ASK_UNIT: Final = "In what unit is '{number}': metres, feet or something else?"
ASK_AMOUNT: Final = "I heard more than one amount ({amounts}): which one did you mean?"
ASK_HOW_MANY: Final = "How far exactly is '{said}'?"
ASK_HOW_MUCH_TURN: Final = "How many degrees exactly is '{said}'?"


class Problem(StrEnum):
    """Why a clause yields no step."""

    NAME = "name"                  # "go to the kitchen"
    OUT_OF_SCOPE = "out_of_scope"  # "make me a sandwich"
    NEGATED = "negated"            # "don't go through the door"
    UNREADABLE = "unreadable"      # nothing recognised
    NO_ANTECEDENT = "no_antecedent"  # "go through it" with nothing before
    OUT_OF_RANGE = "out_of_range"    # "move forward 200 metres"
    QUESTION = "question"            # "how far is the door?" (only pose, path and map are answered)
    OTHER_FLOOR = "other_floor"      # "take the stairs up", "use the lift": the robot stays on its floor
    UNKNOWABLE = "unknowable"        # "the red door", "the wooden door": no colours or materials in a grid
    DURATION = "duration"            # "move forward for 5 seconds": moves go by distance, turns by angle
    BAD_NUMBER = "bad_number"        # "turn left ninety billion degrees": a number not read in full
    BEARING = "bearing"              # "turn to heading one eight zero": a direction in degrees whose convention is not said


class OutOfRange(Exception):
    """A turn beyond MAX_TURN_DEG while building a step (read_clause turns it into OUT_OF_RANGE)."""


def checked_angle(angle: float | None) -> float | None:
    if angle is not None and angle > MAX_TURN_DEG:
        raise OutOfRange
    return angle


#: Words left unread that show a number was not read in full: digits, and magnitudes the
#: number words do not cover.
NUMBERISH_RE: Final = re.compile(r"\d|\b(?:thousands?|millions?|billions?|trillions?|zillions?|gazillions?|"
                                  r"dozens?|hundreds|infinity|infinite)\b")


@dataclass(frozen=True)
class Reading:
    """What one clause says: its steps, the words left unread, and how sure the reading is."""

    steps: tuple[Step, ...] = ()
    unread: tuple[str, ...] = ()
    confidence: float = 1.0
    problem: Problem | None = None
    name: str | None = None
    #: the clause only adds a number or a direction to the previous step ("turn left, 45 degrees")
    amends_previous: bool = False
    #: the element a question names ("which is the largest room?"): a later "it" may mean it
    referent: ElementRef | None = None
    #: "... and stop just after you pass through it": the previous step goes through its element
    through_previous: bool = False
    #: the last step misses an amount or a side that a following fragment may give ("rotate" then
    #: ", ninety degrees left"; "turn thirty degrees" then ", to the left"; "head west" then ", ten feet")
    open: bool = False
    #: questions for the user: the reading would have to guess a side or a unit (nothing runs)
    asks: tuple[str, ...] = ()


#: A direction given as a number of degrees after "heading", "bearing" or "course" ("turn to heading one eight
#: zero", "come to a bearing of 90"). Pilots, sailors and hikers count such a number clockwise from north (090 is
#: east); a robot's map counts its heading counter-clockwise from east (90 is north). The two agree only on
#: nothing the speaker can be assumed to know, so the robot asks instead of turning one way or the other (a turn
#: "by 180" would be a third reading, turning as far as the number). Lengths after the word are no bearing.
BEARING_RE: Final = re.compile(
    r"\b(?:heading|bearing|course)\s+(?:of\s+|to\s+)?\d+(?:\.\d+)?\b"
    r"(?!\s*(?:m|cm|mm|met(?:er|re)s?|centimet(?:er|re)s?|feet|foot|ft|inch(?:es)?|yards?|yd)\b)")
