"""The simulated world: a ground-truth occupancy grid, with obstacles that can be added at run time.

The ground truth is any :class:`~langnav.maps.grid.OccupancyGrid` (a ROS map, a bench world, a
built map). Regions the ground truth does not know (UNKNOWN) are treated as solid: the simulator
has nothing else to show there, and a robot that drove into them would leave the world. So both
the lidar and the collision check see OCCUPIED cells and unknown *regions* as matter. Unknown
*specks* (under SPECK_MAX_M2, inside the map: cells a mapping run never saw) are noise, not
matter: the simulated world has floor there.
"""

from __future__ import annotations

import functools
import math
from typing import Final

import numpy as np
import numpy.typing as npt
from scipy import ndimage

from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN, OccupancyGrid
from langnav.robot.errors import RobotError

#: The robot's radius: an iRobot Create 3 / TurtleBot 4 base is 0.17-0.18 m in radius.
ROBOT_RADIUS_M: Final = 0.17

#: Unknown patches smaller than this inside a map are unobserved specks, not places (the bench's
#: "specks under about 0.05 m2 are noise").
SPECK_MAX_M2: Final = 0.05

#: Block side (cells) of the coarse "any matter in this block" index behind the quick collision accept:
#: 16 cells = 0.8 m at 5 cm, about the robot's diameter plus its margins, so most free-space checks
#: need only a 5x5 block look-up, and the index is 1/256 of the grid.
BLOCK_CELLS: Final = 16

BoolArray = npt.NDArray[np.bool_]


def solid_mask(grid: OccupancyGrid) -> BoolArray:
    """Occupied cells, and unknown regions except specks that do not touch the map's edge."""
    unknown = grid.unknown
    labels, n = ndimage.label(unknown, structure=np.ones((3, 3), dtype=bool))
    speck = np.zeros(n + 1, dtype=bool)
    if n:
        sizes = np.bincount(labels.ravel(), minlength=n + 1)
        border = np.unique(np.concatenate([labels[0], labels[-1], labels[:, 0], labels[:, -1]]))
        speck = sizes * grid.cell_area_m2 < SPECK_MAX_M2
        speck[border] = False
        speck[0] = False
    return grid.occupied | (unknown & ~speck[labels])


