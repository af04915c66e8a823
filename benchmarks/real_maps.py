"""Real ROS maps against a person's point annotation (prints figures; asserts nothing).

  .venv/bin/python benchmarks/real_maps.py

Runs ../shared/maps/eval_points.py (``langnav analyze`` on every map of ../shared/maps/ros
that has a MAP.points.json, scored by score_points.py beside it): one line per map (doors,
spaces, room-or-hallway kind, narrow passages) and the figures pooled over the maps. Then the
time of one analysis of each map (target: under 2 s each). Issue 8's targets: doors, spaces and
kind >= 0.90 precision and recall; narrow passages >= 0.80.
Skips, saying why, when ../shared is not there.
"""

from __future__ import annotations

import logging
import subprocess
import sys
import time
from pathlib import Path

from langnav.analysis.pipeline import analyze
from langnav.maps.io import load_map

SHARED = Path(__file__).resolve().parents[2] / "shared"
MAPS = SHARED / "maps"
ROS = MAPS / "ros"
EVAL = MAPS / "eval_points.py"
#: One map's analysis (subprocess and all) may not take longer than this.
EVAL_TIMEOUT_S = 900
#: Each real map is analysed in under this (issue 8).
TARGET_S = 2.0


def main() -> int:
    if not EVAL.exists() or not ROS.is_dir():
        print(f"real_maps: skipped: {EVAL} or {ROS} is not there (the shared data folder)")
        return 0
    langnav = Path(sys.executable).parent / "langnav"
    if not langnav.exists():
        print(f"real_maps: skipped: no langnav command beside {sys.executable} (install the package)")
        return 0
    print("(a) per map and pooled (../shared/maps/eval_points.py)", flush=True)
    try:
        run = subprocess.run([sys.executable, str(EVAL), str(langnav), str(ROS)], capture_output=True,
                             text=True, timeout=EVAL_TIMEOUT_S, check=False)
    except subprocess.TimeoutExpired:
        print(f"real_maps: eval_points.py timed out after {EVAL_TIMEOUT_S} s")
        return 1
    print(run.stdout, end="", flush=True)
    if run.returncode:
        print(f"real_maps: eval_points.py failed ({run.returncode}): {run.stderr.strip()[-500:]}")
        return 1
    print(f"(b) analysis time per map (target < {TARGET_S:.0f} s)", flush=True)
    logging.disable(logging.WARNING)
    slow = 0
    for pts in sorted(ROS.glob("*.points.json")):
        name = pts.name[: -len(".points.json")]
        grid = load_map(ROS / f"{name}.yaml")
        t0 = time.perf_counter()
        analyze(grid)
        dt = time.perf_counter() - t0
        slow += dt >= TARGET_S
        print(f"  {name:28s} {grid.width}x{grid.height} cells  {dt * 1000:6.0f} ms"
              f"{'' if dt < TARGET_S else '  SLOW'}", flush=True)
    print(f"  {slow} map(s) at or over {TARGET_S:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
