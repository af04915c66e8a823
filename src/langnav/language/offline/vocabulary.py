"""Every word the offline reading knows, as one set: what typo repair aims at and what the speech
clean-up never drops."""

from __future__ import annotations

from typing import Final

from langnav.language.offline import lexicon as lx
from langnav.language.offline.numbers import ANGLE_UNITS_DEG, LENGTH_UNITS_M, ONES, TENS, TURN_NOUNS
from langnav.language.offline.phrases import KNOWN_WORDS

#: Compass points (README "Compass": east is +x, north +y).
COMPASS_WORDS: Final = frozenset({"north", "south", "east", "west", "northeast", "northwest", "southeast",
                                  "southwest", "due"})
#: Everyday words of requests that are no part of any table but are real words, not typos.
_COMMON: Final = frozenset({
    "picture", "pictures", "photo", "photos", "image", "images", "camera", "visual", "see", "show", "tell",
    "send", "take", "give", "what", "clockwise", "counterclockwise", "anticlockwise", "counter", "anti",
    "sideways", "more", "another", "further", "again", "feet", "foot", "inch", "inches", "yard", "yards",
    "half", "quarter", "hundred", "thousand", "and", "or", "not", "no", "yes", "actually", "sorry", "wait",
    "mean", "meant", "rather", "never", "mind", "nevermind", "okay", "ok", "thanks", "thank", "please",
    "circle", "around", "round", "full", "complete", "about", "least", "most", "until", "stop",
})

VOCABULARY: Final = frozenset(
    KNOWN_WORDS | COMPASS_WORDS | _COMMON | set(ONES) | set(TENS) | set(TURN_NOUNS)
    | {w for unit in (*LENGTH_UNITS_M, *ANGLE_UNITS_DEG) for w in unit.split()}
    | {w for phrase in (*lx.TYPO_TARGETS, *lx.NOT_TYPOS, *lx.GO_VERBS, *lx.ROTATE_VERBS, *lx.STOP_PHRASES)
       for w in phrase.split()})
