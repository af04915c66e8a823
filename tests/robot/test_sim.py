"""The simulator backend: navigation, Move / Rotate step semantics, replanning, failures, cancel,
determinism, the clock. Small built worlds; headless, so ``wait`` drives the simulated clock."""

from __future__ import annotations

import math

import numpy as np
import pytest

from langnav.maps.draw import MapBuilder
from langnav.maps.grid import OccupancyGrid
from langnav.robot import RobotError, RobotTimeout, TaskStatus, create_backend
from langnav.robot.protocol import Pose2D, RobotBackend, TaskHandle
from langnav.robot.sim import ROBOT_RADIUS_M, SimBackend, create_sim


def room_world() -> OccupancyGrid:
    """A 6 m x 4 m room (free [0, 6] x [0, 4]) with a 0.6 m box at its centre-right."""
    b = MapBuilder(8.0, 6.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 6.0, 4.0)
    b.box(4.2, 1.7, 4.8, 2.3)
    return b.build("room")


def two_rooms_world() -> OccupancyGrid:
    """Two rooms joined by one 0.9 m door at (4, 1.0); the east room also has a sealed closet."""
    b = MapBuilder(10.0, 6.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 3.9, 4.0)
    b.room(4.1, 0.0, 8.0, 4.0)
    b.door_v(4.0, 1.0, 0.9)
    b.box(6.5, 2.6, 8.0, 4.0)      # the closet's walls ...
    b.free(6.65, 2.75, 7.9, 3.9)   # ... and its sealed inside
    return b.build("two rooms")


def sim(world: OccupancyGrid, pose: tuple[float, float, float], **kw: object) -> SimBackend:
    kw.setdefault("known_map", True)
    return create_sim(world, pose, **kw)  # type: ignore[arg-type]


def yaw_deg(s: SimBackend) -> float:
    return math.degrees(s.pose.yaw_rad)


def test_registered_and_protocol_shaped() -> None:
    s = create_backend("sim", world=room_world(), pose=(1.0, 1.0, 0.0))
    assert isinstance(s, SimBackend)
    assert isinstance(s, RobotBackend)
    h = s.rotate("left", 1)
    assert isinstance(h, TaskHandle)
    assert h.wait(10).status is TaskStatus.SUCCEEDED


def test_navigate_reaches_goal_around_box() -> None:
    s = sim(room_world(), (1.0, 2.0, 0.0))
    h = s.navigate_through_poses([(5.5, 2.0)])
    r = h.wait(120)
    assert r.status is TaskStatus.SUCCEEDED, r.message
    assert math.hypot(s.pose.x_m - 5.5, s.pose.y_m - 2.0) < 0.3
    assert s.collisions == 0
    assert s.linear_mps == 0.0 and s.angular_radps == 0.0
    assert s.get_current_path() == []


def test_navigate_through_poses_visits_each_and_final_yaw() -> None:
    s = sim(room_world(), (1.0, 1.0, 0.0))
    seen: list[tuple[float, float]] = []
    h = s.navigate_through_poses([(1.0, 3.2), (3.0, 3.2, -90.0)])
    while h.status() is TaskStatus.RUNNING:
        s.step(0.2)
        seen.append((s.pose.x_m, s.pose.y_m))
        assert s.time_s < 120
    assert h.wait(1).status is TaskStatus.SUCCEEDED
    assert min(math.hypot(x - 1.0, y - 3.2) for x, y in seen) < 0.5
    assert abs(yaw_deg(s) - (-90.0)) < 10.0


@pytest.mark.parametrize("steps", [1, 10, 33])
def test_move_forward_is_three_cm_a_step(steps: int) -> None:
    s = sim(room_world(), (1.0, 1.0, 30.0))
    r = s.move("forward", steps).wait(60)
    assert r.status is TaskStatus.SUCCEEDED, r.message
    d = math.hypot(s.pose.x_m - 1.0, s.pose.y_m - 1.0)
    assert d == pytest.approx(0.03 * steps, abs=0.006)
    heading = math.degrees(math.atan2(s.pose.y_m - 1.0, s.pose.x_m - 1.0))
    assert heading == pytest.approx(30.0, abs=2.0)


def test_move_backward_drives_in_reverse() -> None:
    s = sim(room_world(), (2.0, 2.0, 0.0))
    assert s.move("backward", 20).wait(60).status is TaskStatus.SUCCEEDED
    assert s.pose.x_m == pytest.approx(2.0 - 0.6, abs=0.01)
    assert s.pose.y_m == pytest.approx(2.0, abs=0.01)
    assert yaw_deg(s) == pytest.approx(0.0, abs=1.0)


