"""The elements a person may refer to, found in an occupancy grid, in world metres.

Every element has an ``id`` (``door_3``), a ``kind`` and a ``ref_point``: the point the bench's
words measure distances to (see ``reference_point``). Geometry is in world metres, map frame.
Arrays of points are (N, 2) float arrays of (x, y).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from enum import StrEnum
from typing import Any

import numpy as np
import numpy.typing as npt

from langnav.analysis.params import AnalysisParams
from langnav.maps.grid import OccupancyGrid

Point = tuple[float, float]
Points = npt.NDArray[np.float64]


class ElementKind(StrEnum):
    ROOM = "room"
    HALLWAY = "hallway"
    DOOR = "door"
    WALL = "wall"
    CORNER = "corner"
    OBSTACLE = "obstacle"
    NARROW_PASSAGE = "narrow_passage"
    UNEXPLORED = "unexplored_area"


def _pt(p: Point | npt.ArrayLike) -> list[float]:
    a = np.asarray(p, dtype=float).reshape(-1)
    return [round(float(a[0]), 3), round(float(a[1]), 3)]


@dataclass(frozen=True, eq=False)
class Room:
    """A room or a hallway: free space bounded by walls and doorways.

    ``label`` is its value in :attr:`MapAnalysis.labels`. ``area_m2`` counts the free cells and the
    unknown cells enclosed by the room; ``centroid`` is the centroid of its free cells.
    ``cells_xy`` are the world centres of its free cells (used for nearest-cell distances).
    """

    id: str
    label: int
    kind: ElementKind  # ROOM or HALLWAY
    area_m2: float
    free_area_m2: float
    centroid: Point
    length_m: float
    width_m: float
    cells_xy: Points = field(repr=False)
    polygon: Points = field(repr=False)  # outline, for drawing

    def to_json(self) -> dict[str, Any]:
        return {"id": self.id, "label": self.label, "kind": "hallway" if self.kind == ElementKind.HALLWAY else "room",
                "area_m2": round(self.area_m2, 2), "free_area_m2": round(self.free_area_m2, 2),
                "centroid": _pt(self.centroid), "length_m": round(self.length_m, 2),
                "width_m": round(self.width_m, 2)}


@dataclass(frozen=True, eq=False)
class Door:
    """A gap in a wall joining two spaces (or a space and unexplored territory).

    ``jambs`` are the two wall ends bounding the opening; ``normal`` a unit vector across it
    (from ``connects[0]`` to ``connects[1]``). ``connects`` holds room ids or unexplored ids.
    """

    id: str
    center: Point
    width_m: float
    jambs: tuple[Point, Point]
    normal: Point
    connects: tuple[str, ...]

    def to_json(self) -> dict[str, Any]:
        return {"id": self.id, "center": _pt(self.center), "width_m": round(self.width_m, 2),
                "jambs": [_pt(j) for j in self.jambs], "normal": _pt(self.normal),
                "connects": list(self.connects)}


@dataclass(frozen=True, eq=False)
class Wall:
    """A straight wall segment bounding a space; ``inward`` is the unit normal pointing into ``room``."""

    id: str
    start: Point
    end: Point
    room: str | None
    inward: Point

    @property
    def length_m(self) -> float:
        return math.dist(self.start, self.end)

    @property
    def midpoint(self) -> Point:
        return ((self.start[0] + self.end[0]) / 2, (self.start[1] + self.end[1]) / 2)

    def to_json(self) -> dict[str, Any]:
        return {"id": self.id, "start": _pt(self.start), "end": _pt(self.end),
                "length_m": round(self.length_m, 2), "room": self.room, "inward": _pt(self.inward)}


@dataclass(frozen=True, eq=False)
class Corner:
    """Where two walls of a room meet, seen from the room (``point`` is the meeting point)."""

    id: str
    point: Point
    room: str | None
    walls: tuple[str, str]
    #: A free point inside the room near the corner, clear of both walls (for goals).
    approach: Point

    def to_json(self) -> dict[str, Any]:
        return {"id": self.id, "point": _pt(self.point), "room": self.room, "walls": list(self.walls),
                "approach": _pt(self.approach)}


@dataclass(frozen=True, eq=False)
class Obstacle:
    """An occupied cluster apart from the main walls (furniture, a box, a pillar)."""

    id: str
    centroid: Point
    area_m2: float
    extent_m: tuple[float, float]  # bounding-box width, height
    room: str | None
    cells_xy: Points = field(repr=False)  # world centres of its occupied cells

    def to_json(self) -> dict[str, Any]:
        return {"id": self.id, "centroid": _pt(self.centroid), "area_m2": round(self.area_m2, 3),
                "extent_m": [round(self.extent_m[0], 2), round(self.extent_m[1], 2)], "room": self.room}


@dataclass(frozen=True, eq=False)
class NarrowPassage:
    """A constriction wider than the robot, narrower than ~1 m, longer than a door is deep.

    ``ends`` are the two mouths along its axis; ``connects`` the spaces at each end.
    """

    id: str
    center: Point
    width_m: float
    length_m: float
    ends: tuple[Point, Point]
    connects: tuple[str, ...]

    def to_json(self) -> dict[str, Any]:
        return {"id": self.id, "center": _pt(self.center), "width_m": round(self.width_m, 2),
                "length_m": round(self.length_m, 2), "ends": [_pt(e) for e in self.ends],
                "connects": list(self.connects)}


@dataclass(frozen=True, eq=False)
class UnexploredArea:
    """A connected unknown region bordering free space; ``frontier`` are the free cells next to it."""

    id: str
    centroid: Point
    area_m2: float
    frontier: Points = field(repr=False)
    #: True when the region is enclosed by the mapped building (not the world outside).
    interior: bool = True

    def to_json(self) -> dict[str, Any]:
        return {"id": self.id, "centroid": _pt(self.centroid), "area_m2": round(self.area_m2, 2),
                "interior": self.interior, "frontier": [_pt(p) for p in self.frontier]}


Element = Room | Door | Wall | Corner | Obstacle | NarrowPassage | UnexploredArea


@dataclass(frozen=True, eq=False)
class MapAnalysis:
    """Everything found in one grid. ``labels`` is int32 in grid orientation (row 0 = bottom):
    0 = no room, k = the room / hallway whose ``label`` is k."""

    grid: OccupancyGrid
    params: AnalysisParams
    rooms: tuple[Room, ...]
    doors: tuple[Door, ...]
    walls: tuple[Wall, ...]
    corners: tuple[Corner, ...]
    obstacles: tuple[Obstacle, ...]
    narrow_passages: tuple[NarrowPassage, ...]
    unexplored: tuple[UnexploredArea, ...]
    labels: npt.NDArray[np.int32] = field(repr=False)
    #: Openings between two spaces wider than a door (an arch, an open front in a wall line):
    #: ways between the spaces (in the graph), not doors a person would count.
    openings: tuple[Door, ...] = ()

    @property
    def elements(self) -> tuple[Element, ...]:
        return (*self.rooms, *self.doors, *self.walls, *self.corners, *self.obstacles,
                *self.narrow_passages, *self.unexplored)

    def by_id(self, element_id: str) -> Element:
        for e in self.elements:
            if e.id == element_id:
                return e
        raise KeyError(f"no element {element_id!r} in this map")

    def room_by_label(self, label: int) -> Room | None:
        for r in self.rooms:
            if r.label == label:
                return r
        return None

    def room_at(self, x_m: float, y_m: float) -> Room | None:
        """The room or hallway holding a world point (None outside every room)."""
        r, c = self.grid.world_to_index(x_m, y_m)
        if not self.grid.in_bounds(r, c):
            return None
        return self.room_by_label(int(self.labels[int(r), int(c)]))

    def graph(self) -> dict[str, list[tuple[str, str]]]:
        """Spaces and the doors (and wide openings) between them: space id -> [(door id, other
        space id)]."""
        g: dict[str, list[tuple[str, str]]] = {r.id: [] for r in self.rooms}
        for d in (*self.doors, *self.openings):
            if len(d.connects) == 2:
                a, b = d.connects
                g.setdefault(a, []).append((d.id, b))
                g.setdefault(b, []).append((d.id, a))
        return g

    def labels_image(self) -> npt.NDArray[np.int32]:
        """``labels`` in image orientation (row 0 = top), as ``--labels`` writes it."""
        return np.flipud(self.labels).astype(np.int32)

    def to_json(self) -> dict[str, Any]:
        g = self.grid
        return {
            "map": {"source": g.source, "width": g.width, "height": g.height,
                    "resolution": g.resolution_m, "origin": [g.origin_x_m, g.origin_y_m, g.origin_yaw_rad]},
            "rooms": [r.to_json() for r in self.rooms],
            "doors": [d.to_json() for d in self.doors],
            "openings": [d.to_json() for d in self.openings],
            "walls": [w.to_json() for w in self.walls],
            "corners": [c.to_json() for c in self.corners],
            "obstacles": [o.to_json() for o in self.obstacles],
            "narrow_passages": [p.to_json() for p in self.narrow_passages],
            "unexplored": [u.to_json() for u in self.unexplored],
            "graph": {k: [{"door": d, "to": o} for d, o in v] for k, v in self.graph().items()},
        }


def reference_point(e: Element) -> Point:
    """The bench's reference point for ordering and sides: door centre, room centroid, etc."""
    if isinstance(e, Door):
        return e.center
    if isinstance(e, Room):
        return e.centroid
    if isinstance(e, Wall):
        return e.midpoint
    if isinstance(e, Corner):
        return e.point
    if isinstance(e, Obstacle):
        return e.centroid
    if isinstance(e, NarrowPassage):
        return e.center
    return e.centroid


def element_kind(e: Element) -> ElementKind:
    if isinstance(e, Room):
        return e.kind
    return {Door: ElementKind.DOOR, Wall: ElementKind.WALL, Corner: ElementKind.CORNER,
            Obstacle: ElementKind.OBSTACLE, NarrowPassage: ElementKind.NARROW_PASSAGE,
            UnexploredArea: ElementKind.UNEXPLORED}[type(e)]
