"""Drawing + geometry helpers for make_buildings.py (fourth blind set (copied from the third)).

Every building is drawn in a LOCAL frame (metres, x right, y up) as rectangles: the free
space of each named space (rooms, corridors), door openings, furniture, unscanned patches.
The world map is the local drawing placed with a rotation `theta` (degrees, CCW) and an
offset; with theta != 0 the drawing is resampled cell by cell (nearest neighbour) and a
little lidar-like noise is added.  Expected regions, poses and yaws are written in local
coordinates and transformed to the world here, with the same numbers the drawing uses.
"""
import math
import sys
from pathlib import Path

import numpy as np
from scipy import ndimage

HERE = Path(__file__).parent
RES = 0.05
OCC, FREE, UNK = 0, 254, 205
WALL = 0.2
DOOR_W = 0.9
sys.path.insert(0, "/work/shared/bench")

# contract tolerances
AT_DOOR, AT_CORNER, MIDDLE, BETWEEN, NEXT_TO = 0.75, 1.0, 0.75, 0.75, 1.0


class Building:
    def __init__(self, name, lx0, ly0, lx1, ly1, theta=0.0, offset=(0.0, 0.0), seed=None):
        self.name, self.theta, self.offset, self.seed = name, theta, offset, seed
        self.lx0, self.ly0 = lx0, ly0
        self.w, self.h = round((lx1 - lx0) / RES), round((ly1 - ly0) / RES)
        self.g = np.full((self.h, self.w), UNK, np.uint8)  # local raster, row 0 = south
        self.spaces = {}     # name -> list of free rects (local)
        self.doors = {}      # name -> dict(x, y, orient, width, spaces=(a, b))
        self.unk = []        # unscanned rects

    # ---------------------------------------------------------- drawing (local)
    def rect(self, x0, y0, x1, y1, v):
        c0, c1 = round((x0 - self.lx0) / RES), round((x1 - self.lx0) / RES)
        r0, r1 = round((y0 - self.ly0) / RES), round((y1 - self.ly0) / RES)
        self.g[r0:r1, c0:c1] = v

    def shell(self, x0, y0, x1, y1):
        self.rect(x0 - WALL, y0 - WALL, x1 + WALL, y1 + WALL, OCC)

    def space(self, name, *rects):
        self.spaces[name] = list(rects)

    def door(self, name, x, y, orient, a, b, width=DOOR_W):
        """orient 'h': opening in a horizontal wall (passes north-south); 'v': in a vertical wall."""
        self.doors[name] = dict(x=x, y=y, orient=orient, width=width, spaces=(a, b))

    def carve(self):
        for rects in self.spaces.values():
            for r in rects:
                self.rect(*r, FREE)
        for d in self.doors.values():
            hw, ht = d["width"] / 2, WALL / 2 + 0.001
            if d["orient"] == "h":
                self.rect(d["x"] - hw, d["y"] - ht, d["x"] + hw, d["y"] + ht, FREE)
            else:
                self.rect(d["x"] - ht, d["y"] - hw, d["x"] + ht, d["y"] + hw, FREE)

    def unknown(self, *r):
        self.unk.append(r)
        self.rect(*r, UNK)

    # ---------------------------------------------------------- local <-> world
    def to_world(self, x, y):
        t = math.radians(self.theta)
        return (self.offset[0] + x * math.cos(t) - y * math.sin(t),
                self.offset[1] + x * math.sin(t) + y * math.cos(t))

    def to_local(self, X, Y):
        t = math.radians(self.theta)
        dx, dy = X - self.offset[0], Y - self.offset[1]
        return dx * math.cos(t) + dy * math.sin(t), -dx * math.sin(t) + dy * math.cos(t)

    def pose(self, x, y, yaw):
        X, Y = self.to_world(x, y)
        return [round(X, 3), round(Y, 3), round((yaw + self.theta) % 360, 1)]

    def region(self, reg):
        if "circle" in reg:
            x, y, r = reg["circle"]
            X, Y = self.to_world(x, y)
            return {"circle": [round(X, 3), round(Y, 3), r]}
        if "polygon" in reg:
            return {"polygon": [[round(c, 3) for c in self.to_world(x, y)] for x, y in reg["polygon"]]}
        return {"any": [self.region(r) for r in reg["any"]]}

    # ---------------------------------------------------------- render + save
    def render(self):
        if self.theta == 0:
            self.W = self.g.copy()
            self.ox, self.oy = self.lx0 + self.offset[0], self.ly0 + self.offset[1]
        else:
            cs = [self.to_world(self.lx0 + a * self.w * RES, self.ly0 + b * self.h * RES)
                  for a in (0, 1) for b in (0, 1)]
            X0 = math.floor(min(c[0] for c in cs)) - 1
            Y0 = math.floor(min(c[1] for c in cs)) - 1
            X1 = math.ceil(max(c[0] for c in cs)) + 1
            Y1 = math.ceil(max(c[1] for c in cs)) + 1
            self.ox, self.oy = X0, Y0
            W, H = round((X1 - X0) / RES), round((Y1 - Y0) / RES)
            cc, rr = np.meshgrid(np.arange(W), np.arange(H))
            Xc, Yc = X0 + (cc + 0.5) * RES, Y0 + (rr + 0.5) * RES
            t = math.radians(self.theta)
            dx, dy = Xc - self.offset[0], Yc - self.offset[1]
            xl = dx * math.cos(t) + dy * math.sin(t)
            yl = -dx * math.sin(t) + dy * math.cos(t)
            ci = np.floor((xl - self.lx0) / RES).astype(int)
            ri = np.floor((yl - self.ly0) / RES).astype(int)
            inside = (ci >= 0) & (ci < self.w) & (ri >= 0) & (ri < self.h)
            out = np.full((H, W), UNK, np.uint8)
            out[inside] = self.g[ri[inside], ci[inside]]
            self.W = out
            self.add_noise()
        img = np.flipud(self.W)
        (HERE / "maps" / f"{self.name}.pgm").write_bytes(
            f"P5\n# {self.name}: drawn by make_buildings.py\n{img.shape[1]} {img.shape[0]}\n255\n".encode()
            + img.tobytes())
        (HERE / "maps" / f"{self.name}.yaml").write_text(
            f"image: {self.name}.pgm\nmode: trinary\nresolution: {RES}\norigin: [{self.ox}, {self.oy}, 0.0]\n"
            "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")

    def add_noise(self):
        """Lidar-like noise: wall faces a cell rougher or smoother, a few 1-3 cell unknown specks."""
        rng = np.random.default_rng(self.seed)
        g = self.W
        occ, free = g == OCC, g == FREE
        k = np.ones((3, 3), bool)
        free_next_occ = free & ndimage.binary_dilation(occ, k)
        occ_next_free = occ & ndimage.binary_dilation(free, k)
        unk_near = ndimage.binary_dilation(g == UNK, np.ones((5, 5), bool))
        bump = free_next_occ & (rng.random(g.shape) < 0.06)
        dent = occ_next_free & ~unk_near & (rng.random(g.shape) < 0.06)
        g[bump] = OCC
        g[dent] = FREE
        # unknown specks in the open (not near walls): 1-3 cells
        far = ndimage.distance_transform_edt(g == FREE) > 12
        ys, xs = np.nonzero(far)
        for i in rng.choice(len(ys), size=min(40, len(ys)), replace=False):
            r, c = ys[i], xs[i]
            g[r, c] = UNK
            if rng.random() < 0.5:
                g[r, c + 1] = UNK
        self.W = g

    # ---------------------------------------------------------- local geometry
    def local_free(self, x0, y0, x1, y1):
        c0, c1 = round((x0 - self.lx0) / RES), round((x1 - self.lx0) / RES)
        r0, r1 = round((y0 - self.ly0) / RES), round((y1 - self.ly0) / RES)
        return c0, r0, self.g[r0:r1, c0:c1] == FREE

    def centroid(self, name):
        """Centroid of the free (scanned, unoccupied) space of a room, from the drawing."""
        xs, ys = [], []
        for r in self.spaces[name]:
            c0, r0, sub = self.local_free(*r)
            rr, cc = np.nonzero(sub)
            xs.append(self.lx0 + (c0 + cc + 0.5) * RES)
            ys.append(self.ly0 + (r0 + rr + 0.5) * RES)
        return float(np.concatenate(xs).mean()), float(np.concatenate(ys).mean())

    def area(self, name):
        """Floor area of a room counting unexplored cells inside it (free + unknown, not furniture)."""
        return sum((r[2] - r[0]) * (r[3] - r[1]) for r in self.spaces[name])

    def space_of_local(self, x, y):
        for n, rects in self.spaces.items():
            for (x0, y0, x1, y1) in rects:
                if x0 <= x <= x1 and y0 <= y <= y1:
                    return n
        for n, d in self.doors.items():
            hw, ht = d["width"] / 2, WALL / 2 + 0.05
            if d["orient"] == "h" and abs(x - d["x"]) <= hw and abs(y - d["y"]) <= ht:
                return "door:" + n
            if d["orient"] == "v" and abs(y - d["y"]) <= hw and abs(x - d["x"]) <= ht:
                return "door:" + n
        return None


