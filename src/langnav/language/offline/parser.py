"""Read one instruction (a step of a prompt) into :class:`~langnav.language.intent.Step` s: the
stages, in order, each in its own module under ``language/offline/``.

The reading marks every word it uses (``scratch``); the words left over (minus harmless function
words) are "unread" and lower the confidence (``reading``). Stages, each consuming its words:

1. ``normalize``: case, symbols, contractions, typos;
2. ``queries``: questions the robot answers (where are you, what path, show the map), element
   questions, exploration, returning to the start;
3. ``refusals``: other floors, negation ("don't ..."), unanswerable questions, requests the robot
   cannot do ("pick up the cup"), times instead of distances;
4. ``patterns``: politeness and filler are taken;
5. ``phrases``: elements, noun phrases with their properties ("the second door on your left", "the
   left wall of the hallway", "between the box and the wall", "it", "the next one"); ``names``:
   places the map cannot know;
6. ``details``: the movement detail of each element (the words before it, or the verb);
7. ``verbs``: the main verb; then the step is built by ``navigation`` (to elements, stop),
   ``turns`` or ``moves`` (numbers with units from ``numbers``, "a little", directions);
8. this module: what is left unread, and whether it makes the reading a misreading.

Conventions the grounding relies on (documented here because the intent schema cannot say them):

* ``in_current_room`` is set only by words ("this room", "the room you're in", "here"); a corner
  or wall with no room named is left to the grounding (README: a corner of the robot's room).
* "of / in the room" sets ``within=ROOM``; "of the hallway" ``within=HALLWAY``; "of / in this
  room" sets ``in_current_room`` instead.
* "between the two obstacles" is ``target`` = obstacle and no ``second_target``.
* "to" an unexplored area is read as ``towards`` (nobody can stand in unknown space); "through" a
  room is its opposite side, "through" a hallway is along it; "the other side of" a door or narrow
  passage is through it; leaving a room or hallway is through a door of the space the robot is in.
* "turn around" is direction ``around`` with 180 degrees; "turn left" alone is ``Amount.DEFAULT``.
* A move with no number and no "a bit" gets ``Amount.DEFAULT`` (and a lower confidence).
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import Final

from langnav.language.intent import (
    Amount,
    Detail,
    Direction,
    Element,
    ElementRef,
    Movement,
    Step,
)
from langnav.language.offline import lexicon as lx
from langnav.language.offline.clock import clock_steps
from langnav.language.offline.compass import compass_steps
from langnav.language.offline.details import assign_details
from langnav.language.offline.idioms import named_turn_alone
from langnav.language.offline.moves import move_steps
from langnav.language.offline.names import named, unknown_destination, unknown_landmark
from langnav.language.offline.navigation import navigate_steps, stop_steps
from langnav.language.offline.normalize import normalize
from langnav.language.offline.numbers import NUMBER_WORD_LIST, NUMBER_WORDS, find_quantities
from langnav.language.offline.patterns import (
    BOAT_SIDE_WORDS,
    EXPLORE_RE,
    FILLER_RE,
    GO_VERB_RE,
    LATE_FILLER_RE,
    MOVE_DIR_RE,
    STOP_RE,
    TURN_SIDE_WORDS,
)
from langnav.language.offline.phrases import Phrase, find_phrases
from langnav.language.offline.queries import (
    START_PLACE_RE,
    START_REF,
    question_referent,
    read_explore,
    read_query,
    read_return,
)
from langnav.language.offline.reading import (
    BEARING_RE,
    ELLIPSIS_FACTOR,
    MIN_CONFIDENCE,
    NOTHING_READ_CONFIDENCE,
    OUT_OF_SCOPE_CONFIDENCE,
    UNREAD_WORD_FACTOR,
    OutOfRange,
    Problem,
    Reading,
)
from langnav.language.offline.refusals import (
    DURATION_RE,
    NUMBERISH_RE,
    OTHER_FLOOR_RE,
    QUESTION_RE,
    is_negated,
    is_out_of_scope,
    is_unsafe,
)
from langnav.language.offline.scratch import Clause, Scratch
from langnav.language.offline.turns import rotate_steps
from langnav.language.offline.verbs import Verb, main_verb
from langnav.language.offline.vocabulary import VOCABULARY

__all__ = ["Problem", "Reading", "is_unsafe", "read_clause"]


def read_clause(text: str, previous: Step | None = None, known_names: Sequence[str] = (),
                previous_target: ElementRef | None = None) -> Reading:
    """Read one instruction. ``previous`` is the step before it and ``previous_target`` the last
    element named (for 'it', 'there', 'the next one')."""
    norm = named_turn_alone(normalize(text), around_alone=previous is None or previous.direction == Direction.AROUND)
    c = Clause(text=text, s=Scratch(norm), previous=previous)
    if not norm:
        return Reading()
    query = read_query(c)
    if query is not None:
        return query
    if BEARING_RE.search(norm):
        return Reading(unread=(text,), confidence=NOTHING_READ_CONFIDENCE, problem=Problem.BEARING)
    if OTHER_FLOOR_RE.search(norm):
        return Reading(unread=(text,), confidence=OUT_OF_SCOPE_CONFIDENCE, problem=Problem.OTHER_FLOOR)
    if is_negated(norm):
        return Reading(unread=(text,), confidence=0.3, problem=Problem.NEGATED)
    if QUESTION_RE.match(norm):
        return Reading(unread=(text,), confidence=OUT_OF_SCOPE_CONFIDENCE, problem=Problem.QUESTION,
                       referent=question_referent(norm))
    if is_out_of_scope(norm) and not EXPLORE_RE.search(norm):
        return Reading(unread=(text,), confidence=OUT_OF_SCOPE_CONFIDENCE, problem=Problem.OUT_OF_SCOPE)
    c.s.take_all(FILLER_RE)
    durations = c.s.take_all(DURATION_RE)
    back = read_return(c)
    if back is not None:
        return back
    compass = compass_steps(c)
    if compass is not None:
        return _compass_reading(c, *compass)
    clock = clock_steps(c)
    if clock is not None:
        return _compass_reading(c, *clock)
    start_place = c.s.find(START_PLACE_RE)
    if start_place is not None:
        c.s.use(start_place.start(), start_place.end())
    if previous_target is None:
        previous_target = _previous_target(previous)
    phrases, name = find_phrases(c.s, previous_target)
    if name is not None:
        return named(c, name, known_names)
    if phrases:
        landmark = unknown_landmark(c.s.masked(), known_names)
        if landmark is not None:
            return named(c, landmark, known_names)  # "the room next to the kitchen": which room is a guess
    if start_place is not None:
        phrases.append(Phrase(ref=START_REF, start=start_place.start(), end=start_place.end(),
                               head_start=start_place.start(), detail=Detail.TO))
        phrases.sort(key=lambda p: p.start)
    explore = read_explore(c, phrases)
    if explore is not None:
        return explore
    verb = main_verb(c)
    if verb[0] == Verb.NONE and c.explore_verb:
        verb = (Verb.GO, None)
    if not phrases and verb[0] in (Verb.GO, Verb.STOP):
        unknown = unknown_destination(c.s.masked())
        if unknown is not None:
            return named(c, unknown, known_names)  # "drive to the desk on your left"
    assign_details(c.s, phrases, 0)
    c.s.take_all(LATE_FILLER_RE)
    if any(p.pronoun and p.ref.kind == Element.NONE and p.ref.name is None for p in phrases):
        stop_only = STOP_RE.search(norm) is not None  # "hold it": the "it" is part of the stop
        if not stop_only:
            return Reading(unread=(text,), confidence=0.3, problem=Problem.NO_ANTECEDENT)
        phrases = [p for p in phrases if p.ref.kind != Element.NONE]
    try:
        steps = _build_steps(c, phrases, verb)
    except OutOfRange:
        return Reading(unread=(text,), confidence=OUT_OF_SCOPE_CONFIDENCE, problem=Problem.OUT_OF_RANGE)
    leftovers = [w for w in c.s.leftover_words() if w not in lx.STOPWORDS]
    if (verb[0] == Verb.NONE and not phrases and steps and (leftovers or c.previous is None)
            and all(st.movement == Movement.MOVE for st in steps) and not MOVE_DIR_RE.search(norm)):
        # a distance with no verb and no direction ("banana 2", "alert(1)", a lone "2 m") is no
        # instruction of its own: it may only complete the step before it ("move forward, 2 m")
        return Reading(unread=(text,), confidence=NOTHING_READ_CONFIDENCE, problem=Problem.UNREADABLE)
    if steps and (any(NUMBERISH_RE.search(w) for w in leftovers) or _number_word_left([w for x in (*leftovers, *c.lost) for w in x.split()], norm)):
        # a number left unread ("the 25th door", "ninety billion degrees", "3.5.5 m") means the
        # step was read without it: never move on a misread number, ask instead
        return Reading(unread=(text,), confidence=NOTHING_READ_CONFIDENCE, problem=Problem.BAD_NUMBER)
    guessed = [st for st in steps if st.movement in (Movement.MOVE, Movement.ROTATE) and st.amount == Amount.DEFAULT]
    if durations and guessed:
        # "drive forward for 5 seconds": a time is no distance; ask rather than guess one
        return Reading(unread=(text,), confidence=OUT_OF_SCOPE_CONFIDENCE, problem=Problem.DURATION)
    unnumbered = [st for st in steps if st.movement in (Movement.MOVE, Movement.ROTATE)
                  and st.target is None] if not find_quantities(norm) else []
    # a move whose way was assumed (forward: "go 2 m") while a word of the clause was not understood: that
    # word may be the way ("go astern one metre", "go backside one metre", "go aft two feet"), and the
    # assumed way could be the very opposite of the one said; a person would ask which way, so do we
    way_unread = (c.guessed_direction and bool(leftovers or c.lost)) or _unread_before_amount(c, norm, steps)
    if ((guessed or unnumbered) and (leftovers or c.lost)) or way_unread:
        # a default move or turn built around words not understood ("take the stairs ..."), or a move
        # whose way was assumed while a word was not understood is a misreading: never motion, hand the
        # clause on instead
        return Reading(unread=(text,), confidence=NOTHING_READ_CONFIDENCE, problem=Problem.UNREADABLE)
    c.lost.extend(c.s.text[m.start():m.end()].strip() for m in durations)
    if not steps:
        if c.out_of_range:
            return Reading(unread=(text,), confidence=OUT_OF_SCOPE_CONFIDENCE, problem=Problem.OUT_OF_RANGE)
        if leftovers and GO_VERB_RE.search(norm) and not phrases:
            return named(c, " ".join(leftovers), known_names)
        if not leftovers and not c.lost and not c.had_verb:
            return Reading()  # only filler ("please", "robot,")
        return Reading(unread=(text,), confidence=NOTHING_READ_CONFIDENCE, problem=Problem.UNREADABLE)
    confidence = 1.0
    for f in c.factors:
        confidence *= f
    unread = [*leftovers, *c.lost]
    confidence *= UNREAD_WORD_FACTOR ** len(unread)
    return Reading(steps=tuple(steps), unread=(" ".join(unread),) if unread else (),
                   confidence=max(MIN_CONFIDENCE, round(confidence, 3)), amends_previous=c.amends,
                   through_previous=c.through_previous, open=_is_open(steps, norm), asks=tuple(c.asks))


#: The last word before a place in the text (its span is checked against what was read).
_LAST_WORD_RE: Final = re.compile(r"([a-z][a-z'-]*)[^a-z0-9]*$")


def _unread_before_amount(c: Clause, norm: str, steps: list[Step]) -> bool:
    """A word not understood right before the amount of a plain move or turn ("move forward zorbl two
    metres", "turn left nigh on ninety degrees"): the word in that slot says something about the amount or
    the way ("nigh", "twenny", "astern"), so the amount read without it may not be the one meant; a person
    would ask, so do we. (Words the reading knows and left as harmless, "full", "direction", and a number
    started and said again, "fif- ninety", are no such word.)"""
    if c.asks or not any(st.movement in (Movement.MOVE, Movement.ROTATE) and st.target is None
                         and st.heading_deg is None for st in steps):
        return False  # (a reading that asks already, "turn lest 30 degrees": which way?, may still be corrected)
    for q in find_quantities(norm):
        m = _LAST_WORD_RE.search(norm[:q.start])
        if m is None:
            continue
        word = m.group(1)
        if word in VOCABULARY or any(n.startswith(word) for n in NUMBER_WORD_SET):
            continue  # a word the reading knows (and chose to leave), or a number started again ("fif- ninety")
        if c.s.is_free(m.start(1), m.end(1)):
            return True
    return False


def _number_word_left(leftovers: list[str], norm: str) -> bool:
    """A number word left unread ("rover, advance one two feet": the "one"): the amount was not read in
    full. ("one" is also a pronoun, "the one on the left": only right before another number is it one.)"""
    return any(w in NUMBER_WORD_SET and w != "one" for w in leftovers) or (
        "one" in leftovers and _ONE_BEFORE_NUMBER_RE.search(norm) is not None)


_ONE_BEFORE_NUMBER_RE: Final = re.compile(rf"\bone\s+(?:\d|(?:{NUMBER_WORDS})\b)")
NUMBER_WORD_SET: Final = frozenset(NUMBER_WORD_LIST)
#: Words that give the side of a move or a turn.
_SIDE_WORD_RE: Final = re.compile(r"\b(?:left|right|forwards?|ahead|straight|back|backwards?|reverse|around|round|"
                                  r"port|starboard|astern|"
                                  r"clockwise|counter\s*clockwise|anti\s*clockwise|sideways)\b")


_TURN_SIDE_RE: Final = re.compile(rf"\b(?:{TURN_SIDE_WORDS}|{BOAT_SIDE_WORDS}|around|round)\b")


def _is_open(steps: list[Step], norm: str) -> bool:
    """The last step is a move or turn with no amount said, or no side said: a fragment that
    follows may complete it ("rotate, ninety degrees left")."""
    if not steps:
        return False
    last = steps[-1]
    if last.movement not in (Movement.MOVE, Movement.ROTATE) or last.target is not None \
            or last.heading_deg is not None:
        return False
    sides = _TURN_SIDE_RE if last.movement == Movement.ROTATE else _SIDE_WORD_RE
    if last.amount in (Amount.DEFAULT, Amount.LITTLE):
        return True
    # a turn around ("180") has its side: either way is the same turn
    return sides.search(norm) is None and last.direction != Direction.AROUND


def _compass_reading(c: Clause, steps: list[Step], open_: bool) -> Reading:
    if c.out_of_range:
        return Reading(unread=(c.text,), confidence=OUT_OF_SCOPE_CONFIDENCE, problem=Problem.OUT_OF_RANGE)
    leftovers = [w for w in c.s.leftover_words() if w not in lx.STOPWORDS]
    unread = [*leftovers, *c.lost]
    confidence = UNREAD_WORD_FACTOR ** len(unread)
    for f in c.factors:
        confidence *= f
    return Reading(steps=tuple(steps), unread=(" ".join(unread),) if unread else (),
                   confidence=max(MIN_CONFIDENCE, round(confidence, 3)), open=open_, asks=tuple(c.asks))


def _previous_target(previous: Step | None) -> ElementRef | None:
    if previous is None:
        return None
    return previous.target


def _build_steps(c: Clause, phrases: list[Phrase], main_verb: tuple[Verb, re.Match[str] | None]) -> list[Step]:
    verb, vm = main_verb
    if vm is not None:
        c.s.use(vm.start(), vm.end())
        c.had_verb = True
    targets = [p for p in phrases if not p.contained]
    if verb == Verb.STOP:
        return stop_steps(c, targets)
    if verb == Verb.ROTATE:
        return rotate_steps(c, targets, vm)
    if targets:
        if verb == Verb.NONE:
            c.doubt(ELLIPSIS_FACTOR)
        return navigate_steps(c, targets, verb)
    return move_steps(c, verb, vm)
