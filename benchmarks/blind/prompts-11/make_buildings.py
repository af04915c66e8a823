#!/usr/bin/env python3
"""Draws three new buildings and writes buildings.jsonl, 30 cases each:
- a DATA CENTRE (axis-aligned, L-SHAPED outline): a security lobby behind a GLASS front, a corridor with a UPS room,
  a battery room, a network operations room, a cleaner's cupboard and a spare-parts room; a meet-me room with a row
  of cabinets; a data hall with two rack rows (one split by a 0.7 m gap) whose north end was never scanned; a back door
  to the never-scanned loading bay;
- a FITNESS GYM (ROTATED 17.3 deg with lidar-like noise, seed 1173; NON-RECTANGULAR outline): reception, two changing
  rooms, the gym floor (treadmills, a bench, two squat racks 0.7 m apart, a dumbbell rack), a group-exercise studio,
  a spin room whose back is dark, an office, a first-aid room and an open fire exit to the never-scanned outside;
- a BANK BRANCH (ROTATED -28.4 deg with noise, seed 2284; NON-RECTANGULAR stepped outline): a banking hall behind a
  GLASS front, a teller counter with a 0.7 m flap gap, two island desks; a staff room behind it; a corridor with two
  interview rooms, a toilet, a copy room, the manager's office and the vault (its back never scanned), and a staff exit.
Every expected region is checked on the drawn map (bld_check.check) and an oracle output built from the
expectations is scored.  Drawing / geometry / check helpers (bld_lib, bld_geom, bld_check, bld_helpers) are copied
from the previous round's tooling; along() is new; the buildings and prompts are new.
Speaker letters follow spoken.jsonl's ten speakers (A child, B Spanglish landscaper, C Mandarin-L1 coordinator,
D sign-language interpreter, E ballet teacher, F air-traffic controller, G chef, H pseudo-code typist,
I South African safety officer, J Italian architect).

Run: /work/main/.venv/bin/python make_buildings.py
"""
import math

from bld_lib import (OCC, UNK, MIDDLE, BETWEEN, Building, rel, circ, poly, ntp, rot, rot_deg, compass, safe_move)
from bld_geom import door_reg, room_reg, corner_reg, side_corner, nearest_corner, band
from bld_helpers import (nth, within2, mid, nearest_obstacles, frontier_dist, hollow, glass_gaps, thr, next_to_in,
                         opposite_far, edge_d, ahead_of)
import bld_check


def along(via, goal, wall_spaces):
    """'along the wall': a via strip on the way and a goal strip at the wall's end, both within 1.0 m of it (new)."""
    return [ntp(poly(*goal), via=[poly(*via)], spaces=wall_spaces, via_spaces=wall_spaces)]


def left_obstacle(p, obs, name):
    lo = {k: o for k, o in obs.items() if rel(p, (o[0] + o[2]) / 2, (o[1] + o[3]) / 2)[1] > 0}
    assert min(lo, key=lambda k: edge_d(lo[k], p)) == name, lo
    assert sorted(edge_d(o, p) for o in lo.values())[1:2] == [] or \
        sorted(edge_d(o, p) for o in lo.values())[1] - edge_d(obs[name], p) > 1.0


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


