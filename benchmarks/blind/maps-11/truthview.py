"""Quick look at a building's truth raster (building frame) with routes, spaces, doors: truthview.py NAME OUT.png"""
import sys, math
import numpy as np
from PIL import Image, ImageDraw
import buildings
f = getattr(buildings, sys.argv[1]); b = f()
s = 5  # downsample truth raster (0.02 m) by s -> 0.1 m px
cls = b.cls[::-1][::s, ::s]
img = np.full(cls.shape + (3,), 255, np.uint8); img[cls == 1] = 0; img[cls == 2] = (0, 160, 255)
im = Image.fromarray(img).resize((cls.shape[1] * 2, cls.shape[0] * 2), Image.NEAREST)
d = ImageDraw.Draw(im)
H = b.TH
def px(u, v):
    return ((u - b.tu0) / (0.02 * s) * 2, (H - (v - b.tv0) / 0.02) / s * 2)
for pts in b.routes:
    d.line([px(*p) for p in pts], fill=(0, 200, 0), width=1)
for sp in b.spaces:
    x, y = px(*sp["point"]); d.ellipse([x - 5, y - 5, x + 5, y + 5], fill=(0, 0, 255))
for dd in b.doors:
    x, y = px(*dd["center"]); d.ellipse([x - 4, y - 4, x + 4, y + 4], outline=(255, 0, 0), width=2)
for p in b.passages:
    x, y = px(*p["center"]); d.ellipse([x - 4, y - 4, x + 4, y + 4], outline=(200, 0, 200), width=2)
m = int(b.m / 0.1 * 2) - 30
im = im.crop((m, m, im.size[0] - m, im.size[1] - m))
im.save(sys.argv[2])