# ---------------------------------------------------------------- robot-frame relations
def rel(pose, x, y):
    """(forward, lateral, distance, bearing_deg) of a point in the robot frame (local coords)."""
    px, py, yaw = pose
    dx, dy = x - px, y - py
    t = math.radians(yaw)
    f = dx * math.cos(t) + dy * math.sin(t)
    l = -dx * math.sin(t) + dy * math.cos(t)
    return f, l, math.hypot(dx, dy), math.degrees(math.atan2(l, f))


def doors_in_order(b, pose, space, side=None, min_lat=0.3, gap=0.5):
    """Doors of `space`, nearest first, optionally only those on 'left' / 'right' (lateral offset sign).
    Asserts that no two are tied (distance gap) and no side is marginal."""
    out = []
    for n, d in b.doors.items():
        if space not in d["spaces"]:
            continue
        f, l, dist, _ = rel(pose, d["x"], d["y"])
        if side is not None:
            assert abs(l) >= min_lat, (n, "marginal side")
            if (side == "left") != (l > 0):
                continue
        out.append((dist, n))
    out.sort()
    for a, c in zip(out, out[1:]):
        assert c[0] - a[0] >= gap, ("tie", a, c)
    return [n for _, n in out]


def circ(x, y, r):
    return {"circle": [round(x, 3), round(y, 3), r]}


