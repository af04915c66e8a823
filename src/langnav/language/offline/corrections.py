"""Spoken instructions come in pieces and get corrected on the way (README "Speech"):

* a fragment after a comma completes the move or turn before it ("rotate, ninety degrees left";
  "turn thirty degrees, to the left"; "head due west, for five feet"), or the one after it
  ("ten inches, go straight");
* a self-correction replaces what it corrects, and only that: "ninety degrees right, actually left"
  is left; "turn left twenty degrees, sorry, turn right twenty degrees" is the right turn; "never
  mind" drops the instruction before it.

Both work on the clause texts before they are read, so the reading sees one whole instruction.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Final

from langnav.language.intent import Direction
from langnav.language.offline import lexicon as lx
from langnav.language.offline.amounts import unit_word, with_unit
from langnav.language.offline.clock import CLOCK_RE
from langnav.language.offline.compass import COMPASS_RE
from langnav.language.offline.idioms import named_turn_alone
from langnav.language.offline.normalize import normalize
from langnav.language.offline.numbers import QuantityKind, find_quantities
from langnav.language.offline.patterns import (
    BOAT_SIDE_WORDS,
    GO_VERB_RE,
    LITTLE_RE,
    MOVE_WAY_WORDS,
    ROTATE_VERB_RE,
    STOP_RE,
    TURN_SIDE_WORDS,
    rx,
)
from langnav.language.offline.vocabulary import VOCABULARY

#: Exclamations of dismay ("aiya", "argh", "oh no", "damn"): said right after an instruction, they mark it as
#: a slip, which the words that follow put right, as "sorry" does ("turn left, aiya, turn right sixty": the
#: right turn). English and its varieties: Singapore / Malaysia "aiya", "aiyo", "alamak"; South Africa "eish".
DISMAY: Final = (r"oops|oopsie|whoops|whoopsie|ar+gh+|ugh+|aiy(?:a+h?|o+h?)|alamak|eish|uh\s+oh|oh\s+dear|"
                 r"dam(?:n|mit)(?:\s+it)?|darn(?:\s+it)?|drat|dang(?:\s+it)?")
#: Words that open a correction of the instruction before ("actually", "no wait", "i'm sorry", "aiya").
CORRECTION_START_RE: Final = re.compile(
    rf"^(?:(?:{DISMAY})\b[\s,!.]*|"
    r"(?:(?:oh|ah|uh|um)\s*,?\s+(?=sorry|no\b|i\s+mean)|actually|no\s+(?:wait|hang\s+on|hold\s+on)|no(?!\s+(?:further|longer|more|need)\b)|na+h|naw|nope|wait(?=\s*,?\s*no\b)|oh\s+wait|(?:i'?m|i\s+am|im)\s+sorry|"
    r"sorry|i\s+meant\s+to\s+say|i\s+mean\s+to\s+say|i\s+meant|i\s+mean|i\s+said|my\s+(?:bad|mistake|error|fault|b)|"
    # the other ways English speakers say they said it wrong ("wrong", "I misspoke", "on second thought")
    # (a typist's "typo" is a speaker's "I misspoke": "rotate right 30, typo, meant left")
    r"(?:that'?s\s+|that\s+is\s+)?wrong|i\s+misspoke|(?:that\s+was\s+a\s+|my\s+|a\s+)?typo|let\s+me\s+(?:rephrase(?:\s+that)?|correct\s+(?:that|myself))|"
    # "the opposite" said alone: the way said was the wrong one ("turn left ninety, the opposite, turn right ninety")
    r"(?:the\s+)?opposite(?=[\s,.!]*$)|"
    r"on\s+second\s+thoughts?|second\s+thoughts?|change\s+of\s+plans?|or\s+actually|or\s+rather|rather|make\s+that|make\s+it|correction|"
    r"oops)\b[\s,]*)+", re.IGNORECASE)
#: Words that take back what was said before ("never mind", "scratch that"). Radio and naval procedure say it
#: with the word alone: "disregard" (ACP 125: the last transmission was in error) and "belay" (cancel the order).
CANCEL_RE: Final = re.compile(r"\b(?:never\s*mind|scratch\s+that|forget\s+(?:it|that|everything|all\s+(?:of\s+)?that)|"
                              r"(?:belay|disregard)(?:\s+(?:that|the\s+last|my\s+last)(?:\s+(?:one|order|transmission))?)?|"
                              # dictation and editing words ("strike that", "delete that", "undo that")
                              r"(?:strike|delete|erase|undo|scrap)\s+(?:that|the\s+last(?:\s+one)?)|"
                              r"(?:let'?s\s+|let\s+me\s+)?(?:start\s+(?:over|again)|start\s+from\s+scratch)|"
                              r"cancel\s+that|ignore\s+that)\b[\s,]*", re.IGNORECASE)
#: Of those, the words that drop the whole request so far, not only its last instruction: "never mind"
#: dismisses what the speaker was asking for ("keep going two feet, go south, go two t- ... never mind,
#: so go three feet, turn south"); "scratch that" takes back the last thing said.
CANCEL_ALL_RE: Final = re.compile(r"\b(?:never\s*mind|forget\s+(?:everything|all\s+(?:of\s+)?that)|start\s+(?:over|again)|"
                                  r"start\s+from\s+scratch)\b", re.IGNORECASE)
#: Words that give the side of a move or a turn (a fragment may carry one).
SIDE_RE: Final = re.compile(
    r"(?:\b(?:to|on|towards?)\s+(?:the|your)\s+)?\b(?:left|right|clockwise|counter\s*clockwise|anti\s*clockwise|cw|ccw|"
    r"forwards?|backwards?|ahead|straight|port|starboard|astern)\b(?:\s+(?:hand\s+)?side)?")
_HEAD_RE: Final = rx([*lx.ELEMENT_NOUNS], "head")
#: Words a speaker holds the floor with while correcting ("no, wait, ..."): no instruction of their own.
_HOLD_RE: Final = re.compile(r"^\s*(?:wait|hold\s+on|hang\s+on|one\s+sec(?:ond)?|let\s+me\s+think)\s*$", re.IGNORECASE)
#: "the one after the second": says which place more exactly (an apposition), does not replace it.
_ONE_RE: Final = re.compile(r"^\s*(?:the|that)\s+one\b", re.IGNORECASE)
#: "back" as the way of a move (not a verb of its own once a side replaces it).
_BACK_RE: Final = re.compile(r"\b(?:back|in\s+reverse)\b")
_BACK_VERB_RE: Final = re.compile(r"\b(?:back\s+up|back\s+off|reverse)\b")

#: ``open(text)``: does the instruction miss an amount or a side a fragment may give?
IsOpen = Callable[[str], bool]


def is_fragment(clause: str) -> bool:
    """Only an amount and/or a side (or a compass point): no verb, no element, no correction word."""
    norm = normalize(clause)
    if not norm or CORRECTION_START_RE.match(norm) or CANCEL_RE.search(norm):
        return False
    quantities = find_quantities(norm)
    words = norm
    for q in quantities:  # the words of an amount are no verb ("one point two metres": no "point" to face)
        words = words[:q.start] + " " * (q.end - q.start) + words[q.end:]
    if GO_VERB_RE.search(words) or ROTATE_VERB_RE.search(words) or STOP_RE.search(words) or _HEAD_RE.search(words):
        return False
    return bool(quantities or SIDE_RE.search(norm) or COMPASS_RE.search(norm) or CLOCK_RE.search(norm)
                or LITTLE_RE.search(norm))


#: Words of a request around a bare verb ("just", "can you", "robot").
_REQUEST_WORDS: Final = frozenset({"can", "could", "will", "would", "you", "robot", "just", "okay", "ok", "please",
                                   "and", "now", "so", "then", "yourself", "let", "us", "try"})
_BARE_VERBS: Final = frozenset(v for v in (*lx.GO_VERBS, *lx.ROTATE_VERBS) if " " not in v) - {"stop", "wait"}


#: A clause that only opens a request ("go ahead", "okay go on", "come on").
_LEAD_IN: Final = re.compile(r"^(?:(?:ok|okay|so|now|alright|robot|please|yeah|yes|well|just)\s+)*(?:go\s+ahead|go\s+on|come\s+on|"
                             r"ready|here\s+we\s+go)(?:\s+(?:please|robot|now))*$")


#: Words that only soften or acknowledge ("about,", "yeah", "okay so"): a clause of them says nothing.
_HEDGE_WORDS: Final = lx.HESITATIONS | frozenset({"about", "like", "roughly", "approximately", "say", "so", "well",
                                 "yeah", "yes", "yep", "okay", "ok", "alright", "sure", "good", "great", "cool",
                                 "robot", "please", "now", "just",
                                 # praise and thanks for what was just done ("lovely, now ..."; "brilliant.")
                                 "lovely", "brilliant", "perfect", "nice", "excellent", "grand", "cheers", "thanks",
                                 "ta", "awesome", "sweet", "super", "fantastic", "wonderful", "splendid", "marvellous",
                                 "champion", "beautiful", "superb", "fine",
                                 # "yes" in the languages most often spoken alongside English (German, Dutch and
                                 # Scandinavian "ja", French "oui", Spanish / Italian "si", Portuguese "sim", Russian
                                 # "da", Polish "tak", Turkish "evet", Japanese "hai"): assent, never a correction
                                 "ja", "oui", "si", "sim", "da", "tak", "evet", "hai"})


def is_hedge(clause: str) -> bool:
    """Only hedges or acknowledgements: "about," in "turn right, about, thirty degrees"."""
    words = normalize(clause).split()
    return bool(words) and all(w in _HEDGE_WORDS for w in words)


def is_bare_verb(clause: str) -> bool:
    """Only a verb of motion, with nothing said about where or how far ("turn", "can you move")."""
    words = normalize(clause).split()
    content = [w for w in words if w not in _REQUEST_WORDS]
    return bool(content) and all(w in _BARE_VERBS for w in content) and len(content) <= 2


def _whole_move(fragment: str) -> bool:
    """A fragment with both an amount and a way ("then 3 feet to your right") is an instruction with
    its verb left out, complete on its own: it completes no instruction after it (the one before it
    was complete, or it would have been joined there)."""
    norm = normalize(fragment)
    return bool(find_quantities(norm)) and SIDE_RE.search(norm) is not None


#: The ways of a move that no turn can take ("forward", "back"): a fragment with one and its amount is a move.
_MOVE_WAY_RE: Final = re.compile(rf"\b(?:{MOVE_WAY_WORDS})\b")
_TURN_SIDE_RE: Final = re.compile(rf"\b(?:{TURN_SIDE_WORDS}|{BOAT_SIDE_WORDS})\b")


def _move_after_turn(instruction: str, fragment: str) -> bool:
    """'turn right, forward ten metres': a way only a move takes, with its amount and no side, after a turn
    that has its side, is the next instruction with its verb left out (drill orders and radio speech), not
    the amount of the turn. Only when the fragment starts with that way: "turn right, two metres ahead" may be
    the turn's place ("turn right in two metres"), so it is not split into a turn and a move (it asks)."""
    norm, frag = normalize(instruction), normalize(fragment)
    return (ROTATE_VERB_RE.search(norm) is not None and GO_VERB_RE.search(norm) is None
            and _TURN_SIDE_RE.search(norm) is not None and _whole_move(fragment)
            and _MOVE_WAY_RE.match(frag.strip()) is not None and _TURN_SIDE_RE.search(frag) is None)


