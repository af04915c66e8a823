from __future__ import annotations

import base64
import io
import math

import numpy as np
from PIL import Image

from langnav.maps.draw import MapBuilder
from langnav.robot.protocol import LaserScan, Pose2D, RobotState
from langnav.web.mapframes import (
    PALETTE,
    grid_digest,
    map_frame,
    path_frame,
    scan_points,
    state_frame,
)


def _grid():  # type: ignore[no-untyped-def]
    return MapBuilder(2.0, 1.0, resolution_m=0.1, origin=(-1.0, 0.5)).free(-1.0, 0.5, 0.0, 1.5).box(0.5, 0.5, 1.0, 1.0).build()


def test_map_png_round_trips_cells_in_image_orientation() -> None:
    g = _grid()
    frame = map_frame(g, grid_digest(g))
    img = Image.open(io.BytesIO(base64.b64decode(frame["png"]))).convert("RGB")
    rgb = np.asarray(img)
    assert (frame["width"], frame["height"], frame["resolution"], frame["origin"]) == (20, 10, 0.1, [-1.0, 0.5, 0.0])
    # bottom-left cell (row 0) is free -> last image row, first column is white
    assert tuple(rgb[-1, 0]) == PALETTE[0]
    # the box's cells (bottom-right quarter) are occupied -> dark
    assert tuple(rgb[-1, -1]) == PALETTE[1]
    # top-right is unknown
    assert tuple(rgb[0, -1]) == PALETTE[2]


def test_digest_changes_with_any_cell() -> None:
    g = _grid()
    cells = g.cells.copy()
    cells[3, 3] = 100
    assert grid_digest(g) == grid_digest(g.with_cells(g.cells.copy()))
    assert grid_digest(g) != grid_digest(g.with_cells(cells))


def test_scan_points_in_map_frame_skip_no_return() -> None:
    pose = Pose2D(1.0, 2.0, math.pi / 2)
    scan = LaserScan(angle_min_rad=0.0, angle_increment_rad=math.pi / 2, range_max_m=10.0,
                     ranges_m=(1.0, math.inf, 2.0, 10.0), pose=pose)
    # beam 0 points along the robot's heading (north), beam 2 behind it (south)
    assert scan_points(RobotState(pose=pose, scan=scan)) == [1.0, 3.0, 1.0, 0.0]


def test_state_frame_is_small_and_path_frame_decimated() -> None:
    st = RobotState(pose=Pose2D(1.23456, 2.0, 0.5), path=tuple((i * 0.01, 0.0) for i in range(5000)),
                    goals=((3.333333, 4.0),), busy=True)
    f = state_frame(st, "sim", "I'm here.", {"state": "running"}, 0.17)
    assert f["pose"] == [1.235, 2.0, 0.5]
    assert "path" not in f and "scan" not in f
    p = path_frame(st)
    assert len(p["path"]) == 400 and p["path"][0] == [0.0, 0.0] and p["path"][-1] == [49.99, 0.0]
    assert p["goals"] == [[3.33, 4.0]]
