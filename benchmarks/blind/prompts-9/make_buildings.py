#!/usr/bin/env python3
"""Draws three new buildings -- a recording studio (axis-aligned, L-SHAPED outline: a lobby behind a GLASS
front, a corridor with two vocal booths, a machine room, a kitchenette and a toilet; a control room with a
mixing desk and a GLASS window onto the live room; a live room with a piano, a drum riser and two rows of
acoustic screens with a 0.7 m gap; a tape archive whose back was never scanned; a back door to the
never-scanned loading yard), a car dealership (ROTATED 21.7 deg with lidar-like noise, fixed seed;
NON-RECTANGULAR outline: a showroom behind a GLASS front with four display cars, two of them 0.8 m apart, a
reception desk; two sales offices and a customer lounge off it; a service bay reached by a 3 m car door and a
0.9 m people door, with an OPEN 3.5 m roller door to the never-scanned yard, two cars on lifts; a parts store
whose back is dark; a toilet) and a ski lodge (ROTATED -34.6 deg with noise; NON-RECTANGULAR stepped
outline: a boot room with the entrance, a ski-rental shop with a counter and two ski racks 0.7 m apart, a
great hall with a GLASS front onto the never-scanned terrace, a fireplace, a sofa and four tables; a drying
room whose back was never scanned, a kitchen, a first-aid room, toilets) -- and writes buildings.jsonl,
30 cases each.  Every expected region is checked on the drawn map (bld_check.check) and an oracle output
built from the expectations is scored.  Drawing / geometry / check helpers (bld_*.py) and the helpers nth,
room_cells, opposite, next_to, within2, mid, nearest_obstacles, frontier_dist, hollow, glass_gaps, thr,
next_to_in are copied from the eighth blind set; glass_gaps_v (a glass wall in a vertical wall line) is new;
the buildings and prompts are new.

Run: /work/main/.venv/bin/python make_buildings.py
"""
import math

import numpy as np

from bld_lib import (RES, OCC, FREE, UNK, AT_DOOR, MIDDLE, BETWEEN, Building, rel, circ, poly, ntp, rot,
                     rot_deg, face, move, compass, safe_move, STOP)
from bld_geom import door_reg, room_reg, through, corner_reg, side_corner, nearest_corner, band
import bld_check


# ------------------------------------------------------------------ helpers copied from the sixth set
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


def frontier_ok(b, name, region_local):
    return region_local



def nearest_obstacles(pose, obs, k):
    """Names of the k obstacles nearest to the robot by nearest cell (edge); asserts the k-th is clearly
    nearer than the (k+1)-th, and that the same k are nearest by centre."""
    def edge(o):
        x = min(max(pose[0], o[0]), o[2]); y = min(max(pose[1], o[1]), o[3])
        return math.hypot(x - pose[0], y - pose[1])
    def cen(o):
        return math.hypot((o[0] + o[2]) / 2 - pose[0], (o[1] + o[3]) / 2 - pose[1])
    by_e = sorted(obs, key=lambda n: edge(obs[n])); by_c = sorted(obs, key=lambda n: cen(obs[n]))
    assert set(by_e[:k]) == set(by_c[:k]), (by_e, by_c)
    assert edge(obs[by_e[k]]) - edge(obs[by_e[k - 1]]) > 1.0
    return by_e[:k]


def frontier_dist(pose, rect):
    """Straight-line distance from the robot to the nearest point of an unknown rectangle."""
    x = min(max(pose[0], rect[0]), rect[2]); y = min(max(pose[1], rect[1]), rect[3])
    return math.hypot(x - pose[0], y - pose[1])



def hollow(b, ring=3):
    """A lidar sees only the faces of solid things: the inside of a thick wall block or a big obstacle (an
    engine, a table top, a shelf block) is never observed.  Occupied cells more than `ring` cells from any
    non-occupied cell become unknown (enclosed by the occupied ring, so they border no free space and are
    not unexplored areas in the contract's sense)."""
    from scipy import ndimage
    d = ndimage.distance_transform_edt(b.g == OCC)
    b.g[d > ring] = UNK


def glass_gaps(b, x0, x1, y, step=1.5, gap=0.2):
    """A glass wall seen by a lidar: the wall line (horizontal, at y .. y+0.2) returns only in stretches;
    every `step` m a `gap` m stretch gave no return, so the never-scanned outside shows through it.
    Returns the gap x ranges (local)."""
    gaps = []
    gx = x0 + step
    while gx + gap <= x1:
        b.rect(gx, y, gx + gap, y + 0.2, UNK)
        gaps.append((gx, gx + gap))
        gx += step
    return gaps




def thr(b, n, into, **kw):
    """through() with the edge on the door's wall pulled 0.1 m away from the door (after rotation and noise
    the cells at the wall line can fall inside the door opening, which is not yet past it)."""
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


def next_to_in(o, room):
    """next_to(o) with every strip clipped to the room rectangle (so it never reaches through a wall)."""
    X0, Y0, X1, Y1 = room
    out = []
    for s in next_to(o)["any"]:
        (x0, y0), (x1, y1) = s["polygon"][0], s["polygon"][2]
        x0, y0, x1, y1 = max(x0, X0), max(y0, Y0), min(x1, X1), min(y1, Y1)
        if x1 - x0 > 0.05 and y1 - y0 > 0.05:
            out.append(poly(x0, y0, x1, y1))
    return {"any": out}


