"""Speech as it comes, made plain before a prompt is split: hesitations ("uh", "um", "hmm"), cut-off
words ("nin- degree- ninety degrees"), stutters ("tur turn", "to l left", "a a left"), noise tokens
("ff", "fff") and self-corrections marked as their own clause ("ninety degrees right, actually left").

Nothing here changes what a word means: it only drops what carries no meaning, so the reading that
follows sees what the speaker meant to say (README "Speech": fillers and cut-off words mean nothing).
"""

from __future__ import annotations

import re
import unicodedata
from typing import Final

from langnav.language.offline.lexicon import (
    FOREIGN_AMOUNTS,
    FOREIGN_NO_WORDS,
    GO_VERBS,
    HESITATIONS,
    ROTATE_VERBS,
    TYPOS,
)
from langnav.language.offline.numbers import NUMBER_WORD_LIST, NUMBER_WORDS, ONES, TENS
from langnav.language.offline.patterns import TURN_SIDE_WORDS
from langnav.language.offline.sidetalk import without_side_talk
from langnav.language.offline.vocabulary import VOCABULARY

#: Hedges a speaker puts before an amount or a direction ("uh maybe forty five degrees"): they soften
#: the words, they never change the amount or the side.
#: Affirmations ("you're right", "that's correct") are no side; "at least" / "at most" and "until I
#: tell you to stop" leave the amount said as it is; "what about / how about" before a verb is a request.
_HEDGES: Final = re.compile(
    r"\b(?:maybe|perhaps|i\s+guess|i\s+think|(?:i\s+)?reckon(?:\s+that)?|kind\s+of|sort\s+of|let\s+us\s+see|let's\s+see|lets\s+see|"
    # ("where you are right now": after "where", "right" says when or where, no affirmation)
    r"(?<!where\s)(?:you'?re|you\s+are|that'?s|that\s+is|thats)\s+(?:right|correct)|"
    r"at\s+(?:least|most)|"
    r"(?:go\s+ahead|go\s+on|come\s+on)\s+and|"
    r"(?:until|till)\s+i\s+(?:tell\s+you(?:\s+(?:to\s+stop|otherwise))?|say\s+(?:so|stop|otherwise))|"
    r"(?:what|how)\s+about(?=\s+(?:you\s+)?(?:move|go|turn|rotate|head|drive|face|pivot|back|proceed)\b)|"
    r"let'?s\s+say|let\s+us\s+say|shall\s+we\s+say|i'?d\s+say|oh(?=\s*,)|let\s+me\s+think|"
    # hedges on an amount said after it: "eighty centimetres, give or take", "more or less half a metre",
    # "three feet or thereabouts": the amount is said; how sure the speaker is of it changes nothing
    r"give\s+or\s+take(?:\s+a\s+(?:bit|little|touch|tad))?|more\s+or\s+less|or\s+there\s*abouts|"
    r"(?:or\s+)?so\s+i(?:'?m|\s+am)\s+told|or\s+so\s+i\s+(?:think|hear|believe|reckon))\b",
    re.IGNORECASE)
#: Discourse particles of Singapore and Malaysian English ("u-turn lah", "go straight lor", "can or not meh"):
#: they carry the speaker's stance (insisting, resigned, doubting), never a way, an amount or a place.
PARTICLES: Final = frozenset({"lah", "leh", "lor", "loh", "meh", "hor", "sia", "liao"})
#: Reported speech before an instruction ("chat says turn left", "my boss said go back two metres", "they want
#: you to turn around"): the speaker relays what someone else asks; the instruction is the same as if the
#: speaker said it (and said again right after, "chat says turn left, okay, turn left forty five", it is one).
#: Only someone named as a speaker (not any word: "nobody said turn left", "who said turn around" relay
#: nothing), and never in a question ("you said turn left?", "he said turn left?": the speaker is asking,
#: not asking the robot): those stay unread, so the robot asks.
REPORTED: Final = re.compile(
    r"(?:^|(?<=[,.;!?]))\s*(?:(?:the|my|our|your|his|her|their|some|someone|somebody|everyone|everybody|people|"
    r"they|he|she|chat|boss|[a-z]+'s)\s+)*(?:chat|boss|they|he|she|someone|somebody|everyone|everybody|people|"
    r"viewers?|folks|guys|team|mum|mom|dad|manager|supervisor|client|caller|user)(?:'s|\s+is|\s+are|'d|\s+would)?\s+"
    r"(?:says?|said|saying|"
    # the verbs of a request relayed: "wants you to", "would like you to", "is asking you to", "tells you to";
    # an interpreter voicing a signer says "she signs" / "she's signing"
    r"wants?\s+(?:you|u)\s+to|want\s+(?:you|u)\s+to|like\s+(?:you|u)\s+to|(?:asks?|asked|asking)\s+(?:you\s+)?to|"
    r"(?:tells?|telling)\s+(?:you|u)\s+to|signs?|signed|signing|reckons?|thinks?)\s+"
    # (a way relayed alone is the request too: "she signed right", as an interpreter voices a signed way)
    r"(?=(?:to\s+)?(?:turn|go|move|rotate|spin|pivot|back|reverse|drive|head|face|stop|come|"
    r"left|right|forwards?|backwards?|ahead|straight|around)\b)",
    re.IGNORECASE)
#: A question relayed ("she asks where you are", "he wants to know where you are"): the question itself, asked
#: of the robot, as when the speaker asks it ("where are you") -- only a question of where the robot is, the
#: one the robot answers; the words of the relay are left as they are before any other question.
REPORTED_QUESTION: Final = re.compile(
    r"(?:^|(?<=[,.;!?]))\s*(?:(?:the|my|our|his|her|their|[a-z]+'s)\s+)*(?:they|he|she|chat|boss|someone|somebody|"
    r"client|caller|user|manager|supervisor)(?:'s|\s+is|\s+are|'d|\s+would)?\s+"
    r"(?:asks?|asked|asking|wants?\s+to\s+know|like\s+to\s+know|wonders?|wondering|signs?|signed|signing)\s+"
    r"(?=where\s+(?:you|u)\s+(?:are|r)\b)",
    re.IGNORECASE)
#: Nigerian Pidgin and Nigerian English, each only where the word has that job: "dey" after a pronoun is the
#: copula "are" ("where you dey now"); "na X i talk / say" is "it is X I said" ("na left i talk"), which says
#: again the way the speaker means; "make you" before a verb is "so that you" ("turn around make you face
#: me"), a purpose, not a second request.
PIDGIN: Final = (
    (re.compile(r"\b(?P<who>you|u|i|we|they|he|she|it)\s+dey\b", re.IGNORECASE), r"\g<who> are"),
    (re.compile(r"\bna\s+(?P<said>(?:(?:to\s+)?(?:the|your)\s+)?(?:left|right|front|back|forward|backward))"
                r"(?:\s+(?:side|hand\s+side))?\s+(?:i|we)\s+(?:talk|tok|say|said|tell\s+(?:you|u))(?:\s+am)?\b",
                re.IGNORECASE), r"i mean \g<said>"),
    (re.compile(r"\s+make\s+(?P<who>you|u)\s+(?=(?:face|see|look|dey|fit|no|reach)\b)", re.IGNORECASE),
     r", so that \g<who> "),
)
#: Words written with their first syllable dropped, as said ("turn 'round", "'bout face", "go 'til the wall"):
#: the whole word.
ELIDED: Final = (
    (re.compile(r"(?<![\w'])'(?P<w>round|bout|til|till|cause|em)\b", re.IGNORECASE),
     lambda m: {"round": "around", "bout": "about", "til": "until", "till": "until", "cause": "because",
                "em": "them"}[m.group("w").lower()]),
)
#: A stammered word: its first sound said and said again before the whole word ("g-g-go", "b-b-back", "t-turn"):
#: the word.
STAMMER: Final = re.compile(r"\b(?P<s>[a-z]{1,3})(?:-(?P=s))*-(?P<w>(?P=s)[a-z]+)\b", re.IGNORECASE)