# ================================================================== data centre: L-shaped outline, axis-aligned
def datacentre():
    b = Building("datacentre", -1.0, -1.0, 27.0, 17.0)
    b.shell(0.0, 0.0, 6.0, 6.0); b.shell(6.2, 0.0, 26.0, 4.8); b.shell(6.2, 5.0, 11.8, 10.0)
    b.shell(12.0, 5.0, 26.0, 16.0)
    b.space("LB", (0.0, 0.0, 6.0, 6.0))            # security lobby, glass front to the south
    b.space("HW", (6.2, 3.0, 26.0, 4.8))           # corridor, 1.8 m
    b.space("UPS", (6.2, 0.0, 11.0, 2.8)); b.space("BAT", (11.2, 0.0, 15.0, 2.8))
    b.space("NOC", (15.2, 0.0, 22.0, 2.8)); b.space("CC", (22.2, 0.0, 23.6, 2.8))   # cleaner's cupboard (smallest)
    b.space("SP", (23.8, 0.0, 26.0, 2.8))          # spare parts
    b.space("MMR", (6.2, 5.0, 11.8, 10.0))         # meet-me room
    b.space("DH", (12.0, 5.0, 26.0, 16.0))         # data hall (biggest)
    b.door("EX", 3.0, -0.1, "h", "LB", "OUT", width=1.2)
    b.door("LD", 6.1, 3.9, "v", "LB", "HW", width=1.0)
    b.door("UPSD", 8.6, 2.9, "h", "HW", "UPS", width=0.9)
    b.door("BATD", 13.1, 2.9, "h", "HW", "BAT", width=0.8)
    b.door("NOCD", 18.6, 2.9, "h", "HW", "NOC", width=1.0)
    b.door("CCD", 22.9, 2.9, "h", "HW", "CC", width=0.7)
    b.door("SPD", 24.9, 2.9, "h", "HW", "SP", width=0.8)
    b.door("MMD", 9.0, 4.9, "h", "HW", "MMR", width=0.9)
    b.door("DHD", 19.0, 4.9, "h", "HW", "DH", width=1.4)      # double door
    b.door("DMD", 11.9, 7.5, "v", "MMR", "DH", width=0.8)
    b.door("BK", 26.1, 3.9, "v", "HW", "OUT", width=1.0)     # back door, loading bay never scanned
    b.carve()
    gaps = glass_gaps(b, 0.0, 2.4, -0.2, step=0.8) + glass_gaps(b, 3.6, 6.0, -0.2, step=0.8)
    SD = (1.0, 4.0, 3.0, 4.8)                      # security desk
    BN = (4.6, 0.6, 5.8, 1.1)                      # bench
    PL = (0.4, 0.4, 1.0, 1.0)                      # plant
    MM1 = (7.0, 6.5, 11.0, 7.1)                    # cabinet row in the meet-me room
    RA1, RA2 = (13.5, 8.0, 18.6, 8.6), (19.3, 8.0, 24.5, 8.6)   # rack row A, 0.7 m gap
    RB = (13.5, 11.0, 24.5, 11.6)                  # rack row B
    CU = (25.2, 9.0, 26.0, 10.5)                   # cooling unit
    UD = (7.0, 0.4, 10.0, 1.2)                     # UPS cabinets
    DK = (16.0, 0.3, 20.0, 1.1)                    # NOC desk
    for o in (SD, BN, PL, MM1, RA1, RA2, RB, CU, UD, DK):
        b.rect(*o, OCC)
    UNK_DH = (12.0, 14.6, 26.0, 16.0)
    b.unknown(*UNK_DH)
    hollow(b)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    HD = ["LD", "UPSD", "BATD", "NOCD", "CCD", "SPD", "MMD", "DHD", "BK"]
    PA = (6.8, 3.9, 0)        # corridor, west end, facing east
    PB = (25.4, 3.9, 180)     # corridor, east end, facing west
    PC = (2.0, 2.0, 0)        # lobby, facing east
    PC2 = (5.0, 5.2, 180)     # lobby, north-east, facing west
    PD = (14.0, 6.0, 0)       # data hall, south-west, facing east
    PE = (18.95, 6.5, 90)     # data hall, the rack gap straight ahead
    PG = (13.0, 12.8, 0)      # data hall, north aisle, facing east
    PH = (8.0, 5.6, 90)       # meet-me room, facing north (cabinet row ahead)
    PI = (13.0, 7.5, 0)       # data hall, facing east, door to the meet-me room behind
    PJ = (22.9, 1.2, 90)      # cleaner's cupboard, facing north (door ahead)
    for doors in (HD, [d for d in HD if d not in ("LD", "BK")]):
        assert nth(b, PA, doors, "right", 2) == "BATD" and nth(b, PA, doors, "right", 3) == "NOCD"
        assert nth(b, PA, doors, "left", 2) == "DHD" and nth(b, PA, doors, "left", 3) is None
        assert nth(b, PA, doors, "left", 1) == "MMD"
        assert nth(b, PB, doors, "left", 1) == "SPD" and nth(b, PB, doors, "left", 3) == "NOCD"
        assert nth(b, PB, doors, "right", 1) == "DHD"
    assert rel(PC, 6.1, 3.9)[1] >= 0.3 and rel(PC, 3.0, -0.1)[1] <= -0.3
    sizes(b, "DH", "CC", [n for n in sp if n != "HW"])
    out_d = min([frontier_dist(PC, (g[0], -0.2, g[1], 0.0)) for g in gaps] + [frontier_dist(PC, (2.4, -0.3, 3.6, -0.2))])
    assert out_d + 5 < frontier_dist(PC, UNK_DH)
    assert set(nearest_obstacles(PC2, dict(SD=SD, BN=BN, PL=PL), 2)) == {"SD", "BN"}
    front_obstacle(PH, dict(MM1=MM1), "MM1")
    assert abs(rel(PE, 18.95, 8.3)[3]) < 2 and abs(abs(rel(PI, 11.9, 7.5)[3]) - 180) < 2
    assert abs(rel(PJ, 22.9, 2.9)[3]) < 2
    left_obstacle(PD, dict(RA1=RA1, RA2=RA2, RB=RB, CU=CU), "RA1")
    mid_dh = b.centroid("DH")
    outside = {"any": [band(2.45, 0.1, 3.55, 0.8)] + [poly(g[0] - 0.3, 0.1, g[1] + 0.3, 0.8) for g in gaps]}
    dh_back = band(12.15, 13.65, 25.85, 14.45)
    gap_n = within2((18.7, 8.75, 19.2, 9.9), 18.95, 8.6)
    C = [
        ("A", PA, "um go to the second door on the right", [ntp(D("BATD"), spaces=["HW", "BAT", "door:BATD"])]),
        ("B", PA, "ándale, through the third door on your right", [ntp(thr(b, "NOCD", "NOC"), spaces=["NOC"], kind="through:NOCD")]),
        ("C", PA, "you go to second door on left side", [ntp(D("DHD"), spaces=["HW", "DH", "door:DHD"])]),
        ("D", PA, "she says go to the third door on your left", "clarify"),
        ("E", PB, "glide over to the first door on your left", [ntp(D("SPD"), spaces=["HW", "SP", "door:SPD"])]),
        ("F", PB, "robot one, proceed to the third door on your left", [ntp(D("NOCD"), spaces=["HW", "NOC", "door:NOCD"])]),
        ("G", PB, "go through the first door on the right, yes chef", [ntp(thr(b, "DHD", "DH"), spaces=["DH"], kind="through:DHD")]),
        ("H", PC, "go_through(door, side=left)", [ntp(thr(b, "LD", "HW"), spaces=["HW"], kind="through:LD")]),
        ("I", PC, "ja, head towards the nearest unexplored area", [ntp(outside, spaces=["LB", "door:EX"], kind="frontier")]),
        ("J", PC2, "go in the middle between the two nearest obstacles", [ntp(circ(*mid(SD, BN), BETWEEN), spaces=["LB"])]),
        ("A", PD, "um go to the right corner of this big room", [ntp(side_corner(PD, sp["DH"][0], "right"), spaces=["DH"])]),
        ("B", PD, "go next to the obstacle on your left, ahí", [ntp(next_to_in(RA1, sp["DH"][0]), spaces=["DH"])]),
        ("C", PD, "go along the wall on right side", along((15.0, 5.15, 18.0, 5.95), (24.3, 5.15, 25.85, 5.95), ["DH"])),
        ("D", PD, "she'd like you on the opposite side of this room", [ntp(opposite_far(b, "DH", PD), spaces=["DH"])]),
        ("E", PE, "and through the narrow gap ahead, gently", [ntp(gap_n, spaces=["DH"])]),
        ("F", PE, "robot one, face west", [compass(b.pose(*PE)[2], 180)]),
        ("G", PG, "heard, go towards the unexplored part of this room", [ntp(dh_back, spaces=["DH"], kind="frontier")]),
        ("H", PA, "goto(biggest_room)", [ntp(R("DH"), spaces=["DH"])]),
        ("I", PA, "go to the smallest room, ja", [ntp(R("CC"), spaces=["CC"])]),
        ("J", PA, "allora, go to the middle of the biggest room", [ntp(circ(*mid_dh, MIDDLE), spaces=["DH"])]),
        ("A", PH, "go right up next to the thing in front of you", [ntp(next_to_in(MM1, sp["MMR"][0]), spaces=["MMR"])]),
        ("B", PH, "back up five meters", {"any": ["clarify", [safe_move(b, PH, "backward")]]}),
        ("C", PI, "you turn around, then go through door in front", [rot("any", 17, 19),
                                                                     ntp(thr(b, "DMD", "MMR", half=0.9), spaces=["MMR"], kind="through:DMD")]),
        ("D", PJ, "she says go out of this room and turn right", [ntp(thr(b, "CCD", "HW"), spaces=["HW"], kind="through:CCD"), rot_deg(-90)]),
        ("E", PH, "go to the nearest corner of this room, darling", [ntp(nearest_corner(PH, sp["MMR"][0]), spaces=["MMR"])]),
        ("F", PA, "robot one, turn to face north", [compass(b.pose(*PA)[2], 90)]),
        ("G", PB, "go to the server room number two", "clarify"),
        ("H", PI, "goto(rack_B12)", "clarify"),
        ("I", PG, "go to the generator room", "clarify"),
        ("J", PC, "go to the left corner of this room, ecco", [ntp(side_corner(PC, sp["LB"][0], "left"), spaces=["LB"])]),
    ]
    assert side_corner(PD, sp["DH"][0], "right") == corner_reg((26.0, 5.0), sp["DH"][0])
    assert side_corner(PC, sp["LB"][0], "left") == corner_reg((6.0, 6.0), sp["LB"][0])
    assert nearest_corner(PH, sp["MMR"][0]) == corner_reg((6.2, 5.0), sp["MMR"][0])
    assert 5.0 / 0.03 > safe_move(b, PH, "backward")["repeat"][1] + 30
    return b, C


