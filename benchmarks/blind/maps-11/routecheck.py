import sys, math
import buildings
from sim import TR
for f in buildings.BUILDINGS:
    if sys.argv[1:] and f.__name__ not in sys.argv[1:]:
        continue
    b = f()
    bad = []
    for pts in b.routes:
        for (a0, b0), (a1, b1) in zip(pts, pts[1:]):
            L = math.hypot(a1 - a0, b1 - b0); n = max(int(L / 0.05), 1)
            for i in range(n + 1):
                u, v = a0 + (a1 - a0) * i / n, b0 + (b1 - b0) * i / n
                r0, c0 = int((v - b.tv0) / TR), int((u - b.tu0) / TR); k = int(0.17 / TR)
                if b.cls[r0 - k:r0 + k + 1, c0 - k:c0 + k + 1].any():
                    bad.append((round(u, 2), round(v, 2)))
    # collapse
    out = []
    for p in bad:
        if not out or math.dist(out[-1][-1], p) > 0.2:
            out.append([p, p])
        else:
            out[-1][-1] = p
    print(b.name, "route collisions:", [(o[0], o[1]) for o in out])