#: The words that name a half turn ("around", "about face", "u-turn", "back side"): a turn said by them has its
#: amount named (``lexicon.ROTATE_DIRECTIONS``).
_HALF_TURN_RE: Final = rx([w for w, d in lx.ROTATE_DIRECTIONS.items() if d == Direction.AROUND and not w[0].isdigit()]
                          + ["back side"], "turn")


def _number_of_a_named_turn(instruction: str, fragment: str) -> bool:
    """'turn around, one hundred eighty': a bare number (no unit) right after a turn said by name with no number
    ("turn around", "about face") counts the turn's degrees: said with it, the turn reads the two together (the
    same half turn, or, another number, a turn whose side it asks about), never a move of that many metres."""
    norm, frag = normalize(instruction), normalize(fragment)
    if _kind(instruction) != "turn" or find_quantities(norm) or SIDE_RE.search(frag) or not _HALF_TURN_RE.search(norm):
        return False
    quantities = find_quantities(frag)
    return len(quantities) == 1 and quantities[0].kind == QuantityKind.BARE


def join_fragments(clauses: list[str], is_open: IsOpen) -> list[str]:
    """Each fragment joined to the open instruction before it (or, failing that, after it)."""
    out: list[str] = []
    i = 0
    while i < len(clauses):
        clause = clauses[i]
        nxt_clause = clauses[i + 1] if i + 1 < len(clauses) else None
        if nxt_clause is not None and _LEAD_IN.match(normalize(clause)):
            i += 1  # "go ahead, turn right": "go ahead" only opens the request
            continue
        if nxt_clause is not None and is_bare_verb(clause) and not is_fragment(nxt_clause):
            i += 1  # "face, face east", "turn and face east": a false start of the next instruction
            continue
        if is_fragment(clause):
            if out and (is_open(out[-1]) or is_bare_verb(out[-1]) or _number_of_a_named_turn(out[-1], clause)) \
                    and not _move_after_turn(out[-1], clause):
                out[-1] = f"{out[-1]} {clause}"
                i += 1
                continue
            nxt = clauses[i + 1] if i + 1 < len(clauses) else None
            if nxt is not None and not is_fragment(nxt) and is_open(nxt) and not _whole_move(clause) \
                    and named_turn_alone(normalize(clause)) == normalize(clause):
                # ("one eighty, then go forward": a named turn said alone is that turn, never 180 metres)
                out.append(f"{nxt} {clause}")
                i += 2
                continue
        out.append(clause)
        i += 1
    return out


