"""Steps to elements: go to / through / along them, stop at them ("stop after you pass through it")."""

from __future__ import annotations

import re
from typing import Final

from langnav.language.intent import Detail, Element, ElementRef, Movement, Side, Step
from langnav.language.offline import lexicon as lx
from langnav.language.offline.details import fit_detail
from langnav.language.offline.numbers import find_quantities
from langnav.language.offline.phrases import Phrase, as_landmark
from langnav.language.offline.reading import WEAK_WORD_FACTOR
from langnav.language.offline.scratch import Clause
from langnav.language.offline.verbs import Verb

_LEAVING_VERBS: Final = frozenset({"exit", "leave", "get out of", "go out of", "exit from", "leave through",
                                   "exit through"})
_PASSED_RE: Final = re.compile(r"\b(?:after|once|when|as\s+soon\s+as)\b.*\b(?:through|past|passed|beyond|"
                               r"cleared|crossed|exit)\b")


def ref_step(c: Clause, p: Phrase, movement: Movement = Movement.NAVIGATE,
              default: Detail | None = None) -> Step:
    detail = p.detail
    if detail is None and default is not None:
        detail = default
    if detail is None and c.previous is not None and p.pronoun is False and c.previous.detail is not None \
            and c.previous.movement == Movement.NAVIGATE and c.elliptical:
        detail = c.previous.detail  # "go through the first door, then the second one"
    kind = p.ref.kind
    fitted = fit_detail(detail, kind)
    target = p.ref
    leaving = p.detail_from_verb in _LEAVING_VERBS or (
        p.detail_from_verb is None and re.search(r"\bout\s+of\b", c.s.text) is not None)
    if leaving and detail == Detail.THROUGH and kind in lx.CONTAINER_KINDS:
        # leaving a room or hallway: through a door of the space the robot is in
        target = ElementRef(kind=Element.DOOR, in_current_room=True)
        fitted = Detail.THROUGH
    if p.weak:
        c.doubt(WEAK_WORD_FACTOR)
    if p.detail_from_verb == "take" and kind in lx.THROUGH_KINDS:
        c.doubt(WEAK_WORD_FACTOR)  # "take the door": to it or through it (README); through chosen
    c.lost.extend(p.lost)
    if fitted == Detail.ALONG and movement == Movement.NAVIGATE:
        movement = Movement.FOLLOW
    second = p.second.ref if p.second is not None else None
    if fitted == Detail.BETWEEN and second is None and not p.pair:
        fitted = Detail.MIDDLE if kind in (Element.ROOM, Element.HALLWAY) else Detail.TO
    if detail == Detail.BETWEEN and second is None and p.pair and kind in (Element.ROOM, Element.HALLWAY):
        fitted = Detail.BETWEEN
    return Step(movement=movement, detail=fitted, target=target, second_target=second, text=c.text[:500])


def navigate_steps(c: Clause, targets: list[Phrase], verb: Verb) -> list[Step]:
    c.elliptical = verb == Verb.NONE
    _infer_side_from_direction(c, targets[0])
    steps: list[Step] = []
    kept = _destinations(targets)
    for p in kept:
        steps.append(ref_step(c, p))
    for p in targets:
        if p not in kept:
            c.s.use(p.start, p.end)
    _discard_quantities(c)
    return steps


def _destinations(targets: list[Phrase]) -> list[Phrase]:
    """Elements that are places to go, in order. A route ('down the hallway to the door') is dropped
    when a destination follows it; an element right after another with 'next to' qualifies it."""
    kept: list[Phrase] = []
    for i, p in enumerate(targets):
        later = targets[i + 1:]
        if p.detail in (Detail.ALONG,) and any(q.detail in (Detail.TO, Detail.NEXT_TO, Detail.STOP_AT,
                                                               Detail.MIDDLE) for q in later):
            continue
        if p.detail == Detail.THROUGH and p.ref.kind == Element.HALLWAY and later:
            continue
        if p.detail == Detail.THROUGH and p.ref.kind in lx.CONTAINER_KINDS and _plain_space(p.ref) and later \
                and later[0].detail == Detail.THROUGH and later[0].ref.kind in lx.THROUGH_KINDS and not later[0].pronoun:
            # "leave the room through the door", "drive out of this room through the door": the door is the
            # way out of the room the robot is in; one step, not a second door from outside the room
            if later[0].ref.label is None and later[0].ref.near is None:
                later[0].ref = later[0].ref.model_copy(update={"in_current_room": True})
            continue
        if p.bare_prep and p.detail == Detail.NEXT_TO and kept and kept[-1].ref.near is None \
                and not p.pronoun and p.ref.kind != Element.NONE and p.ref.kind != kept[-1].ref.kind:
            kept[-1].ref = kept[-1].ref.model_copy(update={"near": as_landmark(p.ref)})
            continue  # "the door next to the box": the box only tells which door
        if p.bare_prep and p.detail in (Detail.NEXT_TO, Detail.BETWEEN) and kept:
            kept[-1].lost.append(f"{p.detail.value.replace('_', ' ')} the {p.ref.kind.value.replace('_', ' ')}")
            continue
        if p.detail == Detail.OPPOSITE_SIDE_OF and any(
                q.detail == Detail.ALONG and q.ref.kind == p.ref.kind for q in kept) and p.ref.ordinal is None \
                and p.ref.superlative is None and p.ref.side is None:
            continue  # "follow the wall until you reach the end of the wall": the end of the same run
        if p.detail is None and p.pronoun is False and kept and kept[-1].detail is not None \
                and kept[-1].detail not in (Detail.BETWEEN,):
            p.detail = kept[-1].detail  # "go to the door and the box" (two places)
        kept.append(p)
    return kept


