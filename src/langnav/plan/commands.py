"""The seven robot commands: a closed, typed union (pydantic), with the bench's output shape.

Move steps are 3 cm, Rotate steps 10 degrees. ``note`` says in plain words why the command is
there ("the second door on your left"); it is for people and is not sent to the robot.
"""

from __future__ import annotations

from typing import Annotated, Any, Final, Literal

from pydantic import BaseModel, ConfigDict, Field, TypeAdapter

MOVE_STEP_M: Final = 0.03
ROTATE_STEP_DEG: Final = 10.0
#: Upper bounds that keep one command sane: 30 m of Move, ten full turns.
MAX_MOVE_STEPS: Final = 1000
MAX_ROTATE_STEPS: Final = 360
MAX_POSES: Final = 100


class _Cmd(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)
    note: str = Field(default="", max_length=300, exclude=True)


PoseXY = Annotated[list[float], Field(min_length=2, max_length=3)]


class NavigateThroughPoses(_Cmd):
    command: Literal["NavigateThroughPoses"] = "NavigateThroughPoses"
    poses: list[PoseXY] = Field(min_length=1, max_length=MAX_POSES)


class Move(_Cmd):
    command: Literal["Move"] = "Move"
    direction: Literal["forward", "backward", "left", "right"]
    repeat: int = Field(ge=1, le=MAX_MOVE_STEPS)

    @property
    def distance_m(self) -> float:
        return self.repeat * MOVE_STEP_M


class Rotate(_Cmd):
    command: Literal["Rotate"] = "Rotate"
    direction: Literal["left", "right"]
    repeat: int = Field(ge=1, le=MAX_ROTATE_STEPS)

    @property
    def angle_deg(self) -> float:
        return self.repeat * ROTATE_STEP_DEG


class Stop(_Cmd):
    command: Literal["Stop"] = "Stop"


class GetCurrentPath(_Cmd):
    command: Literal["GetCurrentPath"] = "GetCurrentPath"


class GetMap(_Cmd):
    command: Literal["GetMap"] = "GetMap"


class GetRobotPoseLast(_Cmd):
    command: Literal["GetRobotPoseLast"] = "GetRobotPoseLast"


Command = Annotated[
    NavigateThroughPoses | Move | Rotate | Stop | GetCurrentPath | GetMap | GetRobotPoseLast,
    Field(discriminator="command"),
]
COMMAND_ADAPTER: TypeAdapter[Command] = TypeAdapter(Command)
COMMAND_NAMES: Final = ("NavigateThroughPoses", "Move", "Rotate", "Stop", "GetCurrentPath", "GetMap",
                        "GetRobotPoseLast")


def parse_command(data: dict[str, Any]) -> Command:
    """Validate one command dict (raises pydantic.ValidationError)."""
    return COMMAND_ADAPTER.validate_python(data)


def to_bench(cmd: Command) -> dict[str, Any]:
    """The bench's output shape of one command (``note`` left out)."""
    out = cmd.model_dump(exclude={"note"})
    if isinstance(cmd, NavigateThroughPoses):
        out["poses"] = [[round(v, 3) for v in p] for p in cmd.poses]
    return out


def steps_for_distance(distance_m: float) -> int:
    """Move steps for a distance: 1 m = 33 steps of 3 cm (at least one)."""
    return max(1, round(distance_m / MOVE_STEP_M))


def steps_for_angle(angle_deg: float) -> int:
    """Rotate steps for an angle: 90 degrees = 9 steps of 10 degrees (at least one)."""
    return max(1, round(angle_deg / ROTATE_STEP_DEG))


def describe(cmd: Command) -> str:
    """A command in plain words, with its note."""
    match cmd:
        case NavigateThroughPoses(poses=poses):
            pts = " → ".join(f"({p[0]:.1f}, {p[1]:.1f})" for p in poses)
            text = f"Navigate to {pts}" if len(poses) == 1 else f"Navigate through {pts}"
        case Move(direction=d, repeat=n):
            text = f"Move {d} {n * MOVE_STEP_M:.2f} m ({n} steps)"
        case Rotate(direction=d, repeat=n):
            text = f"Turn {d} {n * ROTATE_STEP_DEG:.0f}° ({n} steps)"
        case Stop():
            text = "Stop"
        case GetCurrentPath():
            text = "Report the current path"
        case GetMap():
            text = "Show the map"
        case GetRobotPoseLast():
            text = "Report where I am"
        case _:
            text = type(cmd).__name__
    return f"{text} — {cmd.note}" if cmd.note else text
