#!/usr/bin/env python3
"""Extra self-checks: (1) no prompt (lower case, punctuation removed) equals a prompt of the bench dev
set, the SCOUT dev set or any earlier blind set (benchmarks/blind/*/ *.jsonl, /work/blind5-prompts/*.jsonl,
/work/blind6-prompts/*.jsonl, /work/blind7-prompts/*.jsonl, /work/blind8-prompts/*.jsonl), and no prompt text repeats within this set (any map, any pose); (2) per drawn
map: the unknown regions that border free space (>= 20 cells = 0.05 m2 are areas, smaller are noise) and
that the valid floor is one component.  Adapted for this set: compares with every /work/main/benchmarks/blind/prompts*/ set and any other /work/blind*-prompts/ folder; the three new maps."""
import glob, json, re, sys
from pathlib import Path
import numpy as np
from scipy import ndimage
sys.path.insert(0, "/work/shared/bench")
from score import Map
HERE = Path(__file__).parent
norm = lambda s: " ".join(re.sub(r"[^\w\s]", " ", s.lower()).split())
other = set()
files = ["/work/shared/bench/scout/cases_dev.jsonl", "/work/shared/bench/prompts_dev.jsonl"] + \
        sorted(glob.glob("/work/main/benchmarks/blind/prompts*/*.jsonl")) + \
        sorted(f for f in glob.glob("/work/blind*-prompts/*.jsonl") if not f.startswith(str(HERE.resolve())))
for f in files:
    other |= {norm(json.loads(l)["prompt"]) for l in open(f) if l.strip()}
print(len(files), "files,", len(other), "earlier prompts compared")
mine = [json.loads(l)["prompt"] for f in ("spoken.jsonl", "buildings.jsonl") for l in open(HERE / f)]
clash = [m for m in mine if norm(m) in other]
assert not clash, clash
seen = {}
for m in mine:
    assert norm(m) not in seen, ("repeated within this set", m)
    seen[norm(m)] = 1
for n in ("brewery", "cinema", "garden"):
    m = Map((HERE / "maps" / f"{n}.yaml").resolve())
    unk, free = m.grid == 205, m.grid == 254
    lab, k = ndimage.label(unk, structure=np.ones((3, 3)))
    touch = ndimage.binary_dilation(free, np.ones((3, 3), bool))
    sizes = [int((lab == i).sum()) for i in range(1, k + 1) if (touch & (lab == i)).any()]
    big = [s for s in sizes if s >= 20]
    assert m.labels.max() == 1, (n, m.labels.max())
    print(f"{n}: unexplored areas (cells) {big}; noise specks {len(sizes) - len(big)} "
          f"(max {max([s for s in sizes if s < 20], default=0)} cells)")
print(len(mine), "prompts new")
