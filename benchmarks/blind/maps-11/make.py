"""Regenerate: /work/main/.venv/bin/python make.py [--reuse] [NAME ...]
--reuse: skip the lidar simulation and re-check/re-annotate the cached grid (cache/NAME.npz)."""
import sys, time
from pathlib import Path
import numpy as np
import buildings
args = sys.argv[1:]
reuse = "--reuse" in args
names = [a for a in args if not a.startswith("--")]
Path("cache").mkdir(exist_ok=True)
for f in buildings.BUILDINGS:
    if names and f.__name__ not in names:
        continue
    t = time.time()
    b = f()
    c = Path("cache") / f"{b.name}.npz"
    if reuse and c.exists():
        z = np.load(c)
        b.grid, b.ox, b.oy = z["grid"], float(z["ox"]), float(z["oy"])
        b.H, b.W = b.grid.shape
        b.poses, b.route_warn = list(z["poses"]), []
    else:
        b.simulate()
        np.savez_compressed(c, grid=b.grid, ox=b.ox, oy=b.oy, poses=np.array(b.poses))
    log = b.finalize(".")
    o = b.out
    print(f"== {b.name}: {b.W}x{b.H} scans {len(b.poses)} spaces {len(o['spaces'])} doors {len(o['doors'])} "
          f"(opt {sum(d['optional'] for d in o['doors'])}) passages {len(o['narrow_passages'])} ignore {len(o['ignore'])} "
          f"{time.time()-t:.0f}s")
    if b.route_warn:
        print("    ROUTE COLLIDES near", b.route_warn[:8], len(b.route_warn))
    for l in log:
        print("   ", l)