def _unstammer(m: re.Match[str]) -> str:
    """The stammered word, unless its first sound is a number said whole: "six-sixteen metres" is a number
    said twice differently (a correction or a mishearing), never sixteen on its own: left as said, it asks."""
    sound = m.group("s").lower()
    return m.group(0) if sound in ONES or sound in TENS else m.group("w")


def _relay(m: re.Match[str]) -> str:
    """Reported speech relayed as the speaker's own request, unless the clause is a question."""
    rest = m.string[m.end():]
    end = re.search(r"[,.;!?]", rest)
    return m.group(0) if end is not None and end.group(0) == "?" else " "
#: A word cut off in the middle: letters and a dash before a space or the end ("nin-", "c-").
_CUT_OFF: Final = re.compile(r"(?<![\w-])[a-z]+-(?=[\s,.;!?]|$)", re.IGNORECASE)
#: Short consonant runs are sounds, not words ("ff", "fff", "tsk"); units ("ft", "cm") are words, and a
#: longer run is an unknown word the reading must see (and ask about).
_NOISE: Final = re.compile(r"^[bcdfghjklmnpqrstvwxz]{2,4}$")
#: Unit letters that are sounds when no number comes before them ("mm move forward", "uh m uh").
_UNIT_SOUNDS: Final = frozenset({"m", "mm"})
_NUMBER_WORD: Final = re.compile(rf"^(?:[\d.,/]*\d[\d.,/]*|{NUMBER_WORDS}|hundred|half|a|an)$")
#: "can you move, can you turn left": a request started again; the words before the restart go.
_RESTART: Final = re.compile(r"\b(?:can|could|will|would)\s+you\s+(?:(?!(?:and|then)\b)[^\s,.;]+\s+){1,3}?"
                             r"(?=(?:can|could|will|would)\s+you\b)",
                             re.IGNORECASE)
#: Words that open a self-correction; a clause break is put before them so that the correction is
#: read as a clause of its own ("turn ninety degrees right actually left").
CORRECTION_MARKERS: Final = (
    r"actually(?:\s+no)?(?:\s+i\s+meant|\s+i\s+mean)?", r"no,?\s+wait", r"no\s+no", r"wait,?\s+no", r"oh\s+wait",
    r"i\s+meant\s+to\s+say", r"i\s+mean\s+to\s+say", rf"make\s+it(?=\s+(?:\d|a\b|an\b|half|just|only|(?:{NUMBER_WORDS})\b))",
    r"(?:i'?m|i\s+am|im)\s+sorry", r"sorry", r"i\s+meant", r"i\s+mean", r"i\s+said", r"my\s+(?:bad|mistake|error|fault)", r"or\s+rather", r"make\s+that",
    r"scratch\s+that", r"never\s*mind", r"correction", r"oops", r"disregard", r"belay",
    r"(?:strike|delete|erase|undo|scrap)\s+that", r"i\s+misspoke", r"typo", r"on\s+second\s+thoughts?",
    # "turn eighty degrees right no eighty five": "no" right before a number corrects the amount
    rf"no(?=\s+(?:\d|a\s+hundred|half|{NUMBER_WORDS})\b)",
    # "turn left no right thirty degrees": "no" right before another side corrects the side
    r"(?:(?<=\bleft\s)|(?<=\bright\s))no(?=\s+(?:(?:to\s+(?:the|your)\s+)?(?:left|right)|clockwise|counter\s*clockwise)\b)",
)
_MARKER_INSIDE: Final = re.compile(r"(?P<before>\S+)\s+(?=(?:" + "|".join(CORRECTION_MARKERS) + r")\b)",
                                   re.IGNORECASE)
#: Words that belong to the marker that follows them ("i'm sorry", "oh wait", "actually no").
_MARKER_LEAD: Final = frozenset({"i'm", "im", "i", "am", "oh", "actually", "no", "wait", "um", "or", "that"})
_WORD: Final = re.compile(r"\S+")


_UNIT_WORD: Final = (r"(?:feet|foot|ft|inch(?:es)?|yards?|met(?:er|re)s?|centimet(?:er|re)s?|degrees?|deg|"
                    r"o\s*'?\s*clock|oclock)")
_SIDE_SLOT: Final = (r"(?:turn|turning|rotate|spin|pivot|swivel|veer|bear|hang|swing|to\s+your|on\s+your|hard|sharp|"
                     r"your)")
