#!/usr/bin/env python3
"""Draws three new buildings -- a police station (axis-aligned, L-SHAPED outline: a public lobby behind a
GLASS front, a security door into a corridor with three identical holding cells, lockers, an evidence room
whose back was never scanned, a squad room with four desk blocks and a 0.7 m gap between two of them,
interview rooms, a kit room, a briefing room, a back door to the never-scanned yard), a post office
(ROTATED 13.4 deg with lidar-like noise, fixed seed; NON-RECTANGULAR outline; a customer hall with a 0.7 m
queue lane between two barrier rows and a long counter, a sorting room with three sorting frames and an
open 3 m roller door onto the never-scanned yard, a parcel store whose back is dark (not scanned), a
manager's office, a staff room, a toilet) and a ferry passenger deck (ROTATED -23.7 deg with noise;
NON-RECTANGULAR outline: the lounge narrows in two steps towards the bow, whose tip was never scanned; a
foyer round a stairwell with doors to the open deck on both sides, a cafeteria, a kiosk, toilets, a crew
store) -- and writes buildings.jsonl, 30 cases each.  Every expected region is checked on the drawn map
(bld_check.check) and an oracle output built from the expectations is scored.  Drawing / geometry / check
helpers (bld_*.py) and the helpers nth, room_cells, opposite, next_to, within2, mid, nearest_obstacles,
frontier_dist, hollow, glass_gaps are copied from the seventh blind set; next_to_in (next_to clipped to a
room) is new; the buildings and prompts are new.

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


# ================================================================== police station: L-shaped outline, axis-aligned
def police():
    b = Building("police", -1.0, -1.0, 29.0, 13.0)
    b.shell(0.0, 0.0, 8.0, 6.0); b.shell(8.2, 0.0, 28.0, 12.0)
    b.space("LB", (0.0, 0.0, 8.0, 6.0))            # public lobby, glass front to the south
    b.space("HW", (8.2, 2.0, 28.0, 4.0))           # corridor, 2.0 m
    b.space("C1", (8.2, 0.0, 10.5, 1.8)); b.space("C2", (10.7, 0.0, 13.0, 1.8)); b.space("C3", (13.2, 0.0, 15.5, 1.8))
    b.space("LK", (15.7, 0.0, 21.0, 1.8))          # locker room
    b.space("EV", (21.2, 0.0, 25.0, 1.8))          # evidence room (east part not scanned)
    b.space("WC", (25.2, 0.0, 28.0, 1.8))          # toilets
    b.space("SQ", (8.2, 4.2, 18.0, 12.0))          # squad room (biggest)
    b.space("IR1", (18.2, 4.2, 21.5, 8.0)); b.space("IR2", (21.7, 4.2, 25.0, 8.0))   # interview rooms
    b.space("KR", (25.2, 4.2, 28.0, 8.0))          # kit room
    b.space("BR", (18.2, 8.2, 28.0, 12.0))         # briefing room
    b.door("EX", 4.0, -0.1, "h", "LB", "OUT", width=1.6)     # entrance, outside never scanned
    b.door("SD", 8.1, 3.0, "v", "LB", "HW", width=1.0)       # security door
    b.door("C1", 9.35, 1.9, "h", "HW", "C1", width=0.8)
    b.door("C2", 11.85, 1.9, "h", "HW", "C2", width=0.8)
    b.door("C3", 14.35, 1.9, "h", "HW", "C3", width=0.8)
    b.door("LK", 18.3, 1.9, "h", "HW", "LK", width=0.9)
    b.door("EV", 22.2, 1.9, "h", "HW", "EV", width=0.7)
    b.door("WC", 26.6, 1.9, "h", "HW", "WC", width=0.8)
    b.door("SQ", 12.0, 4.1, "h", "HW", "SQ", width=1.4)      # double door
    b.door("IR1", 19.8, 4.1, "h", "HW", "IR1", width=0.9)
    b.door("IR2", 23.3, 4.1, "h", "HW", "IR2", width=0.9)
    b.door("KR", 26.0, 4.1, "h", "HW", "KR", width=0.8)
    b.door("BK", 28.1, 3.0, "v", "HW", "OUT", width=1.2)     # back door to the yard, never scanned
    b.door("BR", 18.1, 10.0, "v", "SQ", "BR", width=0.9)
    b.carve()
    gaps = glass_gaps(b, 0.0, 3.0, -0.2, step=1.0) + glass_gaps(b, 5.0, 8.0, -0.2, step=1.0)
    FC = (2.5, 4.3, 7.5, 5.0)                      # front counter
    BN = (0.3, 0.8, 0.8, 3.5)                      # bench
    D1, D2 = (9.5, 6.0, 12.0, 7.2), (12.7, 6.0, 15.2, 7.2)   # desk blocks, 0.7 m gap
    D3, D4 = (9.5, 9.0, 12.0, 10.2), (13.5, 9.0, 16.0, 10.2)
    T1, T2 = (19.4, 6.4, 20.4, 7.2), (22.9, 6.4, 23.9, 7.2)  # interview tables
    BT = (21.0, 9.5, 25.0, 10.7)                   # briefing table
    LKR = (16.0, 0.1, 20.7, 0.55)                  # lockers
    KS = (27.3, 4.4, 27.9, 7.8)                    # kit shelves
    for o in (FC, BN, D1, D2, D3, D4, T1, T2, BT, LKR, KS):
        b.rect(*o, OCC)
    UNK_EV = (23.8, 0.0, 25.0, 1.8)
    UNK_SQ = (16.2, 11.0, 18.0, 12.0)              # behind partitions, not scanned
    b.unknown(*UNK_EV); b.unknown(*UNK_SQ)
    hollow(b)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    HD = ["C1", "C2", "C3", "LK", "EV", "WC", "SQ", "IR1", "IR2", "KR", "BK", "SD"]
    PA = (8.8, 3.0, 0)        # corridor, west end, facing east
    PB = (27.3, 3.0, 180)     # corridor, east end, facing west
    PC = (2.0, 2.0, 0)        # lobby, facing east
    PD = (10.0, 5.0, 90)      # squad room, facing north (desk D1 ahead)
    PE = (12.35, 4.9, 90)     # squad room, the gap between D1 and D2 straight ahead
    PF = (9.0, 8.1, 0)        # squad room, between the desk rows, facing east
    PG = (21.8, 0.9, 0)       # evidence room, facing east (the unscanned part ahead)
    PH = (19.9, 4.7, 90)      # interview room 1, facing north (table ahead)
    PI = (20.0, 10.0, 0)      # briefing room, facing east
    PJ = (13.1, 4.8, 90)      # squad room, just inside its door, facing north
    for doors in (HD, [d for d in HD if d not in ("BK", "SD")]):   # openings to outside / lobby counted or not
        assert nth(b, PA, doors, "right", 3) == "C3" and nth(b, PA, doors, "left", 2) == "IR1"
        assert nth(b, PA, doors, "left", -1) == "KR" and nth(b, PA, doors, "left", 5) is None
        assert nth(b, PB, doors, "left", 1) == "WC" and nth(b, PB, doors, "right", 2) == "IR2"
        assert nth(b, PB, doors, "left", 4) == "C3"
    # PC: the security door is the only door on the left (the entrance is on the right)
    assert rel(PC, 8.1, 3.0)[1] >= 0.3 and rel(PC, 4.0, -0.1)[1] <= -0.3
    areas = {n: b.area(n) for n in sp if n != "HW"}
    assert max(areas, key=areas.get) == "SQ" and sorted(areas.values())[-2] < areas["SQ"] - 20
    small = sorted(areas, key=areas.get)
    assert set(small[:3]) == {"C1", "C2", "C3"} and areas["C1"] == areas["C2"] == areas["C3"]
    assert areas[small[3]] - areas["C1"] > 0.8
    # PC: the nearest unexplored area is the outside (glass gaps, entrance), far nearer than the others
    out_d = min([frontier_dist(PC, (g[0], -0.2, g[1], 0.0)) for g in gaps] + [frontier_dist(PC, (3.2, -0.3, 4.8, -0.2))])
    assert out_d + 5 < min(frontier_dist(PC, UNK_EV), frontier_dist(PC, UNK_SQ))
    # PD: D1 ahead; PE: the gap straight ahead; PF: D1, D3 the two nearest
    assert abs(rel(PD, 10.75, 6.6)[3]) < 40 and abs(rel(PE, 12.35, 6.6)[3]) < 2
    obs = dict(D1=D1, D2=D2, D3=D3, D4=D4)
    assert set(nearest_obstacles(PF, obs, 2)) == {"D1", "D3"}
    assert abs(rel(PH, 19.9, 6.8)[3]) < 5
    # PI after turning round: the briefing room's only door straight ahead
    assert abs(rel((20.0, 10.0, 180), 18.1, 10.0)[3]) < 2
    mid_sq = b.centroid("SQ")
    outside = {"any": [band(3.35, 0.1, 4.65, 0.8)] + [poly(g[0] - 0.3, 0.1, g[1] + 0.3, 0.8) for g in gaps]}
    ev_front = band(22.95, 0.15, 23.75, 1.65)
    gap_n = within2((12.05, 7.35, 12.65, 8.5), 12.35, 6.6)
    C = [
        ("A", PA, "righto, go to the third door on your right", [ntp(D("C3"), spaces=["HW", "C3", "door:C3"])]),
        ("B", PA, "right then, through the second door on your left, mate",
         [ntp(through(b, "IR1", "IR1"), spaces=["IR1"], kind="through:IR1")]),
        ("C", PA, "could you go to the last door on your left, carefully", [ntp(D("KR"), spaces=["HW", "KR", "door:KR"])]),
        ("H", PA, "PLEASE GO TO THE FIFTH DOOR ON THE LEFT.", "clarify"),
        ("D", PB, "okay chat, we're going through the first door on the left",
         [ntp(through(b, "WC", "WC"), spaces=["WC"], kind="through:WC")]),
        ("E", PB, "oya, go to the second door on your right hand side", [ntp(D("IR2"), spaces=["HW", "IR2", "door:IR2"])]),
        ("F", PB, "go to the biggest room lah", [ntp(R("SQ"), spaces=["SQ"])]),
        ("G", PC, "and if we just pop through the door on your left", [ntp(through(b, "SD", "HW"), spaces=["HW"], kind="through:SD")]),
        ("I", PC, "please go to right corner of this room", [ntp(side_corner(PC, sp["LB"][0], "right"), spaces=["LB"])]),
        ("J", PC, "forward to the nearest unexplored area, move", [ntp(outside, spaces=["LB", "door:EX"], kind="frontier")]),
        ("A", PJ, "go to the opposite side of this room, mate", [ntp(opposite(b, "SQ", PJ, "+y"), spaces=["SQ"])]),
        ("B", PD, "right then, go next to the obstacle in front of you", [ntp(next_to_in(D1, sp["SQ"][0]), spaces=["SQ"])]),
        ("C", PE, "could you go through the narrow gap ahead of you, very slowly", [ntp(gap_n, spaces=["SQ"])]),
        ("D", PF, "okay go halfway between the two closest obstacles", [ntp(circ(*mid(D1, D3), BETWEEN), spaces=["SQ"])]),
        ("E", PD, "oya, turn face west side", [compass(b.pose(*PD)[2], 180)]),
        ("F", PD, "go back five metre lah", {"any": ["clarify", [safe_move(b, PD, "backward")]]}),
        ("G", PF, "and let's pop over to the right corner", [ntp(side_corner(PF, sp["SQ"][0], "right"), spaces=["SQ"])]),
        ("H", PG, "GO TOWARDS THE UNEXPLORED PART OF THIS ROOM.", [ntp(ev_front, spaces=["EV"], kind="frontier")]),
        ("I", PG, "please go out of this room and turn right",
         [ntp(through(b, "EV", "HW"), spaces=["HW"], kind="through:EV"), rot_deg(-90)]),
        ("J", PH, "forward, to the obstacle ahead, move", [ntp(next_to_in(T1, sp["IR1"][0]), spaces=["IR1"])]),
        ("A", PI, "righto, head to the right corner", [ntp(side_corner(PI, sp["BR"][0], "right"), spaces=["BR"])]),
        ("B", PI, "turn round and go through the door in front of you",
         [rot("any", 17, 19), ntp(through(b, "BR", "SQ", half=0.9), spaces=["SQ"], kind="through:BR")]),
        ("C", PC, "could you go and stand by the front desk", "clarify"),
        ("D", PA, "go to the break room", "clarify"),
        ("E", PI, "abeg go to the custody suite", "clarify"),
        ("F", PB, "go to the fourth door on the left side there", [ntp(D("C3"), spaces=["HW", "C3", "door:C3"])]),
        ("G", PB, "face south for me, lovely", [compass(b.pose(*PB)[2], 270)]),
        ("H", PE, "GO TO THE NEAREST CORNER OF THIS ROOM PLEASE.", [ntp(nearest_corner(PE, sp["SQ"][0]), spaces=["SQ"])]),
        ("I", PD, "please go to the smallest room", [ntp({"any": [R("C1"), R("C2"), R("C3")]}, spaces=["C1", "C2", "C3"])]),
        ("J", PA, "forward to the middle of the biggest room, move", [ntp(circ(*mid_sq, MIDDLE), spaces=["SQ"])]),
    ]
    assert side_corner(PC, sp["LB"][0], "right") == corner_reg((8.0, 0.0), sp["LB"][0])
    assert side_corner(PF, sp["SQ"][0], "right") == corner_reg((18.0, 4.2), sp["SQ"][0])
    assert side_corner(PI, sp["BR"][0], "right") == corner_reg((28.0, 8.2), sp["BR"][0])
    assert nearest_corner(PE, sp["SQ"][0]) == corner_reg((8.2, 4.2), sp["SQ"][0])
    assert 5.0 / 0.03 > safe_move(b, PD, "backward")["repeat"][1] + 30
    return b, C


# ================================================================== post office: rotated 13.4 deg, noisy, non-rectangular outline
def postoffice():
    b = Building("postoffice", -1.0, -1.0, 27.5, 15.0, theta=13.4, offset=(2.0, 1.0), seed=8134)
    b.shell(0.0, 0.0, 12.0, 8.0); b.shell(0.0, 8.2, 12.0, 12.0); b.shell(12.2, 0.0, 26.0, 10.0)
    b.shell(12.2, 10.2, 18.0, 14.0); b.shell(18.2, 10.2, 20.5, 12.5)
    b.space("CH", (0.0, 0.0, 12.0, 8.0))           # customer hall (counter, queue barriers)
    b.space("MO", (0.0, 8.2, 5.0, 12.0))           # manager's office
    b.space("ST", (5.2, 8.2, 12.0, 12.0))          # staff room
    b.space("SR", (12.2, 0.0, 26.0, 10.0))         # sorting room (biggest)
    b.space("PS", (12.2, 10.2, 18.0, 14.0))        # parcel store (back part dark, not scanned)
    b.space("WC", (18.2, 10.2, 20.5, 12.5))        # toilet (smallest)
    b.door("EX", 6.0, -0.1, "h", "CH", "OUT", width=1.8)     # automatic doors, street never scanned
    b.door("MO", 2.5, 8.1, "h", "CH", "MO", width=0.8)
    b.door("ST", 9.0, 8.1, "h", "CH", "ST", width=0.9)
    b.door("SR", 12.1, 4.0, "v", "CH", "SR", width=1.0)      # staff door behind the counter
    b.door("PS", 15.0, 10.1, "h", "SR", "PS", width=0.9)
    b.door("WC", 19.3, 10.1, "h", "SR", "WC", width=0.7)
    b.door("RD", 26.1, 5.0, "v", "SR", "OUT", width=3.0)     # roller door, open onto the never-scanned yard
    b.carve()
    QB1, QB2 = (2.5, 3.0, 7.5, 3.15), (2.5, 3.85, 7.5, 4.0)  # queue barriers: a 0.7 m lane
    CN = (9.6, 1.2, 10.4, 6.8)                     # counter
    WD = (0.5, 6.3, 2.3, 7.3)                      # writing desk
    F1, F2, F3 = (14.5, 2.0, 15.1, 7.5), (17.5, 2.0, 18.1, 7.5), (20.5, 2.0, 21.1, 7.5)   # sorting frames
    PC = (22.8, 6.8, 25.2, 9.2)                    # parcel cage
    MD = (3.8, 9.8, 4.8, 11.2)                     # manager's desk
    TB = (7.5, 9.5, 9.5, 10.7)                     # staff-room table
    SF = (10.5, 11.2, 11.8, 11.9)                  # sofa
    for o in (QB1, QB2, CN, WD, F1, F2, F3, PC, MD, TB, SF):
        b.rect(*o, OCC)
    UNK_PS = (15.5, 12.0, 18.0, 14.0)
    b.unknown(*UNK_PS)
    hollow(b)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    CD = ["EX", "MO", "ST", "SR"]
    OA = (1.5, 1.5, 0)        # customer hall, south-west, facing east
    OB = (13.0, 5.0, 0)       # sorting room, just inside, facing east (frame F1 ahead)
    OC = (24.5, 2.0, 90)      # sorting room, south-east, facing north
    OD = (13.0, 11.0, 0)      # parcel store, facing east
    OE = (19.3, 11.5, 270)    # toilet, facing south (its door ahead)
    OF = (2.5, 8.7, 90)       # manager's office, facing north
    OG = (11.2, 7.4, 270)     # customer hall behind the counter, facing south
    OH = (2.0, 3.5, 0)        # customer hall, at the mouth of the queue lane, facing east
    OI = (11.0, 9.0, 180)     # staff room, facing west
    for doors in (CD, CD[1:]):                       # the street door counted or not
        assert nth(b, OA, doors, "left", 2) == "ST" and nth(b, OA, doors, "left", 3) == "SR"
        assert nth(b, OA, doors, "left", 1) == "MO" and nth(b, OA, doors, "left", 4) is None
        assert nth(b, OG, doors, "left", 1) == "SR" and nth(b, OG, doors, "left", 2) is None
    assert rel(OD, 15.0, 10.1)[1] < -0.3 and abs(rel(OD, 15.0, 10.1)[3]) < 60
    areas = {n: b.area(n) for n in sp}
    assert max(areas, key=areas.get) == "SR" and sorted(areas.values())[-2] < areas["SR"] - 30
    assert min(areas, key=areas.get) == "WC" and sorted(areas.values())[1] - areas["WC"] > 5
    obs = dict(F1=F1, F2=F2, F3=F3, PC=PC)
    assert nearest_obstacles(OB, obs, 1) == ["F1"] and set(nearest_obstacles(OB, obs, 2)) == {"F1", "F2"}
    assert abs(rel(OB, 14.8, 4.75)[3]) < 15
    # OC: the roller door's opening is the nearest unexplored area; OH: the street door's opening
    assert frontier_dist(OC, (26.2, 3.5, 26.4, 6.5)) + 5 < frontier_dist(OC, UNK_PS)
    assert frontier_dist(OH, (5.1, -0.4, 6.9, -0.2)) + 5 < min(frontier_dist(OH, UNK_PS), frontier_dist(OH, (26.2, 3.5, 26.4, 6.5)))
    # OI: the table is the nearest obstacle on the right (the sofa also right, farther); the door ahead-left
    assert rel(OI, 8.5, 10.1)[1] < -0.3 and rel(OI, 11.15, 11.55)[1] < -0.3
    assert rel(OI, 9.0, 8.1)[1] > 0.3 and abs(rel(OI, 9.0, 8.1)[3]) < 60
    # OF after turning round: the office's only door straight ahead
    assert abs(rel((2.5, 8.7, 270), 2.5, 8.1)[3]) < 2
    assert abs(rel(OH, 5.0, 3.5)[3]) < 2
    mid_sr = b.centroid("SR")
    mid_ch = b.centroid("CH")
    rd_front = band(25.3, 3.7, 26.0, 6.3)
    ex_front = band(5.25, 0.15, 6.75, 0.85)
    ps_front = {"any": [band(14.6, 12.05, 15.45, 13.85), band(15.55, 11.1, 17.85, 11.95)]}
    lane_e = within2((7.65, 3.0, 9.3, 4.0), 7.5, 3.5)
    C = [
        ("A", OA, "righto, go to the second door on your left", [ntp(D("ST"), spaces=["CH", "ST", "door:ST"])]),
        ("B", OA, "right then, through the third door on the left", [ntp(through(b, "SR", "SR"), spaces=["SR"], kind="through:SR")]),
        ("C", OA, "could you go through the first door on your left, please", [ntp(through(b, "MO", "MO"), spaces=["MO"], kind="through:MO")]),
        ("D", OA, "okay chat, let's go through the fourth door on the left", "clarify"),
        ("E", OH, "oya go through the narrow passage in front of you", [ntp(lane_e, spaces=["CH"])]),
        ("F", OB, "go next to the obstacle in front lah", [ntp(next_to_in(F1, sp["SR"][0]), spaces=["SR"])]),
        ("G", OB, "lovely, if we go halfway between the two nearest obstacles", [ntp(circ(*mid(F1, F2), BETWEEN), spaces=["SR"])]),
        ("H", OC, "GO TOWARDS THE NEAREST UNEXPLORED AREA.", [ntp(rd_front, spaces=["SR", "door:RD"], kind="frontier")]),
        ("I", OC, "please turn to face west", [compass(b.pose(*OC)[2], 180)]),
        ("J", OC, "back, ten metres, move", {"any": ["clarify", [safe_move(b, OC, "backward")]]}),
        ("A", OD, "head towards the unexplored bit of this room, mate", [ntp(ps_front, spaces=["PS"], kind="frontier")]),
        ("B", OD, "right then, go out through the door on your right", [ntp(through(b, "PS", "SR"), spaces=["SR"], kind="through:PS")]),
        ("C", OE, "could you go out through the door and turn left, gently",
         [ntp(through(b, "WC", "SR"), spaces=["SR"], kind="through:WC"), rot_deg(90)]),
        ("D", OE, "okay, go to the biggest room", [ntp(R("SR"), spaces=["SR", "door:SR", "door:RD", "door:PS", "door:WC"])]),
        ("E", OF, "oya go to the opposite side of this room", [ntp(opposite(b, "MO", OF, "+y", min_depth=0.6), spaces=["MO"])]),
        ("F", OF, "go to the right corner lah", [ntp(side_corner(OF, sp["MO"][0], "right"), spaces=["MO"])]),
        ("G", OG, "and if we just pop through the door on the left", [ntp(through(b, "SR", "SR"), spaces=["SR"], kind="through:SR")]),
        ("H", OG, "GO TO THE SMALLEST ROOM PLEASE.", [ntp(R("WC"), spaces=["WC"])]),
        ("I", OI, "please go near to the obstacle on your right side", [ntp(next_to_in(TB, sp["ST"][0]), spaces=["ST"])]),
        ("J", OI, "forward to the left corner, move", [ntp(side_corner(OI, sp["ST"][0], "left"), spaces=["ST"])]),
        ("A", OI, "righto, go out through the door on your left", [ntp(through(b, "ST", "CH"), spaces=["CH"], kind="through:ST")]),
        ("B", OH, "right then, head for the nearest unexplored area", [ntp(ex_front, spaces=["CH", "door:EX"], kind="frontier")]),
        ("C", OB, "could you go to the room with the parcels", "clarify"),
        ("D", OA, "go to the photo booth", "clarify"),
        ("E", OC, "abeg go to the franking machine", "clarify"),
        ("F", OB, "face north can", [compass(b.pose(*OB)[2], 90)]),
        ("G", OD, "lovely, go to the middle of the biggest room", [ntp(circ(*mid_sr, MIDDLE), spaces=["SR"])]),
        ("H", OH, "PLEASE FACE SOUTH.", [compass(b.pose(*OH)[2], 270)]),
        ("I", OA, "please go to the middle of this room", [ntp(circ(*mid_ch, MIDDLE), spaces=["CH"])]),
        ("J", OF, "about face, forward through the door", [rot("any", 17, 19), ntp(through(b, "MO", "CH"), spaces=["CH"], kind="through:MO")]),
    ]
    assert side_corner(OF, sp["MO"][0], "right") == corner_reg((5.0, 12.0), sp["MO"][0])
    assert side_corner(OI, sp["ST"][0], "left") == corner_reg((5.2, 8.2), sp["ST"][0])
    assert 10.0 / 0.03 > safe_move(b, OC, "backward")["repeat"][1] + 30
    return b, C


# ================================================================== ferry passenger deck: tapered bow, rotated -23.7 deg, noisy
def ferry():
    b = Building("ferry", -1.0, -1.0, 40.0, 13.0, theta=-23.7, offset=(4.0, 18.0), seed=8237)
    b.shell(0.0, 0.0, 16.0, 12.0); b.shell(16.2, 0.0, 32.0, 12.0); b.shell(32.0, 1.0, 36.0, 11.0); b.shell(36.0, 3.0, 39.0, 9.0)
    b.space("CS", (0.0, 0.0, 2.0, 4.0))            # crew store (smallest; south end not scanned)
    b.space("WC", (2.2, 0.0, 5.5, 4.0))            # toilets
    b.space("KS", (5.7, 0.0, 10.0, 4.0))           # kiosk
    b.space("CF", (0.0, 4.2, 10.0, 12.0))          # cafeteria
    b.space("FY", (10.2, 0.0, 16.0, 12.0))         # foyer round the stairwell
    b.space("SL", (16.2, 0.0, 32.0, 12.0), (32.0, 1.0, 36.0, 11.0), (36.0, 3.0, 39.0, 9.0))   # seating lounge (biggest)
    b.door("CFD", 10.1, 8.0, "v", "FY", "CF", width=1.6)     # double door
    b.door("KSD", 10.1, 2.0, "v", "FY", "KS", width=1.0)
    b.door("WCD", 3.85, 4.1, "h", "CF", "WC", width=0.8)
    b.door("CSD", 1.0, 4.1, "h", "CF", "CS", width=0.7)
    b.door("SLD", 16.1, 6.0, "v", "FY", "SL", width=2.0)     # wide opening into the lounge
    b.door("ODN", 13.0, 12.1, "h", "FY", "OUT", width=1.2)   # doors to the open deck, never scanned
    b.door("ODS", 13.0, -0.1, "h", "FY", "OUT", width=1.2)
    b.carve()
    STW = (12.0, 4.5, 14.5, 7.5)                   # stairwell (railing all round)
    CC = (0.5, 10.5, 6.0, 11.3)                    # cafeteria counter
    CT1, CT2, CT3 = (2.0, 6.0, 3.2, 7.2), (5.0, 6.0, 6.2, 7.2), (7.5, 8.8, 8.7, 10.0)   # cafeteria tables
    KC = (5.7, 0.0, 9.5, 0.9)                      # kiosk counter, against the wall
    R1 = (18.0, 1.5, 30.0, 2.1)                    # seat rows; rows 2 and 3 split by a 0.7 m gap
    R2a, R2b = (18.0, 4.0, 23.5, 4.6), (24.2, 4.0, 30.0, 4.6)
    R3a, R3b = (18.0, 7.4, 23.5, 8.0), (24.2, 7.4, 30.0, 8.0)
    R4 = (18.0, 9.9, 30.0, 10.5)
    LR = (33.5, 8.0, 35.0, 9.2)                    # luggage rack
    for o in (STW, CC, CT1, CT2, CT3, KC, R1, R2a, R2b, R3a, R3b, R4, LR):
        b.rect(*o, OCC)
    UNK_CS = (0.0, 0.0, 2.0, 1.2)
    UNK_BOW = (37.3, 3.0, 39.0, 9.0)
    b.unknown(*UNK_CS); b.unknown(*UNK_BOW)
    hollow(b)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    FD_ = ["CFD", "KSD", "SLD", "ODN", "ODS"]
    FA = (11.0, 10.5, 270)    # foyer, north-west, facing south
    FB = (17.4, 6.0, 0)       # lounge, just inside, facing east (the 2 m opening 1.3 m behind)
    FC = (23.85, 3.0, 90)     # lounge, the gap in row 2 straight ahead
    FDp = (33.5, 6.0, 0)      # lounge, bow, facing east
    FE = (8.0, 7.5, 180)      # cafeteria, facing west
    FG = (4.1, 5.0, 90)       # cafeteria, between two tables, facing north
    FH = (7.0, 2.5, 0)        # kiosk, facing east (its door ahead)
    FI = (1.0, 3.0, 270)      # crew store, facing south (the unscanned end ahead)
    FJ = (3.85, 2.0, 90)      # toilets, facing north (the door ahead)
    for doors in (FD_, FD_[:3]):                     # the open-deck doors counted or not
        assert nth(b, FA, doors, "right", 1) == "CFD" and nth(b, FA, doors, "right", 2) == "KSD"
        assert nth(b, FA, doors, "right", 3) is None and nth(b, FA, doors, "left", 4) is None
    assert abs(rel(FB, 16.1, 6.0)[3]) > 170 and abs(rel(FE, 10.1, 8.0)[3]) > 150 and abs(rel(FH, 10.1, 2.0)[3]) < 15
    assert abs(rel(FJ, 3.85, 4.1)[3]) < 2
    areas = {n: b.area(n) for n in sp}
    assert max(areas, key=areas.get) == "SL" and sorted(areas.values())[-2] < areas["SL"] - 100
    assert min(areas, key=areas.get) == "CS" and sorted(areas.values())[1] - areas["CS"] > 5
    # FA: nearest unexplored = the open deck beyond the north door; the stairwell ahead-left, the only obstacle there
    assert frontier_dist(FA, (12.4, 12.2, 13.6, 12.4)) + 5 < min(frontier_dist(FA, UNK_CS), frontier_dist(FA, (12.4, -0.4, 13.6, -0.2)))
    assert 15 < rel(FA, 13.25, 6.0)[3] < 45
    # FB: rows 2a and 3a the two nearest obstacles
    obs = dict(R1=R1, R2a=R2a, R2b=R2b, R3a=R3a, R3b=R3b, R4=R4)
    assert set(nearest_obstacles(FB, obs, 2)) == {"R2a", "R3a"}
    # FDp: the luggage rack is the nearest obstacle on the left (rows 3b / 4 farther)
    assert rel(FDp, 34.25, 8.6)[1] > 0.3
    edge = lambda o, p: math.hypot(min(max(p[0], o[0]), o[2]) - p[0], min(max(p[1], o[1]), o[3]) - p[1])
    assert edge(LR, FDp) + 1.0 < min(edge(R3b, FDp), edge(R4, FDp))
    # FG: CT1, CT2 the two nearest obstacles; FH: the kiosk counter on the right
    assert set(nearest_obstacles(FG, dict(CT1=CT1, CT2=CT2, CT3=CT3, CC=CC), 2)) == {"CT1", "CT2"}
    assert rel(FH, 7.75, 0.65)[1] < -0.3
    assert abs(rel(FC, 23.85, 4.3)[3]) < 2
    mid_cf = b.centroid("CF")
    odn_front = band(12.55, 11.15, 13.45, 11.95)
    bow_front = band(36.3, 3.15, 37.25, 8.85)
    cs_front = band(0.15, 1.25, 1.85, 2.15)
    gap_n = within2((23.6, 4.75, 24.1, 6.2), 23.85, 4.3)
    C = [
        ("A", FA, "righto, go to the first door on your right", [ntp(D("CFD"), spaces=["FY", "CF", "door:CFD"])]),
        ("B", FA, "right then, the fourth door on the left, mate", "clarify"),
        ("C", FA, "could you go through the second door on your right, carefully",
         [ntp(thr(b, "KSD", "KS"), spaces=["KS"], kind="through:KSD")]),
        ("D", FA, "okay, go to the nearest unexplored area", [ntp(odn_front, spaces=["FY", "door:ODN"], kind="frontier")]),
        ("E", FA, "oya face east side", [compass(b.pose(*FA)[2], 0)]),
        ("F", FB, "go through the door behind you lah", [ntp(thr(b, "SLD", "FY"), spaces=["FY"], kind="through:SLD")]),
        ("G", FB, "lovely, and if we go halfway between the two closest obstacles", [ntp(circ(*mid(R2a, R3a), BETWEEN), spaces=["SL"])]),
        ("H", FB, "GO TO THE DOOR BEHIND YOU.", [ntp(D("SLD"), spaces=["FY", "SL", "door:SLD"])]),
        ("I", FC, "please go through the narrow gap in front", [ntp(gap_n, spaces=["SL"])]),
        ("J", FC, "back, twenty metres, move", {"any": ["clarify", [safe_move(b, FC, "backward")]]}),
        ("A", FDp, "head towards the unexplored bit up front, mate", [ntp(bow_front, spaces=["SL"], kind="frontier")]),
        ("B", FDp, "right then, go to the obstacle on your left", [ntp(next_to_in(LR, sp["SL"][1]), spaces=["SL"])]),
        ("C", FE, "could you go over to the left corner of this room, please, slowly", [ntp(side_corner(FE, sp["CF"][0], "left"), spaces=["CF"])]),
        ("D", FE, "okay, go to the middle of this room", [ntp(circ(*mid_cf, MIDDLE), spaces=["CF"])]),
        ("E", FG, "oya go between the two nearest obstacles", [ntp(circ(*mid(CT1, CT2), BETWEEN), spaces=["CF"])]),
        ("F", FG, "go to opposite side of this room lah", [ntp(opposite(b, "CF", FG, "+y"), spaces=["CF"])]),
        ("G", FH, "lovely, let's pop next to the obstacle on the right", [ntp(next_to_in(KC, sp["KS"][0]), spaces=["KS"])]),
        ("H", FI, "GO TOWARDS THE UNEXPLORED PART AHEAD.", [ntp(cs_front, spaces=["CS"], kind="frontier")]),
        ("I", FJ, "please go out from this room, then turn right",
         [ntp(thr(b, "WCD", "CF"), spaces=["CF"], kind="through:WCD"), rot_deg(-90)]),
        ("J", FE, "forward, to the nearest corner, move", [ntp(nearest_corner(FE, sp["CF"][0]), spaces=["CF"])]),
        ("A", FB, "righto, go to the smallest room", [ntp(R("CS"), spaces=["CS"])]),
        ("B", FE, "right then, go through the door behind you, mate", [ntp(thr(b, "CFD", "FY"), spaces=["FY"], kind="through:CFD")]),
        ("C", FDp, "could you go to the captain's bridge", "clarify"),
        ("D", FB, "okay chat, go to the gift shop", "clarify"),
        ("E", FG, "abeg go to the car deck", "clarify"),
        ("F", FDp, "turn face north side can", [compass(b.pose(*FDp)[2], 90)]),
        ("G", FA, "lovely, and if we go next to the obstacle in front", [ntp(next_to_in(STW, sp["FY"][0]), spaces=["FY"])]),
        ("H", FB, "TURN TO FACE SOUTH.", [compass(b.pose(*FB)[2], 270)]),
        ("I", FH, "please go to the biggest room", [ntp(R("SL"), spaces=["SL"])]),
        ("J", FH, "forward, through the door in front, then left, face",
         [ntp(thr(b, "KSD", "FY"), spaces=["FY"], kind="through:KSD"), rot_deg(90)]),
    ]
    assert side_corner(FE, sp["CF"][0], "left") == corner_reg((0.0, 4.2), sp["CF"][0])
    assert nearest_corner(FE, sp["CF"][0]) == corner_reg((10.0, 4.2), sp["CF"][0])
    assert 20.0 / 0.03 > safe_move(b, FC, "backward")["repeat"][1] + 30
    return b, C


BUILDINGS = lambda: [(police, "pol"), (postoffice, "pst"), (ferry, "fer")]

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
