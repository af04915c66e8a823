"""The global planner: Dijkstra on the costmap (scikit-image's minimum-cost-path, compiled), with
8-connected moves and a cost per cell that grows with the inflation cost, then a light smoothing.

Like NavFn with ``allow_unknown: true``: unknown cells may be crossed, at a premium, so the robot
can head into space it has not mapped yet; lethal and inscribed cells may not.
"""

from __future__ import annotations

import math
from typing import Final

import numpy as np
import numpy.typing as npt
from skimage.graph import MCP_Geometric

from langnav.robot.errors import RobotError
from langnav.robot.sim.costmap import INSCRIBED, MAX_NON_OBSTACLE, NO_INFORMATION, Costmap

#: NavFn's weights: a free cell costs COST_NEUTRAL, an inflated one COST_NEUTRAL + COST_FACTOR * cost,
#: an unknown one (allow_unknown) COST_OBS - 1 = 253, the dearest cell that may be crossed. Divided
#: by COST_NEUTRAL here, so a free cell costs 1 and a path's cost reads roughly in cells.
COST_NEUTRAL: Final = 50.0
COST_FACTOR: Final = 0.8
UNKNOWN_COST: Final = 253.0 / COST_NEUTRAL
#: A goal inside an obstacle's inflation is moved to the nearest safe cell within this distance
#: (Nav2's planner tolerance).
GOAL_TOLERANCE_M: Final = 0.25
#: Near the start, inscribed cells may be crossed (at a high price) so a robot that ended up close
#: to an obstacle can still leave.
START_ESCAPE_M: Final = 0.3
START_ESCAPE_COST: Final = 50.0
#: Moving-average window (cells) for smoothing the staircase of a grid path.
SMOOTH_WINDOW: Final = 5

Path = list[tuple[float, float]]


class NoPathError(RobotError):
    """The planner found no path on the robot's map."""


class WalledOffError(NoPathError):
    """No path: the goal is cut off from the start on the map searched (a larger window may help)."""


def traversal_costs(costmap: Costmap, allow_unknown: bool = True) -> npt.NDArray[np.float64]:
    """Per-cell cost for the planner: ``inf`` where the robot's centre must not go."""
    c = costmap.costs
    out = (COST_NEUTRAL + COST_FACTOR * np.minimum(c, MAX_NON_OBSTACLE).astype(np.float64)) / COST_NEUTRAL
    out[c >= INSCRIBED] = np.inf
    if allow_unknown:
        out[c == NO_INFORMATION] = UNKNOWN_COST
    return out


def _cell(costmap: Costmap, x_m: float, y_m: float, what: str) -> tuple[int, int]:
    r, c = costmap.frame.world_to_index(x_m, y_m)
    if not costmap.frame.in_bounds(r, c):
        b = costmap.frame.bounds_m
        raise NoPathError(f"the {what} ({x_m:.2f}, {y_m:.2f}) is outside the map "
                          f"(x {b[0]:.1f}..{b[2]:.1f}, y {b[1]:.1f}..{b[3]:.1f})")
    return int(r), int(c)


def _safe_goal(costs: npt.NDArray[np.float64], goal: tuple[int, int], radius_cells: float) -> tuple[int, int] | None:
    if np.isfinite(costs[goal]):
        return goal
    reach = math.ceil(radius_cells)
    r0, c0 = goal
    rr, cc = np.mgrid[r0 - reach:r0 + reach + 1, c0 - reach:c0 + reach + 1]
    h, w = costs.shape
    ok = (rr >= 0) & (rr < h) & (cc >= 0) & (cc < w)
    rr, cc = rr[ok], cc[ok]
    d = np.hypot(rr - r0, cc - c0)
    cand = np.isfinite(costs[rr, cc]) & (d <= radius_cells)
    if not cand.any():
        return None
    i = int(np.argmin(np.where(cand, d, np.inf)))
    return int(rr[i]), int(cc[i])


def plan(costmap: Costmap, start_xy: tuple[float, float], goal_xy: tuple[float, float], *,
         allow_unknown: bool = True, costs: npt.NDArray[np.float64] | None = None) -> Path:
    """A smoothed path (world metres) from start to goal; raises NoPathError with the reason."""
    frame = costmap.frame
    res = frame.resolution_m
    base = traversal_costs(costmap, allow_unknown) if costs is None else costs
    s = _cell(costmap, *start_xy, "start")
    g = _cell(costmap, *goal_xy, "goal")
    goal_cell = _safe_goal(base, g, GOAL_TOLERANCE_M / res)
    if goal_cell is None:
        why = "in an obstacle" if costmap.costs[g] >= INSCRIBED + 1 else "too close to an obstacle"
        if costmap.costs[g] == NO_INFORMATION and not allow_unknown:
            why = "in unknown space"
        raise NoPathError(f"the goal ({goal_xy[0]:.2f}, {goal_xy[1]:.2f}) is {why} "
                          f"(the robot needs {costmap.params.robot_radius_m:.2f} m of clearance)")
    cost = base.copy()
    # let the robot leave an inscribed spot near its start
    reach = math.ceil(START_ESCAPE_M / res)
    r0, c0 = s
    sl = (slice(max(r0 - reach, 0), r0 + reach + 1), slice(max(c0 - reach, 0), c0 + reach + 1))
    window = cost[sl]
    near_lethal = ~np.isfinite(window) & (costmap.costs[sl] == INSCRIBED)
    window[near_lethal] = START_ESCAPE_COST
    cost[s] = max(1.0, float(cost[s]) if np.isfinite(cost[s]) else START_ESCAPE_COST)
    if s == goal_cell:
        return [start_xy, goal_xy]
    mcp = MCP_Geometric(cost)
    cum, _ = mcp.find_costs([s], [goal_cell])
    if not np.isfinite(cum[goal_cell]):
        raise WalledOffError(f"no path from ({start_xy[0]:.2f}, {start_xy[1]:.2f}) to "
                          f"({goal_xy[0]:.2f}, {goal_xy[1]:.2f}): the goal is walled off on the robot's map")
    cells = np.asarray(mcp.traceback(goal_cell), dtype=np.float64)
    xs, ys = frame.cell_to_world(cells[:, 0], cells[:, 1])
    pts = np.column_stack([xs, ys])
    pts = smooth(pts)
    pts[0] = start_xy
    end = goal_xy if goal_cell == g else (float(xs[-1]), float(ys[-1]))
    pts[-1] = end
    return [(float(x), float(y)) for x, y in pts]


def smooth(points: npt.NDArray[np.float64], window: int = SMOOTH_WINDOW) -> npt.NDArray[np.float64]:
    """Moving-average smoothing of a path's interior (ends kept): takes the staircase out of an
    8-connected grid path without moving it more than a cell or two."""
    n = len(points)
    if n <= 2 or window < 2:
        return points.copy()
    half = window // 2
    padded = np.concatenate([np.repeat(points[:1], half, 0), points, np.repeat(points[-1:], half, 0)])
    kernel = np.ones(window) / window
    out = np.column_stack([np.convolve(padded[:, k], kernel, mode="valid") for k in range(2)])
    out = out[:n]
    out[0], out[-1] = points[0], points[-1]
    return out


def path_length_m(path: Path) -> float:
    if len(path) < 2:
        return 0.0
    a = np.asarray(path)
    return float(np.hypot(*np.diff(a, axis=0).T).sum())