#: Words speech recognition writes for the number, side or punctuation that was said, each only in a
#: place where that word is expected (README "Speech"): "move forward to feet" is two feet, "turn
#: write" is right, "turn lift" is left; dictated punctuation ("comma", "period", "new line") is the
#: mark itself. Outside those places the words keep their meaning ("go to the door", "take the lift").
HOMOPHONES: Final = (
    (re.compile(rf"\b(?:to|too)\s+(?={_UNIT_WORD}\b)", re.IGNORECASE), "two "),
    (re.compile(rf"\bfor\s+(?={_UNIT_WORD}\b)", re.IGNORECASE), "four "),
    (re.compile(r"\bwon\b", re.IGNORECASE), "one"),
    # the radiotelephony digits pilots, air traffic and many radio users say (ICAO: "tree", "fower", "fife",
    # "niner"), where a number goes: before a unit or another number ("niner" is nothing else anywhere)
    (re.compile(r"\bniner\b", re.IGNORECASE), "nine"),
    *((re.compile(rf"\b{said}\s+(?=(?:{_UNIT_WORD}|zero|{NUMBER_WORDS})\b)", re.IGNORECASE), f"{digit} ")
      for said, digit in (("tree", "three"), ("fower", "four"), ("fife", "five"))),
    # a number of tens heard as two words ("nine tee degrees", "for tee five degrees"): the recogniser split the
    # word at its stress; only where a number goes (before a unit, a number or the end of a clause)
    *((re.compile(rf"\b(?:{said})\s+tee\b(?=\s*(?:{_UNIT_WORD}\b|(?:{NUMBER_WORDS})\b|[,.;!?]|$))", re.IGNORECASE), tens)
      for said, tens in (("twen|twin", "twenty"), ("thir|thur", "thirty"), ("for|four|fore", "forty"),
                         ("fif|fifth", "fifty"), ("six|sicks", "sixty"), ("seven", "seventy"), ("eigh|ate|eight", "eighty"),
                         ("nine|nigh|nein", "ninety"))),
    # the letters of "cw" / "ccw" said one by one ("rotate ninety deg c w")
    (re.compile(r"\bc\s+c\s+w\b", re.IGNORECASE), "ccw"),
    (re.compile(r"\bc\s+w\b", re.IGNORECASE), "cw"),
    (re.compile(r"\bate\b", re.IGNORECASE), "eight"),
    (re.compile(rf"\b(?P<slot>{_SIDE_SLOT}|go|move|head|drive|slide|step|to\s+the|on\s+the|a)\s+(?:write|rite|wright)\b",
                re.IGNORECASE), r"\g<slot> right"),
    (re.compile(rf"\b(?P<slot>{_SIDE_SLOT})\s+lift\b", re.IGNORECASE), r"\g<slot> left"),
    # "move for word two feet", "move Ford 3 meters": what a recogniser writes for "forward" right after a verb
    # of motion (where a way is expected; "Ford" or "word" there name nothing the robot could go to)
    (re.compile(r"\b(?P<verb>move|moving|go|going|drive|driving|head|step|roll|advance|proceed|inch|creep|continue|"
                r"keep\s+going|carry\s+on|straight|push|nudge|scoot)\s+(?:for\s+word|foreword|fore\s+word|ford|"
                r"four\s+ward|for\s+ward|fore\s+ward)s?\b", re.IGNORECASE), r"\g<verb> forward"),
    (re.compile(r"\s*\b(?:comma)\b\s*", re.IGNORECASE), ", "),
    # "go forward five feet, wait, metres": "wait" right before a unit alone puts the unit right
    (re.compile(rf"\bwait\s*[,.]\s*(?=(?:no\s*,?\s*)?{_UNIT_WORD}\s*(?:[,.;!?]|$))", re.IGNORECASE), "i mean "),
    (re.compile(r"(?<=[a-z0-9])\s+n\s+(?=[a-z])", re.IGNORECASE), " and "),  # chat "n" between two words
    (re.compile(r"\b(?:thn|thne|hten|tehn)\b", re.IGNORECASE), "then"),  # the connective, before the split
    (re.compile(r"\s*\b(?:period(?!\s+of\b)|full\s+stop|new\s*line|new\s+paragraph|semicolon|question\s+mark|"
                r"exclamation\s+(?:mark|point))\b\s*", re.IGNORECASE), ". "),
)


#: Polite frames around a request: they ask for the request, they are not a question to answer
#: ("is it okay if you back up half a metre?", "would it be possible for you to reverse ...", "may I
#: ask you to ...", "I'd be most grateful if you could ...", "could you possibly ...").
REQUEST_FRAMES: Final = re.compile(
    r"\b(?:(?:is|would|will)\s+it\s+be\s+|is\s+it\s+)(?:ok(?:ay)?|alright|all\s+right|possible|fine|cool)\s+"
    r"(?:(?:for\s+you\s+)?to|if\s+(?:you|u)(?:\s+(?:could|can|would))?)\b"
    r"|\b(?:may|can|could|might)\s+i\s+(?:ask|get|have)\s+(?:you\s+)?to\b"
    r"|\bi(?:'d|\s+would)\s+(?:be\s+)?(?:(?:most|very|really|so|truly|extremely)\s+)?(?:grateful|thankful|happy|glad)"
    r"\s+if\s+(?:you|u)(?:\s+(?:could|would|can))?\b"
    r"|\bi\s+(?:was|am)\s+wondering\s+if\s+(?:you|u)\s+(?:could|would|can)\b"
    r"|\bdo\s+you\s+think\s+(?:you|u)\s+(?:could|can)\b"
    r"|\bwould\s+(?:you|u)\s+(?:be\s+so\s+kind\s+as|be\s+able)\s+to\b"
    r"|\b(?:could|can|would|will)\s+(?:you|u)\s+(?:possibly|perhaps|maybe|please|kindly)\b"
    r"|\bif\s+(?:you|u)\s+(?:do\s+not|don't|dont)\s+mind\b"
    r"|\bif\s+(?:you|u)(?:'d|\s+would|\s+could)\s+be\s+so\s+(?:kind|good)(?:\s+as\s+to)?\b"
    r"|\bif\s+(?:it'?s|it\s+is)\s+not\s+too\s+much\s+(?:bother|trouble)\b"
    # "..., if that's okay": asking leave for the request said (the "that" is the request, no place)
    r"|\bif\s+(?:that'?s|that\s+is|it'?s|it\s+is|this\s+is)\s+(?:ok(?:ay)?|alright|all\s+right|fine|cool|possible|"
    r"good|alright\s+with\s+you)(?:\s+with\s+you)?\b",
    re.IGNORECASE)
#: Remarks around a request that ask or say nothing about the motion: "is that a thing you can do?",
#: "sorry if that's a weird number", "so that I can see the door", "I don't want to crash it": each is
#: taken out with its own words, up to the next mark.
REMARKS: Final = re.compile(
    r"(?:^|(?<=[,.;!?])|\b(?=(?:is|would|will)\s+(?:that|this)\b))\s*(?:(?:is|would|will)\s+(?:that|this|it)\s+(?:be\s+)?"
    r"(?:ok(?:ay)?|alright|possible|fine|doable|a\s+(?:thing|problem)|something|too\s+much)\b[^,.;!?]*"
    r"|sorry\s+if\b[^,.;!?]*|(?:sorry|apologies)\s+(?:about|for)\s+(?:that|this)\b"
    r"|(?:i|we)\s+(?:do\s+not|don't|dont)\s+want\s+(?:you\s+|it\s+)?to\s+(?:crash|hit|bump|collide|smash|run\s+into)\b"
    r"[^,.;!?]*"
    r"|(?:and\s+)?(?:be\s+)?careful\s+not\s+to\s+(?:crash|hit|bump|collide|smash|run\s+into|touch)\b[^,.;!?]*)"
    r"|\bso\s+(?:that\s+)?(?:i|we)\s+(?:can|could|may|might|will)\b[^,.;!?]*"
    # a purpose said of someone else ("so the group can see you", "so that the kids can get past"): why, not where
    # (one with a way in it, "so you can see behind you", says where the robot is to turn, and stays)
    r"|\bso\s+(?:that\s+)?(?!(?:you|u)\b)(?:the\s+|my\s+|our\s+|your\s+|his\s+|her\s+|their\s+)?[a-z]+(?:\s+[a-z]+)?\s+"
    r"(?:can|could|may|might|will|would)\b(?![^,.;!?]*\b(?:behind|left|right|around|round|ahead|north|south|east|west)\b)"
    r"[^,.;!?]*"
    # "... so that you face me": the speaker's own place, which the map cannot know, given as why the robot
    # turns (Nigerian English "make you face me" is read as this first); the turn said is the request
    r"|\bso\s+(?:that\s+)?(?:you|u)\s+(?:can\s+)?(?:face|see|look\s+at)\s+(?:me|us)\b[^,.;!?]*"
    # "please do one thing, ...": announces the request that follows
    r"|(?:^|(?<=[,.;!?]))\s*(?:please\s+)?do\s+one\s+thing\b[^,.;!?]*"
    # thanks said ahead: "..., that would be great", "that'd be awesome"
    r"|\b(?:that|it|this)(?:'d|\s+would|\s+will)\s+be\s+(?:(?:really|very|so|just|super)\s+)?(?:great|nice|good|perfect|"
    r"awesome|helpful|wonderful|lovely|fantastic|brilliant|appreciated|ideal|amazing|cool)\b[^,.;!?]*"
    # checks of the radio link: they ask nothing about the motion ("you're breaking up", "do you copy?")
    r"|\b(?:(?:you'?re|you\s+are|ur)\s+breaking\s+up|you\s+(?:cut|broke)\s+(?:out|up)|"
    r"(?:can|could|did|do)\s+(?:you|u)\s+(?:hear|read)\s+me|(?:can|could|did|do)\s+(?:you|u)\s+(?:copy|read)|"
    r"how\s+(?:do\s+you\s+)?(?:copy|read)|are\s+(?:you|u)\s+(?:there|still\s+there|listening|receiving))\b[^,.;!?]*",
    re.IGNORECASE)
