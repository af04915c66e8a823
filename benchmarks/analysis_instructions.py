"""Map analysis: machine instructions per ``analyze()`` of env2, counted by valgrind's callgrind.

On a shared machine the wall time counts the other jobs' turns on the cores, and even the CPU
time rises with their load (caches and cores' hyper-threads are shared). The number of
instructions an analysis executes does not: callgrind counts them exactly, the same on every
run, so a speed change shows as a difference of a fraction of a percent where the times
scatter by tens of percent.

The analysis runs once to warm up (imports, the process's tables) with counting off, then
``REPEATS`` times inside ``operator.call``: callgrind counts only inside that C function
(``--toggle-collect``), which nothing else in the process calls. Needs valgrind and ../shared;
prints why and exits 0 when either is absent. Each count takes a minute or two (callgrind
runs the program some 50 times slower).

    python benchmarks/analysis_instructions.py            # env2
    python benchmarks/analysis_instructions.py MAP.yaml   # any map
"""

from __future__ import annotations

import operator
import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

SHARED = Path(__file__).resolve().parents[2] / "shared"
ENV2 = SHARED / "bench" / "maps" / "env2.yaml"
#: Analyses counted (after the warm-up); the count is exact, one is enough.
REPEATS = 1
#: The C function inside which callgrind counts: CPython's ``operator.call``.
TOGGLE_FUNCTION = "_operator_call"
#: One count may not run longer than this (callgrind is slow; a shared machine slower still).
TIMEOUT_S = 1800
_COLLECTED = re.compile(r"Collected\s*:\s*(\d+)")


def _inner(map_path: str, repeats: int) -> None:
    """Run inside callgrind: the analyses to count."""
    from langnav.analysis.pipeline import analyze
    from langnav.maps.io import load_map

    grid = load_map(map_path)
    analyze(grid)  # warm-up, not counted

    def run() -> None:
        for _ in range(repeats):
            analyze(grid)

    operator.call(run)


def count(map_path: Path, repeats: int = REPEATS) -> int:
    """Instructions executed by ``repeats`` analyses of the map (after a warm-up)."""
    with tempfile.TemporaryDirectory() as tmp:
        cmd = ["valgrind", "--tool=callgrind", "--collect-atstart=no",
               f"--toggle-collect={TOGGLE_FUNCTION}", f"--callgrind-out-file={Path(tmp) / 'out'}",
               sys.executable, __file__, "--inner", str(map_path), str(repeats)]
        # A fixed hash seed: the same dict and set orders, so the same instructions every run.
        env = {**os.environ, "PYTHONHASHSEED": "0"}
        done = subprocess.run(cmd, capture_output=True, text=True, timeout=TIMEOUT_S, check=False, env=env)
    found = _COLLECTED.search(done.stderr)
    if done.returncode != 0 or found is None:
        raise RuntimeError(f"callgrind failed (exit {done.returncode}): {done.stderr[-2000:]}")
    return int(found.group(1))


def main(argv: list[str]) -> int:
    if len(argv) == 3 and argv[0] == "--inner":
        _inner(argv[1], int(argv[2]))
        return 0
    if shutil.which("valgrind") is None:
        print("skipped: valgrind not installed (apt-get install valgrind)")
        return 0
    maps = [Path(a) for a in argv] or [ENV2]
    for path in maps:
        if not path.exists():
            print(f"skipped: {path} not present")
            continue
        n = count(path)
        if n == 0:
            print(f"{path.stem}: 0 instructions counted: the Python binary has no symbol "
                  f"{TOGGLE_FUNCTION} for callgrind to toggle on (a stripped build)")
            continue
        print(f"{path.stem}: {n / REPEATS / 1e6:.1f} M instructions per analyze() (callgrind, exact)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
