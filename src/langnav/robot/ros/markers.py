"""What langnav reads in a map, as a ``visualization_msgs/MarkerArray`` (plain dicts) for RViz and
Foxglove: rooms and hallways (their cells, coloured), doors (the opening between the jambs),
narrow passages (their centre line), unexplored areas (their frontier), each labelled with its
element name as the web app writes it (``door_2`` -> "door 2").

Pure: a :class:`MapAnalysis` in, dicts out (no ROS import); :mod:`langnav.robot.ros.node`
publishes them.
"""

from __future__ import annotations

import colorsys
from typing import Any, Final

import numpy as np

from langnav.analysis.elements import MapAnalysis
from langnav.robot.ros import messages as rm

# visualization_msgs/Marker type and action values
CUBE_LIST: Final = 6
LINE_STRIP: Final = 4
LINE_LIST: Final = 5
POINTS: Final = 8
TEXT_VIEW_FACING: Final = 9
ADD: Final = 0
DELETEALL: Final = 3

#: Room cells are drawn one cube per this many metres (a map has 10^5 cells; RViz draws 10^4 fine).
ROOM_CELL_M: Final = 0.2
#: Height of the labels and where they float (metres): readable from a top view, above the cells.
TEXT_HEIGHT_M: Final = 0.35
TEXT_Z_M: Final = 0.6
LINE_WIDTH_M: Final = 0.08
ROOM_ALPHA: Final = 0.35
DOOR_RGBA: Final = (0.1, 0.75, 0.2, 1.0)
PASSAGE_RGBA: Final = (0.0, 0.7, 0.8, 1.0)
UNEXPLORED_RGBA: Final = (0.9, 0.1, 0.1, 1.0)
TEXT_RGBA: Final = (1.0, 1.0, 1.0, 1.0)


def display_name(element_id: str) -> str:
    """How the web app names an element: ``door_2`` -> "door 2"."""
    return element_id.replace("_", " ")


def _color(rgba: tuple[float, float, float, float]) -> dict[str, float]:
    return {"r": rgba[0], "g": rgba[1], "b": rgba[2], "a": rgba[3]}


def _point(x: float, y: float, z: float = 0.0) -> dict[str, float]:
    return {"x": float(x), "y": float(y), "z": float(z)}


def _marker(ns: str, mid: int, kind: int, frame_id: str, t_s: float | None, *, scale: tuple[float, float, float],
            rgba: tuple[float, float, float, float], points: list[dict[str, float]] | None = None, text: str = "",
            at: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> dict[str, Any]:
    return {
        "header": rm.header(frame_id, t_s), "ns": ns, "id": mid, "type": kind, "action": ADD,
        "pose": {"position": _point(*at), "orientation": {"x": 0.0, "y": 0.0, "z": 0.0, "w": 1.0}},
        "scale": {"x": scale[0], "y": scale[1], "z": scale[2]}, "color": _color(rgba),
        "points": points or [], "text": text, "frame_locked": False,
    }


def _label(ns: str, mid: int, name: str, x: float, y: float, frame_id: str, t_s: float | None) -> dict[str, Any]:
    return _marker(ns, mid, TEXT_VIEW_FACING, frame_id, t_s, scale=(0.0, 0.0, TEXT_HEIGHT_M), rgba=TEXT_RGBA,
                   text=name, at=(x, y, TEXT_Z_M))


def room_rgba(k: int, n: int) -> tuple[float, float, float, float]:
    """Distinct hues for n rooms, translucent so the map shows through."""
    r, g, b = colorsys.hsv_to_rgb((k / max(n, 1)) % 1.0, 0.55, 0.95)
    return (r, g, b, ROOM_ALPHA)


def analysis_markers(analysis: MapAnalysis, frame_id: str = "map", t_s: float | None = None) -> dict[str, Any]:
    """The MarkerArray of an analysis; its first marker deletes the previous array's."""
    g = analysis.grid
    markers: list[dict[str, Any]] = [{**_marker("", 0, 0, frame_id, t_s, scale=(1.0, 1.0, 1.0),
                                                rgba=(0.0, 0.0, 0.0, 0.0)), "action": DELETEALL}]
    cell = max(ROOM_CELL_M, g.resolution_m)
    for k, room in enumerate(analysis.rooms):
        # the room's cells, gathered into squares of `cell` metres (one cube each)
        squares = np.unique(np.floor(np.asarray(room.cells_xy, dtype=float).reshape(-1, 2) / cell), axis=0)
        pts = [_point((i + 0.5) * cell, (j + 0.5) * cell) for i, j in squares]
        markers.append(_marker("rooms", 2 * k, CUBE_LIST, frame_id, t_s, scale=(cell, cell, 0.02),
                               rgba=room_rgba(k, len(analysis.rooms)), points=pts))
        markers.append(_label("rooms", 2 * k + 1, display_name(room.id), *room.centroid, frame_id, t_s))
    for k, door in enumerate(analysis.doors):
        (ax, ay), (bx, by) = door.jambs
        markers.append(_marker("doors", 2 * k, LINE_LIST, frame_id, t_s, scale=(LINE_WIDTH_M * 1.5, 0.0, 0.0),
                               rgba=DOOR_RGBA, points=[_point(ax, ay, 0.05), _point(bx, by, 0.05)]))
        markers.append(_label("doors", 2 * k + 1, display_name(door.id), *door.center, frame_id, t_s))
    for k, passage in enumerate(analysis.narrow_passages):
        (ax, ay), (bx, by) = passage.ends
        markers.append(_marker("passages", 2 * k, LINE_STRIP, frame_id, t_s, scale=(LINE_WIDTH_M, 0.0, 0.0),
                               rgba=PASSAGE_RGBA, points=[_point(ax, ay, 0.05), _point(bx, by, 0.05)]))
        markers.append(_label("passages", 2 * k + 1, display_name(passage.id), *passage.center, frame_id, t_s))
    for k, area in enumerate(analysis.unexplored):
        frontier = [_point(x, y, 0.05) for x, y in area.frontier]
        markers.append(_marker("unexplored", 2 * k, POINTS, frame_id, t_s, scale=(g.resolution_m * 2, g.resolution_m * 2, 0.0),
                               rgba=UNEXPLORED_RGBA, points=frontier))
        markers.append(_label("unexplored", 2 * k + 1, display_name(area.id), *area.centroid, frame_id, t_s))
    return {"markers": markers}
