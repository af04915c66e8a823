#!/usr/bin/env python3
"""Self-check: an output built from each spoken case's first alternative must score 1.0."""
import json
from pathlib import Path
HERE = Path(__file__).parent
out = []
for l in (HERE / "spoken.jsonl").read_text().splitlines():
    c = json.loads(l)
    e = c["expect"]
    alt = e["any"][0] if isinstance(e, dict) else e
    if alt == "clarify":
        out.append({"id": c["id"], "commands": [], "clarification": "Which way / how far?"})
        continue
    cmds = []
    for x in alt:
        if x["command"] in ("Move", "Rotate"):
            d = x["direction"] if x["direction"] != "any" else "right"
            cmds.append({"command": x["command"], "direction": d, "repeat": (x["repeat"][0] + x["repeat"][1]) // 2})
        else:
            cmds.append({"command": x["command"]})
    out.append({"id": c["id"], "commands": cmds, "clarification": None})
(HERE / "out").mkdir(exist_ok=True)
(HERE / "out" / "spoken.oracle.jsonl").write_text("".join(json.dumps(o) + "\n" for o in out))
