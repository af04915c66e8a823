"""Normalise one instruction before reading it: case, quotes, contractions, symbols, typos."""

from __future__ import annotations

import re
from functools import lru_cache
from typing import Final

from langnav.language.offline.idioms import plain_idioms
from langnav.language.offline.lexicon import (
    ELEMENT_NOUNS,
    MOVE_DIRECTIONS,
    NOT_TYPOS,
    ORDINALS,
    OTHER_FLOOR_PATTERNS,
    OUT_OF_SCOPE_PATTERNS,
    ROTATE_DIRECTIONS,
    SIDE_ADJECTIVES,
    SUPERLATIVES,
    TYPO_TARGETS,
    TYPOS,
    UNKNOWABLE_ADJECTIVES,
    UNSAFE_PATTERNS,
)

#: Length units spelt out (the units' table lives with the numbers, which import this module's peers).
LENGTH_UNIT_WORDS: Final = ("meter", "meters", "metre", "metres", "feet", "foot", "inch", "inches", "yard", "yards",
                            "centimeters", "centimetres")

#: Shortest word that edit-distance repair touches (shorter words have too many neighbours).
MIN_TYPO_REPAIR_LEN: Final = 6
#: Typing slips (two letters swapped) are repaired from three letters ("teh"), a letter left out or
#: doubled from four ("rigt"): shorter words have too many neighbours.
MIN_SLIP_REPAIR_LEN: Final = 3
MIN_SLIP_INDEL_LEN: Final = 4

_CHAR_MAP: Final = str.maketrans({"’": "'", "‘": "'", "`": "'", "´": "'", "“": '"', "”": '"',
                                  "–": "-", "—": "-", "×": "x", "π": " pi "})
_SYMBOLS: Final = (
    (re.compile(r"(\d)\s*½"), r"\1.5"), (re.compile(r"½"), " 0.5 "), (re.compile(r"(\d)\s*¼"), r"\1.25"),
    (re.compile(r"¼"), " 0.25 "), (re.compile(r"(\d)\s*¾"), r"\1.75"), (re.compile(r"¾"), " 0.75 "),
    (re.compile(r"\s*[°º]"), " degrees "), (re.compile(r"(?<=\d),(?=\d{1,2}\b)"), "."),
    (re.compile(r"(?<=\d)(?=[a-z])(?!st\b|nd\b|rd\b|th\b)"), " "),
)
_CONTRACTIONS: Final = (
    (re.compile(r"\b(you|we|they)'re\b"), r"\1 are"), (re.compile(r"\bi'm\b"), "i am"),
    (re.compile(r"\b(you|we|they|i|where|what|who|how)'ve\b"), r"\1 have"), (re.compile(r"\b(i|you|we|they)'d\b"), r"\1 would"),
    (re.compile(r"\b(i|you|we|they|that|it|this)'ll\b"), r"\1 will"), (re.compile(r"\bcan't\b"), "cannot"),
    (re.compile(r"\bwon't\b"), "will not"), (re.compile(r"\b(\w+)n't\b"), r"\1 not"),
    (re.compile(r"\blet's\b"), "let us"),
    (re.compile(r"\b(what|where|that|it|there|here|who|how)'s\b"), r"\1 is"),
    (re.compile(r"\b(what|where|who|how)'re\b"), r"\1 are"),
)
#: Idioms rewritten to the plain words they mean (the meaning is safe: poses stay clear of walls).
#: Ordinal words and their digit forms ("second", "2nd"), and "last".
_ORDINAL: Final = (r"first|second|third|fourth|fifth|sixth|seventh|eighth|ninth|tenth|last|next|"
                   r"\d+(?:st|nd|rd|th)")
