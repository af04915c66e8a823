"""My own unseen check (session 7, grounding helper): a clinic drawn with prompts-7's tooling
(bld_*.py copied), rotated 41.3 deg with lidar-like noise, written from the bench contract before
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


def clinic():
    b = Building("clinic", -1.0, -1.5, 17.0, 17.0, theta=41.3, offset=(14.0, 1.0), seed=4113)
    b.shell(0.0, 0.0, 16.0, 16.0)
    b.space("WR", (0.0, 0.0, 8.0, 4.0), (0.0, 4.0, 4.0, 8.0))   # L-shaped waiting room (biggest)
    b.space("HW", (8.2, 0.0, 10.0, 16.0))          # corridor, 1.8 m
    b.space("ST", (4.2, 4.2, 8.0, 8.0))            # store (smallest)
    b.space("C1", (0.0, 8.2, 8.0, 12.0)); b.space("C2", (0.0, 12.2, 8.0, 16.0))   # consulting rooms
    b.space("TR", (10.2, 0.0, 16.0, 6.0))          # treatment room
    b.space("XR", (10.2, 6.2, 16.0, 11.0))         # x-ray
    b.space("OF", (10.2, 11.2, 16.0, 16.0))        # staff office (north-east corner not scanned)
    b.door("EX", 4.0, -0.1, "h", "WR", "OUT", width=1.6)
    b.door("WR", 8.1, 2.0, "v", "WR", "HW", width=1.2)
    for n, y in (("ST", 6.0), ("C1", 10.0), ("C2", 14.0)):
        b.door(n, 8.1, y, "v", "HW", n, width=0.9)
    for n, y, w in (("TR", 3.0, 1.0), ("XR", 8.5, 1.0), ("OF", 13.5, 0.9)):
        b.door(n, 10.1, y, "v", "HW", n, width=w)
    b.carve()
    CH = (1.0, 1.0, 5.0, 1.7)          # row of chairs
    BD = (12.0, 2.0, 14.0, 3.0)        # treatment bed
    MC = (12.5, 7.5, 14.0, 9.5)        # x-ray machine
    DK1, DK2 = (2.0, 10.0, 4.0, 10.8), (11.0, 12.0, 13.0, 12.8)   # desks
    for o in (CH, BD, MC, DK1, DK2):
        b.rect(*o, OCC)
    UNK_OF = (14.0, 14.0, 16.0, 16.0)
    b.unknown(*UNK_OF)
    hollow(b)
    b.render()

    D = lambda n: door_reg(b, n)
    R = lambda n: room_reg(b, n)
    CA = (9.1, 0.8, 90)       # corridor, south end, facing north
    CB = (9.1, 15.2, 270)     # corridor, north end, facing south
    CC = (2.0, 2.5, 0)        # waiting room, facing east (its door to the corridor ahead)
    CD = (11.5, 4.0, 0)       # treatment room, facing east (the bed ahead right, its door behind)
    CE = (11.0, 10.0, 270)    # x-ray, facing south
    CF = (1.5, 6.5, 270)      # waiting room's arm, facing south
    HD = ["WR", "ST", "C1", "C2", "TR", "XR", "OF"]
    assert nth(b, CA, HD, "left", 2) == "ST" and nth(b, CA, HD, "right", 3) == "OF"
    assert nth(b, CA, HD, "left", -1) == "C2" and nth(b, CA, HD, "left", 5) is None
    assert nth(b, CB, HD, "right", 1) == "C2" and nth(b, CB, HD, "left", 2) == "XR"
    areas = {n: b.area(n) for n in b.spaces if n != "HW"}
    assert max(areas, key=areas.get) == "WR" and min(areas, key=areas.get) == "ST"
    assert abs(rel(CD, 10.1, 3.0)[3]) > 130 and abs(rel(CD, 13.0, 2.5)[3]) < 60
    assert rel(CE, 13.25, 8.5)[1] > 0 and rel(CE, 10.1, 8.5)[1] < 0
    mid = lambda n: circ(*b.centroid(n), 0.75)
    uof = {"any": [band(14.05, 13.05, 15.95, 13.95), band(13.05, 14.05, 13.95, 15.95)]}
    C = [
        ("A", CA, "go to the second door on your left", [ntp(D("ST"), spaces=["HW", "ST", "door:ST"])]),
        ("A", CA, "go into the room on your right", [ntp(R("TR"), spaces=["TR"])]),
        ("A", CA, "go to the third door on your right", [ntp(D("OF"), spaces=["HW", "OF", "door:OF"])]),
        ("A", CA, "go through the first door on your right", [ntp(through(b, "TR", "TR"), spaces=["TR"], kind="through:TR")]),
        ("A", CA, "go to the last door on your left", [ntp(D("C2"), spaces=["HW", "C2", "door:C2"])]),
        ("A", CA, "stop between the first and second doors on your right", [ntp(circ(10.1, 5.75, 0.75), spaces=["HW", "TR", "XR"])]),
        ("A", CA, "take me to the pharmacy", "clarify"),
        ("A", CA, "go to the fifth door on your left", "clarify"),
        ("B", CB, "go to the first door on your right", [ntp(D("C2"), spaces=["HW", "C2", "door:C2"])]),
        ("B", CB, "go through the second door on your left", [ntp(through(b, "XR", "XR"), spaces=["XR"], kind="through:XR")]),
        ("B", CB, "go to the biggest room", [ntp(R("WR"), spaces=["WR"])]),
        ("B", CB, "go to the smallest room", [ntp(R("ST"), spaces=["ST"])]),
        ("B", CB, "go towards the unexplored area on your left", [ntp(uof, spaces=["OF"], kind="frontier")]),
        ("C", CC, "go to the middle of this room", [ntp(mid("WR"), spaces=["WR"])]),
        ("C", CC, "go through the door in front of you", [ntp(poly(8.35, 1.0, 9.8, 3.0), spaces=["HW"], kind="through:WR")]),
        ("C", CC, "go to the nearest obstacle", [ntp(next_to(CH), spaces=["WR"])]),
        ("C", CC, "go to the right corner of this room", [ntp(corner_reg((8.0, 0.0), (0.0, 0.0, 8.0, 4.0)), spaces=["WR"])]),
        ("C", CC, "turn to face the door on your right", [face(CC, 4.0, -0.1)]),
        ("C", CC, "go into the room of the nurses", "clarify"),
        ("D", CD, "go next to the obstacle in front of you", [ntp(next_to(BD), spaces=["TR"])]),
        ("D", CD, "go to the farthest corner of this room", [ntp(corner_reg((16.0, 0.0), b.spaces["TR"][0]), spaces=["TR"])]),
        ("D", CD, "go through the door behind you", [ntp(poly(8.4, 2.0, 9.9, 4.0), spaces=["HW"], kind="through:TR")]),
        ("D", CD, "go to the middle of the biggest room", [ntp(mid("WR"), spaces=["WR"])]),
        ("D", CD, "go to the nearest corner", [ntp(corner_reg((10.2, 6.0), b.spaces["TR"][0]), spaces=["TR"])]),
        ("E", CE, "go next to the obstacle on your left", [ntp(next_to(MC), spaces=["XR"])]),
        ("E", CE, "go to the opposite side of this room", [ntp(opposite(b, "XR", CE, "+x"), spaces=["XR"])]),
        ("E", CE, "go towards the nearest unexplored area", [ntp(uof, spaces=["OF"], kind="frontier")]),
        ("E", CE, "go through the door on your right", [ntp(poly(8.4, 7.5, 9.9, 9.5), spaces=["HW"], kind="through:XR")]),
        ("F", CF, "go to the nearest corner", [ntp(corner_reg((0.0, 8.0), (0.0, 4.0, 4.0, 8.0)), spaces=["WR"])]),
        ("F", CF, "go through the door on your left", [ntp(poly(8.35, 1.0, 9.8, 3.0), spaces=["HW"], kind="through:WR")]),
    ]
    return b, C


def main():
    b, C = clinic()
    out = [(b, "cli", i, spk, pose, prompt, exp) for i, (spk, pose, prompt, exp) in enumerate(C, 1)]
    bld_check.write(out)


if __name__ == "__main__":
    main()
