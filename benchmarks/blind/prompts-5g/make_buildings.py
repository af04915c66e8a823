#!/usr/bin/env python3
"""Three more buildings for place-grounded prompts, written in session 5 by the grounding helper
BEFORE reading the grounding code (see README.md): an office floor with an L-shaped corridor
(rotated 14 deg, noisy), a workshop with a T-shaped hall and a side corridor (axis-aligned), and a
ward with a wide hall, rooms facing each other across it and an L-shaped waiting room (rotated
38 deg, noisy).  Drawing / region / check helpers are prompts-4's (bld_lib.py, bld_geom.py,
bld_check.py, ids g5-); the buildings and prompts are new.

Run from this folder: /work/main/.venv/bin/python make_buildings.py
"""
import math

import numpy as np

from bld_lib import (RES, OCC, UNK, AT_DOOR, MIDDLE, BETWEEN, Building, rel, circ, poly, ntp, rot,
                     rot_deg, compass)
from bld_geom import door_reg, room_reg, through, corner_reg, side_corner, nearest_corner, band
import bld_check

#: More wordings of the same places (variants.jsonl), written after the first measurement (see README).
VAR = {}


# ------------------------------------------------------------------ helpers (from prompts-4's make_buildings.py)
def nth(b, pose, doors, side, n, gap=0.5):
    """n-th door (1-based, -1 = last) on `side` among the named doors, nearest first (as prompts-4)."""
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
    """The far third of the room under both readings (along the axis and by distance), as prompts-4."""
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
    m = (xs >= r[0]) & (xs <= r[2]) & (ys >= r[1]) & (ys <= r[3])
    assert np.hypot(xs[m] - px, ys[m] - py).min() >= dstar - 1e-9
    return poly(*[round(v, 3) for v in r])


def next_to(o):
    """Within 1.0 m of an obstacle's edge: the four side strips (no diagonal lobes)."""
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


# ------------------------------------------------------------------ helpers new in this set
def through_r(b, n, r_into, depth=1.5, half=1.2):
    """'through' region for a door into a space whose relevant rectangle is `r_into` (prompts-4's
    `through` always takes the space's first rectangle; an L-shaped corridor needs the other)."""
    d = b.doors[n]
    x, y = d["x"], d["y"]
    rx0, ry0, rx1, ry1 = r_into
    if d["orient"] == "h":
        if ry0 >= y:
            r = (max(x - half, rx0), ry0, min(x + half, rx1), min(y + depth, ry1))
        else:
            r = (max(x - half, rx0), max(y - depth, ry0), min(x + half, rx1), ry1)
    else:
        if rx0 >= x:
            r = (rx0, max(y - half, ry0), min(x + depth, rx1), min(y + half, ry1))
        else:
            r = (max(x - depth, rx0), max(y - half, ry0), rx1, min(y + half, ry1))
    return within2(r, x, y)


def door_mid(b, n1, n2):
    """'between door A and door B': within 0.75 m of the midpoint of their centres."""
    d1, d2 = b.doors[n1], b.doors[n2]
    return circ((d1["x"] + d2["x"]) / 2, (d1["y"] + d2["y"]) / 2, BETWEEN)


def far_corner(pose, rect_corners, rect_of, gap=0.5):
    """'the far corner': of the room's corners, the farthest from the robot (straight line), clear of
    the next one by `gap`; `rect_of` maps a corner to the rectangle that clips its quarter disc."""
    ds = sorted(((math.hypot(cx - pose[0], cy - pose[1]), (cx, cy)) for cx, cy in rect_corners), reverse=True)
    assert ds[0][0] - ds[1][0] >= gap, ("far corner tie", ds[:2])
    return corner_reg(ds[0][1], rect_of(ds[0][1]))


def areas_ok(b, names, biggest, smallest, margin=4.0):
    areas = {n: b.area(n) for n in names}
    s = sorted(areas.values())
    assert max(areas, key=areas.get) == biggest and s[-1] - s[-2] >= margin, ("biggest", areas)
    assert min(areas, key=areas.get) == smallest and s[1] - s[0] >= margin, ("smallest", areas)


