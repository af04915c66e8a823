"""The movement detail of each element (to, through, along, between ...), from the words before it
or the verb ("cross", "follow"), made to fit the element's kind."""

from __future__ import annotations

import re
from typing import Final

from langnav.language.intent import Detail, Element
from langnav.language.offline import lexicon as lx
from langnav.language.offline.patterns import rx
from langnav.language.offline.phrases import Phrase
from langnav.language.offline.scratch import Scratch

_DETAIL_AT_END_RE: Final = re.compile(lx.phrase_regex(lx.DETAIL_PHRASES, "detail") + r"\s*$")
_VERB_DETAIL_RE: Final = rx(lx.VERB_DETAILS, "verb")
_VERB_DETAIL_AT_END_RE: Final = re.compile(lx.phrase_regex(lx.VERB_DETAILS, "verb") + r"\s*$")


def assign_details(s: Scratch, phrases: list[Phrase], clause_start: int) -> None:
    """The detail of each element, from the words just before it (or the verb of the clause)."""
    boundary = clause_start
    for p in phrases:
        region = s.masked()[boundary:p.start]
        m = _VERB_DETAIL_AT_END_RE.search(region) or _DETAIL_AT_END_RE.search(region)
        if m is not None:
            key = m.group("verb") if "verb" in m.groupdict() and m.group("verb") else m.group("detail")
            table = lx.VERB_DETAILS if m.re is _VERB_DETAIL_AT_END_RE else lx.DETAIL_PHRASES
            p.detail = as_detail(lx.lookup(table, key))
            if " ".join(key.split()) in lx.ENTERING_WORDS and p.ref.kind in lx.THROUGH_KINDS:
                p.detail = Detail.THROUGH  # into a doorway is through it (``lx.ENTERING_WORDS``)
            if table is lx.VERB_DETAILS:
                p.detail_from_verb = " ".join(key.split())
            s.use(boundary + m.start(), boundary + m.end())
            p.bare_prep = boundary > clause_start and region[:m.start()].strip() == ""
        else:
            v = _VERB_DETAIL_RE.search(region)
            if v is not None:
                p.detail = as_detail(lx.lookup(lx.VERB_DETAILS, v.group("verb")))
                if " ".join(v.group("verb").split()) in lx.ENTERING_WORDS and p.ref.kind in lx.THROUGH_KINDS:
                    p.detail = Detail.THROUGH
                p.detail_from_verb = " ".join(v.group("verb").split())
                s.use(boundary + v.start(), boundary + v.end())
        boundary = p.second.end if p.second is not None else p.end


def as_detail(value: object) -> Detail:
    if not isinstance(value, Detail):
        raise TypeError(f"lexicon entry {value!r} is not a Detail")
    return value


def fit_detail(detail: Detail | None, kind: Element) -> Detail:
    """Make the detail fit the element (see the module docstring)."""
    d = detail or Detail.TO
    if d == Detail.TO and kind == Element.UNEXPLORED_AREA:
        return Detail.TOWARDS
    if d == Detail.THROUGH and kind == Element.ROOM:
        return Detail.OPPOSITE_SIDE_OF
    if d == Detail.THROUGH and kind == Element.HALLWAY:
        return Detail.ALONG
    if d == Detail.THROUGH and kind not in lx.THROUGH_KINDS:
        return Detail.OPPOSITE_SIDE_OF if kind == Element.OBSTACLE else Detail.TO
    if d == Detail.OPPOSITE_SIDE_OF and kind in lx.THROUGH_KINDS:
        return Detail.THROUGH
    if d == Detail.ALONG and kind not in (Element.WALL, Element.HALLWAY, Element.NARROW_PASSAGE):
        return Detail.NEXT_TO if kind == Element.OBSTACLE else Detail.TO
    if d == Detail.MIDDLE and kind not in (Element.ROOM, Element.HALLWAY, Element.NARROW_PASSAGE,
                                           Element.UNEXPLORED_AREA):
        return Detail.TO
    return d
