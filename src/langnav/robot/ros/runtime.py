"""rclpy for langnav's ROS 2 parts: the import guard, one private rclpy context per user, an
executor spun in a background thread, and a shutdown that always returns.

Each :class:`RosRuntime` owns its own ``rclpy.Context`` (never the global one a host program may
use), initialised without rclpy's signal handlers (a library must not take SIGINT from the program,
and rclpy's handler thread is what ends a process with ``terminate called without an active
exception`` when the context is never shut down). ``close()`` shuts the executor, the nodes and
the context down with bounded waits, and every runtime still open at interpreter exit is closed
by an ``atexit`` hook, so a script that forgets ``close()`` still exits cleanly.

ROS 2 is imported only here and only when a runtime is created: importing langnav needs no ROS.
"""

from __future__ import annotations

import atexit
import importlib
import logging
import threading
import weakref
from types import ModuleType
from typing import Any, Final

from langnav.robot.errors import RobotError

log = logging.getLogger(__name__)

INSTALL_HINT: Final = (
    "this needs ROS 2 (rclpy) and the robot's message packages (nav_msgs, geometry_msgs, sensor_msgs, "
    "tf2_msgs, nav2_msgs): on a ROS 2 machine `source /opt/ros/jazzy/setup.bash` (Jazzy, "
    "or your distro) and run langnav with the Python ROS was built for; from PyPI wheels see "
    "docs/ros2.md (`make test-ros2` sets such a venv up). Or drive the robot from anywhere with "
    "--backend rosbridge (see docs/ros2.md)"
)
#: Waiting for the executor thread to stop when a runtime closes.
SHUTDOWN_TIMEOUT_S: Final = 5.0
#: How long one executor turn may block: bounds how soon the spin thread sees a shutdown.
SPIN_PERIOD_S: Final = 0.1


def import_module(name: str, what: str = "") -> ModuleType:
    """Import a ROS 2 Python module, or raise a RobotError that says how to get it."""
    try:
        return importlib.import_module(name)
    except ImportError as exc:
        raise RobotError(f"{INSTALL_HINT} (import of {name}{' for ' + what if what else ''} failed: {exc})") from None


def interface(type_name: str) -> Any:
    """The rclpy class of a ROS interface: 'nav2_msgs/action/Spin', 'geometry_msgs/msg/Twist'."""
    parts = type_name.strip("/").split("/")
    if len(parts) == 2:
        parts = [parts[0], "msg", parts[1]]
    if len(parts) != 3 or parts[1] not in ("msg", "srv", "action"):
        raise RobotError(f"{type_name!r} is not a ROS interface name (pkg/msg|srv|action/Name)")
    module = import_module(f"{parts[0]}.{parts[1]}", type_name)
    try:
        return getattr(module, parts[2])
    except AttributeError:
        raise RobotError(f"{parts[0]}.{parts[1]} has no {parts[2]}: is the robot's {parts[0]} of another "
                         f"version? ({INSTALL_HINT})") from None


_OPEN: weakref.WeakSet[RosRuntime] = weakref.WeakSet()
_OPEN_LOCK = threading.Lock()


def _close_all_at_exit() -> None:
    with _OPEN_LOCK:
        runtimes = list(_OPEN)
    for rt in runtimes:
        rt.close()


atexit.register(_close_all_at_exit)


class RosRuntime:
    """A private rclpy context, one node, and a multi-threaded executor spun in a thread."""

    def __init__(self, node_name: str, namespace: str = "", threads: int = 4) -> None:
        rclpy = import_module("rclpy")
        executors = import_module("rclpy.executors")
        signals = import_module("rclpy.signals")
        self._rclpy = rclpy
        self._closed = False
        self._close_lock = threading.Lock()
        self.context = rclpy.Context()
        try:
            rclpy.init(context=self.context, signal_handler_options=signals.SignalHandlerOptions.NO)
        except Exception as exc:  # rclpy raises RCLError and others from C
            raise RobotError(f"could not initialise ROS 2 (rclpy.init): {exc}") from None
        try:
            self.node = rclpy.create_node(node_name, namespace=namespace, context=self.context)
        except Exception as exc:
            self._shutdown_context()
            raise RobotError(f"could not create the ROS 2 node {node_name!r} in namespace {namespace!r}: {exc}") from None
        self.executor = executors.MultiThreadedExecutor(num_threads=threads, context=self.context)
        self.executor.add_node(self.node)
        self._spin = threading.Thread(target=self._spin_loop, daemon=True, name=f"langnav-rclpy-{node_name}")
        self._spin.start()
        with _OPEN_LOCK:
            _OPEN.add(self)

    @property
    def closed(self) -> bool:
        return self._closed

    def _spin_loop(self) -> None:
        while not self._closed and self.context.ok():
            try:
                self.executor.spin_once(timeout_sec=SPIN_PERIOD_S)
            except Exception as exc:  # a shutdown race, or a callback that raised
                if self._closed or not self.context.ok():
                    return
                log.error("ROS 2 callback failed: %s", exc)

    def now_s(self) -> float:
        return float(self.node.get_clock().now().nanoseconds) * 1e-9

    def _shutdown_context(self) -> None:
        try:
            if self.context.ok():
                self._rclpy.shutdown(context=self.context)
        except Exception as exc:
            log.warning("rclpy shutdown: %s", exc)

    def close(self, timeout_s: float = SHUTDOWN_TIMEOUT_S) -> None:
        """Stop the executor, destroy the node, shut the context down. Always returns."""
        with self._close_lock:
            if self._closed:
                return
            self._closed = True
        with _OPEN_LOCK:
            _OPEN.discard(self)
        try:
            self.executor.shutdown(timeout_sec=timeout_s)
        except Exception as exc:
            log.warning("rclpy executor shutdown: %s", exc)
        self._spin.join(timeout_s)
        if self._spin.is_alive():
            log.warning("the rclpy spin thread did not stop within %.1f s", timeout_s)
        # Jazzy's Executor.shutdown() returns without waiting for callbacks under way (it tests
        # its shutdown flag after setting it); wait for them here, or destroying the node below
        # fails them ("cannot use Destroyable because destruction was requested").
        tracker = getattr(self.executor, "_work_tracker", None)
        if tracker is not None and not tracker.wait(timeout_s):
            log.warning("ROS 2 callbacks still running %.1f s after the executor's shutdown", timeout_s)
        # Action servers and clients are waitables, which destroy_node leaves alive (and with them
        # the node and the DDS participant: the robot would stay on the graph).
        for waitable in list(self.node.waitables):
            destroy = getattr(waitable, "destroy", None)
            if destroy is not None:
                try:
                    destroy()
                except Exception as exc:
                    log.warning("destroying %s: %s", type(waitable).__name__, exc)
        try:
            self.node.destroy_node()
        except Exception as exc:
            log.warning("destroying the ROS 2 node: %s", exc)
        self._shutdown_context()
        try:
            self.context.destroy()  # frees the participant now, not when the garbage collector runs
        except Exception as exc:
            log.warning("destroying the rclpy context: %s", exc)
