#!/usr/bin/env python3
"""Draw the held-out buildings and write the held-out cases, with every expectation computed.

    .venv/bin/python tools/make_heldout_maps.py [--out src/langnav/eval/heldout]

Writes ``maps/{flat,office,partial}.{yaml,pgm}`` and ``cases.jsonl`` under ``--out``. The
expected regions follow ../shared/bench/README.md ("Meaning of the words") and are derived
from the geometry drawn here and from the drawn arrays (room centroids, frontiers), never from
what langnav's parser or grounding does. See ``src/langnav/eval/heldout/README.md``.
"""

from __future__ import annotations

import argparse
import json
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Final

import numpy as np
import yaml
from scipy import ndimage

from langnav.maps.draw import DEFAULT_WALL_M, MapBuilder
from langnav.maps.grid import FREE, UNKNOWN
from langnav.maps.io import save_map

RESOLUTION_M: Final = 0.05
#: README: "to a door" ends within 0.75 m of its centre; "between" within 0.75 m of the midpoint;
#: "middle" within 0.75 m of the free-space centroid.
DOOR_R_M: Final = 0.75
BETWEEN_R_M: Final = 0.75
MIDDLE_R_M: Final = 0.75
#: README: a corner is reached within 1.0 m of the meeting point of its two walls.
CORNER_R_M: Final = 1.0
#: README: "next to X" ends within 1.0 m of X's edge; "along" keeps within 1.0 m of the wall.
NEXT_TO_M: Final = 1.0
ALONG_M: Final = 1.0
#: README: "through" ends on the far side within 2 m of the door or passage.
THROUGH_M: Final = 2.0
#: README: "towards" an unexplored area ends within *about* 1.0 m of its frontier; the 0.1 m is
#: the "about" (two cells), so that a pose one cell beyond a metre is not a miss.
TOWARDS_M: Final = 1.1
#: Frontier cells are represented by circles centred on a subset of them, no two kept cells
#: closer than this; the union misses the true 1.1 m buffer by under 1 cm.
FRONTIER_SPACING_M: Final = 0.2
#: Moves: 1 m = 33 steps of 3 cm (README); a spoken distance is met within -7 % / +7 %.
STEP_M: Final = 0.03
MOVE_TOL: Final = 0.07
STEP_DEG: Final = 10.0
#: README: "a little" is 0.15-0.5 m or 10-40 degrees.
LITTLE_MOVE: Final = (5, 17)
LITTLE_TURN: Final = (1, 4)
#: Vertices of a full circle when a round region must be a polygon (to be clipped); inscribed,
#: so the polygon never claims more than the README allows.
ARC_VERTICES: Final = 48

Point = tuple[float, float]
Region = dict[str, Any]


# ------------------------------------------------------------------------------ geometry
@dataclass(frozen=True)
class Rect:
    x0: float
    y0: float
    x1: float
    y1: float

    @property
    def centre(self) -> Point:
        return ((self.x0 + self.x1) / 2, (self.y0 + self.y1) / 2)

    @property
    def corners(self) -> list[Point]:
        return [(self.x0, self.y0), (self.x1, self.y0), (self.x1, self.y1), (self.x0, self.y1)]

    @property
    def area(self) -> float:
        return (self.x1 - self.x0) * (self.y1 - self.y0)


@dataclass(frozen=True)
class Door:
    """An opening; ``centre`` is the middle of the opening in the wall's mid-line."""

    centre: Point
    width_m: float
    vertical_wall: bool  # True: the wall runs north-south (door_v)


def r3(v: float) -> float:
    return round(float(v), 3)


def circle(c: Point, r: float) -> Region:
    return {"circle": [r3(c[0]), r3(c[1]), r3(r)]}


def polygon(pts: Sequence[Point]) -> Region:
    return {"polygon": [[r3(x), r3(y)] for x, y in pts]}


def rect_poly(r: Rect) -> list[Point]:
    return r.corners


