#!/usr/bin/env python3
"""Six deliberately wrong outputs, one case changed in each, must each score below 1.0 (score.py)."""
import json, subprocess, sys
from pathlib import Path
HERE = Path(__file__).parent
PY = sys.executable
cases = {json.loads(l)["prompt"]: json.loads(l)["id"] for l in open(HERE / "spoken.jsonl")}
oracle = [json.loads(l) for l in open(HERE / "out" / "spoken.oracle.jsonl")]
R = lambda d, n: {"command": "Rotate", "direction": d, "repeat": n}
M = lambda d, n: {"command": "Move", "direction": d, "repeat": n}
WRONG = [  # (prompt, wrong commands, clarification, what is wrong)
    ("ek minute, turn left, nahi nahi, right side forty five", [R("left", 4)], None, "correction ignored"),
    ("chalo, go to the dispensary counter", [M("forward", 33)], None, "unknown place driven to"),
    ("forward three feet. THREE. not thirty", [M("forward", 100)], None, "feet read as metres"),
    ("turn to your ten o'clock", [R("right", 6)], None, "clock read the wrong way"),
    ("step twelve, drive forward five hundred millimetres", [M("forward", 16666)], None, "mm read as m"),
    ("go forward to meters", [], "How far?", "homophone 'to' not read as two"),
]
bad = 0
for prompt, cmds, clar, why in WRONG:
    cid = cases[prompt]
    out = [dict(o) for o in oracle]
    for o in out:
        if o["id"] == cid:
            o["commands"], o["clarification"] = cmds, clar
    p = HERE / "out" / "negative.jsonl"
    p.write_text("".join(json.dumps(o) + "\n" for o in out))
    res = json.loads(subprocess.run([PY, "/work/shared/bench/score.py", str(HERE / "spoken.jsonl"), str(p), "--json"],
                                    capture_output=True, text=True, check=True).stdout)
    acc = res["prompt_accuracy"]
    print(f"{acc:.4f}  {cid}  {why}")
    bad += acc < 1.0
p.unlink()
assert bad == len(WRONG), bad
print(bad, "of", len(WRONG), "wrong outputs score below 1.0")
