"""My own unseen check (session 7, grounding helper): a hostel drawn with prompts-7's tooling
(bld_*.py copied), rotated -33.3 deg with lidar-like noise, written from the bench contract before
looking at how langnav reads it. Solid free-standing things (a reception counter, a patrol car, a desk
block) stand in rooms; a 0.7 m gap between a desk block and a cabinet row; an unscanned office corner.
Run: /work/main/.venv/bin/python make_police.py  (writes maps/police.{pgm,yaml}, buildings.jsonl)"""
import math
import numpy as np
from scipy import ndimage
from bld_lib import (RES, OCC, FREE, UNK, Building, rel, circ, poly, ntp, rot, rot_deg, face, move, STOP)
from bld_geom import door_reg, room_reg, through, corner_reg, side_corner, nearest_corner, band
import bld_check


def nth(b, pose, doors, side, n):
    lst = []
    for k in doors:
        d = b.doors[k]
        f, l, dist, _ = rel(pose, d["x"], d["y"])
        assert abs(l) >= 0.3, (k, l)
        if (side == "left") == (l > 0):
            lst.append((dist, k))
    lst.sort()
    i = len(lst) - 1 if n == -1 else n - 1
    if i >= len(lst):
        return None
    for j in (i - 1, i + 1):
        if 0 <= j < len(lst):
            assert abs(lst[j][0] - lst[i][0]) >= 0.5, lst
    return lst[i][1]


def room_cells(b, name):
    xs, ys = [], []
    for r in b.spaces[name]:
        c0, r0, sub = b.local_free(*r)
        rr, cc = np.nonzero(sub)
        xs.append(b.lx0 + (c0 + cc + 0.5) * RES)
        ys.append(b.ly0 + (r0 + rr + 0.5) * RES)
    return np.concatenate(xs), np.concatenate(ys)


def opposite(b, name, pose, axis):
    xs, ys = room_cells(b, name)
    dstar = float(np.quantile(np.hypot(xs - pose[0], ys - pose[1]), 2 / 3))
    x0, y0, x1, y1 = b.spaces[name][0]
    px, py = pose[0], pose[1]
    if axis == "+x":
        lo = max(x0 + 2 * (x1 - x0) / 3, px + dstar); r = (lo, y0, x1, y1)
    elif axis == "+y":
        lo = max(y0 + 2 * (y1 - y0) / 3, py + dstar); r = (x0, lo, x1, y1)
    else:
        raise ValueError(axis)
    m = (xs >= r[0]) & (xs <= r[2]) & (ys >= r[1]) & (ys <= r[3])
    assert np.hypot(xs[m] - px, ys[m] - py).min() >= dstar - 1e-9
    return poly(*[round(v, 3) for v in r])


def next_to(o):
    x0, y0, x1, y1 = o
    return {"any": [poly(x0, y1, x1, y1 + 1.0), poly(x0, y0 - 1.0, x1, y0),
                    poly(x0 - 1.0, y0, x0, y1), poly(x1, y0, x1 + 1.0, y1)]}


def hollow(b, ring=3):
    d = ndimage.distance_transform_edt(b.g == OCC)
    b.g[d > ring] = UNK


