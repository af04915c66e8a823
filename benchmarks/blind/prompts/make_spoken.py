#!/usr/bin/env python3
"""Writes spoken.jsonl: hand-written spoken motion prompts on the SCOUT arena map.

Each case is (speaker, prompt, parts). A part is a tuple:
  ("F"|"B", metres)            move forward / backward
  ("L"|"R", metres)            sideways move (alternatives: sideways Move, or 90 deg Rotate + Move forward)
  ("l"|"r", degrees)           rotate left / right
  ("a", degrees)               180 or 360: either way
  ("face", heading_deg)        compass: shorter rotation from the current heading
  ("bitF",), ("bitl",), ("bitr",)  "a little": 0.15-0.5 m / 10-40 deg
  ("stop",)
  "clarify"                    run nothing, explain / ask
  ("alt", [parts...], [parts...] | "clarify")   several right answers
Photo parts are simply not written (dropped), per the contract.
Repeat ranges follow scout/README.md: exact steps +/-7 %, at least +/-1 step and at least
+/-0.5 step per part summed into one command, never below 1.
"""
import itertools
import json
import math
from pathlib import Path

FT, IN, YD = 0.3048, 0.0254, 0.9144
STEP_M, STEP_DEG = 0.03, 10.0
YAWS = [0, 90, 180, 270, 30, 120, 210, 300, 60, 150, 240, 330]
N, NE, E, SE, S, SW, W, NW = 90, 45, 0, 315, 270, 225, 180, 135

