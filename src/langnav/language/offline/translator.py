"""The offline translator: split the prompt into steps, read each, and assemble the intent."""

from __future__ import annotations

import logging
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Final

from langnav.language.intent import (
    Amount,
    Detail,
    Direction,
    ElementRef,
    Intent,
    Movement,
    Side,
    Step,
)
from langnav.language.offline.amounts import said_again, same_way_again, with_unit_said_before
from langnav.language.offline.ask import ask_message, names_destination, only_stops, spatial
from langnav.language.offline.code import plain_code
from langnav.language.offline.composition import read_composed
from langnav.language.offline.corrections import (
    CANCEL_RE,
    apply_corrections,
    is_bare_verb,
    is_fragment,
    is_hedge,
    join_fragments,
    read_consents,
)
from langnav.language.offline.english import is_english
from langnav.language.offline.idioms import plain_idioms
from langnav.language.offline.lexicon import (
    ELEMENT_NOUNS,
    FOREIGN_NUMBERS,
    FOREIGN_WAYS,
    ORDER_WORDS,
    SEQUENCE_WORDS,
    STOPWORDS,
)
from langnav.language.offline.numbers import (
    ANGLE_UNITS_DEG,
    LENGTH_UNITS_M,
    NEGATIVE_NUMBER,
    canonical_numbers,
)
from langnav.language.offline.parser import Problem, Reading, is_unsafe, read_clause
from langnav.language.offline.particles import without_particles
from langnav.language.offline.photos import without_photo
from langnav.language.offline.reading import ASK_AMOUNT, ASK_CONFIDENCE, ASK_SIDE, ASK_UNIT
from langnav.language.offline.restarts import (
    drop_false_start_turns,
    drop_insisted_amounts,
    drop_stopped,
    merge_restated_turns,
    read_stated_amounts,
)
from langnav.language.offline.sidetalk import is_shout, without_spoken_count_in
from langnav.language.offline.speech import plain_letters, plain_speech, unfinished_number
from langnav.language.offline.splitter import split_steps
from langnav.language.offline.vocabulary import VOCABULARY
from langnav.language.translator import Context, clean_prompt

log = logging.getLogger(__name__)

TRANSLATOR_NAME: Final = "offline"
#: Below this confidence a reading has a doubt (unread words, a guessed default): hand it on.
#: (The same bar as ``langnav.language.llm.auto.AUTO_MIN_CONFIDENCE``.)
CONFIDENT: Final = 0.8
#: Refusals the offline reading is sure of: they carry a clarification and nothing unread, so
#: an ``auto`` translator does not pass them (or an injection attempt) on to a model.
SURE_REFUSALS: Final = frozenset({Problem.NAME, Problem.OUT_OF_SCOPE, Problem.OUT_OF_RANGE, Problem.QUESTION,
                                  Problem.OTHER_FLOOR, Problem.DURATION, Problem.UNKNOWABLE})
#: Problems in one step that refuse the whole prompt: a number out of range or not read in full.
WHOLE_PROMPT_REFUSALS: Final = frozenset({Problem.OUT_OF_RANGE, Problem.BAD_NUMBER, Problem.BEARING})
#: Problems whose words were not understood at all: a spatial word among them blocks the prompt.
UNREAD_PROBLEMS: Final = frozenset({Problem.UNREADABLE, Problem.NO_ANTECEDENT})
#: A reading that runs some steps and leaves a whole instruction out is unsure at best.
PARTIAL_CONFIDENCE: Final = 0.5
#: The intent holds at most this many steps (the schema's limit).
MAX_STEPS: Final = 20

UNSAFE_MESSAGE: Final = (
    "I won't do that: my safety rules always stay on, and I never drive into walls, obstacles or "
    "people, or faster than my safe speed. Tell me where to go instead, e.g. 'go to the nearest door'.")
NEGATIVE_MESSAGE: Final = (
    "I can't use the negative number '{number}': say which way instead, e.g. 'move backward 2 metres' "
    "or 'turn right 90 degrees'.")
NO_CAMERA_MESSAGE: Final = (
    "I have no camera, so I can't take pictures or tell you what I see. I can drive, turn, stop, explore "
    "the map and tell you where I am, my path or the map.")
CUT_NUMBER_MESSAGE: Final = (
    "I heard a number cut off ('{said}'), so I don't know how far or how much: say it again, e.g. 'turn left "
    "45 degrees'. Nothing was run.")
SHOUT_MESSAGE: Final = (
    "I heard '{said}' called out: is that a warning, or a place to go to? Nothing was run. Tell me what to do, "
    "e.g. 'go to the nearest corner'.")
CANCELLED_MESSAGE: Final = "You took that back ('never mind'), so I did nothing. Tell me what to do next."
PHOTO_LEFT_OUT_MESSAGE: Final = "I did the motion but took no picture: I have no camera."
TOO_MANY_STEPS_MESSAGE: Final = (
    f"That is more than {MAX_STEPS} steps; give me at most {MAX_STEPS} at a time.")


class OfflineTranslator:
    """Rule-based reading of prompts: no network, no model, a few milliseconds per prompt."""

    name = TRANSLATOR_NAME

    def translate(self, prompt: str, context: Context) -> Intent:
        return translate_offline(prompt, context.known_names)


