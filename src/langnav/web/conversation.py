"""The chat's own answers: help with examples that work on this map, and questions about the map.

Asked for help ("help", "what can you do?"), the robot answers with examples it has checked on
the map it has now: each is planned (read, grounded, validated) and kept only when it would run.
Asked about the map ("how many rooms are there?", "where is door 2?"), it answers from the map
analysis, in the names the map shows. Everything else goes to the translator.

Pure functions of the text, the analysis and the pose (:func:`starter_examples` also takes a
``plan_ok`` callable that says whether a prompt would run).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Sequence
from typing import Final

from langnav.analysis.elements import (
    Door,
    Element,
    ElementKind,
    MapAnalysis,
    NarrowPassage,
    Obstacle,
    Room,
    UnexploredArea,
    element_kind,
    reference_point,
)
from langnav.analysis.identity import label
from langnav.robot.protocol import Pose2D
from langnav.web.feedback import heading_word, place_name

#: Help requests: the word alone, or a question about what the robot can do or be told.
_HELP: Final = re.compile(
    r"^\s*(help( me)?|\?+|what (can|could|do) (you|i) (do|say|ask|type|tell you)|what are (your )?(the )?commands"
    r"|how (do|does) (this|it|i use (this|it|you)) work|how do i use (this|it|you)|what should i (say|type))"
    r"\s*(\?|!|\.)*\s*$", re.I)
#: The element kinds as people name them (singular and plural), for counting and finding.
KIND_WORDS: Final[dict[str, tuple[ElementKind, ...]]] = {
    "room": (ElementKind.ROOM,), "rooms": (ElementKind.ROOM,),
    "hallway": (ElementKind.HALLWAY,), "hallways": (ElementKind.HALLWAY,),
    "corridor": (ElementKind.HALLWAY,), "corridors": (ElementKind.HALLWAY,),
    "space": (ElementKind.ROOM, ElementKind.HALLWAY), "spaces": (ElementKind.ROOM, ElementKind.HALLWAY),
    "door": (ElementKind.DOOR,), "doors": (ElementKind.DOOR,), "doorway": (ElementKind.DOOR,),
    "doorways": (ElementKind.DOOR,),
    "obstacle": (ElementKind.OBSTACLE,), "obstacles": (ElementKind.OBSTACLE,),
    "furniture": (ElementKind.OBSTACLE,),
    "corner": (ElementKind.CORNER,), "corners": (ElementKind.CORNER,),
    "wall": (ElementKind.WALL,), "walls": (ElementKind.WALL,),
    "passage": (ElementKind.NARROW_PASSAGE,), "passages": (ElementKind.NARROW_PASSAGE,),
    "narrow passage": (ElementKind.NARROW_PASSAGE,), "narrow passages": (ElementKind.NARROW_PASSAGE,),
    "unexplored area": (ElementKind.UNEXPLORED,), "unexplored areas": (ElementKind.UNEXPLORED,),
}
_KINDS_RE: Final = "|".join(sorted((re.escape(k) for k in KIND_WORDS), key=len, reverse=True))
_HOW_MANY: Final = re.compile(rf"\bhow many ({_KINDS_RE})\b", re.I)
_WHERE: Final = re.compile(
    rf"^\s*(where|which way)(\s+is|\s+are|'s|’s)\s+(the\s+)?(?P<kind>{_KINDS_RE})\s*(?P<number>\d+)\s*\??\s*$", re.I)
#: Words for the kinds in answers.
_NOUN: Final = {ElementKind.ROOM: "room", ElementKind.HALLWAY: "hallway", ElementKind.DOOR: "door",
                ElementKind.OBSTACLE: "obstacle", ElementKind.CORNER: "corner", ElementKind.WALL: "wall",
                ElementKind.NARROW_PASSAGE: "narrow passage", ElementKind.UNEXPLORED: "unexplored area"}
#: Closer than this, a thing is "right here" (the robot's own footprint and a little more).
NEAR_HERE_M: Final = 0.3
#: Names listed in an answer before "and N more".
LIST_MAX: Final = 6


def is_help(text: str) -> bool:
    return bool(_HELP.match(text))


def _elements(analysis: MapAnalysis, kinds: Sequence[ElementKind]) -> list[Element]:
    return [e for e in analysis.elements if element_kind(e) in kinds]


def _names(items: Sequence[Element]) -> str:
    names = [label(e.id) for e in items[:LIST_MAX]]
    more = len(items) - len(names)
    if more:
        return ", ".join(names) + f" and {more} more"
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def count_answer(text: str, analysis: MapAnalysis) -> str | None:
    """ "I see 3 rooms: room 1, room 3 and room 4." for "how many rooms are there?"."""
    m = _HOW_MANY.search(text)
    if m is None:
        return None
    word = m.group(1).lower()
    kinds = KIND_WORDS[word]
    items = _elements(analysis, kinds)
    noun = _NOUN[kinds[0]] if len(kinds) == 1 else "room and hallway"
    if not items:
        return f"I see no {noun}s on my map yet."
    plural = noun if len(items) == 1 else (noun + "s" if len(kinds) == 1 else "rooms and hallways")
    return f"I see {len(items)} {plural}: {_names(items)}."


def relative_words(pose: Pose2D, point: tuple[float, float]) -> str:
    """ "3.2 m ahead on my left (to the north-east)": from the robot's pose to a point."""
    dx, dy = point[0] - pose.x_m, point[1] - pose.y_m
    dist = math.hypot(dx, dy)
    if dist < NEAR_HERE_M:
        return "right here"
    bearing = (math.degrees(math.atan2(dy, dx) - pose.yaw_rad) + 180.0) % 360.0 - 180.0
    side = "my left" if bearing > 0 else "my right"
    b = abs(bearing)
    if b <= 30:
        where = "ahead of me"
    elif b >= 150:
        where = "behind me"
    elif b < 60:
        where = f"ahead on {side}"
    elif b <= 120:
        where = f"on {side}"
    else:
        where = f"behind me on {side}"
    return f"{dist:.1f} m {where} (to the {heading_word(math.atan2(dy, dx))})"


