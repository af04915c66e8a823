"""The paper's evaluation, with the bench's definitions (``../shared/bench/README.md``):

* both command lists are normalised (Stop dropped unless alone; consecutive NavigateThroughPoses
  joined; consecutive Moves / Rotates in one direction summed);
* a produced command matches an expected one by type and, for NavigateThroughPoses, last pose in
  ``goal``, ``via`` regions visited in order, every pose valid (free, >= 0.15 m from occupied or
  unknown, reachable from the start); for Move / Rotate, direction and repeat range;
* commands are aligned by longest common subsequence; a case is right when all match, none extra;
  a "clarify" case is right when nothing is produced and a clarification is given;
* prompt accuracy, command precision / recall / F1 overall and per command type, and pose validity
  of NavigateThroughPoses poses and of Move end points (following the pose through the plan).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, Final

import numpy as np
import numpy.typing as npt
from scipy import ndimage

from langnav.maps.grid import OCCUPIED, UNKNOWN, OccupancyGrid
from langnav.plan.commands import COMMAND_NAMES, MOVE_STEP_M, ROTATE_STEP_DEG

#: A pose is valid at least this far from occupied or unknown cells (bench README).
VALID_CLEARANCE_M: Final = 0.15
#: Unknown blobs of fewer cells than this are speckle and do not make a pose invalid (the referee's rule).
SPECKLE_CELLS: Final = 5
#: The start pose may hug a wall: it belongs to the component of the nearest valid cell within this.
START_SNAP_M: Final = 0.4
MOTION: Final = ("NavigateThroughPoses", "Move", "Rotate")

Cmd = dict[str, Any]


class ValidityMap:
    """Where a pose is valid (free, clear, reachable), as the bench defines it."""

    def __init__(self, grid: OccupancyGrid) -> None:
        self.grid = grid
        unknown = grid.cells == UNKNOWN
        lab, n = ndimage.label(unknown)
        if n:
            sizes = np.bincount(lab.ravel(), minlength=n + 1)
            big = sizes >= SPECKLE_CELLS
            big[0] = False
            big_unknown = big[lab]
        else:
            big_unknown = unknown
        blocking = (grid.cells == OCCUPIED) | big_unknown
        dist = ndimage.distance_transform_edt(~blocking) * grid.resolution_m
        self.ok: npt.NDArray[np.bool_] = (dist >= VALID_CLEARANCE_M) & ~blocking
        labels, _ = ndimage.label(self.ok, structure=np.ones((3, 3), dtype=bool))
        self.labels: npt.NDArray[np.int32] = labels.astype(np.int32)

    def _idx(self, x: float, y: float) -> tuple[int, int] | None:
        r, c = self.grid.world_to_index(x, y)
        if not bool(self.grid.in_bounds(r, c)):
            return None
        return int(r), int(c)

    def valid(self, x: float, y: float) -> bool:
        idx = self._idx(x, y)
        return idx is not None and bool(self.ok[idx])

    def component_of(self, x: float, y: float) -> int | None:
        ri, ci = self.grid.world_to_index(x, y)
        r0, c0 = int(ri), int(ci)
        k = int(START_SNAP_M / self.grid.resolution_m)
        r_lo, c_lo = max(r0 - k, 0), max(c0 - k, 0)
        win = self.ok[r_lo:min(r0 + k + 1, self.grid.height), c_lo:min(c0 + k + 1, self.grid.width)]
        if not win.any():
            return None
        wr, wc = np.nonzero(win)
        rr, cc = wr + r_lo, wc + c_lo
        i = int(np.argmin((rr - r0) ** 2 + (cc - c0) ** 2))
        return int(self.labels[rr[i], cc[i]])

    def reachable(self, x: float, y: float, comp: int | None) -> bool:
        idx = self._idx(x, y)
        return comp is not None and idx is not None and bool(self.ok[idx]) and int(self.labels[idx]) == comp


# ------------------------------------------------------------------------------ regions, commands
def in_region(region: Mapping[str, Any], x: float, y: float) -> bool:
    if "circle" in region:
        cx, cy, r = region["circle"]
        return math.hypot(x - cx, y - cy) <= r
    if "polygon" in region:
        return point_in_polygon(region["polygon"], x, y)
    if "any" in region:
        return any(in_region(r, x, y) for r in region["any"])
    raise ValueError(f"unknown region {region}")


def point_in_polygon(poly: Sequence[Sequence[float]], x: float, y: float) -> bool:
    inside = False
    n = len(poly)
    for i in range(n):
        (x1, y1), (x2, y2) = poly[i], poly[(i + 1) % n]
        if (y1 > y) != (y2 > y) and x < (x2 - x1) * (y - y1) / (y2 - y1) + x1:
            inside = not inside
    return inside


def _int(v: Any, default: int = 1) -> int:
    try:
        return int(v)
    except (TypeError, ValueError):
        return default


def _xy(p: Any) -> tuple[float, float] | None:
    try:
        return float(p[0]), float(p[1])
    except (TypeError, ValueError, IndexError, KeyError):
        return None


def normalise(cmds: Any) -> list[Cmd]:
    """The bench's normal form of a command list."""
    if not isinstance(cmds, list):
        return []
    cs = [c for c in cmds if isinstance(c, dict) and "command" in c]
    if cs and all(c["command"] == "Stop" for c in cs):
        return [{"command": "Stop"}]
    out: list[Cmd] = []
    for c in cs:
        name = c["command"]
        if name == "Stop":
            continue
        prev = out[-1] if out else None
        if prev and prev["command"] == name == "NavigateThroughPoses":
            prev["poses"] = prev["poses"] + list(c.get("poses", []))
        elif (prev and prev["command"] == name and name in ("Move", "Rotate")
              and prev.get("direction") == c.get("direction")):
            prev["repeat"] = _int(prev.get("repeat")) + _int(c.get("repeat"))
        else:
            d = dict(c)
            if name == "NavigateThroughPoses":
                d["poses"] = list(c.get("poses", []))
            out.append(d)
    return out


