#!/usr/bin/env python3
"""Draws two new buildings (a clinic and a small office) and writes buildings.jsonl.

Geometry is written as rectangles in world metres; the numbers used for the expected regions
are the same variables the drawing uses. Walls are 0.2 m thick; "inner" coordinates are the
free-space boundary (a corner's meeting point is the inner corner of two walls, a door's
reference point is the centre of its opening, mid-wall).
"""
import json
import math
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).parent
RES = 0.05
OCC, FREE, UNK = 0, 254, 205
WALL = 0.2
DOOR_W = 0.9
sys.path.insert(0, "/work/shared/bench")


class Drawing:
    def __init__(self, name, x0, y0, x1, y1):
        self.name, self.ox, self.oy = name, x0, y0
        self.w, self.h = round((x1 - x0) / RES), round((y1 - y0) / RES)
        self.g = np.full((self.h, self.w), UNK, np.uint8)  # row 0 = south

    def rect(self, x0, y0, x1, y1, v):
        c0, c1 = round((x0 - self.ox) / RES), round((x1 - self.ox) / RES)
        r0, r1 = round((y0 - self.oy) / RES), round((y1 - self.oy) / RES)
        self.g[r0:r1, c0:c1] = v

    def save(self):
        img = np.flipud(self.g)
        (HERE / "maps" / f"{self.name}.pgm").write_bytes(
            f"P5\n# {self.name}: drawn by make_buildings.py\n{self.w} {self.h}\n255\n".encode() + img.tobytes())
        (HERE / "maps" / f"{self.name}.yaml").write_text(
            f"image: {self.name}.pgm\nmode: trinary\nresolution: {RES}\norigin: [{self.ox}, {self.oy}, 0.0]\n"
            "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")

    def free_centroid(self, x0, y0, x1, y1):
        c0, c1 = round((x0 - self.ox) / RES), round((x1 - self.ox) / RES)
        r0, r1 = round((y0 - self.oy) / RES), round((y1 - self.oy) / RES)
        sub = self.g[r0:r1, c0:c1] == FREE
        rr, cc = np.nonzero(sub)
        return (round(self.ox + (c0 + cc.mean() + 0.5) * RES, 2), round(self.oy + (r0 + rr.mean() + 0.5) * RES, 2))


def poly(x0, y0, x1, y1):
    return {"polygon": [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]}


def circ(x, y, r):
    return {"circle": [round(x, 3), round(y, 3), r]}


def ntp(goal, via=None):
    d = {"command": "NavigateThroughPoses", "goal": goal}
    if via:
        d["via"] = via
    return d


def rot(direction, lo, hi):
    return {"command": "Rotate", "direction": direction, "repeat": [lo, hi]}


def move(direction, metres):
    exact = metres / 0.03
    tol = max(0.07 * exact, 1.0)
    return {"command": "Move", "direction": direction,
            "repeat": [max(1, math.ceil(exact - tol)), math.floor(exact + tol)]}


STOP = [{"command": "Stop"}]
AT_DOOR, AT_CORNER, BACK_HERE, MIDDLE = 0.75, 1.0, 0.5, 0.75


