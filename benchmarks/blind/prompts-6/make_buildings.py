#!/usr/bin/env python3
"""Draws three new buildings -- a railway station concourse (drawn ROTATED -37 deg with lidar-like noise,
fixed seed), a courthouse whose outline is a CROSS (non-rectangular: foyer wing south, a central hall, a
west wing with a corridor and four rooms, a courtroom east, a notched north wing), and a theatre backstage
(NARROW passages -- a 0.65 m gap in the flats across the stage, a 0.65 m aisle between prop shelves -- and
doors of VARIED width: 0.7, 0.75, 0.8, 0.9, 1.0, 1.2, 2.4 m and a 6 m proscenium opening) -- and writes
buildings.jsonl, 30 cases each.  Every expected region is checked on the drawn map (bld_check.check) and
an oracle output built from the expectations is scored.  Drawing / geometry / check helpers (bld_*.py)
and the helpers nth, room_cells, opposite, next_to, within2, mid are copied from the fifth blind set; the
buildings and prompts are new.

Run: /work/main/.venv/bin/python make_buildings.py
"""
import math

import numpy as np

from bld_lib import (RES, OCC, FREE, UNK, AT_DOOR, MIDDLE, BETWEEN, Building, rel, circ, poly, ntp, rot,
                     rot_deg, face, move, compass, safe_move, STOP)
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


