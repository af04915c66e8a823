"""How far the robot walks to things, and which way the walk sets off: the order in which a person
walking from the robot meets the doors and rooms ("the second door on your left", "the last room on
the right"), not the order of straight lines through walls.

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

from langnav.grounding.geometry import FloatArray, FreeSpace, Point, Pose, bearing_rad

#: The walk sets off in the direction of its first point this far from the robot (past the cells
#: round the robot, where a lattice path bends to reach the lattice).
SET_OFF_M: Final = 1.0
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

    def sets_off_bearing(self, pts: FloatArray, pose: Pose) -> float:
        """The bearing (radians from the heading, left > 0) in which the shortest walk to ``pts``
        sets off from ``pose``: towards its first point ``SET_OFF_M`` away (the target itself when it
        is nearer)."""
        a = np.asarray(pts, dtype=float).reshape(-1, 2)
        li, lj, gap = self._lattice(a)
        i = int(np.argmin(self.metres[li, lj] + gap))
        end = (int(self.via_row[li[i], lj[i]]), int(self.via_col[li[i], lj[i]]))
        grid = self.space.grid
        for r, c in self.mcp.traceback(end):
            x, y = grid.cell_to_world(self.row0 + r * self.stride, self.col0 + c * self.stride)
            p = (float(x), float(y))
            if math.dist(p, pose.xy) >= SET_OFF_M:
                return bearing_rad(pose, p)
        return bearing_rad(pose, (float(a[i, 0]), float(a[i, 1])))


_CACHE: weakref.WeakKeyDictionary[FreeSpace, dict[tuple[int, int], Walk]] = weakref.WeakKeyDictionary()


def walk_from(space: FreeSpace, xy: Point) -> Walk | None:
    """The walks from the robot at ``xy``; None when it stands on no passable cell (nothing is
    reachable). Cached per free space and start cell."""
    start = space.start_cell(*xy)
    if start is None:
        return None
    per_space = _CACHE.setdefault(space, {})
    hit = per_space.get(start)
    if hit is not None:
        return hit
    walk = _walk(space, start, xy)
    if len(per_space) >= WALK_CACHE_SIZE:
        per_space.clear()
    per_space[start] = walk
    return walk


def _walk(space: FreeSpace, start: tuple[int, int], xy: Point) -> Walk:
    k = lattice_stride(space.grid.resolution_m, space.robot_radius_m)
    comp = int(space.components[start])
    rs, cs = space.component_box(comp)
    # the lattice through the start cell, over the component's bounding box
    row0 = start[0] - ((start[0] - rs.start) // k) * k
    col0 = start[1] - ((start[1] - cs.start) // k) * k
    lattice = space.components[row0:rs.stop:k, col0:cs.stop:k] == comp
    s = ((start[0] - row0) // k, (start[1] - col0) // k)
    costs = np.where(lattice, 1.0, np.inf)
    mcp = MCP_Geometric(costs, fully_connected=True)
    cum, _ = mcp.find_costs([s])
    reached = np.isfinite(cum)
    gap, (vi, vj) = ndimage.distance_transform_edt(~reached, return_indices=True)
    step_m = k * space.grid.resolution_m
    metres = np.asarray((cum[vi, vj] + gap) * step_m, dtype=np.float64)
    return Walk(space, xy, k, row0, col0, metres, vi.astype(np.intp), vj.astype(np.intp), mcp)


__all__ = ["SET_OFF_M", "Walk", "lattice_stride", "walk_from"]