# =================================================================== clinic
def clinic():
    d = Drawing("clinic", -1.0, -1.0, 21.0, 13.0)
    d.rect(-WALL, -WALL, 20 + WALL, 12 + WALL, OCC)
    # corridor (free y 5..7), south rooms (free y 0..4.8), north rooms (free y 7.2..12)
    rooms = {
        "S1": (0.0, 0.0, 5.0, 4.8), "S2": (5.2, 0.0, 9.0, 4.8), "S3": (9.2, 0.0, 12.6, 4.8),
        "S4": (12.8, 0.0, 20.0, 4.8),
        "N1": (0.0, 7.2, 5.0, 12.0), "N2": (5.2, 7.2, 9.0, 12.0), "N3": (9.2, 7.2, 14.0, 12.0),
        "N4": (14.2, 7.2, 20.0, 12.0),
    }
    d.rect(0.0, 5.0, 20.0, 7.0, FREE)
    for r in rooms.values():
        d.rect(*r, FREE)
    doors = {"S1": (3.5, 4.9), "S2": (7.0, 4.9), "S3": (11.0, 4.9), "S4": (16.0, 4.9),
             "N1": (2.5, 7.1), "N2": (7.5, 7.1), "N3": (11.5, 7.1), "N4": (15.0, 7.1)}
    for (x, y) in doors.values():
        d.rect(x - DOOR_W / 2, y - WALL / 2, x + DOOR_W / 2, y + WALL / 2, FREE)
    # furniture
    d.rect(1.0, 0.0, 4.0, 0.5, OCC)      # waiting-room chairs along the south wall
    d.rect(6.0, 0.0, 8.0, 0.8, OCC)      # exam bed S2
    d.rect(10.0, 0.0, 12.0, 0.8, OCC)    # exam bed S3
    d.rect(0.8, 9.5, 3.5, 10.2, OCC)     # reception desk N1
    d.rect(6.0, 11.2, 8.0, 12.0, OCC)    # exam bed N2
    d.rect(10.0, 11.2, 12.0, 12.0, OCC)  # exam bed N3
    d.rect(16.0, 8.5, 16.5, 10.5, OCC)   # lab bench west of the passage
    d.rect(17.2, 8.5, 17.7, 10.5, OCC)   # lab bench east of the passage (gap 0.7 m)
    d.rect(19.4, 8.0, 20.0, 11.5, OCC)   # lab shelving on the east wall
    # storage room not yet scanned beyond y = 2.5
    d.rect(12.8, 0.0, 20.0, 2.5, UNK)
    d.save()

    R = {k: poly(*v) for k, v in rooms.items()}
    D = {k: circ(x, y, AT_DOOR) for k, (x, y) in doors.items()}
    cen = {k: d.free_centroid(*v) for k, v in rooms.items()}
    frontier = poly(12.8, 2.5, 20.0, 3.6)

    PA = [1.0, 5.7, 0]      # west end of the corridor, facing east (left = north rooms)
    PB = [11.0, 6.0, 180]   # middle of the corridor, facing west (left = south rooms)
    PC = [7.0, 2.5, 0]      # inside exam room S2, facing east
    PD = [19.0, 6.0, 180]   # east end of the corridor, facing west
    PE = [1.5, 3.0, 90]     # waiting room S1, facing north
    PE2 = [1.0, 2.4, 0]     # waiting room S1 near its west wall, facing east
    PF = [16.85, 7.8, 90]   # lab N4, in front of the gap between the benches
    m = "maps/clinic.yaml"
    C = [
        (PA, "go to the first door on your left", [ntp(D["N1"])]),
        (PA, "take the second door on the right",
         [ntp({"any": [D["S2"], poly(5.2, 2.9, 9.0, 4.8)]})]),
        (PA, "um go thru the 3rd door on ur left", [ntp(poly(10.0, 7.2, 13.0, 9.0))]),
        (PA, "enter the last room on the right", [ntp(R["S4"])]),
        (PA, "go halfway down the corridor", [ntp(poly(9.0, 5.0, 11.5, 7.0))]),
        (PA, "go 2 m past the door on your right", [ntp(poly(4.9, 5.0, 6.1, 7.0))]),
        (PA, "go to the nearest corner, then come back here",
         [ntp(circ(PA[0], PA[1], BACK_HERE), via=[circ(0.0, 5.0, AT_CORNER)])]),
        (PC, "head into the room across the hall", [ntp(R["N2"])]),
        (PC, "turn to face the door", [rot("left", 8, 10)]),
        (PE, "go to the nearest corner then come back here",
         [ntp(circ(PE[0], PE[1], BACK_HERE), via=[circ(0.0, 4.8, AT_CORNER)])]),
        (PE, "go to the room next to this one", [ntp(R["S2"])]),
        (PB, "go into the biggest room", [ntp(R["S4"])]),
        (PB, "find the smallest room and go in there", [ntp(R["S3"])]),
        (PD, "go forward until you reach the wall", [ntp(poly(0.0, 5.0, 1.2, 7.0))]),
        (PF, "go through the narrow passage in front of you", [ntp(poly(15.9, 10.5, 17.8, 12.0))]),
        (PB, "explore the unexplored area", [ntp(frontier)]),
        (PA, "go check out the part of the map that hasn't been scanned yet", [ntp(frontier)]),
        (PA, "go to the kitchen", "clarify"),
        (PA, "open the second door on your left", "clarify"),
        (PA, "go to the fifth door on your left", "clarify"),
        (PD, "stop", STOP),
        (PB, "go to the middle of the room on your right", [ntp(circ(*cen["N3"], MIDDLE))]),
        (PA, "go to the second room on your left and stop in the middle of it", [ntp(circ(*cen["N2"], MIDDLE))]),
        (PA, "go 1 metre past the second door on your left", [ntp(poly(7.9, 5.0, 9.1, 7.0))]),
        (PC, "turn so you're facing the hallway", [rot("left", 8, 10)]),
        (PE, "turn to face the door", [rot("right", 3, 6)]),
        (PA, "face north", [rot("left", 8, 10)]),
        (PB, "go east 3 metres", [rot("any", 17, 19), move("forward", 3.0)]),
        (PA, "move forward five feet then turn left", [move("forward", 5 * 0.3048), rot("left", 8, 10)]),
        (PB, "go into the first room on your left, then come back to where you started",
         [ntp(circ(PB[0], PB[1], BACK_HERE), via=[R["S3"]])]),
        (PD, "go to the third door on your left", [ntp(D["S2"])]),
        (PD, "go to the second door on the right", [ntp(D["N3"])]),
        (PA, "pls go into the room across from the first room on your left", [ntp(R["S1"])]),
        (PA, "what's in the lab?", "clarify"),
        (PA, "take a picture of the hallway", "clarify"),
        (PA, "go into the last room on the left, the one at the far end of the hall", [ntp(R["N4"])]),
        (PE2, "go to the opposite side of the room", [ntp(poly(3.33, 0.0, 5.0, 4.8))]),
        (PA, "go 3 feet forward, then go to the first door on your left",
         [move("forward", 3 * 0.3048), ntp(D["N1"])]),
        (PB, "turn around and go into the first room on your right", [rot("any", 17, 19), ntp(R["S3"])]),
        (PA, "go to the door on your left, the one after the first", [ntp(D["N2"])]),
    ]
    return m, C, d


