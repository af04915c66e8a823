"""Read one instruction (a step of a prompt) into :class:`~langnav.language.intent.Step` s.

The reading marks every word it uses; the words left over (minus harmless function words) are
"unread" and lower the confidence. Order of reading, each stage consuming its words:

1. questions (where are you, what path, show the map) and exploration;
2. negation ("don't ...") and requests the robot cannot do ("pick up the cup");
3. politeness and filler;
4. elements: noun phrases with their properties ("the second door on your left", "the left wall
   of the hallway", "between the box and the wall", "it", "the next one");
5. the movement detail of each element (the words before it, or the verb: "cross", "follow");
6. verbs, numbers with units, "a little", directions; then the step is built.

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
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from enum import StrEnum
from typing import Final

from langnav.language.intent import (
    Amount,
    Detail,
    Direction,
    Element,
    ElementRef,
    Landmark,
    Movement,
    Place,
    Query,
    Side,
    Step,
    Superlative,
)
from langnav.language.offline import lexicon as lx
from langnav.language.offline.normalize import normalize
from langnav.language.offline.numbers import Quantity, QuantityKind, find_quantities

# ------------------------------------------------------------------------------ confidence
#: Confidence factors: each doubt in a reading multiplies the step's confidence.
UNREAD_WORD_FACTOR: Final = 0.7          # per content word left unread
DEFAULT_AMOUNT_FACTOR: Final = 0.75      # "move forward" with no distance: the grounding guesses
GUESSED_DIRECTION_FACTOR: Final = 0.7    # "rotate 90 degrees" with no side: left is a guess
UNITLESS_NUMBER_FACTOR: Final = 0.85     # "move forward 2": metres assumed
VAGUE_NUMBER_FACTOR: Final = 0.75        # "a few metres"
WEAK_WORD_FACTOR: Final = 0.85           # "passage" alone, "the other door", "take the door"
ELLIPSIS_FACTOR: Final = 0.85            # "... then the second one": the verb is borrowed
NOTHING_READ_CONFIDENCE: Final = 0.2     # no instruction recognised at all
OUT_OF_SCOPE_CONFIDENCE: Final = 0.9     # clearly something the robot cannot do
NAME_CONFIDENCE: Final = 0.9             # a place name the map cannot know
MIN_CONFIDENCE: Final = 0.05
#: Longest single move (the intent schema's bound); longer trips should name a place.
MAX_MOVE_M: Final = 100.0
#: Largest single turn (the intent schema's bound: ten full turns).
MAX_TURN_DEG: Final = 3600.0
#: "turn left" alone (README): used only to multiply "turn left twice".
DEFAULT_TURN_DEG: Final = 90.0


class Problem(StrEnum):
    """Why a clause yields no step."""

    NAME = "name"                  # "go to the kitchen"
    OUT_OF_SCOPE = "out_of_scope"  # "make me a sandwich"
    NEGATED = "negated"            # "don't go through the door"
    UNREADABLE = "unreadable"      # nothing recognised
    NO_ANTECEDENT = "no_antecedent"  # "go through it" with nothing before
    OUT_OF_RANGE = "out_of_range"    # "move forward 200 metres"
    QUESTION = "question"            # "how far is the door?" (only pose, path and map are answered)
    OTHER_FLOOR = "other_floor"      # "take the stairs up", "use the lift": the robot stays on its floor
    UNKNOWABLE = "unknowable"        # "the red door", "the wooden door": no colours or materials in a grid
    DURATION = "duration"            # "move forward for 5 seconds": moves go by distance, turns by angle
    BAD_NUMBER = "bad_number"        # "turn left ninety billion degrees": a number not read in full


class _OutOfRange(Exception):
    """A turn beyond MAX_TURN_DEG while building a step (read_clause turns it into OUT_OF_RANGE)."""


def _checked_angle(angle: float | None) -> float | None:
    if angle is not None and angle > MAX_TURN_DEG:
        raise _OutOfRange
    return angle


#: Words left unread that show a number was not read in full: digits, and magnitudes the
#: number words do not cover.
_NUMBERISH_RE: Final = re.compile(r"\d|\b(?:thousands?|millions?|billions?|trillions?|zillions?|gazillions?|"
                                  r"dozens?|hundreds|infinity|infinite)\b")


@dataclass(frozen=True)
class Reading:
    """What one clause says: its steps, the words left unread, and how sure the reading is."""

    steps: tuple[Step, ...] = ()
    unread: tuple[str, ...] = ()
    confidence: float = 1.0
    problem: Problem | None = None
    name: str | None = None
    #: the clause only adds a number or a direction to the previous step ("turn left, 45 degrees")
    amends_previous: bool = False
    #: the element a question names ("which is the largest room?"): a later "it" may mean it
    referent: ElementRef | None = None
    #: "... and stop just after you pass through it": the previous step goes through its element
    through_previous: bool = False


# ------------------------------------------------------------------------------ compiled tables
def _rx(phrases: Iterable[str], group: str | None = None) -> re.Pattern[str]:
    return re.compile(lx.phrase_regex(phrases, group))


def _any(patterns: Sequence[str]) -> re.Pattern[str]:
    return re.compile("|".join(f"(?:{p})" for p in patterns))


_HEAD_RE: Final = _rx([*lx.ELEMENT_NOUNS, "one", "ones"], "head")
_PRONOUN_RE: Final = _rx(lx.PRONOUNS, "pronoun")
_MODIFIER_WORDS: Final = (set(lx.ORDINALS) | set(lx.SUPERLATIVES) | set(lx.SIDE_ADJECTIVES)
                          | set(lx.FRONT_BACK_ADJECTIVES) | set(lx.DETERMINERS)
                          | set(lx.NEUTRAL_ADJECTIVES) | {"other", "another", "remaining", "different",
                                                          "new", "both", "two", "couple", "pair", "of",
                                                          "2"})
_MODIFIERS_RUN: Final = re.compile(rf"(?:{lx.phrase_regex(_MODIFIER_WORDS)}\s+)+$")
_LEAVING_VERBS: Final = frozenset({"exit", "leave", "get out of", "go out of", "exit from", "leave through",
                                   "exit through"})
_BACKWARD_VERBS: Final = frozenset({"back up", "reverse", "back off", "go back", "head back"})
_AROUND_VERBS: Final = frozenset({"u turn", "uturn", "about face", "about turn", "make a u turn"})
_VERB_LIKE_HEADS: Final = frozenset({"exit", "entry"})
_WEAK_MODIFIERS: Final = frozenset({"other", "another", "remaining", "different", "new"})
_PAIR_WORDS: Final = frozenset({"two", "both", "2", "pair", "couple"})
_FILLER_RE: Final = _any(lx.FILLER_PATTERNS)
_LATE_FILLER_RE: Final = _any(lx.LATE_FILLER_PATTERNS)
_UNSAFE_RE: Final = _any(lx.UNSAFE_PATTERNS)
_SAFE_AVOIDANCE_RE: Final = _any(lx.SAFE_AVOIDANCE_PATTERNS)
_OUT_OF_SCOPE_RE: Final = _any(lx.OUT_OF_SCOPE_PATTERNS)
_OTHER_FLOOR_RE: Final = _any(lx.OTHER_FLOOR_PATTERNS)
#: A time instead of a distance or an angle ("for 5 seconds", "for a while").
_DURATION_RE: Final = re.compile(
    r"\b(?:for\s+)?(?:(?:about|around|roughly|approximately|like|another)\s+)?(?:two|three|four|five|six|seven|"
    r"eight|nine|ten|fifteen|twenty|thirty|a\s+few|a\s+couple\s+of|a\s+couple|few|several)\s+(?:more\s+)?"
    r"(?:seconds|secs|minutes|mins|hours|hrs|moments)\b"
    r"|\b\d+(?:\.\d+)?\s*(?:seconds?|secs?|minutes?|mins?|hours?|hrs?|s)\b(?!\s*(?:steps?|times?))"
    r"|\bfor\s+(?:about\s+|around\s+)?(?:a|an|one|half\s+a|another)\s+(?:second|sec|minute|min|moment|hour|"
    r"while|little\s+while)\b|\bfor\s+(?:a\s+)?(?:while|some\s+time|bit\s+of\s+time)\b")
#: Where the prompt started: "to where you started", "to your starting point", "back to the start".
_START_PLACE_RE: Final = re.compile(
    r"\b(?:(?:back\s+)?(?:to|towards?)\s+)?(?:where\s+(?:you|we|i)\s+(?:started(?:\s+from)?|began|set\s+off|came\s+from|"
    r"were(?:\s+before|\s+at\s+the\s+start|\s+at\s+first|\s+originally)?)|(?:the|your|our|my)\s+(?:very\s+)?"
    r"(?:start(?:ing)?(?:\s+(?:point|position|place|spot|pose|location))?|original\s+(?:position|spot|place|location|pose)|"
    r"initial\s+(?:position|pose|spot|place|location)|beginning|point\s+of\s+departure))\b")
#: A whole clause that only says to go back ("come back", "return", "head back again").
_BARE_RETURN_RE: Final = re.compile(
    r"^(?:(?P<go>go|head|drive|move|walk|roll|navigate)|come|get|make\s+your\s+way|find\s+your\s+way|"
    r"(?P<ret>return))(?:\s+(?:all\s+the\s+way\s+)?back)?(?:\s+(?:home|again|now|there|where\s+you\s+came\s+from))?\s*$")
START_REF: Final = ElementRef(kind=Element.NONE, place=Place.START)
#: A question that names an element ("which is the largest room?", "where is the nearest door?").
_ELEMENT_QUESTION_RE: Final = re.compile(
    r"^(?:(?:hey|ok|okay|so|robot)\s+)*(?:which|where|what)\b(?:\s+(?:is|are|one\s+is|one\s+of\s+them\s+is|"
    r"would\s+be|do\s+you\s+think\s+is))?")
#: A question the robot cannot answer (the answerable ones were read as queries before).
_QUESTION_RE: Final = re.compile(r"^(?:(?:hey|ok|okay|so|robot)\s+)*(?:how|what|why|when|which|who|whose|is|are|"
                                 r"where\s+(?:is|are)\s+(?:the|a|an|any|your)\b|"
                                 r"was|were|does|did|do\s+(?:you|i|we)|can\s+i|could\s+i)\b")
_NEGATION_RE: Final = re.compile(lx.NEGATIONS)
_QUERY_RES: Final = ((Query.POSE, _any(lx.QUERY_POSE_PATTERNS)), (Query.MAP, _any(lx.QUERY_MAP_PATTERNS)),
                     (Query.PATH, _any(lx.QUERY_PATH_PATTERNS)))
_EXPLORE_RE: Final = _any(lx.EXPLORE_PATTERNS)
_STOP_RE: Final = _rx(lx.STOP_PHRASES)
_ROTATE_VERB_RE: Final = _rx(lx.ROTATE_VERBS, "verb")
_GO_VERB_RE: Final = _rx(lx.GO_VERBS, "verb")
_LITTLE_RE: Final = _rx(lx.LITTLE_PHRASES)
_MOVE_DIR_RE: Final = _rx(lx.MOVE_DIRECTIONS, "dir")
_ROTATE_DIR_RE: Final = _rx(lx.ROTATE_DIRECTIONS, "dir")
_DETAIL_AT_END_RE: Final = re.compile(lx.phrase_regex(lx.DETAIL_PHRASES, "detail") + r"\s*$")
_VERB_DETAIL_RE: Final = _rx(lx.VERB_DETAILS, "verb")
_VERB_DETAIL_AT_END_RE: Final = re.compile(lx.phrase_regex(lx.VERB_DETAILS, "verb") + r"\s*$")
_SIDE_POST_RE: Final = re.compile(
    r"\s*(?:,\s*)?(?:(?:that|which|who)\s+(?:is|are|lies|sits|stands)\s+|(?:located|situated|lying|standing|"
    r"sitting|positioned|placed)\s+|(?:that\s+)?you\s+(?:can\s+)?see\s+|that\s+you\s+(?:can\s+)?see\s+)?"
    + lx.phrase_regex(lx.SIDE_PHRASES, "side"))
_POST_SUPERLATIVE_RE: Final = re.compile(r"\s*(?:(?:that|which)\s+(?:is|are)\s+)?"
                                         + lx.phrase_regex(lx.POST_SUPERLATIVES, "sup"))
_ROOM_YOU_ARE_IN_RE: Final = re.compile(r"\s*" + lx.phrase_regex(lx.ROOM_YOU_ARE_IN))
_NUMBER_POST_RE: Final = re.compile(r"\s*(?:number|no|#)\s*(?P<n>\d{1,2}|one|two|three|four|five|six|seven|"
                                    r"eight|nine|ten)(?!\w)")
_FAR_END_LINK_RE: Final = re.compile(r"\s*" + lx.phrase_regex(lx.FAR_END_LINKS) + r"\s*")
_CONTAINER_LINK_RE: Final = re.compile(r"\s*" + lx.phrase_regex(lx.CONTAINER_LINKS) + r"\s*$")
_CURRENT_ROOM_POST_RE: Final = re.compile(
    r"\s*(?:(?:of|in|inside|within|inside\s+of)\s+)?" + lx.phrase_regex(lx.CURRENT_ROOM_PHRASES, "cur"))
_ACROSS_LINK_RE: Final = re.compile(r"\s*(?:(?:right|directly|just)\s+)?(?:across|across\s+from\s+you\s+(?:in|on)|"
                                    r"on\s+the\s+(?:other|opposite|far)\s+side\s+of)\s*")
_BETWEEN_AND_RE: Final = re.compile(r"^\s*(?:and|&|,)\s*$")
_TURN_A_SIDE_RE: Final = re.compile(r"\b(?:take|make|hang|do|go)\s+a\s+(?P<dir>left|right)\b(?:\s+turn\b)?")
_TURN_NOUN_RE: Final = re.compile(r"\b(?:turn|rotation|spin|u\s+turn|180|about\s+face|circle|revolution|pirouette)\b")
_PASSED_RE: Final = re.compile(r"\b(?:after|once|when|as\s+soon\s+as)\b.*\b(?:through|past|passed|beyond|"
                               r"cleared|crossed|exit)\b")
_ORDINAL_WORDS: Final = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7,
                         "eight": 8, "nine": 9, "ten": 10}
_WORD_RE: Final = re.compile(r"[a-z][a-z'-]*|\d+(?:\.\d+)?")

#: Every word the lexicon knows (a word outside it, before an element noun, is part of a name).
KNOWN_WORDS: Final = frozenset(
    w for phrase in (*lx.ELEMENT_NOUNS, *lx.ORDINALS, *lx.SUPERLATIVES, *lx.SIDE_ADJECTIVES,
                     *lx.FRONT_BACK_ADJECTIVES, *lx.SIDE_PHRASES, *lx.DETAIL_PHRASES, *lx.VERB_DETAILS,
                     *lx.GO_VERBS, *lx.ROTATE_VERBS, *lx.STOP_PHRASES, *lx.MOVE_DIRECTIONS,
                     *lx.ROTATE_DIRECTIONS, *lx.LITTLE_PHRASES, *lx.STOPWORDS, *lx.DETERMINERS,
                     *lx.NEUTRAL_ADJECTIVES, *lx.CURRENT_ROOM_PHRASES, *lx.CONTAINER_LINKS,
                     *_MODIFIER_WORDS)
    for w in phrase.split())


# ------------------------------------------------------------------------------ scratch text
class _Scratch:
    """The normalised clause and which of its characters have been read."""

    def __init__(self, text: str) -> None:
        self.text = text
        self._used = [False] * len(text)

    def masked(self) -> str:
        return "".join(" " if u else c for c, u in zip(self.text, self._used, strict=True))

    def use(self, start: int, end: int) -> None:
        for i in range(max(start, 0), min(end, len(self.text))):
            self._used[i] = True

    def is_free(self, start: int, end: int) -> bool:
        return not any(self._used[start:end])

    def take_all(self, pattern: re.Pattern[str]) -> list[re.Match[str]]:
        matches = list(pattern.finditer(self.masked()))
        for m in matches:
            self.use(m.start(), m.end())
        return matches

    def find(self, pattern: re.Pattern[str]) -> re.Match[str] | None:
        return pattern.search(self.masked())

    def leftover_words(self) -> list[str]:
        return _WORD_RE.findall(self.masked())


# ------------------------------------------------------------------------------ noun phrases
@dataclass
class _Phrase:
    """One element reference found in the clause."""

    ref: ElementRef
    start: int
    end: int
    head_start: int
    pair: bool = False          # "the two obstacles", "both boxes"
    pronoun: bool = False       # "it", "there", "the second one"
    weak: bool = False          # a doubtful word was read ("passage" alone, "the other door")
    contained: bool = False     # this phrase is the container of another ("of the hallway")
    second: _Phrase | None = None  # the B of "between A and B"
    detail: Detail | None = None
    detail_from_verb: str | None = None
    bare_prep: bool = False     # only a preposition links it to the element before ("the door next to the box")
    lost: list[str] = field(default_factory=list)  # properties the schema cannot hold


def _find_phrases(s: _Scratch, previous: ElementRef | None) -> tuple[list[_Phrase], str | None]:
    """Every element reference in the clause, left to right, with containers and pairs resolved.

    Returns the phrases and, if an unknown word names the place ("the kitchen door"), that name."""
    text = s.masked()
    phrases: list[_Phrase] = []
    name: str | None = None
    for m in _HEAD_RE.finditer(text):
        head = " ".join(m.group("head").split())
        if phrases and m.start() < phrases[-1].end:
            continue
        if head in _VERB_LIKE_HEADS and re.fullmatch(r"\s*", text[:m.start()]) \
                and re.match(r"\s+(?:the|this|that|from|through|out|via|here|a|your|it)\b", text[m.end():]):
            continue  # "exit the room": a verb, not a door
        is_one = head in ("one", "ones")
        if is_one and previous is None:
            continue
        kind = previous.kind if is_one and previous is not None else lx.ELEMENT_NOUNS[head]
        phrase = _read_modifiers(text, m.start(), m.end(), kind, head)
        if phrase is None:
            continue
        if is_one:
            if phrase.start == m.start():  # "one" with no determiner or modifier is a number
                continue
            phrase = _inherit(phrase, previous)
        compound = _compound_name(text, phrase)
        if compound is not None:
            name = compound
            s.use(phrase.start, phrase.end)
            continue
        if phrases and _adjacent_heads(text, phrases[-1], phrase):
            phrase = _merge_heads(phrases.pop(), phrase)
        _read_post_modifiers(text, phrase)
        phrases.append(phrase)
    phrases.extend(_find_pronouns(s, text, phrases, previous))
    phrases.sort(key=lambda p: p.start)
    phrases = _resolve_containers(text, phrases)
    phrases = _resolve_between(text, phrases)
    for p in phrases:
        s.use(p.start, p.end)
        if p.second is not None:
            s.use(p.second.start, p.second.end)
    return phrases, name


def _read_modifiers(text: str, head_start: int, head_end: int, kind: Element, head: str) -> _Phrase | None:
    """The noun phrase ending at this head: determiner, ordinal, superlative, side, pair words."""
    before = text[:head_start]
    run = _MODIFIERS_RUN.search(before)
    tokens = [(m.group(), (run.start() if run else head_start) + m.start())
              for m in re.finditer(r"\S+", before[run.start():] if run else "")]
    words = [w for w, _ in tokens]
    ordinal: int | None = None
    superlative: Superlative | None = None
    side: Side | None = None
    in_current = False
    pair = head in lx.PLURAL_NOUNS
    weak = head in lx.WEAK_NOUNS
    start = head_start
    i = len(words) - 1
    while i >= 0:
        w = words[i]
        two = f"{words[i - 1]} {w}" if i > 0 else ""
        two_value = lx.SIDE_ADJECTIVES.get(two) or lx.SUPERLATIVES.get(two)
        step = 1
        if two_value is not None:
            if isinstance(two_value, Side):
                side = side or two_value
            else:
                superlative = superlative or two_value
            step = 2
        elif w in lx.ORDINALS:
            ordinal = lx.ORDINALS[w]
        elif w in lx.SIDE_ADJECTIVES:
            side = side or lx.SIDE_ADJECTIVES[w]
        elif w in lx.FRONT_BACK_ADJECTIVES:
            if kind not in (Element.WALL, Element.CORNER):
                break  # "the front door" is a name
            side = side or lx.FRONT_BACK_ADJECTIVES[w]
        elif w in lx.SUPERLATIVES:
            sup = lx.SUPERLATIVES[w]
            if not (sup == Superlative.NARROWEST and kind == Element.NARROW_PASSAGE):
                superlative = superlative or sup
        elif w in _PAIR_WORDS:
            pair = True
        elif w in _WEAK_MODIFIERS:
            weak = True
        elif w in ("this", "your", "current") and kind in lx.CONTAINER_KINDS:
            in_current = True
        elif w == "of" and i > 0 and words[i - 1] in ("couple", "pair"):
            pass
        elif w not in lx.DETERMINERS and w not in lx.NEUTRAL_ADJECTIVES and w not in ("couple", "pair"):
            break
        i -= step
        start = tokens[i + 1][1]
        if w in lx.DETERMINERS and w not in _PAIR_WORDS and w != "one":
            break  # the determiner opens the phrase: "near the nearest box"
    if superlative == Superlative.FARTHEST and side in (Side.LEFT, Side.RIGHT) and "far" in words:
        superlative = None  # "the far left corner" is the leftmost one
    ref = ElementRef(kind=kind, ordinal=ordinal, superlative=superlative, side=side,
                     in_current_room=in_current)
    return _Phrase(ref=ref, start=start, end=head_end, head_start=head_start, pair=pair, weak=weak)


def _inherit(phrase: _Phrase, previous: ElementRef | None) -> _Phrase:
    """'the second one': the kind (and where it lies) from the previous element, the rest new."""
    if previous is None:
        return phrase
    ref = phrase.ref
    merged = ref.model_copy(update={
        "side": ref.side or previous.side, "within": previous.within,
        "in_current_room": ref.in_current_room or previous.in_current_room})
    phrase.ref = merged
    phrase.pronoun = True
    return phrase


def _compound_name(text: str, phrase: _Phrase) -> str | None:
    """'the kitchen door', 'the living room', "bob's office": an unknown word before the noun."""
    before = text[:phrase.start]
    m = re.search(r"(?:^|\s)(?P<det>the|a|an|my|our|your|his|her|their)\s+(?P<words>(?:[a-z][\w']*\s+){1,2})$",
                  before)
    possessive = re.search(r"(?P<words>[a-z]+'s?\s+)$", before)
    if m is None and possessive is None:
        return None
    words = (m.group("words") if m else possessive.group("words") if possessive else "").split()
    if not words or any(w in KNOWN_WORDS for w in words[-1:]):
        return None
    if any(w.rstrip("'s") in KNOWN_WORDS and w.endswith("'s") is False for w in words):
        words = words[-1:]
    head = text[phrase.head_start:phrase.end].strip()
    return " ".join([*words, head])


def _adjacent_heads(text: str, first: _Phrase, second: _Phrase) -> bool:
    """'the hallway door', 'the exit door': two nouns in a row are one element."""
    return second.start == second.head_start and text[first.end:second.head_start].strip() == ""


def _merge_heads(first: _Phrase, second: _Phrase) -> _Phrase:
    ref = first.ref.model_copy(update={"kind": second.ref.kind})
    if first.ref.kind in lx.CONTAINER_KINDS and second.ref.kind != first.ref.kind:
        ref = second.ref.model_copy(update={
            "within": first.ref.kind, "ordinal": first.ref.ordinal, "superlative": first.ref.superlative,
            "side": first.ref.side})
    return _Phrase(ref=ref, start=first.start, end=second.end, head_start=second.head_start,
                   pair=first.pair or second.pair, weak=first.weak and second.weak)


def _read_post_modifiers(text: str, phrase: _Phrase) -> None:
    """'on your left', 'in front of you', 'closest to you', 'you are in', 'number 2'."""
    ref = phrase.ref
    while True:
        rest = text[phrase.end:]
        m = _SIDE_POST_RE.match(rest)
        if m and ref.side is None:
            ref = ref.model_copy(update={"side": lx.lookup(lx.SIDE_PHRASES, m.group("side"))})
            phrase.end += m.end()
            continue
        m = _POST_SUPERLATIVE_RE.match(rest)
        if m and ref.superlative is None:
            ref = ref.model_copy(update={"superlative": lx.lookup(lx.POST_SUPERLATIVES, m.group("sup"))})
            phrase.end += m.end()
            continue
        m = _ROOM_YOU_ARE_IN_RE.match(rest)
        if m and ref.kind in lx.CONTAINER_KINDS:
            ref = ref.model_copy(update={"in_current_room": True})
            phrase.end += m.end()
            continue
        m = _NUMBER_POST_RE.match(rest)
        if m and ref.ordinal is None:
            n = m.group("n")
            ref = ref.model_copy(update={"ordinal": int(n) if n.isdigit() else _ORDINAL_WORDS[n]})
            phrase.end += m.end()
            continue
        m = _CURRENT_ROOM_POST_RE.match(rest)
        if m and ref.kind not in lx.CONTAINER_KINDS and not ref.in_current_room:
            ref = ref.model_copy(update={"in_current_room": True})
            phrase.end += m.end()
            continue
        break
    phrase.ref = ref


def _find_pronouns(s: _Scratch, text: str, phrases: list[_Phrase], previous: ElementRef | None) -> list[_Phrase]:
    """'go through it', 'go there': the previous step's element."""
    found: list[_Phrase] = []
    for m in _PRONOUN_RE.finditer(text):
        if any(p.start <= m.start() < p.end for p in phrases):
            continue
        ref = previous if previous is not None else ElementRef(kind=Element.NONE)
        found.append(_Phrase(ref=ref, start=m.start(), end=m.end(), head_start=m.start(), pronoun=True))
    return found


