"""The ROS 2 message definitions and the CDR encoder, checked against an independent implementation
(rosbags: its store of ROS 2 Jazzy types, its .msg parser and its CDR decoder)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from langnav.maps.draw import MapBuilder
from langnav.robot.errors import RobotError
from langnav.robot.protocol import LaserScan, Pose2D
from langnav.robot.ros import interfaces as ri
from langnav.robot.ros import messages as rm

rosbags_typesys = pytest.importorskip("rosbags.typesys")
JAZZY = rosbags_typesys.get_typestore(rosbags_typesys.Stores.ROS2_JAZZY)
Nodetype = pytest.importorskip("rosbags.interfaces").Nodetype


def _rosbags_fields(type_name: str) -> list[tuple[str, str, str, int]]:
    """(name, element type, 'one' | 'seq' | 'array', fixed length) from rosbags' Jazzy store."""
    out = []
    for name, (kind, desc) in JAZZY.get_msgdef(type_name).fields:
        shape, length = "one", 0
        if kind in (Nodetype.ARRAY, Nodetype.SEQUENCE):
            shape = "array" if kind == Nodetype.ARRAY else "seq"
            (kind, desc), length = desc
        elem = desc[0] if kind == Nodetype.BASE else desc
        out.append((name, elem, shape, length if shape == "array" else 0))
    return out


@pytest.mark.parametrize("type_name", sorted(ri.MSG_DEFINITIONS))
def test_each_definition_matches_ros2_jazzy_field_by_field(type_name: str) -> None:
    mine = [(f.name, f.type, "seq" if f.sequence else "array" if f.length else "one", f.length or 0)
            for f in ri.fields(type_name)]
    assert mine == _rosbags_fields(type_name)


@pytest.mark.parametrize("type_name", sorted(ri.MSG_DEFINITIONS))
def test_full_text_is_self_contained_and_parses(type_name: str) -> None:
    text = ri.full_text(type_name)
    parsed = rosbags_typesys.get_types_from_msg(text, type_name)
    assert set(parsed) == {type_name, *ri.dependencies(type_name)}
    sections = text.split(f"\n{ri.SEPARATOR}\n")
    assert sections[0] == ri.definition(type_name)
    assert [s.splitlines()[0] for s in sections[1:]] == [f"MSG: {ri.short_name(d)}" for d in ri.dependencies(type_name)]


def test_occupancy_grid_header_lists_what_it_uses() -> None:
    deps = ri.dependencies("nav_msgs/OccupancyGrid")
    assert deps[:2] == ["std_msgs/msg/Header", "nav_msgs/msg/MapMetaData"]  # its own fields first
    assert sorted(deps) == ["builtin_interfaces/msg/Time", "geometry_msgs/msg/Point", "geometry_msgs/msg/Pose",
                            "geometry_msgs/msg/Quaternion", "nav_msgs/msg/MapMetaData", "std_msgs/msg/Header"]


def _decode(type_name: str, msg: dict[str, Any]) -> Any:
    data = ri.serialize_cdr(type_name, msg)
    assert data[:4] == ri.CDR_LE_HEADER
    return JAZZY.deserialize_cdr(data, type_name)


def test_occupancy_grid_round_trips() -> None:
    grid = MapBuilder(3.0, 2.0, resolution_m=0.05, origin=(-1.0, -0.5)).room(0.0, 0.0, 1.5, 1.0).build("g")
    msg = rm.occupancy_grid(grid, "map", 12.25)
    got = _decode(rm.OCCUPANCY_GRID, msg)
    assert (got.info.width, got.info.height) == (grid.width, grid.height)
    assert got.info.resolution == pytest.approx(0.05)
    assert (got.info.origin.position.x, got.info.origin.position.y) == (-1.0, -0.5)
    assert (got.header.frame_id, got.header.stamp.sec, got.header.stamp.nanosec) == ("map", 12, 250_000_000)
    assert np.array_equal(got.data, np.asarray(msg["data"], dtype=np.int8))
    assert set(np.unique(got.data)) <= {-1, 0, 100}