_IDIOMS: Final = (
    (re.compile(r"\buntil\s+you\s+(?:hit|bump\s+into|run\s+into|meet)\b"), "until you reach"),
    (re.compile(r"\bout\s+of\s+here\b"), "out of this room"),
    (re.compile(r"\bleave\s+here\b"), "leave this room"),
    # "the left side of the room" is the part of the room along its left wall
    (re.compile(r"\b(?:(?:over\s+)?to\s+|towards?\s+|into\s+|at\s+)?the\s+(left|right)(?:\s+hand)?\s+(?:side|half|part|edge)"
                r"\s+of\s+"), r"next to the \1 wall of "),
    # "go around in a circle", "do a full circle": one full turn on the spot
    (re.compile(r"\b(?:go|turn|spin|drive|move|roll|rotate)\s+(?:(?:a)?round\s+)?in\s+a\s+(?:full\s+|complete\s+)?circle\b"),
     "turn 360 degrees"),
    (re.compile(r"\b(?:do|make)\s+a\s+(?:full\s+|complete\s+)?circle\b"), "turn 360 degrees"),
    # "all the circle", "the whole circle" (learners' words for a full circle): one full turn
    (re.compile(r"\b(?:all\s+the|the\s+whole|the\s+full|the\s+entire|the\s+complete)\s+circle\b"), "a full circle"),
    # "do a one eighty", "pull a three sixty": a half or full turn named by its degrees
    (re.compile(r"\b(?:do|make|pull|perform|execute|hit|give\s+(?:me|us))\s+(?:a|an)\s+(one\s+eighty|180|three\s+sixty|360)\b"
                r"(?!\s*(?:degrees?|turn))"),
     r"turn \1 degrees"),
    (re.compile(r"\boutside\s+(?:of\s+)?(?=(?:the|this|that|your)\s+(?:room|hallway|corridor|hall)\b)"), "out of "),
    # "keep turning right", "continue rotating": a turn (the amount follows, or is asked)
    (re.compile(r"\b(?:keep(?:\s+on)?|continue|carry\s+on|go\s+on)\s+(?:turning|rotating|spinning|pivoting|to\s+turn|"
                r"to\s+rotate)\b"), "turn"),
    # "come left / right" is the helm's and the pilot's turn; "come about" is turning around
    (re.compile(r"\bcome\s+(?=(?:hard\s+)?(?:left|right)\b)"), "turn "),
    (re.compile(r"\bcome\s+about\b"), "turn around"),
    # "look at the door", "turn to look towards the corner": face it (looking is facing: the robot turns, it does
    # not go there); a map is looked at, not faced
    (re.compile(r"\b(?:turn\s+(?:(?:a)?round\s+)?(?:and\s+|to\s+)?)?look\s+(?:at|towards?)\s+(?!(?:the\s+|your\s+|my\s+)?map\b)"),
     "face "),
    # "give yourself a turn to the left" (learner phrasing): a turn
    (re.compile(r"\bgive\s+(?:yourself|itself|it|her)\s+(?:a|the|one)\s+turn\b"), "turn"),
    # "turn to look behind (you)", "turn so you can see behind you": a turn whose purpose names its end, behind
    (re.compile(r"\bturn(?:\s+(?:yourself|itself))?\s+(?:(?:so\s+as\s+|in\s+order\s+)?to|so\s+(?:that\s+)?(?:you|u|it)\s+"
                r"(?:can|could|will))\s+(?:look|see|face)\s+(?:behind(?:\s+(?:you|yourself|itself))?|back)\b"), "turn around"),
    # "make the turn around", "do a turn around": the turn around
    (re.compile(r"\b(?:make|do)\s+(?:the\s+|a\s+)?turn\s+(?=(?:a)?round\b)"), "turn "),
    # "do a twirl", "do a spin": one whole turn
    (re.compile(r"\b(?:do|make|perform)\s+(?:a|one)\s+(?:little\s+)?(?:twirl|pirouette|spin)\b"), "turn 360 degrees"),
    # "a quarter of the way round", "half of the way around": that part of a turn
    (re.compile(r"\b(a\s+quarter|one\s+quarter|half|three\s+quarters)\s+of\s+the\s+way\s+(?:a)?round\b"), r"\1 turn"),
    # "turn left a quarter", "rotate a half": after a turn, a share said with no noun is that share of a turn
    # (the noun left out, as "a quarter turn" is said); a share of a unit ("a quarter metre") keeps its noun
    (re.compile(r"\b((?:turn|rotate|spin|pivot|swivel)(?:\s+(?:left|right|around|round|clockwise|anticlockwise|"
                r"counterclockwise))?\s+)(a\s+quarter|one\s+quarter|a\s+half|three\s+quarters)\b(?!\s*(?:of|turns?|"
                r"revolutions?|rotations?|circles?|inch\w*|met\w*|foot|feet|yards?|cm|mm|m|degrees?|more|an?)\b)"),
     r"\1\2 turn"),
    # Yorkshire "thee" / "tha" ("turn thee right", "where's tha got to") are "you"; before a word of a noun
    # phrase ("thee door", "tha biggest room") they are a slip for "the" and are left to the reading
    (re.compile(r"\b(?:thee|tha)\b(?!\s+(?:" + "|".join(sorted(
        {w for w in (*ELEMENT_NOUNS, *ORDINALS, *SUPERLATIVES) if " " not in w and "-" not in w}
        | {"door", "end", "middle", "centre", "center", "corner", "wall", "same", "other", "one", "way"}, key=len, reverse=True))
        + r")\b)"), "you"),
    # "rest there", "and rest here": to rest is to stay still, where the robot is or arrives ("the rest of
    # the way" is no verb)
    (re.compile(r"(?<!\bthe\s)\brest\s+(?=(?:right\s+)?(?:there|here)\b)"), "stay "),
    # "in a forward direction", "in the counterclockwise direction": that way
    (re.compile(r"\bin\s+(?:a|the)\s+(forwards?|backwards?|clockwise|counter\s*clockwise|anti\s*clockwise)\s+direction\b"),
     r"\1"),
    # "turn left one more time", "once more": again (no amount)
    (re.compile(r"\b(?:one\s+more\s+time|once\s+more|once\s+again)\b"), "again"),
    # "turn around one time": "one time" is "once" (a count of times, no amount)
    (re.compile(r"\bone\s+time\b"), "once"),
    # "just a small turn to the right" said with no verb: the turn it names, a little ("make a small turn"
    # keeps its verb)
    (re.compile(r"^(?:(?:just|only)\s+)?(?:a\s+)?(?:very\s+)?(?:small|slight|tiny|little|short)\s+turn\b"), "turn a little"),
    # "one more turn to the left", "another turn": a turn (not one whole turn, not an amount)
    (re.compile(r"\b(?:one\s+more|another|a\s+further)\s+turn\b(?!\s+(?:of|and))"), "turn"),
    # "a right angle" is 90 degrees (the "right" of it is no side)
    (re.compile(r"\b(?:by\s+)?(?:a|one)\s+right\s+angle\b"), "90 degrees"),
    # "i want see behind", "i need go left": the "to" learners leave out after want / need / like
    (re.compile(r"\b(want|wanna|need|would\s+like)\s+(?=(?:see|look|go|turn|move|know|check|have|take|get)\b)"),
     r"\1 to "),
    # "clock wise", "counter clock wise": one word each
    (re.compile(r"\b(?:(counter|anti)\s*)?clock\s+wise\b"), r"\1clockwise"),
    # "so that you are facing north": the facing is the instruction ("so that" is no pronoun "that")
    (re.compile(r"\bso\s+(?:that\s+)?(?:you|it)(?:\s+are|\s+will\s+be)?\s+(?:fac(?:e|es|ing)|looking|pointing)\b"), "face"),
    # "point yourself at the door", "aim at the corner": face it
    (re.compile(r"\b(?:point|aim|orient)(?:\s+yourself)?\s+(?:at|towards?|to)\b"), "face"),
    # "go out into the hallway": into it
    (re.compile(r"\bout\s+(?=(?:into|to|onto)\b)"), ""),
    # "the bit that hasn't been mapped yet": the unexplored area (a negation inside a relative clause
    # describes the place; it does not negate the request)
    (re.compile(r"\b(?:the\s+|a\s+|an\s+|any\s+|some\s+)?(?:bit|bits|part|parts|area|areas|region|regions|section|sections|"
                r"place|places|space|spaces|zone|zones|spot|spots)(?:\s+of\s+(?:the|this)\s+(?:map|building|floor|room|place))?"
                r"\s+(?:that|which|where|you|we|i)\s+(?:(?:you|we|i)\s+)?(?:has|have|had|is|are|was|were|did|do)\s+(?:not|never)\s+"
                r"(?:yet\s+)?(?:been\s+)?(?:yet\s+)?(?:mapped|explored|scanned|visited|seen|covered|checked|surveyed|map|explore|"
                r"scan|visit|see|cover|check|survey)(?:\s+yet)?\b"), "the unexplored area"),
    # "the room on the other side of the hall": the room across it (one place, not two steps; "go to the
    # other side of the hall" alone is still the far side of the hallway)
    (re.compile(r"\b(room|office|space)\s+(?:(?:that|which)\s+is\s+)?(?:on|at)\s+the\s+(?:other|opposite|far)\s+side"
                r"\s+of\s+the\s+(hall|hallway|corridor)\b"), r"\1 across the \2"),
    # "the room which is the smallest", "whichever room is biggest", "the door that is nearest": a
    # superlative said in a relative clause picks the same element as one said before the noun
    (re.compile(r"\b(?:the|whichever|whatever|which\s+ever)\s+(" + "|".join(sorted({n for n in ELEMENT_NOUNS if " " not in n}))
                + r")\s+(?:(?:which|that)\s+)?is\s+(?:the\s+)?(" + "|".join(sorted(
                    {w for w in SUPERLATIVES if w.endswith("est") and " " not in w})) + r")(?:\s+one)?\b"), r"the \2 \1"),
    # "between the first and second doors on your left": both ordinals share the noun and its side
    (re.compile(r"\bbetween\s+the\s+(" + _ORDINAL + r")\s+and\s+(?:the\s+)?(" + _ORDINAL + r")\s+"
                r"(door|doorway|room|obstacle|corner|opening)s?\b(\s+on\s+(?:your|the|my)\s+(?:left|right)"
                r"(?:\s+(?:hand\s+)?side)?)?"), r"between the \1 \3\4 and the \2 \3\4"),
    # "go up the corridor to the unexplored bit at the end of it / at the end": the end of the hallway just
    # named (an "it" or a missing "of ..." after "end" points back at the place of the same sentence)
    (re.compile(r"\b(hall|hallway|corridor)\b(.*?)\b(at|to|near|by)\s+the\s+(far\s+|other\s+)?end(?:\s+of\s+it\b|(?!\s+of\b))"),
     r"\1\2\3 the \4end of the \1"),
    # "face south. south is behind the whiteboard": a sentence saying where a compass point lies is the
    # speaker explaining, not an instruction (the compass of the map is what "face south" turns to)
    (re.compile(r"^(?:and\s+|so\s+)?(?:north|south|east|west)(?:\s+is|\s+'s|'s)\s+(?:behind|in\s+front\s+of|over|"
                r"where|towards?|by|beside|next\s+to|past|beyond|that\s+way|this\s+way|on\s+the\s+side)\b.*$"), ""),
    # "between the first door on the left and the second one": "one" is the same noun, on the same side
    (re.compile(r"\bbetween\s+the\s+(" + _ORDINAL + r")\s+(door|doorway|room|obstacle|corner|opening)\b(\s+on\s+(?:your|the|my)\s+"
                r"(?:left|right)(?:\s+(?:hand\s+)?side)?)?\s+and\s+(?:the\s+)?(" + _ORDINAL + r")\s+one\b"),
     r"between the \1 \2\3 and the \4 \2\3"),
    # "between the first two doors on your left": the first and the second of them
    (re.compile(r"\bbetween\s+the\s+first\s+(?:two|2)\s+(door|doorway|room|obstacle|corner|opening)s\b(\s+on\s+(?:your|the|my)\s+"
                r"(?:left|right)(?:\s+(?:hand\s+)?side)?)?"), r"between the first \1\2 and the second \1\2"),
    # "go out and turn right", "step out, please": out of the room the robot is in (no place called "out")
    (re.compile(r"\b(go|get|step|head|walk|drive|move)\s+out\b(?=\s*(?:$|,|and\b|then\b|now\b|please\b))"),
     r"\1 out of this room"),
    # "go through the door, then come back through it": through it once more, the way the robot came (the
    # far side of a door is read from where the robot then stands); "back" is no move backward here
    (re.compile(r"\b(come|go|head|get|walk|drive)\s+back\s+(?=(?:out\s+|in\s+)?(?:through|via)\b)"), r"\1 "),
    # "back out the door", "back out of the room": leave through it (which way the robot faces while it
    # leaves is Nav2's business, not a backward move of unsaid length)
    (re.compile(r"\bback\s+out\s+(?=(?:of|through|the|this|that|via)\b)"), "go out "),
    # "through the door, then come back through it": going back through a door is going through it,
    # from the side the robot is on now (which is where it came from)
    (re.compile(r"\b(?:come|go|head|get|walk|drive|move)\s+back\s+(?:out\s+|in\s+)?(?=(?:through|thru|via)\b)"), "go "),
    # "back out six feet": with an amount and no place, reversing that far ("back up six feet")
    (re.compile(r"\bback\s+out\s+(?=(?:about\s+|around\s+|roughly\s+|another\s+)?(?:\d|a\s+(?:bit|little|foot|metre|meter|"
                r"yard)\b|half\b|one\b|two\b|three\b|four\b|five\b|six\b|seven\b|eight\b|nine\b|ten\b))"), "back up "),
    # "go out from this room": out of it
    (re.compile(r"\bout\s+from\s+(?=(?:this|the|that|here)\b)"), "out of "),
    # "at end of the corridor": the article dropped in chat and speech
    (re.compile(r"\b(at|to|near|by|till|until)\s+(?:the\s+)?(far\s+|other\s+)?end\s+of\b"), r"\1 the \2end of"),
    # "more to the right", "further left": the same side, the amount is said elsewhere (or asked)
    (re.compile(r"\b(?:a\s+)?(?:more|further|farther)\s+(?=(?:(?:to|towards?)\s+(?:the|your)\s+)?"
                r"(?:left|right|forwards?|backwards?|ahead|clockwise|counter\s*clockwise|anti\s*clockwise)\b)"), ""),
    # "in the same position you're in, move ...": from where the robot is (no place of its own)
    (re.compile(r"\b(?:in|from|at)\s+(?:the\s+)?same\s+(?:position|place|spot|location)(?:\s+(?:that\s+)?(?:you|we)\s+"
                r"are(?:\s+in)?)?\b"), ""),
)
#: Punctuation that carries no meaning inside one instruction (kept: . / - ' " in numbers and units).
_NOISE: Final = re.compile(r"[^\w\s./'\"°-]|(?<!\d)\.|\.(?!\d)|(?<![\w])-|-(?![\w])|(?<!\d)(?<!pi)/|/(?!\d)")


