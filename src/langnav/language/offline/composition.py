"""The composition stage of the offline reading: places with amounts, labels, names, returns.

It reads, around the clause reader (``read_clause``), the words that attach to a place:

* amounts: "2 metres past the door", "stop 1 m before the corner", "halfway down the corridor",
  "a third of the way to the door" (``Step.offset`` / ``offset_m`` / ``fraction``);
* labels drawn on the map: "door 2", "room 3", "hallway 1", "passage 1", "unexplored area 2"
  (``ElementRef.label``: that element, not an order by distance);
* relations between spaces: "the room across the hall", "the room next to this one / to the one you
  are in / to room 3" (``ElementRef.relation``);
* returns: "back to where you were" (``Place.PREVIOUS``), "come back here", "the door you just
  passed" (``ElementRef.passed``);
* named places: "call this spot the kitchen", "this is the charging dock", "remember this place as
  X", "name this room X", "call door 2 the lab", "forget X", "what places do you know?".

The words of an amount, label or relation are taken out of the clause (leaving the words the clause
reader knows: "go 2 m past the door" is read as "go to the door"), the clause is read, and what was
taken out is attached to the step it belongs to. When it belongs to no step, the words come back
as unread: a place word that was not used means the robot asks instead of guessing.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from functools import partial
from typing import Final

from langnav.language.intent import (
    Detail,
    Element,
    ElementRef,
    Landmark,
    Movement,
    Offset,
    Place,
    Query,
    Relation,
    Side,
    Step,
)
from langnav.language.offline.lexicon import ORDINALS
from langnav.language.offline.normalize import normalize
from langnav.language.offline.numbers import ONES, QuantityKind, find_quantities
from langnav.language.offline.parser import Reading, read_clause
from langnav.language.offline.phrases import as_landmark
from langnav.places.store import place_key

#: The clause reader this stage wraps: (clause, previous step, known names, previous target) -> Reading.
ClauseReader = Callable[[str, Step | None, Sequence[str], ElementRef | None], Reading]

# ------------------------------------------------------------------------------ words
#: Nouns of the labels the map picture shows, and the element each names.
LABEL_NOUNS: Final[dict[str, Element]] = {
    "door": Element.DOOR, "doorway": Element.DOOR, "room": Element.ROOM, "hallway": Element.HALLWAY,
    "corridor": Element.HALLWAY, "hall": Element.HALLWAY, "passage": Element.NARROW_PASSAGE,
    "narrow passage": Element.NARROW_PASSAGE, "unexplored area": Element.UNEXPLORED_AREA,
    "unexplored": Element.UNEXPLORED_AREA, "obstacle": Element.OBSTACLE, "corner": Element.CORNER,
    "wall": Element.WALL}
_NUMBER_WORDS: Final = "|".join(sorted((w for w, v in ONES.items() if v > 0), key=len, reverse=True))
#: A number followed by a unit, or by a plural noun, is an amount or a count ("the room 2 doors down"),
#: not the number of a label.
_UNIT_AFTER: Final = (r"(?!\s*(?:m|cm|mm|metres?|meters?|feet|foot|ft|inch(?:es)?|in|yards?|yd|degrees?|deg|"
                      r"times|steps?|x|%|more|rad|radians?|o\s*clock|doors|rooms|hallways|corridors|halls|walls|"
                      r"corners|obstacles|passages|boxes|spaces|places|areas|of)\b)")
_LABEL_RE: Final = re.compile(
    r"\b(?P<noun>narrow\s+passage|unexplored\s+area|" + "|".join(k for k in LABEL_NOUNS if " " not in k)
    + r")\s*(?P<said>number\s+|no\.?\s+|#\s*)?(?P<n>\d{1,4}|" + _NUMBER_WORDS + r")\b" + _UNIT_AFTER)
#: "Go past the second door", "keep going past the box", with no amount: to just beyond it along the
#: way, not through it (a door beside a hallway is passed by, not entered) ...
_JUST_PAST_RE: Final = re.compile(
    r"\b(?:go|goes|going|walk|drive|head|move|roll|get|continue|proceed|carry\s+on|keep\s+going)\s+"
    r"(?:on\s+|straight\s+|right\s+|just\s+)?(?P<prep>past|beyond)"
    r"(?=\s+(?:the|that|this)\s+(?:[a-z]+\s+){0,3}?(?:doors?|doorways?|openings?|entrances?|obstacles?|boxe?s?|"
    r"corners?|passages?|gaps?)\b)")
#: ... and "just beyond" is this far past its far edge: the robot's length and more, so that the whole
#: robot has cleared the doorway, and well within the 2 m a person calls "just past it".
JUST_PAST_M: Final = 1.0
#: A side said right after "door number three": the number counts the doors on that side.
_COUNTED_SIDE_RE: Final = re.compile(r"\s+on\s+(?:your|the|my)\s+(?:left|right)\b")
#: The ordinal word of a count ("three" -> "third"), for the first ones a person counts along a side.
_ORDINAL_WORD: Final = {v: w for w, v in reversed(ORDINALS.items()) if w.isalpha()}

#: "2 m past / before" followed by what it is measured from: a determiner, a label or a place word
#: ("before turning left" is a time, not a place).
_OFFSET_PREP_RE: Final = re.compile(
    r"\s*(?:(?P<past>past|beyond|after|further\s+than|farther\s+than|on\s+from)|"
    r"(?P<before>before|short\s+of|in\s+front\s+of|shy\s+of|away\s+from))\b"
    r"(?=\s+(?:the|a|an|this|that|my|our|your|it|there|door|doorway|room|hallway|corridor|hall|wall|corner|"
    r"obstacle|passage|narrow|unexplored|box|where)\b)")
_FRACTIONS: Final[dict[str, float]] = {"halfway": 0.5, "half way": 0.5, "half the way": 0.5,
                                       "a third of the way": 1 / 3, "one third of the way": 1 / 3,
                                       "third of the way": 1 / 3, "two thirds of the way": 2 / 3,
                                       "a quarter of the way": 0.25, "one quarter of the way": 0.25,
                                       "quarter of the way": 0.25, "three quarters of the way": 0.75,
                                       # the normaliser makes plurals singular ("quarters" -> "quarter")
                                       "three quarter of the way": 0.75, "two third of the way": 2 / 3}
_FRACTION_RE: Final = re.compile(
    r"\b(?P<f>" + "|".join(re.escape(k).replace(r"\ ", r"\s+") for k in sorted(_FRACTIONS, key=len, reverse=True))
    + r")\s+(?P<prep>down|along|up|through|across|into|to|towards|toward|in)\b(?!\s+between)")
_PASSED_RE: Final = re.compile(
    r"\s*(?:that\s+|which\s+)?(?:you|we|i)\s+(?:have\s+|had\s+)?(?:just\s+|just\s+now\s+|recently\s+)?"
    r"(?:passed(?:\s+by|\s+through)?|went\s+(?:past|by|through)|came\s+(?:through|past|by)|drove\s+(?:past|by|through)|"
    r"walked\s+(?:past|by|through)|gone\s+(?:past|by|through)|crossed)(?:\s+(?:just\s+now|earlier|before|a\s+moment\s+ago))?\b")
_PREVIOUS_RE: Final = re.compile(
    r"\bwhere\s+(?:you|we|i)\s+(?:were|was)(?:\s+(?:just\s+)?(?:before|a\s+(?:moment|minute|second|while)\s+ago|"
    r"earlier|just\s+now|last|previously))?(?!\s+(?:at\s+the\s+start|at\s+first|originally|to\s+begin\s+with))\b"
    r"|\b(?:your|my|our|the)\s+(?:previous|last|earlier|former)\s+(?:position|location|spot|place|pose)\b")
#: "Come back here" / "return here": back to where the prompt began ("come here" alone names no place
#: the robot knows: it is left to the clause reader, which asks).
_HERE_RETURN_RE: Final = re.compile(r"\b(?:(?P<verb>come|get|head|go|drive|move)\s+back|(?P<ret>return))\s+here\b")
_SPACE_NOUN: Final = r"(?P<noun>room|office|hallway|corridor|space)"
_ACROSS_RE: Final = re.compile(
    r"\b" + _SPACE_NOUN + r"\s+(?:(?:that|which)\s+is\s+|that\s*'s\s+)?(?:directly\s+|right\s+|just\s+|straight\s+)?"
    r"(?:(?:across|opposite)\s+(?:from\s+(?:us|you|me|here)\s+)?(?:(?:on|in)\s+)?(?:the\s+)?(?:hallway|hall|corridor)\b"
    r"(?:\s+from\s+(?:here|us|you|me|this\s+(?:one|room)|the\s+one\s+(?:you|we)\s+are\s+in))?"
    r"|across\s+from\s+(?:here|us|you|me|this\s+(?:one|room)|the\s+one\s+(?:you|we)\s+are\s+in)"
    r"|opposite(?:\s+(?:this\s+(?:one|room)|us|here|the\s+one\s+(?:you|we)\s+are\s+in))?\s*$)")
_THIS_SPACE: Final = (r"this\s+one|this\s+room|here|yours|ours|the\s+current\s+(?:one|room)|your\s+(?:current\s+)?room|"
                      r"the\s+(?:one|room)\s+(?:that\s+)?(?:you|we|i)\s+(?:are|am)\s+(?:currently\s+|now\s+)?in|"
                      r"where\s+(?:you|we)\s+are")
_ADJACENT_RE: Final = re.compile(
    r"\b" + _SPACE_NOUN + r"\s+(?:(?:that|which)\s+is\s+)?(?:right\s+|just\s+|directly\s+|immediately\s+)?"
    r"(?:next\s+to|beside|adjacent\s+to|next\s+door\s+to|alongside|neighbou?ring)\s+"
    r"(?:(?P<this>" + _THIS_SPACE + r")|(?P<lnoun>room|hallway|corridor)\s+(?P<label>\d{1,4}|" + _NUMBER_WORDS
    + r"))\b|\b(?P<noun2>room)\s+next\s+door\b|\b(?:neighbou?ring|adjoining|adjacent|next\s+door)\s+(?P<noun3>room)\b")
# -- named places --------------------------------------------------------------------------------
_NAME_TAIL: Final = r"(?P<name>[^,;]+?)(?:\s+(?:please|for\s+me|now|from\s+now\s+on))*\s*$"
_SPOT: Final = (r"(?:this\s+(?:spot|place|position|point|location|pose)|here|where\s+(?:you|we)\s+are(?:\s+now)?|"
                r"this(?!\s+(?:room|hallway|corridor|hall|door|doorway|wall|corner|obstacle|passage|one|area)\b))")
_NAME_SPOT_RES: Final = (
    re.compile(r"^(?:please\s+)?(?:call|name|label|mark)\s+" + _SPOT + r"\s+(?:as\s+)?" + _NAME_TAIL),
    re.compile(r"^(?:please\s+)?(?:remember|save|store|mark|memori[sz]e)\s+" + _SPOT + r"\s+as\s+" + _NAME_TAIL),
    re.compile(r"^(?:please\s+)?(?:remember|note)\s+(?:that\s+)?(?:this|here)\s+is\s+" + _NAME_TAIL),
    re.compile(r"^(?:this|here)\s+(?:spot\s+|place\s+)?is\s+(?:called\s+|named\s+)?"
               r"(?P<name>(?:the|a|an|my|our|your)\s+[^,;]+?|home)(?:\s+please)?\s*$"),
)
_NAME_ELEMENT_RES: Final = (
    re.compile(r"^(?:please\s+)?(?:call|name|label)\s+(?P<rest>.+)$"),
    re.compile(r"^(?:please\s+)?(?:remember|save|mark)\s+(?P<target>.+?)\s+as\s+" + _NAME_TAIL),
    re.compile(r"^(?P<target>this\s+(?:room|hallway|corridor|hall|door(?:way)?)|the\s+(?:room|hallway)\s+(?:you|we)\s+are\s+in)"
               r"\s+is\s+(?:called\s+|named\s+)?" + _NAME_TAIL),
)
_FORGET_RE: Final = re.compile(
    r"^(?:please\s+)?(?:(?:forget(?:\s+about)?|unname)\s+(?:the\s+)?(?:(?:place|spot|name)\s+(?:called\s+|named\s+)?)?|"
    r"(?:delete|remove|drop|erase)\s+(?:the\s+)?(?:named\s+|saved\s+)?(?:place|spot|name)\s+(?:called\s+|named\s+)?)"
    + _NAME_TAIL)
_LIST_RE: Final = re.compile(
    r"^(?:(?:please|so|ok|okay)\s+)*(?:(?:what|which)\s+(?:named\s+|saved\s+)?(?:places|spots|locations)"
    r"(?:\s+(?:do|did|have|are|can|you)\b.*)?$|"
    r"(?:list|show(?:\s+me)?|tell\s+me)\s+(?:the\s+|my\s+|your\s+|all\s+(?:the\s+)?)?(?:named\s+|saved\s+|known\s+)?"
    r"(?:places|spots|locations)(?:\s+you\s+know)?\s*$|(?:what|which)\s+places\s+have\s+names)")
_FORGET_NOT_PLACES: Final = re.compile(r"^(?:that|it|this|everything|all|the\s+map|map|what\s+i\s+said)$")
#: "the room across from the first room on your left", "the office opposite room 3": across the hallway
#: from another room (named by its own words, read as a place).
_ACROSS_FROM_RE: Final = re.compile(
    r"\b(?:room|office)\s+(?:(?:that|which)\s+is\s+|that\s*'s\s+)?(?:directly\s+|right\s+|just\s+|straight\s+)?"
    r"(?:across|opposite)\s+(?:(?:the\s+)?(?:hall|hallway|corridor)\s+)?(?:from\s+)?"
    r"(?P<other>(?:the|room)\b(?!\s+(?:hall|hallway|corridor)\b)(?!\s+one\s+(?:you|we)\b).+?)\s*$")
#: "the room two doors down", "the office 3 doors along the hall on the left", "the room a couple of doors
#: back": a count of doors along the hallway picks one room (``Relation.DOORS_ALONG``).
_DOORS_ALONG_RE: Final = re.compile(
    r"\b(?P<noun>room|office|one|space)\s+(?:(?:that|which)\s+is\s+|that\s*'s\s+)?(?:just\s+)?"
    r"(?P<n>\d{1,2}|" + _NUMBER_WORDS + r"|a\s+couple\s+of|a\s+couple)\s+doors?\s+"
    r"(?P<way>(?:further\s+|farther\s+)?(?:down|up|along|on|away|over)|back|behind(?:\s+you)?)"
    r"(?:\s+(?:the|this)\s+(?:hall|hallway|corridor))?(?:\s+from\s+(?:here|us|you|me|this\s+(?:one|room)))?"
    r"(?:\s+(?:on|to)\s+(?:the|your)\s+(?P<side>left|right)(?:\s+(?:hand\s+)?side)?)?\b")


#: An element is named in at most this many words ("the second door on your left in the hallway"):
#: longer heads are not tried when splitting "call <element> <name>".
MAX_TARGET_WORDS: Final = 12
#: The most doors one counts along a hallway ("the room 20 doors down"): the schema's ordinal bound.
MAX_DOORS_ALONG: Final = 20
#: A place word that fit no step halves the reading's confidence (and is reported unread: the
#: planner asks instead of running a plan that ignores it).
LEFT_OVER_FACTOR: Final = 0.5


@dataclass
class Marks:
    """What was taken out of a clause, to attach to its steps."""

    offset: tuple[Offset, float, str] | None = None
    #: "across from the first room on your left": the words of that room, and all the words
    across_from: tuple[str, str] | None = None
    #: "two doors down (on the left)": the count and the side of the hallway, with the words
    doors_along: tuple[int, Side | None, str] | None = None
    fraction: tuple[float, str] | None = None
    labels: list[tuple[Element, int, str]] = field(default_factory=list)
    passed: list[str] = field(default_factory=list)
    previous: bool = False
    relation: tuple[Relation, Landmark | None, str] | None = None
    #: words were rewritten with no mark to attach ("come back here" -> "come back")
    rewritten: bool = False

    @property
    def any(self) -> bool:
        return bool(self.offset or self.fraction or self.labels or self.passed or self.previous or self.relation
                    or self.rewritten or self.doors_along or self.across_from)


def _number(word: str) -> int:
    return int(word) if word.isdigit() else ONES[word]


def _cut(text: str, start: int, end: int, put: str) -> str:
    return f"{text[:start]}{put}{text[end:]}"


def extract(norm: str) -> tuple[str, Marks]:
    """The clause with the composition words replaced by plain ones, and what they said."""
    marks = Marks()
    text = norm
    m = _ADJACENT_RE.search(text)
    if m is not None:
        noun = m.group("noun") or m.group("noun2") or m.group("noun3")
        near: Landmark | None = Landmark(kind=Element.ROOM, in_current_room=True)
        if m.group("label"):
            kind = LABEL_NOUNS[m.group("lnoun")]
            near = Landmark(kind=kind, label=_number(m.group("label")))
        marks.relation = (Relation.ADJACENT, near, m.group(0))
        text = _cut(text, m.start(), m.end(), noun)
    m = _DOORS_ALONG_RE.search(text)
    if m is not None and marks.relation is None:
        word = m.group("n")
        count = 2 if word.startswith("a couple") else _number(word)
        way = m.group("way")
        side = Side.BEHIND if way.startswith(("back", "behind")) else (
            Side.LEFT if m.group("side") == "left" else Side.RIGHT if m.group("side") == "right" else None)
        marks.doors_along = (count, side, m.group(0))
        text = _cut(text, m.start(), m.end(), "room")  # "the office two doors down": one of the rooms
    m = _ACROSS_FROM_RE.search(text)
    if m is not None and marks.relation is None:
        marks.across_from = (m.group("other"), m.group(0))  # read by read_composed, which knows elements
        text = _cut(text, m.start(), m.end(), "room")
    m = _ACROSS_RE.search(text)
    if m is not None and marks.relation is None and marks.across_from is None:
        marks.relation = (Relation.ACROSS, None, m.group(0))
        text = _cut(text, m.start(), m.end(), m.group("noun"))
    for q in find_quantities(text):
        if q.kind != QuantityKind.LENGTH:
            continue
        p = _OFFSET_PREP_RE.match(text, q.end)
        if p is None:
            continue
        relation = Offset.PAST if p.group("past") else Offset.BEFORE
        put = " at" if re.search(r"\b(?:stop|halt|wait|park)\b", text[:q.start]) else " to"
        marks.offset = (relation, q.value, text[q.start:p.end()].strip())
        text = _cut(text, q.start, p.end(), put)
        break
    m = _JUST_PAST_RE.search(text) if marks.offset is None else None
    if m is not None:
        marks.offset = (Offset.PAST, JUST_PAST_M, m.group("prep"))
        text = _cut(text, m.start("prep"), m.end("prep"), "to")
    m = _FRACTION_RE.search(text)
    if m is not None:
        marks.fraction = (_FRACTIONS[" ".join(m.group("f").split())], m.group(0))
        prep = m.group("prep")
        text = _cut(text, m.start(), m.end(), "along" if prep in ("down", "up", "along") else prep)
    m = _PREVIOUS_RE.search(text)
    if m is not None:
        marks.previous = True
        text = _cut(text, m.start(), m.end(), "where you started")
    m = _HERE_RETURN_RE.search(text)
    if m is not None:
        verb = "return" if m.group("ret") else "come" if m.group("verb") in ("come", "get") else m.group("verb")
        text = _cut(text, m.start(), m.end(), "return" if verb == "return" else f"{verb} back")
        marks.rewritten = True
    for m in reversed(list(_PASSED_RE.finditer(text))):
        marks.passed.insert(0, m.group(0).strip())
        text = _cut(text, m.start(), m.end(), "")
    for m in reversed(list(_LABEL_RE.finditer(text))):
        noun = " ".join(m.group("noun").split())
        counted = _COUNTED_SIDE_RE.match(text, m.end())
        if counted is not None and (m.group("said") or not m.group("n").isdigit()) and _number(m.group("n")) in _ORDINAL_WORD:
            # "door number three on your left": counted along a side, as "the third door on your left"
            # is; a label is a name and needs no side ("door 3", typed as the map shows it, stays one)
            text = _cut(text, m.start(), m.end(), f"{_ORDINAL_WORD[_number(m.group('n'))]} {noun}")
            continue
        marks.labels.insert(0, (LABEL_NOUNS[noun], _number(m.group("n")), m.group(0)))
        text = _cut(text, m.start(), m.end(), noun)
    return " ".join(text.split()), marks


# ------------------------------------------------------------------------------ attaching
def _refs(step: Step) -> list[tuple[str, ElementRef]]:
    out: list[tuple[str, ElementRef]] = []
    if step.target is not None:
        out.append(("target", step.target))
    if step.second_target is not None:
        out.append(("second_target", step.second_target))
    return out


def _same_kind(a: Element, b: Element) -> bool:
    spaces = (Element.ROOM, Element.HALLWAY)
    return a == b or (a in spaces and b in spaces)


def _takes_label(kind: Element, ref: ElementRef) -> bool:
    """'Door 2' may number ``ref``: one of that kind, not numbered yet, not a door already passed."""
    return ref.label is None and _same_kind(ref.kind, kind) and not ref.passed


def attach(steps: tuple[Step, ...], marks: Marks) -> tuple[tuple[Step, ...], list[str]]:
    """The steps with the marks attached, and the words of the marks that fit no step."""
    out = list(steps)
    left: list[str] = []

    def update_ref(i: int, key: str, ref: ElementRef) -> None:
        out[i] = out[i].model_copy(update={key: ref})

    def first_ref(fits: Callable[[ElementRef], bool], latest: bool = False) -> tuple[int, str, ElementRef] | None:
        """The first element reference that ``fits``, in the first step that has one (the last when
        ``latest``)."""
        order = reversed(range(len(out))) if latest else range(len(out))
        return next(((i, key, ref) for i in order for key, ref in _refs(out[i]) if fits(ref)), None)

    for kind, number, words in marks.labels:
        hit = first_ref(partial(_takes_label, kind))
        if hit is None:
            left.append(words)
        else:
            i, key, ref = hit
            update_ref(i, key, ref.model_copy(update={"label": number, "kind": kind, "ordinal": None,
                                                      "superlative": None, "side": None, "in_current_room": False}))
    for words in marks.passed:
        hit = first_ref(lambda r: r.kind != Element.NONE and r.label is None and not r.passed, latest=True)
        if hit is None:
            left.append(words)
        else:
            i, key, ref = hit
            update_ref(i, key, ref.model_copy(update={"passed": True, "superlative": None, "ordinal": None}))
    if marks.relation is not None:
        relation, near, words = marks.relation
        hit = first_ref(lambda r: r.kind in (Element.ROOM, Element.HALLWAY))
        if hit is None:
            left.append(words)
        else:
            i, key, ref = hit
            kind = Element.HALLWAY if ref.kind == Element.HALLWAY and relation == Relation.ADJACENT else Element.ROOM
            update_ref(i, key, ref.model_copy(update={"relation": relation, "near": near, "kind": kind,
                                                      "in_current_room": False}))
            if out[i].detail in (Detail.OPPOSITE_SIDE_OF, Detail.THROUGH, Detail.ALONG):
                out[i] = out[i].model_copy(update={"detail": Detail.TO, "movement": Movement.NAVIGATE})
    if marks.doors_along is not None:
        count, side, words = marks.doors_along
        hit = first_ref(lambda r: r.kind in (Element.ROOM, Element.HALLWAY) and r.relation is None)
        if hit is None or count < 1 or count > MAX_DOORS_ALONG:
            left.append(words)
        else:
            i, key, ref = hit
            update_ref(i, key, ref.model_copy(update={"kind": Element.ROOM, "relation": Relation.DOORS_ALONG,
                                                      "ordinal": count, "side": side, "superlative": None,
                                                      "in_current_room": False, "near": None}))
            if out[i].detail in (Detail.OPPOSITE_SIDE_OF, Detail.THROUGH, Detail.ALONG):
                out[i] = out[i].model_copy(update={"detail": Detail.TO, "movement": Movement.NAVIGATE})
    if marks.previous:
        idx = next((i for i, s in enumerate(out) if s.target is not None and s.target.place == Place.START), None)
        if idx is None:
            left.append("where you were")
        else:
            update_ref(idx, "target", ElementRef(kind=Element.NONE, place=Place.PREVIOUS))
    movable = [i for i, s in enumerate(out) if s.movement in (Movement.NAVIGATE, Movement.FOLLOW)
               and s.target is not None]
    if marks.offset is not None:
        way, metres, words = marks.offset
        if not movable:
            left.append(words)
        else:
            i = movable[-1]
            detail = out[i].detail if out[i].detail in (Detail.TO, Detail.STOP_AT) else Detail.TO
            out[i] = out[i].model_copy(update={"offset": way, "offset_m": metres, "detail": detail,
                                               "movement": Movement.NAVIGATE})
    if marks.fraction is not None:
        value, words = marks.fraction
        if not movable:
            left.append(words)
        else:
            out[movable[-1]] = out[movable[-1]].model_copy(update={"fraction": value})
    return tuple(out), left


# ------------------------------------------------------------------------------ named places
#: Words that open or carry a clause of their own: a name is a noun phrase, so words after "is" that hold
#: one ("this room is lovely but I want you to leave it") are a remark about the place, not its name.
_CLAUSE_WORDS_RE: Final = re.compile(r"\b(?:i|you|we|they|but|because|so|if|when|want|need|should|could|would)\b")


def _place_name(raw: str) -> str | None:
    name = re.sub(r"^(?:as|to|by|with)\s+", "", raw.strip())
    name = re.sub(r"\s+(?:please|now|from\s+now\s+on|for\s+me)$", "", name).strip(" .!?\"'")
    if not name or len(name) > 80 or _CLAUSE_WORDS_RE.search(name):
        return None
    return name


def read_place_command(norm: str, text: str, previous: Step | None, known_names: Sequence[str],
                       previous_target: ElementRef | None, reader: ClauseReader) -> tuple[Step, ...] | None:
    """'Call this spot the kitchen', 'name door 2 the lab', 'forget the kitchen', 'what places do you
    know?' as steps; None when the clause is no such command."""
    if _LIST_RE.search(norm):
        return (Step(movement=Movement.QUERY, query=Query.PLACES, text=text[:500]),)
    m = _FORGET_RE.match(norm)
    if m is not None:
        name = _place_name(m.group("name"))
        known = {place_key(n) for n in known_names}
        if name and not _FORGET_NOT_PLACES.match(name) and (place_key(name) in known or not _LABEL_RE.search(name)):
            return (Step(movement=Movement.FORGET_PLACE, place_name=name, text=text[:500]),)
    for rx in _NAME_SPOT_RES:
        m = rx.match(norm)
        if m is not None:
            name = _place_name(m.group("name"))
            if name:
                return (Step(movement=Movement.NAME_PLACE, place_name=name, text=text[:500]),)
    for rx in _NAME_ELEMENT_RES:
        m = rx.match(norm)
        if m is None:
            continue
        if "rest" in m.groupdict() and m.group("rest"):
            split = _split_target_name(m.group("rest"), previous, known_names, previous_target, reader)
            if split is None:
                continue
            target, name = split
        else:
            target_words = m.group("target")
            got = _target_of(target_words, previous, known_names, previous_target, reader)
            name = _place_name(m.group("name"))
            if got is None or not name:
                continue
            target = got
        return (Step(movement=Movement.NAME_PLACE, place_name=name, target=target, text=text[:500]),)
    return None


