#!/usr/bin/env python3
"""Draws a radio station (broadcast house) -- NON-RECTANGULAR outline, ROTATED -52.6 deg with lidar-like
noise (seed 8526) -- and writes buildings.jsonl, 30 place-grounded prompts written from the bench contract
(../shared/bench/README.md) before langnav was run on them.  Every expected region is checked on the drawn
map (bld_check.check) and an oracle output built from the expectations is scored 1.0.

Layout (local frame, metres): a reception (glassless, sofa, reception desk) with a 1.8 m entrance to the
never-scanned street and a 1.2 m door east into a 1.8 m corridor 20 m long.  South of the corridor: studio A
(mixing table), control room (desk against the wall), studio B (table), a record library (free-standing
shelves with a 0.7 m and a 1.0 m aisle, its back corner never scanned).  North: a newsroom (biggest; three
desk blocks, two of them 0.7 m apart; a free-standing pillar), a kitchen (island, counter), a green room
(sofa, coffee table, a 1.0 m fire door onto the never-scanned yard).  A toilet at the corridor's east end;
a server closet (smallest, 0.7 m door) off the newsroom.

Drawing / geometry / check helpers (bld_*.py, render.py) are copied from prompts-8; helpers nth,
opposite, next_to, next_to_in, within2, mid, nearest_obstacles, frontier_dist, hollow, thr are copied from
prompts-8/make_buildings.py.

Run from this folder: /work/main/.venv/bin/python make_radio.py
"""
import math

import numpy as np

from bld_lib import (RES, OCC, FREE, UNK, MIDDLE, BETWEEN, Building, rel, circ, poly, ntp, rot_deg, compass)
from bld_geom import door_reg, room_reg, through, side_corner, nearest_corner, band
import bld_check


# ------------------------------------------------------------------ helpers copied from prompts-8
def nth(b, pose, doors, side, n, gap=0.5):
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
    x0, y0, x1, y1 = o
    return {"any": [poly(x0, y1, x1, y1 + 1.0), poly(x0, y0 - 1.0, x1, y0),
                    poly(x0 - 1.0, y0, x0, y1), poly(x1, y0, x1 + 1.0, y1)]}


def next_to_in(o, room):
    X0, Y0, X1, Y1 = room
    out = []
    for s in next_to(o)["any"]:
        (x0, y0), (x1, y1) = s["polygon"][0], s["polygon"][2]
        x0, y0, x1, y1 = max(x0, X0), max(y0, Y0), min(x1, X1), min(y1, Y1)
        if x1 - x0 > 0.05 and y1 - y0 > 0.05:
            out.append(poly(x0, y0, x1, y1))
    return {"any": out}


def within2(box, cx, cy):
    x0, y0, x1, y1 = box
    for x in (x0, x1):
        for y in (y0, y1):
            assert math.hypot(x - cx, y - cy) <= 2.0 + 1e-9, (box, "beyond 2 m of", cx, cy)
    return poly(*box)


def mid(o1, o2):
    return ((o1[0] + o1[2] + o2[0] + o2[2]) / 4, (o1[1] + o1[3] + o2[1] + o2[3]) / 4)


def edge(o, p):
    x = min(max(p[0], o[0]), o[2]); y = min(max(p[1], o[1]), o[3])
    return math.hypot(x - p[0], y - p[1])


def nearest_obstacles(pose, obs, k):
    def cen(o):
        return math.hypot((o[0] + o[2]) / 2 - pose[0], (o[1] + o[3]) / 2 - pose[1])
    by_e = sorted(obs, key=lambda n: edge(obs[n], pose)); by_c = sorted(obs, key=lambda n: cen(obs[n]))
    assert set(by_e[:k]) == set(by_c[:k]), (by_e, by_c)
    assert edge(obs[by_e[k]], pose) - edge(obs[by_e[k - 1]], pose) > 1.0
    return by_e[:k]


def frontier_dist(pose, rect):
    x = min(max(pose[0], rect[0]), rect[2]); y = min(max(pose[1], rect[1]), rect[3])
    return math.hypot(x - pose[0], y - pose[1])


def hollow(b, ring=3):
    from scipy import ndimage
    d = ndimage.distance_transform_edt(b.g == OCC)
    b.g[d > ring] = UNK


