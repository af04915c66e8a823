"""The blind test material (benchmarks/blind/README.md): prompts and buildings written by people
who had not read the code they measure.

* prompts: ``blind/prompts*/spoken.jsonl`` (spoken motion commands of imagined speakers) and
  ``blind/prompts*/buildings.jsonl`` (place-grounded prompts in new buildings), one folder a round,
  scored by langnav's bench metrics (the same rules as the bench's score.py), with the overshoot count;
* maps: ``blind/maps*/maps`` (drawn and simulated-SLAM buildings with a person's point annotations),
  scored by ``../shared/maps/eval_points.py`` (skipped with the reason when ../shared is absent).
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from langnav.eval.cases import MapCache, load_cases
from langnav.eval.metrics import CaseResult, ValidityMap, score_case, summarise
from langnav.eval.overshoot import Overshoot, overshoots
from langnav.language.translator import get_translator
from langnav.pipeline import Planner

HERE = Path(__file__).resolve().parent
BLIND = HERE / "blind"
EVAL_POINTS = HERE.parents[1] / "shared" / "maps" / "eval_points.py"
#: A whole map analysis is allowed this long before the run is called hung.
ANALYSE_ALL_TIMEOUT_S = 1800


def score_prompts(path: Path) -> None:
    cases = load_cases(path)
    maps = MapCache(path.parent)
    planner = Planner(get_translator("offline"))
    validity: dict[int, ValidityMap] = {}
    results: list[CaseResult] = []
    unsafe: list[Overshoot] = []
    for case in cases:
        grid = maps.get(case)
        planner.history.clear()  # each case is a session of its own
        out = planner.plan(case.prompt, grid, case.pose).to_bench(case.id)
        results.append(score_case(case.model_dump(), out, validity.setdefault(id(grid), ValidityMap(grid))))
        unsafe.extend(overshoots(case.model_dump(), out))
    s = summarise(results)
    ntp = "n/a" if s.ntp_validity is None else f"{s.ntp_validity:.4f}"
    move = "n/a" if s.move_validity is None else f"{s.move_validity:.4f}"
    print(f"{path.relative_to(HERE)}: {len(cases)} cases, prompt accuracy {s.prompt_accuracy:.4f}, "
          f"command F1 {s.overall.f1:.4f}, pose validity NTP {ntp} Move {move}, "
          f"moves farther or turns more than asked: {len({o.id for o in unsafe})} cases")
    for r in results:
        if not r.right:
            print(f"  MISS {r.id}: {r.prompt}  -- {'; '.join(r.why)}")


def main() -> int:
    # every round of blind material in its own folder: prompts*/ (spoken.jsonl, buildings.jsonl),
    # maps*/maps (maps with their points); see blind/README.md for which round is which
    for folder in sorted(BLIND.glob("prompts*/")):
        for name in ("spoken.jsonl", "buildings.jsonl"):
            if (folder / name).exists():
                score_prompts(folder / name)
    if not EVAL_POINTS.exists():
        print(f"blind maps skipped: {EVAL_POINTS} not found (../shared is not on this machine)")
        return 0
    langnav = Path(sys.executable).with_name("langnav")
    for folder in sorted(BLIND.glob("maps*/maps")):
        print(f"blind maps {folder.parent.name}/ (doors, spaces, kind, narrow passages against a person's points):",
              flush=True)
        subprocess.run([sys.executable, str(EVAL_POINTS), str(langnav), str(folder)],
                       check=True, timeout=ANALYSE_ALL_TIMEOUT_S)
    return 0


if __name__ == "__main__":
    sys.exit(main())
