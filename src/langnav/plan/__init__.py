"""Robot commands, the validator / plan checker, and the plan executor."""

from langnav.plan.commands import (
    Command,
    GetCurrentPath,
    GetMap,
    GetRobotPoseLast,
    Move,
    NavigateThroughPoses,
    Rotate,
    Stop,
    describe,
    parse_command,
    to_bench,
)
from langnav.plan.errors import PlanRejected

__all__ = ["Command", "GetCurrentPath", "GetMap", "GetRobotPoseLast", "Move", "NavigateThroughPoses",
           "PlanRejected", "Rotate", "Stop", "describe", "parse_command", "to_bench"]