def _target_of(words: str, previous: Step | None, known_names: Sequence[str], previous_target: ElementRef | None,
               reader: ClauseReader) -> ElementRef | None:
    """The one element the words name, read as 'go to <words>' with nothing left over."""
    inner, marks = extract(normalize(f"go to {words}"))
    reading = reader(inner, previous, known_names, previous_target)
    if len(reading.steps) != 1 or reading.unread or reading.problem is not None:
        return None
    steps, left = attach(reading.steps, marks)
    target = steps[0].target
    if left or target is None or target.kind == Element.NONE or steps[0].offset is not None:
        return None
    return target


def _split_target_name(rest: str, previous: Step | None, known_names: Sequence[str],
                       previous_target: ElementRef | None, reader: ClauseReader) -> tuple[ElementRef, str] | None:
    """'door 2 the lab' -> (door 2, 'lab'): the longest head of the words that names one element, with
    the name after it; a name that opens with an article or 'as' is preferred ('call the room on your
    left the lab')."""
    words = rest.split()
    found: list[tuple[bool, int, ElementRef, str]] = []
    for k in range(1, min(len(words), MAX_TARGET_WORDS + 1)):
        head, tail = " ".join(words[:k]), " ".join(words[k:])
        opens = re.match(r"(?:the|a|an|my|our|as)\b", tail) is not None
        name = _place_name(tail)
        if not name or re.fullmatch(_SPOT, head) or re.match(r"(?:\d|(?:" + _NUMBER_WORDS + r")\b)", tail):
            continue
        target = _target_of(head, previous, known_names, previous_target, reader)
        if target is not None:
            found.append((opens, k, target, name))
    if not found:
        return None
    _, _, target, name = max(found, key=lambda t: (t[0], t[1]))
    return target, name


