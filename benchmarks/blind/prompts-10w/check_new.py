#!/usr/bin/env python3
"""Self-check: no prompt (lower case, punctuation removed) equals a prompt of the bench dev set, the SCOUT
dev set or any earlier blind / dev round (/work/main/benchmarks/blind/prompts*/*.jsonl), and no prompt
repeats within this set.  Adapted from prompts-9's check_new.py (spoken only; no drawn maps here)."""
import glob, json, re
from pathlib import Path
HERE = Path(__file__).parent
norm = lambda s: " ".join(re.sub(r"[^\w\s]", " ", s.lower()).split())
files = ["/work/shared/bench/scout/cases_dev.jsonl", "/work/shared/bench/prompts_dev.jsonl"] + \
        sorted(glob.glob("/work/main/benchmarks/blind/prompts*/*.jsonl"))
other = set()
for f in files:
    other |= {norm(json.loads(l)["prompt"]) for l in open(f) if l.strip()}
print(len(files), "files,", len(other), "earlier prompts compared")
mine = [json.loads(l)["prompt"] for l in open(HERE / "spoken.jsonl") if l.strip()]
clash = [m for m in mine if norm(m) in other]
assert not clash, clash
seen = set()
for m in mine:
    assert norm(m) not in seen, ("repeated within this set", m)
    seen.add(norm(m))
print(len(mine), "prompts new")
