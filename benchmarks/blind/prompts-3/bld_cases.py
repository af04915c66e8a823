"""Hotel floor (rotated 17 deg, noisy) and home; check() and the oracle run.  Used by make_buildings.py."""
import json
import math
import subprocess
import sys

import numpy as np
from scipy import ndimage

from bld_lib import (HERE, RES, OCC, FREE, UNK, AT_DOOR, MIDDLE, BETWEEN, Building, rel, circ, poly, ntp, rot,
                     rot_deg, face, move, compass, safe_move, STOP)
from make_buildings import (door_reg, room_reg, through, corner_reg, side_corner, nearest_corner, nth_door, band,
                            school)


# ================================================================== hotel floor, rotated 17 degrees
def hotel():
    b = Building("hotel", -1.0, -1.0, 31.0, 16.0, theta=17.0, offset=(6.0, 1.0), seed=17)
    b.shell(0.0, 0.0, 30.0, 15.0)
    b.space("C", (0.0, 7.0, 30.0, 8.8))                 # corridor
    b.space("L", (15.0, 8.8, 19.0, 12.0))               # lift lobby: an alcove open to the corridor, no door
    b.space("ICE", (15.0, 12.2, 19.0, 15.0))            # small room off the lobby
    north = {"R1": (0.0, 4.8), "R2": (5.0, 9.8), "R3": (10.0, 14.8), "R4": (19.2, 24.0), "R5": (24.2, 30.0)}
    south = {"Q1": (0.0, 4.8), "Q2": (5.0, 9.8), "Q3": (10.0, 14.8), "Q4": (15.0, 19.8), "Q5": (20.0, 24.8),
             "Q6": (25.0, 30.0)}
    for n, (x0, x1) in north.items():
        b.space(n, (x0, 9.0, x1, 15.0))
        b.door(n, x0 + 3.6, 8.9, "h", "C", n)
    for n, (x0, x1) in south.items():
        b.space(n, (x0, 0.0, x1, 6.8))
        b.door(n, x0 + 1.2, 6.9, "h", "C", n)
    b.door("ICE", 17.0, 12.1, "h", "L", "ICE")
    b.carve()
    for n, (x0, x1) in north.items():
        b.rect(x0 + 1.4, 13.0, x0 + 3.4, 15.0, OCC)     # beds against the north walls
    for n, (x0, x1) in south.items():
        if n != "Q6":
            b.rect(x0 + 1.4, 0.0, x0 + 3.4, 2.0, OCC)   # beds against the south walls
    b.rect(23.8, 7.0, 25.4, 8.0, OCC)                    # housekeeping cart: corridor narrowed to 0.8 m
    b.unknown(25.0, 0.0, 30.0, 3.4)                      # south part of Q6 not scanned
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    HALL = [["C"], ["C", "L"]]
    HA = (0.8, 7.9, 0)        # west end of the corridor, facing east (left = north rooms)
    HB = (29.2, 7.9, 180)     # east end, facing west (left = south rooms)
    HC = (7.4, 4.0, 90)       # in Q2, facing north
    HD = (16.0, 7.6, 0)       # corridor at the lobby, facing east
    HE = (12.4, 11.5, 270)    # in R3, facing south
    HE2 = (11.2, 10.2, 270)   # in R3 near its south-west corner, facing south
    HF = (22.0, 7.9, 0)       # corridor west of the cart, facing east
    HG = (17.0, 10.5, 90)     # in the lobby, facing north
    nd = lambda pose, side, n: nth_door(b, pose, HALL, side, n)
    assert nd(HA, "left", 3) == "R3" and nd(HA, "right", 2) == "Q2" and nd(HA, "left", 1) == "R1"
    assert nd(HA, "left", 2) == "R2" and nd(HA, "right", -1) == "Q6"
    assert nd(HB, "left", 1) == "Q6" and nd(HB, "right", 2) == "R4" and nd(HB, "left", 7) is None
    assert nd(HB, "right", 1) == "R5" and nd(HF, "left", 2) == "R5"
    assert nth_door(b, HD, HALL, "right", 1) == "Q4"
    gap_e = band(25.4, 7.3, 26.2, 8.8)            # east of the cart gap, within 2 m of its centre (24.6, 8.4)
    gap_w = band(23.0, 7.3, 23.8, 8.8)            # west of it
    for (x0, y0, x1, y1) in ((25.4, 7.3, 26.2, 8.8), (23.0, 7.3, 23.8, 8.8)):
        assert all(math.hypot(x - 24.6, y - 8.4) <= 2.0 for x in (x0, x1) for y in (y0, y1))
    q6_front = band(25.0, 3.4, 30.0, 4.4)         # Q6's scanned part within 1 m of its unscanned half
    mid_r3 = b.centroid("R3")
    wy = lambda pose: (pose[2] + b.theta) % 360   # world yaw
    C = [
        ("A", HA, "um, go to the third door on your left?", [ntp(D("R3"), spaces=["C", "R3", "door:R3"])]),
        ("I", HA, "go 2 the 2nd door on ur right", [ntp(D("Q2"), spaces=["C", "Q2", "door:Q2"])]),
        ("J", HA, "go to the second door on your right, then go into the room across the hall",
         [ntp(R("R2"), via=[D("Q2")], spaces=["R2"], via_spaces=["C", "Q2", "door:Q2"])]),
        ("H", HA, "go halfway down the hall and stop", [ntp(band(14.0, 7.0, 16.5, 8.8), spaces=["C", "L"])]),
        ("B", HA, "go to end of corridor", [ntp(band(28.8, 7.0, 30.0, 8.8), spaces=["C"])]),
        ("K", HA, "Could you please take me to the elevator?", "clarify"),
        ("E", HA, "go into the last room on the right", [ntp(R("Q6"), spaces=["Q6"])]),
        ("G", HA, "turn to face due north", [compass(wy(HA), 90)]),
        ("F", HA, "move forward 7 metres and then go through the door on your left",
         [move("forward", 7.0), ntp(through(b, "R2", "R2"), spaces=["R2"], kind="through:R2")]),
        ("D", HA, "stop between the first and second doors on your left",
         [ntp(circ(6.1, 8.9, BETWEEN), spaces=["C", "R2", "R1", "door:R1", "door:R2"])]),
        ("L", HA, "go to the first door on your left- no, the first door on your right", [ntp(D("Q1"), spaces=["C", "Q1", "door:Q1"])]),
        ("C", HA, "go to first door on left, then room across hall",
         [ntp(R("Q1"), via=[D("R1")], spaces=["Q1"], via_spaces=["C", "R1", "door:R1"])]),
        ("A", HB, "could you go to the first door on your left, please?", [ntp(D("Q6"), spaces=["C", "Q6", "door:Q6"])]),
        ("H", HB, "second door on the right", [ntp(D("R4"), spaces=["C", "R4", "door:R4"])]),
        ("J", HB, "go towards the unexplored area", [ntp(q6_front, spaces=["Q6"], kind="frontier")]),
        ("G", HB, "turn to face the first door on your left", [face(HB, 26.2, 6.9)]),
        ("K", HB, "Would you kindly go to the smallest room on this floor?", [ntp(R("ICE"), spaces=["ICE"])]),
        ("E", HB, "go to the seventh door on your left", "clarify"),
        ("B", HB, "face to the west", [compass(wy(HB), 180)]),
        ("D", HB, "back up two meters", {"any": ["clarify", [safe_move(b, HB, "backward")]]}),
        ("L", HB, "go to the door on your left, no wait, on your right", [ntp(D("R5"), spaces=["C", "R5", "door:R5"])]),
        ("I", HC, "go 2 the room across teh hall", [ntp(R("R2"), spaces=["R2"])]),
        ("F", HC, "turn toward the door of this room", [face(HC, 6.2, 6.9)]),
        ("C", HC, "go to left corner of this room", [ntp(side_corner(HC, sp["Q2"][0], "left"), spaces=["Q2"])]),
        ("A", HC, "um, could you go into the room on your right?", [ntp(R("Q3"), spaces=["Q3"])]),
        ("H", HC, "go out of the room and turn left",
         [ntp(through(b, "Q2", "C"), spaces=["C"], kind="through:Q2"), rot_deg(90)]),
        ("J", HC, "go out into the hallway, then go to the first door on your left", [ntp(D("R1"), spaces=["C", "R1", "door:R1"])]),
        ("G", HD, "go through the door on your right", [ntp(through(b, "Q4", "Q4"), spaces=["Q4"], kind="through:Q4")]),
        ("K", HG, "Would you mind going through the door in front of you?", [ntp(through(b, "ICE", "ICE"), spaces=["ICE"], kind="through:ICE")]),
        ("B", HG, "turn around, then go into the room across the hall", [rot("any", 17, 19), ntp(R("Q4"), spaces=["Q4"])]),
        ("E", HE, "go out of the room and turn right",
         [ntp(through(b, "R3", "C"), spaces=["C"], kind="through:R3"), rot_deg(-90)]),
        ("D", HE, "go into the room on the other side of the hall", [ntp(R("Q3"), spaces=["Q3"])]),
        ("F", HE, "go to the room next door", "clarify"),
        ("L", HE2, "go to the, uh, nearest corner", [ntp(nearest_corner(HE2, sp["R3"][0]), spaces=["R3"])]),
        ("C", HE2, "go to middle of the room", [ntp(circ(*mid_r3, MIDDLE), spaces=["R3"])]),
        ("I", HF, "go thru the narrow bit ahead", [ntp(gap_e, spaces=["C"], kind="through_gap")]),
        ("A", HF, "sorry, could you go to the second door on your left?", [ntp(D("R5"), spaces=["C", "R5", "door:R5"])]),
        ("H", HB, "go through the narrow passage ahead of you", [ntp(gap_w, spaces=["C"], kind="through_gap")]),
        ("G", HA, "head to the ice machine", "clarify"),
        ("K", HD, "Could you please go to room two hundred and twelve?", "clarify"),
    ]
    return b, C


