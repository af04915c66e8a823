#!/usr/bin/env python3
"""Writes spoken.jsonl: 150 hand-written spoken motion prompts on the SCOUT arena map, from 10
imagined speakers (README.md), 15 each.  Eight are real people talking to a robot during a task,
transcribed as speech recognition gives it (lowercase, fillers, restarts, commas at pauses, numbers as
words, a few recognition slips); two are distinctive (a man who types in capitals, a drill instructor).
The expansion of meaning parts into expected commands (units, tolerances, compass, alternatives) is
spoken_expand.py, copied unchanged from the seventh blind set (itself from the third to sixth).
Part notation: F/B metres forward/back; L/R metres to the side (sideways Move, or 90 deg Rotate +
Move forward); l/r degrees; a = a turn either way (180, 360); face = compass heading;
bitF/bitB/bitl/bitr = "a little"; far = a forward move beyond the arena wall (clarify, or the safe part);
stop; get = information command; "clarify" = ask / explain and run nothing.
Run: /work/main/.venv/bin/python make_spoken.py
"""
from spoken_expand import FT, IN, YD, CM, N, NE, E, SE, S, SW, W, NW, main

CASES = [
    # ---- A  Bronwyn, Australian greenhouse grower (farm): "righto", "chuck a left", "reckon", "yeah nah"
    ("A", "righto, go forward two metres", [("F", 2.0)]),
    ("A", "chuck a left", [("l", 90)]),
    ("A", "whoa, hang about, stop", [("stop",)]),
    ("A", "go up the row, um, six metres or so", [("F", 6.0)]),
    ("A", "chuck a u-ey", [("a", 180)]),
    ("A", "back up a bit, you're in the tomatoes", [("bitB",)]),
    ("A", "turn right, uh, forty five degrees", [("r", 45)]),
    ("A", "go down to the shed", "clarify"),                                           # place
    ("A", "face east, then go forward ten metres", [("face", E), ("F", 10.0)]),
    ("A", "go forward, nah, backwards, one and a half metres", [("B", 1.5)]),
    ("A", "go up two rows", "clarify"),                                                # unknown unit
    ("A", "turn left twenty degrees and then go forward tree metres", [("l", 20), ("F", 3.0)]),
    ("A", "head up there a good way, i reckon", "clarify"),                            # vague amount
    ("A", "move to your right one metre, mind the hose", [("R", 1.0)]),
    ("A", "where are ya now", [("get", "GetRobotPoseLast")]),
    # ---- B  Gary, London hospital porter in the basement corridors: "right then", "swing round", feet
    ("B", "right then, straight on, thirty feet", [("F", 30 * FT)]),
    ("B", "hang on a tick, stop", [("stop",)]),
    ("B", "swing round to your left, ninety", [("l", 90)]),
    ("B", "back it up two foot", [("B", 2 * FT)]),
    ("B", "take it down to x-ray", "clarify"),                                          # place
    ("B", "mind the bed, come left a foot", [("L", FT)]),
    ("B", "turn it round", [("a", 180)]),
    ("B", "go forward five metres then bear right ninety", [("F", 5.0), ("r", 90)]),
    ("B", "face north, mate", [("face", N)]),
    ("B", "nudge forward six inches", [("F", 6 * IN)]),
    ("B", "where've you got to", [("get", "GetRobotPoseLast")]),
    ("B", "swing it left, clockwise like, forty degrees", "clarify"),                  # contradiction
    ("B", "turn right forty, no, fifty degrees", [("r", 50)]),
    ("B", "forward, um, ten feet, then left thirty", [("F", 10 * FT), ("l", 30)]),
    ("B", "back up, uh, four", "clarify"),                                             # missing unit
    # ---- C  Ingrid, museum conservator checking the galleries at night: careful, centimetres
    ("C", "very carefully, forward fifty centimetres", [("F", 0.5)]),
    ("C", "rotate left fifteen degrees, slowly", [("l", 15)]),
    ("C", "stop, that's close enough", [("stop",)]),
    ("C", "back away thirty centimetres please", [("B", 0.3)]),
    ("C", "could you go over to the egyptian gallery", "clarify"),                     # place
    ("C", "i need a raking light image of the panel", "clarify"),                      # photo only
    ("C", "turn right, um, five degrees, just five", [("r", 5)]),
    ("C", "forward one metre twenty", [("F", 1.2)]),
    ("C", "turn to face south, and then go forward two metres", [("face", S), ("F", 2.0)]),
    ("C", "slide to your left about forty centimetres", [("L", 0.4)]),
    ("C", "inch forward, just a little", [("bitF",)]),
    ("C", "turn one hundred and twenty degrees to the right", [("r", 120)]),
    ("C", "forward another twenty centimetres", [("F", 0.2)]),
    ("C", "turn, um, sixty degrees", "clarify"),                                        # no direction
    ("C", "could you tell me your current position", [("get", "GetRobotPoseLast")]),
    # ---- D  Jess, streaming the robot from her flat: talks to the chat, "like", feet
    ("D", "okay chat, watch this, robot, go forward three feet", [("F", 3 * FT)]),
    ("D", "spin all the way around", [("a", 360)]),
    ("D", "chat says turn left, okay, turn left forty five", [("l", 45)]),
    ("D", "whoa, okay, stop", [("stop",)]),
    ("D", "okay now turn like ninety degrees", "clarify"),                              # no direction
    ("D", "back up like two feet", [("B", 2 * FT)]),
    ("D", "turn right ninety and go forward six feet", [("r", 90), ("F", 6 * FT)]),
    ("D", "someone in chat wants a selfie, take a picture of me", "clarify"),          # photo only
    ("D", "okay, go forward, um, four point five feet", [("F", 4.5 * FT)]),
    ("D", "okay do a one eighty for the stream", [("a", 180)]),
    ("D", "go left three feet", [("L", 3 * FT)]),
    ("D", "turn a little bit to the right", [("bitr",)]),
    ("D", "go forward like a lot", "clarify"),                                          # vague amount
    ("D", "okay now face west for me", [("face", W)]),
    ("D", "turn left seventy five degrees then go forward two yards", [("l", 75), ("F", 2 * YD)]),
    # ---- E  Chinedu, Nigerian English, facility manager at a Lagos warehouse: "oya", "go front", "small"
    ("E", "oya, go front two metres", [("F", 2.0)]),
    ("E", "turn your left hand side ninety degrees", [("l", 90)]),
    ("E", "reverse small", [("bitB",)]),
    ("E", "abeg stop there", [("stop",)]),
    ("E", "go to the store room", "clarify"),                                            # place
    ("E", "no, not right, na left i talk, turn left thirty degrees", [("l", 30)]),
    ("E", "move forward five metres, then turn right hand side", [("F", 5.0), ("r", 90)]),
    ("E", "reverse one metre", [("B", 1.0)]),
    ("E", "face north side", [("face", N)]),
    ("E", "go front like ten feet", [("F", 10 * FT)]),
    ("E", "turn around make you face me", [("a", 180)]),
    ("E", "snap the pallet for me", "clarify"),                                          # photo only
    ("E", "shift to your right hand side one metre", [("R", 1.0)]),
    ("E", "move forward three", "clarify"),                                              # missing unit
    ("E", "where you dey now", [("get", "GetRobotPoseLast")]),
    # ---- F  Mei Ling, Singaporean English, night cleaning supervisor in a shopping mall: "lah", "can", "abit"
    ("F", "go straight two metre lah", [("F", 2.0)]),
    ("F", "turn left can, ninety degree", [("l", 90)]),
    ("F", "aiyo, reverse a bit", [("bitB",)]),
    ("F", "stop stop, enough already", [("stop",)]),
    ("F", "face east lah", [("face", E)]),
    ("F", "turn right forty five degree then go straight three metre", [("r", 45), ("F", 3.0)]),
    ("F", "go straight one more metre", [("F", 1.0)]),
    ("F", "u-turn lah", [("a", 180)]),
    ("F", "now face south can", [("face", S)]),
    ("F", "go straight eight metre then turn left, then go straight two metre", [("F", 8.0), ("l", 90), ("F", 2.0)]),
    ("F", "move left side half metre", [("L", 0.5)]),
    ("F", "turn right, turn left, aiya, turn right sixty degree", [("r", 60)]),
    ("F", "go straight abit", [("bitF",)]),
    ("F", "take photo of the floor there, got stain", "clarify"),                        # photo only
    ("F", "turn clockwise eighty degree", [("r", 80)]),
    # ---- G  Priscilla, estate agent giving a remote client a video tour of a house: "pop", "lovely", feet
    ("G", "and if we just pop forward about six feet", [("F", 6 * FT)]),
    ("G", "lovely, now give it a little turn to the left", [("bitl",)]),
    ("G", "let's have a look at the view, turn around", [("a", 180)]),
    ("G", "and let's go forward fifteen feet", [("F", 15 * FT)]),
    ("G", "get a nice shot of that fireplace", "clarify"),                                # photo only
    ("G", "okay, go forward ten feet and then turn right about ninety degrees", [("F", 10 * FT), ("r", 90)]),
    ("G", "scoot back eighteen inches", [("B", 18 * IN)]),
    ("G", "just pan to the right thirty degrees", [("r", 30)]),
    ("G", "face north so they can see the light", [("face", N)]),
    ("G", "if we go left five feet", [("L", 5 * FT)]),
    ("G", "go about twelve feet forward and snap a photo", [("F", 12 * FT)]),
    ("G", "back up five feet, sorry, it's a bit tight in here", [("B", 5 * FT)]),
    ("G", "and stop right there", [("stop",)]),
    ("G", "go forward eight feet, then turn left forty five", [("F", 8 * FT), ("l", 45)]),
    ("G", "turn about twenty degrees counterclockwise", [("l", 20)]),
    # ---- H  Dennis, retired, types in capitals with full stops and sign-offs
    ("H", "PLEASE MOVE FORWARD 2 METRES.  THANK YOU.", [("F", 2.0)]),
    ("H", "TURN RIGHT 90 DEGREES PLEASE.", [("r", 90)]),
    ("H", "STOP THE ROBOT.", [("stop",)]),
    ("H", "WHERE ARE YOU NOW?", [("get", "GetRobotPoseLast")]),
    ("H", "SHOW ME THE MAP PLEASE.", [("get", "GetMap")]),
    ("H", "MOVE BACKWARDS 1 FOOT 6 INCHES.", [("B", 18 * IN)]),
    ("H", "PLEASE TURN TO FACE EAST.", [("face", E)]),
    ("H", "GO FORWARD 5.", "clarify"),                                                  # missing unit
    ("H", "TURN LEFT 30 DEGREES AND THEN GO FORWARD 4 METRES. REGARDS, DENNIS", [("l", 30), ("F", 4.0)]),
    ("H", "PLEASE TURN LEFT 180 DEGREES.", [("a", 180)]),
    ("H", "TURN AROUND COMPLETELY. 360 DEGREES.", [("a", 360)]),
    ("H", "MOVE FORWARD 3 YARDS.", [("F", 3 * YD)]),
    ("H", "TURN RIGHT 270 DEGREES.", [("r", 270)]),
    ("H", "GO BACK 50 CM PLEASE", [("B", 0.5)]),
    ("H", "TURN LEFT 15 DEGREES CLOCKWISE.", "clarify"),                               # contradiction
    # ---- I  Kenji, Japanese first language, inspecting a utility tunnel: "eto", "meter", "degree", "please"
    ("I", "ah, please go straight, two meter", [("F", 2.0)]),
    ("I", "eto, turn to the write, forty five degree", [("r", 45)]),
    ("I", "little bit back, please", [("bitB",)]),
    ("I", "u turn please", [("a", 180)]),
    ("I", "sorry, sorry, left, not right, turn left ninety degree", [("l", 90)]),
    ("I", "please stop, stop", [("stop",)]),
    ("I", "go straight five meter and turn left sixty degree", [("F", 5.0), ("l", 60)]),
    ("I", "please go back fifty centimeter", [("B", 0.5)]),
    ("I", "face to north, please", [("face", N)]),
    ("I", "move to left side one meter", [("L", 1.0)]),
    ("I", "go back three hundred centimeter", [("B", 3.0)]),
    ("I", "please turn thirty degree", "clarify"),                                      # no direction
    ("I", "please go to exit number two", "clarify"),                                   # place
    ("I", "go straight one meter fifty, and take picture", [("F", 1.5)]),
    ("I", "turn right one hundred fifty degree", [("r", 150)]),
    # ---- J  Darren, ex-army instructor running a search-and-rescue exercise: drill words
    ("J", "left, face", [("l", 90)]),
    ("J", "about face", [("a", 180)]),
    ("J", "forward, three metres, go", [("F", 3.0)]),
    ("J", "squad, halt", [("stop",)]),
    ("J", "forward three paces", "clarify"),                                            # unknown unit
    ("J", "right face, forward ten metres", [("r", 90), ("F", 10.0)]),
    ("J", "back two metres, move", [("B", 2.0)]),
    ("J", "on the double, forward fifty metres", [("far", 50.0)]),
    ("J", "face west, then forward four metres", [("face", W), ("F", 4.0)]),
    ("J", "left turn, forty five degrees", [("l", 45)]),
    ("J", "sidestep right one metre", [("R", 1.0)]),
    ("J", "forward march", "clarify"),                                                  # vague amount
    ("J", "report position", [("get", "GetRobotPoseLast")]),
    ("J", "turn right twenty degrees, correction, twenty five degrees", [("r", 25)]),
    ("J", "forward two metres, right face, forward two metres, right face", [("F", 2.0), ("r", 90), ("F", 2.0), ("r", 90)]),
]

if __name__ == "__main__":
    assert len(CASES) == 150, len(CASES)
    for s in "ABCDEFGHIJ":
        assert sum(1 for c in CASES if c[0] == s) == 15, s
    main(CASES, "b8s")