#: "go forward, what, nine and a half feet": "what" said alone before an amount is the speaker estimating it
#: aloud (as "say" or "oh" are), no question.
ESTIMATING_WHAT: Final = re.compile(
    rf"(?<=[,.;])\s*what\s*[,?]+\s*(?=(?:about\s+|around\s+|roughly\s+|maybe\s+|a\s+|an\s+|half\s+)?(?:\d|(?:{NUMBER_WORDS})\b|"
    r"a\s+(?:foot|metre|meter|yard|half|quarter|couple)\b))", re.IGNORECASE)
#: "turn right, not too far": an amount said by what it must not exceed, alone between marks, is a small
#: one ("a little", README: 10-40 degrees or 0.15-0.5 m): the speaker rules out a big motion, so the
#: default (a quarter turn, a metre) would be more than asked.
NOT_TOO_FAR: Final = re.compile(r"(?:^|(?<=[,.;!?]))\s*(?:but\s+|just\s+)?not\s+(?:too|very|that|so)\s+(?:far|much)"
                                r"\s*(?=[,.;!?]|$)", re.IGNORECASE)
#: "sidestep right two feet, keep facing forward", "..., without turning": said after an instruction, how the
#: robot holds its heading while it does it. A move never turns the robot (a sideways move slides), so the
#: words ask for nothing more; they are no turn and no move "forward".
KEEPING_HEADING: Final = re.compile(
    r"(?:(?<=[,.;])|(?<=\s))\s*(?:and\s+|but\s+|while\s+|just\s+)?"
    r"without\s+(?:turning|rotating|spinning|changing\s+(?:your\s+)?(?:heading|direction|orientation))(?:\s+(?:a)?round)?"
    r"\s*(?=[,.;!?]|$)"
    r"|(?<=[,.;])\s*(?:and\s+|but\s+|while\s+|just\s+)?(?:"
    r"(?:keep|keeping|stay|staying|remain|remaining|still)\s+(?:facing|pointed|pointing|looking)\s+(?:forwards?|ahead|"
    r"straight(?:\s+ahead)?|the\s+same\s+way|this\s+way|the\s+way\s+you\s+are)"
    r"|(?:do\s+not|don'?t|no)\s+(?:turn|turning|rotate|rotating)(?:\s+(?:a)?round)?)"
    r"\s*(?=[,.;!?]|$)", re.IGNORECASE)
#: Asides around a request that give no instruction, each taken out with its own words up to the next
#: mark: a reason ("because I think you're close to that wall": why, not where), a comparison of manner
#: ("like you're peeking round a corner", "as if ..."), a comment on the request or the day ("this is
#: important", "this is the bit I was telling Jim about", "bear with me", "it's been a long day"), an
#: explanation of a place ("that's where the exit is"). None names where or how far the robot goes.
ASIDES: Final = re.compile(
    r"(?:^|(?<=[,.;!?])|(?<=\s))\s*(?:"
    r"(?:and\s+|just\s+)?(?:because|'?cause|cos|coz)\b[^,.;!?]*"
    r"|(?:just\s+)?(?:like|as\s+if|as\s+though)\s+(?:you'?re|you\s+are|you\s+were|you'?d|you\s+would)\b[^,.;!?]*"
    r")"
    r"|(?:^|(?<=[,.;!?]))\s*(?:and\s+|but\s+)?(?:"
    r"(?:this|that|it)(?:'s|\s+is)\s+(?:(?:really|very|quite|super|so)\s+)?(?:important|crucial|critical|key|urgent)"
    r"|(?:this|that|it)(?:'s|\s+is)\s+the\s+(?:bit|part|thing)\s+(?:i|we)\s[^,.;!?]*"
    r"|bear\s+with\s+me|it(?:'s|\s+has)\s+been\s+a\s+long\s+(?:day|night|week|shift)\b[^,.;!?]*"
    r"|(?:that|this|it)(?:'s|\s+is)\s+where\s[^,.;!?]*"
    r")\s*(?=[,.;!?]|$)",
    re.IGNORECASE)
#: "go back out the way, one metre back", "move oot o' the way": getting out of someone's way says why the robot
#: moves, not where to or how far (the way and the amount are said beside it, or asked).
OUT_OF_THE_WAY: Final = re.compile(r"\b(?:out|oot)\s+(?:of\s+|o'?\s+)?(?:the|my|our|his|her|their|your|yer)\s+way\b",
                                   re.IGNORECASE)
#: A concession before a request: "this room is lovely but I want you to leave it": what the place is like,
#: said before "but", is a remark; the request follows "but" (and is no name for the place).
CONCESSION: Final = re.compile(
    r"(?:^|(?<=[,.;!?]))\s*(?:and\s+)?(?:this|that|it|the)\s+(?:(?:room|place|hallway|corridor|hall|spot|area|one)\s+)?"
    r"(?:is|'s|was|looks|seems)\s+[^,.;!?]*?\bbut\s+", re.IGNORECASE)
#: A pseudo-cleft: "what I'd (really) like (you to do now) ... is (for you) to face south" asks for what
#: follows "is"; what stands between the two halves is said in passing ("and bear with me", "if you
#: don't mind"), so the whole frame goes and the request stays.
PSEUDO_CLEFT: Final = re.compile(
    r"\bwhat\s+(?:i|we)(?:'d|\s+would|'ll|\s+will)?\s+(?:really\s+|now\s+)?(?:like|want|need|love|prefer)"
    r"(?:\s+(?:you|u)\s+to\s+do)?(?:\s+(?:now|next|here|then))?\b[^.;!?]*?\b(?:is|would\s+be)\s+"
    r"(?:(?:for\s+(?:you|u)\s+)?to|that\s+(?:you|u))\s+",
    re.IGNORECASE)
#: "that" opening a clause said to someone ("I want that you turn", "I think that we should go"): a
#: conjunction, no place; the clause reads the same without it.
THAT_CLAUSE: Final = re.compile(r"\bthat\s+(?=(?:you|u|we|i)\s)", re.IGNORECASE)
#: Words after which a comma is no clause break: the phrase goes on after the pause ("go to the, uh,
#: the first door", "the nearest, um, corner").
_OPEN_WORDS: Final = frozenset({
    "the", "a", "an", "to", "into", "towards", "toward", "through", "of", "your", "my", "our", "at", "by", "near", "past", "between", "nearest", "closest", "farthest", "furthest", "first", "second",
    "third", "fourth", "last", "biggest", "largest", "smallest", "next", "other", "opposite", "along",
})


