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
ROTATE_DIR_RE: Final = rx(lx.ROTATE_DIRECTIONS, "dir")