_HYPHEN: Final = re.compile(r"(?<=[a-z])-(?=[a-z])")


def _alternation(words: set[str] | list[str]) -> str:
    return "|".join(r"\s+".join(re.escape(w) for w in p.split()) for p in sorted(words, key=lambda p: (-len(p), p)))


#: Words that may stand before the owner's noun or the owned noun of a possessive.
_POSSESSIVE_MODIFIERS: Final = _alternation(
    {w for w in (*ORDINALS, *SUPERLATIVES, *SIDE_ADJECTIVES) if " " not in w and "-" not in w}
    | {"current", "far", "other", "opposite", "very", "whole", "front", "back", "rear", "near"})
_OWNED_NOUNS: Final = _alternation({*ELEMENT_NOUNS, "end", "side", "middle", "centre", "center", "half", "part"})
#: "this room's doorway" -> "the doorway of this room"; "the hallway's far end" -> "the far end of the hallway".
_POSSESSIVE: Final = re.compile(
    rf"(?<![\w'-])(?P<det>(?:the|this|that|your|our|my|a)\s+)?(?P<owner>(?:(?:{_POSSESSIVE_MODIFIERS})\s+){{0,2}}"
    rf"(?:{_alternation(set(ELEMENT_NOUNS))}))'s?\s+(?P<owned>(?:(?:{_POSSESSIVE_MODIFIERS})\s+){{0,2}}"
    rf"(?:{_OWNED_NOUNS}))(?![\w'-])"
    r"(?P<where>\s+(?:on|to)\s+(?:the|your)\s+(?:left|right)(?:\s+(?:hand\s+)?side)?(?![\w'-]))?")


