"""Draw synthetic occupancy grids in world metres: rooms, walls, doors, obstacles, unknown areas.

Used by tests (maps with exactly known elements) and to generate the bundled demo world.
Shapes are drawn in the order of the calls; later calls overwrite earlier ones.

>>> b = MapBuilder(6.0, 4.0)
>>> b.room(0.5, 0.5, 5.5, 3.5).door_v(3.0, 2.0, 0.9)  # doctest: +SKIP
"""

from __future__ import annotations

from typing import Final

import numpy as np

from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN, OccupancyGrid

#: Interior walls of a typical building are 10-20 cm thick.
DEFAULT_WALL_M: Final = 0.15


class MapBuilder:
    """A canvas of ``width_m`` x ``height_m`` metres whose lower-left corner is ``origin``.

    Coordinates of every method are world metres. The canvas starts as ``fill`` (unknown).
    """

    def __init__(self, width_m: float, height_m: float, resolution_m: float = 0.05,
                 origin: tuple[float, float] = (0.0, 0.0), fill: int = UNKNOWN) -> None:
        self.resolution_m = resolution_m
        self.origin = origin
        rows = round(height_m / resolution_m)
        cols = round(width_m / resolution_m)
        self.cells = np.full((rows, cols), fill, dtype=np.int8)

    # -- primitives ----------------------------------------------------------------------------
    def _span(self, a_m: float, b_m: float, axis_origin: float, limit: int) -> slice:
        lo, hi = sorted((a_m, b_m))
        i0 = round((lo - axis_origin) / self.resolution_m)
        i1 = round((hi - axis_origin) / self.resolution_m)
        return slice(max(0, i0), min(limit, max(i1, i0 + 1)))

    def rect(self, x0: float, y0: float, x1: float, y1: float, value: int) -> MapBuilder:
        """Fill the axis-aligned rectangle [x0, x1] x [y0, y1] with ``value``."""
        rs = self._span(y0, y1, self.origin[1], self.cells.shape[0])
        cs = self._span(x0, x1, self.origin[0], self.cells.shape[1])
        self.cells[rs, cs] = value
        return self

    def free(self, x0: float, y0: float, x1: float, y1: float) -> MapBuilder:
        return self.rect(x0, y0, x1, y1, FREE)

    def unknown(self, x0: float, y0: float, x1: float, y1: float) -> MapBuilder:
        return self.rect(x0, y0, x1, y1, UNKNOWN)

    def wall(self, x0: float, y0: float, x1: float, y1: float, thickness_m: float = DEFAULT_WALL_M) -> MapBuilder:
        """A horizontal or vertical wall from (x0, y0) to (x1, y1), ``thickness_m`` thick, centred on the line."""
        h = thickness_m / 2
        if abs(y1 - y0) <= abs(x1 - x0):
            return self.rect(min(x0, x1) - h, y0 - h, max(x0, x1) + h, y0 + h, OCCUPIED)
        return self.rect(x0 - h, min(y0, y1) - h, x0 + h, max(y0, y1) + h, OCCUPIED)

    def room(self, x0: float, y0: float, x1: float, y1: float, wall_m: float = DEFAULT_WALL_M) -> MapBuilder:
        """A free rectangle [x0, x1] x [y0, y1] with walls drawn just outside it."""
        self.rect(x0 - wall_m, y0 - wall_m, x1 + wall_m, y1 + wall_m, OCCUPIED)
        return self.free(x0, y0, x1, y1)

    def door_h(self, x: float, y: float, width_m: float, depth_m: float = 0.4) -> MapBuilder:
        """An opening of ``width_m`` centred at (x, y) through a horizontal wall (the gap runs along x)."""
        return self.free(x - width_m / 2, y - depth_m / 2, x + width_m / 2, y + depth_m / 2)

    def door_v(self, x: float, y: float, width_m: float, depth_m: float = 0.4) -> MapBuilder:
        """An opening of ``width_m`` centred at (x, y) through a vertical wall (the gap runs along y)."""
        return self.free(x - depth_m / 2, y - width_m / 2, x + depth_m / 2, y + width_m / 2)

    def box(self, x0: float, y0: float, x1: float, y1: float) -> MapBuilder:
        """A solid rectangular obstacle."""
        return self.rect(x0, y0, x1, y1, OCCUPIED)

    def disc(self, cx: float, cy: float, radius_m: float, value: int = OCCUPIED) -> MapBuilder:
        """A filled disc (a pillar when occupied, a hole of unknown when UNKNOWN)."""
        rows, cols = np.ogrid[: self.cells.shape[0], : self.cells.shape[1]]
        x = self.origin[0] + (cols + 0.5) * self.resolution_m
        y = self.origin[1] + (rows + 0.5) * self.resolution_m
        self.cells[(x - cx) ** 2 + (y - cy) ** 2 <= radius_m**2] = value
        return self

    def build(self, source: str = "<built map>") -> OccupancyGrid:
        return OccupancyGrid(self.cells.copy(), self.resolution_m, self.origin[0], self.origin[1], 0.0, source)