# =================================================================== office
def office():
    d = Drawing("office", -1.0, -1.0, 17.0, 15.0)
    d.rect(-WALL, -WALL, 16 + WALL, 14 + WALL, OCC)
    # corridor runs north-south, free x 6..8; west rooms free x 0..5.8, east x 8.2..16
    rooms = {
        "W1": (0.0, 0.0, 5.8, 3.6), "W2": (0.0, 3.8, 5.8, 8.5), "W3": (0.0, 8.7, 5.8, 14.0),
        "E1": (8.2, 0.0, 16.0, 9.0), "E2": (8.2, 9.2, 16.0, 14.0),
    }
    d.rect(6.0, 0.0, 8.0, 14.0, FREE)
    for r in rooms.values():
        d.rect(*r, FREE)
    doors = {"W1": (5.9, 2.0, 0.9), "W2": (5.9, 6.5, 0.9), "W3": (5.9, 11.0, 0.9),
             "E1a": (8.1, 3.0, 1.2), "E1b": (8.1, 7.5, 0.9), "E2": (8.1, 12.0, 0.9)}
    for (x, y, w) in doors.values():
        d.rect(x - WALL / 2, y - w / 2, x + WALL / 2, y + w / 2, FREE)
    # furniture
    d.rect(13.5, 1.0, 15.5, 2.0, OCC)    # desk block
    d.rect(13.5, 5.5, 15.5, 6.5, OCC)    # desk block
    d.rect(10.6, 2.0, 11.0, 4.0, OCC)    # shelf, west side of the passage
    d.rect(11.7, 2.0, 12.1, 4.0, OCC)    # shelf, east side of the passage (gap 0.7 m)
    d.rect(0.0, 5.0, 0.6, 7.5, OCC)      # cabinet W2
    d.rect(13.5, 11.0, 15.5, 12.5, OCC)  # meeting table E2 (east half)
    d.rect(0.0, 12.8, 2.0, 14.0, OCC)    # bookcase W3
    # north end of the corridor not yet scanned
    d.rect(6.0, 13.0, 8.0, 14.0, UNK)
    d.save()

    R = {k: poly(*v) for k, v in rooms.items()}
    D = {k: circ(x, y, AT_DOOR) for k, (x, y, _) in doors.items()}
    cen = {k: d.free_centroid(*v) for k, v in rooms.items()}
    frontier = poly(6.0, 12.0, 8.0, 13.0)

    QA = [6.7, 0.8, 90]     # south end of the corridor, facing north (left = west rooms)
    QB = [7.0, 8.2, 270]    # corridor, facing south (left = east)
    QC = [3.0, 6.3, 270]    # room W2, facing south
    QC2 = [4.6, 7.6, 270]   # room W2, near its north-east corner
    QD = [11.35, 1.0, 90]   # open-plan E1, in front of the passage between the shelves
    QE = [12.0, 7.5, 180]   # open-plan E1, facing west towards the corridor
    QF = [2.0, 12.0, 270]   # room W3, facing south
    m = "maps/office.yaml"
    C = [
        (QA, "go to the first door on your right", [ntp(D["E1a"])]),
        (QA, "go to the second door on the left", [ntp(D["W2"])]),
        (QA, "go through the third door on your left", [ntp(poly(4.0, 10.2, 5.8, 11.8))]),
        (QA, "go halfway down the corridor", [ntp(poly(6.0, 5.8, 8.0, 8.0))]),
        (QA, "go 2 metres past the door on your right", [ntp(poly(6.0, 4.4, 8.0, 5.6))]),
        (QA, "go to the nearest corner, then come back here",
         [ntp(circ(QA[0], QA[1], BACK_HERE), via=[circ(6.0, 0.0, AT_CORNER)])]),
        (QC, "go into the room across the hall", [ntp(R["E1"])]),
        (QC, "turn to face the door", [rot("left", 8, 11)]),
        (QC, "go to the room next to the one you are in", {"any": ["clarify", [ntp(R["W1"])], [ntp(R["W3"])]]}),
        (QF, "go to the room next to this one", [ntp(R["W2"])]),
        (QD, "go through the narrow passage in front of you", [ntp(poly(10.4, 4.0, 12.3, 5.9))]),
        (QA, "explore the unexplored area", [ntp(frontier)]),
        (QB, "go into the biggest room", [ntp(R["E1"])]),
        (QB, "go to the smallest room", [ntp(R["W1"])]),
        (QB, "go to the first door on your left", [ntp(D["E1b"])]),
        (QB, "take the first door on your right", [ntp({"any": [D["W2"], poly(4.1, 5.7, 5.8, 7.3)]})]),
        (QA, "last room on your left at the end of the hallway, go in there pls", [ntp(R["W3"])]),
        (QA, "go to the meeting room", "clarify"),
        (QA, "go to the fourth door on your right", "clarify"),
        (QA, "STOP!!", STOP),
        (QE, "go to the door in front of you", [ntp(D["E1b"])]),
        (QE, "go through the door in front of you and turn left",
         [ntp(poly(6.0, 6.5, 8.0, 8.5)), rot("left", 8, 10)]),
        (QC2, "go to the nearest corner and come back", [ntp(circ(QC2[0], QC2[1], BACK_HERE),
                                                            via=[circ(5.8, 8.5, AT_CORNER)])]),
        (QA, "go forward 10 feet then go to the nearest door on your right",
         [move("forward", 10 * 0.3048), ntp(D["E1a"])]),
        (QA, "face west", [rot("left", 8, 10)]),
        (QB, "go north 2 metres", [rot("any", 17, 19), move("forward", 2.0)]),
        (QD, "back up 1 m", {"any": ["clarify", [{"command": "Move", "direction": "backward", "repeat": [1, 28]}]]}),
        (QA, "go 1 metre past the second door on the right", [ntp(poly(6.0, 7.9, 8.0, 9.1))]),
        (QF, "turn to face the hallway", [rot("left", 7, 10)]),
        (QF, "go to the middle of the room across the hall", [ntp(circ(*cen["E2"], MIDDLE))]),
        (QA, "go into the second room on your right", [ntp(R["E2"])]),
        (QA, "pls go 2 the 2nd door on ur left", [ntp(D["W2"])]),
        (QC, "turn to face north", [rot("any", 17, 19)]),
        (QE, "go to the nearest door", [ntp(D["E1b"])]),
        (QA, "go towards the unknown area at the end of the hall", [ntp(frontier)]),
        (QA, "move forward 2 m and then face east", [move("forward", 2.0), rot("right", 8, 10)]),
        (QD, "go to the left corner of this room", [ntp(circ(8.2, 9.0, AT_CORNER))]),
        (QD, "go to the right corner of the room", [ntp(circ(16.0, 9.0, AT_CORNER))]),
        (QA, "what do you see", "clarify"),
        (QA, "go to the third door on the right, then come back here",
         [ntp(circ(QA[0], QA[1], BACK_HERE), via=[D["E2"]])]),
    ]
    return m, C, d


