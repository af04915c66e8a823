"""The real-ROS 2 tier: rclpy from the ROS 2 Jazzy wheels (Kilted's with ROS2_DISTRO=kilted), langnav's interface packages built with
rosidl, a Nav2-shaped robot on rclpy (langnav's simulator behind :class:`RobotNode`) and
rosbridge-server-rs. Run it with ``make test-ros2`` (which sets the venv and the environment up).

Not part of the default ``pytest`` run (tests/conftest.py leaves this folder out unless
LANGNAV_ROS2_TIER=1). A missing prerequisite skips the tier with the reason, except when
LANGNAV_ROS2_REQUIRED=1 (CI): then it is an error.

Each run uses its own ROS_DOMAIN_ID and ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST, so nothing leaves
this machine and two runs do not see each other.
"""

from __future__ import annotations

import importlib
import os
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

os.environ.setdefault("ROS_DOMAIN_ID", str(10 + os.getpid() % 90))
os.environ.setdefault("ROS_AUTOMATIC_DISCOVERY_RANGE", "LOCALHOST")

REQUIRED = os.environ.get("LANGNAV_ROS2_REQUIRED") == "1"
#: the ROS 2 distribution of the tier's wheels (make test-ros2 ROS2_DISTRO=...; tools/ros2/setup.sh)
DISTRO = os.environ.get("LANGNAV_ROS2_DISTRO", "jazzy")
PREREQUISITES = ("rclpy", "nav2_msgs.action", "tf2_msgs.msg", "langnav_interfaces.action", "nav_msgs.msg",
                 "visualization_msgs.msg", "std_srvs.srv")


def _missing() -> str | None:
    for name in PREREQUISITES:
        try:
            importlib.import_module(name)
        except ImportError as exc:
            return (f"{name} does not import ({exc}); run `make test-ros2`, which builds the tier's venv "
                    f"(.venv-ros2) and sets LD_LIBRARY_PATH / AMENT_PREFIX_PATH")
    return None


MISSING = _missing()
if MISSING is not None and REQUIRED:
    raise RuntimeError(f"the real-ROS 2 tier is required here (LANGNAV_ROS2_REQUIRED=1) but {MISSING}")


#: the bench (dev prompts and maps) beside the repository; the tier's own cases need none of it
BENCH = Path(__file__).resolve().parents[3] / "shared" / "bench"


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    if not (BENCH / "prompts_dev.jsonl").is_file():
        # not skipped but left out: nothing in the tier may skip (CI), and this one needs ../shared
        gone = [i for i in items if "bench" in i.name]
        if gone:
            config.hook.pytest_deselected(items=gone)
            items[:] = [i for i in items if i not in gone]
    if MISSING is None:
        return
    skip = pytest.mark.skip(reason=f"real-ROS 2 tier: {MISSING}")
    for item in items:
        if "tests/ros2" in str(item.fspath).replace(os.sep, "/"):
            item.add_marker(skip)


@pytest.fixture
def closer() -> Iterator[Callable[[Any], Any]]:
    """Register things with a close() to be closed after the test, last first."""
    things: list[Any] = []

    def add(thing: Any) -> Any:
        things.append(thing)
        return thing

    yield add
    for thing in reversed(things):
        thing.close()


@pytest.fixture
def demo_robot(closer: Callable[[Any], Any]) -> Callable[..., Any]:
    """A started simulator on the bundled demo world served as a Nav2-shaped ROS 2 robot.
    Returns (sim, node)."""
    from langnav.robot.protocol import create_backend
    from langnav.robot.ros.robot_node import RobotNode

    def make(pose: tuple[float, float, float] = (12.2, 1.8, 180.0), speed: float = 2.0,
             world: Any = "demo", **node_options: Any) -> tuple[Any, Any]:
        sim = closer(create_backend("sim", world=world, pose=pose, known_map=True))
        sim.start(realtime=True, speed=speed)
        node = closer(RobotNode(sim, **node_options))
        return sim, node

    return make


