"""Turns in place: "turn left 90 degrees", "turn around", "face the door", "turn right at the door",
"spin twice"."""

from __future__ import annotations

import re
from typing import Final

from langnav.language.intent import Amount, Detail, Direction, Movement, Step
from langnav.language.offline import lexicon as lx
from langnav.language.offline.navigation import ref_step
from langnav.language.offline.numbers import Quantity, QuantityKind, find_quantities, one_amount
from langnav.language.offline.patterns import LITTLE_RE, MUCH_RE, ROTATE_DIR_RE
from langnav.language.offline.phrases import Phrase
from langnav.language.offline.reading import (
    ASK_AMOUNT,
    ASK_BOTH_SIDES,
    ASK_HOW_MUCH_TURN,
    ASK_SIDE,
    ASK_UNIT,
    DEFAULT_TURN_DEG,
    GUESSED_DIRECTION_FACTOR,
    MAX_MOVE_M,
    MAX_TURN_DEG,
    UNITLESS_NUMBER_FACTOR,
    checked_angle,
)
from langnav.language.offline.scratch import Clause

#: A turn's number without a unit is plainly degrees from here up ("turn left 45"); "turn left 2"
#: may be steps, turns or degrees: ask.
OBVIOUS_DEGREES_MIN: Final = 10.0
_AROUND_VERBS: Final = frozenset({"u turn", "uturn", "about face", "about turn", "make a u turn"})


def rotate_steps(c: Clause, targets: list[Phrase], vm: re.Match[str] | None) -> list[Step]:
    """'turn left 90 degrees', 'turn around', 'face the door', 'turn right at the door'."""
    steps: list[Step] = []
    if targets:
        p = targets[0]
        at = re.search(r"\b(?:at|when\s+you\s+(?:reach|get\s+to)|once\s+you\s+reach|after|by|past)\s*$",
                       c.s.text[:p.start])
        if at is not None or p.detail in (Detail.THROUGH, Detail.STOP_AT, Detail.NEXT_TO):
            c.s.use(at.start() if at else p.start, p.start)
            detail = p.detail if p.detail not in (None, Detail.TO) else Detail.TO
            p.detail = detail
            steps.append(ref_step(c, p))
        else:
            for q in targets:
                c.s.use(q.start, q.end)
            c.s.take_all(re.compile(r"\b(?:to\s+face|face|facing|to|towards?|so\s+that\s+you\s+face|"
                                    r"until\s+you\s+(?:face|see))\b"))
            return [Step(movement=Movement.ROTATE, detail=Detail.TOWARDS, target=p.ref, text=c.text[:500])]
    lengths = [a for a in find_quantities(c.s.masked()) if a.kind == QuantityKind.LENGTH]
    for a in lengths:
        c.s.use(a.start, a.end)
    turn = rotation(c, vm)
    steps.append(turn)
    distance = amount_said(c, lengths) or 0.0
    if lengths and _move_said_apart(c, vm):
        # "turn left 90 move back 1 foot", "turn right 45 or go back 1 foot": the distance is another
        # instruction's, said with its own verb and way, not the straight-on move of "turn right three feet";
        # read as that, the robot would go forward where back was said. Left unread, the robot asks.
        c.lost.extend(c.s.text[a.start:a.end] for a in lengths)
    elif lengths and turn.direction in (Direction.LEFT, Direction.RIGHT) and 0 < distance <= MAX_MOVE_M:
        # "turn right three feet": that turn, then the distance straight on (README: "move N to your
        # right" may be a 90 degree turn and a move forward)
        steps.append(Step(movement=Movement.MOVE, direction=Direction.FORWARD, distance_m=distance, text=c.text[:500]))
    elif lengths:
        c.lost.extend(c.s.text[a.start:a.end] for a in lengths)
    return steps


#: A verb of going after the turn's verb ("turn left 90 move back 1 foot"), or an "or" offering another
#: instruction ("turn left or go back 1 foot"; not "or so", "or more", which hedge the amount).
_SECOND_GO_VERB_RE: Final = re.compile(
    r"\b(?:" + "|".join(sorted((re.escape(v).replace(r"\ ", r"\s+") for v in lx.GO_VERBS if v != "be"),
                                 key=len, reverse=True)) + r")\b")
_OR_RE: Final = re.compile(r"\bor\b(?!\s+(?:so|thereabouts|about|more|less|two|three)\b)")


def _move_said_apart(c: Clause, vm: re.Match[str] | None) -> bool:
    """Whether a distance in a turn's clause belongs to another instruction said in the same breath: a verb
    of going after the turn's verb, or an "or" between them (see ``rotate_steps``)."""
    after = c.s.text[vm.end():] if vm is not None else c.s.text
    return _SECOND_GO_VERB_RE.search(after) is not None or _OR_RE.search(after) is not None


#: "turn round to the left": only a bare "round / around" gives way to a side named with it.
_SPIN_ROUND_RE: Final = re.compile(r"(?<!way\s)\b(?:a)?round\b(?!\s+(?:twice|two|2|three|\d))")
#: Verbs that name a revolution (a spin, a twirl): "all the way around" completes it, a whole turn ("turn all
#: the way around" faces the other way: a half turn).
_REVOLVE_VERB_RE: Final = re.compile(r"\b(?:spin|spinning|twirl|pirouette|whirl)\b")
_ALL_THE_WAY_RE: Final = re.compile(r"\ball\s+the\s+way\s+(?:a)?round\b")
_REPEAT_RE: Final = re.compile(r"\b(?:(?P<word>once|twice|thrice)|(?P<n>\d+|one|two|three|four|five)\s+times)\b")
_REPEAT_WORDS: Final = {"once": 1, "twice": 2, "thrice": 3, "one": 1, "two": 2, "three": 3, "four": 4, "five": 5}


