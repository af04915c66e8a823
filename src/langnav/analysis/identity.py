"""Stable element identity: an element keeps its id (and so its label, "door 2") while the map
grows and across re-analyses.

An analysis numbers its elements afresh every time (``door_1`` is the first door it happened to
find); a person who read "door 2" on the map a minute ago means the same doorway now. So each new
analysis is matched to the elements remembered from the earlier ones, kind by kind, by position
and overlap, and renamed:

* a new element that is the same thing as a remembered one takes its id;
* an element seen for the first time gets the next number of its kind, never one used before;
* an element that vanished is *retired*: its number is not given to anything else, and if the
  same thing is seen again (a doorway hidden for one scan) it gets its number back.

The same thing, in words a person would use about a building:

* rooms and hallways: most of the floor of the one lies in the other (a room seen better grows;
  two rooms that merge keep the name of the larger part). Rooms and hallways share one numbering
  (the analysis numbers them together), so a space that turns out to be a hallway stays number 3;
* doorways and narrow passages: the centres are closer than half the opening plus a margin (a
  doorway's centre shifts as its jambs get mapped; two doorways are never that close);
* obstacles: the centres are closer than half the furniture's size plus a margin;
* unexplored areas: the centres are closer than the area's radius plus a margin (they shrink as
  the robot maps them);
* walls: the same direction and the same line, overlapping; corners: the same point.

:func:`stable_ids` is pure: the remembered state and a new analysis in, the renamed analysis and
the new state out. References between elements (a door's ``connects``, a wall's ``room``, ...)
are renamed with them.
"""

from __future__ import annotations

import math
import re
import threading
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import Final, TypeVar

import numpy as np

from langnav.analysis.elements import (
    Corner,
    Door,
    Element,
    MapAnalysis,
    NarrowPassage,
    Obstacle,
    Room,
    UnexploredArea,
    Wall,
    reference_point,
)
from langnav.analysis.params import AnalysisParams
from langnav.maps.grid import OccupancyGrid

#: Position tolerance (m) on top of an element's own size: a map refined by a few more scans moves
#: a doorway's jambs, a wall's ends or a piece of furniture's outline by a cell or two, and the
#: analysis' own rounding by a few more; half a metre is far less than the space between two
#: doorways, two corners or two pieces of furniture a person would tell apart.
MATCH_MARGIN_M: Final = 0.5
#: Two spaces are the same when this much of the smaller one's sampled floor lies in the other.
SPACE_OVERLAP_MIN: Final = 0.5
#: Floor points remembered per space (a deterministic sample: enough to measure overlap to 1 %).
SPACE_SAMPLE_POINTS: Final = 256
#: Walls: at most this angle apart (degrees) and this far apart across (m) to be one wall.
WALL_ANGLE_MAX_DEG: Final = 15.0
WALL_OFFSET_MAX_M: Final = 0.3
#: Retired elements remembered per kind (oldest forgotten first; their numbers stay used).
RETIRED_KEEP: Final = 500

E = TypeVar("E", Room, Door, Wall, Corner, Obstacle, NarrowPassage, UnexploredArea)

_ID = re.compile(r"^(?P<prefix>[a-z_]+?)_(?P<number>\d+)$")


def split_id(element_id: str) -> tuple[str, int]:
    """``"door_12"`` -> ``("door", 12)``."""
    m = _ID.match(element_id)
    if m is None:
        raise ValueError(f"element id {element_id!r} is not <kind>_<number>")
    return m.group("prefix"), int(m.group("number"))


def family(element: Element) -> str:
    """The numbering an element's id belongs to (rooms and hallways share one)."""
    if isinstance(element, Room):
        return "space"
    return split_id(element.id)[0]


@dataclass(frozen=True)
class Known:
    """What is remembered of one element: its id and the geometry to recognise it by."""

    id: str
    family: str
    point: tuple[float, float]
    size_m: float = 0.0
    #: spaces: a sample of their floor; walls: their two ends
    points: tuple[tuple[float, float], ...] = ()
    retired: bool = False


