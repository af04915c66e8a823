"""A 2D lidar ray-cast on the ground truth: 360 beams, ~10 m, gaussian range noise.

Vectorised stepped sampling: all beams are sampled every half cell, a chunk of samples at a time
for the beams still open, in numpy; the first solid sample is the hit. Half-cell steps cannot jump
over a wall cell edge-on (a grazing touch of a one-cell speck's corner may be missed, as a real beam
may). Beams with no return within range get ``inf`` (REP 117).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Final

import numpy as np
import numpy.typing as npt

from langnav.robot.sim.world import World

#: 1-degree beams, as an RPLIDAR A1 on a TurtleBot 4 gives.
DEFAULT_BEAMS: Final = 360
#: Usable range; the RPLIDAR A1 is rated to 12 m, 10 m is what slam_toolbox is usually given.
DEFAULT_RANGE_MAX_M: Final = 10.0
#: Closest usable return (the sensor's blind zone).
DEFAULT_RANGE_MIN_M: Final = 0.15
#: Range noise, 1-sigma; a cheap 2D lidar is good to about a centimetre indoors.
DEFAULT_NOISE_STD_M: Final = 0.01
#: Sampling step along a beam, in cells: half a cell cannot skip a cell edge-on.
STEP_CELLS: Final = 0.5
#: Samples per marching chunk (48 half-cells = 1.2 m at 5 cm): most beams end in two or three.
CHUNK_SAMPLES: Final = 48

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True)
class LidarSpec:
    beams: int = DEFAULT_BEAMS
    range_max_m: float = DEFAULT_RANGE_MAX_M
    range_min_m: float = DEFAULT_RANGE_MIN_M
    noise_std_m: float = DEFAULT_NOISE_STD_M

    @property
    def angle_increment_rad(self) -> float:
        return 2.0 * math.pi / self.beams

    @property
    def angle_min_rad(self) -> float:
        return -math.pi


class Lidar:
    """Casts scans on the world's ground truth (which may change between scans)."""

    def __init__(self, world: World, spec: LidarSpec | None = None) -> None:
        self.spec = spec or LidarSpec()
        self._world = world
        self._frame = world.frame
        self._angles: FloatArray = (self.spec.angle_min_rad
                                    + np.arange(self.spec.beams, dtype=np.float64) * self.spec.angle_increment_rad)
        self._chunk: FloatArray = np.arange(1, CHUNK_SAMPLES + 1, dtype=np.float64) * STEP_CELLS
        self._solid: npt.NDArray[np.bool_] | None = None
        self._solid_version = -1

    @property
    def angles_rad(self) -> FloatArray:
        """Beam angles in the robot frame."""
        return self._angles

    def true_ranges(self, x_m: float, y_m: float, yaw_rad: float) -> FloatArray:
        """Noise-free ranges (``inf`` for no return) from a sensor at (x, y, yaw)."""
        g = self._frame
        solid = self._padded_solid()
        h, w = solid.shape[0] - 2, solid.shape[1] - 2
        flat = solid.reshape(-1)
        r0, c0 = (float(v) + 1.0 for v in g.world_to_cell(x_m, y_m))  # +1: the padded border
        theta = self._angles + (yaw_rad - g.origin_yaw_rad)
        sin_t, cos_t = np.sin(theta), np.cos(theta)
        t_max = self.spec.range_max_m / g.resolution_m
        ranges = np.full(len(theta), math.inf)
        active = np.arange(len(theta))
        t0 = 0.0
        # march all still-open beams a chunk of samples at a time (most beams end in the first few)
        while active.size and t0 < t_max:
            t = t0 + self._chunk
            rows = np.clip(r0 + sin_t[active, None] * t, 0.0, h + 1.0).astype(np.intp)
            cols = np.clip(c0 + cos_t[active, None] * t, 0.0, w + 1.0).astype(np.intp)
            hit = flat[rows * (w + 2) + cols]
            ended = hit.any(axis=1)
            first = hit.argmax(axis=1)[ended]
            # the surface lies between the last free sample and the first solid one: take the middle
            ranges[active[ended]] = (t[first] - 0.5 * STEP_CELLS) * g.resolution_m
            active = active[~ended]
            t0 += CHUNK_SAMPLES * STEP_CELLS
        ranges[ranges > self.spec.range_max_m] = math.inf
        return ranges

    def _padded_solid(self) -> npt.NDArray[np.bool_]:
        """The world's solid mask with a solid one-cell border (beams stop at the map's edge).
        Cached until the world changes."""
        if self._solid_version != self._world.version or self._solid is None:
            self._solid = np.pad(self._world.solid, 1, constant_values=True)
            self._solid_version = self._world.version
        return self._solid

    def scan(self, x_m: float, y_m: float, yaw_rad: float, rng: np.random.Generator) -> FloatArray:
        """A noisy scan: true ranges plus gaussian noise; out of [range_min, range_max] -> inf."""
        ranges = self.true_ranges(x_m, y_m, yaw_rad)
        finite = np.isfinite(ranges)
        noisy = ranges.copy()
        noisy[finite] += rng.normal(0.0, self.spec.noise_std_m, int(finite.sum()))
        bad = ~finite | (noisy < self.spec.range_min_m) | (noisy > self.spec.range_max_m)
        noisy[bad] = math.inf
        return noisy