#: Of those, the words that may also end what is said ("the opposite"): before a verb or a side, the comma after them ends it
#: ("turn left ninety, the opposite, turn right ninety").
_WHOLE_ALONE: Final = frozenset({"opposite", "other"})
_VERBS_ALONE: Final = (frozenset(v for v in (*GO_VERBS, *ROTATE_VERBS) if " " not in v) - {"be", "do", "have", "make"}
                        | {"left", "right"})


#: "stop, but first turn left": what is said after "but first" (or "but before that") is done before what was said
#: ahead of it, as a person would do it; said in that order, the steps run in the order meant.
FIRST_AFTER: Final = re.compile(r"(?P<a>[^.;!?]+?)[,\s]+but\s+(?:first|before\s+(?:that|this|you\s+do\s+that))\s*,?\s+"
                                r"(?P<b>[^.;!?]+)", re.IGNORECASE)


#: A tag question after a statement ("that's two metres, right?", "..., okay?"): it asks for agreement,
#: it names no side. (If the instruction before it misses its side, the reading asks for it.)
TAG_QUESTION: Final = re.compile(r",\s*(?:right|correct|yes|yeah|ok(?:ay)?|yep|no)\s*\?+", re.IGNORECASE)
#: "wait, ..." / "hang on, ..." opening a prompt that goes on: the speaker holds the floor while
#: thinking ("wait, which way is north... okay, face north"); the instruction that follows is the request.
HOLDING_THE_FLOOR: Final = re.compile(r"^\s*(?:(?:oh|um|uh|okay|ok|so)\s*,?\s+)*(?:wait|hold\s+on|hang\s+on|one\s+sec(?:ond)?)"
                                      r"\s*(?:[,.!]+|\.\.\.)\s*(?=\S)", re.IGNORECASE)
#: Words that announce an instruction said again ("turn left, I say again, turn left forty five degrees"):
#: what follows restates what came before, with more detail or none; the marker goes and the two
#: instructions meet, so that the restatement is read once. ("Again" or "repeat" alone ask to do it
#: again, and are no such marker.)
RESTATEMENT_MARKERS: Final = re.compile(
    r"[,.;]?\s*\b(?:i\s+say\s+again|say\s+again|i\s+repeat|let\s+me\s+repeat(?:\s+that)?|(?:like|as)\s+i\s+said|"
    r"in\s+other\s+words|that\s+is\s+to\s+say|once\s+again\s+i\s+say)\b\s*[,.;:]?"
    # "... Again: move forward 2 m" / "again, turn left": "again" opening what is said once more (said after
    # it, "turn left again", or alone, "... again.", it asks for the motion once more)
    r"|(?:^|(?<=[.;!?]))\s*(?:(?:and|so|ok(?:ay)?)\s+)?(?:once\s+)?again\s*[:,;-]\s*(?=[a-z])", re.IGNORECASE)
#: Radio procedure words, said alone between commas (people who drive robots often talk as on a radio):
#: "negative" is no (a correction or a refusal, never the "negative" = clockwise of a turn), "affirmative",
#: "roger", "copy (that)", "wilco" acknowledge, "over" / "over and out" end the message.
RADIO_NO: Final = re.compile(r"(?:^|(?<=[,.;!?]))\s*negative(?:\s+on\s+that)?(?:\s+(?:robot|rover|bot|base))?\s*(?=[,.;!?]|$)",
                            re.IGNORECASE)
#: "No" in another language said alone between commas, once or again ("turn left forty, hayir, fifty degrees";
#: "turn left, nahi nahi, right side forty five"): "no", which corrects what it follows, as in English.
FOREIGN_NO: Final = re.compile(rf"(?:^|(?<=[,.;!?]))\s*(?:{'|'.join(sorted(FOREIGN_NO_WORDS))})(?:[\s,]+(?:{'|'.join(sorted(FOREIGN_NO_WORDS))}))*"
                               r"\s*(?=[,.;!?]|$)", re.IGNORECASE)
#: "A little" and "more" said in another language (``lexicon.FOREIGN_AMOUNTS``): read as the English words (not
#: after an article: "the konti" names a thing, which the reading asks about).
FOREIGN_AMOUNT: Final = re.compile(
    r"(?<!\bthe\s)(?<!\ba\s)(?<!\ban\s)(?<!\bthis\s)(?<!\bthat\s)\b(?:" + "|".join(re.escape(w).replace(r"\ ", r"\s+") for w in sorted(FOREIGN_AMOUNTS, key=len, reverse=True))
    + r")\b", re.IGNORECASE)
#: A radio call opening a message names who is called and who calls ("base to robot, ...", "robot, this is
#: base, ..."): no instruction.
_STATION: Final = r"(?:robot|rover|bot|unit|base|command|control|operator|team|hq|headquarters|scout)"
#: A station's call sign said alone to open the message ("unit one, advance ...", "rover two, ..."): it names
#: who is called (the robot), as "robot, ..." does; its number counts no amount.
RADIO_CALL: Final = re.compile(rf"^\s*(?:{_STATION}\s+to\s+{_STATION}|{_STATION},?\s+this\s+is\s+{_STATION}|"
                               rf"{_STATION}\s+(?:number\s+)?(?:\d{{1,2}}|one|two|three|four|five|six|seven|eight|nine|ten|"
                               r"alpha|bravo|charlie|delta|echo))\s*(?=[,.;!?]|$)",
                               re.IGNORECASE)
#: A stage manager's cue call ("cue seven go, turn right", "cue three, back up one metre, go", "standby cue
#: four"): the cue's number or letter names which cue is called and counts no amount; the "go" said with it (or
#: alone after the instruction, which the reading already drops) is the call to carry the instruction out.
CUE_CALL: Final = re.compile(
    rf"(?:^|(?<=[,.;!?]))\s*(?:(?:stand\s*by|standby)\s+(?:for\s+)?)?(?:(?:lx|lights?|lighting|sound|sq|lq|fly|deck)\s+)?"
    rf"cue\s+(?:number\s+)?(?:\d+(?:\.\d+)?[a-z]?|(?:{NUMBER_WORDS})(?:[\s-]+(?:{NUMBER_WORDS}))?|[a-z])(?:\s*,?\s+go)?"
    r"\s*(?=[,.;!?]|$)", re.IGNORECASE)
#: "Stand by" opening what follows ("stand by, ... go"): the call to get ready for the instruction said next, no
#: instruction of its own (said alone, it is left to the reading).
STAND_BY: Final = re.compile(r"^\s*(?:stand\s*by|standby)\s*[,.;:!]+\s*(?=\S)", re.IGNORECASE)
#: "... and announce when there", "let me know once you arrive": a request to report the arrival, which the
#: robot's result reports; "there" is where the instruction before it ends, no place of its own.
ARRIVAL_REPORT: Final = re.compile(
    r"\s*[,;]?\s*(?:and\s+)?(?:then\s+)?(?:announce(?:\s+it)?|report(?:\s+back)?|tell\s+(?:me|us)|let\s+(?:me|us)\s+know|"
    r"say\s+so|call\s+out|shout|beep|signal|ping\s+(?:me|us))\s+(?:when|once|as\s+soon\s+as)\s+"
    r"(?:(?:you\s+)?(?:are|'re|get|have\s+got|arrive|reach)\s+)?(?:there|arrived|you\s+arrive)\b", re.IGNORECASE)