def translate_offline(prompt: str, known_names: Sequence[str] = ()) -> Intent:
    """Read ``prompt`` into an intent, in stages: code notation read as the words it spells; prompts refused outright; speech made plain (numbers, hesitations,
    idioms); the prompt split into whole instructions (``_clauses``); each read and joined to the steps before it
    (``_Assembly.add``); the steps, or the question to ask, assembled (``_Assembly.intent``).
    Raises TranslationError for empty, huge or non-text prompts."""
    text = plain_code(clean_prompt(prompt))
    refused = _refused_outright(text)
    if refused is not None:
        return refused
    text = plain_idioms(plain_speech(canonical_numbers(without_spoken_count_in(plain_letters(text)))))
    clauses, photo = _clauses(text, known_names)
    cut = next((c for c in map(unfinished_number, clauses) if c is not None), None)
    if cut is not None:
        return _clarify(CUT_NUMBER_MESSAGE.format(said=cut), confidence=ASK_CONFIDENCE, unread=[cut])
    assembly = _Assembly(known_names=tuple(known_names), sequenced=_SEQUENCE_RE.search(text) is not None)
    for clause in clauses:
        refusal = assembly.add(clause)
        if refusal is not None:
            return refusal
    return assembly.intent(clauses, text, photo)


def _refused_outright(text: str) -> Intent | None:
    """The refusal of a prompt refused before it is read: unsafe, a negative number, a place noun shouted alone."""
    if is_unsafe(text):
        log.info("refused an unsafe prompt: %.80s", text)
        return _clarify(UNSAFE_MESSAGE, confidence=1.0, unread=[])
    negative = NEGATIVE_NUMBER.search(text)
    if negative is not None:
        shown = text[negative.start():negative.start() + 12].split()[0]
        return _clarify(NEGATIVE_MESSAGE.format(number=shown), confidence=1.0, unread=[])
    if is_shout(text) and text.strip(" !").lower() in ELEMENT_NOUNS:  # "corner!": a warning, or the place?
        return _clarify(SHOUT_MESSAGE.format(said=text.strip()), confidence=ASK_CONFIDENCE, unread=[text.strip()])
    return None