def clip_half_plane(poly: list[Point], n: Point, d: float) -> list[Point]:
    """Keep the part of a convex polygon where n . p >= d (Sutherland-Hodgman)."""
    out: list[Point] = []
    k = len(poly)
    for i in range(k):
        p, q = poly[i], poly[(i + 1) % k]
        fp = n[0] * p[0] + n[1] * p[1] - d
        fq = n[0] * q[0] + n[1] * q[1] - d
        if fp >= 0:
            out.append(p)
        if (fp >= 0) != (fq >= 0):
            t = fp / (fp - fq)
            out.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
    return out


def clip_rect(poly: list[Point], r: Rect) -> list[Point]:
    for n, d in (((1.0, 0.0), r.x0), ((-1.0, 0.0), -r.x1), ((0.0, 1.0), r.y0), ((0.0, -1.0), -r.y1)):
        poly = clip_half_plane(poly, n, d)
    return poly


def disc_poly(c: Point, r: float) -> list[Point]:
    return [(c[0] + r * math.cos(2 * math.pi * i / ARC_VERTICES),
             c[1] + r * math.sin(2 * math.pi * i / ARC_VERTICES)) for i in range(ARC_VERTICES)]


def rounded_rect(r: Rect, pad: float) -> list[Point]:
    """The points within ``pad`` of a rectangle, as an inscribed polygon (rounded corners)."""
    pts: list[Point] = []
    quarter = ARC_VERTICES // 4
    for (cx, cy), a0 in (((r.x1, r.y0), -90.0), ((r.x1, r.y1), 0.0), ((r.x0, r.y1), 90.0), ((r.x0, r.y0), 180.0)):
        for i in range(quarter + 1):
            a = math.radians(a0 + 90.0 * i / quarter)
            pts.append((cx + pad * math.cos(a), cy + pad * math.sin(a)))
    return pts


def through_region(door: Door, towards: Point, space: Rect) -> Region:
    """Far side of ``door`` (the side ``towards`` lies on), within 2 m of its centre, inside ``space``."""
    cx, cy = door.centre
    if door.vertical_wall:
        sign = 1.0 if towards[0] > cx else -1.0
        n = (sign, 0.0)
    else:
        sign = 1.0 if towards[1] > cy else -1.0
        n = (0.0, sign)
    face = n[0] * cx + n[1] * cy + DEFAULT_WALL_M / 2  # the far face of the wall
    poly = clip_half_plane(disc_poly(door.centre, THROUGH_M), n, face)
    return polygon(clip_rect(poly, space))


def beyond_line_region(mid: Point, n: Point, space: Rect) -> Region:
    """Past a line through ``mid`` with normal ``n`` (the travel direction), within 2 m of ``mid``."""
    poly = clip_half_plane(disc_poly(mid, THROUGH_M), n, n[0] * mid[0] + n[1] * mid[1])
    return polygon(clip_rect(poly, space))


def corner_region(space: Rect, pt: Point) -> Region:
    """Within 1.0 m of a corner of ``space``, on the room's side of its walls."""
    return polygon(clip_rect(disc_poly(pt, CORNER_R_M), space))


def next_to_rect(ob: Rect, space: Rect) -> Region:
    return polygon(clip_rect(rounded_rect(ob, NEXT_TO_M), space))


def next_to_disc(c: Point, radius: float, space: Rect) -> Region:
    return polygon(clip_rect(disc_poly(c, radius + NEXT_TO_M), space))


def strip(x0: float, y0: float, x1: float, y1: float) -> Region:
    return polygon(rect_poly(Rect(min(x0, x1), min(y0, y1), max(x0, x1), max(y0, y1))))


# ------------------------------------------------------------------------------ commands
def ntp(goal: Region, via: Sequence[Region] = ()) -> dict[str, Any]:
    cmd: dict[str, Any] = {"command": "NavigateThroughPoses", "goal": goal}
    if via:
        cmd["via"] = list(via)
    return cmd


def move(direction: str, metres: float) -> dict[str, Any]:
    n = metres / STEP_M
    return {"command": "Move", "direction": direction,
            "repeat": [math.floor(n * (1 - MOVE_TOL)), math.ceil(n * (1 + MOVE_TOL))]}