def _resolve_containers(text: str, phrases: list[_Phrase]) -> list[_Phrase]:
    """'the corner of the hallway' -> corner within hallway; 'in this room' -> in_current_room;
    'the corner of the biggest room' -> near the biggest room; 'the room at the end of the hallway'
    -> the farthest room off the hallway; 'the door across the hallway' -> the hallway's door ahead."""
    out: list[_Phrase] = []
    for p in phrases:
        if out and p.ref.kind in lx.CONTAINER_KINDS and not p.pronoun:
            host = out[-1]
            link = text[host.end:p.start]
            far_end = _FAR_END_LINK_RE.fullmatch(link) is not None
            if host.ref.kind not in lx.CONTAINER_KINDS and (far_end or _CONTAINER_LINK_RE.fullmatch(link)):
                host.ref = _contain(host.ref, p)
                if far_end and host.ref.superlative is None:
                    host.ref = host.ref.model_copy(update={"superlative": Superlative.FARTHEST})
                host.end = p.end
                continue
            if host.ref.kind not in lx.CONTAINER_KINDS and _ACROSS_LINK_RE.fullmatch(link):
                host.ref = _contain(host.ref, p)
                if host.ref.side is None:
                    host.ref = host.ref.model_copy(update={"side": Side.AHEAD})
                host.end = p.end
                continue
            if host.ref.kind == Element.ROOM and p.ref.kind == Element.HALLWAY and far_end \
                    and host.ref.near is None:
                host.ref = host.ref.model_copy(update={
                    "near": as_landmark(p.ref), "superlative": host.ref.superlative or Superlative.FARTHEST})
                host.end = p.end
                continue
        out.append(p)
    return out


