"""``langnav run`` end to end on a built world: JSON lines, the last one's exact shape, exit codes."""

from __future__ import annotations

import json
import math
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from langnav.cli import main
from langnav.maps.draw import MapBuilder
from langnav.maps.io import save_map
from langnav.robot.protocol import create_backend
from langnav.robot.ros.rosbridge_server import RosbridgeServer, RosbridgeServerConfig


@pytest.fixture
def world_yaml(tmp_path: Path) -> Path:
    b = MapBuilder(8.0, 6.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 6.0, 4.0)
    b.box(4.2, 2.8, 4.8, 3.4)
    yaml_path, _ = save_map(b.build("cli room"), tmp_path / "room.yaml")
    return yaml_path


def lines(out: str) -> list[dict[str, object]]:
    return [json.loads(line) for line in out.splitlines() if line.strip()]


def test_json_run_moves_and_ends_with_the_finished_line(world_yaml: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["run", "--world", str(world_yaml), "--pose", "1,2,0", "--known-map", "--json",
                 "move forward 1 meter, then turn left"])
    events = lines(capsys.readouterr().out)
    assert code == 0
    last = events[-1]
    assert set(last) == {"event", "status", "pose"}
    assert last["event"] == "finished" and last["status"] == "succeeded"
    x, y, yaw = last["pose"]  # type: ignore[misc]
    assert x == pytest.approx(1.99, abs=0.03) and y == pytest.approx(2.0, abs=0.03)
    assert yaw == pytest.approx(90.0, abs=2.0)
    kinds = [e["event"] for e in events if e["event"] != "progress"]
    assert kinds == ["plan", "started", "succeeded", "started", "succeeded", "finished"]


def test_a_refused_prompt_runs_nothing(world_yaml: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["run", "--world", str(world_yaml), "--pose", "1,2,0", "--known-map", "--json", "go to the kitchen"])
    events = lines(capsys.readouterr().out)
    assert code == 2
    assert events[0]["event"] == "rejected" and events[0]["message"]
    assert events[-1] == {"event": "finished", "status": "rejected", "pose": [1.0, 2.0, 0.0]}


def test_text_output_names_each_step(world_yaml: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["run", "--world", str(world_yaml), "--pose", "1,2,0", "--known-map", "turn right 30 degrees"])
    out = capsys.readouterr().out
    assert code == 0
    assert "Turn right 30°" in out
    assert out.strip().splitlines()[-1].startswith("finished: succeeded at (1.00, 2.00, -30°)")


# -- over rosbridge: `langnav run --backend rosbridge` against the server `langnav sim` runs ---------
#: The served simulator's clock runs this many times faster than the wall clock.
SIM_SPEED = 4.0
DEMO_START = (12.2, 1.8, 0.0)  # in the demo floor's south-east room, facing east


@pytest.fixture
def served_demo() -> Iterator[tuple[Any, int]]:
    """What `langnav sim --world demo --known-map --rosbridge-port 0` runs, in-process."""
    sim: Any = create_backend("sim", world="demo", pose=DEMO_START, known_map=True)
    # the clock runs SIM_SPEED times faster: odometry and tf at SIM_SPEED x the default rate keep
    # the same rate in robot time, so the closed-loop Move sees the robot as often as it would live
    default = RosbridgeServerConfig()
    server = RosbridgeServer(sim, RosbridgeServerConfig(state_rate_hz=default.state_rate_hz * SIM_SPEED))
    sim.start(realtime=True, speed=SIM_SPEED)
    port = server.start("127.0.0.1", 0)
    yield sim, port
    server.close()
    sim.close()


def _run_json(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, list[dict[str, Any]]]:
    code = main(["run", "--json", "--timeout", "60", *argv])
    return code, [e for e in lines(capsys.readouterr().out) if e["event"] != "progress"]


def test_move_over_rosbridge_drives_the_served_simulator(served_demo: tuple[Any, int],
                                                         capsys: pytest.CaptureFixture[str]) -> None:
    sim, port = served_demo
    code, events = _run_json(capsys, "--backend", "rosbridge", "--rosbridge-url", f"ws://127.0.0.1:{port}",
                             "move forward half a metre")
    assert code == 0, events
    assert [e["event"] for e in events] == ["plan", "started", "succeeded", "finished"]
    assert events[0]["pose"] == pytest.approx(list(DEMO_START), abs=0.01)  # the robot's pose, from tf
    x, y, yaw = events[-1]["pose"]  # type: ignore[misc]
    moved = events[0]["commands"][0]["repeat"] * 0.03  # type: ignore[index]
    assert moved == pytest.approx(0.5, abs=0.03)
    assert (x, y, yaw) == (pytest.approx(DEMO_START[0] + moved, abs=0.03), pytest.approx(DEMO_START[1], abs=0.02),
                           pytest.approx(0.0, abs=2.0))
    truth = sim.get_robot_pose()  # the simulator agrees with what the robot reported
    assert (truth.x_m, truth.y_m) == (pytest.approx(x, abs=0.02), pytest.approx(y, abs=0.02))
    assert sim.collisions == 0


def test_nearest_door_over_rosbridge_is_grounded_on_the_robots_map(
        served_demo: tuple[Any, int], world_yaml: Path, capsys: pytest.CaptureFixture[str]) -> None:
    sim, port = served_demo
    # the same prompt in the simulator directly, on the same floor: where the nearest door is
    code, local = _run_json(capsys, "--world", "demo", "--pose", ",".join(map(str, DEMO_START)), "--known-map",
                            "go to the nearest door")
    assert code == 0
    door = local[0]["commands"][0]["poses"][-1]  # type: ignore[index]
    # over rosbridge, with a --world that is another floor: ignored, the map comes from the robot's /map
    code, events = _run_json(capsys, "--backend", "rosbridge", "--rosbridge-url", f"ws://127.0.0.1:{port}",
                             "--world", str(world_yaml), "go to the nearest door")
    assert code == 0, events
    plan = events[0]
    assert plan["commands"][0]["command"] == "NavigateThroughPoses"  # type: ignore[index]
    assert plan["commands"][0]["poses"][-1] == pytest.approx(door, abs=0.1)  # type: ignore[index]
    x, y, _ = events[-1]["pose"]  # type: ignore[misc]
    assert math.hypot(x - door[0], y - door[1]) < 0.3  # within Nav2's goal tolerance
    truth = sim.get_robot_pose()
    assert math.hypot(truth.x_m - x, truth.y_m - y) < 0.05
    assert events[-1]["status"] == "succeeded" and sim.collisions == 0


def test_ros2_backend_without_ros_is_a_clear_error(capsys: pytest.CaptureFixture[str]) -> None:
    try:
        import rclpy  # noqa: F401
    except ImportError:
        pass
    else:
        pytest.skip("ROS 2 is installed here")
    code = main(["run", "--backend", "ros2", "--json", "turn left"])
    err = capsys.readouterr().err
    assert code == 2
    assert "needs ROS 2 (rclpy)" in err and "--backend rosbridge" in err


@pytest.mark.parametrize(("url", "message"), [("http://robot:9090", "--rosbridge-url is ws://HOST:PORT"),
                                               ("ws://robot:99999", "bad port")])
def test_a_bad_rosbridge_url_is_refused_before_connecting(url: str, message: str,
                                                          capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["run", "--backend", "rosbridge", "--rosbridge-url", url, "turn left"])
    assert code == 2 and message in capsys.readouterr().err