#: "the room which is the smallest", "the door that's nearest": a relative clause that only says which one
#: of the kind is meant is that superlative before the noun ("the smallest room").
_RELATIVE_SUPERLATIVE: Final = re.compile(
    rf"\b(?:the|whichever|whatever)\s+(?P<noun>{_alternation(set(ELEMENT_NOUNS))})\s+(?:(?:which|that|what)\s+)?(?:is|are|'s)\s+(?:the\s+)?"
    rf"(?P<sup>{_alternation({w for w in SUPERLATIVES if w.endswith(('est', 'last'))})})(?:\s+(?:one|of\s+them|of\s+all))?"
    r"(?![\w'-])")


def _unpossess(m: re.Match[str]) -> str:
    det = (m.group("det") or "the ").strip()
    return f"the {m.group('owned')}{m.group('where') or ''} of {det} {m.group('owner')}"


def normalize(clause: str) -> str:
    """Lower-case, plain-ASCII-ish, single-spaced text with common typos repaired."""
    text = clause.lower().translate(_CHAR_MAP)
    for pattern, repl in _SYMBOLS:
        text = pattern.sub(repl, text)
    for pattern, repl in _CONTRACTIONS:
        text = pattern.sub(repl, text)
    text = _NOISE.sub(" ", text)
    text = _HYPHEN.sub(" ", text)
    words = [_repair(w) for w in text.split()]
    text = " ".join(" ".join(words).split())
    for pattern, repl in _IDIOMS:
        text = pattern.sub(repl, text)
    text = plain_idioms(text)
    if "'" in text:
        text = _POSSESSIVE.sub(_unpossess, text)
    return _RELATIVE_SUPERLATIVE.sub(r"the \g<sup> \g<noun>", text)


