"""Speech that is not addressed to the robot, taken out before a prompt is split.

People talk to a robot while doing other things: they narrate notes ("water line about eighteen inches
on this wall, okay, go forward three feet"), answer someone else ("sorry, one second, bed twelve is
calling, okay, back up two feet"), speak to a child by name ("robot turn left, no, jack, sit down, turn
left forty five degrees"), comment ("..., she's asking about the robot") or count in ("five, six, seven,
eight, step forward"). A person listening would not take any of it as an instruction to the robot:

1. **Before a re-opening word.** Talk that opens the utterance (or a new sentence) and gives no
   instruction -- no verb of motion, no stop, no way, no place to go to -- followed by a word that turns
   back to the robot ("okay", "alright", "noted", "robot,") is talk to someone else or a note.
2. **A statement about someone or something else** ("she's asking about the robot", "they're napping next
   door", "drywall is soft here"): a clause with its own subject and verb that names no way, no amount
   and not the robot ("you") says how things are, it asks nothing; a "sorry" or "no" right before it
   apologises for the interruption, it corrects nothing.
3. **A name said to someone else** ("jack, sit down"; "no, sam, leave it"; "ava, hands off"): a single
   word the reading does not know, set off by pauses, followed by words with no way, no amount, no place
   and no stop, is a person addressed by name and what is said to them.
5. **A note about a place** ("scuff marks all along this wall, fine. go to ..."; "water damage by the door,
   noted."): a thing of the speaker's own (words the reading does not know) said with where it is, and no
   verb, no way and no amount, is a verbless statement of what is there, not a trip: before a word that turns
   back to the robot it is dropped as rule 1 drops talk.
6. **A shout** ("corner!", "door!" with an instruction after it): a single word called out with an
   exclamation, as kitchen and workshop staff warn each other where they are, is a warning to the people
   around, not a place to go to; an instruction after it is the request. Alone, it is asked about (a
   warning or a place?); one holding a way ("behind!") is kept, as all talk with a way is.
4. **A count-in** ("five, six, seven, eight"; "three, two, one"; "five six seven eight,"): numbers said one
   by one in steps of one count time, they measure nothing.

Ask, don't guess, still holds: talk that holds a way, a place to go to ("to / into / through the door") or
a stop is never dropped (a listener could not tell it is not meant for the robot; a note of where a thing
is, rule 5, and a one-word shout, rule 6, are the only talk with a place that is), and an amount is dropped only in talk that opens the
utterance before a re-opening word (where nothing before it could take it). What is left is read as
usual, and anything it leaves unclear is asked about.
"""

from __future__ import annotations

import re
from functools import lru_cache
from typing import Final

from langnav.language.offline import lexicon as lx
from langnav.language.offline.corrections import CANCEL_RE, CORRECTION_START_RE
from langnav.language.offline.normalize import normalize as _normalize
from langnav.language.offline.numbers import ONES, TENS, find_quantities
from langnav.language.offline.patterns import (
    BOAT_SIDE_WORDS,
    GO_VERB_RE,
    MOVE_WAY_WORDS,
    ROTATE_VERB_RE,
    STOP_RE,
    TURN_SIDE_WORDS,
)
from langnav.language.offline.vocabulary import VOCABULARY

#: One stretch of speech between pauses, with the marks that end it.
_SEGMENT_RE: Final = re.compile(r"[^,.;!?]+(?:[,.;!?]+|$)")
#: Marks that end a sentence (a new sentence may open with a note).
_SENTENCE_END: Final = frozenset(".;!?")
#: Words that turn the talk back to the robot.
_REOPEN_RE: Final = re.compile(r"^\s*(?:ok(?:ay)?|alright|all\s+right|noted|anyway|anyhow|robot|rover|fine)\b", re.IGNORECASE)
#: Words that say which way (any of them keeps the talk: it may be meant for the robot).
_WAY_RE: Final = re.compile(
    rf"\b(?:{TURN_SIDE_WORDS}|{MOVE_WAY_WORDS}|{BOAT_SIDE_WORDS}|around|round|north\w*|south\w*|east|west|sideways|"
    r"reverse|behind|o'?clock|turn\w*|spin\w*)\b", re.IGNORECASE)
#: A place named as where to go ("to the door", "through the gap").
_PLACE_RE: Final = re.compile(
    r"\b(?:to|into|through|towards?|past|along|at|near|by|from)\s+(?:the\s+|a\s+|this\s+|that\s+|your\s+)?"
    r"(?:\w+\s+){0,2}?(?:" + "|".join(sorted(map(re.escape, lx.ELEMENT_NOUNS), key=len, reverse=True)) + r")\b",
    re.IGNORECASE)
#: Questions the robot answers, and requests for its map, path or position.
_QUERY_RE: Final = re.compile(r"\b(?:where|map|path|route|position|location|report|explore\w*)\b", re.IGNORECASE)
#: A clause with a subject of its own and a verb ("she's asking", "bed twelve is calling", "drywall is soft").
_STATEMENT_RE: Final = re.compile(
    r"^\s*(?:(?:and|but|oh)\s+)?(?!(?:where|what|which|who|how|why|when|is|are|can|could|would|will|do|does|let|here)\b)"
    r"(?:[a-z]+\s+){0,2}?[a-z]+(?:'s|'re|\s+(?:is|are|was|were|looks|seems|wants|want|needs|says|said|has|have))\b",
    re.IGNORECASE)
