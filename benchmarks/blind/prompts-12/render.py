#!/usr/bin/env python3
"""Pictures of the drawn maps with start poses (red) and expected goal regions (green) / via regions (blue)."""
import json, math, sys
from pathlib import Path
import numpy as np
from PIL import Image, ImageDraw
sys.path.insert(0, "/work/shared/bench")
from score import Map, in_region
HERE = Path(__file__).parent
cases = [json.loads(l) for l in open(HERE / "buildings.jsonl")]
for name in sorted({c["map"] for c in cases}):
    m = Map((HERE / name).resolve())
    g = m.grid
    rgb = np.zeros(g.shape + (3,), np.uint8)
    rgb[g == 254] = (255, 255, 255); rgb[g == 205] = (170, 170, 170); rgb[g == 0] = (0, 0, 0)
    rr, cc = np.nonzero(m.ok)
    xs, ys = m.origin[0] + (cc + 0.5) * m.res, m.origin[1] + (rr + 0.5) * m.res
    for c in cases:
        if c["map"] != name:
            continue
        alts = c["expect"]["any"] if isinstance(c["expect"], dict) else [c["expect"]]
        for alt in alts:
            if alt == "clarify":
                continue
            for cmd in alt:
                if cmd["command"] != "NavigateThroughPoses":
                    continue
                for reg, col in [(cmd["goal"], (60, 200, 60))] + [(v, (80, 80, 255)) for v in cmd.get("via", [])]:
                    inside = np.array([in_region(reg, x, y) for x, y in zip(xs, ys)])
                    rgb[rr[inside], cc[inside]] = col
    img = Image.fromarray(np.flipud(rgb)).resize((g.shape[1] * 2, g.shape[0] * 2), Image.NEAREST)
    d = ImageDraw.Draw(img)
    for c in cases:
        if c["map"] != name:
            continue
        x, y, yaw = c["pose"]
        px, py = 2 * (x - m.origin[0]) / m.res, 2 * (m.h - (y - m.origin[1]) / m.res)
        d.ellipse([px - 6, py - 6, px + 6, py + 6], outline=(255, 0, 0), width=2)
        d.line([px, py, px + 18 * math.cos(math.radians(yaw)), py - 18 * math.sin(math.radians(yaw))], fill=(255, 0, 0), width=2)
    img.save(HERE / "out" / (Path(name).stem + ".png"))
    print("wrote", Path(name).stem + ".png", img.size)
