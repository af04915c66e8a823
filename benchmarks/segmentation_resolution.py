"""Does a building segment alike at two cell sizes? (prints figures; asserts nothing)

  .venv/bin/python benchmarks/segmentation_resolution.py [FOLDER ...]

Every threshold of the segmentation is in metres, so a map and the same map with each cell
split in four (half the cell size) should give the same spaces. For every map with a
MAP.points.json (a person's points, one per room or hallway) in the folders (default: the
blind map rounds in benchmarks/blind), the spaces are found at both cell sizes and compared on
the annotated points: for every pair of points, do they share a space at one size exactly when
they do at the other? Prints one line per map (spaces of at least 2 m2 at each size, pairs
alike) and the share of pairs alike over all maps. Maps whose fine copy would exceed
``MAX_FINE_CELLS`` are left out (time).
"""

from __future__ import annotations

import argparse
import json
import logging
from pathlib import Path

import numpy as np

from langnav.analysis.segmentation import segment_spaces
from langnav.maps.grid import OccupancyGrid
from langnav.maps.io import load_map

HERE = Path(__file__).resolve().parent
DEFAULT_FOLDERS = sorted((HERE / "blind").glob("maps*/maps"))
#: Larger fine copies take minutes each on the shared machine.
MAX_FINE_CELLS = 12_000_000
#: Spaces smaller than this (m2) are not counted (as score_points.py does).
MIN_SPACE_M2 = 2.0


def halved(grid: OccupancyGrid) -> OccupancyGrid:
    """``grid`` with each cell split in four: the same map at half the cell size."""
    cells = np.repeat(np.repeat(grid.cells, 2, axis=0), 2, axis=1)
    return OccupancyGrid(cells, grid.resolution_m / 2, grid.origin_x_m, grid.origin_y_m,
                         grid.origin_yaw_rad, f"{grid.source} (half cells)")


def spaces_at_points(grid: OccupancyGrid, points: list[tuple[float, float]]) -> tuple[list[int], int]:
    """The space label at each point (0: none) and how many spaces of >= MIN_SPACE_M2 there are."""
    seg = segment_spaces(grid)
    labels = []
    for x, y in points:
        r, c = grid.world_to_index(x, y)
        inside = 0 <= int(r) < grid.height and 0 <= int(c) < grid.width
        labels.append(int(seg.labels[int(r), int(c)]) if inside else 0)
    return labels, sum(1 for room in seg.rooms if room.area_m2 >= MIN_SPACE_M2)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="*", type=Path, default=DEFAULT_FOLDERS)
    args = parser.parse_args()
    logging.basicConfig(level=logging.ERROR)
    total = alike = 0
    for folder in args.folders:
        for pts in sorted(folder.glob("*.points.json")):
            name = pts.name[: -len(".points.json")]
            grid = load_map(pts.with_name(f"{name}.yaml"))
            if grid.cells.size * 4 > MAX_FINE_CELLS:
                print(f"{name:28s} left out: {grid.width} x {grid.height} cells (fine copy too large)")
                continue
            points = [tuple(s["point"]) for s in json.loads(pts.read_text(encoding="utf-8"))["spaces"]]
            (a, na), (b, nb) = spaces_at_points(grid, points), spaces_at_points(halved(grid), points)
            n = len(points)
            pairs = n * (n - 1) // 2
            same = sum(1 for i in range(n) for j in range(i + 1, n) if (a[i] == a[j]) == (b[i] == b[j]))
            total += pairs
            alike += same
            print(f"{name:28s} {grid.resolution_m:g} m: {na:3d} spaces, {grid.resolution_m / 2:g} m: {nb:3d}; "
                  f"point pairs alike {same}/{pairs}", flush=True)
    print(f"ALL point pairs alike {alike}/{total} = {alike / max(total, 1):.4f}")


if __name__ == "__main__":
    main()