# ================================================================== office: L-shaped corridor, rotated 14 deg
def office():
    b = Building("office", -1.0, -1.0, 27.0, 23.0, theta=14.0, offset=(3.0, 1.0), seed=5141)
    b.shell(0.0, 0.0, 26.0, 22.0)
    C_A, C_B = (0.0, 8.0, 20.0, 10.0), (18.0, 10.0, 20.0, 22.0)
    b.space("C", C_A, C_B)                         # corridor: west-east leg, then north up its east end
    b.space("S1", (0.0, 0.0, 5.8, 7.8)); b.space("S2", (6.0, 0.0, 11.8, 7.8))
    b.space("S3", (12.0, 0.0, 17.8, 7.8)); b.space("S4", (18.0, 0.0, 26.0, 7.8))
    b.space("N1", (0.0, 10.2, 5.8, 16.0)); b.space("N2", (6.0, 10.2, 9.8, 14.0))
    N3A, N3B = (10.0, 10.2, 17.8, 15.0), (10.0, 15.0, 13.5, 20.0)
    b.space("N3", N3A, N3B)                        # open-plan office, L-shaped
    b.space("N4", (13.7, 15.2, 17.8, 22.0)); b.space("N5", (0.0, 16.2, 7.0, 22.0))
    b.space("E1", (20.2, 10.0, 26.0, 15.8)); b.space("E2", (20.2, 16.0, 26.0, 22.0))
    for n, x in (("S1", 3.0), ("S2", 9.0), ("S3", 15.0), ("S4", 19.0)):
        b.door(n, x, 7.9, "h", "C", n)
    for n, x in (("N1", 3.0), ("N2", 8.0), ("N3a", 15.0)):
        b.door(n, x, 10.1, "h", "C", n[:2])
    b.door("N3b", 17.9, 12.5, "v", "C", "N3"); b.door("N4", 17.9, 18.5, "v", "C", "N4")
    b.door("E1", 20.1, 12.5, "v", "C", "E1"); b.door("E2", 20.1, 18.5, "v", "C", "E2")
    b.door("S12", 5.9, 4.0, "v", "S1", "S2"); b.door("N15", 3.0, 16.1, "h", "N1", "N5")
    b.carve()
    DK1, DK2 = (7.5, 2.5, 8.5, 4.0), (9.5, 2.5, 10.5, 4.0)      # two desks in S2
    CAB = (11.5, 12.0, 12.5, 13.0)                             # a cabinet in the open-plan office
    TBL = (23.0, 12.0, 24.5, 13.5)                             # a table in E1
    for o in (DK1, DK2, CAB, TBL):
        b.rect(*o, OCC)
    b.rect(12.0, 3.9, 16.6, 4.1, OCC); b.rect(17.3, 3.9, 17.8, 4.1, OCC)   # partition in S3, gap x 16.6..17.3
    b.unknown(18.0, 20.5, 20.0, 22.0)             # north end of the corridor not scanned
    b.unknown(24.5, 16.0, 26.0, 22.0)             # east part of E2 not scanned
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    CD = ["S1", "S2", "S3", "S4", "N1", "N2", "N3a", "N3b", "N4", "E1", "E2"]
    OA = (1.0, 9.0, 0)        # corridor, west end, facing east
    OB = (15.0, 6.5, 90)      # S3, just inside its door, facing north (the door ahead)
    OC = (13.0, 5.5, 0)       # S3 north part, facing east (the gap ahead-right)
    OD = (11.0, 18.0, 270)    # N3's arm, facing south
    OE = (22.0, 13.0, 180)    # E1, facing west (its door ahead)
    OF = (19.0, 11.0, 90)     # corridor's north leg, south end, facing north
    OG = (9.0, 6.0, 270)      # S2, facing south (the desks ahead)
    OH = (2.0, 4.0, 0)        # S1, facing east (the door to S2 ahead)
    assert nth(b, OA, CD, "left", 1) == "N1" and nth(b, OA, CD, "left", 3) == "N3a"
    assert nth(b, OA, CD, "right", 2) == "S2" and nth(b, OA, CD, "right", -1) == "S4"
    assert nth(b, OA, CD, "right", 1) == "S1"
    assert nth(b, OF, CD, "right", -1) == "E2"
    areas_ok(b, ["S1", "S2", "S3", "S4", "N1", "N2", "N3", "N4", "N5", "E1", "E2"], "S4", "N2")
    mid_n3 = b.centroid("N3")
    assert b.space_of_local(*mid_n3) == "N3"
    gap_s = within2((16.0, 2.6, 17.8, 3.8), 16.95, 4.0)
    frontB = band(18.0, 19.6, 20.0, 20.5)
    n3_corners = [(10.0, 20.0), (13.5, 20.0), (10.0, 10.2), (17.8, 10.2), (17.8, 15.0)]
    C = [
        ("B", OA, "pop into the second room on your right", [ntp(R("S2"), spaces=["S2"])]),
        ("D", OA, "Stop between the first and second doors on your left.",
         [ntp(door_mid(b, "N1", "N2"), spaces=["C", "N1", "N2"])]),
        ("J", OA, "go thru the 3rd door on ur left", [ntp(through(b, "N3a", "N3"), spaces=["N3"], kind="through:N3a")]),
        ("C", OA, "go to last door on right", [ntp(D("S4"), spaces=["C", "S4", "door:S4"])]),
        ("F", OA, "hmm, where's the most space... go into the biggest room", [ntp(R("S4"), spaces=["S4"])]),
        ("E", OA, "which room is the smallest? go there I guess", [ntp(R("N2"), spaces=["N2"])]),
        ("A", OA, "Could you take me to the bathroom, dear?", "clarify"),
        ("G", OA, "Go to the door on your left, then through it.",
         [ntp(through(b, "N1", "N1"), via=[D("N1")], spaces=["N1"], via_spaces=["C", "N1", "door:N1"], kind="through:N1")]),
        ("H", OA, "stop btwn the 1st and 2nd doors on the right", [ntp(door_mid(b, "S1", "S2"), spaces=["C", "S1", "S2"])]),
        ("I", OA, "Turn to face north.", [compass(b.pose(*OA)[2], 90)]),
        ("D", OB, "Go into the room across the hall.", [ntp(R("N3"), spaces=["N3"])]),
        ("E", OC, "squeeze through the narrow gap on your right", [ntp(gap_s, spaces=["S3"])]),
        ("F", OD, "um, go to the middle of this room", [ntp(circ(*mid_n3, MIDDLE), spaces=["N3"])]),
        ("G", OD, "Go to the nearest corner.", [ntp(nearest_corner(OD, N3B), spaces=["N3"])]),
        ("H", OD, "head over to the far corner of this room",
         [ntp(far_corner(OD, n3_corners, lambda c: N3B if c[1] >= 20.0 else N3A), spaces=["N3"])]),
        ("I", OD, "Go out the door.", "clarify"),
        ("J", OD, "go next to the obstacle, whatever", [ntp(next_to(CAB), spaces=["N3"])]),
        ("A", OE, "Would you go to the room on the other side of the hall, dear?", [ntp(R("N3"), spaces=["N3"])]),
        ("B", OE, "back out the door and turn left",
         [ntp(through_r(b, "E1", C_B), spaces=["C"], kind="through:E1"), rot_deg(90)]),
        ("C", OF, "go towards unexplored bit at end of this corridor", [ntp(frontB, spaces=["C"], kind="frontier")]),
        ("D", (19.0, 14.5, 90), "Go to the door ahead on your left.", [ntp(D("N4"), spaces=["C", "N4", "door:N4"])]),
        ("E", OF, "uh, go into the last room on the right", [ntp(R("E2"), spaces=["E2"])]),
        ("F", OG, "go btwn the two obstacles", [ntp(circ(*mid(DK1, DK2), BETWEEN), spaces=["S2"])]),
        ("G", OG, "Go next to the obstacle on your left.", [ntp(next_to(DK2), spaces=["S2"])]),
        ("H", OG, "go to the room next to this one", "clarify"),
        ("I", OH, "Go to room next to this one.", [ntp(R("S2"), spaces=["S2"])]),
        ("J", OH, "go through the door in front of you, duh",
         [ntp(within2((6.0, 3.0, 7.4, 5.0), 5.9, 4.0), spaces=["S2"], kind="through:S12")]),
    ]
    VAR["office"] = [
        ("A", OA, "head into the second room on the right", [ntp(R("S2"), spaces=["S2"])]),
        ("B", OA, "wait in between the first two doors on your left", [ntp(door_mid(b, "N1", "N2"), spaces=["C", "N1", "N2"])]),
        ("C", OA, "go halfway between the first door on the left and the second one", [ntp(door_mid(b, "N1", "N2"), spaces=["C", "N1", "N2"])]),
        ("D", OA, "Enter the third room on your left.", [ntp(R("N3"), spaces=["N3"])]),
        ("E", OA, "go to the largest room on this floor", [ntp(R("S4"), spaces=["S4"])]),
        ("F", OA, "find the smallest room and go in", [ntp(R("N2"), spaces=["N2"])]),
        ("G", OA, "Go to the restroom.", "clarify"),
        ("H", OA, "go to the conference room", "clarify"),
        ("I", OB, "Go in room directly across the hall.", [ntp(R("N3"), spaces=["N3"])]),
        ("J", OB, "cross the hall into the room opposite", [ntp(R("N3"), spaces=["N3"])]),
        ("A", OF, "Would you go to the unexplored area at the far end of this corridor, dear?", [ntp(frontB, spaces=["C"], kind="frontier")]),
        ("B", OF, "drive towards the unmapped bit at the end of the hall", [ntp(frontB, spaces=["C"], kind="frontier")]),
        ("C", OD, "get next to the obstacle", [ntp(next_to(CAB), spaces=["N3"])]),
        ("D", OD, "Go to the corner furthest from you.",
         [ntp(far_corner(OD, n3_corners, lambda c: N3B if c[1] >= 20.0 else N3A), spaces=["N3"])]),
        ("E", OE, "go to the room across from this one", [ntp(R("N3"), spaces=["N3"])]),
        ("F", OE, "exit the room and turn left", [ntp(through_r(b, "E1", C_B), spaces=["C"], kind="through:E1"), rot_deg(90)]),
        ("G", OE, "Go next to the cabinet.", "clarify"),
        ("H", OG, "park between the 2 obstacles", [ntp(circ(*mid(DK1, DK2), BETWEEN), spaces=["S2"])]),
        ("I", OH, "Go through door in front and stop in middle of next room.", [ntp(circ(*b.centroid("S2"), MIDDLE), spaces=["S2"])]),
        ("J", OA, "go to the room beside the kitchen", "clarify"),
    ]
    return b, C