CASES = [
    # ---- speaker A: terse, radio style (like the SCOUT commanders)
    ("A", "move forward five feet", [("F", 5 * FT)]),
    ("A", "turn left ninety", [("l", 90)]),
    ("A", "face north-east", [("face", NE)]),
    ("A", "go west ten feet", [("face", W), ("F", 10 * FT)]),
    ("A", "back up two feet", [("B", 2 * FT)]),
    ("A", "stop", [("stop",)]),
    ("A", "turn around", [("a", 180)]),
    ("A", "rotate one eighty", [("a", 180)]),
    ("A", "move forward, three feet", [("F", 3 * FT)]),
    ("A", "turn right, forty-five degrees", [("r", 45)]),
    ("A", "face south, take a picture", [("face", S)]),
    ("A", "take a picture", "clarify"),
    ("A", "go north fifteen feet", [("face", N), ("F", 15 * FT)]),
    ("A", "turn counter-clockwise thirty degrees", [("l", 30)]),
    ("A", "spin three sixty", [("a", 360)]),
    # ---- speaker B: hesitant, fillers, cut-off words
    ("B", "um, move, uh, forward... four feet", [("F", 4 * FT)]),
    ("B", "uh turn, like, to your right, um ninety degrees", [("r", 90)]),
    ("B", "okay um go forward uh six more feet", [("F", 6 * FT)]),
    ("B", "um, can you uh turn left like forty five degrees", [("l", 45)]),
    ("B", "turn nin- ninety degrees left", [("l", 90)]),
    ("B", "uh move for- forward two meters", [("F", 2.0)]),
    ("B", "so, um, face, uh, east", [("face", E)]),
    ("B", "uh, another two feet forward", [("F", 2 * FT)]),
    ("B", "um turn rig- right a hundred and twenty degrees", [("r", 120)]),
    ("B", "uh, stop, stop", [("stop",)]),
    ("B", "uh, rotate, um, one hundred eighty degrees", [("a", 180)]),
    ("B", "um go about, uh, a foot and a half forward", [("F", 1.5 * FT)]),
    ("B", "uh, turn like thirty degrees, um, to the left", [("l", 30)]),
    ("B", "okay uh move back, um, like three feet", [("B", 3 * FT)]),
    ("B", "er, face north, um, and uh take a photo", [("face", N)]),
    # ---- speaker C: chatty, polite, questions
    ("C", "Hey robot, could you please move forward about ten feet for me?", [("F", 10 * FT)]),
    ("C", "Can you turn to your left ninety degrees please?", [("l", 90)]),
    ("C", "Could you please face west and then snap a picture for me?", [("face", W)]),
    ("C", "Alright, can you go ahead and turn around for me?", [("a", 180)]),
    ("C", "Okay great, now could you move forward another eight feet?", [("F", 8 * FT)]),
    ("C", "Can you please rotate clockwise about sixty degrees?", [("r", 60)]),
    ("C", "If you could, move two yards forward, thanks!", [("F", 2 * YD)]),
    ("C", "Would you please take a picture of what's in front of you?", "clarify"),
    ("C", "Great job! Now please go east twelve feet.", [("face", E), ("F", 12 * FT)]),
    ("C", "Can you tell me what you see?", "clarify"),
    ("C", "Hmm, could you turn right fifteen degrees, then go forward three feet?", [("r", 15), ("F", 3 * FT)]),
    ("C", "Please move forward five feet, and then turn left forty-five degrees, thanks", [("F", 5 * FT), ("l", 45)]),
    ("C", "Okay could you stop right there please", [("stop",)]),
    ("C", "Can you do a full circle for me and take pictures as you go?", [("a", 360)]),
    ("C", "Would you be able to move about a foot forward?", [("F", 1 * FT)]),
    # ---- speaker D: non-native speaker
    ("D", "robot go front three meter", [("F", 3.0)]),
    ("D", "please you turn to left side 90 degree", [("l", 90)]),
    ("D", "move to back one meter please", [("B", 1.0)]),
    ("D", "turn in right direction forty five degree", [("r", 45)]),
    ("D", "go straight 2 meter and after turn right", [("F", 2.0), ("r", 90)]),
    ("D", "you face to the north please", [("face", N)]),
    ("D", "make photo", "clarify"),
    ("D", "rotate in clockwise 30 degree", [("r", 30)]),
    ("D", "go forward 50 centimeter", [("F", 0.5)]),
    ("D", "turn half circle", [("a", 180)]),
    ("D", "move on left side two meters", [("L", 2.0)]),
    ("D", "go to south direction 4 meters", [("face", S), ("F", 4.0)]),
    ("D", "please stop now", [("stop",)]),
    ("D", "turn to right ninety degree and make one picture", [("r", 90)]),
    ("D", "go ahead 5 feets", [("F", 5 * FT)]),
    # ---- speaker E: typed chat, typos
    ("E", "turn rigth 90", [("r", 90)]),
    ("E", "move foward 3 ft pls", [("F", 3 * FT)]),
    ("E", "can u go back 2 feet", [("B", 2 * FT)]),
    ("E", "turn ur left 45 deg", [("l", 45)]),
    ("E", "go fwd 10 ft then turn rt 90", [("F", 10 * FT), ("r", 90)]),
    ("E", "teh robot shoud move forwrd 4 feet", [("F", 4 * FT)]),
    ("E", "pls face north", [("face", N)]),
    ("E", "trun around", [("a", 180)]),
    ("E", "u can stop now", [("stop",)]),
    ("E", "mvoe back 6 inches", [("B", 6 * IN)]),
    ("E", "go str8 5 meters", [("F", 5.0)]),
    ("E", "turn left 30 degres", [("l", 30)]),
    ("E", "take a pic pls", "clarify"),
    ("E", "rotate 180 n take pic", [("a", 180)]),
    ("E", "move forward 1 foot thx", [("F", 1 * FT)]),
    # ---- speaker F: corrects themselves
    ("F", "turn ninety right, no wait, left", [("l", 90)]),
    ("F", "move forward three feet, sorry, four feet", [("F", 4 * FT)]),
    ("F", "turn left forty five, actually make that thirty", [("l", 30)]),
    ("F", "go back two feet, no, forward two feet", [("F", 2 * FT)]),
    ("F", "face north, er, I mean south", [("face", S)]),
    ("F", "turn right sixty, um, no, ninety degrees", [("r", 90)]),
    ("F", "move five meters, I mean five feet, forward", [("F", 5 * FT)]),
    ("F", "go east, no, west eight feet", [("face", W), ("F", 8 * FT)]),
    ("F", "turn left, no wait, turn right twenty degrees", [("r", 20)]),
    ("F", "move forward ten feet, scratch that, six feet", [("F", 6 * FT)]),
    # ---- speaker G: compass and spoken numbers
    ("G", "face south-west", [("face", SW)]),
    ("G", "turn to face north west", [("face", NW)]),
    ("G", "face southeast then move forward three feet", [("face", SE), ("F", 3 * FT)]),
    ("G", "head north-east for twenty feet", [("face", NE), ("F", 20 * FT)]),
    ("G", "go south a yard", [("face", S), ("F", YD)]),
    ("G", "turn two twenty five degrees to the left", [("l", 225)]),
    ("G", "rotate three fifteen degrees clockwise", [("r", 315)]),
    ("G", "turn one thirty five right", [("r", 135)]),
    ("G", "go one and a half meters forward", [("F", 1.5)]),
    ("G", "move forward two and a half feet", [("F", 2.5 * FT)]),
    ("G", "turn left two seventy", [("l", 270)]),
    ("G", "move forward twelve and a half feet", [("F", 12.5 * FT)]),
    ("G", "back up three quarters of a meter", [("B", 0.75)]),
    ("G", "go forward eighteen inches", [("F", 18 * IN)]),
    ("G", "turn right one hundred and five degrees", [("r", 105)]),
    # ---- speaker H: more / another / again / a further
    ("H", "move two more feet", [("F", 2 * FT)]),
    ("H", "keep going straight about five more feet", [("F", 5 * FT)]),
    ("H", "turn another forty five degrees to your right", [("r", 45)]),
    ("H", "go a further three metres", [("F", 3.0)]),
    ("H", "move forward one more foot", [("F", 1 * FT)]),
    ("H", "again, turn left fifteen degrees", [("l", 15)]),
    ("H", "ok, now go another ten feet forward", [("F", 10 * FT)]),
    ("H", "turn a bit more to the left", [("bitl",)]),
    ("H", "continue moving another ten feet until i tell you to stop", [("F", 10 * FT)]),
    ("H", "can you move forty five more degrees to your right", [("r", 45)]),
    ("H", "move forward a little bit more", [("bitF",)]),
    ("H", "go forward again, seven feet this time", [("F", 7 * FT)]),
    ("H", "rotate twenty more degrees counterclockwise", [("l", 20)]),
    ("H", "inch forward a bit", [("bitF",)]),
    ("H", "go back one more meter", [("B", 1.0)]),
    # ---- speaker I: several steps, sideways, clockwise
    ("I", "move three feet to your left", [("L", 3 * FT)]),
    ("I", "slide right two feet", [("R", 2 * FT)]),
    ("I", "step sideways to the left about half a meter", [("L", 0.5)]),
    ("I", "turn clockwise ninety degrees then go forward four feet", [("r", 90), ("F", 4 * FT)]),
    ("I", "turn counter clockwise forty five and move ahead two meters", [("l", 45), ("F", 2.0)]),
    ("I", "go forward five feet, turn left ninety, go forward five feet", [("F", 5 * FT), ("l", 90), ("F", 5 * FT)]),
    ("I", "back up a foot, then face east", [("B", 1 * FT), ("face", E)]),
    ("I", "face west, go forward ten feet, then face north", [("face", W), ("F", 10 * FT), ("face", N)]),
    ("I", "turn around and go forward three feet", [("a", 180), ("F", 3 * FT)]),
    ("I", "turn right ninety degrees, take a picture, then turn left ninety degrees", [("r", 90), ("l", 90)]),
    ("I", "move forward six feet and take a picture", [("F", 6 * FT)]),
    ("I", "rotate clockwise one eighty and then back up two feet", [("a", 180), ("B", 2 * FT)]),
    ("I", "go left four feet", [("L", 4 * FT)]),
    ("I", "shift to your right by one meter", [("R", 1.0)]),
    ("I", "go forward two meters, turn around, and go forward one meter", [("F", 2.0), ("a", 180), ("F", 1.0)]),
    # ---- speaker J: short, vague, or out of scope
    ("J", "turn a little to the right", [("bitr",)]),
    ("J", "move forward a tiny bit", [("bitF",)]),
    ("J", "stop moving", [("stop",)]),
    ("J", "halt!", [("stop",)]),
    ("J", "turn", "clarify"),
    ("J", "turn forty five degrees", "clarify"),
    ("J", "pick up that box", "clarify"),
    ("J", "go forward like, three", [("alt", "clarify", [("F", 3.0)])]),
    ("J", "turn left", [("l", 90)]),
    ("J", "turn right please", [("r", 90)]),
    ("J", "face the other way", [("a", 180)]),
    ("J", "turn to your left a little, like ten degrees", [("l", 10)]),
    ("J", "look behind you", [("a", 180)]),
    ("J", "do a three sixty", [("a", 360)]),
    ("J", "go backwards like two and a half feet", [("B", 2.5 * FT)]),
    ("J", "move back 30 cm", [("B", 0.30)]),
    ("J", "drive forward 1.5 m", [("F", 1.5)]),
    ("J", "turn left by 5 degrees", [("l", 5)]),
    ("J", "go forward a yard and a half", [("F", 1.5 * YD)]),
    ("J", "what can you see over there", "clarify"),
]


