"""The overshoot check: motion beyond what any right answer allows is flagged; less is not."""

from langnav.eval.overshoot import overshoots

MOVE_2FT = {"id": "c1", "prompt": "move two more feet",
            "expect": [{"command": "Move", "direction": "forward", "repeat": [19, 21]}]}


def out(*cmds: dict) -> dict:
    return {"id": "c1", "commands": list(cmds), "clarification": None}


def test_two_metres_for_two_feet_is_an_overshoot_of_the_move() -> None:
    [o] = overshoots(MOVE_2FT, out({"command": "Move", "direction": "forward", "repeat": 67}))
    assert (o.command, o.produced_steps, o.allowed_steps) == ("Move", 67, 21)


def test_stopping_short_or_asking_is_not_an_overshoot() -> None:
    assert overshoots(MOVE_2FT, out({"command": "Move", "direction": "forward", "repeat": 10})) == []
    assert overshoots(MOVE_2FT, {"id": "c1", "commands": [], "clarification": "how far?"}) == []
    assert overshoots(MOVE_2FT, None) == []


def test_any_motion_where_the_answer_is_to_ask_is_an_overshoot() -> None:
    case = {"id": "c2", "prompt": "turn", "expect": "clarify"}
    [o] = overshoots(case, out({"command": "Rotate", "direction": "left", "repeat": 9}))
    assert (o.command, o.produced_steps, o.allowed_steps) == ("Rotate", 9, 0)


def test_the_most_generous_alternative_sets_the_limit_and_directions_are_summed() -> None:
    case = {"id": "c3", "prompt": "go left two feet", "expect": {"any": [
        [{"command": "Move", "direction": "left", "repeat": [19, 21]}],
        [{"command": "Rotate", "direction": "left", "repeat": [8, 10]},
         {"command": "Move", "direction": "forward", "repeat": [19, 21]}]]}}
    ok = out({"command": "Rotate", "direction": "left", "repeat": 9},
             {"command": "Move", "direction": "forward", "repeat": 20})
    assert overshoots(case, ok) == []
    # a turn to the left and back again is 18 steps of turning where 10 were the most asked
    twice = out({"command": "Rotate", "direction": "left", "repeat": 9},
                {"command": "Rotate", "direction": "right", "repeat": 9},
                {"command": "Move", "direction": "left", "repeat": 20})
    [o] = overshoots(case, twice)
    assert (o.command, o.produced_steps, o.allowed_steps) == ("Rotate", 18, 10)