# ================================================================== workshop: T-shaped hall, side corridor (axis-aligned)
def workshop():
    b = Building("workshop", -1.0, -1.0, 25.0, 19.0)
    b.shell(0.0, 0.0, 24.0, 18.0)
    HA, HB = (0.0, 0.0, 16.0, 10.0), (4.0, 10.0, 12.0, 14.0)
    b.space("H", HA, HB)                           # the workshop hall: a wide part and a bay to the north
    KR = (16.2, 0.0, 18.2, 18.0)
    b.space("K", KR)                               # side corridor
    b.space("R1", (18.4, 0.0, 24.0, 5.8)); b.space("R2", (18.4, 6.0, 24.0, 11.8)); b.space("R3", (18.4, 12.0, 24.0, 18.0))
    b.space("OF", (12.2, 10.2, 16.0, 18.0)); b.space("ST", (0.0, 10.2, 3.8, 18.0))
    b.space("WC", (4.0, 14.2, 6.5, 18.0)); b.space("LK", (6.7, 14.2, 12.0, 18.0))
    b.door("OPEN", 16.1, 5.0, "v", "H", "K", width=1.6)
    b.door("R1", 18.3, 4.5, "v", "K", "R1"); b.door("R2", 18.3, 9.0, "v", "K", "R2"); b.door("R3", 18.3, 15.0, "v", "K", "R3")
    b.door("OF", 16.1, 14.0, "v", "K", "OF"); b.door("ST", 2.0, 10.1, "h", "H", "ST")
    b.door("WC", 5.25, 14.1, "h", "H", "WC"); b.door("LK", 9.0, 14.1, "h", "H", "LK")
    b.carve()
    SH1, SH2, MC = (3.0, 2.0, 3.6, 7.0), (6.0, 2.0, 6.6, 7.0), (10.0, 3.0, 12.0, 5.0)   # two shelf rows, a machine
    for o in (SH1, SH2, MC):
        b.rect(*o, OCC)
    b.rect(18.4, 2.5, 22.6, 2.7, OCC); b.rect(23.3, 2.5, 24.0, 2.7, OCC)   # partition in R1, gap x 22.6..23.3
    b.unknown(16.2, 16.8, 18.2, 18.0)             # north end of the corridor not scanned
    b.unknown(0.0, 16.5, 3.8, 18.0)               # north part of the store not scanned
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    KD = ["OPEN", "R1", "R2", "R3", "OF"]
    KD0 = ["R1", "R2", "R3", "OF"]                # reading: the wide opening is not a door
    WA = (17.2, 1.0, 90)      # corridor, south end, facing north
    WB = (8.0, 8.5, 270)      # hall, facing south
    WD = (8.0, 12.5, 90)      # hall's north bay, facing north (two doors ahead)
    WF = (14.0, 12.0, 90)     # office, facing north (its door on the right)
    WH = (21.0, 15.0, 180)    # R3, facing west (its door ahead)
    for rd in (KD, KD0):
        assert nth(b, WA, rd, "right", 2) == "R2" and nth(b, WA, rd, "right", -1) == "R3"
        assert nth(b, WA, rd, "left", -1) == "OF"
    assert nth(b, WD, ["WC", "LK", "ST"], "right", 1) == "LK" and nth(b, WD, ["WC", "LK"], "left", 1) == "WC"
    areas_ok(b, ["H", "R1", "R2", "R3", "OF", "ST", "WC", "LK"], "H", "WC")
    mid_h = b.centroid("H")
    assert b.space_of_local(*mid_h) == "H"
    gap_r1 = within2((22.2, 1.0, 23.8, 2.4), 22.95, 2.6)
    frontK = band(16.2, 15.9, 18.2, 16.8)
    st_front = band(0.0, 15.6, 3.8, 16.5)
    # nearest unexplored area from WB: the store's (frontier y 16.5) before the corridor's (y 16.8)
    assert math.hypot(3.8 - WB[0], 16.5 - WB[1]) + 2 < math.hypot(16.2 - WB[0], 16.8 - WB[1])
    C = [
        ("A", WA, "Would you go to the second door on your right, dear?", [ntp(D("R2"), spaces=["K", "R2", "door:R2"])]),
        ("B", WA, "last room on the right, go", [ntp(R("R3"), spaces=["R3"])]),
        ("C", WA, "go to last door on left side", [ntp(D("OF"), spaces=["K", "OF", "door:OF"])]),
        ("D", WA, "Go up the corridor towards the unexplored part at the end of it.",
         [ntp(frontK, spaces=["K"], kind="frontier")]),
        ("E", WA, "go through the first door on your right and then squeeze through the gap",
         [ntp(gap_r1, via=[through(b, "R1", "R1")], spaces=["R1"], via_spaces=["R1"])]),
        ("F", WA, "hmm, stop between the first and second doors on your right",
         [ntp(door_mid(b, "R1", "R2"), spaces=["K", "R2"])]),
        ("G", WA, "Go to the biggest room.", [ntp(R("H"), spaces=["H"])]),
        ("H", WA, "go through the wide opening on your left",
         [ntp(within2((14.5, 4.0, 16.0, 6.0), 16.1, 5.0), spaces=["H"], kind="through:OPEN")]),
        ("I", WA, "Turn to face west.", [compass(90, 180)]),
        ("J", WA, "go to the loading bay, obviously", "clarify"),
        ("A", WB, "Would you stop between the two obstacles on your right, dear?",
         [ntp(circ(*mid(SH1, SH2), BETWEEN), spaces=["H"])]),
        ("B", WB, "next to the obstacle on your left", [ntp(next_to(MC), spaces=["H"])]),
        ("C", WB, "go to right corner of this room", [ntp(side_corner(WB, HA, "right"), spaces=["H"])]),
        ("D", WB, "Go to the bathroom, please.", "clarify"),
        ("E", WB, "go to the middle of this room", [ntp(circ(*mid_h, MIDDLE), spaces=["H"])]),
        ("F", WB, "hmm, go towards the nearest unexplored area", [ntp(st_front, spaces=["ST"], kind="frontier")]),
        ("G", WD, "Go through the door on your right.", [ntp(through(b, "LK", "LK"), spaces=["LK"], kind="through:LK")]),
        ("H", WD, "go to the smallest room", [ntp(R("WC"), spaces=["WC"])]),
        ("I", WD, "Go to door on left side, then go through it.",
         [ntp(through(b, "WC", "WC"), via=[D("WC")], spaces=["WC"], via_spaces=["H", "WC", "door:WC"], kind="through:WC")]),
        ("J", WF, "go to the room next to this one, I guess", "clarify"),
        ("A", WF, "Could you go out the door and then turn right, dear?",
         [ntp(through(b, "OF", "K"), spaces=["K"], kind="through:OF"), rot_deg(-90)]),
        ("B", WH, "room on the other side of the corridor", [ntp(R("OF"), spaces=["OF"])]),
    ]
    VAR["workshop"] = [
        ("A", WA, "go into the 2nd room on your right", [ntp(R("R2"), spaces=["R2"])]),
        ("B", WA, "stop in between the first 2 doors on the right", [ntp(door_mid(b, "R1", "R2"), spaces=["K", "R2"])]),
        ("C", WA, "head down the corridor to the unexplored area at the end", [ntp(frontK, spaces=["K"], kind="frontier")]),
        ("D", WA, "Go into the big room on your left.", [ntp(R("H"), spaces=["H"])]),
        ("E", WB, "go halfway between the two obstacles on your right", [ntp(circ(*mid(SH1, SH2), BETWEEN), spaces=["H"])]),
        ("F", WB, "go next to the shelf", "clarify"),
        ("G", WB, "Go to the toilet.", "clarify"),
        ("H", WB, "go to the unexplored area closest to you", [ntp(st_front, spaces=["ST"], kind="frontier")]),
        ("I", WD, "Go through door on right side.", [ntp(through(b, "LK", "LK"), spaces=["LK"], kind="through:LK")]),
        ("J", WD, "go to the tiniest room", [ntp(R("WC"), spaces=["WC"])]),
        ("A", WF, "Would you leave the room and turn right, dear?", [ntp(through(b, "OF", "K"), spaces=["K"], kind="through:OF"), rot_deg(-90)]),
        ("B", WH, "room across the corridor", [ntp(R("OF"), spaces=["OF"])]),
        ("C", WH, "go in the room on the opposite side of the hallway", [ntp(R("OF"), spaces=["OF"])]),
    ]
    return b, C


