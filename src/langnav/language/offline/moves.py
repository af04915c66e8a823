"""Straight moves: "move forward 1 m", "back up a bit", "go left half a metre" (or a fragment:
"then 2 m"); a direction with an angle is a turn ("go left 90 degrees")."""

from __future__ import annotations

import re
from typing import Final

from langnav.language.intent import Amount, Direction, Movement, Step
from langnav.language.offline import lexicon as lx
from langnav.language.offline.numbers import Quantity, QuantityKind, find_quantities
from langnav.language.offline.patterns import LITTLE_RE, MOVE_DIR_RE, MUCH_RE
from langnav.language.offline.reading import (
    ASK_BOTH_SIDES,
    ASK_DISTANCE,
    ASK_HOW_MANY,
    ASK_UNIT,
    DEFAULT_AMOUNT_FACTOR,
    ELLIPSIS_FACTOR,
    GUESSED_DIRECTION_FACTOR,
    MAX_MOVE_M,
    UNITLESS_NUMBER_FACTOR,
    VAGUE_NUMBER_FACTOR,
    checked_angle,
)
from langnav.language.offline.scratch import Clause
from langnav.language.offline.turns import amount_said, repeat_count, rotation
from langnav.language.offline.verbs import Verb

#: Sides only a turn has ("clockwise"): a fragment with one of them is a turn.
_TURN_ONLY_SIDE_RE: Final = re.compile(r"\b(?:clockwise|counter\s*clockwise|anti\s*clockwise|cw|ccw)\b")
_SIDEWAYS_RE: Final = re.compile(r"\bsideways\b")
#: ("back out": reversing out of where one stands, as from a parking space or a tank's manhole)
#: ("backpedal": to step backwards, as a player or a cyclist does)
_BACKWARD_VERBS: Final = frozenset({"back up", "back out", "reverse", "back off", "go back", "head back", "retreat",
                                    "withdraw", "backpedal", "back pedal", "back-pedal"})
#: The way a backward verb already says, said again ("withdraw fifteen metres, straight back"): "straight" right
#: before a way means "directly" (as in "straight ahead"), never the way forward.
_BACK_SAID_AGAIN: Final = re.compile(r"\b(?:straight\s+|directly\s+|right\s+)?(?:backwards?|back|in\s+reverse)\b")


