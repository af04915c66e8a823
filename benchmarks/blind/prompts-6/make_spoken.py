#!/usr/bin/env python3
"""Writes spoken.jsonl: 150 hand-written spoken motion prompts on the SCOUT arena map, from 10
imagined speakers (README.md), 15 each.  Seven talk like real people on a radio in a search task
(transcribed speech: lowercase, fillers, restarts, commas at pauses, numbers as words); three are
distinctive (a gloved tablet typist, a German first-language speaker, a very verbose talker).
The expansion of meaning parts into expected commands (units, tolerances, compass, alternatives) is
spoken_expand.py, copied unchanged from the fifth blind set (itself from the third and fourth).
Part notation: F/B metres forward/back; L/R metres to the side (sideways Move, or 90 deg Rotate +
Move forward); (Ls/Rs, sideways only, are not used: the contract accepts both readings even where the speaker says 'without turning'); l/r degrees; a = a turn either
way (180, 360); face = compass heading; bitF/bitB/bitl/bitr = "a little"; stop; get = information
command; "clarify" = ask / explain and run nothing.
Run: /work/main/.venv/bin/python make_spoken.py
"""
from spoken_expand import FT, IN, YD, CM, N, NE, E, SE, S, SW, W, NW, main

CASES = [
    # ---- A  Imani, structural engineer at a collapse site: metric, decimals, "approximately"
    ("A", "robot, imani here, move forward one point five metres, over", [("F", 1.5)]),
    ("A", "okay, rotate right approximately twenty five degrees", [("r", 25)]),
    ("A", "go back eighty centimetres, give or take", [("B", 0.80)]),
    ("A", "move forward point seven", "clarify"),                                   # no unit
    ("A", "face north east, then advance two point two five metres", [("face", NE), ("F", 2.25)]),
    ("A", "uh, rotate approximately forty degrees", "clarify"),                     # no direction
    ("A", "okay, turn left one hundred and five degrees", [("l", 105)]),
    ("A", "shift to your right sixty centimetres, without rotating", [("R", 0.60)]),
    ("A", "move forward three point four metres, then hold there", [("F", 3.4)]),
    ("A", "hold position, hold", [("stop",)]),
    ("A", "okay, can you confirm your current position, over", [("get", "GetRobotPoseLast")]),
    ("A", "back up, uh, one point two metres, and then turn around", [("B", 1.2), ("a", 180)]),
    ("A", "go forward, sorry, go backward forty five centimetres", [("B", 0.45)]),
    ("A", "rotate counter clockwise two seventy degrees", [("l", 270)]),
    ("A", "move forward twelve metres and send a photo when you get there", [("F", 12.0)]),
    # ---- B  Ray, rancher volunteer: "foot" for feet, "her" for the robot, "reckon"
    ("B", "alright, go on ahead, oh, six foot or so", [("F", 6 * FT)]),
    ("B", "hold up, hold up there", [("stop",)]),
    ("B", "now swing her round to the north", [("face", N)]),
    ("B", "back her up a foot and a half", [("B", 1.5 * FT)]),
    ("B", "go on ahead a few foot", "clarify"),                                     # ambiguous amount
    ("B", "turn her left, oh, thirty five degrees", [("l", 35)]),
    ("B", "yep, now go on forward four yards", [("F", 4 * YD)]),
    ("B", "snap me a picture of that pile there", "clarify"),
    ("B", "turn her right just a little", [("bitr",)]),
    ("B", "go west, uh, twenty two foot", [("face", W), ("F", 22 * FT)]),
    ("B", "reckon you oughta turn around", [("a", 180)]),
    ("B", "forward nine foot, then left ninety", [("F", 9 * FT), ("l", 90)]),
    ("B", "where you at right now", [("get", "GetRobotPoseLast")]),
    ("B", "ease her back a bit", [("bitB",)]),
    ("B", "face south east and go thirteen foot", [("face", SE), ("F", 13 * FT)]),
    # ---- C  Priyanka, rushed medic: restarts, cut-off words, quick corrections
    ("C", "okay go, go for- forward four feet", [("F", 4 * FT)]),
    ("C", "turn left, no, right, right forty degrees", [("r", 40)]),
    ("C", "rotate clockwise to the left, like, fifty", "clarify"),                  # contradiction
    ("C", "back, back up two feet, sorry, three feet", [("B", 3 * FT)]),
    ("C", "move to your le- left five feet", [("L", 5 * FT)]),
    ("C", "what do you see over there", "clarify"),
    ("C", "face wes- west", [("face", W)]),
    ("C", "turn ninety, ninety to the right and then forward six feet", [("r", 90), ("F", 6 * FT)]),
    ("C", "go forward eleven feet, no wait, stop", [("stop",)]),
    ("C", "turn around and, uh, and back up one foot", [("a", 180), ("B", FT)]),
    ("C", "okay turn le- turn left a little", [("bitl",)]),
    ("C", "forward fifteen feet and get me a photo", [("F", 15 * FT)]),
    ("C", "turn right one sixty five", [("r", 165)]),
    ("C", "go forward seven inches, sorry, seven feet", [("F", 7 * FT)]),
    ("C", "spin, spin all the way around once", [("a", 360)]),
    # ---- D  Tomasz, methodical search coordinator: compass, formal, asks for information
    ("D", "robot, state your current position", [("get", "GetRobotPoseLast")]),
    ("D", "turn to face due east", [("face", E)]),
    ("D", "proceed south, distance eight metres", [("face", S), ("F", 8.0)]),
    ("D", "could you display the map for me", [("get", "GetMap")]),
    ("D", "what path are you currently following", [("get", "GetCurrentPath")]),
    ("D", "proceed to the blue door", "clarify"),                                   # a name the map cannot know
    ("D", "move ahead eight", "clarify"),                                           # no unit
    ("D", "face north west, then advance five metres", [("face", NW), ("F", 5.0)]),
    ("D", "rotate right one hundred and twenty degrees", [("r", 120)]),
    ("D", "head north east for six metres", [("face", NE), ("F", 6.0)]),
    ("D", "copy, rotate left forty five degrees", [("l", 45)]),
    ("D", "back up two metres, then face west", [("B", 2.0), ("face", W)]),
    ("D", "proceed forward ten metres, then turn right ninety degrees, then proceed forward four metres",
     [("F", 10.0), ("r", 90), ("F", 4.0)]),
    ("D", "rotate to face south west", [("face", SW)]),
    ("D", "stand by. stop", [("stop",)]),
    # ---- E  Shauna, impatient incident commander: "come on", more / another / again
    ("E", "come on, go forward ten feet", [("F", 10 * FT)]),
    ("E", "no no no, stop, stop", [("stop",)]),
    ("E", "more, more!", "clarify"),                                                # no amount, no context
    ("E", "turn left thirty, and then another thirty", [("l", 30), ("l", 30)]),
    ("E", "just go forward already", "clarify"),                                    # no amount
    ("E", "forward five feet, and then again", [("F", 5 * FT), ("F", 5 * FT)]),
    ("E", "ugh, turn right, like, twenty more degrees", [("r", 20)]),
    ("E", "back up four feet, come on", [("B", 4 * FT)]),
    ("E", "go forward three more feet, then three more", [("F", 3 * FT), ("F", 3 * FT)]),
    ("E", "okay turn around, quick", [("a", 180)]),
    ("E", "turn right sixty, and then do it again", [("r", 60), ("r", 60)]),
    ("E", "sidestep right two feet, keep facing forward", [("R", 2 * FT)]),
    ("E", "forward twenty feet, now, go", [("F", 20 * FT)]),
    ("E", "face north, and go another ten feet", [("face", N), ("F", 10 * FT)]),
    ("E", "left ninety, forward six feet, left ninety again", [("l", 90), ("F", 6 * FT), ("l", 90)]),
    # ---- F  Hamid, British IT volunteer: anticlockwise, reverse, "cheers", "brilliant"
    ("F", "right then, could you go forward two metres please", [("F", 2.0)]),
    ("F", "turn anticlockwise forty five degrees, cheers", [("l", 45)]),
    ("F", "reverse about a metre", [("B", 1.0)]),
    ("F", "could you go forward three paces", "clarify"),                           # unknown unit
    ("F", "shift left half a metre, without turning", [("L", 0.5)]),
    ("F", "brilliant, now turn clockwise a hundred and thirty degrees", [("r", 130)]),
    ("F", "turn to face the lorry", "clarify"),                                     # a thing the map cannot know
    ("F", "could you just turn slightly anticlockwise", [("bitl",)]),
    ("F", "go straight on for five metres, then turn right", [("F", 5.0), ("r", 90)]),
    ("F", "face south please", [("face", S)]),
    ("F", "could you shift right seventy five centimetres", [("R", 0.75)]),
    ("F", "lovely, now reverse one metre twenty centimetres", [("B", 1.2)]),
    ("F", "could you take a photo of the doorway for me", "clarify"),
    ("F", "go east six metres please", [("face", E), ("F", 6.0)]),
    ("F", "right, stop there, thanks", [("stop",)]),
    # ---- G  Ngozi, careful volunteer: hedges every number, asks if it's okay
    ("G", "um, could you go forward about three metres, is that okay", [("F", 3.0)]),
    ("G", "turn about sixty degrees or so", "clarify"),                             # no direction
    ("G", "slide over to your left roughly two feet", [("L", 2 * FT)]),
    ("G", "could you go forward, um, two car lengths or so", "clarify"),             # unknown unit
    ("G", "turn right roughly seventy degrees", [("r", 70)]),
    ("G", "go back, um, more or less half a metre", [("B", 0.5)]),
    ("G", "face north, um, and go about ten feet, if that's okay", [("face", N), ("F", 10 * FT)]),
    ("G", "turn left just a bit, maybe", [("bitl",)]),
    ("G", "go forward about two feet six inches", [("F", 2 * FT + 6 * IN)]),
    ("G", "is it okay if you turn around and take a picture", [("a", 180)]),
    ("G", "turn roughly, um, a hundred and fifty degrees to the right", [("r", 150)]),
    ("G", "could you move to your right about a metre and a half", [("R", 1.5)]),
    ("G", "um, where are you right now, roughly", [("get", "GetRobotPoseLast")]),
    ("G", "go forward eighteen inches or so, and then turn left", [("F", 18 * IN), ("l", 90)]),
    ("G", "um, turn clockwise about two hundred degrees", [("r", 200)]),
    # ---- H  Bex, types on a rugged tablet with gloves on: digits, glued units, fat-finger typos
    ("H", "foward 3ft pls", [("F", 3 * FT)]),
    ("H", "tunr left 45deg", [("l", 45)]),
    ("H", "fwd 4", "clarify"),                                                      # no unit
    ("H", "bakc up 2 ft", [("B", 2 * FT)]),
    ("H", "pic pls", "clarify"),
    ("H", "tunr 20deg", "clarify"),                                                 # no direction
    ("H", "rihgt 90 then fwd 10ft", [("r", 90), ("F", 10 * FT)]),
    ("H", "face nroth", [("face", N)]),
    ("H", "stopp", [("stop",)]),
    ("H", "mvoe left 1m sideways no turning", [("L", 1.0)]),
    ("H", "turn aroudn", [("a", 180)]),
    ("H", "forwrd 2.5m then lft 30", [("F", 2.5), ("l", 30)]),
    ("H", "where r u", [("get", "GetRobotPoseLast")]),
    ("H", "go sotuh 5m", [("face", S), ("F", 5.0)]),
    ("H", "turn rt a lil", [("bitr",)]),
    # ---- I  Juergen, German first language: "drive", "turn you", "in direction"
    ("I", "Drive three meters forwards, please.", [("F", 3.0)]),
    ("I", "Turn you forty-five degrees to the left.", [("l", 45)]),
    ("I", "Go one meter backwards.", [("B", 1.0)]),
    ("I", "Drive forwards two.", "clarify"),                                        # no unit
    ("I", "Please make a photo from the door.", "clarify"),
    ("I", "Turn you around.", [("a", 180)]),
    ("I", "Drive in direction north five meters.", [("face", N), ("F", 5.0)]),
    ("I", "Turn to the right side, sixty degrees.", [("r", 60)]),
    ("I", "Drive some meters forwards.", "clarify"),                                # ambiguous amount
    ("I", "Go one and a half meter to the left side.", [("L", 1.5)]),
    ("I", "Stop! Stay there.", [("stop",)]),
    ("I", "Where do you stand now?", [("get", "GetRobotPoseLast")]),
    ("I", "Turn you a little bit to the left.", [("bitl",)]),
    ("I", "Drive backwards thirty centimeters and then turn you right ninety degrees.", [("B", 0.30), ("r", 90)]),
    ("I", "Turn you in direction east.", [("face", E)]),
    # ---- J  Gordon, very verbose: stories and asides around every request
    ("J", "right, so, what i'd like you to do now, and bear with me, it's been a long day out here, is to go "
          "forward, oh, i'd say four metres, yes, four metres", [("F", 4.0)]),
    ("J", "okay now, and this is the bit i was telling jim about earlier, i want you to turn to your left, "
          "about ninety degrees, just a proper left turn", [("l", 90)]),
    ("J", "now i know this sounds odd but could you go back to where you were before, you know, the spot "
          "with the funny echo", "clarify"),
    ("J", "so what i'd really like, if you don't mind, is for you to face south, because that's where the "
          "noise was coming from, i think", [("face", S)]),
    ("J", "and then, after that, oh, let's see, go forward, um, twelve feet, and maybe take a picture for "
          "us while you're at it", [("F", 12 * FT)]),
    ("J", "what's in front of you now, describe it to me, every detail", "clarify"),
    ("J", "okay, now, i'd like you to turn right, not too far, just a little, like you're peeking round a "
          "corner", [("bitr",)]),
    ("J", "let's have you back up, oh, about a yard, because i think you might be a bit close to that wall",
     [("B", YD)]),
    ("J", "good, good, now if you'd be so kind, spin yourself right around, all the way, three sixty, so we "
          "can get a feel for the place", [("a", 360)]),
    ("J", "and now, this is important, go east for, ooh, twenty feet, give or take", [("face", E), ("F", 20 * FT)]),
    ("J", "right, hold on, hold on, stop there for a moment while i think", [("stop",)]),
    ("J", "so, hmm, where exactly are you on the map now, can you tell me", [("get", "GetRobotPoseLast")]),
    ("J", "okay, and then i'd like you to move over to your right, about two feet, nothing fancy",
     [("R", 2 * FT)]),
    ("J", "right, so, after all that, go forward, what, nine and a half feet, and then turn left about "
          "forty degrees", [("F", 9.5 * FT), ("l", 40)]),
    ("J", "lastly, and i promise this is the last one for a while, turn around and go forward six feet",
     [("a", 180), ("F", 6 * FT)]),
]

if __name__ == "__main__":
    assert len(CASES) == 150
    for s in "ABCDEFGHIJ":
        assert sum(1 for c in CASES if c[0] == s) == 15, s
    main(CASES, "b6s")