_BETWEEN_RE: Final = re.compile(
    r"^(?:please\s+)?(?:(?:go|drive|move|head|navigate|get|stand|wait|stop|park)\s+(?:and\s+(?:stand|wait|stop|park)\s+)?)?"
    r"(?:to\s+)?(?:(?:the\s+)?(?:middle|midpoint|point|spot|halfway|midway)\s+)?(?:of\s+)?"
    r"between\s+(?P<a>.+?)\s+(?:and|&)\s+(?P<b>.+?)(?:\s+please)?\s*$")


def _between_named(norm: str, text: str, previous: Step | None, known_names: Sequence[str],
                   previous_target: ElementRef | None, reader: ClauseReader) -> Step | None:
    """'Between the kitchen and door 2': a named place on either side (the clause reader knows
    elements only)."""
    if not known_names:
        return None
    m = _BETWEEN_RE.match(norm)
    if m is None:
        return None
    known = {place_key(n): n for n in known_names}
    refs: list[ElementRef] = []
    for side in (m.group("a"), m.group("b")):
        name = known.get(place_key(side))
        ref = ElementRef(kind=Element.NONE, name=name[:80]) if name else \
            _target_of(side, previous, known_names, previous_target, reader)
        if ref is None:
            return None
        refs.append(ref)
    if not any(r.name for r in refs):
        return None  # two elements: the clause reader's own reading
    return Step(movement=Movement.NAVIGATE, detail=Detail.BETWEEN, target=refs[0], second_target=refs[1],
                text=text[:500])