#: (North American radio's "ten-four", "10-4" is "understood", as "roger" is.)
RADIO_NOISE: Final = re.compile(r"(?:^|(?<=[,.;!?]))\s*(?:affirmative|roger(?:\s+that)?|copy(?:\s+that)?|wilco|that\s+is|i\.?e|"
                                r"ten\s*-?\s*four|10\s*-\s*4|"
                                r"over(?:\s+and\s+out)?|out)\s*(?=[,.;!?]|$)", re.IGNORECASE)
#: A number started and said again whole ("four, four and a half metres", "twenty, twenty feet"): the
#: first try is no amount of its own.
#: (The restart may follow a pause, a trailing "and a" or a "point" left unfinished: "eleven ... eleven feet",
#: "seven and a ... seven and a half feet", "one point, one point five metres".)
NUMBER_RESTART: Final = re.compile(
    rf"\b(?P<num>\d+(?:\.\d+)?|a\s+hundred|one\s+hundred|(?:{NUMBER_WORDS})(?:\s+point(?:\s+(?:{NUMBER_WORDS}|zero|oh))+)?)(?:\s+(?:and(?:\s+a)?|point)(?=\s*(?:,|\.\.|…)))?"
    r"(?:\s*(?:,|\.{2,}|…))*\s+(?=(?P=num)\b(?![/.]\d))", re.IGNORECASE)
#: Words that name one of several alternatives a speaker may set against each other: sides, ways, compass
#: points, units and numbers.
_ALTERNATIVE: Final = (rf"(?:(?:to\s+(?:the|your)\s+)?(?:{TURN_SIDE_WORDS}|forwards?|backwards?|back|north|south|east|west|north\s*east|north\s*west|south\s*east|south\s*west|"
                       rf"feet|foot|inch(?:es)?|yards?|met(?:er|re)s?|centimet(?:er|re)s?|degrees?|\d+(?:\.\d+)?|"
                       rf"{NUMBER_WORDS}))")
#: A contrast that names what is not meant ("turn left, not right"; "three feet not four"; "not left but
#: right"; "not right, left", "not right, i mean left"): the alternative said with "not" is no instruction,
#: only the other one is (and the clause is no negation of the whole instruction).
CONTRAST_AFTER: Final = re.compile(rf"\b(?P<said>{_ALTERNATIVE})\s*,?\s+(?:and\s+|but\s+)?not\s+(?P<other>{_ALTERNATIVE})\b"
                                   r"(?!\s+(?:but|rather)\b)", re.IGNORECASE)
#: The kinds of alternative a contrast sets against each other.
_SIDE_ALTERNATIVE: Final = re.compile(rf"(?:to\s+(?:the|your)\s+)?(?:{TURN_SIDE_WORDS})$", re.IGNORECASE)
_UNIT_ALTERNATIVE: Final = re.compile(r"(?:feet|foot|inch(?:es)?|yards?|met(?:er|re)s?|centimet(?:er|re)s?|degrees?)$",
                                      re.IGNORECASE)


def _alternative_kind(word: str) -> str:
    if _SIDE_ALTERNATIVE.match(word):
        return "side"
    if _UNIT_ALTERNATIVE.match(word) or re.match(rf"(?:\d+(?:\.\d+)?|{NUMBER_WORDS})$", word, re.IGNORECASE):
        return "amount"  # ("thirty degrees not forty": the unit ends the amount set against the number)
    return "way"


def _contrast_after(m: re.Match[str]) -> str:
    """"turn left, not right", "three feet not four": the alternative said with "not" is set against the one just
    said, of the same kind and another one; "turn left ninety, not left" sets nothing against "ninety": the "not"
    takes the side said before back, and stays to be read (it asks, or a correction follows)."""
    said, other = m.group("said"), m.group("other")
    if _alternative_kind(said) != _alternative_kind(other) or said.lower() == other.lower():
        return m.group(0)
    return said
CONTRAST_BEFORE: Final = re.compile(rf"\bnot\s+{_ALTERNATIVE}\s*(?:,?\s+(?:but|rather)\s+(?=\S)|,\s*(?:i\s+mean\s+)?"
                                    rf"(?={_ALTERNATIVE}\s*(?:[,.;!?]|$)))", re.IGNORECASE)
#: "go forward and stop after two metres": the amount is how far the move goes (a stop after a place,
#: "stop after the door", is read where places are).
STOP_AFTER_AMOUNT: Final = re.compile(rf"\s*,?\s+(?:and\s+)?stop\s+after\s+(?=(?:\d|a\b|an\b|half\b|(?:{NUMBER_WORDS})\b))",
                                      re.IGNORECASE)
#: "twenty feet even", "two metres flat", "ninety degrees exactly": the amount, exactly (no word of its own).
_UNIT_THEN_EXACT: Final = re.compile(
    r"\b(?P<unit>feet|foot|ft|inch(?:es)?|yards?|met(?:er|re)s?|centimet(?:er|re)s?|cm|degrees?)\s+"
    r"(?:even|flat|exactly|precisely|on\s+the\s+(?:nose|dot))\b", re.IGNORECASE)
#: Numbers that count the instructions of a list ("Step one, turn left. Step two, go forward"; "1) turn
#: left 2) go forward"; "number three: stop"): they order the list, they are no amount.
#: (A number followed by a unit or by more number words is an amount, not a list item: "step two feet to the
#: left" is a step of two feet, "point five metres" is half a metre.)
ENUMERATION: Final = re.compile(
    rf"(?:^|(?<=[.;!?,:\n]))\s*(?:(?:step|number|no|item|part|instruction|command|point)\s+(?:{NUMBER_WORDS}|"
    r"\d{1,2})\b(?!\s+(?:(?:and\s+)?(?:a\s+)?(?:half|quarter)|point|" + "|".join(NUMBER_WORD_LIST) + r")\b)"
    r"(?!\s*(?:more\s+|further\s+|extra\s+)?(?:feet|foot|ft|inch(?:es)?|in|yards?|yd|met(?:er|re)s?|m|cm|mm|"
    r"centimet(?:er|re)s?|millimet(?:er|re)s?|degrees?|deg)\b)"
    r"|\(?\d{1,2}\s*[).](?!\d))\s*[,:.)-]?(?=\s)",
    re.IGNORECASE)
#: "1) turn left 2) go forward": a number closed by a bracket marks a list item wherever it stands.
LIST_ITEM: Final = re.compile(r"(?:^|(?<=\s))\(?\d{1,2}\)(?=\s)")


#: Words English speakers open an utterance with to take the floor or mark a new stage of the talk
#: ("right, stop there"; "right then, could you go forward"; "okay, so, ..."; "well now, ..."): discourse
#: markers, which mean nothing about the motion. "Then" and "so" join them only right after another.
_MARKER_WORD: Final = (r"(?:right|ok(?:ay)?|alright|all\s+right|well|so|now|good|great|fine|lovely|cheers|yes|yeah|oh|um|uh|"
                       r"anyway|anyhow|after\s+all\s+that|(?:with\s+)?(?:all\s+)?that\s+said|having\s+said\s+that)")