def test_odometry_path_tf_pose_and_twists_round_trip() -> None:
    p = Pose2D(1.5, -2.0, 0.75)
    odom = _decode(rm.ODOMETRY, rm.odometry(p, 0.2, -0.4, "odom", "base_link", 3.0))
    assert (odom.child_frame_id, odom.pose.pose.position.x, odom.twist.twist.angular.z) == ("base_link", 1.5, -0.4)
    assert len(odom.pose.covariance) == 36
    path = _decode(rm.PATH, rm.path([(0.0, 0.0), (1.0, 0.0), (1.0, 2.0)], "map", 1.0))
    assert [(q.pose.position.x, q.pose.position.y) for q in path.poses] == [(0.0, 0.0), (1.0, 0.0), (1.0, 2.0)]
    tf = _decode(rm.TF_MESSAGE, rm.tf_message([rm.transform_stamped("odom", "base_link", p, 2.0)]))
    assert tf.transforms[0].child_frame_id == "base_link"
    assert rm.quaternion_to_yaw(rm.yaw_to_quaternion(0.75)) == pytest.approx(0.75)
    assert tf.transforms[0].transform.rotation.z == pytest.approx(math.sin(0.375))
    amcl = _decode(rm.POSE_WITH_COV_STAMPED, rm.pose_with_covariance_stamped(p, "map", 1.0, 0.01))
    assert (amcl.pose.covariance[0], amcl.pose.covariance[7]) == (0.01, 0.01)
    tw = _decode(rm.TWIST_STAMPED, rm.cmd_vel(0.3, 0.1, True, "base_link", 1.0))
    assert (tw.twist.linear.x, tw.twist.angular.z, tw.header.frame_id) == (0.3, 0.1, "base_link")
    assert _decode(rm.TWIST, rm.twist(-0.1, 0.0)).linear.x == -0.1


@settings(max_examples=50, deadline=None)
@given(st.lists(st.one_of(st.none(), st.floats(0.0, 12.0, width=32)), min_size=0, max_size=50),
       st.text(max_size=12))
def test_laser_scan_round_trips_with_no_return_as_inf(ranges: list[float | None], frame: str) -> None:
    scan = LaserScan(-math.pi, 0.0175, 10.0, tuple(math.inf if r is None else r for r in ranges), Pose2D(0, 0, 0))
    got = _decode(rm.LASER_SCAN, rm.laser_scan(scan, frame, 5.5))
    assert got.header.frame_id == frame
    assert list(got.ranges) == [math.inf if r is None else pytest.approx(r) for r in ranges]
    assert len(got.intensities) == 0 and got.range_max == 10.0


def test_log_round_trips() -> None:
    msg = {"stamp": rm.stamp(7.5), "level": 30, "name": "langnav.robot", "msg": "blocked: ünïcode",
           "file": "x.py", "function": "f", "line": 12}
    got = _decode("rcl_interfaces/msg/Log", msg)
    assert (got.level, got.msg, got.line, got.stamp.nanosec) == (30, "blocked: ünïcode", 12, 500_000_000)


@pytest.mark.parametrize(("msg", "match"), [
    ({"linear": {"x": 0.1, "y": 0.0, "z": 0.0}}, r"Twist\.angular: missing"),
    ({"linear": {"x": "fast", "y": 0.0, "z": 0.0}, "angular": {"x": 0.0, "y": 0.0, "z": 0.0}},
     r"Twist\.linear\.x: expected a number"),
    ({"linear": [0.1], "angular": {"x": 0.0, "y": 0.0, "z": 0.0}}, r"Twist\.linear: a geometry_msgs/Vector3 must be an object"),
])
def test_a_message_that_does_not_fit_its_definition_is_named(msg: dict[str, Any], match: str) -> None:
    with pytest.raises(RobotError, match=match):
        ri.serialize_cdr(rm.TWIST, msg)


def test_bad_arrays_and_integers_are_refused() -> None:
    odom = rm.odometry(Pose2D(0, 0, 0), 0.0, 0.0, "odom", "base_link")
    odom["pose"]["covariance"] = [0.0] * 35
    with pytest.raises(RobotError, match=r"pose\.covariance: expected exactly 36 items, not 35"):
        ri.serialize_cdr(rm.ODOMETRY, odom)
    grid = rm.occupancy_grid(MapBuilder(1.0, 1.0).build("g"))
    grid["data"][0] = 300
    with pytest.raises(RobotError, match=r"OccupancyGrid\.data: expected integers in \[-128, 127\]"):
        ri.serialize_cdr(rm.OCCUPANCY_GRID, grid)
    with pytest.raises(RobotError, match="no message definition for sensor_msgs/Image; known: builtin"):
        ri.full_text("sensor_msgs/Image")