def where_answer(text: str, analysis: MapAnalysis, pose: Pose2D) -> str | None:
    """ "Door 2 is 3.1 m ahead on my right (south-east of me), between hallway 2 and room 3." """
    m = _WHERE.match(text)
    if m is None:
        return None
    kinds = KIND_WORDS[m.group("kind").lower()]
    number = int(m.group("number"))
    wanted = [e for e in _elements(analysis, kinds) if e.id.rsplit("_", 1)[-1] == str(number)]
    if not wanted:
        names = _elements(analysis, kinds)
        have = f" The ones I know: {_names(names)}." if names else ""
        return f"I don't see {_NOUN[kinds[0]]} {number} on my map.{have}"
    e = wanted[0]
    pt = reference_point(e)
    name = label(e.id)
    text_out = f"{name[:1].upper()}{name[1:]} is {relative_words(pose, pt)}"
    connects: tuple[str, ...] = tuple(getattr(e, "connects", ()))
    if element_kind(e) in (ElementKind.DOOR, ElementKind.NARROW_PASSAGE) and len(connects) == 2:
        text_out += f", between {label(connects[0])} and {label(connects[1])}"
    else:
        where = place_name(analysis, *pt)
        if where and where != name:
            text_out += f", in {where}"
    return text_out + "."


#: A click within this distance of a doorway's or passage's line, or of a corner, means that element
#: (about a finger's width on a phone map of a floor).
PICK_TOLERANCE_M: Final = 0.3


