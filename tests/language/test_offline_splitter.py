"""Splitting prompts into steps: connectives, punctuation, and 'and' only between instructions."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from langnav.language.offline.splitter import split_steps


@pytest.mark.parametrize(("prompt", "steps"), [
    ("Go to the door.", ["Go to the door"]),
    ("Turn left 90 degrees, then move forward half a meter.",
     ["Turn left 90 degrees", "move forward half a meter"]),
    ("go to the door and then turn left", ["go to the door", "turn left"]),
    ("go to the door and turn left", ["go to the door", "turn left"]),
    ("go between the box and the wall", ["go between the box and the wall"]),
    ("go between the box and the wall and turn right", ["go between the box and the wall", "turn right"]),
    ("Move 1.5 m. Turn 45°; stop!", ["Move 1.5 m", "Turn 45°", "stop"]),
    ("move 1,5 m forward", ["move 1.5 m forward"]),
    ("first rotate left, after that go forward, finally stop", ["first rotate left", "go forward", "stop"]),
    ("go to the door afterwards turn right", ["go to the door", "turn right"]),
    ("go to the door and please turn left", ["go to the door", "please turn left"]),
    ("go to the door and once there turn left", ["go to the door", "turn left"]),
    ("move 1 m forward and 50 cm to the left", ["move 1 m forward", "50 cm to the left"]),
    ("go to the door and pick up the cup", ["go to the door", "pick up the cup"]),
    ("go to the box and the wall", ["go to the box and the wall"]),
    ("Robot, go to the door", ["Robot", "go to the door"]),
    ("go to the next door", ["go to the next door"]),
    ("go through the door\nthen stop", ["go through the door", "stop"]),
])
def test_split(prompt: str, steps: list[str]) -> None:
    assert split_steps(prompt) == steps


@given(st.lists(st.sampled_from(["turn left", "move forward 2 m", "go to the door", "stop",
                                 "go between the box and the wall", "rotate right 30 degrees"]),
                min_size=1, max_size=6),
       st.sampled_from([", then ", " and then ", ". ", "; ", " and ", ", after that "]))
def test_joined_instructions_split_back(parts: list[str], joiner: str) -> None:
    assert split_steps(joiner.join(parts)) == parts


def test_nothing_left_of_punctuation_only() -> None:
    assert split_steps("... ,,, ;;") == []
