#!/usr/bin/env python3
"""Draws three new buildings -- a library (reading room, book stacks with a narrow gap, study rooms),
a small museum whose galleries form a ring (drawn ROTATED 31 deg with lidar-like noise), and a
dormitory corridor ending in an L-shaped (non-rectangular) lounge -- and writes buildings.jsonl,
30 cases each.  Every expected region is checked on the drawn map (bld_check.check) and an
oracle output built from the expectations is scored.  Drawing/geometry/check helpers are copied
from the third blind set (bld_lib.py, bld_geom.py, bld_check.py); buildings and prompts are new.

Run: /work/main/.venv/bin/python make_buildings.py
"""
import math

import numpy as np

from bld_lib import (RES, OCC, FREE, UNK, AT_DOOR, MIDDLE, BETWEEN, Building, rel, circ, poly, ntp, rot,
                     rot_deg, face, move, compass, STOP)
from bld_geom import door_reg, room_reg, through, corner_reg, side_corner, nearest_corner, band
import bld_check


# ------------------------------------------------------------------ helpers new in this set
def nth(b, pose, doors, side, n, gap=0.5):
    """n-th door (1-based, -1 = last) on `side` among the named doors of the robot's hallway/room,
    nearest first.  A door within 0.05 m of the robot's heading line is on neither side (directly
    ahead/behind); any other door must be at least 0.3 m to one side.  The chosen door must be at
    least `gap` m apart in distance from its neighbours in the order."""
    lst = []
    for k in doors:
        d = b.doors[k]
        f, l, dist, _ = rel(pose, d["x"], d["y"])
        if abs(l) < 0.05:
            continue
        assert abs(l) >= 0.3, (k, "marginal side", l)
        if (side == "left") == (l > 0):
            lst.append((dist, k))
    lst.sort()
    i = len(lst) - 1 if n == -1 else n - 1
    if i >= len(lst):
        return None
    for j in (i - 1, i + 1):
        if 0 <= j < len(lst):
            assert abs(lst[j][0] - lst[i][0]) >= gap, ("tie", lst)
    return lst[i][1]


def room_cells(b, name):
    xs, ys = [], []
    for r in b.spaces[name]:
        c0, r0, sub = b.local_free(*r)
        rr, cc = np.nonzero(sub)
        xs.append(b.lx0 + (c0 + cc + 0.5) * RES)
        ys.append(b.ly0 + (r0 + rr + 0.5) * RES)
    return np.concatenate(xs), np.concatenate(ys)


def opposite(b, name, pose, axis, min_depth=0.8):
    """'the opposite side of the room': the contract's 'third of the room farthest from the robot'.
    Region = a strip along the far wall (axis '+x', '-x', '+y', '-y' of one rectangle) whose every
    point is (a) in the far third of the room along that axis and (b) at least the 2/3-quantile of
    the distances from the robot to the room's free cells (so it is in the farthest third under
    either reading)."""
    xs, ys = room_cells(b, name)
    dstar = float(np.quantile(np.hypot(xs - pose[0], ys - pose[1]), 2 / 3))
    x0, y0, x1, y1 = b.spaces[name][0]
    px, py = pose[0], pose[1]
    if axis == "+y":
        lo = max(y0 + 2 * (y1 - y0) / 3, py + dstar); r = (x0, lo, x1, y1); depth = y1 - lo
    elif axis == "-y":
        hi = min(y0 + (y1 - y0) / 3, py - dstar); r = (x0, y0, x1, hi); depth = hi - y0
    elif axis == "+x":
        lo = max(x0 + 2 * (x1 - x0) / 3, px + dstar); r = (lo, y0, x1, y1); depth = x1 - lo
    else:
        hi = min(x0 + (x1 - x0) / 3, px - dstar); r = (x0, y0, hi, y1); depth = hi - x0
    assert depth >= min_depth, (name, "opposite strip too thin", depth)
    # every free cell of the strip is in the top third by distance
    m = (xs >= r[0]) & (xs <= r[2]) & (ys >= r[1]) & (ys <= r[3])
    assert np.hypot(xs[m] - px, ys[m] - py).min() >= dstar - 1e-9
    return poly(*[round(v, 3) for v in r])


