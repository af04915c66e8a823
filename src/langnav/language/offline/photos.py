"""Photo requests: the robot has no camera (README "No camera"). A request for a picture, or "what do
you see?", is taken out of its clause; the motion around it is still done, and the reply says what
was left out. "Take a picture to your right" / "of what is behind you" turn that way first: the
turn is the part the robot can do.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Final

_PHOTO_NOUN: Final = (r"(?:pictures?|photos?|photographs?|images?|pics?|snapshots?|snaps?|shots?|visuals?|"
                      r"photo\s+graphs?|selfies?)")
#: The request itself, in its many spoken forms.
PHOTO_RE: Final = re.compile(
    r"\b(?:(?:take|snap|grab|get|capture|send|give|shoot|make|have)\s+(?:me\s+|us\s+)?"
    r"(?:(?:a|an|another|one\s+more|some|the|a\s+new|new|more|one|two|few|a\s+few|couple\s+of|a\s+couple\s+of)\s+)?"
    r"(?:\w+\s+)?" + _PHOTO_NOUN
    + r"|(?:let\s+me|i\s+want\s+to|i\s+would\s+like\s+to|can\s+i)\s+(?:see|get|have)\s+(?:a\s+)?(?:visual|view|look)"
    r"|(?:let\s+me\s+see|show\s+me|tell\s+me|report|(?:i|we)(?:\s+want|\s+would\s+like|'?d\s+like|\s+need|\s+wanna)\s+to\s+(?:see|know))"
    r"\s+what\s+(?:you\s+(?:can\s+)?(?:see|are\s+seeing)|is\s+there|"
    r"is\s+(?:in\s+front|around)(?:\s+of\s+you)?|is(?=\s+(?:behind|to|on|at)\b))"
    r"|what\s+(?:do|can)\s+you\s+see|what\s+are\s+you\s+seeing"
    # "i want to see behind you", "i'd like to look to the left" (learners: "i want see behind")
    r"|(?:i|we)(?:\s+want|\s+would\s+like|'?d\s+like|\s+need|\s+wanna)\s+(?:to\s+)?(?:see|look)"
    r"(?=\s+(?:behind|around|to\s+(?:the|your)|on\s+(?:the|your)|at\s+(?:the|your))\b)"
    # "turn left ninety degrees, i want to see the hallway": seeing a place through the robot is a picture
    # (going there is asked with a verb of going); the map is asked for by name
    r"|(?:i|we)(?:\s+want|\s+would\s+like|'?d\s+like|\s+need|\s+wanna)\s+(?:to\s+)?(?:see|look\s+at)\s+"
    r"(?:the|this|that|it|what|where|how)\b(?![^,.;!?]*\bmap\b)[^,.;!?]*"
    r"|(?:take|have)\s+a\s+look(?:\s+around)?(?=\s*$|\s+(?:to|on)\s+(?:your|the)\s+(?:left|right)\b)"
    r"|(?:turn|switch)\s+on\s+(?:the\s+|your\s+)?(?:video\s+)?camera|(?:start|begin)\s+(?:recording|filming)"
    r"|record\s+(?:a\s+)?video"
    r"|" + _PHOTO_NOUN + r"\s+(?:please|now)?\s*$)\b")
#: What a photo request may say about where to point: the part the robot can do.
_SIDE_RE: Final = re.compile(r"\b(?:to|on|at|of)\s+(?:your|the)\s+(?P<side>left|right)\b")
_BEHIND_RE: Final = re.compile(r"\bbehind(?:\s+(?:you|the\s+robot|yourself)\b|\s*$)")
#: Words around a photo request that only belong to it ("please", "from your location", "in the room").
_PHOTO_LEFTOVER: Final = re.compile(
    r"\b(?:please|now|again|also|too|as\s+well|of\s+(?:it|that|this|what\s+is\s+there|the\s+area|the\s+room)|"
    r"from\s+(?:your|this|the)\s+(?:current\s+)?(?:location|position|spot|place|point\s+of\s+view)|from\s+(?:here|there)|"
    r"in\s+(?:the|this)\s+(?:room|area)|for\s+me|and|then|can\s+you|could\s+you|will\s+you|would\s+you|"
    r"(?:i\s+)?(?:would|want|need)\s+(?:you\s+)?(?:to|like)?|you|robot|okay|ok|go\s+ahead|so|what\s+is|"
    r"let\s+me\s+(?:see|know)|with\s+(?:your|the)\s+camera|one|more|another|a|an|the|of|hi|hey|hello|great|good|"
    r"thanks|thank\s+you)\b|[^\w\s]")


#: Request words left in front of the photo's object ("can you [take a picture] of ...").
_REQUEST_START: Final = re.compile(r"^(?:(?:hi|hey|okay|ok|robot|so|please|can|could|will|would|you|and|now|just)\b[\s,]*)+")
#: The object of a photo request ("of X", "in front of you").
_OBJECT_RE: Final = re.compile(r"^(?:(?:please|and|now)\s+|,\s*)*(?:of|in\s+front|at)\b")
#: A motion verb after the object: the rest is an instruction of its own ("... of the door then turn left").
_MOTION_VERB_RE: Final = re.compile(r"\b(?:move|go|turn|rotate|drive|head|face|pivot|back\s+up|proceed)\b")


@dataclass(frozen=True)
class PhotoReading:
    """A clause without its photo request: ``rest`` is what is left to read (a turn it implies, or
    other words), or empty when the clause was only the request."""

    rest: str
    asked: bool


def without_photo(clause: str) -> PhotoReading:
    """Take the photo request out of ``clause`` (lower-cased, plain speech)."""
    text = " ".join(clause.lower().replace("what's", "what is").split())
    m = PHOTO_RE.search(text)
    if m is None:
        return PhotoReading(clause, False)
    rest = " ".join((text[:m.start()] + " " + text[m.end():]).split()).strip(" ,;")
    rest = re.sub(r"(?:\s+(?:and|then|and\s+then))+$", "", rest)
    rest = _REQUEST_START.sub("", rest)
    if _OBJECT_RE.match(rest) is not None and _MOTION_VERB_RE.search(rest) is None:
        # "of what is in front of you", "of this room", "of the entire wall": what to photograph;
        # only a side or "behind" in it asks for a turn first
        rest = (" behind you" if _BEHIND_RE.search(rest) else "") + (
            f" to your {s.group('side')}" if (s := _SIDE_RE.search(rest)) else "")
        rest = rest.strip()
    side = _SIDE_RE.search(rest)
    behind = _BEHIND_RE.search(rest)
    remaining = _PHOTO_LEFTOVER.sub(" ", _BEHIND_RE.sub(" ", _SIDE_RE.sub(" ", rest)))
    if " ".join(remaining.split()) == "":
        if behind is not None:
            return PhotoReading("turn around", True)
        if side is not None:
            return PhotoReading(f"turn {side.group('side')}", True)
        return PhotoReading("", True)
    return PhotoReading(rest, True)
