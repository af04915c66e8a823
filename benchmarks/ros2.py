"""The ros2 backend on a real ROS 2 graph (the real-ROS 2 tier's venv): prompts end to end, STOP,
reconnects.

1. Every development prompt of ../shared/bench/prompts_dev.jsonl that moves the robot, end to end
   through ROS 2: the simulator at the case's start pose is served as a Nav2-shaped robot
   (RobotNode: the saved map as map_server serves it, tf, Nav2's actions on rclpy); langnav's ros2 backend reads the map and the pose
   from the graph, the offline translator and grounding plan on them, and the plan runs through
   Nav2's action interfaces. Does the robot end in the goal region without a collision (>= 95 %)?
2. STOP: a navigation under way in real time, stop(): time until the robot's speed is zero.
3. 40 connect / disconnect cycles of the backend (pose and map each time): 40/40.

Run inside the tier's venv with its environment (``make bench`` does, when .venv-ros2 exists;
or ``make test-ros2`` first, then ``make bench-ros2``). Prints why and exits 0 when ROS 2 or
../shared is missing.
"""

from __future__ import annotations

import json
import os
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any, Final

if TYPE_CHECKING:
    from langnav.robot.protocol import RobotBackend

os.environ.setdefault("ROS_DOMAIN_ID", str(10 + os.getpid() % 90))
os.environ.setdefault("ROS_AUTOMATIC_DISCOVERY_RANGE", "LOCALHOST")

BENCH = Path(__file__).resolve().parents[2] / "shared" / "bench"
TARGET_PROMPTS: Final = 0.95
#: The simulator runs this many times faster than real time for the prompts (the ROS side is
#: wall-clock: Nav2's time allowances are generous enough for it).
PROMPT_SPEED: Final = 4.0
STOP_TRIALS: Final = 5
RECONNECTS: Final = 40
#: How long a case waits for the map (latched: it is there at once unless the graph is slow to
#: match) and for the pose (tf at 20 Hz).
MAP_TIMEOUT_S: Final = 20.0
POSE_TIMEOUT_S: Final = 10.0


def run_bench_prompts(bench: Path = BENCH, speed: float = PROMPT_SPEED,
                      connect: Callable[[], RobotBackend] | None = None) -> tuple[int, int, list[str]]:
    """(cases in the goal region, cases that move the robot, what went wrong with the others).

    ``connect`` opens langnav's side of the graph for each case (the rclpy backend by default; the
    rosbridge tests pass one that connects through rosbridge).
    """
    from langnav.eval.endpoint import ended_as_expected, expected_end
    from langnav.language.translator import get_translator
    from langnav.maps.io import load_map
    from langnav.pipeline import Planner
    from langnav.plan.events import PlanStatus, pose_tuple
    from langnav.plan.executor import PlanExecutor
    from langnav.robot.ros.backend import Ros2Backend
    from langnav.robot.ros.robot_node import RobotNode
    from langnav.robot.sim import create_sim

    cases = [json.loads(line) for line in (bench / "prompts_dev.jsonl").read_text().splitlines() if line.strip()]
    moving = [c for c in cases if isinstance(c["expect"], list) and expected_end(c) is not None]
    planner = Planner(get_translator("offline"))
    worlds: dict[str, Any] = {}
    ok = 0
    misses: list[str] = []
    for case in moving:
        world = worlds.setdefault(case["map"], load_map(bench / case["map"]))
        sim = create_sim(world, tuple(case["pose"]), known_map=True)
        sim.start(realtime=True, speed=speed)
        node = RobotNode(sim, static_map=world)  # a floor already mapped: map_server's saved map
        robot = connect() if connect is not None else Ros2Backend()
        why = ""
        try:
            result = planner.plan(case["prompt"], robot.get_map(MAP_TIMEOUT_S), pose_tuple(robot.get_robot_pose(POSE_TIMEOUT_S)))
            if result.clarification is not None:
                why = f"not planned: {result.clarification}"
            else:
                status = PlanExecutor(robot).run(result.items, timeout_s=300)
                if status is not PlanStatus.SUCCEEDED:
                    why = f"plan {status.value}"
        finally:
            robot.close()
            node.close()
            sim.close()
        x, y = sim.pose.x_m, sim.pose.y_m
        end = expected_end(case)
        inside = end is not None and ended_as_expected(end, x, y)
        if inside and sim.collisions == 0 and not why:
            ok += 1
        else:
            misses.append(f"{case['id']}: {case['prompt']!r}: "
                          f"{why or ('collision' if sim.collisions else f'ended at ({x:.2f}, {y:.2f})')}")
    return ok, len(moving), misses


