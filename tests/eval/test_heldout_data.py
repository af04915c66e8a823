"""The held-out evaluation set (src/langnav/eval/heldout) is well-formed and its expectations are
achievable: every map loads, ids are unique, start poses are safe, every expected region holds
poses the bench referee would accept, and every expected Move keeps clear of walls.

The acceptance rule mirrors ../shared/bench/score.py: a pose is valid on a free cell at least
0.15 m from any occupied or unknown cell (unknown specks under 5 cells ignored), in the start
pose's 8-connected component of valid cells.
"""

from __future__ import annotations

import math
import subprocess
import sys
from collections.abc import Iterator
from functools import cache
from importlib.resources import files
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt
import pytest
from scipy import ndimage

from langnav.eval.cases import BenchCase, MapCache, load_cases
from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN, OccupancyGrid

HELDOUT = Path(str(files("langnav.eval") / "heldout"))
CASES = HELDOUT / "cases.jsonl"
REPO = Path(__file__).resolve().parents[2]
TOOL = REPO / "tools" / "make_heldout_maps.py"

#: The referee's pose clearance and its speck rule (score.py).
CLEARANCE_M = 0.15
SPECK_CELLS = 5
STEP_M, STEP_DEG = 0.03, 10.0
#: A region must hold at least this many acceptable cells (0.05 m² at 5 cm): a target, not a dot.
MIN_REGION_CELLS = 20
#: The start pose may not stand in a wall: same rule as any produced pose.
COMMANDS = {"NavigateThroughPoses", "Move", "Rotate", "Stop", "GetCurrentPath", "GetMap",
            "GetRobotPoseLast"}
MOVE_DIRECTIONS = {"forward", "backward", "left", "right"}
ROTATE_DIRECTIONS = {"left", "right", "any"}


class Acceptable:
    """The cells where the referee accepts a pose, per map."""

    def __init__(self, grid: OccupancyGrid) -> None:
        self.grid = grid
        unk = grid.cells == UNKNOWN
        lab, n = ndimage.label(unk)
        sizes = ndimage.sum(unk, lab, range(1, n + 1)) if n else np.array([])
        big_unk = np.isin(lab, np.nonzero(sizes >= SPECK_CELLS)[0] + 1)
        blocking = (grid.cells == OCCUPIED) | big_unk
        dist = ndimage.distance_transform_edt(~blocking) * grid.resolution_m
        self.ok = (dist >= CLEARANCE_M) & ~blocking & (grid.cells == FREE)
        self.labels, _ = ndimage.label(self.ok, structure=np.ones((3, 3)))
        rows, cols = np.indices(grid.cells.shape)
        self.x = np.asarray(grid.origin_x_m + (cols + 0.5) * grid.resolution_m, dtype=np.float64)
        self.y = np.asarray(grid.origin_y_m + (rows + 0.5) * grid.resolution_m, dtype=np.float64)

    def index(self, x: float, y: float) -> tuple[int, int]:
        r = math.floor((y - self.grid.origin_y_m) / self.grid.resolution_m)
        c = math.floor((x - self.grid.origin_x_m) / self.grid.resolution_m)
        return r, c

    def valid(self, x: float, y: float) -> bool:
        r, c = self.index(x, y)
        return 0 <= r < self.ok.shape[0] and 0 <= c < self.ok.shape[1] and bool(self.ok[r, c])

    def component(self, x: float, y: float) -> int:
        r, c = self.index(x, y)
        return int(self.labels[r, c])


def in_region(region: dict[str, Any], x: npt.NDArray[np.float64], y: npt.NDArray[np.float64]) -> npt.NDArray[np.bool_]:
    if "circle" in region:
        cx, cy, r = region["circle"]
        return np.asarray(np.hypot(x - cx, y - cy) <= r)
    if "polygon" in region:
        poly = region["polygon"]
        inside = np.zeros(x.shape, dtype=bool)
        for i in range(len(poly)):
            (x1, y1), (x2, y2) = poly[i], poly[(i + 1) % len(poly)]
            if y1 == y2:
                continue
            crosses = ((y1 > y) != (y2 > y)) & (x < (x2 - x1) * (y - y1) / (y2 - y1) + x1)
            inside ^= crosses
        return inside
    if "any" in region:
        out = np.zeros(x.shape, dtype=bool)
        for sub in region["any"]:
            out |= in_region(sub, x, y)
        return out
    raise AssertionError(f"unknown region {region}")