def check(path, cases):
    """Every expected region holds at least one valid cell reachable from the start."""
    from score import Map, in_region
    mp = Map((HERE / path).resolve())
    ok = mp.ok & (mp.labels > 0)
    rr, cc = np.nonzero(ok)
    xs = mp.origin[0] + (cc + 0.5) * mp.res
    ys = mp.origin[1] + (rr + 0.5) * mp.res
    for pose, prompt, exp in cases:
        comp = mp.component_of(pose[0], pose[1])
        assert comp is not None and mp.valid(pose[0], pose[1]), (prompt, pose, "start invalid")
        sel = mp.labels[rr, cc] == comp
        alts = exp["any"] if isinstance(exp, dict) else [exp]
        for alt in alts:
            if alt == "clarify":
                continue
            for c in alt:
                if c["command"] != "NavigateThroughPoses":
                    continue
                for reg in [c["goal"]] + c.get("via", []):
                    n = sum(1 for x, y in zip(xs[sel][::3], ys[sel][::3]) if in_region(reg, x, y))
                    assert n > 0, (prompt, reg, "no valid reachable cell")


def main():
    out = []
    for fn, tag in ((clinic, "cl"), (office, "of")):
        m, C, d = fn()
        check(m, C)
        for i, (pose, prompt, exp) in enumerate(C, 1):
            out.append({"id": f"bd-{tag}-{i:02d}", "map": m, "pose": pose, "prompt": prompt, "expect": exp})
    (HERE / "buildings.jsonl").write_text("".join(json.dumps(c) + "\n" for c in out))
    print(len(out), "cases")


if __name__ == "__main__":
    main()
