"""The main verb of a clause: stop, turn, go, or none (a fragment that borrows the previous verb)."""

from __future__ import annotations

import re
from enum import StrEnum
from typing import Final

from langnav.language.offline import lexicon as lx
from langnav.language.offline.numbers import find_quantities
from langnav.language.offline.patterns import GO_VERB_RE, ROTATE_VERB_RE, STOP_RE
from langnav.language.offline.scratch import Clause

_TURN_A_SIDE_RE: Final = re.compile(r"\b(?:take|make|hang|do|go)\s+a\s+(?P<dir>left|right)\b(?:\s+turn\b)?")
_TURN_NOUN_RE: Final = re.compile(r"\b(?:turn|rotation|spin|u\s+turn|180|360|about\s+face|circle|revolution|pirouette|twirl)\b")


class Verb(StrEnum):
    STOP = "stop"
    ROTATE = "rotate"
    GO = "go"
    NONE = "none"


def main_verb(c: Clause) -> tuple[Verb, re.Match[str] | None]:
    text = c.s.masked()
    candidates: list[tuple[int, Verb, re.Match[str]]] = []
    amounts = [(q.start, q.end) for q in find_quantities(text)]
    for verb, pattern in ((Verb.STOP, STOP_RE), (Verb.ROTATE, ROTATE_VERB_RE), (Verb.GO, GO_VERB_RE)):
        # a verb inside an amount is its unit ("five inch": inch is no verb there)
        m = next((m for m in pattern.finditer(text)
                  if not any(a <= m.start() and m.end() <= b for a, b in amounts)), None)
        if m is None:
            continue
        if verb == Verb.ROTATE and m.group("verb").split()[0] in lx.ROTATE_NOUN_VERBS \
                and not _TURN_NOUN_RE.search(text[m.start():]):
            continue
        candidates.append((m.start(), verb, m))
    turn_a_side = _TURN_A_SIDE_RE.search(text)
    if turn_a_side is not None:
        return Verb.ROTATE, turn_a_side
    if not candidates:
        return Verb.NONE, None
    candidates.sort(key=lambda t: t[0])
    # "stop" wins wherever it is ("go to the door and stop there" was split already)
    for _, verb, m in candidates:
        if verb == Verb.STOP:
            return verb, m
    return candidates[0][1], candidates[0][2]
