"""Map analysis: precision / recall against the bench annotations, speed and peak memory.

Prints, per bench map and summed over them, precision and recall per element kind, then the
time of ``analyze()`` on env2 (target < 100 ms) and on strands_aaf_y4_cropped (< 2 s) and the
peak memory (target < 500 MB). Needs ../shared; prints why and exits 0 when it is absent.
"""

from __future__ import annotations

import gc
import resource
import statistics
import sys
import time
import tracemalloc
from pathlib import Path

from langnav.analysis.pipeline import analyze
from langnav.eval.annotations import TARGET_KINDS, KindScore, load_annotations, score_analysis
from langnav.maps.io import load_map

SHARED = Path(__file__).resolve().parents[2] / "shared"
BENCH_MAPS = ("env1", "env2")
STRANDS = SHARED / "maps" / "ros" / "strands_aaf_y4_cropped.yaml"
#: Timing repeats (median reported); few, the machine is shared.
REPEATS_SMALL = 7
REPEATS_LARGE = 3
TARGET_SCORE = 0.95


def _time(grid_path: Path, repeats: int) -> tuple[float, float, float, int, float]:
    """Median and best wall seconds, peak traced MB (one traced run), cells, and the median
    CPU seconds of the process (on a shared machine the wall time counts the other jobs' turns
    on the cores too; the CPU time does not)."""
    grid = load_map(grid_path)
    analyze(grid)  # warm-up (imports, caches)
    times = []
    cpu = []
    for _ in range(repeats):
        gc.collect()
        c0 = time.process_time()
        t0 = time.perf_counter()
        analyze(grid)
        times.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
    tracemalloc.start()
    analyze(grid)
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    return statistics.median(times), min(times), peak / 1e6, grid.width * grid.height, statistics.median(cpu)


def main() -> int:
    if not SHARED.is_dir():
        print(f"skipped: {SHARED} not present (bench maps and real maps)")
        return 0
    totals: dict[str, list[int]] = {}
    for name in BENCH_MAPS:
        grid = load_map(SHARED / "bench" / "maps" / f"{name}.yaml")
        ann = load_annotations(SHARED / "bench" / "maps" / f"{name}.annotations.json")
        scores = score_analysis(analyze(grid), ann)
        print(f"{name}:")
        for s in scores.values():
            print(f"  {s.kind:24s} detected {s.detected:3d}  annotated {s.annotated:3d}  matched {s.matched:3d}"
                  f"  P {s.precision:.3f}  R {s.recall:.3f}")
            t = totals.setdefault(s.kind, [0, 0, 0])
            t[0] += s.detected
            t[1] += s.annotated
            t[2] += s.matched
    print("env1+env2:")
    for kind, (det, ann_n, matched) in totals.items():
        s = KindScore(kind, det, ann_n, matched)
        flag = ""
        if kind in TARGET_KINDS:
            flag = "ok" if s.precision >= TARGET_SCORE and s.recall >= TARGET_SCORE else "BELOW TARGET"
        print(f"  {kind:24s} P {s.precision:.3f}  R {s.recall:.3f}  {flag}")
    env2 = SHARED / "bench" / "maps" / "env2.yaml"
    med, best, peak, cells, cpu = _time(env2, REPEATS_SMALL)
    print(f"env2 ({cells} cells): analyze median {med * 1000:.1f} ms, best {best * 1000:.1f} ms "
          f"(target < 100 ms), traced peak {peak:.1f} MB, CPU median {cpu * 1000:.1f} ms")
    if STRANDS.exists():
        med, best, peak, cells, cpu = _time(STRANDS, REPEATS_LARGE)
        print(f"strands_aaf_y4_cropped ({cells} cells): analyze median {med:.2f} s, best {best:.2f} s "
              f"(target < 2 s), traced peak {peak:.1f} MB, CPU median {cpu:.2f} s")
    else:
        print(f"strands map not found at {STRANDS}")
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"process max RSS {rss:.0f} MB (target < 500 MB)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