def stop_times(trials: int = STOP_TRIALS) -> list[float]:
    """Seconds from stop() to zero speed, the simulator in real time, one navigation per trial."""
    from langnav.robot.ros.backend import Ros2Backend
    from langnav.robot.ros.robot_node import RobotNode
    from langnav.robot.sim import create_sim

    sim = create_sim(None, (12.2, 1.8, 180.0), known_map=True)
    sim.start(realtime=True, speed=1.0)
    node = RobotNode(sim)
    robot = Ros2Backend()
    times: list[float] = []
    try:
        for i in range(trials):
            goal = (6.5, 4.9) if i % 2 == 0 else (12.5, 1.8)
            handle = robot.navigate_through_poses([goal])
            deadline = time.monotonic() + 10.0
            while abs(sim.linear_mps) < 0.1 and time.monotonic() < deadline:
                time.sleep(0.01)
            time.sleep(0.5)
            t0 = time.monotonic()
            robot.stop()
            while abs(sim.linear_mps) > 1e-6 or abs(sim.angular_radps) > 1e-6:
                if time.monotonic() - t0 > 5.0:
                    break
                time.sleep(0.002)
            times.append(time.monotonic() - t0)
            handle.wait(10.0)
    finally:
        robot.close()
        node.close()
        sim.close()
    return times


def reconnects(n: int = RECONNECTS) -> tuple[int, float]:
    from langnav.robot.ros.backend import Ros2Backend
    from langnav.robot.ros.robot_node import RobotNode
    from langnav.robot.sim import create_sim

    sim = create_sim(None, (12.2, 1.8, 180.0), known_map=True)
    sim.start(realtime=True)
    node = RobotNode(sim)
    ok = 0
    t0 = time.monotonic()
    try:
        for _ in range(n):
            try:
                robot = Ros2Backend()
            except Exception as exc:
                print(f"  connect failed: {exc}")
                continue
            try:
                pose = robot.get_robot_pose(5.0)
                grid = robot.get_map(5.0)
                ok += int(abs(pose.x_m - sim.pose.x_m) < 0.05 and grid.width > 0)
            except Exception as exc:
                print(f"  cycle failed: {exc}")
            finally:
                robot.close()
    finally:
        node.close()
        sim.close()
    return ok, time.monotonic() - t0


def main() -> int:
    try:
        import nav2_msgs.action  # noqa: F401
        import rclpy  # noqa: F401
    except ImportError as exc:
        print(f"skipped: ROS 2 is not importable here ({exc}); run it in the tier's venv (make bench-ros2)")
        return 0
    if (BENCH / "prompts_dev.jsonl").exists():
        t0 = time.perf_counter()
        ok, total, misses = run_bench_prompts()
        for m in misses:
            print(f"  miss {m}")
        rate = ok / total if total else 0.0
        print(f"ros2 backend, dev prompts that move the robot, end to end over ROS 2 (offline translator, known "
              f"map, sim at {PROMPT_SPEED:.0f}x real time): {ok}/{total} in the goal region without a collision = "
              f"{rate:.1%} (target >= {TARGET_PROMPTS:.0%}); {time.perf_counter() - t0:.0f} s wall")
    else:
        print(f"dev prompts skipped: {BENCH} not found (../shared is not on this machine)")
    times = stop_times()
    print(f"ros2 backend, STOP -> zero speed (navigation at full speed, real time, {len(times)} trials): median "
          f"{statistics.median(times):.3f} s, max {max(times):.3f} s")
    ok_c, wall = reconnects()
    print(f"ros2 backend, connect / pose / map / disconnect cycles: {ok_c}/{RECONNECTS} in {wall:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
