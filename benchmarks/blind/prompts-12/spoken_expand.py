"""Expansion of meaning parts into expected commands: copied unchanged from the third blind set's make_spoken.py
(docstring there describes the parts).  make_spoken.py imports it."""
import json
import math
import sys
from pathlib import Path

FT, IN, YD, CM = 0.3048, 0.0254, 0.9144, 0.01
STEP_M, STEP_DEG = 0.03, 10.0
YAWS = [0, 90, 180, 270, 30, 120, 210, 300, 60, 150, 240, 330]
N, NE, E, SE, S, SW, W, NW = 90, 45, 0, 315, 270, 225, 180, 135
HERE = Path(__file__).parent
sys.path.insert(0, "/work/shared/bench")

# ------------------------------------------------------------------ expansion
ARENA = None


def arena():
    global ARENA
    if ARENA is None:
        from score import Map
        ARENA = Map((HERE / "maps" / "arena.yaml").resolve())
    return ARENA


def safe_steps(x, y, yaw):
    """Largest forward Move (steps) whose whole path stays valid on the arena (score.py's check)."""
    m = arena()
    n = 0
    while True:
        d = STEP_M * (n + 1)
        nx, ny = x + d * math.cos(math.radians(yaw)), y + d * math.sin(math.radians(yaw))
        if not m.valid(nx, ny):
            return n
        n += 1


def prim_choices(part, yaw):
    """Alternatives for one part: list of (primitives, new_yaw). A primitive is
    (cmd, dir, exact_steps, fixed_range_or_None, was_any)."""
    k = part[0]
    if k in ("F", "B"):
        return [([("Move", "forward" if k == "F" else "backward", part[1] / STEP_M, None, False)], yaw)]
    if k in ("Ls", "Rs"):
        return [([("Move", "left" if k == "Ls" else "right", part[1] / STEP_M, None, False)], yaw)]
    if k in ("L", "R"):
        side = "left" if k == "L" else "right"
        turn = 90 if k == "L" else -90
        return [([("Move", side, part[1] / STEP_M, None, False)], yaw),
                ([("Rotate", side, 9.0, None, False), ("Move", "forward", part[1] / STEP_M, None, False)],
                 (yaw + turn) % 360)]
    if k in ("l", "r"):
        d = part[1] if k == "l" else -part[1]
        return [([("Rotate", "left" if k == "l" else "right", part[1] / STEP_DEG, None, False)], (yaw + d) % 360)]
    if k == "a":
        return [([("Rotate", s, part[1] / STEP_DEG, None, True)], (yaw + part[1]) % 360) for s in ("left", "right")]
    if k == "face":
        diff = (part[1] - yaw + 180) % 360 - 180  # (-180, 180]
        if abs(abs(diff) - 180) < 1e-9:
            return [([("Rotate", s, 18.0, None, True)], part[1]) for s in ("left", "right")]
        assert abs(diff) > 1e-9, "compass turn already done"
        return [([("Rotate", "left" if diff > 0 else "right", abs(diff) / STEP_DEG, None, False)], part[1])]
    if k in ("bitF", "bitB"):
        return [([("Move", "forward" if k == "bitF" else "backward", None, (5, 17), False)], yaw)]
    if k in ("bitl", "bitr"):
        side = "left" if k == "bitl" else "right"
        return [([("Rotate", side, None, (1, 4), False)], (yaw + (25 if side == "left" else -25)) % 360)]
    if k == "far":
        n = safe_steps(40.0, 10.0, yaw)
        assert part[1] / STEP_M > n + 50, "not impossible"
        return [([("Move", "forward", None, (1, n), False)], yaw)]
    raise ValueError(part)


def rng(exact, nparts):
    tol = max(0.07 * exact, 1.0, 0.5 * nparts)
    lo = max(1, math.ceil(exact - tol - 1e-9))
    hi = max(lo, math.floor(exact + tol + 1e-9))
    return [lo, hi]


