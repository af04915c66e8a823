"""Places the map cannot know ("the kitchen", "the desk"): a step to them if the user named them
before, otherwise a question; colours and materials ("the red door") cannot be told apart."""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import Final

from langnav.language.intent import Detail, Element, ElementRef, Movement, Step
from langnav.language.offline import lexicon as lx
from langnav.language.offline.details import as_detail
from langnav.language.offline.phrases import KNOWN_WORDS
from langnav.language.offline.reading import NAME_CONFIDENCE, Problem, Reading
from langnav.language.offline.scratch import Clause
from langnav.places.store import place_key

_NAME_DETAIL_RE: Final = re.compile(lx.phrase_regex(lx.DETAIL_PHRASES, "detail")
                                     + r"\s+(?:(?:the|a|an|my|our|your)\s+)?$")
_DESTINATION_RE: Final = re.compile(
    r"\b(?:to|towards?|into|next\s+to|beside|near|through|at|by|reach|enter|approach|visit|find)\s+"
    r"(?:the\s+|a\s+|an\s+|my\s+|our\s+|your\s+)?(?P<name>[a-z][\w']*(?:\s+[a-z][\w']*)?)")


def unknown_destination(masked: str) -> str | None:
    """The unknown word(s) after 'to the' in a clause with no element: a place name."""
    for m in _DESTINATION_RE.finditer(masked):
        words = m.group("name").split()
        if words[0] in KNOWN_WORDS or words[0] in lx.EXPLORE_SCOPE_WORDS:
            continue  # (a word of the map's elements, or of the whole place: "the entrance of the building")
        if len(words) > 1 and words[1] in KNOWN_WORDS:
            words = words[:1]
        return " ".join(words)
    return None


#: A place named as the landmark of another one: "the room next to THE KITCHEN", "the room across the hall
#: from THE BATHROOM", "the door by THE FRIDGE". The word after the determiner is the landmark's name.
#: A place may also be named by a thing it holds: "the room WITH THE SOFA", "the room that has a piano in it",
#: "the room where the printer is": the grid shows no furniture by name, so which room is meant is a guess.
#: So is a place named by whom it belongs to or serves: "the room OF THE BABIES", "the room FOR THE STAFF".
_LANDMARK_RE: Final = re.compile(
    r"\b(?:(?:next\s+to|beside|near|by|from|opposite|behind|past|beyond)\s+(?:the|my|our|your)"
    # a place named by whom or what it belongs to or serves ("the room of the babies", "the room for the staff")
    r"|(?:of|for|belonging\s+to)\s+(?:the|my|our|your)"
    r"|(?:with|containing|(?:that|which)\s+(?:has|have|holds|contains)|where)\s+(?:the|my|our|your|a|an|some))\s+"
    r"(?P<name>[a-z][\w']*(?:\s+[a-z][\w']*)?)")


def unknown_landmark(masked: str, known_names: Sequence[str] = ()) -> str | None:
    """The unknown word(s) naming the landmark of an element ("the room next to the kitchen") when the user
    has not named such a place: the map cannot know it, so which element is meant cannot be told (asked,
    not guessed)."""
    known = {place_key(n) for n in known_names}
    for m in _LANDMARK_RE.finditer(masked):
        words = m.group("name").split()
        if words[0] in KNOWN_WORDS or words[0] in lx.EXPLORE_SCOPE_WORDS:
            continue  # (a word of the map's elements, or of the whole place: "the entrance of the building")
        if len(words) > 1 and words[1] in KNOWN_WORDS:
            words = words[:1]
        if any(place_key(" ".join(words[:k])) in known for k in range(1, len(words) + 1)):
            return None
        return " ".join(words)
    return None


def named(c: Clause, name: str, known_names: Sequence[str]) -> Reading:
    """A place the map cannot know: a step to it if the user named it before, else a question."""
    clean = re.sub(r"^(?:the|a|an|my|our)\s+", "", name).strip()
    known = {place_key(n): n for n in known_names}  # the one rule for names (langnav.places)
    if place_key(clean) in known:
        detail = Detail.TO
        m = _NAME_DETAIL_RE.search(c.s.text[:c.s.text.find(clean.split()[0])] if clean else "")
        if m is not None:
            detail = as_detail(lx.lookup(lx.DETAIL_PHRASES, m.group("detail")))
        ref = ElementRef(kind=Element.NONE, name=known[place_key(clean)][:80])
        return Reading(steps=(Step(movement=Movement.NAVIGATE, detail=detail, target=ref, text=c.text[:500]),))
    if any(w in lx.UNKNOWABLE_ADJECTIVES for w in clean.split()[:-1]):
        # "the red door": a real element described by what a grid cannot show
        return Reading(confidence=NAME_CONFIDENCE, problem=Problem.UNKNOWABLE, name=clean[:80], unread=(c.text,))
    return Reading(confidence=NAME_CONFIDENCE, problem=Problem.NAME, name=clean[:80], unread=(c.text,))
