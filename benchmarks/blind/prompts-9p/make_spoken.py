#!/usr/bin/env python3
"""Writes spoken.jsonl: 64 spoken motion prompts on the SCOUT arena map from ten imagined speakers of kinds
no earlier round had, written by the parser helper in session 9 BEFORE reading how the parser handles them
(README.md).  The meaning parts are expanded into expected commands by round 8's spoken_expand.py (imported
from ../prompts-9, unchanged); the map is round 8's copy of the arena (../prompts-9/maps, CC0).
Part notation (spoken_expand.py): F/B metres forward/back; L/R metres to the side; l/r degrees; a = a turn
either way; face = compass heading; bitF/bitB/bitl/bitr = "a little"; stop; get = information command;
"clarify" = ask / explain and run nothing.
Run: .venv/bin/python benchmarks/blind/prompts-9p/make_spoken.py
"""
import json
import sys
from pathlib import Path

HERE = Path(__file__).parent
sys.path.insert(0, str(HERE.parent / "prompts-9"))
from spoken_expand import FT, YAWS, S, check_case, expand, yaw_ok  # noqa: E402

CASES = [
    # ---- A  Kev, paramedic at the end of a fourteen-hour night shift: tired, trailing, "yeah", "mate"
    ("A", "yeah just... go forward two metres, cheers", [("F", 2.0)]),
    ("A", "turn left mate. like, forty five", [("l", 45)]),
    ("A", "ok stop. stop there.", [("stop",)]),
    ("A", "right, back up a metre would ya", [("B", 1.0)]),
    ("A", "can you just turn round for me", [("a", 180)]),
    ("A", "take it over to resus", "clarify"),                                          # place
    # ---- B  Stan, tower-crane banksman calling moves as he would to the crane driver
    ("B", "travel forward three metres, dead slow", [("F", 3.0)]),
    ("B", "slew left ninety", [("l", 90)]),
    ("B", "inch it forward", [("bitF",)]),
    ("B", "all stop, all stop", [("stop",)]),
    ("B", "slew right, easy, about thirty degrees", [("r", 30)]),
    ("B", "travel back four metres", [("B", 4.0)]),
    ("B", "take it up to the top floor", "clarify"),                                    # place / impossible
    # ---- C  Agnieszka, Polish first language, hospital logistics: "no" = "well", "on left", "and after this"
    ("C", "no, go straight three meters", [("F", 3.0)]),
    ("C", "turn on left ninety degrees", [("l", 90)]),
    ("C", "dobrze, now go back one meter", [("B", 1.0)]),
    ("C", "kurcze, stop!", [("stop",)]),
    ("C", "turn to right side forty five degrees", [("r", 45)]),
    ("C", "go to the magazine", "clarify"),                                             # place (magazyn = store)
    ("C", "go forward two meters and after this turn on right", [("F", 2.0), ("r", 90)]),
    # ---- D  Ji-woo, Korean first language, semiconductor fab technician: "ne", verb last, "meter" / "degree"
    ("D", "ne, go straight two meter please", [("F", 2.0)]),
    ("D", "right turn, ninety degree", [("r", 90)]),
    ("D", "move backward a little please", [("bitB",)]),
    ("D", "aigoo, stop stop", [("stop",)]),
    ("D", "left side turn forty five degree", [("l", 45)]),
    ("D", "you go one point five meter front", [("F", 1.5)]),
    ("D", "go to the clean room", "clarify"),                                           # place
    # ---- E  Mike, airline captain using radio procedure: "niner", "fife", "wilco", "negative", headings
    ("E", "turn to heading one eight zero", [("face", S)]),
    ("E", "wilco, go forward fife metres", [("F", 5.0)]),
    ("E", "say position", [("get", "GetRobotPoseLast")]),
    ("E", "hold your position", [("stop",)]),
    ("E", "turn right niner zero degrees", [("r", 90)]),
    ("E", "turn right three zero, negative, left three zero", [("l", 30)]),
    ("E", "request you taxi to gate four", "clarify"),                                  # place
    # ---- F  Giulia, Italian first language, museum guard: "allora", "ecco", "basta", "at left", "of"
    ("F", "allora, turn at left, ninety degrees", [("l", 90)]),
    ("F", "go ahead for two meters, piano piano", [("F", 2.0)]),
    ("F", "basta, basta!", [("stop",)]),
    ("F", "ecco, now go back of one meter", [("B", 1.0)]),
    ("F", "turn at right of thirty degrees", [("r", 30)]),
    ("F", "go to the sala of the caravaggio", "clarify"),                               # place
    # ---- G  Dana, film camera operator directing the robot like a dolly: "dolly in/out", "track", "pan"
    ("G", "pan right forty five", [("r", 45)]),
    ("G", "dolly in two feet", [("F", 2 * FT)]),
    ("G", "track left three feet", [("L", 3 * FT)]),
    ("G", "and cut. hold it there", [("stop",)]),
    ("G", "dolly out a metre", [("B", 1.0)]),
    ("G", "tilt up a bit", "clarify"),                                                  # no tilt: out of scope
    # ---- H  a phone dictation on a noisy line: homophones, lost words, echoes
    ("H", "move forward for meters", [("F", 4.0)]),
    ("H", "turn left [inaudible] degrees", "clarify"),                                  # number lost
    ("H", "go back to meters", [("B", 2.0)]),
    ("H", "hello? can you hear me? stop", [("stop",)]),
    ("H", "turn right thirty degrees, sorry, the line's bad, thirty degrees right", [("r", 30)]),
    ("H", "uh-huh, now go forward one meter, one meter", [("F", 1.0)]),
    # ---- I  Tyler, Gen Z: "bet", "ngl", "fr", "lowkey", "no cap", "bro"
    ("I", "bet, go forward like three meters", [("F", 3.0)]),
    ("I", "ngl turn left real quick", [("l", 90)]),
    ("I", "bro stop fr", [("stop",)]),
    ("I", "lowkey back up two feet", [("B", 2 * FT)]),
    ("I", "do a full three sixty no cap", [("a", 360)]),
    ("I", "go to the vending machine", "clarify"),                                      # place
    # ---- J  Sam, Deaf, types in the chat in ASL-gloss order: verb last, "finish" = done, then
    ("J", "you forward two meter go", [("F", 2.0)]),
    ("J", "you left turn ninety", [("l", 90)]),
    ("J", "stop now stop", [("stop",)]),
    ("J", "back one meter move", [("B", 1.0)]),
    ("J", "turn right finish, forward three meter", [("r", 90), ("F", 3.0)]),
    ("J", "forty five degree right turn", [("r", 45)]),
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
        case = {"id": f"b9p-{spk}-{i:03d}", "map": "../prompts-9/maps/arena.yaml",
                "pose": [40.0, 10.0, yaw], "prompt": prompt, "expect": exp}
        check_case(case)
        out.append(case)
    assert len({c["prompt"] for c in out}) == len(out), "duplicate prompt"
    (HERE / "spoken.jsonl").write_text("".join(json.dumps(c) + "\n" for c in out))
    print(len(out), "cases")


if __name__ == "__main__":
    main()