def apply_corrections(clauses: list[str]) -> list[str]:
    """The clauses with every self-correction applied to the instruction it corrects.

    A take-back followed by only an amount or a side corrects that part of the instruction before
    ("move forward ten feet, scratch that, six feet" is six feet forward); followed by anything else,
    it drops what it takes back ("never mind": everything so far; "scratch that": the last one)."""
    out: list[str] = []
    correct_next = False  # "i'm sorry" alone: the next clause is the correction
    dismay_next = False  # ... opened by an exclamation of dismay alone ("damn")
    take_back: bool | None = None  # a take-back alone, waiting for what follows: whether it drops everything
    for i, clause in enumerate(clauses):
        if not correct_next and take_back is None and out and i + 1 < len(clauses) \
                and _takes_back_between(out[-1], clause, clauses[i + 1]):
            out.pop()  # "turn left ninety, cancel, turn right ninety": only the right turn
            continue
        cancel = CANCEL_RE.search(clause)
        start = CORRECTION_START_RE.match(clause)
        everything: bool | None = None
        if cancel is not None and (cancel.start() == 0 or (start is not None and cancel.start() <= start.end())):
            everything = bool(take_back) or CANCEL_ALL_RE.search(clause[:cancel.end()]) is not None
            correct_next = False
            clause = clause[cancel.end():].strip()
            while (again := CANCEL_RE.match(clause) or CORRECTION_START_RE.match(clause)) and again.end() > 0:
                clause = clause[again.end():].strip()  # "never mind, forget that": one take-back
            if not clause:
                take_back = everything  # "..., scratch that, six feet": what follows decides
                continue
        elif take_back is not None:
            everything = take_back
        take_back = None
        if everything is not None:
            if out and is_fragment(clause):
                out[-1] = _corrected(out[-1], clause)
            else:
                _take_back(out, everything)
                out.append(clause)
            continue
        if correct_next and _HOLD_RE.match(clause):
            continue  # "no, wait, two metres": "wait" belongs to the correction, it is no stop
        correcting = correct_next
        correct_next = False
        if start is not None:
            clause = clause[start.end():].strip()
            only_dismay = _DISMAY_ONLY_RE.fullmatch(start.group(0).strip()) is not None
            if not clause:
                if out and _HOLD_RE.match(out[-1]):
                    out.pop()  # "..., wait, no, forward two feet": the "wait" opened the correction, it is no stop
                correct_next = bool(out)
                dismay_next = only_dismay
                continue
            correcting = True
        else:
            only_dismay = dismay_next and correcting
        dismay_next = False
        if correcting and only_dismay and out and not is_fragment(clause) and _kind(out[-1]) != _kind(clause):
            out.append(clause)  # "turn left, damn, go forward two metres": dismay puts right a slip of its own kind
            continue
        if correcting and out and _ONE_RE.match(clause):
            out.append(clause)  # "the doorway on the right, I mean the one after the second": it says more
            continue
        if correcting and out and _UNIT_ONLY_RE.match(normalize(clause)):
            out[-1] = _unit_corrected(out[-1], normalize(clause))  # "five metres, oops, I meant feet"
            continue
        if correcting and out:
            out[-1] = _corrected(out[-1], clause) if is_fragment(clause) else _restated(out[-1], clause)
            continue
        out.append(clause)
    if take_back is not None:
        _take_back(out, take_back)  # "turn left thirty five degrees, never mind": nothing is left
    return out


