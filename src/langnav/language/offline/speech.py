"""Speech as it comes, made plain before a prompt is split: hesitations ("uh", "um", "hmm"), cut-off
words ("nin- degree- ninety degrees"), stutters ("tur turn", "to l left", "a a left"), noise tokens
("ff", "fff") and self-corrections marked as their own clause ("ninety degrees right, actually left").

Nothing here changes what a word means: it only drops what carries no meaning, so the reading that
follows sees what the speaker meant to say (README "Speech": fillers and cut-off words mean nothing).
"""

from __future__ import annotations

import re
from typing import Final

from langnav.language.offline.lexicon import TYPOS
from langnav.language.offline.vocabulary import VOCABULARY

#: Hesitation sounds: no meaning in any position.
HESITATIONS: Final = frozenset({
    "uh", "uhh", "uhhh", "uhhhh", "um", "umm", "ummm", "uhm", "uhmm", "hmm", "hmmm", "hm", "er", "erm", "err",
    "ah", "ahh", "eh", "mmm", "mhm", "huh", "ehm",
})
#: Hedges a speaker puts before an amount or a direction ("uh maybe forty five degrees"): they soften
#: the words, they never change the amount or the side.
#: Affirmations ("you're right", "that's correct") are no side; "at least" / "at most" and "until I
#: tell you to stop" leave the amount said as it is; "what about / how about" before a verb is a request.
_HEDGES: Final = re.compile(
    r"\b(?:maybe|perhaps|i\s+guess|i\s+think|kind\s+of|sort\s+of|let\s+us\s+see|let's\s+see|lets\s+see|"
    r"(?:you'?re|you\s+are|that'?s|that\s+is|thats)\s+(?:right|correct)|at\s+(?:least|most)|"
    r"(?:go\s+ahead|go\s+on|come\s+on)\s+and|"
    r"(?:until|till)\s+i\s+(?:tell\s+you(?:\s+(?:to\s+stop|otherwise))?|say\s+(?:so|stop|otherwise))|"
    r"(?:what|how)\s+about(?=\s+(?:you\s+)?(?:move|go|turn|rotate|head|drive|face|pivot|back|proceed)\b))\b",
    re.IGNORECASE)
#: A word cut off in the middle: letters and a dash before a space or the end ("nin-", "c-").
_CUT_OFF: Final = re.compile(r"(?<![\w-])[a-z]+-(?=[\s,.;!?]|$)", re.IGNORECASE)
#: Short consonant runs are sounds, not words ("ff", "fff", "tsk"); units ("ft", "cm") are words, and a
#: longer run is an unknown word the reading must see (and ask about).
_NOISE: Final = re.compile(r"^[bcdfghjklmnpqrstvwxz]{2,4}$")
#: Unit letters that are sounds when no number comes before them ("mm move forward", "uh m uh").
_UNIT_SOUNDS: Final = frozenset({"m", "mm"})
_NUMBER_WORD: Final = re.compile(r"^(?:[\d.,/]*\d[\d.,/]*|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|"
                                 r"\w+teen|twenty|thirty|forty|fifty|sixty|seventy|eighty|ninety|hundred|half|a|an)$")
#: "can you move, can you turn left": a request started again; the words before the restart go.
_RESTART: Final = re.compile(r"\b(?:can|could|will|would)\s+you\s+(?:(?!(?:and|then)\b)[^\s,.;]+\s+){1,3}?"
                             r"(?=(?:can|could|will|would)\s+you\b)",
                             re.IGNORECASE)
#: Words that open a self-correction; a clause break is put before them so that the correction is
#: read as a clause of its own ("turn ninety degrees right actually left").
CORRECTION_MARKERS: Final = (
    r"actually(?:\s+no)?(?:\s+i\s+meant|\s+i\s+mean)?", r"no\s+wait", r"no\s+no", r"wait\s+no", r"oh\s+wait",
    r"(?:i'?m|i\s+am|im)\s+sorry", r"sorry", r"i\s+meant", r"i\s+mean", r"or\s+rather", r"make\s+that",
    r"scratch\s+that", r"never\s*mind", r"correction", r"oops",
)
_MARKER_INSIDE: Final = re.compile(r"(?P<before>\S+)\s+(?=(?:" + "|".join(CORRECTION_MARKERS) + r")\b)",
                                   re.IGNORECASE)
#: Words that belong to the marker that follows them ("i'm sorry", "oh wait", "actually no").
_MARKER_LEAD: Final = frozenset({"i'm", "im", "i", "am", "oh", "actually", "no", "wait", "um", "or", "that"})
_WORD: Final = re.compile(r"\S+")


def plain_speech(prompt: str) -> str:
    """``prompt`` with hesitations, hedges, cut-off words, stutters and noise tokens removed, and a
    comma before each self-correction marker."""
    text = _CUT_OFF.sub(" ", prompt)
    text = _HEDGES.sub(" ", text)
    text = _RESTART.sub("", text)
    tokens = _WORD.findall(text)
    kept: list[str] = []
    for i, token in enumerate(tokens):
        bare = token.lower().strip(",.;:!?\"'")
        punct = token[len(token.rstrip(",.;:!?")):]
        after_number = bool(kept) and _NUMBER_WORD.match(kept[-1].lower()) is not None
        # chat spellings ("fwd", "rt") are words, not noise
        if bare in HESITATIONS or (_NOISE.match(bare) and bare not in VOCABULARY and bare not in TYPOS) \
                or (bare in _UNIT_SOUNDS and not after_number):
            _carry(kept, punct)
            continue
        nxt = tokens[i + 1].lower().strip(",.;:!?\"'") if i + 1 < len(tokens) else ""
        if bare.isalpha() and not punct and nxt.startswith(bare) and len(bare) < len(nxt) \
                and bare not in VOCABULARY:
            continue  # "tur turn", "l left": a false start of the next word
        if bare.isalpha() and not punct and bare == nxt and bare not in _REPEATABLE:
            continue  # "a a left", "the the door": a stutter
        kept.append(token)
    text = " ".join(kept)
    return _MARKER_INSIDE.sub(_break_before_marker, text)


def _break_before_marker(m: re.Match[str]) -> str:
    before = m.group("before")
    if before.lower().strip(",.;:!?") in _MARKER_LEAD or before.endswith(tuple(",.;:!?")):
        return m.group(0)
    return f"{before}, "


#: Words that may be said twice on purpose ("turn left, left": no; "very very slowly": harmless).
_REPEATABLE: Final = frozenset({"very", "no", "right"})  # "turn right right now": a side, then "right now"


def _carry(kept: list[str], punct: str) -> None:
    """A dropped token's comma stays with the word before it ("turn, uh, left")."""
    if punct and kept and not kept[-1].endswith(tuple(",.;:!?")):
        kept[-1] += punct
