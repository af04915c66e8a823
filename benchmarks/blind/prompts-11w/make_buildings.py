#!/usr/bin/env python3
"""Draws one new building and writes buildings.jsonl (30 cases):
a VETERINARY PRACTICE (ROTATED 23.7 deg with lidar-like noise, seed 2377; NON-RECTANGULAR outline): a waiting room
with a reception desk and a bench behind an automatic street door (1.8 m) to the never-scanned outside; a staff room
and a toilet off it; a corridor (1.8 m) with two consulting rooms, a pharmacy, an X-ray room whose east end was never
scanned, a treatment room (double door 1.4 m) and the kennel room (two kennel banks with a 0.7 m passage between
them); a back door (1.0 m) to the never-scanned exercise yard.  Door widths 0.7 to 1.8 m.
Every expected region is checked on the drawn map (bld_check.check) and an oracle output built from the
expectations is scored.  Drawing / geometry / check helpers (bld_lib, bld_geom, bld_check, bld_helpers) are copied
from /work/main/benchmarks/blind/prompts-11/; along(), left_obstacle(), front_obstacle() are copied from its
make_buildings.py, sizes() takes a margin argument; the building and prompts are new.
Speaker letters follow spoken.jsonl (A smartwatch, B screen reader, C Thai-first checklist reader, D Yorkshire
farmer, E Gulf Arabic-first engineer, F physiotherapist, G Cantonese-first property manager, H lagging video call,
I stage manager, J Finnish-first forestry worker).
Run: /work/main/.venv/bin/python make_buildings.py
"""
from bld_lib import (OCC, UNK, MIDDLE, BETWEEN, Building, rel, circ, poly, ntp, rot, rot_deg, compass, safe_move)
from bld_geom import door_reg, room_reg, corner_reg, side_corner, nearest_corner, band
from bld_helpers import (nth, within2, mid, nearest_obstacles, frontier_dist, hollow, thr, next_to_in,
                         opposite_far, edge_d, ahead_of)
import bld_check


def along(via, goal, wall_spaces):
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


def sizes(b, big, small, names, margin=10.0):
    areas = {n: b.area(n) for n in names}
    s = sorted(areas.values())
    assert max(areas, key=areas.get) == big and s[-2] < areas[big] - margin, areas
    assert min(areas, key=areas.get) == small and s[1] - areas[small] > 1.0, areas