def as_landmark(ref: ElementRef) -> Landmark:
    """The properties of an element reference that a landmark holds."""
    return Landmark(kind=ref.kind, ordinal=ref.ordinal, superlative=ref.superlative, side=ref.side,
                    in_current_room=ref.in_current_room, within=ref.within)


def _contain(ref: ElementRef, container: _Phrase) -> ElementRef:
    c = container.ref
    if c.in_current_room:
        return ref.model_copy(update={"in_current_room": True})
    if c.ordinal is not None or c.superlative is not None or c.side is not None:
        # "the corner of the biggest room": which room the words say too
        return ref.model_copy(update={"within": c.kind, "near": as_landmark(c)})
    return ref.model_copy(update={"within": c.kind})


def _resolve_between(text: str, phrases: list[_Phrase]) -> list[_Phrase]:
    """'between A and B': B becomes A's second element."""
    out: list[_Phrase] = []
    for p in phrases:
        if out and out[-1].second is None and _BETWEEN_AND_RE.match(text[out[-1].end:p.start]):
            before = text[:out[-1].start]
            if re.search(r"\b(?:between|betwixt|in\s+the\s+middle\s+of|halfway\s+between|midway\s+between)\s*$",
                         before):
                out[-1].second = p
                continue
        out.append(p)
    return out


