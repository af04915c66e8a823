#!/usr/bin/env python3
"""Writes spoken.jsonl: 200 hand-written spoken motion prompts on the SCOUT arena map,
from 12 imagined speakers (README.md).  Tooling adapted from the previous blind set's
make_spoken.py; every prompt here is new.

Each case is (speaker, prompt, parts). A part is a tuple:
  ("F"|"B", metres)            move forward / backward
  ("L"|"R", metres)            sideways move (alternatives: sideways Move, or 90 deg Rotate + Move forward)
  ("Ls"|"Rs", metres)          sideways move where the speaker says "without turning": sideways Move only
  ("l"|"r", degrees)           rotate left / right
  ("a", degrees)               180 or 360: either way
  ("face", heading_deg)        compass: shorter rotation from the current heading
  ("bitF",), ("bitB",), ("bitl",), ("bitr",)  "a little": 0.15-0.5 m / 10-40 deg
  ("far", metres)              forward move that would cross the arena wall: clarify, or the safe part
                               (Move forward 1 .. the last step that stays valid)
  ("get", "GetRobotPoseLast"|"GetMap"|"GetCurrentPath")   information asked for (alone)
  ("stop",)                    alone
  "clarify"                    run nothing, explain / ask
  ("alt", [parts...] | "clarify", ...)   several right answers
Photo parts are simply not written (dropped), per the contract.
Needs numpy + scipy only for the "far" part (score.py's Map); run with /work/main/.venv/bin/python.
"""
import json
import math
import sys
from pathlib import Path

FT, IN, YD, CM = 0.3048, 0.0254, 0.9144, 0.01
STEP_M, STEP_DEG = 0.03, 10.0
YAWS = [0, 90, 180, 270, 30, 120, 210, 300, 60, 150, 240, 330]
N, NE, E, SE, S, SW, W, NW = 90, 45, 0, 315, 270, 225, 180, 135
HERE = Path(__file__).parent
sys.path.insert(0, "/work/shared/bench")