def poly(x0, y0, x1, y1):
    return {"polygon": [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]}


def ntp(goal, via=None, spaces=None, via_spaces=None, kind=None):
    """NavigateThroughPoses expectation. `spaces` (list of space names, 'door:X' allowed) is where every
    valid cell of the goal must lie; checked by make_buildings.check()."""
    d = {"command": "NavigateThroughPoses", "goal": goal}
    if via:
        d["via"] = via
    d["_spaces"] = spaces
    d["_via_spaces"] = via_spaces
    d["_kind"] = kind
    return d


def rot(direction, lo, hi):
    return {"command": "Rotate", "direction": direction, "repeat": [lo, hi]}


def rot_deg(deg):
    """A turn of `deg` (positive = left) with the spoken tolerance (+/-7 %, at least 1 step)."""
    exact = abs(deg) / 10.0
    tol = max(0.07 * exact, 1.0)
    lo, hi = max(1, math.ceil(exact - tol - 1e-9)), math.floor(exact + tol + 1e-9)
    return rot("left" if deg > 0 else "right", lo, hi)


def face(pose, x, y):
    """Turn to face a point: the shorter turn to its bearing, +/-1 step (10 degrees) around it."""
    _, _, _, bearing = rel(pose, x, y)
    assert 15 < abs(bearing) < 165, ("facing turn too small or near 180", bearing)
    exact = abs(bearing) / 10.0
    return rot("left" if bearing > 0 else "right", max(1, math.floor(exact - 1)), math.ceil(exact + 1))


def move(direction, metres):
    exact = metres / 0.03
    tol = max(0.07 * exact, 1.0)
    return {"command": "Move", "direction": direction,
            "repeat": [max(1, math.ceil(exact - tol)), math.floor(exact + tol)]}


def compass(yaw_world, heading):
    diff = (heading - yaw_world + 180) % 360 - 180
    assert abs(abs(diff) - 180) > 1e-6 and abs(diff) > 1e-6
    return rot_deg(diff)


STOP = [{"command": "Stop"}]


def safe_move(b, pose, direction, limit=None):
    """Move the robot can make from `pose` without leaving valid floor (score.py's Map and its
    move-validity walk): Move `direction` [1, last valid step]; `limit` asserts the asked
    distance is really beyond it."""
    from score import Map
    m = Map((HERE / "maps" / f"{b.name}.yaml").resolve())
    X, Y, yaw = b.pose(*pose)
    h = {"forward": 0.0, "backward": 180.0, "left": 90.0, "right": -90.0}[direction]
    t = math.radians(yaw + h)
    n = 0
    while True:
        d = 0.03 * (n + 1)
        steps = max(int(d / (m.res / 2)), 1)
        ok = all(m.valid(X + d * math.cos(t) * s / steps, Y + d * math.sin(t) * s / steps) for s in range(1, steps + 1))
        if not ok:
            break
        n += 1
    assert n >= 1
    return {"command": "Move", "direction": direction, "repeat": [1, n]}