# ================================================================== home
def home():
    b = Building("home", -1.0, -1.0, 15.0, 15.0)
    b.shell(0.0, 0.0, 14.0, 14.0)
    b.space("LK", (0.0, 0.0, 8.0, 7.0))      # open living room + kitchen
    b.space("HW", (8.2, 3.0, 9.6, 14.0))     # hallway
    b.space("BR1", (9.8, 3.0, 14.0, 7.0)); b.space("BATH", (9.8, 7.2, 14.0, 9.6))
    b.space("BR2", (9.8, 9.8, 14.0, 14.0)); b.space("BR3", (3.0, 7.2, 8.0, 14.0))
    b.space("ST", (0.0, 7.2, 2.8, 14.0));    b.space("LD", (8.2, 0.0, 14.0, 2.8))
    b.door("ARCH", 8.1, 5.5, "v", "HW", "LK", width=1.2)   # doorless opening between living room and hallway
    b.door("BR3", 8.1, 11.0, "v", "HW", "BR3")
    b.door("BR1", 9.7, 4.0, "v", "HW", "BR1")
    b.door("BATH", 9.7, 8.4, "v", "HW", "BATH")
    b.door("BR2", 9.7, 12.9, "v", "HW", "BR2")
    b.door("ST", 1.4, 7.1, "h", "LK", "ST")
    b.door("LD", 13.0, 2.9, "h", "BR1", "LD")
    b.carve()
    b.rect(1.0, 2.0, 3.5, 2.8, OCC)      # sofa
    b.rect(5.0, 3.5, 6.5, 4.3, OCC)      # kitchen island
    b.rect(4.5, 11.5, 6.5, 14.0, OCC)    # bed in BR3
    b.rect(3.0, 9.3, 5.6, 10.0, OCC)     # wardrobe in BR3 (touches the west wall)
    b.rect(6.3, 9.3, 8.0, 10.0, OCC)     # desk in BR3 (touches the east wall); gap 5.6..6.3 = 0.7 m
    b.unknown(12.5, 9.8, 14.0, 14.0)     # east part of BR2 not scanned
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    sp = b.spaces
    HALL = [["HW"]]
    MA = (8.9, 3.6, 90)       # south end of the hallway, facing north (left = living room, BR3)
    MB = (2.0, 4.0, 0)        # living room, facing east
    MC = (8.9, 13.4, 270)     # north end of the hallway, facing south (left = BR2, BATH, BR1)
    MD = (11.5, 6.0, 180)     # in BR1, facing west
    ME = (5.95, 10.6, 270)    # BR3 north part, facing south at the gap between wardrobe and desk
    MF = (5.0, 8.2, 0)        # BR3 south part (behind the gap), facing east
    nd = lambda pose, side, n: nth_door(b, pose, HALL, side, n)
    assert nd(MA, "right", 1) == "BR1" and nd(MA, "right", 2) == "BATH" and nd(MA, "right", 3) == "BR2"
    assert nd(MA, "left", 1) == "ARCH" and nd(MA, "left", 2) == "BR3"
    assert nd(MC, "right", 1) == "BR3" and nd(MC, "left", 3) == "BR1" and nd(MC, "left", -1) == "BR1"
    assert nd(MC, "left", 4) is None
    # living room doors seen from MB: the study door is the nearest on the left
    assert nth_door(b, MB, [["LK"]], "left", 1) == "ST"
    assert nth_door(b, MD, [["BR1"]], "left", 1) == "BR1"
    areas = {n: b.area(n) for n in ("LK", "BR1", "BATH", "BR2", "BR3", "ST", "LD")}
    assert max(areas, key=areas.get) == "LK" and min(areas, key=areas.get) == "BATH"
    gap_s = band(5.1, 7.9, 6.8, 9.3)       # south of the BR3 gap (centre 5.95, 9.65), within 2 m
    gap_n = band(5.1, 10.0, 6.8, 11.4)     # north of it
    for (x0, y0, x1, y1) in ((5.1, 7.9, 6.8, 9.3), (5.1, 10.0, 6.8, 11.4)):
        assert all(math.hypot(x - 5.95, y - 9.65) <= 2.0 for x in (x0, x1) for y in (y0, y1))
    br2_front = band(11.5, 9.8, 12.5, 14.0)
    isl = (5.0, 3.5, 6.5, 4.3)
    next_isl = {"any": [poly(isl[0], isl[3], isl[2], isl[3] + 1.0), poly(isl[0], isl[1] - 1.0, isl[2], isl[1]),
                        poly(isl[0] - 1.0, isl[1], isl[0], isl[3]), poly(isl[2], isl[1], isl[2] + 1.0, isl[3])]}
    mid_lk = b.centroid("LK")
    C = [
        ("A", MA, "um, can you go to the first door on the right?", [ntp(D("BR1"), spaces=["HW", "BR1", "door:BR1"])]),
        ("B", MA, "2nd door right", [ntp(D("BATH"), spaces=["HW", "BATH", "door:BATH"])]),
        ("I", MA, "go thru the 3rd door on ur right", [ntp(through(b, "BR2", "BR2"), spaces=["BR2"], kind="through:BR2")]),
        ("C", MA, "go through opening on your left", [ntp(through(b, "ARCH", "LK"), spaces=["LK"], kind="through:ARCH")]),
        ("E", MA, "I want you to go to the kitchen", "clarify"),
        ("F", MA, "go to the end of the hallway", [ntp(band(8.2, 12.8, 9.6, 14.0), spaces=["HW"])]),
        ("H", MA, "stop halfway down the hallway", [ntp(band(8.2, 7.7, 9.6, 9.6), spaces=["HW"])]),
        ("G", MA, "go to the second door on your left", [ntp(D("BR3"), spaces=["HW", "BR3", "door:BR3"])]),
        ("K", MA, "Would you please go into the room across the hall from the bathroom?", "clarify"),
        ("J", MA, "go through the second door on your right and then turn around",
         [ntp(through(b, "BATH", "BATH"), spaces=["BATH"], kind="through:BATH"), rot("any", 17, 19)]),
        ("L", MA, "move forward six- six metres, then go through the door on your left",
         [move("forward", 6.0), ntp(through(b, "BR3", "BR3"), spaces=["BR3"], kind="through:BR3")]),
        ("D", MA, "turn to face the first door on your left hand side", [face(MA, 8.1, 5.5)]),
        ("E", MB, "go through the opening in front of you", [ntp(through(b, "ARCH", "HW"), spaces=["HW"], kind="through:ARCH")]),
        ("A", MB, "sorry, could you go to the door on your left?", [ntp(D("ST"), spaces=["LK", "ST", "door:ST"])]),
        ("B", MB, "go to right corner of room", [ntp(side_corner(MB, sp["LK"][0], "right"), spaces=["LK"])]),
        ("K", MB, "Could you go to the left corner of this room, please?", [ntp(side_corner(MB, sp["LK"][0], "left"), spaces=["LK"])]),
        ("G", MB, "go to the centre of this room", [ntp(circ(*mid_lk, MIDDLE), spaces=["LK"])]),
        ("H", MB, "park next to the obstacle ahead of you", [ntp(next_isl, spaces=["LK"])]),
        ("I", MB, "go btwn the 2 obstacles", [ntp(circ(4.0, 3.15, BETWEEN), spaces=["LK"])]),
        ("J", MB, "go forward 2 metres, turn left, and go to the door in front of you",
         [move("forward", 2.0), rot_deg(90), ntp(D("ST"), spaces=["LK", "ST", "door:ST"])]),
        ("C", MB, "you go to bedroom please", "clarify"),
        ("F", MC, "drive to the first door on your right-hand side", [ntp(D("BR3"), spaces=["HW", "BR3", "door:BR3"])]),
        ("D", MC, "go into the second room on your left", [ntp(R("BATH"), spaces=["BATH"])]),
        ("L", MC, "go through the last- the last door on your left", [ntp(through(b, "BR1", "BR1"), spaces=["BR1"], kind="through:BR1")]),
        ("A", MC, "um, could you go to the biggest room?", [ntp(R("LK"), spaces=["LK"])]),
        ("K", MC, "Would you be so kind as to go to the smallest room?", [ntp(R("BATH"), spaces=["BATH"])]),
        ("E", MC, "go over towards the bit that hasn't been mapped yet", [ntp(br2_front, spaces=["BR2"], kind="frontier")]),
        ("G", MC, "go to the fourth door on your left", "clarify"),
        ("B", MC, "halfway down hallway, then turn left",
         [ntp(band(8.2, 7.5, 9.6, 9.5), spaces=["HW"]), rot_deg(90)]),
        ("H", MC, "go to the third door on the left", [ntp(D("BR1"), spaces=["HW", "BR1", "door:BR1"])]),
        ("I", MD, "go out teh door on ur left and turn right",
         [ntp(through(b, "BR1", "HW"), spaces=["HW"], kind="through:BR1"), rot_deg(-90)]),
        ("J", MD, "go into the room beside this one", "clarify"),
        ("C", MD, "go to the laundry room", "clarify"),
        ("F", ME, "go through the narrow gap in front of you", [ntp(gap_s, spaces=["BR3"], kind="through_gap")]),
        ("D", ME, "go to the door", [ntp(D("BR3"), spaces=["BR3", "HW", "door:BR3"])]),
        ("L", MF, "go to the nearest, um, corner", [ntp(nearest_corner(MF, sp["BR3"][0]), spaces=["BR3"])]),
        ("A", MF, "could you turn to face the gap?", [face(MF, 5.95, 9.65)]),
        ("K", MF, "Would you go back through the gap and then out through the door, please?",
         [ntp(through(b, "BR3", "HW"), via=[gap_n], spaces=["HW"], via_spaces=["BR3"], kind="through:BR3")]),
        ("G", MB, "go to the study", "clarify"),
        ("B", MA, "go to the nearest door on your left, then turn right", [ntp(D("ARCH"), spaces=["HW", "LK", "door:ARCH"]), rot_deg(-90)]),
    ]
    return b, C


