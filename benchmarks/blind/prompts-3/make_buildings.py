#!/usr/bin/env python3
"""Draws three new buildings (a school wing, a hotel floor drawn rotated by 17 degrees with
lidar-like noise, and a home) and writes buildings.jsonl, 40 cases each.  Every expected
region is checked against the drawn map (check()), and an oracle output is scored.

Run: /work/main/.venv/bin/python make_buildings.py
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


# ================================================================== school wing
def school():
    b = Building("school", -1.0, -1.0, 34.0, 25.0)
    b.shell(0.0, 0.0, 26.0, 15.0)
    b.shell(16.0, 8.6, 33.0, 24.0)
    b.space("A", (0.0, 6.0, 26.0, 8.4))        # east-west corridor
    b.space("B", (23.6, 8.4, 26.0, 24.0))      # north-south corridor from A's east end (north end unscanned)
    b.space("S1", (0.0, 0.0, 7.8, 5.8)); b.space("S2", (8.0, 0.0, 15.8, 5.8))
    b.space("S3", (16.0, 0.0, 21.8, 5.8)); b.space("S4", (22.0, 0.0, 26.0, 5.8))
    b.space("N1", (0.0, 8.6, 7.8, 15.0)); b.space("N2", (8.0, 8.6, 15.8, 15.0))
    b.space("N3", (16.0, 8.6, 23.4, 15.0))
    b.space("W1", (16.0, 15.2, 23.4, 24.0))
    b.space("E1", (26.2, 8.6, 33.0, 16.0)); b.space("E2", (26.2, 16.2, 33.0, 24.0))
    for n, x in (("S1", 6.5), ("S2", 14.5), ("S3", 20.5), ("S4", 23.0)):
        b.door(n, x, 5.9, "h", "A", n)
    for n, x in (("N1", 2.0), ("N2", 9.5), ("N3", 17.5)):
        b.door(n, x, 8.5, "h", "A", n)
    b.door("W1", 23.5, 20.0, "v", "B", "W1")
    b.door("E1", 26.1, 10.0, "v", "B", "E1")
    b.door("E2", 26.1, 18.0, "v", "B", "E2")
    b.carve()
    b.rect(8.0, 11.0, 11.6, 11.8, OCC)    # lab bench, west part of N2 (touches the west wall)
    b.rect(12.3, 11.0, 15.8, 11.8, OCC)   # lab bench, east part (gap 11.6..12.3 = 0.7 m)
    b.rect(18.5, 2.5, 19.5, 3.5, OCC)     # a cabinet standing free in S3
    b.unknown(23.6, 22.0, 26.0, 24.0)     # corridor B beyond y 22 not scanned
    b.unknown(29.0, 16.2, 33.0, 24.0)     # east part of E2 not scanned
    b.render()

    HALL = [["A"], ["A", "B"]]            # readings of "the robot's hallway" in the L
    HALLB = [["B"], ["A", "B"]]
    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    SA = (1.0, 7.2, 0)        # west end of A, facing east (left = north rooms)
    SD = (25.0, 7.2, 180)     # east end of A (the bend), facing west (left = south rooms)
    SB = (24.8, 9.0, 90)      # foot of B, facing north (right = E1, E2)
    SF = (24.8, 21.0, 270)    # north part of B, facing south (left = E2, right = W1)
    SC = (4.0, 1.5, 90)       # in S1, facing north
    SC2 = (2.0, 1.5, 0)       # in S1 near its south-west corner, facing east
    SE = (11.95, 10.2, 90)    # in N2, south of the gap between the benches, facing north
    SG = (31.0, 12.3, 180)    # in E1, facing west
    SH = (12.0, 3.0, 90)      # in S2, facing north
    SJ = (17.0, 1.0, 0)       # in S3, facing east
    gap_n = band(11.0, 11.8, 12.9, 13.1)   # north of the gap, within 2 m of its centre (11.95, 11.4)
    e2_front = band(28.0, 16.2, 29.0, 24.0)  # E2's free part within 1 m of its unscanned half
    b_front = band(23.6, 21.0, 26.0, 22.0)   # B's free part within 1 m of its unscanned end
    cab = (18.5, 2.5, 19.5, 3.5)
    next_cab = {"any": [poly(cab[0], cab[3], cab[2], cab[3] + 1.0), poly(cab[0], cab[1] - 1.0, cab[2], cab[1]),
                        poly(cab[0] - 1.0, cab[1], cab[0], cab[3]), poly(cab[2], cab[1], cab[2] + 1.0, cab[3])]}
    n2_south = band(8.0, 8.6, 15.8, 11.0)

    def nd(pose, side, n, hv=HALL):
        return nth_door(b, pose, hv, side, n)

    assert nd(SA, "left", 2) == "N2" and nd(SA, "right", 3) == "S3" and nd(SA, "right", -1) == "S4"
    assert nd(SD, "left", 2) == "S3" and nd(SD, "left", -1) == "S1" and nd(SD, "left", 5) is None
    assert nd(SB, "right", 1, HALLB) == "E1" and nd(SB, "right", 2, HALLB) == "E2"
    assert nd(SA, "right", 1) == "S1" and nd(SA, "left", 1) == "N1" and nd(SA, "right", 5) is None
    mid_s2 = b.centroid("S2")
    mid_n1 = b.centroid("N1")
    mid_e1 = b.centroid("E1")
    cor = lambda *n: n
    C = [
        ("A", SA, "um, could you go to the second door on your left?", [ntp(D("N2"), spaces=["A", "N2", "door:N2"])]),
        ("B", SA, "take 3rd door on right", [ntp({"any": [D("S3"), through(b, "S3", "S3")]}, spaces=["A", "S3", "door:S3"])]),
        ("K", SA, "Would you please stop at the last door on your right?", [ntp(D("S4"), spaces=["A", "S4", "door:S4"])]),
        ("H", SA, "go halfway down this corridor", [ntp(band(12.0, 6.0, 14.5, 8.4), spaces=["A"])]),
        ("L", SA, "go two metres past the, uh, the first door on your right", [ntp(band(8.0, 6.0, 9.0, 8.4), spaces=["A"])]),
        ("J", SA, "go into the first room on your left and then go to the middle of it",
         [ntp(circ(*mid_n1, MIDDLE), spaces=["N1"])]),
        ("C", SA, "go in second room on left, after go through narrow gap",
         [ntp(gap_n, via=[n2_south], spaces=["N2"], via_spaces=["N2"])]),
        ("I", SA, "go 2 the gym pls", "clarify"),
        ("E", SA, "go to the fifth door on the right", "clarify"),
        ("D", SA, "go to the first door on your right comma then turn right",
         [ntp(D("S1"), spaces=["A", "S1", "door:S1"]), rot_deg(-90)]),
        ("F", SD, "go to the end of the hall", [ntp(band(0.0, 6.0, 1.2, 8.4), spaces=["A"])]),
        ("B", SD, "stop 1 m before the wall at the end of the corridor", [ntp(band(0.65, 6.0, 1.35, 8.4), spaces=["A"])]),
        ("A", SD, "sorry, could you go to the second door on the left?", [ntp(D("S3"), spaces=["A", "S3", "door:S3"])]),
        ("J", SD, "go to the second door on your left, then go into the room across the hall",
         [ntp(R("N3"), via=[D("S3")], spaces=["N3"], via_spaces=["A", "S3", "door:S3"])]),
        ("G", SD, "head for the last door on your left", [ntp(D("S1"), spaces=["A", "S1", "door:S1"])]),
        ("K", SD, "Could you kindly go to the fifth door on your left?", "clarify"),
        ("H", SB, "go to the first door on the right", [ntp(D("E1"), spaces=["B", "E1", "door:E1"])]),
        ("E", SB, "go through the second door on your right!", [ntp(through(b, "E2", "E2"), spaces=["E2"], kind="through:E2")]),
        ("L", SB, "go to the- um, go towards the nearest unexplored area",
         [ntp(e2_front, spaces=["E2"], kind="frontier")]),
        ("F", SF, "go into the room on your right", [ntp(R("W1"), spaces=["W1"])]),
        ("A", SF, "um, could you go towards the unexplored area behind you?",
         [ntp(b_front, spaces=["B"], kind="frontier")]),
        ("C", SF, "enter room on your left and go towards unexplored part",
         [ntp(e2_front, spaces=["E2"], kind="frontier")]),
        ("D", SF, "pass through the doorway on your left", [ntp(through(b, "E2", "E2"), spaces=["E2"], kind="through:E2")]),
        ("G", SC, "turn so you're facing the door", [face(SC, 6.5, 5.9)]),
        ("I", SC, "go 2 the left corner of this room", [ntp(side_corner(SC, sp["S1"][0], "left"), spaces=["S1"])]),
        ("K", SC, "Would you mind going to the right corner of this room, please?",
         [ntp(side_corner(SC, sp["S1"][0], "right"), spaces=["S1"])]),
        ("B", SC, "go to the room across the hall", [ntp(R("N1"), spaces=["N1"])]),
        ("E", SC2, "go to the nearest corner", [ntp(nearest_corner(SC2, sp["S1"][0]), spaces=["S1"])]),
        ("J", SC2, "go into the neighbouring room", [ntp(R("S2"), spaces=["S2"])]),
        ("H", SC2, "back up two metres", {"any": ["clarify", [safe_move(b, SC2, "backward")]]}),
        ("L", SH, "go to the, uh, room next to this one please", "clarify"),
        ("F", SH, "go to the middle of this room", [ntp(circ(*mid_s2, MIDDLE), spaces=["S2"])]),
        ("C", SH, "go out the door and turn left",
         [ntp(through(b, "S2", "A"), spaces=["A"], kind="through:S2"), rot_deg(90)]),
        ("A", SE, "um, can you squeeze through the narrow gap in front of you?",
         [ntp(gap_n, spaces=["N2"], kind="through_gap")]),
        ("I", SE, "go bak out thru the door", [ntp(through(b, "N2", "A", half=1.1), spaces=["A"], kind="through:N2")]),
        ("G", SG, "point yourself at the door", [face(SG, 26.1, 10.0)]),
        ("D", SG, "go to the right-hand corner of this room", [ntp(side_corner(SG, sp["E1"][0], "right"), spaces=["E1"])]),
        ("K", SG, "Would you be so kind as to go to the middle of this room?", [ntp(circ(*mid_e1, MIDDLE), spaces=["E1"])]),
        ("E", SJ, "go next to the obstacle", [ntp(next_cab, spaces=["S3"])]),
        ("B", SJ, "go between the obstacle and the door", [ntp(circ(19.75, 4.45, BETWEEN), spaces=["S3", "door:S3", "A"])]),
    ]
    return b, C


def main():
    import bld_cases
    out = []
    for fn, tag in ((school, "sch"),) + bld_cases.MORE:
        b, C = fn()
        assert len(C) == 40, (tag, len(C))
        for i, (spk, pose, prompt, exp) in enumerate(C, 1):
            out.append((b, tag, i, spk, pose, prompt, exp))
    bld_cases.write(out)


if __name__ == "__main__":
    main()
