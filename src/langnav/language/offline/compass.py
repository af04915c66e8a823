"""Compass headings: "face north", "turn due west", "go east ten feet", "move three feet north west".

README "Compass": east is +x of the map (heading 0), north 90, west 180, south 270, the diagonals
between. Facing a point is one turn the shorter way, worked out by the grounding from the heading
the robot has then (:attr:`~langnav.language.intent.Step.heading_deg`); going that way is that turn
and then a move forward.
"""

from __future__ import annotations

import re
from typing import Final

from langnav.language.intent import Direction, Movement, Step
from langnav.language.offline.numbers import QuantityKind, find_quantities
from langnav.language.offline.patterns import GO_VERB_RE, ROTATE_VERB_RE
from langnav.language.offline.reading import MAX_MOVE_M, VAGUE_NUMBER_FACTOR
from langnav.language.offline.scratch import Clause

#: Compass points in degrees counter-clockwise from east (the map's +x).
HEADINGS_DEG: Final[dict[str, float]] = {
    "east": 0.0, "northeast": 45.0, "north": 90.0, "northwest": 135.0, "west": 180.0, "southwest": 225.0,
    "south": 270.0, "southeast": 315.0,
}
#: "nor'east", "sou west": the sailors' and speakers' short forms of the diagonals.
_POINT: Final = r"(?:north|south|nor|sou)\s*'?\s*(?:east|west)|north|south|east|west"
#: "to the north", "towards due east", "facing north west", "in the direction of the south",
#: "northwards", "to your north".
COMPASS_RE: Final = re.compile(
    r"(?:\bback\s+)?(?:\b(?:to|towards?|facing|to\s+face|in\s+the\s+direction\s+of|direction)\s+(?:the\s+|your\s+)?)?"
    rf"(?:\b(?:due|true)\s+)?\b(?P<point>{_POINT})(?:wards?|erly|bound)?\b(?:\s+direction\b)?")
#: Words of a compass clause that say nothing more ("straight", "forward" when going that way).
_FORWARD_RE: Final = re.compile(r"\b(?:forwards?|straight|ahead|directly|yourself|so\s+that\s+you\s+are|"
                                r"back(?=\s+(?:to\s+)?(?:the\s+)?(?:north|south|east|west)))\b")


_ROUND_RE: Final = re.compile(r"\b(?:a)?round\b")
_FACING_SIDE_RE: Final = re.compile(r"\s+(?:wall|side|end)\b")


def distance_said(c: Clause) -> float | None:
    """The length said in a clause that turns to a heading or an hour and may then go on ("go north
    five feet six inches": summed), its words taken. Any other amount is left unread: an angle beside
    a heading or a clock hour is a second turn, and which one is meant cannot be told."""
    distance: float | None = None
    for q in find_quantities(c.s.masked()):
        c.s.use(q.start, q.end)
        if q.kind == QuantityKind.LENGTH:
            distance = (distance or 0.0) + q.value
            if q.approximate:
                c.doubt(VAGUE_NUMBER_FACTOR)
        else:
            c.lost.append(c.s.text[q.start:q.end])  # "go north 90 degrees", "turn 90 to your two o'clock"
    return distance


def forward_move(c: Clause, distance_m: float) -> Step | None:
    """The move ahead after such a turn, or None (and the clause marked out of range) when it is
    farther than any move langnav runs."""
    if distance_m > MAX_MOVE_M:
        c.out_of_range = True
        return None
    return Step(movement=Movement.MOVE, direction=Direction.FORWARD, distance_m=distance_m, text=c.text[:500])


def heading_of(point: str) -> float:
    word = "".join(point.replace("'", " ").split())
    word = re.sub(r"^nor(?=east|west)", "north", re.sub(r"^sou(?=east|west)", "south", word))
    return HEADINGS_DEG[word]


def compass_steps(c: Clause) -> tuple[list[Step], bool] | None:
    """The steps of a clause that names a compass point, and whether it still misses a distance
    ("proceed due west" then ", for five feet"); None when it names none."""
    m = c.s.find(COMPASS_RE)
    if m is None:
        return None
    c.s.use(m.start(), m.end())
    heading = heading_of(m.group("point"))
    go = c.s.find(GO_VERB_RE)
    turn = c.s.find(ROTATE_VERB_RE)
    if turn is not None:
        c.s.take_all(ROTATE_VERB_RE)  # "turn so that you face north": one turn
        c.s.take_all(_ROUND_RE)  # "turn around to face north", "swing round to the east": the facing is the turn
        side = _FACING_SIDE_RE.match(c.s.text, m.end())
        if side is not None:
            c.s.use(side.start(), side.end())  # "face the north wall": facing it is facing north
    c.s.take_all(_FORWARD_RE)
    steps = [Step(movement=Movement.ROTATE, heading_deg=heading, text=c.text[:500])]
    distance = distance_said(c)
    if go is not None and (turn is None or go.start() < turn.start()):
        c.s.use(go.start(), go.end())
        c.had_verb = True
        if distance is None:
            return steps, True  # "head north": the turn now, the distance may follow
    elif turn is not None:
        c.had_verb = True
    elif distance is None:
        return steps, True  # "north," then "five feet": no verb yet, a distance may follow
    if distance is not None:
        move = forward_move(c, distance)
        if move is None:
            return [], False
        steps.append(move)
    return steps, False
