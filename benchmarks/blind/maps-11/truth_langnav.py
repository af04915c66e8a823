#!/work/main/.venv/bin/python
"""Stand-in for `langnav` that answers with the ground truth itself, so that eval_points.py /
score_points.py can be run truth-vs-truth (every figure must come out 1.00):

    /work/main/.venv/bin/python /work/shared/maps/eval_points.py ./truth_langnav.py maps

`truth_langnav.py analyze MAP.yaml --json OUT.json --labels OUT.npy` reads MAP.points.json beside the
yaml and writes: every door / passage centre (required and optional) as a detection, and a label
image where each annotated space (a group counts as one space) owns the mapped floor cells within
1.2 m of its point(s) that are nearer to it than to any other space's point."""
import json, sys
from pathlib import Path
import numpy as np, yaml
from PIL import Image
from scipy import ndimage

a = sys.argv[1:]
assert a[0] == "analyze"
y = Path(a[1]); js = a[a.index("--json") + 1]; npy = a[a.index("--labels") + 1]
meta = yaml.safe_load(y.read_text())
img = np.array(Image.open(y.parent / meta["image"]))
H, W = img.shape
res, (ox, oy) = float(meta["resolution"]), meta["origin"][:2]
ann = json.loads(y.with_name(y.stem + ".points.json").read_text())
keys, lab_of = [], []
for i, s in enumerate(ann["spaces"]):
    k = s.get("group") or f"#{i}"
    if k not in keys:
        keys.append(k)
    lab_of.append(keys.index(k) + 1)
seed = np.zeros((H, W), np.int32)
for s, L in zip(ann["spaces"], lab_of):
    x, yy = s["point"]
    seed[H - 1 - int((yy - oy) / res), int((x - ox) / res)] = L
dist, (ri, ci) = ndimage.distance_transform_edt(seed == 0, return_indices=True)
lab = np.where((dist * res <= 1.2) & (img > 250), seed[ri, ci], 0).astype(np.int32)
for s, L in zip(ann["spaces"], lab_of):          # the point's own cell always carries its label
    x, yy = s["point"]
    lab[H - 1 - int((yy - oy) / res), int((x - ox) / res)] = L
rooms = []
for k, L in zip(keys, range(1, len(keys) + 1)):
    rr, cc = np.nonzero(lab == L)
    kind = next(s["kind"] for s, l in zip(ann["spaces"], lab_of) if l == L)
    rooms.append({"label": L, "kind": kind,
                  "centroid": [ox + (cc.mean() + 0.5) * res, oy + (H - rr.mean() - 0.5) * res]})
out = {"rooms": rooms, "doors": [{"center": d["center"]} for d in ann["doors"]],
       "narrow_passages": [{"center": p["center"]} for p in ann["narrow_passages"]]}
Path(js).write_text(json.dumps(out))
np.save(npy, lab)
