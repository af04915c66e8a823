"""``langnav translate``: a prompt on a map -> the intent and the validated commands; or a whole
bench case file -> one output line per case in the bench's format (stdout)."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from langnav.cli.options import pose_arg
from langnav.cli.places import add_places_option, places_path
from langnav.errors import LangnavError
from langnav.eval.cases import MapCache, bench_output, load_cases
from langnav.language.translator import get_translator
from langnav.maps.io import load_map
from langnav.pipeline import Planner, PlanResult
from langnav.places import JsonPlaceStore, MemoryPlaceStore
from langnav.plan.commands import describe


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("prompt", nargs="?", help="what the robot should do (with --map and --pose)")
    p.add_argument("--map", type=Path, help="map_server YAML (or a map image)")
    p.add_argument("--pose", type=pose_arg,
                   help="robot pose X,Y,YAW_DEG in the map frame (use --pose=-1,2,0 for negatives)")
    p.add_argument("--cases", type=Path, help="bench case file (JSONL); writes one output line per case")
    p.add_argument("--translator", default="offline", help="offline (default), gemini, openai, local, auto")
    p.add_argument("--json", action="store_true", help="machine-readable output")
    add_places_option(p)


def run(args: argparse.Namespace) -> int:
    # a dry run: the named places are read, and naming or forgetting in a prompt changes only this copy
    places = MemoryPlaceStore(JsonPlaceStore(places_path(args.places)).all()) if args.places is not None else None
    planner = Planner(get_translator(args.translator), places=places)
    if args.cases is not None:
        return run_cases(planner, args.cases)
    if args.map is None or args.pose is None or not args.prompt:
        raise LangnavError("give --map MAP.yaml --pose X,Y,YAW_DEG \"prompt\", or --cases CASES.jsonl")
    grid = load_map(args.map)
    result = planner.plan(args.prompt, grid, args.pose)
    if args.json:
        print(json.dumps(result.to_json(), indent=2))
    else:
        print_result(result)
    return 0 if result.ok else 2


def run_cases(planner: Planner, cases_path: Path) -> int:
    cases = load_cases(cases_path)
    maps = MapCache(cases_path.resolve().parent)
    for case in cases:
        sys.stdout.write(json.dumps(bench_output(planner, maps, case)) + "\n")
    sys.stdout.flush()
    return 0


def print_result(result: PlanResult) -> None:
    print(f"translator: {result.translator}")
    if result.intent is not None:
        for i, s in enumerate(result.intent.steps, 1):
            fields = s.model_dump(mode="json", exclude_none=True, exclude_defaults=True)
            print(f"step {i}: {json.dumps(fields)}")
    if result.clarification:
        print(f"nothing will run: {result.clarification}")
        return
    for c in result.commands:
        print(f"  {describe(c)}")
    for m in result.messages:
        print(f"note: {m}")
