#!/usr/bin/env python3
"""Writes spoken.jsonl: spoken motion prompts on the SCOUT arena map from ten imagined speakers of kinds no
earlier round had, written by the parser helper in session 10 BEFORE reading the parser (README.md).
The meaning parts are expanded into expected commands by round 8's spoken_expand.py (imported from
../prompts-9, unchanged); the map is a copy of the arena (maps/, CC0).
Part notation (spoken_expand.py): F/B metres forward/back; L/R metres to the side; l/r degrees; a = a turn
either way; face = compass heading; bitF/bitB/bitl/bitr = "a little"; stop; get = information command;
"clarify" = ask / explain and run nothing; ("alt", A, B) = either A or B is right (a word of another
language that names the way: asking is as right as reading it).
Run: .venv/bin/python benchmarks/blind/prompts-10p/make_spoken.py
"""
import json
import sys
from pathlib import Path

HERE = Path(__file__).parent
sys.path.insert(0, str(HERE.parent / "prompts-9"))
from spoken_expand import FT, YAWS, check_case, expand, yaw_ok  # noqa: E402

ASK = "clarify"

CASES = [
    # ---- A  Buck, livestock auctioneer: rapid patter, numbers said again and again, "going once", "sold"
    ("A", "forward now, two metre, two metre, two metres, go", [("F", 2.0)]),
    ("A", "turn her left ninety, ninety, ninety, sold", [("l", 90)]),
    ("A", "hup! stop right there", [("stop",)]),
    ("A", "back her up one metre, going once, going twice, and gone", [("B", 1.0)]),
    ("A", "do i hear forty five degrees to the right? forty five right it is", [("r", 45)]),
    ("A", "bring it on over to the sale ring", ASK),                                     # place
    # ---- B  Rosa, sign-language interpreter voicing a Deaf client to the robot, in the third person
    ("B", "she's saying, move forward three metres please", [("F", 3.0)]),
    ("B", "he'd like you to turn right, about forty five degrees", [("r", 45)]),
    ("B", "turn left, sorry, my error, she signed right, turn right ninety", [("r", 90)]),
    ("B", "she asks where you are right now", [("get", "GetRobotPoseLast")]),
    ("B", "he says go back two feet, and then turn left", [("B", 2 * FT), ("l", 90)]),
    ("B", "she wants you to go and find her husband", ASK),                              # person / place
    # ---- C  Dee, night-shift order picker on a voice-picking headset: "ready", "confirm", "next", tired
    ("C", "ready. forward four metres. confirm", [("F", 4.0)]),
    ("C", "ugh. ready. turn left forty five", [("l", 45)]),
    ("C", "next. back up three feet", [("B", 3 * FT)]),
    ("C", "stop. hold. hold", [("stop",)]),
    ("C", "turn right one twenty, check", [("r", 120)]),
    ("C", "go to aisle twelve slot four", ASK),                                          # place
    ("C", "uh what's my position, i mean your position", [("get", "GetRobotPoseLast")]),
    # ---- D  Pieter, Dutch first language, port warehouse planner: "zo", "ja", "nee", "even" (= just)
    ("D", "zo, go straight on two meter", [("F", 2.0)]),
    ("D", "turn to the left, ja, ninety degrees", [("l", 90)]),
    ("D", "nee nee, stop", [("stop",)]),
    ("D", "go even one meter back", [("B", 1.0)]),
    ("D", "turn links, ninety degrees", [("alt", ASK, [("l", 90)])]),                    # links = left
    ("D", "rechtdoor three meter", [("alt", ASK, [("F", 3.0)])]),                        # = straight on
    ("D", "go to the kantine", ASK),                                                     # place
    # ---- E  Emre, Turkish first language, bakery owner: "hadi", "sey" (um), "yani" (I mean), "tamam"
    ("E", "hadi, go forward one meter", [("F", 1.0)]),
    ("E", "sey... turn right thirty degree", [("r", 30)]),
    ("E", "dur, stop!", [("stop",)]),
    ("E", "go back yani two meter", [("B", 2.0)]),
    ("E", "sola don, ninety degrees", [("alt", ASK, [("l", 90)])]),                      # sola = to the left
    ("E", "tamam, now turn around", [("a", 180)]),
    ("E", "go to the depo", ASK),                                                        # place
    # ---- F  a speech-to-text app: no punctuation, all lower case, run-on steps
    ("F", "go forward three meters then turn left ninety degrees then go forward one meter",
     [("F", 3.0), ("l", 90), ("F", 1.0)]),
    ("F", "turn right forty five degrees no wait turn left forty five degrees", [("l", 45)]),
    ("F", "move back two feet and stop", [("B", 2 * FT)]),
    ("F", "rotate clockwise one hundred eighty degrees and then move forward half a meter",
     [("a", 180), ("F", 0.5)]),
    ("F", "what is your current location", [("get", "GetRobotPoseLast")]),
    ("F", "turn left 90 degrees go forward 2 meters", [("l", 90), ("F", 2.0)]),
    ("F", "go forward ten meters um actually make that five", [("F", 5.0)]),
    # ---- G  Lorraine, night taxi dispatcher: "unit one", "copy", "what's your twenty", "disregard", "tree"
    ("G", "unit one, what's your twenty", [("get", "GetRobotPoseLast")]),
    ("G", "copy that, proceed forward six feet", [("F", 6 * FT)]),
    ("G", "unit one, hold where you are", [("stop",)]),
    ("G", "make a left, then proceed four metres", [("l", 90), ("F", 4.0)]),
    ("G", "turn right forty five, disregard, turn right fifteen", [("r", 15)]),
    ("G", "pick up at the corner of fifth and main", ASK),                               # place
    ("G", "stand by... okay, back up tree metres", [("B", 3.0)]),
    # ---- H  Pam, driving instructor: "pull forward", "nice and steady", "reverse", "bring it round"
    ("H", "okay, pull forward about two metres, nice and steady", [("F", 2.0)]),
    ("H", "and reverse back one metre", [("B", 1.0)]),
    ("H", "bring it round to the right, ninety degrees", [("r", 90)]),
    ("H", "check your mirrors, then pull away forward three metres", [("F", 3.0)]),
    ("H", "and brake, brake!", [("stop",)]),
    ("H", "parallel park behind the blue car", ASK),                                     # place / object
    ("H", "take a left here", [("l", 90)]),
    # ---- I  Bree, yoga teacher: "gently", "and breathe", "all the way round", "as you exhale"
    ("I", "and gently, turn to your right, about forty five degrees, breathe", [("r", 45)]),
    ("I", "slowly step back, just a little", [("bitB",)]),
    ("I", "now all the way round, a full circle", [("a", 360)]),
    ("I", "and rest. stay there", [("stop",)]),
    ("I", "float forward one metre as you exhale", [("F", 1.0)]),
    ("I", "turn left a touch", [("bitl",)]),
    ("I", "now take a photo of your pose", ASK),                                         # no camera
    # ---- J  Harold, cautious first-time user: asks permission, hypotheticals, negations
    ("J", "um, hello, could you maybe go forward just one metre? only one", [("F", 1.0)]),
    ("J", "if i say turn left, will you turn left?", ASK),                               # a question, not an order
    ("J", "is it safe to turn right ninety degrees? okay, please do", [("r", 90)]),
    ("J", "please stop, i think that's enough", [("stop",)]),
    ("J", "could you back up a tiny bit, not too far", [("bitB",)]),
    ("J", "don't go forward yet", ASK),                                                  # negated: nothing runs
    ("J", "okay now turn left thirty degrees, carefully", [("l", 30)]),
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
        case = {"id": f"b10p-{spk}-{i:03d}", "map": "maps/arena.yaml",
                "pose": [40.0, 10.0, yaw], "prompt": prompt, "expect": exp}
        check_case(case)
        out.append(case)
    assert len({" ".join(c["prompt"].lower().split()) for c in out}) == len(out), "duplicate prompt"
    (HERE / "spoken.jsonl").write_text("".join(json.dumps(c) + "\n" for c in out))
    print(len(out), "cases")


if __name__ == "__main__":
    main()