def move_steps(direction: str, lo: int, hi: int) -> dict[str, Any]:
    return {"command": "Move", "direction": direction, "repeat": [lo, hi]}


def rotate(direction: str, degrees: float) -> dict[str, Any]:
    n = degrees / STEP_DEG
    rng = [round(n) - 1, round(n) + 1] if degrees >= 60 else [math.floor(n), math.ceil(n)]
    return {"command": "Rotate", "direction": direction, "repeat": rng}


def rotate_steps(direction: str, lo: int, hi: int) -> dict[str, Any]:
    return {"command": "Rotate", "direction": direction, "repeat": [lo, hi]}


def simple(name: str) -> dict[str, Any]:
    return {"command": name}


CLARIFY: Final = "clarify"


# ------------------------------------------------------------------------------ arrays
class Drawn:
    """A drawn building: the builder's array plus helpers that read geometry off it."""

    def __init__(self, name: str, b: MapBuilder) -> None:
        self.name = name
        self.b = b
        self.cells = b.cells
        rows, cols = np.indices(self.cells.shape)
        self.x = b.origin[0] + (cols + 0.5) * b.resolution_m
        self.y = b.origin[1] + (rows + 0.5) * b.resolution_m

    def centroid(self, room: Rect) -> Point:
        """Centroid of the free cells whose centres lie in ``room`` (obstacles, unknown excluded)."""
        m = ((self.cells == FREE) & (self.x >= room.x0) & (self.x <= room.x1)
             & (self.y >= room.y0) & (self.y <= room.y1))
        return float(self.x[m].mean()), float(self.y[m].mean())

    def frontier_region(self, seed: Point) -> Region:
        """Within ~1 m of the frontier of the unexplored area holding ``seed``."""
        unk = self.cells == UNKNOWN
        lab, _ = ndimage.label(unk)
        r = int((seed[1] - self.b.origin[1]) / self.b.resolution_m)
        c = int((seed[0] - self.b.origin[0]) / self.b.resolution_m)
        k = lab[r, c]
        if k == 0:
            raise ValueError(f"{self.name}: seed {seed} is not on unknown space")
        near = ndimage.binary_dilation(lab == k)  # 4-neighbourhood: "next to it"
        front = near & (self.cells == FREE)
        pts = np.column_stack([self.x[front], self.y[front]])
        kept: list[np.ndarray] = []
        for p in pts:
            if all(np.hypot(*(p - q)) >= FRONTIER_SPACING_M for q in kept):
                kept.append(p)
        return {"any": [circle((float(p[0]), float(p[1])), TOWARDS_M) for p in kept]}

    def save(self, out: Path) -> None:
        yaml_path, _ = save_map(self.b.build(f"{self.name}.yaml"), out / "maps" / f"{self.name}.yaml")
        # save_map writes ``origin`` as a block list; map_server files (and the bench's
        # line-based referee, score.py) have it in flow style on one line: rewrite it so.
        doc = yaml.safe_load(yaml_path.read_text(encoding="utf-8"))
        lines = [f"{k}: [{', '.join(repr(float(v)) for v in val)}]" if isinstance(val, list) else f"{k}: {val}"
                 for k, val in doc.items()]
        yaml_path.write_text("\n".join(lines) + "\n", encoding="utf-8")


def door_v(b: MapBuilder, x: float, y: float, w: float) -> Door:
    b.door_v(x, y, w)
    return Door((x, y), w, True)


def door_h(b: MapBuilder, x: float, y: float, w: float) -> Door:
    b.door_h(x, y, w)
    return Door((x, y), w, False)


def room(b: MapBuilder, r: Rect) -> Rect:
    b.room(r.x0, r.y0, r.x1, r.y1)
    return r


Case = dict[str, Any]
CaseMaker = Callable[[str, tuple[float, float, float], str, Any], Case]


