"""Simulated-SLAM map maker for blind langnav test maps (blind9: blind8's, changes marked (blind8) / (blind9);
blind11 / blind12 changes marked (blind11) / (blind12)).

A building is drawn as geometry in its own frame (u east, v north, metres) on a fine truth
raster (0.02 m): opaque walls/furniture, glass (returns only near normal incidence), open door
leaves, outside objects.  A robot drives a waypoint route; at every 0.15 m a 360 deg lidar
(720 beams, 12 m max, 10 m mapping range, sigma 1.5 cm) is cast on the truth raster from the
TRUE pose, and its returns are inserted into a world grid (0.05 m, or B(res=...)) from the ESTIMATED pose (true
pose + slowly drifting, mean-reverting error + per-scan jitter), rotated by the building angle.
Log-odds accumulate (hit +0.9, pass -0.45, clamp +-6), thresholded like map_server (trinary:
p > 0.65 occupied 0, p < 0.196 free 254, else unknown 205).

Ground truth comes from the same geometry, then is CHECKED on the simulated grid: space points
are moved to the best-cleared mapped free floor of their room (or dropped when the room is
hardly seen), doors are kept required / made optional / dropped by how much of the opening the
map shows, narrow passages likewise; ignore polygons are built over mapped free floor outside
the building footprint (ray fans).
"""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import yaml
from PIL import Image, ImageDraw
from scipy import ndimage

RES = 0.05          # default map resolution (per building: B(res=...))
TR = 0.02           # truth raster resolution
FREE, OCC, UNK = 254, 0, 205
SEED = 20261126   # (blind12: new seed)


def _inside(poly, p):
    x, y = p
    hit = False
    for (x0, y0), (x1, y1) in zip(poly, poly[1:] + poly[:1]):
        if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            hit = not hit
    return hit


