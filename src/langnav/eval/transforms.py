"""Metamorphic transforms of an annotated map: the same building as another mapper would save it.

Users' slam_toolbox maps of one building differ in three ways that say nothing about the building:
the map frame's rotation (where the robot started facing), the cell size (``resolution`` in the
mapper's parameters) and the scan noise. An analysis that reads buildings, not pixels, must find the
same doors, spaces and passages in all of them. These functions make such variants of an
:class:`~langnav.maps.grid.OccupancyGrid` together with its annotation (the ``*.points.json`` of
``../shared/maps/ros/ANNOTATION.md``: points and polygons in metres in the map frame), so an
evaluation can score the analysis on each and compare:

* :func:`rotate` turns the map about its centre by any angle (grid enlarged so nothing is cut,
  unknown padding; the annotation turned the same way);
* :func:`resample` saves the map at another cell size (occupied wins where cells merge, as a mapper
  marks a cell a wall passes through);
* :func:`add_scan_noise` adds lidar-like noise with a fixed seed (isolated hits on free floor near
  walls, wall edges that wobble by a cell).

All are pure: arrays and annotations in, new ones out. The output grids have no origin yaw, so a
scorer that ignores yaw (as ``score_points.py`` does) reads them right.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Any, Final

import numpy as np
import numpy.typing as npt
from pydantic import BaseModel, ConfigDict, Field
from scipy import ndimage

from langnav.maps.errors import MapError
from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN, OccupancyGrid

XY = tuple[float, float]

#: Sub-cell sample offsets (in output cells) used when rotating: an output cell is a wall when a
#: wall lies under any of them, else it takes the value under its centre (nearest neighbour). A
#: mapper marks every cell a wall surface passes through, so a wall drawn at an angle stays closed
#: (4-connected); pure centre sampling leaves diagonal walls whose cells touch only at corners,
#: which free space leaks through and which no real map has.
ROTATE_SUBSAMPLES: Final = ((-0.25, -0.25), (-0.25, 0.25), (0.25, -0.25), (0.25, 0.25))

#: Speckle: free cells this close to a wall may turn occupied. Spurious hits in lidar maps sit near
#: surfaces (chair legs, cables, reflections off a wall's foot), not in the middle of a room.
SPECKLE_NEAR_WALL_M: Final = 0.3
#: Spurious hits per square metre of such floor: the density of isolated hits along walls in the
#: slam_toolbox maps of ../shared/maps/ros (about 3 % of the 0.05 m cells). Given per area, not per
#: cell, because spurious returns come from the floor and its clutter, whatever the cell size: a
#: 0.025 m map has the same hits per metre of wall as a 0.05 m one, each in a smaller cell.
SPECKLE_PER_M2: Final = 12.0
#: Chance that a wall's edge cell moves by one cell (out into the free cell beside it, or in, when
#: the wall behind it stays at least one cell thick): a lidar's range noise of a few centimetres
#: at 0.05 m cells.
WOBBLE_PROBABILITY: Final = 0.15

_FOUR: Final = np.array([[0, 1, 0], [1, 1, 1], [0, 1, 0]], dtype=bool)


class _Model(BaseModel):
    model_config = ConfigDict(extra="allow", frozen=True)


class PointsSpace(_Model):
    point: XY
    kind: str = "room"
    group: str | None = None


class PointsDoor(_Model):
    center: XY
    width_m: float | None = None
    optional: bool = False


class PointsIgnore(_Model):
    polygon: list[XY]


class PointsAnnotation(_Model):
    """A person's point annotation of one map (``MAP.points.json``; unknown keys are kept)."""

    map: str | None = None
    spaces: list[PointsSpace] = Field(default_factory=list)
    doors: list[PointsDoor] = Field(default_factory=list)
    narrow_passages: list[PointsDoor] = Field(default_factory=list)
    ignore: list[PointsIgnore] = Field(default_factory=list)

    def mapped(self, f: Callable[[XY], XY]) -> PointsAnnotation:
        """The same annotation with every point and polygon vertex passed through ``f``."""
        return self.model_copy(update={
            "spaces": [s.model_copy(update={"point": f(s.point)}) for s in self.spaces],
            "doors": [d.model_copy(update={"center": f(d.center)}) for d in self.doors],
            "narrow_passages": [p.model_copy(update={"center": f(p.center)}) for p in self.narrow_passages],
            "ignore": [g.model_copy(update={"polygon": [f(v) for v in g.polygon]}) for g in self.ignore],
        })

    def to_json(self) -> dict[str, Any]:
        return self.model_dump(mode="json")