@dataclass
class _Assembly:
    """The steps read so far from a prompt's clauses, and what the reading of them left open."""

    known_names: tuple[str, ...]
    #: a word that orders the instructions is in the prompt: the same instruction twice is meant twice
    sequenced: bool
    steps: list[Step] = field(default_factory=list)
    unread: list[str] = field(default_factory=list)
    problems: list[tuple[Problem, str, Reading]] = field(default_factory=list)
    confidence: float = 1.0
    previous: Step | None = None
    previous_target: ElementRef | None = None
    #: "which is the largest room?" before "drive into it"
    asked: tuple[Problem, str, Reading] | None = None
    #: what the reading would have to guess
    questions: list[str] = field(default_factory=list)
    #: what the clause before asked, when its one step is the last step
    last_asks: tuple[str, ...] = ()
    #: words left unread that could change where or how far
    blocking: list[str] = field(default_factory=list)
    #: clauses left unread since the last motion step (see ``_unread_between``)
    between: list[str] = field(default_factory=list)
    #: each word of where left unread, with the steps said next to it (see ``_said_in_both_languages``)
    near: list[tuple[str, list[Step]]] = field(default_factory=list)
    #: of those, the ones said in a clause with no step: the next step said is next to them too
    awaiting: list[list[Step]] = field(default_factory=list)

    def add(self, clause: str) -> Intent | None:
        """Read ``clause`` and join its steps to those before; the refusal of the whole prompt when the clause
        names a place the map cannot know."""
        clause = with_unit_said_before(clause, self.previous, is_fragment(clause))
        again = said_again(clause, self.previous)
        if again is not None:
            self._doubt(_unread_between(self.steps, [again], self.between), [*self.steps[-1:], again])
            self.between = []
            self.steps.append(again)  # "turn left ninety, and again": the same turn once more
            self.previous = again
            return None
        reading = read_composed(clause, self.previous, self.known_names, self.previous_target)
        if reading.problem == Problem.QUESTION and reading.referent is not None:
            self.asked = (reading.problem, clause, reading)
            self.previous_target = reading.referent
            return None
        if self.asked is not None:
            if not any(s.target == self.asked[2].referent for s in reading.steps):
                self._left_open(self.asked)  # (a question that only named the place the next instruction goes to is no problem)
            self.asked = None
        if reading.problem == Problem.NAME:
            return _clarify(_name_message(reading.name or clause), confidence=reading.confidence, unread=[])
        if reading.problem == Problem.UNKNOWABLE:
            return _clarify(_unknowable_message(reading.name or clause), confidence=reading.confidence, unread=[])
        if reading.problem is not None:
            self.problems.append((reading.problem, clause, reading))
        self.confidence = min(self.confidence, reading.confidence)
        self.unread.extend(u for u in reading.unread if u)
        self.questions.extend(reading.asks)
        before = self.steps[-1:]
        if reading.steps:
            for near in self.awaiting:
                near.append(reading.steps[0])
            self.awaiting = []
        if reading.steps or reading.problem in UNREAD_PROBLEMS:
            self._doubt([u for u in reading.unread if u and (spatial(u) or names_destination(u))],
                        [*before, *reading.steps],
                        waits=not reading.steps)
        if reading.problem in _UNREAD_ALONE and not reading.steps:
            self.between.extend(u for u in reading.unread if u)
        elif reading.steps:
            self._doubt(_unread_between(self.steps, list(reading.steps), self.between,
                                        whole=not reading.amends_previous), [*before, reading.steps[0]])
            self.between = []
        self._join(clause, reading)
        return None

    def _doubt(self, unread: list[str], near: list[Step], *, waits: bool = False) -> None:
        """Words left unread that could change where or how far, with the steps said next to them (``waits``: and
        the next step said, still to come)."""
        for text in unread:
            self.blocking.append(text)
            self.near.append((text, near))
        if unread and waits:
            self.awaiting.append(near)

    def _left_open(self, asked: tuple[Problem, str, Reading]) -> None:
        """A question the instructions after it did not take up: a problem of the prompt."""
        self.problems.append(asked)
        self.confidence = min(self.confidence, asked[2].confidence)
        self.unread.extend(asked[2].unread)

    def _join(self, clause: str, reading: Reading) -> None:
        """The clause's steps joined to the steps before: a place said more exactly, a step completed, amended,
        said again or confirmed is one step; the rest follow."""
        steps, questions, sequenced = self.steps, self.questions, self.sequenced
        new_steps = [_come_back_way(steps[-1] if steps else None, s) for s in reading.steps]
        if steps and _refines(clause, steps[-1], new_steps):
            # "go to the door on your left, the one after the first": the same place, said more exactly
            steps[-1] = steps[-1].model_copy(update={"target": _merged(steps[-1].target, new_steps.pop(0).target),
                                                     "text": f"{steps[-1].text}, {clause}"[:500]})
        if reading.through_previous and steps and steps[-1].movement == Movement.NAVIGATE:
            steps[-1] = steps[-1].model_copy(update={"detail": Detail.THROUGH,
                                                     "text": f"{steps[-1].text}, {clause}"[:500]})
        if reading.amends_previous and steps and new_steps and _amendable(steps[-1], new_steps[0]):
            if steps[-1].movement == Movement.ROTATE:
                # "turn left, hands, ninety": a bare number completing a turn counts the turn's degrees (as
                # "turn left, ninety" does), whatever word came between: no unit to ask about
                for question in reading.asks:
                    if question.startswith(ASK_UNIT_START) and question in questions:
                        questions.remove(question)
            steps[-1] = _amend(steps[-1], new_steps.pop(0), clause)
        if (reading.amends_previous and steps and new_steps and not sequenced and not _REPEAT_RE.search(clause)
                and same_way_again(steps[-1], new_steps[0]) and not _restates(steps[-1], new_steps[0], clause)):
            # "go forward ten feet... ten metres": a different amount alone, with no word that corrects the first
            # ("no", "sorry", "I mean") or adds to it: two readings of how far, so ask (never the sum)
            questions.append(ASK_AMOUNT.format(amounts=f"'{steps[-1].text}', '{clause}'"))
        elif steps and new_steps and not sequenced and _restates(steps[-1], new_steps[0], clause):
            steps[-1] = _smaller(steps[-1], new_steps.pop(0))  # "forward two metres. forward two metres.": done once
        elif steps and new_steps and not sequenced and _confirms(steps[-1], new_steps[0], clause):
            new_steps.pop(0)  # "turn to your left, about ninety degrees, just a proper left turn": said once
            if not new_steps:
                for question in reading.asks:  # "how far?" of the bare one is answered by the amount said first
                    if question in questions:
                        questions.remove(question)
        elif steps and new_steps and not sequenced and _completes(steps[-1], new_steps[0], clause):
            steps.pop()  # "turn left ... turn left fifty degrees": the same turn said again with its amount
            for question in self.last_asks:
                # "move forward ... you're breaking up ... move forward two metres": the bare move's
                # question ("how far?") is answered by the move said again with its amount
                if question in questions and question not in reading.asks:
                    questions.remove(question)
        if steps and new_steps and not sequenced and _side_word_after_place(steps[-1], new_steps[0], clause):
            # "go to the left corner, left": the place's side said again, not a turn after it; another side
            # ("go to the left corner, right") may put the place right or add a turn: ask, don't guess
            side = Side(str(new_steps.pop(0).direction))
            if steps[-1].target is None or steps[-1].target.side != side:
                questions.append(ASK_SIDE_OR_TURN.format(side=side.value))
        while steps and new_steps and _asked_again(steps[-1], new_steps[0]):
            new_steps.pop(0)  # "hold it, hold it"; "where are you? can you tell me where you are?"
        steps.extend(new_steps)
        if new_steps:
            self.last_asks = reading.asks if len(new_steps) == 1 else ()
        if steps:
            self.previous = steps[-1]
            targets = [s.target for s in steps if s.target is not None]
            self.previous_target = targets[-1] if targets else None

    def intent(self, clauses: list[str], text: str, photo: bool) -> Intent:
        """The intent of the whole prompt once every clause is read: its steps, or the question to ask."""
        if self.asked is not None:
            self._left_open(self.asked)
        steps = self.steps
        if len(steps) > MAX_STEPS:
            return _clarify(TOO_MANY_STEPS_MESSAGE, confidence=1.0, unread=[])
        problems, unread = self.problems, self.unread
        answered = [(p, clause, r) for p, clause, r in problems if p == Problem.QUESTION and _answered_by(clause, steps)]
        if answered:
            problems = [x for x in problems if x not in answered]
            said = {u for _, _, r in answered for u in r.unread}
            unread = [u for u in unread if u not in said]
        misread = [(p, clause, r) for p, clause, r in problems if p in WHOLE_PROMPT_REFUSALS]
        if misread:
            # a step whose number is beyond range or unreadable: the other steps were planned around
            # it ("turn left, 4000 degrees"; "go to door 2 and turn left"), so none of them runs
            problem, clause, reading = misread[0]
            return _clarify(_problem_message(problem, clause), confidence=reading.confidence,
                            unread=[] if problem in SURE_REFUSALS else list(reading.unread))
        said_twice = {text for text, near in self.near if _said_in_both_languages(text, near)}
        unread = [u for u in unread if u not in said_twice]
        blocking = [] if only_stops(steps) else [u for u in dict.fromkeys(self.blocking) if u not in said_twice]
        if steps and (blocking or self.questions):
            # ask, don't guess: nothing runs; the reply says what would run and asks about the rest
            return _clarify(ask_message(steps, blocking, self.questions), confidence=ASK_CONFIDENCE,
                            unread=blocking or [clause[:200] for clause in clauses][:MAX_STEPS])
        if not steps:
            return _nothing_to_run(problems, unread, clauses, text, photo)
        confidence = min(self.confidence, PARTIAL_CONFIDENCE) if problems else self.confidence  # part not done
        return Intent(steps=steps, translator=TRANSLATOR_NAME, confidence=round(confidence, 3), unread=unread,
                      clarification=PHOTO_LEFT_OUT_MESSAGE if photo else None)


