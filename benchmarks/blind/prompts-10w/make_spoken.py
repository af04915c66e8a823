#!/usr/bin/env python3
"""Writes spoken.jsonl: 150 hand-written spoken motion prompts on the SCOUT arena map, from 10 new
imagined speakers (README.md), 15 each.  Written in session 10 from the contract
(/work/shared/bench/README.md) before anyone ran them; dev material.
The expansion of meaning parts into expected commands (units, tolerances, compass, alternatives) is
spoken_expand.py, copied unchanged from prompts-9 (itself from earlier rounds).
Part notation: F/B metres forward/back; L/R metres to the side (sideways Move, or 90 deg Rotate +
Move forward); l/r degrees; a = a turn either way (180, 360); face = compass heading;
bitF/bitB/bitl/bitr = "a little"; stop; get = information command; "clarify" = ask / explain, run nothing.
Run: /work/main/.venv/bin/python make_spoken.py
"""
from spoken_expand import FT, IN, YD, CM, N, NE, E, SE, S, SW, W, NW, main

MM = 0.001

CASES = [
    # ---- A  Priya, Hindi first language, hospital pharmacist (Hinglish): "achha", "bas", "thoda", "nahi", "karo", "na"
    ("A", "achha, go straight two meter, haan", [("F", 2.0)]),
    ("A", "bas bas, stop it", [("stop",)]),
    ("A", "thoda sa left turn karo, just a little", [("bitl",)]),
    ("A", "arre, turn right ninety degree na", [("r", 90)]),
    ("A", "please go back one and half meter ji", [("B", 1.5)]),
    ("A", "ek minute, turn left, nahi nahi, right side forty five", [("r", 45)]),
    ("A", "chalo, go to the dispensary counter", "clarify"),                          # place
    ("A", "aage jao, do meter, two meter forward", [("F", 2.0)]),                      # do = two (Hindi), glossed
    ("A", "north ki taraf face karo", [("face", N)]),
    ("A", "one meter forward then turn left, theek hai", [("F", 1.0), ("l", 90)]),
    ("A", "peeche, back side, thirty centimetre only", [("B", 0.3)]),
    ("A", "where are you right now, batao", [("get", "GetRobotPoseLast")]),
    ("A", "please pick up the medicine box from the shelf", "clarify"),               # out of scope
    ("A", "turn around karo, full back side", [("a", 180)]),
    ("A", "go forward some more, haan", "clarify"),                                    # vague amount
    # ---- B  Mehmet, Turkish first language, night-shift baker: "hadi", "dur", "tamam", "şey", "yavaş yavaş", "hayır"
    ("B", "hadi, go forward three meter", [("F", 3.0)]),
    ("B", "dur, dur, stop", [("stop",)]),
    ("B", "şey, turn to left ninety", [("l", 90)]),
    ("B", "yavaş yavaş go back, half meter, slowly", [("B", 0.5)]),
    ("B", "tamam, now turn right thirty degree", [("r", 30)]),
    ("B", "go to the oven, abi", "clarify"),                                           # place
    ("B", "go front bir buçuk meter, one and half", [("F", 1.5)]),                     # glossed
    ("B", "turn for east, abi", [("face", E)]),
    ("B", "turn left forty, hayır, fifty degree", [("l", 50)]),
    ("B", "again turn right, ninety degree again", [("r", 90)]),
    ("B", "go forward two meter, after that again two meter", [("F", 2.0), ("F", 2.0)]),   # summed: 4 m
    ("B", "bring me the flour sack", "clarify"),                                       # out of scope
    ("B", "a little go forward, very little", [("bitF",)]),
    ("B", "turn to back side, one hundred eighty", [("a", 180)]),
    ("B", "go south two meter, tamam", [("face", S), ("F", 2.0)]),
    # ---- C  Lan, Vietnamese first language, seafood-plant shift lead: "nha", "rồi", "đi", "chút xíu", "không"
    ("C", "ok, go straight one meter nha", [("F", 1.0)]),
    ("C", "stop, stop rồi", [("stop",)]),
    ("C", "turn right chút xíu, little bit", [("bitr",)]),
    ("C", "three meter, go straight", [("F", 3.0)]),
    ("C", "left turn ninety, đi", [("l", 90)]),
    ("C", "không không, turn right, not left, sixty", [("r", 60)]),
    ("C", "go to the freezer room nha", "clarify"),                                    # place
    ("C", "back two meter, slowly nha", [("B", 2.0)]),
    ("C", "you turn, face to west", [("face", W)]),
    ("C", "go forward one point five meter then turn left", [("F", 1.5), ("l", 90)]),
    ("C", "go more, more", "clarify"),                                                 # no amount
    ("C", "now you where? tell me position", [("get", "GetRobotPoseLast")]),
    ("C", "turn one circle, full", [("a", 360)]),
    ("C", "forty centimeter forward, đi", [("F", 0.4)]),
    ("C", "you wash the floor here", "clarify"),                                       # out of scope
    # ---- D  Mr Adeyemi, Yoruba first language, university lab technician in Ibadan: "oya", "ehn", "o", "sha", "small"
    ("D", "oya, move forward two metres o", [("F", 2.0)]),
    ("D", "ehn ehn, stop there", [("stop",)]),
    ("D", "turn left small, just small", [("bitl",)]),
    ("D", "go backwards one metre sha", [("B", 1.0)]),
    ("D", "turn right forty five degrees o", [("r", 45)]),
    ("D", "oya face south now", [("face", S)]),
    ("D", "move to the fume cupboard", "clarify"),                                     # place
    ("D", "go forward, ehn, let me see, three metres", [("F", 3.0)]),
    ("D", "turn to your right hand side, ninety", [("r", 90)]),
    ("D", "turn left thirty, ehn no, make it sixty", [("l", 60)]),
    ("D", "move forward four feet and turn right o", [("F", 4 * FT), ("r", 90)]),
    ("D", "snap the bench for me", "clarify"),                                         # photo only
    ("D", "turn around o, the other way", [("a", 180)]),
    ("D", "oya, where you dey now sef?", [("get", "GetRobotPoseLast")]),
    ("D", "shift small to your left, like half metre", [("L", 0.5)]),
    # ---- E  Carol, hotel night manager, ANGRY at a robot that keeps misbehaving
    ("E", "no no no, STOP", [("stop",)]),
    ("E", "I said turn LEFT, ninety degrees, left", [("l", 90)]),
    ("E", "for heaven's sake, back up one metre", [("B", 1.0)]),
    ("E", "not that way, the other way, turn right forty five", [("r", 45)]),
    ("E", "just go forward two metres, is that so hard", [("F", 2.0)]),
    ("E", "turn around, you useless tin can", [("a", 180)]),
    ("E", "get out of my lobby", "clarify"),                                          # place
    ("E", "forward three feet. THREE. not thirty", [("F", 3 * FT)]),
    ("E", "turn right twenty degrees, no, thirty, honestly", [("r", 30)]),
    ("E", "go over there", "clarify"),                                                 # vague place
    ("E", "again, turn left ninety, and this time actually do it", [("l", 90)]),
    ("E", "what path are you even on", [("get", "GetCurrentPath")]),
    ("E", "back up two feet and then stop moving", [("B", 2 * FT)]),
    ("E", "face east and stay there", [("face", E)]),
    ("E", "why do you keep doing that", "clarify"),                                    # question, no command
    # ---- F  Ben, QA intern READING a printed test sheet aloud: "step N", abbreviations read out, "c w", "heading"
    ("F", "step one, drive forward two m", [("F", 2.0)]),
    ("F", "step two, rotate ninety deg c w", [("r", 90)]),
    ("F", "step three, rotate forty five degrees counter clockwise", [("l", 45)]),
    ("F", "step four, reverse zero point five metres", [("B", 0.5)]),
    ("F", "step five, halt", [("stop",)]),
    ("F", "step six, capture an image, um, that's the camera one", "clarify"),         # photo only
    ("F", "step seven, orient to heading north", [("face", N)]),
    ("F", "step eight, translate one metre to the right, lateral", [("R", 1.0)]),
    ("F", "step nine, drive forward one point two metres then rotate one eighty", [("F", 1.2), ("a", 180)]),
    ("F", "step ten, report pose", [("get", "GetRobotPoseLast")]),
    ("F", "step eleven, perform a full rotation, three six zero degrees", [("a", 360)]),
    ("F", "step twelve, drive forward five hundred millimetres", [("F", 500 * MM)]),
    ("F", "step thirteen, dock at the charging station", "clarify"),                   # place
    ("F", "step fourteen, rotate clockwise by, uh, fifteen degrees, sorry, the sheet says twenty", [("r", 20)]),
    ("F", "step fifteen, drive forward, and the distance is blank on my sheet", "clarify"),  # no amount
    # ---- G  Dave, bottling-plant line operator on a headset; a poor recogniser in the noise (homophones, tags)
    ("G", "go forward to meters", [("F", 2.0)]),                                       # to = two
    ("G", "turn write nine tee degrees", [("r", 90)]),                                   # write = right
    ("G", "move back for feet", [("B", 4 * FT)]),                                      # for = four
    ("G", "stop stop stop stop stop", [("stop",)]),
    ("G", "turn left for tee five degrees", [("l", 45)]),                              # forty five
    ("G", "go forward [noise] metres", "clarify"),                                     # number lost
    ("G", "turn to your three o'clock", [("r", 90)]),                                  # clock
    ("G", "turn to your ten o'clock", [("l", 60)]),                                    # clock
    ("G", "back up won meter", [("B", 1.0)]),                                          # won = one
    ("G", "turn right, um, a tad", [("bitr",)]),
    ("G", "go forward six feet and turn to the left", [("F", 6 * FT), ("l", 90)]),
    ("G", "face nor west", [("face", NW)]),
    ("G", "go forward eight feet [clanking] and then turn right", [("F", 8 * FT), ("r", 90)]),
    ("G", "go over to line three", "clarify"),                                         # place
    ("G", "turn around one eighty", [("a", 180)]),
    # ---- H  Jess, wedding caterer IN A HURRY: clipped, "go go go", "quick", no politeness
    ("H", "quick, forward three metres, go go go", [("F", 3.0)]),
    ("H", "stop stop, hang on", [("stop",)]),
    ("H", "left, ninety, quick", [("l", 90)]),
    ("H", "back a metre, move", [("B", 1.0)]),
    ("H", "go to the marquee", "clarify"),                                             # place
    ("H", "right forty five now now now", [("r", 45)]),
    ("H", "come on, two metres forward then left", [("F", 2.0), ("l", 90)]),
    ("H", "turn around and go two metres, hurry", [("a", 180), ("F", 2.0)]),
    ("H", "face south quick", [("face", S)]),
    ("H", "forward a foot, no, two feet", [("F", 2 * FT)]),
    ("H", "carry these plates to table six", "clarify"),                               # out of scope + place
    ("H", "little bit forward, quick", [("bitF",)]),
    ("H", "go east three metres, hurry up", [("face", E), ("F", 3.0)]),
    ("H", "another metre forward", [("F", 1.0)]),
    ("H", "turn right, then forward four metres, then right again", [("r", 90), ("F", 4.0), ("r", 90)]),
    # ---- I  Tom, exhausted new father at 4 am: mumbling, trailing off, "like", "I guess", apologising
    ("I", "mm, go forward like one metre", [("F", 1.0)]),
    ("I", "okay stop, shh", [("stop",)]),
    ("I", "turn... left, yeah, left, ninety", [("l", 90)]),
    ("I", "back up a tiny bit, quietly", [("bitB",)]),
    ("I", "go check on the baby", "clarify"),                                          # place
    ("I", "turn right I guess, thirty degrees", [("r", 30)]),
    ("I", "just, uh, forward two feet", [("F", 2 * FT)]),
    ("I", "turn around, sorry, I'm half asleep", [("a", 180)]),
    ("I", "go forward one and a half metres and then... stop there", [("F", 1.5)]),
    ("I", "where even are you", [("get", "GetRobotPoseLast")]),
    ("I", "face, um, east? yeah east", [("face", E)]),
    ("I", "turn left a bit more", [("bitl",)]),
    ("I", "forward three metres, no wait, two", [("F", 2.0)]),
    ("I", "make me a bottle", "clarify"),                                              # out of scope
    ("I", "turn right sixty and go forward a metre", [("r", 60), ("F", 1.0)]),
    # ---- J  Rhona, land surveyor: decimals, bearings, "offset", "chain forward", clock directions
    ("J", "advance two point four metres", [("F", 2.4)]),
    ("J", "face grid north", [("face", N)]),
    ("J", "turn to bearing one eight zero", [("face", S)]),                            # bearing = compass
    ("J", "bearing two seven zero, then go ten metres", [("face", W), ("F", 10.0)]),
    ("J", "rotate clockwise twelve and a half degrees", [("r", 12.5)]),
    ("J", "set up over the benchmark", "clarify"),                                     # place
    ("J", "reverse one point zero five metres", [("B", 1.05)]),
    ("J", "offset left one point five metres", [("L", 1.5)]),
    ("J", "hold there", [("stop",)]),
    ("J", "read me your coordinates", [("get", "GetRobotPoseLast")]),
    ("J", "face southeast and chain forward twenty metres", [("face", SE), ("F", 20.0)]),
    ("J", "turn anticlockwise seven and a half degrees", [("l", 7.5)]),
    ("J", "walk it out to the tree line", "clarify"),                                  # place
    ("J", "turn to your two o'clock and go five metres", [("r", 60), ("F", 5.0)]),     # clock
    ("J", "take a photo of the peg and turn left ninety", [("l", 90)]),                # motion + photo
]

if __name__ == "__main__":
    assert len(CASES) == 150, len(CASES)
    for s in "ABCDEFGHIJ":
        assert sum(1 for c in CASES if c[0] == s) == 15, s
    main(CASES, "d10w")
