"""Code-style input read as the words it spells (issue 9: wording).

A developer types to the robot the way they write code: ``move_forward(1.5m)``, ``goto(biggest_room)``,
``go_through(door, side=left)``, ``forward(3ft); turn_right(15deg)``, ``rotate(right, 30) // typo, meant left``,
``repeat 3x: forward 0.5 m``. The notation is a way of writing words, not another language of instructions:

- names join their words with underscores or by capitals (``move_forward``, ``turnLeft``; ``goto`` is "go to");
- a call ``name(args)`` is the verb its name spells said of its arguments, and the arguments of one call are one
  phrase ("go through the narrow gap ahead"); code drops the article a noun takes in speech ("the");
- ``key=value`` names the role of a value: a value said of a place noun describes it ("room=biggest": "the biggest
  room"), a side of a place is "on the left" of it, a part of a place ("where=middle") is "the middle of" it, a key
  naming a unit gives the value's unit ("distance_m=2": "2 m"), and any other key is said before its value
  ("heading=south": "heading south");
- ``;`` ends a statement, as a full stop does;
- a comment (``//``, ``#``) is the writer's note about the line: a sentence of its own, often a correction, whose
  subject "I" is dropped as notes drop it ("typo, meant left": "I meant left");
- ``repeat N x: S`` / ``repeat N times: S`` / ``for i in range(N): S`` says S N times.

Read this way before anything else, the same reading and grounding apply as to the words spoken. Only input that
shows the notation is rewritten (a call, a joined name, a ``key=value`` or a ``//`` comment); speech is left as it
is.
"""

from __future__ import annotations

import re
from typing import Final

from langnav.language.offline.lexicon import DETERMINERS, ELEMENT_NOUNS, SIDE_ADJECTIVES

#: A name as code writes it: letters, digits and underscores, methods called on an object (``robot.stop``).
_NAME: Final = r"[A-Za-z_][A-Za-z0-9_]*(?:\.[A-Za-z_][A-Za-z0-9_]*)*"
#: A call with its arguments, the bracket right after the name ("left (clockwise)" is speech's aside); no nested
#: calls: an instruction is not a program.
_CALL: Final = re.compile(rf"\b(?P<name>{_NAME})\((?P<args>[^()]*)\)")
#: A call's closing bracket with another call after it: two statements.
_NEXT_CALL: Final = re.compile(rf"\)\s+(?={_NAME}\()")
#: Words joined by underscores or capitals ("move_forward", "turnLeft"), a key given a value ("side=left").
_JOINED: Final = re.compile(r"[A-Za-z]_[A-Za-z0-9]|[a-z][A-Z][a-z]")
_KEY_VALUE: Final = re.compile(r"\b[A-Za-z_]\w*\s*=\s*\S")
#: A comment: ``//`` anywhere, ``#`` after a statement (not "door #2", which numbers the door).
_COMMENT: Final = re.compile(r"(?://+|(?:(?<=[);])|(?<=\s))#+(?=\s))\s*(?P<note>[^;]*)")
#: "repeat 3x:", "repeat 3 times:", "repeat(3):", "for i in range(3):", "3x:" before the statement repeated.
_REPEAT: Final = re.compile(
    r"^\s*(?:repeat\s*\(?\s*(?P<n1>\d+)\s*(?:x|times)?\s*\)?|for\s+\w+\s+in\s+range\s*\(\s*(?P<n2>\d+)\s*\)|"
    r"(?P<n3>\d+)\s*x)\s*[:{]\s*(?P<body>.+?)\s*\}?\s*$", re.IGNORECASE)
#: The signs of code in a prompt: any one of them and the prompt is read as code.
_CODE_SIGNS: Final = (_CALL, _JOINED, _KEY_VALUE, re.compile(r"//"), _REPEAT)
#: Names written joined in code for two words: "goto" is "go to".
_JOINED_WORDS: Final = {"goto": "go to"}
#: Keys that only name the role of their value (where, which way, how much): the value alone says it.
_ROLE_KEYS: Final = frozenset({
    "where", "at", "to", "target", "goal", "dest", "destination", "place", "location", "loc", "pos", "position",
    "side", "dir", "direction", "way", "angle", "distance", "dist", "amount", "by", "value", "val", "n", "x",
    "count", "name", "part", "point", "spot", "which", "what", "kind", "type", "element", "obj", "object"})
#: Parts of a place said as "the <part> of <the place>".
_PARTS: Final = frozenset({"middle", "centre", "center", "end", "far end", "near end", "edge", "back", "front"})
#: Units a key may end in ("distance_m", "angle_deg"): the value is in that unit.
_KEY_UNITS: Final = {"m": "m", "cm": "cm", "mm": "mm", "ft": "ft", "in": "inches", "deg": "degrees",
                     "degrees": "degrees", "meters": "m", "metres": "m", "rad": "radians"}
