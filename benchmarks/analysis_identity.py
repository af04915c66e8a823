"""Identity check for speed work: dump the full analysis of many maps, then compare two dumps.

A speed change must not change what the analysis finds. ``dump`` writes, for each map, every
element of ``analyze()`` field by field (floats exactly, as ``repr``; arrays as shape, dtype and a
hash of their bytes, so a polygon or a label image that moved by one cell shows), the wide
openings and the label image. ``compare`` prints every map and field where two dumps differ and
exits 1 if any do.

    PYTHONPATH=/path/to/old/src python benchmarks/analysis_identity.py dump /tmp/before
    PYTHONPATH=src python benchmarks/analysis_identity.py dump /tmp/after
    python benchmarks/analysis_identity.py compare /tmp/before /tmp/after

Maps: the bench maps (env1, env2), the real ROS maps, the committed blind map rounds, the round-5
dev maps when present, and a few IPA maps (read as the IPA authors read them). Missing folders are
skipped with a note.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import sys
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
from PIL import Image

from langnav.analysis.pipeline import analyze
from langnav.maps.grid import FREE, OCCUPIED, OccupancyGrid
from langnav.maps.io import load_map

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared"
YAML_DIRS = (
    SHARED / "maps" / "ros",
    ROOT / "benchmarks" / "blind" / "maps" / "maps",
    ROOT / "benchmarks" / "blind" / "maps-3" / "maps",
    ROOT / "benchmarks" / "blind" / "maps-4" / "maps",
    ROOT / "benchmarks" / "blind" / "maps-5" / "maps",
    ROOT / "benchmarks" / "blind" / "maps-6" / "maps",
    ROOT / "benchmarks" / "blind" / "maps-7" / "maps",
    ROOT / "benchmarks" / "blind" / "maps-8" / "maps",
    ROOT / "benchmarks" / "blind" / "maps-10" / "maps",
    ROOT / "benchmarks" / "blind" / "maps-11" / "maps",
    ROOT.parent / "blind5-maps-dev",
)
BENCH_MAPS = ("env1", "env2")
IPA = SHARED / "maps" / "ipa_room_segmentation" / "test_maps"
#: A few IPA maps of different kinds (scan, furnished office, large lab).
IPA_MAPS = ("lab_ipa", "office_e", "Freiburg52_scan", "NLB", "lab_c_scan")
IPA_RESOLUTION_M = 0.05
#: The IPA authors read pixels >= 250 as free, everything else as occupied.
IPA_FREE_MIN = 250


def _ipa_grid(path: Path) -> OccupancyGrid:
    with Image.open(path) as im:
        img = np.asarray(im.convert("L"))
    cells = np.where(img >= IPA_FREE_MIN, FREE, OCCUPIED).astype(np.int8)
    return OccupancyGrid(np.flipud(cells).copy(), IPA_RESOLUTION_M, source=str(path))


def maps() -> Iterator[tuple[str, OccupancyGrid]]:
    for name in BENCH_MAPS:
        path = SHARED / "bench" / "maps" / f"{name}.yaml"
        if path.exists():
            yield name, load_map(path)
        else:
            print(f"note: {path} missing", file=sys.stderr)
    for folder in YAML_DIRS:
        if not folder.is_dir():
            print(f"note: {folder} missing", file=sys.stderr)
            continue
        for path in sorted(folder.glob("*.yaml")):
            label = folder.parent.name if folder.name == "maps" else folder.name
            yield f"{label}/{path.stem}", load_map(path)
    for name in IPA_MAPS:
        path = IPA / f"{name}.png"
        if path.exists():
            yield f"ipa/{name}", _ipa_grid(path)
        else:
            print(f"note: {path} missing", file=sys.stderr)


def canonical(obj: Any) -> Any:
    """A JSON value equal for two objects exactly when their contents are equal."""
    if isinstance(obj, np.ndarray):
        arr = np.ascontiguousarray(obj)
        return {"shape": list(arr.shape), "dtype": str(arr.dtype),
                "sha1": hashlib.sha1(arr.tobytes(), usedforsecurity=False).hexdigest()}
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        return {"type": type(obj).__name__,
                **{f.name: canonical(getattr(obj, f.name)) for f in dataclasses.fields(obj)
                   if f.name not in ("grid", "params")}}
    if isinstance(obj, (list, tuple)):
        return [canonical(v) for v in obj]
    if isinstance(obj, dict):
        return {str(k): canonical(v) for k, v in obj.items()}
    if isinstance(obj, (float, np.floating)):
        return repr(float(obj))
    if isinstance(obj, (bool, np.bool_)):
        return bool(obj)
    if isinstance(obj, (int, np.integer)):
        return int(obj)
    return str(obj)


def dump(out: Path) -> int:
    out.mkdir(parents=True, exist_ok=True)
    total = 0.0
    for name, grid in maps():
        t0 = time.perf_counter()
        result = analyze(grid)
        dt = time.perf_counter() - t0
        total += dt
        (out / (name.replace("/", "__") + ".json")).write_text(json.dumps(canonical(result), indent=0))
        print(f"{name:50s} {dt * 1000:8.0f} ms  {len(result.elements)} elements")
    print(f"total {total:.1f} s")
    return 0


def _diff(a: Any, b: Any, where: str, out: list[str]) -> None:
    if type(a) is not type(b):
        out.append(f"{where}: {a!r} != {b!r}")
    elif isinstance(a, dict):
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                out.append(f"{where}.{k}: only in {'after' if k in b else 'before'}")
            else:
                _diff(a[k], b[k], f"{where}.{k}", out)
    elif isinstance(a, list):
        if len(a) != len(b):
            out.append(f"{where}: {len(a)} items != {len(b)} items")
        for i, (x, y) in enumerate(zip(a, b, strict=False)):
            _diff(x, y, f"{where}[{i}]", out)
    elif a != b:
        out.append(f"{where}: {a!r} != {b!r}")


def compare(before: Path, after: Path) -> int:
    names = sorted({p.name for p in before.glob("*.json")} | {p.name for p in after.glob("*.json")})
    bad = 0
    for name in names:
        pa, pb = before / name, after / name
        if not pa.exists() or not pb.exists():
            print(f"{name}: only in {'after' if pb.exists() else 'before'}")
            bad += 1
            continue
        diffs: list[str] = []
        _diff(json.loads(pa.read_text()), json.loads(pb.read_text()), name[:-5], diffs)
        if diffs:
            bad += 1
            print(f"{name[:-5]}: {len(diffs)} differences")
            for d in diffs[:10]:
                print(f"  {d}")
    print(f"{len(names)} maps compared, {bad} differ")
    return 1 if bad else 0


def main(argv: list[str]) -> int:
    if len(argv) == 2 and argv[0] == "dump":
        return dump(Path(argv[1]))
    if len(argv) == 3 and argv[0] == "compare":
        return compare(Path(argv[1]), Path(argv[2]))
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