def _nothing_to_run(problems: list[tuple[Problem, str, Reading]], unread: list[str], clauses: list[str], text: str,
                    photo: bool) -> Intent:
    """What to tell the user when no step was read: a picture asked for, a request taken back, the first
    problem, or that nothing was understood."""
    if not problems and photo:
        return _clarify(NO_CAMERA_MESSAGE, confidence=1.0, unread=[])
    if not problems and not clauses and CANCEL_RE.search(text):
        return _clarify(CANCELLED_MESSAGE, confidence=1.0, unread=[])
    if not problems:
        return _clarify(_unreadable_message(text), confidence=0.2, unread=[text[:200]])
    problem, clause, _ = problems[0]
    sure = all(p in SURE_REFUSALS for p, _, _ in problems)
    return _clarify(_problem_message(problem, clause), confidence=min(r.confidence for _, _, r in problems),
                    unread=[] if sure else unread)


def _said_in_both_languages(text: str, near: Sequence[Step]) -> bool:
    """Every word of where in ``text`` is a way said in another language (``lexicon.FOREIGN_WAYS``) that a step
    said next to it takes: a bilingual speaker says the way in both languages ("peeche, back side, thirty
    centimetre": Hindi "back"; "turn left, izquierda, ninety degrees"), so the word is read. A way the steps next
    to it do not take ("turn right, izquierda, ninety degrees") may be the way meant: the robot asks."""
    if _amount_said_again(text, near):
        return True
    words = [w.strip(",.;:!?'\"") for w in spatial(text)]
    if len(text.split()) == 1 and len(words) == 1 and words[0] in _WAYS_ALONE:
        # an English way word said on its own ("behind! back up two feet") is read the same way: it says again
        # the way of the motion beside it, or (another way) may be the way meant, and the robot asks
        return any(_takes(_WAYS_ALONE[words[0]], s) for s in near)
    return bool(words) and all(w in FOREIGN_WAYS and any(_takes(FOREIGN_WAYS[w], s) for s in near) for w in words)


def _amount_said_again(text: str, near: Sequence[Step]) -> bool:
    """``text`` is only an amount said in another language (``lexicon.FOREIGN_NUMBERS``, with or without its unit)
    that a step next to it has: the speaker said the amount in both languages ("do meter, two meter forward"), so
    the words are read. (Any other amount, or a word that is no number, may be the amount meant: the robot asks.)"""
    value, unit_m, unit_deg, said = 0.0, None, None, False
    for word in (w.strip(",.;:!?'\"") for w in text.lower().split()):
        if word in FOREIGN_NUMBERS:
            value, said = value + FOREIGN_NUMBERS[word], said or FOREIGN_NUMBERS[word] > 0
        elif word in LENGTH_UNITS_M and unit_m is None and unit_deg is None:
            unit_m = LENGTH_UNITS_M[word]
        elif word in ANGLE_UNITS_DEG and unit_m is None and unit_deg is None:
            unit_deg = ANGLE_UNITS_DEG[word]
        else:
            return False
    if not said:
        return False
    for step in near:
        if step.movement == Movement.MOVE and unit_m is not None and step.distance_m is not None:
            amount, had = value * unit_m, step.distance_m
        elif step.movement == Movement.ROTATE and unit_m is None and step.angle_deg is not None:
            amount, had = value * (unit_deg or 1.0), step.angle_deg
        else:
            continue
        if abs(had - amount) <= _SAME_AMOUNT_REL * had:
            return True
    return False