# ------------------------------------------------------------------ expansion
def prim_choices(part, yaw):
    """Alternatives for one part: list of (primitives, new_yaw). A primitive is
    (cmd, dir, exact_steps, fixed_range_or_None, was_any)."""
    k = part[0]
    if k in ("F", "B"):
        return [([("Move", "forward" if k == "F" else "backward", part[1] / STEP_M, None, False)], yaw)]
    if k in ("L", "R"):
        side = "left" if k == "L" else "right"
        turn = 90 if k == "L" else -90
        return [([("Move", side, part[1] / STEP_M, None, False)], yaw),
                ([("Rotate", side, 9.0, None, False), ("Move", "forward", part[1] / STEP_M, None, False)],
                 (yaw + turn) % 360)]
    if k in ("l", "r"):
        d = part[1] if k == "l" else -part[1]
        return [([("Rotate", "left" if k == "l" else "right", part[1] / STEP_DEG, None, False)], (yaw + d) % 360)]
    if k == "a":
        return [([("Rotate", s, part[1] / STEP_DEG, None, True)], (yaw + part[1]) % 360) for s in ("left", "right")]
    if k == "face":
        diff = (part[1] - yaw + 180) % 360 - 180  # (-180, 180]
        if abs(abs(diff) - 180) < 1e-9:
            return [([("Rotate", s, 18.0, None, True)], part[1]) for s in ("left", "right")]
        assert abs(diff) > 1e-9, "compass turn already done"
        return [([("Rotate", "left" if diff > 0 else "right", abs(diff) / STEP_DEG, None, False)], part[1])]
    if k == "bitF":
        return [([("Move", "forward", None, (5, 17), False)], yaw)]
    if k in ("bitl", "bitr"):
        side = "left" if k == "bitl" else "right"
        return [([("Rotate", side, None, (1, 4), False)], (yaw + (25 if side == "left" else -25)) % 360)]
    raise ValueError(part)