def merge(prims):
    out = []  # [cmd, dir, [prims]]
    for p in prims:
        if out and out[-1][0] == p[0] and out[-1][1] == p[1]:
            out[-1][2].append(p)
        else:
            out.append([p[0], p[1], [p]])
    cmds = []
    for cmd, d, ps in out:
        if len(ps) == 1 and ps[0][3] is not None:
            r = list(ps[0][3])
        else:
            assert all(p[3] is None for p in ps), "cannot sum a vague amount"
            r = rng(sum(p[2] for p in ps), len(ps))
        if len(ps) == 1 and ps[0][4]:
            d = "any"
        cmds.append({"command": cmd, "direction": d, "repeat": r})
    return cmds


def expand(parts, yaw):
    if parts == "clarify":
        return ["clarify"]
    if parts == [("stop",)]:
        return [[{"command": "Stop"}]]
    if len(parts) == 1 and parts[0][0] == "get":
        return [[{"command": parts[0][1]}]]
    if len(parts) == 1 and parts[0][0] == "alt":
        res = []
        for a in parts[0][1:]:
            res.extend(expand(a, yaw))
        return res
    assert all(p[0] not in ("stop", "get", "alt") for p in parts), parts
    if any(p[0] == "far" for p in parts):
        assert parts[-1][0] == "far" and all(p[0] == "face" for p in parts[:-1])
    seqs = [([], yaw)]
    for part in parts:
        nxt = []
        for prims, y in seqs:
            for add, y2 in prim_choices(part, y):
                nxt.append((prims + add, y2))
        seqs = nxt
    alts = []
    for prims, _ in seqs:
        c = merge(prims)
        if c not in alts:
            alts.append(c)
    if any(p[0] == "far" for p in parts):
        alts = ["clarify"] + alts
    return alts


def yaw_ok(parts, yaw):
    if parts == "clarify" or parts[0][0] in ("alt", "get", "stop"):
        return True
    y = yaw
    for part in parts:
        if part[0] == "face":
            if abs((part[1] - y + 180) % 360 - 180) < 1e-9:
                return False
            y = part[1]
        elif part[0] in ("l", "r", "a"):
            y = (y + (part[1] if part[0] != "r" else -part[1])) % 360
        elif part[0] in ("L", "R", "bitl", "bitr"):
            # the heading after these depends on the reading; no compass part may follow
            assert not any(p[0] == "face" for p in parts[parts.index(part) + 1:]), parts
    return True


def check_case(c):
    """Every command well formed as score.py reads it."""
    alts = c["expect"]["any"] if isinstance(c["expect"], dict) else [c["expect"]]
    for alt in alts:
        if alt == "clarify":
            continue
        assert isinstance(alt, list) and alt
        for i, cmd in enumerate(alt):
            name = cmd["command"]
            assert name in ("Move", "Rotate", "Stop", "GetRobotPoseLast", "GetMap", "GetCurrentPath"), cmd
            if name in ("Move", "Rotate"):
                dirs = ("forward", "backward", "left", "right") if name == "Move" else ("left", "right", "any")
                assert cmd["direction"] in dirs, cmd
                lo, hi = cmd["repeat"]
                assert isinstance(lo, int) and isinstance(hi, int) and 1 <= lo <= hi, cmd
                if i:  # score.py sums consecutive same-direction commands: never expect two in a row
                    p = alt[i - 1]
                    assert not (p["command"] == name and p["direction"] == cmd["direction"]), alt
            if name == "Stop":
                assert len(alt) == 1


def main(CASES, prefix):
    out = []
    k = 0
    for i, (spk, prompt, parts) in enumerate(CASES, 1):
        while not yaw_ok(parts, YAWS[k % len(YAWS)]):
            k += 1
        yaw = YAWS[k % len(YAWS)]
        k += 1
        alts = expand(parts, yaw)
        exp = alts[0] if len(alts) == 1 else {"any": alts}
        case = {"id": f"{prefix}-{spk}-{i:03d}", "map": "maps/arena.yaml",
                "pose": [40.0, 10.0, yaw], "prompt": prompt, "expect": exp}
        check_case(case)
        out.append(case)
    ids = [c["id"] for c in out]
    assert len(set(ids)) == len(ids)
    assert len({" ".join(c["prompt"].lower().split()) for c in out}) == len(out), "duplicate prompt"
    (HERE / "spoken.jsonl").write_text("".join(json.dumps(c) + "\n" for c in out))
    print(len(out), "cases")


