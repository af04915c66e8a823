"""How far the robot walks to places, and the way it walks there: "follow the corridor" and
"halfway down the hallway" are measured along the way the hallway leads, round the bend of an
L-shaped corridor, not along a straight line through its walls.

The walk is the shortest path through passable cells (clearance at least the robot's radius, in
the robot's component), measured on the lattice of every ``k``-th cell (``lattice_stride``): two
neighbouring lattice cells that are both passable lie closer than the robot's diameter, and then
nothing blocking can lie between them (every point of the segment is nearer than the robot's
radius to one of its ends), so the lattice adds no way through a wall; and it is ``k``² times
smaller than the grid, which keeps a prompt's grounding in milliseconds on a large floor.

A point off the passable lattice (a door's centre line, an obstacle's cells, another component) is
reached by walking to the nearest lattice cell that is reached, then the straight gap from there.
"""

from __future__ import annotations

import math
import weakref
from dataclasses import dataclass
from typing import Final

import numpy as np
import numpy.typing as npt
from scipy import ndimage
from skimage.graph import MCP_Geometric

from langnav.grounding.geometry import FloatArray, FreeSpace, Point

#: With a way onward, the cells closed behind the robot begin this far back (the start's own
#: lattice neighbours stay open).
CLOSED_FROM_M: Final = 0.1
#: Walks kept per free space (the starts of the steps of a few prompts).
WALK_CACHE_SIZE: Final = 8


def lattice_stride(resolution_m: float, robot_radius_m: float) -> int:
    """The largest ``k`` whose diagonal step (k x resolution x sqrt 2) is shorter than the robot's
    diameter: neighbouring passable lattice cells then see each other (module docstring)."""
    k = math.ceil(2.0 * robot_radius_m / (math.sqrt(2.0) * resolution_m)) - 1
    return max(1, k)


@dataclass(frozen=True, eq=False)
class Walk:
    """The walks from one start over one free space. Build it with :func:`walk_from`."""

    space: FreeSpace
    start: Point
    stride: int
    #: first grid row and column of the lattice (its cell (0, 0))
    row0: int
    col0: int
    #: metres of walk to every lattice cell (unreached cells: to the nearest reached one + the gap)
    metres: FloatArray
    #: for every lattice cell, the reached lattice cell its walk goes through last
    via_row: npt.NDArray[np.intp]
    via_col: npt.NDArray[np.intp]
    mcp: MCP_Geometric

    def _lattice(self, pts: FloatArray) -> tuple[npt.NDArray[np.intp], npt.NDArray[np.intp], FloatArray]:
        """The lattice cell nearest to each point, and the straight gap from the point to it."""
        grid = self.space.grid
        rr, cc = grid.world_to_index(pts[:, 0], pts[:, 1])
        li = np.clip(np.rint((rr - self.row0) / self.stride), 0, self.metres.shape[0] - 1).astype(np.intp)
        lj = np.clip(np.rint((cc - self.col0) / self.stride), 0, self.metres.shape[1] - 1).astype(np.intp)
        xs, ys = grid.cell_to_world(self.row0 + li * self.stride, self.col0 + lj * self.stride)
        gap = np.hypot(pts[:, 0] - xs, pts[:, 1] - ys)
        return li, lj, np.asarray(gap, dtype=np.float64)

    def to(self, pts: FloatArray) -> float:
        """The shortest walk to any of ``pts`` (N, 2) in metres."""
        a = np.asarray(pts, dtype=float).reshape(-1, 2)
        if len(a) == 0:
            return math.inf
        li, lj, gap = self._lattice(a)
        return float(np.min(self.metres[li, lj] + gap))

    def reached(self, xs: FloatArray, ys: FloatArray) -> npt.NDArray[np.bool_]:
        """Whether the walk reaches each point's lattice cell itself (not only a cell near it)."""
        pts = np.column_stack([np.ravel(xs), np.ravel(ys)])
        if len(pts) == 0:
            return np.zeros(np.shape(xs), dtype=bool)
        li, lj, _ = self._lattice(pts)
        hit = (self.via_row[li, lj] == li) & (self.via_col[li, lj] == lj)
        return np.asarray(hit.reshape(np.shape(xs)), dtype=bool)

    def each(self, xs: FloatArray, ys: FloatArray) -> FloatArray:
        """The walk to each point (x, y arrays of one shape), in metres."""
        pts = np.column_stack([np.ravel(xs), np.ravel(ys)])
        if len(pts) == 0:
            return np.zeros(np.shape(xs), dtype=np.float64)
        li, lj, gap = self._lattice(pts)
        return np.asarray((self.metres[li, lj] + gap).reshape(np.shape(xs)), dtype=np.float64)

    def path_to(self, pt: Point) -> list[Point]:
        """The shortest walk to ``pt`` as world points: the start, the lattice cells walked through,
        and ``pt``."""
        li, lj, _ = self._lattice(np.asarray([pt], dtype=float))
        end = (int(self.via_row[li[0], lj[0]]), int(self.via_col[li[0], lj[0]]))
        grid = self.space.grid
        out: list[Point] = [self.start]
        for r, c in self.mcp.traceback(end):
            x, y = grid.cell_to_world(self.row0 + r * self.stride, self.col0 + c * self.stride)
            out.append((float(x), float(y)))
        out.append((float(pt[0]), float(pt[1])))
        return out