def rng(exact, nparts):
    tol = max(0.07 * exact, 1.0, 0.5 * nparts)
    lo = max(1, math.ceil(exact - tol - 1e-9))
    hi = max(lo, math.floor(exact + tol + 1e-9))
    return [lo, hi]


def merge(prims):
    out = []  # [cmd, dir, [prims]]
    for p in prims:
        if out and out[-1][0] == p[0] and out[-1][1] == p[1]:
            out[-1][2].append(p)
        else:
            out.append([p[0], p[1], [p]])
    cmds = []
    for cmd, d, ps in out:
        if len(ps) == 1 and ps[0][3] is not None:
            r = list(ps[0][3])
        else:
            assert all(p[3] is None for p in ps), "cannot sum a vague amount"
            r = rng(sum(p[2] for p in ps), len(ps))
        if len(ps) == 1 and ps[0][4]:
            d = "any"
        cmds.append({"command": cmd, "direction": d, "repeat": r})
    return cmds


def expand(parts, yaw):
    if parts == "clarify":
        return ["clarify"]
    if parts == [("stop",)]:
        return [[{"command": "Stop"}]]
    if len(parts) == 1 and parts[0][0] == "alt":
        res = []
        for a in parts[0][1:]:
            res.extend(expand(a, yaw))
        return res
    seqs = [([], yaw)]
    for part in parts:
        nxt = []
        for prims, y in seqs:
            for add, y2 in prim_choices(part, y):
                nxt.append((prims + add, y2))
        seqs = nxt
    alts = []
    for prims, _ in seqs:
        c = merge(prims)
        if c not in alts:
            alts.append(c)
    return alts


def yaw_ok(parts, yaw):
    if parts == "clarify" or parts[0][0] == "alt":
        return True
    y = yaw
    for part in parts:
        if part[0] == "face":
            if abs((part[1] - y + 180) % 360 - 180) < 1e-9:
                return False
            y = part[1]
        elif part[0] in ("l", "r", "a"):
            y = (y + (part[1] if part[0] != "r" else -part[1])) % 360
    return True


def main():
    out = []
    k = 0
    for i, (spk, prompt, parts) in enumerate(CASES, 1):
        while not yaw_ok(parts, YAWS[k % len(YAWS)]):
            k += 1
        yaw = YAWS[k % len(YAWS)]
        k += 1
        alts = expand(parts, yaw)
        exp = alts[0] if len(alts) == 1 else {"any": alts}
        out.append({"id": f"sp-{spk}-{i:03d}", "map": "maps/arena.yaml",
                    "pose": [40.0, 10.0, yaw], "prompt": prompt, "expect": exp})
    ids = [c["id"] for c in out]
    assert len(set(ids)) == len(ids)
    assert len({c["prompt"].lower() for c in out}) == len(out), "duplicate prompt"
    Path(__file__).with_name("spoken.jsonl").write_text("".join(json.dumps(c) + "\n" for c in out))
    print(len(out), "cases")


if __name__ == "__main__":
    main()
