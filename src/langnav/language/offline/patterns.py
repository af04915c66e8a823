"""The lexicon's tables compiled into the patterns several reading stages share."""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence
from typing import Final

from langnav.language.offline import lexicon as lx


def rx(phrases: Iterable[str], group: str | None = None) -> re.Pattern[str]:
    return re.compile(lx.phrase_regex(phrases, group))


def any_of(patterns: Sequence[str]) -> re.Pattern[str]:
    return re.compile("|".join(f"(?:{p})" for p in patterns))


FILLER_RE: Final = any_of(lx.FILLER_PATTERNS)
LATE_FILLER_RE: Final = any_of(lx.LATE_FILLER_PATTERNS)
EXPLORE_RE: Final = any_of(lx.EXPLORE_PATTERNS)
STOP_RE: Final = rx(lx.STOP_PHRASES)
ROTATE_VERB_RE: Final = rx(lx.ROTATE_VERBS, "verb")
GO_VERB_RE: Final = rx(lx.GO_VERBS, "verb")
#: "a little bit more", "a tad further": a little (it adds to what was done).
LITTLE_RE: Final = re.compile(lx.phrase_regex(lx.LITTLE_PHRASES) + r"(?:\s+(?:more|further|farther|extra|again)\b)?")
#: "a fair bit", "quite a way further": an amount said only to be large (ask how far).
MUCH_RE: Final = re.compile("(?:" + any_of(lx.MUCH_PATTERNS).pattern + r")(?:\s+(?:more|further|farther|extra|again))?\b")
MOVE_DIR_RE: Final = rx(lx.MOVE_DIRECTIONS, "dir")
#: Words that give a turn its side (README "Turns": clockwise is right, counter-clockwise left), as regex
#: alternatives: the one list every stage asking "is a side said?" builds its pattern from.
TURN_SIDE_WORDS: Final = r"left|right|clockwise|counter\s*clockwise|anti\s*clockwise|cw|ccw"
#: A boat's sides (port is left, starboard right), said by anyone who has been on one.
BOAT_SIDE_WORDS: Final = r"port|starboard"
#: Words that give a straight move its way along the heading (forward or back), which no turn can take.
MOVE_WAY_WORDS: Final = r"forwards?|backwards?|back|ahead|straight|astern"
ROTATE_DIR_RE: Final = rx(lx.ROTATE_DIRECTIONS, "dir")
