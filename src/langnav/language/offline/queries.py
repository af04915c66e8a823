"""Clauses that are no trip to an element: questions the robot answers (pose, path, map), element
questions ("which is the largest room?"), exploration, and returning to where the prompt started."""

from __future__ import annotations

import re
from typing import Final

from langnav.language.intent import Detail, Element, ElementRef, Movement, Place, Query, Step
from langnav.language.offline import lexicon as lx
from langnav.language.offline.patterns import EXPLORE_RE, any_of
from langnav.language.offline.phrases import Phrase, find_phrases
from langnav.language.offline.reading import MIN_CONFIDENCE, UNREAD_WORD_FACTOR, Reading
from langnav.language.offline.scratch import Clause, Scratch

#: Where the prompt started: "to where you started", "to your starting point", "back to the start".
START_PLACE_RE: Final = re.compile(
    r"\b(?:(?:back\s+)?(?:to|towards?)\s+)?(?:where\s+(?:you|we|i)\s+(?:started(?:\s+from)?|began|set\s+off|came\s+from|"
    r"were(?:\s+before|\s+at\s+the\s+start|\s+at\s+first|\s+originally)?)|(?:the|your|our|my)\s+(?:very\s+)?"
    r"(?:start(?:ing)?(?:\s+(?:point|position|place|spot|pose|location))?|original\s+(?:position|spot|place|location|pose)|"
    r"initial\s+(?:position|pose|spot|place|location)|beginning|point\s+of\s+departure))\b")
#: A whole clause that only says to go back ("come back", "return", "head back again").
BARE_RETURN_RE: Final = re.compile(
    r"^(?:(?P<go>go|head|drive|move|walk|roll|navigate)|come|get|make\s+your\s+way|find\s+your\s+way|"
    r"(?P<ret>return))(?:\s+(?:all\s+the\s+way\s+)?back)?(?:\s+(?:home|again|now|there|where\s+you\s+came\s+from))?\s*$")
START_REF: Final = ElementRef(kind=Element.NONE, place=Place.START)
#: A question that names an element ("which is the largest room?", "where is the nearest door?").
ELEMENT_QUESTION_RE: Final = re.compile(
    r"^(?:(?:hey|ok|okay|so|robot)\s+)*(?:which|where|what)\b(?:\s+(?:is|are|one\s+is|one\s+of\s+them\s+is|"
    r"would\s+be|do\s+you\s+think\s+is))?")
QUERY_RES: Final = ((Query.POSE, any_of(lx.QUERY_POSE_PATTERNS)), (Query.MAP, any_of(lx.QUERY_MAP_PATTERNS)),
                     (Query.PATH, any_of(lx.QUERY_PATH_PATTERNS)))


def read_return(c: Clause) -> Reading | None:
    """'come back', 'return', 'go back' after a trip: back to where the prompt started. ('go back'
    as the first instruction is a move backward.)"""
    m = BARE_RETURN_RE.match(" ".join(c.s.masked().split()))
    if m is None:
        return None
    moved = c.previous is not None and c.previous.movement in (Movement.NAVIGATE, Movement.MOVE, Movement.FOLLOW,
                                                                 Movement.EXPLORE)
    if m.group("go") and "back" in c.s.masked() and not moved:
        return None  # "go back" with no trip before it: a move backward
    if m.group("go") and "back" not in c.s.masked():
        return None
    return Reading(steps=(Step(movement=Movement.NAVIGATE, detail=Detail.TO, target=START_REF, text=c.text[:500]),))


def question_referent(norm: str) -> ElementRef | None:
    """The one element a 'which / where / what is the X' question names, if it names exactly one."""
    if ELEMENT_QUESTION_RE.match(norm) is None:
        return None
    # "which room is the smallest" -> "which is the smallest room"
    norm = re.sub(r"^(which|what)\s+([a-z]+(?:\s+[a-z]+)?)\s+(?:is|are)\s+(?:the\s+)?([a-z]+)(\s+(?:one|of\s+them))?\s*$",
                  r"\1 is the \3 \2", norm)
    phrases, name = find_phrases(Scratch(norm), None)
    keep = [p for p in phrases if not p.contained and not p.pronoun]
    if name is not None or len(keep) != 1:
        return None
    return keep[0].ref


def read_query(c: Clause) -> Reading | None:
    norm = c.s.text
    if re.match(r"^\s*(?:go|drive|move|head|navigate|turn|rotate)\b", norm):
        return None
    for query, pattern in QUERY_RES:
        if pattern.search(norm):
            if query == Query.MAP and EXPLORE_RE.search(norm) and not re.search(r"\b(?:show|display|see|view)\b", norm):
                continue
            return Reading(steps=(Step(movement=Movement.QUERY, query=query, text=c.text),))
    return None


def read_explore(c: Clause, phrases: list[Phrase]) -> Reading | None:
    m = c.s.find(EXPLORE_RE)
    if m is None:
        return None
    if any(p.ref.kind == Element.UNEXPLORED_AREA for p in phrases):
        c.s.use(m.start(), m.end())
        c.explore_verb = True
        return None  # "explore the unknown area on your left": go towards it
    if any(p.ref.kind not in (Element.ROOM, Element.HALLWAY, Element.NONE) for p in phrases):
        return None  # "explore behind the box": read as a trip to the box
    leftovers = [w for w in c.s.leftover_words() if w not in lx.EXPLORE_SCOPE_WORDS and w not in lx.STOPWORDS]
    confidence = max(MIN_CONFIDENCE, UNREAD_WORD_FACTOR ** len(leftovers))
    return Reading(steps=(Step(movement=Movement.EXPLORE, text=c.text),),
                   unread=(" ".join(leftovers),) if leftovers else (), confidence=round(confidence, 3))
