#!/usr/bin/env python3
"""Draws three NEW buildings and writes buildings.jsonl, 30 cases each:
- a CRAFT BREWERY (axis-aligned, STEPPED outline): a taproom with a 1.8 m roller door to the street, tables and a
  bar; a barrel store behind it; a corridor with an office, a cold store (1.2 m pallet door), a toilet (0.7 m, the
  smallest), a malt store and a lab, and a 1.2 m yard door to the never-scanned yard; the brewhouse (the biggest)
  with a mash tun, a kettle, three fermenters (two of them 0.6 m apart: the narrow passage) and a never-scanned
  north strip;
- a CINEMA (ROTATED 23.7 deg, lidar-like noise seed 2370; NON-RECTANGULAR outline): a foyer (2.4 m entrance,
  concession counter, ticket kiosk, sofa), a north-south corridor with screen 1 (the biggest; two doors; seat rows,
  the first split by a 0.7 m gap), screen 2 (seat rows; its screen end never scanned), toilets, a store (0.7 m, the
  smallest), a staff room and a fire exit to the never-scanned outside;
- a GARDEN CENTRE (ROTATED -36.2 deg, noise seed 3620; L-SHAPED outline): a shop (2.0 m entrance, tills, two
  display tables), a corridor behind it with a potting shed, a staff room, a toilet (0.7 m, the smallest) and a
  store, a greenhouse (the biggest: 2.0 m opening from the shop, three benches, two of them 0.65 m apart, an open
  1.5 m door to the never-scanned outside, a never-scanned north strip under the misting line).
Drawing / geometry / check helpers (bld_lib, bld_geom, bld_check, bld_helpers) are copied from round 11's
tooling (/work/main/benchmarks/blind/prompts-11/); along(), left_obstacle(), front_obstacle(), sizes() are copied
from its make_buildings.py; the buildings and prompts are new.
Speaker letters follow spoken.jsonl (A stammering accountant, B Ghanaian taxi driver, C Persian-L1 carpet dealer,
D CB-radio trucker, E golf greenkeeper, F auctioneer, G surgeon, H AAC symbol-board user, I Dutch bike mechanic,
J Israeli founder).
Run: /work/main/.venv/bin/python make_buildings.py
"""
import math

from bld_lib import (OCC, UNK, MIDDLE, BETWEEN, Building, rel, circ, poly, ntp, rot, rot_deg, compass, safe_move)
from bld_geom import door_reg, room_reg, corner_reg, side_corner, nearest_corner, band
from bld_helpers import (nth, within2, mid, nearest_obstacles, frontier_dist, hollow, thr, next_to_in,
                         opposite_far, edge_d, ahead_of)
import bld_check


def along(via, goal, wall_spaces):
    """'along the wall': a via strip on the way and a goal strip at the wall's end, both within 1.0 m of it."""
    return [ntp(poly(*goal), via=[poly(*via)], spaces=wall_spaces, via_spaces=wall_spaces)]


def left_obstacle(p, obs, name):
    lo = {k: o for k, o in obs.items() if rel(p, (o[0] + o[2]) / 2, (o[1] + o[3]) / 2)[1] > 0}
    assert min(lo, key=lambda k: edge_d(lo[k], p)) == name, lo
    ds = sorted(edge_d(o, p) for o in lo.values())
    assert len(ds) == 1 or ds[1] - ds[0] > 1.0, ds


def front_obstacle(p, obs, name):
    ah = {k: o for k, o in obs.items() if abs(ahead_of(p, o)) < 60}
    assert min(ah, key=lambda k: edge_d(ah[k], p)) == name, ah
    ds = sorted(edge_d(o, p) for o in ah.values())
    assert len(ds) == 1 or ds[1] - ds[0] > 1.0, ds


def sizes(b, big, small, names):
    areas = {n: b.area(n) for n in names}
    s = sorted(areas.values())
    assert max(areas, key=areas.get) == big and s[-2] < areas[big] - 30, areas
    assert min(areas, key=areas.get) == small and s[1] - areas[small] > 1.0, areas


def D_(b, n, extra=()):
    d = b.doors[n]
    return ntp(door_reg(b, n), spaces=list(d["spaces"]) + ["door:" + n] + list(extra))


def T_(b, n, into, **kw):
    return ntp(thr(b, n, into, **kw), spaces=[into], kind="through:" + n)