@pytest.mark.parametrize(("direction", "dy"), [("left", 0.3), ("right", -0.3)])
def test_move_sideways_turns_drives_turns_back(direction: str, dy: float) -> None:
    s = sim(room_world(), (2.0, 2.0, 0.0))
    h = s.move(direction, 10)
    s.step(1.0)
    fb = h.feedback()
    assert fb is not None and fb.angle_remaining_rad is not None and fb.angle_remaining_rad > 0
    assert h.wait(60).status is TaskStatus.SUCCEEDED
    assert s.pose.x_m == pytest.approx(2.0, abs=0.015)
    assert s.pose.y_m == pytest.approx(2.0 + dy, abs=0.015)
    assert yaw_deg(s) == pytest.approx(0.0, abs=1.0)


@pytest.mark.parametrize(("direction", "steps", "expect"), [("left", 9, 90.0), ("right", 9, -90.0),
                                                             ("left", 1, 10.0), ("right", 18, 180.0)])
def test_rotate_is_ten_degrees_a_step(direction: str, steps: int, expect: float) -> None:
    s = sim(room_world(), (2.0, 2.0, 0.0))
    assert s.rotate(direction, steps).wait(60).status is TaskStatus.SUCCEEDED
    err = (yaw_deg(s) - expect + 180.0) % 360.0 - 180.0
    assert abs(err) < 1.0
    assert (s.pose.x_m, s.pose.y_m) == (2.0, 2.0)


def test_rotate_full_turns_counts_the_angle_not_the_heading() -> None:
    s = sim(room_world(), (2.0, 2.0, 0.0))
    h = s.rotate("left", 36)
    s.step(2.0)
    assert h.status() is TaskStatus.RUNNING  # 360 degrees take longer than 2 s at 1 rad/s
    assert h.wait(60).status is TaskStatus.SUCCEEDED
    assert s.time_s > 2 * math.pi / 1.0


def test_move_into_a_wall_stops_short_without_touching_it() -> None:
    s = sim(room_world(), (5.5, 3.0, 0.0))  # 0.5 m from the east wall
    r = s.move("forward", 40).wait(60)
    assert r.status is TaskStatus.FAILED
    assert "obstacle ahead" in r.message
    s.step(1.0)
    assert s.collisions == 0
    assert s.world.clearance_m(s.pose.x_m, s.pose.y_m) >= ROBOT_RADIUS_M
    assert s.linear_mps == 0.0


def test_new_obstacle_on_the_path_is_seen_and_avoided() -> None:
    s = sim(room_world(), (0.6, 0.8, 0.0))
    h = s.navigate_through_poses([(5.5, 0.8)])
    s.step(2.0)
    s.add_obstacle(3.0, 0.8, 0.3)  # right across the straight line along the south wall
    track = []
    while h.status() is TaskStatus.RUNNING and s.time_s < 150:
        s.step(0.2)
        track.append((s.pose.x_m, s.pose.y_m))
    r = h.wait(1)
    assert r.status is TaskStatus.SUCCEEDED, r.message
    assert s.collisions == 0
    assert min(math.hypot(x - 3.0, y - 0.8) for x, y in track) >= 0.3 + ROBOT_RADIUS_M
    grid = s.get_map()  # the obstacle's faces that the robot saw are on its map now
    rows, cols = np.nonzero(grid.occupied)
    xs, ys = grid.cell_to_world(rows, cols)
    assert int((np.hypot(xs - 3.0, ys - 0.8) < 0.35).sum()) >= 5


def test_doorway_blocked_then_goal_fails_with_reason_and_robot_stops() -> None:
    s = sim(two_rooms_world(), (1.0, 1.0, 0.0))
    h = s.navigate_through_poses([(6.0, 1.0)])
    s.step(1.0)
    s.add_obstacle(4.0, 1.0, 0.5)  # seals the only door
    r = h.wait(200)
    assert r.status is TaskStatus.FAILED
    assert "cannot reach" in r.message or "no progress" in r.message
    assert s.collisions == 0
    s.step(0.5)
    assert s.linear_mps == 0.0 and s.angular_radps == 0.0
    assert s.pose.x_m < 4.0


def test_unreachable_goal_fails_quickly_with_reason() -> None:
    s = sim(two_rooms_world(), (1.0, 1.0, 0.0))
    r = s.navigate_through_poses([(7.2, 3.3)]).wait(60)  # inside the sealed closet
    assert r.status is TaskStatus.FAILED
    assert "cannot reach the goal" in r.message and "walled off" in r.message
    assert s.time_s < 10.0


def test_goal_inside_a_wall_fails_with_reason() -> None:
    s = sim(room_world(), (1.0, 1.0, 0.0))
    r = s.navigate_through_poses([(4.5, 2.0)]).wait(60)  # the box's centre
    assert r.status is TaskStatus.FAILED
    assert "obstacle" in r.message