class B:
    def __init__(self, name, notes, size, theta=0.0, seed=0, margin=11.0, res=RES, fov=360.0, pad=1.0,
                 start_frame=False, rmax=12.0, rmap=10.0, nbeams=720, scan_step=0.15):
        # (blind9) pad: unknown border kept around the observed area when the grid is cropped (m; 0 = cropped
        # tight, 5+ = a big unknown canvas as map_server maps often have).  start_frame: the world frame is the
        # robot's START pose (as slam_toolbox / gmapping do), so the origin is NOT the building's lower-left
        # corner and world (0, 0) lies wherever the robot started.
        self.pad, self.start_frame = pad, start_frame
        # (blind11) per-map lidar range (a cheaper 8 m lidar on some robots): max range / mapping range
        self.rmax, self.rmap = rmax, rmap
        # (blind12) per-map beam count / scan spacing (a cheaper 360-beam lidar; scans every 0.2 m)
        self.nbeams, self.scan_step = nbeams, scan_step
        self.name, self.notes = name, notes
        self.res, self.fov = res, fov
        self.people = []
        self.wu, self.wv = size
        self.theta = math.radians(theta)
        self.rng = np.random.default_rng(SEED + seed)
        self.m = margin
        self.tu0, self.tv0 = -margin, -margin
        self.TW = int((self.wu + 2 * margin) / TR)
        self.TH = int((self.wv + 2 * margin) / TR)
        self.cls = np.zeros((self.TH, self.TW), np.uint8)       # 0 empty 1 opaque 2 glass
        self.gn = np.zeros((self.TH, self.TW), np.float32)      # glass normal angle
        self.spaces, self.doors, self.passages, self.ignores = [], [], [], []
        self.routes = []
        self.foot = [(0, 0), (self.wu, 0), (self.wu, self.wv), (0, self.wv)]
        self.unseen_rooms = []
        self.biases = []

    # ---------------- truth geometry ----------------
    def _win(self, u0, v0, u1, v1, pad):
        c0 = max(int((u0 - pad - self.tu0) / TR), 0)
        c1 = min(int((u1 + pad - self.tu0) / TR) + 2, self.TW)
        r0 = max(int((v0 - pad - self.tv0) / TR), 0)
        r1 = min(int((v1 + pad - self.tv0) / TR) + 2, self.TH)
        U = self.tu0 + (np.arange(c0, c1) + 0.5) * TR
        V = self.tv0 + (np.arange(r0, r1) + 0.5) * TR
        return np.s_[r0:r1, c0:c1], U[None, :], V[:, None]

    def seg(self, p0, p1, th, kind=1, cuts=()):
        (u0, v0), (u1, v1) = p0, p1
        L = math.hypot(u1 - u0, v1 - v0)
        tx, ty = (u1 - u0) / L, (v1 - v0) / L
        half = th / 2
        sl, U, V = self._win(min(u0, u1), min(v0, v1), max(u0, u1), max(v0, v1), half + 0.1)
        s = (U - u0) * tx + (V - v0) * ty
        d = -(U - u0) * ty + (V - v0) * tx
        ext = half if kind == 1 else 0.0
        m = (s >= -ext) & (s <= L + ext) & (np.abs(d) <= half)
        for a, b in cuts:
            m &= ~((s >= a) & (s <= b))
        self.cls[sl][m] = kind
        if kind == 2:
            self.gn[sl][m] = math.atan2(tx, -ty)

    def poly(self, pts, kind=1):
        us, vs = [p[0] for p in pts], [p[1] for p in pts]
        sl, U, V = self._win(min(us), min(vs), max(us), max(vs), 0.05)
        hit = np.zeros((V.shape[0], U.shape[1]), bool)
        for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1]):
            if y0 == y1:
                continue
            hit ^= ((y0 > V) != (y1 > V)) & (U < x0 + (V - y0) * (x1 - x0) / (y1 - y0))
        self.cls[sl][hit] = kind

    def box(self, u0, v0, u1, v1):
        self.poly([(u0, v0), (u1, v0), (u1, v1), (u0, v1)])

    def rbox(self, cu, cv, w, h, ang):
        a = math.radians(ang)
        c, s = math.cos(a), math.sin(a)
        pts = [(cu + c * x - s * y, cv + s * x + c * y) for x, y in
               [(-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2)]]
        self.poly(pts)

    def dot(self, u, v, r=0.03):
        self.box(u - r, v - r, u + r, v + r)

    def table(self, u0, v0, u1, v1, leg=0.05):
        k = 0.04 + leg / 2
        for u, v in [(u0 + k, v0 + k), (u1 - k, v0 + k), (u1 - k, v1 - k), (u0 + k, v1 - k)]:
            self.dot(u, v, leg / 2)

    def chair(self, u, v, ang=None):
        ang = self.rng.uniform(0, 90) if ang is None else ang
        a = math.radians(ang)
        for x, y in [(-0.2, -0.2), (0.2, -0.2), (0.2, 0.2), (-0.2, 0.2)]:
            self.dot(u + x * math.cos(a) - y * math.sin(a), v + x * math.sin(a) + y * math.cos(a), 0.02)

    def desk(self, u0, v0, u1, v1, panel="n"):
        self.table(u0, v0, u1, v1)
        if panel == "n":
            self.seg((u0 + 0.05, v1 - 0.05), (u1 - 0.05, v1 - 0.05), 0.03)
        elif panel == "s":
            self.seg((u0 + 0.05, v0 + 0.05), (u1 - 0.05, v0 + 0.05), 0.03)
        elif panel == "e":
            self.seg((u1 - 0.05, v0 + 0.05), (u1 - 0.05, v1 - 0.05), 0.03)
        elif panel == "w":
            self.seg((u0 + 0.05, v0 + 0.05), (u0 + 0.05, v1 - 0.05), 0.03)

    def wall(self, p0, p1, th=0.12, doors=(), glass=False, windows=(), mullion=1.2):
        """doors: dicts/tuples (at, width, note, leaf=None|('a'|'b', side, deg), optional, closed).
        windows: (s0, s1) stretches of glass (rays escape, dashed returns)."""
        (u0, v0), (u1, v1) = p0, p1
        L = math.hypot(u1 - u0, v1 - v0)
        t = ((u1 - u0) / L, (v1 - v0) / L)
        n = (-t[1], t[0])
        cuts = []
        for d in doors:
            d = dict(zip(("at", "w", "note", "leaf", "optional", "closed"), d)) if isinstance(d, tuple) else d
            d.setdefault("leaf", None); d.setdefault("optional", False); d.setdefault("closed", False)
            c = (u0 + t[0] * d["at"], v0 + t[1] * d["at"])
            if d["closed"]:
                # a closed door: leaf in the frame, slightly recessed (no annotation)
                continue
            cuts.append((d["at"] - d["w"] / 2, d["at"] + d["w"] / 2))
            if not glass and d.get("casing", True) and th <= 0.2:
                # (blind7) door casings / architraves: 8 cm strips standing 3 cm proud of both wall faces
                for s0, s1 in ((d["at"] - d["w"] / 2 - 0.08, d["at"] - d["w"] / 2),
                               (d["at"] + d["w"] / 2, d["at"] + d["w"] / 2 + 0.08)):
                    o = th / 2 + 0.03
                    self.poly([(u0 + t[0] * s0 + n[0] * o, v0 + t[1] * s0 + n[1] * o),
                               (u0 + t[0] * s1 + n[0] * o, v0 + t[1] * s1 + n[1] * o),
                               (u0 + t[0] * s1 - n[0] * o, v0 + t[1] * s1 - n[1] * o),
                               (u0 + t[0] * s0 - n[0] * o, v0 + t[1] * s0 - n[1] * o)])
            self.doors.append({"center": c, "width_m": d["w"], "optional": d["optional"], "note": d["note"],
                               "t": t, "n": n, "glass": glass, "th": th})
            if d["leaf"] and d["leaf"][0] in ("s", "s2"):
                # (blind12) sliding door: the leaf (or two half leaves for "s2") parked beside the opening,
                # parallel to the wall, on the normal side d["leaf"][1] (a pocket-less surface-mounted slider)
                side = d["leaf"][1]
                o = th / 2 + 0.04
                parts = [(d["at"] + d["w"] / 2 - 0.05, d["at"] + d["w"] * 1.5 + 0.05)] if d["leaf"][0] == "s" else \
                    [(d["at"] - d["w"] - 0.05, d["at"] - d["w"] / 2 + 0.05), (d["at"] + d["w"] / 2 - 0.05, d["at"] + d["w"] + 0.05)]
                for s0, s1 in parts:
                    self.seg((u0 + t[0] * s0 + n[0] * o * side, v0 + t[1] * s0 + n[1] * o * side),
                             (u0 + t[0] * s1 + n[0] * o * side, v0 + t[1] * s1 + n[1] * o * side), 0.045)
            elif d["leaf"] and d["leaf"][0] == "d":      # double door: two half leaves
                _, side, ang = d["leaf"]
                a = math.radians(ang)
                for hp, tt in (((c[0] - t[0] * d["w"] / 2, c[1] - t[1] * d["w"] / 2), t),
                               ((c[0] + t[0] * d["w"] / 2, c[1] + t[1] * d["w"] / 2), (-t[0], -t[1]))):
                    dv = (math.cos(a) * tt[0] + math.sin(a) * n[0] * side, math.cos(a) * tt[1] + math.sin(a) * n[1] * side)
                    q0 = (hp[0] + dv[0] * (th / 2 + 0.02), hp[1] + dv[1] * (th / 2 + 0.02))
                    q1 = (hp[0] + dv[0] * d["w"] * 0.48, hp[1] + dv[1] * d["w"] * 0.48)
                    self.seg(q0, q1, 0.045)
            elif d["leaf"]:
                hinge, side, ang = d["leaf"]
                if hinge == "a":
                    hp, tt = (c[0] - t[0] * d["w"] / 2, c[1] - t[1] * d["w"] / 2), t
                else:
                    hp, tt = (c[0] + t[0] * d["w"] / 2, c[1] + t[1] * d["w"] / 2), (-t[0], -t[1])
                a = math.radians(ang)
                dv = (math.cos(a) * tt[0] + math.sin(a) * n[0] * side, math.cos(a) * tt[1] + math.sin(a) * n[1] * side)
                q0 = (hp[0] + dv[0] * (th / 2 + 0.02), hp[1] + dv[1] * (th / 2 + 0.02))
                q1 = (hp[0] + dv[0] * d["w"] * 0.95, hp[1] + dv[1] * d["w"] * 0.95)
                self.seg(q0, q1, 0.045)
        if glass:
            self.seg(p0, p1, 0.03, kind=2, cuts=cuts)
            s = 0.0
            while s <= L + 1e-6:       # mullions / frame posts
                if not any(a - 0.02 < s < b + 0.02 for a, b in cuts):
                    q = (u0 + t[0] * s, v0 + t[1] * s)
                    self.box(q[0] - 0.04, q[1] - 0.04, q[0] + 0.04, q[1] + 0.04)
                s += mullion
            for a, b in cuts:          # door frames
                for s in (a - 0.04, b + 0.04):
                    q = (u0 + t[0] * s, v0 + t[1] * s)
                    self.box(q[0] - 0.05, q[1] - 0.05, q[0] + 0.05, q[1] + 0.05)
        else:
            self.seg(p0, p1, th, cuts=cuts + list(windows))
            for a, b in windows:
                qa = (u0 + t[0] * a, v0 + t[1] * a)
                qb = (u0 + t[0] * b, v0 + t[1] * b)
                self.seg(qa, qb, 0.03, kind=2)
                s = a + 0.9
                posts = []
                while s < b - 0.3:
                    q = (u0 + t[0] * s, v0 + t[1] * s)
                    self.box(q[0] - 0.03, q[1] - 0.03, q[0] + 0.03, q[1] + 0.03)
                    posts.append(s)
                    s += 0.9
                # the glass may come out as gaps in the wall: OPTIONAL door entries ("a break in a
                # glass wall"); the checker keeps them optional or drops them if not visible
                edges = [a] + [x for p_ in posts for x in (p_ - 0.03, p_ + 0.03)] + [b]
                for ga, gb in zip(edges[::2], edges[1::2]):
                    if gb - ga >= 0.3:
                        c = (u0 + t[0] * (ga + gb) / 2, v0 + t[1] * (ga + gb) / 2)
                        self.doors.append({"center": c, "width_m": round(gb - ga, 2), "optional": True,
                                           "note": "window / glass gap in a wall (optional)", "t": t, "n": n,
                                           "glass": True, "th": th})

    def bars(self, p0, p1, gap=0.1, r=0.012):
        """(blind11) A bar / mesh front (kennel pens, railings): thin round bars every `gap` m; the lidar
        sees some bars and shoots between others."""
        (u0, v0), (u1, v1) = p0, p1
        L = math.hypot(u1 - u0, v1 - v0)
        n = max(int(L / gap), 1)
        for i in range(n + 1):
            self.dot(u0 + (u1 - u0) * i / n, v0 + (v1 - v0) * i / n, r)

    def arc(self, cu, cv, r, a0, a1, th=0.2, n=None):
        """A curved wall: polyline approximation of a circular arc (degrees a0 -> a1)."""
        n = n or max(int(abs(a1 - a0) / 4), 2)
        pts = [(cu + r * math.cos(math.radians(a0 + (a1 - a0) * i / n)),
                cv + r * math.sin(math.radians(a0 + (a1 - a0) * i / n))) for i in range(n + 1)]
        for p, q in zip(pts, pts[1:]):
            self.seg(p, q, th)
        return pts

    def clutter(self, p0, p1, side, n, depth=(0.3, 0.6), length=(0.3, 1.0), avoid=()):
        """n random boxes against the wall p0->p1 on normal side +-1 (bins, cabinets, boxes)."""
        (u0, v0), (u1, v1) = p0, p1
        L = math.hypot(u1 - u0, v1 - v0)
        t = ((u1 - u0) / L, (v1 - v0) / L)
        nn = (-t[1] * side, t[0] * side)
        for _ in range(n):
            ln = self.rng.uniform(*length)
            dp = self.rng.uniform(*depth)
            s = self.rng.uniform(0.1, L - ln - 0.1)
            if any(a - 0.2 < s + ln and s < b + 0.2 for a, b in avoid):
                continue
            off = 0.08 + self.rng.uniform(0, 0.05)
            a = (u0 + t[0] * s + nn[0] * off, v0 + t[1] * s + nn[1] * off)
            pts = [a, (a[0] + t[0] * ln, a[1] + t[1] * ln),
                   (a[0] + t[0] * ln + nn[0] * dp, a[1] + t[1] * ln + nn[1] * dp),
                   (a[0] + nn[0] * dp, a[1] + nn[1] * dp)]
            self.poly(pts)

    def outside(self, n, dmin=2.0, dmax=8.0):
        """Random objects outside the footprint (bushes, cars, fences) that stop some rays."""
        for _ in range(n):
            for _ in range(50):
                u = self.rng.uniform(-dmax, self.wu + dmax)
                v = self.rng.uniform(-dmax, self.wv + dmax)
                du = max(-u, 0, u - self.wu)
                dv = max(-v, 0, v - self.wv)
                if dmin < math.hypot(du, dv) < dmax:
                    break
            r = self.rng.uniform(0.2, 1.2)
            self.rbox(u, v, r, self.rng.uniform(0.2, 1.5), self.rng.uniform(0, 180))

    # ---------------- annotation ----------------
    def space(self, u, v, kind, note, group=None, region=None):
        self.spaces.append({"point": (u, v), "kind": kind, "group": group, "note": note, "region": region})

    def passage(self, u, v, w, note, across=(1, 0), optional=False):
        self.passages.append({"center": (u, v), "width_m": w, "optional": optional, "note": note,
                              "across": across})

    def person(self, pts, speed=0.35, start=0, stop=10 ** 9):
        """(blind7) A person walking back and forth along pts (building frame) at speed metres per scan
        (~1 m/s at the robot's 0.15 m per scan), present from scan index start to stop; one point = standing."""
        self.people.append((pts, speed, start, stop, self.rng.uniform(0, 6.28)))

    def legs_at(self, j):
        out = []
        for pts, speed, start, stop, ph in self.people:
            if not start <= j < stop:
                continue
            if len(pts) == 1:
                u, v = pts[0]; hd = ph
            else:
                segs = [math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(pts, pts[1:])]
                tot = sum(segs)
                d = ((j - start) * speed) % (2 * tot)
                fwd = d <= tot
                d = d if fwd else 2 * tot - d
                for i_, ((a, b), L) in enumerate(zip(zip(pts, pts[1:]), segs)):
                    if d <= L or i_ == len(segs) - 1:
                        f = min(d / L, 1.0)
                        u, v = a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f
                        hd = math.atan2(b[1] - a[1], b[0] - a[0])
                        break
                    d -= L
            sw = 0.15 * math.sin(j * 1.3 + ph) if len(pts) > 1 else 0.0   # stride
            cx, cy = math.cos(hd), math.sin(hd)
            for side in (-1, 1):
                out.append((u - cy * 0.12 * side + cx * sw * side, v + cx * 0.12 * side + cy * sw * side))
        return out

    def route(self, pts, bias=(0.0, 0.0, 0.0)):
        """bias: constant (du, dv, deg) error of the estimated pose on this route (a loop closure
        that did not fully converge -> doubled walls where two routes see the same wall)."""
        self.routes.append(pts)
        self.biases.append(bias)

    def tour(self, pts, bias=(0.0, 0.0, 0.0), clear=0.3):
        """(blind8) A route through the given stops, each leg planned on the truth raster (0.1 m grid,
        cells within `clear` m of any obstacle or outside the footprint blocked, cost rising near
        obstacles so the robot keeps to the middle of corridors and doorways).  Call after drawing."""
        from skimage.graph import route_through_array
        from skimage.measure import approximate_polygon
        k = 5                                           # 0.1 m planning cells
        occ = self.cls[: self.TH // k * k, : self.TW // k * k] > 0
        occ = occ.reshape(self.TH // k, k, self.TW // k, k).any((1, 3))
        dist = ndimage.distance_transform_edt(~occ) * TR * k
        rows, cols = np.indices(occ.shape)
        U = self.tu0 + (cols + 0.5) * TR * k
        V = self.tv0 + (rows + 0.5) * TR * k
        infp = np.zeros(occ.shape, bool)
        fp = self.foot
        for (x0, y0), (x1, y1) in zip(fp, fp[1:] + fp[:1]):
            if y0 == y1:
                continue
            infp ^= ((y0 > V) != (y1 > V)) & (U < x0 + (V - y0) * (x1 - x0) / (y1 - y0))
        cost = np.where(dist >= clear, 1.0 + 0.6 / np.maximum(dist, 0.05), 1e6)
        cost = np.where(infp | (cost >= 1e6), cost, cost * 30)        # outside the footprint: only if needed
        free_rc = np.argwhere(cost < 1e6)

        def snap(p):
            r_, c_ = int((p[1] - self.tv0) / (TR * k)), int((p[0] - self.tu0) / (TR * k))
            if cost[r_, c_] < 1e6:
                return (r_, c_), p
            j = np.argmin(((free_rc - (r_, c_)) ** 2).sum(1))
            r2, c2 = free_rc[j]
            if math.hypot(r2 - r_, c2 - c_) * TR * k > 0.4:
                raise ValueError(f"{self.name}: stop {p} is blocked")
            return (int(r2), int(c2)), (round(self.tu0 + (c2 + 0.5) * TR * k, 2), round(self.tv0 + (r2 + 0.5) * TR * k, 2))
        out = [snap(pts[0])[1]]
        for a, b_ in zip(pts, pts[1:]):
            (ra, ca), _ = snap(a)
            (rb, cb), b_ = snap(b_)
            path, c_ = route_through_array(cost, (ra, ca), (rb, cb), fully_connected=True, geometric=True)
            if c_ >= 1e6:
                raise ValueError(f"{self.name}: no clear route {a} -> {b_}")
            path = np.array(path, float)
            path = approximate_polygon(path, tolerance=0.6)
            for r_, c2 in path[1:-1]:
                out.append((round(self.tu0 + (c2 + 0.5) * TR * k, 2), round(self.tv0 + (r_ + 0.5) * TR * k, 2)))
            out.append(b_)
        self.route(out, bias)

    def set_footprint(self, *rings):
        """(blind9) Footprint made of several disjoint rings (a main building and a detached outbuilding):
        the rings are chained through a connector walked there and back, so the even-odd tests used for
        the footprint see exactly the union of the rings."""
        fp = []
        for r in rings:
            fp += list(r) + [r[0]]
        rest = [r[0] for r in rings[1:]][::-1]
        self.foot = fp + rest

    def ignore_rect(self, u0, v0, u1, v1, note):
        self.ignores.append({"polygon_uv": [(u0, v0), (u1, v0), (u1, v1), (u0, v1)], "note": note})

    # ---------------- simulation ----------------
    def to_world(self, u, v):
        c, s = math.cos(self.theta), math.sin(self.theta)
        return (u * c - v * s, u * s + v * c)

    def simulate(self, nbeams=None, rmax=None, rmap=None, step=None):
        rmax = rmax or self.rmax; rmap = rmap or self.rmap      # (blind11)
        nbeams = nbeams or self.nbeams; step = step or self.scan_step   # (blind12)
        rng = self.rng
        c, s = math.cos(self.theta), math.sin(self.theta)
        corners = [self.to_world(u, v) for u, v in [(self.tu0, self.tv0), (-self.tu0 + self.wu, self.tv0),
                                                    (-self.tu0 + self.wu, -self.tv0 + self.wv),
                                                    (self.tu0, -self.tv0 + self.wv)]]
        self.gx0 = math.floor(min(p[0] for p in corners) / self.res) * self.res
        self.gy0 = math.floor(min(p[1] for p in corners) / self.res) * self.res
        GW = int((max(p[0] for p in corners) - self.gx0) / self.res) + 1
        GH = int((max(p[1] for p in corners) - self.gy0) / self.res) + 1
        NC = GW * GH
        hits = np.zeros(NC, np.int32)
        passes = np.zeros(NC, np.int32)
        ts = np.arange(0.0, rmax, TR)
        if self.fov >= 360:
            bang = np.arange(nbeams) * 2 * math.pi / nbeams
        else:                       # (blind7) front-facing lidar, e.g. a 270 deg Hokuyo: blind sector behind
            bang = np.radians(np.linspace(-self.fov / 2, self.fov / 2, nbeams))
        dstep = min(0.03, 0.6 * self.res)   # (blind7) free-ray sampling fine enough for the cell size
        # (blind8) surface normals of opaque geometry (range noise grows at grazing incidence)
        sm = ndimage.gaussian_filter((self.cls == 1).astype(np.float32), 1.5)
        gy, gx = np.gradient(sm)
        onrm = np.arctan2(gy, gx).astype(np.float32)
        del sm, gy, gx
        err = np.zeros(3)
        poses = []
        pbias = []
        for pts, bs in zip(self.routes, self.biases):
            n0 = len(poses)
            for (a0, b0), (a1, b1) in zip(pts, pts[1:]):
                L = math.hypot(a1 - a0, b1 - b0)
                k = max(int(L / step), 1)
                h = math.atan2(b1 - b0, a1 - a0)
                for i in range(k):
                    poses.append((a0 + (a1 - a0) * i / k, b0 + (b1 - b0) * i / k, h))
            poses.append((pts[-1][0], pts[-1][1], h))
            pbias += [bs] * (len(poses) - n0)
        self.poses = poses
        self.route_warn = []
        for (pu, pv, ph) in poses[::2]:
            r0, c0 = int((pv - self.tv0) / TR), int((pu - self.tu0) / TR)
            k = int(0.17 / TR)
            if self.cls[r0 - k:r0 + k + 1, c0 - k:c0 + k + 1].any():
                self.route_warn.append((round(pu, 2), round(pv, 2)))
        for j, ((pu, pv, ph), bs) in enumerate(zip(poses, pbias)):
            # true scan
            ang = ph + bang
            cu, su = np.cos(ang), np.sin(ang)
            U = pu + cu[:, None] * ts[None, :]
            V = pv + su[:, None] * ts[None, :]
            ci = ((U - self.tu0) / TR).astype(np.int32)
            ri = ((V - self.tv0) / TR).astype(np.int32)
            ok = (ci >= 0) & (ci < self.TW) & (ri >= 0) & (ri < self.TH)
            ci = np.clip(ci, 0, self.TW - 1); ri = np.clip(ri, 0, self.TH - 1)
            k = np.where(ok, self.cls[ri, ci], 0)
            refl = k == 1
            g = k == 2
            if g.any():
                nrm = self.gn[ri, ci]
                cosi = np.abs(np.cos(ang[:, None] - nrm))
                pg = np.where(cosi > 0.92, 0.95, np.where(cosi > 0.6, 0.4, 0.03))
                refl |= g & (rng.random(g.shape) < pg)
            has = refl.any(1)
            first = np.where(has, refl.argmax(1), len(ts) - 1)
            r = ts[first].copy()
            bi = np.arange(nbeams)
            hr, hc = ri[bi, first], ci[bi, first]
            nrm_h = np.where(k[bi, first] == 2, self.gn[hr, hc], onrm[hr, hc])
            cos_h = np.abs(np.cos(ang - nrm_h))
            # (blind7) people walking / standing while the map was made: two legs each, seen by the lidar
            for (lu, lv) in self.legs_at(j):
                dx, dy = lu - pu, lv - pv
                tp = dx * cu + dy * su
                d2 = dx * dx + dy * dy - tp * tp
                hitp = (tp > 0.1) & (d2 < 0.07 ** 2)
                rp = tp - np.sqrt(np.maximum(0.07 ** 2 - d2, 0))
                closer = hitp & (~has | (rp < r))
                r = np.where(closer, rp, r)
                has = has | closer
            # (blind8) mixed pixels: a beam that grazes an edge (range jump to the neighbouring beam) often
            # returns a range between the near and the far surface -> stray points behind corners
            rn = np.roll(r, 1); hn = np.roll(has, 1)
            jump = has & hn & (np.abs(r - rn) > 0.25) & (rng.random(nbeams) < 0.3)
            far_i = np.where(r > rn, bi, (bi - 1) % nbeams)[jump]
            near_r = np.minimum(r, rn)[jump]
            r[far_i] = near_r + rng.uniform(0.1, 0.9, far_i.size) * (r[far_i] - near_r)
            # (blind8) range noise: 1.2 cm at normal incidence, up to ~4.5 cm at grazing incidence
            r = r + rng.normal(0, 1, nbeams) * (0.012 + 0.035 * (1 - cos_h) ** 1.5)
            has &= r < rmax
            # dropouts (dark / shiny surfaces)
            drop = rng.random(nbeams) < 0.01
            # estimated pose
            err[:2] = 0.985 * err[:2] + rng.normal(0, 0.004, 2)
            err[2] = 0.985 * err[2] + rng.normal(0, 0.0007)
            eu = pu + err[0] + rng.normal(0, 0.004) + bs[0]
            ev = pv + err[1] + rng.normal(0, 0.004) + bs[1]
            eh = ph + err[2] + rng.normal(0, 0.0015) + math.radians(bs[2])
            ea = eh + bang
            # free stretch
            rf = np.where(has, np.minimum(r - 0.06, rmap), rmap)
            rf[drop] = 0
            tt = np.arange(0.0, rmap, dstep)
            msk = tt[None, :] < rf[:, None]
            bu = eu + np.cos(ea)[:, None] * tt[None, :]
            bv = ev + np.sin(ea)[:, None] * tt[None, :]
            x = bu * c - bv * s
            y = bu * s + bv * c
            cx = ((x - self.gx0) / self.res).astype(np.int64)
            cy = ((y - self.gy0) / self.res).astype(np.int64)
            inb = msk & (cx >= 0) & (cx < GW) & (cy >= 0) & (cy < GH)
            key = (np.arange(nbeams)[:, None] * NC + cy * GW + cx)[inb]
            key = np.unique(key) % NC
            passes += np.bincount(key, minlength=NC).astype(np.int32)
            hb = has & (r <= rmap) & ~drop
            hu = eu + np.cos(ea[hb]) * r[hb]
            hv = ev + np.sin(ea[hb]) * r[hb]
            x = hu * c - hv * s
            y = hu * s + hv * c
            cx = ((x - self.gx0) / self.res).astype(np.int64)
            cy = ((y - self.gy0) / self.res).astype(np.int64)
            ok = (cx >= 0) & (cx < GW) & (cy >= 0) & (cy < GH)
            hits += np.bincount((cy * GW + cx)[ok], minlength=NC).astype(np.int32)
        L = np.clip(hits * 0.9 - passes * 0.45, -6, 6)
        # (ordering-free accumulation approximates clamped sequential log-odds)
        p = 1 / (1 + np.exp(-L))
        g = np.full(NC, UNK, np.uint8)
        g[p > 0.65] = OCC
        g[p < 0.196] = FREE
        g = g.reshape(GH, GW)[::-1]          # row 0 = north
        # crop to observed area + 1 m
        obs = np.argwhere(g != UNK)
        mg = int(round(self.pad / self.res))   # (blind9) per-map padding
        r0, c0 = obs.min(0) - mg
        r1, c1 = obs.max(0) + mg + 1
        r0, c0 = max(r0, 0), max(c0, 0)
        r1, c1 = min(r1, GH), min(c1, GW)
        g = g[r0:r1, c0:c1]
        self.ox = float(self.gx0 + c0 * self.res)
        self.oy = float(self.gy0 + (GH - r1) * self.res)
        self.grid = g
        self.H, self.W = g.shape

    # ---------------- checks on the simulated map ----------------
    def cell(self, x, y):
        return self.H - 1 - int((y - self.oy) / self.res), int((x - self.ox) / self.res)

    def uv_cell(self, u, v):
        return self.cell(*self.to_world(u, v))

    def val_uv(self, u, v):
        r, c = self.uv_cell(u, v)
        if 0 <= r < self.H and 0 <= c < self.W:
            return self.grid[r, c]
        return UNK

    def finalize(self, outdir):
        g = self.grid
        self.dist_occ = ndimage.distance_transform_edt(g != OCC) * self.res
        self.dist_nf = ndimage.distance_transform_edt(g == FREE) * self.res
        log = []
        spaces = []
        for sp in self.spaces:
            u, v = sp["point"]
            r, c = self.uv_cell(u, v)
            good = 0 <= r < self.H and 0 <= c < self.W and g[r, c] == FREE and self.dist_occ[r, c] >= 0.55 and self.dist_nf[r, c] >= 0.3
            if not good and sp["region"]:
                u0, v0, u1, v1 = sp["region"]
                best, bp = -1, None
                for uu in np.arange(u0 + 0.3, u1 - 0.3, 0.1):
                    for vv in np.arange(v0 + 0.3, v1 - 0.3, 0.1):
                        rr, cc = self.uv_cell(uu, vv)
                        if not (0 <= rr < self.H and 0 <= cc < self.W) or g[rr, cc] != FREE:
                            continue
                        sc = min(self.dist_occ[rr, cc], self.dist_nf[rr, cc] + 0.25) - 0.05 * math.hypot(uu - u, vv - v)
                        if sc > best:
                            best, bp = sc, (uu, vv)
                if bp is not None:
                    rr, cc = self.uv_cell(*bp)
                    if self.dist_occ[rr, cc] >= 0.55 and self.dist_nf[rr, cc] >= 0.3:
                        log.append(f"space moved {sp['note']}: ({u:.2f},{v:.2f}) -> ({bp[0]:.2f},{bp[1]:.2f})")
                        u, v = bp
                        good = True
            if not good:
                log.append(f"SPACE DROPPED {sp['note']} (no mapped floor with 0.55 m clearance)")
                if sp["region"]:
                    u0, v0, u1, v1 = sp["region"]
                    self.ignores.append({"polygon_uv": [(u0, v0), (u1, v0), (u1, v1), (u0, v1)],
                                         "note": f"barely seen: {sp['note']}"})
                continue
            spaces.append({"point": [round(x, 3) for x in self.to_world(u, v)], "kind": sp["kind"],
                           "group": sp["group"], "note": sp["note"]})
        doors = []
        for d in self.doors:
            (u, v), t, w = d["center"], d["t"], d["w"] if "w" in d else d["width_m"]
            # fraction of the opening seen free (centre line, inner 70 %)
            ss = np.linspace(-w * 0.35, w * 0.35, 15)
            vals = [self.val_uv(u + t[0] * s_, v + t[1] * s_) for s_ in ss]
            ff = np.mean([x == FREE for x in vals])
            # clear width measured along the wall line
            def run(sign):
                s_ = 0.0
                while s_ < 1.5:
                    s_ += 0.025
                    if self.val_uv(u + t[0] * s_ * sign, v + t[1] * s_ * sign) == OCC:
                        return s_
                return None
            a, b = run(-1), run(1)
            meas = (a + b) if a and b else None
            opt = d["optional"]
            note = d["note"]
            def jamb(sign):
                hit = 0
                ss_ = np.arange(w / 2 + 0.06, w / 2 + 0.4, 0.04)
                for s_ in ss_:
                    q = (u + t[0] * s_ * sign, v + t[1] * s_ * sign)
                    n_ = d["n"]
                    ext = max(0.15, d.get("th", 0.12) / 2 + 0.07)   # thick walls: faces lie th/2 off the centre line
                    hit += any(self.val_uv(q[0] + n_[0] * o, q[1] + n_[1] * o) == OCC for o in np.linspace(-ext, ext, 7))
                return hit / len(ss_)
            ja, jb = jamb(-1), jamb(1)
            if ff < 0.35 and note.startswith("window"):
                continue                       # the glass came out as wall: no gap on the map
            if note.startswith("window") and self.val_uv(u, v) == OCC:
                # (blind11) the window gap's centre cell is mapped occupied (a mullion / the glass): no gap there
                log.append(f"window gap dropped {note}: its centre is mapped occupied")
                continue
            if self.val_uv(u, v) == OCC:
                log.append(f"WARNING door centre mapped occupied: {note}")
            if note.startswith("window") and (meas is None or meas < 0.3):
                log.append(f"window gap dropped {note}: the map shows obstacles in it (clear {meas})")
                continue                       # (blind6) glass / furniture behind it mapped inside the gap
            if ff < 0.35:
                if min(ja, jb) >= 0.3:
                    # the wall and both jambs are mapped but the opening itself is unknown (seen edge-on
                    # from afar): a person may or may not call it a door
                    opt = True
                    log.append(f"door optional (gap with unknown floor) {note}: free frac {ff:.2f}")
                else:
                    log.append(f"DOOR DROPPED {note}: free frac {ff:.2f}, jambs {ja:.2f}/{jb:.2f}")
                    continue
            if (max(ja, jb) < 0.3 or min(ja, jb) < (0.5 if d.get("glass") else 0.1)) and not opt:
                opt = True
                log.append(f"door made optional {note}: jamb evidence {ja:.2f}/{jb:.2f}")
            if ff < 0.8 and not opt:
                opt = True
                log.append(f"door made optional {note}: free frac {ff:.2f}")
            if meas and meas > d["width_m"] + 0.6 and not opt:
                # (blind11) the map shows a much wider gap than the door (the wall beside it is hardly mapped,
                # seen from afar): a person may or may not point at a door there
                opt = True
                log.append(f"door made optional {note}: measured {meas:.2f} vs drawn {d['width_m']} (wall beside it hardly mapped)")
            width = d["width_m"]
            if meas and abs(meas - width) <= 0.25:
                width = round(meas, 2)
            elif meas:
                log.append(f"door {note}: measured {meas:.2f} vs drawn {width}")
            doors.append({"center": [round(x, 3) for x in self.to_world(u, v)], "width_m": round(width, 2),
                          "optional": bool(opt), "note": note, "_t": t})
        passages = []
        for p in self.passages:
            (u, v), ac = p["center"], p["across"]
            L = math.hypot(*ac); ac = (ac[0] / L, ac[1] / L)
            th = (-ac[1], ac[0])
            ok = all(self.val_uv(u + th[0] * s_, v + th[1] * s_) == FREE for s_ in np.linspace(-0.4, 0.4, 9))
            def run(sign):
                s_ = 0.0
                while s_ < 1.2:
                    s_ += 0.025
                    if self.val_uv(u + ac[0] * s_ * sign, v + ac[1] * s_ * sign) != FREE:
                        return s_
                return None
            a, b = run(-1), run(1)
            meas = (a + b) if a and b else None
            opt = p["optional"]
            if self.val_uv(u, v) != FREE:
                # (blind8) the passage is not on mapped floor at all (unseen part of the building): a person
                # annotating the map would not mark it
                log.append(f"PASSAGE DROPPED {p['note']}: centre not on mapped floor")
                continue
            if not ok:
                log.append(f"passage {p['note']}: centre line not all free -> optional")
                opt = True
            width = p["width_m"]
            if meas and abs(meas - width) <= 0.2:
                width = round(meas, 2)
            else:
                log.append(f"passage {p['note']}: measured {meas} vs drawn {width}")
            passages.append({"center": [round(x, 3) for x in self.to_world(u, v)], "width_m": round(width, 2),
                             "optional": bool(opt), "note": p["note"], "_a": ac})
        ignores = self.fan_ignores([d["center"] for d in doors] + [p["center"] for p in passages])
        # (blind8) rectangles over barely seen rooms keep 0.8 m away from every kept door / passage centre
        # (as the fan polygons do), so that a detection a little inside the room is not discarded
        cth, sth = math.cos(self.theta), math.sin(self.theta)
        keep_uv = [(cth * x + sth * y, -sth * x + cth * y) for x, y in
                   [d["center"] for d in doors] + [p["center"] for p in passages]]
        for ig in self.ignores:
            us = [q[0] for q in ig["polygon_uv"]]; vs = [q[1] for q in ig["polygon_uv"]]
            u0, u1, v0, v1 = min(us), max(us), min(vs), max(vs)
            for _ in range(3):
                for ku, kv in keep_uv:
                    du = max(u0 - ku, 0, ku - u1); dv = max(v0 - kv, 0, kv - v1)
                    if math.hypot(du, dv) >= 0.8:
                        continue
                    # move the edge nearest to the point inward
                    cand = [(abs(ku - u0), "u0"), (abs(ku - u1), "u1"), (abs(kv - v0), "v0"), (abs(kv - v1), "v1")]
                    # (blind11) a point outside the box is kept out by the edge FACING it (blind9 picked the nearest
                    # edge line, which for a door centred below a narrow box could be a side edge -> box collapsed)
                    if ku < u0 or ku > u1 or kv < v0 or kv > v1:
                        cand = [(0 if ku < u0 else 9, "u0"), (0 if ku > u1 else 9, "u1"),
                                (0 if kv < v0 else 9, "v0"), (0 if kv > v1 else 9, "v1")]
                        cand = [c_ for c_ in cand if c_[0] == 0]
                        cand = [(abs(ku - u0) if e_ == "u0" else abs(ku - u1) if e_ == "u1" else
                                 abs(kv - v0) if e_ == "v0" else abs(kv - v1), e_) for _, e_ in cand]
                        cand = [(-d_, e_) for d_, e_ in cand]   # the edge the point lies farthest beyond
                    e = min(cand)[1]
                    if e == "u0": u0 = ku + 0.8
                    elif e == "u1": u1 = ku - 0.8
                    elif e == "v0": v0 = kv + 0.8
                    else: v1 = kv - 0.8
            if u1 - u0 < 0.5 or v1 - v0 < 0.5:
                log.append(f"ignore box dropped (too close to doors): {ig['note']}")
                continue
            ignores.append({"polygon": [[round(x, 3) for x in self.to_world(*q)] for q in
                                        [(u0, v0), (u1, v0), (u1, v1), (u0, v1)]], "note": ig["note"]})
        if self.start_frame:
            # (blind9) world frame = the robot's start pose: shift every world coordinate (and the origin) so
            # that the first pose of the first route is (0, 0).  All checks above ran in the unshifted frame.
            sx, sy = self.to_world(*self.routes[0][0])
            self.shift = (sx, sy)
            for sp in spaces:
                sp["point"] = [round(sp["point"][0] - sx, 3), round(sp["point"][1] - sy, 3)]
            for d in doors + passages:
                d["center"] = [round(d["center"][0] - sx, 3), round(d["center"][1] - sy, 3)]
            for ig in ignores:
                ig["polygon"] = [[round(x - sx, 3), round(y - sy, 3)] for x, y in ig["polygon"]]
            self.ox, self.oy = self.ox - sx, self.oy - sy
        self.out = {"map": f"{self.name}.yaml", "notes": self.notes, "spaces": spaces,
                    "doors": [{k: v for k, v in d.items() if not k.startswith("_")} for d in doors],
                    "narrow_passages": [{k: v for k, v in d.items() if not k.startswith("_")} for d in passages],
                    "ignore": ignores}
        self._doors, self._pass = doors, passages
        outdir = Path(outdir)
        (outdir / "maps").mkdir(parents=True, exist_ok=True)
        (outdir / "render").mkdir(parents=True, exist_ok=True)
        Image.fromarray(g).save(outdir / "maps" / f"{self.name}.pgm")
        (outdir / "maps" / f"{self.name}.yaml").write_text(yaml.safe_dump({
            "image": f"{self.name}.pgm", "resolution": self.res, "origin": [round(float(self.ox), 3), round(float(self.oy), 3), 0.0],
            "negate": 0, "occupied_thresh": 0.65, "free_thresh": 0.196, "mode": "trinary"}, sort_keys=False))
        (outdir / "maps" / f"{self.name}.points.json").write_text(json.dumps(self.out, indent=1))
        self.render(outdir / "render" / f"{self.name}.png")
        return log

    def fan_ignores(self, keep=()):
        """Mapped free floor outside the footprint (+0.35 m) -> ignore polygons (component hulls,
        or 1 m tile runs where a hull would reach back over the building).  (blind7) The polygons also
        keep 0.8 m away from every annotated door / passage centre (keep, world x, y), so that a
        detection within the 0.6 / 0.75 m match radius of an outside door is never ignored."""
        from skimage.morphology import convex_hull_image  # noqa
        from skimage import measure
        g = self.grid
        H, W = g.shape
        rows = np.arange(H); cols = np.arange(W)
        X = self.ox + (cols[None, :] + 0.5) * self.res
        Y = self.oy + (H - rows[:, None] - 0.5) * self.res
        c, s = math.cos(self.theta), math.sin(self.theta)
        U = c * X + s * Y
        V = -s * X + c * Y
        inside = np.zeros((H, W), bool)
        fp = self.foot
        for (x0, y0), (x1, y1) in zip(fp, fp[1:] + fp[:1]):
            if y0 == y1:
                continue
            inside ^= ((y0 > V) != (y1 > V)) & (U < x0 + (V - y0) * (x1 - x0) / (y1 - y0))
        buf = ndimage.binary_dilation(inside, iterations=int(0.35 / self.res))
        out = (g != UNK) & ~buf
        out = ndimage.binary_closing(out, iterations=max(1, round(0.15 / self.res))) & ~buf
        res = []
        near = ndimage.binary_dilation(inside, iterations=int(0.2 / self.res))
        for (kx, ky) in keep:
            kr = np.hypot(X - kx, Y - ky) <= 0.8
            near |= kr
            out &= ~kr
        lab, n = ndimage.label(out)
        for i in range(1, n + 1):
            m = lab == i
            if m.sum() * self.res ** 2 < 0.1:
                continue
            rr, cc = np.nonzero(m)
            # hull in cell coords
            from scipy.spatial import ConvexHull
            ptsc = np.stack([cc, rr], 1).astype(float)
            try:
                hull = ConvexHull(ptsc)
                hp = ptsc[hull.vertices]
            except Exception:
                continue
            # rasterise hull, check it does not cover the building
            from skimage.draw import polygon as skpoly
            pr, pc = skpoly(hp[:, 1], hp[:, 0], shape=(H, W))
            if not near[pr, pc].any():
                polys = [hp]
            else:
                # (blind7) the hull reaches the building or a door: hull minus the keep-out zone, traced as a
                # (non-convex) polygon; 1 m tile runs only where that still holds a kept point
                M = np.zeros((H, W), bool)
                M[pr, pc] = True
                M &= ~near
                lm, nm = ndimage.label(M)
                polys = []
                for j in range(1, nm + 1):
                    mj = lm == j
                    if not (mj & m).any() or mj.sum() * self.res ** 2 < 0.1:
                        continue
                    cs = measure.find_contours(np.pad(mj, 1).astype(float), 0.5)
                    cont = max(cs, key=len)
                    ap = measure.approximate_polygon(cont, tolerance=0.7)
                    hp2 = np.stack([ap[:, 1] - 0.5, ap[:, 0] - 0.5], 1)     # (x = col, y = row), cell centre = +0.5
                    if np.allclose(hp2[0], hp2[-1]):
                        hp2 = hp2[:-1]
                    wp = [(self.ox + x * self.res, self.oy + (H - y) * self.res) for x, y in hp2]
                    if any(_inside(wp, kp) for kp in keep):
                        continue
                    polys.append(hp2)
                if polys:
                    for hp in polys:
                        poly = [[round(self.ox + x * self.res, 3), round(self.oy + (H - y) * self.res, 3)] for x, y in hp]
                        res.append({"polygon": poly, "note": "laser-ray fan / mapped floor outside the building"})
                    continue
                k = int(round(1.0 / self.res))   # 1 m tiles
                for r0 in range(rr.min() // k * k, rr.max() + 1, k):
                    run = None
                    for c0 in range(cc.min() // k * k, cc.max() + k + 1, k):
                        t_ = m[r0:r0 + k, c0:c0 + k]
                        okt = t_.any() and not near[r0:r0 + k, c0:c0 + k].any()
                        if okt and run is None:
                            run = c0
                        if not okt and run is not None:
                            polys.append(np.array([[run, r0], [c0, r0], [c0, r0 + k], [run, r0 + k]], float))
                            run = None
            for hp in polys:
                poly = [[round(self.ox + x * self.res, 3), round(self.oy + (H - y) * self.res, 3)] for x, y in hp]
                res.append({"polygon": poly, "note": "laser-ray fan / mapped floor outside the building"})
        return res

    def render(self, path, s=None):
        s = s or max(1, round(self.res / 0.025))     # ~2.5 cm per pixel whatever the cell size
        g = self.grid
        H, W = g.shape
        rgb = Image.fromarray(np.stack([g] * 3, -1)).resize((W * s, H * s), Image.NEAREST)
        d = ImageDraw.Draw(rgb)
        def px(p):
            return ((p[0] - self.ox) / self.res * s, (H - (p[1] - self.oy) / self.res) * s)
        c, sn = math.cos(self.theta), math.sin(self.theta)
        def rot(t):
            return (t[0] * c - t[1] * sn, t[0] * sn + t[1] * c)
        for ig in self.out["ignore"]:
            d.polygon([px(p) for p in ig["polygon"]], outline=(230, 180, 0))
        for dd, col in [(x, (220, 0, 0)) for x in self._doors] + [(x, (170, 0, 220)) for x in self._pass]:
            t = rot(dd.get("_t") or dd.get("_a"))
            if dd["optional"]:
                col = (255, 150, 0)
            x, y = dd["center"]
            h = dd["width_m"] / 2
            d.line([px((x - t[0] * h, y - t[1] * h)), px((x + t[0] * h, y + t[1] * h))], fill=col, width=4)
        for sp in self.out["spaces"]:
            x, y = px(sp["point"])
            col = (0, 90, 255) if sp["kind"] == "room" else (0, 170, 0)
            d.ellipse([x - 6, y - 6, x + 6, y + 6], fill=col)
            if sp["group"]:
                d.ellipse([x - 10, y - 10, x + 10, y + 10], outline=(230, 0, 230), width=2)
        rgb.save(path)