# ------------------------------------------------------------------------------ details
def _assign_details(s: _Scratch, phrases: list[_Phrase], clause_start: int) -> None:
    """The detail of each element, from the words just before it (or the verb of the clause)."""
    boundary = clause_start
    for p in phrases:
        region = s.masked()[boundary:p.start]
        m = _VERB_DETAIL_AT_END_RE.search(region) or _DETAIL_AT_END_RE.search(region)
        if m is not None:
            key = m.group("verb") if "verb" in m.groupdict() and m.group("verb") else m.group("detail")
            table = lx.VERB_DETAILS if m.re is _VERB_DETAIL_AT_END_RE else lx.DETAIL_PHRASES
            p.detail = _as_detail(lx.lookup(table, key))
            if table is lx.VERB_DETAILS:
                p.detail_from_verb = " ".join(key.split())
            s.use(boundary + m.start(), boundary + m.end())
            p.bare_prep = boundary > clause_start and region[:m.start()].strip() == ""
        else:
            v = _VERB_DETAIL_RE.search(region)
            if v is not None:
                p.detail = _as_detail(lx.lookup(lx.VERB_DETAILS, v.group("verb")))
                p.detail_from_verb = " ".join(v.group("verb").split())
                s.use(boundary + v.start(), boundary + v.end())
        boundary = p.second.end if p.second is not None else p.end


