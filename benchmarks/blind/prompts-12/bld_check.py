"""check(), world_expect(), the oracle and write(): copied from the sixth blind set (changes: ids b12-)."""
import json
import math
import subprocess
import sys

import numpy as np
from scipy import ndimage

from bld_lib import (HERE, RES, OCC, FREE, UNK, AT_DOOR, MIDDLE, BETWEEN, Building, rel, circ, poly, ntp, rot,
                     rot_deg, face, move, compass, safe_move, STOP)

# ================================================================== checks and output
def strip_meta(cmd):
    return {k: v for k, v in cmd.items() if not k.startswith("_")}


def world_expect(b, exp):
    def one(alt):
        if alt == "clarify":
            return "clarify"
        out = []
        for c in alt:
            c = strip_meta(c)
            if c["command"] == "NavigateThroughPoses":
                c["goal"] = b.region(c["goal"])
                if "via" in c:
                    c["via"] = [b.region(v) for v in c["via"]]
            out.append(c)
        return out
    if isinstance(exp, dict):
        return {"any": [one(a) for a in exp["any"]]}
    return one(exp)


def check(b, cases):
    """Each expected region: (1) holds at least 8 valid cells reachable from the start (score.py's
    own Map), (2) every such cell lies in the intended space(s) of the drawing, (3) for a
    frontier goal every such cell is within 1.0 m of a frontier cell of a real unexplored area
    (>= 20 unknown cells), (4) for a 'through' goal every such cell is within 2.0 m of the door."""
    from score import Map, in_region
    mp = Map((HERE / "maps" / f"{b.name}.yaml").resolve())
    rr, cc = np.nonzero(mp.ok & (mp.labels > 0))
    xs = mp.origin[0] + (cc + 0.5) * mp.res
    ys = mp.origin[1] + (rr + 0.5) * mp.res
    lab = mp.labels[rr, cc]
    # frontier distance
    unk = mp.grid == UNK
    ul, un = ndimage.label(unk, structure=np.ones((3, 3)))
    sizes = ndimage.sum(unk, ul, range(1, un + 1))
    big = np.isin(ul, np.nonzero(sizes >= 20)[0] + 1)
    frontier = (mp.grid == FREE) & ndimage.binary_dilation(big, np.ones((3, 3), bool))
    fdist = ndimage.distance_transform_edt(~frontier) * mp.res
    report = []
    for (spk, pose, prompt, exp) in cases:
        X, Y, _ = b.pose(*pose)
        comp = mp.component_of(X, Y)
        assert comp is not None and mp.valid(X, Y), (b.name, prompt, "start invalid")
        assert b.space_of_local(pose[0], pose[1]) is not None
        sel = lab == comp
        alts = exp["any"] if isinstance(exp, dict) else [exp]
        for alt in alts:
            if alt == "clarify":
                continue
            for c in alt:
                if c["command"] != "NavigateThroughPoses":
                    continue
                regs = [(c["goal"], c.get("_spaces"), c.get("_kind"))] + \
                       [(v, c.get("_via_spaces"), None) for v in c.get("via", [])]
                for reg, spaces, kind in regs:
                    wreg = b.region(reg)
                    inside = np.array([in_region(wreg, x, y) for x, y in zip(xs[sel], ys[sel])], bool)
                    n = int(inside.sum())
                    assert n >= 8, (b.name, prompt, reg, "only %d valid reachable cells" % n)
                    assert spaces, (b.name, prompt, "no intended space given")
                    bad = set()
                    for x, y in zip(xs[sel][inside], ys[sel][inside]):
                        s = b.space_of_local(*b.to_local(x, y))
                        if s not in spaces:
                            bad.add(s)
                    assert not bad, (b.name, prompt, "region reaches", bad)
                    if kind == "frontier":
                        r_ = ((ys[sel][inside] - mp.origin[1]) / mp.res).astype(int)
                        c_ = ((xs[sel][inside] - mp.origin[0]) / mp.res).astype(int)
                        assert fdist[r_, c_].max() <= 1.0 + 1e-6, (b.name, prompt, "frontier", fdist[r_, c_].max())
                    if kind and kind.startswith("through:"):
                        d = b.doors[kind.split(":")[1]]
                        DX, DY = b.to_world(d["x"], d["y"])
                        dd = np.hypot(xs[sel][inside] - DX, ys[sel][inside] - DY).max()
                        assert dd <= 2.0, (b.name, prompt, "through beyond 2 m", dd)
                    report.append((b.name, prompt[:40], n))
    return report


def oracle_output(case, mp, comp_cells):
    """An output that follows the expectation (first alternative): a valid cell in each region."""
    from score import in_region
    exp = case["expect"]
    alt = exp["any"][0] if isinstance(exp, dict) else exp
    if alt == "clarify":
        return {"id": case["id"], "commands": [], "clarification": "Which one do you mean?"}
    xs, ys = comp_cells
    cmds = []
    for c in alt:
        if c["command"] == "NavigateThroughPoses":
            poses = []
            for reg in c.get("via", []) + [c["goal"]]:
                k = next(i for i in range(len(xs)) if in_region(reg, xs[i], ys[i]))
                poses.append([round(float(xs[k]), 3), round(float(ys[k]), 3)])
            cmds.append({"command": "NavigateThroughPoses", "poses": poses})
        elif c["command"] in ("Move", "Rotate"):
            d = c["direction"] if c["direction"] != "any" else "left"
            cmds.append({"command": c["command"], "direction": d, "repeat": c["repeat"][0]})
        else:
            cmds.append({"command": c["command"]})
    return {"id": case["id"], "commands": cmds, "clarification": None}


def write(rows):
    from score import Map
    out, report = [], []
    by_b = {}
    for (b, tag, i, spk, pose, prompt, exp) in rows:
        by_b.setdefault(b.name, (b, []))[1].append((spk, pose, prompt, exp))
    for name, (b, cases) in by_b.items():
        report += check(b, cases)
    for (b, tag, i, spk, pose, prompt, exp) in rows:
        out.append({"id": f"b12-{tag}-{spk}{i:02d}", "map": f"maps/{b.name}.yaml", "pose": b.pose(*pose),
                    "prompt": prompt, "expect": world_expect(b, exp)})
    ids = [c["id"] for c in out]
    assert len(set(ids)) == len(ids)
    (HERE / "buildings.jsonl").write_text("".join(json.dumps(c) + "\n" for c in out))
    # oracle: score.py must give 1.0 on an output built from the expectations
    orc = []
    maps = {}
    for c in out:
        if c["map"] not in maps:
            mp = Map((HERE / c["map"]).resolve())
            maps[c["map"]] = mp
        mp = maps[c["map"]]
        comp = mp.component_of(c["pose"][0], c["pose"][1])
        rr, cc = np.nonzero(mp.ok & (mp.labels == comp))
        # prefer cells far from walls: sort by clearance
        orc.append(oracle_output(c, mp, (mp.origin[0] + (cc + 0.5) * mp.res, mp.origin[1] + (rr + 0.5) * mp.res)))
    (HERE / "out").mkdir(exist_ok=True)
    (HERE / "out" / "buildings.oracle.jsonl").write_text("".join(json.dumps(o) + "\n" for o in orc))
    print(len(out), "cases;", len(report), "regions checked; smallest region has",
          min(r[2] for r in report), "valid cells")