@dataclass(frozen=True)
class IdentityState:
    """Every element remembered so far, and the next number of each kind's numbering."""

    known: tuple[Known, ...] = ()
    next_number: Mapping[str, int] = field(default_factory=dict)


def _remember(e: Element) -> Known:
    fam = family(e)
    pt = tuple(float(v) for v in reference_point(e))
    if isinstance(e, Room):
        cells = np.asarray(e.cells_xy, dtype=float).reshape(-1, 2)
        step = max(1, math.ceil(len(cells) / SPACE_SAMPLE_POINTS))
        sample = tuple((float(x), float(y)) for x, y in cells[::step])
        return Known(e.id, fam, (pt[0], pt[1]), math.sqrt(max(e.area_m2, 0.0)), sample)
    if isinstance(e, Door | NarrowPassage):
        return Known(e.id, fam, (pt[0], pt[1]), float(e.width_m))
    if isinstance(e, Obstacle):
        return Known(e.id, fam, (pt[0], pt[1]), float(math.hypot(*e.extent_m)))
    if isinstance(e, UnexploredArea):
        return Known(e.id, fam, (pt[0], pt[1]), 2.0 * math.sqrt(max(e.area_m2, 0.0) / math.pi))
    if isinstance(e, Wall):
        return Known(e.id, fam, (pt[0], pt[1]), e.length_m,
                     ((float(e.start[0]), float(e.start[1])), (float(e.end[0]), float(e.end[1]))))
    return Known(e.id, fam, (pt[0], pt[1]))


def _space_overlap(old: Known, new: Room, analysis: MapAnalysis) -> float:
    """The share of the old space's floor sample that lies in ``new`` (0..1)."""
    if not old.points:
        return 0.0
    pts = np.asarray(old.points, dtype=float)
    rows, cols = analysis.grid.world_to_index(pts[:, 0], pts[:, 1])
    rows, cols = np.asarray(rows, dtype=int), np.asarray(cols, dtype=int)
    inside = (rows >= 0) & (rows < analysis.grid.height) & (cols >= 0) & (cols < analysis.grid.width)
    hits = np.zeros(len(pts), dtype=bool)
    hits[inside] = analysis.labels[rows[inside], cols[inside]] == new.label
    # the old space's share: a room seen better contains the room seen before
    return float(hits.mean())


def _wall_score(old: Known, new: Wall) -> float | None:
    """A distance-like score (smaller is better) when ``new`` is the same wall, else None."""
    if len(old.points) != 2:
        return None
    (ax, ay), (bx, by) = old.points
    ux, uy = bx - ax, by - ay
    length = math.hypot(ux, uy)
    if length == 0:
        return None
    ux, uy = ux / length, uy / length
    nx, ny = new.end[0] - new.start[0], new.end[1] - new.start[1]
    nlen = math.hypot(nx, ny)
    if nlen == 0:
        return None
    cos = abs(ux * nx + uy * ny) / nlen
    if cos < math.cos(math.radians(WALL_ANGLE_MAX_DEG)):
        return None
    mx, my = new.midpoint
    offset = abs(-(mx - ax) * uy + (my - ay) * ux)
    if offset > WALL_OFFSET_MAX_M:
        return None
    # the projections overlap along the wall
    s0 = (new.start[0] - ax) * ux + (new.start[1] - ay) * uy
    s1 = (new.end[0] - ax) * ux + (new.end[1] - ay) * uy
    if max(s0, s1) < 0 or min(s0, s1) > length:
        return None
    return offset + math.dist(old.point, new.midpoint) * 0.1


def _score(old: Known, new: Element, analysis: MapAnalysis) -> float | None:
    """How well a remembered element matches a new one: smaller is better; None = not the same."""
    if isinstance(new, Room):
        share = _space_overlap(old, new, analysis)
        return None if share < SPACE_OVERLAP_MIN else 1.0 - share
    if isinstance(new, Wall):
        return _wall_score(old, new)
    d = math.dist(old.point, reference_point(new))
    mine = _remember(new).size_m
    reach = 0.5 * max(old.size_m, mine) + MATCH_MARGIN_M
    if isinstance(new, Corner):
        reach = MATCH_MARGIN_M
    return d if d <= reach else None