def _as_detail(value: object) -> Detail:
    if not isinstance(value, Detail):
        raise TypeError(f"lexicon entry {value!r} is not a Detail")
    return value


def _fit_detail(detail: Detail | None, kind: Element) -> Detail:
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


# ------------------------------------------------------------------------------ the clause
@dataclass
class _Clause:
    text: str                  # as the user wrote it
    s: _Scratch
    previous: Step | None
    factors: list[float] = field(default_factory=list)
    lost: list[str] = field(default_factory=list)
    elliptical: bool = False   # no verb: the movement is borrowed from the previous step
    amends: bool = False       # only a number: it completes the previous step
    had_verb: bool = False     # a movement verb was read
    out_of_range: bool = False  # a number beyond what a step may hold
    explore_verb: bool = False  # "explore the unknown area on your left" (a trip towards it)
    through_previous: bool = False  # "stop after you pass through it": the previous step goes through

    def doubt(self, factor: float) -> None:
        self.factors.append(factor)


def read_clause(text: str, previous: Step | None = None, known_names: Sequence[str] = (),
                previous_target: ElementRef | None = None) -> Reading:
    """Read one instruction. ``previous`` is the step before it and ``previous_target`` the last
    element named (for 'it', 'there', 'the next one')."""
    norm = normalize(text)
    c = _Clause(text=text, s=_Scratch(norm), previous=previous)
    if not norm:
        return Reading()
    query = _read_query(c)
    if query is not None:
        return query
    if _OTHER_FLOOR_RE.search(norm):
        return Reading(unread=(text,), confidence=OUT_OF_SCOPE_CONFIDENCE, problem=Problem.OTHER_FLOOR)
    if _is_negated(norm):
        return Reading(unread=(text,), confidence=0.3, problem=Problem.NEGATED)
    if _QUESTION_RE.match(norm):
        return Reading(unread=(text,), confidence=OUT_OF_SCOPE_CONFIDENCE, problem=Problem.QUESTION,
                       referent=_question_referent(norm))
    if _OUT_OF_SCOPE_RE.search(norm) and not _EXPLORE_RE.search(norm):
        return Reading(unread=(text,), confidence=OUT_OF_SCOPE_CONFIDENCE, problem=Problem.OUT_OF_SCOPE)
    c.s.take_all(_FILLER_RE)
    durations = c.s.take_all(_DURATION_RE)
    back = _read_return(c)
    if back is not None:
        return back
    start_place = c.s.find(_START_PLACE_RE)
    if start_place is not None:
        c.s.use(start_place.start(), start_place.end())
    if previous_target is None:
        previous_target = _previous_target(previous)
    phrases, name = _find_phrases(c.s, previous_target)
    if name is not None:
        return _named(c, name, known_names)
    if start_place is not None:
        phrases.append(_Phrase(ref=START_REF, start=start_place.start(), end=start_place.end(),
                               head_start=start_place.start(), detail=Detail.TO))
        phrases.sort(key=lambda p: p.start)
    explore = _read_explore(c, phrases)
    if explore is not None:
        return explore
    verb = _main_verb(c)
    if verb[0] == _Verb.NONE and c.explore_verb:
        verb = (_Verb.GO, None)
    if not phrases and verb[0] in (_Verb.GO, _Verb.STOP):
        unknown = _unknown_destination(c.s.masked())
        if unknown is not None:
            return _named(c, unknown, known_names)  # "drive to the desk on your left"
    _assign_details(c.s, phrases, 0)
    c.s.take_all(_LATE_FILLER_RE)
    if any(p.pronoun and p.ref.kind == Element.NONE and p.ref.name is None for p in phrases):
        stop_only = c.s.find(_STOP_RE) is not None
        if not stop_only:
            return Reading(unread=(text,), confidence=0.3, problem=Problem.NO_ANTECEDENT)
        phrases = [p for p in phrases if p.ref.kind != Element.NONE]
    try:
        steps = _build_steps(c, phrases, verb)
    except _OutOfRange:
        return Reading(unread=(text,), confidence=OUT_OF_SCOPE_CONFIDENCE, problem=Problem.OUT_OF_RANGE)
    leftovers = [w for w in c.s.leftover_words() if w not in lx.STOPWORDS]
    if (verb[0] == _Verb.NONE and not phrases and steps and (leftovers or c.previous is None)
            and all(st.movement == Movement.MOVE for st in steps) and not _MOVE_DIR_RE.search(norm)):
        # a distance with no verb and no direction ("banana 2", "alert(1)", a lone "2 m") is no
        # instruction of its own: it may only complete the step before it ("move forward, 2 m")
        return Reading(unread=(text,), confidence=NOTHING_READ_CONFIDENCE, problem=Problem.UNREADABLE)
    if steps and any(_NUMBERISH_RE.search(w) for w in leftovers):
        # a number left unread ("the 25th door", "ninety billion degrees", "3.5.5 m") means the
        # step was read without it: never move on a misread number, ask instead
        return Reading(unread=(text,), confidence=NOTHING_READ_CONFIDENCE, problem=Problem.BAD_NUMBER)
    guessed = [st for st in steps if st.movement in (Movement.MOVE, Movement.ROTATE) and st.amount == Amount.DEFAULT]
    if durations and guessed:
        # "drive forward for 5 seconds": a time is no distance; ask rather than guess one
        return Reading(unread=(text,), confidence=OUT_OF_SCOPE_CONFIDENCE, problem=Problem.DURATION)
    unnumbered = [st for st in steps if st.movement in (Movement.MOVE, Movement.ROTATE)
                  and st.target is None] if not find_quantities(norm) else []
    if (guessed or unnumbered) and (leftovers or c.lost):
        # a default move or turn built around words not understood ("take the stairs ...") is a
        # misreading: never motion, hand the clause on instead
        return Reading(unread=(text,), confidence=NOTHING_READ_CONFIDENCE, problem=Problem.UNREADABLE)
    c.lost.extend(c.s.text[m.start():m.end()].strip() for m in durations)
    if not steps:
        if c.out_of_range:
            return Reading(unread=(text,), confidence=OUT_OF_SCOPE_CONFIDENCE, problem=Problem.OUT_OF_RANGE)
        if leftovers and _GO_VERB_RE.search(norm) and not phrases:
            return _named(c, " ".join(leftovers), known_names)
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
                   through_previous=c.through_previous)