def _repair(word: str) -> str:
    if word in TYPOS:
        return TYPOS[word]
    if word in NOT_TYPOS or not word.isalpha() or len(word) < MIN_SLIP_REPAIR_LEN:
        return word
    if len(word) >= MIN_TYPO_REPAIR_LEN and word not in TYPO_TARGETS:
        found = _closest_target(word)
        if found is not None:
            return found
    return _typing_slip(word) or skeleton_word(word) or word


_VOWELS_RE: Final = re.compile(r"[aeiou]")
#: A word typed by its consonants has at most this many vowels left ("bak", "mov"; "trn", "bckwrds").
MAX_SKELETON_VOWELS: Final = 1


def _skeleton(word: str) -> str:
    """The consonants of a word in order, as they sound: "ck" is "k" and a doubled letter one ("bak" and
    "back" are both "bk")."""
    bones = (word[:1] + _VOWELS_RE.sub("", word[1:])).replace("ck", "k")
    return re.sub(r"(.)\1+", r"\1", bones)


@lru_cache(maxsize=4096)
def skeleton_word(word: str) -> str | None:
    """Chat spelling by dropped vowels ("trn", "bckwrds", "rght", "bak", "mov"): the one vocabulary word,
    longer and with the same first letter, whose consonants are the typed ones in order. A typed word
    that keeps two vowels is a word of its own ("bike" is not "back"), and two candidates are no answer."""
    from langnav.language.offline.vocabulary import VOCABULARY

    vowels = _VOWELS_RE.findall(word[1:])
    if word in VOCABULARY or word in _REQUEST_WORDS or word in UNKNOWABLE_ADJECTIVES or len(vowels) > MAX_SKELETON_VOWELS:
        return None
    bones = _skeleton(word)
    if len(word) < MIN_SLIP_REPAIR_LEN or len(bones) < 2:
        return None
    hits = {v for v in _skeletons().get(bones, ()) if len(v) > len(word) and v[:1] == word[:1]}
    if vowels:
        # a vowel kept ("bak", "mov") may be a short real word ("red", "cold", "rat"): only the words
        # of a motion, with that vowel first, are meant
        hits = {v for v in hits if v in _MOTION_WORDS and (_VOWELS_RE.findall(v[1:])[:1] == vowels
                                                          or word[-1] == v[-1] == "e")}  # a silent e kept
    return hits.pop() if len(hits) == 1 else None