def glass_gaps_v(b, x, y0, y1, step=0.8, gap=0.15):
    """A glass pane in a vertical wall line (x .. x+0.2) between two scanned rooms: the lidar got a return
    only in stretches; every `step` m a `gap` m stretch stayed unknown (under 20 cells each: noise specks,
    not unexplored areas).  Returns the gap y ranges (local)."""
    gaps = []
    gy = y0 + step
    while gy + gap <= y1:
        b.rect(x, gy, x + 0.2, gy + gap, UNK)
        gaps.append((gy, gy + gap))
        gy += step
    return gaps


def opposite_far(b, name, pose, step=0.5, min_area=4.0):
    """'the opposite side of the room' as the contract words it: the third of the room farthest from the robot.
    dstar = the 2/3-quantile of the distances from the robot to the room's free cells; the region is the union
    of the room's step x step squares (clipped to the room) whose nearest point is at least dstar away, merged
    into runs per row (so every point of it is in the farthest third).  New in this set (the eighth set's
    opposite() needs the robot near the middle of the opposite wall)."""
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
    m = np.zeros(len(xs), bool)
    for p in polys:
        (a, c), (d, e) = p["polygon"][0], p["polygon"][2]
        m |= (xs >= a) & (xs <= d) & (ys >= c) & (ys <= e)
    assert np.hypot(xs[m] - pose[0], ys[m] - pose[1]).min() >= dstar - 1e-9
    return {"any": polys}


def edge_d(o, p):
    return math.hypot(min(max(p[0], o[0]), o[2]) - p[0], min(max(p[1], o[1]), o[3]) - p[1])


def ahead_of(p, o):
    """Bearing (deg) of an obstacle's nearest cell from pose p."""
    x = min(max(p[0], o[0]), o[2]); y = min(max(p[1], o[1]), o[3])
    return rel(p, x, y)[3]


