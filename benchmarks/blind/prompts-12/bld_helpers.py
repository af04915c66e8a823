"""Helpers copied unchanged from the previous round's make_buildings.py (/work/main/benchmarks/blind/prompts-9/):
nth, room_cells, opposite, next_to, within2, mid, nearest_obstacles, frontier_dist, hollow, glass_gaps, thr,
next_to_in, glass_gaps_v, opposite_far, edge_d, ahead_of."""
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




def thr(b, n, into, **kw):
    """through() with the edge on the door's wall pulled 0.1 m away from the door (after rotation and noise
    the cells at the wall line can fall inside the door opening, which is not yet past it)."""
    reg = through(b, n, into, **kw)
    (x0, y0), (x1, y1) = reg["polygon"][0], reg["polygon"][2]
    d = b.doors[n]
    if d["orient"] == "v":
        if abs(x0 - d["x"]) < abs(x1 - d["x"]):
            x0 += 0.1
        else:
            x1 -= 0.1
    else:
        if abs(y0 - d["y"]) < abs(y1 - d["y"]):
            y0 += 0.1
        else:
            y1 -= 0.1
    return poly(round(x0, 3), round(y0, 3), round(x1, 3), round(y1, 3))


def next_to_in(o, room):
    """next_to(o) with every strip clipped to the room rectangle (so it never reaches through a wall)."""
    X0, Y0, X1, Y1 = room
    out = []
    for s in next_to(o)["any"]:
        (x0, y0), (x1, y1) = s["polygon"][0], s["polygon"][2]
        x0, y0, x1, y1 = max(x0, X0), max(y0, Y0), min(x1, X1), min(y1, Y1)
        if x1 - x0 > 0.05 and y1 - y0 > 0.05:
            out.append(poly(x0, y0, x1, y1))
    return {"any": out}


def glass_gaps_v(b, x, y0, y1, step=0.8, gap=0.15):
    """A glass pane in a vertical wall line (x .. x+0.2) between two scanned rooms: the lidar got a return
    only in stretches; every `step` m a `gap` m stretch stayed unknown (under 20 cells each: noise specks,
    not unexplored areas).  Returns the gap y ranges (local)."""
    gaps = []
    gy = y0 + step
    while gy + gap <= y1:
        b.rect(x, gy, x + 0.2, gy + gap, UNK)
        gaps.append((gy, gy + gap))
        gy += step
    return gaps


def opposite_far(b, name, pose, step=0.5, min_area=4.0):
    """'the opposite side of the room' as the contract words it: the third of the room farthest from the robot.
    dstar = the 2/3-quantile of the distances from the robot to the room's free cells; the region is the union
    of the room's step x step squares (clipped to the room) whose nearest point is at least dstar away, merged
    into runs per row (so every point of it is in the farthest third).  New in this set (the eighth set's
    opposite() needs the robot near the middle of the opposite wall)."""
    xs, ys = room_cells(b, name)
    dstar = float(np.quantile(np.hypot(xs - pose[0], ys - pose[1]), 2 / 3))
    X0, Y0, X1, Y1 = b.spaces[name][0]
    polys, area = [], 0.0
    y = Y0
    while y < Y1 - 1e-9:
        ya, yb = y, min(y + step, Y1)
        run = None
        x = X0
        while x < X1 - 1e-9:
            xa, xb = x, min(x + step, X1)
            ok = edge_d((xa, ya, xb, yb), pose) >= dstar
            if ok and run is None:
                run = xa
            if not ok and run is not None:
                polys.append(poly(round(run, 3), round(ya, 3), round(xa, 3), round(yb, 3))); area += (xa - run) * (yb - ya); run = None
            x = xb
        if run is not None:
            polys.append(poly(round(run, 3), round(ya, 3), round(X1, 3), round(yb, 3))); area += (X1 - run) * (yb - ya)
        y = yb
    assert area >= min_area, (name, "opposite region too small", area)
    m = np.zeros(len(xs), bool)
    for p in polys:
        (a, c), (d, e) = p["polygon"][0], p["polygon"][2]
        m |= (xs >= a) & (xs <= d) & (ys >= c) & (ys <= e)
    assert np.hypot(xs[m] - pose[0], ys[m] - pose[1]).min() >= dstar - 1e-9
    return {"any": polys}


def edge_d(o, p):
    return math.hypot(min(max(p[0], o[0]), o[2]) - p[0], min(max(p[1], o[1]), o[3]) - p[1])


def ahead_of(p, o):
    """Bearing (deg) of an obstacle's nearest cell from pose p."""
    x = min(max(p[0], o[0]), o[2]); y = min(max(p[1], o[1]), o[3])
    return rel(p, x, y)[3]