#: A run of discourse markers opening the utterance: each said with a pause after it (a mark), or
#: followed by another ("right then, ...", "right so, ...", "okay now, ...").
_OPENING_MARKERS: Final = re.compile(
    rf"^\s*(?:{_MARKER_WORD}(?:\s*(?:[,;:!-]+|\.+)\s*|\s+(?=(?:{_MARKER_WORD}|then)\b)|\s+(?=(?:then|so)\s*[,;:!-])))*"
    rf"(?:(?:{_MARKER_WORD}|then)(?:\s*(?:[,;:!-]+|\.+))|(?<=\s)(?:so|now)\s+(?=\S))", re.IGNORECASE)
#: What "right" completes when it is a direction: an amount, a unit, a way, or a sequence going on from
#: it ("right, ninety degrees", "right, a little", "right, then forward two feet", "right. forward").
#: ("Back up / off / out / away" is a verb of its own, an instruction: "right, back up a metre" opens with the
#: marker, as "right, stop there" does.)
_COMPLETES_A_SIDE: Final = re.compile(
    rf"^\s*(?:$|(?:about|around|roughly|approximately|maybe|like|just|only|some|by|another|and|then|after|to\s+(?:the|your)|"
    r"a\s+(?:little|bit|tad|touch|quarter|half|few|couple|hundred)|half|quarter|full|degrees?|deg|feet|foot|met(?:er|re)s?|"
    r"forwards?|backwards?|back(?!\s+(?:up|off|out|away)\b)|ahead|straight|left|right|around|round|clockwise|counter\s*clockwise|anti\s*clockwise|"
    rf"(?:north|south|east|west)\w*|hand|side|turn\b(?=\s*(?:$|[,.;!?])))\b|\d|(?:{NUMBER_WORDS})\b)", re.IGNORECASE)
_RIGHT: Final = re.compile(r"\bright\b", re.IGNORECASE)
#: "Right then," and "right so," with a pause after them open an utterance in British and Irish English ("right
#: then, straight on, thirty feet"): whatever follows, they are no side (a turn said that way runs on with no
#: pause: "right then forward two feet").
_OPENER_PHRASE: Final = re.compile(r"^\s*(?:(?:ok(?:ay)?|well|so|now|oh)\s*,?\s+)*right\s+(?:then|so|now)\s*[,;:!.-]",
                                   re.IGNORECASE)


def without_discourse_markers(text: str) -> str:
    """``text`` without the discourse markers that open it, when one of them is "right" and what follows is
    an instruction of its own ("right then, could you go forward two metres"; "right, stop there"; "right, so,
    what I'd like is ..."): that "right" says the speaker is moving on (as "okay" does), not which way to turn.
    "Right" followed by what a side completes is a direction ("right, ninety degrees"; "right then forward two
    feet"). A turn with no side of its own after the marker ("right, turn ninety degrees") is left without one:
    the reading asks which way instead of guessing from a word that was most likely no direction.
    Only a run holding "right" is touched: the other markers are no direction and are read as fillers anyway."""
    m = _OPENING_MARKERS.match(text)
    if m is None or _RIGHT.search(m.group(0)) is None:
        return text
    rest = text[m.end():]
    if _COMPLETES_A_SIDE.match(rest) and not _OPENER_PHRASE.match(m.group(0)):
        return text
    return rest.lstrip()


#: Letters of other alphabets that carry no accent to drop but are written as a plain letter when typed without
#: them (Turkish dotless "ı", Polish "ł", Vietnamese "đ", Nordic "ø").
_PLAIN_LETTER: Final = str.maketrans({"ı": "i", "ł": "l", "Ł": "L", "đ": "d", "Đ": "D", "ø": "o", "Ø": "O"})


def plain_letters(text: str) -> str:
    """``text`` with the accents dropped from its letters ("atrás", "yavaş", "chút xíu", "hayır"): people type the
    words of other languages with and without them, and the reading knows them without ("atras", "hayir"). Only
    accents go (canonical decomposition, combining marks dropped): "½", "°" and every other sign stay."""
    decomposed = unicodedata.normalize("NFD", text.translate(_PLAIN_LETTER))
    return "".join(c for c in decomposed if unicodedata.category(c) != "Mn")


def plain_speech(prompt: str) -> str:
    """``prompt`` with hesitations, hedges, cut-off words, stutters and noise tokens removed, a comma
    before each self-correction marker, the words speech recognition mistook put right, and polite
    frames and side remarks taken out."""
    for pattern, spelled in ELIDED:
        prompt = pattern.sub(spelled, prompt)
    text = without_discourse_markers(without_side_talk(STAMMER.sub(_unstammer, prompt)))
    text = REPORTED_QUESTION.sub(" ", REPORTED.sub(_relay, text))
    for pattern, repl in PIDGIN:
        text = pattern.sub(repl, text)
    for pattern, repl in HOMOPHONES:
        text = pattern.sub(repl, text)
    text = LIST_ITEM.sub(". ", ENUMERATION.sub(" ", text))
    text = HOLDING_THE_FLOOR.sub("", TAG_QUESTION.sub(".", text))
    text = RESTATEMENT_MARKERS.sub(", ", text)
    text = CONTRAST_AFTER.sub(_contrast_after, CONTRAST_BEFORE.sub("", text))
    text = STOP_AFTER_AMOUNT.sub(" ", text)
    text = RADIO_NOISE.sub(" ", RADIO_NO.sub(" no", FOREIGN_NO.sub(" no", RADIO_CALL.sub(" ", text))))
    text = FOREIGN_AMOUNT.sub(lambda m: f" {FOREIGN_AMOUNTS[' '.join(m.group(0).lower().split())]} ", text)
    text = ARRIVAL_REPORT.sub("", STAND_BY.sub("", CUE_CALL.sub(" ", text)))
    text = _UNIT_THEN_EXACT.sub(r"\g<unit>", NUMBER_RESTART.sub("", text))
    text = FIRST_AFTER.sub(r"\g<b>, then \g<a>", text)
    text = REQUEST_FRAMES.sub(" ", PSEUDO_CLEFT.sub(" ", text))
    text = THAT_CLAUSE.sub("", REMARKS.sub(" ", ASIDES.sub(" ", CONCESSION.sub(" ", text))))
    text = NOT_TOO_FAR.sub(" a little", KEEPING_HEADING.sub(" ", ESTIMATING_WHAT.sub(" ", text)))
    text = OUT_OF_THE_WAY.sub(" ", text)
    text = _ABANDONED.sub(_drop_abandoned, text)
    kept_cuts = {m.start() for m in _unfinished(text)}  # kept: the reading must ask about them
    text = _CUT_OFF.sub(lambda m: m.group(0) if m.start() in kept_cuts else " ", text)
    text = _HEDGES.sub(" ", text)
    text = _RESTART.sub("", text)
    tokens = _WORD.findall(text)
    kept: list[str] = []
    for i, token in enumerate(tokens):
        bare = token.lower().strip(",.;:!?\"'")
        punct = token[len(token.rstrip(",.;:!?")):]
        after_number = bool(kept) and _NUMBER_WORD.match(kept[-1].lower()) is not None
        # chat spellings ("fwd", "rt") are words, not noise
        if bare in HESITATIONS or bare in PARTICLES or (_NOISE.match(bare) and bare not in VOCABULARY and bare not in TYPOS
                                   and not _typed_direction(bare)) \
                or (bare in _UNIT_SOUNDS and not after_number):
            _carry(kept, punct)
            continue
        nxt = tokens[i + 1].lower().strip(",.;:!?\"'") if i + 1 < len(tokens) else ""
        if bare.isalpha() and not punct and nxt.startswith(bare) and len(bare) < len(nxt) \
                and bare not in VOCABULARY:
            continue  # "tur turn", "l left": a false start of the next word
        if bare.isalpha() and not punct and bare == nxt and bare not in _REPEATABLE:
            continue  # "a a left", "the the door": a stutter
        kept.append(token)
    for i in range(len(kept) - 1):
        word = kept[i].lower()
        if word.endswith(",") and word.rstrip(",") in _OPEN_WORDS \
                and not (word.rstrip(",") in _WHOLE_ALONE and kept[i + 1].lower() in _VERBS_ALONE):
            kept[i] = kept[i].rstrip(",")  # "the, uh, the first door": one phrase
    kept = [t for i, t in enumerate(kept) if not (i + 1 < len(kept) and t.lower() in _OPEN_WORDS
                                                  and t.lower() == kept[i + 1].lower().strip(",.;:!?"))]
    text = NUMBER_RESTART.sub("", " ".join(kept))  # "three, uh, three feet": the restart seen once "uh" is gone
    return _MARKER_INSIDE.sub(_break_before_marker, text)