# ================================================================== recording studio: L-shaped outline, axis-aligned
def studio():
    b = Building("studio", -1.0, -1.0, 26.0, 14.0)
    b.shell(0.0, 0.0, 7.0, 6.0); b.shell(7.2, 0.0, 25.0, 13.0)
    b.space("LB", (0.0, 0.0, 7.0, 6.0))            # lobby, glass front to the south
    b.space("HW", (7.2, 2.0, 25.0, 3.8))           # corridor, 1.8 m
    b.space("VB1", (7.2, 0.0, 9.8, 1.8)); b.space("VB2", (10.0, 0.0, 13.0, 1.8))   # vocal booths
    b.space("MR", (13.2, 0.0, 16.4, 1.8))          # machine room
    b.space("KT", (16.6, 0.0, 23.0, 1.8))          # kitchenette
    b.space("WC", (23.2, 0.0, 25.0, 1.8))          # toilet (smallest)
    b.space("CR", (7.2, 4.0, 13.0, 10.0))          # control room
    b.space("AR", (7.2, 10.2, 13.0, 13.0))         # tape archive (back part not scanned)
    b.space("LR", (13.2, 4.0, 25.0, 13.0))         # live room (biggest)
    b.door("EX", 3.5, -0.1, "h", "LB", "OUT", width=1.2)     # front door, street never scanned
    b.door("LD", 7.1, 2.9, "v", "LB", "HW", width=1.0)
    b.door("VB1", 8.5, 1.9, "h", "HW", "VB1", width=0.8)
    b.door("VB2", 11.5, 1.9, "h", "HW", "VB2", width=0.8)
    b.door("MR", 14.8, 1.9, "h", "HW", "MR", width=0.7)
    b.door("KT", 19.0, 1.9, "h", "HW", "KT", width=0.9)
    b.door("WC", 24.1, 1.9, "h", "HW", "WC", width=0.7)
    b.door("CRD", 9.5, 3.9, "h", "HW", "CR", width=0.9)
    b.door("LRD", 16.5, 3.9, "h", "HW", "LR", width=1.4)     # double door (load-in)
    b.door("CLD", 13.1, 5.0, "v", "CR", "LR", width=0.8)     # control room <-> live room
    b.door("ARD", 9.0, 10.1, "h", "CR", "AR", width=0.8)
    b.door("BK", 25.1, 2.9, "v", "HW", "OUT", width=1.0)     # back door to the loading yard, never scanned
    b.carve()
    gaps = glass_gaps(b, 0.0, 2.8, -0.2, step=0.9) + glass_gaps(b, 4.2, 7.0, -0.2, step=0.9)
    glass_gaps_v(b, 13.0, 6.0, 9.6)                # control-room window onto the live room
    RD = (1.0, 4.0, 3.5, 4.8)                      # reception desk
    SF = (4.5, 0.5, 6.5, 1.3)                      # sofa
    CT = (4.8, 3.5, 5.6, 4.3)                      # coffee table
    MX = (8.5, 6.5, 11.5, 7.5)                     # mixing desk
    SH = (7.4, 10.4, 7.9, 11.6)                    # archive shelf
    GP = (14.5, 10.5, 17.0, 12.0)                  # grand piano
    DR = (21.0, 10.0, 24.0, 12.5)                  # drum riser
    G1, G2 = (15.0, 7.5, 18.2, 7.7), (18.9, 7.5, 22.0, 7.7)   # acoustic screens, 0.7 m gap
    for o in (RD, SF, CT, MX, SH, GP, DR, G1, G2):
        b.rect(*o, OCC)
    UNK_AR = (7.2, 11.9, 13.0, 13.0)
    b.unknown(*UNK_AR)
    hollow(b)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    HD = ["LD", "VB1", "VB2", "MR", "KT", "WC", "CRD", "LRD", "BK"]
    PA = (7.8, 2.9, 0)        # corridor, west end, facing east
    PB = (24.4, 2.9, 180)     # corridor, east end, facing west
    PC = (2.0, 2.5, 0)        # lobby, facing east
    PC2 = (5.5, 5.2, 180)     # lobby, north-east, facing west
    PD = (14.0, 5.0, 90)      # live room, by the control-room door, facing north
    PE = (18.55, 5.0, 90)     # live room, the screen gap straight ahead
    PF = (15.0, 9.0, 0)       # live room, facing east (piano on the left)
    PG = (10.0, 10.7, 90)     # tape archive, facing north (unscanned back ahead)
    PH = (9.5, 5.0, 90)       # control room, facing north (mixing desk ahead, its door behind)
    for doors in (HD, [d for d in HD if d not in ("LD", "BK")]):   # lobby door / back door counted or not
        assert nth(b, PA, doors, "right", 2) == "VB2" and nth(b, PA, doors, "right", 3) == "MR"
        assert nth(b, PA, doors, "left", -1) == "LRD" and nth(b, PA, doors, "left", 3) is None
        assert nth(b, PB, doors, "left", 1) == "WC" and nth(b, PB, doors, "right", 2) == "CRD"
        assert nth(b, PB, doors, "right", 1) == "LRD"
    assert rel(PC, 7.1, 2.9)[1] >= 0.3 and rel(PC, 3.5, -0.1)[1] <= -0.3      # LD left, EX right
    areas = {n: b.area(n) for n in sp if n != "HW"}
    assert max(areas, key=areas.get) == "LR" and sorted(areas.values())[-2] < areas["LR"] - 30
    assert min(areas, key=areas.get) == "WC" and sorted(areas.values())[1] - areas["WC"] > 1.0
    out_d = min([frontier_dist(PC, (g[0], -0.2, g[1], 0.0)) for g in gaps] + [frontier_dist(PC, (2.9, -0.3, 4.1, -0.2))])
    assert out_d + 5 < frontier_dist(PC, UNK_AR)
    assert set(nearest_obstacles(PC2, dict(RD=RD, SF=SF, CT=CT), 2)) == {"RD", "CT"}
    assert abs(ahead_of(PH, MX)) < 30 and abs(rel(PH, 9.5, 3.9)[3]) > 170
    assert abs(rel(PE, 18.55, 7.6)[3]) < 2
    assert rel(PF, 15.75, 11.25)[1] > 0.3
    left_obs = {k: o for k, o in dict(GP=GP, DR=DR, G1=G1, G2=G2).items() if rel(PF, (o[0] + o[2]) / 2, (o[1] + o[3]) / 2)[1] > 0}
    assert min(left_obs, key=lambda k: edge_d(left_obs[k], PF)) == "GP"
    assert sorted(edge_d(o, PF) for o in left_obs.values())[1] - edge_d(GP, PF) > 1.0
    assert abs(rel((14.0, 5.0, 180), 13.1, 5.0)[3]) < 2        # PD after turning left: CLD straight ahead
    mid_lr = b.centroid("LR")
    outside = {"any": [band(2.95, 0.1, 4.05, 0.8)] + [poly(g[0] - 0.3, 0.1, g[1] + 0.3, 0.8) for g in gaps]}
    ar_front = band(8.1, 11.05, 12.85, 11.85)
    gap_n = within2((18.25, 7.85, 18.85, 9.0), 18.55, 7.7)
    C = [
        ("A", PA, "go on so, to the second door on your right", [ntp(D("VB2"), spaces=["HW", "VB2", "door:VB2"])]),
        ("B", PA, "move up to the third door on the right and hold", [ntp(D("MR"), spaces=["HW", "MR", "door:MR"])]),
        ("C", PA, "go to the last door on your left for me", [ntp(D("LRD"), spaces=["HW", "LR", "door:LRD"])]),
        ("H", PA, "Go through the 3rd door on the left pls.", "clarify"),
        ("D", PB, "go to the first door on the left side", [ntp(D("WC"), spaces=["HW", "WC", "door:WC"])]),
        ("E", PB, "yalla, the second door on the right, go there", [ntp(D("CRD"), spaces=["HW", "CR", "door:CRD"])]),
        ("F", PB, "go on through that first door on your right", [ntp(thr(b, "LRD", "LR"), spaces=["LR"], kind="through:LRD")]),
        ("G", PC, "go through the door on your left, please", [ntp(thr(b, "LD", "HW"), spaces=["HW"], kind="through:LD")]),
        ("I", PC, "go to the left corner of this room po", [ntp(side_corner(PC, sp["LB"][0], "left"), spaces=["LB"])]),
        ("J", PC, "head for the nearest unexplored area, let's go", [ntp(outside, spaces=["LB", "door:EX"], kind="frontier")]),
        ("A", PD, "grand, go over to the opposite side of this room", [ntp(opposite_far(b, "LR", PD), spaces=["LR"])]),
        ("B", PE, "creep through the narrow gap ahead", [ntp(gap_n, spaces=["LR"])]),
        ("C", PC2, "go in between the two nearest obstacles for me now", [ntp(circ(*mid(RD, CT), BETWEEN), spaces=["LB"])]),
        ("D", PH, "go to near the obstacle in front of you", [ntp(next_to_in(MX, sp["CR"][0]), spaces=["CR"])]),
        ("E", PG, "yalla, go towards the unexplored part of this room", [ntp(ar_front, spaces=["AR"], kind="frontier")]),
        ("F", PH, "go on out through the door behind you", [ntp(thr(b, "CRD", "HW"), spaces=["HW"], kind="through:CRD")]),
        ("G", PA, "go to the middle of the biggest room, please", [ntp(circ(*mid_lr, MIDDLE), spaces=["LR"])]),
        ("H", PA, "Go to the smallest room, thx.", [ntp(R("WC"), spaces=["WC"])]),
        ("I", PD, "face east po", [compass(b.pose(*PD)[2], 0)]),
        ("J", PH, "back pedal ten yards", {"any": ["clarify", [safe_move(b, PH, "backward")]]}),
        ("A", PC, "go to the biggest room there", [ntp(R("LR"), spaces=["LR"])]),
        ("B", PH, "move to the nearest corner of this room and hold", [ntp(nearest_corner(PH, sp["CR"][0]), spaces=["CR"])]),
        ("C", PB, "could you go into the green room for me", "clarify"),
        ("D", PH, "go to the mixing desk", "clarify"),
        ("E", PA, "face to the north", [compass(b.pose(*PA)[2], 90)]),
        ("F", PF, "scooch on over to the right corner", [ntp(side_corner(PF, sp["LR"][0], "right"), spaces=["LR"])]),
        ("G", PC, "could you pop into the vocal booth", "clarify"),
        ("H", PG, "Go out of this room and turn left.",
         [ntp(thr(b, "ARD", "CR"), spaces=["CR"], kind="through:ARD"), rot_deg(90)]),
        ("I", PF, "go next to the obstacle on your left po", [ntp(next_to_in(GP, sp["LR"][0]), spaces=["LR"])]),
        ("J", PD, "cut left ninety, then through the door in front of you",
         [rot_deg(90), ntp(thr(b, "CLD", "CR"), spaces=["CR"], kind="through:CLD")]),
    ]
    assert side_corner(PC, sp["LB"][0], "left") == corner_reg((7.0, 6.0), sp["LB"][0])
    assert side_corner(PF, sp["LR"][0], "right") == corner_reg((25.0, 4.0), sp["LR"][0])
    assert nearest_corner(PH, sp["CR"][0]) == corner_reg((7.2, 4.0), sp["CR"][0])
    assert 10 * 0.9144 / 0.03 > safe_move(b, PH, "backward")["repeat"][1] + 30
    return b, C