def _candidates(olds: Sequence[Known], news: Sequence[Element], analysis: MapAnalysis) -> list[tuple[int, int]]:
    """(old, new) index pairs that may be the same element, found at once for the whole kind (the
    exact test, :func:`_score`, then runs on these only: a warehouse map has hundreds of walls and
    shelves, and testing every pair one by one would take seconds).

    Spaces: the new spaces the old one's floor sample falls in. Others: centres close enough for
    the most generous reach of the kind (walls: half their lengths apart, plus the offset)."""
    if not olds or not news:
        return []
    if isinstance(news[0], Room):
        by_label = {r.label: j for j, r in enumerate(news) if isinstance(r, Room)}
        out: list[tuple[int, int]] = []
        grid = analysis.grid
        for i, old in enumerate(olds):
            if not old.points:
                continue
            pts = np.asarray(old.points, dtype=float)
            rows, cols = (np.asarray(v, dtype=int) for v in grid.world_to_index(pts[:, 0], pts[:, 1]))
            inside = (rows >= 0) & (rows < grid.height) & (cols >= 0) & (cols < grid.width)
            found = np.unique(analysis.labels[rows[inside], cols[inside]])
            out.extend((i, by_label[int(k)]) for k in found if int(k) in by_label)
        return out
    old_pts = np.asarray([k.point for k in olds], dtype=float)
    new_pts = np.asarray([reference_point(e) for e in news], dtype=float)
    old_size = np.asarray([k.size_m for k in olds], dtype=float)
    new_size = np.asarray([_remember(e).size_m for e in news], dtype=float)
    dist = np.hypot(old_pts[:, None, 0] - new_pts[None, :, 0], old_pts[:, None, 1] - new_pts[None, :, 1])
    if isinstance(news[0], Wall):
        reach = (old_size[:, None] + new_size[None, :]) / 2 + WALL_OFFSET_MAX_M
    else:
        reach = 0.5 * np.maximum(old_size[:, None], new_size[None, :]) + MATCH_MARGIN_M
    ii, jj = np.nonzero(dist <= reach)
    return list(zip(ii.tolist(), jj.tolist(), strict=True))


def _prefix(e: Element) -> str:
    return split_id(e.id)[0]


def stable_ids(previous: IdentityState | None, analysis: MapAnalysis) -> tuple[MapAnalysis, IdentityState]:
    """Rename ``analysis``' elements to the ids they had before (see the module docstring).

    With no previous state the analysis keeps its own ids, and numbering goes on after them.
    Pure: neither argument is changed."""
    elements = analysis.elements
    if previous is None:
        next_number: dict[str, int] = {}
        for e in elements:
            fam = family(e)
            next_number[fam] = max(next_number.get(fam, 1), split_id(e.id)[1] + 1)
        known = tuple(_remember(e) for e in elements)
        return analysis, IdentityState(known, next_number)

    state = previous
    next_number = dict(state.next_number)
    mapping: dict[str, str] = {}
    by_family: dict[str, list[Element]] = {}
    for e in elements:
        by_family.setdefault(family(e), []).append(e)
    remembered: dict[str, list[Known]] = {}
    for k in state.known:
        remembered.setdefault(k.family, []).append(k)

    for fam, news in by_family.items():
        olds = remembered.get(fam, [])
        # (retired, score, -size, old, new): live elements first, then the best match, then the
        # larger of two equally good (two rooms merged keep the larger one's name)
        pairs: list[tuple[bool, float, float, int, int]] = []
        for i, j in _candidates(olds, news, analysis):
            s = _score(olds[i], news[j], analysis)
            if s is not None:
                pairs.append((olds[i].retired, s, -olds[i].size_m, i, j))
        pairs.sort()
        used_old: set[int] = set()
        for _, _, _, i, j in pairs:
            new = news[j]
            if new.id in mapping or i in used_old:
                continue
            used_old.add(i)
            number = split_id(olds[i].id)[1]
            mapping[new.id] = f"{_prefix(new)}_{number}"
        for new in sorted(news, key=lambda e: split_id(e.id)[1]):
            if new.id not in mapping:
                number = next_number.get(fam, 1)
                next_number[fam] = number + 1
                mapping[new.id] = f"{_prefix(new)}_{number}"

    renamed = rename(analysis, mapping)
    live = {e.id for e in renamed.elements}
    new_known = [_remember(e) for e in renamed.elements]
    live_numbers = {(family(e), split_id(e.id)[1]) for e in renamed.elements}
    retired: dict[str, list[Known]] = {}
    for k in state.known:
        if k.id in live or (k.family, split_id(k.id)[1]) in live_numbers:
            continue
        retired.setdefault(k.family, []).append(replace(k, retired=True))
    for ks in retired.values():
        new_known.extend(ks[-RETIRED_KEEP:])
    return renamed, IdentityState(tuple(new_known), next_number)