def move_steps(c: Clause, verb: Verb, vm: re.Match[str] | None) -> list[Step]:
    """'move forward 1 m', 'back up a bit', 'go left half a metre' (or a fragment: 'then 2 m')."""
    text = c.s.masked()
    quantities = find_quantities(text)
    lengths = [q for q in quantities if q.kind == QuantityKind.LENGTH]
    angles = [q for q in quantities if q.kind == QuantityKind.ANGLE]
    directions = _move_directions(c, vm)
    direction = directions[0] if directions else None
    c.amends = verb == Verb.NONE and direction is None and bool(quantities)
    prev = c.previous
    if verb == Verb.NONE and direction is None and prev is not None and prev.target is None:
        # "back up 2 m, then another 3 feet", "turn left 45 degrees, then 20 more": an amount alone
        # goes on the way the move or turn before it went
        if lengths and prev.movement == Movement.MOVE and prev.direction is not None:
            direction = prev.direction
        elif angles and not lengths and prev.movement == Movement.ROTATE \
                and prev.direction in (Direction.LEFT, Direction.RIGHT):
            return [rotation_from(c, prev.direction, quantities, [])]
    if verb == Verb.NONE and not lengths and _TURN_ONLY_SIDE_RE.search(text):
        return [rotation(c, None)]  # "cw 90", "then counterclockwise 45": only a turn goes clockwise
    if len({d for d in directions if d in (Direction.LEFT, Direction.RIGHT)}) > 1 and not lengths:
        c.asks.append(ASK_BOTH_SIDES)  # "right, left ninety degrees": both sides for one turn, none corrected
    if angles and not lengths:
        # "move back forty five degrees to your left": an angle goes with the side said
        direction = next((d for d in directions if d in (Direction.LEFT, Direction.RIGHT)), direction)
        return [rotation_from(c, direction, quantities, [])] if direction in (Direction.LEFT, Direction.RIGHT) \
            else [rotation(c, None)]  # "go left 90 degrees", "then 45 degrees"
    much = c.s.take_all(MUCH_RE)
    little = c.s.take_all(LITTLE_RE)
    if verb == Verb.NONE and direction is None and not quantities and not much:
        return []
    if verb == Verb.NONE and direction in (Direction.LEFT, Direction.RIGHT) and not lengths:
        c.doubt(ELLIPSIS_FACTOR)  # "then left": a turn
        return [rotation_from(c, direction, quantities, little)]
    # a move goes one way: another way said in the clause ("move forward 2 m before turning left")
    # is an instruction not read, never dropped: it stays unread, so the translator asks
    c.lost.extend(d.value for d in directions[1:] if d != direction)
    if direction in (Direction.LEFT, Direction.RIGHT):
        c.s.take_all(_SIDEWAYS_RE)  # "to the right, like a metre, sideways": the same way said again
    amount: Amount | None = None
    counted: list[Quantity] = []
    for q in quantities:
        c.s.use(q.start, q.end)
        if q.kind == QuantityKind.LENGTH:
            counted.append(q)
            if q.approximate:
                # "a few feet", "several metres": how far is not said; ask, never guess a count
                c.doubt(VAGUE_NUMBER_FACTOR)
                c.asks.append(ASK_HOW_MANY.format(said=c.s.text[q.start:q.end].strip()))
        elif q.kind == QuantityKind.BARE and not lengths:
            counted.append(q)
            c.doubt(UNITLESS_NUMBER_FACTOR)
            c.asks.append(ASK_UNIT.format(number=c.s.text[q.start:q.end].strip()))
        else:
            c.lost.append(c.s.text[q.start:q.end])
    distance = amount_said(c, counted)
    if distance is None and direction is None and not little and not much:
        return []  # "go to the kitchen": no element, no direction, no number -> a name or nothing
    if distance is None and much:
        # "go forward a fair bit": an amount said only to be large has no bound: ask how far
        c.asks.append(ASK_HOW_MANY.format(said=c.s.text[much[0].start():much[0].end()].strip()))
        little = []
    if distance is None:
        if little:
            amount = Amount.LITTLE
        else:
            amount = Amount.DEFAULT
            c.doubt(DEFAULT_AMOUNT_FACTOR)
    if direction is None:
        if verb == Verb.NONE and distance is None:
            return []
        direction = Direction.FORWARD
        c.guessed_direction = True
        if distance is None and amount == Amount.DEFAULT:
            c.doubt(GUESSED_DIRECTION_FACTOR)
    if amount == Amount.DEFAULT:
        c.asks.append(ASK_DISTANCE.format(direction=direction.value))  # never a guessed distance
    if distance is not None and distance > MAX_MOVE_M:
        c.out_of_range = True
        return []
    times = repeat_count(c)
    if distance is not None and times > 1:
        distance *= times
    if distance is not None and distance > MAX_MOVE_M:
        c.out_of_range = True
        return []
    return [Step(movement=Movement.MOVE, direction=direction, distance_m=distance, amount=amount,
                 text=c.text[:500])]


def rotation_from(c: Clause, direction: Direction, quantities: list[Quantity],
                   little: list[re.Match[str]]) -> Step:
    for q in quantities:
        c.s.use(q.start, q.end)
    angle = amount_said(c, quantities)
    amount = None if angle is not None else Amount.LITTLE if little else Amount.DEFAULT
    return Step(movement=Movement.ROTATE, direction=direction, angle_deg=checked_angle(angle), amount=amount,
                text=c.text[:500])


def _move_directions(c: Clause, vm: re.Match[str] | None) -> list[Direction]:
    """Every direction word of the clause, in order (the first is the move's)."""
    found: list[Direction] = []
    if vm is not None and " ".join(vm.group(0).split()) in _BACKWARD_VERBS:
        c.s.take_all(_BACK_SAID_AGAIN)
        found.append(Direction.BACKWARD)
    for m in c.s.take_all(MOVE_DIR_RE):
        d = lx.lookup(lx.MOVE_DIRECTIONS, m.group("dir"))
        if isinstance(d, Direction):
            found.append(d)
    return found