# ================================================================== car dealership: rotated 21.7 deg, noisy, non-rectangular outline
def dealer():
    b = Building("dealer", -1.0, -1.0, 31.0, 19.0, theta=21.7, offset=(3.0, 1.0), seed=9217)
    b.shell(0.0, 0.0, 18.0, 12.0); b.shell(0.0, 12.2, 12.0, 18.0); b.shell(18.2, 0.0, 30.0, 10.0)
    b.shell(18.2, 10.2, 26.0, 14.0)
    b.space("SH", (0.0, 0.0, 18.0, 12.0))          # showroom (biggest), glass front to the south
    b.space("SO1", (0.0, 12.2, 3.8, 18.0)); b.space("SO2", (4.0, 12.2, 7.5, 18.0))   # sales offices
    b.space("CL", (7.7, 12.2, 12.0, 18.0))         # customer lounge
    b.space("SB", (18.2, 0.0, 30.0, 10.0))         # service bay
    b.space("PS", (18.2, 10.2, 24.0, 14.0))        # parts store (back part dark)
    b.space("WC", (24.2, 10.2, 26.0, 12.4))        # toilet (smallest)
    b.door("EX", 9.0, -0.1, "h", "SH", "OUT", width=2.0)     # automatic doors, forecourt never scanned
    b.door("SO1D", 1.9, 12.1, "h", "SH", "SO1", width=0.9)
    b.door("SO2D", 5.75, 12.1, "h", "SH", "SO2", width=0.9)
    b.door("CLD", 9.85, 12.1, "h", "SH", "CL", width=1.2)
    b.door("CD", 18.1, 2.5, "v", "SH", "SB", width=3.0)      # car door (handover)
    b.door("SBD", 18.1, 7.0, "v", "SH", "SB", width=0.9)     # people door
    b.door("PSD", 20.0, 10.1, "h", "SB", "PS", width=0.9)
    b.door("WCD", 25.1, 10.1, "h", "SB", "WC", width=0.7)
    b.door("RD", 24.0, -0.1, "h", "SB", "OUT", width=3.5)    # roller door, open, yard never scanned
    b.carve()
    gaps = glass_gaps(b, 0.0, 7.6, -0.2, step=1.2) + glass_gaps(b, 10.4, 17.0, -0.2, step=1.2)
    C1, C2 = (3.0, 3.0, 7.5, 4.8), (3.0, 7.0, 7.5, 8.8)     # display cars
    C3, C4 = (11.0, 3.0, 15.5, 4.8), (8.3, 7.0, 12.8, 8.8)  # C2 / C4: a 0.8 m gap
    RC = (14.0, 9.5, 17.0, 10.3)                   # reception desk
    V1, V2 = (19.5, 4.5, 21.5, 8.5), (24.0, 4.5, 26.0, 8.5)   # cars on lifts
    TC = (29.2, 1.0, 29.9, 2.5)                    # tool chest
    PSH = (23.3, 10.4, 23.9, 12.6)                 # parts shelving
    DK1 = (0.5, 15.5, 2.5, 16.5); DK2 = (4.5, 15.5, 6.5, 16.5)   # office desks
    LS = (10.8, 13.0, 11.8, 17.0)                  # lounge sofa
    for o in (C1, C2, C3, C4, RC, V1, V2, TC, PSH, DK1, DK2, LS):
        b.rect(*o, OCC)
    UNK_PS = (18.2, 12.8, 24.0, 14.0)
    b.unknown(*UNK_PS)
    hollow(b)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    SHD = ["EX", "SO1D", "SO2D", "CLD", "CD", "SBD"]
    SBDs = ["CD", "SBD", "PSD", "WCD", "RD"]
    QA = (16.5, 11.0, 180)    # showroom, north-east, facing west
    QB = (1.2, 1.5, 90)       # showroom, south-west, facing north
    QC = (5.2, 14.3, 270)     # sales office 2, facing south (its door ahead, a little to the left)
    QD = (19.0, 3.0, 0)       # service bay, just inside the car door, facing east
    QE = (20.0, 10.8, 90)     # parts store, facing north (dark back ahead, door behind)
    QF = (25.1, 11.6, 270)    # toilet, facing south (door ahead)
    QG = (7.9, 10.5, 270)     # showroom, the gap between two cars straight ahead
    QH = (1.5, 5.9, 0)        # showroom, west, facing east between two cars
    QI = (13.5, 1.0, 90)      # showroom, south, facing north
    QJ = (28.5, 8.0, 180)     # service bay, east end, facing west
    for doors in (SHD, SHD[1:]):                     # the street door counted or not
        assert nth(b, QA, doors, "right", 1) == "CLD" and nth(b, QA, doors, "right", 2) == "SO2D"
        assert nth(b, QA, doors, "right", 3) == "SO1D" and nth(b, QA, doors, "right", 4) is None
    for doors in (SBDs, SBDs[:4]):                   # the roller door counted or not
        assert nth(b, QJ, doors, "right", 2) == "PSD" and nth(b, QJ, doors, "right", 1) == "WCD"
        assert nth(b, QJ, doors, "right", 3) is None
    areas = {n: b.area(n) for n in sp}
    assert max(areas, key=areas.get) == "SH" and sorted(areas.values())[-2] < areas["SH"] - 50
    assert min(areas, key=areas.get) == "WC" and sorted(areas.values())[1] - areas["WC"] > 5
    # QA: the reception desk is the nearest obstacle on the left
    left_obs = {k: o for k, o in dict(C1=C1, C2=C2, C3=C3, C4=C4, RC=RC).items()
                if rel(QA, (o[0] + o[2]) / 2, (o[1] + o[3]) / 2)[1] > 0}
    assert min(left_obs, key=lambda k: edge_d(left_obs[k], QA)) == "RC"
    assert sorted(edge_d(o, QA) for o in left_obs.values())[1] - edge_d(RC, QA) > 1.0
    # QD: the nearest unexplored area is the outside (roller door, glass front), far nearer than the parts store
    rd_open = (22.25, -0.4, 25.75, -0.2)
    assert frontier_dist(QD, rd_open) + 4 < frontier_dist(QD, UNK_PS)
    # QD: V2 is the nearest obstacle ahead (V1 is not ahead)
    ahead = {k: o for k, o in dict(V1=V1, V2=V2, TC=TC).items() if abs(ahead_of(QD, o)) < 60}
    assert min(ahead, key=lambda k: edge_d(ahead[k], QD)) == "V2" and "V1" not in ahead
    assert sorted(edge_d(o, QD) for o in ahead.values())[1] - edge_d(V2, QD) > 1.0
    assert abs(rel(QG, 7.9, 7.9)[3]) < 2 and abs(rel(QC, 5.75, 12.1)[3]) < 20 and abs(rel(QF, 25.1, 10.1)[3]) < 2
    assert abs(rel(QE, 20.0, 10.1)[3]) > 170
    assert set(nearest_obstacles(QH, dict(C1=C1, C2=C2, C3=C3, C4=C4), 2)) == {"C1", "C2"}
    mid_sh = b.centroid("SH")
    outside = {"any": [band(22.45, 0.15, 25.55, 0.85)] +
               [poly(g[0] - 0.3, 0.1, g[1] + 0.3, 0.8) for g in gaps]}
    ps_front = band(18.35, 11.9, 23.15, 12.7)
    gap_s = within2((7.6, 5.8, 8.2, 6.85), 7.9, 7.0)
    C = [
        ("A", QA, "go on so, to the first door on your right", [ntp(D("CLD"), spaces=["SH", "CL", "door:CLD"])]),
        ("B", QA, "move to the second door on the right", [ntp(D("SO2D"), spaces=["SH", "SO2", "door:SO2D"])]),
        ("C", QA, "go on through the third door on your right for me", [ntp(thr(b, "SO1D", "SO1"), spaces=["SO1"], kind="through:SO1D")]),
        ("D", QA, "go near to the obstacle on the left side", [ntp(next_to_in(RC, sp["SH"][0]), spaces=["SH"])]),
        ("E", QA, "go to the left corner, left", [ntp(side_corner(QA, sp["SH"][0], "left"), spaces=["SH"])]),
        ("F", QA, "go on over to the right corner of this room", [ntp(side_corner(QA, sp["SH"][0], "right"), spaces=["SH"])]),
        ("G", QJ, "could you go to the second door on your right", [ntp(D("PSD"), spaces=["SB", "PS", "door:PSD"])]),
        ("H", QJ, "Go to the first door on your right pls.", [ntp(D("WCD"), spaces=["SB", "WC", "door:WCD"])]),
        ("I", QD, "go to the nearest unexplored area po", [ntp(outside, spaces=["SB", "SH", "door:RD", "door:EX"], kind="frontier")]),
        ("J", QD, "hustle up next to the obstacle in front of you", [ntp(next_to_in(V2, sp["SB"][0]), spaces=["SB"])]),
        ("A", QE, "go on towards the unexplored bit of this room", [ntp(ps_front, spaces=["PS"], kind="frontier")]),
        ("B", QE, "back out through the door behind you", [ntp(thr(b, "PSD", "SB"), spaces=["SB"], kind="through:PSD")]),
        ("C", QF, "go out through the door and turn right, quiet now",
         [ntp(thr(b, "WCD", "SB"), spaces=["SB"], kind="through:WCD"), rot_deg(-90)]),
        ("D", QG, "pass the narrow gap in front of you", [ntp(gap_s, spaces=["SH"])]),
        ("E", QG, "go back fifteen meter", {"any": ["clarify", [safe_move(b, QG, "backward")]]}),
        ("F", QH, "go on halfway between the two closest obstacles", [ntp(circ(*mid(C1, C2), BETWEEN), spaces=["SH"])]),
        ("G", QI, "could you go to the opposite side of this room", [ntp(opposite_far(b, "SH", QI), spaces=["SH"])]),
        ("H", QD, "Go to the biggest room, thx.", [ntp(R("SH"), spaces=["SH"])]),
        ("I", QD, "go to the smallest room po", [ntp(R("WC"), spaces=["WC"])]),
        ("J", QB, "get to the middle of this room", [ntp(circ(*mid_sh, MIDDLE), spaces=["SH"])]),
        ("A", QB, "face east so", [compass(b.pose(*QB)[2], 0)]),
        ("B", QC, "move to the nearest corner of this room", [ntp(nearest_corner(QC, sp["SO2"][0]), spaces=["SO2"])]),
        ("C", QB, "go over by the red car, love", "clarify"),
        ("D", QA, "go to the office of finance", "clarify"),
        ("E", QD, "go to the car wash", "clarify"),
        ("F", QD, "go on and face north", [compass(b.pose(*QD)[2], 90)]),
        ("G", QA, "could you go to the fourth door on your right", "clarify"),
        ("H", QI, "Face west pls.", [compass(b.pose(*QI)[2], 180)]),
        ("I", QC, "go through the door in front of you po", [ntp(thr(b, "SO2D", "SH"), spaces=["SH"], kind="through:SO2D")]),
        ("J", QG, "hustle over to the left corner", [ntp(side_corner(QG, sp["SH"][0], "left"), spaces=["SH"])]),
    ]
    assert side_corner(QA, sp["SH"][0], "left") == corner_reg((0.0, 0.0), sp["SH"][0])
    assert side_corner(QA, sp["SH"][0], "right") == corner_reg((0.0, 12.0), sp["SH"][0])
    assert side_corner(QG, sp["SH"][0], "left") == corner_reg((18.0, 0.0), sp["SH"][0])
    assert nearest_corner(QC, sp["SO2"][0]) == corner_reg((4.0, 12.2), sp["SO2"][0])
    assert 15.0 / 0.03 > safe_move(b, QG, "backward")["repeat"][1] + 30
    return b, C