def next_to(o):
    """Within 1.0 m of an obstacle's edge: the four side strips (conservative: no diagonal lobes)."""
    x0, y0, x1, y1 = o
    return {"any": [poly(x0, y1, x1, y1 + 1.0), poly(x0, y0 - 1.0, x1, y0),
                    poly(x0 - 1.0, y0, x0, y1), poly(x1, y0, x1 + 1.0, y1)]}


def within2(box, cx, cy):
    x0, y0, x1, y1 = box
    for x in (x0, x1):
        for y in (y0, y1):
            assert math.hypot(x - cx, y - cy) <= 2.0 + 1e-9, (box, "beyond 2 m of", cx, cy)
    return poly(*box)


def mid(o1, o2):
    return ((o1[0] + o1[2] + o2[0] + o2[2]) / 4, (o1[1] + o1[3] + o2[1] + o2[3]) / 4)


# ================================================================== library (axis-aligned)
def library():
    b = Building("library", -1.0, -1.0, 21.0, 16.0)
    b.shell(0.0, 0.0, 20.0, 15.0)
    b.space("RR", (0.0, 0.0, 12.0, 9.0))         # reading room
    b.space("ST", (12.2, 0.0, 20.0, 9.0))        # book stacks
    b.space("C", (0.0, 9.2, 20.0, 11.2))         # corridor (east end not scanned)
    b.space("Q1", (0.0, 11.4, 4.0, 15.0)); b.space("Q2", (4.2, 11.4, 8.0, 15.0))
    b.space("Q3", (8.2, 11.4, 11.0, 15.0)); b.space("OF", (12.2, 11.4, 20.0, 15.0))
    b.door("RR", 3.0, 9.1, "h", "C", "RR"); b.door("ST", 16.0, 9.1, "h", "C", "ST")
    for n, x in (("Q1", 2.0), ("Q2", 6.0), ("Q3", 10.0), ("OF", 14.0)):
        b.door(n, x, 11.3, "h", "C", n)
    b.door("RS", 12.1, 2.0, "v", "RR", "ST")      # reading room <-> stacks
    b.carve()
    T1, T2 = (3.0, 3.0, 5.0, 4.0), (7.0, 3.0, 9.0, 4.0)      # two tables in the reading room
    for o in (T1, T2):
        b.rect(*o, OCC)
    b.rect(14.0, 0.0, 14.5, 3.8, OCC)            # stack row touching the south wall
    b.rect(14.0, 4.5, 14.5, 9.0, OCC)            # stack row touching the north wall: gap y 3.8..4.5 (0.7 m)
    b.rect(16.8, 1.5, 17.3, 7.0, OCC)            # free-standing stack rows
    b.rect(18.3, 1.5, 18.8, 7.0, OCC)
    b.unknown(18.5, 9.2, 20.0, 11.2)             # corridor east end not scanned
    b.unknown(18.0, 11.4, 20.0, 15.0)            # east part of the office not scanned
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    CD = ["RR", "ST", "Q1", "Q2", "Q3", "OF"]     # the corridor's doors
    LA = (0.8, 10.2, 0)       # corridor, west end, facing east (left = study rooms)
    LB = (8.0, 1.0, 90)       # reading room, south side, facing north
    LC = (13.1, 1.0, 90)      # stacks, west aisle, facing north (gap on the right)
    LD = (19.0, 8.0, 180)     # stacks, north-east, facing west
    LE = (1.4, 12.6, 0)       # study room Q1, facing east
    LF = (10.0, 13.2, 270)    # study room Q3, facing south (its door ahead)
    assert nth(b, LA, CD, "left", 2) == "Q2" and nth(b, LA, CD, "left", 3) == "Q3"
    assert nth(b, LA, CD, "left", 4) == "OF" and nth(b, LA, CD, "left", 5) is None
    assert nth(b, LA, CD, "right", 1) == "RR" and nth(b, LA, CD, "right", 2) == "ST" and nth(b, LA, CD, "right", -1) == "ST"
    assert nth(b, LA, CD, "left", 1) == "Q1"
    assert nth(b, (11.8, 10.2, 0), CD, "right", 1) == "ST"       # after moving 11 m
    assert nth(b, LB, ["RR", "RS"], "right", 1) == "RS" and nth(b, LB, ["RR", "RS"], "left", 1) == "RR"
    assert nth(b, LD, ["ST", "RS"], "right", 1) == "ST"
    assert nth(b, LC, ["ST", "RS"], "left", 1) == "RS" and nth(b, LC, ["ST", "RS"], "left", 2) is None
    areas = {n: b.area(n) for n in ("RR", "ST", "Q1", "Q2", "Q3", "OF")}
    assert max(areas, key=areas.get) == "RR" and min(areas, key=areas.get) == "Q3"
    assert sorted(areas.values())[1] - areas["Q3"] > 2.0
    gap_e = within2((14.6, 3.4, 16.0, 4.9), 14.25, 4.15)     # east of the stack gap
    frontC = band(17.5, 9.2, 18.5, 11.2)                     # corridor within 1 m of its unscanned end
    mid_rr, mid_q1 = b.centroid("RR"), b.centroid("Q1")
    C = [
        ("B", LA, "second door on the left, go", [ntp(D("Q2"), spaces=["C", "Q2", "door:Q2"])]),
        ("A", LA, "Would you go through the last door on your right, dear?",
         [ntp(through(b, "ST", "ST"), spaces=["ST"], kind="through:ST")]),
        ("E", LA, "go towards the unexplored bit at the end of this corridor", [ntp(frontC, spaces=["C"], kind="frontier")]),
        ("D", LA, "Go through the first door on your right. Then go to the middle of that room.",
         [ntp(circ(*mid_rr, MIDDLE), spaces=["RR"])]),
        ("J", LA, "go to the biggest room, obviously", [ntp(R("RR"), spaces=["RR"])]),
        ("F", LA, "hmm, which one is smallest... go to the smallest room", [ntp(R("Q3"), spaces=["Q3"])]),
        ("I", LA, "Go to third door on left side.", [ntp(D("Q3"), spaces=["C", "Q3", "door:Q3"])]),
        ("C", LA, "go to the fifth door on the left", "clarify"),
        ("G", LA, "Go to the fourth door on your left and turn right.", [ntp(D("OF"), spaces=["C", "OF", "door:OF"]), rot_deg(-90)]),
        ("H", LA, "go find the librarian's office", "clarify"),
        ("E", LA, "uh, go forward eleven metres, then go to the nearest door on your right",
         [move("forward", 11.0), ntp(D("ST"), spaces=["C", "ST", "door:ST"])]),
        ("F", LA, "okay, go to the first door on your left and then go through it",
         [ntp(through(b, "Q1", "Q1"), via=[D("Q1")], spaces=["Q1"], via_spaces=["C", "Q1", "door:Q1"], kind="through:Q1")]),
        ("A", LB, "Go to the left corner of this room, dear.", [ntp(side_corner(LB, sp["RR"][0], "left"), spaces=["RR"])]),
        ("C", LB, "go to right corner of room", [ntp(side_corner(LB, sp["RR"][0], "right"), spaces=["RR"])]),
        ("J", LB, "go between the two obstacles I guess", [ntp(circ(*mid(T1, T2), BETWEEN), spaces=["RR"])]),
        ("D", LB, "Go to the opposite side of this room.", [ntp(opposite(b, "RR", LB, "+y"), spaces=["RR"])]),
        ("E", LB, "go out the door", "clarify"),
        ("F", LB, "go next to the nearest obstacle, the one closest to you", [ntp(next_to(T2), spaces=["RR"])]),
        ("G", LB, "Go through the door on your right.", [ntp(through(b, "RS", "ST"), spaces=["ST"], kind="through:RS")]),
        ("I", LB, "Go to middle of room and after turn on ninety degrees to right.",
         [ntp(circ(*mid_rr, MIDDLE), spaces=["RR"]), rot_deg(-90)]),
        ("H", LC, "squeeze through the narrow gap on your right", [ntp(gap_e, spaces=["ST"])]),
        ("I", LC, "Go along wall on your left until end.",
         [ntp(poly(12.2, 7.5, 13.2, 9.0), via=[poly(12.2, 2.5, 13.2, 7.0)], spaces=["ST"], via_spaces=["ST"])]),
        ("B", LD, "through the door on your right", [ntp(through(b, "ST", "C"), spaces=["C"], kind="through:ST")]),
        ("J", LD, "go to the reference desk, duh", "clarify"),
        ("E", LE, "go to the room next to this one", [ntp(R("Q2"), spaces=["Q2"])]),
        ("B", LE, "middle of this room", [ntp(circ(*mid_q1, MIDDLE), spaces=["Q1"])]),
        ("C", LE, "go to nearest corner", [ntp(nearest_corner(LE, sp["Q1"][0]), spaces=["Q1"])]),
        ("D", LF, "Please go out through the door, and then turn left.",
         [ntp(through(b, "Q3", "C"), spaces=["C"], kind="through:Q3"), rot_deg(90)]),
        ("G", LF, "Go out the door and go to the biggest room.",
         [ntp(R("RR"), via=[through(b, "Q3", "C")], spaces=["RR"], via_spaces=["C"])]),
        ("H", LC, "head on through the door on your left", [ntp(through(b, "RS", "RR"), spaces=["RR"], kind="through:RS")]),
    ]
    return b, C