def thr(b, n, into, **kw):
    reg = through(b, n, into, **kw)
    (x0, y0), (x1, y1) = reg["polygon"][0], reg["polygon"][2]
    d = b.doors[n]
    if d["orient"] == "v":
        if abs(x0 - d["x"]) < abs(x1 - d["x"]):
            x0 += 0.1
        else:
            x1 -= 0.1
    else:
        if abs(y0 - d["y"]) < abs(y1 - d["y"]):
            y0 += 0.1
        else:
            y1 -= 0.1
    return poly(round(x0, 3), round(y0, 3), round(x1, 3), round(y1, 3))


# ================================================================== radio station
def radio():
    b = Building("radio", -1.0, -1.0, 29.5, 15.0, theta=-52.6, offset=(1.0, 24.0), seed=8526)
    b.shell(0.0, 0.0, 6.0, 8.0); b.shell(6.2, 0.0, 26.0, 6.8); b.shell(6.2, 7.0, 16.0, 14.0)
    b.shell(16.2, 7.0, 26.0, 11.0); b.shell(16.2, 11.2, 18.0, 14.0); b.shell(26.2, 3.5, 28.5, 7.5)
    b.space("RC", (0.0, 0.0, 6.0, 8.0))            # reception
    b.space("HW", (6.2, 5.0, 26.0, 6.8))           # corridor, 1.8 m
    b.space("SA", (6.2, 0.0, 11.0, 4.8))           # studio A
    b.space("CA", (11.2, 0.0, 14.0, 4.8))          # control room
    b.space("SB", (14.2, 0.0, 19.0, 4.8))          # studio B
    b.space("LB", (19.2, 0.0, 26.0, 4.8))          # record library (back corner never scanned)
    b.space("NR", (6.2, 7.0, 16.0, 14.0))          # newsroom (biggest)
    b.space("KT", (16.2, 7.0, 20.0, 11.0))         # kitchen
    b.space("GR", (20.2, 7.0, 26.0, 11.0))         # green room
    b.space("SV", (16.2, 11.2, 18.0, 14.0))        # server closet (smallest)
    b.space("WC", (26.2, 3.5, 28.5, 7.5))          # toilet
    b.door("EX", 3.0, -0.1, "h", "RC", "OUT", width=1.8)     # entrance, street never scanned
    b.door("RD", 6.1, 5.9, "v", "RC", "HW", width=1.2)
    b.door("SAD", 8.0, 4.9, "h", "HW", "SA", width=0.9)
    b.door("CAD", 12.6, 4.9, "h", "HW", "CA", width=0.8)
    b.door("SBD", 15.5, 4.9, "h", "HW", "SB", width=0.9)
    b.door("LBD", 20.0, 4.9, "h", "HW", "LB", width=1.0)
    b.door("NRD", 9.0, 6.9, "h", "HW", "NR", width=1.4)      # double door
    b.door("KTD", 17.5, 6.9, "h", "HW", "KT", width=0.8)
    b.door("GRD", 22.0, 6.9, "h", "HW", "GR", width=0.9)
    b.door("WCD", 26.1, 5.9, "v", "HW", "WC", width=0.8)     # at the corridor's east end
    b.door("SVD", 16.1, 12.6, "v", "NR", "SV", width=0.7)
    b.door("FD", 26.1, 9.0, "v", "GR", "OUT", width=1.0)     # fire door, yard never scanned
    b.carve()
    SOF = (0.3, 1.5, 0.9, 4.0)                     # reception sofa
    RDK = (1.0, 5.8, 4.0, 6.6)                     # reception desk
    SAT = (7.5, 1.5, 9.5, 2.7)                     # studio A mixing table
    CDK = (11.4, 0.0, 13.8, 0.8)                   # control desk against the wall
    SBT = (15.5, 1.5, 17.5, 2.7)                   # studio B table
    L1, L2, L3 = (20.5, 1.0, 21.0, 2.8), (21.7, 1.0, 22.2, 2.8), (23.2, 1.0, 23.7, 2.8)   # shelves: 0.7 / 1.0 m aisles
    ND1, ND2, ND3 = (8.0, 9.0, 10.5, 10.2), (11.2, 9.0, 13.7, 10.2), (8.0, 12.0, 10.5, 13.2)   # desks
    PIL = (14.6, 11.5, 15.0, 11.9)                 # pillar
    KI = (17.3, 8.3, 18.9, 9.1)                    # kitchen island
    KC = (16.2, 10.2, 20.0, 11.0)                  # kitchen counter along the north wall
    GS, GT = (20.5, 9.6, 23.0, 10.4), (21.2, 8.5, 22.4, 9.1)   # green-room sofa, coffee table
    for o in (SOF, RDK, SAT, CDK, SBT, L1, L2, L3, ND1, ND2, ND3, PIL, KI, KC, GS, GT):
        b.rect(*o, OCC)
    UNK_LB = (24.8, 0.0, 26.0, 2.0)
    b.unknown(*UNK_LB)
    hollow(b)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    HD = ["RD", "SAD", "CAD", "SBD", "LBD", "NRD", "KTD", "GRD", "WCD"]
    PA = (6.8, 5.9, 0)        # corridor, west end, facing east
    PB = (25.5, 5.9, 180)     # corridor, east end, facing west
    PC = (3.0, 3.0, 90)       # reception, facing north (desk ahead)
    PD = (10.85, 7.8, 90)     # newsroom, the gap between desks 1 and 2 straight ahead
    PE = (14.5, 8.0, 180)     # newsroom, facing west
    PF = (21.35, 4.0, 270)    # record library, the 0.7 m aisle straight ahead
    PG = (17.0, 8.0, 0)       # kitchen, facing east (island ahead-left)
    PH = (22.0, 7.6, 90)      # green room, facing north (coffee table ahead)
    PI = (27.4, 5.9, 180)     # toilet, facing west (its door ahead)
    PJ = (17.1, 12.6, 0)      # server closet, facing east (its door behind)
    PK = (9.0, 3.5, 270)      # studio A, facing south (mixing table ahead)
    # door order in the corridor, with or without the reception door and the toilet door (on the axis)
    for doors in (HD, HD[1:-1]):
        assert nth(b, PA, doors, "right", 2) == "CAD" and nth(b, PA, doors, "right", 3) == "SBD"
        assert nth(b, PA, doors, "left", -1) == "GRD"
        assert nth(b, PB, doors, "left", 1) == "LBD" and nth(b, PB, doors, "right", 2) == "KTD"
        assert nth(b, PB, doors, "left", 6) is None
    # PC: the corridor door on the right; PE: the newsroom door the only one on the left
    assert rel(PC, 6.1, 5.9)[1] <= -0.3 and rel(PE, 9.0, 6.9)[1] >= 0.3 and rel(PE, 16.1, 12.6)[1] <= -0.3
    areas = {n: b.area(n) for n in sp if n != "HW"}
    assert max(areas, key=areas.get) == "NR" and sorted(areas.values())[-2] < areas["NR"] - 20
    assert min(areas, key=areas.get) == "SV" and sorted(areas.values())[1] - areas["SV"] > 3
    # PC: the nearest unexplored area is the street beyond the entrance
    assert frontier_dist(PC, (2.1, -0.4, 3.9, -0.2)) + 5 < min(frontier_dist(PC, UNK_LB), frontier_dist(PC, (26.2, 8.5, 26.4, 9.5)))
    # PC: the desk ahead; PD: the gap straight ahead; PH: the coffee table ahead; PK: the table ahead
    assert abs(rel(PC, 2.5, 5.8)[3]) < 15 and abs(rel(PD, 10.85, 9.6)[3]) < 2
    assert abs(rel(PH, 22.0, 8.5)[3]) < 2 and abs(rel(PK, 9.0, 2.7)[3]) < 2
    assert set(nearest_obstacles(PH, dict(GS=GS, GT=GT, KI=KI, KC=KC), 2)) == {"GS", "GT"}
    # PG: the island is the nearest obstacle on the left (the counter also left, farther)
    assert rel(PG, 18.1, 8.7)[1] > 0.3 and edge(KI, PG) + 1.0 < edge(KC, PG)
    assert abs(rel(PI, 26.1, 5.9)[3]) < 2 and abs(rel(PJ, 16.1, 12.6)[3]) > 170
    mid_nr = b.centroid("NR")
    ex_front = band(2.25, 0.15, 3.75, 0.85)
    lb_front = {"any": [band(23.85, 0.15, 24.75, 1.95), band(24.85, 2.05, 25.85, 2.95)]}
    aisle_s = within2((20.75, 0.15, 21.95, 0.85), 21.35, 1.0)
    gap_n = within2((10.6, 10.35, 11.1, 11.7), 10.85, 10.2)
    C = [
        ("A", PA, "go to the second door on your right", [ntp(D("CAD"), spaces=["HW", "CA", "door:CAD"])]),
        ("B", PA, "ok so through the third door on the right please", [ntp(through(b, "SBD", "SB"), spaces=["SB"], kind="through:SBD")]),
        ("C", PA, "head down to the last door on your left", [ntp(D("GRD"), spaces=["HW", "GR", "door:GRD"])]),
        ("D", PA, "take me to the vending machine", "clarify"),
        ("E", PB, "go to the first door on the left hand side", [ntp(D("LBD"), spaces=["HW", "LB", "door:LBD"])]),
        ("F", PB, "drive through the second door on your right", [ntp(through(b, "KTD", "KT"), spaces=["KT"], kind="through:KTD")]),
        ("G", PB, "go to the sixth door on your left", "clarify"),
        ("H", PB, "could you make your way to the largest room", [ntp(R("NR"), spaces=["NR"])]),
        ("I", PC, "go through the door to your right", [ntp(thr(b, "RD", "HW"), spaces=["HW"], kind="through:RD")]),
        ("J", PC, "move up next to the obstacle in front of you", [ntp(next_to_in(RDK, sp["RC"][0]), spaces=["RC"])]),
        ("A", PC, "go towards the closest unexplored area", [ntp(ex_front, spaces=["RC", "door:EX"], kind="frontier")]),
        ("B", PC, "go over to the left corner of the room", [ntp(side_corner(PC, sp["RC"][0], "left"), spaces=["RC"])]),
        ("C", PD, "squeeze through the narrow gap ahead", [ntp(gap_n, spaces=["NR"])]),
        ("D", PD, "now go to the right corner of this room", [ntp(side_corner(PD, sp["NR"][0], "right"), spaces=["NR"])]),
        ("E", PE, "go to the centre of this room", [ntp(circ(*mid_nr, MIDDLE), spaces=["NR"])]),
        ("F", PE, "head for the door on your left", [ntp(D("NRD"), spaces=["HW", "NR", "door:NRD"])]),
        ("G", PH, "go between the two nearest obstacles", [ntp(circ(*mid(GT, GS), BETWEEN), spaces=["GR"])]),
        ("H", PH, "go to the obstacle straight ahead of you", [ntp(next_to_in(GT, sp["GR"][0]), spaces=["GR"])]),
        ("I", PF, "go through the narrow passage in front of you", [ntp(aisle_s, spaces=["LB"])]),
        ("J", PF, "please go to the smallest room", [ntp(R("SV"), spaces=["SV"])]),
        ("A", PF, "head towards the unexplored part of this room", [ntp(lb_front, spaces=["LB"], kind="frontier")]),
        ("B", PG, "go next to the obstacle on your left", [ntp(next_to_in(KI, sp["KT"][0]), spaces=["KT"])]),
        ("C", PG, "turn to face south", [compass(b.pose(*PG)[2], 270)]),
        ("D", PI, "leave through the door and then turn right",
         [ntp(thr(b, "WCD", "HW"), spaces=["HW"], kind="through:WCD"), rot_deg(-90)]),
        ("E", PJ, "go back out through the door behind you", [ntp(thr(b, "SVD", "NR"), spaces=["NR"], kind="through:SVD")]),
        ("F", PK, "go near the obstacle in front of you", [ntp(next_to_in(SAT, sp["SA"][0]), spaces=["SA"])]),
        ("G", PK, "go to the nearest corner", [ntp(nearest_corner(PK, sp["SA"][0]), spaces=["SA"])]),
        ("H", PK, "go to the kitchen", "clarify"),
        ("I", PD, "go to the opposite side of this room", [ntp(opposite(b, "NR", PD, "+y"), spaces=["NR"])]),
        ("J", PE, "take me to the green room", "clarify"),
    ]
    assert side_corner(PC, sp["RC"][0], "left") == bld_geom_corner((0.0, 8.0), sp["RC"][0])
    assert side_corner(PD, sp["NR"][0], "right") == bld_geom_corner((16.0, 14.0), sp["NR"][0])
    assert nearest_corner(PK, sp["SA"][0]) == bld_geom_corner((11.0, 4.8), sp["SA"][0])
    return b, C


def bld_geom_corner(c, rect):
    from bld_geom import corner_reg
    return corner_reg(c, rect)


if __name__ == "__main__":
    b, C = radio()
    assert len(C) == 30
    bld_check.write([(b, "rad", i, spk, pose, prompt, exp) for i, (spk, pose, prompt, exp) in enumerate(C, 1)])