# ================================================================== ski lodge: rotated -34.6 deg, noisy, stepped outline
def lodge():
    b = Building("lodge", -1.0, -1.0, 26.0, 20.0, theta=-34.6, offset=(2.0, 16.0), seed=9346)
    b.shell(0.0, 0.0, 8.0, 6.0); b.shell(0.0, 6.2, 8.0, 14.0); b.shell(8.2, 0.0, 22.0, 14.0)
    b.shell(8.2, 14.2, 11.8, 17.5); b.shell(12.0, 14.2, 18.0, 19.0); b.shell(18.2, 14.2, 20.6, 16.6)
    b.shell(22.2, 8.0, 25.0, 11.0)
    b.space("BR", (0.0, 0.0, 8.0, 6.0))            # boot room (entrance)
    b.space("RS", (0.0, 6.2, 8.0, 14.0))           # ski-rental shop
    b.space("GH", (8.2, 0.0, 22.0, 14.0))          # great hall (biggest), glass front onto the terrace
    b.space("DY", (8.2, 14.2, 11.8, 17.5))         # drying room (back part not scanned)
    b.space("KT", (12.0, 14.2, 18.0, 19.0))        # kitchen
    b.space("FA", (18.2, 14.2, 20.6, 16.6))        # first-aid room (smallest)
    b.space("WC", (22.2, 8.0, 25.0, 11.0))         # toilets
    b.door("EX", 4.0, -0.1, "h", "BR", "OUT", width=1.4)     # entrance, snow outside never scanned
    b.door("BRD", 8.1, 3.0, "v", "BR", "GH", width=1.0)
    b.door("BRS", 6.5, 6.1, "h", "BR", "RS", width=0.9)
    b.door("RSD", 8.1, 10.0, "v", "RS", "GH", width=1.2)
    b.door("DYD", 10.0, 14.1, "h", "GH", "DY", width=0.8)
    b.door("KTD", 12.6, 14.1, "h", "GH", "KT", width=0.9)
    b.door("FAD", 19.5, 14.1, "h", "GH", "FA", width=0.8)
    b.door("WCD", 22.1, 9.5, "v", "GH", "WC", width=0.8)
    b.door("TD", 15.0, -0.1, "h", "GH", "OUT", width=1.6)    # terrace doors, terrace never scanned
    b.carve()
    gaps = glass_gaps(b, 8.2, 14.0, -0.2, step=1.1) + glass_gaps(b, 16.0, 22.0, -0.2, step=1.1)
    BN = (0.0, 1.0, 0.5, 5.0)                      # boot-room bench, against the west wall
    BL = (2.5, 5.3, 5.8, 5.9)                      # boot lockers (north wall, clear of the shop door)
    RC = (6.0, 7.5, 6.6, 11.5)                     # rental counter
    RA, RB = (1.5, 9.0, 4.0, 9.5), (1.5, 10.2, 4.0, 10.7)     # ski racks: a 0.7 m aisle between them
    FP = (13.5, 12.8, 16.5, 14.0)                  # fireplace (chimney breast on the north wall)
    SF = (13.0, 10.3, 17.0, 11.0)                  # sofa
    T1, T2 = (10.0, 3.0, 12.0, 4.2), (10.0, 7.0, 12.0, 8.2)   # tables
    T3, T4 = (15.0, 3.0, 17.0, 4.2), (18.5, 7.0, 20.5, 8.2)
    KI = (14.0, 16.0, 16.5, 17.0)                  # kitchen island
    for o in (BN, BL, RC, RA, RB, FP, SF, T1, T2, T3, T4, KI):
        b.rect(*o, OCC)
    UNK_DY = (8.2, 16.0, 11.8, 17.5)
    b.unknown(*UNK_DY)
    hollow(b)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    GHD = ["BRD", "RSD", "DYD", "KTD", "FAD", "WCD", "TD"]
    KA = (9.0, 12.5, 0)       # great hall, north-west, facing east
    KB = (21.0, 7.0, 90)      # great hall, east, facing north
    KC = (6.5, 3.0, 90)       # boot room, facing north (shop door ahead)
    KD = (5.0, 9.85, 180)     # rental shop, facing west, the rack aisle ahead
    KE = (9.6, 15.0, 90)      # drying room, facing north (unscanned back ahead, door behind-right)
    KF = (19.4, 15.8, 270)    # first-aid room, facing south (door ahead)
    KG = (15.0, 1.5, 90)      # great hall by the terrace doors, facing north (table T3 ahead)
    KH = (9.0, 5.6, 0)        # great hall, west, facing east between two tables
    KJ = (12.0, 10.0, 0)      # great hall, facing east
    KL = (9.0, 10.0, 0)       # great hall, just inside the shop door, facing east
    for doors in (GHD, GHD[:-1]):                    # the terrace doors counted or not
        assert nth(b, KA, doors, "left", 2) == "KTD" and nth(b, KA, doors, "left", 3) == "FAD"
        assert nth(b, KA, doors, "left", 4) is None and nth(b, KL, doors, "left", 1) == "DYD"
        assert nth(b, KB, doors, "right", 1) == "WCD" and nth(b, KB, doors, "left", 1) == "FAD"
    assert abs(rel(KC, 6.5, 6.1)[3]) < 2 and abs(rel(KF, 19.5, 14.1)[3]) < 5 and abs(rel(KE, 10.0, 14.1)[3]) > 150
    assert abs(rel((9.0, 10.0, 180), 8.1, 10.0)[3]) < 2
    assert abs(rel(KD, 2.75, 9.85)[3]) < 2
    areas = {n: b.area(n) for n in sp}
    assert max(areas, key=areas.get) == "GH" and sorted(areas.values())[-2] < areas["GH"] - 50
    assert min(areas, key=areas.get) == "FA" and sorted(areas.values())[1] - areas["FA"] > 2
    # KA: the drying room's dark back is the nearest unexplored area (straight line), far nearer than outside
    out_rects = [(g[0], -0.2, g[1], 0.0) for g in gaps] + [(14.2, -0.4, 15.8, -0.2), (3.3, -0.4, 4.7, -0.2)]
    assert frontier_dist(KA, UNK_DY) + 5 < min(frontier_dist(KA, r) for r in out_rects)
    # KC: the outside is nearest (entrance / glass), the drying room far
    assert min(frontier_dist(KC, r) for r in out_rects) + 5 < frontier_dist(KC, UNK_DY)
    ahead = {k: o for k, o in dict(T1=T1, T2=T2, T3=T3, T4=T4, SF=SF, FP=FP).items() if abs(ahead_of(KG, o)) < 60}
    assert abs(ahead_of(KG, T3)) < 5 and min(ahead, key=lambda k: edge_d(ahead[k], KG)) == "T3"
    assert sorted(edge_d(o, KG) for o in ahead.values())[1] - edge_d(T3, KG) > 1.0
    assert set(nearest_obstacles(KH, dict(T1=T1, T2=T2, T3=T3, T4=T4, SF=SF), 2)) == {"T1", "T2"}
    mid_gh = b.centroid("GH")
    dy_front = band(8.35, 15.1, 11.65, 15.9)
    outside = {"any": [band(3.45, 0.1, 4.55, 0.8), band(14.35, 0.1, 15.65, 0.8)] +
               [poly(g[0] - 0.3, 0.1, g[1] + 0.3, 0.8) for g in gaps]}
    aisle = within2((0.2, 9.3, 1.3, 10.4), 1.5, 9.85)
    C = [
        ("A", KA, "go on so, to the second door on your left", [ntp(D("KTD"), spaces=["GH", "KT", "door:KTD"])]),
        ("B", KA, "move through the third door on the left", [ntp(thr(b, "FAD", "FA"), spaces=["FA"], kind="through:FAD")]),
        ("C", KA, "go on through the fourth door on your left now", "clarify"),
        ("D", KL, "go to the first door of the left side", [ntp(D("DYD"), spaces=["GH", "DY", "door:DYD"])]),
        ("E", KB, "yalla, first door on the right", [ntp(D("WCD"), spaces=["GH", "WC", "door:WCD"])]),
        ("F", KB, "go on to the first door on your left", [ntp(D("FAD"), spaces=["GH", "FA", "door:FAD"])]),
        ("G", KC, "go through the door in front of you, please", [ntp(thr(b, "BRS", "RS"), spaces=["RS"], kind="through:BRS")]),
        ("H", KC, "Pls go to the biggest room.", [ntp(R("GH"), spaces=["GH"])]),
        ("I", KC, "sige, go to the nearest unexplored area po", [ntp(outside, spaces=["BR", "GH", "door:EX", "door:TD"], kind="frontier")]),
        ("J", KD, "let's go, through the narrow passage ahead", [ntp(aisle, spaces=["RS"])]),
        ("A", KD, "back up eight metres there", {"any": ["clarify", [safe_move(b, KD, "backward")]]}),
        ("B", KE, "advance towards the unexplored part of this room", [ntp(dy_front, spaces=["DY"], kind="frontier")]),
        ("C", KE, "go out the door behind you and turn right, quiet now",
         [ntp(thr(b, "DYD", "GH"), spaces=["GH"], kind="through:DYD"), rot_deg(-90)]),
        ("D", KF, "go out to the door in front and after turn to the left",
         [ntp(thr(b, "FAD", "GH"), spaces=["GH"], kind="through:FAD"), rot_deg(90)]),
        ("E", KG, "tamam, go next to the obstacle in front of you", [ntp(next_to_in(T3, sp["GH"][0]), spaces=["GH"])]),
        ("F", KG, "go on up to the opposite side of this room", [ntp(opposite_far(b, "GH", KG), spaces=["GH"])]),
        ("G", KH, "could you go halfway between the two closest obstacles", [ntp(circ(*mid(T1, T2), BETWEEN), spaces=["GH"])]),
        ("H", KJ, "Go to the right corner of this room, thx.", [ntp(side_corner(KJ, sp["GH"][0], "right"), spaces=["GH"])]),
        ("I", KJ, "go to the left corner po", [ntp(side_corner(KJ, sp["GH"][0], "left"), spaces=["GH"])]),
        ("J", KA, "head towards the nearest unexplored area", [ntp(dy_front, spaces=["DY"], kind="frontier")]),
        ("A", KA, "go down to the smallest room", [ntp(R("FA"), spaces=["FA"])]),
        ("B", KB, "move to the middle of this room", [ntp(circ(*mid_gh, MIDDLE), spaces=["GH"])]),
        ("C", KJ, "go and sit by the fireplace now", "clarify"),
        ("D", KB, "rotate to the west", [compass(b.pose(*KB)[2], 180)]),
        ("E", KD, "face to the south", [compass(b.pose(*KD)[2], 270)]),
        ("F", KC, "go on over to the ski rental", "clarify"),
        ("G", KJ, "could you go to the bar, please", "clarify"),
        ("H", KE, "Go to the nearest corner of this room.", [ntp(nearest_corner(KE, sp["DY"][0]), spaces=["DY"])]),
        ("I", KF, "face north po", [compass(b.pose(*KF)[2], 90)]),
        ("J", KL, "turn around and go through the door in front of you",
         [rot("any", 17, 19), ntp(thr(b, "RSD", "RS", half=0.9), spaces=["RS"], kind="through:RSD")]),
    ]
    assert side_corner(KJ, sp["GH"][0], "right") == corner_reg((22.0, 0.0), sp["GH"][0])
    assert side_corner(KJ, sp["GH"][0], "left") == corner_reg((22.0, 14.0), sp["GH"][0])
    assert 8.0 / 0.03 > safe_move(b, KD, "backward")["repeat"][1] + 30
    return b, C


BUILDINGS = lambda: [(studio, "std"), (dealer, "dlr"), (lodge, "ski")]

def main_one(fn, tag):
    b, C = fn()
    assert len(C) == 30, (tag, len(C))
    for s in "ABCDEFGHIJ":
        assert sum(1 for c in C if c[0] == s) == 3, (tag, s)
    return [(b, tag, i, spk, pose, prompt, exp) for i, (spk, pose, prompt, exp) in enumerate(C, 1)]


if __name__ == "__main__":
    import sys
    out = []
    for fn, tag in BUILDINGS():
        out += main_one(fn, tag)
    bld_check.write(out)