# ================================================================== museum: a ring of galleries, rotated 31 deg, noisy
def museum():
    b = Building("museum", -1.0, -6.0, 30.0, 22.0, theta=31.0, offset=(5.0, 3.0), seed=4031)
    b.shell(0.0, 0.0, 24.0, 18.2)
    b.shell(15.0, -5.0, 21.0, -0.2)             # entrance lobby
    b.shell(24.2, 6.0, 29.0, 12.0)              # shop
    b.shell(10.0, 18.4, 14.0, 21.0)             # archive room off the north gallery
    b.space("GS", (0.0, 0.0, 24.0, 5.8)); b.space("GN", (0.0, 12.2, 24.0, 18.2))
    b.space("GW", (0.0, 6.0, 6.8, 12.0)); b.space("GE", (17.2, 6.0, 24.0, 12.0))
    b.space("LB", (15.0, -5.0, 21.0, -0.2)); b.space("SH", (24.2, 6.0, 29.0, 12.0))
    b.space("AR", (10.0, 18.4, 14.0, 21.0))
    b.door("SW", 3.4, 5.9, "h", "GS", "GW"); b.door("SE", 20.6, 5.9, "h", "GS", "GE")
    b.door("WN", 3.4, 12.1, "h", "GW", "GN"); b.door("EN", 20.6, 12.1, "h", "GE", "GN")
    b.door("LB", 18.0, -0.1, "h", "LB", "GS", width=1.6)
    b.door("SH", 24.1, 9.0, "v", "GE", "SH"); b.door("AR", 12.0, 18.3, "h", "GN", "AR")
    b.carve()
    b.rect(7.2, 6.2, 16.8, 11.8, UNK)           # inside of the walled core: never seen (no free cell touches it)
    P1, P2 = (8.0, 2.4, 9.0, 3.4), (15.0, 2.4, 16.0, 3.4)   # plinths in the south gallery
    BE = (19.5, 8.5, 21.5, 9.5)                 # bench in the east gallery
    for o in (P1, P2, BE, (8.0, 14.6, 16.0, 15.6)):          # + a long display case in the north gallery
        b.rect(*o, OCC)
    b.rect(0.0, 8.9, 3.0, 9.1, OCC); b.rect(3.7, 8.9, 6.8, 9.1, OCC)   # partition in GW, gap x 3.0..3.7
    b.unknown(27.5, 6.0, 29.0, 12.0)            # east part of the shop not scanned
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    GSD = ["SW", "SE", "LB"]; GND = ["WN", "EN", "AR"]; GED = ["SE", "EN", "SH"]; LBD = ["LB"]
    MA = (1.5, 3.0, 0)        # south gallery, west end, facing east
    MA2 = (12.0, 1.0, 0)      # south gallery, middle, facing east
    MB = (3.4, 7.0, 90)       # west gallery, south half, facing north (the gap ahead)
    MC = (20.6, 7.0, 90)      # east gallery, just in from the south, facing north
    MD = (10.0, 16.8, 180)    # north gallery, north of the display case, facing west
    ME = (13.5, 16.8, 180)    # north gallery, facing west, archive door on the right
    MF = (18.0, -3.0, 90)     # lobby, facing north (its door ahead)
    MG = (3.4, 16.5, 270)     # north gallery, west end, facing south (door WN ahead)
    assert nth(b, MA, GSD, "left", 1) == "SW" and nth(b, MA, GSD, "left", 2) == "SE"
    assert nth(b, MA, GSD, "right", 1) == "LB" and nth(b, MA, GSD, "right", 2) is None
    assert nth(b, MC, GED, "right", 1) == "SH" and nth(b, MC, GED, "left", 1) is None
    assert nth(b, MD, GND, "left", 1) == "WN" and nth(b, ME, GND, "right", 1) == "AR"
    areas = {n: b.area(n) for n in sp}
    assert min(areas, key=areas.get) == "AR"
    gap_n = within2((2.5, 9.2, 4.2, 10.6), 3.35, 9.0)
    gap_s = within2((2.5, 7.4, 4.2, 8.8), 3.35, 9.0)
    sh_front = band(26.5, 6.0, 27.5, 12.0)
    mid_gs = b.centroid("GS")
    C = [
        ("A", MA, "Would you go to the first door on your left, dear?", [ntp(D("SW"), spaces=["GS", "GW", "door:SW"])]),
        ("B", MA, "second door left", [ntp(D("SE"), spaces=["GS", "GE", "door:SE"])]),
        ("C", MA, "you go through door on right side", [ntp(through(b, "LB", "LB"), spaces=["LB"], kind="through:LB")]),
        ("D", MA, "Go to the third door on your left, please.", "clarify"),
        ("J", MA2, "go between the two obstacles, wow", [ntp(circ(*mid(P1, P2), BETWEEN), spaces=["GS"])]),
        ("D", MA2, "Go to the middle of this room.", [ntp(circ(*mid_gs, MIDDLE), spaces=["GS"])]),
        ("E", MA2, "go to the right corner of this room", [ntp(side_corner(MA2, sp["GS"][0], "right"), spaces=["GS"])]),
        ("F", MA2, "hmm, the left corner, go to the left corner", [ntp(side_corner(MA2, sp["GS"][0], "left"), spaces=["GS"])]),
        ("G", MA2, "Go to the statue.", "clarify"),
        ("I", MB, "Go through narrow gap in front.", [ntp(gap_n, spaces=["GW"])]),
        ("J", MB, "go through the gap, then through the door in front of you, whatever",
         [ntp(through(b, "WN", "GN"), via=[gap_n], spaces=["GN"], via_spaces=["GW"], kind="through:WN")]),
        ("A", MB, "Would you go towards the unexplored area, dear?", [ntp(sh_front, spaces=["SH"], kind="frontier")]),
        ("D", MC, "Go through the door on your right, and then go towards the unexplored area.",
         [ntp(sh_front, via=[through(b, "SH", "SH", depth=1.4)], spaces=["SH"], via_spaces=["SH"], kind="frontier")]),
        ("E", MC, "go to the opposite side of this room", [ntp(opposite(b, "GE", MC, "+y"), spaces=["GE"])]),
        ("F", MC, "hmm, go next to the obstacle in front of you, that one", [ntp(next_to(BE), spaces=["GE"])]),
        ("G", MC, "Go along the wall on your right to its end.",
         [ntp(poly(23.0, 10.5, 24.0, 12.0), via=[poly(23.0, 7.5, 24.0, 10.0)], spaces=["GE"], via_spaces=["GE", "door:SH"])]),
        ("C", MC, "go to left corner of this room", [ntp(side_corner(MC, sp["GE"][0], "left"), spaces=["GE"])]),
        ("H", MC, "back up a yard", [move("backward", 0.9144)]),
        ("I", MD, "Go to door on left side.", [ntp(D("WN"), spaces=["GN", "GW", "door:WN"])]),
        ("C", MD, "you go to door on left side, then turn right", [ntp(D("WN"), spaces=["GN", "GW", "door:WN"]), rot_deg(-90)]),
        ("B", MD, "face north, quick", [compass(b.pose(*MD)[2], 90)]),
        ("J", ME, "go through the door on your right, ugh", [ntp(through(b, "AR", "AR"), spaces=["AR"], kind="through:AR")]),
        ("B", ME, "smallest room", [ntp(R("AR"), spaces=["AR"])]),
        ("D", ME, "Go to the room next to this one.", "clarify"),
        ("E", MF, "go through the door in front of you", [ntp(through(b, "LB", "GS"), spaces=["GS"], kind="through:LB")]),
        ("F", MF, "hmm, go to the right corner of this room", [ntp(side_corner(MF, sp["LB"][0], "right"), spaces=["LB"])]),
        ("A", MF, "Could you take me to the gift shop, dear?", "clarify"),
        ("G", MG, "Go through the door in front of you and then through the narrow gap.",
         [ntp(gap_s, via=[through(b, "WN", "GW")], spaces=["GW"], via_spaces=["GW"])]),
        ("H", MG, "turn round to face east", [compass(b.pose(*MG)[2], 0)]),
        ("I", MC, "Go to shop.", "clarify"),
    ]
    return b, C


