"""``langnav analyze MAP``: find every element of a map; write JSON, a picture, the room labels.

MAP is a map_server YAML, a bare image (with ``--resolution``), or the word ``demo`` for the
bundled demo world.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import time
from collections.abc import Iterator
from pathlib import Path

import numpy as np

from langnav.analysis.elements import ElementKind, MapAnalysis
from langnav.analysis.pipeline import analyze
from langnav.analysis.render import save_png, save_svg
from langnav.errors import LangnavError
from langnav.maps.demo import DEMO_NAME, demo_map_path
from langnav.maps.io import load_map


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("map", metavar="MAP",
                        help=f"map_server .yaml, a bare map image, or '{DEMO_NAME}' for the bundled demo world")
    parser.add_argument("--resolution", type=float, default=None, metavar="R",
                        help="metres per cell for a bare image (default 0.05; a YAML gives its own)")
    parser.add_argument("--unknown-grey", action="store_true",
                        help="read the map image's grey 205 as unknown even where the YAML's thresholds "
                             "read it as free or occupied (a warning says when they do)")
    parser.add_argument("--json", type=Path, default=None, metavar="OUT", help="write the elements as JSON")
    parser.add_argument("--png", type=Path, default=None, metavar="OUT",
                        help="write the map with every element drawn and labelled (PNG)")
    parser.add_argument("--svg", type=Path, default=None, metavar="OUT",
                        help="write the same picture as a zoomable SVG (the way to read a large map)")
    parser.add_argument("--labels", type=Path, default=None, metavar="OUT.npy",
                        help="write int32 room labels in image orientation (row 0 = top; 0 = no room)")


def resolve_map_path(name: str) -> Path:
    """The map file for a CLI argument: ``demo`` is the bundled world, anything else a path."""
    return demo_map_path() if name == DEMO_NAME else Path(name)


def summary(a: MapAnalysis, seconds: float) -> str:
    g = a.grid
    rooms = sum(1 for r in a.rooms if r.kind == ElementKind.ROOM)
    halls = sum(1 for r in a.rooms if r.kind == ElementKind.HALLWAY)
    interior = sum(1 for u in a.unexplored if u.interior)
    return "\n".join([
        f"{g.source}: {g.width}x{g.height} cells at {g.resolution_m:g} m, analysed in {seconds * 1000:.0f} ms",
        f"  {rooms} rooms, {halls} hallways, {len(a.doors)} doors, {len(a.walls)} walls, "
        f"{len(a.corners)} corners",
        f"  {len(a.obstacles)} obstacles, {len(a.narrow_passages)} narrow passages, "
        f"{len(a.unexplored)} unexplored areas ({interior} inside the map)",
    ])


def run(args: argparse.Namespace) -> int:
    grid = load_map(resolve_map_path(args.map), resolution_m=args.resolution, unknown_grey=args.unknown_grey)
    t0 = time.perf_counter()
    result = analyze(grid)
    seconds = time.perf_counter() - t0
    print(summary(result, seconds))
    if args.json is not None:
        with _writing(args.json, "--json"):
            args.json.parent.mkdir(parents=True, exist_ok=True)
            args.json.write_text(json.dumps(result.to_json(), indent=1), encoding="utf-8")
        print(f"  wrote {args.json}")
    if args.png is not None:
        with _writing(args.png, "--png"):
            written = save_png(result, args.png)
        print(f"  wrote {written}")
    if args.svg is not None:
        with _writing(args.svg, "--svg"):
            written = save_svg(result, args.svg)
        print(f"  wrote {written}")
    if args.labels is not None:
        with _writing(args.labels, "--labels"):
            args.labels.parent.mkdir(parents=True, exist_ok=True)
            np.save(args.labels, result.labels_image().astype(np.int32))
        print(f"  wrote {args.labels}")
    return 0


@contextlib.contextmanager
def _writing(path: Path, option: str) -> Iterator[None]:
    """An output file that cannot be written becomes an error naming the option, file and reason."""
    try:
        yield
    except (OSError, ValueError) as exc:
        reason = getattr(exc, "strerror", None) or str(exc)
        raise LangnavError(f"{option} {path}: cannot write it ({reason}); pick a writable file path") from exc