def pose_flags(cmd: Cmd, m: ValidityMap, comp: int | None) -> list[bool]:
    flags = []
    for p in cmd.get("poses", []):
        xy = _xy(p)
        flags.append(xy is not None and m.reachable(xy[0], xy[1], comp))
    return flags


def mismatch(exp: Cmd, got: Cmd, m: ValidityMap, comp: int | None) -> str:
    """Why ``got`` does not match ``exp`` ('' when it does)."""
    if exp["command"] != got.get("command"):
        return f"type {got.get('command')} is not {exp['command']}"
    name = exp["command"]
    if name == "NavigateThroughPoses":
        poses = [_xy(p) for p in got.get("poses", [])]
        if not poses or any(p is None for p in poses):
            return "poses missing or malformed"
        bad = [i + 1 for i, ok in enumerate(pose_flags(got, m, comp)) if not ok]
        if bad:
            return f"pose {', '.join(map(str, bad))} invalid (occupied, < 0.15 m from a wall/unknown, or unreachable)"
        last = poses[-1]
        assert last is not None
        if not in_region(exp["goal"], *last):
            return f"last pose ({last[0]:.2f}, {last[1]:.2f}) is not in the goal region {_region_text(exp['goal'])}"
        k = 0
        via = exp.get("via", [])
        for p in poses[:-1]:
            assert p is not None
            if k < len(via) and in_region(via[k], *p):
                k += 1
        if k != len(via):
            return f"via region {k + 1} ({_region_text(via[k])}) not visited on the way"
        return ""
    if name in ("Move", "Rotate"):
        if exp["direction"] == "any":
            if got.get("direction") not in ("left", "right"):
                return f"direction {got.get('direction')} is not left or right"
        elif exp["direction"] != got.get("direction"):
            return f"direction {got.get('direction')} is not {exp['direction']}"
        lo, hi = exp["repeat"]
        r = _int(got.get("repeat"), -1)
        if not lo <= r <= hi:
            return f"repeat {r} outside [{lo}, {hi}]"
    return ""


def _region_text(r: Mapping[str, Any]) -> str:
    if "circle" in r:
        cx, cy, rad = r["circle"]
        return f"circle ({cx}, {cy}) r {rad}"
    if "polygon" in r:
        xs = [p[0] for p in r["polygon"]]
        ys = [p[1] for p in r["polygon"]]
        return f"polygon x {min(xs)}..{max(xs)}, y {min(ys)}..{max(ys)}"
    return "any of " + " / ".join(_region_text(x) for x in r.get("any", []))