def is_unsafe(prompt: str) -> bool:
    """True when the prompt asks for something unsafe or tries to override the rules."""
    norm = _SAFE_AVOIDANCE_RE.sub(" ", normalize(prompt))  # "without hitting the wall" is safe
    return _UNSAFE_RE.search(norm) is not None


def _read_return(c: _Clause) -> Reading | None:
    """'come back', 'return', 'go back' after a trip: back to where the prompt started. ('go back'
    as the first instruction is a move backward.)"""
    m = _BARE_RETURN_RE.match(" ".join(c.s.masked().split()))
    if m is None:
        return None
    moved = c.previous is not None and c.previous.movement in (Movement.NAVIGATE, Movement.MOVE, Movement.FOLLOW,
                                                                 Movement.EXPLORE)
    if m.group("go") and "back" in c.s.masked() and not moved:
        return None  # "go back" with no trip before it: a move backward
    if m.group("go") and "back" not in c.s.masked():
        return None
    return Reading(steps=(Step(movement=Movement.NAVIGATE, detail=Detail.TO, target=START_REF, text=c.text[:500]),))


def _question_referent(norm: str) -> ElementRef | None:
    """The one element a 'which / where / what is the X' question names, if it names exactly one."""
    if _ELEMENT_QUESTION_RE.match(norm) is None:
        return None
    # "which room is the smallest" -> "which is the smallest room"
    norm = re.sub(r"^(which|what)\s+([a-z]+(?:\s+[a-z]+)?)\s+(?:is|are)\s+(?:the\s+)?([a-z]+)(\s+(?:one|of\s+them))?\s*$",
                  r"\1 is the \3 \2", norm)
    phrases, name = _find_phrases(_Scratch(norm), None)
    keep = [p for p in phrases if not p.contained and not p.pronoun]
    if name is not None or len(keep) != 1:
        return None
    return keep[0].ref


def _previous_target(previous: Step | None) -> ElementRef | None:
    if previous is None:
        return None
    return previous.target


def _is_negated(norm: str) -> bool:
    m = _NEGATION_RE.search(norm)
    if m is None:
        return False
    # "do not move", "don't go any further" are stops, read as such
    return _STOP_RE.search(norm) is None or "stop" in norm[m.end():m.end() + 12]


def _read_query(c: _Clause) -> Reading | None:
    norm = c.s.text
    if re.match(r"^\s*(?:go|drive|move|head|navigate|turn|rotate)\b", norm):
        return None
    for query, pattern in _QUERY_RES:
        if pattern.search(norm):
            if query == Query.MAP and _EXPLORE_RE.search(norm) and not re.search(r"\b(?:show|display|see|view)\b", norm):
                continue
            return Reading(steps=(Step(movement=Movement.QUERY, query=query, text=c.text),))
    return None


def _read_explore(c: _Clause, phrases: list[_Phrase]) -> Reading | None:
    m = c.s.find(_EXPLORE_RE)
    if m is None:
        return None
    if any(p.ref.kind == Element.UNEXPLORED_AREA for p in phrases):
        c.s.use(m.start(), m.end())
        c.explore_verb = True
        return None  # "explore the unknown area on your left": go towards it
    if any(p.ref.kind not in (Element.ROOM, Element.HALLWAY, Element.NONE) for p in phrases):
        return None  # "explore behind the box": read as a trip to the box
    leftovers = [w for w in c.s.leftover_words() if w not in lx.EXPLORE_SCOPE_WORDS and w not in lx.STOPWORDS]
    confidence = max(MIN_CONFIDENCE, UNREAD_WORD_FACTOR ** len(leftovers))
    return Reading(steps=(Step(movement=Movement.EXPLORE, text=c.text),),
                   unread=(" ".join(leftovers),) if leftovers else (), confidence=round(confidence, 3))


_NAME_DETAIL_RE: Final = re.compile(lx.phrase_regex(lx.DETAIL_PHRASES, "detail")
                                     + r"\s+(?:(?:the|a|an|my|our|your)\s+)?$")
_DESTINATION_RE: Final = re.compile(
    r"\b(?:to|towards?|into|next\s+to|beside|near|through|at|by|reach|enter|approach|visit|find)\s+"
    r"(?:the\s+|a\s+|an\s+|my\s+|our\s+|your\s+)?(?P<name>[a-z][\w']*(?:\s+[a-z][\w']*)?)")


def _unknown_destination(masked: str) -> str | None:
    """The unknown word(s) after 'to the' in a clause with no element: a place name."""
    for m in _DESTINATION_RE.finditer(masked):
        words = m.group("name").split()
        if words[0] in KNOWN_WORDS:
            continue
        if len(words) > 1 and words[1] in KNOWN_WORDS:
            words = words[:1]
        return " ".join(words)
    return None