CASES = [
    # ---- A  Nina, nervous first-timer: apologises, hedges, asks permission
    ("A", "um hi... is this on? could you maybe go forward one metre?", [("F", 1.0)]),
    ("A", "sorry, I'm new at this. turn left please? like ninety degrees?", [("l", 90)]),
    ("A", "oh no, stop! stop!", [("stop",)]),
    ("A", "is it okay if you back up, um, half a metre? sorry", [("B", 0.5)]),
    ("A", "could you turn right... just a little bit?", [("bitr",)]),
    ("A", "I don't want to crash it... move forward maybe thirty centimetres?", [("F", 30 * CM)]),
    ("A", "um, okay, can you turn around? is that a thing you can do?", [("a", 180)]),
    ("A", "sorry, I mean, um... go forward two feet. just two.", [("F", 2 * FT)]),
    ("A", "can you, uh, turn sixty degrees? I'm not sure which way, sorry", "clarify"),
    ("A", "please go forward, um, five? is five okay?", "clarify"),
    ("A", "okay, just inch forward a tiny bit please", [("bitF",)]),
    ("A", "I think... face north? if that's alright", [("face", N)]),
    ("A", "um could you slide to your left, like one metre, without turning?", [("Ls", 1.0)]),
    ("A", "sorry, could you turn another forty-five degrees to the right", [("r", 45)]),
    ("A", "oh gosh, can you take a picture so I can see?", "clarify"),
    ("A", "uh, drive backwards... one and a half feet maybe", [("B", 1.5 * FT)]),
    ("A", "could you rotate left, um, twenty degrees? sorry if that's a weird number", [("l", 20)]),
    # ---- B  Tom, terse engineer: abbreviations, decimals, no courtesy
    ("B", "fwd 1.2 m", [("F", 1.2)]),
    ("B", "rot cw 30 deg", [("r", 30)]),
    ("B", "reverse 40 cm", [("B", 0.40)]),
    ("B", "yaw left 15 deg", [("l", 15)]),
    ("B", "translate right 0.5 m", [("R", 0.5)]),
    ("B", "halt, halt", [("stop",)]),
    ("B", "ccw 135 deg", [("l", 135)]),
    ("B", "forward 750 mm", [("F", 0.75)]),
    ("B", "heading east", [("face", E)]),
    ("B", "fwd 2.5 m, cw 90", [("F", 2.5), ("r", 90)]),
    ("B", "rotate 360", [("a", 360)]),
    ("B", "report current pose", [("get", "GetRobotPoseLast")]),
    ("B", "get map", [("get", "GetMap")]),
    ("B", "back 0.25 m", [("B", 0.25)]),
    ("B", "rotate 7 deg right", [("r", 7)]),
    ("B", "fwd 3", "clarify"),
    ("B", "rot 45", "clarify"),
    # ---- C  Ana, non-native: drops articles, verb last, "meter" without plural
    ("C", "robot forward go two meter", [("F", 2.0)]),
    ("C", "please make turn on left, thirty degree", [("l", 30)]),
    ("C", "go back little bit", [("bitB",)]),
    ("C", "three meter you go forward", [("F", 3.0)]),
    ("C", "to right you turn ninety", [("r", 90)]),
    ("C", "face to direction of south", [("face", S)]),
    ("C", "go right side one and half meter", [("R", 1.5)]),
    ("C", "make full rotation", [("a", 360)]),
    ("C", "stop here", [("stop",)]),
    ("C", "back go sixty centimeter", [("B", 0.60)]),
    ("C", "you turn around and go forward one meter", [("a", 180), ("F", 1.0)]),
    ("C", "please make picture of room", "clarify"),
    ("C", "you go to kitchen please", "clarify"),
    ("C", "turn right direction hundred twenty degree", [("r", 120)]),
    ("C", "walk forward four feets then stop", [("F", 4 * FT)]),
    ("C", "turn little to right side", [("bitr",)]),
    ("C", "you move four, please", "clarify"),
    # ---- D  Raj, dictating on a phone: speech-recognition slips, spoken punctuation
    ("D", "move for word too feet", [("F", 2 * FT)]),
    ("D", "turn write ninety degrees", [("r", 90)]),
    ("D", "go back won meter", [("B", 1.0)]),
    ("D", "rotate lift forty five degrees", [("l", 45)]),
    ("D", "face nor east", [("face", NE)]),
    ("D", "move forward ate feet", [("F", 8 * FT)]),
    ("D", "turn around period", [("a", 180)]),
    ("D", "go forward three meters comma then turn left", [("F", 3.0), ("l", 90)]),
    ("D", "stop stop stop exclamation point", [("stop",)]),
    ("D", "turn right thirty degrees new line move forward to meters", [("r", 30), ("F", 2.0)]),
    ("D", "back up for feet", [("B", 4 * FT)]),
    ("D", "take a photo question mark", "clarify"),
    ("D", "turn to the rite sixty degrees", [("r", 60)]),
    ("D", "go forward one point five meters", [("F", 1.5)]),
    ("D", "rotate counter clock wise ninety", [("l", 90)]),
    ("D", "turn sixty degrees period", "clarify"),
    ("D", "moved backward eighteen inches", [("B", 18 * IN)]),
    # ---- E  Maya, a child
    ("E", "robot robot go forward three metres!", [("F", 3.0)]),
    ("E", "do a circle!!", [("a", 360)]),
    ("E", "turn around silly", [("a", 180)]),
    ("E", "go backwards one metre pleeeease", [("B", 1.0)]),
    ("E", "spin to the left a teeny bit", [("bitl",)]),
    ("E", "can you go over there", "clarify"),
    ("E", "go forward two feet then turn left", [("F", 2 * FT), ("l", 90)]),
    ("E", "freeze!", [("stop",)]),
    ("E", "find my teddy", "clarify"),
    ("E", "go forward a teeny tiny bit", [("bitF",)]),
    ("E", "turn left and go forward one metre", [("l", 90), ("F", 1.0)]),
    ("E", "can you dance", "clarify"),
    ("E", "go backwards half a metre", [("B", 0.5)]),
    ("E", "turn right ninety!!", [("r", 90)]),
    ("E", "what do you see robot", "clarify"),
    ("E", "go to my bedroom", "clarify"),
    # ---- F  Greg, mixes feet and metres
    ("F", "go forward two metres and then another three feet", [("F", 2.0), ("F", 3 * FT)]),
    ("F", "move forward 1 metre 6 inches", [("F", 1.0 + 6 * IN)]),
    ("F", "go forward six feet, then back half a metre", [("F", 6 * FT), ("B", 0.5)]),
    ("F", "move forward a yard", [("F", YD)]),
    ("F", "turn right ninety and go 4 feet, then two more metres", [("r", 90), ("F", 4 * FT), ("F", 2.0)]),
    ("F", "forward 150 cm", [("F", 1.5)]),
    ("F", "go forward five", "clarify"),
    ("F", "move back about a foot", [("B", FT)]),
    ("F", "go forward two and a half metres", [("F", 2.5)]),
    ("F", "move left three feet", [("L", 3 * FT)]),
    ("F", "go forward 2 foot 6", [("F", 2.5 * FT)]),
    ("F", "forward half a metre then another 10 inches", [("F", 0.5), ("F", 10 * IN)]),
    ("F", "go forward a couple of feet", [("F", 2 * FT)]),
    ("F", "back up 12 inches", [("B", 12 * IN)]),
    ("F", "move forward 2 m, turn left, move forward 3 ft", [("F", 2.0), ("l", 90), ("F", 3 * FT)]),
    ("F", "go east 3 metres and then 4 more feet", [("face", E), ("F", 3.0), ("F", 4 * FT)]),
    ("F", "move back two", "clarify"),
    # ---- G  Sam, ex-pilot: clock directions (12 = ahead, 3 = right, 30 degrees an hour)
    ("G", "turn to your two o'clock", [("r", 60)]),
    ("G", "face your ten o'clock", [("l", 60)]),
    ("G", "turn to your six o'clock", [("a", 180)]),
    ("G", "go 3 metres toward your nine o'clock", [("L", 3.0)]),
    ("G", "turn to one o'clock", [("r", 30)]),
    ("G", "rotate to your four o'clock", [("r", 120)]),
    ("G", "turn to eight o'clock then go forward 2 metres", [("l", 120), ("F", 2.0)]),
    ("G", "move forward five feet, twelve o'clock", [("F", 5 * FT)]),
    ("G", "swing to your eleven o'clock", [("l", 30)]),
    ("G", "go two feet at your three o'clock", [("R", 2 * FT)]),
    ("G", "turn to your 5 o'clock", [("r", 150)]),
    ("G", "turn to your 7 o'clock and back up a metre", [("l", 150), ("B", 1.0)]),
    ("G", "face north then turn to your three o'clock", [("face", N), ("r", 90)]),
    ("G", "turn to your 2 o'clock and go 1 metre", [("r", 60), ("F", 1.0)]),
    ("G", "turn to your two o'clock, take a photo", [("r", 60)]),
    ("G", "turn to your 9 o'clock", [("l", 90)]),
    # ---- H  Hannah, hiker: compass points
    ("H", "face due south", [("face", S)]),
    ("H", "head north-west for four metres", [("face", NW), ("F", 4.0)]),
    ("H", "swing round to face east", [("face", E)]),
    ("H", "go south 10 feet", [("face", S), ("F", 10 * FT)]),
    ("H", "point yourself southeast", [("face", SE)]),
    ("H", "go west two metres then north three metres", [("face", W), ("F", 2.0), ("face", N), ("F", 3.0)]),
    ("H", "face south-west and back up a metre", [("face", SW), ("B", 1.0)]),
    ("H", "face north, then turn right 45", [("face", N), ("r", 45)]),
    ("H", "go due east for a hundred metres", [("face", E), ("far", 100.0)]),
    ("H", "head northeast 5 m", [("face", NE), ("F", 5.0)]),
    ("H", "point west", [("face", W)]),
    ("H", "where am I right now on the map?", [("get", "GetRobotPoseLast")]),
    ("H", "face northeast, no, northwest", [("face", NW)]),
    ("H", "go north a foot and a half", [("face", N), ("F", 1.5 * FT)]),
    ("H", "turn to face south-east then go forward 6 feet", [("face", SE), ("F", 6 * FT)]),
    ("H", "face the sun", "clarify"),
    ("H", "face east then go backwards 2 m", [("face", E), ("B", 2.0)]),
    # ---- I  Kai, heavy chat spelling
    ("I", "trn lft 45", [("l", 45)]),
    ("I", "mve fwrd 2m plz", [("F", 2.0)]),
    ("I", "go bak 1ft", [("B", FT)]),
    ("I", "turnn arund", [("a", 180)]),
    ("I", "rotat rite 30 dgr", [("r", 30)]),
    ("I", "fcae north", [("face", N)]),
    ("I", "stahp", [("stop",)]),
    ("I", "go foward 3 m thn trn rght", [("F", 3.0), ("r", 90)]),
    ("I", "mov 2 ft to the lft", [("L", 2 * FT)]),
    ("I", "u ok? tak pic", "clarify"),
    ("I", "go fwd a lil bit", [("bitF",)]),
    ("I", "trn 90", "clarify"),
    ("I", "go 2 teh door", "clarify"),
    ("I", "wat is ur positon", [("get", "GetRobotPoseLast")]),
    ("I", "bckwrds 50cm", [("B", 0.5)]),
    ("I", "turn lft 15 deg n go fwd 1m", [("l", 15), ("F", 1.0)]),
    ("I", "rotaet 360", [("a", 360)]),
    # ---- J  Priya, chains three steps
    ("J", "go forward two metres, turn left ninety, then go forward one metre", [("F", 2.0), ("l", 90), ("F", 1.0)]),
    ("J", "turn right 45, move forward 3 feet, and then turn back left 45", [("r", 45), ("F", 3 * FT), ("l", 45)]),
    ("J", "back up a foot, turn around, then go forward two feet", [("B", FT), ("a", 180), ("F", 2 * FT)]),
    ("J", "face north, go forward 2 m, then face east", [("face", N), ("F", 2.0), ("face", E)]),
    ("J", "turn left, go a metre, turn left again", [("l", 90), ("F", 1.0), ("l", 90)]),
    ("J", "move forward 50 cm, turn right 30 degrees, and move forward another 50 cm",
     [("F", 0.5), ("r", 30), ("F", 0.5)]),
    ("J", "go forward one metre, turn around, and drive forward one metre", [("F", 1.0), ("a", 180), ("F", 1.0)]),
    ("J", "turn right 90, back up 2 feet, then turn left 90", [("r", 90), ("B", 2 * FT), ("l", 90)]),
    ("J", "go forward 3 feet, then 3 feet to your right, then turn left", [("F", 3 * FT), ("R", 3 * FT), ("l", 90)]),
    ("J", "rotate 360, then go forward 1 metre, then take a picture", [("a", 360), ("F", 1.0)]),
    ("J", "turn left 60, go forward 2 metres, turn right 60", [("l", 60), ("F", 2.0), ("r", 60)]),
    ("J", "go south 1 m, go east 1 m, then face north", [("face", S), ("F", 1.0), ("face", E), ("F", 1.0), ("face", N)]),
    ("J", "back up half a metre, turn right a bit, then stop", [("B", 0.5), ("bitr",)]),
    ("J", "go forward 4 feet, then turn left 45, then pick up the box",
     [("alt", "clarify", [("F", 4 * FT), ("l", 45)])]),
    ("J", "turn around, go forward 1.5 metres, turn around again", [("a", 180), ("F", 1.5), ("a", 180)]),
    ("J", "go forward two metres, then go to the kitchen, then turn left", "clarify"),
    ("J", "move forward 1 m, turn 45 degrees, then move forward 1 m", [("alt", "clarify", [("F", 1.0)])]),
    # ---- K  Mr Whitfield, very polite, long questions
    ("K", "Good afternoon. Would you be so kind as to move forward approximately two metres, if it's not too much trouble?",
     [("F", 2.0)]),
    ("K", "I wonder whether you might turn to your right by about forty-five degrees, please?", [("r", 45)]),
    ("K", "Would it be possible for you to reverse by roughly one metre so that I can see the area in front of you better?",
     [("B", 1.0)]),
    ("K", "Could you possibly turn all the way around, so that you are facing the other direction?", [("a", 180)]),
    ("K", "If it isn't too much bother, could you face west for me?", [("face", W)]),
    ("K", "Would you kindly tell me where you are at the moment?", [("get", "GetRobotPoseLast")]),
    ("K", "May I ask you to move slightly forward?", [("bitF",)]),
    ("K", "Would you be able to show me the map you have built so far?", [("get", "GetMap")]),
    ("K", "I'd be most grateful if you could turn left by thirty degrees and then move forward three feet.",
     [("l", 30), ("F", 3 * FT)]),
    ("K", "Could you please make your way to the kitchen when you have a moment?", "clarify"),
    ("K", "Might you be able to rotate a full three hundred and sixty degrees, please?", [("a", 360)]),
    ("K", "Would you mind going forward about, oh, let's say two and a half feet?", [("F", 2.5 * FT)]),
    ("K", "Could you please turn by ninety degrees?", "clarify"),
    ("K", "Would you be so good as to move one metre to your right?", [("R", 1.0)]),
    ("K", "Would you please tell me which path you are currently following?", [("get", "GetCurrentPath")]),
    ("K", "Could you kindly bring me a cup of tea?", "clarify"),
    # ---- L  Dave, corrects himself, restarts, fillers
    ("L", "go forward three- no, wait, two metres", [("F", 2.0)]),
    ("L", "turn le- turn right, sixty degrees", [("r", 60)]),
    ("L", "back up two feet, actually, make it one foot", [("B", FT)]),
    ("L", "um, face south- er, no, east", [("face", E)]),
    ("L", "move forward, uh, four metres, no, four feet", [("F", 4 * FT)]),
    ("L", "turn right ninety, sorry, I meant to say left ninety", [("l", 90)]),
    ("L", "uh go forward, hmm, let me think, one and a half metres", [("F", 1.5)]),
    ("L", "turn left thirty, no, forty, no, fifty degrees", [("l", 50)]),
    ("L", "okay so, um, go backward... actually, go forward half a metre", [("F", 0.5)]),
    ("L", "rotate left uh I mean right one hundred degrees", [("r", 100)]),
    ("L", "stop, no, keep going... actually, stop", [("stop",)]),
    ("L", "go to the- uh, never mind, just turn around", [("a", 180)]),
    ("L", "move forward uh- two, um", "clarify"),
    ("L", "go north fi- fifteen feet", [("face", N), ("F", 15 * FT)]),
    ("L", "turn, um, uh... I don't know, just turn", "clarify"),
    ("L", "move right- left, move left a metre", [("L", 1.0)]),
]