# ================================================================== craft brewery: axis-aligned, stepped outline
def brewery():
    b = Building("brewery", -1.0, -1.0, 29.5, 19.5)
    b.shell(0.0, 0.0, 10.0, 8.0); b.shell(0.0, 8.2, 10.0, 14.0)
    b.shell(10.2, 0.0, 28.0, 4.6); b.shell(10.2, 4.8, 28.0, 18.0)
    b.space("TR", (0.0, 0.0, 10.0, 8.0))           # taproom
    b.space("BS", (0.0, 8.2, 10.0, 14.0))          # barrel store
    b.space("HW", (10.2, 3.0, 28.0, 4.6))          # corridor, 1.6 m
    b.space("OF", (10.2, 0.0, 13.8, 2.8)); b.space("CS", (14.0, 0.0, 18.0, 2.8))   # office, cold store
    b.space("WC", (18.2, 0.0, 19.6, 2.8))          # toilet (smallest)
    b.space("MS", (19.8, 0.0, 24.0, 2.8)); b.space("LB", (24.2, 0.0, 28.0, 2.8))   # malt store, lab
    b.space("BH", (10.2, 4.8, 28.0, 18.0))         # brewhouse (biggest)
    b.door("EX", 4.0, -0.1, "h", "TR", "OUT", width=1.8)     # roller door to the street
    b.door("TD", 10.1, 3.8, "v", "TR", "HW", width=1.1)
    b.door("OFD", 12.0, 2.9, "h", "HW", "OF", width=0.8)
    b.door("CSD", 16.0, 2.9, "h", "HW", "CS", width=1.2)
    b.door("WCD", 18.9, 2.9, "h", "HW", "WC", width=0.7)
    b.door("MSD", 22.0, 2.9, "h", "HW", "MS", width=1.0)
    b.door("LBD", 26.0, 2.9, "h", "HW", "LB", width=0.8)
    b.door("BHD", 15.0, 4.7, "h", "HW", "BH", width=1.6)     # double door
    b.door("BKD", 25.0, 4.7, "h", "HW", "BH", width=0.9)
    b.door("YD", 28.1, 3.8, "v", "HW", "OUT", width=1.2)     # yard door, yard never scanned
    b.door("BSD", 5.0, 8.1, "h", "TR", "BS", width=0.9)
    b.door("BBD", 10.1, 11.0, "v", "BS", "BH", width=1.2)
    b.carve()
    BAR = (1.0, 6.0, 6.0, 6.8)
    T1, T2, T3 = (2.0, 2.0, 3.0, 3.0), (6.0, 1.5, 7.0, 2.5), (7.5, 4.5, 8.5, 5.5)
    BR = (1.0, 10.5, 8.0, 11.3)                    # barrel rack
    MT, KT = (12.0, 7.0, 14.0, 9.0), (15.5, 7.0, 17.5, 9.0)   # mash tun, kettle
    FV1, FV2 = (20.0, 9.0, 22.0, 11.0), (22.6, 9.0, 24.6, 11.0)   # fermenters, 0.6 m apart
    FV3 = (20.0, 13.0, 22.0, 15.0)
    for o in (BAR, T1, T2, T3, BR, MT, KT, FV1, FV2, FV3):
        b.rect(*o, OCC)
    UNK_BH = (10.2, 16.6, 28.0, 18.0)
    b.unknown(*UNK_BH)
    hollow(b)
    b.render()

    sp = b.spaces
    HD = ["TD", "OFD", "CSD", "WCD", "MSD", "LBD", "BHD", "BKD", "YD"]
    PA = (10.8, 3.8, 0)       # corridor, west end, facing east
    PB = (27.4, 3.8, 180)     # corridor, east end, facing west
    PC = (2.0, 1.0, 0)        # taproom, south-west, facing east
    PC2 = (8.0, 3.5, 180)     # taproom, east, facing west
    PD = (11.0, 5.6, 0)       # brewhouse, south-west, facing east
    PE = (22.3, 7.5, 90)      # brewhouse, the fermenter gap straight ahead
    PF = (14.0, 15.5, 0)      # brewhouse, north, facing east
    PH = (12.6, 0.9, 90)      # office, facing north
    PI = (5.0, 9.0, 90)       # barrel store, facing north (rack ahead, door behind)
    PJ = (16.0, 1.2, 90)      # cold store, facing north (door ahead)
    for doors in (HD, HD[1:-1]):                   # the taproom door / yard door counted or not
        assert nth(b, PA, doors, "right", 2) == "CSD" and nth(b, PA, doors, "right", 3) == "WCD"
        assert nth(b, PA, doors, "left", 2) == "BKD" and nth(b, PA, doors, "left", 3) is None
        assert nth(b, PB, doors, "left", 1) == "LBD" and nth(b, PB, doors, "left", 3) == "WCD"
        assert nth(b, PB, doors, "right", 1) == "BKD"
    sizes(b, "BH", "WC", [n for n in sp if n != "HW"])
    assert frontier_dist(PC, (3.1, -0.3, 4.9, -0.2)) + 5 < frontier_dist(PC, UNK_BH)
    assert set(nearest_obstacles(PC2, dict(BAR=BAR, T1=T1, T2=T2, T3=T3), 2)) == {"T2", "T3"}
    left_obstacle(PD, dict(MT=MT, KT=KT, FV1=FV1, FV2=FV2, FV3=FV3), "MT")
    front_obstacle(PI, dict(BR=BR), "BR")
    assert abs(rel(PE, 22.3, 9.0)[3]) < 2 and abs(abs(rel(PI, 5.0, 8.1)[3]) - 180) < 2
    assert abs(rel(PJ, 16.0, 2.9)[3]) < 2
    mid_bh = b.centroid("BH")
    outside = band(3.2, 0.1, 4.8, 0.8)
    bh_back = band(10.35, 15.65, 27.85, 16.45)
    gap_n = within2((21.9, 11.15, 22.7, 11.9), 22.3, 10.0)
    C = [
        ("A", PA, "um the s- second door on your right, go there", [D_(b, "CSD")]),
        ("B", PA, "chale pass through the third door on your right", [T_(b, "WCD", "WC")]),
        ("C", PA, "please go to second door on the left hand", [D_(b, "BKD")]),
        ("D", PA, "third door on your left, ten-four", "clarify"),                    # only two on the left
        ("E", PB, "okay, the first door on your left, go up to it", [D_(b, "LBD")]),
        ("F", PB, "to the third door on your left, third, do I hear third", [D_(b, "WCD")]),
        ("G", PB, "proceed through the first door on your right", [T_(b, "BKD", "BH")]),
        ("H", PC, "go. corner. left.", [ntp(side_corner(PC, sp["TR"][0], "left"), spaces=["TR"])]),
        ("I", PC, "drive to the nearest unexplored area, hè", [ntp(outside, spaces=["TR", "door:EX"], kind="frontier")]),
        ("J", PC2, "go between the two nearest obstacles, yalla", [ntp(circ(*mid(T2, T3), BETWEEN), spaces=["TR"])]),
        ("A", PD, "go to the r- right corner of this room", [ntp(side_corner(PD, sp["BH"][0], "right"), spaces=["BH"])]),
        ("B", PD, "go next to the thing on your left, small small", [ntp(next_to_in(MT, sp["BH"][0]), spaces=["BH"])]),
        ("C", PD, "go along the wall of right side until the end", along((13.0, 4.95, 17.0, 5.75), (25.8, 4.95, 27.85, 5.75), ["BH"])),
        ("D", PD, "breaker, get yourself over to the opposite side of this room", [ntp(opposite_far(b, "BH", PD), spaces=["BH"])]),
        ("E", PE, "through the narrow gap in front, lightly", [ntp(gap_n, spaces=["BH"])]),
        ("F", PE, "turn to face south-east, going once", [compass(b.pose(*PE)[2], 315)]),
        ("G", PF, "proceed towards the unexplored part of this room", [ntp(bh_back, spaces=["BH"], kind="frontier")]),
        ("H", PA, "go. biggest. room.", [ntp(room_reg(b, "BH"), spaces=["BH"])]),
        ("I", PA, "go to the smallest room, hè", [ntp(room_reg(b, "WC"), spaces=["WC"])]),
        ("J", PA, "yalla, middle of the biggest room", [ntp(circ(*mid_bh, MIDDLE), spaces=["BH"])]),
        ("A", PI, "go next to the th- thing in front of you", [ntp(next_to_in(BR, sp["BS"][0]), spaces=["BS"])]),
        ("B", PE, "reverse ten metres, chale", {"any": ["clarify", [safe_move(b, PE, "backward")]]}),
        ("C", PI, "turn to back side and go through door in front", [rot("any", 17, 19), T_(b, "BSD", "TR")]),
        ("D", PH, "get on out of this room and hang a left", [T_(b, "OFD", "HW"), rot_deg(90)]),
        ("E", PH, "head for the nearest corner of this room, please", [ntp(nearest_corner(PH, sp["OF"][0]), spaces=["OF"])]),
        ("F", PA, "turn to face north, sold", [compass(b.pose(*PA)[2], 90)]),
        ("G", PB, "go to the hop store", "clarify"),                                  # a name the grid cannot know
        ("H", PD, "goto. fermenter. three.", "clarify"),
        ("I", PC, "go to the tap handles at the bar", "clarify"),
        ("J", PJ, "go through the door in front of you, yalla", [T_(b, "CSD", "HW")]),
    ]
    assert side_corner(PC, sp["TR"][0], "left") == corner_reg((10.0, 8.0), sp["TR"][0])
    assert side_corner(PD, sp["BH"][0], "right") == corner_reg((28.0, 4.8), sp["BH"][0])
    assert nearest_corner(PH, sp["OF"][0]) == corner_reg((13.8, 0.0), sp["OF"][0])
    assert 10.0 / 0.03 > safe_move(b, PE, "backward")["repeat"][1] + 30
    return b, C


