#!/usr/bin/env python3
"""Draws three new buildings -- an airport gate area (drawn ROTATED 28.6 deg with lidar-like noise, fixed
seed; a GLASS front whose wall returns have gaps onto the never-scanned apron; a jet bridge whose far end
was never scanned), a fire station whose outline is an L (NON-RECTANGULAR: apparatus bay with two engines
and a 0.7 m passage between an engine and a locker block, a living-quarters wing with a corridor, a hose
tower), and a kindergarten (stepped, non-rectangular outline, ROTATED -8.4 deg with noise; doors of
VARIED width 0.7 .. 1.5 m, a 0.65 m gap between two low shelves, an unscanned corner of the playroom) --
and writes buildings.jsonl, 30 cases each.  Every expected region is checked on the drawn map
(bld_check.check) and an oracle output built from the expectations is scored.  Drawing / geometry / check
helpers (bld_*.py) and the helpers nth, room_cells, opposite, next_to, within2, mid, nearest_obstacles,
frontier_dist are copied from the sixth blind set; the buildings and prompts are new.

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


# ================================================================== airport gate area, rotated 28.6 deg, noisy
def gate():
    b = Building("gate", -1.0, -7.5, 28.0, 19.5, theta=28.6, offset=(3.0, 2.0), seed=7286)
    b.shell(0.0, -6.0, 26.0, 12.0); b.shell(19.2, 12.0, 20.8, 18.0)
    b.space("GL", (0.0, 0.0, 26.0, 12.0))          # gate lounge (biggest), glass front to the north
    b.space("CF", (0.0, -6.0, 8.0, -0.2))          # cafe
    b.space("WC", (8.2, -6.0, 11.0, -0.2))         # toilets
    b.space("NR", (11.2, -3.2, 13.8, -0.2))        # nursing room (smallest)
    b.space("CR", (14.2, -6.0, 20.0, -0.2))        # crew room
    b.space("SR", (20.2, -4.0, 26.0, -0.2))        # storage
    b.space("JB", (19.2, 12.2, 20.8, 18.0))        # jet bridge (far end not scanned)
    b.door("CF", 4.0, -0.1, "h", "GL", "CF", width=1.2)    # double door
    b.door("WC", 9.6, -0.1, "h", "GL", "WC", width=0.9)
    b.door("NR", 12.5, -0.1, "h", "GL", "NR", width=0.8)
    b.door("CR", 17.0, -0.1, "h", "GL", "CR", width=1.0)
    b.door("SR", 23.5, -0.1, "h", "GL", "SR", width=0.9)
    b.door("JB", 20.0, 12.1, "h", "GL", "JB", width=1.0)    # boarding door to the 1.6 m bridge
    b.door("EN", -0.1, 6.0, "v", "GL", "OUT", width=3.0)   # 3 m opening to the concourse, never scanned
    b.carve()
    gaps = glass_gaps(b, 0.0, 18.0, 12.0)
    SA1, SA2 = (3.0, 3.0, 9.0, 3.6), (3.0, 6.0, 9.0, 6.6)       # seat rows, west block
    SB1, SB2 = (12.0, 3.0, 17.0, 3.6), (12.0, 6.0, 17.0, 6.6)   # seat rows, east block
    PD = (21.5, 8.0, 24.0, 8.8)                                  # gate podium
    CC, FS = (0.5, -2.0, 5.0, -1.4), (5.7, -2.0, 7.5, -1.4)      # cafe counter + fridge shelf, 0.7 m gap
    CT1, CT2 = (1.2, -5.2, 2.2, -4.4), (3.6, -5.2, 4.6, -4.4)    # cafe tables
    CT = (16.0, -4.0, 18.5, -2.5)                                # crew room table
    SS = (21.0, -3.8, 25.5, -3.0)                                # storage shelves
    for o in (SA1, SA2, SB1, SB2, PD, CC, FS, CT1, CT2, CT, SS):
        b.rect(*o, OCC)
    UNK_CF = (6.5, -6.0, 8.0, -4.8)                # cafe corner not scanned
    UNK_JB = (19.2, 15.8, 20.8, 18.0)              # far end of the jet bridge not scanned
    b.unknown(*UNK_CF); b.unknown(*UNK_JB)
    hollow(b)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    LD = ["CF", "WC", "NR", "CR", "SR", "JB", "EN"]
    GA = (1.0, 1.5, 0)        # lounge, south-west, facing east
    GB = (24.5, 10.5, 180)    # lounge, north-east, facing west
    GC = (3.0, -3.3, 0)       # cafe, south of the counter, facing east
    GD = (20.0, 14.5, 270)    # jet bridge, facing south (the lounge ahead)
    GE = (12.5, -2.5, 90)     # nursing room, facing north (its door ahead)
    GF = (17.0, -5.3, 90)     # crew room, facing north (the table ahead)
    GH = (11.0, 1.5, 90)      # lounge, between the seat blocks, facing north
    GI = (11.5, 10.0, 0)      # lounge, north part near the glass front, facing east
    for doors in (LD, LD[:-1]):                     # the 3 m concourse opening counted as a door or not
        assert nth(b, GA, doors, "right", 2) == "WC" and nth(b, GA, doors, "right", 4) == "CR"
        assert nth(b, GA, doors, "right", -1) == "SR" and nth(b, GA, doors, "right", 6) is None
        assert nth(b, GB, doors, "left", 1) == "SR" and nth(b, GB, doors, "left", 3) == "NR"
        assert nth(b, GB, doors, "right", 1) == "JB" and nth(b, GB, doors, "right", 2) is None
    areas = {n: b.area(n) for n in sp if n != "JB"}
    assert max(areas, key=areas.get) == "GL" and min(areas, key=areas.get) == "NR"
    assert sorted(areas.values())[-2] < areas["GL"] - 100
    # GD: the jet bridge door is straight ahead; the bridge's unscanned end is the nearest unexplored area
    assert abs(rel(GD, 20.0, 12.1)[3]) < 5
    assert frontier_dist(GD, UNK_JB) + 1.5 < min(math.hypot(20.0 - g[1], 14.5 - 12.1) for g in gaps)
    # GI: nearest unexplored = the outside, seen through the glass gaps (same area as beyond the 3 m opening)
    glass_d = min(frontier_dist(GI, (g[0], 12.0, g[1], 12.2)) for g in gaps)
    assert glass_d + 3 < min(frontier_dist(GI, UNK_JB), frontier_dist(GI, UNK_CF))
    # GA: the nearest unexplored area is the outside (beyond the 3 m opening); nearest obstacle SA1
    assert frontier_dist(GA, (-1.0, 4.5, -0.2, 7.5)) + 3 < frontier_dist(GA, UNK_CF)
    obs = dict(SA1=SA1, SA2=SA2, SB1=SB1, SB2=SB2, PD=PD)
    assert nearest_obstacles(GA, obs, 1) == ["SA1"]
    assert set(nearest_obstacles(GH, obs, 2)) == {"SA1", "SB1"}
    # GH: SB1 is the nearest obstacle on the right
    assert rel(GH, 14.5, 3.3)[1] < 0 and rel(GH, 6.0, 3.3)[1] > 0 and rel(GH, 14.5, 6.3)[1] < 0
    # GC: the counter/shelf gap is on the left, ahead; GF: the table is straight ahead
    assert 15 < rel(GC, 5.35, -1.7)[3] < 60 and abs(rel(GF, 17.25, -3.25)[3]) < 10
    # GE: the only door of the nursing room is ahead
    assert abs(rel(GE, 12.5, -0.1)[3]) < 5
    mid_gl = b.centroid("GL")
    en_front = band(0.0, 4.65, 0.7, 7.35)
    glass_front = [poly(g[0] - 0.4, 11.25, g[1] + 0.4, 11.95) for g in gaps]
    outside = {"any": [en_front] + glass_front}
    cf_front = band(5.6, -5.85, 6.45, -4.85)
    jb_front = band(19.35, 15.0, 20.65, 15.75)
    gap_n = within2((5.0, -1.35, 5.7, -0.3), 5.35, -1.7)
    C = [
        ("A", GA, "okay, gently, can you go to the second door on your right", [ntp(D("WC"), spaces=["GL", "WC", "door:WC"])]),
        ("B", GA, "advance through the fourth door on your right", [ntp(through(b, "CR", "CR"), spaces=["CR"], kind="through:CR")]),
        ("C", GA, "okay robot, go to the last door on the right, no, sam, leave it", [ntp(D("SR"), spaces=["GL", "SR", "door:SR"])]),
        ("H", GA, "6th door on the right pls 🙏", "clarify"),
        ("D", GB, "aye, go tae the first door on yer left", [ntp(D("SR"), spaces=["GL", "SR", "door:SR"])]),
        ("J", GB, "make your way through the door on your starboard side", [ntp(through(b, "JB", "JB"), spaces=["JB"], kind="through:JB")]),
        ("F", GB, "point your nose south", [compass(b.pose(*GB)[2], 270)]),
        ("G", GB, "carpet's stained all along here, noted. okay, go to the third door on your left",
         [ntp(D("NR"), spaces=["GL", "NR", "door:NR"])]),
        ("I", GB, "Go to the corner at the left of this room.", [ntp(side_corner(GB, sp["GL"][0], "left"), spaces=["GL"])]),
        ("H", GC, "thru the narrow gap on ur left", [ntp(gap_n, spaces=["CF"])]),
        ("A", GC, "could you go to the unexplored part of this room, gently", [ntp(cf_front, spaces=["CF"], kind="frontier")]),
        ("C", GC, "robot, go to the biggest room, ben, shoes on please", [ntp(R("GL"), spaces=["GL"])]),
        ("D", GD, "aye, go tae the door in front o' ye", [ntp(D("JB"), spaces=["GL", "JB", "door:JB"])]),
        ("F", GD, "head for the nearest unexplored area", [ntp(jb_front, spaces=["JB"], kind="frontier")]),
        ("B", GD, "advance through the door ahead of you", [ntp(through(b, "JB", "GL"), spaces=["GL"], kind="through:JB")]),
        ("E", GE, "kindly go to the biggest room", [ntp(R("GL"), spaces=["GL"])]),
        ("G", GE, "nursing chair looks fine, no damage. okay, go out through the door and turn right",
         [ntp(through(b, "NR", "GL"), spaces=["GL"], kind="through:NR"), rot_deg(-90)]),
        ("I", GE, "Go to the corner at your right.", [ntp(side_corner(GE, sp["NR"][0], "right"), spaces=["NR"])]),
        ("J", GF, "make your way alongside the obstacle dead ahead", [ntp(next_to(CT), spaces=["CR"])]),
        ("A", GF, "okay, gently, go to the opposite side of the room", [ntp(opposite(b, "CR", GF, "+y"), spaces=["CR"])]),
        ("H", GF, "go to left corner 👈", [ntp(side_corner(GF, sp["CR"][0], "left"), spaces=["CR"])]),
        ("C", GH, "robot, go halfway between the two closest obstacles, mason, stop climbing",
         [ntp(circ(*mid(SA1, SB1), BETWEEN), spaces=["GL"])]),
        ("E", GH, "go near to the obstacle on your right side", [ntp(next_to(SB1), spaces=["GL"])]),
        ("F", GH, "point your nose east", [compass(b.pose(*GH)[2], 0)]),
        ("G", GB, "base of the gate desk is swollen, can you go over to the gate desk", "clarify"),
        ("J", GA, "make your way over to the duty free shop", "clarify"),
        ("I", GA, "Go back of five meters.", {"any": ["clarify", [safe_move(b, GA, "backward")]]}),
        ("D", GI, "aye, go tae the nearest unexplored bit", [ntp(outside, spaces=["GL", "door:EN"], kind="frontier")]),
        ("B", GB, "advance to the middle of this room", [ntp(circ(*mid_gl, MIDDLE), spaces=["GL"])]),
        ("E", GA, "kindly go near to the nearest obstacle", [ntp(next_to(SA1), spaces=["GL"])]),
    ]
    assert side_corner(GB, sp["GL"][0], "left") == corner_reg((0.0, 0.0), sp["GL"][0])
    assert side_corner(GE, sp["NR"][0], "right") == corner_reg((13.8, -0.2), sp["NR"][0])
    assert side_corner(GF, sp["CR"][0], "left") == corner_reg((14.2, -0.2), sp["CR"][0])
    assert 5.0 / 0.03 > safe_move(b, GA, "backward")["repeat"][1] + 30
    return b, C


# ================================================================== fire station: L-shaped outline, axis-aligned
def firestation():
    b = Building("firestation", -1.0, -1.5, 24.0, 27.5)
    b.shell(0.0, 0.0, 20.0, 12.0); b.shell(0.0, 12.2, 10.0, 26.0); b.shell(20.2, 8.2, 22.4, 11.8)
    b.space("BAY", (0.0, 0.0, 20.0, 12.0))         # apparatus bay (biggest)
    b.space("HW", (4.0, 12.2, 5.8, 26.0))          # quarters corridor, 1.8 m
    b.space("D1", (0.0, 12.2, 3.8, 17.0)); b.space("D2", (0.0, 17.2, 3.8, 21.5))   # dormitories
    b.space("BA", (0.0, 21.7, 3.8, 26.0))          # bathroom
    b.space("DY", (6.0, 12.2, 10.0, 18.5))         # day room / kitchen
    b.space("OF", (6.0, 18.7, 10.0, 26.0))         # office (north part not scanned)
    b.space("TW", (20.2, 8.2, 22.4, 11.8))         # hose tower (smallest)
    b.door("BD1", 5.5, -0.1, "h", "BAY", "OUT", width=4.0)   # open roll-up bay door, outside never scanned
    b.door("HWD", 4.9, 12.1, "h", "BAY", "HW", width=1.2)
    b.door("BDY", 8.0, 12.1, "h", "BAY", "DY", width=0.9)
    b.door("TW", 20.1, 10.0, "v", "BAY", "TW", width=0.7)
    b.door("D1", 3.9, 14.5, "v", "HW", "D1", width=0.9)
    b.door("D2", 3.9, 19.3, "v", "HW", "D2", width=0.9)
    b.door("BA", 3.9, 23.8, "v", "HW", "BA", width=0.8)
    b.door("DY", 5.9, 15.0, "v", "HW", "DY", width=1.6)     # double door
    b.door("OF", 5.9, 22.0, "v", "HW", "OF", width=0.9)
    b.carve()
    E1, E2 = (4.3, 1.5, 6.8, 9.5), (10.5, 1.5, 13.0, 9.5)    # two engines, nose to the bay doors
    LK = (13.7, 4.0, 14.4, 6.0)                    # locker block: 0.7 m passage beside engine 2
    WB = (15.5, 0.6, 18.5, 1.3)                    # workbench
    CP = (18.8, 5.0, 19.6, 5.8)                    # compressor
    DT = (7.2, 14.5, 9.0, 16.0)                    # day-room table
    KC = (9.4, 16.5, 10.0, 18.3)                   # kitchen counter
    B1, B2 = (0.2, 12.4, 2.2, 13.4), (0.2, 19.8, 2.2, 20.8)  # beds
    DK = (7.0, 19.2, 9.0, 20.0)                    # office desk
    for o in (E1, E2, LK, WB, CP, DT, KC, B1, B2, DK):
        b.rect(*o, OCC)
    UNK_OF = (6.0, 24.5, 10.0, 26.0)
    b.unknown(*UNK_OF)
    hollow(b)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    HD = ["HWD", "D1", "D2", "BA", "DY", "OF"]
    DD = ["DY", "BDY"]
    FA = (4.9, 12.8, 90)      # corridor, south end, facing north (the bay door to the corridor on its heading line)
    FB = (1.5, 6.0, 0)        # bay, west, facing east (engine 1 ahead)
    FC = (13.35, 2.6, 90)     # bay, south mouth of the engine / locker passage, facing north
    FD = (8.5, 17.5, 180)     # day room, facing west
    FE = (2.0, 24.5, 270)     # bathroom, facing south
    FF = (7.0, 23.5, 90)      # office, facing north (the unscanned part ahead)
    FG = (21.3, 9.0, 90)      # hose tower, facing north
    FH = (17.0, 6.0, 270)     # bay, east part, facing south
    assert nth(b, FA, HD, "left", 2) == "D2" and nth(b, FA, HD, "left", -1) == "BA"
    assert nth(b, FA, HD, "right", 1) == "DY" and nth(b, FA, HD, "right", 2) == "OF" and nth(b, FA, HD, "right", 3) is None
    assert nth(b, FD, DD, "left", 1) == "DY" and nth(b, FD, DD, "left", 2) == "BDY" and nth(b, FD, DD, "right", 1) is None
    areas = {n: b.area(n) for n in sp if n != "HW"}
    assert max(areas, key=areas.get) == "BAY" and min(areas, key=areas.get) == "TW"
    assert sorted(areas.values())[-2] < areas["BAY"] - 100 and sorted(areas.values())[1] - areas["TW"] > 5
    # FA after turning round: the corridor door to the bay is the only door ahead
    assert [n for n in HD if abs(rel((4.9, 12.8, 270), b.doors[n]["x"], b.doors[n]["y"])[3]) < 60] == ["HWD"]
    # FB: engine 1 straight ahead; nearest unexplored = outside beyond the open bay door
    assert abs(rel(FB, 5.55, 5.5)[3]) < 10
    assert frontier_dist(FB, (3.5, -1.0, 7.5, -0.2)) + 5 < frontier_dist(FB, UNK_OF)
    # FC: the passage (x 13.0 .. 13.7, y 4 .. 6) straight ahead
    assert abs(rel(FC, 13.35, 5.0)[3]) < 5
    # FD: the table is on the left (port), the counter behind / right
    assert rel(FD, 8.1, 15.25)[1] > 1.0 and abs(rel(FD, 9.7, 17.4)[3]) > 120
    # FF: the office door is behind (> 120 deg)
    assert abs(rel(FF, 5.9, 22.0)[3]) > 120
    # FE: the bathroom door; FG: the tower door
    mid_bay = b.centroid("BAY")
    of_front = band(6.15, 23.6, 9.85, 24.45)
    bd_front = band(3.65, -0.2, 7.35, 0.7)
    passage_n = within2((13.05, 6.15, 14.3, 7.4), 13.35, 6.0)   # past the north end of the passage
    C = [
        ("A", FA, "gently now, go to the second door on your left", [ntp(D("D2"), spaces=["HW", "D2", "door:D2"])]),
        ("B", FA, "advance through the last door on the left", [ntp(through(b, "BA", "BA"), spaces=["BA"], kind="through:BA")]),
        ("C", FA, "okay robot, first door on your right, go, mia, not now", [ntp(D("DY"), spaces=["HW", "DY", "door:DY"])]),
        ("D", FA, "aye, gonnae go through the second door on yer right", [ntp(through(b, "OF", "OF"), spaces=["OF"], kind="through:OF")]),
        ("E", FA, "kindly go to the third door on right side", "clarify"),
        ("F", FA, "yaw around and go through the door in front of you",
         [rot("any", 17, 19), ntp(through(b, "HWD", "BAY"), spaces=["BAY"], kind="through:HWD")]),
        ("G", FB, "paint's blistered on the engine side, okay, go next to the obstacle in front of you",
         [ntp(next_to(E1), spaces=["BAY"])]),
        ("H", FB, "go to middle of this room pls", [ntp(circ(*mid_bay, MIDDLE), spaces=["BAY"])]),
        ("I", FB, "Go to the corner which is at your left.", [ntp(side_corner(FB, sp["BAY"][0], "left"), spaces=["BAY"])]),
        ("J", FB, "make your way over to the hose reels", "clarify"),
        ("A", FC, "go through the narrow passage ahead, nice and slow", [ntp(passage_n, spaces=["BAY"])]),
        ("B", FC, "advance to the nearest corner", [ntp(nearest_corner(FC, sp["BAY"][0]), spaces=["BAY"])]),
        ("C", FH, "robot, back up eight metres, no, harper, that's mine", {"any": ["clarify", [safe_move(b, FH, "backward")]]}),
        ("D", FH, "face east, aye", [compass(b.pose(*FH)[2], 0)]),
        ("E", FH, "kindly go to the smallest room", [ntp(R("TW"), spaces=["TW"])]),
        ("F", FG, "exit through the door and yaw left", [ntp(through(b, "TW", "BAY"), spaces=["BAY"], kind="through:TW"), rot_deg(90)]),
        ("G", FG, "rust on the ladder rungs in here. okay, go to the biggest room", [ntp(R("BAY"), spaces=["BAY"])]),
        ("H", FD, "1st door on the left 👈", [ntp(D("DY"), spaces=["DY", "HW", "door:DY"])]),
        ("I", FD, "Go through the second door at your left.", [ntp(through(b, "BDY", "BAY"), spaces=["BAY"], kind="through:BDY")]),
        ("J", FD, "make your way alongside the obstacle on your port side", [ntp(next_to(DT), spaces=["DY"])]),
        ("A", FE, "okay, quietly, go out the door and then turn right",
         [ntp(through(b, "BA", "HW"), spaces=["HW"], kind="through:BA"), rot_deg(-90)]),
        ("B", FE, "advance to the right corner of this room", [ntp(side_corner(FE, sp["BA"][0], "right"), spaces=["BA"])]),
        ("C", FF, "okay robot, go towards the unexplored part in front of you, sorry, she's asking about the robot",
         [ntp(of_front, spaces=["OF"], kind="frontier")]),
        ("D", FF, "aye, go tae the door behind ye", [ntp(D("OF"), spaces=["OF", "HW", "door:OF"])]),
        ("E", FB, "turn towards south side", [compass(b.pose(*FB)[2], 270)]),
        ("F", FB, "head for the closest unexplored area", [ntp(bd_front, spaces=["BAY", "door:BD1"], kind="frontier")]),
        ("G", FH, "okay, can you go into the radio room", "clarify"),
        ("H", FE, "go to the biggest room pls", [ntp(R("BAY"), spaces=["BAY"])]),
        ("I", FH, "Go to the room with the beds.", "clarify"),
        ("J", FA, "make your way to the middle of the biggest room", [ntp(circ(*mid_bay, MIDDLE), spaces=["BAY"])]),
    ]
    assert side_corner(FB, sp["BAY"][0], "left") == corner_reg((20.0, 12.0), sp["BAY"][0])
    assert nearest_corner(FC, sp["BAY"][0]) == corner_reg((20.0, 0.0), sp["BAY"][0])
    assert side_corner(FE, sp["BA"][0], "right") == corner_reg((0.0, 21.7), sp["BA"][0])
    assert 8.0 / 0.03 > safe_move(b, FH, "backward")["repeat"][1] + 30
    return b, C


# ================================================================== kindergarten: stepped outline, rotated -8.4 deg, noisy
def kindergarten():
    b = Building("kindergarten", -1.0, -1.0, 25.0, 23.0, theta=-8.4, offset=(1.0, 4.0), seed=7084)
    b.shell(0.0, 8.0, 24.0, 10.0); b.shell(0.0, 10.2, 15.0, 18.0); b.shell(15.2, 10.2, 24.0, 22.0)
    b.shell(0.0, 5.4, 2.8, 7.8); b.shell(3.2, 3.0, 10.0, 7.8); b.shell(10.2, 4.5, 24.0, 7.8)
    b.space("CO", (0.0, 8.0, 24.0, 10.0))          # cloakroom corridor, 2.0 m
    b.space("CA", (0.0, 10.2, 8.0, 18.0))          # classroom A (two low shelves across it, a 0.65 m gap)
    b.space("CB", (8.2, 10.2, 15.0, 18.0))         # classroom B
    b.space("PH", (15.2, 10.2, 24.0, 22.0))        # playroom (biggest; north-west part not scanned)
    b.space("WC", (0.0, 5.4, 2.8, 7.8))            # toilets (smallest)
    b.space("NP", (3.2, 3.0, 10.0, 7.8))           # nap room
    b.space("KT", (10.2, 4.5, 15.0, 7.8))          # kitchen
    b.space("OF", (15.2, 4.5, 19.0, 7.8))          # office
    b.space("EN", (19.2, 4.5, 24.0, 7.8))          # entrance vestibule
    b.door("CA", 4.0, 10.1, "h", "CO", "CA", width=0.9)
    b.door("CB", 11.6, 10.1, "h", "CO", "CB", width=1.2)    # double door
    b.door("PH", 19.6, 10.1, "h", "CO", "PH", width=1.5)    # folding door, open
    b.door("WC", 1.5, 7.9, "h", "CO", "WC", width=0.7)
    b.door("NP", 6.5, 7.9, "h", "CO", "NP", width=0.8)
    b.door("KT", 12.6, 7.9, "h", "CO", "KT", width=0.9)
    b.door("OF", 17.1, 7.9, "h", "CO", "OF", width=0.8)
    b.door("EN", 21.6, 7.9, "h", "CO", "EN", width=1.4)
    b.door("CAB", 8.1, 16.0, "v", "CA", "CB", width=0.8)   # between the two classrooms
    b.door("EX", 21.6, 4.4, "h", "EN", "OUT", width=1.8)   # front door, outside never scanned
    b.carve()
    SH1, SH2 = (0.0, 14.0, 3.5, 14.4), (4.15, 14.0, 8.0, 14.4)  # low shelves across classroom A, 0.65 m gap
    T1, T2 = (1.0, 11.5, 2.5, 12.5), (5.0, 11.5, 6.5, 12.5)     # tables, classroom A
    T3, T4, T5 = (9.5, 12.0, 11.0, 13.0), (12.5, 12.0, 14.0, 13.0), (10.5, 15.5, 12.5, 16.5)   # classroom B
    CFR = (17.0, 14.0, 20.0, 17.0)                 # climbing frame
    HK = (6.0, 9.6, 10.5, 10.0)                    # coat hooks + bags along the corridor wall
    C1 = (4.0, 3.5, 9.5, 4.3)                      # row of cots
    KC = (10.4, 4.6, 14.8, 5.3)                    # kitchen counter
    OD = (16.5, 5.0, 18.5, 5.8)                    # office desk
    SB = (19.5, 6.8, 20.5, 7.6)                    # shoe bench
    for o in (SH1, SH2, T1, T2, T3, T4, T5, CFR, HK, C1, KC, OD, SB):
        b.rect(*o, OCC)
    UNK_PH = (15.2, 19.5, 18.0, 22.0)              # behind a curtain: not scanned
    b.unknown(*UNK_PH)
    hollow(b)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    CD = ["CA", "CB", "PH", "WC", "NP", "KT", "OF", "EN"]
    KA = (0.8, 9.0, 0)        # corridor, west end, facing east
    KB = (23.2, 9.0, 180)     # corridor, east end, facing west
    KC_ = (6.0, 17.0, 270)    # classroom A, behind the shelves, facing south
    KD = (20.0, 12.0, 90)     # playroom, just inside, facing north
    KE = (2.0, 6.5, 0)        # toilets, facing east
    KF = (11.0, 11.0, 90)     # classroom B, facing north
    KG = (21.5, 6.8, 270)     # vestibule, facing south (the front door ahead)
    KG2 = (21.0, 5.5, 270)    # vestibule, near the front door, facing south
    KH = (7.0, 5.0, 180)      # nap room, facing west
    assert nth(b, KA, CD, "right", 2) == "NP" and nth(b, KA, CD, "left", 3) == "PH" and nth(b, KA, CD, "left", 1) == "CA"
    assert nth(b, KA, CD, "right", -1) == "EN" and nth(b, KA, CD, "right", 1) == "WC" and nth(b, KA, CD, "left", 4) is None
    assert nth(b, KB, CD, "right", 2) == "CB" and nth(b, KB, CD, "left", 3) == "KT" and nth(b, KB, CD, "right", 1) == "PH"
    assert nth(b, KB, CD, "left", -1) == "WC"
    areas = {n: b.area(n) for n in sp if n != "CO"}
    assert max(areas, key=areas.get) == "PH" and min(areas, key=areas.get) == "WC"
    assert sorted(areas.values())[-2] < areas["PH"] - 30 and sorted(areas.values())[1] - areas["WC"] > 5
    # KC_: the shelf gap is on the right, the classroom door (CAB) on the left, nothing else near
    assert rel(KC_, 3.825, 14.2)[1] < -1.0 and rel(KC_, 8.1, 16.0)[1] > 1.0
    # KD: the climbing frame is ahead; the unscanned corner is the only unexplored part of the playroom
    assert abs(rel(KD, 18.5, 15.5)[3]) < 40
    # KF: T3 and T4 are the two nearest obstacles; T3 is the only one on the left
    obs = dict(T3=T3, T4=T4, T5=T5)
    assert set(nearest_obstacles(KF, obs, 2)) == {"T3", "T4"}
    assert rel(KF, 10.25, 12.5)[1] > 0 and rel(KF, 13.25, 12.5)[1] < 0 and rel(KF, 11.5, 16.0)[1] < 0
    # KG: the front door straight ahead; KE: the toilets' only door
    assert abs(rel(KG, 21.6, 4.4)[3]) < 5
    mid_ph = b.centroid("PH")
    ph_front = band(15.35, 18.6, 17.95, 19.45)
    ex_front = band(20.85, 4.45, 22.35, 5.2)
    gap_s = within2((3.45, 12.6, 4.2, 13.85), 3.825, 14.2)    # south of the shelves' gap
    C = [
        ("A", KA, "gently, go to the second door on your right", [ntp(D("NP"), spaces=["CO", "NP", "door:NP"])]),
        ("B", KA, "advance through the third door on your left", [ntp(through(b, "PH", "PH"), spaces=["PH"], kind="through:PH")]),
        ("C", KA, "okay robot, go to the first door on your left, ava, hands off", [ntp(D("CA"), spaces=["CO", "CA", "door:CA"])]),
        ("D", KA, "aye, go tae the last door on yer right", [ntp(D("EN"), spaces=["CO", "EN", "door:EN"])]),
        ("E", KA, "kindly go through the first door on right side", [ntp(through(b, "WC", "WC"), spaces=["WC"], kind="through:WC")]),
        ("H", KA, "4th door on the left pls", "clarify"),
        ("F", KB, "head through the second door on your right", [ntp(through(b, "CB", "CB"), spaces=["CB"], kind="through:CB")]),
        ("G", KB, "scuff marks all along this wall, fine. go to the third door on your left",
         [ntp(D("KT"), spaces=["CO", "KT", "door:KT"])]),
        ("I", KB, "Go to the first door at your right.", [ntp(D("PH"), spaces=["CO", "PH", "door:PH"])]),
        ("J", KB, "make your way to the last door on your port side", [ntp(D("WC"), spaces=["CO", "WC", "door:WC"])]),
        ("A", KC_, "can you go through the narrow gap on your right, gently", [ntp(gap_s, spaces=["CA"])]),
        ("B", KC_, "advance through the door on your left", [ntp(through(b, "CAB", "CB"), spaces=["CB"], kind="through:CAB")]),
        ("C", KC_, "okay robot, go to the biggest room, evie, shoes on", [ntp(R("PH"), spaces=["PH"])]),
        ("D", KD, "aye, head tae the unexplored bit o' this room", [ntp(ph_front, spaces=["PH"], kind="frontier")]),
        ("E", KD, "kindly go near to the obstacle in front", [ntp(next_to(CFR), spaces=["PH"])]),
        ("F", KD, "go to the right corner", [ntp(side_corner(KD, sp["PH"][0], "right"), spaces=["PH"])]),
        ("G", KD, "sand from the sandpit everywhere in here. okay, go to the middle of this room",
         [ntp(circ(*mid_ph, MIDDLE), spaces=["PH"])]),
        ("H", KE, "out the door then turn rt", [ntp(through(b, "WC", "CO"), spaces=["CO"], kind="through:WC"), rot_deg(-90)]),
        ("I", KE, "Go to the door of this room and after through it.",
         [ntp(through(b, "WC", "CO"), via=[D("WC")], spaces=["CO"], via_spaces=["WC", "CO", "door:WC"], kind="through:WC")]),
        ("J", KF, "make your way halfway between the two nearest obstacles", [ntp(circ(*mid(T3, T4), BETWEEN), spaces=["CB"])]),
        ("A", KF, "okay, go to the opposite side of this room, quietly, they're napping next door",
         [ntp(opposite(b, "CB", KF, "+y"), spaces=["CB"])]),
        ("B", KF, "advance next to the obstacle on your left", [ntp(next_to(T3), spaces=["CB"])]),
        ("C", KG, "robot, go towards the unexplored area ahead of you", [ntp(ex_front, spaces=["EN", "door:EX"], kind="frontier")]),
        ("D", KH, "aye, face north", [compass(b.pose(*KH)[2], 90)]),
        ("E", KH, "kindly go out of this room and turn left side",
         [ntp(through(b, "NP", "CO"), spaces=["CO"], kind="through:NP"), rot_deg(90)]),
        ("F", KH, "back off five metres", {"any": ["clarify", [safe_move(b, KH, "backward")]]}),
        ("G", KB, "okay, go to the staff room", "clarify"),
        ("H", KH, "go to the kitchen pls 🍎", "clarify"),
        ("I", KA, "Go to the room of the babies.", "clarify"),
        ("J", KG2, "make your way to the nearest corner", [ntp(nearest_corner(KG2, sp["EN"][0]), spaces=["EN"])]),
    ]
    assert side_corner(KD, sp["PH"][0], "right") == corner_reg((24.0, 22.0), sp["PH"][0])
    assert nearest_corner(KG2, sp["EN"][0]) == corner_reg((19.2, 4.5), sp["EN"][0])
    assert 5.0 / 0.03 > safe_move(b, KH, "backward")["repeat"][1] + 30
    return b, C


def main():
    out = []
    for fn, tag in ((gate, "gat"), (firestation, "fst"), (kindergarten, "kdg")):
        b, C = fn()
        assert len(C) == 30, (tag, len(C))
        for s in "ABCDEFGHIJ":
            assert sum(1 for c in C if c[0] == s) == 3, (tag, s)
        for i, (spk, pose, prompt, exp) in enumerate(C, 1):
            out.append((b, tag, i, spk, pose, prompt, exp))
    bld_check.write(out)


if __name__ == "__main__":
    main()
