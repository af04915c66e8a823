"""Every missed and every false narrow passage of annotated maps, with why each miss was refused
(prints a list; asserts nothing).

  .venv/bin/python benchmarks/passage_misses.py FOLDER [FOLDER ...]
  e.g. ../shared/maps/ros benchmarks/blind/maps*/maps

For each map with a MAP.points.json beside its MAP.yaml: the analysis's narrow passages, matched
to the annotated ones as ../shared/maps/score_points.py matches them (one-to-one, nearest pairs
first, within ``MATCH_RADIUS_M``; detections in ignore polygons left out, optional passages
neither required nor penalised). A required passage with no match is printed as MISS with the
reasons :mod:`langnav.analysis.passages` logged (at debug level) for the candidates it refused
nearest to it (up to ``REASONS_SHOWN`` within ``REASON_RADIUS_M``); none means the middle line
never made a candidate there. A detection with no match is printed as FALSE with its width and
length. Last line: the pooled counts, precision and recall.
"""

from __future__ import annotations

import io
import json
import logging
import math
import re
import sys
from pathlib import Path
from typing import Any

from langnav.analysis.pipeline import analyze
from langnav.maps.io import load_map

#: A detection is that passage when its centre is within this of the annotated centre (m), as
#: in score_points.py.
MATCH_RADIUS_M = 0.75
#: Refusals logged within this of a missed passage (m) are shown with it, the nearest first.
REASON_RADIUS_M = 1.5
REASONS_SHOWN = 4

REFUSAL = re.compile(r"no passage at \(([-\d.]+), ([-\d.]+)\)(.*)")


def inside(poly: list[list[float]], p: tuple[float, float]) -> bool:
    """Is ``p`` inside the polygon (even-odd rule)?"""
    x, y = p
    hit = False
    for (x0, y0), (x1, y1) in zip(poly, poly[1:] + poly[:1], strict=True):
        if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            hit = not hit
    return hit


def matched(dets: list[tuple[float, float]], truth: list[dict[str, Any]]) -> dict[int, int]:
    """{detection index: annotation index}, one-to-one, nearest pairs first."""
    pairs = sorted((math.dist(d, t["center"]), i, j) for i, d in enumerate(dets) for j, t in enumerate(truth)
                   if math.dist(d, t["center"]) <= MATCH_RADIUS_M)
    out: dict[int, int] = {}
    for _, i, j in pairs:
        if i not in out and j not in out.values():
            out[i] = j
    return out


def main(folders: list[str]) -> int:
    log_text = io.StringIO()
    handler = logging.StreamHandler(log_text)
    handler.setLevel(logging.DEBUG)
    passages_log = logging.getLogger("langnav.analysis.passages")
    passages_log.setLevel(logging.DEBUG)
    passages_log.addHandler(handler)
    det_n = right_n = req_n = found_n = 0
    for folder in folders:
        for pts in sorted(Path(folder).glob("*.points.json")):
            name = pts.name[: -len(".points.json")]
            ann = json.loads(pts.read_text())
            truth = ann.get("narrow_passages", [])
            log_text.seek(0)
            log_text.truncate()
            found = analyze(load_map(Path(folder) / f"{name}.yaml")).narrow_passages
            kept = [p for p in found if not any(inside(r["polygon"], p.center) for r in ann.get("ignore", []))]
            m = matched([p.center for p in kept], truth)
            refused = [(float(g[1]), float(g[2]), g[3]) for g in map(REFUSAL.match, log_text.getvalue().splitlines())
                       if g]
            judged = [i for i in range(len(kept)) if not (i in m and truth[m[i]].get("optional"))]
            required = [j for j, t in enumerate(truth) if not t.get("optional")]
            det_n += len(judged)
            right_n += sum(i in m for i in judged)
            req_n += len(required)
            found_n += sum(j in m.values() for j in required)
            for j in required:
                if j in m.values():
                    continue
                t = truth[j]
                print(f"MISS {name} {t['center']} width {t.get('width_m')} m: {t.get('note', '')}")
                near = sorted((math.dist((x, y), t["center"]), x, y, why) for x, y, why in refused
                              if math.dist((x, y), t["center"]) <= REASON_RADIUS_M)
                for d, x, y, why in near[:REASONS_SHOWN]:
                    print(f"    {d:.2f} m off, at ({x:.2f}, {y:.2f}){why}")
            for i in judged:
                if i not in m:
                    p = kept[i]
                    print(f"FALSE {name} ({p.center[0]:.2f}, {p.center[1]:.2f}) width {p.width_m:.2f} m, "
                          f"length {p.length_m:.2f} m")
    precision = right_n / det_n if det_n else 1.0
    recall = found_n / req_n if req_n else 1.0
    print(f"POOLED passages: {det_n} detected, {right_n} right, {req_n} required, {found_n} found: "
          f"P/R {precision:.3f}/{recall:.3f}")
    return 0


if __name__ == "__main__":
    if len(sys.argv) < 2:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(sys.argv[1:]))