def test_cancel_mid_way_stops_the_robot() -> None:
    s = sim(room_world(), (1.0, 1.0, 0.0))
    h = s.navigate_through_poses([(5.5, 3.5)])
    s.step(3.0)
    assert s.linear_mps > 0
    h.cancel()
    r = h.wait(1)
    assert r.status is TaskStatus.CANCELED
    here = s.pose
    s.step(2.0)
    assert (s.pose.x_m, s.pose.y_m) == (here.x_m, here.y_m)
    assert not s.state().busy


def test_stop_wins_at_once() -> None:
    s = sim(room_world(), (1.0, 1.0, 0.0))
    h = s.move("forward", 60)
    s.step(1.0)
    s.stop()
    assert h.status() is TaskStatus.CANCELED
    assert s.linear_mps == 0.0


def test_new_command_preempts_the_running_one() -> None:
    s = sim(room_world(), (1.0, 1.0, 0.0))
    first = s.navigate_through_poses([(5.5, 3.5)])
    s.step(1.0)
    second = s.rotate("left", 3)
    assert first.wait(0.1).status is TaskStatus.CANCELED
    assert "preempted" in first.wait(0.1).message
    assert second.wait(30).status is TaskStatus.SUCCEEDED


def test_wait_timeout_raises_and_leaves_the_task_running() -> None:
    s = sim(room_world(), (1.0, 1.0, 0.0))
    h = s.navigate_through_poses([(5.5, 3.5)])
    with pytest.raises(RobotTimeout, match="still running"):
        h.wait(1.0)
    assert h.status() is TaskStatus.RUNNING
    assert s.time_s == pytest.approx(1.0, abs=0.06)
    assert h.wait(120).status is TaskStatus.SUCCEEDED


def test_feedback_reports_distance_and_time() -> None:
    s = sim(room_world(), (1.0, 1.0, 0.0))
    h = s.navigate_through_poses([(3.0, 1.0)])
    s.step(1.0)
    fb = h.feedback()
    assert fb is not None
    assert fb.elapsed_s == pytest.approx(1.0, abs=0.06)
    assert fb.distance_remaining_m is not None and 1.4 < fb.distance_remaining_m < 2.0
    assert fb.poses_remaining == 1
    path = s.get_current_path()
    assert len(path) > 10 and math.hypot(path[-1][0] - 3.0, path[-1][1] - 1.0) < 0.3


def test_same_seed_same_run_different_seed_different_noise() -> None:
    def run(seed: int) -> tuple[Pose2D, tuple[float, ...]]:
        s = sim(room_world(), (1.0, 1.0, 0.0), known_map=False, seed=seed)
        s.navigate_through_poses([(5.0, 3.3)]).wait(120)
        s.move("left", 5).wait(30)
        scan = s.state().scan
        assert scan is not None
        return s.pose, scan.ranges_m

    a, b, c = run(7), run(7), run(8)
    assert a == b
    assert a[1] != c[1]


def test_empty_map_is_built_from_scans() -> None:
    world = room_world()
    s = sim(world, (1.0, 2.0, 0.0), known_map=False)
    grid0 = s.get_map()
    s.rotate("left", 36).wait(60)
    grid = s.get_map()
    assert grid.free.sum() > grid0.free.sum()
    truth_free = world.free
    seen = grid.free & truth_free
    assert seen.sum() / truth_free.sum() > 0.8  # a 6 x 4 m room is all in view
    assert not (grid.free & world.occupied).any()
    # walls come out occupied where the beams hit them (the west wall, 1 m away)
    assert grid.value_at(-0.05, 2.0) == 100
    # map_saver's trinary shades
    assert set(np.unique(grid.to_image()).tolist()) <= {0, 205, 254}


def test_known_map_starts_with_the_world() -> None:
    world = room_world()
    s = sim(world, (1.0, 2.0, 0.0), known_map=True)
    grid = s.get_map()
    assert (grid.free == world.free).mean() > 0.99


def test_start_in_a_wall_is_refused() -> None:
    with pytest.raises(RobotError, match="start pose"):
        sim(room_world(), (4.5, 2.0, 0.0))


@pytest.mark.parametrize(("call", "args"), [("move", ("up", 3)), ("move", ("forward", 0)),
                                            ("rotate", ("forward", 3)), ("rotate", ("left", -1))])
def test_bad_arguments_are_refused_with_the_options(call: str, args: tuple[object, ...]) -> None:
    s = sim(room_world(), (1.0, 1.0, 0.0))
    with pytest.raises(RobotError):
        getattr(s, call)(*args)