#: An exclamation of dismay alone (no "sorry", "I mean"): it says the speaker slipped, not what the slip was;
#: the words after it put right an instruction of their own kind only (a turn a turn, a move a move): an
#: instruction of another kind after it is the next one ("turn left, damn, go forward two metres": both).
_DISMAY_ONLY_RE: Final = re.compile(rf"(?:(?:{DISMAY})\b[\s,!.]*)+", re.IGNORECASE)
#: An exclamation of dismay anywhere in a stretch of speech.
DISMAY_RE: Final = re.compile(rf"\b(?:{DISMAY})\b")


def _kind(instruction: str) -> str | None:
    """'turn' or 'move' for an instruction with only a turning or only a going verb; None otherwise."""
    norm = normalize(instruction)
    turn, go = ROTATE_VERB_RE.search(norm) is not None, GO_VERB_RE.search(norm) is not None
    return "turn" if turn and not go else "move" if go and not turn else None


#: A correction that only names a unit ("I meant feet"): the amount said before, in that unit.
_UNIT_ONLY_RE: Final = re.compile(r"^(?:in\s+)?(?P<unit>feet|foot|met(?:er|re)s?|inch(?:es)?|yards?|centimet(?:er|re)s?|"
                                  r"degrees?)$")


def _unit_corrected(previous: str, unit: str) -> str:
    """'forward five metres' corrected by 'feet': the last amount's number with the unit put right (left as
    said when its unit cannot be told apart from its number)."""
    norm = normalize(previous)
    said = [q for q in find_quantities(norm) if q.unit > 0]
    if not said:
        return f"{norm} {unit}"  # "turn left forty, I meant degrees": the unit the number lacked
    q = said[-1]
    words = norm[q.start:q.end].split()
    return f"{norm[:q.start]}{' '.join(words[:-1])} {unit}{norm[q.end:]}" if len(words) > 1 else norm


