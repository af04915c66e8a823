"""Option types the subcommands share (argparse ``type=`` callables), so each is parsed one way."""

from __future__ import annotations

import argparse
import math


def pose_arg(text: str) -> tuple[float, float, float]:
    """``--pose X,Y[,YAW_DEG]``: map-frame metres and degrees (yaw 0 when left out), all finite."""
    try:
        parts = [float(v) for v in text.replace(" ", "").split(",")]
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"--pose is X,Y,YAW_DEG in metres and degrees, e.g. 1.5,4.9,0 (use --pose=-1,2,0 for negatives); "
            f"got {text!r}") from None
    if len(parts) not in (2, 3) or not all(math.isfinite(v) for v in parts):
        raise argparse.ArgumentTypeError(f"--pose is X,Y[,YAW_DEG] (two or three finite numbers), got {text!r}")
    return parts[0], parts[1], parts[2] if len(parts) == 3 else 0.0


def seconds_arg(text: str) -> float:
    """A time limit in seconds: a positive, finite number."""
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and value > 0):
        raise argparse.ArgumentTypeError(f"expected a positive number of seconds, e.g. 600; got {text!r}")
    return value


def seed_arg(text: str) -> int:
    """A random seed: a whole number >= 0."""
    try:
        value = int(text)
    except ValueError:
        value = -1
    if value < 0:
        raise argparse.ArgumentTypeError(f"expected a whole number >= 0, got {text!r}")
    return value


__all__ = ["pose_arg", "seconds_arg", "seed_arg"]