# ================================================================== cinema: rotated 23.7 deg, noisy, non-rectangular
def cinema():
    b = Building("cinema", -1.0, -1.0, 29.5, 21.5, theta=23.7, offset=(3.0, 2.0), seed=2370)
    b.shell(0.0, 0.0, 12.0, 7.5); b.shell(12.2, 0.0, 13.8, 20.0); b.shell(14.0, 0.0, 28.0, 9.0)
    b.shell(14.0, 9.2, 22.0, 20.0); b.shell(8.0, 7.7, 12.0, 10.6); b.shell(9.6, 10.8, 12.0, 13.2)
    b.shell(6.0, 13.4, 12.0, 20.0)
    b.space("FY", (0.0, 0.0, 12.0, 7.5))           # foyer
    b.space("HW", (12.2, 0.0, 13.8, 20.0))         # corridor, 1.6 m, north-south
    b.space("S1", (14.0, 0.0, 28.0, 9.0))          # screen 1 (biggest)
    b.space("S2", (14.0, 9.2, 22.0, 20.0))         # screen 2 (screen end never scanned)
    b.space("WC", (8.0, 7.7, 12.0, 10.6))          # toilets
    b.space("ST", (9.6, 10.8, 12.0, 13.2))         # store (smallest)
    b.space("SR", (6.0, 13.4, 12.0, 20.0))         # staff room
    b.door("EX", 6.0, -0.1, "h", "FY", "OUT", width=2.4)
    b.door("FD", 12.1, 3.5, "v", "FY", "HW", width=1.4)
    b.door("S1D", 13.9, 2.5, "v", "HW", "S1", width=1.2)
    b.door("S1B", 13.9, 7.2, "v", "HW", "S1", width=1.0)
    b.door("S2D", 13.9, 11.0, "v", "HW", "S2", width=1.2)
    b.door("WCD", 12.1, 9.0, "v", "HW", "WC", width=0.8)
    b.door("STD", 12.1, 12.0, "v", "HW", "ST", width=0.7)
    b.door("SRD", 12.1, 16.5, "v", "HW", "SR", width=0.9)
    b.door("FXD", 13.0, 20.1, "h", "HW", "OUT", width=1.0)   # fire exit, outside never scanned
    b.carve()
    CC = (1.0, 5.0, 6.0, 5.8)                      # concession counter
    KI = (8.5, 2.0, 9.5, 3.0)                      # ticket kiosk
    SO = (10.0, 6.6, 11.8, 7.4)                    # sofa
    R1a, R1b = (17.0, 0.9, 17.6, 4.15), (17.0, 4.85, 17.6, 8.1)   # screen 1, first seat row, 0.7 m gap
    R2, R3 = (19.5, 0.9, 20.1, 8.1), (22.0, 0.9, 22.6, 8.1)
    Q1, Q2 = (15.0, 12.0, 21.0, 12.6), (15.0, 14.5, 21.0, 15.1)   # screen 2 seat rows
    for o in (CC, KI, SO, R1a, R1b, R2, R3, Q1, Q2):
        b.rect(*o, OCC)
    UNK_S2 = (14.0, 18.6, 22.0, 20.0)
    b.unknown(*UNK_S2)
    hollow(b)
    b.render()

    sp = b.spaces
    HD = ["FD", "S1D", "S1B", "S2D", "WCD", "STD", "SRD", "FXD"]
    CA = (13.0, 0.8, 90)      # corridor, south end, facing north
    CB = (13.0, 19.2, 270)    # corridor, north end, facing south
    CD = (14.8, 1.5, 0)       # screen 1, just inside, facing east
    CE = (16.0, 4.5, 0)       # screen 1, the seat-row gap straight ahead
    CF = (18.0, 16.5, 90)     # screen 2, facing north (dark screen end ahead)
    CG = (9.0, 17.0, 0)       # staff room, facing east (door ahead)
    CH = (10.8, 12.0, 180)    # store, facing west (door behind)
    CI = (9.0, 9.0, 0)        # toilets, facing east (door ahead)
    CJ = (14.8, 10.0, 90)     # screen 2, just inside, facing north
    CK = (7.5, 4.0, 0)        # foyer, middle
    CL = (10.5, 1.0, 180)     # foyer, south-east, facing west
    CM = (9.0, 0.6, 90)       # foyer, kiosk ahead
    for doors in (HD, HD[:-1]):                    # the fire exit counted or not
        assert nth(b, CA, doors, "left", 3) == "STD" and nth(b, CA, doors, "right", 2) == "S1B"
        assert nth(b, CA, doors, "right", 4) is None and nth(b, CA, doors, "right", 1) == "S1D"
        assert nth(b, CB, doors, "right", 1) == "SRD" and nth(b, CB, doors, "right", 2) == "STD"
        assert nth(b, CB, doors, "left", 1) == "S2D" and nth(b, CB, doors, "left", 3) == "S1D"
    for doors in (HD[1:], HD[1:-1]):               # the foyer door counted or not: the same answers
        assert nth(b, CA, doors, "right", 2) == "S1B" and nth(b, CA, doors, "right", 4) is None
        assert nth(b, CB, doors, "right", 2) == "STD" and nth(b, CB, doors, "left", 3) == "S1D"
    sizes(b, "S1", "ST", [n for n in sp if n != "HW"])
    assert frontier_dist(CL, (4.8, -0.3, 7.2, -0.2)) + 5 < frontier_dist(CL, UNK_S2)
    assert set(nearest_obstacles(CK, dict(CC=CC, KI=KI, SO=SO), 2)) == {"CC", "KI"}
    left_obstacle(CK, dict(CC=CC, KI=KI, SO=SO), "CC")
    assert rel(CK, 6.0, 5.0)[1] > 0.5 and rel(CK, 8.5, 3.0)[1] < -0.5   # nearest cells too: counter left, kiosk right
    front_obstacle(CM, dict(CC=CC, KI=KI, SO=SO), "KI")
    assert abs(rel(CE, 17.0, 4.5)[3]) < 2 and abs(abs(rel(CH, 12.1, 12.0)[3]) - 180) < 2
    assert abs(rel(CG, 12.1, 16.5)[3]) < 15 and abs(rel(CI, 12.1, 9.0)[3]) < 2
    mid_s1 = b.centroid("S1")
    outside = band(4.95, 0.1, 7.05, 0.8)
    s2_back = band(14.15, 17.65, 21.85, 18.45)
    gap_e = within2((17.75, 4.2, 18.9, 4.8), 17.3, 4.5)
    C = [
        ("A", CB, "th- third door on your left", [D_(b, "S1D")]),
        ("B", CA, "go and stop at second door by your right", [D_(b, "S1B")]),
        ("C", CA, "please go to the fourth door on right hand", "clarify"),            # three on the right
        ("D", CA, "take the first door on your right and roll on through it", [T_(b, "S1D", "S1")]),
        ("E", CB, "the first door on your right, just go up to it", [D_(b, "SRD")]),
        ("F", CB, "second door on your right, second, sold", [D_(b, "STD")]),
        ("G", CB, "through the first door on your left", [T_(b, "S2D", "S2")]),
        ("H", CL, "go. corner. right.", [ntp(side_corner(CL, sp["FY"][0], "right"), spaces=["FY"])]),
        ("I", CL, "go towards the nearest unexplored area, toch", [ntp(outside, spaces=["FY", "door:EX"], kind="frontier")]),
        ("J", CK, "go to between the two nearest obstacles", [ntp(circ(*mid(CC, KI), BETWEEN), spaces=["FY"])]),
        ("A", CD, "go along the w- wall on your right", along((18.2, 0.15, 19.3, 0.8), (26.0, 0.15, 27.85, 0.95), ["S1"])),
        ("B", CK, "chale go and stand next to the obstacle by your left", [ntp(next_to_in(CC, sp["FY"][0]), spaces=["FY"])]),
        ("C", CD, "go to the left corner of this room please", [ntp(side_corner(CD, sp["S1"][0], "left"), spaces=["S1"])]),
        ("D", CE, "squeeze on through that narrow gap up ahead", [ntp(gap_e, spaces=["S1"])]),
        ("E", CE, "and face south for me", [compass(b.pose(*CE)[2], 270)]),
        ("F", CF, "towards the unexplored part of this room, going once", [ntp(s2_back, spaces=["S2"], kind="frontier")]),
        ("G", CJ, "proceed to the opposite side of this room", [ntp(opposite_far(b, "S2", CJ), spaces=["S2"])]),
        ("H", CA, "go. room. smallest.", [ntp(room_reg(b, "ST"), spaces=["ST"])]),
        ("I", CA, "drive to the biggest room, hè", [ntp(room_reg(b, "S1"), spaces=["S1"])]),
        ("J", CA, "yalla, to the centre of the biggest room", [ntp(circ(*mid_s1, MIDDLE), spaces=["S1"])]),
        ("A", CJ, "go to the n- nearest corner of this room", [ntp(nearest_corner(CJ, sp["S2"][0]), spaces=["S2"])]),
        ("B", CE, "reverse eight metres", {"any": ["clarify", [safe_move(b, CE, "backward")]]}),
        ("C", CH, "turn to your back and go through door in front", [rot("any", 17, 19), T_(b, "STD", "HW")]),
        ("D", CG, "head on out of this room and hang a right", [T_(b, "SRD", "HW"), rot_deg(-90)]),
        ("E", CI, "go through the door just ahead of you", [T_(b, "WCD", "HW")]),
        ("F", CM, "go up next to the thing in front, lot seven", [ntp(next_to_in(KI, sp["FY"][0]), spaces=["FY"])]),
        ("G", CB, "go to screen three", "clarify"),                                   # names the grid cannot know
        ("H", CD, "go. seat. F12.", "clarify"),
        ("I", CK, "go to the popcorn stand", "clarify"),
        ("J", CB, "yalla, face west now", [compass(b.pose(*CB)[2], 180)]),
    ]
    assert side_corner(CL, sp["FY"][0], "right") == corner_reg((0.0, 7.5), sp["FY"][0])
    assert side_corner(CD, sp["S1"][0], "left") == corner_reg((28.0, 9.0), sp["S1"][0])
    assert nearest_corner(CJ, sp["S2"][0]) == corner_reg((14.0, 9.2), sp["S2"][0])
    assert 8.0 / 0.03 > safe_move(b, CE, "backward")["repeat"][1] + 30
    return b, C


