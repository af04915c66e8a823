"""Noun phrases: every element a clause names, with its properties ("the second door on your left",
"the left wall of the hallway", "between the box and the wall", "it", "the next one")."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Final

from langnav.language.intent import Detail, Element, ElementRef, Landmark, Side, Superlative
from langnav.language.offline import lexicon as lx
from langnav.language.offline.patterns import rx
from langnav.language.offline.scratch import Scratch

_HEAD_RE: Final = rx([*lx.ELEMENT_NOUNS, "one", "ones"], "head")
_PRONOUN_RE: Final = rx(lx.PRONOUNS, "pronoun")
_MODIFIER_WORDS: Final = (set(lx.ORDINALS) | set(lx.SUPERLATIVES) | set(lx.SIDE_ADJECTIVES)
                          | set(lx.FRONT_BACK_ADJECTIVES) | set(lx.DETERMINERS)
                          | set(lx.NEUTRAL_ADJECTIVES) | {"other", "another", "remaining", "different",
                                                          "new", "both", "two", "couple", "pair", "of",
                                                          "2"})
_MODIFIERS_RUN: Final = re.compile(rf"(?:{lx.phrase_regex(_MODIFIER_WORDS)}\s+)+$")
_VERB_LIKE_HEADS: Final = frozenset({"exit", "entry"})
_WEAK_MODIFIERS: Final = frozenset({"other", "another", "remaining", "different", "new"})
_PAIR_WORDS: Final = frozenset({"two", "both", "2", "pair", "couple"})
_SIDE_POST_RE: Final = re.compile(
    r"\s*(?:,\s*)?(?:(?:that|which|who)\s+(?:is|are|lies|sits|stands)\s+|(?:located|situated|lying|standing|"
    r"sitting|positioned|placed)\s+|(?:that\s+)?you\s+(?:can\s+)?see\s+|that\s+you\s+(?:can\s+)?see\s+)?"
    + lx.phrase_regex(lx.SIDE_PHRASES, "side"))
_POST_SUPERLATIVE_RE: Final = re.compile(r"\s*(?:(?:that|which)\s+(?:is|are)\s+)?"
                                         + lx.phrase_regex(lx.POST_SUPERLATIVES, "sup"))
_ROOM_YOU_ARE_IN_RE: Final = re.compile(r"\s*" + lx.phrase_regex(lx.ROOM_YOU_ARE_IN))
_NUMBER_POST_RE: Final = re.compile(r"\s*(?:number|no|#)\s*(?P<n>\d{1,2}|one|two|three|four|five|six|seven|"
                                    r"eight|nine|ten)(?!\w)")
#: "the one after the first", "the door after the second one": the next in the order counted.
_AFTER_ORDINAL_RE: Final = re.compile(r"\s*(?:(?:right|just|immediately)\s+)?after\s+the\s+(?P<ord>"
                                      + "|".join(sorted((w for w in lx.ORDINALS if w.isalpha()), key=len, reverse=True))
                                      + r")(?:\s+(?:one|door|room|corner|obstacle))?\b")
_FAR_END_LINK_RE: Final = re.compile(r"\s*" + lx.phrase_regex(lx.FAR_END_LINKS) + r"\s*")
_CONTAINER_LINK_RE: Final = re.compile(r"\s*" + lx.phrase_regex(lx.CONTAINER_LINKS) + r"\s*$")
_CURRENT_ROOM_POST_RE: Final = re.compile(
    r"\s*(?:(?:of|in|inside|within|inside\s+of)\s+)?" + lx.phrase_regex(lx.CURRENT_ROOM_PHRASES, "cur"))
_ACROSS_LINK_RE: Final = re.compile(r"\s*(?:(?:right|directly|just)\s+)?(?:across|across\s+from\s+you\s+(?:in|on)|"
                                    r"on\s+the\s+(?:other|opposite|far)\s+side\s+of)\s*")
_BETWEEN_AND_RE: Final = re.compile(r"^\s*(?:and|&|,)\s*$")
_ORDINAL_WORDS: Final = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7,
                         "eight": 8, "nine": 9, "ten": 10}

#: The largest ordinal the intent holds ("the twentieth door").
MAX_ORDINAL: Final = 20

#: Every word the lexicon knows (a word outside it, before an element noun, is part of a name).
KNOWN_WORDS: Final = frozenset(
    w for phrase in (*lx.ELEMENT_NOUNS, *lx.ORDINALS, *lx.SUPERLATIVES, *lx.SIDE_ADJECTIVES,
                     *lx.FRONT_BACK_ADJECTIVES, *lx.SIDE_PHRASES, *lx.DETAIL_PHRASES, *lx.VERB_DETAILS,
                     *lx.GO_VERBS, *lx.ROTATE_VERBS, *lx.STOP_PHRASES, *lx.MOVE_DIRECTIONS,
                     *lx.ROTATE_DIRECTIONS, *lx.LITTLE_PHRASES, *lx.STOPWORDS, *lx.DETERMINERS,
                     *lx.NEUTRAL_ADJECTIVES, *lx.CURRENT_ROOM_PHRASES, *lx.CONTAINER_LINKS,
                     *_MODIFIER_WORDS)
    for w in phrase.split())


@dataclass
class Phrase:
    """One element reference found in the clause."""

    ref: ElementRef
    start: int
    end: int
    head_start: int
    pair: bool = False          # "the two obstacles", "both boxes"
    pronoun: bool = False       # "it", "there", "the second one"
    weak: bool = False          # a doubtful word was read ("passage" alone, "the other door")
    contained: bool = False     # this phrase is the container of another ("of the hallway")
    second: Phrase | None = None  # the B of "between A and B"
    detail: Detail | None = None
    detail_from_verb: str | None = None
    bare_prep: bool = False     # only a preposition links it to the element before ("the door next to the box")
    lost: list[str] = field(default_factory=list)  # properties the schema cannot hold


def find_phrases(s: Scratch, previous: ElementRef | None) -> tuple[list[Phrase], str | None]:
    """Every element reference in the clause, left to right, with containers and pairs resolved.

    Returns the phrases and, if an unknown word names the place ("the kitchen door"), that name."""
    text = s.masked()
    phrases: list[Phrase] = []
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


def _read_modifiers(text: str, head_start: int, head_end: int, kind: Element, head: str) -> Phrase | None:
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
    return Phrase(ref=ref, start=start, end=head_end, head_start=head_start, pair=pair, weak=weak)


def _inherit(phrase: Phrase, previous: ElementRef | None) -> Phrase:
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


def _compound_name(text: str, phrase: Phrase) -> str | None:
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


def _adjacent_heads(text: str, first: Phrase, second: Phrase) -> bool:
    """'the hallway door', 'the exit door': two nouns in a row are one element."""
    return second.start == second.head_start and text[first.end:second.head_start].strip() == ""


def _merge_heads(first: Phrase, second: Phrase) -> Phrase:
    ref = first.ref.model_copy(update={"kind": second.ref.kind})
    if first.ref.kind in lx.CONTAINER_KINDS and second.ref.kind != first.ref.kind:
        ref = second.ref.model_copy(update={
            "within": first.ref.kind, "ordinal": first.ref.ordinal, "superlative": first.ref.superlative,
            "side": first.ref.side})
    return Phrase(ref=ref, start=first.start, end=second.end, head_start=second.head_start,
                   pair=first.pair or second.pair, weak=first.weak and second.weak)


_FRONT_BACK: Final = frozenset({Side.AHEAD, Side.BEHIND})
_LEFT_RIGHT: Final = frozenset({Side.LEFT, Side.RIGHT})


def _read_post_modifiers(text: str, phrase: Phrase) -> None:
    """'on your left', 'in front of you', 'closest to you', 'you are in', 'number 2'."""
    ref = phrase.ref
    while True:
        rest = text[phrase.end:]
        m = _SIDE_POST_RE.match(rest)
        if m and ref.side is None:
            ref = ref.model_copy(update={"side": lx.lookup(lx.SIDE_PHRASES, m.group("side"))})
            phrase.end += m.end()
            continue
        second = lx.lookup(lx.SIDE_PHRASES, m.group("side")) if m else None
        if m and isinstance(second, Side) and second != ref.side and ref.also_side is None:
            if ({ref.side, second} & _FRONT_BACK and {ref.side, second} & _LEFT_RIGHT
                    and ref.kind not in (Element.CORNER, Element.WALL)):  # "the left corner" names which corner
                # "the door behind you on the left": both sides hold, a quarter around the robot
                ref = ref.model_copy(update={"also_side": second})
            else:
                # "the door on your left on the right": one side against the other; kept as words not read,
                # so that the reading asks rather than drop one of them
                phrase.lost.append(m.group(0).strip(" ,"))
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
        m = _AFTER_ORDINAL_RE.match(rest)
        if m and ref.ordinal is None and lx.ORDINALS[m.group("ord")] < MAX_ORDINAL:
            ref = ref.model_copy(update={"ordinal": lx.ORDINALS[m.group("ord")] + 1})
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


def _find_pronouns(s: Scratch, text: str, phrases: list[Phrase], previous: ElementRef | None) -> list[Phrase]:
    """'go through it', 'go there': the previous step's element."""
    found: list[Phrase] = []
    for m in _PRONOUN_RE.finditer(text):
        if any(p.start <= m.start() < p.end for p in phrases):
            continue
        ref = previous if previous is not None else ElementRef(kind=Element.NONE)
        found.append(Phrase(ref=ref, start=m.start(), end=m.end(), head_start=m.start(), pronoun=True))
    return found


