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

#: Log-odds are stored as int8 in units of 1/LOGODDS_SCALE: every constant above is a whole number of
#: tenths, so the sums are exact (no float drift) and the map takes a byte a cell.
LOGODDS_SCALE: Final = 10
_HIT: Final = round(L_HIT * LOGODDS_SCALE)
_MISS: Final = round(L_MISS * LOGODDS_SCALE)
_MIN: Final = round(L_MIN * LOGODDS_SCALE)
_MAX: Final = round(L_MAX * LOGODDS_SCALE)
#: A scan touches cells within the range plus the hit depth plus this many cells of slack.
WINDOW_SLACK_CELLS: Final = 2

FloatArray = npt.NDArray[np.float64]
Window = tuple[slice, slice]


class LogOddsMap:
    """An occupancy map in the frame of ``frame``, built from scans. Each scan touches only the
    window its beams reach; the trinary cells are kept up to date in that window."""

    def __init__(self, frame: OccupancyGrid, *, known: OccupancyGrid | None = None) -> None:
        self._frame = frame
        self._logodds: npt.NDArray[np.int8] = np.zeros(frame.cells.shape, dtype=np.int8)
        if known is not None:
            if known.cells.shape != frame.cells.shape:
                raise ValueError(f"the known map {known.cells.shape} must have the world's shape "
                                 f"{frame.cells.shape}")
            self._logodds[known.cells == FREE] = _MIN
            self._logodds[known.cells == OCCUPIED] = _MAX
        self.version = 0
        self._cells = np.full(frame.cells.shape, UNKNOWN, dtype=np.int8)
        self._classify((slice(None), slice(None)))

    @property
    def logodds(self) -> FloatArray:
        """The log-odds of every cell (a float copy)."""
        return self._logodds.astype(np.float64) / LOGODDS_SCALE

    def _classify(self, win: Window) -> bool:
        """Recompute the trinary cells in ``win``; whether any changed."""
        lo = self._logodds[win]
        out = np.full(lo.shape, UNKNOWN, dtype=np.int8)
        out[lo >= L_OCCUPIED * LOGODDS_SCALE] = OCCUPIED
        out[lo <= L_FREE * LOGODDS_SCALE] = FREE
        changed = not np.array_equal(out, self._cells[win])
        if changed:
            self._cells[win] = out
        return changed

    def integrate(self, x_m: float, y_m: float, yaw_rad: float, angles_rad: FloatArray,
                  ranges_m: FloatArray, range_max_m: float) -> Window | None:
        """Add one scan taken at (x, y, yaw). ``inf`` ranges clear out to ``range_max_m``.
        Returns the window of cells the scan could change when some cell's class changed, else None."""
        g = self._frame
        res = g.resolution_m
        h, w = g.height, g.width
        r0, c0 = (float(v) for v in g.world_to_cell(x_m, y_m))
        reach = math.ceil(range_max_m / res + HIT_DEPTH_CELLS) + WINDOW_SLACK_CELLS
        wr0, wr1 = max(math.floor(r0) - reach, 0), min(math.floor(r0) + reach + 1, h)
        wc0, wc1 = max(math.floor(c0) - reach, 0), min(math.floor(c0) + reach + 1, w)
        self.version += 1
        if wr0 >= wr1 or wc0 >= wc1:
            return None  # the sensor is far off the map
        wh, ww = wr1 - wr0, wc1 - wc0
        lr, lc = r0 - wr0, c0 - wc0  # the sensor in window coordinates
        theta = angles_rad + (yaw_rad - g.origin_yaw_rad)
        hit = np.isfinite(ranges_m)
        reach_cells = np.where(hit, ranges_m, range_max_m) / res
        clear_to = reach_cells - np.where(hit, END_MARGIN_CELLS, 0.0)
        sin_t, cos_t = np.sin(theta), np.cos(theta)
        touched = np.zeros(wh * ww, dtype=bool)
        # samples along each beam up to its own end only: (beam, t) pairs built with repeat
        counts = np.ceil(np.maximum(clear_to, 0.0) / STEP_CELLS).astype(np.intp)
        total = int(counts.sum())
        if total:
            beam = np.repeat(np.arange(len(theta)), counts)
            starts = np.repeat(np.cumsum(counts) - counts, counts)
            t = (np.arange(total) - starts) * STEP_CELLS
            ri = np.floor(lr + sin_t[beam] * t).astype(np.intp)
            ci = np.floor(lc + cos_t[beam] * t).astype(np.intp)
            ok = (ri >= 0) & (ri < wh) & (ci >= 0) & (ci < ww)
            touched[ri[ok] * ww + ci[ok]] = True
        ends = np.zeros(wh * ww, dtype=bool)
        if hit.any():
            depth = reach_cells[hit] + HIT_DEPTH_CELLS
            er = np.floor(lr + sin_t[hit] * depth).astype(np.intp)
            ec = np.floor(lc + cos_t[hit] * depth).astype(np.intp)
            ok = (er >= 0) & (er < wh) & (ec >= 0) & (ec < ww)
            ends[er[ok] * ww + ec[ok]] = True
        win = (slice(wr0, wr1), slice(wc0, wc1))
        sub = self._logodds[win].astype(np.int16).reshape(-1)  # int16: no overflow before the clamp
        miss = touched & ~ends
        sub[miss] = np.maximum(sub[miss] + _MISS, _MIN)
        sub[ends] = np.minimum(sub[ends] + _HIT, _MAX)
        self._logodds[win] = sub.reshape(wh, ww).astype(np.int8)
        return win if self._classify(win) else None

    def cells(self) -> npt.NDArray[np.int8]:
        """The trinary cells (FREE / OCCUPIED / UNKNOWN) of the current map (read-only view)."""
        view = self._cells.view()
        view.flags.writeable = False
        return view

    def grid(self) -> OccupancyGrid:
        """The current map as an OccupancyGrid (a copy, safe to keep)."""
        g = self._frame
        return OccupancyGrid(self._cells.copy(), g.resolution_m, g.origin_x_m, g.origin_y_m,
                             g.origin_yaw_rad, source="sim:map")

    def window_grid(self, rows: slice, cols: slice) -> OccupancyGrid:
        """A copy of part of the map (``rows`` x ``cols`` of cells, clipped to the map) as a grid of
        its own, its origin moved to the window's corner."""
        g = self._frame
        r0, r1, _ = rows.indices(g.height)
        c0, c1, _ = cols.indices(g.width)
        x, y = g.grid_to_world(r0, c0)
        return OccupancyGrid(self._cells[r0:r1, c0:c1].copy(), g.resolution_m, float(x), float(y),
                             g.origin_yaw_rad, source="sim:map")
