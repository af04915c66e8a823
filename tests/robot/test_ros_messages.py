"""ROS 2 message converters: round trips, shapes per the message definitions, clear errors."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN, OccupancyGrid
from langnav.robot.errors import RobotError
from langnav.robot.protocol import LaserScan, Pose2D
from langnav.robot.ros import messages as rm

angles = st.floats(min_value=-math.pi + 1e-6, max_value=math.pi, allow_nan=False)
coords = st.floats(min_value=-1e4, max_value=1e4, allow_nan=False)


@given(angles)
def test_yaw_quaternion_round_trip(yaw: float) -> None:
    assert rm.quaternion_to_yaw(rm.yaw_to_quaternion(yaw)) == pytest.approx(yaw, abs=1e-9)


def test_quaternion_is_normalised_and_zero_is_rejected() -> None:
    q = rm.yaw_to_quaternion(0.7)
    scaled = {k: 3.0 * v for k, v in q.items()}
    assert rm.quaternion_to_yaw(scaled) == pytest.approx(0.7)
    with pytest.raises(RobotError, match="norm"):
        rm.quaternion_to_yaw({"x": 0.0, "y": 0.0, "z": 0.0, "w": 0.0})


@given(coords, coords, angles)
def test_pose_stamped_round_trip(x: float, y: float, yaw: float) -> None:
    msg = json.loads(json.dumps(rm.pose_stamped(Pose2D(x, y, yaw), "map", 12.5)))
    p, frame = rm.parse_pose_stamped(msg)
    assert frame == "map"
    assert msg["header"]["stamp"] == {"sec": 12, "nanosec": 500_000_000}
    assert (p.x_m, p.y_m) == (pytest.approx(x), pytest.approx(y))
    assert p.yaw_rad == pytest.approx(yaw, abs=1e-9)


def test_occupancy_grid_round_trip_keeps_layout_and_origin() -> None:
    cells = np.full((3, 4), UNKNOWN, dtype=np.int8)
    cells[0, :] = FREE
    cells[2, 3] = OCCUPIED
    grid = OccupancyGrid(cells, 0.05, -1.0, 2.0, 0.3)
    msg = json.loads(json.dumps(rm.occupancy_grid(grid)))
    assert (msg["info"]["width"], msg["info"]["height"]) == (4, 3)
    assert msg["data"][:4] == [0, 0, 0, 0]  # row 0 is the bottom row
    assert msg["data"][11] == 100
    back = rm.parse_occupancy_grid(msg)
    assert np.array_equal(back.cells, cells)
    assert (back.origin_x_m, back.origin_y_m) == (-1.0, 2.0)
    assert back.origin_yaw_rad == pytest.approx(0.3)


def test_occupancy_grid_thresholds_and_bad_data() -> None:
    msg = rm.occupancy_grid(OccupancyGrid(np.zeros((1, 3), dtype=np.int8), 0.1))
    msg["data"] = [10, 50, 90]  # free, unknown, occupied by map_server's thresholds
    assert rm.parse_occupancy_grid(msg).cells.tolist() == [[FREE, UNKNOWN, OCCUPIED]]
    msg["data"] = [0, 0]
    with pytest.raises(RobotError, match="expected width\\*height = 3"):
        rm.parse_occupancy_grid(msg)
    with pytest.raises(RobotError, match=r"info.resolution"):
        rm.parse_occupancy_grid({"info": {"resolution": "fine", "width": 1, "height": 1,
                                          "origin": rm.pose(0, 0, 0)}, "data": [0]})


def test_malformed_messages_name_the_field() -> None:
    with pytest.raises(RobotError, match=r"malformed /plan .*poses.0.pose"):
        rm.parse_path({"header": rm.header("map"), "poses": [{"header": rm.header("map")}]})
    with pytest.raises(RobotError, match="expected a JSON object"):
        rm.parse_cmd_vel([1, 2])


def test_path_and_scan_round_trip() -> None:
    pts = [(0.0, 0.0), (1.0, 0.0), (1.0, 2.0)]
    msg = rm.path(pts)
    assert rm.parse_path(msg) == (pts, "map")
    assert rm.quaternion_to_yaw(msg["poses"][1]["pose"]["orientation"]) == pytest.approx(math.pi / 2)
    scan = LaserScan(-math.pi, math.pi / 2, 10.0, (1.0, math.inf, 2.5, math.nan), Pose2D(1, 2, 0))
    smsg = json.loads(json.dumps(rm.laser_scan(scan), allow_nan=False))  # strict JSON
    assert smsg["ranges"] == [1.0, None, 2.5, None]
    assert smsg["angle_max"] == pytest.approx(math.pi / 2)
    back = rm.parse_laser_scan(smsg, scan.pose)
    assert back.ranges_m == (1.0, math.inf, 2.5, math.inf)


def test_cmd_vel_twist_and_twist_stamped() -> None:
    plain = rm.cmd_vel(0.2, -0.5, stamped=False)
    stamped = rm.cmd_vel(0.2, -0.5, stamped=True, frame_id="base_link")
    assert set(plain) == {"linear", "angular"}
    assert stamped["header"]["frame_id"] == "base_link"
    assert rm.parse_cmd_vel(plain) == rm.parse_cmd_vel(stamped) == (0.2, -0.5)


def test_tf_tree_composes_map_odom_base() -> None:
    tree = rm.TransformTree()
    tree.update(rm.tf_message([rm.transform_stamped("map", "odom", Pose2D(1.0, 0.0, math.pi / 2))]))
    tree.update(rm.tf_message([rm.transform_stamped("odom", "base_link", Pose2D(2.0, 0.0, 0.0))]))
    p = tree.lookup("map", "base_link")
    assert p is not None
    assert (p.x_m, p.y_m, p.yaw_rad) == (pytest.approx(1.0), pytest.approx(2.0), pytest.approx(math.pi / 2))
    inv = tree.lookup("base_link", "map")
    assert inv is not None
    back = rm.compose(p, inv)
    assert (back.x_m, back.y_m, back.yaw_rad) == (pytest.approx(0.0, abs=1e-12), pytest.approx(0.0, abs=1e-12),
                                                  pytest.approx(0.0, abs=1e-12))
    assert tree.lookup("map", "laser") is None  # not connected


@given(coords, coords, angles, coords, coords, angles)
def test_compose_invert(ax: float, ay: float, ayaw: float, bx: float, by: float, byaw: float) -> None:
    a, b = Pose2D(ax, ay, ayaw), Pose2D(bx, by, byaw)
    back = rm.compose(rm.invert(a), rm.compose(a, b))
    assert back.x_m == pytest.approx(bx, abs=1e-6)
    assert back.y_m == pytest.approx(by, abs=1e-6)
    assert rm.wrap_angle(back.yaw_rad - byaw) == pytest.approx(0.0, abs=1e-9)


def test_navigate_goal_shapes_per_distro() -> None:
    poses = [Pose2D(1.0, 2.0, 0.0), Pose2D(3.0, 4.0, math.pi)]
    jazzy = rm.navigate_through_poses_goal(poses, goal_format="pose_array")
    kilted = rm.navigate_through_poses_goal(poses, goal_format="goals")
    assert isinstance(jazzy["poses"], list) and len(jazzy["poses"]) == 2
    assert kilted["poses"]["header"]["frame_id"] == "map" and len(kilted["poses"]["goals"]) == 2
    for goal in (jazzy, kilted):
        parsed, frame = rm.parse_navigate_through_poses_goal(goal)
        assert frame == "map"
        assert [(p.x_m, p.y_m) for p in parsed] == [(1.0, 2.0), (3.0, 4.0)]
    with pytest.raises(RobotError, match="at least one"):
        rm.parse_navigate_through_poses_goal({"poses": []})
    with pytest.raises(RobotError, match="goal_format"):
        rm.navigate_through_poses_goal(poses, goal_format="array")


def test_feedback_round_trip() -> None:
    fb = rm.navigate_through_poses_feedback(Pose2D(1, 2, 0.5), "map", 3.25, 4.0, 2, recoveries=1, speed_mps=0.5)
    assert fb["estimated_time_remaining"] == {"sec": 8, "nanosec": 0}
    parsed = rm.parse_navigate_through_poses_feedback(json.loads(json.dumps(fb)), "/navigate_through_poses")
    assert parsed.distance_remaining_m == 4.0
    assert parsed.elapsed_s == pytest.approx(3.25)
    assert (parsed.poses_remaining, parsed.recoveries) == (2, 1)
    assert parsed.pose.yaw_rad == pytest.approx(0.5)


def test_robot_pose_from_each_pose_topic_type() -> None:
    p = Pose2D(1.5, -2.0, 1.0)
    for msg in (rm.pose_with_covariance_stamped(p, "map"), rm.pose_stamped(p, "map"),
                rm.odometry(p, 0.1, 0.2, "odom", "base_link")):
        got, _frame = rm.parse_robot_pose(msg, "/pose")
        assert (got.x_m, got.y_m, got.yaw_rad) == (pytest.approx(1.5), pytest.approx(-2.0), pytest.approx(1.0))