def _segment_distance(p: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> float:
    ax, ay = a
    bx, by = b
    dx, dy = bx - ax, by - ay
    L2 = dx * dx + dy * dy
    t = 0.0 if L2 == 0 else max(0.0, min(1.0, ((p[0] - ax) * dx + (p[1] - ay) * dy) / L2))
    return math.hypot(p[0] - (ax + t * dx), p[1] - (ay + t * dy))


def element_at(analysis: MapAnalysis, x_m: float, y_m: float,
               tolerance_m: float = PICK_TOLERANCE_M) -> Element | None:
    """The element a click at (x, y) points at: doorways and passages first (they are thin), then
    furniture, corners, unexplored areas, and last the room or hallway the point is in."""
    p = (x_m, y_m)
    for d in analysis.doors:
        if _segment_distance(p, d.jambs[0], d.jambs[1]) <= tolerance_m:
            return d
    for n in analysis.narrow_passages:
        if _segment_distance(p, n.ends[0], n.ends[1]) <= max(tolerance_m, n.width_m / 2):
            return n
    for o in analysis.obstacles:
        w, h = o.extent_m
        if abs(x_m - o.centroid[0]) <= w / 2 + tolerance_m / 2 and abs(y_m - o.centroid[1]) <= h / 2 + tolerance_m / 2:
            return o
    for c in analysis.corners:
        if math.dist(c.point, p) <= tolerance_m:
            return c
    for u in analysis.unexplored:
        if math.dist(u.centroid, p) <= max(tolerance_m, math.sqrt(u.area_m2 / math.pi)):
            return u
    return analysis.room_at(x_m, y_m)


def element_card(e: Element) -> dict[str, object]:
    """What the map shows about one element: its name, kind, size and what the robot can do with it
    (each action is a prompt the planner reads)."""
    kind = element_kind(e)
    name = label(e.id)
    size = ""
    actions = [{"label": "Go to it", "prompt": f"go to {name}"}]
    if isinstance(e, Room):
        size = f"{e.area_m2:.0f} m², {e.length_m:.1f} × {e.width_m:.1f} m"
    elif isinstance(e, Door):
        size = f"{e.width_m:.2f} m wide"
        actions.append({"label": "Go through it", "prompt": f"go through {name}"})
    elif isinstance(e, NarrowPassage):
        size = f"{e.width_m:.2f} m wide, {e.length_m:.1f} m long"
        actions.append({"label": "Go through it", "prompt": f"go through {name}"})
    elif isinstance(e, Obstacle):
        size = f"{e.extent_m[0]:.1f} × {e.extent_m[1]:.1f} m"
    elif isinstance(e, UnexploredArea):
        size = f"about {e.area_m2:.0f} m²"
        actions.append({"label": "Explore", "prompt": "explore"})
    actions.append({"label": "Name it…", "name": e.id})
    return {"id": e.id, "name": name, "kind": _NOUN.get(kind, kind.value), "size": size, "actions": actions}


#: A plan "reaches" a named doorway, passage, piece of furniture or unexplored area when one of its
#: goals is this close to it, beyond the element's own half-size (goals stand clear of walls and
#: furniture, and a way through a doorway stops on either side of it).
REACH_MARGIN_M: Final = 1.0


def plan_reaches(goals: Sequence[tuple[float, float]], analysis: MapAnalysis, element_id: str) -> bool:
    """Whether a plan whose navigation goals are ``goals`` goes to the element ``element_id``:
    a goal in the room, or next to the doorway / passage / furniture / unexplored area."""
    try:
        e = analysis.by_id(element_id)
    except KeyError:
        return False
    if isinstance(e, Room):
        return any(analysis.room_at(x, y) is e for x, y in goals)
    size = 0.0
    if isinstance(e, Door | NarrowPassage):
        size = e.width_m / 2
    elif isinstance(e, Obstacle):
        size = math.hypot(*e.extent_m) / 2
    elif isinstance(e, UnexploredArea):
        size = math.sqrt(e.area_m2 / math.pi)
    pt = reference_point(e)
    return any(math.dist(pt, g) <= size + REACH_MARGIN_M for g in goals)


_NAMED: Final = re.compile(rf"\b(?P<kind>{_KINDS_RE})\s+(?P<number>\d+)\b", re.I)


def named_elements(text: str, analysis: MapAnalysis) -> list[str]:
    """Ids of the map elements a text names by their label ("door 2", "room 3")."""
    out: list[str] = []
    for m in _NAMED.finditer(text):
        kinds = KIND_WORDS.get(m.group("kind").lower(), ())
        for e in _elements(analysis, kinds):
            if e.id.rsplit("_", 1)[-1] == m.group("number"):
                out.append(e.id)
    return out


def help_answer(examples: Sequence[str], analysis: MapAnalysis | None = None) -> str:
    shown = "\n".join(f"• {e}" for e in examples)
    names = [label(e.id) for group in ((analysis.doors, analysis.rooms) if analysis is not None else ())
             for e in group[:1]]
    by_name = f"by the names on the map, like {' or '.join(f'“{n}”' for n in names)}, " if names else ""
    return ("Tell me what to do in your own words: where to go (" + by_name +
            "or by what you see: “the nearest door”, “the room on your left”), "
            "how far to move or turn, or to explore. On this map, for example:\n" + shown +
            "\nYou can also ask me about the map (“how many rooms are there?”), click the map to send me "
            "somewhere, and press STOP (or Esc) to halt me at once.")


def answer(text: str, analysis: MapAnalysis | None, pose: Pose2D, examples: Callable[[], Sequence[str]]) -> str | None:
    """The chat's own answer to ``text``, or None when it is for the translator."""
    if is_help(text):
        return help_answer(examples(), analysis)
    if analysis is None:
        return None
    return count_answer(text, analysis) or where_answer(text, analysis, pose)


def candidate_examples(analysis: MapAnalysis | None, pose: Pose2D) -> list[str]:
    """Prompts worth showing on this map, best first (each still has to be checked by planning)."""
    out = ["where are you?"]
    if analysis is None:
        return [*out, "move forward 1 metre", "turn left", "explore"]
    if analysis.doors:
        out += ["go to the nearest door", "go through the door on your left, then turn around",
                "go through the door on your right, then turn around"]
    here = analysis.room_at(pose.x_m, pose.y_m)
    others = sorted((r for r in analysis.rooms if r is not here),
                    key=lambda r: math.dist(r.centroid, (pose.x_m, pose.y_m)))
    out += [f"go to {label(r.id)}" for r in others[:1]]
    if any(u.interior for u in analysis.unexplored):
        out += ["explore", "go to the nearest unexplored area, then come back here"]
    out += [f"go to {label(r.id)}" for r in others[1:2]]
    if analysis.obstacles:
        nearest = min(analysis.obstacles, key=lambda o: math.dist(o.centroid, (pose.x_m, pose.y_m)))
        out.append(f"go to {label(nearest.id)}")
    out += ["how many rooms are there?", "move forward 1 metre, then turn left", "turn around"]
    return out


def starter_examples(analysis: MapAnalysis | None, pose: Pose2D, plan_ok: Callable[[str], bool],
                     limit: int = 5) -> list[str]:
    """Up to ``limit`` prompts that would run on this map from this pose (each one planned)."""
    out: list[str] = []
    sides_done = False
    for text in candidate_examples(analysis, pose):
        if len(out) >= limit:
            break
        if "door on your" in text and sides_done:
            continue  # one of left / right is enough
        if plan_ok(text):
            out.append(text)
            sides_done = sides_done or "door on your" in text
    return out


__all__ = [
    "answer",
    "candidate_examples",
    "count_answer",
    "element_at",
    "element_card",
    "help_answer",
    "is_help",
    "named_elements",
    "plan_reaches",
    "relative_words",
    "starter_examples",
    "where_answer",
]