# ================================================================== ward: wide hall, rooms facing across it, rotated 38 deg
def ward():
    b = Building("ward", -1.0, -1.0, 23.0, 15.0, theta=38.0, offset=(12.0, 0.0), seed=5383)
    b.shell(0.0, 0.0, 22.0, 14.0)
    HW = (0.0, 6.0, 22.0, 8.2)
    b.space("Hw", HW)
    b.space("A1", (0.0, 0.0, 4.8, 5.8)); b.space("A2", (5.0, 0.0, 9.8, 5.8))
    b.space("A3", (10.0, 0.0, 14.8, 5.8)); b.space("A4", (15.0, 0.0, 22.0, 5.8))
    b.space("B1", (0.0, 8.4, 4.8, 14.0)); b.space("B2", (5.0, 8.4, 9.8, 14.0))
    B3A, B3B = (10.0, 8.4, 22.0, 11.2), (10.0, 11.2, 18.3, 14.0)
    b.space("B3", B3A, B3B)                        # waiting room, L-shaped
    b.space("B4", (18.5, 11.4, 22.0, 14.0))
    b.door("A1", 2.4, 5.9, "h", "Hw", "A1"); b.door("A2", 6.2, 5.9, "h", "Hw", "A2")
    b.door("A3", 12.4, 5.9, "h", "Hw", "A3"); b.door("A4", 17.0, 5.9, "h", "Hw", "A4")
    b.door("B1", 2.4, 8.3, "h", "Hw", "B1"); b.door("B2", 7.4, 8.3, "h", "Hw", "B2")
    b.door("B3", 12.4, 8.3, "h", "Hw", "B3"); b.door("B3b", 19.0, 8.3, "h", "Hw", "B3")
    b.door("B4", 20.2, 11.3, "h", "B3", "B4")
    b.carve()
    BD1, BD2 = (10.8, 1.0, 11.8, 3.0), (13.0, 1.0, 14.0, 3.0)   # two beds in A3
    SOFA = (16.0, 9.4, 17.5, 10.2)                               # in the waiting room
    for o in (BD1, BD2, SOFA):
        b.rect(*o, OCC)
    b.rect(7.3, 0.0, 7.5, 2.2, OCC); b.rect(7.3, 2.9, 7.5, 5.8, OCC)   # partition in A2, gap y 2.2..2.9
    b.unknown(20.5, 6.0, 22.0, 8.2)               # east end of the hall not scanned
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    HD = ["A1", "A2", "A3", "A4", "B1", "B2", "B3", "B3b"]
    VA = (1.0, 7.1, 0)        # hall, west end, facing east
    VB = (12.4, 4.5, 90)      # A3, facing north (its door ahead)
    VC = (20.2, 13.0, 270)    # B4, facing south (its door ahead)
    VE = (16.0, 4.5, 0)       # A4, facing east
    VF = (6.0, 3.0, 0)        # A2 west part, facing east (the gap ahead)
    VG = (14.0, 7.1, 180)     # hall, facing west
    assert nth(b, VA, HD, "left", 3) == "B3" and nth(b, VA, HD, "right", 2) == "A2"
    assert nth(b, VA, HD, "left", 2) == "B2" and nth(b, VA, HD, "left", 5) is None
    assert nth(b, VG, HD, "left", 1) == "A3" and nth(b, VG, HD, "right", -1) == "B1"
    areas_ok(b, ["A1", "A2", "A3", "A4", "B1", "B2", "B3", "B4"], "B3", "B4", margin=4.0)
    mid_b3 = b.centroid("B3")
    assert b.space_of_local(*mid_b3) == "B3"
    frontH = band(19.5, 6.0, 20.5, 8.2)
    gap_e = within2((7.5, 1.6, 8.9, 3.5), 7.4, 2.55)
    C = [
        ("A", VA, "Would you go to the third door on your left, dear?", [ntp(D("B3"), spaces=["Hw", "B3", "door:B3"])]),
        ("B", VA, "take the 2nd door on the right and go in", [ntp(through(b, "A2", "A2"), spaces=["A2"], kind="through:A2")]),
        ("C", VA, "go towards unexplored area at end of hall", [ntp(frontH, spaces=["Hw"], kind="frontier")]),
        ("D", VA, "Stop between the second and third doors on your left.",
         [ntp(door_mid(b, "B2", "B3"), spaces=["Hw", "B2", "B3"])]),
        ("E", VA, "go into the biggest room", [ntp(R("B3"), spaces=["B3"])]),
        ("F", VA, "hmm, the x-ray room, go to the x-ray room", "clarify"),
        ("G", VA, "Face south.", [compass(b.pose(*VA)[2], 270)]),
        ("H", VA, "go to the smallest room", [ntp(R("B4"), spaces=["B4"])]),
        ("I", VA, "Go to fifth door on left side.", "clarify"),
        ("J", VB, "go into the room across the hall, duh", [ntp(R("B3"), spaces=["B3"])]),
        ("A", VB, "Could you turn around and go between the two obstacles, dear?",
         [rot("any", 17, 19), ntp(circ(*mid(BD1, BD2), BETWEEN), spaces=["A3"])]),
        ("B", VB, "room next to this one", "clarify"),
        ("C", VB, "go next to obstacle on your left", [ntp(next_to(BD1), spaces=["A3"])]),
        ("D", VC, "Go to the room next to this one.", [ntp(R("B3"), spaces=["B3"])]),
        ("E", (11.0, 13.0, 270), "go to the middle of this room", [ntp(circ(*mid_b3, MIDDLE), spaces=["B3"])]),
        ("F", VE, "hmm, go to the left corner of the room", [ntp(side_corner(VE, b.spaces["A4"][0], "left"), spaces=["A4"])]),
        ("G", VE, "Go to the right corner of this room.", [ntp(side_corner(VE, b.spaces["A4"][0], "right"), spaces=["A4"])]),
        ("H", VE, "go over to the opposite side of this room", [ntp(opposite(b, "A4", VE, "+x"), spaces=["A4"])]),
        ("I", VE, "Go out door and go in room across hall.",
         [ntp(R("B3"), via=[through(b, "A4", "Hw")], spaces=["B3"], via_spaces=["Hw"])]),
        ("J", VF, "go thru the narrow passage I guess", [ntp(gap_e, spaces=["A2"])]),
        ("A", VG, "Would you go to the first door on your left, dear?", [ntp(D("A3"), spaces=["Hw", "A3", "door:A3"])]),
        ("B", VG, "last room on ur right", [ntp(R("B1"), spaces=["B1"])]),
        ("C", VG, "go to the nurses station", "clarify"),
        ("D", VG, "Go into the room behind you on the left.", [ntp(R("A4"), spaces=["A4"])]),
    ]
    VAR["ward"] = [
        ("A", VA, "go to door number three on your left", [ntp(D("B3"), spaces=["Hw", "B3", "door:B3"])]),
        ("B", VA, "stop between the 2nd and 3rd doors on the left", [ntp(door_mid(b, "B2", "B3"), spaces=["Hw", "B2", "B3"])]),
        ("C", VA, "go down the hall towards the unexplored bit at the end of it", [ntp(frontH, spaces=["Hw"], kind="frontier")]),
        ("D", VA, "Go to the largest room.", [ntp(R("B3"), spaces=["B3"])]),
        ("E", VA, "go to the operating theatre", "clarify"),
        ("F", VB, "hmm, go to the room on the other side of the corridor", [ntp(R("B3"), spaces=["B3"])]),
        ("G", VB, "Turn around and stop between the two obstacles.", [rot("any", 17, 19), ntp(circ(*mid(BD1, BD2), BETWEEN), spaces=["A3"])]),
        ("H", VC, "go to the room beside this one", [ntp(R("B3"), spaces=["B3"])]),
        ("I", VE, "Go in left corner of room.", [ntp(side_corner(VE, b.spaces["A4"][0], "left"), spaces=["A4"])]),
        ("J", VE, "go out the door and into the room across the hall, duh",
         [ntp(R("B3"), via=[through(b, "A4", "Hw")], spaces=["B3"], via_spaces=["Hw"])]),
        ("A", VG, "Would you go into the last room on your right, dear?", [ntp(R("B1"), spaces=["B1"])]),
        ("B", VG, "room behind you on the left", [ntp(R("A4"), spaces=["A4"])]),
        ("C", VF, "go through the narrow gap in front of you", [ntp(gap_e, spaces=["A2"])]),
    ]
    return b, C


def main():
    out = []
    for fn, tag in ((office, "ofc"), (workshop, "wks"), (ward, "wrd")):
        b, C = fn()
        for i, (spk, pose, prompt, exp) in enumerate(C, 1):
            out.append((b, tag, i, spk, pose, prompt, exp))
    bld_check.write(out)
    write_variants({fn: b for fn, b in ((tag, row[0]) for row in out for tag in [row[0].name])})


def write_variants(buildings):
    """variants.jsonl: the same checks (bld_check.check) and the same id scheme (g5v-)."""
    import json
    rows = []
    for name, cases in VAR.items():
        b = buildings[name]
        bld_check.check(b, cases)
        tag = {"office": "ofc", "workshop": "wks", "ward": "wrd"}[name]
        for i, (spk, pose, prompt, exp) in enumerate(cases, 1):
            rows.append({"id": f"g5v-{tag}-{spk}{i:02d}", "map": f"maps/{b.name}.yaml", "pose": b.pose(*pose),
                         "prompt": prompt, "expect": bld_check.world_expect(b, exp)})
    (bld_check.HERE / "variants.jsonl").write_text("".join(json.dumps(c) + "\n" for c in rows))
    print(len(rows), "variant cases")


if __name__ == "__main__":
    main()