#: Words that start an argument that is no place: a number, a way, a turn's side.
_NOT_A_PLACE: Final = re.compile(
    r"^(?:[-+]?\.?\d|(?:left|right|forwards?|backwards?|back|ahead|behind|straight|around|round|clockwise|"
    r"counter\s*clockwise|anti\s*clockwise|cw|ccw|north|south|east|west|up|down|true|false|none|null|here|there)\b)")
#: A note whose subject was dropped ("meant left", "wanted right"): the writer speaks of what they said.
_SUBJECTLESS_NOTE: Final = re.compile(r"(?:^|(?<=,)|(?<=, ))(?=(?:meant|wanted|intended)\b)")


def is_code(text: str) -> bool:
    """Whether ``text`` shows the notation of code (a call, a joined name, a ``key=value``, a ``//`` comment)."""
    return any(sign.search(text) for sign in _CODE_SIGNS)


def plain_code(text: str) -> str:
    """``text`` with code notation read as the words it spells (see the module docstring); other text unchanged."""
    if not is_code(text):
        return text
    # (calls one after another, as lines are once the line breaks are gone, are statements of their own)
    statements = [s.strip() for s in _NEXT_CALL.sub(");", text).split(";")]
    out: list[str] = []
    for statement in statements:
        if not statement:
            continue
        code, note = _split_comment(statement)
        if code:
            out.append(_repeated(code))
        if note:
            out.append(_SUBJECTLESS_NOTE.sub("i ", note.strip().lower()))
    return ". ".join(out)


def _split_comment(statement: str) -> tuple[str, str]:
    m = _COMMENT.search(statement)
    if m is None:
        return statement, ""
    return statement[:m.start()].strip(), m.group("note").strip()


def _repeated(code: str) -> str:
    """A statement said N times ("repeat 3x: forward 0.5 m": "forward 0.5 m 3 times")."""
    m = _REPEAT.match(code)
    if m is None:
        return _statement(code)
    times = next(n for n in (m.group("n1"), m.group("n2"), m.group("n3")) if n is not None)
    return f"{_statement(m.group('body'))} {times} times"


def _statement(code: str) -> str:
    return _words(_CALL.sub(lambda m: _call(m.group("name"), m.group("args")), code))


def _words(name: str) -> str:
    """The words a name spells: "move_forward" is "move forward", "turnLeft" "turn left", "goto" "go to"."""
    spaced = re.sub(r"(?<=[a-z])(?=[A-Z][a-z])", " ", name.replace("_", " "))
    spaced = re.sub(r"(?<=[A-Za-z])\.(?=[A-Za-z])", " ", spaced)  # "robot.stop": the robot addressed
    words = [_JOINED_WORDS.get(w.lower(), w.lower()) for w in spaced.split()]
    return " ".join(words)


def _call(name: str, args: str) -> str:
    """A call said as words: the verb its name spells, then its arguments as one phrase."""
    place: list[str] = []
    sides: list[str] = []
    parts: list[str] = []
    rest: list[str] = []
    for arg in (a.strip().strip("'\"") for a in args.split(",")):
        if not arg:
            continue
        key, _, value = arg.partition("=") if "=" in arg else ("", "", arg)
        key, value = _words(key.strip()), _words(value.strip().strip("'\""))
        if key in ELEMENT_NOUNS:
            place.append(f"{value} {key}")  # "room=biggest": the biggest room
        elif value in _PARTS and key in _ROLE_KEYS | {""} and (place or key):
            parts.append(value)  # "where=middle": the middle of the place (with no place, said as it is)
        elif value in SIDE_ADJECTIVES and key in _ROLE_KEYS | {""} and place:
            sides.append(value)  # "side=left": the one on the left
        elif key.split()[-1:] and key.split()[-1] in _KEY_UNITS:
            rest.append(f"{value} {_KEY_UNITS[key.split()[-1]]}")  # "distance_m=2": 2 m
        elif key in _ROLE_KEYS:
            rest.append(value)
        elif key:
            rest.append(f"{key} {value}")  # "heading=south": heading south
        elif not place and not _NOT_A_PLACE.match(value):
            place.append(value)
        else:
            rest.append(value)
    phrase = [_words(name)]
    if place:
        said = " ".join(place)
        said = said if said.split()[0] in DETERMINERS else f"the {said}"
        if parts:
            said = f"the {parts[0]} of {said}"
        phrase.append(said)
        phrase.extend(f"on the {side}" for side in sides)
    else:
        phrase.extend(parts)
        phrase.extend(sides)
    phrase.extend(rest)
    return " ".join(phrase)
