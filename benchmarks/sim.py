"""The simulator: speed, exploration coverage, and the development prompts run end to end.

1. Speed on env2 (known map, headless): simulation steps per second and the real-time factor
   while driving a long route across the floor (target >= 20x real time), wall and CPU.
2. Exploring env2 from the hallway (1.5, 5.75, 0) with an empty map: the share of the reachable
   free area that ends up FREE on the robot's map (target >= 95%), simulated and wall time.
3. Every development prompt of ../shared/bench/prompts_dev.jsonl that moves the robot, run end to
   end (offline translator -> grounding -> validator -> executor -> simulator, known map) from its
   start pose: does the robot end inside the expected goal region, without a collision (>= 95%)?

Needs ../shared; prints why and exits 0 when it is absent.
"""

from __future__ import annotations

import json
import sys
import time
from pathlib import Path
from typing import Final

import numpy as np
from scipy import ndimage

from langnav.eval.endpoint import ended_as_expected, expected_end
from langnav.maps.grid import OccupancyGrid
from langnav.maps.io import load_map
from langnav.plan.events import PlanStatus
from langnav.plan.executor import PlanExecutor
from langnav.robot.explore import Explorer
from langnav.robot.sim import SimBackend, create_sim

SHARED = Path(__file__).resolve().parents[2] / "shared"
BENCH = SHARED / "bench"
ENV2 = BENCH / "maps" / "env2.yaml"
HALLWAY_START: Final = (1.5, 5.75, 0.0)
#: A long known-map route: the hallway's west end to the far south-east room.
SPEED_ROUTE: Final = [(16.2, 3.1)]
TARGET_RTF: Final = 20.0
TARGET_COVERAGE: Final = 0.95
TARGET_PROMPTS: Final = 0.95


def speed() -> float:
    grid = load_map(ENV2)
    sim = create_sim(grid, HALLWAY_START, known_map=True)
    h = sim.navigate_through_poses(SPEED_ROUTE)
    t0, c0 = time.perf_counter(), time.process_time()
    result = h.wait(600)
    wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    rtf = sim.time_s / wall
    print(f"drive env2 hallway -> SE room (known map): {result.status.value}, {sim.steps} steps, "
          f"{sim.time_s:.1f} s simulated in {wall:.2f} s wall ({cpu:.2f} s CPU)")
    print(f"  steps/s: {sim.steps / wall:.0f} wall, {sim.steps / cpu:.0f} CPU; real-time factor "
          f"{rtf:.1f}x wall, {sim.time_s / cpu:.1f}x CPU (target >= {TARGET_RTF:.0f}x); collisions {sim.collisions}")
    # standing still: the sensing cost alone (lidar + mapping at 5 Hz, 20 Hz control)
    t0 = time.perf_counter()
    sim.step(30.0)
    wall = time.perf_counter() - t0
    print(f"  standing (scans + mapping only): {30.0 / wall:.1f}x real time")
    return rtf


def reachable_free(world: OccupancyGrid, x: float, y: float) -> np.ndarray:
    labels, _ = ndimage.label(world.free)
    r, c = world.world_to_index(x, y)
    return labels == labels[int(r), int(c)]


def exploration() -> float:
    world = load_map(ENV2)
    sim = create_sim(world, HALLWAY_START, known_map=False)
    t0, c0 = time.perf_counter(), time.process_time()
    status = Explorer(sim).run()
    wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    reach = reachable_free(world, *HALLWAY_START[:2])
    grid = sim.get_map()
    covered = float((grid.free & reach).sum() / reach.sum())
    print(f"explore env2 from the hallway, empty map: {status.value}; covered {covered:.1%} of the "
          f"{reach.sum() * world.cell_area_m2:.0f} m2 reachable free area (target >= {TARGET_COVERAGE:.0%})")
    print(f"  simulated {sim.time_s:.0f} s, wall {wall:.1f} s ({cpu:.1f} s CPU), real-time factor "
          f"{sim.time_s / wall:.1f}x; collisions {sim.collisions}")
    return covered


def prompts() -> float:
    from langnav.language.translator import get_translator
    from langnav.pipeline import Planner

    cases = [json.loads(line) for line in (BENCH / "prompts_dev.jsonl").read_text().splitlines() if line.strip()]
    moving = [c for c in cases if isinstance(c["expect"], list) and expected_end(c) is not None]
    planner = Planner(get_translator("offline"))
    worlds: dict[str, OccupancyGrid] = {}
    ok = 0
    t0 = time.perf_counter()
    for case in moving:
        world = worlds.setdefault(case["map"], load_map(BENCH / case["map"]))
        sim: SimBackend = create_sim(world, tuple(case["pose"]), known_map=True)
        result = planner.plan(case["prompt"], world, tuple(case["pose"]))
        why = ""
        if result.clarification is not None:
            why = f"not planned: {result.clarification}"
        else:
            status = PlanExecutor(sim).run(result.items, timeout_s=900)
            if status is not PlanStatus.SUCCEEDED:
                why = f"plan {status.value}"
        x, y = sim.pose.x_m, sim.pose.y_m
        end = expected_end(case)
        inside = end is not None and ended_as_expected(end, x, y)
        good = inside and sim.collisions == 0 and not why
        ok += good
        if not good:
            why = why or ("collision" if sim.collisions else f"ended at ({x:.2f}, {y:.2f}), outside the goal")
            print(f"  miss {case['id']}: {case['prompt']!r}: {why}")
    rate = ok / len(moving) if moving else 0.0
    print(f"dev prompts that move the robot, end to end (offline translator, known map): {ok}/{len(moving)} "
          f"end in the goal region without a collision = {rate:.1%} (target >= {TARGET_PROMPTS:.0%}); "
          f"{time.perf_counter() - t0:.1f} s wall")
    return rate


def main() -> int:
    if not ENV2.exists():
        print(f"skipped: {ENV2} not found (../shared is not on this machine)")
        return 0
    rtf = speed()
    covered = exploration()
    rate = prompts()
    print(f"summary: real-time factor {rtf:.1f}x (>= {TARGET_RTF:.0f}x: {'yes' if rtf >= TARGET_RTF else 'NO'}), "
          f"coverage {covered:.1%} (>= {TARGET_COVERAGE:.0%}: {'yes' if covered >= TARGET_COVERAGE else 'NO'}), "
          f"prompts {rate:.1%} (>= {TARGET_PROMPTS:.0%}: {'yes' if rate >= TARGET_PROMPTS else 'NO'})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
