"""My own unseen check (session 7, grounding helper): a police station drawn with prompts-7's tooling
(bld_*.py copied), rotated 13.7 deg with lidar-like noise, written from the bench contract before
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


def police():
    b = Building("police", -1.0, -1.5, 25.0, 20.5, theta=13.7, offset=(2.0, 1.0), seed=1377)
    b.shell(0.0, 0.0, 24.0, 19.0)
    b.space("LB", (0.0, 0.0, 9.0, 7.0))            # public lobby
    b.space("HW", (0.0, 7.2, 24.0, 9.0))           # corridor, 1.8 m
    b.space("IV1", (0.0, 9.2, 3.8, 13.0)); b.space("IV2", (4.0, 9.2, 8.0, 13.0))   # interview rooms
    b.space("OF", (8.2, 9.2, 17.0, 19.0))          # open office (biggest)
    b.space("LK", (17.2, 9.2, 20.0, 13.0))         # locker room
    b.space("CB", (20.2, 9.2, 24.0, 15.0))         # cell block
    b.space("CS", (9.2, 0.0, 16.0, 7.0))           # custody suite
    b.space("AR", (16.2, 4.5, 19.0, 7.0))          # armoury (smallest)
    b.space("GR", (19.2, 0.0, 24.0, 7.0))          # garage
    # the walls north of IV1/IV2 and LK/CB up to the outline: fill as wall
    b.door("EX", 4.5, -0.1, "h", "LB", "OUT", width=1.8)
    b.door("LB", 4.5, 7.1, "h", "LB", "HW", width=1.2)
    b.door("LBCS", 9.1, 3.5, "v", "LB", "CS", width=0.9)
    b.door("IV1", 2.0, 9.1, "h", "HW", "IV1", width=0.9)
    b.door("IV2", 6.0, 9.1, "h", "HW", "IV2", width=0.9)
    b.door("OF", 12.0, 9.1, "h", "HW", "OF", width=1.0)
    b.door("LK", 18.0, 9.1, "h", "HW", "LK", width=0.8)
    b.door("CB", 22.0, 9.1, "h", "HW", "CB", width=0.9)
    b.door("CS", 12.5, 7.1, "h", "HW", "CS", width=1.0)
    b.door("AR", 17.5, 7.1, "h", "HW", "AR", width=0.8)
    b.door("GR", 21.5, 7.1, "h", "HW", "GR", width=1.2)
    b.door("GX", 21.5, -0.1, "h", "GR", "OUT", width=3.0)
    b.carve()
    CT = (3.0, 5.0, 7.0, 6.0)          # reception counter, free-standing
    BN = (1.0, 1.5, 3.0, 2.0)          # bench
    CSD, FC = (10.0, 3.0, 12.5, 4.0), (13.2, 3.0, 15.0, 4.0)   # custody desk + cabinets: 0.7 m gap
    D1, D2 = (9.5, 11.0, 11.5, 11.8), (12.8, 11.0, 14.8, 11.8)  # office desks
    D3 = (9.5, 14.5, 14.8, 15.5)       # a long desk block
    CAR = (20.5, 1.0, 22.3, 5.5)       # patrol car
    BK = (17.4, 12.3, 19.8, 12.8)      # locker-room bench along... free
    for o in (CT, BN, CSD, FC, D1, D2, D3, CAR, BK):
        b.rect(*o, OCC)
    UNK_OF = (15.0, 17.0, 17.0, 19.0)  # office north-east corner not scanned
    UNK_CB = (22.5, 13.0, 24.0, 15.0)  # back of the cell block not scanned
    b.unknown(*UNK_OF); b.unknown(*UNK_CB)
    hollow(b)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    PA = (1.0, 8.1, 0)        # corridor, west end, facing east
    PB = (23.0, 8.1, 180)     # corridor, east end, facing west
    PC = (4.5, 2.5, 90)       # lobby, facing north (counter ahead)
    PD = (12.0, 1.5, 90)      # custody suite, facing north (the desk/cabinet gap ahead right)
    PE = (10.0, 12.8, 0)      # office, facing east
    PF = (23.2, 2.0, 90)      # garage, east of the car, facing north
    PG = (18.6, 11.0, 270)    # locker room, facing south (its door ahead)
    HD = ["IV1", "IV2", "OF", "LK", "CB", "LB", "CS", "AR", "GR"]
    assert nth(b, PA, HD, "left", 2) == "IV2" and nth(b, PA, HD, "left", 3) == "OF"
    assert nth(b, PA, HD, "right", 1) == "LB" and nth(b, PA, HD, "right", -1) == "GR"
    assert nth(b, PA, HD, "left", 6) is None
    assert nth(b, PB, HD, "right", 1) == "CB" and nth(b, PB, HD, "left", 2) == "AR"
    areas = {n: b.area(n) for n in b.spaces if n != "HW"}
    assert max(areas, key=areas.get) == "OF" and min(areas, key=areas.get) == "AR"
    mid = lambda n: circ(*b.centroid(n), 0.75)
    gap_n = poly(12.5, 4.05, 13.2, 5.4)                      # north of the desk/cabinet gap
    uof = {"any": [band(15.1, 16.1, 16.9, 16.95), band(14.1, 17.05, 14.95, 18.9)]}
    ucb = {"any": [band(22.6, 12.1, 23.9, 12.95), band(21.6, 13.05, 22.45, 14.9)]}
    C = [
        ("A", PA, "go to the second door on your left", [ntp(D("IV2"), spaces=["HW", "IV2", "door:IV2"])]),
        ("A", PA, "go through the third door on your left", [ntp(through(b, "OF", "OF"), spaces=["OF"], kind="through:OF")]),
        ("A", PA, "take me to the first door on the right", [ntp(D("LB"), spaces=["HW", "LB", "door:LB"])]),
        ("A", PA, "head for the last door on your right", [ntp(D("GR"), spaces=["HW", "GR", "door:GR"])]),
        ("A", PA, "go to the sixth door on your left", "clarify"),
        ("A", PA, "take me to the detectives' room", "clarify"),
        ("A", PA, "go to the smallest room", [ntp(R("AR"), spaces=["AR"])]),
        ("B", PB, "go to the first door on your right", [ntp(D("CB"), spaces=["HW", "CB", "door:CB"])]),
        ("B", PB, "go to the second door on your left", [ntp(D("AR"), spaces=["HW", "AR", "door:AR"])]),
        ("B", PB, "go towards the nearest unexplored area", [ntp(ucb, spaces=["CB"], kind="frontier")]),
        ("B", PB, "go to the middle of the biggest room", [ntp(mid("OF"), spaces=["OF"])]),
        ("C", PC, "go to the middle of this room", [ntp(mid("LB"), spaces=["LB"])]),
        ("C", PC, "go next to the obstacle in front of you", [ntp(next_to(CT), spaces=["LB"])]),
        ("C", PC, "go to the nearest obstacle", [ntp(next_to(BN), spaces=["LB"])]),
        ("C", PC, "go to the left corner of this room", [ntp(side_corner(PC, b.spaces["LB"][0], "left"), spaces=["LB"])]),
        ("C", PC, "go through the door ahead of you", [ntp(through(b, "LB", "HW", depth=1.7, half=1.0), spaces=["HW"], kind="through:LB")]),
        ("C", PC, "turn to face the door on your right", [face(PC, 9.1, 3.5)]),
        ("C", PC, "go to the biggest room", [ntp(R("OF"), spaces=["OF"])]),
        ("D", PD, "go through the narrow passage ahead", [ntp(gap_n, spaces=["CS"])]),
        ("D", PD, "go to the middle of this room", [ntp(mid("CS"), spaces=["CS"])]),
        ("D", PD, "go to the door on your left", [ntp(D("LBCS"), spaces=["CS", "LB", "door:LBCS"])]),
        ("E", PE, "go to the opposite side of this room", [ntp(opposite(b, "OF", PE, "+x"), spaces=["OF"])]),
        ("E", PE, "go towards the unexplored part of this room", [ntp(uof, spaces=["OF"], kind="frontier")]),
        ("E", PE, "go to the right corner of the room", [ntp(side_corner(PE, b.spaces["OF"][0], "right"), spaces=["OF"])]),
        ("E", PE, "go to the nearest corner", [ntp(nearest_corner(PE, b.spaces["OF"][0]), spaces=["OF"])]),
        ("F", PF, "go next to the obstacle on your left", [ntp(next_to(CAR), spaces=["GR", "door:GX"])]),
        ("F", PF, "go through the door in front of you", [ntp(through(b, "GR", "HW", depth=1.7, half=1.0), spaces=["HW"], kind="through:GR")]),
        ("F", PF, "go to the right corner of this room", [ntp(side_corner(PF, b.spaces["GR"][0], "right"), spaces=["GR"])]),
        ("G", PG, "go through the door in front of you", [ntp(through(b, "LK", "HW", depth=1.7, half=1.0), spaces=["HW"], kind="through:LK")]),
        ("G", PG, "go to the biggest room", [ntp(R("OF"), spaces=["OF"])]),
    ]
    return b, C


def main():
    b, C = police()
    out = [(b, "pol", i, spk, pose, prompt, exp) for i, (spk, pose, prompt, exp) in enumerate(C, 1)]
    bld_check.write(out)


if __name__ == "__main__":
    main()
