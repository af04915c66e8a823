"""Run every benchmark script in this folder (``make bench``) and print their figures.

Each script prints its own figures and exits 0; one that needs ../shared prints why it
skipped. Speed and memory targets are checked here, never in timed unit tests.
"""

from __future__ import annotations

import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
#: One benchmark may not run longer than this (the IPA benchmark is the longest).
TIMEOUT_S = 1800


def main() -> int:
    scripts = sorted(p for p in HERE.glob("*.py") if p.name not in {"run_all.py", "__init__.py"})
    failed: list[str] = []
    for script in scripts:
        print(f"\n=== {script.stem} ===", flush=True)
        t0 = time.perf_counter()
        try:
            rc = subprocess.run([sys.executable, str(script)], timeout=TIMEOUT_S, check=False).returncode
        except subprocess.TimeoutExpired:
            rc = -1
            print(f"{script.name}: timed out after {TIMEOUT_S} s")
        print(f"--- {script.stem}: exit {rc}, {time.perf_counter() - t0:.1f} s", flush=True)
        if rc != 0:
            failed.append(script.stem)
    if failed:
        print(f"\nfailed: {', '.join(failed)}")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
