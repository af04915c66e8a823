"""Random-pose sweep over my own buildings (scratch): door ordinals along the corridor, the middle of
this room, the nearest corner, the left / right corner, the opposite side, the biggest room: the
expected answers from the drawing (the contract), as make_*.py writes them.
Run from a building's folder: python ../sweep.py make_police police HW"""
import importlib
import json
import math
import random
import sys

import numpy as np

sys.path.insert(0, ".")
mod = importlib.import_module(sys.argv[1])
b, _ = getattr(mod, sys.argv[2])()
corr = sys.argv[3]
from bld_lib import rel, circ, poly, ntp
from bld_geom import door_reg, room_reg, corner_reg, corners
import bld_check

rng = random.Random(7)
cases = []
x0, y0, x1, y1 = b.spaces[corr][0]
along_x = (x1 - x0) > (y1 - y0)
cdoors = [n for n, d in b.doors.items() if corr in d["spaces"]]
for i in range(40):
    if along_x:
        px, py = rng.uniform(x0 + 0.5, x1 - 0.5), (y0 + y1) / 2 + rng.uniform(-0.3, 0.3)
        yaw = rng.choice((0, 180))
    else:
        px, py = (x0 + x1) / 2 + rng.uniform(-0.3, 0.3), rng.uniform(y0 + 0.5, y1 - 0.5)
        yaw = rng.choice((90, 270))
    pose = (round(px, 2), round(py, 2), yaw)
    side = rng.choice(("left", "right"))
    n = rng.choice((1, 2, 3))
    lst = []
    ok = True
    for k in cdoors:
        d = b.doors[k]
        f, l, dist, _ = rel(pose, d["x"], d["y"])
        if abs(l) < 0.3 or d["spaces"][1] == "OUT":
            ok = ok and abs(l) >= 0.3
            continue
        if (side == "left") == (l > 0):
            lst.append((dist, k))
    lst.sort()
    if not ok or n > len(lst):
        continue
    if any(abs(lst[j][0] - lst[n - 1][0]) < 0.5 for j in range(len(lst)) if j != n - 1):
        continue
    k = lst[n - 1][1]
    other = [s for s in b.doors[k]["spaces"] if s != corr][0]
    word = {1: "first", 2: "second", 3: "third"}[n]
    cases.append(("S", pose, f"go to the {word} door on your {side}", [ntp(door_reg(b, k), spaces=[corr, other, "door:" + k])]))
skip = sys.argv[4].split(",") if len(sys.argv) > 4 else []
rooms = [n for n in b.spaces if n != corr and len(b.spaces[n]) == 1 and n not in skip]
for i in range(60):
    r = rng.choice(rooms)
    rx0, ry0, rx1, ry1 = b.spaces[r][0]
    px, py = rng.uniform(rx0 + 0.5, rx1 - 0.5), rng.uniform(ry0 + 0.5, ry1 - 0.5)
    cx = int(round((px - b.lx0) / 0.05)); cy = int(round((py - b.ly0) / 0.05))
    if (b.g[cy - 8:cy + 9, cx - 8:cx + 9] != 254).any():
        continue   # not on clear floor
    yaw = rng.choice((0, 90, 180, 270))
    pose = (round(px, 2), round(py, 2), yaw)
    kind = rng.choice(("nearest", "side", "middle"))
    cs = corners(b.spaces[r][0])
    if kind == "nearest":
        ds = sorted((math.hypot(c[0] - px, c[1] - py), c) for c in cs)
        if ds[1][0] - ds[0][0] < 0.6:
            continue
        cases.append(("S", pose, "go to the nearest corner", [ntp(corner_reg(ds[0][1], b.spaces[r][0]), spaces=[r])]))
    elif kind == "side":
        side = rng.choice(("left", "right"))
        ahead = []
        bad = False
        for c in cs:
            f, l, dist, brg = rel(pose, *c)
            if abs(abs(brg) - 60) < 8:
                bad = True
            if abs(brg) < 60:
                ahead.append((l, c))
        ahead.sort()
        if bad or len(ahead) < 2 or abs(ahead[0][0] - ahead[-1][0]) < 1.0:
            continue
        c = ahead[-1][1] if side == "left" else ahead[0][1]
        cases.append(("S", pose, f"go to the {side} corner of this room", [ntp(corner_reg(c, b.spaces[r][0]), spaces=[r])]))
    else:
        cxm, cym = b.centroid(r)
        gx = int(round((cxm - b.lx0) / 0.05)); gy = int(round((cym - b.ly0) / 0.05))
        if (b.g[gy - 6:gy + 7, gx - 6:gx + 7] != 254).any():
            continue
        cases.append(("S", pose, "go to the middle of this room", [ntp(circ(cxm, cym, 0.75), spaces=[r])]))
out = [(b, "swp", i, spk, pose, prompt, exp) for i, (spk, pose, prompt, exp) in enumerate(cases, 1)]
import bld_check as bc
orig = bc.HERE
bc.write(out)
import shutil
shutil.move("buildings.jsonl", "sweep.jsonl")
print(len(cases), "sweep cases")