@pytest.fixture
def ros2_backend(closer: Callable[[Any], Any]) -> Callable[..., Any]:
    from langnav.robot.ros.backend import Ros2Backend

    def make(**options: Any) -> Any:
        return closer(Ros2Backend(**options))

    return make


def rosbridge_rs_env(venv: Path, link_dir: Path) -> dict[str, str]:
    """The environment rosbridge-server-rs needs with the PyPI wheels (../shared/notes/ros2-wheels.md):
    ROS_DISTRO, a librmw_implementation.so (the wheels ship only Fast DDS's rmw), the wheels' vendored
    libraries (site-packages/*.libs) and libpython preloaded (its type-support loading needs it)."""
    import sysconfig

    site = Path(sysconfig.get_paths()["purelib"])
    link = link_dir / "librmw_implementation.so"
    if not link.exists():
        link.symlink_to(venv / "lib" / "librmw_fastrtps_cpp.so")
    libdir = Path(sysconfig.get_config_var("LIBDIR") or "")
    libpython = next((p for p in (libdir / str(sysconfig.get_config_var("INSTSONAME") or ""),
                                  libdir / str(sysconfig.get_config_var("LDLIBRARY") or ""))
                      if p.is_file()), None)
    if libpython is None:
        raise RuntimeError(f"rosbridge-server-rs needs libpython3.11 as a shared library; none in {libdir}")
    paths = [str(link_dir), str(venv / "lib"), *sorted(str(p) for p in site.glob("*.libs")),
             os.environ.get("LD_LIBRARY_PATH", "")]
    return {**os.environ, "ROS_DISTRO": DISTRO, "LD_LIBRARY_PATH": ":".join(p for p in paths if p),
            "LD_PRELOAD": str(libpython), "AMENT_PREFIX_PATH": str(venv)}


@pytest.fixture
def rosbridge_rs(tmp_path: Path) -> Iterator[int]:
    """rosbridge-server-rs (a real rosbridge v2 server on rclpy's libraries) on a free loopback
    port; yields the port once it accepts connections."""
    import socket
    import stat
    import subprocess
    import sys
    import sysconfig
    import time

    venv = Path(sys.prefix)
    package = Path(sysconfig.get_paths()["purelib"]) / "rosbridge_server_rs"
    binary = package / f"rosbridge_server_rs_{DISTRO}"
    if not binary.is_file() and package.is_dir() and not REQUIRED:
        # rosbridge-server-rs 0.1.6 ships builds for humble and jazzy only (it links that distro's rcl)
        pytest.skip(f"rosbridge-server-rs has no {DISTRO} build in {package}")
    if not binary.is_file():
        raise RuntimeError(f"rosbridge-server-rs is not installed in {venv} (tools/ros2/requirements.txt)")
    if not os.access(binary, os.X_OK):  # the wheel ships it without the executable bit
        binary.chmod(binary.stat().st_mode | stat.S_IXUSR | stat.S_IXGRP | stat.S_IXOTH)
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    log = (tmp_path / "rosbridge_rs.log").open("w")
    proc = subprocess.Popen([str(binary), "--no-rosapi", "--bind", f"127.0.0.1:{port}", "--log-ansi", "false"],
                            env=rosbridge_rs_env(venv, tmp_path), stdout=log, stderr=subprocess.STDOUT)
    try:
        deadline = time.monotonic() + 20.0
        while True:
            assert proc.poll() is None, (tmp_path / "rosbridge_rs.log").read_text()[-2000:]
            try:
                socket.create_connection(("127.0.0.1", port), timeout=0.5).close()
                break
            except OSError:
                assert time.monotonic() < deadline, "rosbridge-server-rs did not listen within 20 s"
                time.sleep(0.1)
        yield port
    finally:
        proc.terminate()
        try:
            proc.wait(10)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait(5)
        log.close()