def vet():
    b = Building("vet", -1.0, -1.0, 26.5, 13.0, theta=23.7, offset=(4.0, 3.0), seed=2377)
    b.shell(0.0, 0.0, 8.0, 7.0); b.shell(0.0, 7.2, 4.0, 11.0); b.shell(4.2, 7.2, 6.0, 9.5)
    b.shell(8.2, 0.0, 25.0, 4.8); b.shell(8.2, 5.0, 14.0, 11.0); b.shell(14.2, 5.0, 25.0, 12.0)
    b.space("WR", (0.0, 0.0, 8.0, 7.0))            # waiting room, street door south
    b.space("SR", (0.0, 7.2, 4.0, 11.0))           # staff room
    b.space("WC", (4.2, 7.2, 6.0, 9.5))            # toilet (smallest)
    b.space("HW", (8.2, 3.0, 25.0, 4.8))           # corridor 1.8 m
    b.space("CR1", (8.2, 0.0, 12.0, 2.8)); b.space("CR2", (12.2, 0.0, 16.0, 2.8))   # consulting rooms
    b.space("PH", (16.2, 0.0, 18.2, 2.8))          # pharmacy
    b.space("XR", (18.4, 0.0, 25.0, 2.8))          # X-ray, east end never scanned
    b.space("TR", (8.2, 5.0, 14.0, 11.0))          # treatment room
    b.space("KN", (14.2, 5.0, 25.0, 12.0))         # kennels (biggest)
    b.door("EX", 4.0, -0.1, "h", "WR", "OUT", width=1.8)      # automatic street door
    b.door("SRD", 2.0, 7.1, "h", "WR", "SR", width=0.8)
    b.door("WCD", 5.1, 7.1, "h", "WR", "WC", width=0.7)
    b.door("HWD", 8.1, 3.9, "v", "WR", "HW", width=1.0)
    b.door("C1D", 10.1, 2.9, "h", "HW", "CR1", width=0.9)
    b.door("C2D", 14.1, 2.9, "h", "HW", "CR2", width=0.9)
    b.door("PHD", 17.2, 2.9, "h", "HW", "PH", width=0.7)
    b.door("XRD", 20.5, 2.9, "h", "HW", "XR", width=1.2)
    b.door("TRD", 11.0, 4.9, "h", "HW", "TR", width=1.4)      # double door
    b.door("KND", 19.0, 4.9, "h", "HW", "KN", width=1.0)
    b.door("TKD", 14.1, 8.0, "v", "TR", "KN", width=0.8)
    b.door("BK", 25.1, 3.9, "v", "HW", "OUT", width=1.0)      # back door, yard never scanned
    b.carve()
    RD = (1.0, 4.5, 4.0, 5.3)                      # reception desk
    BN = (5.5, 0.4, 7.6, 0.9)                      # bench
    TT = (10.5, 7.5, 12.5, 8.5)                    # treatment table
    SC = (13.2, 5.0, 14.0, 5.8)                    # floor scale, in the corner
    K1, K2 = (14.8, 7.5, 18.65, 8.3), (19.35, 7.5, 24.4, 8.3)   # kennel banks, 0.7 m passage
    K3 = (14.8, 10.8, 24.4, 11.4)                  # kennel bank along the north wall
    for o in (RD, BN, TT, SC, K1, K2, K3):
        b.rect(*o, OCC)
    UNK_XR = (23.0, 0.0, 25.0, 2.8)
    b.unknown(*UNK_XR)
    hollow(b)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    HD = ["HWD", "C1D", "C2D", "PHD", "XRD", "TRD", "KND", "BK"]
    WD = ["EX", "SRD", "WCD", "HWD"]
    PA = (8.8, 3.9, 0)        # corridor, west end, facing east
    PB = (24.4, 3.9, 180)     # corridor, east end, facing west
    PC = (2.0, 2.0, 0)        # waiting room, facing east
    PD = (6.0, 5.5, 180)      # waiting room, north-east, facing west
    PE = (19.0, 5.7, 90)      # kennels, the passage straight ahead
    PG = (19.0, 3.9, 90)      # corridor, kennel door straight ahead
    PK = (15.0, 6.0, 0)       # kennels, south-west, facing east
    PT = (9.5, 6.0, 90)       # treatment room, facing north
    PV = (0.8, 1.5, 90)       # waiting room, west wall on the left
    PW = (6.0, 1.5, 90)       # waiting room, facing north
    PX = (19.5, 1.4, 0)       # X-ray room, facing east (dark end ahead)
    PY = (20.5, 1.2, 270)     # X-ray room, facing south, its door behind
    for doors in (HD, HD[1:-1]):                   # the end doors counted or not
        assert nth(b, PA, doors, "right", 2) == "C2D" and nth(b, PA, doors, "right", 3) == "PHD"
        assert nth(b, PA, doors, "right", 1) == "C1D"
        assert nth(b, PA, doors, "left", 1) == "TRD" and nth(b, PA, doors, "left", 2) == "KND"
        assert nth(b, PA, doors, "left", 3) is None
        assert nth(b, PB, doors, "left", 1) == "XRD" and nth(b, PB, doors, "left", 3) == "C2D"
        assert nth(b, PB, doors, "right", 2) == "TRD"
    for doors in (WD, WD[1:]):
        assert nth(b, PW, doors, "right", 1) == "HWD"
    sizes(b, "KN", "WC", [n for n in sp if n != "HW"])
    assert frontier_dist(PC, (3.1, -0.3, 4.9, -0.2)) + 5 < frontier_dist(PC, UNK_XR)
    assert set(nearest_obstacles(PC, dict(RD=RD, BN=BN, TT=TT, SC=SC), 2)) == {"RD", "BN"}
    front_obstacle(PT, dict(TT=TT, SC=SC), "TT")
    left_obstacle(PK, dict(K1=K1, K2=K2, K3=K3), "K1")
    assert abs(rel(PE, 19.0, 7.9)[3]) < 2 and abs(rel(PG, 19.0, 4.9)[3]) < 2
    assert abs(abs(rel(PY, 20.5, 2.9)[3]) - 180) < 2
    mid_wr, mid_kn = b.centroid("WR"), b.centroid("KN")
    outside = band(3.25, 0.1, 4.75, 0.8)
    xr_back = band(22.15, 0.15, 22.85, 2.65)
    gap_n = within2((18.75, 8.45, 19.25, 9.9), 19.0, 8.3)
    C = [
        ("A", PA, "Go to the 2nd door on the right.", [ntp(D("C2D"), spaces=["HW", "CR2", "door:C2D"])]),
        ("A", PB, "Go through the 1st door on your left.", [ntp(thr(b, "XRD", "XR"), spaces=["XR"], kind="through:XRD")]),
        ("A", PC, "Head to the closest corner period", [ntp(nearest_corner(PC, sp["WR"][0]), spaces=["WR"])]),
        ("B", PA, "move to the third doorway on the right-hand side", [ntp(D("PHD"), spaces=["HW", "PH", "door:PHD"])]),
        ("B", PA, "navigate to the second doorway on the left-hand side", [ntp(D("KND"), spaces=["HW", "KN", "door:KND"])]),
        ("B", PC, "move to the centre of the largest room and announce when there", [ntp(circ(*mid_kn, MIDDLE), spaces=["KN"])]),
        ("C", PA, "item sixteen, drive to third door on left side", "clarify"),
        ("C", PC, "item seventeen, drive to nearest unexplored area, check", [ntp(outside, spaces=["WR", "door:EX"], kind="frontier")]),
        ("C", PX, "item eighteen, drive toward unexplored area in this room", [ntp(xr_back, spaces=["XR"], kind="frontier")]),
        ("D", PG, "go through yon door in front o' thee", [ntp(thr(b, "KND", "KN"), spaces=["KN"], kind="through:KND")]),
        ("D", PK, "go an' stand next to t' thing on thi left", [ntp(next_to_in(K1, sp["KN"][0]), spaces=["KN"])]),
        ("D", PD, "get thisen to t' littlest room", [ntp(R("WC"), spaces=["WC"])]),
        ("E", PE, "yalla, go through the narrow gap in front", [ntp(gap_n, spaces=["KN"])]),
        ("E", PT, "go next to the thing in front of you, yalla", [ntp(next_to_in(TT, sp["TR"][0]), spaces=["TR"])]),
        ("E", PK, "go back twenty meter, yalla", {"any": ["clarify", [safe_move(b, PK, "backward")]]}),
        ("F", PC, "walk to the middle of this room for me, nice and slowly", [ntp(circ(*mid_wr, MIDDLE), spaces=["WR"])]),
        ("F", PW, "through the door on your right for me, lovely", [ntp(thr(b, "HWD", "HW"), spaces=["HW"], kind="through:HWD")]),
        ("F", PV, "walk along the wall on your left for me, gently", along((0.15, 2.5, 0.85, 4.0), (0.15, 5.8, 0.85, 6.85), ["WR"])),
        ("G", PB, "go to second door on right side lah", [ntp(D("TRD"), spaces=["HW", "TR", "door:TRD"])]),
        ("G", PC, "go in between the two closest things lah", [ntp(circ(*mid(RD, BN), BETWEEN), spaces=["WR"])]),
        ("G", PT, "go to the left corner of this room ah", [ntp(side_corner(PT, sp["TR"][0], "left"), spaces=["TR"])]),
        ("H", PA, "go to the first, first door on the left", [ntp(D("TRD"), spaces=["HW", "TR", "door:TRD"])]),
        ("H", PC, "go to the big- biggest room", [ntp(R("KN"), spaces=["KN"])]),
        ("H", PK, "can you hear me, go to the opposite side of this room", [ntp(opposite_far(b, "KN", PK), spaces=["KN"])]),
        ("I", PY, "cue twelve go, exit through the door behind you", [ntp(thr(b, "XRD", "HW"), spaces=["HW"], kind="through:XRD")]),
        ("I", PB, "cue thirteen go, to the third door on your left", [ntp(D("C2D"), spaces=["HW", "CR2", "door:C2D"])]),
        ("I", PE, "cue fourteen, go to the cat ward", "clarify"),
        ("J", PK, "to right corner of room", [ntp(side_corner(PK, sp["KN"][0], "right"), spaces=["KN"])]),
        ("J", PC, "to vet table", "clarify"),
        ("J", PA, "through first door right", [ntp(thr(b, "C1D", "CR1"), spaces=["CR1"], kind="through:C1D")]),
    ]
    assert nearest_corner(PC, sp["WR"][0]) == corner_reg((0.0, 0.0), sp["WR"][0])
    assert side_corner(PT, sp["TR"][0], "left") == corner_reg((8.2, 11.0), sp["TR"][0])
    assert side_corner(PK, sp["KN"][0], "right") == corner_reg((25.0, 5.0), sp["KN"][0])
    assert 20.0 / 0.03 > safe_move(b, PK, "backward")["repeat"][1] + 30
    return b, C


if __name__ == "__main__":
    b, C = vet()
    assert len(C) == 30
    for s in "ABCDEFGHIJ":
        assert sum(1 for c in C if c[0] == s) == 3, s
    bld_check.write([(b, "vet", i, spk, pose, prompt, exp) for i, (spk, pose, prompt, exp) in enumerate(C, 1)])