def case_maker(prefix: str, map_name: str, cases: list[Case]) -> CaseMaker:
    def add(tag: str, pose: tuple[float, float, float], prompt: str, expect: Any) -> Case:
        c = {"id": f"h-{prefix}-{len([k for k in cases if k['id'].startswith(f'h-{prefix}-')]) + 1:02d}",
             "map": f"maps/{map_name}.yaml", "pose": list(pose), "prompt": prompt,
             "expect": expect, "tags": tag.split()}
        cases.append(c)
        return c
    return add


# ------------------------------------------------------------------------------ building A
def flat(cases: list[Case]) -> Drawn:
    """An L-shaped flat: living room (south-west), N-S corridor (east), bedroom and bathroom
    west of the corridor's north part; the corridor's south door opens onto unexplored space."""
    b = MapBuilder(9.0, 13.0, RESOLUTION_M, origin=(-0.5, -2.0))
    living = room(b, Rect(0.0, 0.0, 6.0, 4.5))
    corridor = room(b, Rect(6.15, 0.0, 7.45, 10.5))
    bedroom = room(b, Rect(2.8, 4.65, 6.0, 8.5))
    bathroom = room(b, Rect(3.8, 8.65, 6.0, 10.5))
    d_living = door_v(b, 6.075, 3.0, 1.0)
    d_bed = door_v(b, 6.075, 6.0, 0.9)
    d_bath = door_v(b, 6.075, 9.6, 0.8)
    d_entry = door_h(b, 7.0, -0.075, 0.8)  # onto unknown: nothing was mapped outside
    sofa = Rect(1.0, 2.6, 3.0, 3.5)  # sofa-sized block, free-standing
    b.box(sofa.x0, sofa.y0, sofa.x1, sofa.y1)
    pillar_c, pillar_r = (4.4, 1.2), 0.2
    b.disc(*pillar_c, pillar_r)
    d = Drawn("flat", b)
    add = case_maker("a", "flat", cases)

    north_in_corr = (6.7, 1.0, 90.0)
    south_in_corr = (6.7, 5.0, 270.0)
    add("door ordinal left", north_in_corr, "Please head to the second doorway on your left.",
        [ntp(circle(d_bed.centre, DOOR_R_M))])
    add("clarify no-such door ordinal", north_in_corr, "Could you go to the fourth door on your left?", CLARIFY)
    add("door behind farthest", south_in_corr, "Head for the farthest doorway behind you.",
        [ntp(circle(d_bath.centre, DOOR_R_M))])
    add("through door ahead right", south_in_corr, "Go through the door ahead of you on the right.",
        [ntp(through_region(d_living, (3.0, 3.0), living))])
    add("clarify through unknown door behind", north_in_corr,
        "Go out through the door behind you.",
        {"any": [CLARIFY, [ntp(circle(d_entry.centre, DOOR_R_M))]]})
    add("towards unexplored", (2.0, 1.0, 0.0), "Drive towards the unexplored area, please.",
        [ntp(d.frontier_region((7.0, -1.5)))])
    add("next-to obstacle ahead", (3.0, 1.2, 0.0),
        "Go next to the small round obstacle in front of you.",
        [ntp(next_to_disc(pillar_c, pillar_r, living))])
    sofa_c = sofa.centre
    add("between obstacles", (5.0, 0.6, 180.0), "Go and wait halfway between the two obstacles here.",
        [ntp(circle(((sofa_c[0] + pillar_c[0]) / 2, (sofa_c[1] + pillar_c[1]) / 2), BETWEEN_R_M))])
    # heading west from (5.0, 0.6): corners ahead are (0, 0) and (0, 4.5); right = north
    add("corner right", (5.0, 0.6, 180.0), "Drive over to the right corner of the room.",
        [ntp(corner_region(living, (0.0, 4.5)))])
    add("corner farthest", (2.0, 0.6, 90.0), "Go to the farthest corner of this room, please.",
        [ntp(corner_region(living, (6.0, 4.5)))])
    add("room on-left", north_in_corr, "Pop into the room to your left.", [ntp(polygon(rect_poly(living)))])
    add("room smallest", (6.7, 2.0, 90.0), "Take me to the smallest room.", [ntp(polygon(rect_poly(bathroom)))])
    add("room biggest", (4.0, 6.5, 0.0), "Which is the largest room? Drive into it.",
        [ntp(polygon(rect_poly(living)))])
    add("middle this-room", (3.2, 5.0, 45.0), "Go to the centre of this room.",
        [ntp(circle(d.centroid(bedroom), MIDDLE_R_M))])
    add("clarify name", (6.7, 8.5, 90.0), "Go into the bathroom, please.", CLARIFY)
    # heading north from (1.5, 1.0): the left wall is the west wall x = 0, which ends at y = 4.5
    add("along wall left", (1.5, 1.0, 90.0), "Drive along the wall on your left.",
        [ntp(strip(0.0, 3.5, ALONG_M, 4.5), via=[strip(0.0, 1.0, ALONG_M, 3.5)])])
    add("move cm words", (5.3, 0.5, 90.0), "Move forward seventy centimetres.", [move("forward", 0.70)])
    add("rotate quarter", (3.5, 1.0, 90.0), "Give me a quarter turn to the right.", [rotate("right", 90)])
    add("multi move rotate", (3.5, 1.0, 90.0), "Back up half a metre, then spin around.",
        [move("backward", 0.5), rotate_steps("any", 17, 19)])
    add("stop", south_in_corr, "Hold it - stop moving!", [simple("Stop")])
    add("query pose", south_in_corr, "Can you tell me where you are at the moment?", [simple("GetRobotPoseLast")])
    living_mid = d.centroid(living)
    add("multi through middle", north_in_corr,
        "First go through the first door on your left, then go to the middle of that room.",
        [ntp(circle(living_mid, MIDDLE_R_M), via=[through_region(d_living, (3.0, 3.0), living)])])
    add("clarify out-of-scope", (3.5, 1.0, 90.0), "Water the plants in the living room.", CLARIFY)
    add("door this-room", (1.5, 1.0, 90.0), "Um, could you drive to this room's doorway?",
        [ntp(circle(d_living.centre, DOOR_R_M))])
    add("door nearest", (5.0, 7.5, 270.0), "Go to the closest door.", [ntp(circle(d_bed.centre, DOOR_R_M))])
    del corridor
    return d


