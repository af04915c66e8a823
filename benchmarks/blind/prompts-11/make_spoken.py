#!/usr/bin/env python3
"""Writes spoken.jsonl: 150 hand-written spoken motion prompts on the SCOUT arena map, from 10 new
imagined speakers (README.md), 15 each.  Spoken ones are transcribed as a recognizer gives them
(lowercase, fillers, restarts, commas at pauses, numbers as words); H types pseudo-code in a terminal.
The expansion of meaning parts into expected commands is spoken_expand.py, copied unchanged from the
previous round's tooling (/work/main/benchmarks/blind/prompts-9/).
Part notation: F/B metres forward/back; L/R metres to the side (sideways Move, or 90 deg Rotate +
Move forward); l/r degrees; a = a turn either way (180, 360); face = compass heading;
bitF/bitB/bitl/bitr = "a little"; far = a forward move beyond the arena wall (clarify, or the safe part);
stop; get = information command; "clarify" = ask / explain and run nothing;
("alt", A, B) = either reading is right (e.g. "clarify" or the safe part of a request).
Run: /work/main/.venv/bin/python make_spoken.py
"""
from spoken_expand import FT, IN, YD, CM, N, NE, E, SE, S, SW, W, NW, main

CASES = [
    # ---- A  Maya, 9, driving the robot at a science-museum open day (child: "like", "um", big numbers, "please mister robot")
    ("A", "um robot go forward like two metres", [("F", 2.0)]),
    ("A", "now turn left", [("l", 90)]),
    ("A", "go backwards three metres please mister robot", [("B", 3.0)]),
    ("A", "go forward a hundred metres", [("far", 100.0)]),                                 # beyond the wall
    ("A", "can you do a dance", "clarify"),                                                   # out of scope
    ("A", "turn right um um fifty", [("r", 50)]),
    ("A", "go forward five giant steps", "clarify"),                                          # not a unit
    ("A", "spin all the way round in a whole circle", [("a", 360)]),
    ("A", "stop robot stop", [("stop",)]),
    ("A", "go to my mum", "clarify"),                                                         # place the map cannot know
    ("A", "turn around and go forward one metre", [("a", 180), ("F", 1.0)]),
    ("A", "are you lost where are you", [("get", "GetRobotPoseLast")]),
    ("A", "go forward four, no, six metres", [("F", 6.0)]),
    ("A", "turn a teeny tiny bit to the left", [("bitl",)]),
    ("A", "face north robot", [("face", N)]),
    # ---- B  Luis, Mexican landscaper (Spanish first language), Spanglish; glosses most Spanish amounts
    ("B", "ándale, go forward two meters", [("F", 2.0)]),
    ("B", "turn right, a la derecha, forty five degrees", [("r", 45)]),
    ("B", "back up un poquito, a little", [("bitB",)]),
    ("B", "ya, ya, stop ahí", [("stop",)]),
    ("B", "go to the big tree, el árbol", "clarify"),                                         # place
    ("B", "órale, go forward ten feet", [("F", 10 * FT)]),
    ("B", "turn left, no, perdón, right, ninety", [("r", 90)]),
    ("B", "pick up the leaves there", "clarify"),                                             # out of scope
    ("B", "go straight three meters and then turn to the left", [("F", 3.0), ("l", 90)]),
    ("B", "move back one meter, un metro", [("B", 1.0)]),
    ("B", "turn to face the south, al sur", [("face", S)]),
    ("B", "go forward, eh, como, seven", "clarify"),                                         # missing unit
    ("B", "move to your right two feet", [("R", 2 * FT)]),
    ("B", "turn around, la vuelta", [("a", 180)]),
    ("B", "forward a little bit más, poquito", [("bitF",)]),
    # ---- C  Wei, logistics coordinator, Mandarin first language: no plurals, "first ... then", "one circle"
    ("C", "you go straight three meter first, then turn left", [("F", 3.0), ("l", 90)]),
    ("C", "you turn right side, forty-five degree", [("r", 45)]),
    ("C", "go back one point five meter", [("B", 1.5)]),
    ("C", "stop stop stop", [("stop",)]),
    ("C", "go forward two meter, ah no, three meter", [("F", 3.0)]),
    ("C", "turn to east side", [("face", E)]),
    ("C", "walk to south two meter", [("face", S), ("F", 2.0)]),
    ("C", "where you are now", [("get", "GetRobotPoseLast")]),
    ("C", "turn one circle", [("a", 360)]),
    ("C", "go forward little bit only", [("bitF",)]),
    ("C", "go to loading dock number three", "clarify"),                                     # place
    ("C", "turn left side one hundred twenty degree", [("l", 120)]),
    ("C", "how is the map now, show me", [("get", "GetMap")]),
    ("C", "you take photo for me of the pallet", "clarify"),                                 # photo only
    ("C", "go forward eighty centimeter", [("F", 0.8)]),
    # ---- D  Ruth, sign-language interpreter relaying for a Deaf site engineer (third person: "she says")
    ("D", "she says go forward four metres", [("F", 4.0)]),
    ("D", "she wants you to turn left thirty degrees", [("l", 30)]),
    ("D", "he's asking where you are right now", [("get", "GetRobotPoseLast")]),
    ("D", "she says turn left, sorry, she signed right, forty degrees", [("r", 40)]),
    ("D", "she's asking for a photo of the control panel", "clarify"),                       # photo only
    ("D", "she says stop, stop there", [("stop",)]),
    ("D", "she wants you facing north-west", [("face", NW)]),
    ("D", "he says back up two metres and then turn around", [("B", 2.0), ("a", 180)]),
    ("D", "she says go over there", "clarify"),                                               # pointing: vague
    ("D", "she says move a metre and a half to your left", [("L", 1.5)]),
    ("D", "he'd like you to go to the site office", "clarify"),                              # place
    ("D", "she says turn right a little", [("bitr",)]),
    ("D", "he says go forward twelve feet", [("F", 12 * FT)]),
    ("D", "she's asking what route you're taking", [("get", "GetCurrentPath")]),
    ("D", "she says go east five metres", [("face", E), ("F", 5.0)]),
    # ---- E  Rosa, ballet teacher in the school hall: quarter / half / eighth turns, counts
    ("E", "and a quarter turn to the right", [("r", 90)]),
    ("E", "half turn, either way, darling", [("a", 180)]),
    ("E", "three quarter turn to the left", [("l", 270)]),
    ("E", "an eighth of a turn to the left", [("l", 45)]),
    ("E", "five, six, seven, eight, travel forward two metres", [("F", 2.0)]),
    ("E", "and a full pirouette", [("a", 360)]),
    ("E", "step back just a touch", [("bitB",)]),
    ("E", "and hold. hold it", [("stop",)]),
    ("E", "take it from the top", "clarify"),                                                 # vague
    ("E", "a quarter turn", "clarify"),                                                       # no direction
    ("E", "go to the barre", "clarify"),                                                      # place
    ("E", "glide forward one metre, then quarter turn left", [("F", 1.0), ("l", 90)]),
    ("E", "and face the south wall", [("face", S)]),
    ("E", "back four metres, nice and slow", [("B", 4.0)]),
    ("E", "turn right, twenty degrees, lovely", [("r", 20)]),
    # ---- F  Dev, air-traffic controller trying ground-robot phraseology: digit-by-digit numbers, "hold position"
    ("F", "robot one, taxi forward two zero metres", [("F", 20.0)]),
    ("F", "robot one, turn right three zero degrees", [("r", 30)]),
    ("F", "robot one, hold position", [("stop",)]),
    ("F", "robot one, say position", [("get", "GetRobotPoseLast")]),
    ("F", "robot one, turn left one two zero degrees", [("l", 120)]),
    ("F", "robot one, correction, turn right one five, not five zero", [("r", 15)]),
    ("F", "robot one, back up three metres, three", [("B", 3.0)]),
    ("F", "robot one, turn to face due west", [("face", W)]),
    ("F", "robot one, proceed forward niner metres", [("F", 9.0)]),
    ("F", "robot one, taxi to stand four", "clarify"),                                        # place
    ("F", "robot one, turn left two seven zero degrees", [("l", 270)]),
    ("F", "robot one, proceed north four metres", [("face", N), ("F", 4.0)]),
    ("F", "robot one, expedite, forward five zero metres", [("far", 50.0)]),                  # beyond the wall
    ("F", "robot one, sidestep right one metre", [("R", 1.0)]),
    ("F", "robot one, turn, uh, four five degrees", "clarify"),                              # no direction
    # ---- G  Sandro, head chef testing a kitchen runner robot: "behind", "heard", "yes chef"
    ("G", "behind! back up two feet", [("B", 2 * FT)]),
    ("G", "forward, forward, three feet, yes chef", [("F", 3 * FT)]),
    ("G", "turn left, hands, ninety", [("l", 90)]),
    ("G", "eighty-six that, stop", [("stop",)]),
    ("G", "go to the pass", "clarify"),                                                       # place
    ("G", "go in the walk-in", "clarify"),                                                    # place
    ("G", "heard, now turn right forty", [("r", 40)]),
    ("G", "bring table six their soup", "clarify"),                                           # out of scope
    ("G", "go forward a metre and grab the tray", [("alt", "clarify", [("F", 1.0)])]),       # safe part
    ("G", "turn a little to the right, yes chef", [("bitr",)]),
    ("G", "turn around, I need you facing the other way", [("a", 180)]),
    ("G", "move over to the left eighteen inches", [("L", 18 * IN)]),
    ("G", "go forward six feet then turn right", [("F", 6 * FT), ("r", 90)]),
    ("G", "chef wants you facing east", [("face", E)]),
    ("G", "take a photo of this plate for the menu", "clarify"),                             # photo only
    # ---- H  Tomasz, software developer TYPING pseudo-code into the robot's terminal
    ("H", "move_forward(1.5m)", [("F", 1.5)]),
    ("H", "rotate(left, 45deg)", [("l", 45)]),
    ("H", "fwd 2m; rot right 90", [("F", 2.0), ("r", 90)]),
    ("H", "emergency_stop()", [("stop",)]),
    ("H", "get_pose()", [("get", "GetRobotPoseLast")]),
    ("H", "rotate(right, 30) // typo, meant left", [("l", 30)]),
    ("H", "repeat 3x: forward 0.5 m", [("F", 1.5)]),
    ("H", "goto(kitchen)", "clarify"),                                                        # place
    ("H", "backward(40cm)", [("B", 0.4)]),
    ("H", "forward(6)", "clarify"),                                                           # missing unit
    ("H", "turn_to(heading=south)", [("face", S)]),
    ("H", "strafe_left(0.75 m)", [("L", 0.75)]),
    ("H", "rotate_in_place(360deg)", [("a", 360)]),
    ("H", "capture_image()", "clarify"),                                                      # photo only
    ("H", "forward(3ft); turn_right(15deg)", [("F", 3 * FT), ("r", 15)]),
    # ---- I  Thandi, South African mine safety officer: "ja", "eish", "just now", "shame", "is it"
    ("I", "ja, go forward two metres", [("F", 2.0)]),
    ("I", "eish, stop, stop there", [("stop",)]),
    ("I", "turn left just now, ninety degrees", [("l", 90)]),
    ("I", "go to the robot and turn left", "clarify"),                                       # 'robot' = traffic light: place
    ("I", "reverse one and a half metres", [("B", 1.5)]),
    ("I", "turn right by sixty, ja", [("r", 60)]),
    ("I", "ag shame, you went too far, back up a bit", [("bitB",)]),
    ("I", "go forward, um, ten feet", [("F", 10 * FT)]),
    ("I", "where are you standing now", [("get", "GetRobotPoseLast")]),
    ("I", "ja, face south-east now", [("face", SE)]),
    ("I", "go up to the shaft entrance", "clarify"),                                         # place
    ("I", "turn left twenty, no, left thirty five", [("l", 35)]),
    ("I", "now now, go forward four metres and stop", [("F", 4.0)]),
    ("I", "check if the air is okay there", "clarify"),                                      # out of scope
    ("I", "go right two metres sideways", [("R", 2.0)]),
    # ---- J  Giulia, Italian architect surveying an old church (Italian first language): "of", "allora", "basta"
    ("J", "go ahead of two meters", [("F", 2.0)]),
    ("J", "turn on the left of thirty degrees", [("l", 30)]),
    ("J", "basta, basta, stop", [("stop",)]),
    ("J", "go back a little, piano piano", [("bitB",)]),
    ("J", "make a complete turn on yourself", [("a", 360)]),
    ("J", "allora, go forward one meter and half", [("F", 1.5)]),
    ("J", "ecco, turn right of ninety, no, sixty", [("r", 60)]),
    ("J", "go near the altar", "clarify"),                                                    # place
    ("J", "turn of one hundred eighty degrees", [("a", 180)]),
    ("J", "go towards west for three meters", [("face", W), ("F", 3.0)]),
    ("J", "you can show me the map, please", [("get", "GetMap")]),
    ("J", "go ahead some meters", "clarify"),                                                 # vague
    ("J", "turn on the right a little", [("bitr",)]),
    ("J", "measure the width of the nave", "clarify"),                                        # out of scope
    ("J", "go ahead of fifty centimeters and turn on the left", [("F", 0.5), ("l", 90)]),
]

if __name__ == "__main__":
    assert len(CASES) == 150, len(CASES)
    for s in "ABCDEFGHIJ":
        assert sum(1 for c in CASES if c[0] == s) == 15, s
    main(CASES, "b11s")