class World:
    """Ground truth for the simulator: which cells hold matter, and whether a disc collides."""

    def __init__(self, grid: OccupancyGrid) -> None:
        self._base = grid
        self._base_solid = solid_mask(grid)
        self._solid: BoolArray = self._base_solid.copy()
        self.version = 0
        self._block_solid: BoolArray | None = None
        self._block_version = -1

    # -- reading ---------------------------------------------------------------------------------
    @property
    def grid(self) -> OccupancyGrid:
        """The ground truth as a grid (added obstacles OCCUPIED)."""
        cells = self._base.cells.copy()
        cells[self._solid & ~self._base_solid] = OCCUPIED
        cells[~self._solid & (cells == UNKNOWN)] = FREE  # the unknown specks the world has floor under
        return self._base.with_cells(cells)

    @property
    def frame(self) -> OccupancyGrid:
        """The grid whose frame (origin, resolution, shape) the world uses."""
        return self._base

    @property
    def solid(self) -> BoolArray:
        """True where the lidar is stopped and the robot cannot be (read-only view)."""
        view = self._solid.view()
        view.flags.writeable = False
        return view

    def clearance_m(self, x_m: float, y_m: float, radius_m: float = ROBOT_RADIUS_M) -> float:
        """Distance from (x, y) to the nearest solid cell, searched within ``radius_m`` + a cell."""
        return disc_clearance_m(self._solid, self._base, x_m, y_m, radius_m)

    def collides(self, x_m: float, y_m: float, radius_m: float = ROBOT_RADIUS_M) -> bool:
        """Whether a disc of ``radius_m`` at (x, y) overlaps matter."""
        r, c = self._base.world_to_index(x_m, y_m)
        if self._base.in_bounds(r, c) and self._no_matter_near(int(r), int(c), radius_m):
            return False
        return self.clearance_m(x_m, y_m, radius_m) < radius_m

    def _no_matter_near(self, r: int, c: int, radius_m: float) -> bool:
        """Quick accept: no solid cell in the blocks around cell (r, c) that a disc of ``radius_m``
        (plus a cell) can reach, and those blocks all inside the map (outside counts as matter)."""
        blocks = self._blocks()
        k = math.ceil((radius_m / self._base.resolution_m + 2.0) / BLOCK_CELLS)
        br, bc = r // BLOCK_CELLS, c // BLOCK_CELLS
        if br - k < 0 or bc - k < 0 or br + k >= blocks.shape[0] or bc + k >= blocks.shape[1]:
            return False
        # a cell outside these blocks is at least k * BLOCK_CELLS - 1 cells from (r, c) in row or column
        return not blocks[br - k:br + k + 1, bc - k:bc + k + 1].any()

    def _blocks(self) -> BoolArray:
        """Which BLOCK_CELLS x BLOCK_CELLS blocks hold matter (a partial block at the far edges counts
        as matter: part of it lies off the map). 1/256 of the grid, rebuilt when the world changes."""
        if self._block_solid is None or self._block_version != self.version:
            h, w = self._solid.shape
            bh, bw = -(-h // BLOCK_CELLS), -(-w // BLOCK_CELLS)
            padded = np.ones((bh * BLOCK_CELLS, bw * BLOCK_CELLS), dtype=bool)
            padded[:h, :w] = self._solid
            blocks: BoolArray = np.asarray(padded.reshape(bh, BLOCK_CELLS, bw, BLOCK_CELLS).any(axis=(1, 3)))
            self._block_solid = blocks
            self._block_version = self.version
            return blocks
        return self._block_solid

    def widest_clearance_m(self) -> float:
        """The largest clearance (to matter or the map's edge) of any cell centre: whether the robot
        fits anywhere at all. A distance transform of the whole grid: for error messages only."""
        free = np.pad(~self._solid, 1, constant_values=False)
        if not free.any():
            return 0.0
        d = ndimage.distance_transform_edt(free)
        return max(float(d.max()) - 0.5, 0.0) * self._base.resolution_m

    # -- changing --------------------------------------------------------------------------------
    def add_obstacle(self, x_m: float, y_m: float, radius_m: float = 0.2) -> None:
        """Put a round obstacle (a bin, a person standing) into the world at (x, y)."""
        self._paint(x_m, y_m, radius_m, True)

    def add_box(self, min_x_m: float, min_y_m: float, max_x_m: float, max_y_m: float) -> None:
        """Put an axis-aligned box obstacle into the world (world metres)."""
        if not (max_x_m > min_x_m and max_y_m > min_y_m):
            raise RobotError(f"a box needs max > min, got ({min_x_m}, {min_y_m})-({max_x_m}, {max_y_m})")
        g = self._base
        # only the cells under the box's bounding rectangle (in grid coordinates) can be in it
        cr, cc0 = g.world_to_cell([min_x_m, min_x_m, max_x_m, max_x_m], [min_y_m, max_y_m, min_y_m, max_y_m])
        r_lo, r_hi = max(math.floor(float(cr.min())) - 1, 0), min(math.ceil(float(cr.max())) + 1, g.height)
        c_lo, c_hi = max(math.floor(float(cc0.min())) - 1, 0), min(math.ceil(float(cc0.max())) + 1, g.width)
        rr, cc = np.mgrid[r_lo:max(r_hi, r_lo), c_lo:max(c_hi, c_lo)]
        x, y = g.cell_to_world(rr, cc)
        mask = (x >= min_x_m) & (x <= max_x_m) & (y >= min_y_m) & (y <= max_y_m)
        if not mask.any():
            raise RobotError(f"the box ({min_x_m}, {min_y_m})-({max_x_m}, {max_y_m}) misses the world "
                             f"{g.bounds_m}")
        self._solid[r_lo:r_hi, c_lo:c_hi] |= mask
        self.version += 1

    def remove_obstacles(self) -> None:
        """Take every added obstacle away again."""
        self._solid = self._base_solid.copy()
        self.version += 1

    def _paint(self, x_m: float, y_m: float, radius_m: float, value: bool) -> None:
        if not (radius_m > 0 and math.isfinite(radius_m)):
            raise RobotError(f"an obstacle radius must be a positive number of metres, got {radius_m!r}")
        g = self._base
        rc, cc = g.world_to_cell(x_m, y_m)
        reach = math.ceil(radius_m / g.resolution_m) + 1
        r0, c0 = math.floor(float(rc)), math.floor(float(cc))
        rows = np.arange(max(r0 - reach, 0), min(r0 + reach + 1, g.height))
        cols = np.arange(max(c0 - reach, 0), min(c0 + reach + 1, g.width))
        if rows.size == 0 or cols.size == 0:
            raise RobotError(f"the obstacle at ({x_m}, {y_m}) lies outside the world {g.bounds_m}")
        rr, cc2 = np.meshgrid(rows, cols, indexing="ij")
        d = np.hypot(rr + 0.5 - float(rc), cc2 + 0.5 - float(cc)) * g.resolution_m
        inside = d <= radius_m
        self._solid[rr[inside], cc2[inside]] = value
        self.version += 1


@functools.lru_cache(maxsize=16)
def _offsets(reach: int) -> tuple[npt.NDArray[np.intp], npt.NDArray[np.intp]]:
    off = np.arange(-reach, reach + 1, dtype=np.intp)
    dr, dc = np.meshgrid(off, off, indexing="ij")
    return dr.reshape(1, -1), dc.reshape(1, -1)


def disc_clearances_m(solid: BoolArray, frame: OccupancyGrid, xs_m: npt.ArrayLike, ys_m: npt.ArrayLike,
                      radius_m: float) -> npt.NDArray[np.float64]:
    """For each point, the exact distance to the nearest True cell's square of ``solid`` (in the
    frame of ``frame``), searched within ``radius_m`` plus one cell; ``inf`` when none is that
    near. Cells outside the grid count as solid. Vectorised over the points."""
    res = frame.resolution_m
    dr, dc = _offsets(math.ceil(radius_m / res) + 1)
    r, c = frame.world_to_cell(np.atleast_1d(np.asarray(xs_m, dtype=float)),
                               np.atleast_1d(np.asarray(ys_m, dtype=float)))
    r = r[:, None]
    c = c[:, None]
    rr = np.floor(r).astype(np.intp) + dr
    cc = np.floor(c).astype(np.intp) + dc
    h, w = solid.shape
    inside = (rr >= 0) & (rr < h) & (cc >= 0) & (cc < w)
    hit = ~inside
    hit[inside] = solid[rr[inside], cc[inside]]
    # distance from the point to each square [r, r+1) x [c, c+1), in cells
    gr = np.maximum(np.maximum(rr - r, r - (rr + 1)), 0.0)
    gc = np.maximum(np.maximum(cc - c, c - (cc + 1)), 0.0)
    d = np.where(hit, np.hypot(gr, gc), np.inf)
    return d.min(axis=1) * res


def disc_clearance_m(solid: BoolArray, frame: OccupancyGrid, x_m: float, y_m: float, radius_m: float) -> float:
    """:func:`disc_clearances_m` for one point."""
    return float(disc_clearances_m(solid, frame, x_m, y_m, radius_m)[0])
