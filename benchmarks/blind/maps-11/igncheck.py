import json, sys, math
from pathlib import Path
sys.path.insert(0, "/work/shared/maps")
from score_points import inside
def segd(p, a, b):
    ax, ay = a; bx, by = b; px, py = p
    L2 = (bx-ax)**2 + (by-ay)**2
    t = max(0, min(1, ((px-ax)*(bx-ax)+(py-ay)*(by-ay))/L2)) if L2 else 0
    return math.hypot(px-ax-t*(bx-ax), py-ay-t*(by-ay))
for p in sorted(Path(sys.argv[1]).glob("*.points.json")):
    a = json.loads(p.read_text())
    for kind, key in (("doors", "center"), ("narrow_passages", "center"), ("spaces", "point")):
        for d in a[kind]:
            c = d[key]
            for ig in a["ignore"]:
                poly = ig["polygon"]
                dist = min(segd(c, poly[i], poly[(i+1) % len(poly)]) for i in range(len(poly)))
                if inside(poly, c) or dist < 0.75:
                    print(p.name, kind, d["note"], "inside" if inside(poly, c) else f"{dist:.2f} from", "ignore", d.get("optional"))
