"""Spoken instructions come in pieces and get corrected on the way (README "Speech"):

* a fragment after a comma completes the move or turn before it ("rotate, ninety degrees left";
  "turn thirty degrees, to the left"; "head due west, for five feet"), or the one after it
  ("ten inches, go straight");
* a self-correction replaces what it corrects, and only that: "ninety degrees right, actually left"
  is left; "turn left twenty degrees, sorry, turn right twenty degrees" is the right turn; "never
  mind" drops the instruction before it.

Both work on the clause texts before they are read, so the reading sees one whole instruction.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Final

from langnav.language.offline import lexicon as lx
from langnav.language.offline.compass import COMPASS_RE
from langnav.language.offline.normalize import normalize
from langnav.language.offline.numbers import find_quantities
from langnav.language.offline.patterns import GO_VERB_RE, ROTATE_VERB_RE, STOP_RE, rx

#: Words that open a correction of the instruction before ("actually", "no wait", "i'm sorry").
CORRECTION_START_RE: Final = re.compile(
    r"^(?:(?:actually|no\s+wait|no(?!\s+(?:further|longer|more|need)\b)|wait(?=\s*,?\s*no\b)|oh\s+wait|(?:i'?m|i\s+am|im)\s+sorry|"
    r"sorry|i\s+meant|i\s+mean|or\s+rather|rather|make\s+that|correction|oops)\b[\s,]*)+", re.IGNORECASE)
#: Words that take back the instruction before ("never mind", "scratch that").
CANCEL_RE: Final = re.compile(r"\b(?:never\s*mind|scratch\s+that|forget\s+(?:it|that)|cancel\s+that|ignore\s+that|"
                              r"disregard\s+that)\b[\s,]*", re.IGNORECASE)
#: Words that give the side of a move or a turn (a fragment may carry one).
SIDE_RE: Final = re.compile(
    r"(?:\b(?:to|on|towards?)\s+(?:the|your)\s+)?\b(?:left|right|clockwise|counter\s*clockwise|anti\s*clockwise|"
    r"forwards?|backwards?|ahead|straight)\b(?:\s+(?:hand\s+)?side)?")
_HEAD_RE: Final = rx([*lx.ELEMENT_NOUNS], "head")

#: ``open(text)``: does the instruction miss an amount or a side a fragment may give?
IsOpen = Callable[[str], bool]


def is_fragment(clause: str) -> bool:
    """Only an amount and/or a side (or a compass point): no verb, no element, no correction word."""
    norm = normalize(clause)
    if not norm or CORRECTION_START_RE.match(norm) or CANCEL_RE.search(norm):
        return False
    if GO_VERB_RE.search(norm) or ROTATE_VERB_RE.search(norm) or STOP_RE.search(norm) or _HEAD_RE.search(norm):
        return False
    return bool(find_quantities(norm) or SIDE_RE.search(norm) or COMPASS_RE.search(norm))


#: Words of a request around a bare verb ("just", "can you", "robot").
_REQUEST_WORDS: Final = frozenset({"can", "could", "will", "would", "you", "robot", "just", "okay", "ok", "please",
                                   "and", "now", "so", "then", "yourself"})
_BARE_VERBS: Final = frozenset(v for v in (*lx.GO_VERBS, *lx.ROTATE_VERBS) if " " not in v) - {"stop", "wait"}


#: A clause that only opens a request ("go ahead", "okay go on", "come on").
_LEAD_IN: Final = re.compile(r"^(?:(?:ok|okay|so|now|alright|robot|please|yeah|yes|well|just)\s+)*(?:go\s+ahead|go\s+on|come\s+on|"
                             r"ready|here\s+we\s+go)(?:\s+(?:please|robot|now))*$")


#: Words that only soften or acknowledge ("about,", "yeah", "okay so"): a clause of them says nothing.
_HEDGE_WORDS: Final = frozenset({"about", "like", "roughly", "approximately", "say", "so", "well", "yeah", "yes",
                                 "yep", "okay", "ok", "alright", "sure", "good", "great", "cool",
                                 "um", "uh", "hmm", "robot", "please", "now", "just"})


def is_hedge(clause: str) -> bool:
    """Only hedges or acknowledgements: "about," in "turn right, about, thirty degrees"."""
    words = normalize(clause).split()
    return bool(words) and all(w in _HEDGE_WORDS for w in words)


def is_bare_verb(clause: str) -> bool:
    """Only a verb of motion, with nothing said about where or how far ("turn", "can you move")."""
    words = normalize(clause).split()
    content = [w for w in words if w not in _REQUEST_WORDS]
    return bool(content) and all(w in _BARE_VERBS for w in content) and len(content) <= 2


def join_fragments(clauses: list[str], is_open: IsOpen) -> list[str]:
    """Each fragment joined to the open instruction before it (or, failing that, after it)."""
    out: list[str] = []
    i = 0
    while i < len(clauses):
        clause = clauses[i]
        nxt_clause = clauses[i + 1] if i + 1 < len(clauses) else None
        if nxt_clause is not None and _LEAD_IN.match(normalize(clause)):
            i += 1  # "go ahead, turn right": "go ahead" only opens the request
            continue
        if nxt_clause is not None and is_bare_verb(clause) and not is_fragment(nxt_clause):
            i += 1  # "face, face east", "turn and face east": a false start of the next instruction
            continue
        if is_fragment(clause):
            if out and is_open(out[-1]):
                out[-1] = f"{out[-1]} {clause}"
                i += 1
                continue
            nxt = clauses[i + 1] if i + 1 < len(clauses) else None
            if nxt is not None and not is_fragment(nxt) and is_open(nxt):
                out.append(f"{nxt} {clause}")
                i += 2
                continue
        out.append(clause)
        i += 1
    return out


def apply_corrections(clauses: list[str]) -> list[str]:
    """The clauses with every self-correction applied to the instruction it corrects."""
    out: list[str] = []
    pending = False  # "i'm sorry" alone: the next clause is the correction
    for clause in clauses:
        cancel = CANCEL_RE.search(clause)
        start = CORRECTION_START_RE.match(clause)
        if cancel is not None and (cancel.start() == 0 or (start is not None and cancel.start() <= start.end())):
            if out:
                out.pop()  # "actually no, never mind": the instruction before is taken back
            pending = False
            clause = clause[cancel.end():].strip()
            if clause:
                out.append(clause)
            continue
        correcting = pending
        pending = False
        if start is not None:
            clause = clause[start.end():].strip()
            if not clause:
                pending = bool(out)
                continue
            correcting = True
        if correcting and out:
            out[-1] = _corrected(out[-1], clause) if is_fragment(clause) else clause
            continue
        out.append(clause)
    return out


def _corrected(previous: str, fragment: str) -> str:
    """'turn ninety degrees right' corrected by 'left': the side (or the amount) the fragment gives
    replaces the one said before."""
    norm_prev = normalize(previous)
    norm_frag = normalize(fragment)
    if SIDE_RE.search(norm_frag):
        norm_prev = SIDE_RE.sub(" ", norm_prev)
    if COMPASS_RE.search(norm_frag):
        norm_prev = COMPASS_RE.sub(" ", norm_prev)
    quantities = find_quantities(norm_frag)
    if quantities:
        for q in reversed(find_quantities(norm_prev)):
            norm_prev = norm_prev[:q.start] + " " + norm_prev[q.end:]
    return " ".join(f"{norm_prev} {norm_frag}".split())
