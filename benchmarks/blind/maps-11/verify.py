"""Independent check of the written files: reads YAML + PGM + points.json the way score_points.py
does and reports where each annotated element falls on the map (cell value, nearest occupied)."""
import json, sys
from pathlib import Path
import numpy as np, yaml
from PIL import Image
folder = Path(sys.argv[1])
for y in sorted(folder.glob("*.yaml")):
    meta = yaml.safe_load(y.read_text())
    img = np.array(Image.open(folder / meta["image"]))
    vals = set(np.unique(img).tolist())
    H, W = img.shape
    res, (ox, oy) = meta["resolution"], meta["origin"][:2]
    ann = json.loads((folder / (y.stem + ".points.json")).read_text())
    def cell(p):
        return H - 1 - int((p[1] - oy) / res), int((p[0] - ox) / res)
    def near_occ(p, rad=0.6):
        r, c = cell(p); k = int(rad / res)
        win = img[max(r-k,0):r+k+1, max(c-k,0):c+k+1]
        rr, cc = np.nonzero(win == 0)
        return float(np.hypot(rr - min(k, r), cc - min(k, c)).min()) * res if rr.size else 9
    bad = []
    for s in ann["spaces"]:
        r, c = cell(s["point"])
        if img[r, c] != 254 or near_occ(s["point"]) < 0.3:
            bad.append(("space", s["note"], int(img[r, c]), near_occ(s["point"])))
    for d in ann["doors"] + ann["narrow_passages"]:
        r, c = cell(d["center"])
        if img[r, c] == 0:
            bad.append(("door/passage on occupied", d["note"]))
    print(y.stem, W, "x", H, "values", sorted(vals), "spaces", len(ann["spaces"]), "doors", len(ann["doors"]),
          "passages", len(ann["narrow_passages"]), "BAD:" if bad else "ok", bad or "")
