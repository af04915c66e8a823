"""The offline translator's vocabulary: every table of words and phrases, as named constants.

Phrases are written lower-case with single spaces; :func:`phrase_regex` turns a table into one
compiled alternation (longest phrase first, whole words, any run of spaces between words). The
words follow ``../shared/bench/README.md`` ("Meaning of the words") and issue 3 §1-2.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from typing import Final

from langnav.language.intent import Detail, Direction, Element, Side, Superlative


def phrase_regex(phrases: Iterable[str], group: str | None = None) -> str:
    """One regex alternation matching any of ``phrases`` as whole words, longest first."""
    ordered = sorted(set(phrases), key=lambda p: (-len(p), p))
    body = "|".join(r"\s+".join(re.escape(w).replace(r"\-", r"[\s-]") for w in p.split()) for p in ordered)
    inner = f"(?P<{group}>{body})" if group else f"(?:{body})"
    return rf"(?<![\w'-]){inner}(?![\w'-])"


def compile_phrases(phrases: Iterable[str]) -> re.Pattern[str]:
    return re.compile(phrase_regex(phrases))


def lookup(table: Mapping[str, object], phrase: str) -> object:
    """The value of ``phrase`` in a phrase table, ignoring runs of spaces."""
    return table[" ".join(phrase.split())]


# ------------------------------------------------------------------------------ elements
#: Head nouns of each reference element (singular and plural). Longest match wins, so
#: "narrow corridor" is a narrow passage while "corridor" is a hallway.
ELEMENT_NOUNS: Final[dict[str, Element]] = {
    **{w: Element.DOOR for w in (
        "door", "doors", "doorway", "doorways", "opening", "openings", "entrance", "entrances",
        "exit", "exits", "doorframe", "doorframes", "door frame", "door frames", "entryway",
        "entryways", "entry", "archway", "archways", "way out", "gap", "gaps", "door opening")},
    **{w: Element.WALL for w in ("wall", "walls", "wall segment")},
    **{w: Element.ROOM for w in ("room", "rooms", "chamber", "chambers")},
    **{w: Element.HALLWAY for w in (
        "hallway", "hallways", "corridor", "corridors", "hall", "halls", "passageway",
        "passageways", "hall way", "aisle", "main corridor", "main hallway")},
    **{w: Element.NARROW_PASSAGE for w in (
        "narrow passage", "narrow passages", "narrow gap", "narrow gaps", "tight spot", "tight spots",
        "constriction", "constrictions", "bottleneck", "bottlenecks", "narrow corridor",
        "narrow hallway", "narrow hall", "narrow passageway", "narrow opening", "tight gap",
        "tight passage", "tight space", "narrow space", "narrow spot", "narrow section",
        "narrow part", "narrowing", "choke point", "chokepoint", "pinch point",
        "passage", "passages", "narrow way", "tight squeeze", "narrow bit")},
    **{w: Element.OBSTACLE for w in (
        "obstacle", "obstacles", "object", "objects", "thing", "things", "box", "boxes", "item",
        "items", "pillar", "pillars", "column", "columns", "post", "posts", "block", "blocks",
        "crate", "crates", "barrier", "barriers", "obstruction", "obstructions", "blockage",
        "furniture", "piece of furniture", "pieces of furniture", "pole", "poles", "clutter",
        "blob", "blobs", "structure", "cube")},
    **{w: Element.CORNER for w in ("corner", "corners", "nook")},
    **{f"{adj} {noun}": Element.UNEXPLORED_AREA
       for adj in ("unexplored", "unknown", "unmapped", "uncharted", "unseen", "unvisited",
                   "undiscovered", "unscanned")
       for noun in ("area", "areas", "region", "regions", "space", "spaces", "territory",
                    "part", "parts", "zone", "zones", "section", "sections", "spot", "place",
                    # said of a piece of the map: "the unexplored bit at the end of the corridor"
                    "bit", "bits", "patch", "patches", "stretch")},
    **{w: Element.UNEXPLORED_AREA for w in (
        "frontier", "frontiers", "unexplored", "unknown space", "unknown",
        "exploration frontier")},
}

#: Heads that are plural ("the two obstacles", "between the boxes").
PLURAL_NOUNS: Final = frozenset(w for w in ELEMENT_NOUNS if w.endswith("s") and not w.endswith(
    ("ss", "entrance", "space", "place")) and w not in ("gas", "furniture", "the unknown", "unknown"))

#: "passage" alone is probably, not surely, a narrow passage.
WEAK_NOUNS: Final = frozenset({"passage", "passages", "gap", "gaps", "thing", "things", "structure"})

#: Pronouns that point back at the previous step's element.
PRONOUNS: Final = frozenset({"it", "that", "there", "that one", "this one", "them", "that place",
                             "the same one", "the same place", "where you were"})

#: Kinds that contain other elements ("the corner of the hallway", "the obstacle in this room").
CONTAINER_KINDS: Final = frozenset({Element.ROOM, Element.HALLWAY})

# ------------------------------------------------------------------------------ properties
ORDINALS: Final[dict[str, int]] = {
    "first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5, "sixth": 6, "seventh": 7,
    "eighth": 8, "ninth": 9, "tenth": 10, "eleventh": 11, "twelfth": 12, "thirteenth": 13,
    "fourteenth": 14, "fifteenth": 15, "1st": 1, "2nd": 2, "3rd": 3, "4th": 4, "5th": 5, "6th": 6,
    "sixteenth": 16, "seventeenth": 17, "eighteenth": 18, "nineteenth": 19, "twentieth": 20,
    **{f"{n}{'st' if n % 10 == 1 and n != 11 else 'nd' if n % 10 == 2 and n != 12 else 'rd' if n % 10 == 3 and n != 13 else 'th'}": n
       for n in range(1, 21)},
}

SUPERLATIVES: Final[dict[str, Superlative]] = {
    **{w: Superlative.NEAREST for w in ("nearest", "closest", "next", "near", "nearby", "close",
                                         "closer", "nearer", "most near")},
    **{w: Superlative.FARTHEST for w in ("farthest", "furthest", "last", "far", "final",
                                          "most distant", "remotest", "farther", "further",
                                          "opposite", "far away", "distant", "far end")},
    **{w: Superlative.BIGGEST for w in ("biggest", "largest", "big", "large", "huge", "largest size",
                                         "bigger", "larger", "main")},
    # ("littlest": the superlative of "little", said in Northern English and by children)
    **{w: Superlative.SMALLEST for w in ("smallest", "small", "tiny", "smaller", "tiniest", "little", "littlest")},
    **{w: Superlative.WIDEST for w in ("widest", "wide", "wider", "broadest", "broad")},
    **{w: Superlative.NARROWEST for w in ("narrowest", "narrow", "narrower", "tightest", "thinnest")},
}

#: Post-modifier superlatives: "the door closest to you".
POST_SUPERLATIVES: Final[dict[str, Superlative]] = {
    **{f"{w} {p} {o}": Superlative.NEAREST
       for w in ("closest", "nearest") for p in ("to",) for o in ("you", "the robot", "yourself", "me")},
    **{f"{w} from {o}": Superlative.FARTHEST
       for w in ("farthest", "furthest", "farthest away", "furthest away") for o in ("you", "the robot", "me")},
    "farthest away": Superlative.FARTHEST, "furthest away": Superlative.FARTHEST,
    "nearby": Superlative.NEAREST, "closest by": Superlative.NEAREST,
}

#: Sides as adjectives before the noun ("the left wall", "the right-hand door").
SIDE_ADJECTIVES: Final[dict[str, Side]] = {
    "left": Side.LEFT, "left-hand": Side.LEFT, "left hand": Side.LEFT, "lefthand": Side.LEFT,
    "right": Side.RIGHT, "right-hand": Side.RIGHT, "right hand": Side.RIGHT, "righthand": Side.RIGHT,
    # a boat's sides ("the starboard door")
    "port": Side.LEFT, "starboard": Side.RIGHT,
}

#: Sides only for walls and corners ("the front wall", "the back corner"); "the front door" is a name.
FRONT_BACK_ADJECTIVES: Final[dict[str, Side]] = {
    "front": Side.AHEAD, "facing": Side.AHEAD, "back": Side.BEHIND, "rear": Side.BEHIND,
}

_YOU: Final = ("you", "yourself", "the robot", "me", "us")
_SIDE_WORDS: Final = {"left": Side.LEFT, "left-hand": Side.LEFT, "left hand": Side.LEFT,
                      "right": Side.RIGHT, "right-hand": Side.RIGHT, "right hand": Side.RIGHT,
                      # a boat's sides, said of places too ("the door on your starboard side")
                      "port": Side.LEFT, "starboard": Side.RIGHT}

#: Sides as phrases after the noun ("the door on your left", "the door in front of you").
SIDE_PHRASES: Final[dict[str, Side]] = {
    **{f"{p} {d} {w}{s}": side
       for w, side in _SIDE_WORDS.items()
       for p in ("on", "to", "at", "towards", "toward")
       for d in ("your", "the", "my")
       for s in ("", " side", " hand side", " of you", " side of you")},
    **{f"{w} of {y}": side for w, side in _SIDE_WORDS.items() for y in _YOU},
    **{f"{w}{s}": side for w, side in _SIDE_WORDS.items() for s in (" side", " hand side")},
    **{f"on {w}": side for w, side in _SIDE_WORDS.items()},
    **{f"in front of {y}": Side.AHEAD for y in _YOU},
    **{f"ahead of {y}": Side.AHEAD for y in _YOU},
    **{f"straight ahead of {y}": Side.AHEAD for y in _YOU},
    "in front": Side.AHEAD, "ahead": Side.AHEAD, "straight ahead": Side.AHEAD, "up ahead": Side.AHEAD,
    "dead ahead": Side.AHEAD, "before you": Side.AHEAD, "facing you": Side.AHEAD,
    "in your way": Side.AHEAD, "in your path": Side.AHEAD, "right ahead": Side.AHEAD,
    "straight in front of you": Side.AHEAD, "directly ahead": Side.AHEAD,
    "directly in front of you": Side.AHEAD, "right in front of you": Side.AHEAD,
    **{f"behind {y}": Side.BEHIND for y in _YOU},
    **{f"at {d} back": Side.BEHIND for d in ("your", "the")},
    "behind": Side.BEHIND, "in back of you": Side.BEHIND, "back there": Side.BEHIND,
    "to your rear": Side.BEHIND, "at your rear": Side.BEHIND, "to the rear": Side.BEHIND,
    "directly behind you": Side.BEHIND, "right behind you": Side.BEHIND,
}

#: Phrases that make the element (or its room) the one holding the robot.
CURRENT_ROOM_PHRASES: Final = (
    "this room", "the room you are in", "the room you are currently in", "the current room",
    "current room", "your room", "your current room", "the same room", "this very room",
    "the room you are standing in", "the room you are in now", "the room you are in right now",
    "this space", "here", "in here", "the room we are in", "where you are",
)

#: After a room noun: "the room you are in" (the noun already read).
ROOM_YOU_ARE_IN: Final = ("you are in", "you are currently in", "you are standing in", "we are in",
                          "you are in now", "you are in right now", "you are in at the moment",
                          "that you are in", "which you are in")

#: Words linking an element to its container: "the corner OF the hallway".
CONTAINER_LINKS: Final = ("of", "in", "inside", "within", "inside of", "belonging to", "on", "at")
#: Links that also pick the farthest one: "the door at the end of the hallway".
FAR_END_LINKS: Final = tuple(f"{p} the {w}end of" for p in ("at", "on", "by", "near") for w in ("", "far ", "other "))

#: Determiners and harmless pre-modifiers inside a noun phrase.
DETERMINERS: Final = frozenset({"the", "a", "an", "that", "this", "your", "any", "some", "our", "my",
                                "these", "those", "one", "its"})
NEUTRAL_ADJECTIVES: Final = frozenset({"open", "nearest-by", "available", "free", "empty", "same",
                                       "only", "single", "whole", "entire", "actual", "real",
                                       "visible", "two", "both", "very", "most", "the"})

# ------------------------------------------------------------------------------ details
#: Words before an element that give the movement detail. Checked on the words between the verb
#: (or the previous element) and the element, longest first.
DETAIL_PHRASES: Final[dict[str, Detail]] = {
    **{f"{pre}{the}{w} {e} of": Detail.OPPOSITE_SIDE_OF
       # "go across to the opposite side of the room": across to a place is over to it
       for pre in ("", "to ", "over to ", "across to ", "on ", "onto ", "go to ")
       for the in ("the ", "")
       for w in ("other", "opposite", "far", "farther", "further", "farthest", "furthest", "another")
       for e in ("side", "end", "half", "part")},
    "opposite": Detail.OPPOSITE_SIDE_OF, "opposite to": Detail.OPPOSITE_SIDE_OF,
    "across": Detail.OPPOSITE_SIDE_OF, "across to the other side of": Detail.OPPOSITE_SIDE_OF,
    "to the end of": Detail.OPPOSITE_SIDE_OF, "the end of": Detail.OPPOSITE_SIDE_OF,
    "to the far end of": Detail.OPPOSITE_SIDE_OF, "behind": Detail.OPPOSITE_SIDE_OF,
    "around": Detail.OPPOSITE_SIDE_OF, "round": Detail.OPPOSITE_SIDE_OF,
    "beyond": Detail.OPPOSITE_SIDE_OF,
    **{f"{pre}{the}{w}{o}": Detail.MIDDLE
       for pre in ("", "to ", "into ", "in ", "at ")
       for the in ("the ", "")
       for w in ("middle", "centre", "center", "midpoint", "central part", "centre point",
                 "center point", "very middle", "very centre", "very center", "heart")
       for o in (" of",)},
    **{f"{r}{w}": Detail.NEXT_TO
       for r in ("", "right ", "just ", "up ", "close ")
       for w in ("next to", "beside", "besides", "alongside", "adjacent to", "by the side of",
                 "close to", "near to", "near", "nearby", "by", "close by", "closer to", "nearer to",
                 "to the side of", "the side of", "up against", "against", "up next to",
                 "right up to", "right by", "close up to", "as close as possible to",
                 "as near as possible to", "near the side of")},
    **{w: Detail.TO for w in (
        "to", "into", "in to", "at", "up to", "over to", "onto", "on to", "in front of",
        "right in front of", "just in front of", "as far as", "until you reach", "till you reach",
        "until you get to", "till you get to", "until", "till", "until you are at", "back to",
        "down to", "out to", "inside", "in", "over by", "all the way to", "on over to",
        "until you arrive at", "to where", "in the", "in front of the", "the front of",
        "to the front of", "for", "up until")},
    **{w: Detail.TOWARDS for w in ("towards", "toward", "in the direction of", "to the direction of",
                                   "in direction of", "direction of", "approaching")},
    **{w: Detail.THROUGH for w in ("through", "thru", "via", "out through", "in through",
                                   "straight through", "right through", "all the way through",
                                   "out of", "out the", "out", "past")},
    **{w: Detail.ALONG for w in ("along", "the length of", "down", "up", "all along",
                                 "the entire length of", "the whole length of", "right along",
                                 "close along", "down the length of", "parallel to",
                                 "following")},
    **{w: Detail.BETWEEN for w in ("between", "in between", "halfway between", "midway between",
                                   "in the middle between", "in the middle of", "betwixt")},
}

#: "in the middle of A and B" reads as between; "in the middle of the room" as middle. The
#: entry above is corrected by the parser when there is no second element.
MIDDLE_PHRASE_BETWEEN: Final = "in the middle of"

#: Details given by a verb ("cross the room", "take the door", "enter the room").
VERB_DETAILS: Final[dict[str, Detail]] = {
    **{w: Detail.THROUGH for w in ("pass through", "go through", "cross", "take", "pass", "traverse",
                                   "exit through", "squeeze through", "get through", "drive through",
                                   "move through", "navigate through", "head through", "walk through",
                                   "exit", "leave", "exit from", "get out of", "go out of", "leave through")},
    **{w: Detail.TO for w in ("reach", "enter", "approach", "visit", "find", "get to", "arrive at", "take me",
                              "take us", "bring me", "bring us",
                              "swing by", "drop by", "pop by", "come by", "pop over to", "nip to",
                              "return to", "come to", "go into", "park at", "head into", "check out", "go check out",
                              "go and check out", "go check", "go see", "go and see")},
    **{w: Detail.ALONG for w in ("follow", "hug", "trace", "track", "skirt", "shadow", "follow along",
                                 "keep to", "stick to", "stay along", "keep along", "stay close to",
                                 "keep close to", "stick close to", "run along", "keep following")},
    **{w: Detail.STOP_AT for w in ("stop at", "stop by", "stop in front of", "halt at", "stop when you reach",
                                   "stop once you reach", "stop when you get to", "stop when you are at",
                                   "stop as soon as you reach", "park", "wait at", "stay at",
                                   "stop next to", "stop beside", "stop near", "stop in")},
}

#: Details that only fit some elements, and their reading for the others.
THROUGH_KINDS: Final = frozenset({Element.DOOR, Element.NARROW_PASSAGE})
#: Words of going in: into a room is to be inside it, but one goes into a doorway or a gap only by
#: passing through it ("go into the first door on your right": through it, into what lies beyond).
ENTERING_WORDS: Final = frozenset({"into", "in to", "enter", "go into", "head into"})

# ------------------------------------------------------------------------------ movements
#: Verbs that move the robot somewhere (navigate with an element, move without one).
GO_VERBS: Final = (
    "go", "goes", "going", "head", "heading", "drive", "driving", "navigate", "move", "moving", "get",
    "reach", "proceed", "travel", "walk", "roll", "come", "return", "advance", "make your way",
    "take me", "bring me", "get me", "lead me", "take us", "bring us", "guide me", "take yourself",
    "enter", "exit", "leave", "cross", "pass", "approach", "visit", "find", "park", "position yourself",
    "get yourself", "continue", "keep going", "carry on", "step", "slide", "shift", "creep", "inch", "sidestep",
    "side step",
    "scoot", "back up", "back out", "reverse", "back off", "go back", "head back", "strafe", "run", "ride",
    "navigate yourself", "steer", "relocate", "put yourself", "place yourself", "be", "traverse",
    "squeeze", "wander", "journey", "cruise", "zip", "hop", "nudge", "budge", "position", "get over",
    "come over", "swing by", "pull up", "pull over", "pull", "arrive", "set off", "follow", "hug",
    "trace", "track", "skirt", "take", "stay", "keep", "edge", "shuffle", "ease", "stand", "go stand",
    "go and stand", "go and", "sit", "wait", "retreat", "withdraw", "backpedal", "back pedal", "back-pedal",
)

ROTATE_VERBS: Final = ("turn", "rotate", "spin", "pivot", "swivel", "swing round", "swing around", "face", "look", "twist", "yaw",
                       "turn yourself", "rotate yourself", "orient", "orient yourself", "veer",
                       "turn your body", "point", "do", "make", "perform", "execute", "give me", "give us",
                       "give", "have", "take a", "try", "turn on the spot", "u turn", "uturn", "about face", "about turn", "make a u turn",
                       "turn in place", "rotate in place", "spin in place", "turn on spot")
#: "do / make / perform" only rotate with a turn noun ("do a quarter turn", "make a u-turn").
ROTATE_NOUN_VERBS: Final = frozenset({"do", "make", "perform", "execute", "give", "have", "take", "try"})

STOP_PHRASES: Final = (
    "stop", "halt", "freeze", "stop moving", "stop now", "stop right there", "stop immediately",
    "stop here", "stay here", "stay where you are", "stay put", "stand still", "hold still",
    "hold on", "hold position", "hold your position", "do not move", "cancel", "abort", "pause",
    "brake", "emergency stop", "wait", "wait here", "stop there", "stop everything",
    "cease moving", "come to a halt", "come to a stop", "stop the robot", "stop driving",
    "stop the motion", "cancel that", "cancel the navigation", "cancel navigation", "abort mission",
    "stay", "whoa", "enough", "stop it", "e-stop", "estop", "stop right now", "stop at once",
    "break", "hault", "stahp", "stopp", "stop please", "do not go any further", "go no further",
    "that is far enough", "that is enough", "no further",
    # idioms of stopping: "hold it (right there)", "hold up", "hang on", "that will do"
    "hold it", "hold it there", "hold it right there", "hold it right here", "hold up", "hang on",
    "hang on a second", "hang on a sec", "hold on a second", "hold on a sec", "wait a second", "wait a sec",
    "wait a moment", "wait a minute", "just a second", "just a moment", "whoa there", "stop stop", "stay right there", "freeze right there",
    "halt right there", "quit moving", "okay stop", "ok stop", "stop right here", "hold up there",
    # "hold" alone is the radio's stop ("hold, hold"; "turn around and hold")
    "hold",
)

#: Questions and their answers.
QUERY_POSE_PATTERNS: Final = (
    # ("whereabouts" asks where, in every English: "whereabouts are you (to) now?")
    r"\bwhere(?:abouts)?\s+(?:exactly\s+|now\s+|on\s+earth\s+|even\s+)?(?:are|r)\s+(?:you|u)\b(?!\s+(?:going|heading|headed|driving|off\s+to))", r"\bwhere\s+am\s+i\b", r"\bwhere\s+is\s+the\s+robot\b",
    # ("hold your position", "keep your heading" ask to stay, not where the robot is)
    r"(?<!\bhold\s)(?<!\bkeep\s)(?<!\bmaintain\s)"
    r"\b(?:your|the\s+robot'?s?|current|robot)\s+(?:current\s+|exact\s+|present\s+|last\s+)?"
    r"(?:position|location|pose|coordinates|whereabouts|heading|orientation|place)\b",
    # ("say position": radio procedure's "say" asks the other station to tell it; "get pose": a developer's
    # "get" fetches a value, as "get map" does)
    r"\b(?:report|send|give|tell|say|get|fetch)\s+(?:me\s+|us\s+)?(?:your\s+|the\s+)?(?:current\s+|present\s+)?"
    r"(?:position|location|pose|coordinates|whereabouts)\b(?!\s+of\b)",
    r"\bwhich\s+(?:way|direction)\s+are\s+you\s+(?:facing|pointing|heading|looking)\b",
    r"\bwhere\s+(?:is\s+it|are\s+we)\b", r"^\s*where\s+(?:you|u)\s+(?:are|r)\b",
    r"\bwhere\s+(?:is|are|r)\s+(?:you|u|ya)\b(?!\s+(?:going|heading|headed|driving|off\s+to))", r"\b(?:tell|show|say|know|report)\b.*\bwhere\s+you\s+are\b", r"\blocali[sz]e\s+yourself\b",
    r"\bwhat\s+is\s+your\s+(?:position|location|pose)\b", r"\bwhere\s+abouts\b",
    # "what's your twenty?": radio ten-code 10-20 is "location" (police, taxi and CB radio)
    r"\bwhat(?:'?s|\s+is)\s+(?:your|ur|the\s+robot'?s)\s+(?:twenty|20|10-20|ten[\s-]twenty)\b",
    # ("where's he got to": the "'s" of "where's" is "has" as often as "is")
    r"\bwhat\s+room\s+are\s+you\s+in\b", r"\bwhere\s+(?:have|has|is)\s+(?:you|u)\s+got\s+to\b",
    # "where you at?" (the copula dropped, as many English dialects do); "where do you stand now?" (where
    # one stands is where one is, as learners and formal speakers ask it)
    r"^\s*where\s+(?:you|u|ya|y'all)\s+at\b",
    # ("where you now?", "where you right now": the copula dropped before "now", as learners and many
    # varieties ask it)
    r"^\s*where\s+(?:you|u|ya)\s+(?:right\s+)?now\b",
    # "you are where now?", "you now where?": the question word left in the place of what is asked, as Chinese,
    # Cantonese, Thai and Arabic ask it ("ni zai nali", "you at where") and English does in surprise
    r"^\s*(?:you|u|ya)\s+(?:are\s+|r\s+|is\s+)?(?:(?:right\s+)?now\s+)?where\b"
    r"(?!\s+(?:is|are|was|were|the|a|an|you|u|i|we|it|they|to|from|do|does|did)\b)",  # (no clause after it: "where the door is")
    r"\bwhere\s+(?:do|does)\s+(?:you|u|the\s+robot|it)\s+(?:stand|find\s+(?:yourself|itself)|sit|stay)\b"
    r"(?!\s+(?:on|with)\b)",
)
QUERY_PATH_PATTERNS: Final = (
    # ("which way is north?" asks where a direction is, not the robot's path)
    r"\b(?:what|which|show|tell|give|send|display|get|report)\b.*\b(?:path|route|plan|trajectory|way(?!\s+(?:is|are)\b))\b",
    r"\b(?:path|route|trajectory)\b.*\b(?:following|taking|using|on|planned|current)\b",
    r"\bwhere\s+are\s+you\s+(?:going|heading|headed|driving)\b",
    r"\b(?:current|planned|your)\s+(?:path|route|trajectory|plan)\b",
    r"\bhow\s+(?:are|will)\s+you\s+(?:get|going\s+to\s+get)\s+there\b",
)
QUERY_MAP_PATTERNS: Final = (
    r"\b(?:show|give|send|display|get|fetch|let\s+me\s+see|can\s+i\s+see|see|view|open|bring\s+up|"
    r"pull\s+up|print|draw|download|share|provide|transmit|upload|export|post)\b(?:\s+\w+){0,4}?\s+(?:(?:mini|floor|site|overview)\s*-?\s*)?"
    r"(?:map|occupancy\s+grid)\b",
    r"\bwhat\s+does\s+(?:the|your)\s+map\s+look\s+like\b",
    # "how is the map now?", "how's the map looking": asking how the map is, as "what does it look like", is asking
    # to see it
    r"\bhow\s+(?:is|does|are)\s+(?:the|your|our)\s+map\b(?!\s+(?:made|built|drawn|saved|stored)\b)", r"\b(?:the|your|current)\s+map\s*\?",
    r"^\s*(?:the\s+)?map\s*$", r"\bwhat\s+(?:have\s+you|did\s+you)\s+mapped\b",
    r"\bwhat\s+is\s+on\s+(?:the|your)\s+map\b", r"\bwhat\s+(?:you\s+have|have\s+you)\s+(?:mapped|explored|seen)\b",
)

#: Exploration (frontier exploration until done).
EXPLORE_PATTERNS: Final = (
    r"\bexplor(?:e|ing|ation)\b", r"\bmap\s+(?:out\s+)?(?:this|the|our|everything|all|it|the\s+rest|"
    r"the\s+whole|the\s+entire|this\s+whole|this\s+entire|more|around|the\s+area|the\s+environment|"
    r"the\s+floor|the\s+building|the\s+place|the\s+room|the\s+surroundings|your\s+surroundings)\b",
    r"\b(?:build|make|create|complete|finish|extend|update)\s+(?:a|the|your|the\s+whole)?\s*map\b",
    r"\bscan\s+(?:the|this|your)?\s*(?:area|room|building|floor|surroundings|environment|place|everything)\b",
    r"\bsurvey\s+(?:the|this)\s+(?:area|room|building|floor|place)\b",
    r"\bdiscover\s+(?:new|the|unknown|more)\b", r"\bgo\s+mapping\b", r"\bstart\s+mapping\b",
    r"\bmap\s+(?:this|the|every|each)\s+\w+\b", r"^\s*map\s*$",
)
#: Scope words an explore clause may name without changing it.
EXPLORE_SCOPE_WORDS: Final = frozenset({
    "area", "areas", "room", "rooms", "floor", "building", "environment", "surroundings", "place",
    "map", "everything", "rest", "whole", "entire", "all", "this", "the", "it", "world", "house",
    "office", "apartment", "level", "space", "region", "site", "more", "around", "out", "of",
    "new", "unknown", "territory", "every", "each", "corner", "on", "own", "your", "until",
    "done", "finished", "complete", "completely", "fully", "autonomously", "by", "yourself",
    "mapping", "start", "go", "build", "make", "create", "a", "finish", "extend", "update", "scan",
    "survey", "discover", "exploring", "exploration", "premises", "lab", "flat", "there",
    "surrounding", "nearby", "parts", "part", "you", "can", "explore", "explored",
})

# ------------------------------------------------------------------------------ directions
MOVE_DIRECTIONS: Final[dict[str, Direction]] = {
    **{w: Direction.FORWARD for w in (
        "forward", "forwards", "ahead", "straight", "straight ahead", "straight on", "onward",
        "onwards", "frontward", "frontwards", "to the front", "in front", "straight forward", "front",
        "up", "closer", "nearer")},
    **{w: Direction.BACKWARD for w in (
        "backward", "backwards", "back", "in reverse", "reverse", "rearward", "rearwards",
        "to the back", "straight back", "back up", "backup", "back off", "the other way",
        # a boat's words, ordinary English for anyone who has been on one: astern is backwards
        "astern")},
    **{w: Direction.LEFT for w in (
        "left", "to the left", "to your left", "leftward", "leftwards", "sideways left",
        "sideways to the left", "to the left side", "left side", "on the left", "on your left",
        "toward the left", "towards the left", "toward your left", "towards your left", "port", "on left")},
    **{w: Direction.RIGHT for w in (
        "right", "to the right", "to your right", "rightward", "rightwards", "sideways right",
        "sideways to the right", "to the right side", "right side", "on the right", "on your right",
        "toward the right", "towards the right", "toward your right", "towards your right",
        "starboard", "on right")},
    # (the side with "hand" said, as for a turn: "move to your left hand side one metre")
    **{f"{lead}{side} hand side": Direction(side) for side in ("left", "right")
       for lead in ("", "to the ", "to your ", "your ", "the ", "on the ", "on your ")},
}

ROTATE_DIRECTIONS: Final[dict[str, Direction]] = {
    **{w: Direction.LEFT for w in (
        "left", "to the left", "to your left", "leftward", "leftwards", "counterclockwise",
        "counter clockwise", "counter-clockwise", "anticlockwise", "anti clockwise",
        "anti-clockwise", "ccw", "to the left side", "toward the left", "towards the left",
        "toward your left", "towards your left", "your left", "the left", "port", "left side",
        "left hand side", "on the left", "on your left", "positive", "on left")},
    **{w: Direction.RIGHT for w in (
        "right", "to the right", "to your right", "rightward", "rightwards", "clockwise", "cw",
        "to the right side", "toward the right", "towards the right", "toward your right",
        "towards your right", "your right", "the right", "starboard", "right side",
        "right hand side", "on the right", "on your right", "negative", "on right")},
    # "to your right hand side", "on the left-hand side": the side with "hand" said, after any of its leads
    **{f"{lead} {side} hand side": Direction(side) for side in ("left", "right")
       for lead in ("to the", "to your", "your", "the", "on the", "on your", "towards the", "towards your",
                    "toward the", "toward your")},
    **{w: Direction.AROUND for w in (
        "around", "round", "back", "backwards", "backward", "about", "the other way", "the opposite way",
        "the other direction", "the opposite direction", "behind", "behind you", "to face behind",
        "u-turn", "u turn", "about-face", "about face", "180", "a 180", "one eighty", "an about-face",
        "all the way around", "all the way round", "the way you came", "the way we came")},
}

# ------------------------------------------------------------------------------ amounts
LITTLE_PHRASES: Final = (
    "a little", "a little bit", "a bit", "slightly", "a tad", "a touch", "just a bit",
    "just a little", "a smidge", "a small amount", "a short distance", "a little way",
    "a small step", "a tiny bit", "a wee bit", "a few centimeters", "a few centimetres",
    "a few cm", "a few degrees", "a small turn", "a bit more", "a little more", "somewhat",
    "marginally", "a hair", "a nudge", "a small distance", "a short way", "bit", "little",
    "little bit", "a fraction", "a tiny amount", "ever so slightly", "a couple of centimeters",
    "a couple of centimetres", "a couple of degrees", "a smidgen", "gently", "a small bit",
    "just slightly", "very slightly", "only slightly",
    # "make small turn to the left", "a slight turn right": a turn said to be small is a little turn
    *(f"{pre}{size} turn" for pre in ("a ", "") for size in ("small", "slight", "tiny", "little", "short", "quick")),
    # "a teeny bit", "just a tiny touch", "a teeny tiny bit", "a lil bit": a small word before a small noun
    *(f"{pre}{size}{noun}" for pre in ("a ", "just a ", "only a ", "") for size in (
        "", "little ", "tiny ", "teeny ", "teeny tiny ", "teensy ", "teensy weensy ", "teeny weeny ", "wee ",
        "itsy bitsy ", "small ", "very small ", "very little ", "tiny little ", "little tiny ")
      for noun in ("bit", "touch", "tad", "smidge", "nudge", "amount", "skosh")),
)

#: Amounts said only to be large ("a fair bit", "quite a way", "a good distance", "a lot"): unlike "a
#: little", which the contract bounds (0.15-0.5 m, 10-40 degrees), a large amount said without a number
#: has no bound a person would agree on, so the robot asks how far (never a guessed distance).
MUCH_PATTERNS: Final = (
    r"\b(?:a\s+)?(?:fair|good|decent|big|long|large|great|considerable|healthy|reasonable|sizeable|sizable|"
    r"fair\s+old|good\s+long)\s+(?:bit|way|ways|distance|amount|stretch|piece|chunk|whack|lot)\b",
    r"\bquite\s+(?:a\s+)?(?:bit|way|ways|distance|lot|stretch)\b", r"\ba\s+(?:whole\s+)?lot\b", r"\ba\s+ways\b",
    r"\bsome\s+(?:way|distance)\b(?!\s+(?:to|of)\b)", r"\bplenty\b", r"\bloads\b", r"\ba\s+(?:fair\s+)?whack\b",
    r"\bheaps\b", r"\ba\s+long\s+way\b",
)

# ------------------------------------------------------------------------------ filler & safety
#: Hesitation sounds, the one list (speech drops them before anything is read; the readings that come after
#: count them as pauses too): no meaning in any position. ("em" is how Irish and Scottish speech is written for
#: "um"; the pronoun "'em" keeps its apostrophe and is read as "them" first, see ``speech.ELIDED``.)
HESITATIONS: Final = frozenset({
    "uh", "uhh", "uhhh", "uhhhh", "um", "umm", "ummm", "uhm", "uhmm", "hmm", "hmmm", "hm", "er", "erm", "err",
    "ah", "ahh", "eh", "mmm", "mhm", "huh", "ehm", "ooh", "oooh", "ohh", "aah", "phew", "hmph", "em", "emm",
})
#: The same sounds drawn out to any length ("ummmm", "uhhhhh"), as a regex: filler wherever they stand (the side
#: talk reader knows more sounds, which are words elsewhere: "oh", "wow").
HESITATION_SOUNDS: Final = r"um+|uh+|er+m?|hmm+"
#: Words that put instructions in order, the one list, read in three ways:
#: ``SEQUENCE_WORDS``: with one of them in a prompt, the same instruction said twice is meant twice ("turn left 90
#: degrees, then turn left 90 degrees"; ``translator``); ``ORDER_WORDS``: those and the words that join or count
#: instructions: between a turn and a turn to the other side, any of them says both are meant ("turn left, later,
#: turn right"; ``restarts``); ``LATE_FILLER_PATTERNS`` (below): the ones read as nothing once a clause's elements
#: are read ("first" may be an ordinal, "and" may join the two elements of "between"; ``parser``).
SEQUENCE_WORDS: Final = ("then", "after that", "afterwards", "next", "followed by")
ORDER_WORDS: Final = (*SEQUENCE_WORDS, "after", "later", "subsequently", "second", "secondly", "plus", "also", "too",
                      "and", "den", "n", "followed")
#: What people call the robot when they speak to it ("robot", "buddy"): filler wherever said
#: ("dear robot" too; the side talk reader adds radio call words, which are words elsewhere).
ROBOT_NAMES: Final = ("robot", "robo", "buddy", "mate")

#: Politeness and filler, removed before reading (consumed, never "unread").
FILLER_PATTERNS: Final = (
    r"\b(?:would|do|will)\s+you\s+(?:please\s+)?mind\b",
    r"\b(?:could|can|would|will|might)\s+(?:you|u)(?:\s+please)?(?:\s+kindly)?\b",
    r"\b(?:i(?:\s+would|\s+will)?|we(?:\s+would)?)\s+(?:like|love|want|need|wish)\s+(?:you\s+)?(?:to\s+)?",
    r"\b(?:i|we)\s+(?:want|need)\s+(?:you\s+)?(?:to\s+)?", r"\bplease\b", r"\bpls\b", r"\bplz\b",
    r"\bkindly\b", r"\bthanks?(?:\s+you)?(?:\s+so\s+much|\s+a\s+lot)?\b", r"\bthank\s+you\b",
    r"\bcheers\b", r"\bonly\b",
    # "a distance of two metres", "by an angle of forty-five degrees": the words that announce the amount
    r"\b(?:(?:for|by|over|through)\s+)?a\s+distance\s+of\b", r"\b(?:(?:by|through)\s+)?an\s+angle\s+of\b",
    r"\bbe\s+(?:a\s+(?:dear|love|darling|star|sweetheart|good\s+robot)|so\s+kind)\s+(?:and|as\s+to)\b",
    r"\bdo\s+me\s+a\s+favou?r(?:\s+and)?\b", r"\b(?:lol|lmao|rofl|haha+|hehe+|omg|btw|tbh)\b", r"\b(?:hey|hi|hello|ok(?:ay)?|alright|all\s+right|right\s+then|so|well|now|" + HESITATION_SOUNDS + r")\b",
    r"\b(?:dear\s+)?" + ROBOT_NAMES[0] + r"\b", *(rf"\b{name}\b" for name in ROBOT_NAMES[1:]), r"\bfirst\s+of\s+all\b",
    r"\bto\s+begin(?:\s+with)?\b", r"\bstart\s+by\b", r"\bbegin\s+by\b", r"\bjust\b", r"\balso\b",
    r"\bfor\s+me\b", r"\bif\s+you\s+(?:can|could|would|do\s+not\s+mind|please)\b", r"\bgo\s+ahead\s+and\b",
    r"\bwhen\s+you\s+(?:are\s+ready|can|get\s+a\s+chance)\b", r"\blet\s+us\b", r"\blets\b",
    r"\bi\s+(?:think|guess|believe|suppose)\b", r"\bmaybe\b", r"\bperhaps\b", r"\bright\s+(?:now|away)\b",
    r"\bimmediately\b", r"\bquickly\b", r"\bslowly\b", r"\bcarefully\b", r"\bsafely\b", r"\bgently\b(?=.*\b(?:to|through|towards)\b)",
    r"\bthen\b", r"\bafter\s+that\b", r"\bafterwards\b", r"\bfinally\b", r"\blastly\b",
    r"\byourself\b(?!\s+(?:to|in|at|by|next))", r"\bagain\b", r"\bsoon\b", r"\bat\s+once\b", r"\bfor\s+a\s+moment\b",
    r"\bwhile\s+avoiding\s+(?:the\s+|any\s+)?(?:obstacles?|walls?|objects?|things?|collisions?)\b",
    r"\bavoiding\s+(?:the\s+|any\s+)?(?:obstacles?|walls?|objects?|things?|collisions?)\b",
    r"\bwithout\s+(?:hitting|touching|bumping\s+into|crashing\s+into|colliding\s+with|running\s+into)\s+"
    r"(?:the\s+|any\s+|a\s+)?(?:\w+\s+)?(?:walls?|obstacles?|objects?|things?|boxes?|anything|doors?|doorframes?|furniture)\b",
    r"\bonce\s+(?:you\s+are\s+|you\s+get\s+|you\s+have\s+got\s+|you\s+have\s+)?(?:there|through|done|finished|arrived)\b",
    r"\bwhen\s+you\s+(?:get|are)\s+there\b", r"\bof\s+the\s+map\b", r"\b(?:to|until|till|up\s+to)\s+(?:the|its)\s+(?:very\s+)?end\b(?!\s+of)", r"\b(?:until|till|til|up\s+to\s+where)\s+(?:it|the\s+wall|the\s+hallway|the\s+corridor|the\s+hall|that|"
    r"this)\s+(?:ends|stops|finishes|runs\s+out|is\s+over|comes\s+to\s+an\s+end)\b", r"\bto\s+the\s+end\s+of\s+it\b", r"\bwhen\s+(?:done|finished)\b", r"\bthere\s+you\s+go\b",
    r"\b(?:okay|ok)\s+(?:robot|so)\b", r"\bnice\s+and\s+(?:slow|easy)\b", r"\bat\s+a\s+slow\s+pace\b",
    r"\bover\s+there\b(?=.*\b(?:to|through)\b)", r"\bmy\s+friend\b", r"\bsir\b", r"\bmister\b",
    r"\bwhat\s+i\s+want\s+is\s+(?:for\s+you\s+)?(?:to\s+)?", r"\bdo\s+me\s+a\s+favou?r\s+and\b",
    r"\bi\s+(?:would\s+)?appreciate\s+(?:it\s+)?if\s+you\s+(?:would|could)?\b", r"\byou\s+(?:should|must|need\s+to|have\s+to|can|may)\b",
    # "start moving ten feet", "begin to turn left": the aspect verb says when the motion begins, not where
    r"\b(?:start|begin)\s+(?:to\s+)?(?=\w+ing\b|(?:move|go|drive|turn|rotate|head|back|reverse|roll)\b)",
    r"\bmake\s+sure\s+(?:to|you)\b", r"\btry\s+(?:to|and)\b", r"\btry\s+(?=\w+ing\b)", r"\bplease\s+do\b", r"\bgo\s+on\b(?=\s+and\b)",
    r"\bfrom\s+(?:here|there|where\s+you\s+are(?:\s+now)?)\b", r"\bstarting\s+from\s+here\b",
    # a name for the robot said in passing ("turn around, silly")
    r"\b(?:you\s+)?(?:silly|sweetie|dummy|little\s+guy|little\s+buddy)(?:\s+(?:robot|thing|billy))?\s*$",
    # a greeting or address opening the instruction ("yo turn left", "oi, stop", "bro go forward 3 feet") and a
    # tag or address closing it ("turn left innit", "turn right ya", "back up a bit eh", "go on, man"): they
    # address the listener or ask agreement, never a way, an amount or a place (only at the edges, where they
    # cannot be part of the instruction)
    r"^\s*(?:yo|ay|ey|oi|oy|bro|dude|fam|boss|chief|guv|mate)\b(?!\s*(?:'s|is|are)\b)",
    r"\b(?:innit|init|eh|ya|yah|yeah|yep|bro|dude|fam|man|boss|chief|guv|mate|hey|aye)\s*[?!.]*\s*$",
    # "there" said after the place it points at ("the fourth door on the left side there"): pointing while
    # speaking, no second place
    r"(?:" + "|".join(rf"(?<=\b{w})" for w in ("left", "right", "side", "door", "doorway", "room", "corner", "wall",
                                              "one", "hallway", "corridor", "obstacle", "area", "gap", "passage"))
    + r")\s+there\s*$",
    # "there" ending a turn on the spot or a move whose amount is said ("turn around there", "go forward four feet
    # there", "back up a bit there"): Irish and British speech ends an instruction with it, as "now"; the turn or
    # the amount already says where the robot ends, so it names no place ("go back there", "go there" still do)
    r"(?:" + "|".join(rf"(?<=\b{w})" for w in ("around", "round", "feet", "foot", "metres", "meters", "metre", "meter",
                                              "yards", "yard", "inches", "inch", "degrees", "degree", "bit", "little",
                                              "touch", "tad"))
    + r")\s+there\s*$",
    # how fast, said of the motion ("real quick", "nice and quick"): the robot keeps its safe speed
    r"\b(?:real|really|very|nice\s+and|super)\s+(?:quick|quickly|fast|slow|slowly)\b",
)

#: Phrases that mention walls or obstacles only to avoid them: removed before the safety check.
SAFE_AVOIDANCE_PATTERNS: Final = (
    # a worry is no request: "I don't want to crash it", "careful not to bump into anything"
    r"\b(?:i|we)\s+(?:do\s+not|dont)\s+want\s+(?:you\s+|it\s+|us\s+)?to\s+(?:crash|hit|bump|collide|smash|run\s+into)\b"
    r"(?:\s+(?:it|into\s+(?:it|anything|something|the\s+\w+)|anything|something))?",
    r"\b(?:careful|make\s+sure|be\s+sure)\s+(?:not\s+to|you\s+do\s+not|that\s+you\s+do\s+not)\s+(?:crash|hit|bump|collide|smash|"
    r"run\s+into)\b(?:\s+(?:into\s+)?(?:it|anything|something|the\s+\w+))?",
    r"\bwithout\s+(?:crashing|colliding|bumping)(?:\s+into\s+(?:it|anything|something|the\s+\w+))?\b",
    r"\bwithout\s+(?:hitting|touching|bumping\s+into|crashing\s+into|colliding\s+with|running\s+into)\s+"
    r"(?:the\s+|any\s+|a\s+)?(?:\w+\s+)?(?:walls?|obstacles?|objects?|things?|boxes?|anything|doors?|doorframes?|furniture)\b",
    r"\b(?:while\s+)?avoiding\s+(?:the\s+|any\s+)?(?:obstacles?|walls?|objects?|things?|collisions?)\b",
    r"\b(?:do\s+not|never|don't)\s+(?:hit|bump\s+into|crash\s+into|touch|collide\s+with|run\s+into)\s+"
    r"(?:the\s+|any\s+|a\s+)?(?:\w+\s+)?(?:walls?|obstacles?|objects?|things?|boxes?|anything|doors?|furniture)\b",
)

#: Ordering words read as filler only after the elements and their details (see ``ORDER_WORDS``).
LATE_FILLER_PATTERNS: Final = (r"\bfirst\b", r"\bnext\b", r"\bsecond(?:ly)?\b(?=\s*$)",
                               r"\bto\s+start\b", r"\bstraight\s+away\b")

#: Requests that must never become motion: they are refused as a whole (prompt injection, crashing).
UNSAFE_PATTERNS: Final = (
    r"\bignore\b.{0,40}\b(?:rules?|instructions?|safety|limits?|constraints?|guidelines?|prompt|programming|restrictions?|commands?)\b",
    r"\b(?:disregard|forget|override|bypass|disable|deactivate|switch\s+off|turn\s+off)\b.{0,30}"
    r"\b(?:rules?|instructions?|safety|limits?|constraints?|collision|avoidance|sensors?|restrictions?|brakes?|guidelines?|bumpers?|lidar)\b",
    r"\b(?:full|max(?:imum)?|top|high|highest|maximal|breakneck|ludicrous)\s+speed\b", r"\bas\s+fast\s+as\s+(?:you\s+can|possible)\b",
    r"\b(?:crash|ram|smash|slam|collide|plow|plough|barrel|bash)\w*\b",
    r"\b(?:hit|bump|knock|run)\s+(?:into\s+)?(?:the|a|that|this|any|every|some|somebody|someone|people|person)\b",
    r"\b(?:into|through|against)\s+(?:the\s+|a\s+|that\s+|this\s+)?(?:\w+\s+)?walls?\b(?!\s+and)",
    r"\brun\s+over\b", r"\b(?:hurt|injure|kill|attack|chase|harm)\b", r"\bjailbreak\b", r"\bdeveloper\s+mode\b",
    r"\bdown\s+the\s+stairs\b", r"\boff\s+(?:the|a)\s+(?:edge|cliff|ledge|balcony)\b",
    r"\bpretend\s+(?:you|to)\b", r"(?<!where\s)\byou\s+are\s+now\b", r"\bsystem\s+prompt\b", r"\bno\s+limits\b",
    r"\bspeed\s+limit\b", r"\bunsafe(?:ly)?\b", r"\breckless(?:ly)?\b", r"\bfloor\s+it\b",
    r"\binto\s+(?:the|a|that)\s+(?:obstacle|box|pillar|column|object)\b",
)

#: Verbs of things the robot cannot do (it only drives, turns, stops, explores and reports).
OUT_OF_SCOPE_PATTERNS: Final = (
    r"\bpick\s+(?:\w+\s+)?up\b", r"\bgrab\b", r"\bfetch\b", r"\bcarry\b(?!\s+on\b)", r"\bbring\s+(?:me|us)\s+(?!to\b|back\b)",
    r"\bbring\b(?!\s+(?:me|us)\b)", r"\bmake\s+(?:me|us)\b", r"\bcook\b", r"\bclean\b", r"\bvacuum\b",
    r"\bmop\b", r"\bsweep\b", r"\b(?:open|close)\s+(?:the|a|an|that|this|it|them|your|my|up)\b",
    r"(?<!\bthe\s)(?<!\ba\s)\bclose\s+(?:doors?|doorways?|gates?|windows?)\b",
    r"\bshut\b", r"\bpush\b", r"\blift\b", r"\bpress\b", r"\bsing\b", r"\bdance\b",
    r"\btell\s+(?:me|us)\s+a\s+(?:joke|story)\b", r"\bjoke\b", r"\bplay\b", r"\bcall\b", r"\bphone\b",
    r"\bwater\s+the\b", r"\bwash\b", r"\border\b", r"\bbuy\b", r"\bfeed\b", r"\bthrow\b", r"\bkick\b",
    r"\bdeliver\b", r"\bhand\s+(?:me|over)\b", r"\bgive\s+(?:me|us)\s+(?:a|the|some|my)\s+(?!map\b|path\b|route\b|position\b|location\b|pose\b)"
    r"(?!(?:\w+\s+){0,3}(?:turn|spin|rotation|twirl|u\s+turn|pirouette|one\s+eighty|three\s+sixty|180|360)\b)",
    r"\bturn\s+(?:on|off)\s+(?:the|a)\b", r"\bswitch\s+(?:on|off)\b", r"\bcharge\b", r"\brecharge\b",
    r"\bdock\b", r"\bphoto\b", r"\bpicture\b", r"\btake\s+a\s+(?:photo|picture|selfie)\b", r"\brecord\b",
    r"\bsay\b", r"\bspeak\b", r"\bwrite\b", r"\bread\b", r"\bsend\s+(?:an?\s+)?(?:email|message|text)\b",
    r"\bfly\b", r"\bjump\b", r"\bclimb\b", r"\bleap\b", r"\bvault\b",
    r"\b(?:hop|step|go|get|drive|roll|ride)\s+(?:over|onto|on\s+top\s+of|up\s+on|on\s+to)\s+(?:the|a|that|this)\s+"
    r"(?:\w+\s+)?(?:box|boxes|obstacle|obstacles|object|crate|block|table|chair|sofa|couch|bed|bench|pillar)\b", r"\bswim\b", r"\bwhat\s+time\b", r"\bweather\b",
    r"\bsandwich\b", r"\bcoffee\b", r"\btea\b", r"\bbeer\b", r"\bdrink\b", r"\bfood\b", r"\beat\b",
    r"\bknock\s+on\b", r"\bring\s+the\b", r"\bunlock\b", r"\block\b", r"\bmove\s+the\s+\w+\s+(?:to|out|away|aside)\b",
    r"\bput\s+(?:the|this|that|it|my)\b", r"\bdrop\b", r"\bpour\b", r"\bfold\b", r"\bhelp\s+me\b",
    r"\bfollow\s+(?:me|him|her|them|the\s+person|that\s+person|the\s+man|the\s+woman)\b", r"\bcome\s+here\b",
    r"\bcome\s+to\s+me\b", r"\bfind\s+(?:me|my|him|her|them|someone|somebody|the\s+person)\b",
    r"\bwhat\s+(?:is|are)\s+(?:you|your\s+name|the\s+meaning)\b(?!.*\b(?:position|location|pose|path|route|map|doing)\b)",
    r"\bwho\s+are\s+you\b", r"\bhow\s+are\s+you\b", r"\bcharging\s+station\b", r"\bdance\b",
    r"\bhold\s+(?:the|a|an|that|this|my|our)\s+(?!position\b|place\b|spot\b|location\b|pose\b|heading\b)",
    r"\bwatch\b", r"\bguard\b", r"\bpatrol\b", r"\bsearch\s+for\b", r"\blook\s+for\b", r"\bhide\b",
)

#: "open" is an adjective after these words ("the open door", "through open doors", "the door is
#: open"); anywhere else it is the verb, a thing the robot cannot do ("open door", "please open door").
OPEN_ADJECTIVE_AFTER: Final = frozenset({
    "the", "a", "an", "that", "this", "any", "some", "your", "our", "my", "its", "every", "each", "both", "two",
    "through", "via", "into", "to", "towards", "toward", "past", "beyond", "near", "by", "between", "and", "or",
    "is", "are", "was", "were", "wide", "only", "other", "another", "nearest", "closest", "next", "first",
    "second", "third", "last", "farthest", "furthest", "biggest", "largest", "widest", "left", "right", "same",
})

#: Other floors: the robot drives on the floor its map shows and cannot climb or ride a lift.
OTHER_FLOOR_PATTERNS: Final = (
    r"\bstair(?:s|case|cases|way|ways|well)?\b", r"\b(?:up|down)stairs\b", r"\bescalators?\b",
    r"\belevators?\b", r"\b(?:the|a|an|by)\s+lifts?\b", r"\blifts?\s+(?:to|up|down)\b", r"\bladders?\b", r"\bbasement\b", r"\battic\b",
    r"\b(?:next|upper|lower|ground|first|second|third|fourth|fifth|top|bottom|another|other|different|"
    r"1st|2nd|3rd|4th|5th|above|below)\s+(?:floor|level|storey|story)\b",
    r"\b(?:floor|level|storey|story)\s+(?:up|down|above|below|\d+|one|two|three|four|five)\b",
    r"\b(?:up|down)\s+(?:a|one|the|two|\d+)\s+(?:floor|level|storey|story|flights?)s?\b",
    r"\bflights?\s+of\s+stairs\b",
)

#: Colours and materials: an occupancy grid holds neither, so "the red door" cannot be told apart.
UNKNOWABLE_ADJECTIVES: Final = frozenset({
    "red", "green", "blue", "yellow", "white", "black", "grey", "gray", "brown", "orange", "purple",
    "pink", "beige", "golden", "silver", "dark", "light", "bright", "colourful", "colorful",
    "wooden", "wood", "metal", "metallic", "steel", "iron", "glass", "plastic", "concrete", "brick",
    "stone", "marble", "cardboard", "painted", "shiny", "striped", "tiled", "carpeted", "fabric",
    "leather", "rusty", "old", "modern", "heavy", "blue-ish", "reddish", "greenish",
})

#: Words that negate a step ("don't go through the door"): the step is not run.
NEGATIONS: Final = r"\b(?:do\s+not|dont|never|not|no\s+longer|avoid|refrain\s+from|stop\s+going)\b"

#: Words that may be left over without making the reading doubtful.
#: The words for left, right, straight on / forward, back, stop and no in the languages most often spoken alongside
#: English (as people type them, accents dropped; the recogniser writes them so), with the way each one says. The
#: reading does not read them as instructions: one left unread may be the way the speaker meant ("turn right,
#: izquierda, ninety degrees"; "turn links ninety"), so it is a word of where or how far (``ask.SPATIAL_WORDS``) and
#: the robot asks, unless it says the same way as the instruction next to it (a bilingual speaker saying the way in
#: both languages: "peeche, back side, thirty centimetre": ``translator``). Words that are also common English
#: ("you", "no", "la", "para") are left out: they are read as English.
FOREIGN_WAYS: Final[dict[str, str]] = {
    # Spanish
    "izquierda": "left", "derecha": "right", "adelante": "forward", "atras": "back", "recto": "forward",
    "derecho": "forward", "alto": "stop", "parate": "stop",
    # Portuguese
    "esquerda": "left", "direita": "right", "frente": "forward", "tras": "back", "pare": "stop",
    # French
    "gauche": "left", "droite": "right", "droit": "forward", "avance": "forward", "avancez": "forward",
    "recule": "back", "reculez": "back", "arriere": "back", "arrete": "stop", "arretez": "stop",
    # Italian
    "sinistra": "left", "destra": "right", "avanti": "forward", "indietro": "back", "dritto": "forward",
    "diritto": "forward", "fermo": "stop", "ferma": "stop", "basta": "stop",
    # German and Dutch
    "links": "left", "rechts": "right", "geradeaus": "forward", "vorwaerts": "forward", "vorwarts": "forward",
    "zurueck": "back", "zuruck": "back", "rueckwaerts": "back", "ruckwarts": "back", "stopp": "stop", "nein": "no",
    "rechtdoor": "forward", "vooruit": "forward", "achteruit": "back", "terug": "back", "nee": "no",
    # Polish and Russian
    "lewo": "left", "prawo": "right", "prosto": "forward", "naprzod": "forward", "przodu": "forward", "tylu": "back",
    "stoj": "stop", "nie": "no", "nalevo": "left", "napravo": "right", "pryamo": "forward", "vpered": "forward",
    "nazad": "back", "stoi": "stop", "nyet": "no",
    # Turkish
    "sola": "left", "sag": "right", "saga": "right", "ileri": "forward", "geri": "back", "dur": "stop", "hayir": "no",
    "duz": "forward",
    # Arabic
    "yamin": "right", "yameen": "right", "shimal": "left", "shemal": "left", "yasar": "left", "odam": "forward",
    "amam": "forward", "wara": "back", "ogaf": "stop",
    # Hindi and Urdu
    "baayen": "left", "baen": "left", "daayen": "right", "daen": "right", "seedha": "forward", "sidha": "forward",
    "peeche": "back", "piche": "back", "ruko": "stop", "nahin": "no", "nahi": "no",
    # Japanese and Korean
    "hidari": "left", "migi": "right", "mae": "forward", "ushiro": "back", "massugu": "forward", "tomare": "stop",
    "tomatte": "stop", "iie": "no", "oenjjok": "left", "oreunjjok": "right", "jikjin": "forward", "meomchwo": "stop",
    "aniyo": "no",
    # Mandarin (pinyin)
    "zuo": "left", "zuobian": "left", "youbian": "right", "qianmian": "forward", "houmian": "back", "houtui": "back",
    "tingzhi": "stop",
    # Tagalog, Swahili, Vietnamese
    "kaliwa": "left", "kanan": "right", "diretso": "forward", "deretso": "forward", "hinto": "stop", "tigil": "stop",
    "kushoto": "left", "kulia": "right", "mbele": "forward", "nyuma": "back", "simama": "stop", "hapana": "no",
    "trai": "left", "phai": "right", "thang": "forward", "khong": "no",
    # (Turkish written with its dotless i)
    "hayır": "no",
}
FOREIGN_WAY_WORDS: Final = frozenset(FOREIGN_WAYS)
#: Of those, the words for "no": said alone, they correct as "no" does (``speech.FOREIGN_NO``).
FOREIGN_NO_WORDS: Final = frozenset(w for w, way in FOREIGN_WAYS.items() if way == "no")
#: "A little" / "a bit" and "more" in the same languages (accents dropped, as typed): an amount said small is the
#: contract's small amount in every language ("back up un poquito": 0.15-0.5 m, 10-40 degrees), and "more" after
#: it is "a little more" ("a little bit mas"). Unlike a way word, the reading takes them as the English words: a
#: small amount is bounded, so reading it never moves or turns more than a person would agree to. Words that are
#: also English ("plus", "motto", "duo") or another common word ("jom", "kami", "zara", "etwas") are left out.
FOREIGN_AMOUNTS: Final[dict[str, str]] = {
    **{w: "a little" for w in (
        # Spanish, Portuguese, French, Italian
        "un poco", "un poquito", "poquito", "un poquitito", "poquitito", "tantito", "un tantito",
        "um pouco", "um pouquinho", "pouquinho", "um tiquinho",
        "un peu", "un petit peu", "un tout petit peu",
        "un po", "un poco", "un pochino", "pochino", "un pochettino", "pochettino",
        # German, Dutch, Polish, Russian
        "ein bisschen", "ein bischen", "bisschen", "ein wenig", "ein klein wenig", "ein bisserl",
        "een beetje", "beetje", "een klein beetje", "een stukje", "stukje",
        "troche", "troszke", "troszeczke", "odrobine",
        "nemnogo", "nemnozhko", "chut chut", "chut-chut",
        # Turkish, Arabic, Hindi and Urdu, Persian
        "biraz", "birazcik", "azicik", "shwaya", "shwayya", "shwaiya", "shwai", "shway", "shwy",
        "thoda", "thora", "thoda sa", "thora sa", "thodi", "thodi si", "thoda thoda", "kam kam", "yekam", "yek kam",
        # Japanese, Korean, Mandarin (pinyin), Tagalog, Swahili, Vietnamese, Indonesian and Malay, Greek, Hebrew
        "sukoshi", "chotto", "jogeum", "chogeum", "yidian", "yi dian", "yidiandian", "yidianr",
        "konti", "kaunti", "konting", "kidogo", "mot chut", "chut xiu", "mot it", "sedikit", "sikit", "ligo", "ktsat",
    )},
    **{w: "more" for w in ("mas", "mais", "piu", "mehr", "meer", "wiecej", "bolshe", "daha", "zyada", "jyada")},
}
#: The numbers one to ten, and the halves, in the languages whose speakers most often say an amount in it and again
#: in English ("do meter, two meter forward": Hindi "do" is two; "bir bucuk meter, one and a half": Turkish one and a
#: half). Many are English words too ("do", "on", "ba", "sau"): the reading takes them for a number only where they
#: say again, in a stretch left unread of only numbers and a unit, the amount a step beside them has
#: (``translator``); said alone, the amount is not read, and the robot asks. The halves add to the number before them
#: ("bir bucuk": 1.5); "dedh" and "dhai" are Hindi one and a half and two and a half.
FOREIGN_NUMBERS: Final[dict[str, float]] = {
    # Hindi and Urdu
    "ek": 1, "do": 2, "teen": 3, "tin": 3, "char": 4, "chaar": 4, "paanch": 5, "panch": 5, "chhe": 6, "chhah": 6,
    "saat": 7, "aath": 8, "nau": 9, "das": 10, "dedh": 1.5, "derh": 1.5, "dhai": 2.5, "adha": 0.5, "aadha": 0.5,
    # Turkish
    "bir": 1, "iki": 2, "uc": 3, "dort": 4, "bes": 5, "alti": 6, "yedi": 7, "sekiz": 8, "dokuz": 9, "on": 10,
    "bucuk": 0.5, "yarim": 0.5,
    # Vietnamese
    "mot": 1, "hai": 2, "ba": 3, "bon": 4, "nam": 5, "sau": 6, "bay": 7, "tam": 8, "chin": 9, "muoi": 10, "ruoi": 0.5,
    # Spanish
    "uno": 1, "dos": 2, "tres": 3, "cuatro": 4, "cinco": 5, "seis": 6, "siete": 7, "ocho": 8, "nueve": 9, "diez": 10,
    "medio": 0.5, "y": 0,
}
STOPWORDS: Final = frozenset({
    "the", "a", "an", "to", "you", "your", "yourself", "and", "then", "of", "in", "on", "at", "is",
    "are", "be", "it", "its", "that", "this", "there", "here", "now", "please", "for", "with", "from",
    "up", "me", "us", "we", "i", "my", "our", "so", "just", "also", "again", "way", "over", "all",
    "robot", "ok", "okay", "do", "can", "will", "would", "could", "by", "as", "one", "which", "who",
    "what", "where", "some", "any", "about", "directly", "exactly", "precisely",
    "approximately", "roughly", "nearly", "almost", "or", "that's", "well", "very", "really", "currently", "going", "get", "got", "have", "has",
    "let", "lets", "carefully", "slowly", "quickly", "safely", "smoothly", "gently", "straight",
    "other", "move", "go", "drive", "head", "towards", "toward", "into", "onto", "when",
    "once", "after", "before", "until", "till", "while", "having", "been", "being", "am",
    "were", "was", "should", "must", "may", "might", "shall", "continue", "keep", "stay", "remain",
    "position", "self", "own", "like", "kind", "sort", "spot", "location", "place",
    "point", "area", "side", "part", "bit", "steps", "step", "totally",
    "fully", "completely", "immediately", "soon", "afterward", "afterwards",
    "finally", "first", "second", "lastly", "next", "quick", "slow", "thanks", "thank",
    "hey", "hi", "hello", "sure", "fine", "good", "great", "nice", "cool", "man", "pal", "dude",
    # words of address: Northern English "lad" / "lass", Arabic "habibi" / "habibti" ("my dear")
    "lad", "lass", "habibi", "habibti",
    "they", "their", "them", "those", "these", "if", "than", "how", "far", "long", "whole",
    "entire", "total", "altogether", "approx", "ca",
    "circa", "reached", "reach", "arrived", "arrive",
    "passed", "pass", "gone", "through", "make", "want", "need", "wish", "able",
    # the -ing of the verb already read ("continue moving forward", "keep rolling")
    "moving", "driving", "rolling", "heading", "turning", "rotating", "travelling", "traveling", "proceeding",
    # assent said before an instruction ("yeah, just turn north")
    "yeah", "yes", "yep", "yup",
    # a focus word, as "just" ("go even one metre back": Dutch and German "even" / "eben" is "just"): it never
    # sizes or points a motion ("even further" is read by "further")
    "even",
})

# ------------------------------------------------------------------------------ typos
#: Common misspellings of the words the parser relies on (short words that edit distance misses).
TYPOS: Final[dict[str, str]] = {
    "foward": "forward", "fowards": "forwards", "forwad": "forward", "forwrad": "forward",
    "fordward": "forward", "froward": "forward", "foreward": "forward", "fwd": "forward",
    "rigth": "right", "rihgt": "right", "rite": "right", "riht": "right", "righ": "right",
    "lfet": "left", "letf": "left", "lef": "left", "elft": "left", "dor": "door", "doorr": "door",
    "dorr": "door", "odor": "door", "drs": "doors", "wal": "wall", "wll": "wall", "trun": "turn",
    "tunr": "turn", "tuen": "turn", "trn": "turn", "rotat": "rotate", "roate": "rotate",
    "rotae": "rotate", "nagivate": "navigate", "navgate": "navigate", "naviagte": "navigate",
    "navigte": "navigate", "goto": "go to", "gotta": "go to", "oughta": "should", "shoulda": "should", "hallwya": "hallway",
    "halway": "hallway", "hallwy": "hallway", "corridoor": "corridor", "coridor": "corridor",
    "corrdor": "corridor", "corrider": "corridor", "cornr": "corner", "conrer": "corner",
    "corener": "corner", "obstcle": "obstacle", "obsticle": "obstacle", "obstacel": "obstacle",
    "obstical": "obstacle", "metre": "metre", "meter": "meter", "mtr": "meter", "mtrs": "meters",
    "metrs": "meters", "meteres": "meters", "metres": "metres", "meteers": "meters",
    "degress": "degrees", "degres": "degrees", "degreees": "degrees", "dgrees": "degrees",
    "dergees": "degrees", "nearst": "nearest", "neares": "nearest", "closet": "closest",
    "clostest": "closest", "farest": "farthest", "furthes": "furthest", "biggst": "biggest",
    "bigest": "biggest", "smalest": "smallest", "secnd": "second", "seccond": "second",
    "thrid": "third", "frist": "first", "fisrt": "first", "throught": "through", "thru": "through",
    "throuhg": "through", "trough": "through", "towrds": "towards", "twards": "towards",
    "torwards": "towards", "twoards": "towards", "nxt": "next", "bewteen": "between",
    "betwen": "between", "betweeen": "between", "middel": "middle", "midle": "middle",
    "cetner": "center", "centr": "centre", "stp": "stop", "sotp": "stop", "exlpore": "explore",
    "explor": "explore", "exploer": "explore", "unexplord": "unexplored", "unexplroed": "unexplored",
    "backwrd": "backward", "bakward": "backward", "backwords": "backwards", "bck": "back",
    "opposit": "opposite", "oposite": "opposite", "roon": "room", "rom": "room", "romm": "room",
    "bix": "box", "bos": "box", "mvoe": "move", "mvove": "move", "moev": "move", "mve": "move",
    "og": "go", "goo": "go", "ur": "your", "yor": "your", "youre": "you are",
    "youare": "you are", "whats": "what is", "wheres": "where is", "pls": "please", "plz": "please",
    "dont": "do not", "doesnt": "does not", "alng": "along", "alogn": "along", "folow": "follow",
    "follw": "follow", "fllow": "follow", "passage": "passage", "pasage": "passage",
    "passsage": "passage", "narow": "narrow", "narrrow": "narrow", "doorwya": "doorway",
    "entrence": "entrance", "enterance": "entrance", "grad": "degrees", "quater": "quarter",
    "qaurter": "quarter", "hafl": "half", "hlaf": "half", "aroud": "around", "arround": "around",
    "arond": "around", "cm.": "cm", "mm.": "mm", "m.": "m", "infront": "in front",
    "inbetween": "in between", "nextto": "next to", "alot": "a lot", "abit": "a bit",
    "alittle": "a little", "wherer": "where", "sohw": "show", "shwo": "show", "mpa": "map",
    # chat abbreviations of place words ("go btwn the 2 obstacles", "the rm across the hall")
    "btwn": "between", "btween": "between", "rm": "room", "rms": "rooms", "crnr": "corner",
    "crnrs": "corners",
    # chat spelling and abbreviations of the words that say which way
    "rt": "right", "rght": "right", "lt": "left", "lft": "left", "str8": "straight", "strait": "straight",
    "staight": "straight", "bk": "back", "bwd": "backward", "bkwd": "backward", "bkwds": "backwards",
    "fwrd": "forward", "frwd": "forward", "fwds": "forwards", "yr": "your", "thx": "thanks",
    "acw": "anticlockwise", "aprox": "approximately", "abt": "about", "lil": "little", "litle": "little",
    "thn": "then", "nd": "and", "rly": "really",
    "arnd": "around", "til": "till", "untill": "until", "b4": "before", "shw": "show",
    "niner": "nine", "wru": "where are you", "wya": "where are you", "nrth": "north", "noth": "north", "nort": "north",
    "souht": "south", "suoth": "south", "wset": "west", "esat": "east",
    # Scots as a recogniser writes it ("turn tae yer left", "can ye tell me where ye are", "oot the way",
    # "aye"): the same words of general English, said in a variety of it
    "tae": "to", "yer": "your", "ye": "you", "oot": "out", "aye": "yes", "gonnae": "going to", "intae": "into",
    "ontae": "onto", "yersel": "yourself", "yerself": "yourself", "wantae": "want to", "dinnae": "do not",
    "doon": "down", "o'": "of",
    # Yorkshire and other Northern English dialect words ("forrard ten foot", "turn reet", "back up nobbut a bit",
    # "get thisen to t' door"): the same words of general English ("thee" / "tha", the pronouns, are read in
    # ``normalize``: spelt so, they may also be a slip for "the")
    "reet": "right", "forrard": "forward", "forrards": "forwards", "thi": "your", "thisen": "yourself",
    "thysen": "yourself", "nobbut": "only", "t'": "the", "an'": "and",
    # Gulf and Levantine Arabic "shwayya" (also spelt "shwaya", "shwaiya"), said inside English as "a little"
    "shwayya": "a little", "shwaya": "a little", "shwaiya": "a little",
}

#: Words that typo repair may aim at (edit distance 1, words of at least five letters).
TYPO_TARGETS: Final = frozenset({
    "forward", "forwards", "backward", "backwards", "right", "left", "door", "doors", "doorway",
    "wall", "walls", "room", "rooms", "hallway", "corridor", "corner", "corners", "obstacle",
    "obstacles", "passage", "narrow", "unexplored", "unknown", "unmapped", "navigate", "rotate",
    "turn", "move", "drive", "follow", "along", "towards", "toward", "through", "between", "middle",
    "centre", "center", "opposite", "nearest", "closest", "farthest", "furthest", "biggest",
    "largest", "smallest", "widest", "narrowest", "first", "second", "third", "fourth", "fifth",
    "meter", "meters", "metre", "metres", "degrees", "degree", "centimeters", "centimetres",
    "millimeters", "millimetres", "explore", "entrance", "opening", "frontier", "region",
    "around", "stop", "halt", "where", "position", "location", "please", "quarter", "half",
    "clockwise", "counterclockwise", "anticlockwise", "beside", "behind", "front", "ahead",
    "slightly", "little", "proceed", "approach", "enter", "pillar",
    "object", "doorframe", "constriction", "bottleneck", "passageway", "straight", "other", "side", "next", "seventh", "eighth", "ninth", "tenth", "sixth", "twenty", "thirty",
    "forty", "fifty", "sixty", "seventy", "eighty", "ninety", "hundred", "three", "seven",
    "eight", "eleven", "twelve", "inches", "feet",
})

#: Real words one edit away from a vocabulary word: never "repaired" ("among" is not "along").
NOT_TYPOS: Final = frozenset({
    "among", "alone", "mother", "halfway", "hallways", "seconds", "second", "minutes", "minute", "riddle", "fiddle",
    "lights", "nights", "rights", "sights", "fights", "others", "cornea", "corned", "rotates",
    "behold", "frosty", "stoop", "bottles", "toward", "towards", "straighten", "meters", "metres",
    "centers", "centres", "turned", "turning", "rooms", "doors", "walls", "corners", "throw",
    "though", "thorough", "thought", "tough", "bought", "father", "farther", "further", "closer",
    "sixths", "eights", "eighty", "fifth", "fifty", "fourth", "forty", "fourty", "nearer",
    "navigator", "explorer", "explored", "exploring", "follows", "follower", "middles", "cold",
    # "a fair bit" is a large amount (it asks how far), not "far"
    "fair",
})
