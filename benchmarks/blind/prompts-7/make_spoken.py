#!/usr/bin/env python3
"""Writes spoken.jsonl: 150 hand-written spoken motion prompts on the SCOUT arena map, from 10
imagined speakers (README.md), 15 each.  Seven are real people talking to a robot during a task,
transcribed as speech recognition gives it (lowercase, fillers, restarts, commas at pauses, numbers as
words, a few recognition slips); three are distinctive (an emoji phone texter, a French first-language
speaker, a retired merchant mariner).
The expansion of meaning parts into expected commands (units, tolerances, compass, alternatives) is
spoken_expand.py, copied unchanged from the sixth blind set (itself from the third to fifth).
Part notation: F/B metres forward/back; L/R metres to the side (sideways Move, or 90 deg Rotate +
Move forward); l/r degrees; a = a turn either way (180, 360); face = compass heading;
bitF/bitB/bitl/bitr = "a little"; stop; get = information command; "clarify" = ask / explain and run
nothing.
Run: /work/main/.venv/bin/python make_spoken.py
"""
from spoken_expand import FT, IN, YD, CM, N, NE, E, SE, S, SW, W, NW, main

CASES = [
    # ---- A  Mercy, hospital night-shift nurse: quiet, "gently", "nice and slow", interrupted by patients
    ("A", "okay, nice and slow, go forward three feet", [("F", 3 * FT)]),
    ("A", "gently, turn to your right about forty five degrees", [("r", 45)]),
    ("A", "hang on, hang on, stop there", [("stop",)]),
    ("A", "sorry, one second, bed twelve is calling, okay, back up two feet, quietly", [("B", 2 * FT)]),
    ("A", "can you go to the nurses station", "clarify"),                          # place
    ("A", "turn left ninety and then go forward, um, seven feet", [("l", 90), ("F", 7 * FT)]),
    ("A", "just scoot forward a tiny bit", [("bitF",)]),
    ("A", "can you turn around, quietly please", [("a", 180)]),
    ("A", "move forward four and a half feet", [("F", 4.5 * FT)]),
    ("A", "okay, um, face east", [("face", E)]),
    ("A", "go forward, uh, ten feet, and then stop", [("F", 10 * FT)]),
    ("A", "rotate to the left, um, twenty degrees, gently", [("l", 20)]),
    ("A", "go slowly forward", "clarify"),                                          # vague amount
    ("A", "move over to your right two feet, mind the trolley", [("R", 2 * FT)]),
    ("A", "okay come back toward me, back up four feet", [("B", 4 * FT)]),
    # ---- B  Dale, boiler / tank inspection technician: "advance", "jog", decimals of feet, inches
    ("B", "advance two point five feet", [("F", 2.5 * FT)]),
    ("B", "jog right five degrees", [("r", 5)]),
    ("B", "okay, log your position", [("get", "GetRobotPoseLast")]),
    ("B", "back out eighteen inches", [("B", 18 * IN)]),
    ("B", "rotate counterclockwise fifteen degrees, then advance one point two five feet", [("l", 15), ("F", 1.25 * FT)]),
    ("B", "hold, hold, hold", [("stop",)]),
    ("B", "give me a shot of the weld seam", "clarify"),                            # photo only
    ("B", "advance six", "clarify"),                                                # missing unit
    ("B", "jog left ten degrees clockwise", "clarify"),                             # contradiction
    ("B", "face north, advance eight feet", [("face", N), ("F", 8 * FT)]),
    ("B", "rotate one thirty five clockwise", [("r", 135)]),
    ("B", "offset to your left one foot", [("L", FT)]),
    ("B", "advance twenty two inches and grab a photo", [("F", 22 * IN)]),
    ("B", "pull up the map for me", [("get", "GetMap")]),
    ("B", "back out one point five, uh, one point five metres", [("B", 1.5)]),
    # ---- C  Kelsey, parent at home with the kids around: side talk to the children, "okay robot"
    ("C", "okay robot, go forward two metres, emma, don't touch it", [("F", 2.0)]),
    ("C", "robot turn left, no, jack, sit down, turn left forty five degrees", [("l", 45)]),
    ("C", "go into the kitchen", "clarify"),                                        # place
    ("C", "stop stop stop, the cat", [("stop",)]),
    ("C", "back up a little bit, there's a lego", [("bitB",)]),
    ("C", "turn around and go forward three metres", [("a", 180), ("F", 3.0)]),
    ("C", "mommy's talking to the robot, okay, turn right ninety", [("r", 90)]),
    ("C", "um, go to the left about a metre", [("L", 1.0)]),
    ("C", "go forward like five feet, wait, metres, five metres", [("F", 5.0)]),
    ("C", "face the front door", "clarify"),                                        # place
    ("C", "rotate a full circle, they want to see it spin", [("a", 360)]),
    ("C", "go forward one and a half metres then turn left", [("F", 1.5), ("l", 90)]),
    ("C", "what can you see right now", "clarify"),                                 # camera
    ("C", "lily, stop it. robot, go backwards sixty centimetres", [("B", 0.60)]),
    ("C", "turn right a bit", [("bitr",)]),
    # ---- D  Fergus, Scottish search volunteer: "aye", "wee", "naw", "gonnae", "tae", "yer"
    ("D", "aye, go forward four metres", [("F", 4.0)]),
    ("D", "turn tae yer left a wee bit", [("bitl",)]),
    ("D", "naw naw, stop", [("stop",)]),
    ("D", "gonnae back up two metres", [("B", 2.0)]),
    ("D", "right, face south", [("face", S)]),
    ("D", "go forward a wee bit more", [("bitF",)]),
    ("D", "aye, just turn yerself around", [("a", 180)]),
    ("D", "go tae the left three metres", [("L", 3.0)]),
    ("D", "turn right eighty degrees, then forward six metres", [("r", 80), ("F", 6.0)]),
    ("D", "head west ten metres", [("face", W), ("F", 10.0)]),
    ("D", "go forward a fair bit", "clarify"),                                      # vague amount
    ("D", "rotate, eh, thirty degrees", "clarify"),                                 # no direction
    ("D", "go back oot the way, one metre back", [("B", 1.0)]),
    ("D", "can ye tell me where ye are", [("get", "GetRobotPoseLast")]),
    ("D", "aye, turn left a hundred and twenty degrees", [("l", 120)]),
    # ---- E  Rajesh, warehouse shift supervisor, Indian English: "kindly", "take left", "U-turn", "side"
    ("E", "kindly go straight three meters", [("F", 3.0)]),
    ("E", "take left", [("l", 90)]),
    ("E", "take one u turn", [("a", 180)]),
    ("E", "come back one and half meter", [("B", 1.5)]),
    ("E", "do one thing, go to aisle number seven", "clarify"),                     # place
    ("E", "turn right side forty five degree", [("r", 45)]),
    ("E", "just stop there only", [("stop",)]),
    ("E", "go little bit front", [("bitF",)]),
    ("E", "move right side two meter", [("R", 2.0)]),
    ("E", "first turn left ninety degree, then go straight five meter", [("l", 90), ("F", 5.0)]),
    ("E", "rotate right ninety and show me photo of that rack", [("r", 90)]),
    ("E", "turn towards north side", [("face", N)]),
    ("E", "go straight, eight", "clarify"),                                         # missing unit
    ("E", "where you are now, tell me the location", [("get", "GetRobotPoseLast")]),
    ("E", "rotate left side sixty degree", [("l", 60)]),
    # ---- F  Lin, drone pilot volunteering at a disaster site: "yaw", "crab", "nose", "creep"
    ("F", "yaw left ninety", [("l", 90)]),
    ("F", "okay crab right one metre", [("R", 1.0)]),
    ("F", "point your nose north", [("face", N)]),
    ("F", "creep forward half a metre", [("F", 0.5)]),
    ("F", "yaw right, uh, thirty degrees, then forward two metres", [("r", 30), ("F", 2.0)]),
    ("F", "back off a metre", [("B", 1.0)]),
    ("F", "okay hold it there", [("stop",)]),
    ("F", "do a slow three sixty", [("a", 360)]),
    ("F", "give me a video feed", "clarify"),                                       # camera
    ("F", "yaw left a touch", [("bitl",)]),
    ("F", "go forward about four metres and then yaw right forty five", [("F", 4.0), ("r", 45)]),
    ("F", "what's your heading", [("get", "GetRobotPoseLast")]),
    ("F", "yaw right sixty counterclockwise", "clarify"),                           # contradiction
    ("F", "head south west five metres", [("face", SW), ("F", 5.0)]),
    ("F", "back up two metres, then point your nose east", [("B", 2.0), ("face", E)]),
    # ---- G  Anita, insurance loss adjuster in a flooded house: narrates her notes between commands
    ("G", "water line about eighteen inches on this wall, okay, go forward three feet", [("F", 3 * FT)]),
    ("G", "turn left ninety degrees, i want to see the hallway", [("l", 90)]),
    ("G", "take a picture of the baseboard there", "clarify"),                      # photo only
    ("G", "move forward six feet and take a photo of the ceiling", [("F", 6 * FT)]),
    ("G", "go to the master bedroom", "clarify"),                                   # place
    ("G", "back up, um, two and a half feet", [("B", 2.5 * FT)]),
    ("G", "rotate right one twenty", [("r", 120)]),
    ("G", "note, drywall is soft here. turn around please", [("a", 180)]),
    ("G", "okay, move over to the right one foot", [("R", FT)]),
    ("G", "go forward four feet, then turn right forty five, then forward two feet",
     [("F", 4 * FT), ("r", 45), ("F", 2 * FT)]),
    ("G", "stop right there", [("stop",)]),
    ("G", "move forward about, hmm, three floor tiles", "clarify"),                 # unknown unit
    ("G", "face north west", [("face", NW)]),
    ("G", "let me see the map", [("get", "GetMap")]),
    ("G", "turn a little to your left", [("bitl",)]),
    # ---- H  Ola, types on her phone: digits, units glued on, emoji, "pls", "r u"
    ("H", "go forward 2m 👍", [("F", 2.0)]),
    ("H", "turn left 90 pls 🙏", [("l", 90)]),
    ("H", "STOP NOW 🛑🛑", [("stop",)]),
    ("H", "back 50cm", [("B", 0.50)]),
    ("H", "turn right 30° then go 1.5m", [("r", 30), ("F", 1.5)]),
    ("H", "face west now 🧭", [("face", W)]),
    ("H", "spin 360 😂", [("a", 360)]),
    ("H", "go forward 3 😅", "clarify"),                                            # missing unit
    ("H", "where r u now? 📍", [("get", "GetRobotPoseLast")]),
    ("H", "move right 1m ➡️", [("R", 1.0)]),
    ("H", "turn 45°", "clarify"),                                                   # no direction
    ("H", "send pic 📸", "clarify"),                                                # photo only
    ("H", "inch fwd a bit 🐢", [("bitF",)]),
    ("H", "turn around then fwd 4ft 🙂", [("a", 180), ("F", 4 * FT)]),
    ("H", "rotate left a bit pls", [("bitl",)]),
    # ---- I  Helene, French first language, speech recognised: "of two meters", "half-turn", "on the left"
    ("I", "go forward of two meters please", [("F", 2.0)]),
    ("I", "turn on the right of forty-five degrees", [("r", 45)]),
    ("I", "make a half-turn", [("a", 180)]),
    ("I", "make a complete turn", [("a", 360)]),
    ("I", "go back of one meter fifty", [("B", 1.5)]),
    ("I", "go to the north of three meters", [("face", N), ("F", 3.0)]),
    ("I", "turn on the left", [("l", 90)]),
    ("I", "stop, stop here", [("stop",)]),
    ("I", "move on the side right of fifty centimeters", [("R", 0.5)]),
    ("I", "advance of one meter and take a photo please", [("F", 1.0)]),
    ("I", "turn of thirty degrees", "clarify"),                                     # no direction
    ("I", "turn on the left of one hundred thirty-five degrees and advance of four meters", [("l", 135), ("F", 4.0)]),
    ("I", "turn towards the east please", [("face", E)]),
    ("I", "go back a little", [("bitB",)]),
    ("I", "move forward of eighty centimeters, and after turn on the right", [("F", 0.8), ("r", 90)]),
    # ---- J  Joe, retired merchant mariner inspecting a ship's hold: port / starboard, "astern", "belay that"
    ("J", "ahead slow, two metres", [("F", 2.0)]),
    ("J", "come right to starboard thirty degrees", [("r", 30)]),
    ("J", "hard to port, ninety degrees", [("l", 90)]),
    ("J", "go astern one metre", [("B", 1.0)]),
    ("J", "all stop", [("stop",)]),
    ("J", "come about, one eighty", [("a", 180)]),
    ("J", "come round to face north", [("face", N)]),
    ("J", "make your way south about twenty feet", [("face", S), ("F", 20 * FT)]),
    ("J", "ahead two boat lengths", "clarify"),                                     # unknown unit
    ("J", "starboard side, shift over one metre", [("R", 1.0)]),
    ("J", "give us your position", [("get", "GetRobotPoseLast")]),
    ("J", "ahead a ways", "clarify"),                                               # vague amount
    ("J", "turn to port ten degrees", [("l", 10)]),
    ("J", "ahead one metre, then starboard ninety, then ahead three metres", [("F", 1.0), ("r", 90), ("F", 3.0)]),
    ("J", "turn left, i mean port, forty, belay that, sixty degrees", [("l", 60)]),
]

if __name__ == "__main__":
    assert len(CASES) == 150, len(CASES)
    for s in "ABCDEFGHIJ":
        assert sum(1 for c in CASES if c[0] == s) == 15, s
    main(CASES, "b7s")
