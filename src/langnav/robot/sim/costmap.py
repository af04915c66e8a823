"""A global costmap with inflation, in Nav2's cost semantics.

Like Nav2's inflation layer: occupied cells are LETHAL (254), cells closer to one than the robot's
inscribed radius are INSCRIBED (253, the robot's centre must not go there), and the cost then
decays as ``252 * exp(-cost_scaling_factor * (d - inscribed_radius))`` out to the inflation radius.
Unknown cells are NO_INFORMATION (255) unless inflation puts a higher-priority cost on them
(Nav2's ``track_unknown_space: true``); the planner decides whether it may cross them.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Final

import numpy as np
import numpy.typing as npt
from scipy import ndimage

from langnav.maps.grid import OccupancyGrid
from langnav.robot.sim.world import ROBOT_RADIUS_M

FREE_SPACE: Final = 0
MAX_NON_OBSTACLE: Final = 252
INSCRIBED: Final = 253
LETHAL: Final = 254
NO_INFORMATION: Final = 255

#: Nav2's default inflation radius in the TurtleBot 4 configuration.
DEFAULT_INFLATION_RADIUS_M: Final = 0.55
#: Nav2's cost_scaling_factor in the TurtleBot 4 configuration (1/m).
DEFAULT_COST_SCALING: Final = 3.0
#: Extra margin on the inscribed radius: distances are measured between cell centres, so a cell's
#: own half-width (and a smoothed path's drift) can hide about this much of the true gap.
CELL_MARGIN_CELLS: Final = 1.0

UInt8Array = npt.NDArray[np.uint8]


@dataclass(frozen=True)
class InflationParams:
    robot_radius_m: float = ROBOT_RADIUS_M
    inflation_radius_m: float = DEFAULT_INFLATION_RADIUS_M
    cost_scaling_factor: float = DEFAULT_COST_SCALING


@dataclass(frozen=True, eq=False)
class Costmap:
    """Costs (uint8, Nav2 semantics) in the frame of ``frame``; ``clearance_m`` is the distance
    from each cell centre to the nearest occupied cell centre."""

    costs: UInt8Array
    clearance_m: npt.NDArray[np.float64]
    frame: OccupancyGrid
    params: InflationParams

    def cost_at(self, x_m: float, y_m: float) -> int:
        r, c = self.frame.world_to_index(x_m, y_m)
        if not self.frame.in_bounds(r, c):
            return LETHAL
        return int(self.costs[int(r), int(c)])


def inflate(grid: OccupancyGrid, params: InflationParams | None = None) -> Costmap:
    """The costmap of a map: LETHAL on occupied cells, INSCRIBED within the robot's radius, an
    exponential decay out to the inflation radius, NO_INFORMATION on unknown cells."""
    p = params or InflationParams()
    res = grid.resolution_m
    occupied = grid.occupied
    if occupied.any():
        dist_m = ndimage.distance_transform_edt(~occupied).astype(np.float64) * res
    else:
        dist_m = np.full(occupied.shape, np.inf)
    inscribed_m = p.robot_radius_m + CELL_MARGIN_CELLS * res
    decay = MAX_NON_OBSTACLE * np.exp(-p.cost_scaling_factor * np.maximum(dist_m - inscribed_m, 0.0))
    costs = np.where(dist_m <= p.inflation_radius_m, decay, 0.0)
    costs = np.floor(costs).astype(np.uint8)
    costs[dist_m <= inscribed_m] = INSCRIBED
    costs[occupied] = LETHAL
    costs[grid.unknown & (costs < INSCRIBED)] = NO_INFORMATION
    return Costmap(costs, dist_m, grid, p)
