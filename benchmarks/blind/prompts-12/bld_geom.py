#!/usr/bin/env python3
"""Region builders (door, room, through, corners, nth_door) copied from the third blind set.
"""
import json
import math
import subprocess
import sys

import numpy as np
from scipy import ndimage

from bld_lib import (HERE, RES, OCC, FREE, UNK, WALL, AT_DOOR, AT_CORNER, MIDDLE, BETWEEN, NEXT_TO,
                     Building, rel, safe_move, doors_in_order, circ, poly, ntp, rot, rot_deg, face, move, compass, STOP)


# ------------------------------------------------------------------ region builders (local)
def door_reg(b, n):
    d = b.doors[n]
    return circ(d["x"], d["y"], AT_DOOR)


def room_reg(b, n):
    rs = b.spaces[n]
    return poly(*rs[0]) if len(rs) == 1 else {"any": [poly(*r) for r in rs]}


def through(b, n, into, depth=1.5, half=1.2):
    """Far side of door n, inside space `into`, every point within 2 m of the door centre."""
    d = b.doors[n]
    x, y = d["x"], d["y"]
    (rx0, ry0, rx1, ry1) = b.spaces[into][0]
    if d["orient"] == "h":
        if ry0 >= y:   # space north of the door
            r = (max(x - half, rx0), ry0, min(x + half, rx1), min(y + depth, ry1))
        else:
            r = (max(x - half, rx0), max(y - depth, ry0), min(x + half, rx1), ry1)
    else:
        if rx0 >= x:   # space east
            r = (rx0, max(y - half, ry0), min(x + depth, rx1), min(y + half, ry1))
        else:
            r = (max(x - depth, rx0), max(y - half, ry0), rx1, min(y + half, ry1))
    for cx in (r[0], r[2]):
        for cy in (r[1], r[3]):
            assert math.hypot(cx - x, cy - y) <= 2.0 + 1e-9, (n, "through box beyond 2 m")
    return poly(*r)


def corners(rect):
    x0, y0, x1, y1 = rect
    return [(x0, y0), (x1, y0), (x0, y1), (x1, y1)]


def corner_reg(c, rect):
    """Corner region: within 1.0 m of the meeting point, clipped to the room (a quarter disc)."""
    cx, cy = c
    x0, y0, x1, y1 = rect
    sx = 1 if abs(cx - x0) < 1e-9 else -1
    sy = 1 if abs(cy - y0) < 1e-9 else -1
    pts = [[cx, cy]]
    for k in range(9):
        a = math.radians(90 * k / 8)
        pts.append([round(cx + sx * 0.99 * math.cos(a), 3), round(cy + sy * 0.99 * math.sin(a), 3)])
    return {"polygon": pts}


def side_corner(pose, rect, side, margin=8.0):
    """'the left/right corner': of the room's corners ahead (within +/-60 deg), the one farthest
    to that side.  Asserts no corner sits near the 60 degree limit."""
    ahead = []
    for (cx, cy) in corners(rect):
        f, l, dist, brg = rel(pose, cx, cy)
        assert abs(abs(brg) - 60) > margin, ("corner near the ahead limit", brg)
        if abs(brg) < 60:
            ahead.append((l, (cx, cy)))
    ahead.sort()
    assert len(ahead) >= 2
    c = ahead[-1][1] if side == "left" else ahead[0][1]
    return corner_reg(c, rect)


def nearest_corner(pose, rect, gap=0.5):
    ds = sorted((math.hypot(cx - pose[0], cy - pose[1]), (cx, cy)) for cx, cy in corners(rect))
    assert ds[1][0] - ds[0][0] >= gap, ("corner tie", ds[:2])
    return corner_reg(ds[0][1], rect)


def nth_door(b, pose, spaces_variants, side, n):
    """n-th (1-based; -1 = last) door on `side`, the same under every reading of which doors belong
    to the robot's hallway (spaces_variants: list of space names, each one reading)."""
    answers = set()
    for sp in spaces_variants:
        lst = []
        for s in sp:
            lst += doors_in_order(b, pose, s, side, gap=0.0)
        # order over the union again by distance
        lst = sorted(set(lst), key=lambda k: rel(pose, b.doors[k]["x"], b.doors[k]["y"])[2])
        ds = [rel(pose, b.doors[k]["x"], b.doors[k]["y"])[2] for k in lst]
        k = len(lst) - 1 if n == -1 else n - 1
        for j in (k - 1, k + 1):   # the chosen door is clearly apart from its neighbours in the order
            if 0 <= k < len(ds) and 0 <= j < len(ds):
                assert abs(ds[j] - ds[k]) >= 0.5, ("tie", lst, ds)
        if n == -1:
            answers.add(lst[-1])
        elif n <= len(lst):
            answers.add(lst[n - 1])
        else:
            answers.add(None)
    assert len(answers) == 1, ("hallway readings disagree", answers)
    return answers.pop()


def strip_to_unknown(rect):
    return poly(*rect)


def band(x0, y0, x1, y1):
    return poly(x0, y0, x1, y1)

