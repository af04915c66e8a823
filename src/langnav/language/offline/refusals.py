"""Clauses that must not become motion: unsafe requests, negations, other floors, things the robot
cannot do, questions it cannot answer, times instead of distances, numbers not read in full."""

from __future__ import annotations

import re
from typing import Final

from langnav.language.offline import lexicon as lx
from langnav.language.offline.normalize import normalize
from langnav.language.offline.numbers import NUMBER_WORDS
from langnav.language.offline.patterns import STOP_RE, any_of

UNSAFE_RE: Final = any_of(lx.UNSAFE_PATTERNS)
SAFE_AVOIDANCE_RE: Final = any_of(lx.SAFE_AVOIDANCE_PATTERNS)
OUT_OF_SCOPE_RE: Final = any_of(lx.OUT_OF_SCOPE_PATTERNS)
OTHER_FLOOR_RE: Final = any_of(lx.OTHER_FLOOR_PATTERNS)
#: A time instead of a distance or an angle ("for 5 seconds", "for a while").
DURATION_RE: Final = re.compile(
    rf"\b(?:for\s+)?(?:(?:about|around|roughly|approximately|like|another)\s+)?(?:{NUMBER_WORDS}|"
    r"a\s+few|a\s+couple\s+of|a\s+couple|few|several)\s+(?:more\s+)?"
    r"(?:seconds|secs|minutes|mins|hours|hrs|moments)\b"
    r"|\b\d+(?:\.\d+)?\s*(?:seconds?|secs?|minutes?|mins?|hours?|hrs?|s)\b(?!\s*(?:steps?|times?))"
    r"|\bfor\s+(?:about\s+|around\s+)?(?:a|an|one|half\s+a|another)\s+(?:second|sec|minute|min|moment|hour|"
    r"while|little\s+while)\b|\bfor\s+(?:a\s+)?(?:while|some\s+time|bit\s+of\s+time)\b")
#: A question the robot cannot answer (the answerable ones were read as queries before).
QUESTION_RE: Final = re.compile(r"^(?:(?:hey|ok|okay|so|robot)\s+)*(?:how|what|why|when|which|who|whose|is|are|"
                                 r"where\s+(?:is|are)\s+(?:the|a|an|any|your)\b|"
                                 r"was|were|does|did|do\s+(?:you|i|we)|can\s+i|could\s+i|"
                                 # "tell me the position of the door": a question about a place, no trip to it
                                 r"(?:(?:please|can\s+you|could\s+you)\s+)?(?:tell|give|send)\s+(?:me|us)\s+(?:the\s+)?"
                                 r"(?:position|location|coordinates|distance|size|width|length)\s+(?:of|to)\b)\b")
NEGATION_RE: Final = re.compile(lx.NEGATIONS)
#: Words left unread that show a number was not read in full: digits, and magnitudes the
#: number words do not cover.
NUMBERISH_RE: Final = re.compile(r"\d|\b(?:thousands?|millions?|billions?|trillions?|zillions?|gazillions?|"
                                  r"dozens?|hundreds|infinity|infinite)\b")


def is_unsafe(prompt: str) -> bool:
    """True when the prompt asks for something unsafe or tries to override the rules."""
    norm = SAFE_AVOIDANCE_RE.sub(" ", normalize(prompt))  # "without hitting the wall" is safe
    return UNSAFE_RE.search(norm) is not None


def is_negated(norm: str) -> bool:
    m = NEGATION_RE.search(norm)
    if m is None:
        return False
    # "do not move", "don't go any further" are stops, read as such
    return STOP_RE.search(norm) is None or "stop" in norm[m.end():m.end() + 12]


_OPEN_RE: Final = re.compile(r"(?:(?P<before>[a-z']+)\s+)?\bopen\b")


def is_out_of_scope(norm: str) -> bool:
    """A verb of something the robot cannot do ("pick up the cup", "open door"): the clause never
    moves the robot. "open" is that verb unless it stands as an adjective ("the open door")."""
    if OUT_OF_SCOPE_RE.search(norm):
        return True
    return any(m.group("before") not in lx.OPEN_ADJECTIVE_AFTER for m in _OPEN_RE.finditer(norm)
               if not re.match(r"\s+(?:space|spaces|area|areas|floor|plan)\b", norm[m.end():]))
