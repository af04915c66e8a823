"""`langnav analyze MAP --png --svg` on every map in ../shared: none may fail.

  .venv/bin/python benchmarks/render_all.py [--out DIR] [--only SUBSTRING]

The maps: every map_server YAML under ../shared, the IPA benchmark's input maps (not their
ground-truth images) and ROSE²'s maps (also the incremental ones), as bare images. Prints one
line per map (cells, picture size, labels placed / left to the legend, seconds) and exits 1 if
any map failed. Runs the CLI in this process (one import, not one per map).
"""

from __future__ import annotations

import argparse
import contextlib
import io
import sys
import tempfile
import time
from pathlib import Path

from PIL import Image

from langnav.cli import main as langnav_main

SHARED = Path(__file__).resolve().parents[2] / "shared"
#: Images of the IPA and ROSE² folders that are ground truth or training labels, not maps.
NOT_MAPS = ("_gt_segmentation", "training", "voronoi", "/gt/", "/gt_annotated/", "rose2_output")


def maps(root: Path) -> list[Path]:
    """Every map under ``root``: YAMLs, and IPA / ROSE² input images."""
    found = sorted(root.rglob("*.yaml"))
    for folder in ("maps/ipa_room_segmentation", "maps/rose2_segmentation"):
        for p in sorted((root / folder).rglob("*")):
            if p.suffix.lower() in (".png", ".pgm") and not any(s in p.as_posix() for s in NOT_MAPS):
                found.append(p)
    return found


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", type=Path, default=None, help="keep the pictures in this folder")
    ap.add_argument("--only", default="", help="only maps whose path holds this")
    args = ap.parse_args()
    if not SHARED.is_dir():
        print(f"skipped: {SHARED} not present")
        return 0
    todo = [m for m in maps(SHARED) if args.only in m.as_posix()]
    failed: list[str] = []
    start = time.perf_counter()
    with tempfile.TemporaryDirectory() as tmp:
        out = args.out or Path(tmp)
        out.mkdir(parents=True, exist_ok=True)
        for m in todo:
            name = m.relative_to(SHARED).as_posix().replace("/", "__").rsplit(".", 1)[0]
            png, svg = out / f"{name}.png", out / f"{name}.svg"
            t0 = time.perf_counter()
            buf = io.StringIO()
            try:
                with contextlib.redirect_stdout(buf):
                    rc = langnav_main(["analyze", str(m), "--png", str(png), "--svg", str(svg)])
            except Exception as exc:  # a crash on any map is what this check reports
                rc = -1
                buf.write(f"{type(exc).__name__}: {exc}")
            dt = time.perf_counter() - t0
            if rc != 0 or not png.exists() or not svg.exists():
                failed.append(m.relative_to(SHARED).as_posix())
                print(f"FAILED {m.relative_to(SHARED)}: {buf.getvalue().strip()[-300:]}", flush=True)
                continue
            with Image.open(png) as im:
                size = im.size
            print(f"ok  {m.relative_to(SHARED)}: picture {size[0]}x{size[1]}, {dt:.1f} s", flush=True)
    print(f"{len(todo) - len(failed)} of {len(todo)} maps rendered (PNG and SVG) in {time.perf_counter() - start:.0f} s"
          + (f"; FAILED: {', '.join(failed)}" if failed else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