_Key = tuple[tuple[int, int], tuple[float, float, float] | None, tuple[int, ...] | None]
_CACHE: weakref.WeakKeyDictionary[FreeSpace, dict[_Key, Walk]] = weakref.WeakKeyDictionary()


def walk_from(space: FreeSpace, xy: Point, *, onward: Point | None = None, onward_m: float = 0.0,
              within: tuple[npt.NDArray[np.int32], tuple[int, ...]] | None = None) -> Walk | None:
    """The walks from the robot at ``xy``; None when it stands on no passable cell (nothing is
    reachable). With ``onward`` (a unit direction), the walks that set off that way: the passable
    cells within ``onward_m`` of the robot behind it (against ``onward``) are closed, so that the
    way back is shut (``onward_m`` a hallway's width: "down the corridor" is the way it faces).
    With ``within`` (the analysis' label array and the labels of one space's parts), the walks that stay
    in that space ("down the corridor" walks the corridor, not a short cut through a room with two
    doors onto it; the corridor's part past a cart that narrows it is the corridor).
    Cached per free space, start cell, closure and space."""
    start = space.start_cell(*xy)
    if start is None:
        return None
    key = (start, None if onward is None else (round(onward[0], 3), round(onward[1], 3), round(onward_m, 2)),
           None if within is None else within[1])  # a free space's labels are those of its one grid's analysis
    per_space = _CACHE.setdefault(space, {})
    hit = per_space.get(key)
    if hit is not None:
        return hit
    walk = _walk(space, start, xy, onward, onward_m, within)
    if len(per_space) >= WALK_CACHE_SIZE:
        per_space.clear()
    per_space[key] = walk
    return walk


def _walk(space: FreeSpace, start: tuple[int, int], xy: Point, onward: Point | None, onward_m: float,
          within: tuple[npt.NDArray[np.int32], tuple[int, ...]] | None = None) -> Walk:
    k = lattice_stride(space.grid.resolution_m, space.robot_radius_m)
    comp = int(space.components[start])
    rs, cs = space.component_box(comp)
    # the lattice through the start cell, over the component's bounding box
    row0 = start[0] - ((start[0] - rs.start) // k) * k
    col0 = start[1] - ((start[1] - cs.start) // k) * k
    lattice = space.components[row0:rs.stop:k, col0:cs.stop:k] == comp
    s = ((start[0] - row0) // k, (start[1] - col0) // k)
    if onward is not None and onward_m > 0:
        rr, cc = np.indices(lattice.shape)
        xs, ys = space.grid.cell_to_world(row0 + rr * k, col0 + cc * k)
        dx, dy = xs - space.xs[start], ys - space.ys[start]
        behind = (dx * onward[0] + dy * onward[1] < -CLOSED_FROM_M) & (np.hypot(dx, dy) <= onward_m)
        lattice = lattice & ~behind
    if within is not None:
        labels, parts = within
        lattice = lattice & np.isin(labels[row0:rs.stop:k, col0:cs.stop:k], parts)
    costs = np.where(lattice, 1.0, np.inf)
    mcp = MCP_Geometric(costs, fully_connected=True)
    cum, _ = mcp.find_costs([s])
    reached = np.isfinite(cum)
    gap, (vi, vj) = ndimage.distance_transform_edt(~reached, return_indices=True)
    step_m = k * space.grid.resolution_m
    metres = np.asarray((cum[vi, vj] + gap) * step_m, dtype=np.float64)
    return Walk(space, xy, k, row0, col0, metres, vi.astype(np.intp), vj.astype(np.intp), mcp)


__all__ = ["Walk", "lattice_stride", "walk_from"]