#: English words of a way said on their own, and the way each says (as ``lexicon.FOREIGN_WAYS``).
_WAYS_ALONE: Final = {"behind": "back", "back": "back", "backward": "back", "backwards": "back", "ahead": "forward",
                      "forward": "forward", "forwards": "forward", "left": "left", "right": "right"}


def _takes(way: str, step: Step) -> bool:
    """Whether ``step`` goes the way a word of ``lexicon.FOREIGN_WAYS`` says."""
    if way == "stop":
        return step.movement == Movement.STOP
    if way in ("left", "right"):
        # (the side said in English too: a turn whose side was not said carries a placeholder side, which agrees
        # with nothing: "turn links, ninety degrees" asks)
        return step.movement in (Movement.MOVE, Movement.ROTATE) and step.direction == Direction(way) \
            and re.search(rf"\b{way}\b", step.text.lower()) is not None
    if way in ("forward", "back"):
        way_said = Direction.FORWARD if way == "forward" else Direction.BACKWARD
        return step.movement == Movement.MOVE and step.direction == way_said
    return False


#: The steps that move the robot: an unknown word between two of them may undo the first (see _unread_between).
_MOTIONS: Final = frozenset({Movement.MOVE, Movement.ROTATE, Movement.NAVIGATE})


#: Clauses read as no instruction at all, or as one not to do ("not left"): between two instructions, they may
#: take the first back (see _unread_between).
_UNREAD_ALONE: Final = frozenset({Problem.UNREADABLE, Problem.NO_ANTECEDENT, Problem.NEGATED})


def _unread_between(before: Sequence[Step], after: Sequence[Step], unread: Sequence[str], *,
                    whole: bool = False) -> list[str]:
    """The clauses left unread (``unread``) that stand between a motion said before and one said after.

    Speakers take an instruction back with a word and then say what they mean: "turn right ninety, nein, turn
    left ninety"; "turn right, hayir, turn left". In English the words that do so are known (``corrections``:
    "sorry", "disregard", "belay" ...); a word of another language the reading does not know may be one, and
    then it cannot tell a correction (only the second motion is meant) from a pause (both are): doing both would
    move or turn more than asked if it was a correction. So such a word blocks the plan and the robot asks. (An
    English word it does not know before an amount that completes the instruction before it, "turn to your left,
    dear, ninety degrees", "slew right, easy, about thirty degrees", is no correction; before the first motion or
    after the last, an unknown word takes nothing back: "unit one, stop"; "turn around po".)

    Between two whole instructions (``whole``: the second no amount completing the first), English words it does
    not know ask too: English has more ways to say "I said it wrong" than any list ("turn left ninety, the
    opposite, turn right ninety"; "go forward two metres, not that, go back one metre"), and doing both would move
    or turn more than asked if it was one."""
    if not unread or not any(s.movement in _MOTIONS for s in before) \
            or not any(s.movement in _MOTIONS for s in after):
        return []
    # (the same facing or stop said again is no second instruction: "face north, dear? the window is north")
    whole = whole and not _asked_again(before[-1], after[0])
    # (words that put the instructions in order say both are meant: "turn left, later, turn right forty five")
    return [u for u in unread if (whole and not _ORDER_ONLY_RE.match(u)) or any(_foreign(w) for w in u.split())]


#: A clause of only words that put instructions in order (``lexicon.ORDER_WORDS``: "later", "plus", "n", "&").
_ORDER_ONLY_RE: Final = re.compile(r"^\W*(?:(?:" + "|".join(w.replace(" ", r"\s+") for w in ORDER_WORDS)
                                   + r")\b\W*|&\W*)+$", re.IGNORECASE)


def _foreign(word: str) -> bool:
    """A word of no English (SCOWL's lists) that the reading does not know either: the class of words whose
    meaning the robot cannot tell (an English word it does not know, "dear", "easy", is no correction: the
    words English speakers correct with are known, ``corrections``)."""
    bare = word.lower().strip(",.;:!?'\"")
    return bare.isalpha() and not is_english(bare) and bare not in VOCABULARY and bare not in STOPWORDS


def _clauses(text: str, known_names: Sequence[str] = ()) -> tuple[list[str], bool]:
    """The instructions of a prompt, each whole: particles of other languages and photo requests taken out
    (and whether there was one), fragments joined to the move or turn they complete, self-corrections applied."""
    kept: list[str] = []
    photo = False
    for clause in without_particles(split_steps(text), _read, known_names):
        without = without_photo(clause)
        photo = photo or without.asked
        if without.asked and is_bare_verb(without.rest):
            continue  # "then turn take picture": a verb cut short by the photo request
        if without.asked and kept and _same_turn(kept[-1], without.rest):
            continue  # "turn left, I'd like to see what's on your left": the picture's turn is the one just made
        if without.rest and not is_hedge(without.rest):
            kept.append(without.rest)
    # fragments join the instruction they complete both before and after the corrections: "move five
    # meters, I mean five feet, forward" is corrected first, then completed
    kept = drop_insisted_amounts(read_stated_amounts(read_consents(kept)))  # before joining: "..., only a little"
    joined = join_fragments(apply_corrections(join_fragments(kept, _is_open)), _is_open)
    said_once = drop_false_start_turns(drop_stopped(drop_insisted_amounts(joined), _read), text, _read)
    return merge_restated_turns(said_once, _read), photo


