#!/usr/bin/env python3
"""Draws a mosque -- NON-RECTANGULAR outline, ROTATED 27.3 deg with lidar-like noise (seed 9273) -- and writes
buildings.jsonl, 30 place-grounded prompts written from the bench contract (../shared/bench/README.md) before
langnav was run on them.  Every expected region is checked on the drawn map (bld_check.check) and an oracle
output built from the expectations is scored 1.0.

Layout (local frame, metres): an entrance lobby (shoe racks along the west wall, a free-standing bench) with
a 1.8 m entrance to the never-scanned street, a 0.9 m door north into the women's prayer room and a 1.2 m
door east into a 1.8 m corridor 17.8 m long.  North of the corridor the prayer hall (biggest, 15.8 x 11.8 m;
six free-standing pillars in two rows, a minbar against the north wall; a 1.6 m double door and a 0.9 m
side door from the corridor).  South of the corridor, west to east: the men's ablution room (a free-standing
ablution block, a bench on the west wall), the women's ablution room (a bench on the south wall), the
imam's office (desk, cabinet) and a toilet (smallest, 0.7 m door).  At the corridor's east end a 1.0 m door
into a library (two free-standing bookcases 0.75 m apart; its north-east corner never scanned).

Drawing / geometry / check helpers (bld_*.py, render.py) are copied from prompts-8g (themselves from the
blind rounds); helpers nth, room_cells, next_to, next_to_in, within2, mid, nearest_obstacles, frontier_dist,
hollow, thr, edge_d, ahead_of, opposite_far are copied from prompts-9/make_buildings.py.

Run from this folder: /work/main/.venv/bin/python make_mosque.py
"""
import math

import numpy as np

from bld_lib import (RES, MIDDLE, BETWEEN, OCC, UNK, Building, rel, circ, poly, ntp, rot_deg, compass)
from bld_geom import door_reg, room_reg, through, side_corner, nearest_corner, corner_reg, corners, band
import bld_check


# ------------------------------------------------------------------ helpers copied from prompts-9
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


def next_to(o):
    x0, y0, x1, y1 = o
    return {"any": [poly(x0, y1, x1, y1 + 1.0), poly(x0, y0 - 1.0, x1, y0),
                    poly(x0 - 1.0, y0, x0, y1), poly(x1, y0, x1 + 1.0, y1)]}


def next_to_in(o, room):
    """Within 1.0 m of the thing's edge (the contract), clipped to the room: the four strips beside its
    sides and, where they stay inside the room, the quarter discs off its corners (added after the first
    run: prompts-9's helper, copied at first, leaves the corners out, which the contract does not)."""
    X0, Y0, X1, Y1 = room
    out = []
    for s in next_to(o)["any"]:
        (x0, y0), (x1, y1) = s["polygon"][0], s["polygon"][2]
        x0, y0, x1, y1 = max(x0, X0), max(y0, Y0), min(x1, X1), min(y1, Y1)
        if x1 - x0 > 0.05 and y1 - y0 > 0.05:
            out.append(poly(x0, y0, x1, y1))
    for cx in (o[0], o[2]):
        for cy in (o[1], o[3]):
            if X0 <= cx - 1.0 and cx + 1.0 <= X1 and Y0 <= cy - 1.0 and cy + 1.0 <= Y1:
                out.append(circ(cx, cy, 0.99))
    return {"any": out}


def within2(box, cx, cy):
    x0, y0, x1, y1 = box
    for x in (x0, x1):
        for y in (y0, y1):
            assert math.hypot(x - cx, y - cy) <= 2.0 + 1e-9, (box, "beyond 2 m of", cx, cy)
    return poly(*box)


def mid(o1, o2):
    return ((o1[0] + o1[2] + o2[0] + o2[2]) / 4, (o1[1] + o1[3] + o2[1] + o2[3]) / 4)


def edge_d(o, p):
    return math.hypot(min(max(p[0], o[0]), o[2]) - p[0], min(max(p[1], o[1]), o[3]) - p[1])