def _plain_space(ref: ElementRef) -> bool:
    """"The room", "this room": the space the robot is in, with no words that pick another."""
    return (ref.ordinal is None and ref.side is None and ref.superlative is None and ref.label is None
            and ref.name is None and ref.relation is None and ref.near is None)


def _infer_side_from_direction(c: Clause, first: Phrase) -> None:
    """'go forward to the wall': the wall ahead; 'go left through the door': the door on the left."""
    m = c.s.find(re.compile(r"\b(?P<dir>forwards?|ahead|left|right)\b"))
    if m is None:
        return
    c.s.use(m.start(), m.end())
    if first.ref.side is not None or first.pronoun:
        return
    side = {"forward": Side.AHEAD, "forwards": Side.AHEAD, "ahead": Side.AHEAD, "left": Side.LEFT,
            "right": Side.RIGHT}[m.group("dir")]
    if first.ref.kind in (Element.ROOM, Element.HALLWAY, Element.UNEXPLORED_AREA, Element.DOOR,
                          Element.NARROW_PASSAGE, Element.OBSTACLE, Element.WALL, Element.CORNER):
        first.ref = first.ref.model_copy(update={"side": side})


def _discard_quantities(c: Clause) -> None:
    """Numbers in a navigation ('go 2 m past the door') cannot be kept: they stay unread."""
    for q in find_quantities(c.s.masked()):
        c.lost.append(c.s.masked()[q.start:q.end].strip())
        c.s.use(q.start, q.end)


def stop_steps(c: Clause, targets: list[Phrase]) -> list[Step]:
    """'stop', 'stop at the door', 'stop just after you pass through it', 'stop there'."""
    stop = Step(movement=Movement.STOP, text=c.text[:500])
    explicit = [p for p in targets if not p.pronoun]
    passed = _PASSED_RE.search(c.s.text) is not None
    if not explicit:
        for p in targets:
            c.s.use(p.start, p.end)
        pronoun = next((p for p in targets if p.pronoun and p.ref.kind in lx.THROUGH_KINDS), None)
        if passed and pronoun is not None:
            # "... and stop just after you pass through it": through that door, then stop
            prev = c.previous
            if prev is not None and prev.movement == Movement.NAVIGATE and prev.target == pronoun.ref:
                c.through_previous = True
            else:
                pronoun.detail = Detail.THROUGH
                c.s.take_all(re.compile(r"\b(?:after|once|when|as\s+soon\s+as|you|pass|passed|passing|going|driving|getting|are|have|get|got|"
                                        r"through|past|beyond|cleared|crossed|just|right|immediately|exit|exited)\b"))
                return [ref_step(c, pronoun), stop]
        c.s.take_all(re.compile(r"\b(?:after|once|when|as\s+soon\s+as|you|pass|passed|passing|going|driving|getting|are|have|get|got|"
                                r"through|past|beyond|cleared|crossed|reach|reached|arrive|arrived|"
                                r"right|immediately|just|behind|exit|exited)\b"))
        return [stop]
    p = explicit[0]
    if passed:
        c.s.take_all(re.compile(r"\b(?:after|once|when|as\s+soon\s+as|you|pass|passed|passing|going|driving|getting|are|have|get|got|"
                                r"through|past|beyond|cleared|crossed|just|right|immediately|exit|exited)\b"))
        p.detail = Detail.THROUGH
        return [ref_step(c, p), stop]
    c.s.take_all(re.compile(r"\b(?:when|once|as\s+soon\s+as|you|reach|get|are|arrive|at)\b"))
    detail = p.detail if p.detail not in (None, Detail.TO) else Detail.STOP_AT
    p.detail = detail
    return [ref_step(c, p)]