def _answered_by(question: str, steps: list[Step]) -> bool:
    """A question the robot cannot answer, said next to an instruction that uses every word of where it
    asks about ("wait, which way is north... okay, face north"), is the speaker thinking aloud: the
    instruction is the request, and nothing of where or how far was left unread."""
    words = spatial(question)
    said = " ".join(s.text.lower() for s in steps).split()
    return bool(words) and bool(steps) and all(w.strip(",.;:!?'\"").lower() in said for w in words)


def _same_turn(before: str, implied: str) -> bool:
    """The turn a picture request implies ("... what's on your left") is a turn to the side the
    instruction before it just turned to."""
    first = read_clause(before)
    a, b = first.steps, read_clause(implied).steps
    if ASK_SIDE in first.asks:
        return False  # "turn 130 degrees, and take a picture counterclockwise": the side is the picture's
    return (len(a) >= 1 and len(b) == 1 and a[-1].movement == b[0].movement == Movement.ROTATE
            and b[0].angle_deg is None and a[-1].direction == b[0].direction and a[-1].heading_deg is None)


def _read(clause: str) -> Reading:
    return read_clause(clause)


def _is_open(clause: str) -> bool:
    return read_clause(clause).open


def _clarify(message: str, *, confidence: float, unread: list[str]) -> Intent:
    return Intent(steps=[], clarification=message[:500], translator=TRANSLATOR_NAME,
                  confidence=round(confidence, 3), unread=unread)


#: An apposition: "the one ..." (or "I mean the one ...") with no verb of its own.
_APPOSITION_RE: Final = re.compile(r"^(?:(?:i\s+mean|i\s+meant|that\s+is|namely|i\.e\.?)\s*,?\s*)?(?:the|that)\s+one\b",
                                   re.IGNORECASE)


def _merged(said: ElementRef | None, again: ElementRef | None) -> ElementRef | None:
    """The place said first, with what the apposition says more exactly ("the second door, the one on
    your right": the second, on the right)."""
    if said is None or again is None:
        return again or said
    update = {k: v for k, v in again.model_dump(exclude_defaults=True).items() if k != "kind"}
    return said.model_copy(update={k: getattr(again, k) for k in update})


def _refines(clause: str, previous: Step, new: list[Step]) -> bool:
    """The clause only names again, more exactly, the place the step before goes to."""
    return (_APPOSITION_RE.match(clause.strip()) is not None and len(new) == 1 and previous.target is not None
            and previous.movement == Movement.NAVIGATE and new[0].movement == Movement.NAVIGATE
            and new[0].target is not None and new[0].target.kind == previous.target.kind)


#: Words that ask for a motion once more ("again", "another metre", "two more", "a second time").
_REPEAT_RE: Final = re.compile(r"\b(?:again|another|more|further|twice|second\s+time|repeat|once\s+more)\b",
                               re.IGNORECASE)
#: Words that put instructions in a sequence: with them, the same instruction twice is meant twice
#: ("turn left 90 degrees, then turn left 90 degrees").
_SEQUENCE_RE: Final = re.compile(r"\b(?:" + "|".join(w.replace(" ", r"\s+") for w in SEQUENCE_WORDS) + r")\b",
                                 re.IGNORECASE)
#: Two amounts closer than this are the same amount said again (less than one 3 cm / 10 degree step).
_SAME_AMOUNT_TOL: Final = 1e-6
#: Two amounts within this fraction of each other are one amount said again in another unit or rounded
#: ("two metres, that is, about six and a half feet": 1.98 m; "ten feet, about three metres"): unit
#: conversions people say in their head are this close; done once, the smaller.
_SAME_AMOUNT_REL: Final = 0.05


def _same_motion_said_again(previous: Step, step: Step, clause: str) -> bool:
    """The same plain move or turn (no place, no heading) on the same side, said again with no word
    asking for it once more: the shared test of _restates and _completes."""
    if step.movement not in (Movement.MOVE, Movement.ROTATE) or step.movement != previous.movement:
        return False
    if step.target is not None or previous.target is not None or step.heading_deg is not None:
        return False
    return step.direction == previous.direction and not _REPEAT_RE.search(clause)


def _restates(previous: Step, step: Step, clause: str) -> bool:
    """The same move or turn, with the same amount, said again right after it with no word asking
    for it once more, in a prompt with no word that sequences its instructions: a speaker repeating or confirming an instruction ("move forward. Two metres.
    Forward two metres."; "fifty. fifty degrees left.") means it once. Doing it twice would take the
    robot farther than asked; doing it once never does, and the user can ask again."""
    if not _same_motion_said_again(previous, step, clause):
        return False
    if step.movement == Movement.MOVE:
        a, b = previous.distance_m, step.distance_m
    else:
        a, b = previous.angle_deg, step.angle_deg
        if a is None and b is None and previous.amount == step.amount == Amount.DEFAULT:
            return True  # "robot, turn left, turn left, over": one turn said twice
    return a is not None and b is not None and abs(a - b) <= max(_SAME_AMOUNT_TOL, _SAME_AMOUNT_REL * max(a, b))