def _named(c: _Clause, name: str, known_names: Sequence[str]) -> Reading:
    """A place the map cannot know: a step to it if the user named it before, else a question."""
    clean = re.sub(r"^(?:the|a|an|my|our)\s+", "", name).strip()
    known = {n.lower().strip(): n for n in known_names}
    if clean in known:
        detail = Detail.TO
        m = _NAME_DETAIL_RE.search(c.s.text[:c.s.text.find(clean.split()[0])] if clean else "")
        if m is not None:
            detail = _as_detail(lx.lookup(lx.DETAIL_PHRASES, m.group("detail")))
        ref = ElementRef(kind=Element.NONE, name=known[clean][:80])
        return Reading(steps=(Step(movement=Movement.NAVIGATE, detail=detail, target=ref, text=c.text[:500]),))
    if any(w in lx.UNKNOWABLE_ADJECTIVES for w in clean.split()[:-1]):
        # "the red door": a real element described by what a grid cannot show
        return Reading(confidence=NAME_CONFIDENCE, problem=Problem.UNKNOWABLE, name=clean[:80], unread=(c.text,))
    return Reading(confidence=NAME_CONFIDENCE, problem=Problem.NAME, name=clean[:80], unread=(c.text,))


# ------------------------------------------------------------------------------ building steps
class _Verb(StrEnum):
    STOP = "stop"
    ROTATE = "rotate"
    GO = "go"
    NONE = "none"


def _main_verb(c: _Clause) -> tuple[_Verb, re.Match[str] | None]:
    text = c.s.masked()
    candidates: list[tuple[int, _Verb, re.Match[str]]] = []
    for verb, pattern in ((_Verb.STOP, _STOP_RE), (_Verb.ROTATE, _ROTATE_VERB_RE), (_Verb.GO, _GO_VERB_RE)):
        m = pattern.search(text)
        if m is None:
            continue
        if verb == _Verb.ROTATE and m.group("verb").split()[0] in lx.ROTATE_NOUN_VERBS \
                and not _TURN_NOUN_RE.search(text[m.start():]):
            continue
        candidates.append((m.start(), verb, m))
    turn_a_side = _TURN_A_SIDE_RE.search(text)
    if turn_a_side is not None:
        return _Verb.ROTATE, turn_a_side
    if not candidates:
        return _Verb.NONE, None
    candidates.sort(key=lambda t: t[0])
    # "stop" wins wherever it is ("go to the door and stop there" was split already)
    for _, verb, m in candidates:
        if verb == _Verb.STOP:
            return verb, m
    return candidates[0][1], candidates[0][2]


def _build_steps(c: _Clause, phrases: list[_Phrase], main_verb: tuple[_Verb, re.Match[str] | None]) -> list[Step]:
    verb, vm = main_verb
    if vm is not None:
        c.s.use(vm.start(), vm.end())
        c.had_verb = True
    targets = [p for p in phrases if not p.contained]
    if verb == _Verb.STOP:
        return _stop_steps(c, targets)
    if verb == _Verb.ROTATE:
        return _rotate_steps(c, targets, vm)
    if targets:
        if verb == _Verb.NONE:
            c.doubt(ELLIPSIS_FACTOR)
        return _navigate_steps(c, targets, verb)
    return _move_steps(c, verb, vm)


def _ref_step(c: _Clause, p: _Phrase, movement: Movement = Movement.NAVIGATE,
              default: Detail | None = None) -> Step:
    detail = p.detail
    if detail is None and default is not None:
        detail = default
    if detail is None and c.previous is not None and p.pronoun is False and c.previous.detail is not None \
            and c.previous.movement == Movement.NAVIGATE and c.elliptical:
        detail = c.previous.detail  # "go through the first door, then the second one"
    kind = p.ref.kind
    fitted = _fit_detail(detail, kind)
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


def _navigate_steps(c: _Clause, targets: list[_Phrase], verb: _Verb) -> list[Step]:
    c.elliptical = verb == _Verb.NONE
    _infer_side_from_direction(c, targets[0])
    steps: list[Step] = []
    kept = _destinations(targets)
    for p in kept:
        steps.append(_ref_step(c, p))
    for p in targets:
        if p not in kept:
            c.s.use(p.start, p.end)
    _discard_quantities(c)
    return steps


def _destinations(targets: list[_Phrase]) -> list[_Phrase]:
    """Elements that are places to go, in order. A route ('down the hallway to the door') is dropped
    when a destination follows it; an element right after another with 'next to' qualifies it."""
    kept: list[_Phrase] = []
    for i, p in enumerate(targets):
        later = targets[i + 1:]
        if p.detail in (Detail.ALONG,) and any(q.detail in (Detail.TO, Detail.NEXT_TO, Detail.STOP_AT,
                                                               Detail.MIDDLE) for q in later):
            continue
        if p.detail == Detail.THROUGH and p.ref.kind == Element.HALLWAY and later:
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


def _infer_side_from_direction(c: _Clause, first: _Phrase) -> None:
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


def _discard_quantities(c: _Clause) -> None:
    """Numbers in a navigation ('go 2 m past the door') cannot be kept: they stay unread."""
    for q in find_quantities(c.s.masked()):
        c.lost.append(c.s.masked()[q.start:q.end].strip())
        c.s.use(q.start, q.end)


def _stop_steps(c: _Clause, targets: list[_Phrase]) -> list[Step]:
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
                return [_ref_step(c, pronoun), stop]
        c.s.take_all(re.compile(r"\b(?:after|once|when|as\s+soon\s+as|you|pass|passed|passing|going|driving|getting|are|have|get|got|"
                                r"through|past|beyond|cleared|crossed|reach|reached|arrive|arrived|"
                                r"right|immediately|just|behind|exit|exited)\b"))
        return [stop]
    p = explicit[0]
    if passed:
        c.s.take_all(re.compile(r"\b(?:after|once|when|as\s+soon\s+as|you|pass|passed|passing|going|driving|getting|are|have|get|got|"
                                r"through|past|beyond|cleared|crossed|just|right|immediately|exit|exited)\b"))
        p.detail = Detail.THROUGH
        return [_ref_step(c, p), stop]
    c.s.take_all(re.compile(r"\b(?:when|once|as\s+soon\s+as|you|reach|get|are|arrive|at)\b"))
    detail = p.detail if p.detail not in (None, Detail.TO) else Detail.STOP_AT
    p.detail = detail
    return [_ref_step(c, p)]


def _rotate_steps(c: _Clause, targets: list[_Phrase], vm: re.Match[str] | None) -> list[Step]:
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
            steps.append(_ref_step(c, p))
        else:
            for q in targets:
                c.s.use(q.start, q.end)
            c.s.take_all(re.compile(r"\b(?:to\s+face|face|facing|to|towards?|so\s+that\s+you\s+face|"
                                    r"until\s+you\s+(?:face|see))\b"))
            return [Step(movement=Movement.ROTATE, detail=Detail.TOWARDS, target=p.ref, text=c.text[:500])]
    steps.append(_rotation(c, vm))
    return steps