#: The robot addressed ("you", "your"): a statement about the robot may ask something of it.
_YOU_RE: Final = re.compile(r"\b(?:you|your|yourself|u|ur)\b", re.IGNORECASE)
#: An apology or a "no" said alone right before talk to someone else belongs to that talk.
_LEAD_RE: Final = re.compile(r"^\s*(?:sorry|no|oh|oops|(?:one|a|just\s+a)\s+(?:second|sec|moment|minute))\s*$",
                             re.IGNORECASE)
_NUMBER_VALUES: Final = {**ONES, **TENS}
#: Sounds said while thinking or in surprise ("um", "uhh", "hmm", "erm", "ah", "oh"): no name.
_SOUND_RE: Final = re.compile(lx.HESITATION_SOUNDS + r"|u+[hm]+|h+m+|e+r+m*|a+h+|o+h+|m+h?m+|e+h+|huh|phew|hmph|oops|whoops"
                              r"|wow|ooh|aw+")
#: What people call the robot (and radio call words): the robot addressed, not someone else.
_ROBOT_NAMES: Final = frozenset({*lx.ROBOT_NAMES, "rover", "bot", "unit", "base", "scout", "pal"})
#: A count-in has at least this many numbers (two may be an amount said again: "four, four metres").
MIN_COUNT_IN: Final = 3


def without_side_talk(text: str) -> str:
    """``text`` without the talk that is not addressed to the robot (module docstring)."""
    segments = _SEGMENT_RE.findall(text)
    if len(segments) < 2:
        return text
    drop = [False] * len(segments)
    bodies = [s.strip().rstrip(",.;!?").strip() for s in segments]
    instructs = [_instructs(b) and not _note_about_place(b) for b in bodies]
    _before_reopening(segments, bodies, instructs, drop)
    _statements(bodies, instructs, drop)
    _vocatives(bodies, drop)
    _count_ins(bodies, drop)
    _shouts(segments, bodies, instructs, drop)
    if all(drop) or not any(drop):
        return text
    kept = [s for s, d in zip(segments, drop, strict=True) if not d]
    return " ".join(" ".join(kept).split())


def without_spoken_count_in(text: str) -> str:
    """``text`` without a count-in said with no pauses between its numbers ("five six seven eight, turn left"),
    before the numbers are read: read as one number, it would be 5678 (rule 4 finds the others later)."""
    segments = _SEGMENT_RE.findall(text)
    kept = [seg for k, seg in enumerate(segments) if k + 1 == len(segments) or not _counted(seg)]
    return text if len(kept) == len(segments) else " ".join(" ".join(kept).split())


def _counted(segment: str) -> bool:
    words = segment.strip().rstrip(",.;!?").lower().split()
    said = [_NUMBER_VALUES.get(w) for w in (words[1:] if words[:1] == ["and"] else words)]
    return len(said) >= MIN_COUNT_IN and all(_counts_on(said, 0, m) for m in range(len(said) - 1))


@lru_cache(maxsize=1024)
def normalize(text: str) -> str:
    """The reading's normalised words of a stretch (each stretch is looked at by several rules)."""
    return _normalize(text)


def _instructs(body: str) -> bool:
    """Whether the words may ask something of the robot: a verb of motion, a stop, a way, a place to go
    to, or a question it answers."""
    norm = normalize(body)
    # verbs as said (with the known misspellings): the typo repair that helps read an instruction would make
    # verbs of other words ("sand" -> "stand"); ways, stops and places are looked for in the repaired words
    said = " ".join(lx.TYPOS.get(w, w) for w in body.lower().split())
    return bool(GO_VERB_RE.search(said) or ROTATE_VERB_RE.search(said) or STOP_RE.search(norm)
                or _WAY_RE.search(norm) or _PLACE_RE.search(norm) or _QUERY_RE.search(norm))


def _note_about_place(body: str) -> bool:
    """Rule 5: words the reading does not know (a thing), then where it is, and nothing that instructs."""
    norm = normalize(body)
    place = _PLACE_RE.search(norm)
    if place is None or place.start() == 0:
        return False
    said = " ".join(lx.TYPOS.get(w, w) for w in body.lower().split())
    if GO_VERB_RE.search(said) or ROTATE_VERB_RE.search(said) or STOP_RE.search(norm) or _WAY_RE.search(norm) \
            or _QUERY_RE.search(norm) or _has_amount(body):
        return False
    before = norm[:place.start()].split()
    if place.group(0).split()[0].lower() in _GOING_TO:
        return False  # "hurry to the door": where something goes is a trip, never a note of where a thing is
    thing = [w for w in before if w not in lx.STOPWORDS and w != "all"]
    return bool(thing) and not any(_known(w) for w in thing)


#: Words that say where something goes ("to", "into", "through"), not where a thing is ("by", "along", "on").
_GOING_TO: Final = frozenset({"to", "into", "through", "towards", "toward", "past", "from"})


