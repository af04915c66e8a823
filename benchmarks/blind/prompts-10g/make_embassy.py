#!/usr/bin/env python3
"""Draws an embassy's consular wing -- NON-RECTANGULAR stepped outline, ROTATED -58.7 deg with lidar-like
noise (seed 10587) -- and writes buildings.jsonl, 30 place-grounded prompts written from the bench contract
(../shared/bench/README.md) before langnav was run on them and before the grounding code was read.  Every
expected region is checked on the drawn map (bld_check.check) and an oracle output built from the
expectations is scored 1.0.

Layout (local frame, metres): a security lobby (an x-ray machine free-standing) with a 1.6 m entrance in its
west wall to the never-scanned street and a 1.4 m door east into the waiting hall (biggest, 9.8 x 11 m; three
rows of 5 m benches 1.5 m apart, a counter along the east wall, a plant).  North of the waiting hall, through
a 1.0 m door, a 1.8 m corridor 19.8 m long running east.  North of the corridor, west to east: two offices,
the visa interview room (1.6 m double door; a table) and an archive (two shelves 0.7 m apart).  South of the
corridor, west to east: the waiting hall's door, the consul's office (desk, cabinet), a server room and a
toilet (smallest, 0.7 m door).  At the corridor's east end a 1.2 m door into a reception hall (a piano and a
sofa free-standing; its north-east corner never scanned).

Drawing / geometry / check helpers (bld_*.py, render.py) are copied from prompts-9g (ids g10-); the helpers
below are copied from prompts-9g/make_mosque.py.

Run from this folder: /work/main/.venv/bin/python make_embassy.py
"""
import math

import numpy as np

from bld_lib import (RES, MIDDLE, BETWEEN, OCC, UNK, Building, rel, circ, poly, ntp, rot_deg, face, compass)
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