#: The words of a motion (its verb, way, amount and unit): what a vowel-dropped word with one vowel
#: left may stand for.
_MOTION_WORDS: Final = frozenset(
    w for phrase in (*MOVE_DIRECTIONS, *ROTATE_DIRECTIONS, *LENGTH_UNIT_WORDS, "go", "move", "drive", "turn",
                     "rotate", "spin", "back", "head", "walk", "degrees", "then", "and", "little", "around",
                     "straight", "forward", "backward", "north", "south", "east", "west")
    for w in phrase.split() if w.isalpha())


@lru_cache(maxsize=1)
def _skeletons() -> dict[str, frozenset[str]]:
    """Every vocabulary word by its consonant skeleton (built on first use: the vocabulary is made
    from the parser's tables)."""
    from langnav.language.offline.vocabulary import VOCABULARY

    table: dict[str, set[str]] = {}
    for v in VOCABULARY:
        if v.isalpha() and len(v) >= MIN_SLIP_REPAIR_LEN:
            table.setdefault(_skeleton(v), set()).add(v)
    return {k: frozenset(v) for k, v in table.items()}


@lru_cache(maxsize=4096)
def _closest_target(word: str) -> str | None:
    """The one vocabulary word at edit distance 1 (with transpositions) from ``word``, if unique."""
    hits = [t for t in TYPO_TARGETS
            if len(t) >= MIN_TYPO_REPAIR_LEN and abs(len(t) - len(word)) <= 1 and _within_one_edit(word, t)]
    return hits[0] if len(hits) == 1 else None


