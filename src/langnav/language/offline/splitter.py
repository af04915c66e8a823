"""Split a prompt into its instructions, in order.

Steps are separated by full stops, semicolons, commas, "then", "after that", "finally", and by
"and" when it joins two instructions ("go to the door and turn left") rather than two things
("go between the box and the wall"). Decimal points and commas ("1.5 m", "1,5 m") are kept.
"""

from __future__ import annotations

import re
from typing import Final

from langnav.language.offline.lexicon import GO_VERBS, ROTATE_VERBS, STOP_PHRASES, TYPOS
from langnav.language.offline.numbers import NUMBER_WORDS

#: Sentence punctuation, commas and line breaks, except inside a number ("1.5", "1,5").
_PUNCTUATION_SPLIT: Final = re.compile(r"(?:[.!?;:,]+(?!\d)|(?<!\d)[.!?;:,]+|\n+|\s+-{1,2}\s+|\s+–\s+|\s+—\s+)")
#: Connectives between steps; the words themselves carry no meaning and are dropped.
_CONNECTIVE_SPLIT: Final = re.compile(
    r"\b(?:and\s+)?(?:then|after\s+that|after\s+this|afterwards|afterward|after\s+which|finally|lastly|"
    r"subsequently|and\s+next|and\s+also|as\s+well\s+as|followed\s+by|once\s+done|when\s+done|"
    r"once\s+finished|when\s+finished|once\s+you\s+are\s+done|and\s+when\s+you\s+are\s+done|"
    r"and\s+once\s+there|and\s+when\s+there|and\s+from\s+there"
    # learners' "and after" (French "et après", Spanish "y después") before the next way or place: "then"
    r"|and\s+after(?=\s+(?:through|into|to|towards?|past|along|across|out|back|left|right|forwards?|ahead|straight)\b)"
    # "move forward two metres but don't turn": what not to do is an instruction of its own
    r"|but(?=\s+(?:do\s+not|don'?t|never)\b))\b",
    re.IGNORECASE)
#: A piece that opens with "the one" / "that one": after a connective it is a step of its own.
_ONE_RE: Final = re.compile(r"^\s*(?:the|that)\s+one\b", re.IGNORECASE)
_DECIMAL_COMMA: Final = re.compile(r"(?<=\d),(?=\d{1,2}(?!\d))")
_LEAD_IN: Final = re.compile(r"^\s*(?:(?:please|now|ok(?:ay)?|yeah|yes|alright|so|well|just|robot|um|uh)\s+)*"
                             r"(?:go\s+ahead|go\s+on|come\s+on|try|"
                             r"be\s+(?:a\s+(?:dear|love|darling|star|sweetheart|good\s+robot)|so\s+kind)|do\s+me\s+a\s+favou?r)\s*$", re.IGNORECASE)
_AND: Final = re.compile(r"\s+(?:and|&|plus|\+)\s+", re.IGNORECASE)
#: Words that may stand between "and" and the verb of a new instruction.
_LEAD_FILLER: Final = frozenset({"please", "also", "then", "now", "just", "immediately", "kindly",
                                 "finally", "afterwards", "quickly", "slowly", "carefully", "once",
                                 "there", "when", "you", "get", "are", "through", "done", "arrived",
                                 "reached", "try", "to", "next", "straight", "again",
                                 # "and after turn right": "after" with no event after it is "then"
                                 "after"})
#: Verbs that start an instruction (the first word of each multi-word verb is enough).
_STEP_VERBS: Final = frozenset(
    {v.split()[0] for v in (*GO_VERBS, *ROTATE_VERBS, *STOP_PHRASES)}
    | {"show", "tell", "report", "give", "send", "display", "explore", "map", "scan", "where",
       "what", "which", "drive", "spin", "come", "wait", "hug", "follow", "take", "pass", "back",
       "reverse", "return", "stop", "halt", "freeze", "hold", "pause", "cancel",
       # things the robot cannot do still start a step of their own ("... and pick up the cup")
       "pick", "grab", "fetch", "bring", "carry", "open", "close", "clean", "push", "lift", "cook",
       "sing", "dance", "play", "wash", "water", "deliver", "put", "drop", "hand", "charge", "call"}
) - {"be", "do", "make", "keep", "stay", "point", "position", "get", "run", "pull", "edge", "have", "try"}
#: Verbs that start an instruction only if followed by more words (not "the box and get").
_WEAK_STEP_VERBS: Final = frozenset({"get", "keep", "make", "do", "stay", "position", "point", "have"})


#: Speech written with no punctuation ("move forward seven feet turn right"): an amount's unit ends an
#: instruction, and a verb that starts one right after it starts the next.
_UNIT_THEN_VERB: Final = re.compile(
    r"\b(?:feet|foot|ft|inch(?:es)?|yards?|met(?:er|re)s?|centimet(?:er|re)s?|cm|degrees?|deg)\s+"
    # (a verb said last closes its own instruction: "right 30 degrees rotate" is one turn)
    r"(?=(?:rotate|pivot|face|move|go|drive|head|advance|proceed|reverse)\s+[a-z0-9]|(?:stop|halt|freeze)\b"
    # "turn" / "spin" after a unit is a noun ("a 360 degree turn") unless a side follows it ("... turn right")
    r"|(?:turn|spin)\s+(?:to\s+(?:the|your)\s+)?(?:left|right|around|round|back)\b)",
    re.IGNORECASE)