def _smaller(previous: Step, step: Step) -> Step:
    """Of one motion said twice, the one that goes less far (never farther than either said)."""
    if step.movement == Movement.MOVE:
        return step if (step.distance_m or 0.0) < (previous.distance_m or 0.0) else previous
    return step if (step.angle_deg or 0.0) < (previous.angle_deg or 0.0) else previous


def _completes(previous: Step, step: Step, clause: str) -> bool:
    """The same move or turn said first with no amount and right after again with one ("turn left ...
    you're breaking up ... turn left fifty degrees"), with no word asking for it once more and no word
    sequencing the prompt: the speaker is repeating the instruction and completing it, so it is done
    once, with the amount said. Doing the bare one too would add a default amount nobody asked for and
    take the robot farther than asked; doing it once never does, and the user can ask again."""
    if previous.heading_deg is not None or not _same_motion_said_again(previous, step, clause):
        return False
    if step.movement == Movement.MOVE:
        return previous.distance_m is None and step.distance_m is not None
    return previous.angle_deg is None and step.angle_deg is not None


#: What a clause of only a side word may hold besides the side ("left", "to the left", "on your left").
_SIDE_ONLY_RE: Final = re.compile(r"^\W*(?:to\s+|on\s+)?(?:the\s+|your\s+)?(left|right)\W*$", re.IGNORECASE)
#: Asked when a side word follows a place it could describe or follow as a turn.
ASK_SIDE_OR_TURN: Final = "Did you mean the one on the {side}, or to turn {side} once there?"


def _side_word_after_place(previous: Step, step: Step, clause: str) -> bool:
    """A side word said on its own ("left") straight after an instruction to go to a place: a person
    saying it there names, or repeats for stress, which place ("the left corner, left"); it could also be a
    turn once there ("go to the door, left"), so only the same side as the place's is taken as said again."""
    return (previous.movement == Movement.NAVIGATE and previous.target is not None
            and step.movement == Movement.ROTATE and step.direction in (Direction.LEFT, Direction.RIGHT)
            and step.amount == Amount.DEFAULT and step.angle_deg is None
            and step.heading_deg is None and step.target is None and _SIDE_ONLY_RE.match(clause) is not None)


def _confirms(previous: Step, step: Step, clause: str) -> bool:
    """The same move or turn said first with its amount and right after again with none ("turn to your
    left, about ninety degrees, just a proper left turn"; "go forward two metres, forward"), with no word
    asking for it once more and no word sequencing the prompt: the speaker confirms the instruction, so
    it is done once, with the amount said (the bare one would add a default amount nobody asked for)."""
    if previous.heading_deg is not None or not _same_motion_said_again(previous, step, clause):
        return False
    if step.amount != Amount.DEFAULT:
        return False
    if step.movement == Movement.MOVE:
        return previous.distance_m is not None and step.distance_m is None
    return previous.angle_deg is not None and step.angle_deg is None


#: "come back" said of a move: towards where the robot came from (not "go back", which is the way behind it).
_COME_BACK_RE: Final = re.compile(r"\bcome\s+back\b", re.IGNORECASE)


def _come_back_way(previous: Step | None, step: Step) -> Step:
    """"Go forward ten feet, turn around, come back ten feet": "come back" is towards where the robot came
    from; once it has turned around, that lies ahead, so the move is forward (a move backward would take it
    ten more feet away)."""
    if (previous is None or step.movement != Movement.MOVE or step.direction != Direction.BACKWARD
            or not _COME_BACK_RE.search(step.text)):
        return step
    turned_around = previous.movement == Movement.ROTATE and previous.heading_deg is None and (
        previous.direction == Direction.AROUND or (previous.angle_deg is not None and abs(previous.angle_deg - 180.0) < 1e-6))
    return step.model_copy(update={"direction": Direction.FORWARD}) if turned_around else step


#: Words that point back at the place just named ("go in there", "go into it").
_POINTS_BACK_RE: Final = re.compile(r"\b(?:there|it|inside)\b", re.IGNORECASE)
_ELEMENT_NOUN_RE: Final = re.compile(r"\b(?:" + "|".join(sorted(map(re.escape, ELEMENT_NOUNS), key=len, reverse=True))
                                     + r")\b", re.IGNORECASE)
#: The start of the question of a number's unit (``reading.ASK_UNIT``).
ASK_UNIT_START: Final = ASK_UNIT.split("{")[0]
#: Steps that move nothing: said twice in a row, they are one request.
_NO_MOTION: Final = frozenset({Movement.STOP, Movement.QUERY})