# ================================================================== embassy
def embassy():
    b = Building("embassy", -1.0, -4.0, 34.5, 17.0, theta=-58.7, offset=(3.0, 30.0), seed=10587)
    b.shell(0.0, 0.0, 7.0, 5.0); b.shell(7.2, -3.0, 17.0, 8.0); b.shell(7.2, 8.2, 27.0, 10.0)
    b.shell(7.2, 10.2, 11.0, 14.0); b.shell(11.2, 10.2, 15.0, 14.0); b.shell(15.2, 10.2, 21.0, 16.0)
    b.shell(21.2, 10.2, 25.5, 14.5); b.shell(17.2, 3.0, 22.0, 8.0); b.shell(22.2, 5.5, 24.5, 8.0)
    b.shell(24.7, 6.2, 26.0, 8.0); b.shell(27.2, 4.0, 33.0, 14.0)
    b.space("SL", (0.0, 0.0, 7.0, 5.0))            # security lobby
    b.space("WH", (7.2, -3.0, 17.0, 8.0))          # waiting hall (biggest)
    b.space("HW", (7.2, 8.2, 27.0, 10.0))          # corridor, 1.8 m
    b.space("O1", (7.2, 10.2, 11.0, 14.0))         # office 1
    b.space("O2", (11.2, 10.2, 15.0, 14.0))        # office 2
    b.space("VI", (15.2, 10.2, 21.0, 16.0))        # visa interview room
    b.space("AR", (21.2, 10.2, 25.5, 14.5))        # archive
    b.space("CO", (17.2, 3.0, 22.0, 8.0))          # consul's office
    b.space("SR", (22.2, 5.5, 24.5, 8.0))          # server room
    b.space("WC", (24.7, 6.2, 26.0, 8.0))          # toilet (smallest)
    b.space("RH", (27.2, 4.0, 33.0, 14.0))         # reception hall (north-east corner never scanned)
    b.door("EX", -0.1, 2.5, "v", "SL", "OUT", width=1.6)     # entrance, street never scanned
    b.door("SLD", 7.1, 2.5, "v", "SL", "WH", width=1.4)
    b.door("WHD", 10.0, 8.1, "h", "WH", "HW", width=1.0)
    b.door("O1D", 9.0, 10.1, "h", "HW", "O1", width=0.9)
    b.door("O2D", 13.0, 10.1, "h", "HW", "O2", width=0.9)
    b.door("VID", 17.0, 10.1, "h", "HW", "VI", width=1.6)    # double door
    b.door("ARD", 22.85, 10.1, "h", "HW", "AR", width=0.9)
    b.door("COD", 19.0, 8.1, "h", "HW", "CO", width=0.9)
    b.door("SRD", 23.3, 8.1, "h", "HW", "SR", width=0.8)
    b.door("WCD", 25.3, 8.1, "h", "HW", "WC", width=0.7)
    b.door("RHD", 27.1, 9.1, "v", "HW", "RH", width=1.2)
    b.carve()
    XR = (2.5, 1.0, 4.5, 1.8)                      # x-ray machine, free-standing
    B1, B2, B3 = (9.0, 0.0, 14.0, 0.5), (9.0, 2.0, 14.0, 2.5), (9.0, 4.0, 14.0, 4.5)   # bench rows
    CT = (16.4, -1.5, 17.0, 5.5)                   # counter along the waiting hall's east wall
    PL = (15.0, 6.5, 15.6, 7.1)                    # plant
    TB = (17.0, 12.5, 19.0, 13.3)                  # interview table
    S1, S2 = (22.0, 11.2, 22.5, 13.0), (23.2, 11.2, 23.7, 13.0)   # archive shelves: a 0.7 m aisle
    DK = (19.0, 5.0, 20.6, 5.8)                    # consul's desk
    CB = (21.4, 3.0, 22.0, 4.0)                    # cabinet in the office's south-east corner
    PN = (29.5, 9.0, 31.0, 10.5)                   # piano
    SF = (28.5, 5.0, 30.5, 5.8)                    # sofa, free-standing
    OBS = dict(XR=XR, B1=B1, B2=B2, B3=B3, CT=CT, PL=PL, TB=TB, S1=S1, S2=S2, DK=DK, CB=CB, PN=PN, SF=SF)
    for o in OBS.values():
        b.rect(*o, OCC)
    UNK_RH = (31.5, 12.5, 33.0, 14.0)
    b.unknown(*UNK_RH)
    hollow(b)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    HD = ["WHD", "O1D", "O2D", "VID", "ARD", "COD", "SRD", "WCD", "RHD"]
    MA = (7.8, 9.1, 0)        # corridor, west end, facing east
    MB = (26.5, 9.1, 180)     # corridor, east end, facing west
    MC = (1.0, 2.5, 0)        # security lobby, just in from the street, facing east
    MD = (7.8, 2.5, 0)        # waiting hall, just inside the lobby door, facing east
    MP = (8.0, 3.25, 0)       # waiting hall, in the aisle between the 2nd and 3rd bench rows, facing east
    ME = (19.0, 7.2, 270)     # consul's office, just inside its door, facing south (desk ahead)
    MX = (19.0, 7.4, 90)      # consul's office at its door, facing north (the corridor ahead)
    MT = (25.3, 6.9, 90)      # toilet, facing north (its door ahead)
    MF = (22.85, 10.7, 90)    # archive, just inside, facing north, the shelf aisle straight ahead
    MG = (27.8, 9.1, 0)       # reception hall, just inside its door, facing east
    # door order in the corridor (all its doors; the reception hall door lies on its axis)
    assert nth(b, MA, HD, "right", 3) == "SRD" and nth(b, MA, HD, "right", -1) == "WCD"
    assert nth(b, MA, HD, "left", 2) == "O2D" and nth(b, MA, HD, "left", 5) is None
    assert nth(b, MB, HD, "left", 1) == "WCD" and nth(b, MB, HD, "right", 2) == "VID"
    # doors straight ahead / behind
    assert abs(rel(MC, 7.1, 2.5)[3]) < 1 and abs(rel(MG, 27.1, 9.1)[3]) > 179 and abs(rel(MT, 25.3, 8.1)[3]) < 1
    # MD: the corridor door on the left (the only door there; the lobby door straight behind)
    assert rel(MD, 10.0, 8.1)[1] > 5 and abs(rel(MD, 7.1, 2.5)[3]) > 179
    areas = {n: b.area(n) for n in sp if n != "HW"}
    assert max(areas, key=areas.get) == "WH" and sorted(areas.values())[-2] < areas["WH"] - 40
    assert min(areas, key=areas.get) == "WC" and sorted(areas.values())[1] - areas["WC"] > 3
    # MC: the nearest unexplored area is the street behind (the reception hall's dark corner far away)
    assert frontier_dist(MC, (-0.4, 1.7, -0.2, 3.3)) + 20 < frontier_dist(MC, UNK_RH)
    # MC: the x-ray machine is on the right, the only obstacle in the lobby
    assert rel(MC, 3.5, 1.4)[1] < -1.0 and rel(MC, 2.5, 1.8)[1] < -0.6
    # MP: the two nearest obstacles are the 2nd and 3rd bench rows
    assert set(nearest_obstacles(MP, OBS, 2)) == {"B2", "B3"}
    # ME: the desk is the nearest obstacle ahead (the cabinet ahead too, farther)
    assert abs(ahead_of(ME, DK)) < 1 and edge_d(DK, ME) + 2.0 < edge_d(CB, ME)
    # MG: the sofa on the right, the only obstacle there; the piano straight ahead
    assert rel(MG, 28.5, 5.8)[1] < -3 and rel(MG, 30.25, 9.75)[1] > 0
    # MF: the shelf aisle straight ahead
    assert abs(rel(MF, 22.85, 12.0)[3]) < 1
    # WC's neighbours sharing a wall: only the server room (the reception hall lies 1.2 m beyond its east wall)
    mid_wh = b.centroid("WH")
    ex_front = band(0.1, 1.8, 0.75, 3.2)
    rh_front = {"any": [band(30.6, 12.55, 31.45, 13.95), band(31.55, 11.6, 32.95, 12.45)]}
    aisle_n = within2((22.1, 13.05, 23.6, 14.5), 22.85, 13.0)
    start_e = circ(ME[0], ME[1], 0.75)
    C = [
        ("A", MA, "go to the third door on your right", [ntp(D("SRD"), spaces=["HW", "SR", "door:SRD"])]),
        ("B", MA, "could you go thru the second door on the left", [ntp(thr(b, "O2D", "O2"), spaces=["O2"], kind="through:O2D")]),
        ("C", MA, "head down to the last door on the right hand side", [ntp(D("WCD"), spaces=["HW", "WC", "door:WCD"])]),
        ("D", MA, "fifth door on your left", "clarify"),
        ("E", MA, "go halfway down the corridor", [ntp(band(16.35, 8.2, 18.15, 10.0), spaces=["HW"])]),
        ("F", MA, "go 2 metres past the second door on your left", [ntp(band(14.5, 8.2, 15.5, 10.0), spaces=["HW"])]),
        ("G", MA, "stop a metre before the last door on your right", [ntp(band(23.8, 8.2, 24.8, 10.0), spaces=["HW"])]),
        ("H", MB, "first door on your left please", [ntp(D("WCD"), spaces=["HW", "WC", "door:WCD"])]),
        ("I", MB, "take the second door on your right",
         {"any": [[ntp(D("VID"), spaces=["HW", "VI", "door:VID"])],
                  [ntp(thr(b, "VID", "VI"), spaces=["VI"], kind="through:VID")]]}),
        ("J", MX, "go into the room across the hall", [ntp(R("VI"), spaces=["VI"])]),
        ("A", MC, "go to the door straight ahead", [ntp(D("SLD"), spaces=["SL", "WH", "door:SLD"])]),
        ("B", MC, "go over to the x-ray machine", "clarify"),
        ("C", MC, "go and wait next to the obstacle on your right", [ntp(next_to_in(XR, sp["SL"][0]), spaces=["SL"])]),
        ("D", MC, "make your way to the nearest unexplored area", [ntp(ex_front, spaces=["SL", "door:EX"], kind="frontier")]),
        ("E", MC, "go to the biggest room", [ntp(R("WH"), spaces=["WH"])]),
        ("F", MC, "please take me to the smallest room", [ntp(R("WC"), spaces=["WC"])]),
        ("G", MD, "go to the far right corner of this room", [ntp(side_corner(MD, sp["WH"][0], "right"), spaces=["WH"])]),
        ("H", MD, "go to the centre of the room", [ntp(circ(*mid_wh, MIDDLE), spaces=["WH"])]),
        ("I", MD, "go across to the opposite side of this room", [ntp(opposite_far(b, "WH", MD), spaces=["WH"])]),
        ("J", MD, "turn to face the door on your left", [face(MD, 10.0, 8.1)]),
        ("A", MP, "drive between the two closest obstacles", [ntp(circ(*mid(B2, B3), BETWEEN), spaces=["WH"])]),
        ("B", ME, "go to the obstacle in front of you", [ntp(next_to_in(DK, sp["CO"][0]), spaces=["CO"])]),
        ("C", ME, "go to the nearest corner and then come back here",
         [ntp(start_e, via=[nearest_corner(ME, sp["CO"][0])], spaces=["CO"], via_spaces=["CO"])]),
        ("D", MT, "go to the room next to this one", [ntp(R("SR"), spaces=["SR"])]),
        ("E", MT, "go out the door in front of you and turn right",
         [ntp(thr(b, "WCD", "HW"), spaces=["HW"], kind="through:WCD"), rot_deg(-90)]),
        ("F", MF, "squeeze through the narrow gap ahead", [ntp(aisle_n, spaces=["AR"])]),
        ("G", MF, "go to the left corner of this room", [ntp(side_corner(MF, sp["AR"][0], "left"), spaces=["AR"])]),
        ("H", MG, "head towards the unexplored part of this room", [ntp(rh_front, spaces=["RH"], kind="frontier")]),
        ("I", MG, "go next to the obstacle on your right", [ntp(next_to_in(SF, sp["RH"][0]), spaces=["RH"])]),
        ("J", MG, "go back through the door behind you", [ntp(thr(b, "RHD", "HW"), spaces=["HW"], kind="through:RHD")]),
    ]
    assert side_corner(MD, sp["WH"][0], "right") == corner_reg((17.0, -3.0), sp["WH"][0])
    assert side_corner(MF, sp["AR"][0], "left") == corner_reg((21.2, 14.5), sp["AR"][0])
    assert nearest_corner(ME, sp["CO"][0]) == corner_reg((17.2, 8.0), sp["CO"][0])
    return b, C


if __name__ == "__main__":
    b, C = embassy()
    assert len(C) == 30
    for s in "ABCDEFGHIJ":
        assert sum(1 for c in C if c[0] == s) == 3, s
    bld_check.write([(b, "emb", i, spk, pose, prompt, exp) for i, (spk, pose, prompt, exp) in enumerate(C, 1)])