#: "turn round to the left": only a bare "round / around" gives way to a side named with it.
_SPIN_ROUND_RE: Final = re.compile(r"(?<!way\s)\b(?:a)?round\b(?!\s+(?:twice|two|2|three|\d))")
_REPEAT_RE: Final = re.compile(r"\b(?:(?P<word>once|twice|thrice)|(?P<n>\d+|one|two|three|four|five)\s+times)\b")
_REPEAT_WORDS: Final = {"once": 1, "twice": 2, "thrice": 3, "one": 1, "two": 2, "three": 3, "four": 4, "five": 5}


def _repeat_count(c: _Clause) -> int:
    """'twice', 'three times': how many times the move or turn is done (1 when not said)."""
    m = c.s.find(_REPEAT_RE)
    if m is None:
        return 1
    c.s.use(m.start(), m.end())
    word = m.group("word") or m.group("n")
    return int(word) if word.isdigit() else _REPEAT_WORDS[word]


def _rotation(c: _Clause, vm: re.Match[str] | None) -> Step:
    step = _single_rotation(c, vm)
    times = _repeat_count(c)
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


def _single_rotation(c: _Clause, vm: re.Match[str] | None) -> Step:
    direction: Direction | None = None
    if vm is not None and " ".join(vm.group(0).split()) in _AROUND_VERBS:
        direction = Direction.AROUND
    elif vm is not None and "dir" in vm.groupdict() and vm.group("dir"):
        direction = Direction.LEFT if vm.group("dir") == "left" else Direction.RIGHT
    quantities = find_quantities(c.s.masked())
    angle: float | None = None
    for q in quantities:
        c.s.use(q.start, q.end)
        if q.kind == QuantityKind.ANGLE or q.kind == QuantityKind.BARE:
            if q.kind == QuantityKind.BARE:
                c.doubt(UNITLESS_NUMBER_FACTOR if q.value not in (90, 180, 45, 360, 270, 30, 60) else 1.0)
            angle = (angle or 0.0) + q.value
        else:
            c.lost.append(c.text)
    little = c.s.take_all(_LITTLE_RE)
    sides: list[Direction] = []
    for m in c.s.take_all(_ROTATE_DIR_RE):
        d = lx.lookup(lx.ROTATE_DIRECTIONS, m.group("dir"))
        if isinstance(d, Direction):
            if d in (Direction.LEFT, Direction.RIGHT):
                sides.append(d)
            if direction is None:
                direction = d
    if direction == Direction.AROUND and sides and _SPIN_ROUND_RE.search(c.s.text):
        direction = sides[0]  # "spin round to your left": a turn to that side, not a U-turn
    amount: Amount | None = None
    if direction == Direction.AROUND:
        if angle is None or abs(angle - 180.0) < 1e-6:
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
    elif angle is None:
        amount = Amount.LITTLE if little else Amount.DEFAULT
        if direction is None:
            verb = vm.group(0) if vm is not None else ""
            if re.search(r"\b(?:spin|pirouette|twirl)\b", verb) or re.search(r"\blook\s+around\b", c.s.text):
                direction, angle, amount = Direction.LEFT, 360.0, None
            else:
                direction = Direction.LEFT
                c.doubt(GUESSED_DIRECTION_FACTOR)
    return Step(movement=Movement.ROTATE, direction=direction, angle_deg=_checked_angle(angle), amount=amount,
                text=c.text[:500])


def _move_steps(c: _Clause, verb: _Verb, vm: re.Match[str] | None) -> list[Step]:
    """'move forward 1 m', 'back up a bit', 'go left half a metre' (or a fragment: 'then 2 m')."""
    text = c.s.masked()
    quantities = find_quantities(text)
    lengths = [q for q in quantities if q.kind == QuantityKind.LENGTH]
    angles = [q for q in quantities if q.kind == QuantityKind.ANGLE]
    direction = _move_direction(c, vm)
    c.amends = verb == _Verb.NONE and direction is None and bool(quantities)
    if angles and not lengths:
        return [_rotation_from(c, direction, quantities, [])] if direction in (Direction.LEFT, Direction.RIGHT) \
            else [_rotation(c, None)]  # "go left 90 degrees", "then 45 degrees"
    little = c.s.take_all(_LITTLE_RE)
    if verb == _Verb.NONE and direction is None and not quantities:
        return []
    if verb == _Verb.NONE and direction in (Direction.LEFT, Direction.RIGHT) and not lengths:
        c.doubt(ELLIPSIS_FACTOR)  # "then left": a turn
        return [_rotation_from(c, direction, quantities, little)]
    distance: float | None = None
    amount: Amount | None = None
    for q in quantities:
        c.s.use(q.start, q.end)
        if q.kind == QuantityKind.LENGTH:
            distance = (distance or 0.0) + q.value
            if q.approximate:
                c.doubt(VAGUE_NUMBER_FACTOR)
        elif q.kind == QuantityKind.BARE and not lengths:
            distance = (distance or 0.0) + q.value
            c.doubt(UNITLESS_NUMBER_FACTOR)
        else:
            c.lost.append(c.s.text[q.start:q.end])
    if distance is None and direction is None and not little:
        return []  # "go to the kitchen": no element, no direction, no number -> a name or nothing
    if distance is None:
        if little:
            amount = Amount.LITTLE
        else:
            amount = Amount.DEFAULT
            c.doubt(DEFAULT_AMOUNT_FACTOR)
    if direction is None:
        if verb == _Verb.NONE and distance is None:
            return []
        direction = Direction.FORWARD
        if distance is None and amount == Amount.DEFAULT:
            c.doubt(GUESSED_DIRECTION_FACTOR)
    if distance is not None and distance > MAX_MOVE_M:
        c.out_of_range = True
        return []
    times = _repeat_count(c)
    if distance is not None and times > 1:
        distance *= times
    if distance is not None and distance > MAX_MOVE_M:
        c.out_of_range = True
        return []
    return [Step(movement=Movement.MOVE, direction=direction, distance_m=distance, amount=amount,
                 text=c.text[:500])]


def _rotation_from(c: _Clause, direction: Direction, quantities: list[Quantity],
                   little: list[re.Match[str]]) -> Step:
    angle = None
    for q in quantities:
        c.s.use(q.start, q.end)
        angle = (angle or 0.0) + q.value
    amount = None if angle is not None else Amount.LITTLE if little else Amount.DEFAULT
    return Step(movement=Movement.ROTATE, direction=direction, angle_deg=_checked_angle(angle), amount=amount,
                text=c.text[:500])


def _move_direction(c: _Clause, vm: re.Match[str] | None) -> Direction | None:
    if vm is not None and " ".join(vm.group(0).split()) in _BACKWARD_VERBS:
        c.s.take_all(re.compile(r"\b(?:backwards?|back|in\s+reverse)\b"))
        return Direction.BACKWARD
    direction: Direction | None = None
    for m in c.s.take_all(_MOVE_DIR_RE):
        d = lx.lookup(lx.MOVE_DIRECTIONS, m.group("dir"))
        if isinstance(d, Direction) and direction is None:
            direction = d
    return direction