#: "cancel" said alone: the instruction before it is called off.
_CANCEL_ALONE_RE: Final = re.compile(r"^(?:cancel|cancel\s+it|call\s+it\s+off|abort|abort\s+that)$")


def _takes_back_between(before: str, clause: str, after: str) -> bool:
    """Whether ``clause``, said alone between two instructions, takes the first back: "cancel" calls it off
    whatever follows ("go forward two metres, cancel, go back one metre"); "wait" / "hold on" between two
    instructions of the same kind ("turn left ninety, wait, turn right ninety") is the speaker stopping to say it
    again, as they meant it. (Doing both would move or turn more than asked if it was a take-back; doing only the
    second never does. A pause between two kinds of instruction, "go forward, wait, turn left", orders them.)"""
    norm = normalize(clause)
    kinds = _kind(before), _kind(after)
    if kinds[0] is None or kinds[1] is None:
        return False
    if _CANCEL_ALONE_RE.match(norm):
        return True
    return _HOLD_RE.match(norm) is not None and kinds[0] == kinds[1]


def _take_back(out: list[str], everything: bool) -> None:
    if everything:
        out.clear()
    elif out:
        out.pop()


def _corrected(previous: str, fragment: str) -> str:
    """'turn ninety degrees right' corrected by 'left': the side (or the amount) the fragment gives
    replaces the one said before."""
    norm_prev = normalize(previous)
    norm_frag = normalize(fragment)
    if SIDE_RE.search(norm_frag):
        if not SIDE_RE.search(norm_prev):
            # no side was read before: the word said where the side goes (right after the verb) is the one
            # put right ("turn lest 30 degrees. no. left": the recogniser's "lest" was the side)
            norm_prev = _SIDE_SLOT_RE.sub(lambda m: m.group("verb") if m.group("word") not in VOCABULARY
                                          and m.group("word") not in lx.STOPWORDS else m.group(0), norm_prev, count=1)
        # the side said before goes, "back" too ("go back two feet, no, forward two feet"; "reverse
        # one metre, actually forward")
        norm_prev = _BACK_RE.sub(" ", _BACK_VERB_RE.sub("move", SIDE_RE.sub(" ", norm_prev)))
    if COMPASS_RE.search(norm_frag):
        norm_prev = COMPASS_RE.sub(" ", norm_prev)
    quantities = find_quantities(norm_frag)
    if quantities:
        said = find_quantities(norm_prev)
        # "go forward ten feet, actually make that eight": the number put right is in the unit said before
        norm_frag = with_unit(norm_frag, unit_word(said[-1]) if said else None)
        for q in reversed(said):
            norm_prev = norm_prev[:q.start] + " " + norm_prev[q.end:]
    return " ".join(f"{norm_prev} {norm_frag}".split())