# ================================================================== fitness gym: rotated 17.3 deg, noisy, non-rectangular outline
def gym():
    b = Building("gym", -1.0, -1.0, 28.0, 20.0, theta=17.3, offset=(2.0, 1.0), seed=1173)
    b.shell(0.0, 0.0, 8.0, 10.0); b.shell(8.2, 0.0, 24.0, 12.0); b.shell(8.2, 12.2, 18.0, 19.0)
    b.shell(18.2, 12.2, 24.0, 16.0); b.shell(24.2, 0.0, 27.0, 3.0); b.shell(24.2, 3.2, 26.0, 5.4)
    b.space("RC", (0.0, 0.0, 8.0, 5.0))            # reception
    b.space("LM", (0.0, 5.2, 3.9, 10.0)); b.space("LW", (4.1, 5.2, 8.0, 10.0))   # changing rooms
    b.space("GF", (8.2, 0.0, 24.0, 12.0))          # gym floor (biggest)
    b.space("ST", (8.2, 12.2, 18.0, 19.0))         # group-exercise studio
    b.space("SP", (18.2, 12.2, 24.0, 16.0))        # spin room (back dark)
    b.space("OF", (24.2, 0.0, 27.0, 3.0))          # office
    b.space("FA", (24.2, 3.2, 26.0, 5.4))          # first aid (smallest)
    b.door("EX", 4.0, -0.1, "h", "RC", "OUT", width=1.6)
    b.door("LMD", 2.0, 5.1, "h", "RC", "LM", width=0.8)
    b.door("LWD", 6.0, 5.1, "h", "RC", "LW", width=0.8)
    b.door("RGD", 8.1, 2.5, "v", "RC", "GF", width=1.2)
    b.door("STD", 13.0, 12.1, "h", "GF", "ST", width=1.6)
    b.door("SPD", 21.0, 12.1, "h", "GF", "SP", width=0.9)
    b.door("OFD", 24.1, 1.5, "v", "GF", "OF", width=0.8)
    b.door("FAD", 24.1, 4.3, "v", "GF", "FA", width=0.7)
    b.door("FE", 24.1, 10.0, "v", "GF", "OUT", width=1.0)    # fire exit, open, outside never scanned
    b.carve()
    RD = (1.0, 3.5, 4.0, 4.3)                      # reception desk
    TM = (10.0, 10.6, 16.0, 11.4)                  # treadmills
    BE = (11.0, 4.0, 12.5, 4.6)                    # bench
    SQ1, SQ2 = (17.5, 3.0, 20.0, 5.0), (17.5, 5.7, 20.0, 7.7)   # squat racks, 0.7 m gap
    DB = (23.2, 6.0, 23.8, 9.0)                    # dumbbell rack
    MT = (8.6, 18.0, 10.6, 18.6)                   # mat stack
    BK1, BK2 = (19.0, 13.0, 20.0, 14.0), (22.0, 13.0, 23.0, 14.0)   # spin bikes
    OD = (25.8, 0.0, 26.8, 1.5)                    # office desk, against the south wall (a 0.3 m slot under it was a second component)
    for o in (RD, TM, BE, SQ1, SQ2, DB, MT, BK1, BK2, OD):
        b.rect(*o, OCC)
    UNK_SP = (18.2, 15.0, 24.0, 16.0)
    b.unknown(*UNK_SP)
    hollow(b)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    GFD = ["RGD", "STD", "SPD", "OFD", "FAD", "FE"]
    RCD = ["EX", "LMD", "LWD", "RGD"]
    GA = (23.0, 1.0, 90)      # gym floor, south-east, facing north
    GB = (9.0, 4.0, 0)        # gym floor, west, facing east
    GC = (16.3, 5.35, 0)      # gym floor, the squat-rack gap straight ahead
    GD = (14.5, 2.0, 90)      # gym floor, south
    GE = (13.0, 8.5, 90)      # gym floor, treadmills ahead
    GF2 = (21.0, 12.8, 90)    # spin room, just inside, facing north (dark back ahead)
    GR = (4.0, 2.0, 90)       # reception, facing north
    GR2 = (1.0, 2.5, 0)       # reception, west, facing east (gym door straight ahead)
    GT = (21.0, 10.5, 0)      # gym floor, facing east, spin-room door to the left
    GU = (25.1, 4.3, 180)     # first-aid room, facing west (door ahead)
    GV = (9.0, 7.0, 90)       # gym floor, west wall on the left
    GW = (5.0, 1.0, 90)       # reception, south, facing north (gym door and a changing-room door on the right)
    GX = (19.0, 12.7, 90)     # spin room, just inside its west part, facing north
    for doors in (GFD, GFD[:-1]):                   # the fire exit counted or not
        assert nth(b, GA, doors, "right", 1) == "OFD" and nth(b, GA, doors, "right", 2) == "FAD"
        assert nth(b, GA, doors, "left", 1) == "SPD"
    for doors in (RCD, RCD[1:]):                    # the street door counted or not
        assert nth(b, GR2, doors, "left", 2) == "LWD" and nth(b, GR2, doors, "left", 3) is None
    sizes(b, "GF", "FA", list(sp))
    assert frontier_dist(GR, (3.2, -0.3, 4.8, -0.2)) + 5 < frontier_dist(GR, UNK_SP)
    assert set(nearest_obstacles(GD, dict(BE=BE, SQ1=SQ1, SQ2=SQ2, TM=TM, RD=RD), 2)) == {"BE", "SQ1"}
    front_obstacle(GE, dict(TM=TM, BE=BE, SQ1=SQ1, SQ2=SQ2, DB=DB), "TM")
    left_obstacle(GC, dict(SQ1=SQ1, SQ2=SQ2, TM=TM, DB=DB, BE=BE), "SQ2")
    assert abs(rel(GC, 20.0, 5.35)[3]) < 2 and abs(rel((21.0, 10.5, 90), 21.0, 12.1)[3]) < 2
    assert abs(rel(GU, 24.1, 4.3)[3]) < 2
    mid_gf = b.centroid("GF")
    outside = band(3.25, 0.1, 4.75, 0.8)
    sp_back = band(18.35, 14.15, 23.85, 14.85)
    gap_e = within2((20.15, 4.85, 21.4, 5.85), 20.0, 5.35)
    C = [
        ("A", GA, "robot go to the first door on your right", [ntp(D("OFD"), spaces=["GF", "OF", "door:OFD"])]),
        ("B", GA, "the second door on the right, go there, ándale", [ntp(D("FAD"), spaces=["GF", "FA", "door:FAD"])]),
        ("C", GA, "you go through first door on left side", [ntp(thr(b, "SPD", "SP"), spaces=["SP"], kind="through:SPD")]),
        ("D", GR2, "she says go to the second door on your left", [ntp(D("LWD"), spaces=["RC", "LW", "door:LWD"])]),
        ("E", GR2, "and to the third door on your left", "clarify"),
        ("F", GR, "robot one, proceed to the nearest unexplored area", [ntp(outside, spaces=["RC", "door:EX"], kind="frontier")]),
        ("G", GB, "nearest corner of this room, go, go", [ntp(nearest_corner(GB, sp["GF"][0]), spaces=["GF"])]),
        ("H", GC, "go_through(narrow_gap, ahead)", [ntp(gap_e, spaces=["GF"])]),
        ("I", GC, "go and stand next to the obstacle on your left", [ntp(next_to_in(SQ2, sp["GF"][0]), spaces=["GF"])]),
        ("J", GD, "go to halfway between the two nearest obstacles", [ntp(circ(*mid(BE, SQ1), BETWEEN), spaces=["GF"])]),
        ("A", GE, "go next to that thing in front of you", [ntp(next_to_in(TM, sp["GF"][0]), spaces=["GF"])]),
        ("B", GE, "back up fifteen meters, ándale", {"any": ["clarify", [safe_move(b, GE, "backward")]]}),
        ("C", GF2, "go toward unexplored part of this room", [ntp(sp_back, spaces=["SP"], kind="frontier")]),
        ("D", GT, "she says turn left and go through the door in front of you",
         [rot_deg(90), ntp(thr(b, "SPD", "SP"), spaces=["SP"], kind="through:SPD")]),
        ("E", GU, "out through the door, then a quarter turn to the left",
         [ntp(thr(b, "FAD", "GF"), spaces=["GF"], kind="through:FAD"), rot_deg(90)]),
        ("F", GV, "robot one, proceed along the wall on your left", along((8.35, 7.6, 9.2, 9.6), (8.35, 10.6, 9.2, 11.85), ["GF"])),
        ("G", GB, "behind! go to the opposite side of this room", [ntp(opposite_far(b, "GF", GB), spaces=["GF", "door:FE"])]),
        ("H", GR, "goto(room=biggest, where=middle)", [ntp(circ(*mid_gf, MIDDLE), spaces=["GF"])]),
        ("I", GR, "go to the smallest room, is it", [ntp(R("FA"), spaces=["FA"])]),
        ("J", GR, "go in the biggest room, please", [ntp(R("GF"), spaces=["GF"])]),
        ("A", GB, "face north robot please", [compass(b.pose(*GB)[2], 90)]),
        ("B", GE, "turn to face the west, al oeste", [compass(b.pose(*GE)[2], 180)]),
        ("C", GB, "you go left corner of this room", [ntp(side_corner(GB, sp["GF"][0], "left"), spaces=["GF"])]),
        ("D", GW, "she says go through the door on your right", [ntp(thr(b, "RGD", "GF"), spaces=["GF"], kind="through:RGD")]),
        ("E", GE, "go to the yoga mats, darling", "clarify"),
        ("F", GA, "robot one, taxi to the sauna", "clarify"),
        ("G", GR, "go to the protein bar", "clarify"),
        ("H", GX, "goto(nearest_corner)", [ntp(nearest_corner(GX, sp["SP"][0]), spaces=["SP"])]),
        ("I", GD, "go to the middle of this room, ja", [ntp(circ(*mid_gf, MIDDLE), spaces=["GF"])]),
        ("J", GC, "go to the right corner of this room, grazie", [ntp(side_corner(GC, sp["GF"][0], "right"), spaces=["GF"])]),
    ]
    assert nearest_corner(GB, sp["GF"][0]) == corner_reg((8.2, 0.0), sp["GF"][0])
    assert side_corner(GB, sp["GF"][0], "left") == corner_reg((24.0, 12.0), sp["GF"][0])
    assert side_corner(GC, sp["GF"][0], "right") == corner_reg((24.0, 0.0), sp["GF"][0])
    for doors in (RCD, RCD[1:]):
        assert nth(b, GW, doors, "right", 1) == "RGD"      # the changing-room door is also on the right, farther
    assert 15.0 / 0.03 > safe_move(b, GE, "backward")["repeat"][1] + 30
    return b, C