def ahead_of(p, o):
    """Bearing (deg) of an obstacle's nearest cell from pose p."""
    x = min(max(p[0], o[0]), o[2]); y = min(max(p[1], o[1]), o[3])
    return rel(p, x, y)[3]


def nearest_obstacles(pose, obs, k):
    """The k obstacles nearest by nearest cell; the same k nearest by centre; the k-th clearly nearer
    than the (k+1)-th."""
    def cen(o):
        return math.hypot((o[0] + o[2]) / 2 - pose[0], (o[1] + o[3]) / 2 - pose[1])
    by_e = sorted(obs, key=lambda n: edge_d(obs[n], pose)); by_c = sorted(obs, key=lambda n: cen(obs[n]))
    assert set(by_e[:k]) == set(by_c[:k]), (by_e, by_c)
    assert edge_d(obs[by_e[k]], pose) - edge_d(obs[by_e[k - 1]], pose) > 1.0
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


def opposite_far(b, name, pose, step=0.5, min_area=4.0):
    """The contract's farthest third of a room from the robot: the room's step x step squares whose nearest
    point is at least the 2/3-quantile of the distances from the robot to the room's free cells."""
    xs, ys = room_cells(b, name)
    dstar = float(np.quantile(np.hypot(xs - pose[0], ys - pose[1]), 2 / 3))
    X0, Y0, X1, Y1 = b.spaces[name][0]
    polys, area = [], 0.0
    y = Y0
    while y < Y1 - 1e-9:
        ya, yb = y, min(y + step, Y1)
        run = None
        x = X0
        while x < X1 - 1e-9:
            xa, xb = x, min(x + step, X1)
            ok = edge_d((xa, ya, xb, yb), pose) >= dstar
            if ok and run is None:
                run = xa
            if not ok and run is not None:
                polys.append(poly(round(run, 3), round(ya, 3), round(xa, 3), round(yb, 3))); area += (xa - run) * (yb - ya); run = None
            x = xb
        if run is not None:
            polys.append(poly(round(run, 3), round(ya, 3), round(X1, 3), round(yb, 3))); area += (X1 - run) * (yb - ya)
        y = yb
    assert area >= min_area, (name, "opposite region too small", area)
    return {"any": polys}


def farthest_corner(pose, rect, gap=0.5):
    ds = sorted((math.hypot(cx - pose[0], cy - pose[1]), (cx, cy)) for cx, cy in corners(rect))
    assert ds[-1][0] - ds[-2][0] >= gap, ("corner tie", ds[-2:])
    return corner_reg(ds[-1][1], rect)


