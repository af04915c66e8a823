"""Room / hallway / doorway segmentation benchmarks (prints figures; asserts nothing).

  .venv/bin/python benchmarks/segmentation.py [--quick]

(a) ROSE² maps (real, cluttered): IPA/ROSE² room precision / recall; ROSE² publishes 89.0 / 93.9.
(b) IPA benchmark, 20 maps, without furniture (ROSE²: 93.3 / 97.6) and furnished (93.5 / 91.0).
(c) Doorway detection on the 9 IPA maps with doorway labels.
(d) Bench maps env1 / env2 against their annotations; timing of env2 and the STRANDS AAF map.

Protocols: IPA images are read as the authors do (>= 250 free, anything else occupied) at
0.05 m/pixel; ROSE² images with langnav's bare-image reader (>= 250 free, <= 50 occupied, the
rest unknown), cropped to the common top-left size of map and ground truth.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import logging
import resource
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np
from PIL import Image

from langnav.analysis.elements import Door
from langnav.analysis.params import AnalysisParams
from langnav.analysis.segmentation import Segmentation
from langnav.analysis.segmentation import segment_spaces as _segment_spaces
from langnav.eval.segmentation import (
    PrecisionRecall,
    colour_gt_rooms,
    door_precision_recall,
    ipa_doorway_blobs,
    ipa_doorways,
    ipa_gt_rooms,
    room_precision_recall,
)
from langnav.maps.grid import FREE, OCCUPIED, OccupancyGrid
from langnav.maps.io import load_bare_image, load_map

SHARED = Path(__file__).resolve().parents[2] / "shared"
ROSE2 = SHARED / "maps" / "rose2_segmentation"
IPA = SHARED / "maps" / "ipa_room_segmentation"
IPA_VRF = IPA / "training_maps" / "voronoi_random_field_training"
BENCH = SHARED / "bench" / "maps"
AAF = SHARED / "maps" / "ros" / "strands_aaf_y4_cropped.yaml"
#: The IPA authors' resolution (hard-coded in their client; the images have no YAML).
IPA_RESOLUTION_M = 0.05
IPA_MAPS = ("lab_ipa", "lab_c_scan", "Freiburg52_scan", "Freiburg79_scan", "lab_b_scan", "lab_intel",
            "Freiburg101_scan", "lab_d_scan", "lab_f_scan", "lab_a_scan", "NLB", "office_a",
            "office_b", "office_c", "office_d", "office_e", "office_f", "office_g", "office_h",
            "office_i")
#: Doorway-labelled maps: input map -> label map.
IPA_DOOR_MAPS = {"Fr101": "Fr101", "Fr52": "Fr52", "NLB": "NLB_furniture", "lab_c_furnitures":
                 "lab_c_furnitures", "lab_d_furnitures": "lab_d_furniture", "lab_intel": "intel",
                 "lab_ipa": "lab_ipa", "office_e": "office_e", "office_h": "office_h"}
#: Parameters under test (``--set name=value`` overrides a field, for tuning on the whole benchmark).
PARAMS = AnalysisParams()


def segment_spaces(grid: OccupancyGrid) -> Segmentation:
    return _segment_spaces(grid, PARAMS)


#: Published ROSE² figures (precision, recall), in percent.
ROSE2_PUBLISHED = {"rose2": (89.0, 93.9), "ipa": (93.3, 97.6), "ipa_furnished": (93.5, 91.0)}
#: A detected door matches an annotated one within this distance (m) of its centre.
BENCH_DOOR_TOL_M = 0.5


def _grey(path: Path) -> np.ndarray:
    with Image.open(path) as im:
        return np.asarray(im.convert("L"))


def ipa_grid(path: Path) -> OccupancyGrid:
    """An IPA image as the authors read it: >= 250 free, everything else occupied."""
    img = _grey(path)
    cells = np.where(img >= 250, FREE, OCCUPIED).astype(np.int8)
    return OccupancyGrid(np.flipud(cells).copy(), IPA_RESOLUTION_M, source=str(path))


def image_labels(seg: Segmentation) -> np.ndarray:
    return np.flipud(seg.labels)


def _line(name: str, pr: PrecisionRecall, extra: str = "") -> None:
    print(f"  {name:<28} precision {100 * pr.precision:5.1f}  recall {100 * pr.recall:5.1f}"
          f"  (segments {pr.n_predicted:3d}, rooms {pr.n_truth:3d}){extra}", flush=True)


def _mean(name: str, prs: list[PrecisionRecall], published: tuple[float, float] | None) -> None:
    p = 100 * statistics.mean(x.precision for x in prs)
    r = 100 * statistics.mean(x.recall for x in prs)
    ref = f"   [ROSE² published {published[0]:.1f} / {published[1]:.1f}]" if published else ""
    print(f"  MEAN {name:<23} precision {p:5.1f}  recall {r:5.1f}   over {len(prs)} maps{ref}", flush=True)


def bench_rose2(quick: bool) -> None:
    print("(a) ROSE² real maps (langnav, then ROSE²'s own output image scored by the same code)")
    prs = []
    theirs: list[PrecisionRecall] = []
    for mp in sorted((ROSE2 / "maps").glob("*.png")):
        gp = ROSE2 / "gt" / mp.name
        if not gp.exists():
            continue
        grid = load_bare_image(mp)
        with Image.open(gp) as im:
            gt = colour_gt_rooms(np.asarray(im.convert("RGB")))
        h = min(grid.height, gt.shape[0])
        w = min(grid.width, gt.shape[1])
        img = grid.to_image()[:h, :w]
        cells = np.full(img.shape, -1, dtype=np.int8)
        cells[img == 254] = FREE
        cells[img == 0] = OCCUPIED
        grid = OccupancyGrid(np.flipud(cells).copy(), grid.resolution_m, source=str(mp))
        t0 = time.perf_counter()
        seg = segment_spaces(grid)
        dt = time.perf_counter() - t0
        pr = room_precision_recall(gt[:h, :w], image_labels(seg))
        prs.append(pr)
        _line(mp.stem, pr, f"  {dt * 1000:5.0f} ms")
        own = rose2_output_labels(ROSE2 / "rose2_output" / mp.name)
        if own is not None and own.shape[0] >= h and own.shape[1] >= w:
            rp = room_precision_recall(gt[:h, :w], own[:h, :w])
            theirs.append(rp)
            _line(f"  ROSE² output {mp.stem}", rp)
    _mean("ROSE² maps", prs, ROSE2_PUBLISHED["rose2"])
    if theirs:
        _mean("ROSE² own outputs", theirs, None)
        p_us, r_us = statistics.mean(p.precision for p in prs), statistics.mean(p.recall for p in prs)
        p_th, r_th = statistics.mean(p.precision for p in theirs), statistics.mean(p.recall for p in theirs)
        ahead = "ahead in both" if p_us > p_th and r_us > r_th else "NOT ahead in both"
        print(f"  langnav vs ROSE²'s own outputs, same maps and scorer: precision {100 * p_us:.1f} vs {100 * p_th:.1f}, "
              f"recall {100 * r_us:.1f} vs {100 * r_th:.1f}: {ahead}", flush=True)


def rose2_output_labels(path: Path) -> np.ndarray | None:
    """ROSE²'s own segmentation image (one colour per room on white) as room labels, or None
    when it is not there."""
    if not path.exists():
        return None
    with Image.open(path) as im:
        rgb = np.asarray(im.convert("RGB")).copy()
    rgb[(rgb == 255).all(axis=-1)] = 0  # white: no room
    return colour_gt_rooms(rgb)


def bench_ipa(quick: bool) -> None:
    names = IPA_MAPS[::4] if quick else IPA_MAPS
    for suffix, key, title in (("", "ipa", "without furniture"), ("_furnitures", "ipa_furnished", "furnished")):
        print(f"(b) IPA benchmark, {title}")
        prs = []
        for name in names:
            gt = ipa_gt_rooms(_grey(IPA / "test_maps" / f"{name}_gt_segmentation.png"))
            grid = ipa_grid(IPA / "test_maps" / f"{name}{suffix}.png")
            t0 = time.perf_counter()
            seg = segment_spaces(grid)
            dt = time.perf_counter() - t0
            pr = room_precision_recall(gt, image_labels(seg))
            prs.append(pr)
            _line(name + suffix, pr, f"  {dt * 1000:5.0f} ms")
        _mean(f"IPA {title}", prs, ROSE2_PUBLISHED[key])


def bench_ipa_doors() -> None:
    print("(c) IPA doorway detection (the IPA labels mark every way between two rooms: doors the robot "
          "can pass and wider openings; + narrow: with the narrow doors too)")
    tp = det = truth = 0
    tp_n = det_n = 0
    tp_w = det_w = truth_w = 0
    split = 0
    for inp, lab in IPA_DOOR_MAPS.items():
        grid = ipa_grid(IPA_VRF / "original_maps" / f"{inp}_original.png")
        blobs = ipa_doorway_blobs(_grey(IPA_VRF / "training_maps" / f"training_{lab}.png"))
        seg = segment_spaces(grid)

        def image_rc(doors: tuple[Door, ...], grid: OccupancyGrid = grid) -> list[tuple[int, int]]:
            rc = []
            for d in doors:
                r, c = grid.world_to_index(*d.center)
                rc.append((grid.height - 1 - int(r), int(c)))
            return rc

        ways = seg.doors + seg.openings
        pr = door_precision_recall(image_rc(ways), blobs, grid.resolution_m)
        prn = door_precision_recall(image_rc(ways + seg.narrow_doors), blobs, grid.resolution_m)
        tp += round(pr.recall * pr.n_truth)
        det += pr.n_predicted
        truth += pr.n_truth
        # Doorways at least as wide as the robot's doors (door_min_width_m), one per opening
        # (a blob painted over two doors side by side is two doorways) and by their clear width
        # in the map: detections matched to a narrower labelled doorway are neither right nor
        # wrong there.
        occupied = np.flipud(grid.cells == OCCUPIED)
        doorways = ipa_doorways(blobs, occupied, grid.resolution_m)
        widths = [blob_width_m(d.pixels, grid.resolution_m) if d.clear_width_m is None else d.clear_width_m
                  for d in doorways]
        wide = [d.pixels for d, w in zip(doorways, widths, strict=True) if w >= PARAMS.door_min_width_m]
        narrow = [d.pixels for d, w in zip(doorways, widths, strict=True) if w < PARAMS.door_min_width_m]
        split += len(doorways) - len(blobs)
        if wide:
            pw = door_precision_recall(image_rc(ways), wide, grid.resolution_m)
            on_narrow = round(door_precision_recall(image_rc(ways), narrow, grid.resolution_m).recall
                              * len(narrow)) if narrow else 0
            tp_w += round(pw.recall * pw.n_truth)
            det_w += pw.n_predicted - on_narrow
            truth_w += pw.n_truth
        tp_n += round(prn.recall * prn.n_truth)
        det_n += prn.n_predicted
        print(f"  {inp:<28} precision {100 * pr.precision:5.1f}  recall {100 * pr.recall:5.1f}"
              f"  (detected {pr.n_predicted:3d}, labelled {pr.n_truth:3d}); + narrow: precision "
              f"{100 * prn.precision:5.1f}  recall {100 * prn.recall:5.1f}", flush=True)
    print(f"  ALL doorways                 precision {100 * tp / max(det, 1):5.1f}  recall "
          f"{100 * tp / max(truth, 1):5.1f}  (detected {det}, labelled {truth})", flush=True)
    print(f"  ALL doorways + narrow        precision {100 * tp_n / max(det_n, 1):5.1f}  recall "
          f"{100 * tp_n / max(truth, 1):5.1f}  (detected {det_n}, labelled {truth})", flush=True)
    print(f"  doorways >= {PARAMS.door_min_width_m:.2f} m clear     precision {100 * tp_w / max(det_w, 1):5.1f}  "
          f"recall {100 * tp_w / max(truth_w, 1):5.1f}  (detected {det_w} not at a narrower one, "
          f"labelled {truth_w}; {split} more doorways than blobs: blobs over two doors)", flush=True)


def blob_width_m(blob: np.ndarray, resolution_m: float) -> float:
    """The length (m) of a labelled doorway blob along its long axis (the opening's width)."""
    pts = blob.astype(float)
    if len(pts) < 2:
        return resolution_m
    centred = pts - pts.mean(axis=0)
    _evals, evecs = np.linalg.eigh(centred.T @ centred)
    proj = centred @ evecs[:, -1]
    return float(proj.max() - proj.min() + 1.0) * resolution_m


def _in_poly(x: float, y: float, poly: list[list[float]]) -> bool:
    inside = False
    n = len(poly)
    for i in range(n):
        x1, y1 = poly[i]
        x2, y2 = poly[(i + 1) % n]
        if (y1 > y) != (y2 > y) and x < x1 + (y - y1) * (x2 - x1) / (y2 - y1):
            inside = not inside
    return inside


def bench_env() -> None:
    print("(d) bench maps vs annotations (rooms+hallways matched by centroid, doors within "
          f"{BENCH_DOOR_TOL_M} m)")
    for env in ("env1", "env2"):
        grid = load_map(BENCH / f"{env}.yaml")
        ann = json.loads((BENCH / f"{env}.annotations.json").read_text())
        seg = segment_spaces(grid)
        spaces = [(s["id"], s["polygon"], kind) for kind in ("rooms", "hallways") for s in ann[kind]]
        matched = set()
        ok_rooms = 0
        for r in seg.rooms:
            hit = [sid for sid, poly, _ in spaces if _in_poly(*r.centroid, poly) and sid not in matched]
            if hit:
                matched.add(hit[0])
                ok_rooms += 1
        kind_ok = sum(1 for r in seg.rooms for sid, poly, kind in spaces
                      if _in_poly(*r.centroid, poly) and (kind == "hallways") == (r.kind.value == "hallway"))
        used: set[int] = set()
        ok_doors = 0
        for gd in ann["doors"]:
            best = None
            for i, d in enumerate(seg.doors):
                dist = float(np.hypot(d.center[0] - gd["center"][0], d.center[1] - gd["center"][1]))
                if i not in used and dist <= BENCH_DOOR_TOL_M and (best is None or dist < best[0]):
                    best = (dist, i)
            if best:
                used.add(best[1])
                ok_doors += 1
        def pr(ok: int, n_pred: int, n_true: int) -> str:
            return f"precision {ok / max(n_pred, 1):.2f} recall {ok / max(n_true, 1):.2f} ({n_pred} found, {n_true} annotated)"
        print(f"  {env}: spaces {pr(ok_rooms, len(seg.rooms), len(spaces))}, kind right {kind_ok}/{len(seg.rooms)}")
        print(f"  {env}: doors  {pr(ok_doors, len(seg.doors), len(ann['doors']))}", flush=True)


def _time(fn: Callable[[], object], repeat: int) -> tuple[float, float]:
    """Median wall-clock and CPU seconds (CPU time is what the machine's load does not inflate)."""
    walls, cpus = [], []
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        fn()
        walls.append(time.perf_counter() - t0)
        cpus.append(time.process_time() - c0)
    return statistics.median(walls), statistics.median(cpus)


def bench_timing(quick: bool) -> None:
    print("(e) timing (median of runs, segmentation only; wall clock and CPU time)")
    env2 = load_map(BENCH / "env2.yaml")
    w, c = _time(lambda: segment_spaces(env2), 5 if quick else 11)
    print(f"  env2 {env2.width}x{env2.height}: {1000 * w:.0f} ms wall, {1000 * c:.0f} ms CPU  "
          f"(target: well under 100 ms)")
    aaf = load_map(AAF)
    w, c = _time(lambda: segment_spaces(aaf), 1 if quick else 3)
    print(f"  strands_aaf_y4_cropped {aaf.width}x{aaf.height}: {1000 * w:.0f} ms wall, {1000 * c:.0f} ms CPU"
          f"  (whole-analysis target 2 s)")
    peak_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"  peak resident memory of this process: {peak_mb:.0f} MB (target < 500 MB)", flush=True)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="a subset of the IPA maps, fewer timing runs")
    ap.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                    help="override an AnalysisParams field (tuning on the whole benchmark)")
    ap.add_argument("--only", choices=["env", "rose2", "ipa", "doors", "timing"], action="append",
                    help="run only these parts")
    args = ap.parse_args(argv)
    global PARAMS
    for item in args.set:
        name, _, value = item.partition("=")
        cur = getattr(PARAMS, name)
        PARAMS = dataclasses.replace(PARAMS, **{name: (value.lower() in ("1", "true")) if isinstance(cur, bool)
                                                else type(cur)(value)})
    if args.set:
        print("parameters:", ", ".join(args.set))
    logging.basicConfig(level=logging.WARNING)
    if not SHARED.is_dir():
        print(f"segmentation benchmark skipped: {SHARED} (the shared maps) is not on this machine")
        return 0
    parts = set(args.only or ["env", "rose2", "ipa", "doors", "timing"])
    if "env" in parts:
        bench_env()
    if "rose2" in parts:
        bench_rose2(args.quick)
    if "ipa" in parts:
        bench_ipa(args.quick)
    if "doors" in parts:
        bench_ipa_doors()
    if "timing" in parts:
        bench_timing(args.quick)
    return 0


if __name__ == "__main__":
    sys.exit(main())
