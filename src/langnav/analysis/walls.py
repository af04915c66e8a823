"""Walls: straight segments of the boundary between each space's free cells and occupied cells.

For every free cell of a space that touches a wall cell (4-neighbour), the direction into the
wall is the gradient of the lightly smoothed wall mask; the *face point* is on the cell edge
towards the wall. Per space, face points are grouped by direction (histogram peaks), then by
offset along that direction (points within ``params.wall_max_deviation_m`` of one line), then
split along the line where the gap is wider than a doorway (a door does not break a wall: the
wall of a room is the whole side). Runs shorter than ``params.wall_min_length_m``, or solid for
less than half their length outside their widest opening, are dropped.
Everything is computed in grid coordinates and turned into world metres at the end, so a map
with a rotated origin gives rotated walls.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Final

import numpy as np
import numpy.typing as npt
from scipy import ndimage as ndi

from langnav.analysis.elements import Wall
from langnav.analysis.params import AnalysisParams
from langnav.analysis.precompute import GridLayers, cov2, dilate4, median, nonzero2
from langnav.maps.grid import OccupancyGrid

#: Smoothing of the wall mask before taking its gradient, in cells: enough to turn a pixel
#: staircase into one direction, small enough that a corner only blurs its last cell or two.
GRADIENT_SIGMA_CELLS: Final = 1.0
#: Reach of the smoothing and Sobel filters (4 sigma + 1 cell), plus one: a window of the wall mask
#: this far past the cells whose gradient is taken gives the same values as the whole grid.
_GRADIENT_PAD: Final = int(4 * GRADIENT_SIGMA_CELLS) + 2
#: On large maps, the wall mask is smoothed only in square tiles of this size (cells) that hold
#: wall faces; the open floor and the unknown margin between them are skipped.
GRADIENT_TILE_CELLS: Final = 256
#: ... when the faces' window has at least this many cells: on smaller ones the per-tile overhead
#: outweighs the saving (on a 3-Mcell map tiles halve the time: fewer cells, and cache-sized).
TILED_MIN_WINDOW_CELLS: Final = 1_000_000
#: Direction histogram bin (degrees); wall directions within this of each other are one group.
DIRECTION_BIN_DEG: Final = 5.0
#: A face point joins a wall direction when its own direction is within this (degrees).
DIRECTION_TOL_DEG: Final = 20.0
#: Face points within this of the group direction (degrees) define the fitted line.
REFIT_TOL_DEG: Final = 5.0
#: A wall run is solid (face points per cell of length) for at least this share of its length
#: outside its widest opening (a door does not make a wall sparse; scattered clutter does).
MIN_SOLID_FRACTION: Final = 0.5
#: At most this many lines are taken out of one direction group (guards noisy real maps).
MAX_LINES_PER_DIRECTION: Final = 200

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True)
class WallLine:
    """A fitted wall in grid coordinates (x = col, y = row, in cells; continuous)."""

    label: int
    normal: tuple[float, float]  # unit, grid frame, pointing *into the wall* (out of the room)
    rho: float  # face line: p . normal = rho
    s0: float  # extent along the tangent (-ny, nx)
    s1: float

    @property
    def tangent(self) -> tuple[float, float]:
        return (-self.normal[1], self.normal[0])

    def point(self, s: float) -> tuple[float, float]:
        nx, ny = self.normal
        tx, ty = self.tangent
        return (self.rho * nx + s * tx, self.rho * ny + s * ty)


def _face_points(labels: npt.NDArray[np.int32], wall: npt.NDArray[np.bool_], free: npt.NDArray[np.bool_]
                 ) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray, npt.NDArray[np.int32]]:
    """Face points (x, y) in grid cells, their unit normals into the wall, and their space label.

    Only *free* cells of a space count: a space's unknown cells (an unscanned patch counted in
    its floor area) do not show where its walls are.
    """
    near_wall = dilate4(wall)
    boundary = (labels > 0) & free & near_wall & ~wall
    rows, cols = nonzero2(boundary)
    empty = np.zeros(0)
    if len(rows) == 0:
        return empty, empty, empty, empty, np.zeros(0, dtype=np.int32)
    gy, gx = _wall_gradient(wall, rows, cols)
    norm = np.hypot(gx, gy)
    ok = norm > 1e-6
    rows, cols, gx, gy, norm = rows[ok], cols[ok], gx[ok], gy[ok], norm[ok]
    nx, ny = gx / norm, gy / norm
    # Face point: the cell centre moved half a cell towards the wall (on the free/occupied edge).
    x = cols + 0.5 + 0.5 * nx
    y = rows + 0.5 + 0.5 * ny
    return x, y, nx, ny, labels[rows, cols]


def _wall_gradient(wall: npt.NDArray[np.bool_], rows: npt.NDArray[np.intp], cols: npt.NDArray[np.intp]
                   ) -> tuple[FloatArray, FloatArray]:
    """Sobel gradient (d/d row, d/d col) of the smoothed wall mask at the given cells.

    Smooths only windows holding those cells (real maps are mostly unknown margin and open
    floor): the window around them all, or on a large map the square tiles holding any of them.
    Every window reaches ``_GRADIENT_PAD`` cells past its cells (past the filters' reach) or the
    grid's own edge, so each value is exactly the one the filters give on the whole grid.
    """
    h, w = wall.shape
    r0, r1 = max(0, int(rows.min()) - _GRADIENT_PAD), min(h, int(rows.max()) + _GRADIENT_PAD + 1)
    c0, c1 = max(0, int(cols.min()) - _GRADIENT_PAD), min(w, int(cols.max()) + _GRADIENT_PAD + 1)
    if (r1 - r0) * (c1 - c0) < TILED_MIN_WINDOW_CELLS:
        return _gradient_window(wall, rows, cols, (r0, r1, c0, c1))
    t = GRADIENT_TILE_CELLS
    n_tc = (c1 - c0 + t - 1) // t
    key = ((rows - r0) // t) * n_tc + (cols - c0) // t
    counts = np.bincount(key)
    tiles = np.flatnonzero(counts)
    bounds = np.concatenate([[0], np.cumsum(counts[tiles])])
    order = np.argsort(key, kind="stable")
    gy = np.empty(len(rows))
    gx = np.empty(len(rows))
    for i in range(len(tiles)):
        sel = order[bounds[i]:bounds[i + 1]]
        rs, cs = rows[sel], cols[sel]
        # The window around this tile's cells only.
        win = (max(0, int(rs.min()) - _GRADIENT_PAD), min(h, int(rs.max()) + _GRADIENT_PAD + 1),
               max(0, int(cs.min()) - _GRADIENT_PAD), min(w, int(cs.max()) + _GRADIENT_PAD + 1))
        gy[sel], gx[sel] = _gradient_window(wall, rs, cs, win)
    return gy, gx


def _gradient_window(wall: npt.NDArray[np.bool_], rows: npt.NDArray[np.intp], cols: npt.NDArray[np.intp],
                     win: tuple[int, int, int, int]) -> tuple[FloatArray, FloatArray]:
    """``ndi.sobel`` along rows and along columns of the smoothed window, at the given cells only.

    Spelt out as ``ndi.sobel`` computes it (each pass in double, stored as float32, reflected at
    the edges), so the values are bit for bit the same without filtering the whole window. The
    cells are at least ``_GRADIENT_PAD`` inside every edge of the window that is not the grid's,
    so a neighbour index off the window is off the grid, where "reflect" repeats the edge cell.
    """
    r0, r1, c0, c1 = win
    sm = ndi.gaussian_filter(wall[r0:r1, c0:c1].astype(np.float32), GRADIENT_SIGMA_CELLS)
    hh, ww = sm.shape
    rr = rows - r0
    cc = cols - c0
    near_r = {d: np.clip(rr + d, 0, hh - 1) for d in (-1, 0, 1)}
    near_c = {d: np.clip(cc + d, 0, ww - 1) for d in (-1, 0, 1)}

    def at(dr: int, dc: int) -> FloatArray:
        return sm[near_r[dr], near_c[dc]].astype(np.float64)

    def stored(v: FloatArray) -> FloatArray:  # a pass's output, kept as float32
        return v.astype(np.float32).astype(np.float64)

    # First pass: the [-1, 0, 1] derivative (centre weight 0: 0.0 + (next - previous)); second:
    # the [1, 2, 1] smoothing across it (2 * centre + (next + previous)).
    d_row = [stored((at(1, dc) - at(-1, dc)) + 0.0) for dc in (-1, 0, 1)]
    gy = stored(d_row[1] * 2.0 + (d_row[2] + d_row[0]) * 1.0)
    d_col = [stored((at(dr, 1) - at(dr, -1)) + 0.0) for dr in (-1, 0, 1)]
    gx = stored(d_col[1] * 2.0 + (d_col[2] + d_col[0]) * 1.0)
    return gy, gx


def _direction_peaks(theta_deg: FloatArray, min_points: float) -> list[float]:
    """Dominant directions (degrees) of a set of face normals: peaks of a circular histogram."""
    nbins = round(360 / DIRECTION_BIN_DEG)
    hist = np.bincount((theta_deg // DIRECTION_BIN_DEG).astype(int) % nbins, minlength=nbins).astype(float)
    # (The neighbours round the circle: ``np.roll`` by 1 and by -1, without its generic set-up.)
    smooth = hist + 0.5 * (np.concatenate((hist[-1:], hist[:-1])) + np.concatenate((hist[1:], hist[:1])))
    peaks: list[float] = []
    order = np.argsort(-smooth)
    # The bins walked one by one: as Python values (a numpy scalar per look costs more).
    sm = smooth.tolist()
    taken = [False] * nbins
    span = math.ceil(DIRECTION_TOL_DEG / DIRECTION_BIN_DEG)
    for b in order.tolist():
        if sm[b] < min_points:
            break
        if taken[b]:
            continue
        if sm[b] < sm[(b - 1) % nbins] or sm[b] < sm[(b + 1) % nbins]:
            continue
        for d in range(-span, span + 1):
            taken[(b + d) % nbins] = True
        peaks.append((b + 0.5) * DIRECTION_BIN_DEG)
    return peaks


def _ang_diff(a: FloatArray, b: float) -> FloatArray:
    return np.abs((a - b + 180.0) % 360.0 - 180.0)


def _refit(x: FloatArray, y: FloatArray, n_x: float, n_y: float) -> tuple[float, float, float] | None:
    """Total-least-squares line through face points: (normal x, normal y, offset), the normal
    towards the wall; ``None`` when the fit turns more than half the direction tolerance away
    from the group's direction (a degenerate set of points), so the caller keeps the group's line.
    """
    if len(x) < 3:
        return None
    mx, my = float(x.mean()), float(y.mean())
    _evals, evecs = np.linalg.eigh(cov2(np.stack([x - mx, y - my])))
    fx, fy = float(evecs[0, 0]), float(evecs[1, 0])  # smallest eigenvalue: the normal
    if fx * n_x + fy * n_y < 0:
        fx, fy = -fx, -fy
    if fx * n_x + fy * n_y < math.cos(math.radians(DIRECTION_TOL_DEG / 2)):
        return None
    return fx, fy, mx * fx + my * fy


def fit_wall_lines(grid: OccupancyGrid, params: AnalysisParams, labels: npt.NDArray[np.int32],
                   wall: npt.NDArray[np.bool_], layers: GridLayers | None = None) -> list[WallLine]:
    """Straight wall lines per space label, in grid coordinates (see the module docstring)."""
    free = grid.free if layers is None else layers.free
    x, y, nx, ny, lab = _face_points(labels, wall, free)
    res = grid.resolution_m
    min_len = params.wall_min_length_m / res
    max_dev = max(params.wall_max_deviation_m / res, 0.5)
    max_gap = params.door_max_width_m / res + 1.0
    # Counting points within +-max_dev of each offset bin: a box kernel that wide.
    half = math.ceil(max_dev)
    window = np.ones(2 * half + 1)
    lines: list[WallLine] = []
    if len(x) == 0:
        return lines
    theta = np.degrees(np.arctan2(ny, nx)) % 360.0
    order = np.argsort(lab, kind="stable")
    bounds = [*np.searchsorted(lab[order], np.unique(lab), side="left").tolist(), len(lab)]
    for i, space in enumerate(np.unique(lab).tolist()):
        idx = order[bounds[i]:bounds[i + 1]]
        th = theta[idx]
        # The histogram alone can merge two close directions; the tolerance keeps groups tight.
        for peak in _direction_peaks(th, min_points=min_len * 0.5):
            near = _ang_diff(th, peak) <= DIRECTION_TOL_DEG
            if np.count_nonzero(near) < min_len * 0.5:
                continue
            sel = idx[near]
            x_sel, y_sel = x[sel], y[sel]
            # Refine the direction: circular mean of the members.
            phi = math.atan2(float(ny[sel].sum()), float(nx[sel].sum()))
            n_x, n_y = math.cos(phi), math.sin(phi)
            rho = x_sel * n_x + y_sel * n_y
            squarely = _ang_diff(th[near], math.degrees(phi)) <= REFIT_TOL_DEG
            remaining = np.ones(len(sel), dtype=bool)
            for _ in range(MAX_LINES_PER_DIRECTION):
                if np.count_nonzero(remaining) < min_len * 0.5:
                    break
                r_rem = rho[remaining]
                base = math.floor(float(r_rem.min()))
                hist = np.bincount((r_rem - base).astype(int))
                # Count within +-half of each bin (bin k: "full" output k + half): the densest
                # line offset. Of tied bins take the middle one (a compact line ties every bin
                # whose window holds it; the first of them is off by the half window), then the
                # median of the points in its window.
                dens = np.convolve(hist, window, mode="full")[half:half + len(hist)]
                ties = np.flatnonzero(dens == dens.max())
                k = int(ties[len(ties) // 2])
                in_window = remaining & (rho >= base + k - half) & (rho < base + k + half + 1)
                centre = median(rho[in_window])
                member = remaining & (np.abs(rho - centre) <= max_dev)
                remaining &= ~member
                if np.count_nonzero(member) < min_len * 0.5:
                    break  # the densest line left is too short: so is every other one
                # Fit the line through the points that face squarely onto it (the ends of a run
                # bend round corners and bumps and would tilt it).
                square = member & squarely
                fit_set = square if np.count_nonzero(square) >= 3 else member
                fit = _refit(x_sel[fit_set], y_sel[fit_set], n_x, n_y)
                m_nx, m_ny, m_centre = (n_x, n_y, centre) if fit is None else fit
                s_line = -x_sel[member] * m_ny + y_sel[member] * m_nx
                s_m = np.sort(s_line)
                steps = np.diff(s_m)
                gaps = np.flatnonzero(steps > max_gap)
                starts = np.concatenate([[0], gaps + 1])
                ends = np.concatenate([gaps, [len(s_m) - 1]])
                for a, b in zip(starts.tolist(), ends.tolist(), strict=True):
                    # Face points are cell centres projected on the face: the run covers half a
                    # cell more at each end.
                    s0, s1 = float(s_m[a]) - 0.5, float(s_m[b]) + 0.5
                    # Solid for at least half its length not counting its widest opening (a
                    # short wall that is mostly a doorway, as at a corridor's end, is still a
                    # wall), and for at least half the shortest wall's length.
                    opening = max(float(steps[a:b].max()) - 1.0, 0.0) if b > a else 0.0
                    solid_needed = MIN_SOLID_FRACTION * max(s1 - s0 - opening, min_len)
                    if s1 - s0 >= min_len and (b - a + 1) >= solid_needed:
                        lines.append(WallLine(int(space), (m_nx, m_ny), m_centre, s0, s1))
    return lines


def line_to_world(grid: OccupancyGrid, line: WallLine) -> tuple[tuple[float, float], tuple[float, float], tuple[float, float]]:
    """(start, end, inward unit normal) of a grid-frame line in world metres."""
    p0 = line.point(line.s0)
    p1 = line.point(line.s1)
    x0, y0 = grid.grid_to_world(p0[1], p0[0])
    x1, y1 = grid.grid_to_world(p1[1], p1[0])
    c, s = math.cos(grid.origin_yaw_rad), math.sin(grid.origin_yaw_rad)
    inx, iny = -line.normal[0], -line.normal[1]
    return ((_clean(x0), _clean(y0)), (_clean(x1), _clean(y1)),
            (_clean(c * inx - s * iny), _clean(s * inx + c * iny)))


def _clean(v: float | np.floating | npt.NDArray[np.float64]) -> float:
    """Drop floating-point dust (1e-17, -0.0) from a coordinate: nanometres do not matter."""
    return round(float(v), 9) + 0.0


def find_walls(grid: OccupancyGrid, params: AnalysisParams, labels: npt.NDArray[np.int32],
               room_ids: Mapping[int, str], wall: npt.NDArray[np.bool_] | None = None,
               layers: GridLayers | None = None) -> tuple[Wall, ...]:
    """Wall segments bounding each space. ``wall`` is the mask of wall cells (default: occupied;
    the pipeline removes obstacles from it so furniture sides are not walls); ``layers`` the
    grid's shared masks (built when not given)."""
    layers = layers or GridLayers(grid)
    mask = layers.occupied if wall is None else wall
    walls: list[Wall] = []
    for k, line in enumerate(fit_wall_lines(grid, params, labels, mask, layers), start=1):
        start, end, inward = line_to_world(grid, line)
        walls.append(Wall(id=f"wall_{k}", start=start, end=end, room=room_ids.get(line.label), inward=inward))
    return tuple(walls)