def _resolve_containers(text: str, phrases: list[Phrase]) -> list[Phrase]:
    """'the corner of the hallway' -> corner within hallway; 'in this room' -> in_current_room;
    'the corner of the biggest room' -> near the biggest room; 'the room at the end of the hallway'
    -> the farthest room off the hallway; 'the door across the hallway' -> the hallway's door ahead."""
    out: list[Phrase] = []
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
                    in_current_room=ref.in_current_room, within=ref.within, label=ref.label)


def _contain(ref: ElementRef, container: Phrase) -> ElementRef:
    c = container.ref
    if c.in_current_room:
        return ref.model_copy(update={"in_current_room": True})
    if c.ordinal is not None or c.superlative is not None or c.side is not None:
        # "the corner of the biggest room": which room the words say too
        return ref.model_copy(update={"within": c.kind, "near": as_landmark(c)})
    return ref.model_copy(update={"within": c.kind})


def _resolve_between(text: str, phrases: list[Phrase]) -> list[Phrase]:
    """'between A and B': B becomes A's second element."""
    out: list[Phrase] = []
    for p in phrases:
        if out and out[-1].second is None and _BETWEEN_AND_RE.match(text[out[-1].end:p.start]):
            before = text[:out[-1].start]
            if re.search(r"\b(?:between|betwixt|in\s+the\s+middle\s+of|halfway\s+between|midway\s+between)\s*$",
                         before):
                out[-1].second = p
                continue
        out.append(p)
    return out