def test_navigate_refuses_empty_or_non_finite_poses() -> None:
    s = sim(room_world(), (1.0, 1.0, 0.0))
    with pytest.raises(RobotError):
        s.navigate_through_poses([])
    with pytest.raises(RobotError):
        s.navigate_through_poses([(math.nan, 1.0)])


def test_threaded_clock_and_wall_clock_wait() -> None:
    s = sim(room_world(), (1.0, 1.0, 0.0))
    s.start(realtime=False)
    try:
        assert s.running
        r = s.navigate_through_poses([(2.0, 1.0)]).wait(30)
        assert r.status is TaskStatus.SUCCEEDED
    finally:
        s.close()
    assert not s.running
    with pytest.raises(RobotError, match="closed"):
        s.rotate("left", 1)


def test_state_snapshot() -> None:
    s = sim(room_world(), (1.0, 1.0, 0.0))
    s.navigate_through_poses([(5.0, 1.0)])
    s.step(1.0)
    st = s.state()
    assert st.busy and st.goals == ((5.0, 1.0),)
    assert st.scan is not None and len(st.scan.ranges_m) == 360
    assert len(st.path) > 5
    assert st.time_s == pytest.approx(1.0, abs=0.06)
    assert st.extra["collisions"] == 0


# -- teleop (set_velocity: what /cmd_vel drives over rosbridge) ----------------------------------
def test_teleop_velocity_is_held_for_the_timeout_then_the_base_stops() -> None:
    from langnav.robot.sim.backend import TELEOP_TIMEOUT_S

    s = sim(room_world(), (1.0, 2.0, 0.0))
    s.set_velocity(0.2, 0.0)
    s.step(TELEOP_TIMEOUT_S - 0.1)
    assert s.linear_mps == pytest.approx(0.2)  # reached (0.5 m/s² ramp) and held
    assert s.state().extra["teleop"] is True
    s.step(1.0)  # no new command: the cmd_vel timeout stops it
    assert s.linear_mps == 0.0 and s.state().extra["teleop"] is False
    stopped = s.pose
    s.step(1.0)
    assert s.pose == stopped
    # it drove at most 0.2 m/s for the timeout plus the braking
    assert 0.04 < stopped.x_m - 1.0 < 0.2 * (TELEOP_TIMEOUT_S + 0.2)


def test_teleop_respects_speed_and_acceleration_limits() -> None:
    s = sim(room_world(), (1.0, 2.0, 0.0))
    lim = s.config.limits
    s.set_velocity(5.0, -9.0)
    s.step()
    assert s.linear_mps == pytest.approx(lim.max_linear_accel_mps2 * s.config.control_dt_s)
    for _ in range(40):
        s.set_velocity(5.0, -9.0)
        s.step(0.1)
    assert s.linear_mps == pytest.approx(lim.max_linear_mps)
    assert s.angular_radps == pytest.approx(-lim.max_angular_radps)


def test_teleop_into_a_wall_stops_short_without_a_collision() -> None:
    s = sim(room_world(), (5.0, 3.2, 0.0))
    for _ in range(60):  # 6 s at full speed towards the east wall at x = 6
        s.set_velocity(0.3, 0.0)
        s.step(0.1)
    assert s.collisions == 0 and s.teleop_blocks >= 1
    assert 6.0 - ROBOT_RADIUS_M - 0.15 < s.pose.x_m < 6.0 - ROBOT_RADIUS_M
    s.set_velocity(0.0, 1.0)  # turning in place stays allowed
    s.step(0.4)
    assert s.pose.yaw_rad > 0.1


def test_teleop_cancels_a_running_task_but_a_zero_command_does_not() -> None:
    s = sim(room_world(), (1.0, 2.0, 0.0))
    h = s.navigate_through_poses([(3.0, 2.0)])
    s.step(1.0)
    s.set_velocity(0.0, 0.0)  # a released joystick: navigation goes on
    assert h.status() is TaskStatus.RUNNING
    v0 = s.linear_mps
    s.set_velocity(-0.1, 0.0)
    r = h.wait(1.0)
    assert r.status is TaskStatus.CANCELED and "teleop" in r.message
    s.step(0.3)
    assert not s.state().busy
    assert s.linear_mps == pytest.approx(v0 - 0.5 * 0.3)  # braking towards -0.1 m/s at 0.5 m/s²
    h2 = s.rotate("left", 9)  # a new task ends teleop
    assert s.state().extra["teleop"] is False
    assert h2.wait(20).status is TaskStatus.SUCCEEDED


@pytest.mark.parametrize(("v", "w"), [(math.nan, 0.0), (0.1, math.inf)])
def test_teleop_refuses_non_finite_velocity(v: float, w: float) -> None:
    s = sim(room_world(), (1.0, 2.0, 0.0))
    with pytest.raises(RobotError, match="finite"):
        s.set_velocity(v, w)
