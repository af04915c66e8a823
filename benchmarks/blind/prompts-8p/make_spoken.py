#!/usr/bin/env python3
"""Writes spoken.jsonl: 61 spoken motion prompts on the SCOUT arena map from ten imagined speakers of kinds
no earlier round had, written by the parser helper in session 8 BEFORE reading how the parser handles them
(README.md).  The meaning parts are expanded into expected commands by round 7's spoken_expand.py (imported
from ../prompts-8, unchanged); the map is round 7's copy of the arena (../prompts-8/maps, CC0).
Run: .venv/bin/python benchmarks/blind/prompts-8p/make_spoken.py
"""
import json
import sys
from pathlib import Path

HERE = Path(__file__).parent
sys.path.insert(0, str(HERE.parent / "prompts-8"))
from spoken_expand import FT, IN, N, YAWS, check_case, expand, yaw_ok  # noqa: E402

CASES = [
    # ---- K  Siobhan, Irish dairy farmer: "go on", "a small bit", "grand", "right so"
    ("K", "go on ahead there two metres, good robot", [("F", 2.0)]),
    ("K", "give it a small bit of a turn to the left", [("bitl",)]),
    ("K", "reverse back there a metre, grand", [("B", 1.0)]),
    ("K", "turn yourself round", [("a", 180)]),
    ("K", "will you stop, stop", [("stop",)]),
    ("K", "go over to the parlour", "clarify"),                                        # place
    ("K", "right so, turn left, fifty degrees", [("l", 50)]),
    # ---- L  Thandi, South African mine safety officer: "ag", "now now", "sharp sharp", "just now"
    ("L", "ag man, go forward three metres", [("F", 3.0)]),
    ("L", "turn right now now, ninety degrees", [("r", 90)]),
    ("L", "go backwards two metres, sharp sharp", [("B", 2.0)]),
    ("L", "just now turn left forty degrees", [("l", 40)]),
    ("L", "shame, you're stuck, move left half a metre", [("L", 0.5)]),
    ("L", "go to the shaft", "clarify"),                                                # place
    # ---- M  Coach Reyes, basketball coach: "pivot", "drop back", "slide", "square up"
    ("M", "pivot left, forty five", [("l", 45)]),
    ("M", "drop back three feet", [("B", 3 * FT)]),
    ("M", "hold up, hold up", [("stop",)]),
    ("M", "square up, face north", [("face", N)]),
    ("M", "defensive slide to your right, two feet", [("R", 2 * FT)]),
    ("M", "go the length of the court", "clarify"),                                     # no such element
    ("M", "push up five feet and pivot right", [("F", 5 * FT), ("r", 90)]),
    # ---- N  Wei, Mandarin first language: "meter", "degree", "left side", "little bit"
    ("N", "go straight two meter", [("F", 2.0)]),
    ("N", "turn left side ninety degree", [("l", 90)]),
    ("N", "please go back one little bit", [("bitB",)]),
    ("N", "you turn around please", [("a", 180)]),
    ("N", "go front three meter then turn right", [("F", 3.0), ("r", 90)]),
    ("N", "where you now", [("get", "GetRobotPoseLast")]),
    # ---- O  Owain, stammers: repeated sounds and words
    ("O", "g-g-go forward, forward two metres", [("F", 2.0)]),
    ("O", "t-turn, turn right thirty degrees", [("r", 30)]),
    ("O", "move b-b-back one metre", [("B", 1.0)]),
    ("O", "st- st- stop", [("stop",)]),
    ("O", "turn left turn left forty five degrees", [("l", 45)]),
    ("O", "go go go forward one metre", [("F", 1.0)]),
    # ---- P  Ilse, dance teacher: quarter / half / full turns, counts, "and step"
    ("P", "quarter turn to the right", [("r", 90)]),
    ("P", "half turn", [("a", 180)]),
    ("P", "and step forward one metre", [("F", 1.0)]),
    ("P", "five six seven eight, turn left", [("l", 90)]),
    ("P", "full turn, clockwise", [("a", 360)]),
    ("P", "step to the side, left, half a metre", [("L", 0.5)]),
    ("P", "eighth of a turn left", [("l", 45)]),
    # ---- Q  Marcus, talks to the robot like a voice assistant: wake words
    ("Q", "hey robot, move forward four feet", [("F", 4 * FT)]),
    ("Q", "alexa, turn left, sorry, robot, turn left", [("l", 90)]),
    ("Q", "ok robot, stop", [("stop",)]),
    ("Q", "hey robot what's your location", [("get", "GetRobotPoseLast")]),
    ("Q", "robot, rotate one hundred twenty degrees counterclockwise", [("l", 120)]),
    ("Q", "hey robot, back up eighteen inches", [("B", 18 * IN)]),
    # ---- R  Bud, US forklift driver: "hang a right", "scootch", "a skosh", "ten-four"
    ("R", "hang a right", [("r", 90)]),
    ("R", "scootch up a skosh", [("bitF",)]),
    ("R", "back her up ten feet", [("B", 10 * FT)]),
    ("R", "ten-four, now hang a left and go twenty feet", [("l", 90), ("F", 20 * FT)]),
    ("R", "whoa whoa whoa", [("stop",)]),
    ("R", "head on down to loading dock three", "clarify"),                             # place
    # ---- S  Youssef, Arabic first language: articles and prepositions from Arabic
    ("S", "go to the forward two meters", [("F", 2.0)]),
    ("S", "turn to the right direction ninety", [("r", 90)]),
    ("S", "return back one meter", [("B", 1.0)]),
    ("S", "make turn left forty five degree", [("l", 45)]),
    ("S", "stop here please", [("stop",)]),
    # ---- T  Ruth, easily flustered office worker: exclamations and false starts
    ("T", "turn left, oh no, right, ninety degrees", [("r", 90)]),
    ("T", "go forward three, oops, two metres", [("F", 2.0)]),
    ("T", "turn right, no wait, turn left thirty degrees", [("l", 30)]),
    ("T", "move back, ugh, forward one metre", [("F", 1.0)]),
    ("T", "turn left turn right turn left sixty degrees", [("l", 60)]),
]


def main() -> None:
    out = []
    k = 0
    for i, (spk, prompt, parts) in enumerate(CASES, 1):
        while not yaw_ok(parts, YAWS[k % len(YAWS)]):
            k += 1
        yaw = YAWS[k % len(YAWS)]
        k += 1
        alts = expand(parts, yaw)
        exp = alts[0] if len(alts) == 1 else {"any": alts}
        case = {"id": f"b8p-{spk}-{i:03d}", "map": "../prompts-8/maps/arena.yaml",
                "pose": [40.0, 10.0, yaw], "prompt": prompt, "expect": exp}
        check_case(case)
        out.append(case)
    assert len({c["prompt"] for c in out}) == len(out), "duplicate prompt"
    (HERE / "spoken.jsonl").write_text("".join(json.dumps(c) + "\n" for c in out))
    print(len(out), "cases")


if __name__ == "__main__":
    main()