# ================================================================== dormitory corridor with an L-shaped lounge
def dorm():
    b = Building("dorm", -1.0, -1.0, 27.0, 13.0)
    b.shell(0.0, 0.0, 26.0, 12.0)
    b.space("K", (0.0, 5.0, 19.0, 6.8))
    for i, x0 in enumerate((0.0, 4.8, 9.6, 14.4), 1):
        b.space(f"D{i}", (x0, 0.0, x0 + 4.6, 4.8))
        b.door(f"D{i}", x0 + 3.8, 4.9, "h", "K", f"D{i}")
    for i, x0 in enumerate((0.0, 4.8, 9.6), 5):
        b.space(f"D{i}", (x0, 7.0, x0 + 4.6, 12.0))
        b.door(f"D{i}", x0 + 1.0, 6.9, "h", "K", f"D{i}")
    b.space("BA", (14.4, 7.0, 17.0, 10.0)); b.door("BA", 15.5, 6.9, "h", "K", "BA")
    b.space("LO", (19.2, 0.0, 26.0, 6.8), (19.2, 6.8, 22.5, 12.0))     # L-shaped lounge
    b.space("KT", (22.7, 7.0, 26.0, 12.0)); b.door("KT", 24.3, 6.9, "h", "LO", "KT")
    b.door("OPEN", 19.1, 5.9, "v", "K", "LO", width=1.6)               # wide opening corridor -> lounge
    b.carve()
    SF, TB = (20.5, 2.0, 23.0, 2.8), (20.8, 3.8, 22.0, 4.4)             # two pieces of furniture in the lounge
    for o in (SF, TB):
        b.rect(*o, OCC)
    b.rect(9.6, 2.4, 11.6, 3.0, OCC); b.rect(12.3, 2.4, 14.2, 3.0, OCC)  # wardrobe + desk in D3, gap 0.7 m
    b.unknown(9.6, 10.5, 14.2, 12.0)             # north part of D7 not scanned
    b.unknown(19.2, 11.0, 22.5, 12.0)            # north end of the lounge's arm not scanned
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    KD = [f"D{i}" for i in range(1, 8)] + ["BA", "OPEN"]
    KD0 = [f"D{i}" for i in range(1, 8)] + ["BA"]        # reading: the wide opening is not a door
    LOD, LOD0 = ["OPEN", "KT"], ["KT"]
    DA = (0.8, 5.9, 0)        # corridor west end, facing east (the lounge opening straight ahead)
    DB = (13.4, 4.2, 270)     # in D3 just inside its door, facing south (desk ahead, the gap to the right)
    DC = (12.0, 1.2, 90)      # D3 south part, behind the gap, facing north
    DD = (20.0, 5.9, 0)       # lounge, just past the opening, facing east
    DE = (25.4, 11.4, 270)    # kitchenette, north-east, facing south
    DF = (3.2, 10.8, 0)       # D5, facing east
    DG = (0.6, 9.5, 0)        # D5, at its west wall, facing east
    for rd in (KD, KD0):
        assert nth(b, DA, rd, "right", 2) == "D2" and nth(b, DA, rd, "left", 3) == "D7"
        assert nth(b, DA, rd, "right", -1) == "D4" and nth(b, DA, rd, "right", 4) == "D4"
        assert nth(b, DA, rd, "left", 5) is None and nth(b, DA, rd, "right", 1) == "D1"
        assert nth(b, (0.8 + 5 * 0.9144, 5.9, 0), rd, "left", 1) == "D6"
    for rd in (LOD, LOD0):
        assert nth(b, DD, rd, "left", 1) == "KT"
    areas = {n: b.area(n) for n in sp}
    assert max(areas, key=areas.get) == "LO" and min(areas, key=areas.get) == "BA"
    gap_s = within2((11.1, 1.0, 12.8, 2.4), 11.95, 2.7)
    gap_n = within2((11.1, 3.0, 12.8, 4.4), 11.95, 2.7)
    d7_front = band(9.6, 9.5, 14.2, 10.5)
    lo_front = band(19.2, 10.0, 22.5, 11.0)
    # nearest unexplored area: D7's (frontier y ~10.5) vs the lounge arm's (y ~11.0), straight-line distance
    def fr(p, x0, x1, y):
        return math.hypot(min(max(p[0], x0), x1) - p[0], y - p[1])
    assert fr(DA, 9.6, 14.2, 10.5) + 3 < fr(DA, 19.2, 22.5, 11.0)
    assert fr(DD, 19.2, 22.5, 11.0) + 1.5 < fr(DD, 9.6, 14.2, 10.5)
    mid_d4, mid_lo = b.centroid("D4"), b.centroid("LO")
    C = [
        ("A", DA, "Would you go to the second door on your right, dear?", [ntp(D("D2"), spaces=["K", "D2", "door:D2"])]),
        ("B", DA, "third door left", [ntp(D("D7"), spaces=["K", "D7", "door:D7"])]),
        ("C", DA, "go to last door on right side", [ntp(D("D4"), spaces=["K", "D4", "door:D4"])]),
        ("D", DA, "Go through the fourth door on your right. Then go to the middle of that room.",
         [ntp(circ(*mid_d4, MIDDLE), spaces=["D4"])]),
        ("E", DA, "go to the bathroom", "clarify"),
        ("F", DA, "hmm, the biggest room... yeah, go to the biggest room", [ntp(R("LO"), spaces=["LO"])]),
        ("G", DA, "Go to the smallest room.", [ntp(R("BA"), spaces=["BA"])]),
        ("H", DA, "go forward five yards, then go to the nearest door on your left",
         [move("forward", 5 * 0.9144), ntp(D("D6"), spaces=["K", "D6", "door:D6"])]),
        ("I", DA, "Go through fifth door on left side.", "clarify"),
        ("J", DA, "go towards the nearest unexplored area I guess", [ntp(d7_front, spaces=["D7"], kind="frontier")]),
        ("F", DA, "go to the first door on your right, then turn right, then go forward one metre",
         [ntp(D("D1"), spaces=["K", "D1", "door:D1"]), rot_deg(-90), move("forward", 1.0)]),
        ("A", DB, "Could you squeeze through that narrow gap, dear?", [ntp(gap_s, spaces=["D3"])]),
        ("C", DB, "go to room next to this one", "clarify"),
        ("D", DB, "Please go out through the door, and then turn right.",
         [ntp(through(b, "D3", "K"), spaces=["K"], kind="through:D3"), rot_deg(-90)]),
        ("F", DC, "um, go through the narrow gap in front of you", [ntp(gap_n, spaces=["D3"])]),
        ("G", DC, "Go to the left corner of this room.", [ntp(side_corner(DC, sp["D3"][0], "left"), spaces=["D3"])]),
        ("H", DD, "go between the two obstacles", [ntp(circ(*mid(SF, TB), BETWEEN), spaces=["LO"])]),
        ("I", DD, "Go to door on left side.", [ntp(D("KT"), spaces=["LO", "KT", "door:KT"])]),
        ("J", DD, "go through the door on your left, whatever", [ntp(through(b, "KT", "KT"), spaces=["KT"], kind="through:KT")]),
        ("A", DD, "Would you go towards the nearest unexplored area, dear?", [ntp(lo_front, spaces=["LO"], kind="frontier")]),
        ("B", DD, "middle of this room", [ntp(circ(*mid_lo, MIDDLE), spaces=["LO"])]),
        ("C", DD, "go to right corner of this room", [ntp(side_corner(DD, sp["LO"][0], "right"), spaces=["LO"])]),
        ("B", DD, "now face north", [compass(0, 90)]),
        ("D", DE, "Go along the wall on your left until you reach its end.",
         [ntp(poly(25.0, 7.0, 26.0, 8.0), via=[poly(25.0, 8.5, 26.0, 10.5)], spaces=["KT"], via_spaces=["KT"])]),
        ("E", DE, "go out the door and turn left",
         [ntp(through(b, "KT", "LO"), spaces=["LO"], kind="through:KT"), rot_deg(90)]),
        ("G", DF, "Go to the room next to this one.", [ntp(R("D6"), spaces=["D6"])]),
        ("H", DF, "go to the nearest corner", [ntp(nearest_corner(DF, sp["D5"][0]), spaces=["D5"])]),
        ("I", DG, "Go to opposite side of room.", [ntp(opposite(b, "D5", DG, "+x"), spaces=["D5"])]),
        ("J", DF, "go out the door, then turn right, I guess",
         [ntp(through(b, "D5", "K"), spaces=["K"], kind="through:D5"), rot_deg(-90)]),
        ("A", DF, "Could you take me to the lounge, dear?", "clarify"),
    ]
    return b, C


def main():
    out = []
    for fn, tag in ((library, "lib"), (museum, "mus"), (dorm, "dor")):
        b, C = fn()
        assert len(C) == 30, (tag, len(C))
        for i, (spk, pose, prompt, exp) in enumerate(C, 1):
            out.append((b, tag, i, spk, pose, prompt, exp))
    bld_check.write(out)


if __name__ == "__main__":
    main()