#: A verb of motion opening an instruction and the word right after it (where a side or a way is said).
_SIDE_SLOT_RE: Final = re.compile(r"^\s*(?P<verb>turn|rotate|move|go|spin|pivot|drive|head|step|veer)\s+(?P<word>[a-z]+)\b")


def _restated(previous: str, correction: str) -> str:
    """'reverse one metre, actually go forward': a correction that says the same kind of instruction
    again (a move for a move, a turn for a turn) and leaves out the amount keeps the amount said
    before; anything else replaces the instruction as said."""
    norm_prev, norm_new = normalize(previous), normalize(correction)
    same_kind = ((ROTATE_VERB_RE.search(norm_prev) is not None) == (ROTATE_VERB_RE.search(norm_new) is not None)
                 and not _HEAD_RE.search(norm_new) and not _HEAD_RE.search(norm_prev))
    if not same_kind or find_quantities(norm_new) or not SIDE_RE.search(norm_new):
        return correction
    amounts = " ".join(norm_prev[q.start:q.end] for q in find_quantities(norm_prev))
    return f"{norm_new} {amounts}" if amounts else correction


#: A question whether an instruction may be done ("is it safe to turn right ninety degrees?", "would it be okay
#: for you to go forward?"): no request yet, only the instruction asked about (group ``x``).
_MAY_I_QUESTION_RE: Final = re.compile(
    r"^(?:(?:so|and|okay|ok|um|well)\s+)*(?:is\s+it|would\s+it\s+be|will\s+it\s+be)\s+(?:safe|ok|okay|alright|all\s+right|"
    r"possible|fine)\s+(?:for\s+(?:you|u)\s+)?(?:to\s+)?(?P<x>.+)$")
#: Consent said after such a question ("okay, please do", "yes, do it", "go for it"): the instruction asked
#: about is now asked for. (A bare "go ahead" opens a request, see _LEAD_IN; with nothing after it, it consents.)
_CONSENT_RE: Final = re.compile(
    r"^(?:(?:ok|okay|yes|yeah|yep|alright|good|great|then|so|in\s+that\s+case|right)\s+)*(?:please\s+do(?:\s+(?:it|so|that))?|"
    r"(?:please\s+)?do\s+(?:it|so|that)(?:\s+(?:please|then|now))*|go\s+(?:ahead|for\s+it)(?:\s+(?:please|then|now))*)$")


def read_consents(clauses: list[str]) -> list[str]:
    """The clauses with each question whether an instruction may be done that a consent follows ("is it safe to
    turn right ninety degrees? okay, please do") read as that instruction: English "do it" / "please do" points
    back at the action just named. A question with no consent after it stays a question (the robot answers
    that it cannot tell, and runs nothing)."""
    out: list[str] = []
    for clause in clauses:
        if out and _CONSENT_RE.match(normalize(clause)):
            asked = _MAY_I_QUESTION_RE.match(normalize(out[-1]))
            if asked is not None:
                out[-1] = asked.group("x")
                continue
        out.append(clause)
    return out