# ------------------------------------------------------------------------------ building B
def office(cases: list[Case]) -> Drawn:
    """An office floor: a N-S hallway with three rooms on each side. West-middle room: a long
    shelf 0.7 m off the west wall (a 3.5 m narrow passage) and a square block. East-middle
    room: an unexplored pocket inside it."""
    b = MapBuilder(14.5, 19.0, RESOLUTION_M, origin=(-0.5, -0.5))
    hall = room(b, Rect(6.0, 0.0, 7.8, 18.0))
    w1 = room(b, Rect(0.0, 0.0, 5.85, 4.85))
    w2 = room(b, Rect(0.0, 5.0, 5.85, 11.35))
    w3 = room(b, Rect(0.0, 11.5, 5.85, 18.0))
    e1 = room(b, Rect(7.95, 0.0, 13.5, 3.0))
    e2 = room(b, Rect(7.95, 3.15, 13.5, 9.85))
    e3 = room(b, Rect(7.95, 10.0, 13.5, 18.0))
    dw1 = door_v(b, 5.925, 3.9, 0.9)
    dw2 = door_v(b, 5.925, 6.0, 0.9)
    dw3 = door_v(b, 5.925, 16.8, 1.0)
    de1 = door_v(b, 7.875, 1.5, 0.8)
    de2 = door_v(b, 7.875, 8.9, 0.9)
    de3 = door_v(b, 7.875, 11.2, 1.0)
    shelf = Rect(0.7, 6.0, 1.0, 9.5)
    block = Rect(3.0, 7.6, 4.2, 8.8)
    for ob in (shelf, block):
        b.box(ob.x0, ob.y0, ob.x1, ob.y1)
    b.unknown(11.0, 4.6, 12.6, 6.0)  # not yet scanned, inside room e2
    d = Drawn("office", b)
    add = case_maker("b", "office", cases)
    del dw2, de1, w3

    north_start = (6.9, 0.5, 90.0)
    south_start = (6.9, 17.0, 270.0)
    add("door ordinal right", north_start, "Go to the second doorway on your right.",
        [ntp(circle(de2.centre, DOOR_R_M))])
    add("door ordinal left", north_start, "Drive up to the third door on the left.",
        [ntp(circle(dw3.centre, DOOR_R_M))])
    add("door nearest left", south_start, "Navigate to the nearest doorway on your left.",
        [ntp(circle(de3.centre, DOOR_R_M))])
    add("through door right", south_start, "Go through the first door on your right.",
        [ntp(through_region(dw3, (3.0, 16.8), Rect(0.0, 11.5, 5.85, 18.0)))])
    add("room smallest", (6.9, 9.0, 90.0), "Find the smallest room and go in there.",
        [ntp(polygon(rect_poly(e1)))])
    add("room biggest", (3.0, 2.0, 0.0), "Go to the biggest room, thanks.", [ntp(polygon(rect_poly(e3)))])
    add("through passage ahead", (0.35, 5.4, 90.0), "Go through the narrow gap ahead of you.",
        [ntp(beyond_line_region((0.35, shelf.y1), (0.0, 1.0), w2))])
    add("between obstacles", (2.5, 6.0, 90.0), "Park between the two obstacles in here.",
        [ntp(circle(((shelf.centre[0] + block.centre[0]) / 2, (shelf.centre[1] + block.centre[1]) / 2),
                    BETWEEN_R_M))])
    # heading west from (4.8, 6.0): right = north; the block is the nearer obstacle on the right
    add("next-to obstacle right", (4.8, 6.0, 180.0), "Go and stand next to the obstacle on your right.",
        [ntp(next_to_rect(block, w2))])
    add("towards unexplored", (6.9, 7.0, 90.0), "Go towards the unexplored area.",
        [ntp(d.frontier_region((11.8, 5.3)))])
    add("room on-right", (6.9, 3.0, 270.0), "Navigate into the room on your right.",
        [ntp(polygon(rect_poly(w1)))])
    add("room on-right", (6.9, 12.0, 90.0), "Enter the room to your right.", [ntp(polygon(rect_poly(e3)))])
    # heading west from (10.5, 1.5) in e1: corners ahead (7.95, 0) and (7.95, 3); left = south
    add("corner left", (10.5, 1.5, 180.0), "Head to the left corner of this room.",
        [ntp(corner_region(e1, (7.95, 0.0)))])
    add("along wall right", (10.5, 1.5, 180.0), "Drive along the right-hand wall until it ends.",
        [ntp(strip(e1.x0, e1.y1 - ALONG_M, e1.x0 + 1.5, e1.y1),
             via=[strip(e1.x0 + 1.5, e1.y1 - ALONG_M, 10.5, e1.y1)])])
    add("opposite side", (10.7, 10.5, 90.0), "Cross to the opposite side of this room.",
        [ntp(polygon(rect_poly(Rect(e3.x0, e3.y1 - (e3.y1 - e3.y0) / 3, e3.x1, e3.y1))))])
    add("multi move rotate words", (6.9, 14.0, 270.0),
        "Move ahead two and a half metres and then turn right by forty-five degrees.",
        [move("forward", 2.5), rotate("right", 45)])
    add("move little", (6.9, 14.0, 270.0), "Scoot a little to the left.", [move_steps("left", *LITTLE_MOVE)])
    add("rotate little", (6.9, 14.0, 270.0), "Turn slightly to your right.", [rotate_steps("right", *LITTLE_TURN)])
    add("door take either", south_start, "Take the first door on your right.",
        {"any": [[ntp(circle(dw3.centre, DOOR_R_M))],
                 [ntp(through_region(dw3, (3.0, 16.8), Rect(0.0, 11.5, 5.85, 18.0)))]]})
    add("rotate words ccw", (6.9, 14.0, 270.0), "Spin a hundred and twenty degrees anticlockwise.",
        [rotate("left", 120)])
    add("query path", south_start, "What route are you taking right now?", [simple("GetCurrentPath")])
    add("query map", south_start, "Send me the occupancy map, please.", [simple("GetMap")])
    add("clarify name", north_start, "Please go to the printer.", CLARIFY)
    add("clarify no-such door ordinal", north_start, "Go to the fourth door on your right.", CLARIFY)
    add("multi through farthest", (3.0, 2.0, 90.0),
        "Go through the door of this room and then go to the farthest door.",
        [ntp(circle(dw3.centre, DOOR_R_M), via=[through_region(dw1, (7.0, 3.9), hall)])])
    add("multi rotate move words", (3.0, 14.0, 0.0),
        "Rotate to the left by a quarter turn, then roll forward eighty centimetres.",
        [rotate("left", 90), move("forward", 0.8)])
    add("middle this-room", (9.0, 4.0, 0.0), "Could you go to the middle of the room you're in?",
        [ntp(circle(d.centroid(e2), MIDDLE_R_M))])
    add("clarify out-of-scope", (6.9, 9.0, 90.0), "Take the stairs up to the next floor.", CLARIFY)
    return d