def _ids(values: Iterable[str], mapping: Mapping[str, str]) -> tuple[str, ...]:
    return tuple(mapping.get(v, v) for v in values)


def rename(analysis: MapAnalysis, mapping: Mapping[str, str]) -> MapAnalysis:
    """The same analysis with element ids (and every reference to them) renamed by ``mapping``."""
    def m(v: str | None) -> str | None:
        return None if v is None else mapping.get(v, v)

    def order(items: Iterable[E]) -> tuple[E, ...]:
        return tuple(sorted(items, key=lambda e: split_id(e.id)[1]))

    rooms = [replace(r, id=mapping.get(r.id, r.id)) for r in analysis.rooms]
    doors = [replace(d, id=mapping.get(d.id, d.id), connects=_ids(d.connects, mapping)) for d in analysis.doors]
    walls = [replace(w, id=mapping.get(w.id, w.id), room=m(w.room)) for w in analysis.walls]
    corners = [replace(c, id=mapping.get(c.id, c.id), room=m(c.room),
                       walls=(mapping.get(c.walls[0], c.walls[0]), mapping.get(c.walls[1], c.walls[1])))
               for c in analysis.corners]
    obstacles = [replace(o, id=mapping.get(o.id, o.id), room=m(o.room)) for o in analysis.obstacles]
    passages = [replace(p, id=mapping.get(p.id, p.id), connects=_ids(p.connects, mapping))
                for p in analysis.narrow_passages]
    unexplored = [replace(u, id=mapping.get(u.id, u.id)) for u in analysis.unexplored]
    return replace(analysis, rooms=order(rooms), doors=order(doors), walls=order(walls), corners=order(corners),
                   obstacles=order(obstacles), narrow_passages=order(passages), unexplored=order(unexplored))


def label(element_id: str) -> str:
    """The name shown on the map and that a prompt may use: ``door_2`` -> ``door 2``."""
    return element_id.replace("_", " ")


class StableAnalyzer:
    """Wraps an analyzer ``(grid, params) -> MapAnalysis`` so that every analysis it makes keeps
    the ids of the ones before (thread-safe). The web session and its planner share one."""

    def __init__(self, analyzer: Callable[[OccupancyGrid, AnalysisParams], MapAnalysis]) -> None:
        self._analyzer = analyzer
        self._lock = threading.Lock()
        self.state: IdentityState | None = None

    def __call__(self, grid: OccupancyGrid, params: AnalysisParams) -> MapAnalysis:
        return self.adopt(self._analyzer(grid, params))

    def adopt(self, analysis: MapAnalysis) -> MapAnalysis:
        """Rename a fresh analysis against what is remembered, and remember it."""
        with self._lock:
            renamed, self.state = stable_ids(self.state, analysis)
        return renamed


__all__ = ["IdentityState", "Known", "StableAnalyzer", "family", "label", "rename", "split_id", "stable_ids"]