# ------------------------------------------------------------------------------ the stage
def read_composed(text: str, previous: Step | None = None, known_names: Sequence[str] = (),
                  previous_target: ElementRef | None = None, reader: ClauseReader = read_clause) -> Reading:
    """Read one clause with the composition words taken out and attached (see the module docstring)."""
    norm = normalize(text)
    places = read_place_command(norm, text, previous, known_names, previous_target, reader)
    if places is not None:
        return Reading(steps=places)
    between = _between_named(norm, text, previous, known_names, previous_target, reader)
    if between is not None:
        return Reading(steps=(between,))
    rewritten, marks = extract(norm)
    if marks.across_from is not None:
        other, words = marks.across_from
        mark = _target_of(other, previous, known_names, previous_target, reader)
        if mark is not None and mark.kind == Element.ROOM:
            marks.relation = (Relation.ACROSS, as_landmark(mark), words)
        else:
            rewritten = norm  # not a room the words name: read as said (and asked about)
            marks.across_from = None
    rewritten, stand_ins = _stand_in_names(rewritten, known_names)
    face = _FACE_NAMED_RE.match(rewritten) if stand_ins else None
    if face is not None and face.group("token") in stand_ins:
        # "turn to face the kitchen": the clause reader turns towards elements only
        ref = ElementRef(kind=Element.NONE, name=stand_ins[face.group("token")][:80])
        return Reading(steps=(Step(movement=Movement.ROTATE, detail=Detail.TOWARDS, target=ref, text=text[:500]),))
    if not marks.any and not stand_ins:
        return reader(text, previous, known_names, previous_target)
    reading = _words_back(reader(rewritten, previous, (*known_names, *stand_ins), previous_target), stand_ins)
    if not reading.steps:
        # what was not understood is reported in the user's words, not in the rewritten ones
        return replace(reading, unread=tuple(text if u.strip() in (rewritten, _words_back_text(rewritten, stand_ins))
                                             else u for u in reading.unread))
    steps, left = attach(reading.steps, marks)
    steps = tuple(_named_back(s, stand_ins).model_copy(update={"text": text[:500]}) for s in steps)
    confidence = reading.confidence * (LEFT_OVER_FACTOR if left else 1.0)
    return replace(reading, steps=steps, unread=(*reading.unread, *left), confidence=round(confidence, 3))


