#!/usr/bin/env python3
"""The referee can fail: six deliberately wrong outputs, built from the oracle outputs, must each score a prompt
accuracy below 1.0 with score.py (new in this set)."""
import copy, json, sys
from pathlib import Path
sys.path.insert(0, "/work/shared/bench")
from score import score
HERE = Path(__file__).parent
OUT = HERE / "out"


def load(name):
    return [json.loads(l) for l in open(OUT / f"{name}.oracle.jsonl")]


def flip_rotates(o):
    for c in o["commands"]:
        if c["command"] == "Rotate":
            c["direction"] = {"left": "right", "right": "left"}[c["direction"]]
    return o


def double_moves(o):
    for c in o["commands"]:
        if c["command"] == "Move":
            c["repeat"] = 2 * int(c["repeat"]) + 5
    return o


def always_ask(o):
    return {"id": o["id"], "commands": [], "clarification": "Could you say that again?"}


def ntp_to_start(o, pose):
    for c in o["commands"]:
        if c["command"] == "NavigateThroughPoses":
            c["poses"] = [[pose[0], pose[1]]]
    return o


def act_instead_of_asking(o):
    if not o["commands"]:
        o["commands"] = [{"command": "Rotate", "direction": "left", "repeat": 9}]
        o["clarification"] = None
    return o




cases = {f: {json.loads(l)["id"]: json.loads(l) for l in open(HERE / f"{f}.jsonl")} for f in ("spoken", "buildings")}
tests = [
    ("spoken", "every Rotate the other way", lambda o: flip_rotates(o)),
    ("spoken", "every Move twice as far", lambda o: double_moves(o)),
    ("spoken", "always asks", lambda o: always_ask(o)),
    ("buildings", "every NavigateThroughPoses ends at the start", lambda o: ntp_to_start(o, cases["buildings"][o["id"]]["pose"])),
    ("buildings", "acts where it should ask", lambda o: act_instead_of_asking(o)),
    ("buildings", "always asks", lambda o: always_ask(o)),
]
tmp = OUT / "wrong.jsonl"
for f, what, fn in tests:
    outs = [fn(copy.deepcopy(o)) for o in load(f)]
    tmp.write_text("".join(json.dumps(o) + "\n" for o in outs))
    s, _ = score(HERE / f"{f}.jsonl", tmp)
    assert s["prompt_accuracy"] < 1.0, (f, what, s)
    print(f"wrong output scored below 1.0 as it should: {f:9s} {what:45s} prompt_accuracy {s['prompt_accuracy']}")
tmp.unlink()
