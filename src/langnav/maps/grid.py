"""The occupancy grid: a trinary map in ROS orientation with world <-> cell transforms.

Cells are stored as in ``nav_msgs/OccupancyGrid``: row 0 is the *bottom* row (lowest y),
column 0 the left column; ``cells[row, col]``. Values are the ROS ones, reduced to three:
``FREE`` (0), ``OCCUPIED`` (100) and ``UNKNOWN`` (-1).

The origin is the world pose of the lower-left corner of cell (0, 0), as in map_server YAML
(``origin: [x, y, yaw]``). A non-zero yaw is supported by every transform here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Final

import numpy as np
import numpy.typing as npt

from langnav.maps.errors import MapError

FREE: Final = 0
OCCUPIED: Final = 100
UNKNOWN: Final = -1

#: ROS OccupancyGrid values at or above this are occupied (map_server's default occupied_thresh 0.65).
OCCUPIED_MIN_PCT: Final = 65
#: ROS values at or below this are free (map_server's default free_thresh 0.196 -> 19.6 %).
FREE_MAX_PCT: Final = 19

#: Refuse grids larger than this many cells: 20000 x 20000 at 5 cm is a 1 km square floor.
MAX_CELLS: Final = 400_000_000
#: Sane resolutions, in metres per cell.
MIN_RESOLUTION_M: Final = 0.001
MAX_RESOLUTION_M: Final = 10.0
#: Largest origin offset accepted, in metres: 10 000 km (a map frame anchored anywhere on Earth)
#: while a float64 still resolves a cell to better than a micrometre; beyond it, world <-> cell
#: transforms lose whole cells.
MAX_ORIGIN_M: Final = 1e7

Int8Array = npt.NDArray[np.int8]
FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True, eq=False)
class OccupancyGrid:
    """A trinary occupancy grid.

    Attributes:
        cells: int8 array (rows = y, row 0 at the bottom) of FREE / OCCUPIED / UNKNOWN.
        resolution_m: cell edge in metres.
        origin_x_m, origin_y_m, origin_yaw_rad: world pose of the lower-left corner of cell (0, 0).
        source: where the grid came from (a file name), for messages.
    """

    cells: Int8Array
    resolution_m: float
    origin_x_m: float = 0.0
    origin_y_m: float = 0.0
    origin_yaw_rad: float = 0.0
    source: str = "<array>"
    _cos: float = field(init=False, repr=False)
    _sin: float = field(init=False, repr=False)

    def __post_init__(self) -> None:
        if self.cells.ndim != 2:
            raise MapError(f"{self.source}: a grid must be 2-D, got shape {self.cells.shape}")
        if self.cells.size == 0:
            raise MapError(f"{self.source}: the grid is empty")
        if self.cells.size > MAX_CELLS:
            raise MapError(
                f"{self.source}: {self.cells.shape[1]}x{self.cells.shape[0]} cells is more than "
                f"the {MAX_CELLS} langnav accepts; crop the map or lower its resolution"
            )
        if not (math.isfinite(self.resolution_m) and MIN_RESOLUTION_M <= self.resolution_m <= MAX_RESOLUTION_M):
            raise MapError(
                f"{self.source}: resolution {self.resolution_m!r} m/cell is out of range "
                f"[{MIN_RESOLUTION_M}, {MAX_RESOLUTION_M}]"
            )
        for name in ("origin_x_m", "origin_y_m", "origin_yaw_rad"):
            if not math.isfinite(getattr(self, name)):
                raise MapError(f"{self.source}: {name} must be finite")
            if abs(getattr(self, name)) > MAX_ORIGIN_M:
                raise MapError(f"{self.source}: {name} {getattr(self, name)!r} is beyond ±{MAX_ORIGIN_M:g}; "
                               "put the map's origin near its own floor")
        if self.cells.dtype != np.int8:
            object.__setattr__(self, "cells", self.cells.astype(np.int8))
        bad = ~np.isin(self.cells, (FREE, OCCUPIED, UNKNOWN))
        if bad.any():
            raise MapError(
                f"{self.source}: cells must be {FREE}, {OCCUPIED} or {UNKNOWN}; "
                f"use from_ros_data() for ROS 0..100 values"
            )
        object.__setattr__(self, "_cos", math.cos(self.origin_yaw_rad))
        object.__setattr__(self, "_sin", math.sin(self.origin_yaw_rad))

    # -- shape ---------------------------------------------------------------------------------
    @property
    def height(self) -> int:
        return int(self.cells.shape[0])

    @property
    def width(self) -> int:
        return int(self.cells.shape[1])

    @property
    def free(self) -> npt.NDArray[np.bool_]:
        return self.cells == FREE

    @property
    def occupied(self) -> npt.NDArray[np.bool_]:
        return self.cells == OCCUPIED

    @property
    def unknown(self) -> npt.NDArray[np.bool_]:
        return self.cells == UNKNOWN

    @property
    def cell_area_m2(self) -> float:
        return self.resolution_m * self.resolution_m

    def cells_for(self, metres: float) -> float:
        """A length in metres expressed in cells (not rounded)."""
        return metres / self.resolution_m

    # -- transforms ----------------------------------------------------------------------------
    def world_to_cell(self, x_m: npt.ArrayLike, y_m: npt.ArrayLike) -> tuple[FloatArray, FloatArray]:
        """World metres -> continuous (row, col); cell (r, c) spans [r, r+1) x [c, c+1)."""
        dx = np.asarray(x_m, dtype=float) - self.origin_x_m
        dy = np.asarray(y_m, dtype=float) - self.origin_y_m
        u = (self._cos * dx + self._sin * dy) / self.resolution_m
        v = (-self._sin * dx + self._cos * dy) / self.resolution_m
        return v, u

    def world_to_index(self, x_m: npt.ArrayLike, y_m: npt.ArrayLike) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.int64]]:
        """World metres -> integer (row, col) of the containing cell (may be outside the grid)."""
        r, c = self.world_to_cell(x_m, y_m)
        return np.floor(r).astype(np.int64), np.floor(c).astype(np.int64)

    def cell_to_world(self, row: npt.ArrayLike, col: npt.ArrayLike) -> tuple[FloatArray, FloatArray]:
        """Integer or continuous (row, col) -> world metres of the cell *centre* (adds 0.5)."""
        return self.grid_to_world(np.asarray(row, dtype=float) + 0.5, np.asarray(col, dtype=float) + 0.5)

    def grid_to_world(self, row: npt.ArrayLike, col: npt.ArrayLike) -> tuple[FloatArray, FloatArray]:
        """Continuous grid coordinates (no half-cell shift) -> world metres."""
        u = np.asarray(col, dtype=float) * self.resolution_m
        v = np.asarray(row, dtype=float) * self.resolution_m
        x = self.origin_x_m + self._cos * u - self._sin * v
        y = self.origin_y_m + self._sin * u + self._cos * v
        return x, y

    def in_bounds(self, row: npt.ArrayLike, col: npt.ArrayLike) -> npt.NDArray[np.bool_]:
        r = np.asarray(row)
        c = np.asarray(col)
        return (r >= 0) & (r < self.height) & (c >= 0) & (c < self.width)

    def value_at(self, x_m: float, y_m: float) -> int:
        """The cell value at a world point; UNKNOWN outside the grid."""
        r, c = self.world_to_index(x_m, y_m)
        if not self.in_bounds(r, c):
            return UNKNOWN
        return int(self.cells[int(r), int(c)])

    @property
    def bounds_m(self) -> tuple[float, float, float, float]:
        """(min_x, min_y, max_x, max_y) of the grid's corners in the world."""
        xs, ys = self.grid_to_world([0, 0, self.height, self.height], [0, self.width, 0, self.width])
        return float(xs.min()), float(ys.min()), float(xs.max()), float(ys.max())

    # -- conversions ---------------------------------------------------------------------------
    def to_image(self) -> npt.NDArray[np.uint8]:
        """The grid as a map_saver trinary image (row 0 = top): 0 occupied, 205 unknown, 254 free."""
        img = np.full(self.cells.shape, 205, dtype=np.uint8)
        img[self.cells == FREE] = 254
        img[self.cells == OCCUPIED] = 0
        return np.flipud(img)

    def to_ros_data(self) -> Int8Array:
        """The flat int8 data of a nav_msgs/OccupancyGrid (row-major from the bottom row)."""
        return self.cells.reshape(-1).copy()

    def with_cells(self, cells: Int8Array) -> OccupancyGrid:
        """The same frame and resolution with other cells (same shape)."""
        if cells.shape != self.cells.shape:
            raise MapError(f"{self.source}: new cells {cells.shape} differ from {self.cells.shape}")
        return OccupancyGrid(cells, self.resolution_m, self.origin_x_m, self.origin_y_m,
                             self.origin_yaw_rad, self.source)

    def translated(self, dx_m: float, dy_m: float) -> OccupancyGrid:
        """The same grid with its origin moved by (dx, dy) metres."""
        return OccupancyGrid(self.cells, self.resolution_m, self.origin_x_m + dx_m,
                             self.origin_y_m + dy_m, self.origin_yaw_rad, self.source)


