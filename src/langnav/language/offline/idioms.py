"""Spoken motion idioms rewritten to the plain words they mean, before a clause is read (issue 9:
"speech as it comes"). Each rule is a fact about how English speakers talk to something they drive,
with its reason; none names a case. The text is lower-case and single-spaced (``normalize``).

* **Informal verbs of going.** Speakers drive with any verb of self-motion: "push forward five
  metres", "press on two feet", "mosey ahead a yard". A verb that takes a thing as its object
  ("push the box") is a request to move that thing and stays out of scope; followed by a way or an
  amount it is the robot going, and reads as "move".
* **Informal verbs of turning.** "Swing left", "whip around", "bank right", "hook left", "kick it
  around": a verb of swinging a vehicle, followed by a side or "around", is a turn to that side.
* **The driver's "it".** Drivers call the vehicle "it" ("back it up", "bring it around", "swing it
  left"): "it" between a motion verb and a way is the robot, never a place to go to.
* **Turns as things one does.** "Hit a three sixty", "pull a u-turn", "throw a left", "bust a one
  eighty": a light verb with a turn as its object is that turn (not a collision: "hit a wall" is no
  turn, and the unsafe check still sees it).
* **"A one-eighty", "a three-sixty".** English names a half and a full turn by their degrees, as
  nouns: said alone ("180 then push three metres forward", "kick it around, one eighty"), the number
  is that turn, never 180 metres.
* **"Give me" an amount.** "Give me two more feet", "give me ninety degrees to the left": the amount
  asked of the robot is the motion (moves and turns are told apart by the unit, as everywhere).
* **Stopping idioms with a dummy subject or object.** "Hold it (right there)", "that will do": the
  "it" and "that" point at nothing; the phrase means stop.
* **"Right round".** "Spin yourself right around", "turn right round": "right" before "around" means
  "all the way" (as in "right through"), not a side, unless a place follows ("right round the corner").
* **Amounts by name.** "Proceed south, distance eight metres", "angle forty five": the word that names
  the amount before it is no instruction of its own.
* **Praise of a turn.** "A proper left turn", "a nice clean one eighty": the adjective says how well the
  turn is done, not which way or how far.
* **Learner grammar.** The article dropped ("make turn on left"): "make / do / take turn" is a turn.
* **"Give it a turn".** "Give it a little turn to the left", "give yourself a small bit of a turn": the
  driver's "it" with a light verb; the turn is the motion, "little / small bit of a" its size.
* **"Small" as an adverb.** Nigerian and West African English (and Pidgin) say "reverse small", "go front
  small small" for a little: "small" right after a verb or a way, ending the instruction, is "a little".
* **Drill orders.** "Right face", "left, face": a quarter turn to that side ("about face" is the lexicon's
  half turn); "face" after a side with nothing after it is the drill order, not a facing.
* **The way of the speaker's setting.** "Go up the row", "down the aisle", "along the lane": a row, an aisle,
  a lane, a track is a line the speaker stands in, which no occupancy grid names; going up or down it is
  going ahead (how far is said, or asked). A hallway or corridor is a place the map knows, and not this.
* **Vague "there".** "Go on ahead there two metres", "reverse back there a metre": "there" between a way
  and an amount points at nothing (the amount says how far).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Final

from langnav.language.offline.numbers import NUMBER

#: What may follow a verb of going for it to be the robot going: a way, or an amount.
_AMOUNT: Final = (r"(?:another|a\s+(?:bit|little|tad|touch|skosh|few|couple|further|foot|metre|meter|yard|step)|"
                  rf"(?:about\s+|around\s+|roughly\s+|some\s+)?(?:{NUMBER})\b)")
#: A way said with no object after it ("push back the chair" moves the chair), or "up / on / down /
#: along" followed by an amount or nothing ("push on", "push up one metre"; not "push on the door").
_WAY: Final = (r"(?:(?:forwards?|ahead|onwards?|straight|back(?:wards?)?|left|right|sideways|further|farther)\b"
               r"(?!\s+(?:the|this|that|these|those|it|them|my|his|her|their)\b)"
               rf"|(?:up|on|down|along)\b(?=\s+{_AMOUNT}|\s*$)|{_AMOUNT})")
#: Verbs that, said of a vehicle with no object, mean it goes ("push on", "scoot over two feet"). ("Inch"
#: is left to the lexicon, which reads it as a verb only where it is no unit: "a quarter inch forward".)
INFORMAL_GO_VERBS: Final = ("push", "press", "mosey", "trundle", "glide", "drift", "scuttle", "scurry", "crawl",
                            "sneak", "tiptoe", "jog", "amble", "stroll", "march", "trot", "toddle", "pootle",
                            "zoom", "coast", "motor", "wheel", "scoot", "creep", "nudge", "shuffle",
                            "roll", "zip", "cruise", "hop", "edge", "ease", "bump", "scooch", "scootch", "drop")
#: Verbs of swinging a vehicle round: followed by a side or "around" they are a turn.
#: ("Bear left" is no such verb: it means keep to the left, a slight turn of no known amount.)
INFORMAL_TURN_VERBS: Final = ("swing", "whip", "bank", "hook", "kick", "flip", "crank", "wheel", "cut", "swerve",
                              "slew", "bring", "haul", "yank", "jerk")
#: Verbs after which "it" is the vehicle (the turn verbs the lexicon knows, and the informal ones).
#: ("inch it forward": "inch" is a verb there, and the unit only after a number)
_DRIVER_VERBS: Final = (*INFORMAL_GO_VERBS, *INFORMAL_TURN_VERBS, "back", "move", "drive", "pull", "turn", "rotate",
                        "spin", "swivel", "pivot", "twist", "steer", "inch")
#: A side or "around" after a turn verb.
_TURN_SIDE: Final = (r"(?:hard\s+|sharp\s+|quickly\s+|slightly\s+|a\s+bit\s+|a\s+little\s+)?(?:to\s+(?:the|your)\s+)?"
                     r"(?:left|right|around|round|about|clockwise|counter\s*clockwise|anti\s*clockwise)\b")
#: Light verbs that take a turn as their object ("hit a left", "pull a u-turn").
_TURN_LIGHT_VERBS: Final = r"(?:hit|pull|throw|bust|chuck|bang|whip|hook|swing|cut|rip|hang|do|make|perform|execute|take|try)"
#: Turns named as things: a side, a u-turn, or a half or full turn by its degrees.
_NAMED_TURN: Final = (r"(?P<named>(?:quick\s+|fast\s+|sharp\s+|hard\s+|little\s+|full\s+|complete\s+|whole\s+|slow\s+|"
                      r"gentle\s+|careful\s+|smooth\s+|steady\s+|lazy\s+|nice\s+)?"
                      r"(?:(?P<side>left|right)|(?P<u>u\s*turn|u\s*ey|u\s*ie|yooie|uey|youey)|(?P<half>one\s+eighty|180)"
                      r"|(?P<full>three\s+sixty|360)))\b(?!\s*(?:degrees?|deg|turns?|spins?))")

def _named_turn(m: re.Match[str]) -> str:
    if m.group("side"):
        return f"take a {m.group('side')}"
    if m.group("u"):
        return "turn around"
    return "turn 180 degrees" if m.group("half") else "turn 360 degrees"


#: What a rule writes: the plain words, or a function of what was said.
Replacement = str | Callable[[re.Match[str]], str]

_IDIOMS: Final[tuple[tuple[re.Pattern[str], Replacement], ...]] = (
    # "hold it right there", "that will do": stop (no place is meant by "it" or "that")
    (re.compile(r"\b(?:hold\s+it(?:\s+(?:right\s+)?(?:there|here))?|that\s+will\s+do)\b"), "stop"),
    # the driver's "it": "back it up", "bring it around", "swing it left"
    (re.compile(rf"\b(?P<verb>{'|'.join(_DRIVER_VERBS)})"
                r"\s+(?:it|her|yourself|the\s+robot)\s+(?=(?:up|back|forwards?|ahead|left|right|around|round|over)\b)"),
     r"\g<verb> "),
    # "hit a three sixty", "pull a u-turn", "throw a quick left"
    (re.compile(rf"\b{_TURN_LIGHT_VERBS}\s+(?:a|an|another|one)\s+{_NAMED_TURN}"), _named_turn),
    # "swing left", "whip around", "bank hard right"
    (re.compile(rf"\b(?:{'|'.join(INFORMAL_TURN_VERBS)})\s+(?={_TURN_SIDE})"), "turn "),
    # "turn hard left", "veer sharp right": how firmly, not how far (the amount is said elsewhere or asked)
    (re.compile(r"\b(?P<v>turn|rotate|veer|steer|pivot|spin|swivel)\s+(?:hard|sharp|quickly|fast)\s+"
                r"(?=(?:to\s+(?:the|your)\s+)?(?:left|right)\b)"), r"\g<v> "),
    # "give me two more feet", "give us ninety degrees left"
    (re.compile(rf"\bgive\s+(?:me|us)\s+(?=(?:another\s+|a\s+further\s+|an\s+extra\s+)?(?:{NUMBER}|a|an|half)\s+"
                r"(?:(?:more|further|extra)\s+)?(?:and\s+a\s+half\s+)?(?:feet|foot|ft|inch|inches|yards?|met(?:er|re)s?|"
                r"cm|centimet(?:er|re)s?|degrees?|deg)\b)"), "move "),
    # "go along five feet", "move along two metres": "along" with no object is onward, the way the robot faces
    (re.compile(rf"\b(?P<v>go|move|head|drive|walk|come|keep\s+going|carry\s+on)\s+along\s+(?={_AMOUNT})"),
     r"\g<v> forward "),
    # "push forward", "press on two feet", "mosey ahead": a verb of going with no object
    (re.compile(rf"\b(?:{'|'.join(INFORMAL_GO_VERBS)})(?:\s+(?:on|onwards?|along))?\s+(?={_WAY})"), "move "),
    # "spin yourself right around", "turn right round": "right" before "around" is the intensifier "all the
    # way" (as in "right through", "right back"), not a side; a place after it ("right round the corner")
    # keeps the side
    (re.compile(r"\b(?P<v>turn|spin|rotate|swing|swivel|pivot|twirl|whirl|wheel|come)(?P<obj>\s+(?:yourself|itself|her|it))?"
                r"\s+right\s+(?:a)?round\b(?!\s+(?:the|a|an|this|that|it|to|towards?)\b)"), r"\g<v> all the way around"),
    # "proceed south, distance eight metres", "turn left, angle forty five": the name of the amount said
    # before it (formal radio and report phrasing) is no word of its own
    (re.compile(rf"\b(?:(?:for|at|by)\s+)?(?:a\s+|the\s+)?(?:distance|range|angle|amount)(?:\s+of)?\s*:?\s+"
                rf"(?=(?:about\s+|around\s+|roughly\s+|approximately\s+)?(?:{NUMBER})\b)"), ""),
    # "a proper left turn", "a nice clean one eighty": words that praise a turn say nothing of its side or size
    (re.compile(r"\b(?:(?:proper|real|nice|clean|normal|regular|standard|decent|good|neat|tidy)\s+)+"
                r"(?=(?:left|right|u)\s*turn\b|(?:one\s+eighty|three\s+sixty|180|360)\b)"), ""),
    # learner grammar (Indian English and others): "take left", "take right" with no article and no place after
    # it is a turn that way, as "take a left" is
    (re.compile(r"\btake\s+(?P<side>left|right)\b(?!\s+(?:hand\s+|side\s+)?(?:door|doorway|room|corridor|hallway|hall|exit|"
                r"passage|corner|wall|one|turn)\b)"), r"take a \g<side>"),
    # a boat's helm orders: "hard to port", "hard a-starboard", "hard over to port": the rudder put over, a turn
    # that way (how far is said after, or asked)
    (re.compile(r"\b(?:(?:turn|come|go)\s+)?(?:hard|full)(?:\s+over)?\s+(?:to\s+|a\s*-?\s*)(?P<side>port|starboard)\b"),
     r"turn \g<side>"),
    # "come round to face north", "swing around to face the door": the facing is the turn; "round" says only
    # that the robot turns to it
    (re.compile(r"\b(?:come|swing|turn|bring\s+(?:her|it))\s+(?:a)?round\s+(?:so\s+as\s+)?(?:to\s+)?(?=face\b)"), ""),
    # French and other learners: "turn on the left" (tourner à gauche) is a turn to the left; a side is nothing
    # one switches on
    (re.compile(r"\bturn\s+on\s+(?:the|your)\s+(?P<side>left|right)\b"), r"turn \g<side>"),
    # learners' "of" before an amount ("advance of four meters", "turn right of forty-five degrees", after
    # French "de"): the amount of the motion, as "by"
    (re.compile(rf"\b(?P<w>forwards?|backwards?|back|left|right|ahead|advance|move|go|turn|rotate|reverse)\s+of\s+"
                rf"(?=(?:about\s+|around\s+|roughly\s+)?(?:{NUMBER}|a|an|half)\b)"), r"\g<w> "),
    # "give it a little turn to the left", "give yourself a small bit of a turn": the turn, of that size
    (re.compile(r"\bgive\s+(?:it|her|yourself|the\s+robot)\s+(?:a|an)\s+(?P<small>(?:small\s+|little\s+|tiny\s+|wee\s+)?"
                r"(?:bit|touch|tad)\s+of\s+a\s+|(?:small|little|slight|tiny|wee)\s+)?(?:(?:quick|gentle|nice)\s+)?turn\b"),
     lambda m: "turn a little" if m.group("small") else "turn"),
    # "reverse small", "go front small small": "small" after a verb or a way, ending the instruction, is a little
    (re.compile(r"\b(?P<w>reverse|back|up|move|go|shift|turn|come|forwards?|front|left|right|backwards?|straight|ahead)"
                r"(?:\s+(?:hand\s+)?side)?\s+small(?:\s+small)?(?=\s*(?:$|[,.;!?]|please\b|abeg\b|o\b))"), r"\g<w> a little"),
    # drill orders: "right face", "left, face" (nothing after "face": not a facing of something)
    (re.compile(r"\b(?P<side>left|right)\s*,?\s+face\b(?=\s*(?:$|[,.;!?]))"), r"turn \g<side>"),
    # "go up the row", "down the aisle": a line of the speaker's setting the map does not name; along it is ahead
    (re.compile(r"\b(?:up|down|along)\s+(?:the|this|that|your)\s+(?:row|aisle|lane|track|line|bay|run|gangway|racking)\b"
                r"(?!\s+(?:of|to|towards?|into)\b)"), "forward"),
    # "go on ahead there two metres": "there" between a way and an amount points at nothing (only after
    # ahead / forward / back: "go over there two metres", "go right there" may point at a place: ask)
    (re.compile(rf"\b(?P<w>ahead|forwards?|back(?:wards?)?)\s+there\s+(?={_AMOUNT})"), r"\g<w> "),
    # "the break room", "the rest area": a word of stopping that names a kind of room is part of the room's name
    # (one the map cannot know, so it is asked about), not a stop
    (re.compile(r"\b(?P<a>the|a|an|this|that|our|your|my)\s+(?P<w>break|rest|stop|halt|pause)\s+"
                r"(?P<n>room|area|space|bay|zone|kitchen)\b"), r"\g<a> \g<w>\g<n>"),
    # learner grammar: "make turn", "do turn" (no article) is a turn
    (re.compile(r"\b(?:make|do|take|perform|give)\s+(?:a\s+)?turn(?=\s+(?:on|in|to|at|towards?)?\s*(?:the\s+)?"
                r"(?:left|right)\b)"), "turn"),
)
#: The same rules, for text in any case (a whole prompt is read before it is lower-cased).
IDIOMS: Final = tuple((re.compile(p.pattern, re.IGNORECASE), repl) for p, repl in _IDIOMS)


def plain_idioms(text: str) -> str:
    """``text`` with each spoken idiom written in the plain words it means (a whole prompt before it is
    split, so that "... and swing left" starts an instruction; and each clause when it is read)."""
    for pattern, repl in IDIOMS:
        text = pattern.sub(repl, text)
    return text


#: "180", "a quick one eighty", "full three sixty" said as a whole instruction.
_NAMED_TURN_ALONE: Final = re.compile(
    r"^(?:(?:a|an|another|one|the)\s+)?(?:(?:quick|fast|full|complete|whole|little)\s+)?"
    r"(?P<deg>one\s+eighty|180|three\s+sixty|360)(?:\s+(?:please|now|again))?$")
#: "Around" said alone as the whole instruction ("around!", "round, yeah"): the turn around it names, as "left"
#: alone is a turn to the left (with a verb or a place, "go around the box", it is read as usual).
_AROUND_ALONE: Final = re.compile(r"^(?:(?:all\s+the\s+way|right)\s+)?(?:a)?round(?:\s+(?:please|now))?$")


def named_turn_alone(clause: str, around_alone: bool = True) -> str:
    """A whole instruction (normalised) that is only "180" or "three sixty" is the turn of that name, and
    one that is only "around" the turn around when ``around_alone`` (it opens the prompt, or says again the turn
    around before it: "turn around, around"; after another step, "turn left, around", it may correct that step
    or add to it, and is asked about).
    (As a fragment it completes the instruction before it instead: "turn left, 180"; that joining
    happens before a clause is read, so this applies only to what is read as a clause.)"""
    if around_alone and _AROUND_ALONE.match(clause):
        return "turn around"
    m = _NAMED_TURN_ALONE.match(clause)
    if m is None:
        return clause
    return "turn 180 degrees" if m.group("deg") in ("one eighty", "180") else "turn 360 degrees"