MORE = ((hotel, "hot"), (home, "hom"))


# ================================================================== checks and output
def strip_meta(cmd):
    return {k: v for k, v in cmd.items() if not k.startswith("_")}


def world_expect(b, exp):
    def one(alt):
        if alt == "clarify":
            return "clarify"
        out = []
        for c in alt:
            c = strip_meta(c)
            if c["command"] == "NavigateThroughPoses":
                c["goal"] = b.region(c["goal"])
                if "via" in c:
                    c["via"] = [b.region(v) for v in c["via"]]
            out.append(c)
        return out
    if isinstance(exp, dict):
        return {"any": [one(a) for a in exp["any"]]}
    return one(exp)


def check(b, cases):
    """Each expected region: (1) holds at least 8 valid cells reachable from the start (score.py's
    own Map), (2) every such cell lies in the intended space(s) of the drawing, (3) for a
    frontier goal every such cell is within 1.0 m of a frontier cell of a real unexplored area
    (>= 20 unknown cells), (4) for a 'through' goal every such cell is within 2.0 m of the door."""
    from score import Map, in_region
    mp = Map((HERE / "maps" / f"{b.name}.yaml").resolve())
    rr, cc = np.nonzero(mp.ok & (mp.labels > 0))
    xs = mp.origin[0] + (cc + 0.5) * mp.res
    ys = mp.origin[1] + (rr + 0.5) * mp.res
    lab = mp.labels[rr, cc]
    # frontier distance
    unk = mp.grid == UNK
    ul, un = ndimage.label(unk, structure=np.ones((3, 3)))
    sizes = ndimage.sum(unk, ul, range(1, un + 1))
    big = np.isin(ul, np.nonzero(sizes >= 20)[0] + 1)
    frontier = (mp.grid == FREE) & ndimage.binary_dilation(big, np.ones((3, 3), bool))
    fdist = ndimage.distance_transform_edt(~frontier) * mp.res
    report = []
    for (spk, pose, prompt, exp) in cases:
        X, Y, _ = b.pose(*pose)
        comp = mp.component_of(X, Y)
        assert comp is not None and mp.valid(X, Y), (b.name, prompt, "start invalid")
        assert b.space_of_local(pose[0], pose[1]) is not None
        sel = lab == comp
        alts = exp["any"] if isinstance(exp, dict) else [exp]
        for alt in alts:
            if alt == "clarify":
                continue
            for c in alt:
                if c["command"] != "NavigateThroughPoses":
                    continue
                regs = [(c["goal"], c.get("_spaces"), c.get("_kind"))] + \
                       [(v, c.get("_via_spaces"), None) for v in c.get("via", [])]
                for reg, spaces, kind in regs:
                    wreg = b.region(reg)
                    inside = np.array([in_region(wreg, x, y) for x, y in zip(xs[sel], ys[sel])], bool)
                    n = int(inside.sum())
                    assert n >= 8, (b.name, prompt, reg, "only %d valid reachable cells" % n)
                    assert spaces, (b.name, prompt, "no intended space given")
                    bad = set()
                    for x, y in zip(xs[sel][inside], ys[sel][inside]):
                        s = b.space_of_local(*b.to_local(x, y))
                        if s not in spaces:
                            bad.add(s)
                    assert not bad, (b.name, prompt, "region reaches", bad)
                    if kind == "frontier":
                        r_ = ((ys[sel][inside] - mp.origin[1]) / mp.res).astype(int)
                        c_ = ((xs[sel][inside] - mp.origin[0]) / mp.res).astype(int)
                        assert fdist[r_, c_].max() <= 1.0 + 1e-6, (b.name, prompt, "frontier", fdist[r_, c_].max())
                    if kind and kind.startswith("through:"):
                        d = b.doors[kind.split(":")[1]]
                        DX, DY = b.to_world(d["x"], d["y"])
                        dd = np.hypot(xs[sel][inside] - DX, ys[sel][inside] - DY).max()
                        assert dd <= 2.0, (b.name, prompt, "through beyond 2 m", dd)
                    report.append((b.name, prompt[:40], n))
    return report


