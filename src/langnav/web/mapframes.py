"""Robot state, maps and map analyses as the small JSON frames the page draws.

The map goes as a palette PNG (base64), sent only when its cells change; the state frame
(pose, scan end points, path, goals) is a few kilobytes and goes at up to 10 Hz.
"""

from __future__ import annotations

import base64
import hashlib
import io
from typing import Any, Final

import numpy as np
from PIL import Image

from langnav.analysis.elements import MapAnalysis
from langnav.analysis.identity import label
from langnav.maps.grid import FREE, OCCUPIED, OccupancyGrid
from langnav.robot.protocol import RobotState

#: Page colours of the three cell values (free, occupied, unknown), as RGB.
PALETTE: Final = ((255, 255, 255), (43, 52, 64), (223, 227, 232))
#: Paths are drawn, not measured: a few hundred points look the same as thousands.
MAX_PATH_POINTS: Final = 400
#: Room outlines are shaded, not measured: 200 points per outline is plenty at any zoom.
MAX_POLYGON_POINTS: Final = 200
#: Centimetres are finer than a map cell and keep frames small.
DECIMALS: Final = 2


def grid_digest(grid: OccupancyGrid) -> str:
    """A short fingerprint of a grid's cells and frame: equal digests, same picture."""
    h = hashlib.blake2b(digest_size=12)
    h.update(np.ascontiguousarray(grid.cells).tobytes())
    h.update(repr((grid.cells.shape, grid.resolution_m, grid.origin_x_m, grid.origin_y_m,
                   grid.origin_yaw_rad)).encode())
    return h.hexdigest()


def map_png(grid: OccupancyGrid) -> bytes:
    """The grid as a 3-colour palette PNG in image orientation (row 0 at the top)."""
    index = np.full(grid.cells.shape, 2, dtype=np.uint8)
    index[grid.cells == FREE] = 0
    index[grid.cells == OCCUPIED] = 1
    img = Image.fromarray(np.flipud(index), mode="P")
    img.putpalette([v for rgb in PALETTE for v in rgb])
    buf = io.BytesIO()
    img.save(buf, format="PNG", optimize=False, compress_level=6)
    return buf.getvalue()


def known_bounds(grid: OccupancyGrid) -> list[float] | None:
    """[x_min, y_min, x_max, y_max] (map frame, m) of the mapped cells, or None when none is:
    what "Fit" frames (a slam map is mostly unknown margin around the floor)."""
    known = grid.cells != -1
    rows = np.flatnonzero(known.any(axis=1))
    cols = np.flatnonzero(known.any(axis=0))
    if not len(rows):
        return None
    r = np.array([rows[0], rows[0], rows[-1] + 1, rows[-1] + 1], dtype=float)
    c = np.array([cols[0], cols[-1] + 1, cols[0], cols[-1] + 1], dtype=float)
    xs, ys = grid.grid_to_world(r, c)
    return [round(float(np.min(xs)), DECIMALS), round(float(np.min(ys)), DECIMALS),
            round(float(np.max(xs)), DECIMALS), round(float(np.max(ys)), DECIMALS)]


def map_frame(grid: OccupancyGrid, digest: str) -> dict[str, Any]:
    return {"type": "map", "version": digest, "png": base64.b64encode(map_png(grid)).decode("ascii"),
            "width": grid.width, "height": grid.height, "resolution": grid.resolution_m,
            "origin": [grid.origin_x_m, grid.origin_y_m, grid.origin_yaw_rad], "known": known_bounds(grid)}


def _decimate(points: Any, limit: int) -> list[list[float]]:
    pts = np.asarray(points, dtype=float).reshape(-1, 2)
    if len(pts) > limit:
        pts = pts[np.linspace(0, len(pts) - 1, limit).round().astype(int)]
    return np.round(pts, DECIMALS).tolist()  # type: ignore[no-any-return]


def scan_points(state: RobotState) -> list[float]:
    """The lidar's hits as a flat [x0, y0, x1, y1, ...] in the map frame (no-return beams left out)."""
    scan = state.scan
    if scan is None or not scan.ranges_m:
        return []
    r = np.asarray(scan.ranges_m, dtype=float)
    ang = scan.angle_min_rad + np.arange(len(r)) * scan.angle_increment_rad + scan.pose.yaw_rad
    ok = np.isfinite(r) & (r > 0) & (r < scan.range_max_m)
    x = scan.pose.x_m + r[ok] * np.cos(ang[ok])
    y = scan.pose.y_m + r[ok] * np.sin(ang[ok])
    return np.round(np.column_stack([x, y]).reshape(-1), DECIMALS).tolist()  # type: ignore[no-any-return]


def state_frame(state: RobotState, backend: str, where: str, plan: dict[str, Any],
                radius_m: float) -> dict[str, Any]:
    """The small frame sent at up to 10 Hz: pose, velocity, connection, plan state."""
    p = state.pose
    return {"type": "state", "t": round(state.time_s, 3), "backend": backend, "connected": state.connected,
            "busy": state.busy, "pose": [round(p.x_m, 3), round(p.y_m, 3), round(p.yaw_rad, 4)],
            "v": round(state.linear_mps, 3), "w": round(state.angular_radps, 3), "radius_m": radius_m,
            "where": where, "plan": plan}


def scan_frame(state: RobotState) -> dict[str, Any]:
    """The lidar's hits (sent when a new scan arrives, 5-10 Hz)."""
    return {"type": "scan", "points": scan_points(state)}


def path_frame(state: RobotState) -> dict[str, Any]:
    """The planned path and the goals (sent when they change: on a new goal or a replan)."""
    return {"type": "path", "path": _decimate(state.path, MAX_PATH_POINTS) if state.path else [],
            "goals": [[round(g[0], DECIMALS), round(g[1], DECIMALS)] for g in state.goals]}


def space_labels(analysis: MapAnalysis) -> dict[str, str]:
    """Room id -> the name the map shows and the chat uses for it: the id read as words
    ("room 3", "hallway 2"), which is also a name a prompt may use."""
    return {r.id: label(r.id) for r in analysis.rooms}


def elements_frame(analysis: MapAnalysis, digest: str) -> dict[str, Any]:
    """The analysis for drawing: every element's geometry and label, no frontier cell lists."""
    doc = analysis.to_json()
    names = space_labels(analysis)
    for room_doc, room in zip(doc["rooms"], analysis.rooms, strict=True):
        room_doc["label"] = names.get(room.id, room.id)
        room_doc["polygon"] = _decimate(room.polygon, MAX_POLYGON_POINTS) if len(room.polygon) else []
    for key in ("doors", "walls", "corners", "obstacles", "narrow_passages", "unexplored"):
        for e in doc[key]:
            e["label"] = label(e["id"])
    for u in doc["unexplored"]:
        u.pop("frontier", None)
    doc.pop("graph", None)
    doc.update({"type": "elements", "version": digest})
    return doc