def align(exp: Sequence[Cmd], got: Sequence[Cmd], m: ValidityMap, comp: int | None) -> list[tuple[int, int]]:
    """Matched (expected index, produced index) pairs of a longest common subsequence."""
    n, k = len(exp), len(got)
    match = [[not mismatch(exp[i], got[j], m, comp) for j in range(k)] for i in range(n)]
    t = [[0] * (k + 1) for _ in range(n + 1)]
    for i in range(n - 1, -1, -1):
        for j in range(k - 1, -1, -1):
            t[i][j] = 1 + t[i + 1][j + 1] if match[i][j] else max(t[i + 1][j], t[i][j + 1])
    pairs: list[tuple[int, int]] = []
    i = j = 0
    while i < n and j < k:
        if match[i][j] and t[i][j] == 1 + t[i + 1][j + 1]:
            pairs.append((i, j))
            i += 1
            j += 1
        elif t[i + 1][j] >= t[i][j + 1]:
            i += 1
        else:
            j += 1
    return pairs


def move_end_flags(start: Sequence[float], cmds: Sequence[Cmd], m: ValidityMap, comp: int | None) -> list[bool]:
    """Validity of the end point (and straight path) of every Move, following the pose."""
    x, y, yaw = float(start[0]), float(start[1]), math.radians(float(start[2]))
    flags = []
    for c in cmds:
        name = c["command"]
        if name == "NavigateThroughPoses":
            poses = [p for p in (_xy(q) for q in c.get("poses", [])) if p is not None]
            if poses:
                px, py = (x, y) if len(poses) == 1 else poses[-2]
                nx, ny = poses[-1]
                last = c["poses"][-1]
                if isinstance(last, list | tuple) and len(last) >= 3:
                    yaw = math.radians(float(last[2]))
                elif math.hypot(nx - px, ny - py) > 1e-6:
                    yaw = math.atan2(ny - py, nx - px)
                x, y = nx, ny
        elif name == "Rotate":
            sign = 1 if c.get("direction") == "left" else -1
            yaw += sign * math.radians(ROTATE_STEP_DEG) * _int(c.get("repeat"))
        elif name == "Move":
            d = MOVE_STEP_M * _int(c.get("repeat"))
            heading = {"forward": 0.0, "backward": math.pi, "left": math.pi / 2,
                       "right": -math.pi / 2}.get(str(c.get("direction")), 0.0)
            nx, ny = x + d * math.cos(yaw + heading), y + d * math.sin(yaw + heading)
            steps = max(int(d / (m.grid.resolution_m / 2)), 1)
            clear = all(m.valid(x + (nx - x) * s / steps, y + (ny - y) * s / steps) for s in range(1, steps + 1))
            flags.append(clear and m.reachable(nx, ny, comp))
            x, y = nx, ny
    return flags


# ------------------------------------------------------------------------------ per case, overall
@dataclass
class CaseResult:
    id: str
    prompt: str
    right: bool
    matched: int
    produced: int
    expected: int
    why: list[str]
    expected_cmds: Any
    produced_cmds: list[Cmd]
    clarification: str | None
    by_type: dict[str, list[int]] = field(default_factory=dict)  # name -> [matched, produced, expected]
    ntp_flags: list[bool] = field(default_factory=list)
    move_flags: list[bool] = field(default_factory=list)
    seconds: float = 0.0


def score_case(case: Mapping[str, Any], output: Mapping[str, Any] | None, m: ValidityMap) -> CaseResult:
    pose = case["pose"]
    comp = m.component_of(pose[0], pose[1])
    out = output or {}
    got = normalise(out.get("commands", []))
    clar = out.get("clarification")
    expect = case["expect"]
    alternatives = expect["any"] if isinstance(expect, dict) else [expect]
    best: CaseResult | None = None
    for alt in alternatives:
        r = _judge(case, alt, got, clar, m, comp)
        if best is None or (r.right, r.matched - r.expected) > (best.right, best.matched - best.expected):
            best = r
    assert best is not None
    if output is None:
        best.why = ["no output line for this case"]
    for c in got:
        if c["command"] == "NavigateThroughPoses":
            best.ntp_flags.extend(pose_flags(c, m, comp))
    best.move_flags = move_end_flags(pose, got, m, comp)
    return best


