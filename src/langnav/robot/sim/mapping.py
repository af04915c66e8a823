"""Log-odds occupancy mapping from lidar scans (what slam_toolbox's map is, with perfect localisation).

Every scan lowers the log-odds of the cells its beams cross and raises those where they end. The
rays are traced by stepped sampling (every ``STEP_CELLS`` of a cell, all beams at once in numpy),
each cell updated at most once per scan. The map is published with map_server's semantics:
probability >= 0.65 occupied (0 in a saved PGM), <= 0.196 free (254), otherwise or never seen
unknown (205) -> :class:`OccupancyGrid` OCCUPIED / FREE / UNKNOWN.

The simulated robot knows its pose exactly (no SLAM drift): the map is only as wrong as the
lidar noise makes it.
"""

from __future__ import annotations

import math
from typing import Final

import numpy as np
import numpy.typing as npt

from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN, OccupancyGrid

#: log-odds added where a beam ends (p = 0.77: one hit makes a cell occupied).
L_HIT: Final = 1.2
#: log-odds added where a beam passes (p = 0.18: one pass makes an unseen cell free, as the first
#: scan of slam_toolbox shows free space at once; a cleared cell needs three hits to turn occupied).
L_MISS: Final = -1.5
#: Clamps, so a cell can change its mind after a few scans (a moved obstacle).
L_MIN: Final = -2.5
L_MAX: Final = 3.5
#: map_server's thresholds (occupied_thresh 0.65, free_thresh 0.196) in log-odds.
L_OCCUPIED: Final = math.log(0.65 / 0.35)
L_FREE: Final = math.log(0.196 / 0.804)
#: Ray sampling step in cells (0.7 visits nearly every crossed cell at a third of the half-step cost).
STEP_CELLS: Final = 0.7
#: A beam clears cells up to this far (in cells) before its end, so the end cell is not cleared.
END_MARGIN_CELLS: Final = 0.5
#: The hit is marked this far (in cells) beyond the measured range: a return lies on the surface,
#: the boundary of two cells, and the cell to mark is the one behind it (the wall's), not the free
#: one in front, which would thicken every wall by a cell at random.
HIT_DEPTH_CELLS: Final = 0.5

FloatArray = npt.NDArray[np.float64]


class LogOddsMap:
    """An occupancy map in the frame of ``frame``, built from scans."""

    def __init__(self, frame: OccupancyGrid, *, known: OccupancyGrid | None = None) -> None:
        self._frame = frame
        self._logodds: FloatArray = np.zeros(frame.cells.shape, dtype=np.float64)
        if known is not None:
            if known.cells.shape != frame.cells.shape:
                raise ValueError(f"the known map {known.cells.shape} must have the world's shape "
                                 f"{frame.cells.shape}")
            self._logodds[known.cells == FREE] = L_MIN
            self._logodds[known.cells == OCCUPIED] = L_MAX
        self.version = 0
        self._cells_cache: npt.NDArray[np.int8] | None = None

    @property
    def logodds(self) -> FloatArray:
        view = self._logodds.view()
        view.flags.writeable = False
        return view

    def integrate(self, x_m: float, y_m: float, yaw_rad: float, angles_rad: FloatArray,
                  ranges_m: FloatArray, range_max_m: float) -> None:
        """Add one scan taken at (x, y, yaw). ``inf`` ranges clear out to ``range_max_m``."""
        g = self._frame
        res = g.resolution_m
        h, w = self._logodds.shape
        r0, c0 = (float(v) for v in g.world_to_cell(x_m, y_m))
        theta = angles_rad + (yaw_rad - g.origin_yaw_rad)
        hit = np.isfinite(ranges_m)
        reach_cells = np.where(hit, ranges_m, range_max_m) / res
        clear_to = reach_cells - np.where(hit, END_MARGIN_CELLS, 0.0)
        sin_t, cos_t = np.sin(theta), np.cos(theta)
        flat_size = h * w
        touched = np.zeros(flat_size, dtype=bool)
        # samples along each beam up to its own end only: (beam, t) pairs built with repeat
        counts = np.ceil(np.maximum(clear_to, 0.0) / STEP_CELLS).astype(np.intp)
        total = int(counts.sum())
        if total:
            beam = np.repeat(np.arange(len(theta)), counts)
            starts = np.repeat(np.cumsum(counts) - counts, counts)
            t = (np.arange(total) - starts) * STEP_CELLS
            ri = np.floor(r0 + sin_t[beam] * t).astype(np.intp)
            ci = np.floor(c0 + cos_t[beam] * t).astype(np.intp)
            ok = (ri >= 0) & (ri < h) & (ci >= 0) & (ci < w)
            touched[ri[ok] * w + ci[ok]] = True
        ends = np.zeros(flat_size, dtype=bool)
        if hit.any():
            depth = reach_cells[hit] + HIT_DEPTH_CELLS
            er = np.floor(r0 + sin_t[hit] * depth).astype(np.intp)
            ec = np.floor(c0 + cos_t[hit] * depth).astype(np.intp)
            ok = (er >= 0) & (er < h) & (ec >= 0) & (ec < w)
            ends[er[ok] * w + ec[ok]] = True
        flat = self._logodds.reshape(-1)
        miss = touched & ~ends
        flat[miss] = np.maximum(flat[miss] + L_MISS, L_MIN)
        flat[ends] = np.minimum(flat[ends] + L_HIT, L_MAX)
        self.version += 1
        self._cells_cache = None

    def cells(self) -> npt.NDArray[np.int8]:
        """The trinary cells (FREE / OCCUPIED / UNKNOWN) of the current map."""
        if self._cells_cache is None:
            out = np.full(self._logodds.shape, UNKNOWN, dtype=np.int8)
            out[self._logodds >= L_OCCUPIED] = OCCUPIED
            out[self._logodds <= L_FREE] = FREE
            self._cells_cache = out
        return self._cells_cache

    def grid(self) -> OccupancyGrid:
        """The current map as an OccupancyGrid (a copy, safe to keep)."""
        g = self._frame
        return OccupancyGrid(self.cells().copy(), g.resolution_m, g.origin_x_m, g.origin_y_m,
                             g.origin_yaw_rad, source="sim:map")