# ================================================================== garden centre: rotated -36.2 deg, noisy, L-shaped
def garden():
    b = Building("garden", -1.0, -1.0, 31.5, 16.5, theta=-36.2, offset=(4.0, 22.0), seed=3620)
    b.shell(0.0, 0.0, 14.0, 9.0); b.shell(0.0, 9.2, 14.0, 10.6); b.shell(0.0, 10.8, 4.5, 15.0)
    b.shell(4.7, 10.8, 8.5, 15.0); b.shell(8.7, 10.8, 10.1, 13.0); b.shell(10.3, 10.8, 14.0, 15.0)
    b.shell(14.2, 0.0, 30.0, 12.0)
    b.space("SH", (0.0, 0.0, 14.0, 9.0))           # shop
    b.space("HW", (0.0, 9.2, 14.0, 10.6))          # corridor, 1.4 m
    b.space("PT", (0.0, 10.8, 4.5, 15.0))          # potting shed
    b.space("SF", (4.7, 10.8, 8.5, 15.0))          # staff room
    b.space("WC", (8.7, 10.8, 10.1, 13.0))         # toilet (smallest)
    b.space("SO", (10.3, 10.8, 14.0, 15.0))        # store
    b.space("GH", (14.2, 0.0, 30.0, 12.0))         # greenhouse (biggest)
    b.door("EX", 5.0, -0.1, "h", "SH", "OUT", width=2.0)
    b.door("SHD", 2.0, 9.1, "h", "SH", "HW", width=1.0)
    b.door("PTD", 2.2, 10.7, "h", "HW", "PT", width=1.0)
    b.door("SFD", 6.6, 10.7, "h", "HW", "SF", width=0.8)
    b.door("WCD", 9.4, 10.7, "h", "HW", "WC", width=0.7)
    b.door("SOD", 12.2, 10.7, "h", "HW", "SO", width=1.2)
    b.door("GHD", 14.1, 9.9, "v", "HW", "GH", width=0.9)
    b.door("SGD", 14.1, 4.5, "v", "SH", "GH", width=2.0)     # wide opening shop -> greenhouse
    b.door("GX", 30.1, 4.0, "v", "GH", "OUT", width=1.5)     # open door, outside never scanned
    b.carve()
    TL = (1.0, 6.5, 4.0, 7.3)                      # tills
    DT1, DT2 = (6.0, 3.0, 8.0, 4.2), (10.0, 3.0, 12.0, 4.2)   # display tables
    B1, B2 = (16.0, 6.0, 21.0, 7.2), (21.65, 6.0, 27.0, 7.2)  # benches, 0.65 m apart
    B3 = (16.0, 1.5, 27.0, 2.5)
    for o in (TL, DT1, DT2, B1, B2, B3):
        b.rect(*o, OCC)
    UNK_GH = (14.2, 10.8, 30.0, 12.0)
    b.unknown(*UNK_GH)
    hollow(b)
    b.render()

    sp = b.spaces
    HD = ["SHD", "PTD", "SFD", "WCD", "SOD", "GHD"]
    GA = (0.6, 9.9, 0)        # corridor, west end, facing east
    GB = (13.4, 9.9, 180)     # corridor, east end, facing west
    GC = (12.5, 1.0, 110)     # shop, south-east
    GD = (9.0, 1.0, 90)       # shop, between the display tables' line, facing north
    GD2 = (7.0, 1.0, 90)      # shop, display table 1 ahead
    GE = (21.325, 4.5, 90)    # greenhouse, the bench gap straight ahead
    GF = (15.0, 9.0, 0)       # greenhouse, north-west, facing east
    GG = (15.0, 0.8, 0)       # greenhouse, south-west, facing east (south wall on the right)
    GH_ = (2.2, 12.5, 270)    # potting shed, facing south (door ahead)
    GI = (6.6, 12.5, 90)      # staff room, facing north (door behind)
    GJ = (12.2, 13.5, 270)    # store, facing south (door ahead)
    GJ2 = (13.3, 14.0, 180)   # store, north-east
    for doors in (HD, HD[:-1]):                    # the greenhouse door (dead ahead / behind) counted or not
        assert nth(b, GA, doors, "left", 3) == "WCD" and nth(b, GA, doors, "right", 2) is None
        assert nth(b, GA, doors, "left", 1) == "PTD"
        assert nth(b, GB, doors, "right", 1) == "SOD" and nth(b, GB, doors, "right", 4) == "PTD"
        assert nth(b, GB, doors, "left", 1) == "SHD" and nth(b, GB, doors, "left", 2) is None
    sizes(b, "GH", "WC", [n for n in sp if n != "HW"])
    assert frontier_dist(GC, (3.9, -0.3, 6.1, -0.2)) + 2 < frontier_dist(GC, UNK_GH)
    assert set(nearest_obstacles(GD, dict(TL=TL, DT1=DT1, DT2=DT2), 2)) == {"DT1", "DT2"}
    front_obstacle(GD2, dict(TL=TL, DT1=DT1, DT2=DT2), "DT1")
    assert abs(rel(GE, 21.325, 6.0)[3]) < 2 and abs(abs(rel(GI, 6.6, 10.7)[3]) - 180) < 2
    assert abs(rel(GH_, 2.2, 10.7)[3]) < 2 and abs(rel(GJ, 12.2, 10.7)[3]) < 2
    mid_gh = b.centroid("GH")
    outside = band(4.2, 0.1, 5.8, 0.8)
    gh_back = band(14.35, 9.85, 29.85, 10.65)
    gap_g = within2((20.95, 7.35, 21.7, 8.5), 21.325, 6.6)
    C = [
        ("A", GA, "go to the th- third door on your left", [D_(b, "WCD")]),
        ("B", GA, "second door by your right, go there", "clarify"),                  # only one on the right
        ("C", GA, "please go through the first door on left hand", [T_(b, "PTD", "PT")]),
        ("D", GB, "first door on your right, go on through, come back", [T_(b, "SOD", "SO")]),
        ("E", GB, "up to the fourth door on your right, please", [D_(b, "PTD")]),
        ("F", GB, "to the door on your left, the one on the left, thank you", [D_(b, "SHD")]),
        ("G", GA, "proceed to the door straight ahead", [D_(b, "GHD")]),
        ("H", GC, "go. corner. on. left.", [ntp(side_corner(GC, sp["SH"][0], "left"), spaces=["SH"])]),
        ("I", GC, "drive towards the nearest unexplored area", [ntp(outside, spaces=["SH", "door:EX"], kind="frontier")]),
        ("J", GD, "go between the two closest obstacles, yalla", [ntp(circ(*mid(DT1, DT2), BETWEEN), spaces=["SH"])]),
        ("A", GG, "go along the w- wall on your right to the end", along((17.0, 0.15, 21.0, 0.95), (28.6, 0.15, 29.85, 0.95), ["GH"])),
        ("B", GD2, "go next to the thing in front of you, chale", [ntp(next_to_in(DT1, sp["SH"][0]), spaces=["SH"])]),
        ("C", GF, "please go to right corner of this room, merci", [ntp(side_corner(GF, sp["GH"][0], "right"), spaces=["GH"])]),
        ("D", GF, "run on over to the opposite side of this room", [ntp(opposite_far(b, "GH", GF), spaces=["GH", "door:GX"])]),
        ("E", GE, "through that narrow gap ahead, slowly", [ntp(gap_g, spaces=["GH"])]),
        ("F", GE, "face east, going once, going twice", [compass(b.pose(*GE)[2], 0)]),
        ("G", GF, "proceed to the edge of the unexplored part of this room", [ntp(gh_back, spaces=["GH"], kind="frontier")]),
        ("H", GA, "go. room. biggest. middle.", [ntp(circ(*mid_gh, MIDDLE), spaces=["GH"])]),
        ("I", GA, "drive to the smallest room, ja", [ntp(room_reg(b, "WC"), spaces=["WC"])]),
        ("J", GB, "biggest room, yalla, go", [ntp(room_reg(b, "GH"), spaces=["GH"])]),
        ("A", GJ2, "go to the n- nearest corner, this room", [ntp(nearest_corner(GJ2, sp["SO"][0]), spaces=["SO"])]),
        ("B", GD, "back up five metres, massa", {"any": ["clarify", [safe_move(b, GD, "backward")]]}),
        ("C", GI, "turn to back side and pass through door in front", [rot("any", 17, 19), T_(b, "SFD", "HW")]),
        ("D", GH_, "get on out of this room, then hang a left", [T_(b, "PTD", "HW"), rot_deg(90)]),
        ("E", GJ, "go through the door facing you", [T_(b, "SOD", "HW")]),
        ("F", GC, "turn to face west, sold to the robot", [compass(b.pose(*GC)[2], 180)]),
        ("G", GE, "go to the orchid house", "clarify"),                               # names the grid cannot know
        ("H", GF, "go. tomato. plants.", "clarify"),
        ("I", GC, "go to the till, I want to pay", "clarify"),
        ("J", GD2, "go next to the seed display", "clarify"),
    ]
    assert side_corner(GC, sp["SH"][0], "left") == corner_reg((0.0, 9.0), sp["SH"][0])
    assert side_corner(GF, sp["GH"][0], "right") == corner_reg((30.0, 0.0), sp["GH"][0])
    assert nearest_corner(GJ2, sp["SO"][0]) == corner_reg((14.0, 15.0), sp["SO"][0])
    assert 5.0 / 0.03 > safe_move(b, GD, "backward")["repeat"][1] + 30
    return b, C


BUILDINGS = lambda: [(brewery, "brew"), (cinema, "cine"), (garden, "gard")]


def main_one(fn, tag):
    b, C = fn()
    assert len(C) == 30, (tag, len(C))
    for s in "ABCDEFGHIJ":
        assert sum(1 for c in C if c[0] == s) == 3, (tag, s)
    return [(b, tag, i, spk, pose, prompt, exp) for i, (spk, pose, prompt, exp) in enumerate(C, 1)]


if __name__ == "__main__":
    out = []
    for fn, tag in BUILDINGS():
        out += main_one(fn, tag)
    bld_check.write(out)
