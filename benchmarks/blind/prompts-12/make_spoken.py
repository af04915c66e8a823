#!/usr/bin/env python3
"""Writes spoken.jsonl: 150 hand-written spoken motion prompts on the SCOUT arena map, from 10 NEW imagined
speakers (README.md), 15 each.  Spoken ones are written as a recognizer gives them (lowercase, fillers,
cut-off words with a dash, commas at pauses, numbers as words); H is a text-to-speech symbol board (AAC).
Expansion of meaning parts into expected commands: spoken_expand.py (copied unchanged from round 11's tooling).
Part notation: F/B metres forward/back; L/R metres to the side (sideways Move, or 90 deg Rotate + Move forward);
Ls/Rs metres sideways only; l/r degrees; a = a turn either way (180, 360); face = compass heading;
bitF/bitB/bitl/bitr = "a little"; far = beyond the arena wall (clarify, or the safe part); stop; get;
"clarify"; ("alt", A, B) = either reading is right.
Run: /work/main/.venv/bin/python make_spoken.py
"""
from spoken_expand import FT, IN, YD, CM, N, NE, E, SE, S, SW, W, NW, main

MM = 0.001
CASES = [
    # ---- A  Amir, accountant who stammers (repetitions, blocks, cut-off words as the recognizer writes them)
    ("A", "g- go go forward t- two metres", [("F", 2.0)]),
    ("A", "t-t-turn left, s-sorry, it's, it's the right, right, forty degrees", [("r", 40)]),
    ("A", "b- back, back up one metre", [("B", 1.0)]),
    ("A", "please st- st- stop", [("stop",)]),
    ("A", "turn, t- turn to f- face north", [("face", N)]),
    ("A", "move forward th- th- three feet and then t-turn left", [("F", 3 * FT), ("l", 90)]),
    ("A", "can you, can you go to the f- filing room", "clarify"),                       # place
    ("A", "t- turn all the way around, one eighty", [("a", 180)]),
    ("A", "forward a l- l- little bit", [("bitF",)]),
    ("A", "where, where are you right n- now", [("get", "GetRobotPoseLast")]),
    ("A", "go forward f- f- fifteen, no, fifty centimetres", [("F", 0.5)]),
    ("A", "take a ph- photo of the desk", "clarify"),                                     # photo only
    ("A", "turn right s-s-seventy five degrees", [("r", 75)]),
    ("A", "go left, l- left one metre", [("L", 1.0)]),
    ("A", "go forward um s- some distance", "clarify"),                                   # vague
    # ---- B  Kwame, Ghanaian taxi driver in Accra (Ghanaian English: chale, small small, go front, eii, herh)
    ("B", "chale go front two metres", [("F", 2.0)]),
    ("B", "eii, stop stop", [("stop",)]),
    ("B", "go front small small", [("bitF",)]),
    ("B", "reverse three feet, massa", [("B", 3 * FT)]),
    ("B", "turn by your right, ninety", [("r", 90)]),
    ("B", "make left turn and go front one metre", [("l", 90), ("F", 1.0)]),
    ("B", "go and pick my passenger at the junction", "clarify"),                         # place / out of scope
    ("B", "chale, turn face west side", [("face", W)]),
    ("B", "herh, turn back, one eighty", [("a", 180)]),
    ("B", "go front five metres, no wait, four metres", [("F", 4.0)]),
    ("B", "turn to your left small", [("bitl",)]),
    ("B", "where are you now, tell me", [("get", "GetRobotPoseLast")]),
    ("B", "take me to kaneshie market", "clarify"),                                       # place
    ("B", "face north-west, then go front two metres", [("face", NW), ("F", 2.0)]),
    ("B", "go sideways to the right half metre", [("R", 0.5)]),
    # ---- C  Dariush, Iranian carpet dealer (Persian first language: khob, merci, bas, "left hand", no plurals)
    ("C", "khob, please go forward two meter, merci", [("F", 2.0)]),
    ("C", "turn to the left hand forty five degree", [("l", 45)]),
    ("C", "please go back one and half meter", [("B", 1.5)]),
    ("C", "stop, stop, enough, bas", [("stop",)]),
    ("C", "turn to the right hand a little", [("bitr",)]),
    ("C", "please turn to direction of south", [("face", S)]),
    ("C", "go forward three meter and after turn right", [("F", 3.0), ("r", 90)]),
    ("C", "go and bring the blue carpet", "clarify"),                                     # out of scope
    ("C", "turn one complete round around yourself", [("a", 360)]),
    ("C", "khob, go forward eighty centimeter please", [("F", 0.8)]),
    ("C", "please turn to your back side", [("a", 180)]),
    ("C", "go forward six meter, no, sorry, seven", [("F", 7.0)]),
    ("C", "please show me the map of the place", [("get", "GetMap")]),
    ("C", "go to the left side one meter", [("L", 1.0)]),
    ("C", "go to the shop of my brother", "clarify"),                                     # place
    # ---- D  Earl, long-haul trucker on a CB radio (breaker, ten-four, come back, "what's your twenty", a hair)
    ("D", "breaker breaker, robot, pull ahead twelve feet, come back", [("F", 12 * FT)]),
    ("D", "ten-four, now back 'er down about six feet", [("B", 6 * FT)]),
    ("D", "what's your twenty, robot", [("get", "GetRobotPoseLast")]),
    ("D", "hang a left, ninety degrees", [("l", 90)]),
    ("D", "whoa whoa, shut 'er down", [("stop",)]),
    ("D", "swing her around, a one-eighty", [("a", 180)]),
    ("D", "put the hammer down and run to the truck stop", "clarify"),                    # place
    ("D", "hang a right about thirty degrees, over", [("r", 30)]),
    ("D", "point her east, over", [("face", E)]),
    ("D", "ease ahead just a hair", [("bitF",)]),
    ("D", "pull up twenty feet then hang a left", [("F", 20 * FT), ("l", 90)]),
    ("D", "pull ahead ten feet and snap me a picture of that rig", [("F", 10 * FT)]),      # photo part dropped
    ("D", "back her up a hair", [("bitB",)]),
    ("D", "head south fifteen feet, come back", [("face", S), ("F", 15 * FT)]),
    ("D", "roll on down the road a piece", "clarify"),                                    # vague amount
    # ---- E  Fiona, golf-course greenkeeper (yards, fore, dogleg, the green)
    ("E", "go forward ten yards", [("F", 10 * YD)]),
    ("E", "back up a yard and a half", [("B", 1.5 * YD)]),
    ("E", "turn left, like a dogleg, about forty-five", [("l", 45)]),
    ("E", "fore! stop!", [("stop",)]),
    ("E", "line up facing north-east", [("face", NE)]),
    ("E", "go to the seventh green", "clarify"),                                          # place
    ("E", "rake the bunker", "clarify"),                                                  # out of scope
    ("E", "go forward three yards and turn right", [("F", 3 * YD), ("r", 90)]),
    ("E", "just a touch forward", [("bitF",)]),
    ("E", "turn around and go five yards", [("a", 180), ("F", 5 * YD)]),
    ("E", "go forward two hundred yards", [("far", 200 * YD)]),                           # beyond the wall
    ("E", "turn right a hundred and twenty degrees", [("r", 120)]),
    ("E", "where are you on the course", [("get", "GetRobotPoseLast")]),
    ("E", "go sideways left two yards", [("L", 2 * YD)]),
    ("E", "go down to the, ah, go forward, forty feet", [("F", 40 * FT)]),
    # ---- F  Bernard, livestock auctioneer (chant: repeats, "do I hear", going once, sold)
    ("F", "forward two metres, do I hear two, two metres, sold", [("F", 2.0)]),
    ("F", "going once, going twice, turn left ninety", [("l", 90)]),
    ("F", "back one metre, one metre, one, thank you", [("B", 1.0)]),
    ("F", "right forty-five, forty-five, any advance on forty-five? no? right forty-five", [("r", 45)]),
    ("F", "hold it there, stop", [("stop",)]),
    ("F", "forward three, three and a half metres, three and a half", [("F", 3.5)]),
    ("F", "turn to face the south, lot twelve", [("face", S)]),
    ("F", "go up to the rostrum", "clarify"),                                             # place
    ("F", "turn round, all the way round, full circle", [("a", 360)]),
    ("F", "gently now, a touch to the right", [("bitr",)]),
    ("F", "forward five feet, five, now six, six feet", [("F", 6 * FT)]),
    ("F", "turn about, one-eighty", [("a", 180)]),
    ("F", "show the bidders a photo of lot forty", "clarify"),                            # photo only
    ("F", "where are we, where's the robot", [("get", "GetRobotPoseLast")]),
    ("F", "move along to somewhere over by the pens there", "clarify"),                   # vague / place
    # ---- G  Dr Lindqvist, surgeon testing a theatre robot (millimetres, "mil", advance / retract, terse)
    ("G", "advance five hundred millimetres", [("F", 500 * MM)]),
    ("G", "retract two hundred and fifty millimetres", [("B", 250 * MM)]),
    ("G", "rotate left, fifteen degrees", [("l", 15)]),
    ("G", "hold. stop.", [("stop",)]),
    ("G", "advance one point two metres", [("F", 1.2)]),
    ("G", "hand me the clamp", "clarify"),                                                # out of scope
    ("G", "rotate right ninety and advance sixty centimetres", [("r", 90), ("F", 0.6)]),
    ("G", "rotate fractionally to the left", [("bitl",)]),
    ("G", "orient to north", [("face", N)]),
    ("G", "advance one metre and hand me the retractor", [("alt", "clarify", [("F", 1.0)])]),  # out of scope + motion
    ("G", "reverse, uh, eight hundred mil- millimetres", [("B", 800 * MM)]),
    ("G", "rotate one hundred and eighty", [("a", 180)]),
    ("G", "status: where are you", [("get", "GetRobotPoseLast")]),
    ("G", "lateral shift right, thirty centimetres", [("R", 0.3)]),
    ("G", "advance to the incision site", "clarify"),                                     # place
    # ---- H  Zoe, uses a symbol-board AAC device (cerebral palsy); the device speaks word by word, telegraphic
    ("H", "robot. go. forward. two. metre.", [("F", 2.0)]),
    ("H", "robot. turn. left. now.", [("l", 90)]),
    ("H", "stop. stop. robot.", [("stop",)]),
    ("H", "go back. one. metre. please.", [("B", 1.0)]),
    ("H", "turn. right. 45. degree.", [("r", 45)]),
    ("H", "go. forward. little.", [("bitF",)]),
    ("H", "robot. turn. face. east.", [("face", E)]),
    ("H", "want. go. kitchen.", "clarify"),                                               # place
    ("H", "turn. around. please.", [("a", 180)]),
    ("H", "go forward. 3. metre. then. turn. right.", [("F", 3.0), ("r", 90)]),
    ("H", "where. you.", [("get", "GetRobotPoseLast")]),
    ("H", "go. forward. 5. no. 2. metre.", [("F", 2.0)]),
    ("H", "picture. take.", "clarify"),                                                   # photo only
    ("H", "turn. left. little.", [("bitl",)]),
    ("H", "go. north. 1. metre.", [("face", N), ("F", 1.0)]),
    # ---- I  Joost, Dutch bicycle mechanic (Dutch first language: hè, even, nee, toch, beetje, word order)
    ("I", "go two meters forward, hè", [("F", 2.0)]),
    ("I", "turn even a quarter to the left", [("l", 90)]),
    ("I", "nee, nee, stop now, hè", [("stop",)]),
    ("I", "drive one and a half meter backwards", [("B", 1.5)]),
    ("I", "turn to the right, thirty degrees, ja toch", [("r", 30)]),
    ("I", "go forward, nee, backward, fifty centimeter", [("B", 0.5)]),
    ("I", "turn half around", [("a", 180)]),
    ("I", "put the bike in the rack", "clarify"),                                         # out of scope
    ("I", "turn yourself to the south-west", [("face", SW)]),
    ("I", "go a little bit forward, beetje", [("bitF",)]),
    ("I", "turn a whole round", [("a", 360)]),
    ("I", "go to the workshop of henk", "clarify"),                                       # place
    ("I", "go three meter forward and then to the left", [("F", 3.0), ("l", 90)]),
    ("I", "shift one meter to the right side, without turning", [("Rs", 1.0)]),
    ("I", "show me where you have driven", [("get", "GetCurrentPath")]),
    # ---- J  Noa, Israeli start-up founder (Hebrew first language: yalla, achi, sababa, tachles, rega; blunt)
    ("J", "yalla, forward three meters", [("F", 3.0)]),
    ("J", "no no no, left, turn left sixty", [("l", 60)]),
    ("J", "stop, achi, stop", [("stop",)]),
    ("J", "go back two meters, sababa", [("B", 2.0)]),
    ("J", "tachles, turn right one hundred and thirty five", [("r", 135)]),
    ("J", "face north, then forward four meters", [("face", N), ("F", 4.0)]),
    ("J", "turn a little left, rega", [("bitl",)]),
    ("J", "bring me coffee from the kitchen", "clarify"),                                 # out of scope / place
    ("J", "go forward like, i don't know, some meters", "clarify"),                       # vague
    ("J", "turn around, full one-eighty", [("a", 180)]),
    ("J", "forward one point five, meters, yalla yalla", [("F", 1.5)]),
    ("J", "where are you, send me location", [("get", "GetRobotPoseLast")]),
    ("J", "turn right twenty, wait, rega, left twenty", [("l", 20)]),
    ("J", "move sideways left half a meter", [("L", 0.5)]),
    ("J", "what path did you do until now", [("get", "GetCurrentPath")]),
]

if __name__ == "__main__":
    assert len(CASES) == 150, len(CASES)
    for s in "ABCDEFGHIJ":
        assert sum(1 for c in CASES if c[0] == s) == 15, s
    main(CASES, "b12s")