@lru_cache(maxsize=4096)
def _typing_slip(word: str) -> str | None:
    """A short word the lexicon does not know, one typing slip away from exactly one word it does:
    two letters swapped ("teh", "rigth", "lfet"), or (from four letters) one letter left out or
    doubled ("rigt", "leftt", "degres"). The first letter is kept: slips rarely hit it, and real words
    that differ in it ("saw" / "was", "on" / "no") are not slips."""
    from langnav.language.offline.vocabulary import (
        VOCABULARY,  # the vocabulary is built from the parser's tables
    )

    if word in VOCABULARY or word in _REQUEST_WORDS:
        return None
    hits = {v for v in VOCABULARY if v[:1] == word[:1] and len(v) >= MIN_SLIP_REPAIR_LEN
            and _one_slip(word, v)}
    return hits.pop() if len(hits) == 1 else None


#: Words of requests the robot refuses ("sing", "push", "stairs"): real words, never slips of a known one.
_REQUEST_WORDS: Final = frozenset(
    w for pattern in (*OUT_OF_SCOPE_PATTERNS, *OTHER_FLOOR_PATTERNS, *UNSAFE_PATTERNS)
    for w in re.findall(r"[a-z]{3,}", re.sub(r"\\[a-zA-Z]", " ", pattern)))


def _one_slip(typed: str, known: str) -> bool:
    if len(typed) == len(known):
        diff = [i for i in range(len(typed)) if typed[i] != known[i]]
        return (len(diff) == 2 and diff[1] == diff[0] + 1 and typed[diff[0]] == known[diff[1]]
                and typed[diff[1]] == known[diff[0]])
    if len(typed) < MIN_SLIP_INDEL_LEN or abs(len(typed) - len(known)) != 1:
        return False
    if len(typed) > len(known) and typed.startswith(known) and typed[-1] != typed[-2]:
        return False  # "ends", "runs", "turned": an inflection of a known word, not a slip
    short, long_ = (typed, known) if len(typed) < len(known) else (known, typed)
    i = 0
    while i < len(short) and short[i] == long_[i]:
        i += 1
    return short[i:] == long_[i + 1:]


def _within_one_edit(a: str, b: str) -> bool:
    if a == b:
        return True
    if len(a) == len(b):
        diff = [i for i in range(len(a)) if a[i] != b[i]]
        if len(diff) == 1:
            return True
        return len(diff) == 2 and diff[1] == diff[0] + 1 and a[diff[0]] == b[diff[1]] and a[diff[1]] == b[diff[0]]
    short, long_ = (a, b) if len(a) < len(b) else (b, a)
    i = 0
    while i < len(short) and short[i] == long_[i]:
        i += 1
    return short[i:] == long_[i + 1:]