# ================================================================== bank branch: rotated -28.4 deg, noisy, stepped outline
def bank():
    b = Building("bank", -1.0, -1.0, 29.0, 15.0, theta=-28.4, offset=(5.0, 20.0), seed=2284)
    b.shell(0.0, 0.0, 16.0, 10.0); b.shell(0.0, 10.2, 6.0, 14.0); b.shell(16.2, 0.0, 28.0, 4.6)
    b.shell(16.2, 4.8, 21.0, 9.0); b.shell(21.2, 4.8, 28.0, 11.0)
    b.space("BH", (0.0, 0.0, 16.0, 10.0))          # banking hall (biggest), glass front to the south
    b.space("SR", (0.0, 10.2, 6.0, 14.0))          # staff room
    b.space("HW", (16.2, 3.0, 28.0, 4.6))          # corridor, 1.6 m
    b.space("IR1", (16.2, 0.0, 19.8, 2.8)); b.space("IR2", (20.0, 0.0, 23.6, 2.8))  # interview rooms
    b.space("WC", (23.8, 0.0, 25.4, 2.8))          # toilet (smallest)
    b.space("CP", (25.6, 0.0, 28.0, 2.8))          # copy room
    b.space("MG", (16.2, 4.8, 21.0, 9.0))          # manager's office
    b.space("VT", (21.2, 4.8, 28.0, 11.0))         # vault (back never scanned)
    b.door("EX", 8.0, -0.1, "h", "BH", "OUT", width=2.0)
    b.door("SRD", 3.0, 10.1, "h", "BH", "SR", width=0.8)
    b.door("HD", 16.1, 3.8, "v", "BH", "HW", width=1.0)
    b.door("IR1D", 18.0, 2.9, "h", "HW", "IR1", width=0.8)
    b.door("IR2D", 21.8, 2.9, "h", "HW", "IR2", width=0.8)
    b.door("WCD", 24.6, 2.9, "h", "HW", "WC", width=0.7)
    b.door("CPD", 26.8, 2.9, "h", "HW", "CP", width=0.9)
    b.door("MGD", 18.5, 4.7, "h", "HW", "MG", width=0.9)
    b.door("VTD", 24.5, 4.7, "h", "HW", "VT", width=1.1)
    b.door("BK", 28.1, 3.8, "v", "HW", "OUT", width=0.9)     # staff exit, outside never scanned
    b.carve()
    gaps = glass_gaps(b, 0.0, 6.8, -0.2, step=1.2) + glass_gaps(b, 9.2, 16.0, -0.2, step=1.2)
    TC1, TC2 = (3.0, 7.0, 7.65, 7.8), (8.35, 7.0, 13.0, 7.8)   # teller counter, 0.7 m flap gap
    ID1, ID2 = (4.0, 3.0, 5.5, 4.0), (10.5, 3.0, 12.0, 4.0)    # island desks
    STB = (2.0, 11.5, 4.0, 12.5)                   # staff-room table
    IT1, IT2 = (17.5, 0.8, 18.5, 1.6), (21.3, 0.8, 22.3, 1.6)  # interview tables
    MD = (17.0, 8.2, 19.0, 9.0)                    # manager's desk
    SB1, SB2 = (21.4, 5.0, 21.9, 9.0), (27.3, 5.0, 27.8, 9.0)  # safe-deposit boxes
    CPM = (26.5, 0.2, 27.8, 1.0)                   # copier
    for o in (TC1, TC2, ID1, ID2, STB, IT1, IT2, MD, SB1, SB2, CPM):
        b.rect(*o, OCC)
    UNK_VT = (21.2, 9.8, 28.0, 11.0)
    b.unknown(*UNK_VT)
    hollow(b)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    HWD = ["HD", "IR1D", "IR2D", "WCD", "CPD", "MGD", "VTD", "BK"]
    KA = (16.8, 3.8, 0)       # corridor, west end, facing east
    KB = (27.4, 3.8, 180)     # corridor, east end, facing west
    KC = (8.0, 5.6, 90)       # hall, the counter flap straight ahead
    KD = (2.0, 2.0, 0)        # hall, south-west, facing east
    KE = (14.0, 5.0, 180)     # hall, east, facing west
    KF = (23.5, 7.0, 90)      # vault, just inside, facing north (dark back ahead)
    KG = (18.0, 2.2, 90)      # interview room 1, facing north (door ahead)
    KH = (24.5, 3.8, 0)       # corridor, facing east, vault door to the left
    KI = (19.5, 5.5, 90)      # manager's office, facing north
    KJ = (11.25, 1.2, 90)     # hall, south, island desk ahead
    KL = (0.8, 1.0, 90)       # hall, west wall on the left
    for doors in (HWD, HWD[1:-1]):                  # the hall door / staff exit counted or not
        assert nth(b, KA, doors, "right", 3) == "WCD" and nth(b, KA, doors, "left", 2) == "VTD"
        assert nth(b, KA, doors, "left", 3) is None and nth(b, KA, doors, "right", 1) == "IR1D"
        assert nth(b, KB, doors, "left", 2) == "WCD" and nth(b, KB, doors, "right", 1) == "VTD"
        assert nth(b, KB, doors, "right", 3) is None
    sizes(b, "BH", "WC", [n for n in sp if n != "HW"])
    assert set(nearest_obstacles(KD, dict(ID1=ID1, ID2=ID2, TC1=TC1, TC2=TC2), 2)) == {"ID1", "TC1"}
    front_obstacle(KJ, dict(ID1=ID1, ID2=ID2, TC1=TC1, TC2=TC2), "ID2")
    assert abs(rel(KC, 8.0, 7.8)[3]) < 2 and abs(rel(KG, 18.0, 2.9)[3]) < 2
    assert abs(rel((24.5, 3.8, 90), 24.5, 4.7)[3]) < 2
    assert frontier_dist(KF, UNK_VT) + 2 < min(frontier_dist(KF, (27.9, 3.35, 28.3, 4.25)),
                                               min(frontier_dist(KF, (g[0], -0.2, g[1], 0.0)) for g in gaps))
    mid_mg = b.centroid("MG")
    mid_bh = b.centroid("BH")
    vt_back = band(22.1, 8.85, 27.1, 9.65)
    flap = within2((7.75, 7.95, 8.25, 9.6), 8.0, 7.8)
    C = [
        ("A", KA, "go to the third door on the right", [ntp(D("WCD"), spaces=["HW", "WC", "door:WCD"])]),
        ("B", KA, "go through the second door on your left, ándale", [ntp(thr(b, "VTD", "VT"), spaces=["VT"], kind="through:VTD")]),
        ("C", KA, "you go third door on left side", "clarify"),
        ("D", KA, "she says go into the first door on your right", [ntp(thr(b, "IR1D", "IR1"), spaces=["IR1"], kind="through:IR1D")]),
        ("E", KB, "glide to the second door on your left", [ntp(D("WCD"), spaces=["HW", "WC", "door:WCD"])]),
        ("F", KB, "robot one, proceed to the first door on your right", [ntp(D("VTD"), spaces=["HW", "VT", "door:VTD"])]),
        ("G", KB, "third door on the right, go", "clarify"),
        ("H", KC, "go_through(gap, ahead)", [ntp(flap, spaces=["BH"])]),
        ("I", KC, "ag, back up twelve metres", {"any": ["clarify", [safe_move(b, KC, "backward")]]}),
        ("J", KD, "go in the middle of the two nearest obstacles", [ntp(circ(*mid(ID1, TC1), BETWEEN), spaces=["BH"])]),
        ("A", KD, "go to the other end of this room, the opposite side", [ntp(opposite_far(b, "BH", KD), spaces=["BH"])]),
        ("B", KE, "go to the left corner of this room, ahí", [ntp(side_corner(KE, sp["BH"][0], "left"), spaces=["BH"])]),
        ("C", KE, "you go to right corner of this room", [ntp(side_corner(KE, sp["BH"][0], "right"), spaces=["BH"])]),
        ("D", KF, "she says head towards the unexplored part of this room", [ntp(vt_back, spaces=["VT"], kind="frontier")]),
        ("E", KF, "to the nearest unexplored area, darling", [ntp(vt_back, spaces=["VT"], kind="frontier")]),
        ("F", KG, "robot one, exit this room and turn right",
         [ntp(thr(b, "IR1D", "HW"), spaces=["HW"], kind="through:IR1D"), rot_deg(-90)]),
        ("G", KH, "turn left, then through the door in front of you",
         [rot_deg(90), ntp(thr(b, "VTD", "VT"), spaces=["VT"], kind="through:VTD")]),
        ("H", KI, "goto(center_of_this_room)", [ntp(circ(*mid_mg, MIDDLE), spaces=["MG"])]),
        ("I", KJ, "go next to the obstacle in front of you, ja", [ntp(next_to_in(ID2, sp["BH"][0]), spaces=["BH"])]),
        ("J", KL, "go along the wall on your left", along((0.15, 3.0, 1.0, 6.0), (0.15, 8.6, 1.0, 9.85), ["BH"])),
        ("A", KA, "um can you go to the biggest room", [ntp(R("BH"), spaces=["BH"])]),
        ("B", KJ, "go to the smallest room, the little one", [ntp(R("WC"), spaces=["WC"])]),
        ("C", KA, "go to center of biggest room", [ntp(circ(*mid_bh, MIDDLE), spaces=["BH"])]),
        ("D", KD, "she says face south", [compass(b.pose(*KD)[2], 270)]),
        ("E", KA, "and face north, lovely", [compass(b.pose(*KA)[2], 90)]),
        ("F", KI, "robot one, proceed to the nearest corner of this room", [ntp(nearest_corner(KI, sp["MG"][0]), spaces=["MG"])]),
        ("G", KD, "go over to the cash machine", "clarify"),
        ("H", KF, "goto(safe_deposit_box_114)", "clarify"),
        ("I", KE, "go to the manager's office", "clarify"),
        ("J", KC, "go behind the counter, to the cashier", "clarify"),
    ]
    assert side_corner(KE, sp["BH"][0], "left") == corner_reg((0.0, 0.0), sp["BH"][0])
    assert side_corner(KE, sp["BH"][0], "right") == corner_reg((0.0, 10.0), sp["BH"][0])
    assert nearest_corner(KI, sp["MG"][0]) == corner_reg((21.0, 4.8), sp["MG"][0])
    assert 12.0 / 0.03 > safe_move(b, KC, "backward")["repeat"][1] + 30
    return b, C


BUILDINGS = lambda: [(datacentre, "dc"), (gym, "gym"), (bank, "bank")]


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
