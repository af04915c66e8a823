"""The plan checker: every command well-formed and safe before anything runs.

Checks, following the robot's pose through the sequence:

* schema and ranges (the pydantic command union; raw dicts from an LLM or a file are parsed here);
* every NavigateThroughPoses pose inside the map, on a free cell, at least the robot's radius from
  occupied and unknown cells, and reachable from where the robot is at that moment;
* every Move's straight path and end point clear by the robot's radius;
* sequence logic: a Stop between motions is dropped (it would do nothing), a Stop first halts what
  runs; a bounded number of commands.

Safe repairs are made and reported (a pose snapped to the nearest valid cell within 0.5 m);
anything else raises :class:`PlanRejected` with sentences a user can read.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, Final

from pydantic import ValidationError

from langnav.analysis.params import DEFAULT_PARAMS, AnalysisParams
from langnav.grounding.geometry import FreeSpace, Pose, free_space_for
from langnav.maps.grid import OccupancyGrid
from langnav.plan.commands import (
    MOVE_STEP_M,
    ROTATE_STEP_DEG,
    Command,
    Move,
    NavigateThroughPoses,
    Rotate,
    Stop,
    parse_command,
)
from langnav.plan.errors import PlanRejected

#: A pose off by at most this much is moved to the nearest valid cell instead of refused.
SNAP_MAX_M: Final = 0.5
#: Longest plan accepted: twenty steps of a few commands each.
MAX_COMMANDS: Final = 60
_MOVE_OFFSET: Final = {"forward": 0.0, "backward": math.pi, "left": math.pi / 2, "right": -math.pi / 2}


@dataclass(frozen=True)
class CheckedPlan:
    """A plan that passed: the (possibly repaired) commands, what was repaired, and where it ends."""

    commands: tuple[Command, ...]
    repairs: tuple[str, ...]
    end_pose: Pose


def parse_commands(raw: Sequence[Command | dict[str, Any]]) -> list[Command]:
    """Commands from dicts (LLM / file output) or already-typed commands; schema errors as reasons."""
    out: list[Command] = []
    reasons: list[str] = []
    for i, c in enumerate(raw, 1):
        if isinstance(c, dict):
            try:
                out.append(parse_command(c))
            except ValidationError as exc:
                first = exc.errors()[0]
                where = ".".join(str(p) for p in first.get("loc", ()))
                reasons.append(f"command {i} ({c.get('command', '?')!s}) is malformed: "
                               f"{first.get('msg', 'invalid')} at {where or 'top level'}")
        else:
            out.append(c)
    if reasons:
        raise PlanRejected(reasons)
    return out


def validate_plan(commands: Sequence[Command | dict[str, Any]], grid: OccupancyGrid,
                  start: Pose | tuple[float, float, float], *,
                  params: AnalysisParams = DEFAULT_PARAMS, space: FreeSpace | None = None) -> CheckedPlan:
    """Check a command sequence from ``start`` ((x, y, yaw_deg) or a Pose). Raises PlanRejected."""
    cmds = parse_commands(commands)
    pose = start if isinstance(start, Pose) else Pose.from_deg(*start)
    fs = space or free_space_for(grid, params)
    reasons: list[str] = []
    repairs: list[str] = []
    if len(cmds) > MAX_COMMANDS:
        raise PlanRejected([f"the plan has {len(cmds)} commands; at most {MAX_COMMANDS} are accepted"])
    # a Stop first halts what runs; a Stop between motions does nothing (each command finishes first)
    kept: list[Command] = []
    for i, c in enumerate(cmds):
        later_motion = any(isinstance(d, NavigateThroughPoses | Move | Rotate) for d in cmds[i + 1:])
        if isinstance(c, Stop) and i > 0 and later_motion:
            repairs.append(f"command {i + 1}: a Stop between motions does nothing (each command finishes "
                           "before the next starts), so it was left out")
            continue
        kept.append(c)
    cmds = kept
    out: list[Command] = []
    for i, c in enumerate(cmds, 1):
        if isinstance(c, NavigateThroughPoses):
            comp = fs.component_at(pose.x_m, pose.y_m)
            if comp == 0:
                where = fs.standing_problem(pose.x_m, pose.y_m)
                reasons.append(f"command {i}: there is no free space around the robot's pose "
                               f"({pose.x_m:.2f}, {pose.y_m:.2f})" + (f", which is {where}" if where else "")
                               + "; check the pose before navigating")
                out.append(c)
                continue
            new_poses: list[list[float]] = []
            for j, p in enumerate(c.poses, 1):
                x, y = float(p[0]), float(p[1])
                if not (math.isfinite(x) and math.isfinite(y)):
                    reasons.append(f"command {i}, pose {j}: coordinates must be finite numbers")
                    continue
                fixed, why = _check_pose(fs, grid, x, y, comp, params)
                if fixed is None:
                    reasons.append(f"command {i}, pose {j} ({x:.2f}, {y:.2f}): {why}")
                    continue
                if fixed != (x, y):
                    repairs.append(f"command {i}, pose {j}: moved from ({x:.2f}, {y:.2f}) to "
                                   f"({fixed[0]:.2f}, {fixed[1]:.2f}) because {why}")
                new_poses.append([round(fixed[0], 3), round(fixed[1], 3), *p[2:]])
            if new_poses:
                c = NavigateThroughPoses(poses=new_poses, note=c.note)
                prev = pose.xy if len(new_poses) == 1 else (new_poses[-2][0], new_poses[-2][1])
                last = (new_poses[-1][0], new_poses[-1][1])
                if len(new_poses[-1]) >= 3:
                    yaw = math.radians(new_poses[-1][2])
                elif math.dist(prev, last) > 1e-6:
                    yaw = math.atan2(last[1] - prev[1], last[0] - prev[0])
                else:
                    yaw = pose.yaw_rad
                pose = Pose(last[0], last[1], yaw)
        elif isinstance(c, Move):
            d = c.repeat * MOVE_STEP_M
            a = pose.yaw_rad + _MOVE_OFFSET[c.direction]
            end = (pose.x_m + d * math.cos(a), pose.y_m + d * math.sin(a))
            clear, run = fs.segment_clear(pose.xy, end, params.robot_radius_m)
            if not clear:
                reasons.append(f"command {i}: moving {c.direction} {d:.2f} m from ({pose.x_m:.2f}, "
                               f"{pose.y_m:.2f}) runs into a wall, an obstacle or unmapped space after "
                               f"{run:.2f} m")
            pose = Pose(end[0], end[1], pose.yaw_rad)
        elif isinstance(c, Rotate):
            sign = 1.0 if c.direction == "left" else -1.0
            pose = Pose(pose.x_m, pose.y_m, pose.yaw_rad + sign * math.radians(c.repeat * ROTATE_STEP_DEG))
        out.append(c)
    if reasons:
        raise PlanRejected(reasons)
    return CheckedPlan(tuple(out), tuple(repairs), pose)


def _check_pose(fs: FreeSpace, grid: OccupancyGrid, x: float, y: float, comp: int,
                params: AnalysisParams) -> tuple[tuple[float, float] | None, str]:
    """(the pose or its repair, why) — None when it can be neither used nor safely repaired."""
    if fs.index(x, y) is None:
        return None, fs.standing_problem(x, y) or "outside the map"
    problem = fs.standing_problem(x, y)
    if problem is None and fs.is_reachable(x, y, comp):
        return (x, y), ""
    why = f"it is {problem}" if problem else "the robot cannot reach it through free space from where it is"
    snapped = fs.safe_point_near((x, y), comp, SNAP_MAX_M)
    if snapped is None:
        return None, why + f", and no valid cell is within {SNAP_MAX_M} m"
    return snapped, why
