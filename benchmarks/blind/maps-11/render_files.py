"""Draws a map's points.json over its PGM from the written files only (score_points.py's cell
convention), to check the ground truth independently of the generator's geometry."""
import json, sys
from pathlib import Path
import numpy as np, yaml
from PIL import Image, ImageDraw
y = Path(sys.argv[1]); out = sys.argv[2]
meta = yaml.safe_load(y.read_text())
img = np.array(Image.open(y.parent / meta["image"]))
H, W = img.shape
res, (ox, oy) = meta["resolution"], meta["origin"][:2]
s = max(1, round(res / 0.025))
ann = json.loads(y.with_name(y.stem + ".points.json").read_text())
rgb = Image.fromarray(np.stack([img] * 3, -1)).resize((W * s, H * s), Image.NEAREST)
d = ImageDraw.Draw(rgb)
def px(p):
    return ((p[0] - ox) / res * s, (H - (p[1] - oy) / res) * s)
for ig in ann["ignore"]:
    d.polygon([px(p) for p in ig["polygon"]], outline=(230, 180, 0))
for k, col in (("doors", (220, 0, 0)), ("narrow_passages", (200, 0, 200))):
    for e in ann[k]:
        x, yy = px(e["center"]); r = e["width_m"] / 2 / res * s
        d.ellipse([x - r, yy - r, x + r, yy + r], outline=col if not e["optional"] else (255, 150, 0), width=2)
for sp in ann["spaces"]:
    x, yy = px(sp["point"])
    d.ellipse([x - 6, yy - 6, x + 6, yy + 6], fill=(0, 90, 255) if sp["kind"] == "room" else (0, 170, 0))
rgb.save(out)
