#!/usr/bin/env python3
"""Prints the mix of both case files (the counts quoted in README.md)."""
import json
from collections import Counter
from pathlib import Path
HERE = Path(__file__).parent


def alts(e):
    return e["any"] if isinstance(e, dict) else [e]


for f in ("spoken.jsonl", "buildings.jsonl"):
    cs = [json.loads(l) for l in open(HERE / f)]
    c = Counter()
    for k in cs:
        a = alts(k["expect"])
        first = a[0]
        if first == "clarify" and len(a) == 1:
            c["clarify"] += 1
        elif "clarify" in a:
            c["clarify or safe part"] += 1
        else:
            c["one command" if len(first) == 1 else "several commands"] += 1
        if len(a) > 1 and "clarify" not in a:
            c["with alternatives"] += 1
        names = {x["command"] for alt in a if alt != "clarify" for x in alt}
        for n in names:
            c["with " + n] += 1
    n = len(cs)
    print(f, n, "cases;", ", ".join(f"{k} {v}" for k, v in sorted(c.items())),
          f"; clarify share {c['clarify'] / n:.3f} (with clarify-or-safe {(c['clarify'] + c['clarify or safe part']) / n:.3f})")