def repeat_count(c: Clause) -> int:
    """'twice', 'three times': how many times the move or turn is done (1 when not said)."""
    m = c.s.find(_REPEAT_RE)
    if m is None:
        return 1
    c.s.use(m.start(), m.end())
    word = m.group("word") or m.group("n")
    return int(word) if word.isdigit() else _REPEAT_WORDS[word]


def amount_said(c: Clause, quantities: list[Quantity]) -> float | None:
    """The one amount ``quantities`` say (``numbers.one_amount``); when they disagree, the first, and a
    question: which one was meant (nothing runs on a guess)."""
    if not quantities:
        return None
    value = one_amount(quantities)
    if value is None:
        said = ", ".join(f"'{c.s.text[q.start:q.end].strip()}'" for q in quantities)
        c.asks.append(ASK_AMOUNT.format(amounts=said))
        return quantities[0].value
    return value


def rotation(c: Clause, vm: re.Match[str] | None) -> Step:
    step = _single_rotation(c, vm)
    times = repeat_count(c)
    if times == 1:
        return step
    angle = step.angle_deg if step.angle_deg is not None else (
        DEFAULT_TURN_DEG if step.amount == Amount.DEFAULT else None)
    if angle is None:
        return step  # "a little" twice stays a little
    total = min(angle * times, MAX_TURN_DEG)
    # "turn around twice" is a full turn: either way will do, left is the convention
    direction = Direction.LEFT if step.direction == Direction.AROUND else step.direction
    return step.model_copy(update={"angle_deg": total, "amount": None, "direction": direction})


def _single_rotation(c: Clause, vm: re.Match[str] | None) -> Step:
    direction: Direction | None = None
    if vm is not None and " ".join(vm.group(0).split()) in _AROUND_VERBS:
        direction = Direction.AROUND
    elif vm is not None and "dir" in vm.groupdict() and vm.group("dir"):
        direction = Direction.LEFT if vm.group("dir") == "left" else Direction.RIGHT
    quantities = find_quantities(c.s.masked())
    counted: list[Quantity] = []
    for q in quantities:
        c.s.use(q.start, q.end)
        if q.kind == QuantityKind.ANGLE or q.kind == QuantityKind.BARE:
            if q.kind == QuantityKind.BARE:
                c.doubt(UNITLESS_NUMBER_FACTOR if q.value not in (90, 180, 45, 360, 270, 30, 60) else 1.0)
                if q.value < OBVIOUS_DEGREES_MIN:
                    c.asks.append(ASK_UNIT.format(number=c.s.text[q.start:q.end].strip()))
            counted.append(q)
        else:
            c.lost.append(c.text)
    angle = amount_said(c, counted)
    much = c.s.take_all(MUCH_RE)
    little = c.s.take_all(LITTLE_RE)
    if much and angle is None:
        # "turn left a fair bit": a turn said only to be large has no bound a person would agree on: ask
        c.asks.append(ASK_HOW_MUCH_TURN.format(said=c.s.text[much[0].start():much[0].end()].strip()))
        little = []
    sides: list[Direction] = []
    for m in c.s.take_all(ROTATE_DIR_RE):
        d = lx.lookup(lx.ROTATE_DIRECTIONS, m.group("dir"))
        if isinstance(d, Direction):
            if d in (Direction.LEFT, Direction.RIGHT):
                sides.append(d)
            if direction is None:
                direction = d
    named = set(sides) | ({direction} if direction in (Direction.LEFT, Direction.RIGHT) else set())
    if len(named) > 1:
        # "rotate clockwise to the left": both sides in one turn with no word correcting one of them (a
        # correction is split off before a clause is read): either may be the slip, so ask
        c.asks.append(ASK_BOTH_SIDES)
    if direction == Direction.AROUND and sides and _SPIN_ROUND_RE.search(c.s.text):
        direction = sides[0]  # "spin round to your left": a turn to that side, not a U-turn
    if direction == Direction.AROUND and angle is not None and abs(angle - 180.0) > 1e-6 and angle % 360 != 0:
        # "turn about twenty degrees to the right": "about" is roughly, not a U-turn; the side is
        # the one said, and none said is a guess
        direction = sides[0] if sides else None
    amount: Amount | None = None
    if direction == Direction.AROUND:
        verb = vm.group(0) if vm is not None else ""
        if angle is None and _REVOLVE_VERB_RE.search(verb) and _ALL_THE_WAY_RE.search(c.s.text):
            angle, direction = 360.0, Direction.LEFT  # "spin all the way around": a spin is a whole turn
        elif angle is None or abs(angle - 180.0) < 1e-6:
            angle = 180.0
        else:
            direction = Direction.LEFT  # "spin around 360 degrees"
    elif angle is not None and direction is None:
        if abs(angle - 180.0) < 1e-6:
            direction = Direction.AROUND
        else:
            direction = Direction.LEFT
            if angle % 360 != 0:
                c.doubt(GUESSED_DIRECTION_FACTOR)
                c.asks.append(ASK_SIDE)
    elif angle is None:
        amount = Amount.LITTLE if little else Amount.DEFAULT
        if direction is None:
            verb = vm.group(0) if vm is not None else ""
            if re.search(r"\b(?:spin|pirouette|twirl)\b", verb) or re.search(r"\blook\s+around\b", c.s.text):
                direction, angle, amount = Direction.LEFT, 360.0, None
            else:
                direction = Direction.LEFT
                c.doubt(GUESSED_DIRECTION_FACTOR)
                c.asks.append(ASK_SIDE)
    return Step(movement=Movement.ROTATE, direction=direction, angle_deg=checked_angle(angle), amount=amount,
                text=c.text[:500])