# ================================================================== station concourse, rotated -37 deg, noisy
def station():
    b = Building("station", -1.0, -1.5, 29.0, 18.0, theta=-37.0, offset=(2.0, 20.0), seed=6037)
    b.shell(0.0, 0.0, 28.0, 17.0)
    b.space("CO", (0.0, 0.0, 28.0, 11.0))          # concourse
    b.space("TO", (0.0, 11.2, 6.0, 17.0))          # ticket office
    b.space("WR", (6.2, 11.2, 15.0, 17.0))         # waiting room
    b.space("WC", (15.2, 11.2, 18.0, 17.0))        # toilets (smallest)
    b.space("LL", (18.2, 11.2, 28.0, 17.0))        # left luggage (north-east part not scanned)
    b.door("TO", 3.0, 11.1, "h", "CO", "TO"); b.door("WR", 10.5, 11.1, "h", "CO", "WR", width=1.2)
    b.door("WC", 16.6, 11.1, "h", "CO", "WC", width=0.8); b.door("LL", 21.0, 11.1, "h", "CO", "LL")
    b.door("EN", 14.0, -0.1, "h", "CO", "OUT", width=2.4)   # street entrance, outside never scanned
    b.carve()
    P = {f"P{i}": (x - 0.4, 5.1, x + 0.4, 5.9) for i, x in enumerate((5.0, 11.0, 17.0, 23.0), 1)}   # pillars
    TM = (1.0, 8.6, 4.0, 9.4)                      # ticket machines
    KI = (23.5, 1.0, 26.0, 3.0)                    # kiosk
    WB = (7.5, 15.4, 13.5, 16.0)                   # bench row in the waiting room
    RK = (19.0, 13.5, 22.0, 14.1)                  # luggage rack
    for o in list(P.values()) + [TM, KI, WB, RK, (0.5, 15.8, 5.5, 16.4)]:
        b.rect(*o, OCC)
    UNK_LL = (25.5, 14.0, 28.0, 17.0)
    b.unknown(*UNK_LL)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    CD = ["TO", "WR", "WC", "LL", "EN"]
    SA = (2.0, 2.0, 0)        # concourse, south-west, facing east
    SB = (26.0, 9.0, 180)     # concourse, north-east, facing west
    SE = (14.0, 0.8, 90)      # just inside the street entrance, facing north
    SC = (14.2, 13.5, 180)    # waiting room, east part, facing west
    SD = (19.5, 12.2, 90)     # left luggage, facing north (the rack ahead)
    SF = (2.0, 13.0, 0)       # ticket office, facing east
    SG = (16.6, 15.5, 270)    # toilets, facing south (the door ahead)
    for doors in (CD, CD[:-1]):                     # the street entrance counted as a door or not: same answers
        assert nth(b, SA, doors, "left", 2) == "WR" and nth(b, SA, doors, "left", 3) == "WC"
        assert nth(b, SA, doors, "left", 5) is None
        assert nth(b, SB, doors, "right", 1) == "LL" and nth(b, SB, doors, "right", 3) == "WR"
        assert nth(b, SB, doors, "right", -1) == "TO"
    areas = {n: b.area(n) for n in sp}
    assert max(areas, key=areas.get) == "CO" and min(areas, key=areas.get) == "WC"
    assert sorted(areas.values())[1] - areas["WC"] > 10 and sorted(areas.values())[-2] < areas["CO"] - 100
    # SA: nearest unexplored area is the outside beyond the entrance (frontier along y = -0.2)
    assert frontier_dist(SA, (12.8, -1.0, 15.2, -0.2)) + 5 < frontier_dist(SA, UNK_LL)
    # SE: the two closest obstacles are P2 and P3 (a clear gap to the third)
    obs = dict(P, TM=TM, KI=KI)
    assert set(nearest_obstacles(SE, obs, 2)) == {"P2", "P3"}
    # SD: the rack is the only obstacle in the room and it is in front
    assert abs(rel(SD, 20.5, 13.8)[3]) < 45
    mid_co = b.centroid("CO")
    front_en = band(12.9, -0.2, 15.1, 0.7)
    front_ll = band(24.6, 14.1, 25.45, 16.9)
    C = [
        ("A", SA, "robot, make your way to the second door on your left, over", [ntp(D("WR"), spaces=["CO", "WR", "door:WR"])]),
        ("H", SA, "thru 3rd door on left pls", [ntp(through(b, "WC", "WC"), spaces=["WC"], kind="through:WC")]),
        ("D", SA, "proceed toward the nearest unexplored area", [ntp(front_en, spaces=["CO", "door:EN"], kind="frontier")]),
        ("F", SA, "could you go to the centre of this room please", [ntp(circ(*mid_co, MIDDLE), spaces=["CO"])]),
        ("H", SA, "rt corner pls", [ntp(side_corner(SA, sp["CO"][0], "right"), spaces=["CO"])]),
        ("C", SB, "go over to the, um, the left corner", [ntp(side_corner(SB, sp["CO"][0], "left"), spaces=["CO"])]),
        ("E", SB, "first door on the right, go", [ntp(D("LL"), spaces=["CO", "LL", "door:LL"])]),
        ("B", SB, "go on through the third door on your right", [ntp(through(b, "WR", "WR"), spaces=["WR"], kind="through:WR")]),
        ("G", SB, "could you go to the last door on your right, if that's okay", [ntp(D("TO"), spaces=["CO", "TO", "door:TO"])]),
        ("J", SB, "take me to the ticket office, would you, i need to check something over there", "clarify"),
        ("I", SB, "Go to the room which is the smallest.", [ntp(R("WC"), spaces=["WC"])]),
        ("D", SB, "face south west, then hold", [compass(b.pose(*SB)[2], 225)]),
        ("A", SE, "go halfway between the two closest obstacles, over", [ntp(circ(*mid(P["P2"], P["P3"]), BETWEEN), spaces=["CO"])]),
        ("B", SE, "turn her north now", [compass(b.pose(*SE)[2], 90)]),
        ("G", SE, "um, could you go to the information desk, if that's okay", "clarify"),
        ("E", SD, "unexplored part of this room, head toward it", [ntp(front_ll, spaces=["LL"], kind="frontier")]),
        ("F", SD, "could you go next to the obstacle in front of you please", [ntp(next_to(RK), spaces=["LL"])]),
        ("I", SD, "Drive out of this room through the door and then turn you to the right.",
         [ntp(through(b, "LL", "CO"), spaces=["CO"], kind="through:LL"), rot_deg(-90)]),
        ("G", SC, "um, could you go to the middle of this room, if that's alright", [ntp(circ(*b.centroid("WR"), MIDDLE), spaces=["WR"])]),
        ("J", SF, "right, so, this room is lovely but i want you to leave it now, go out through the door, yes, that one",
         [ntp(through(b, "TO", "CO"), spaces=["CO"], kind="through:TO")]),
        ("A", SC, "go to the right corner, over", [ntp(side_corner(SC, sp["WR"][0], "right"), spaces=["WR"])]),
        ("C", SF, "go to the, uh, the right corner of this room", [ntp(side_corner(SF, sp["TO"][0], "right"), spaces=["TO"])]),
        ("B", SG, "go on out the door and turn left", [ntp(through(b, "WC", "CO"), spaces=["CO"], kind="through:WC"), rot_deg(90)]),
        ("D", SF, "proceed to the centre of the biggest room", [ntp(circ(*mid_co, MIDDLE), spaces=["CO"])]),
        ("H", SG, "go thru the door ahead then fwd 2m",
         [ntp(through(b, "WC", "CO"), spaces=["CO"], kind="through:WC"), move("forward", 2.0)]),
        ("E", SA, "fifth door on the left, go", "clarify"),
        ("J", SB, "now, the platform, you know, where the trains come in, could you take yourself over there", "clarify"),
        ("F", SD, "could you turn around and go through the door, please",
         [rot("any", 17, 19), ntp(through(b, "LL", "CO"), spaces=["CO"], kind="through:LL")]),
        ("I", SC, "Drive to the door of this room and then through it.",
         [ntp(through(b, "WR", "CO"), via=[D("WR")], spaces=["CO"], via_spaces=["WR", "CO", "door:WR"], kind="through:WR")]),
        ("D", SB, "back up five metres", {"any": ["clarify", [safe_move(b, SB, "backward")]]}),
    ]
    # corners: SA right = (28, 0); SB left = (0, 0); SC right = (6.2, 17); SF right = (6, 11.2)
    assert side_corner(SA, sp["CO"][0], "right") == corner_reg((28.0, 0.0), sp["CO"][0])
    assert side_corner(SB, sp["CO"][0], "left") == corner_reg((0.0, 0.0), sp["CO"][0])
    assert side_corner(SC, sp["WR"][0], "right") == corner_reg((6.2, 17.0), sp["WR"][0])
    assert side_corner(SF, sp["TO"][0], "right") == corner_reg((6.0, 11.2), sp["TO"][0])
    assert 5.0 / 0.03 > safe_move(b, SB, "backward")["repeat"][1] + 30       # five metres really hits the wall
    return b, C