# ------------------------------------------------------------------ expansion
ARENA = None


def arena():
    global ARENA
    if ARENA is None:
        from score import Map
        ARENA = Map((HERE / "maps" / "arena.yaml").resolve())
    return ARENA


def safe_steps(x, y, yaw):
    """Largest forward Move (steps) whose whole path stays valid on the arena (score.py's check)."""
    m = arena()
    n = 0
    while True:
        d = STEP_M * (n + 1)
        nx, ny = x + d * math.cos(math.radians(yaw)), y + d * math.sin(math.radians(yaw))
        if not m.valid(nx, ny):
            return n
        n += 1


def prim_choices(part, yaw):
    """Alternatives for one part: list of (primitives, new_yaw). A primitive is
    (cmd, dir, exact_steps, fixed_range_or_None, was_any)."""
    k = part[0]
    if k in ("F", "B"):
        return [([("Move", "forward" if k == "F" else "backward", part[1] / STEP_M, None, False)], yaw)]
    if k in ("Ls", "Rs"):
        return [([("Move", "left" if k == "Ls" else "right", part[1] / STEP_M, None, False)], yaw)]
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
    if k in ("bitF", "bitB"):
        return [([("Move", "forward" if k == "bitF" else "backward", None, (5, 17), False)], yaw)]
    if k in ("bitl", "bitr"):
        side = "left" if k == "bitl" else "right"
        return [([("Rotate", side, None, (1, 4), False)], (yaw + (25 if side == "left" else -25)) % 360)]
    if k == "far":
        n = safe_steps(40.0, 10.0, yaw)
        assert part[1] / STEP_M > n + 50, "not impossible"
        return [([("Move", "forward", None, (1, n), False)], yaw)]
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
    if len(parts) == 1 and parts[0][0] == "get":
        return [[{"command": parts[0][1]}]]
    if len(parts) == 1 and parts[0][0] == "alt":
        res = []
        for a in parts[0][1:]:
            res.extend(expand(a, yaw))
        return res
    assert all(p[0] not in ("stop", "get", "alt") for p in parts), parts
    if any(p[0] == "far" for p in parts):
        assert parts[-1][0] == "far" and all(p[0] == "face" for p in parts[:-1])
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
    if any(p[0] == "far" for p in parts):
        alts = ["clarify"] + alts
    return alts