def oracle_output(case, mp, comp_cells):
    """An output that follows the expectation (first alternative): a valid cell in each region."""
    from score import in_region
    exp = case["expect"]
    alt = exp["any"][0] if isinstance(exp, dict) else exp
    if alt == "clarify":
        return {"id": case["id"], "commands": [], "clarification": "Which one do you mean?"}
    xs, ys = comp_cells
    cmds = []
    for c in alt:
        if c["command"] == "NavigateThroughPoses":
            poses = []
            for reg in c.get("via", []) + [c["goal"]]:
                k = next(i for i in range(len(xs)) if in_region(reg, xs[i], ys[i]))
                poses.append([round(float(xs[k]), 3), round(float(ys[k]), 3)])
            cmds.append({"command": "NavigateThroughPoses", "poses": poses})
        elif c["command"] in ("Move", "Rotate"):
            d = c["direction"] if c["direction"] != "any" else "left"
            cmds.append({"command": c["command"], "direction": d, "repeat": c["repeat"][0]})
        else:
            cmds.append({"command": c["command"]})
    return {"id": case["id"], "commands": cmds, "clarification": None}


def write(rows):
    from score import Map
    out, report = [], []
    by_b = {}
    for (b, tag, i, spk, pose, prompt, exp) in rows:
        by_b.setdefault(b.name, (b, []))[1].append((spk, pose, prompt, exp))
    for name, (b, cases) in by_b.items():
        report += check(b, cases)
    for (b, tag, i, spk, pose, prompt, exp) in rows:
        out.append({"id": f"b3-{tag}-{spk}{i:02d}", "map": f"maps/{b.name}.yaml", "pose": b.pose(*pose),
                    "prompt": prompt, "expect": world_expect(b, exp)})
    ids = [c["id"] for c in out]
    assert len(set(ids)) == len(ids)
    (HERE / "buildings.jsonl").write_text("".join(json.dumps(c) + "\n" for c in out))
    # oracle: score.py must give 1.0 on an output built from the expectations
    orc = []
    maps = {}
    for c in out:
        if c["map"] not in maps:
            mp = Map((HERE / c["map"]).resolve())
            maps[c["map"]] = mp
        mp = maps[c["map"]]
        comp = mp.component_of(c["pose"][0], c["pose"][1])
        rr, cc = np.nonzero(mp.ok & (mp.labels == comp))
        # prefer cells far from walls: sort by clearance
        orc.append(oracle_output(c, mp, (mp.origin[0] + (cc + 0.5) * mp.res, mp.origin[1] + (rr + 0.5) * mp.res)))
    (HERE / "out").mkdir(exist_ok=True)
    (HERE / "out" / "buildings.oracle.jsonl").write_text("".join(json.dumps(o) + "\n" for o in orc))
    print(len(out), "cases;", len(report), "regions checked; smallest region has",
          min(r[2] for r in report), "valid cells")
