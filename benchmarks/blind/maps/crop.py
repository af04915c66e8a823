import sys, importlib.util
from pathlib import Path
spec = importlib.util.spec_from_file_location("mu", str(Path(__file__).with_name("make_unseen.py")))
mu = importlib.util.module_from_spec(spec); sys.modules["mu"] = mu; spec.loader.exec_module(mu)
from PIL import Image
name, u, v, half = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
scale = 2
img = Image.open(Path(__file__).with_name("render") / f"{name}.png")
b = [f for f in mu.BUILDINGS if f.__name__ in name][0]()
r, c = b.to_cell((u, v))
k = int(half / mu.RES)
box = ((c - k) * scale, (r - k) * scale, (c + k) * scale, (r + k) * scale)
img.crop(box).resize(((2 * k) * scale * 2, (2 * k) * scale * 2), Image.NEAREST).save(f"/tmp/crop_{name}.png")