__all__ = ["LABEL_NOUNS", "Marks", "attach", "extract", "read_composed", "read_place_command"]


#: Stand-in words for the user's place names while the clause reader reads the clause: a name made of
#: words the reader knows ("the front door", "the big room") would otherwise be read as those words.
_STAND_IN: Final = "zqxplace{}"
#: At most this many names stand in at once: one letter each ("zqxplacea" ...) within a-z, and far
#: more places than one instruction names.
MAX_STAND_INS: Final = 20


_FACE_NAMED_RE: Final = re.compile(
    r"^(?:please\s+)?(?:turn\s+(?:(?:a)?round\s+)?(?:to\s+face|to\s+look\s+at|towards?|to)|face|look\s+(?:at|towards?)|"
    r"point\s+(?:at|towards?))\s+the\s+(?P<token>" + _STAND_IN.format("") + r"[a-z])(?:\s+please)?\s*$")


def _stand_in_names(norm: str, known_names: Sequence[str]) -> tuple[str, dict[str, str]]:
    """The clause with each known place name (longest first) replaced by a stand-in word."""
    stand_ins: dict[str, str] = {}
    originals: dict[str, str] = {}
    for n in known_names:
        originals.setdefault(place_key(n), n)  # the first name the user gave with that key
    for name in sorted((k for k in originals if k), key=len, reverse=True):
        rx = re.compile(r"\b(?:(?:the|a|an|my|our|your)\s+)?" + r"\s+".join(map(re.escape, name.split())) + r"\b")
        if rx.search(norm) is None:
            continue
        token = _STAND_IN.format(chr(ord("a") + len(stand_ins)))
        stand_ins[token] = originals[name]
        norm = rx.sub(f"the {token}", norm)
        if len(stand_ins) >= MAX_STAND_INS:
            break
    return norm, stand_ins


def _words_back_text(text: str, stand_ins: dict[str, str]) -> str:
    for token, original in stand_ins.items():
        text = text.replace(token, original)
    return text


def _words_back(reading: Reading, stand_ins: dict[str, str]) -> Reading:
    """The user's names instead of the stand-ins in what a reading reports (unread words, a name)."""
    if not stand_ins:
        return reading

    def back(text: str) -> str:
        for token, original in stand_ins.items():
            text = text.replace(token, original)
        return text

    return replace(reading, unread=tuple(back(u) for u in reading.unread),
                   name=back(reading.name) if reading.name else reading.name)


def _named_back(step: Step, stand_ins: dict[str, str]) -> Step:
    if not stand_ins:
        return step
    update: dict[str, ElementRef] = {}
    for key, ref in _refs(step):
        if ref.name is not None and ref.name in stand_ins:
            update[key] = ref.model_copy(update={"name": stand_ins[ref.name][:80]})
    return step.model_copy(update=update) if update else step