# ================================================================== courthouse: cross-shaped outline, axis-aligned
def courthouse():
    b = Building("courthouse", -1.0, -1.5, 29.0, 23.0)
    b.shell(11.0, 0.0, 17.0, 7.8); b.shell(10.0, 8.0, 18.0, 16.0); b.shell(0.0, 6.0, 9.8, 18.0)
    b.shell(18.2, 6.0, 28.0, 18.0); b.shell(11.0, 16.2, 14.9, 22.0); b.shell(15.1, 16.2, 17.0, 19.0)
    b.space("FO", (11.0, 0.0, 17.0, 7.8))          # foyer (south wing)
    b.space("CH", (10.0, 8.0, 18.0, 16.0))         # central hall
    b.space("WK", (0.0, 11.0, 9.8, 13.0))          # west wing corridor
    b.space("JR", (0.0, 13.2, 5.0, 18.0)); b.space("JC", (5.2, 13.2, 9.8, 18.0))
    b.space("CL", (0.0, 6.0, 4.8, 10.8)); b.space("RR", (5.0, 6.0, 9.8, 10.8))
    b.space("CR", (18.2, 6.0, 28.0, 18.0))         # courtroom (biggest)
    b.space("HC", (11.0, 16.2, 14.9, 22.0)); b.space("IR", (15.1, 16.2, 17.0, 19.0))   # north wing; IR smallest
    b.door("EN", 14.0, -0.1, "h", "FO", "OUT", width=1.8)  # main entrance, outside never scanned
    b.door("FOCH", 14.0, 7.9, "h", "FO", "CH", width=2.0)
    b.door("CHW", 9.9, 12.0, "v", "CH", "WK", width=1.2)
    b.door("CHCR", 18.1, 12.0, "v", "CH", "CR", width=1.6)
    b.door("CHHC", 13.0, 16.1, "h", "CH", "HC"); b.door("CHIR", 16.0, 16.1, "h", "CH", "IR", width=0.8)
    b.door("JR", 2.5, 13.1, "h", "WK", "JR"); b.door("JC", 7.5, 13.1, "h", "WK", "JC")
    b.door("CL", 2.4, 10.9, "h", "WK", "CL"); b.door("RR", 7.0, 10.9, "h", "WK", "RR")
    b.carve()
    D1 = (11.0, 9.0, 12.5, 10.0)                   # desk in the hall
    S1, S2 = (13.0, 5.0, 13.8, 5.6), (14.5, 5.0, 15.3, 5.6)   # two obstacles in the foyer, 0.7 m gap
    FB = (11.3, 2.0, 12.0, 4.5)                    # bench in the foyer
    T1, T2, JB = (20.5, 9.0, 22.5, 10.0), (20.5, 14.0, 22.5, 15.0), (25.5, 9.0, 26.5, 15.0)
    JT = (1.0, 15.0, 3.0, 16.5)                    # table in JR
    for o in (D1, S1, S2, FB, T1, T2, JB, JT):
        b.rect(*o, OCC)
    UNK_RR = (8.0, 6.0, 9.8, 8.0)
    b.unknown(*UNK_RR)                             # south-east part of RR not scanned
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    WD = ["JR", "JC", "CL", "RR", "CHW"]
    HD = ["FOCH", "CHW", "CHCR", "CHHC", "CHIR"]
    CA = (1.0, 12.0, 0)       # west corridor, west end, facing east
    CW_ = (8.5, 11.6, 180)    # west corridor, east end, facing west (south of the hall door's axis)
    CB = (13.5, 2.5, 90)      # foyer, facing north
    CC = (15.0, 14.5, 0)      # hall, north part, facing east
    CD = (20.0, 7.5, 90)      # courtroom, south-west, facing north
    CE = (24.5, 16.8, 180)    # courtroom, north part, facing west
    CF = (4.0, 14.2, 90)      # JR, facing north
    CG = (5.8, 9.6, 0)        # RR, facing east
    assert nth(b, CA, WD, "left", 2) == "JC" and nth(b, CA, WD, "left", 6) is None
    assert nth(b, CA, WD, "right", 1) == "CL"
    assert nth(b, CW_, WD, "left", 1) == "RR" and nth(b, CW_, WD, "right", -1) == "JR"
    assert nth(b, CC, HD, "left", 1) == "CHIR" and nth(b, CC, HD, "right", 2) == "CHW" and nth(b, CC, HD, "right", 1) == "CHCR"
    areas = {n: b.area(n) for n in sp if n != "WK"}
    assert max(areas, key=areas.get) == "CR" and min(areas, key=areas.get) == "IR"
    assert sorted(areas.values())[-2] < areas["CR"] - 40 and sorted(areas.values())[1] - areas["IR"] > 10
    # CB: the 0.7 m gap between S1 and S2 and the hall door are ahead; nearest foyer corner (11, 0)
    assert abs(rel(CB, 14.15, 5.3)[3]) < 15 and abs(rel(CB, 14.0, 7.9)[3]) < 10
    # after turning round at CW_, the hall door is the only door ahead
    assert [n for n in WD if abs(rel((8.5, 11.6, 0), b.doors[n]["x"], b.doors[n]["y"])[3]) < 60] == ["CHW"]
    # CD: the nearest obstacle is T1 (clear margin); CF: JT is the only obstacle in JR, on the left
    ed = lambda p, o: math.hypot(min(max(p[0], o[0]), o[2]) - p[0], min(max(p[1], o[1]), o[3]) - p[1])
    assert ed(CD, T1) + 3 < min(ed(CD, T2), ed(CD, JB))
    assert rel(CF, 2.0, 15.75)[1] > 1.0
    # CA: 'the door on your right' = the nearest door with negative lateral offset = CL
    assert nth(b, CA, WD, "right", 1) == "CL"
    mid_ch, mid_cr = b.centroid("CH"), b.centroid("CR")
    gap_n = within2((13.7, 5.75, 14.6, 6.9), 14.15, 5.3)
    front_en = band(13.15, -0.2, 14.85, 0.7)
    front_rr = band(7.1, 6.1, 7.95, 7.9)
    C = [
        ("B", CA, "uh, go on to the second door on your left", [ntp(D("JC"), spaces=["WK", "JC", "door:JC"])]),
        ("C", CA, "go to the, um, the holding cells", "clarify"),
        ("H", CA, "thru 2nd door on rt", [ntp(through(b, "RR", "RR"), spaces=["RR"], kind="through:RR")]),
        ("J", CA, "well now, what i'd like, if it's not too much bother, is for you to find the biggest room in the "
                  "whole building and go in there", [ntp(R("CR"), spaces=["CR"])]),
        ("D", CW_, "proceed to the first door on your left", [ntp(D("RR"), spaces=["WK", "RR", "door:RR"])]),
        ("E", CW_, "last door on the right, go", [ntp(D("JR"), spaces=["WK", "JR", "door:JR"])]),
        ("G", CW_, "um, could you turn around and go through the door in front of you",
         [rot("any", 17, 19), ntp(through(b, "CHW", "CH"), spaces=["CH"], kind="through:CHW")]),
        ("A", CB, "go through the narrow gap ahead of you, over", [ntp(gap_n, spaces=["FO"])]),
        ("F", CB, "could you go through the door straight ahead and then to the middle of that room",
         [ntp(circ(*mid_ch, MIDDLE), spaces=["CH"])]),
        ("I", CB, "Drive to the corner which is most close to you.", [ntp(nearest_corner(CB, sp["FO"][0]), spaces=["FO"])]),
        ("C", CB, "go toward the, uh, the unexplored area behind you", [ntp(front_en, spaces=["FO", "door:EN"], kind="frontier")]),
        ("D", CC, "proceed through the first door on your left", [ntp(through(b, "CHIR", "IR"), spaces=["IR"], kind="through:CHIR")]),
        ("E", CC, "second door on your right, now", [ntp(D("CHW"), spaces=["CH", "WK", "door:CHW"])]),
        ("F", CC, "could you go to the smallest room, please", [ntp(R("IR"), spaces=["IR"])]),
        ("G", CC, "um, could you go into the biggest room and then to the middle of it",
         [ntp(circ(*mid_cr, MIDDLE), spaces=["CR"])]),
        ("H", CD, "go to rt corner", [ntp(side_corner(CD, sp["CR"][0], "right"), spaces=["CR"])]),
        ("A", CD, "head to the opposite side of the room, over", [ntp(opposite(b, "CR", CD, "+y"), spaces=["CR"])]),
        ("B", CD, "go on over next to the nearest obstacle", [ntp(next_to(T1), spaces=["CR"])]),
        ("C", CD, "um, face west", [compass(b.pose(*CD)[2], 180)]),
        ("E", CE, "leave the room through the door", [ntp(through(b, "CHCR", "CH"), spaces=["CH"], kind="through:CHCR")]),
        ("I", CF, "Drive next to the obstacle on your left side.", [ntp(next_to(JT), spaces=["JR"])]),
        ("J", CF, "and now, if you would, nip out through the door and then turn right, and that'll do for now",
         [ntp(through(b, "JR", "WK"), spaces=["WK"], kind="through:JR"), rot_deg(-90)]),
        ("D", CF, "proceed to the right corner", [ntp(side_corner(CF, sp["JR"][0], "right"), spaces=["JR"])]),
        ("F", CG, "would you head toward the unexplored part of this room, please",
         [ntp(front_rr, spaces=["RR"], kind="frontier")]),
        ("A", CG, "robot, go to the judge's chambers, over", "clarify"),
        ("G", CB, "could you go over to the witness stand, if that's okay", "clarify"),
        ("H", CA, "go thru the 6th door on ur left", "clarify"),
        ("B", CD, "back her up three metres there", {"any": ["clarify", [safe_move(b, CD, "backward")]]}),
        ("C", CC, "go to the, uh, first door on your right, and then through it",
         [ntp(through(b, "CHCR", "CR"), via=[D("CHCR")], spaces=["CR"], via_spaces=["CH", "CR", "door:CHCR"],
              kind="through:CHCR")]),
        ("E", CA, "through the door on your right, then come back through it",
         [ntp(through(b, "CL", "WK"), via=[through(b, "CL", "CL")], spaces=["WK"], via_spaces=["CL"], kind="through:CL")]),
    ]
    assert side_corner(CD, sp["CR"][0], "right") == corner_reg((28.0, 18.0), sp["CR"][0])
    assert side_corner(CF, sp["JR"][0], "right") == corner_reg((5.0, 18.0), sp["JR"][0])
    assert nearest_corner(CB, sp["FO"][0]) == corner_reg((11.0, 0.0), sp["FO"][0])
    assert 3.0 / 0.03 > safe_move(b, CD, "backward")["repeat"][1] + 30
    return b, C