def hostel():
    b = Building("hostel", -1.0, -1.5, 27.0, 17.0, theta=-33.3, offset=(2.0, 16.0), seed=3303)
    b.shell(0.0, 0.0, 26.0, 15.0)
    b.space("HW", (0.0, 6.0, 26.0, 7.8))           # corridor
    b.space("DR1", (0.0, 8.0, 5.0, 13.0)); b.space("DR2", (5.2, 8.0, 10.0, 13.0))   # dorms
    b.space("CM", (10.2, 8.0, 18.0, 15.0))         # common room (biggest)
    b.space("KT", (18.2, 8.0, 26.0, 13.0))         # kitchen, island in the middle
    b.space("RC", (0.0, 0.0, 6.0, 5.8))            # reception
    b.space("WC", (6.2, 2.5, 9.0, 5.8))            # toilets (smallest)
    b.space("LD", (9.2, 0.0, 14.0, 5.8))           # laundry
    b.space("BK", (14.2, 0.0, 20.0, 5.8))          # bike room
    b.space("ST", (20.2, 0.0, 26.0, 5.8))          # store (south-east part not scanned)
    b.door("EX", 3.0, -0.1, "h", "RC", "OUT", width=1.6)
    for n, x in (("DR1", 2.5), ("DR2", 7.5), ("CM", 12.0), ("CM2", 16.5), ("KT", 22.0)):
        b.door(n, x, 7.9, "h", "HW", n[:2] if n == "CM2" else n, width=1.2 if n == "CM" else 0.9)
    for n, x in (("RC", 3.0), ("WC", 7.6), ("LD", 11.6), ("BK", 17.0), ("ST", 23.0)):
        b.door(n, x, 5.9, "h", "HW", n, width={"RC": 1.2, "WC": 0.8, "BK": 1.0}.get(n, 0.9))
    b.door("CMKT", 18.1, 11.0, "v", "CM", "KT", width=0.9)
    b.carve()
    IS = (20.5, 10.0, 23.5, 11.2)      # kitchen island
    SF = (11.5, 13.5, 13.5, 14.3)      # sofa
    R1, R2 = (15.5, 2.0, 16.1, 4.0), (16.8, 2.0, 17.4, 4.0)   # bike racks: 0.7 m aisle
    MC = (9.2, 0.0, 14.0, 0.8)         # washing machines along the south wall
    DK = (0.5, 4.0, 2.0, 4.8)          # reception desk
    for o in (IS, SF, R1, R2, MC, DK):
        b.rect(*o, OCC)
    UNK_ST = (23.0, 0.0, 26.0, 2.5)
    b.unknown(*UNK_ST)
    hollow(b)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    HA = (0.8, 6.9, 0)        # corridor, west end, facing east
    HB = (25.2, 6.9, 180)     # corridor, east end, facing west
    HD = (19.3, 12.0, 0)      # kitchen, facing east (the island ahead)
    HE = (11.0, 9.0, 45)      # common room, facing north-east
    HF = (11.6, 4.0, 90)      # laundry, facing north (its door ahead, the common room across)
    HG = (16.45, 5.0, 270)    # bike room, facing south (the aisle between the racks ahead)
    HI = (2.0, 2.0, 90)       # reception, facing north
    HD_ = ["DR1", "DR2", "CM", "CM2", "KT", "RC", "WC", "LD", "BK", "ST"]
    assert nth(b, HA, HD_, "left", 3) == "CM" and nth(b, HA, HD_, "right", 2) == "WC"
    assert nth(b, HA, HD_, "right", 4) == "BK" and nth(b, HA, HD_, "left", -1) == "KT"
    assert nth(b, HA, HD_, "right", 6) is None
    assert nth(b, HB, HD_, "right", 1) == "KT" and nth(b, HB, HD_, "left", 2) == "BK"
    areas = {n: b.area(n) for n in b.spaces if n != "HW"}
    assert max(areas, key=areas.get) == "CM" and min(areas, key=areas.get) == "WC"
    assert rel(HD, 18.1, 11.0)[3] < -120 or rel(HD, 18.1, 11.0)[3] > 120
    assert rel(HE, 12.5, 13.9)[1] > 0
    mid = lambda n: circ(*b.centroid(n), 0.75)
    ust = {"any": [band(23.1, 2.55, 25.9, 3.4), band(22.05, 0.1, 22.95, 2.4)]}
    aisle_s = poly(15.8, 1.0, 17.1, 1.95)
    C = [
        ("A", HA, "go to the third door on your left", [ntp(D("CM"), spaces=["HW", "CM", "door:CM"])]),
        ("A", HA, "go to the second door on your right", [ntp(D("WC"), spaces=["HW", "WC", "door:WC"])]),
        ("A", HA, "go through the fourth door on your right", [ntp(through(b, "BK", "BK"), spaces=["BK"], kind="through:BK")]),
        ("A", HA, "go to the last door on the left", [ntp(D("KT"), spaces=["HW", "KT", "door:KT"])]),
        ("A", HA, "go to the sixth door on your right", "clarify"),
        ("A", HA, "go to the room of the manager", "clarify"),
        ("B", HB, "go to the first door on your right", [ntp(D("KT"), spaces=["HW", "KT", "door:KT"])]),
        ("B", HB, "go through the second door on your left", [ntp(through(b, "BK", "BK"), spaces=["BK"], kind="through:BK")]),
        ("B", HB, "go to the biggest room", [ntp(R("CM"), spaces=["CM"])]),
        ("B", HB, "go to the smallest room", [ntp(R("WC"), spaces=["WC"])]),
        ("B", HB, "go towards the nearest unexplored area", [ntp(ust, spaces=["ST"], kind="frontier")]),
        ("B", HB, "go to the middle of the biggest room", [ntp(mid("CM"), spaces=["CM"])]),
        ("D", HD, "go next to the obstacle in front of you", [ntp(next_to(IS), spaces=["KT"])]),
        ("D", HD, "go to the opposite side of this room", [ntp(opposite(b, "KT", HD, "+x"), spaces=["KT"])]),
        ("D", HD, "go through the door behind you", [ntp(through(b, "CMKT", "CM"), spaces=["CM"], kind="through:CMKT")]),
        ("D", HD, "go to the right corner of this room", [ntp(side_corner(HD, b.spaces["KT"][0], "right"), spaces=["KT"])]),
        ("D", HD, "go to the nearest door", [ntp(D("CMKT"), spaces=["KT", "CM", "door:CMKT"])]),
        ("E", HE, "go to the farthest corner of this room", [ntp(corner_reg((18.0, 15.0), b.spaces["CM"][0]), spaces=["CM"])]),
        ("E", HE, "go to the corner behind you", [ntp(corner_reg((10.2, 8.0), b.spaces["CM"][0]), spaces=["CM"])]),
        ("E", HE, "go to the middle of this room", [ntp(mid("CM"), spaces=["CM"])]),
        ("E", HE, "go to the nearest door", [ntp(D("CM"), spaces=["HW", "CM", "door:CM"])]),
        ("E", HE, "go next to the obstacle on your left", [ntp(next_to(SF), spaces=["CM"])]),
        ("F", HF, "go into the room across the hall", [ntp(R("CM"), spaces=["CM"])]),
        ("F", HF, "go to the middle of this room", [ntp(mid("LD"), spaces=["LD"])]),
        ("G", HG, "go through the narrow passage ahead", [ntp(aisle_s, spaces=["BK"])]),
        ("G", HG, "go to the left corner of this room", [ntp(side_corner(HG, b.spaces["BK"][0], "left"), spaces=["BK"])]),
        ("I", HI, "go through the door in front of you", [ntp(through(b, "RC", "HW", depth=1.7, half=1.0), spaces=["HW"], kind="through:RC")]),
        ("I", HI, "take me to the kitchen", "clarify"),
        ("I", HI, "go to the nearest corner", [ntp(nearest_corner(HI, b.spaces["RC"][0]), spaces=["RC"])]),
        ("I", HI, "go to the biggest room", [ntp(R("CM"), spaces=["CM"])]),
    ]
    return b, C


def main():
    b, C = hostel()
    out = [(b, "hos", i, spk, pose, prompt, exp) for i, (spk, pose, prompt, exp) in enumerate(C, 1)]
    bld_check.write(out)


if __name__ == "__main__":
    main()
