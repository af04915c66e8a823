"""Zoomed crop of a render with a 1 m world grid: crop.py NAME X Y HALF [OUT]  (world coords, metres)."""
import sys, yaml
from pathlib import Path
from PIL import Image, ImageDraw
name, x, y, half = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
out = sys.argv[5] if len(sys.argv) > 5 else f"/tmp/crop_{name}.png"
here = Path(__file__).parent
meta = yaml.safe_load((here / "maps" / f"{name}.yaml").read_text())
img = Image.open(here / "render" / f"{name}.png").convert("RGB")
res = meta["resolution"]; s = max(1, round(res / 0.025)); ox, oy = meta["origin"][:2]
H = img.size[1] // s
def px(X, Y):
    return ((X - ox) / res * s, (H - (Y - oy) / res) * s)
d = ImageDraw.Draw(img)
import math
for gx in range(math.floor(x - half), math.ceil(x + half) + 1):
    a = px(gx, y - half); b = px(gx, y + half)
    d.line([a, b], fill=(120, 200, 255), width=1); d.text((a[0] + 2, b[1] + 2), str(gx), fill=(0, 0, 160))
for gy in range(math.floor(y - half), math.ceil(y + half) + 1):
    a = px(x - half, gy); b = px(x + half, gy)
    d.line([a, b], fill=(120, 200, 255), width=1); d.text((a[0] + 2, a[1] + 2), str(gy), fill=(0, 0, 160))
c0 = px(x - half, y + half); c1 = px(x + half, y - half)
img = img.crop((int(c0[0]), int(c0[1]), int(c1[0]), int(c1[1])))
k = max(1, int(900 / img.size[0]))
img.resize((img.size[0] * k, img.size[1] * k), Image.NEAREST).save(out)
print(out)
