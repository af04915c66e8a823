"""Accuracy and speed of prompt -> validated commands.

* the bench's figures (prompt accuracy, command F1, pose validity; as ``score.py`` counts them) for
  the dev prompts and the SCOUT dev cases (real spoken commands), with the time per prompt;

* per prompt on env2 with the analysis cached: the translator alone, grounding + validation alone,
  and the whole Planner.plan (target < 50 ms per prompt);
* the 34 dev cases end to end as ``langnav translate --cases`` does it, maps loaded and analysed once
  (target < 5 s in all), in-process and as a fresh process (with imports).

Needs ../shared/bench; prints why it skips otherwise.
"""

from __future__ import annotations

import argparse
import io
import statistics
import subprocess
import sys
import time
from contextlib import redirect_stdout
from pathlib import Path
from typing import Final

from langnav.errors import LangnavError
from langnav.eval.cases import MapCache, load_cases
from langnav.eval.metrics import CaseResult, ValidityMap, score_case, summarise
from langnav.eval.overshoot import Overshoot, overshoots
from langnav.grounding import ground
from langnav.language.translator import Context, get_translator
from langnav.pipeline import Planner
from langnav.plan.validator import validate_plan

BENCH = Path(__file__).resolve().parents[2] / "shared" / "bench"
REPEATS = 20
#: Case files scored by ``make bench`` (relative to the bench folder).
SCORED: Final = ("prompts_dev.jsonl", "scout/cases_dev.jsonl")


def score_file(cases_path: Path, translator: str) -> None:
    """The bench's figures for one case file, each prompt planned (translated, grounded, validated)
    and timed as ``langnav eval`` does it."""
    cases = load_cases(cases_path)
    maps = MapCache(cases_path.resolve().parent)
    planner = Planner(get_translator(translator))
    validity: dict[int, ValidityMap] = {}
    results: list[CaseResult] = []
    times: list[float] = []
    unsafe: list[Overshoot] = []
    for case in cases:
        grid = maps.get(case)
        planner.analysis_for(grid)  # analysed once per map, not timed as a prompt
        t0 = time.perf_counter()
        out = planner.plan(case.prompt, grid, case.pose).to_bench(case.id)
        times.append(time.perf_counter() - t0)
        results.append(score_case(case.model_dump(), out, validity.setdefault(id(grid), ValidityMap(grid))))
        unsafe.extend(overshoots(case.model_dump(), out))
    s = summarise(results)
    ntp = "n/a" if s.ntp_validity is None else f"{s.ntp_validity:.4f}"
    move = "n/a" if s.move_validity is None else f"{s.move_validity:.4f}"
    ms = sorted(1000 * x for x in times)
    print(f"{cases_path.relative_to(BENCH)}: {len(cases)} cases, prompt accuracy {s.prompt_accuracy:.4f}, "
          f"command F1 {s.overall.f1:.4f} (P {s.overall.precision:.4f} R {s.overall.recall:.4f}), "
          f"pose validity NTP {ntp} Move {move}")
    print(f"  per prompt: median {statistics.median(ms):.2f} ms, p95 {ms[int(0.95 * (len(ms) - 1))]:.2f} ms, "
          f"max {ms[-1]:.2f} ms   (target: median < 50 ms)")
    print(f"  moves farther or turns more than asked: {len({o.id for o in unsafe})} cases (target 0)")
    for o in unsafe:
        print(f"    {o}")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--translator", default="offline")
    ap.add_argument("--cases", type=Path, default=BENCH / "prompts_dev.jsonl")
    args = ap.parse_args()
    if not args.cases.exists():
        print(f"skipped: {args.cases} not found (../shared/bench is not on this machine)")
        return 0
    for name in SCORED:
        path = BENCH / name
        if path.exists():
            score_file(path, args.translator)
        else:
            print(f"skipped: {path} not found")
    cases = load_cases(args.cases)
    maps = MapCache(args.cases.resolve().parent)
    translator = get_translator(args.translator)
    planner = Planner(translator)
    env2 = [c for c in cases if c.map.endswith("env2.yaml")]
    grid = maps.get(env2[0])
    analysis = planner.analysis_for(grid)  # cached from here on
    t_tr: list[float] = []
    t_gr: list[float] = []
    t_all: list[float] = []
    for _ in range(REPEATS):
        for c in env2:
            ctx = Context(analysis=analysis, pose=c.pose)
            t0 = time.perf_counter()
            intent = translator.translate(c.prompt, ctx)
            t1 = time.perf_counter()
            try:
                plan = ground(intent, analysis, c.pose)
                validate_plan(plan.commands, grid, c.pose)
            except LangnavError:
                pass  # refusals are timed too
            t2 = time.perf_counter()
            planner.plan(c.prompt, grid, c.pose)
            t3 = time.perf_counter()
            t_tr.append(t1 - t0)
            t_gr.append(t2 - t1)
            t_all.append(t3 - t2)

    def fig(xs: list[float]) -> str:
        xs_ms = sorted(1000 * x for x in xs)
        return (f"mean {statistics.mean(xs_ms):6.2f} ms  median {statistics.median(xs_ms):6.2f} ms  "
                f"p95 {xs_ms[int(0.95 * (len(xs_ms) - 1))]:6.2f} ms  max {xs_ms[-1]:6.2f} ms")

    print(f"env2, {len(env2)} prompts x {REPEATS}, analysis cached, translator {translator.name}:")
    print(f"  translator           {fig(t_tr)}")
    print(f"  grounding+validation {fig(t_gr)}")
    print(f"  Planner.plan         {fig(t_all)}   (target < 50 ms)")

    # all cases in-process, as `langnav translate --cases` runs them (fresh planner, maps analysed once)
    from langnav.cli.translate import run_cases

    t0 = time.perf_counter()
    with redirect_stdout(io.StringIO()):
        run_cases(Planner(get_translator(args.translator)), args.cases)
    t_in = time.perf_counter() - t0
    t0 = time.perf_counter()
    proc = subprocess.run([sys.executable, "-c", "import sys; from langnav.cli import main; sys.exit(main())",
                           "translate", "--cases", str(args.cases), "--translator", args.translator],
                          capture_output=True, text=True, timeout=120, check=False)
    t_proc = time.perf_counter() - t0
    print(f"{len(cases)} cases with --cases: {t_in:.2f} s in-process (maps loaded + analysed once), "
          f"{t_proc:.2f} s as a fresh process with imports (exit {proc.returncode})   (target < 5 s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
