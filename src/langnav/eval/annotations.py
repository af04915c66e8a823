"""Scoring a map analysis against ground-truth annotations (``../shared/bench/maps/*.annotations.json``).

Each element kind is matched one-to-one (greedily, closest first) and scored by precision
(matched / detected) and recall (matched / annotated):

* doors: centre within :data:`DOOR_MATCH_M`;
* rooms and hallways: mutual majority overlap of free cells (each covers more than half of the
  other's cells inside the annotated polygon);
* obstacles: detected centroid inside the annotated polygon grown by :data:`OBSTACLE_MARGIN_M`;
* narrow passages: detected centre inside the polygon grown by :data:`PASSAGE_MARGIN_M`;
* interior unexplored areas (``interior=True`` only; the outside world is not annotated):
  centroid inside the polygon grown by :data:`UNEXPLORED_MARGIN_M`;
* corners: point within :data:`CORNER_MATCH_M`;
* walls: same direction (within :data:`WALL_ANGLE_DEG`), on the same line (within
  :data:`WALL_OFFSET_M`) and overlapping over at least half of the shorter segment.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Final

import numpy as np
import numpy.typing as npt
from pydantic import BaseModel, ConfigDict, Field
from skimage.draw import polygon as draw_polygon

from langnav.analysis.elements import MapAnalysis

DOOR_MATCH_M: Final = 0.5
CORNER_MATCH_M: Final = 0.5
OBSTACLE_MARGIN_M: Final = 0.25
PASSAGE_MARGIN_M: Final = 0.5
UNEXPLORED_MARGIN_M: Final = 0.5
WALL_ANGLE_DEG: Final = 10.0
WALL_OFFSET_M: Final = 0.25
ROOM_MIN_OVERLAP: Final = 0.5

XY = tuple[float, float]


class _Model(BaseModel):
    model_config = ConfigDict(extra="ignore", frozen=True)


class AnnSpace(_Model):
    id: str
    polygon: list[XY]
    area_m2: float | None = None


class AnnDoor(_Model):
    id: str
    center: XY
    width: float
    connects: list[str] = Field(default_factory=list)


class AnnRegion(_Model):
    id: str
    polygon: list[XY]
    width: float | None = None


class AnnCorner(_Model):
    space: str
    point: XY
    label: str | None = None


class AnnWall(_Model):
    space: str
    segment: tuple[XY, XY]
    side: str | None = None


class Annotations(_Model):
    """The ground truth of one map, in world metres."""

    name: str
    rooms: list[AnnSpace] = Field(default_factory=list)
    hallways: list[AnnSpace] = Field(default_factory=list)
    doors: list[AnnDoor] = Field(default_factory=list)
    obstacles: list[AnnRegion] = Field(default_factory=list)
    narrow_passages: list[AnnRegion] = Field(default_factory=list)
    unexplored: list[AnnRegion] = Field(default_factory=list)
    corners: list[AnnCorner] = Field(default_factory=list)
    walls: list[AnnWall] = Field(default_factory=list)


def load_annotations(path: str | Path) -> Annotations:
    p = Path(path)
    return Annotations.model_validate(json.loads(p.read_text(encoding="utf-8")))


@dataclass(frozen=True)
class KindScore:
    kind: str
    detected: int
    annotated: int
    matched: int

    @property
    def precision(self) -> float:
        return self.matched / self.detected if self.detected else (1.0 if self.annotated == 0 else 0.0)

    @property
    def recall(self) -> float:
        return self.matched / self.annotated if self.annotated else 1.0


def _greedy(n_det: int, n_ann: int, cost: Callable[[int, int], float | None]) -> int:
    """One-to-one matches, cheapest pair first; ``cost`` None = not a match."""
    pairs = [(c, i, j) for i in range(n_det) for j in range(n_ann) if (c := cost(i, j)) is not None]
    pairs.sort()
    used_i: set[int] = set()
    used_j: set[int] = set()
    for _, i, j in pairs:
        if i not in used_i and j not in used_j:
            used_i.add(i)
            used_j.add(j)
    return len(used_i)


def _dist_to_polygon(p: XY, poly: Sequence[XY]) -> float:
    """0 inside the polygon, else the distance to its boundary."""
    x, y = p
    inside = False
    d = math.inf
    n = len(poly)
    for k in range(n):
        (x0, y0), (x1, y1) = poly[k], poly[(k + 1) % n]
        if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            inside = not inside
        dx, dy = x1 - x0, y1 - y0
        t = max(0.0, min(1.0, ((x - x0) * dx + (y - y0) * dy) / (dx * dx + dy * dy or 1.0)))
        d = min(d, math.hypot(x - x0 - t * dx, y - y0 - t * dy))
    return 0.0 if inside else d


def _centroid(poly: Sequence[XY]) -> XY:
    a = np.asarray(poly, dtype=float)
    return float(a[:, 0].mean()), float(a[:, 1].mean())


def _in_region(points: Sequence[XY], regions: Sequence[Sequence[XY]], margin: float) -> Callable[[int, int], float | None]:
    def cost(i: int, j: int) -> float | None:
        if _dist_to_polygon(points[i], regions[j]) > margin:
            return None
        return math.dist(points[i], _centroid(regions[j]))
    return cost


def _near(points: Sequence[XY], targets: Sequence[XY], tol: float) -> Callable[[int, int], float | None]:
    def cost(i: int, j: int) -> float | None:
        d = math.dist(points[i], targets[j])
        return d if d <= tol else None
    return cost


def _polygon_mask(analysis: MapAnalysis, poly: Sequence[XY]) -> npt.NDArray[np.bool_]:
    g = analysis.grid
    xs = [p[0] for p in poly]
    ys = [p[1] for p in poly]
    r, c = g.world_to_cell(xs, ys)
    mask = np.zeros(g.cells.shape, dtype=bool)
    rr, cc = draw_polygon(np.asarray(r) - 0.5, np.asarray(c) - 0.5, shape=mask.shape)
    mask[rr, cc] = True
    return mask


def _wall_cost(det: Sequence[tuple[XY, XY]], ann: Sequence[tuple[XY, XY]]) -> Callable[[int, int], float | None]:
    def cost(i: int, j: int) -> float | None:
        (a0, a1), (b0, b1) = det[i], ann[j]
        da = np.subtract(a1, a0)
        db = np.subtract(b1, b0)
        la, lb = float(np.hypot(*da)), float(np.hypot(*db))
        if la == 0 or lb == 0:
            return None
        ua, ub = da / la, db / lb
        if abs(float(ua @ ub)) < math.cos(math.radians(WALL_ANGLE_DEG)):
            return None
        mid = (np.asarray(a0) + np.asarray(a1)) / 2
        off = abs(float(np.cross(ub, mid - np.asarray(b0))))
        if off > WALL_OFFSET_M:
            return None
        s = sorted([float(ub @ (np.asarray(a0) - b0)), float(ub @ (np.asarray(a1) - b0))])
        overlap = min(s[1], lb) - max(s[0], 0.0)
        if overlap < 0.5 * min(la, lb):
            return None
        return off
    return cost


def score_analysis(analysis: MapAnalysis, ann: Annotations) -> dict[str, KindScore]:
    """Precision / recall per element kind (see the module docstring)."""
    out: dict[str, KindScore] = {}

    def put(kind: str, n_det: int, n_ann: int, cost: Callable[[int, int], float | None]) -> None:
        out[kind] = KindScore(kind, n_det, n_ann, _greedy(n_det, n_ann, cost))

    put("doors", len(analysis.doors), len(ann.doors),
        _near([d.center for d in analysis.doors], [d.center for d in ann.doors], DOOR_MATCH_M))

    spaces = [*ann.rooms, *ann.hallways]
    free = analysis.grid.free
    ann_masks = [_polygon_mask(analysis, s.polygon) & free for s in spaces]
    det_masks = [(analysis.labels == r.label) & free for r in analysis.rooms]

    def room_cost(i: int, j: int) -> float | None:
        inter = int((det_masks[i] & ann_masks[j]).sum())
        a_det = int((det_masks[i] & (ann_masks[j] | ~np.logical_or.reduce(ann_masks))).sum()) or 1
        a_ann = int(ann_masks[j].sum()) or 1
        if inter / a_ann > ROOM_MIN_OVERLAP and inter / a_det > ROOM_MIN_OVERLAP:
            return -inter
        return None

    put("rooms+hallways", len(analysis.rooms), len(spaces), room_cost)
    put("obstacles", len(analysis.obstacles), len(ann.obstacles),
        _in_region([o.centroid for o in analysis.obstacles], [o.polygon for o in ann.obstacles],
                   OBSTACLE_MARGIN_M))
    put("narrow_passages", len(analysis.narrow_passages), len(ann.narrow_passages),
        _in_region([p.center for p in analysis.narrow_passages], [p.polygon for p in ann.narrow_passages],
                   PASSAGE_MARGIN_M))
    interior = [u for u in analysis.unexplored if u.interior]
    put("unexplored (interior)", len(interior), len(ann.unexplored),
        _in_region([u.centroid for u in interior], [u.polygon for u in ann.unexplored], UNEXPLORED_MARGIN_M))
    put("corners", len(analysis.corners), len(ann.corners),
        _near([c.point for c in analysis.corners], [c.point for c in ann.corners], CORNER_MATCH_M))
    put("walls", len(analysis.walls), len(ann.walls),
        _wall_cost([(w.start, w.end) for w in analysis.walls], [w.segment for w in ann.walls]))
    return out


#: The kinds with a precision / recall target of 0.95 (issue 2).
TARGET_KINDS: Final = ("doors", "rooms+hallways", "obstacles", "narrow_passages", "unexplored (interior)")