#: A stretch of speech that ends in a cut-off word ("and take another ph-", "send me a phot-"): the
#: speaker gave it up.
_ABANDONED: Final = re.compile(r"(?:(?<=[,.;!?])|^)(?P<part>[^,.;!?]*?[a-z]+-)(?=\s*(?:[,.;!?]|$))", re.IGNORECASE)


def _drop_abandoned(m: re.Match[str]) -> str:
    """A stretch given up with no word of where or how far in it is dropped whole ("take another ph-"
    asks for nothing); one with such words keeps them, cut-off word removed, so that the reading sees
    them (and asks if they make no instruction)."""
    from langnav.language.offline.ask import spatial  # the ask stage's words of where and how far

    part = m.group("part")
    words = _CUT_OFF.sub(" ", part)
    return part if spatial(words) or _RESTART_WORDS.search(words) else " "


#: An instruction verb in a stretch that was cut off keeps it ("move six- six metres"): only a
#: stretch that asks for nothing the robot does is dropped.
_RESTART_WORDS: Final = re.compile(r"\b(?:move|go|turn|rotate|drive|back|face|head|spin|stop|reverse)\b", re.IGNORECASE)


#: Number words a cut-off word may be the start of ("fi-" of five, fifteen or fifty).
_NUMBER_WORDS: Final = NUMBER_WORD_LIST
#: A cut-off word of this many letters may be the start of many words ("t-", "f-"): only after a
#: number is it surely one.
MIN_NUMBER_PREFIX: Final = 2
_CUT_TOKEN: Final = re.compile(r"(?<![\w-])(?P<cut>[a-z]+)-(?=[\s,.;!?]|$)", re.IGNORECASE)
_NUMBER_BEFORE: Final = re.compile(r"(?:\d|\b(?:" + "|".join(_NUMBER_WORDS) + r"))\s*$", re.IGNORECASE)
_NUMBER_AFTER: Final = re.compile(r"^\W*(?:\S+\W+){0,5}?(?:\d|(?:" + "|".join(_NUMBER_WORDS) + r")\b)",
                                  re.IGNORECASE)
#: Number words that begin other words a speaker may cut off ("fo-" of forward, "te-" of ten or of
#: "tell"): such a start is a number only right after another number.
_OTHER_STARTS: Final = ("forward", "forwards", "feet", "foot", "turn", "to", "towards", "the", "then", "there", "this",
                        "that", "three", "sixty", "seven", "eight", "nine", "tell", "take", "tiny", "first",
                        "on", "one", "onto", "around", "all", "and", "now", "north", "south", "east", "west",
                        "each", "exactly", "front", "face", "half", "head", "here", "hundred", "say", "send", "side",
                        "step", "stop", "straight", "see")


def unfinished_number(text: str) -> str | None:
    """A number the speaker cut off and did not say again ("turn left forty fi-": forty-five? fifty?),
    with the words before it, or None. The amount is not known, so the robot must ask: reading "forty"
    would turn the wrong amount, dropping it would guess one. A cut-off word is a number's start when
    it follows a number ("forty fi-", "one hun-") or, said alone, when it can only start a number word
    ("thir-", "fif-"); said again with a number right after ("forty fi- forty five degrees") it was
    only a restart. (``plain_speech`` keeps such a word, so that a correction may still take it back:
    "go two t-, never mind, go three feet".)"""
    for m in _unfinished(text):
        before = re.search(r"(?:\S+\s+){0,2}$", text[:m.start()])
        return f"{before.group(0) if before else ''}{m.group(0)}".strip()
    return None


def _unfinished(text: str) -> list[re.Match[str]]:
    found: list[re.Match[str]] = []
    for m in _CUT_TOKEN.finditer(text):
        cut = m.group("cut").lower()
        if not any(w.startswith(cut) for w in _NUMBER_WORDS):
            continue
        after_number = _NUMBER_BEFORE.search(text[:m.start()]) is not None
        only_number = len(cut) >= MIN_NUMBER_PREFIX and not any(
            w.startswith(cut) for w in _OTHER_STARTS if w not in _NUMBER_WORDS)
        if (after_number or only_number) and _NUMBER_AFTER.search(text[m.end():]) is None:
            found.append(m)
    return found


def _break_before_marker(m: re.Match[str]) -> str:
    before = m.group("before")
    if before.lower().strip(",.;:!?") in _MARKER_LEAD or before.endswith(tuple(",.;:!?")):
        return m.group(0)
    return f"{before}, "


#: Words that may be said twice on purpose ("turn left, left": no; "very very slowly": harmless).
_REPEATABLE: Final = frozenset({"very", "no", "right"})  # "turn right right now": a side, then "right now"


#: Directions people type by their consonants ("face sth", "nrth", "trn lft"): such a run is a word, not a sound.
_DIRECTION_WORDS: Final = frozenset({"north", "south", "east", "west", "left", "right", "forward", "back"})


def _typed_direction(token: str) -> bool:
    """A consonant run that is a direction typed without its vowels ("sth" is south, "lft" left)."""
    from langnav.language.offline.normalize import (
        skeleton_word,  # normalize reads the vocabulary this module feeds
    )

    return skeleton_word(token) in _DIRECTION_WORDS


def _carry(kept: list[str], punct: str) -> None:
    """A dropped token's comma stays with the word before it ("turn, uh, left")."""
    if punct and kept and not kept[-1].endswith(tuple(",.;:!?")):
        kept[-1] += punct