# ================================================================== mosque
def mosque():
    b = Building("mosque", -1.0, -5.0, 32.0, 17.0, theta=27.3, offset=(12.0, 2.0), seed=9273)
    b.shell(0.0, 0.0, 8.0, 6.0); b.shell(0.0, 6.2, 8.0, 14.0); b.shell(8.2, 2.2, 26.0, 4.0)
    b.shell(8.2, 4.2, 24.0, 16.0); b.shell(8.2, -4.0, 14.0, 2.0); b.shell(14.2, -4.0, 18.5, 2.0)
    b.shell(18.7, -4.0, 23.0, 2.0); b.shell(23.2, 0.0, 25.0, 2.0); b.shell(26.2, -2.0, 31.0, 8.0)
    b.space("EH", (0.0, 0.0, 8.0, 6.0))            # entrance lobby
    b.space("WP", (0.0, 6.2, 8.0, 14.0))           # women's prayer room
    b.space("HW", (8.2, 2.2, 26.0, 4.0))           # corridor, 1.8 m
    b.space("PH", (8.2, 4.2, 24.0, 16.0))          # prayer hall (biggest)
    b.space("AM", (8.2, -4.0, 14.0, 2.0))          # men's ablution room
    b.space("AW", (14.2, -4.0, 18.5, 2.0))         # women's ablution room
    b.space("IO", (18.7, -4.0, 23.0, 2.0))         # imam's office
    b.space("WC", (23.2, 0.0, 25.0, 2.0))          # toilet (smallest)
    b.space("LB", (26.2, -2.0, 31.0, 8.0))         # library (north-east corner never scanned)
    b.door("EX", 3.0, -0.1, "h", "EH", "OUT", width=1.8)     # entrance, street never scanned
    b.door("WPD", 4.0, 6.1, "h", "EH", "WP", width=0.9)
    b.door("EHD", 8.1, 3.1, "v", "EH", "HW", width=1.2)
    b.door("PHD", 12.0, 4.1, "h", "HW", "PH", width=1.6)     # double door
    b.door("PHD2", 21.0, 4.1, "h", "HW", "PH", width=0.9)    # side door
    b.door("AMD", 10.0, 2.1, "h", "HW", "AM", width=0.9)
    b.door("AWD", 16.0, 2.1, "h", "HW", "AW", width=0.9)
    b.door("IOD", 20.0, 2.1, "h", "HW", "IO", width=0.9)
    b.door("WCD", 24.2, 2.1, "h", "HW", "WC", width=0.7)
    b.door("LBD", 26.1, 3.1, "v", "HW", "LB", width=1.0)
    b.carve()
    SR = (0.0, 1.0, 0.5, 5.0)                      # shoe racks on the lobby's west wall
    BE = (2.5, 3.5, 4.5, 4.0)                      # lobby bench, free-standing
    WCB = (0.0, 8.0, 0.5, 11.0)                    # cabinet in the women's prayer room
    P1, P2, P3 = (12.0, 9.0, 12.5, 9.5), (16.0, 9.0, 16.5, 9.5), (20.0, 9.0, 20.5, 9.5)
    P4, P5, P6 = (12.0, 12.5, 12.5, 13.0), (16.0, 12.5, 16.5, 13.0), (20.0, 12.5, 20.5, 13.0)
    MB = (14.0, 14.8, 15.2, 16.0)                  # minbar against the north wall
    AB = (9.5, -2.0, 12.5, -1.2)                   # ablution block, free-standing
    AMB = (8.2, -3.0, 8.7, 1.0)                    # bench on the ablution room's west wall
    AWB = (14.8, -4.0, 17.8, -3.5)                 # bench on the women's ablution room's south wall
    DK = (19.8, -2.5, 21.8, -1.7)                  # imam's desk
    CB = (18.7, -3.8, 19.3, -2.6)                  # cabinet in the office's south-west corner
    S1, S2 = (27.5, 1.0, 28.0, 5.0), (28.75, 1.0, 29.25, 5.0)   # bookcases: a 0.75 m aisle
    for o in (SR, BE, WCB, P1, P2, P3, P4, P5, P6, MB, AB, AMB, AWB, DK, CB, S1, S2):
        b.rect(*o, OCC)
    UNK_LB = (29.8, 6.5, 31.0, 8.0)
    b.unknown(*UNK_LB)
    hollow(b)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    HD = ["EHD", "PHD", "PHD2", "AMD", "AWD", "IOD", "WCD", "LBD"]
    MA = (9.0, 3.1, 0)        # corridor, west end, facing east
    MB_ = (25.3, 3.1, 180)    # corridor, east end, facing west
    MC = (4.0, 2.0, 90)       # lobby, facing north (women's prayer room door ahead)
    MD = (12.0, 6.0, 90)      # prayer hall just inside the double door, facing north
    MP = (14.0, 7.5, 90)      # prayer hall, between the first two pillars' row and the door
    MQ = (12.0, 5.0, 90)      # prayer hall at the double door, facing north
    MR = (20.0, 6.0, 180)     # prayer hall, south-east, facing west
    MS = (22.0, 8.0, 90)      # prayer hall, east, facing north (pillar 3 ahead-left)
    ME = (11.8, -3.0, 0)      # men's ablution room, facing east (ablution block on the left)
    MF = (28.375, 6.5, 270)   # library, facing south, the bookcase aisle straight ahead
    MG = (27.0, -1.0, 90)     # library, south-west, facing north
    MH = (4.0, 7.0, 90)       # women's prayer room, facing north
    MT = (24.1, 0.8, 90)      # toilet, facing north (its door ahead)
    MU = (21.0, 0.8, 270)     # imam's office, facing south (desk ahead)
    # door order in the corridor, with or without the doors on its axis (lobby, library)
    for doors in (HD, HD[1:-1]):
        assert nth(b, MA, doors, "right", 3) == "IOD" and nth(b, MA, doors, "right", -1) == "WCD"
        assert nth(b, MA, doors, "left", 2) == "PHD2" and nth(b, MA, doors, "left", 4) is None
        assert nth(b, MB_, doors, "left", 1) == "WCD" and nth(b, MB_, doors, "left", 2) == "IOD"
        assert nth(b, MB_, doors, "right", 1) == "PHD2"
    # MC: the women's prayer room door straight ahead; MD: the double door straight behind; MT: toilet door ahead
    assert abs(rel(MC, 4.0, 6.1)[3]) < 2 and abs(rel(MD, 12.0, 4.1)[3]) > 178 and abs(rel(MT, 24.2, 2.1)[3]) < 5
    # MD: the side door is to the right, not behind
    assert abs(rel(MD, 21.0, 4.1)[3]) < 120
    areas = {n: b.area(n) for n in sp if n != "HW"}
    assert max(areas, key=areas.get) == "PH" and sorted(areas.values())[-2] < areas["PH"] - 50
    assert min(areas, key=areas.get) == "WC" and sorted(areas.values())[1] - areas["WC"] > 10
    # MC: the nearest unexplored area is the street beyond the entrance (the library's dark corner far)
    assert frontier_dist(MC, (2.1, -0.4, 3.9, -0.2)) + 10 < frontier_dist(MC, UNK_LB)
    # MG: the library's dark corner is the nearest unexplored area (the street is beyond the lobby)
    assert frontier_dist(MG, UNK_LB) + 10 < frontier_dist(MG, (2.1, -0.4, 3.9, -0.2))
    # MP: the two nearest obstacles are the first two pillars
    PIL = dict(P1=P1, P2=P2, P3=P3, P4=P4, P5=P5, P6=P6, MB=MB)
    assert set(nearest_obstacles(MP, PIL, 2)) == {"P1", "P2"}
    # ME: the ablution block is on the left, the only obstacle there; MU: the desk straight ahead
    assert rel(ME, 11.8, -2.0)[1] >= 0.9 and rel(ME, 8.7, -3.0)[0] < -2.5
    assert abs(ahead_of(MU, DK)) < 5 and edge_d(DK, MU) + 1.0 < edge_d(CB, MU)
    # MS: pillar 3 is the nearest obstacle on the left, clearly nearer than pillar 6
    assert rel(MS, 20.5, 9.0)[1] > 1.0 and edge_d(P3, MS) + 2.0 < edge_d(P6, MS)
    assert all(rel(MS, *c)[1] < 0 or edge_d(o, MS) > edge_d(P3, MS) + 2.0
               for o in (P1, P2, P4, P5, MB) for c in [((o[0] + o[2]) / 2, (o[1] + o[3]) / 2)])
    # MF: the aisle straight ahead
    assert abs(rel(MF, 28.375, 5.0)[3]) < 1
    mid_ph = b.centroid("PH")
    ex_front = band(2.25, 0.15, 3.75, 0.85)
    lb_front = {"any": [band(28.85, 6.55, 29.75, 7.95), band(29.85, 5.55, 30.95, 6.45)]}
    aisle_s = within2((27.75, -0.4, 29.0, 0.85), 28.375, 1.0)
    C = [
        ("A", MA, "go to the third door on your right", [ntp(D("IOD"), spaces=["HW", "IO", "door:IOD"])]),
        ("B", MA, "go through the second door on the left", [ntp(thr(b, "PHD2", "PH"), spaces=["PH"], kind="through:PHD2")]),
        ("C", MA, "head for the last door on your right", [ntp(D("WCD"), spaces=["HW", "WC", "door:WCD"])]),
        ("D", MA, "take the fourth door on your left", "clarify"),
        ("E", MB_, "first door on your left please", [ntp(D("WCD"), spaces=["HW", "WC", "door:WCD"])]),
        ("F", MB_, "go through the second door on the left", [ntp(thr(b, "IOD", "IO"), spaces=["IO"], kind="through:IOD")]),
        ("G", MC, "go through the door in front of you", [ntp(thr(b, "WPD", "WP"), spaces=["WP"], kind="through:WPD")]),
        ("H", MC, "make your way to the nearest unexplored area", [ntp(ex_front, spaces=["EH", "door:EX"], kind="frontier")]),
        ("I", MC, "go to the largest room", [ntp(R("PH"), spaces=["PH"])]),
        ("J", MC, "please go to the smallest room", [ntp(R("WC"), spaces=["WC"])]),
        ("A", MD, "go to the left corner of this room", [ntp(side_corner(MD, sp["PH"][0], "left"), spaces=["PH"])]),
        ("B", MD, "go over to the right corner", [ntp(side_corner(MD, sp["PH"][0], "right"), spaces=["PH"])]),
        ("C", MP, "go halfway between the two nearest obstacles", [ntp(circ(*mid(P1, P2), BETWEEN), spaces=["PH"])]),
        ("D", MQ, "go to the opposite side of this room", [ntp(opposite_far(b, "PH", MQ), spaces=["PH"])]),
        ("E", MR, "go to the middle of this room", [ntp(circ(*mid_ph, MIDDLE), spaces=["PH"])]),
        ("F", ME, "go near the obstacle on your left side", [ntp(next_to_in(AB, sp["AM"][0]), spaces=["AM"])]),
        ("G", ME, "go to the nearest corner", [ntp(nearest_corner(ME, sp["AM"][0]), spaces=["AM"])]),
        ("H", MF, "squeeze through the narrow gap in front of you", [ntp(aisle_s, spaces=["LB"])]),
        ("I", MF, "head towards the unexplored part of this room", [ntp(lb_front, spaces=["LB"], kind="frontier")]),
        ("J", MT, "go out the door in front and then turn left",
         [ntp(thr(b, "WCD", "HW"), spaces=["HW"], kind="through:WCD"), rot_deg(90)]),
        ("A", MU, "go next to the obstacle ahead of you", [ntp(next_to_in(DK, sp["IO"][0]), spaces=["IO"])]),
        ("B", MU, "turn to face west", [compass(b.pose(*MU)[2], 180)]),
        ("C", MH, "go into the right corner of this room", [ntp(side_corner(MH, sp["WP"][0], "right"), spaces=["WP"])]),
        ("D", MH, "go to the mihrab", "clarify"),
        ("E", MQ, "take me to the ablution room", "clarify"),
        ("F", MD, "go back through the door behind you", [ntp(thr(b, "PHD", "HW"), spaces=["HW"], kind="through:PHD")]),
        ("G", MS, "go to the obstacle on your left", [ntp(next_to_in(P3, sp["PH"][0]), spaces=["PH"])]),
        ("H", MG, "drive towards the closest unexplored area", [ntp(lb_front, spaces=["LB"], kind="frontier")]),
        ("I", MB_, "go through the first door on your right", [ntp(thr(b, "PHD2", "PH"), spaces=["PH"], kind="through:PHD2")]),
        ("J", MQ, "go to the farthest corner of this room", [ntp(farthest_corner(MQ, sp["PH"][0]), spaces=["PH"])]),
    ]
    assert side_corner(MD, sp["PH"][0], "left") == corner_reg((8.2, 16.0), sp["PH"][0])
    assert side_corner(MD, sp["PH"][0], "right") == corner_reg((24.0, 16.0), sp["PH"][0])
    assert side_corner(MH, sp["WP"][0], "right") == corner_reg((8.0, 14.0), sp["WP"][0])
    assert nearest_corner(ME, sp["AM"][0]) == corner_reg((14.0, -4.0), sp["AM"][0])
    assert farthest_corner(MQ, sp["PH"][0]) == corner_reg((24.0, 16.0), sp["PH"][0])
    return b, C


if __name__ == "__main__":
    b, C = mosque()
    assert len(C) == 30
    for s in "ABCDEFGHIJ":
        assert sum(1 for c in C if c[0] == s) == 3, s
    bld_check.write([(b, "mos", i, spk, pose, prompt, exp) for i, (spk, pose, prompt, exp) in enumerate(C, 1)])
