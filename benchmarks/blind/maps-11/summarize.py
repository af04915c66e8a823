"""Counts per map (for README): summarize.py"""
import json
from pathlib import Path
rows = []; tot = [0] * 9
for p in sorted(Path("maps").glob("*.points.json")):
    a = json.loads(p.read_text())
    sp = a["spaces"]; d = a["doors"]; n = a["narrow_passages"]
    r = [len(sp), sum(s["kind"] == "hallway" for s in sp), sum(bool(s["group"]) for s in sp),
         sum(not x["optional"] for x in d), sum(x["optional"] for x in d),
         sum(not x["optional"] for x in n), sum(x["optional"] for x in n), len(a["ignore"])]
    rows.append((p.name[:-12], r))
    tot = [t + x for t, x in zip(tot, r + [0])]
print("| map | spaces (of them hallway, grouped) | doors required + optional | passages required + optional | ignore polygons |")
print("|---|---|---|---|---|")
for name, r in rows:
    print(f"| `{name}` | {r[0]} ({r[1]}, {r[2]}) | {r[3]} + {r[4]} | {r[5]} + {r[6]} | {r[7]} |")
print(f"| total ({len(rows)} maps) | {tot[0]} ({tot[1]}, {tot[2]}) | {tot[3]} + {tot[4]} | {tot[5]} + {tot[6]} | {tot[7]} |")
