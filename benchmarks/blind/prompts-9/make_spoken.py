#!/usr/bin/env python3
"""Writes spoken.jsonl: 150 hand-written spoken motion prompts on the SCOUT arena map, from 10
imagined speakers (README.md), 15 each.  Most are real people talking to a robot during a task,
transcribed as speech recognition gives it (lowercase, fillers, restarts, commas at pauses, numbers as
words, a few recognition slips); some are distinctive (a Swedish engineer who types with decimal commas,
a football coach, non-native speakers who code-switch).
The expansion of meaning parts into expected commands (units, tolerances, compass, alternatives) is
spoken_expand.py, copied unchanged from the eighth blind set (itself from the third to seventh).
Part notation: F/B metres forward/back; L/R metres to the side (sideways Move, or 90 deg Rotate +
Move forward); l/r degrees; a = a turn either way (180, 360); face = compass heading;
bitF/bitB/bitl/bitr = "a little"; far = a forward move beyond the arena wall (clarify, or the safe part);
stop; get = information command; "clarify" = ask / explain and run nothing.
Run: /work/main/.venv/bin/python make_spoken.py
"""
from spoken_expand import FT, IN, YD, CM, N, NE, E, SE, S, SW, W, NW, main

CASES = [
    # ---- A  Siobhan, Dublin caretaker checking a closed school at night: "go on so", "grand", "c'mere", "em"
    ("A", "go on so, straight ahead two metres", [("F", 2.0)]),
    ("A", "grand, now turn left", [("l", 90)]),
    ("A", "ah here, stop, stop", [("stop",)]),
    ("A", "c'mere, back up a small bit", [("bitB",)]),
    ("A", "turn around there", [("a", 180)]),
    ("A", "go down to the staff room", "clarify"),                                      # place
    ("A", "turn right, em, thirty degrees", [("r", 30)]),
    ("A", "go forward, em, four feet there", [("F", 4 * FT)]),
    ("A", "face west now so", [("face", W)]),
    ("A", "go forward a good bit", "clarify"),                                          # vague amount
    ("A", "turn right sixty, no, left, left sixty", [("l", 60)]),
    ("A", "where are you now at all", [("get", "GetRobotPoseLast")]),
    ("A", "move over to your left a metre", [("L", 1.0)]),
    ("A", "forward five metres and then turn right ninety", [("F", 5.0), ("r", 90)]),
    ("A", "turn, em, forty five", "clarify"),                                           # no direction
    # ---- B  Tariq, bomb-disposal (EOD) operator steering up to a suspect package: precise, metric, "creep", "hold"
    ("B", "creep it forward half a metre", [("F", 0.5)]),
    ("B", "hold, hold position", [("stop",)]),
    ("B", "rotate right ten degrees", [("r", 10)]),
    ("B", "back off two metres, slowly", [("B", 2.0)]),
    ("B", "standby, okay, forward thirty centimetres", [("F", 0.3)]),
    ("B", "give me a picture of the bag", "clarify"),                                   # photo only
    ("B", "rotate left five degrees", [("l", 5)]),
    ("B", "forward one point two five metres", [("F", 1.25)]),
    ("B", "confirm your position", [("get", "GetRobotPoseLast")]),
    ("B", "turn and face north east", [("face", NE)]),
    ("B", "withdraw fifteen metres, straight back", [("B", 15.0)]),
    ("B", "move up to the car", "clarify"),                                             # place
    ("B", "rotate left, uh, rotate right fifteen, correction, twenty", [("r", 20)]),
    ("B", "advance two vehicle lengths", "clarify"),                                    # unknown unit
    ("B", "creep forward a touch", [("bitF",)]),
    # ---- C  Rhian, Welsh care-home night carer: "now then", "there's lovely", "tidy", "whereabouts are you to", feet
    ("C", "right now then, go forward three feet for me", [("F", 3 * FT)]),
    ("C", "there's lovely, stop there now", [("stop",)]),
    ("C", "turn to your left, ninety degrees, quiet now", [("l", 90)]),
    ("C", "back up two foot, cariad", [("B", 2 * FT)]),
    ("C", "whereabouts are you to now", [("get", "GetRobotPoseLast")]),
    ("C", "go along the corridor, um, twelve feet", [("F", 12 * FT)]),
    ("C", "turn round, tidy", [("a", 180)]),
    ("C", "go forward a few steps", "clarify"),                                         # vague amount
    ("C", "turn right, about twenty degrees", [("r", 20)]),
    ("C", "now go along five feet and turn left", [("F", 5 * FT), ("l", 90)]),
    ("C", "face south for me now", [("face", S)]),
    ("C", "go forward, um, one and a half feet", [("F", 1.5 * FT)]),
    ("C", "go forward two feet and take a photo for the night report", [("F", 2 * FT)]),   # motion + photo
    ("C", "shift over to the right a foot", [("R", FT)]),
    ("C", "now turn, um, seventy degrees", "clarify"),                                  # no direction
    # ---- D  Gabriel, Brazilian (Portuguese first language), maintenance technician in a paper mill
    ("D", "go to front two meters", [("F", 2.0)]),
    ("D", "turn to the right side ninety degrees", [("r", 90)]),
    ("D", "go to back one meter", [("B", 1.0)]),
    ("D", "stop, stop, is ok", [("stop",)]),
    ("D", "turn for the left forty five degrees", [("l", 45)]),
    ("D", "walk three meters to front and after turn to the left", [("F", 3.0), ("l", 90)]),
    ("D", "go to the machine number four", "clarify"),                                  # place
    ("D", "turn a little for the right", [("bitr",)]),
    ("D", "go to front fifty centimeters", [("F", 0.5)]),
    ("D", "make one turn complete", [("a", 360)]),
    ("D", "go to front, um, six", "clarify"),                                           # missing unit
    ("D", "rotate to the north", [("face", N)]),
    ("D", "turn to the left side, no, right side, thirty degrees", [("r", 30)]),
    ("D", "go to the left two meters", [("L", 2.0)]),
    ("D", "send me one photo of the motor", "clarify"),                                 # photo only
    # ---- E  Omar, Egyptian civil-defence officer at a collapsed building: "yalla", "khalas", "tamam", "shwaya"
    ("E", "yalla, go straight three meters", [("F", 3.0)]),
    ("E", "khalas, stop", [("stop",)]),
    ("E", "go back a little, shwaya shwaya", [("bitB",)]),
    ("E", "tamam, now turn right ninety", [("r", 90)]),
    ("E", "turn left, left, forty five degree", [("l", 45)]),
    ("E", "go straight, straight, five meter", [("F", 5.0)]),
    ("E", "turn around yalla", [("a", 180)]),
    ("E", "go straight, ah, seven", "clarify"),                                         # missing unit
    ("E", "face to the east", [("face", E)]),
    ("E", "go forward two meter and turn right and go forward one meter", [("F", 2.0), ("r", 90), ("F", 1.0)]),
    ("E", "go right side one meter", [("R", 1.0)]),
    ("E", "where are you, give me your position", [("get", "GetRobotPoseLast")]),
    ("E", "turn right thirty degree", [("r", 30)]),
    ("E", "turn left ninety and take photo", [("l", 90)]),                              # motion + photo
    ("E", "go forward little by little, one meter", [("F", 1.0)]),
    # ---- F  Rick, Texan refinery inspector: "go on ahead", "scooch", "a hair", "hold up", "yonder", feet and yards
    ("F", "alright go on ahead ten feet", [("F", 10 * FT)]),
    ("F", "hang on now, hold up", [("stop",)]),
    ("F", "scooch back a hair", [("bitB",)]),
    ("F", "turn on around", [("a", 180)]),
    ("F", "go on up about fifteen feet", [("F", 15 * FT)]),
    ("F", "turn right, uh, about thirty five degrees", [("r", 35)]),
    ("F", "turn counterclockwise to your right forty five", "clarify"),                 # contradiction
    ("F", "back it up six feet", [("B", 6 * FT)]),
    ("F", "go on and face south", [("face", S)]),
    ("F", "go forward twenty feet and then turn right", [("F", 20 * FT), ("r", 90)]),
    ("F", "scooch over to the left about a foot and a half", [("L", 1.5 * FT)]),
    ("F", "go a ways up yonder", "clarify"),                                            # vague amount
    ("F", "turn left a hundred and thirty five", [("l", 135)]),
    ("F", "take me a picture of that valve", "clarify"),                                # photo only
    ("F", "forward three yards", [("F", 3 * YD)]),
    # ---- G  Martin, wheelchair user directing his assistance robot at home: calm, dry, metric
    ("G", "could you come over to me", "clarify"),                                      # place (where he is)
    ("G", "okay, forward two metres", [("F", 2.0)]),
    ("G", "turn left ninety, please", [("l", 90)]),
    ("G", "go forward about one point five metres, then stop", [("F", 1.5)]),
    ("G", "no, stop there", [("stop",)]),
    ("G", "just turn right a bit", [("bitr",)]),
    ("G", "forward one metre then left", [("F", 1.0), ("l", 90)]),
    ("G", "move about eighty centimetres forward", [("F", 0.8)]),
    ("G", "turn left about a hundred degrees", [("l", 100)]),
    ("G", "back up half a metre, you're on the rug", [("B", 0.5)]),
    ("G", "go round in a full circle", [("a", 360)]),
    ("G", "turn to the right one hundred and eighty degrees", [("a", 180)]),
    ("G", "show me your map", [("get", "GetMap")]),
    ("G", "go forward three feet, that's it", [("F", 3 * FT)]),
    ("G", "move to your right forty centimetres", [("R", 0.4)]),
    # ---- H  Astrid, Swedish test engineer, TYPES in a chat console: decimal commas, "ca.", "pls", "thx"
    ("H", "Forward 2,5 m pls.", [("F", 2.5)]),
    ("H", "Rotate 45 degrees to the left, thx.", [("l", 45)]),
    ("H", "Back 0,5 m.", [("B", 0.5)]),
    ("H", "Stop now pls.", [("stop",)]),
    ("H", "Go forward ca. 1,2 m.", [("F", 1.2)]),
    ("H", "Rotate 30 deg left (clockwise).", "clarify"),                               # contradiction
    ("H", "Go 3 m north.", [("face", N), ("F", 3.0)]),
    ("H", "Turn 180.", [("a", 180)]),
    ("H", "Forward 3,5.", "clarify"),                                                   # missing unit
    ("H", "Turn right 22,5 degrees.", [("r", 22.5)]),
    ("H", "Move 1 m to the right, then forward 2 m.", [("R", 1.0), ("F", 2.0)]),
    ("H", "What is your position?", [("get", "GetRobotPoseLast")]),
    ("H", "Forward 1 m, then take a photo pls.", [("F", 1.0)]),                        # motion + photo
    ("H", "Turn left 100 degrees and go forward 4,75 m.", [("l", 100), ("F", 4.75)]),
    ("H", "Go south-west 2 m.", [("face", SW), ("F", 2.0)]),
    # ---- I  Joy, Filipina caregiver in a care home (Taglish): "sige", "po", "lang", "ano", "ay", "pala", "konti"
    ("I", "sige, go straight two meters po", [("F", 2.0)]),
    ("I", "ay wait, stop muna", [("stop",)]),
    ("I", "turn left lang, ninety", [("l", 90)]),
    ("I", "go back konti, a little", [("bitB",)]),
    ("I", "ano, turn right forty five po", [("r", 45)]),
    ("I", "go to lola's room", "clarify"),                                              # place
    ("I", "go forward, ano, one and a half meters", [("F", 1.5)]),
    ("I", "turn around po", [("a", 180)]),
    ("I", "forward a little bit more po", [("bitF",)]),
    ("I", "face west po", [("face", W)]),
    ("I", "turn ano, turn sixty degrees", "clarify"),                                   # no direction
    ("I", "move to the left side one meter", [("L", 1.0)]),
    ("I", "go forward three meters then turn right po", [("F", 3.0), ("r", 90)]),
    ("I", "ay sorry, turn left, no, right pala, thirty degrees", [("r", 30)]),
    ("I", "can you take a picture of lola sleeping", "clarify"),                        # photo only
    # ---- J  Dwayne, high-school football coach trying the robot in the gym: yards, "cut", "back pedal", "shuffle"
    ("J", "let's go, ten yards straight ahead", [("F", 10 * YD)]),
    ("J", "whoa whoa, hold it right there", [("stop",)]),
    ("J", "cut left, forty five", [("l", 45)]),
    ("J", "back pedal five yards", [("B", 5 * YD)]),
    ("J", "turn and face the end zone", "clarify"),                                     # place
    ("J", "spin it, full three sixty", [("a", 360)]),
    ("J", "go forward one first down", "clarify"),                                      # unknown unit
    ("J", "shuffle right two yards", [("R", 2 * YD)]),
    ("J", "face north, then go fifteen yards", [("face", N), ("F", 15 * YD)]),
    ("J", "turn right ninety and hustle up twenty feet", [("r", 90), ("F", 20 * FT)]),
    ("J", "go fifty yards straight downfield", [("far", 50 * YD)]),                    # beyond the wall
    ("J", "reverse field, turn around", [("a", 180)]),
    ("J", "take a snapshot for the team", "clarify"),                                   # photo only
    ("J", "step up a yard", [("F", YD)]),
    ("J", "where you at right now, buddy", [("get", "GetRobotPoseLast")]),
]

if __name__ == "__main__":
    assert len(CASES) == 150, len(CASES)
    for s in "ABCDEFGHIJ":
        assert sum(1 for c in CASES if c[0] == s) == 15, s
    main(CASES, "b9s")