def _asked_again(previous: Step, step: Step) -> bool:
    """A stop, a question or a facing said again right after itself ("hold it, hold it"; "where are you
    now? can you tell me where you are?"; "face north, face north") is the speaker insisting: one stop,
    one answer, one turn (the second facing would turn by nothing). (With a motion between, the second
    question asks something new: where the robot is now.)"""
    if step.heading_deg is not None and step.target is None and previous.target is None:
        return step.heading_deg == previous.heading_deg  # "face north, I repeat, face north": facing it once
    if (step.movement == previous.movement == Movement.NAVIGATE and step.target is not None
            and step.target == previous.target and step.detail in (None, Detail.TO)
            and previous.detail in (None, Detail.TO) and _POINTS_BACK_RE.search(step.text)
            and not _ELEMENT_NOUN_RE.search(step.text)):
        # "find the biggest room and go in there": one trip to it (the second names no place of its own and
        # arrives where the robot already is; "the next door, then the next door" names two)
        return True
    return (step.movement in _NO_MOTION and step.movement == previous.movement and step.query == previous.query
            and step.target == previous.target)


def _amendable(previous: Step, fragment: Step) -> bool:
    """'turn left, about 45 degrees': a bare number completes the step before it."""
    if previous.movement == Movement.ROTATE and previous.angle_deg is None:
        return fragment.movement == Movement.ROTATE or fragment.movement == Movement.MOVE
    if previous.movement == Movement.MOVE and previous.distance_m is None:
        return fragment.movement == Movement.MOVE
    return False


def _amend(previous: Step, fragment: Step, clause: str) -> Step:
    text = f"{previous.text}, {clause}"[:500]
    if previous.movement == Movement.ROTATE:
        angle = fragment.angle_deg if fragment.movement == Movement.ROTATE else fragment.distance_m
        direction = previous.direction
        if direction == Direction.AROUND and angle is not None and abs(angle - 180.0) > 1e-6:
            direction = Direction.LEFT
        return previous.model_copy(update={"angle_deg": angle, "amount": None if angle is not None else Amount.DEFAULT,
                                           "direction": direction, "text": text})
    return previous.model_copy(update={"distance_m": fragment.distance_m, "amount": fragment.amount,
                                       "text": text})


def _name_message(name: str) -> str:
    return (f"I don't know a place called '{name}'; name it first: stand there and say 'call this spot the "
            f"{name}'. Or tell me where it is by what the map shows, e.g. 'the second door on your left' or "
            "'room 3'.")


def _unknowable_message(name: str) -> str:
    return (f"I can't tell which one is '{name}': my map shows walls, doors and free space, but no colours, weights "
            "or materials. Tell me which one by where it is or its size, e.g. 'the second door on your left', "
            "'the nearest door' or 'the widest door'.")


#: What to tell the user for each problem a step may have; ``{quoted}`` is the step as written.
PROBLEM_MESSAGES: Final[dict[Problem, str]] = {
    Problem.OTHER_FLOOR: ("I can't do \"{quoted}\": I drive only on the floor my map shows; I can't use stairs, "
                          "lifts or escalators, or go to another floor."),
    Problem.DURATION: ("In \"{quoted}\" I'm given a time, but I move by distance and turn by angle. Tell me how "
                       "far or how much, e.g. 'move forward 1 metre' or 'turn left 45 degrees'."),
    Problem.OUT_OF_SCOPE: ("I can't do \"{quoted}\": I can only drive, turn, stop, explore the map and tell you "
                           "where I am, my path or the map."),
    Problem.NEGATED: ("I read \"{quoted}\" as something not to do, so I will not move. Tell me what to do "
                      "instead, e.g. 'go to the door on your right'."),
    Problem.QUESTION: ("I can't answer \"{quoted}\": I can tell you where I am, the path I am following, or "
                       "show the map. Ask e.g. 'where are you?' or 'show me the map'."),
    Problem.OUT_OF_RANGE: ("\"{quoted}\" asks for more than one move or turn may do (at most 100 m or ten full "
                           "turns). Name a place to go to instead, e.g. 'go to the farthest door'."),
    Problem.BAD_NUMBER: ("I could not read the number in \"{quoted}\", so I will not move. Give it in digits or "
                         "words, e.g. 'move forward 2.5 metres', 'turn left 90 degrees' or 'the second door'."),
    Problem.BEARING: ("I can't tell which way \"{quoted}\" points: on a compass a heading in degrees counts "
                      "clockwise from north (90 is east), on my map counter-clockwise from east (90 is north). Nothing "
                      "was run: say it with a compass point, e.g. 'face south', or as a turn, e.g. 'turn right 90 "
                      "degrees'."),
    Problem.NO_ANTECEDENT: ("In \"{quoted}\" I can't tell what 'it' or 'there' means. Name the place, e.g. "
                            "'the nearest door' or 'the left corner of this room'."),
}


def _problem_message(problem: Problem, clause: str) -> str:
    template = PROBLEM_MESSAGES.get(problem)
    if template is None:
        return _unreadable_message(clause)
    return template.format(quoted=_quoted(clause))


def _quoted(text: str) -> str:
    return text if len(text) <= 120 else text[:117] + "..."


def _unreadable_message(text: str) -> str:
    return (f"I didn't understand \"{_quoted(text)}\". Try for example 'go through the first door on your left', "
            "'move forward 1 metre' or 'turn right 90 degrees'.")