def map_centre(grid: OccupancyGrid) -> XY:
    """The world point at the middle of the grid."""
    x, y = grid.grid_to_world(grid.height / 2.0, grid.width / 2.0)
    return float(x), float(y)


def rotate_point(p: XY, centre: XY, angle_rad: float) -> XY:
    """``p`` turned counter-clockwise by ``angle_rad`` about ``centre``."""
    c, s = math.cos(angle_rad), math.sin(angle_rad)
    dx, dy = p[0] - centre[0], p[1] - centre[1]
    return centre[0] + c * dx - s * dy, centre[1] + s * dx + c * dy


def rotate(grid: OccupancyGrid, ann: PointsAnnotation, angle_deg: float) -> tuple[OccupancyGrid, PointsAnnotation]:
    """The map and its annotation turned counter-clockwise by ``angle_deg`` about the map's centre.

    The output grid has the same cell size, no origin yaw, and is as large as the turned map's
    bounding box, so nothing is cut; cells outside the original are unknown.
    """
    if not math.isfinite(angle_deg):
        raise MapError(f"rotate: the angle must be a finite number of degrees, got {angle_deg!r}")
    a = math.radians(angle_deg)
    centre = map_centre(grid)
    res = grid.resolution_m
    corners_x, corners_y = grid.grid_to_world(np.array([0.0, 0.0, grid.height, grid.height]),
                                              np.array([0.0, grid.width, 0.0, grid.width]))
    turned = [rotate_point((float(x), float(y)), centre, a) for x, y in zip(corners_x, corners_y, strict=True)]
    xs, ys = [p[0] for p in turned], [p[1] for p in turned]
    # a hair under a whole cell of slack so that float noise on an exact fit adds no extra row
    width = max(1, math.ceil((max(xs) - min(xs)) / res - 1e-9))
    height = max(1, math.ceil((max(ys) - min(ys)) / res - 1e-9))
    ox = centre[0] - width * res / 2.0
    oy = centre[1] - height * res / 2.0
    rows, cols = np.mgrid[0:height, 0:width]

    def sample(dr: float, dc: float) -> npt.NDArray[np.int8]:
        # output cell point -> world -> turned back by -a -> the original cell under it
        x = ox + (cols + 0.5 + dc) * res
        y = oy + (rows + 0.5 + dr) * res
        cb, sb = math.cos(-a), math.sin(-a)
        bx = centre[0] + cb * (x - centre[0]) - sb * (y - centre[1])
        by = centre[1] + sb * (x - centre[0]) + cb * (y - centre[1])
        r, c = grid.world_to_index(bx, by)
        inside = (r >= 0) & (r < grid.height) & (c >= 0) & (c < grid.width)
        out = np.full((height, width), UNKNOWN, dtype=np.int8)
        out[inside] = grid.cells[r[inside], c[inside]]
        return out

    cells = sample(0.0, 0.0)
    wall = np.zeros_like(cells, dtype=bool)
    for dr, dc in ROTATE_SUBSAMPLES:
        wall |= sample(dr, dc) == OCCUPIED
    cells[wall] = OCCUPIED
    out = OccupancyGrid(cells, res, ox, oy, 0.0, source=f"{grid.source} rotated {angle_deg:g}°")
    return out, ann.mapped(lambda p: rotate_point(p, centre, a))


def resample(grid: OccupancyGrid, resolution_m: float) -> OccupancyGrid:
    """The map saved at another cell size, over the same extent and origin.

    Coarser: each new cell gathers the old cells whose centres fall in it; it is occupied when any
    of them is (a mapper marks a cell a wall passes through, so walls and their gaps keep their
    width in metres up to a cell), else free when free cells outnumber unknown ones, else unknown.
    Finer: each new cell takes the old cell under its centre. The annotation is unchanged (metres).
    """
    if not (math.isfinite(resolution_m) and resolution_m > 0):
        raise MapError(f"resample: the cell size must be a positive number of metres, got {resolution_m!r}")
    scale = resolution_m / grid.resolution_m
    height = max(1, math.ceil(grid.height / scale - 1e-9))
    width = max(1, math.ceil(grid.width / scale - 1e-9))
    if scale <= 1.0:
        r = np.minimum(((np.arange(height) + 0.5) * scale).astype(np.int64), grid.height - 1)
        c = np.minimum(((np.arange(width) + 0.5) * scale).astype(np.int64), grid.width - 1)
        cells = grid.cells[np.ix_(r, c)]
    else:
        tr = np.minimum(((np.arange(grid.height) + 0.5) / scale).astype(np.int64), height - 1)
        tc = np.minimum(((np.arange(grid.width) + 0.5) / scale).astype(np.int64), width - 1)
        target = (tr[:, None] * width + tc[None, :]).ravel()

        def count(value: int) -> npt.NDArray[np.int64]:
            hits = (grid.cells.ravel() == value).astype(np.int64)
            return np.bincount(target, weights=hits, minlength=height * width).astype(np.int64).reshape(height, width)

        occupied, free, unknown = count(OCCUPIED), count(FREE), count(UNKNOWN)
        cells = np.full((height, width), UNKNOWN, dtype=np.int8)
        cells[free > unknown] = FREE
        cells[occupied > 0] = OCCUPIED
    return OccupancyGrid(cells, resolution_m, grid.origin_x_m, grid.origin_y_m, grid.origin_yaw_rad,
                         source=f"{grid.source} at {resolution_m:g} m")