def alternatives(case: BenchCase) -> list[Any]:
    exp = case.expect
    return list(exp["any"]) if isinstance(exp, dict) else [exp]


def commands(case: BenchCase) -> Iterator[dict[str, Any]]:
    for alt in alternatives(case):
        if alt != "clarify":
            yield from alt


@cache
def all_cases() -> tuple[BenchCase, ...]:
    return tuple(load_cases(CASES))


_CACHE = MapCache(CASES.parent)
_ACCEPT: dict[Path, Acceptable] = {}


def acceptable(case: BenchCase) -> Acceptable:
    p = _CACHE.path(case)
    if p not in _ACCEPT:
        _ACCEPT[p] = Acceptable(_CACHE.get(case))
    return _ACCEPT[p]


def ids(case: BenchCase) -> str:
    return case.id


# ------------------------------------------------------------------------------------ tests
def test_case_file_loads_and_has_the_advertised_size() -> None:
    cases = all_cases()
    assert 60 <= len(cases) <= 90
    assert {c.map for c in cases} == {"maps/flat.yaml", "maps/office.yaml", "maps/partial.yaml"}


def test_ids_are_unique_and_prefixed() -> None:
    got = [c.id for c in all_cases()]
    assert len(got) == len(set(got))
    assert all(i.startswith("h-") for i in got)


def test_prompts_are_unique_per_pose_and_not_dev_copies(shared_dir: Path) -> None:
    dev = {c.prompt.strip().lower() for c in load_cases(shared_dir / "bench" / "prompts_dev.jsonl")}
    seen: set[tuple[str, str, tuple[float, float, float]]] = set()
    for c in all_cases():
        key = (c.map, c.prompt, c.pose)
        assert key not in seen, f"{c.id}: duplicate of an earlier case"
        seen.add(key)
        assert c.prompt.strip().lower() not in dev, f"{c.id}: copies a dev prompt"


@pytest.mark.parametrize("name", ["flat", "office", "partial"])
def test_maps_load_at_5cm_with_free_occupied_and_unknown(name: str) -> None:
    from langnav.maps.io import load_map

    g = load_map(HELDOUT / "maps" / f"{name}.yaml")
    assert g.resolution_m == pytest.approx(0.05)
    values = set(np.unique(g.cells).tolist())
    assert values == {FREE, OCCUPIED, UNKNOWN}
    assert 30.0 < float((g.cells == FREE).sum()) * g.resolution_m**2 < 300.0


def test_map_yaml_origin_is_on_one_line_for_line_based_readers() -> None:
    # the bench referee splits each line on ':'; a block-style origin would read as empty
    for y in (HELDOUT / "maps").glob("*.yaml"):
        line = next(ln for ln in y.read_text().splitlines() if ln.startswith("origin:"))
        assert line.split(":", 1)[1].strip().startswith("[")


@pytest.mark.parametrize("case", all_cases(), ids=ids)
def test_case_shape(case: BenchCase) -> None:
    assert case.prompt.strip()
    alts = alternatives(case)
    assert alts
    for alt in alts:
        if alt == "clarify":
            continue
        assert isinstance(alt, list) and alt, f"{case.id}: expect must be 'clarify' or a command list"
        for cmd in alt:
            assert cmd["command"] in COMMANDS
            if cmd["command"] == "NavigateThroughPoses":
                assert "goal" in cmd
            if cmd["command"] in ("Move", "Rotate"):
                lo, hi = cmd["repeat"]
                assert isinstance(lo, int) and isinstance(hi, int) and 1 <= lo <= hi
                dirs = MOVE_DIRECTIONS if cmd["command"] == "Move" else ROTATE_DIRECTIONS
                assert cmd["direction"] in dirs