# ------------------------------------------------------------------------------ building C
def partial(cases: list[Case]) -> Drawn:
    """A partly explored floor: three mapped rooms west of a hall; the hall's east wall has a
    3 m opening beyond which a little was scanned before mapping stopped (frontier). The small
    north room has an unscanned pocket against its west wall."""
    b = MapBuilder(14.0, 13.0, RESOLUTION_M, origin=(-0.5, -0.5))
    c1 = room(b, Rect(0.0, 0.0, 6.0, 4.5))
    c2 = room(b, Rect(0.0, 4.65, 6.0, 8.5))
    c3 = room(b, Rect(0.0, 8.65, 3.5, 11.5))
    hall = room(b, Rect(6.15, 0.0, 10.0, 8.5))
    door_v(b, 6.075, 2.0, 2.0)  # wide opening c1 - hall
    d_c2_hall = door_v(b, 6.075, 7.0, 0.9)
    d_c2_c3 = door_h(b, 1.75, 8.575, 0.9)
    opening = door_v(b, 10.075, 4.0, 3.0)  # wide opening in the hall's east wall
    scanned = Rect(10.15, 2.0, 11.8, 6.0)  # what the sensor saw through it before mapping stopped
    b.free(scanned.x0, scanned.y0, scanned.x1, scanned.y1)
    block = Rect(7.6, 6.0, 8.6, 7.0)
    b.box(block.x0, block.y0, block.x1, block.y1)
    pillar_c, pillar_r = (1.5, 3.3), 0.25
    b.disc(*pillar_c, pillar_r)
    b.unknown(0.0, 9.5, 0.9, 10.5)  # unscanned pocket in c3
    d = Drawn("partial", b)
    add = case_maker("c", "partial", cases)
    outside = d.frontier_region((13.0, 12.0))
    pocket = d.frontier_region((0.4, 10.0))

    add("towards unexplored", (8.0, 1.0, 90.0), "Head towards the unexplored region closest to you.", [ntp(outside)])
    add("towards unexplored nearest", (2.0, 6.5, 0.0), "Head for the nearest unmapped part of the map.",
        [ntp(pocket)])
    add("through door ahead", (2.0, 6.5, 90.0), "Pass through the doorway in front of you.",
        [ntp(through_region(d_c2_c3, (1.75, 10.0), c3))])
    add("middle this-room", (1.0, 6.0, 0.0), "Go to the middle of the room you're in.",
        [ntp(circle(d.centroid(c2), MIDDLE_R_M))])
    add("middle this-room unknown", (3.0, 9.2, 180.0), "Could you move to the centre of this room?",
        [ntp(circle(d.centroid(c3), MIDDLE_R_M))])
    # heading west from (3.0, 9.2) in c3: corners ahead (0, 8.65) and (0, 11.5); right = north
    add("corner right", (3.0, 9.2, 180.0), "Go to the right corner.", [ntp(corner_region(c3, (0.0, 11.5)))])
    add("next-to obstacle ahead", (8.0, 1.0, 90.0), "Get yourself next to the obstacle that's straight ahead.",
        [ntp(next_to_rect(block, hall))])
    add("through opening right", (8.0, 1.0, 90.0), "Go through the wide opening on your right.",
        [ntp(through_region(opening, (11.0, 4.0), scanned))])
    add("next-to round obstacle", (3.0, 2.0, 90.0), "Go next to the round obstacle.",
        [ntp(next_to_disc(pillar_c, pillar_r, c1))])
    add("move decimal words", (3.0, 2.0, 90.0), "Go forward one point two metres.", [move("forward", 1.2)])
    add("rotate around", (3.0, 2.0, 90.0), "Face the other way.", [rotate_steps("any", 17, 19)])
    add("rotate plain", (3.0, 2.0, 90.0), "Turn to the left, please.", [rotate("left", 90)])
    add("multi move rotate move", (8.0, 1.0, 90.0),
        "Go forward three metres, turn right, and go forward one metre.",
        [move("forward", 3.0), rotate("right", 90), move("forward", 1.0)])
    add("move little backward", (3.0, 2.0, 90.0), "Go slightly backwards.", [move_steps("backward", *LITTLE_MOVE)])
    add("move sideways", (8.0, 2.0, 90.0), "Move 2 metres to the left.", [move("left", 2.0)])
    # from (8.0, 1.0) north: the block's south face is at y = 6.0; a pose needs 0.15 m clearance
    safe_steps = math.floor((block.y0 - 0.15 - 1.0) / STEP_M)
    add("clarify move into obstacle", (8.0, 1.0, 90.0), "Move forward ten metres.",
        {"any": [CLARIFY, [move_steps("forward", 1, safe_steps)]]})
    add("clarify out-of-scope", (8.0, 1.0, 90.0), "Pick up the box in front of you.", CLARIFY)
    add("query pose", (8.0, 1.0, 90.0), "Report your current pose.", [simple("GetRobotPoseLast")])
    add("stop", (2.0, 6.5, 0.0), "Halt.", [simple("Stop")])
    add("clarify name", (2.0, 6.5, 0.0), "Go to the laundry room.", CLARIFY)
    add("door nearest left", (9.0, 7.8, 180.0), "Head over to the doorway on your left-hand side.",
        [ntp(circle(d_c2_hall.centre, DOOR_R_M))])
    add("multi through rotate", (2.0, 6.5, 90.0), "Go through the doorway ahead; once you're there, turn around.",
        [ntp(through_region(d_c2_c3, (1.75, 10.0), c3)), rotate_steps("any", 17, 19)])
    add("multi rotate move after", (2.0, 6.5, 0.0), "After you turn left, move forward fifty centimetres.",
        [rotate("left", 90), move("forward", 0.5)])
    # heading north from (0.5, 5.2) in c2: the left wall is x = 0, ending at y = 8.5
    add("follow wall left", (0.5, 5.2, 90.0), "Follow the wall on your left to its end.",
        [ntp(strip(0.0, 7.5, ALONG_M, c2.y1), via=[strip(0.0, 5.2, ALONG_M, 7.5)])])
    add("query map", (2.0, 6.5, 0.0), "Can I see what you've mapped so far?", [simple("GetMap")])
    return d


BUILDINGS: Final = (flat, office, partial)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", type=Path, default=Path(__file__).resolve().parents[1] / "src/langnav/eval/heldout")
    a = ap.parse_args()
    cases: list[Case] = []
    for make in BUILDINGS:
        make(cases).save(a.out)
    lines = [json.dumps(c) for c in cases]
    (a.out / "cases.jsonl").write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"{len(cases)} cases, {len(BUILDINGS)} maps -> {a.out}")


if __name__ == "__main__":
    main()
