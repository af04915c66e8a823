"""Where a bench case must leave the robot (langnav.eval.endpoint), checked on hand-worked cases."""

from __future__ import annotations

import math

import pytest

from langnav.eval.endpoint import ended_as_expected, expected_end, segment_distance


def test_a_navigation_ends_in_its_goal_region() -> None:
    case = {"pose": [1.0, 1.0, 0.0], "expect": [
        {"command": "NavigateThroughPoses", "goal": {"circle": [5.0, 5.0, 0.5]}}]}
    end = expected_end(case)
    assert end == ("region", {"circle": [5.0, 5.0, 0.5]})
    assert ended_as_expected(end, 5.2, 5.1)
    assert not ended_as_expected(end, 6.0, 5.0)


def test_a_turn_then_a_move_ends_on_the_segment_of_its_step_range() -> None:
    # turn left 90 (9 steps of 10 degrees), then forward 1 m (33-34 steps of 3 cm): the robot ends
    # north of its start, 0.99-1.02 m away
    case = {"pose": [2.0, 3.0, 0.0], "expect": [
        {"command": "Rotate", "direction": "left", "repeat": [9, 9]},
        {"command": "Move", "direction": "forward", "repeat": [33, 34]}]}
    end = expected_end(case)
    assert end is not None and end[0] == "segment"
    (ax, ay), (bx, by) = end[1]
    assert (ax, ay, bx, by) == pytest.approx((2.0, 3.99, 2.0, 4.02))
    assert ended_as_expected(end, 2.05, 4.0)
    assert not ended_as_expected(end, 2.0, 4.2)


def test_commands_that_do_not_move_the_robot_have_no_end() -> None:
    assert expected_end({"pose": [0, 0, 0], "expect": [
        {"command": "Rotate", "direction": "right", "repeat": [18, 18]}]}) is None


def test_segment_distance() -> None:
    assert segment_distance((0.0, 1.0), (0.0, 0.0), (2.0, 0.0)) == pytest.approx(1.0)
    assert segment_distance((3.0, 0.0), (0.0, 0.0), (2.0, 0.0)) == pytest.approx(1.0)
    assert segment_distance((1.0, 1.0), (0.0, 0.0), (0.0, 0.0)) == pytest.approx(math.sqrt(2))