def add_scan_noise(grid: OccupancyGrid, seed: int, *, speckle_per_m2: float = SPECKLE_PER_M2,
                   wobble_probability: float = WOBBLE_PROBABILITY) -> OccupancyGrid:
    """The map with lidar-like noise drawn from ``seed`` (the same seed gives the same map).

    Speckle: free cells within :data:`SPECKLE_NEAR_WALL_M` of a wall turn occupied, ``speckle_per_m2``
    of them per square metre of such floor. Wobble: a wall's edge moves by one cell with ``wobble_probability``
    per edge cell, outwards (the free cell beside it turns occupied) or inwards (the edge cell turns
    free, only where the wall behind it is occupied, so no hole opens through a wall).
    """
    speckle_probability = speckle_per_m2 * grid.cell_area_m2
    for name, p in (("speckle_per_m2 x cell area", speckle_probability), ("wobble_probability", wobble_probability)):
        if not 0.0 <= p <= 1.0:
            raise MapError(f"add_scan_noise: {name} must be in [0, 1], got {p!r}")
    rng = np.random.default_rng(seed)
    cells = grid.cells.copy()
    wall = cells == OCCUPIED
    free = cells == FREE
    # free cells beside a wall and wall cells beside free floor (4-neighbours)
    free_edge = free & ndimage.binary_dilation(wall, structure=_FOUR)
    wall_edge = wall & ndimage.binary_dilation(free, structure=_FOUR)
    # a wall edge cell may recede only when the cell across it (away from the free side) is wall
    padded = np.pad(wall, 1, constant_values=False)
    padded_free = np.pad(free, 1, constant_values=False)
    backed = np.zeros_like(wall)
    h, w = wall.shape
    for dr, dc in ((0, 1), (0, -1), (1, 0), (-1, 0)):
        free_side = padded_free[1 + dr:1 + dr + h, 1 + dc:1 + dc + w]
        wall_behind = padded[1 - dr:1 - dr + h, 1 - dc:1 - dc + w]
        backed |= free_side & wall_behind
    # distance from a cell's centre to the nearest wall cell's edge (half a cell less than centre to
    # centre), so the band is as wide in metres at every cell size
    near = (ndimage.distance_transform_edt(~wall) - 0.5) * grid.resolution_m <= SPECKLE_NEAR_WALL_M + 1e-9
    speckle = free & near & ~free_edge & (rng.random(cells.shape) < speckle_probability)
    grow = free_edge & (rng.random(cells.shape) < wobble_probability / 2.0)
    recede = wall_edge & backed & (rng.random(cells.shape) < wobble_probability / 2.0)
    cells[speckle | grow] = OCCUPIED
    cells[recede] = FREE
    return OccupancyGrid(cells, grid.resolution_m, grid.origin_x_m, grid.origin_y_m, grid.origin_yaw_rad,
                         source=f"{grid.source} with scan noise (seed {seed})")


def free_area_m2(grid: OccupancyGrid) -> float:
    """Free floor of a map in square metres."""
    return float(np.count_nonzero(grid.cells == FREE)) * grid.cell_area_m2


def points_of(ann: PointsAnnotation) -> list[XY]:
    """Every point of an annotation, in a fixed order (spaces, doors, passages, polygon vertices)."""
    pts: list[XY] = [s.point for s in ann.spaces]
    pts += [d.center for d in ann.doors] + [p.center for p in ann.narrow_passages]
    for g in ann.ignore:
        pts += list(g.polygon)
    return pts


def max_point_shift_m(a: Sequence[XY], b: Sequence[XY]) -> float:
    """The largest distance between corresponding points of two equal-length lists."""
    if len(a) != len(b):
        raise ValueError(f"max_point_shift_m: {len(a)} points against {len(b)}")
    return max((math.dist(p, q) for p, q in zip(a, b, strict=True)), default=0.0)
