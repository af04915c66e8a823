"""Clock directions: "turn to your two o'clock", "face your ten o'clock", "go 3 metres toward your nine
o'clock", "go two feet at your three o'clock".

The rule a person states: the robot stands in the middle of a clock face, twelve o'clock straight
ahead; each hour is 30 degrees, one to five o'clock to the right, seven to eleven to the left, six
behind. Facing an hour is that turn; going towards it is that turn, then a move forward.
"""

from __future__ import annotations

import re
from typing import Final

from langnav.language.intent import Direction, Movement, Step
from langnav.language.offline.compass import distance_said, forward_move
from langnav.language.offline.numbers import ONES
from langnav.language.offline.patterns import GO_VERB_RE, ROTATE_VERB_RE
from langnav.language.offline.scratch import Clause

#: Degrees between two hours of a clock face (360 / 12).
DEGREES_PER_HOUR: Final = 30.0
HOURS_ON_A_CLOCK: Final = 12

_HOUR_WORDS: Final = "|".join(w for w, v in sorted(ONES.items(), key=lambda kv: -len(kv[0])) if 1 <= v <= 12)
#: "your two o'clock", "towards your 9 o clock", "at the three oclock position".
CLOCK_RE: Final = re.compile(
    r"(?:\b(?:to(?:wards?)?|toward|at|facing|to\s+face|in\s+the\s+direction\s+of|around|round)\s+)?"
    r"(?:\b(?:your|my|the|its|his|her)\s+)?\b(?P<hour>1[0-2]|[1-9]|" + _HOUR_WORDS + r")\s*"
    r"(?:o\s*'?\s*clock|oclock)\b(?:\s+(?:position|direction|mark))?")
_FORWARD_RE: Final = re.compile(r"\b(?:forwards?|straight|ahead|directly|yourself|so\s+that\s+you\s+(?:are\s+)?face)\b")


def clock_turn(hour: int) -> tuple[Direction, float] | None:
    """The turn that faces ``hour`` o'clock (None for twelve: already facing it)."""
    h = hour % HOURS_ON_A_CLOCK
    if h == 0:
        return None
    if h == HOURS_ON_A_CLOCK // 2:
        return Direction.AROUND, 180.0
    if h < HOURS_ON_A_CLOCK // 2:
        return Direction.RIGHT, h * DEGREES_PER_HOUR
    return Direction.LEFT, (HOURS_ON_A_CLOCK - h) * DEGREES_PER_HOUR


def clock_steps(c: Clause) -> tuple[list[Step], bool] | None:
    """The steps of a clause that names a clock direction, and whether it still misses a distance
    ("head towards your two o'clock" then ", three feet"); None when it names none."""
    m = c.s.find(CLOCK_RE)
    if m is None:
        return None
    c.s.use(m.start(), m.end())
    word = m.group("hour")
    hour = int(word) if word.isdigit() else ONES[word]
    go = c.s.find(GO_VERB_RE)
    turn_verb = c.s.find(ROTATE_VERB_RE)
    if turn_verb is not None:
        c.s.use(turn_verb.start(), turn_verb.end())
        c.had_verb = True
    c.s.take_all(_FORWARD_RE)
    steps: list[Step] = []
    turn = clock_turn(hour)
    if turn is not None:
        direction, angle = turn
        steps.append(Step(movement=Movement.ROTATE, direction=direction, angle_deg=angle, text=c.text[:500]))
    distance = distance_said(c)
    if go is not None and (turn_verb is None or go.start() < turn_verb.start()):
        c.s.use(go.start(), go.end())
        c.had_verb = True
        if distance is None:
            return steps, True
    if distance is not None:
        move = forward_move(c, distance)
        if move is None:
            return [], False
        steps.append(move)
    return steps, False