# ================================================================== theatre backstage: narrow passages, varied doors
def theatre():
    b = Building("theatre", -1.0, -1.5, 25.0, 13.0)
    b.shell(0.0, 0.0, 15.6, 10.0); b.shell(15.8, 0.0, 24.0, 6.0); b.shell(15.8, 6.2, 22.0, 10.0)
    b.shell(16.0, 10.2, 18.3, 12.0)
    b.space("ST", (0.0, 0.0, 14.0, 10.0))          # stage (flats across it, a 0.65 m gap)
    b.space("BC", (14.2, 0.0, 15.6, 10.0))         # backstage corridor, 1.4 m
    b.space("DR1", (15.8, 0.0, 19.5, 3.0)); b.space("DR2", (15.8, 3.2, 19.5, 6.0))   # dressing rooms
    b.space("GR", (15.8, 6.2, 22.0, 10.0))         # green room
    b.space("PR", (19.7, 0.0, 24.0, 6.0))          # prop room (two shelf blocks, a 0.65 m aisle)
    b.space("LB", (16.0, 10.2, 18.3, 12.0))        # tiny booth north of the green room (smallest)
    b.door("PRO", 7.0, -0.1, "h", "ST", "OUT", width=6.0)   # proscenium: the auditorium was never scanned
    b.door("SD", 14.1, 2.0, "v", "ST", "BC", width=2.4)     # scene dock door
    b.door("SU", 14.1, 9.0, "v", "ST", "BC", width=0.8)
    b.door("D1", 15.7, 1.5, "v", "BC", "DR1", width=0.7)
    b.door("D2", 15.7, 4.6, "v", "BC", "DR2", width=0.75)
    b.door("DG", 15.7, 8.0, "v", "BC", "GR", width=1.0)
    b.door("DP", 21.0, 6.1, "h", "GR", "PR", width=0.9)
    b.door("DL", 17.0, 10.1, "h", "GR", "LB", width=0.7)
    b.carve()
    FL1, FL2 = (0.0, 8.0, 6.0, 8.3), (6.65, 8.0, 14.0, 8.3)   # flats; gap x 6.0..6.65
    PF = (3.0, 3.0, 6.0, 5.0)                      # platform on stage
    BX = (9.5, 5.5, 10.5, 6.5)                     # box on stage
    DT = (18.5, 0.2, 19.3, 2.0)                    # dressing table in DR1
    SO = (19.5, 9.0, 21.5, 9.8)                    # sofa in the green room
    PS1, PS2 = (19.7, 1.0, 20.9, 4.8), (21.55, 1.0, 24.0, 4.8)   # prop shelves; aisle x 20.9..21.55
    for o in (FL1, FL2, PF, BX, DT, SO, PS1, PS2):
        b.rect(*o, OCC)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    BD = ["SD", "SU", "D1", "D2", "DG"]
    TA = (14.9, 0.8, 90)      # corridor, south end, facing north
    TB = (10.5, 4.0, 180)     # stage, facing west
    TC = (17.3, 1.0, 180)     # DR1, facing west
    TD = (18.0, 7.5, 0)       # green room, facing east
    TE = (21.2, 5.5, 270)     # prop room, north of the shelves, facing south (the aisle ahead)
    TF = (2.0, 9.2, 0)        # upstage behind the flats, facing east
    TG = (17.2, 11.2, 270)    # booth, facing south
    assert nth(b, TA, BD, "right", 2) == "D2" and nth(b, TA, BD, "right", 3) == "DG" and nth(b, TA, BD, "right", 4) is None
    assert nth(b, TA, BD, "left", 1) == "SD" and nth(b, TA, BD, "left", -1) == "SU" and nth(b, TA, BD, "right", 1) == "D1"
    areas = {n: b.area(n) for n in sp if n != "BC"}
    assert max(areas, key=areas.get) == "ST" and min(areas, key=areas.get) == "LB"
    assert sorted(areas.values())[1] - areas["LB"] > 5
    # TB: nearest unexplored = the auditorium beyond the proscenium (frontier y = -0.2, x 4..10)
    assert rel(TB, 6.325, 8.15)[1] < -3 and abs(rel(TB, 4.5, 4.0)[3]) < 5 and abs(rel(TB, 10.0, 6.0)[3]) > 60
    assert rel(TF, 6.325, 8.15)[1] < -0.8
    assert nearest_corner(TC, sp["DR1"][0]) == corner_reg((15.8, 0.0), sp["DR1"][0])
    assert side_corner(TB, sp["ST"][0], "left") == corner_reg((0.0, 0.0), sp["ST"][0])
    assert abs(rel(TD, 17.0, 10.1)[3]) < 120 and rel(TD, 17.0, 10.1)[1] > 0     # DL: not behind, not right
    assert abs(rel((18.0, 7.5, 180), 17.0, 10.1)[3]) > 60                        # DL: not ahead after turning
    assert abs(rel(TD, 15.7, 8.0)[3]) > 120 and abs(rel(TD, 21.0, 6.1)[3]) < 120 and rel(TD, 21.0, 6.1)[1] < 0
    assert abs(rel(TD, 20.5, 9.4)[3]) < 60
    # after turning round in the green room, DG is ahead and DP is not
    assert abs(rel((18.0, 7.5, 180), 15.7, 8.0)[3]) < 30 and abs(rel((18.0, 7.5, 180), 21.0, 6.1)[3]) > 120
    mid_gr = b.centroid("GR")
    front_pro = band(4.1, -0.2, 9.9, 0.7)
    gap_up = within2((5.6, 8.45, 7.05, 9.9), 6.325, 8.15)     # north of the flats' gap
    gap_dn = within2((5.6, 6.4, 7.05, 7.85), 6.325, 8.15)     # south of the flats' gap
    aisle_s = within2((20.5, 0.15, 22.0, 0.95), 21.225, 1.0)  # south end of the prop aisle
    su_in = within2((12.6, 8.45, 14.0, 9.9), 14.1, 9.0)       # stage side of SU, behind the flats
    C = [
        ("A", TA, "second door on your right, go there, over", [ntp(D("D2"), spaces=["BC", "DR2", "door:D2"])]),
        ("B", TA, "go on through the third door on the right", [ntp(through(b, "DG", "GR"), spaces=["GR"], kind="through:DG")]),
        ("C", TA, "go through the, the first door on your left", [ntp(through(b, "SD", "ST"), spaces=["ST"], kind="through:SD")]),
        ("D", TA, "proceed through the last door on the left", [ntp(su_in, spaces=["ST"], kind="through:SU")]),
        ("E", TA, "smallest room, go", [ntp(R("LB"), spaces=["LB"])]),
        ("F", TB, "would you go toward the nearest unexplored area, please", [ntp(front_pro, spaces=["ST", "door:PRO"], kind="frontier")]),
        ("G", TB, "um, could you go through the narrow gap on your right", [ntp(gap_up, spaces=["ST"])]),
        ("H", TB, "go nxt to the obstacle in front", [ntp(next_to(PF), spaces=["ST"])]),
        ("I", TB, "Drive to the left corner of this room.", [ntp(side_corner(TB, sp["ST"][0], "left"), spaces=["ST"])]),
        ("J", TB, "now then, the piano, i'd love you to go and park yourself right beside the piano", "clarify"),
        ("A", TC, "exit through the door and turn left, over",
         [ntp(through(b, "D1", "BC"), spaces=["BC"], kind="through:D1"), rot_deg(90)]),
        ("B", TC, "head on over to the biggest room", [ntp(R("ST"), spaces=["ST"])]),
        ("C", TC, "go to the, um, nearest corner", [ntp(nearest_corner(TC, sp["DR1"][0]), spaces=["DR1"])]),
        ("D", TD, "proceed to the door behind you", [ntp(D("DG"), spaces=["GR", "BC", "door:DG"])]),
        ("E", TD, "next to the obstacle ahead, go", [ntp(next_to(SO), spaces=["GR"])]),
        ("F", TD, "could you go to the middle of this room, please", [ntp(circ(*mid_gr, MIDDLE), spaces=["GR"])]),
        ("G", TD, "um, could you turn around and then go through the door that's in front of you",
         [rot("any", 17, 19), ntp(through(b, "DG", "BC"), spaces=["BC"], kind="through:DG")]),
        ("H", TE, "go thru the narrow passage ahead", [ntp(aisle_s, spaces=["PR"])]),
        ("I", TE, "Drive out of this room and then to the smallest room.",
         [ntp(R("LB"), via=[through(b, "DP", "GR")], spaces=["LB"], via_spaces=["GR"])]),
        ("J", TE, "right then, if you'd be so good, turn yourself to face east, that's where i think the exit is, "
                  "or so i'm told", [compass(b.pose(*TE)[2], 0)]),
        ("A", TF, "go through the narrow gap on your right, over", [ntp(gap_dn, spaces=["ST"])]),
        ("B", TF, "face her south, would ya", [compass(b.pose(*TF)[2], 270)]),
        ("C", TG, "go out the, um, the door and then over to the biggest room",
         [ntp(R("ST"), via=[through(b, "DL", "GR")], spaces=["ST"], via_spaces=["GR"])]),
        ("D", TG, "report to the stage manager's desk", "clarify"),
        ("E", TA, "fourth door on your right, go", "clarify"),
        ("F", TA, "could you go through the first door on your right and then come back out through it",
         [ntp(through(b, "D1", "BC"), via=[through(b, "D1", "DR1")], spaces=["BC"], via_spaces=["DR1"], kind="through:D1")]),
        ("G", TA, "um, could you back up two metres", {"any": ["clarify", [safe_move(b, TA, "backward")]]}),
        ("H", TB, "face sth", [compass(b.pose(*TB)[2], 270)]),
        ("I", TC, "Please drive to the room with the sofa.", "clarify"),
        ("J", TD, "okay, so, first of all, go to the door on your right, and then, when you're there, go on through "
                  "it, lovely", [ntp(through(b, "DP", "PR"), via=[D("DP")], spaces=["PR"], via_spaces=["GR", "PR", "door:DP"],
                                     kind="through:DP")]),
    ]
    assert 2.0 / 0.03 > safe_move(b, TA, "backward")["repeat"][1] + 30
    return b, C


def main():
    out = []
    for fn, tag in ((station, "stn"), (courthouse, "crt"), (theatre, "thr")):
        b, C = fn()
        assert len(C) == 30, (tag, len(C))
        for i, (spk, pose, prompt, exp) in enumerate(C, 1):
            out.append((b, tag, i, spk, pose, prompt, exp))
    bld_check.write(out)


if __name__ == "__main__":
    main()