def _has_amount(body: str) -> bool:
    norm = normalize(body)
    return bool(find_quantities(norm)) or any(w in _NUMBER_VALUES for w in norm.split())


def _before_reopening(segments: list[str], bodies: list[str], instructs: list[bool], drop: list[bool]) -> None:
    """Rule 1: talk with no instruction, opening the utterance or a sentence, before a word that turns back
    to the robot (and an instruction after it)."""
    for i in range(1, len(segments)):
        if _REOPEN_RE.match(bodies[i]) is None or not any(instructs[i:]):
            continue
        start = i
        while start > 0 and not instructs[start - 1]:
            start -= 1  # the talk with no instruction right before the re-opening word
        # it must open the utterance or a sentence: talk after an instruction, in the same sentence, may go
        # on from it ("move forward, two metres, okay")
        while 0 < start < i and segments[start - 1].rstrip()[-1:] not in _SENTENCE_END:
            start += 1
        if start == i or (start > 0 and any(_has_amount(b) for b in bodies[start:i])):
            continue  # (an amount in a new sentence after an instruction may still complete it)
        for k in range(start, i):
            drop[k] = True


def _statements(bodies: list[str], instructs: list[bool], drop: list[bool]) -> None:
    """Rule 2: a statement about someone or something else, with no way, no amount and no "you"."""
    if not any(instructs):
        return
    for i, body in enumerate(bodies):
        if (_STATEMENT_RE.match(body) and not instructs[i] and not _has_amount(body)
                and _YOU_RE.search(body) is None):
            drop[i] = True
            if i > 0 and _LEAD_RE.match(bodies[i - 1]):
                drop[i - 1] = True


def _vocatives(bodies: list[str], drop: list[bool]) -> None:
    """Rule 3: a person named alone between pauses, and what is said to them."""
    for i in range(len(bodies) - 1):
        word = bodies[i].lower()
        if not re.fullmatch(r"[a-z]{2,}", word) or _known(word):
            continue
        said = bodies[i + 1]
        norm = normalize(said)
        if (_has_amount(said) or _WAY_RE.search(norm) or _PLACE_RE.search(norm) or STOP_RE.search(norm)
                or _QUERY_RE.search(norm) or CORRECTION_START_RE.match(norm) or CANCEL_RE.search(norm)
                or any(noun in norm.split() for noun in lx.ELEMENT_NOUNS)):
            continue  # (what follows may be meant for the robot, or put right what was said to it)
        drop[i] = drop[i + 1] = True
        if i > 0 and _LEAD_RE.match(bodies[i - 1]):
            drop[i - 1] = True


def _known(word: str) -> bool:
    """A word the reading knows, or one it would repair into a known word (a typo, not a name)."""
    fixed = normalize(word)
    return (_SOUND_RE.fullmatch(word) is not None or CORRECTION_START_RE.match(word) is not None
            or _REOPEN_RE.match(word) is not None or word in _ROBOT_NAMES or word in VOCABULARY or word in lx.STOPWORDS or fixed != word or word in _NUMBER_VALUES
            or GO_VERB_RE.search(word) is not None or ROTATE_VERB_RE.search(word) is not None)


def _count_ins(bodies: list[str], drop: list[bool]) -> None:
    """Rule 4: numbers said one by one in steps of one ("five, six, seven, eight")."""
    values: list[int | None] = []
    for body in bodies:
        words = normalize(body).split()
        if words and words[0] == "and":
            words = words[1:]
        values.append(_NUMBER_VALUES.get(words[0]) if len(words) == 1 else None)
    i = 0
    while i < len(values):
        j = i
        while j + 1 < len(values) and _counts_on(values, i, j):
            j += 1
        if values[i] is not None and j - i + 1 >= MIN_COUNT_IN and j + 1 < len(values):
            for k in range(i, j + 1):
                drop[k] = True  # (a count-in precedes what it counts in: one at the very end is left as said)
        i = j + 1


def _shouts(segments: list[str], bodies: list[str], instructs: list[bool], drop: list[bool]) -> None:
    """Rule 6: one word called out with "!" before an instruction."""
    for i in range(len(segments) - 1):
        if any(instructs[i + 1:]) and is_shout(segments[i]):
            drop[i] = True


def is_shout(segment: str) -> bool:
    """One word called out with "!" that holds no way, no amount and no stop ("corner!"): a warning (rule 6).
    Alone, a listener cannot tell a warning from a place to go to, so the reading asks."""
    body = segment.strip().rstrip(",.;!?").strip()
    norm = normalize(body)
    return ("!" in segment and len(body.split()) == 1 and not _has_amount(body) and STOP_RE.search(norm) is None
            and _WAY_RE.search(norm) is None)


def _counts_on(values: list[int | None], first: int, last: int) -> bool:
    """Whether the number after ``values[last]`` goes on the count begun at ``first`` (one up or one down,
    the same way throughout)."""
    a, b = values[last], values[last + 1]
    if a is None or b is None or abs(b - a) != 1:
        return False
    before = values[last - 1] if last > first else None
    return before is None or b - a == a - before
