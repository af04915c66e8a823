"""``langnav eval``: the paper's evaluation over a bench case file — prompt accuracy, command
precision / recall / F1 overall and per command type, pose validity — a table on stdout and,
with --report, a Markdown or HTML report of every miss with a chart."""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

from langnav.errors import LangnavError
from langnav.eval.cases import MapCache, load_cases
from langnav.eval.metrics import CaseResult, ValidityMap, score_case, summarise
from langnav.eval.overshoot import Overshoot, overshoots
from langnav.eval.report import table, write_report
from langnav.language.translator import get_translator
from langnav.maps.grid import OccupancyGrid
from langnav.pipeline import Planner


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--cases", type=Path, required=True, help="bench case file (JSONL)")
    p.add_argument("--translator", default="offline", help="offline (default), gemini, openai, local, auto")
    p.add_argument("--report", type=Path, help="write a report: OUT.md (with OUT.png) or OUT.html")
    p.add_argument("--outputs", type=Path, help="also write the bench output lines here (JSONL)")
    p.add_argument("--json", action="store_true", help="print the summary as JSON instead of a table")


def run(args: argparse.Namespace) -> int:
    cases = load_cases(args.cases)
    if not cases:
        raise LangnavError(f"{args.cases}: no cases")
    planner = Planner(get_translator(args.translator))
    maps = MapCache(args.cases.resolve().parent)
    validity: dict[int, ValidityMap] = {}
    results: list[CaseResult] = []
    unsafe: list[Overshoot] = []
    lines: list[str] = []
    t_all = 0.0
    show = sys.stderr.isatty() or len(cases) > 20
    for n, case in enumerate(cases, 1):
        grid: OccupancyGrid = maps.get(case)
        planner.history.clear()  # each case is a session of its own: no trail from the cases before it
        t0 = time.perf_counter()
        out = planner.plan(case.prompt, grid, case.pose).to_bench(case.id)
        dt = time.perf_counter() - t0
        t_all += dt
        lines.append(json.dumps(out))
        vm = validity.setdefault(id(grid), ValidityMap(grid))
        r = score_case(case.model_dump(), out, vm)
        unsafe.extend(overshoots(case.model_dump(), out))
        r.seconds = dt
        results.append(r)
        if show:
            print(f"\r[{n}/{len(cases)}] {case.id} {'ok  ' if r.right else 'MISS'}", end="", file=sys.stderr,
                  flush=True)
    if show:
        print(file=sys.stderr)
    summary = summarise(results)
    name = planner.translator.name
    if args.json:
        print(json.dumps({**summary.to_json(), "translator": name, "seconds": round(t_all, 3),
                          "overshoot_cases": len({o.id for o in unsafe})}))
    else:
        print(table(summary, name, t_all))
        print(f"moves farther or turns more than asked: {len({o.id for o in unsafe})} cases")
        for o in unsafe:
            print(f"OVERSHOOT {o}")
        for r in results:
            if not r.right:
                print(f"MISS {r.id}: {r.prompt}  -- {'; '.join(r.why)}")
    if args.outputs:
        args.outputs.write_text("\n".join(lines) + "\n", encoding="utf-8")
    if args.report:
        for p in write_report(args.report, summary, results, name, t_all):
            print(f"wrote {p}", file=sys.stderr)
    return 0