def from_ros_data(
    data: npt.ArrayLike,
    width: int,
    height: int,
    resolution_m: float,
    origin_x_m: float = 0.0,
    origin_y_m: float = 0.0,
    origin_yaw_rad: float = 0.0,
    source: str = "<OccupancyGrid>",
) -> OccupancyGrid:
    """Build a grid from ``nav_msgs/OccupancyGrid`` data: -1 unknown, 0..100 occupancy %.

    Values >= OCCUPIED_MIN_PCT are occupied, <= FREE_MAX_PCT free, the rest unknown.
    """
    arr = np.asarray(data)
    if width <= 0 or height <= 0:
        raise MapError(f"{source}: width and height must be positive, got {width}x{height}")
    if width * height > MAX_CELLS:
        raise MapError(f"{source}: {width}x{height} cells is more than the {MAX_CELLS} langnav accepts")
    if arr.size != width * height:
        raise MapError(f"{source}: data has {arr.size} values, expected width*height = {width * height}")
    if not np.issubdtype(arr.dtype, np.integer):
        raise MapError(f"{source}: data must be integers (-1, 0..100), got {arr.dtype}")
    vals = arr.reshape(height, width).astype(np.int16)
    vals = np.where(vals > 127, vals - 256, vals)  # uint8 transport of int8
    if ((vals < -1) | (vals > 100)).any():
        raise MapError(f"{source}: data values must be -1 or 0..100")
    cells = np.full((height, width), UNKNOWN, dtype=np.int8)
    cells[(vals >= 0) & (vals <= FREE_MAX_PCT)] = FREE
    cells[vals >= OCCUPIED_MIN_PCT] = OCCUPIED
    return OccupancyGrid(cells, written_resolution(resolution_m), float(origin_x_m), float(origin_y_m),
                         float(origin_yaw_rad), source)


def written_resolution(resolution_m: float) -> float:
    """The cell size as it was written, from the ``float32`` a ``nav_msgs/OccupancyGrid`` carries.

    The message stores ``info.resolution`` as a float32, so a map saved with 0.05 m cells arrives as
    0.0500000007 m. Read that way, every length the analysis turns into cells ("0.30 m is 6 cells")
    can round the other way than for the saved map, and the same floor gives different doors over
    ROS than from its YAML. The shortest decimal that the float32 stands for is the value the map's
    author wrote, so that is the resolution read.
    """
    value = float(resolution_m)
    if not math.isfinite(value) or value <= 0.0:
        return value  # OccupancyGrid itself says what is wrong with it
    as_float32 = np.float32(value)
    if float(as_float32) != value:
        return value  # more precise than a float32 holds: it did not come through one
    return float(np.format_float_positional(as_float32, unique=True, trim="-"))