def split_steps(prompt: str) -> list[str]:
    """The instructions of ``prompt`` (already cleaned), in order, as the user wrote them."""
    text = _UNIT_THEN_VERB.sub(lambda m: m.group(0).rstrip() + ". ", _DECIMAL_COMMA.sub(".", prompt))
    pieces: list[str] = []
    for sentence in _PUNCTUATION_SPLIT.split(text):
        for i, part in enumerate(_CONNECTIVE_SPLIT.split(sentence)):
            if i and _ONE_RE.match(part):
                part = f"then {part}"  # "..., then the one after the second": a step, not an apposition
            pieces.extend(_split_on_and(part))
    return [p for p in (_trim(p) for p in pieces) if p]


def _trim(piece: str) -> str:
    trimmed = piece.strip(" \t\"'()[]{}*")
    rest = piece.rstrip(" \t()[]{}*")
    if trimmed and rest.endswith(("'", '"')) and rest[-2:-1].isdigit() and rest.count(rest[-1]) == 1:
        return trimmed + rest[-1]  # "go forward 4'", "5'10\"": the foot and inch marks, not quotes
    return trimmed


def _split_on_and(part: str) -> list[str]:
    """Split at each 'and' followed (after filler) by the verb of a new instruction."""
    out: list[str] = []
    start = 0
    for m in _AND.finditer(part):
        if _LEAD_IN.search(part[start:m.start()]):
            continue  # "go ahead and turn right" is one instruction
        if _inside_a_number(part[start:m.start()], part[m.end():]):
            continue  # "one hundred and fifty degrees", "one and a half feet": one number
        if _starts_instruction(part[m.end():]):
            out.append(part[start:m.start()])
            start = m.end()
    out.append(part[start:])
    return out


#: "one hundred and fifty", "a foot and a half", "one and a half": the "and" is inside a number.
_HUNDRED_AND: Final = re.compile(r"\b(?:hundred|thousand)\s*$", re.IGNORECASE)
_NUMBER_WORD_START: Final = re.compile(rf"^(?:{NUMBER_WORDS})\b", re.IGNORECASE)
_AMOUNT_END: Final = re.compile(
    rf"(?:\d|\b(?:{NUMBER_WORDS}|a|an|foot|feet|inch(?:es)?|yards?|met(?:er|re)s?|degrees?))\s*$", re.IGNORECASE)
_FRACTION_START: Final = re.compile(r"^(?:(?:a|one)\s+)?(?:half|quarter|third)\b", re.IGNORECASE)


def _inside_a_number(left: str, right: str) -> bool:
    return bool((_HUNDRED_AND.search(left) and _NUMBER_WORD_START.match(right))
                or (_AMOUNT_END.search(left) and _FRACTION_START.match(right)))


def _starts_instruction(rest: str) -> bool:
    words = [TYPOS.get(w, w) for w in re.findall(r"[a-z']+", rest.lower())[:6]]
    words = [w for token in words for w in token.split()]
    i = 0
    while i < len(words) and words[i] in _LEAD_FILLER:
        if words[i] == "get" and i + 1 < len(words) and words[i + 1] not in ("there", "through", "done"):
            break
        i += 1
    if i >= len(words):
        return _starts_with_amount(rest)
    word = words[i]
    if word in _STEP_VERBS:
        return True
    if _starts_with_amount(rest):
        return True
    return word in _WEAK_STEP_VERBS and i + 1 < len(words) and words[i + 1] in (
        "to", "into", "out", "a", "an", "yourself", "going", "through", "next", "close", "near", "back", "me",
        "us", "sure")


_AMOUNT_START: Final = re.compile(
    rf"^\s*(?:\d+(?:\.\d+)?|{NUMBER_WORDS}|a|an|half)\b[\w\s.-]{{0,20}}?\b(?:m|cm|mm|meters?|metres?|centimet(?:er|re)s?|"
    r"feet|foot|ft|inch(?:es)?|degrees?|deg)\b\s+(?:to\s+the\s+)?(?:forwards?|backwards?|back|left|right|"
    r"clockwise|counter\s*clockwise|anti\s*clockwise)\b",
    re.IGNORECASE)


#: "... and forward 1 m", "... and again two feet": a second move given by its way (or as more of the
#: same) and its amount, with no verb.
_WAY_THEN_AMOUNT: Final = re.compile(
    rf"^\s*(?:(?:forwards?|backwards?|back|straight(?:\s+ahead)?|ahead|again|another|once\s+more|a\s+further)\s+)+"
    rf"(?:\d|(?:{NUMBER_WORDS}|a|an|half)\b)", re.IGNORECASE)


def _starts_with_amount(rest: str) -> bool:
    """'... and 2 metres left', '... and forward 1 m': a second move given by its amount and direction only."""
    plain = " ".join(TYPOS.get(w, w) for w in rest.lower().split())  # "... and fwd 1m"
    return _AMOUNT_START.match(rest) is not None or _WAY_THEN_AMOUNT.match(plain) is not None
