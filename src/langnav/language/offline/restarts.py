"""A spoken request is often started again or stopped on the way (README "Speech"). Read on the
clauses before the steps are built:

* a move said again with its amount is one move ("move left, move left a metre");
* a turn said again with what it missed is one turn: "fifteen degrees turn, turn to your left" (the
  side added), "face up, face north" and "turn, um, turn right" (a false start), "turn left, turn left
  two hundred seventy degrees" (the amount added), "turn around, face south" and "turn left and face
  the door" (a facing says where the turn ends: the turn before it, with no amount of its own, is it);
* a number said again on its own insists on it: "go forward two feet. just two." is one move;
* an amount stated ("it's about two metres", "that's forty five degrees to your right") says what the
  amount is: it gives the amount an instruction next to it misses, or says again the one it has;
* a bare turn to one side said right before a turn to the other side ("turn right, turn left, ...") is a
  fumbled start, not a request: doing both would bring the robot back where it started, which nobody
  asks for, so the last one said counts (README "Speech": the last version counts). It never turns more
  than the last turn asks; with a word that puts them in order ("turn left, then turn right") both run;
* a "stop" between two instructions stops the motion before it when that motion had no amount: the
  speaker let it run and stopped it, and how far it went cannot be known, so it is not run ("turn
  right, stop, turn left" is the left turn). A motion with its amount ends on its own: "go forward
  three feet, stop, turn left" keeps all three.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Final

from langnav.language.intent import Amount, Direction, Movement, Step
from langnav.language.offline import lexicon as lx
from langnav.language.offline.ask import spatial
from langnav.language.offline.corrections import DISMAY_RE
from langnav.language.offline.normalize import normalize
from langnav.language.offline.numbers import NUMBER, Quantity, QuantityKind, find_quantities
from langnav.language.offline.patterns import GO_VERB_RE, LITTLE_RE, ROTATE_VERB_RE, TURN_SIDE_WORDS
from langnav.language.offline.reading import ASK_SIDE, Reading
from langnav.language.offline.vocabulary import VOCABULARY

#: Words that give a turn its side.
_TURN_SIDE_RE: Final = re.compile(rf"\b(?:{TURN_SIDE_WORDS})\b")
#: Reads one clause on its own (the parser's ``read_clause``).
ClauseReader = Callable[[str], Reading]


def _only_turn(reading: Reading) -> Step | None:
    if len(reading.steps) != 1 or reading.problem is not None:
        return None
    step = reading.steps[0]
    return step if step.movement == Movement.ROTATE else None


def _no_amount_said(clause: str) -> bool:
    return not find_quantities(normalize(clause))


def _facing(step: Step) -> bool:
    return step.heading_deg is not None or step.target is not None


def merge_restated_turns(clauses: list[str], read: ClauseReader) -> list[str]:
    """The clauses with each turn said again (see the module docstring) read as one."""
    out: list[str] = []
    for clause in clauses:
        if out:
            merged = _restated(out[-1], clause, read)
            if merged is not None:
                out[-1] = merged
                continue
        out.append(clause)
    return out


def _only_move(reading: Reading) -> Step | None:
    if len(reading.steps) != 1 or reading.problem is not None:
        return None
    step = reading.steps[0]
    return step if step.movement == Movement.MOVE and step.target is None else None


#: Words that ask for a motion once more ("turn around, and then turn around again"): no restatement.
_ONCE_MORE_RE: Final = re.compile(r"\b(?:again|another|once\s+more|one\s+more\s+time|twice|repeat)\b", re.IGNORECASE)


def _restated(first: str, second: str, read: ClauseReader) -> str | None:
    if _ONCE_MORE_RE.search(second):
        return None  # "turn around, and then, uh, turn around again": two turns, the second asked for again
    a_reading, b_reading = read(first), read(second)
    a_move, b_move = _only_move(a_reading), _only_move(b_reading)
    if a_move is not None and b_move is not None and a_move.direction == b_move.direction \
            and a_move.amount == Amount.DEFAULT and b_move.distance_m is not None:
        return second  # "move left, move left a metre": the move said again with its amount
    a, b = _only_turn(a_reading), _only_turn(b_reading)
    if a is None or b is None or _facing(a):
        return None
    a_bare = _no_amount_said(first)
    if _facing(b):
        return second if a_bare else None  # "turn around, face south": the facing is the turn
    a_sideless = ASK_SIDE in a_reading.asks
    b_bare = _no_amount_said(second)
    if a_sideless and not a_bare and b_bare and b.direction in (Direction.LEFT, Direction.RIGHT) \
            and ASK_SIDE not in b_reading.asks:
        amounts = normalize(first)
        said = " ".join(amounts[q.start:q.end] for q in find_quantities(amounts))
        return f"{second} {said}"  # "fifteen degrees turn, turn to your left"
    if a_sideless and a_bare and ASK_SIDE not in b_reading.asks:
        return second  # "face up, face north", "turn, um, turn right": a false start
    if a_bare and not b_bare and a.direction == b.direction and a.direction in (Direction.LEFT, Direction.RIGHT) \
            and ASK_SIDE not in b_reading.asks:
        return second  # "turn left, turn left two hundred seventy degrees"
    if a_bare and not b_bare and not a_sideless and ASK_SIDE in b_reading.asks \
            and a.direction in (Direction.LEFT, Direction.RIGHT):
        amounts = normalize(second)
        said = " ".join(amounts[q.start:q.end] for q in find_quantities(amounts))
        return f"{first} {said}"  # "turn to your left, a quarter turn": the amount of the turn just asked for
    if a_bare and b_bare and a.direction == b.direction == Direction.AROUND:
        return first  # "turn all the way around, so that you face the other direction"
    if a_bare and not b_bare and a.direction == Direction.AROUND and _TURN_SIDE_RE.search(normalize(second)) is None:
        return second  # "spin all the way around, a full three sixty": the amount of the turn just asked for
    return None


def _bare_stop(reading: Reading) -> bool:
    return (len(reading.steps) == 1 and reading.steps[0].movement == Movement.STOP
            and reading.steps[0].target is None and reading.problem is None)


def _open_ended(reading: Reading) -> bool:
    return (len(reading.steps) == 1 and reading.steps[0].movement in (Movement.MOVE, Movement.ROTATE)
            and reading.steps[0].amount == Amount.DEFAULT and reading.steps[0].target is None
            and reading.steps[0].heading_deg is None)


def drop_stopped(clauses: list[str], read: ClauseReader) -> list[str]:
    """The clauses without each open-ended motion stopped by a 'stop' that more instructions follow."""
    out: list[str] = []
    for i, clause in enumerate(clauses):
        if out and i + 1 < len(clauses) and _bare_stop(read(clause)):
            if _open_ended(read(out[-1])):
                out.pop()
            continue  # the stop itself: what follows is the request now
        out.append(clause)
    return out


#: "just two", "only two, I said": a number alone, said again to insist on it.
_INSIST_RE: Final = re.compile(rf"^(?:(?:just|only|exactly|i\s+said|that\s+is|that's)\s+)*(?P<num>{NUMBER})"
                               r"(?:\s+(?:only|i\s+said|please))*$")
#: "only a little", "just a bit, I said": a small amount said again to insist on it.
_INSIST_LITTLE_RE: Final = re.compile(r"^(?:(?:just|only|exactly|i\s+said|really)\s+)+(?:a\s+)?(?:little|bit|tad|touch|"
                                      r"little\s+bit|tiny\s+bit|smidge)(?:\s+(?:only|i\s+said|please|more))*$")


#: "it's about two metres", "that's forty five degrees to your right", "which is two metres": an amount
#: stated, not asked for.
_STATED_RE: Final = re.compile(
    r"^(?:(?:so|and|okay|ok|well|yeah|i\s+think|i\s+guess)\s+)*(?:it|that|this|which)\s+(?:is|would\s+be|will\s+be|should\s+be)\s+"
    r"(?=(?:about|around|roughly|approximately|like|maybe|just|only|exactly|almost|nearly)?\s*\S)")
#: A stated amount this close to the one an instruction says (relatively) is that amount said roughly
#: in other words ("two metres, that's about six feet": 1.83 m): one move. Further apart, the two say
#: different things, and the robot asks.
ROUGHLY_SAME: Final = 0.1


def read_stated_amounts(clauses: list[str]) -> list[str]:
    """Each amount stated on its own (see the module docstring) dropped when an instruction next to it
    says roughly the same amount, kept as it is (the reading will ask) when the instruction before it
    says another amount, and otherwise left as the bare amount, which completes the instruction it
    belongs to ("turn left, it's about thirty degrees")."""
    out: list[str] = []
    for i, clause in enumerate(clauses):
        norm = normalize(clause)
        m = _STATED_RE.match(norm)
        said = [q for q in find_quantities(norm[m.end():]) if q.kind != QuantityKind.BARE] if m else []
        if m is None or len(said) != 1 or GO_VERB_RE.search(norm[m.end():]) or ROTATE_VERB_RE.search(norm[m.end():]):
            out.append(clause)
            continue
        before = _amounts(out[-1]) if out else []
        after = _amounts(clauses[i + 1]) if i + 1 < len(clauses) else []
        if any(_roughly_same(q, said[0]) for q in (*before, *after)):
            continue  # said again in other words
        if any(q.kind == said[0].kind for q in before):
            out.append(clause)  # another amount than the instruction's: not read, so asked about
            continue
        out.append(norm[m.end():])
    return out


def _amounts(clause: str) -> list[Quantity]:
    norm = normalize(clause)
    return [q for q in find_quantities(norm) if q.kind != QuantityKind.BARE]


def _roughly_same(a: Quantity, b: Quantity) -> bool:
    return a.kind == b.kind and abs(a.value - b.value) <= ROUGHLY_SAME * max(a.value, b.value)


#: "sideways" said on its own after a move to a side.
_SIDEWAYS_ALONE_RE: Final = re.compile(r"^(?:(?:like|so|just|um|uh)\s+)*sideways$")


def drop_insisted_amounts(clauses: list[str]) -> list[str]:
    """The clauses without an amount said again on its own right after the instruction that says it:
    "go forward two feet. just two." and "turn a little to the left. only a little." insist on it, they
    ask for no second move (which would take the robot farther than asked)."""
    out: list[str] = []
    for clause in clauses:
        norm = normalize(clause)
        m = _INSIST_RE.match(norm)
        if out and m is not None:
            said = normalize(out[-1])
            quantities = [q for q in find_quantities(said) if q.kind != QuantityKind.BARE]
            if any(re.search(rf"\b{re.escape(m.group('num'))}\b", said[q.start:q.end]) for q in quantities):
                continue
        if out and _INSIST_LITTLE_RE.match(norm) and LITTLE_RE.search(normalize(out[-1])):
            continue
        if out and _SIDEWAYS_ALONE_RE.match(norm) and re.search(r"\b(?:left|right)\b", normalize(out[-1])):
            continue  # "go to the right a bit, like a metre, sideways": the way said again
        out.append(clause)
    return out


#: What may stand between a turn and the turn to the other side that takes it back: pauses, fillers and
#: exclamations ("turn right, uh, turn left"). Any other word between them ("then", "and", "take a picture")
#: says both are meant.
_PAUSE_WORDS: Final = lx.HESITATIONS | frozenset({"oh", "like", "so", "well", "okay", "ok", "wait", "no", "sorry",
                                                 "robot", "please", "now", "just", "i", "mean"})
#: A bare turn as said ("turn right", "rotate to the left"): between two turns, a false start too.
_BARE_TURN_RE: Final = re.compile(r"\b(?:turn|rotate|spin|pivot|swing|veer)\s+(?:to\s+(?:the|your)\s+)?(?:left|right)\b")
#: A side said on its own ("left.", "no, right"): a bare turn too, said short.
_SIDE_WORD_RE: Final = re.compile(r"\b(?:left|right)\b")
_SIDES: Final = frozenset({Direction.LEFT, Direction.RIGHT})


def _bare_side_turn(reading: Reading) -> Step | None:
    """A turn to a side with no amount, no heading and no place said ("turn right"), and nothing else: a
    turn that asked something ("turn left a lot": how many degrees?) or left words unread is no bare turn,
    and taking it back would drop the question with it."""
    turn = _only_turn(reading)
    if turn is None or turn.direction not in _SIDES or reading.asks or reading.unread:
        return None
    if turn.amount != Amount.DEFAULT or turn.angle_deg is not None or _facing(turn):
        return None
    return turn


#: A corrected clause is found in the prompt by at least its first two words as said (a verb and its
#: side: "rotate right"); one word alone ("rotate") could be any other instruction's.
_SAID_PREFIX_WORDS: Final = 2


def _spans(text: str, clauses: list[str]) -> list[tuple[int, int] | None]:
    """Where each clause stands in ``text`` (the prompt), found in order. A clause whose amount was
    corrected on the way ("rotate right fifteen, correction, twenty" became "rotate right twenty") is
    found by the words it was said with before the correction ("rotate right"): where it starts is known,
    and its end is taken as that of those words, so the correction itself stays between it and what
    follows (which is then no pause). None where not even the first two words are found as said."""
    lowered = text.lower()
    cursor = 0
    spans: list[tuple[int, int] | None] = []
    for clause in clauses:
        # the clause's words with any pauses between them ("right sixty" was said "right, sixty")
        words = re.findall(r"[^\s,.;!?]+", clause.lower())
        found = None
        for n in range(len(words), min(len(words), _SAID_PREFIX_WORDS) - 1, -1):
            found = re.compile(r"[\s,.;!?]+".join(map(re.escape, words[:n]))).search(lowered, cursor)
            if found is not None:
                break
        if found is None:
            spans.append(None)
            continue
        cursor = found.end()
        spans.append((found.start(), cursor))
    return spans


def _only_pauses(between: str) -> bool:
    """Nothing but pauses, fillers and exclamations (see _PAUSE_WORDS), or words the reading does not know at
    all ("turn left, oh bugger, right"; "turn right, jeez, turn left"): an oath or a name, which asks for no
    motion of its own (a word that orders, "then", or an instruction, "take a picture", is known)."""
    words = re.findall(r"[a-z0-9&']+", DISMAY_RE.sub(" ", between.lower()))
    return all(w in _PAUSE_WORDS or _oath(w) for w in words)


#: An unknown word is taken for an oath or a name only when it is a word of some length: a short token
#: the reading does not know ("x", "n", "den", "&") may be an amount or an ordering word in chat spelling.
_OATH_MIN_LETTERS: Final = 4


#: Words that put instructions in order ("turn left, later, turn right"): what they join was meant, each of it.
_ORDER_RE: Final = re.compile(r"\b(?:" + "|".join(w.replace(" ", r"\s+") for w in lx.ORDER_WORDS) + r")\b|&", re.IGNORECASE)


def _oath(word: str) -> bool:
    """A word the reading does not know at all, long enough to be an oath or a name, and not one that asks
    for a motion again or sizes one ("twice", "again")."""
    return (word.isalpha() and len(word) >= _OATH_MIN_LETTERS and word not in VOCABULARY
            and not _ONCE_MORE_RE.search(word) and not _ORDER_RE.search(word) and not spatial(word))


def drop_false_start_turns(clauses: list[str], text: str, read: ClauseReader) -> list[str]:
    """The clauses without each bare turn that a turn to the other side follows straight away (see the
    module docstring): with nothing but pauses, or turns taken back, between them in ``text`` (the prompt)."""
    spans = _spans(text, clauses)
    kept: list[int] = []
    for i, clause in enumerate(clauses):
        reading = read(clause)
        turn = _only_turn(reading)
        # (a turn whose side was not said, "thirty degrees" in "turn right, em, thirty degrees", takes nothing
        # back: its side is only the reading's placeholder, and the turn said before it is the side meant)
        if turn is not None and turn.direction in _SIDES and ASK_SIDE not in reading.asks and not _facing(turn) \
                and not _ONCE_MORE_RE.search(clause):
            while kept:
                said = [k for k in kept if not _interjection(clauses[k], read)]  # "oh bugger": no instruction
                first = _bare_side_turn(read(clauses[said[-1]])) if said else None
                if (first is None or first.direction == turn.direction or not _said_bare(clauses[said[-1]])
                        or _ORDER_RE.match(clause) or not _taken_back(text, spans, said[-1], i)):
                    break
                del kept[kept.index(said[-1]):]  # "turn right, turn left, ...": the turn started and taken back at once
        kept.append(i)
    return [clauses[i] for i in kept]


def _said_bare(clause: str) -> bool:
    """The clause as said is a turn and pauses only ("uh, turn left"): a word joined to it that orders
    ("turn left next") or that the reading left aside makes it more than a start taken back."""
    return _only_pauses(_SIDE_WORD_RE.sub(" ", _BARE_TURN_RE.sub(" ", clause.lower())))



def _interjection(clause: str, read: ClauseReader) -> bool:
    """A clause of pauses, exclamations or words the reading does not know, that it reads as nothing."""
    return not read(clause).steps and _only_pauses(clause)


def _taken_back(text: str, spans: list[tuple[int, int] | None], first: int, second: int) -> bool:
    """Whether clause ``second`` follows clause ``first`` in ``text`` with nothing between them but pauses
    and other bare turns (false starts too, taken back already or corrected)."""
    a, b = spans[first], spans[second]
    return a is not None and b is not None and _only_pauses(_BARE_TURN_RE.sub(" ", text[a[1]:b[0]].lower()))