def yaw_ok(parts, yaw):
    if parts == "clarify" or parts[0][0] in ("alt", "get", "stop"):
        return True
    y = yaw
    for part in parts:
        if part[0] == "face":
            if abs((part[1] - y + 180) % 360 - 180) < 1e-9:
                return False
            y = part[1]
        elif part[0] in ("l", "r", "a"):
            y = (y + (part[1] if part[0] != "r" else -part[1])) % 360
        elif part[0] in ("L", "R", "bitl", "bitr"):
            # the heading after these depends on the reading; no compass part may follow
            assert not any(p[0] == "face" for p in parts[parts.index(part) + 1:]), parts
    return True


def check_case(c):
    """Every command well formed as score.py reads it."""
    alts = c["expect"]["any"] if isinstance(c["expect"], dict) else [c["expect"]]
    for alt in alts:
        if alt == "clarify":
            continue
        assert isinstance(alt, list) and alt
        for i, cmd in enumerate(alt):
            name = cmd["command"]
            assert name in ("Move", "Rotate", "Stop", "GetRobotPoseLast", "GetMap", "GetCurrentPath"), cmd
            if name in ("Move", "Rotate"):
                dirs = ("forward", "backward", "left", "right") if name == "Move" else ("left", "right", "any")
                assert cmd["direction"] in dirs, cmd
                lo, hi = cmd["repeat"]
                assert isinstance(lo, int) and isinstance(hi, int) and 1 <= lo <= hi, cmd
                if i:  # score.py sums consecutive same-direction commands: never expect two in a row
                    p = alt[i - 1]
                    assert not (p["command"] == name and p["direction"] == cmd["direction"]), alt
            if name == "Stop":
                assert len(alt) == 1


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
        case = {"id": f"b3s-{spk}-{i:03d}", "map": "maps/arena.yaml",
                "pose": [40.0, 10.0, yaw], "prompt": prompt, "expect": exp}
        check_case(case)
        out.append(case)
    ids = [c["id"] for c in out]
    assert len(set(ids)) == len(ids)
    assert len({" ".join(c["prompt"].lower().split()) for c in out}) == len(out), "duplicate prompt"
    (HERE / "spoken.jsonl").write_text("".join(json.dumps(c) + "\n" for c in out))
    print(len(out), "cases")


if __name__ == "__main__":
    main()
