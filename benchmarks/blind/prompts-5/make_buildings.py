#!/usr/bin/env python3
"""Draws three new buildings -- a restaurant (dining room with tables, kitchen split by counters with a
narrow gap, a service hallway with side rooms, a front entrance open to the unscanned outside), a
supermarket (sales floor with long shelf rows and two checkout counters with a narrow lane, a
storeroom, an office, two back rooms; drawn ROTATED 23 deg with lidar-like noise), and a lab floor
whose outline is T-SHAPED (non-rectangular: a long corridor, a branch corridor, an L-shaped lab) --
and writes buildings.jsonl, 30 cases each.  Every expected region is checked on the drawn map
(bld_check.check) and an oracle output built from the expectations is scored.  Drawing / geometry /
check helpers and the helpers nth, opposite, next_to, within2, mid are copied from the fourth blind
set; the buildings and prompts are new.

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


# ================================================================== restaurant (axis-aligned)
def restaurant():
    b = Building("restaurant", -1.0, -1.5, 21.0, 17.0)
    b.shell(0.0, 0.0, 20.0, 16.0)
    b.space("DR", (0.0, 0.0, 11.0, 10.0))          # dining room
    b.space("KT", (0.0, 10.2, 11.0, 16.0))         # kitchen (split by two counter rows with a gap)
    b.space("H", (11.2, 0.0, 13.0, 16.0))          # service hallway, 1.8 m
    b.space("E1", (13.2, 0.0, 20.0, 3.8)); b.space("E2", (13.2, 4.0, 16.5, 7.0))
    b.space("E3", (13.2, 7.2, 20.0, 11.5)); b.space("E4", (13.2, 11.7, 20.0, 16.0))
    b.door("DH", 11.1, 4.0, "v", "H", "DR"); b.door("KH", 11.1, 14.8, "v", "H", "KT")
    b.door("DK", 8.0, 10.1, "h", "DR", "KT")
    for n, y in (("E1", 2.0), ("E2", 5.5), ("E3", 9.5), ("E4", 14.5)):
        b.door(n, 13.1, y, "v", "H", n)
    b.door("EN", 4.0, -0.1, "h", "DR", "OUT", width=1.6)   # front entrance, outside never scanned
    b.carve()
    T1, T2, T3, T4 = (2.0, 3.0, 3.2, 4.2), (5.5, 3.0, 6.7, 4.2), (2.0, 6.5, 3.2, 7.7), (5.5, 6.5, 6.7, 7.7)
    BAR = (9.0, 6.0, 9.6, 9.0)
    SH = (15.0, 9.8, 18.0, 10.4)
    for o in (T1, T2, T3, T4, BAR, SH, (6.5, 14.3, 9.0, 15.2), (18.0, 14.5, 19.5, 15.5)):
        b.rect(*o, OCC)
    b.rect(0.0, 12.6, 4.5, 13.2, OCC); b.rect(5.2, 12.6, 11.0, 13.2, OCC)   # counter rows, gap x 4.5..5.2
    b.unknown(18.5, 7.2, 20.0, 11.5)               # east part of E3 not scanned
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    HD = ["DH", "KH", "E1", "E2", "E3", "E4"]
    RA = (12.1, 0.8, 90)      # hallway, south end, facing north
    RB = (1.0, 5.2, 0)        # dining room, west side, facing east (between the table rows)
    RC = (2.0, 11.2, 0)       # kitchen, south part, facing east
    RD = (14.2, 9.0, 0)       # E3, facing east (its east part unscanned)
    RE = (15.5, 5.5, 180)     # E2, facing west (its door ahead)
    RF = (12.1, 15.3, 270)    # hallway, north end, facing south
    RG = (6.0, 1.0, 90)       # dining room, south, facing north
    assert nth(b, RA, HD, "right", 2) == "E2" and nth(b, RA, HD, "right", 3) == "E3"
    assert nth(b, RA, HD, "right", 5) is None and nth(b, RA, HD, "left", -1) == "KH"
    assert nth(b, RA, HD, "left", 1) == "DH"
    assert nth(b, RF, HD, "left", 2) == "E3" and nth(b, RF, HD, "right", 1) == "KH" and nth(b, RF, HD, "right", 2) == "DH"
    assert nth(b, RC, ["DK", "KH"], "right", 1) == "DK" and nth(b, RC, ["DK", "KH"], "right", 2) is None
    areas = {n: b.area(n) for n in sp}
    assert max(areas, key=areas.get) == "DR" and min(areas, key=areas.get) == "E2"
    assert sorted(areas.values())[1] - areas["E2"] > 5 and sorted(areas.values())[-2] < areas["DR"] - 20
    # RB: the nearest obstacle on each side, the two nearest obstacles
    f1, l1, d1, _ = rel(RB, 2.6, 3.6); f3, l3, d3, _ = rel(RB, 2.6, 7.1)
    assert l1 < 0 < l3 and d1 < 4 and d3 < 4
    mid_dr = b.centroid("DR")
    front_en = band(3.4, 0.0, 4.6, 0.7)                       # dining room side of the open entrance
    front_e3 = band(17.6, 7.4, 18.5, 11.3)                     # E3 within 1 m of its unscanned part
    gap_k = within2((4.0, 13.3, 5.7, 14.6), 4.85, 12.9)        # kitchen, north of the counter gap
    C = [
        ("A", RA, "go to the second door on your right, over", [ntp(D("E2"), spaces=["H", "E2", "door:E2"])]),
        ("B", RA, "um can u go thru the third door on the right", [ntp(through(b, "E3", "E3"), spaces=["E3"], kind="through:E3")]),
        ("F", RA, "could you please go to the last door on your left? thanks", [ntp(D("KH"), spaces=["H", "KT", "door:KH"])]),
        ("E", RA, "first door on the left, then the middle of that room",
         [ntp(circ(*mid_dr, MIDDLE), spaces=["DR"])]),
        ("C", RA, "go to the fifth door on the right side", "clarify"),
        ("G", RA, "okay head down the hall and into the biggest room", [ntp(R("DR"), spaces=["DR"])]),
        ("D", RA, "which room is the smallest? go there please", [ntp(R("E2"), spaces=["E2"])]),
        ("H", RA, "go all the way to the end of this hallway", [ntp(band(11.2, 14.6, 13.0, 16.0), spaces=["H"])]),
        ("J", RA, "go sit by the cash register buddy", "clarify"),
        ("I", RA, "Go to third door on right side and after turn to left.",
         [ntp(D("E3"), spaces=["H", "E3", "door:E3"]), rot_deg(90)]),
        ("A", RB, "go halfway between the obstacle on your left and the obstacle on your right",
         [ntp(circ(*mid(T1, T3), BETWEEN), spaces=["DR"])]),
        ("B", RB, "uh go to the right corner of this room", [ntp(side_corner(RB, sp["DR"][0], "right"), spaces=["DR"])]),
        ("C", RB, "get to the opposite side of the room pls", [ntp(opposite(b, "DR", RB, "+x"), spaces=["DR"])]),
        ("D", RB, "can you leave the room through the door?", "clarify"),
        ("E", RB, "go toward the nearest unexplored area", [ntp(front_en, spaces=["DR", "door:EN"], kind="frontier")]),
        ("F", RB, "would you go next to the obstacle on your right please", [ntp(next_to(T1), spaces=["DR"])]),
        ("G", RG, "turn and face west", [compass(b.pose(*RG)[2], 180)]),
        ("H", RG, "go over to the left corner", [ntp(side_corner(RG, sp["DR"][0], "left"), spaces=["DR"])]),
        ("I", RC, "Pass through the narrow gap on your left side.", [ntp(gap_k, spaces=["KT"])]),
        ("J", RC, "go to the walk in freezer", "clarify"),
        ("A", RC, "head through the door on your right, over", [ntp(through(b, "DK", "DR"), spaces=["DR"], kind="through:DK")]),
        ("B", RC, "um, go to the closest corner", [ntp(nearest_corner(RC, sp["KT"][0]), spaces=["KT"])]),
        ("C", RD, "head toward the unexplored part of this room", [ntp(front_e3, spaces=["E3"], kind="frontier")]),
        ("D", RD, "can you go next to that obstacle", [ntp(next_to(SH), spaces=["E3"])]),
        ("E", RE, "go out the door, then turn right",
         [ntp(through(b, "E2", "H"), spaces=["H"], kind="through:E2"), rot_deg(-90)]),
        ("F", RE, "could you go into the room next to this one", "clarify"),
        ("G", RF, "second door on the left please", [ntp(D("E3"), spaces=["H", "E3", "door:E3"])]),
        ("H", RF, "go on through the first door on your right", [ntp(through(b, "KH", "KT"), spaces=["KT"], kind="through:KH")]),
        ("I", RF, "Go in corridor to second door on right side.", [ntp(D("DH"), spaces=["H", "DR", "door:DH"])]),
        ("J", RA, "go through the first door on the left and then to the right corner of that room",
         [ntp(corner_reg((0.0, 10.0), sp["DR"][0]), via=[through(b, "DH", "DR")], spaces=["DR"], via_spaces=["DR"])]),
    ]
    # 'right corner' after entering the dining room heading west: of its corners ahead, (0, 10) is farthest right
    post = (10.0, 4.0, 180)
    assert side_corner(post, sp["DR"][0], "right") == corner_reg((0.0, 10.0), sp["DR"][0])
    return b, C


# ================================================================== supermarket, rotated 23 deg, noisy
def supermarket():
    b = Building("supermarket", -1.0, -1.5, 25.0, 19.0, theta=23.0, offset=(3.0, 2.0), seed=5023)
    b.shell(0.0, 0.0, 24.0, 14.0); b.shell(0.0, 14.0, 14.0, 18.0)
    b.space("SF", (0.0, 0.0, 18.0, 14.0))          # sales floor
    b.space("BK", (18.2, 0.0, 24.0, 9.0))          # storeroom (south-east part not scanned)
    b.space("OF", (18.2, 9.2, 24.0, 14.0))         # office
    b.space("BA", (0.0, 14.2, 8.0, 18.0))          # back room (bakery)
    b.space("ST", (8.2, 14.2, 14.0, 18.0))         # back room (staff), smallest
    b.door("BK", 18.1, 5.0, "v", "SF", "BK"); b.door("OF", 18.1, 12.0, "v", "SF", "OF")
    b.door("BA", 4.0, 14.1, "h", "SF", "BA"); b.door("ST", 11.0, 14.1, "h", "SF", "ST")
    b.door("EN", 7.0, -0.1, "h", "SF", "OUT", width=1.6)    # entrance, outside never scanned
    b.carve()
    S1, S2, S3, S4 = [(x, 3.0, x + 0.8, 11.0) for x in (3.0, 6.0, 9.0, 12.0)]   # shelf rows
    CK1, CK2 = (14.0, 1.0, 14.8, 3.0), (15.5, 1.0, 16.3, 3.0)                  # checkouts, lane x 14.8..15.5
    P1 = (20.5, 6.5, 22.0, 8.0)                    # pallet in the storeroom
    DK = (21.0, 12.5, 22.5, 13.5)                  # desk in the office
    for o in (S1, S2, S3, S4, CK1, CK2, P1, DK, (0.5, 16.6, 2.0, 17.6)):
        b.rect(*o, OCC)
    b.unknown(21.5, 0.0, 24.0, 3.0)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    FD = ["BK", "OF", "BA", "ST", "EN"]
    SA = (1.5, 1.5, 90)       # west aisle, south end, facing north
    SB = (15.5, 7.0, 0)       # east open area, facing east
    SC = (10.9, 1.6, 90)      # south end of the aisle between S3 and S4, facing north
    SD = (19.5, 2.0, 90)      # storeroom, facing north
    SE = (11.0, 12.8, 180)    # north of the shelves, facing west
    SF_ = (2.0, 16.0, 0)      # bakery, facing east
    SG = (20.5, 11.0, 90)     # office, facing north
    SH = (7.6, 1.2, 90)       # just inside the entrance, facing north
    assert nth(b, SB, FD, "right", 1) == "BK" and nth(b, SB, FD, "left", 2) == "ST" and nth(b, SB, FD, "left", 1) == "OF"
    assert nth(b, SE, FD, "right", 1) == "ST" and nth(b, SE, FD, "right", 2) == "BA" and nth(b, SE, FD, "left", 1) == "OF"
    areas = {n: b.area(n) for n in sp}
    assert min(areas, key=areas.get) == "ST" and sorted(areas.values())[1] - areas["ST"] > 5
    # obstacle orders used below
    cen = {k: ((o[0] + o[2]) / 2, (o[1] + o[3]) / 2) for k, o in
           dict(S1=S1, S2=S2, S3=S3, S4=S4, CK1=CK1, CK2=CK2).items()}
    def order(pose, side=None, ahead=False):
        out = []
        for k, (x, y) in cen.items():
            f, l, d, brg = rel(pose, x, y)
            if side and (side == "left") != (l > 0):
                continue
            if ahead and abs(brg) > 60:
                continue
            out.append((round(d, 2), k))
        return sorted(out)
    o = order(SC, ahead=True); assert [k for _, k in o[:2]] == ["S3", "S4"] or [k for _, k in o[:2]] == ["S4", "S3"]
    assert o[2][0] - o[1][0] > 1.0
    o = order(SH, side="left"); assert [k for _, k in o[:2]] == ["S2", "S1"] and o[2][0] - o[1][0] > 1.0 if len(o) > 2 else True
    assert rel(SH, 6.8, 3.0)[1] > 0.5 and rel(SH, 3.8, 3.0)[1] > 0.5 and rel(SH, 9.0, 3.0)[1] < -0.5
    assert rel(SB, 15.15, 2.0)[1] < -3                          # the checkout lane is on SB's right
    mid_ba = b.centroid("BA")
    front_en = band(6.4, 0.0, 7.6, 0.7)
    front_bk = band(20.6, 0.3, 21.45, 2.8)
    lane_s = within2((14.5, 0.3, 15.8, 0.95), 15.15, 2.0)    # south of the checkout lane
    C = [
        ("A", SA, "go to the nearest corner, over", [ntp(nearest_corner(SA, sp["SF"][0]), spaces=["SF"])]),
        ("B", SA, "um go towards the closest unexplored area", [ntp(front_en, spaces=["SF", "door:EN"], kind="frontier")]),
        ("C", SC, "go between the two nearest obstacles ahead of you", [ntp(circ(*mid(S3, S4), BETWEEN), spaces=["SF"])]),
        ("D", SB, "could you go through the door on your right?", [ntp(through(b, "BK", "BK"), spaces=["BK"], kind="through:BK")]),
        ("E", SB, "second door on your left", [ntp(D("ST"), spaces=["SF", "ST", "door:ST"])]),
        ("F", SB, "go over to the customer service desk please", "clarify"),
        ("G", SB, "go through the narrow gap between the two obstacles on your right",
         [ntp(lane_s, spaces=["SF"])]),
        ("H", SD, "head towards the unexplored part of this room", [ntp(front_bk, spaces=["BK"], kind="frontier")]),
        ("I", SD, "Go out from this room by the door.", [ntp(through(b, "BK", "SF"), spaces=["SF"], kind="through:BK")]),
        ("J", SD, "go next to the obstacle buddy", [ntp(next_to(P1), spaces=["BK"])]),
        ("A", SE, "go to the second door on your right", [ntp(D("BA"), spaces=["SF", "BA", "door:BA"])]),
        ("B", SE, "uh go thru the second door on the right and then go to the middle of that room",
         [ntp(circ(*mid_ba, MIDDLE), spaces=["BA"])]),
        ("C", SE, "go to whichever room is smallest", [ntp(R("ST"), spaces=["ST"])]),
        ("D", SF_, "can you go out the door and then turn right",
         [ntp(through(b, "BA", "SF"), spaces=["SF"], kind="through:BA"), rot_deg(-90)]),
        ("E", SF_, "go to the room that's next to this one", "clarify"),
        ("F", SF_, "could you go to the right corner of this room", [ntp(side_corner(SF_, sp["BA"][0], "right"), spaces=["BA"])]),
        ("G", SG, "go to the storeroom", "clarify"),
        ("H", SG, "pull up next to the obstacle in front of you", [ntp(next_to(DK), spaces=["OF"])]),
        ("I", SG, "Go through the door from left side.", [ntp(through(b, "OF", "SF"), spaces=["SF"], kind="through:OF")]),
        ("J", SH, "face east buddy", [compass(b.pose(*SH)[2], 0)]),
        ("A", SH, "go to the left corner of this room, over", [ntp(side_corner(SH, sp["SF"][0], "left"), spaces=["SF"])]),
        ("B", SH, "um go in between the two closest obstacles on your left", [ntp(circ(*mid(S1, S2), BETWEEN), spaces=["SF"])]),
        ("C", SA, "go to the bakery section", "clarify"),
        ("D", SC, "can you back up two meters",
         {"any": ["clarify", [safe_move(b, SC, "backward")]]}),
        ("E", SB, "go to the door on your left, then through it",
         [ntp(through(b, "OF", "OF"), via=[D("OF")], spaces=["OF"], via_spaces=["SF", "OF", "door:OF"], kind="through:OF")]),
        ("F", SF_, "would you face south please", [compass(b.pose(*SF_)[2], 270)]),
        ("G", SD, "turn around and go through the door",
         [rot("any", 17, 19), ntp(through(b, "BK", "SF"), spaces=["SF"], kind="through:BK")]),
        ("H", SE, "get over to the closest door on your left", [ntp(D("OF"), spaces=["SF", "OF", "door:OF"])]),
        ("I", SD, "Go to corner of room which is most near.", [ntp(nearest_corner(SD, sp["BK"][0]), spaces=["BK"])]),
        ("J", SE, "go through the first door on your right", [ntp(through(b, "ST", "ST"), spaces=["ST"], kind="through:ST")]),
    ]
    return b, C


# ================================================================== lab floor: T-shaped outline, L-shaped lab
def labfloor():
    b = Building("labfloor", -1.0, -1.0, 31.0, 23.0)
    b.shell(0.0, 0.0, 30.0, 12.0); b.shell(9.0, 8.0, 21.0, 16.0); b.shell(9.0, 8.0, 19.0, 22.0)
    b.space("C", (0.0, 6.0, 30.0, 8.0))            # main corridor, 2 m
    b.space("B", (14.0, 8.0, 16.0, 22.0))          # branch corridor north (open to C, north end not scanned)
    for i, x0 in enumerate((0.0, 7.2, 13.2, 18.7, 24.2), 1):
        x1 = (7.0, 13.0, 18.5, 24.0, 30.0)[i - 1]
        b.space(f"L{i}", (x0, 0.0, x1, 5.8))
    b.space("N1", (0.0, 8.2, 8.8, 12.0)); b.space("N2", (21.2, 8.2, 30.0, 12.0))
    b.space("W1", (9.0, 8.2, 13.8, 13.0)); b.space("W2", (9.0, 13.2, 13.8, 22.0))
    b.space("E1", (16.2, 8.2, 21.0, 16.0), (16.2, 16.0, 19.0, 22.0))   # L-shaped lab
    for n, x in (("L1", 3.5), ("L2", 10.0), ("L3", 16.6), ("L4", 21.5), ("L5", 27.0)):
        b.door(n, x, 5.9, "h", "C", n)
    b.door("N1", 4.5, 8.1, "h", "C", "N1"); b.door("N2", 25.5, 8.1, "h", "C", "N2")
    b.door("W1", 13.9, 10.5, "v", "B", "W1"); b.door("W2", 13.9, 19.0, "v", "B", "W2")
    b.door("E1", 16.1, 12.5, "v", "B", "E1")
    b.carve()
    BA1, BA2 = (3.0, 1.4, 4.0, 2.2), (3.0, 3.8, 4.0, 4.6)     # two obstacles in L1
    BE = (17.5, 11.0, 19.5, 11.8)                               # bench in E1
    for o in (BA1, BA2, BE, (7.2, 3.0, 9.5, 3.6), (10.2, 3.0, 13.0, 3.6), (11.5, 19.5, 13.0, 21.0)):
        b.rect(*o, OCC)                             # + two benches across L2 (gap x 9.5..10.2) + a cabinet in W2
    b.unknown(14.0, 21.0, 16.0, 22.0)              # north end of the branch corridor not scanned
    b.unknown(28.0, 0.0, 30.0, 2.5)                # south-east corner of L5 not scanned
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    CD = ["L1", "L2", "L3", "L4", "L5", "N1", "N2"]
    BD = ["W1", "W2", "E1"]
    readings = (CD, CD + BD)                        # the branch's doors counted or not: same answers
    LA = (0.8, 7.0, 0)        # main corridor, west end, facing east
    LB = (15.0, 18.0, 270)    # branch corridor, facing south
    LC = (17.0, 9.0, 90)      # L-shaped lab E1, south-west part, facing north
    LD = (8.0, 1.5, 90)       # L2, south of the benches, facing north
    LE = (29.2, 7.0, 180)     # main corridor, east end, facing west
    LF = (1.2, 3.0, 0)        # L1, facing east (two obstacles ahead)
    LG = (11.0, 9.0, 90)      # W1, facing north
    def nth2(pose, side, n):
        rd = readings if b.space_of_local(pose[0], pose[1]) == "C" else (BD, BD + CD)
        a = {nth(b, pose, r, side, n) for r in rd}
        assert len(a) == 1, a
        return a.pop()
    assert nth2(LA, "left", 1) == "N1" and nth2(LA, "right", 3) == "L3" and nth2(LA, "right", -1) == "L5"
    assert nth2(LB, "left", 1) == "E1" and nth2(LB, "right", 2) == "W1"
    assert nth2(LE, "left", 2) == "L4" and nth2(LE, "right", 1) == "N2"
    assert nth(b, LC, ["E1"], "left", 1) == "E1"
    areas = {n: b.area(n) for n in sp if n not in ("C", "B")}
    assert max(areas, key=areas.get) == "E1" and min(areas, key=areas.get) == "W1"
    assert sorted(areas.values())[-2] < areas["E1"] - 10 and sorted(areas.values())[1] - areas["W1"] > 5
    # nearest unexplored area from LE: the one in L5 (straight-line distance to its nearest frontier cell)
    assert math.hypot(LE[0] - 28.0, LE[1] - 2.5) + 2 < math.hypot(LE[0] - 16.0, LE[1] - 21.0)
    # LC: the right corner of the L-shaped room: corners ahead, farthest right is (21, 16)
    Lc = [(16.2, 8.2), (21.0, 8.2), (21.0, 16.0), (19.0, 16.0), (19.0, 22.0), (16.2, 22.0)]
    ah = sorted((rel(LC, x, y)[1], (x, y)) for x, y in Lc if abs(rel(LC, x, y)[3]) < 60)
    assert ah[0][1] == (21.0, 16.0) and ah[1][0] - ah[0][0] > 1.5
    assert all(abs(abs(rel(LC, x, y)[3]) - 60) > 8 for x, y in Lc)
    assert abs(rel(LC, 18.5, 11.4)[3]) < 45        # the bench is in front
    mid_e1 = b.centroid("E1")
    gap_l2 = within2((9.0, 3.7, 10.7, 5.0), 9.85, 3.3)
    front_b = band(14.0, 20.1, 16.0, 20.95)
    front_l5 = band(27.2, 0.2, 27.95, 2.4)
    C = [
        ("A", LA, "go to the first door on your left, over", [ntp(D("N1"), spaces=["C", "N1", "door:N1"])]),
        ("B", LA, "um third door on the right", [ntp(D("L3"), spaces=["C", "L3", "door:L3"])]),
        ("C", LA, "go thru the last door on the right", [ntp(through(b, "L5", "L5"), spaces=["L5"], kind="through:L5")]),
        ("D", LA, "can you drive all the way down to the end of this corridor?", [ntp(band(28.5, 6.0, 30.0, 8.0), spaces=["C"])]),
        ("E", LA, "go to the biggest room on this floor", [ntp(R("E1"), spaces=["E1"])]),
        ("F", LA, "could you find the smallest room and go in there", [ntp(R("W1"), spaces=["W1"])]),
        ("G", LA, "okay now face south", [compass(b.pose(*LA)[2], 270)]),
        ("H", LA, "go through the first door on the right, then on to the right corner of that room",
         [ntp(corner_reg((0.0, 0.0), sp["L1"][0]), via=[through(b, "L1", "L1")], spaces=["L1"], via_spaces=["L1"])]),
        ("I", LA, "Go to the cafeteria please.", "clarify"),
        ("A", LB, "go to the first door on your left, over", [ntp(D("E1"), spaces=["B", "E1", "door:E1"])]),
        ("B", LB, "uh go through the second door on your right", [ntp(through(b, "W1", "W1"), spaces=["W1"], kind="through:W1")]),
        ("C", LB, "go towards the unexplored area behind you", [ntp(front_b, spaces=["B"], kind="frontier")]),
        ("D", LB, "turn around and then go to the door on your left",
         [rot("any", 17, 19), ntp(D("W2"), spaces=["B", "W2", "door:W2"])]),
        ("E", LC, "go to the middle of this room, its kind of an odd shape", [ntp(circ(*mid_e1, MIDDLE), spaces=["E1"])]),
        ("F", LC, "would you go to the right corner of this room", [ntp(corner_reg((21.0, 16.0), sp["E1"][0]), spaces=["E1"])]),
        ("G", LC, "go next to that obstacle in front of you", [ntp(next_to(BE), spaces=["E1"])]),
        ("H", LC, "scoot out through the door on your left", [ntp(through(b, "E1", "B"), spaces=["B"], kind="through:E1")]),
        ("I", LD, "Go through the narrow gap which is in front.", [ntp(gap_l2, spaces=["L2"])]),
        ("J", LD, "go out the door buddy", [ntp(through(b, "L2", "C"), spaces=["C"], kind="through:L2")]),
        ("A", LD, "go to the room next door, over", "clarify"),
        ("B", LE, "um the second door on your left", [ntp(D("L4"), spaces=["C", "L4", "door:L4"])]),
        ("C", LE, "go to the first door on your right and then go thru it",
         [ntp(through(b, "N2", "N2"), via=[D("N2")], spaces=["N2"], via_spaces=["C", "N2", "door:N2"], kind="through:N2")]),
        ("D", LE, "could you go toward the nearest unexplored area", [ntp(front_l5, spaces=["L5"], kind="frontier")]),
        ("E", LE, "go through the door at the end of the corridor", "clarify"),
        ("F", LF, "could you go halfway between the two obstacles in front of you",
         [ntp(circ(*mid(BA1, BA2), BETWEEN), spaces=["L1"])]),
        ("G", LF, "go next to the obstacle on your left", [ntp(next_to(BA2), spaces=["L1"])]),
        ("H", LF, "go over to the right corner", [ntp(side_corner(LF, sp["L1"][0], "right"), spaces=["L1"])]),
        ("I", LG, "Go to opposite side of this room.", [ntp(opposite(b, "W1", LG, "+y"), spaces=["W1"])]),
        ("J", LG, "leave the room and go to the biggest room",
         [ntp(R("E1"), via=[through(b, "W1", "B")], spaces=["E1"], via_spaces=["B"])]),
        ("A", LG, "go check the fume hood, over", "clarify"),
    ]
    # LA 'then the right corner of that room': entering L1 heading south, (0, 0) is farthest right
    assert side_corner((3.5, 4.5, 270), sp["L1"][0], "right") == corner_reg((0.0, 0.0), sp["L1"][0])
    # LF: the two obstacles ahead, one on each side; the nearest obstacle on the left is BA2
    assert rel(LF, 3.5, 1.8)[1] < 0 < rel(LF, 3.5, 4.2)[1]
    return b, C


def main():
    out = []
    for fn, tag in ((restaurant, "rst"), (supermarket, "mkt"), (labfloor, "lab")):
        b, C = fn()
        assert len(C) == 30, (tag, len(C))
        for i, (spk, pose, prompt, exp) in enumerate(C, 1):
            out.append((b, tag, i, spk, pose, prompt, exp))
    bld_check.write(out)


if __name__ == "__main__":
    main()