@pytest.mark.parametrize("case", all_cases(), ids=ids)
def test_start_pose_is_a_valid_pose(case: BenchCase) -> None:
    acc = acceptable(case)
    assert acc.valid(case.pose[0], case.pose[1]), f"{case.id}: start pose {case.pose} is not a valid pose"


@pytest.mark.parametrize("case", [c for c in all_cases() if any(
    k["command"] == "NavigateThroughPoses" for k in commands(c))], ids=ids)
def test_every_expected_region_holds_reachable_valid_poses(case: BenchCase) -> None:
    acc = acceptable(case)
    comp = acc.component(case.pose[0], case.pose[1])
    reach = acc.labels == comp
    for cmd in commands(case):
        if cmd["command"] != "NavigateThroughPoses":
            continue
        for region in [*cmd.get("via", []), cmd["goal"]]:
            n = int((in_region(region, acc.x, acc.y) & reach).sum())
            assert n >= MIN_REGION_CELLS, f"{case.id}: only {n} acceptable cells in {region}"


@pytest.mark.parametrize("case", all_cases(), ids=ids)
def test_the_robot_does_not_start_inside_its_goal(case: BenchCase) -> None:
    x, y = np.array([case.pose[0]]), np.array([case.pose[1]])
    for alt in alternatives(case):
        if alt == "clarify" or alt[0]["command"] != "NavigateThroughPoses":
            continue
        assert not in_region(alt[0]["goal"], x, y)[0], f"{case.id}: already in the goal"


def _sweep_clear(acc: Acceptable, x: float, y: float, nx: float, ny: float) -> bool:
    steps = max(int(math.hypot(nx - x, ny - y) / (acc.grid.resolution_m / 2)), 1)
    return all(acc.valid(x + (nx - x) * s / steps, y + (ny - y) * s / steps) for s in range(1, steps + 1))


@pytest.mark.parametrize("case", [c for c in all_cases() if any(
    alt != "clarify" and all(k["command"] in ("Move", "Rotate") for k in alt)
    and any(k["command"] == "Move" for k in alt) for alt in alternatives(c))], ids=ids)
def test_expected_moves_stay_clear_at_both_ends_of_their_range(case: BenchCase) -> None:
    acc = acceptable(case)
    for alt in alternatives(case):
        if alt == "clarify":
            continue
        for pick in (0, 1):  # fewest and most steps allowed
            x, y, yaw = case.pose[0], case.pose[1], math.radians(case.pose[2])
            for cmd in alt:
                n = cmd["repeat"][pick]
                if cmd["command"] == "Rotate":
                    sign = -1 if cmd["direction"] == "right" else 1
                    yaw += sign * math.radians(STEP_DEG) * n
                    continue
                heading = {"forward": 0.0, "backward": math.pi, "left": math.pi / 2,
                           "right": -math.pi / 2}[cmd["direction"]]
                nx = x + STEP_M * n * math.cos(yaw + heading)
                ny = y + STEP_M * n * math.sin(yaw + heading)
                assert _sweep_clear(acc, x, y, nx, ny), f"{case.id}: {cmd} with {n} steps hits something"
                x, y = nx, ny


def test_every_map_has_a_clarify_case_and_a_towards_unexplored_case() -> None:
    for m in ("maps/flat.yaml", "maps/office.yaml", "maps/partial.yaml"):
        on_map = [c for c in all_cases() if c.map == m]
        assert any("clarify" in alternatives(c) for c in on_map)
        assert any("towards" in c.prompt.lower() for c in on_map)


def test_the_tool_regenerates_the_shipped_data(tmp_path: Path) -> None:
    subprocess.run([sys.executable, str(TOOL), "--out", str(tmp_path)], check=True, capture_output=True,
                   timeout=120)
    assert (tmp_path / "cases.jsonl").read_text() == CASES.read_text()
    for name in ("flat", "office", "partial"):
        for ext in ("yaml", "pgm"):
            assert (tmp_path / "maps" / f"{name}.{ext}").read_bytes() == (HELDOUT / "maps" / f"{name}.{ext}").read_bytes()