def _judge(case: Mapping[str, Any], alt: Any, got: list[Cmd], clar: Any, m: ValidityMap,
           comp: int | None) -> CaseResult:
    by_type: dict[str, list[int]] = {}
    for c in got:
        by_type.setdefault(c["command"], [0, 0, 0])[1] += 1
    res = CaseResult(case["id"], case["prompt"], False, 0, len(got), 0, [], alt, got,
                     clar if isinstance(clar, str) else None, by_type)
    if alt == "clarify":
        res.right = not got and bool(clar)
        if got:
            res.why.append("should have asked or explained and run nothing, but produced "
                           + ", ".join(c["command"] for c in got))
        elif not clar:
            res.why.append("produced nothing but gave no clarification text")
        return res
    exp = list(alt)
    for e in exp:
        by_type.setdefault(e["command"], [0, 0, 0])[2] += 1
    pairs = align(exp, got, m, comp)
    res.matched, res.expected = len(pairs), len(exp)
    for i, _ in pairs:
        by_type[exp[i]["command"]][0] += 1
    res.right = len(pairs) == len(exp) == len(got)
    if not res.right:
        done_e = {i for i, _ in pairs}
        done_g = {j for _, j in pairs}
        for i, e in enumerate(exp):
            if i in done_e:
                continue
            reasons = [mismatch(e, g, m, comp) for j, g in enumerate(got) if j not in done_g]
            same = [r for r in reasons if not r.startswith("type ")]
            detail = same[0] if same else "nothing of that type produced"
            res.why.append(f"expected {e['command']} {i + 1}: {detail}")
        for j, g in enumerate(got):
            if j not in done_g:
                res.why.append(f"extra {g['command']} (produced command {j + 1})")
        if not got and clar:
            res.why.append(f"asked instead: {clar}")
    return res


@dataclass(frozen=True)
class TypeScore:
    matched: int
    produced: int
    expected: int

    @property
    def precision(self) -> float:
        return self.matched / self.produced if self.produced else 1.0

    @property
    def recall(self) -> float:
        return self.matched / self.expected if self.expected else 1.0

    @property
    def f1(self) -> float:
        p, r = self.precision, self.recall
        return 2 * p * r / (p + r) if p + r else 0.0


@dataclass(frozen=True)
class Summary:
    cases: int
    right: int
    overall: TypeScore
    by_type: dict[str, TypeScore]
    ntp_valid: int
    ntp_all: int
    move_valid: int
    move_all: int

    @property
    def prompt_accuracy(self) -> float:
        return self.right / self.cases if self.cases else 0.0

    @property
    def ntp_validity(self) -> float | None:
        return self.ntp_valid / self.ntp_all if self.ntp_all else None

    @property
    def move_validity(self) -> float | None:
        return self.move_valid / self.move_all if self.move_all else None

    def to_json(self) -> dict[str, Any]:
        return {"cases": self.cases, "prompt_accuracy": round(self.prompt_accuracy, 4),
                "command_precision": round(self.overall.precision, 4),
                "command_recall": round(self.overall.recall, 4), "command_f1": round(self.overall.f1, 4),
                "ntp_pose_validity": None if self.ntp_validity is None else round(self.ntp_validity, 4),
                "move_validity": None if self.move_validity is None else round(self.move_validity, 4),
                "by_type": {k: {"matched": v.matched, "produced": v.produced, "expected": v.expected,
                                "precision": round(v.precision, 4), "recall": round(v.recall, 4),
                                "f1": round(v.f1, 4)} for k, v in self.by_type.items()}}


def summarise(results: Iterable[CaseResult]) -> Summary:
    rs = list(results)
    tm = tp = te = 0
    types: dict[str, list[int]] = {}
    for r in rs:
        tm += r.matched
        tp += r.produced
        te += r.expected
        for k, v in r.by_type.items():
            acc = types.setdefault(k, [0, 0, 0])
            for i in range(3):
                acc[i] += v[i]
    order = {n: i for i, n in enumerate(COMMAND_NAMES)}
    by_type = {k: TypeScore(*types[k]) for k in sorted(types, key=lambda n: order.get(n, 99))}
    return Summary(len(rs), sum(r.right for r in rs), TypeScore(tm, tp, te), by_type,
                   sum(sum(r.ntp_flags) for r in rs), sum(len(r.ntp_flags) for r in rs),
                   sum(sum(r.move_flags) for r in rs), sum(len(r.move_flags) for r in rs))
