"""``langnav node``: langnav as a ROS 2 node, next to the robot's own.

============================  ==========================================  =============================
name (relative)               type                                        what
============================  ==========================================  =============================
langnav/instruct              langnav_interfaces/action/Instruct          goal: the prompt; feedback:
                                                                          each step in plain words;
                                                                          result: outcome and reply
langnav/stop                  std_srvs/srv/Trigger                        stop the running instruction
                                                                          and the robot
langnav/map_analysis          visualization_msgs/msg/MarkerArray          rooms, doors, passages,
                                                                          unexplored areas, labelled
                                                                          as in the web app (transient
                                                                          local; again when the map
                                                                          changes)
============================  ==========================================  =============================

An instruction is planned on the robot's map and pose (offline translator by default), then run
by the plan executor on the robot backend (the ``ros2`` backend: Nav2 on the same graph). A new
goal preempts the running one. Outcomes: ``succeeded``, ``failed``, ``canceled``, or ``refused``
(nothing ran: the reply says why, or what to add). The node never crashes on a bad prompt: every
failure is an outcome with its reason.
"""

from __future__ import annotations

import contextlib
import logging
import threading
import time
from typing import Any, Final

from langnav.analysis.pipeline import AnalysisCache, grid_key
from langnav.errors import LangnavError
from langnav.plan.events import EventKind, ExecEvent, PlanStatus, pose_tuple
from langnav.plan.executor import PlanExecutor, PlanRun
from langnav.robot.errors import RobotError
from langnav.robot.protocol import RobotBackend
from langnav.robot.ros.convert import to_msg
from langnav.robot.ros.markers import analysis_markers
from langnav.robot.ros.runtime import RosRuntime, import_module, interface

log = logging.getLogger(__name__)

INSTRUCT: Final = "langnav_interfaces/action/Instruct"
#: How long one instruction may run (a long route plus exploration).
INSTRUCT_TIMEOUT_S: Final = 1800.0
#: How often the robot's map is checked for a change that needs new markers.
MAP_CHECK_S: Final = 2.0
#: How often the execute loop looks at the plan.
_POLL_S: Final = 0.05
#: Waiting for a cancelled plan to stop the robot.
CANCEL_GRACE_S: Final = 10.0

OUTCOMES: Final = {PlanStatus.SUCCEEDED: "succeeded", PlanStatus.FAILED: "failed",
                   PlanStatus.CANCELLED: "canceled", PlanStatus.REJECTED: "refused"}


def step_words(ev: ExecEvent) -> str | None:
    """One executor event in plain words for the action's feedback (None: not worth a line)."""
    n = "" if ev.index is None else f"step {ev.index + 1}: "
    if ev.kind is EventKind.STARTED:
        return f"{n}{ev.text}"
    if ev.kind is EventKind.PROGRESS:
        pct = f" ({ev.fraction:.0%} done)" if ev.fraction is not None else ""
        return f"{n}{ev.message or ev.text}{pct}"
    if ev.kind in (EventKind.SUCCEEDED, EventKind.FAILED, EventKind.CANCELLED, EventKind.PAUSED, EventKind.RESUMED):
        return f"{n}{ev.kind.value}{': ' + ev.message if ev.message else ''}"
    return None


class LangnavNode:
    """The node (see the module docstring). ``robot`` is any backend; ``translator`` a name."""

    def __init__(self, robot: RobotBackend, translator: str = "offline", namespace: str = "",
                 node_name: str = "langnav_node", map_frame: str = "map", map_check_s: float = MAP_CHECK_S) -> None:
        from langnav.language.translator import get_translator
        from langnav.pipeline import Planner

        self.robot = robot
        self.map_frame = map_frame
        self._planner = Planner(get_translator(translator))
        self._analyses = AnalysisCache()
        self._executor = PlanExecutor(robot)
        self._lock = threading.Lock()
        self._run: PlanRun | None = None
        self._closed = False
        self._marker_key = ""
        self.markers_published = 0
        action = import_module("rclpy.action")
        qos = import_module("rclpy.qos")
        groups = import_module("rclpy.callback_groups")
        self._action = action
        self._types = {n: interface(n) for n in (INSTRUCT, "std_srvs/srv/Trigger", "visualization_msgs/msg/MarkerArray")}
        self._rt = RosRuntime(node_name, namespace, threads=6)
        node = self._rt.node
        try:
            reentrant = groups.ReentrantCallbackGroup()
            self._server = action.ActionServer(
                node, self._types[INSTRUCT], "langnav/instruct", self._execute, goal_callback=self._on_goal,
                cancel_callback=lambda _h: action.CancelResponse.ACCEPT, handle_accepted_callback=self._on_accepted,
                callback_group=reentrant)
            node.create_service(self._types["std_srvs/srv/Trigger"], "langnav/stop", self._on_stop,
                                callback_group=reentrant)
            latched = qos.QoSProfile(depth=1, durability=qos.DurabilityPolicy.TRANSIENT_LOCAL,
                                     reliability=qos.ReliabilityPolicy.RELIABLE)
            self._pub_markers = node.create_publisher(self._types["visualization_msgs/msg/MarkerArray"],
                                                      "langnav/map_analysis", latched)
            self._timer = node.create_timer(map_check_s, self._publish_markers,
                                            callback_group=groups.MutuallyExclusiveCallbackGroup())
            self._current_goal: Any = None
        except BaseException:
            self._rt.close()
            raise

    # -- the map analysis --------------------------------------------------------------------------
    def _publish_markers(self) -> None:
        try:
            grid = self.robot.get_map(timeout_s=0.0)
        except RobotError:
            return  # no map yet: try again at the next check
        key = grid_key(grid)
        if key == self._marker_key:
            return
        try:
            analysis = self._analyses.get(grid)
        except LangnavError as exc:
            log.warning("could not analyse the map: %s", exc)
            return
        self._marker_key = key
        msg = to_msg(self._types["visualization_msgs/msg/MarkerArray"],
                     analysis_markers(analysis, self.map_frame, self._rt.now_s()))
        self._pub_markers.publish(msg)
        self.markers_published += 1

    # -- /langnav/stop -------------------------------------------------------------------------------
    def _on_stop(self, _request: Any, response: Any) -> Any:
        with self._lock:
            run = self._run
        try:
            if run is not None and not run.done:
                run.cancel()
            else:
                self.robot.stop()
            response.success, response.message = True, "stopped"
        except LangnavError as exc:
            response.success, response.message = False, f"could not stop the robot: {exc}"
        return response

    # -- /langnav/instruct ---------------------------------------------------------------------------
    def _on_goal(self, goal: Any) -> Any:
        ok = isinstance(goal.prompt, str) and goal.prompt.strip() and not self._closed
        return self._action.GoalResponse.ACCEPT if ok else self._action.GoalResponse.REJECT

    def _on_accepted(self, handle: Any) -> None:
        """One instruction at a time: a new one preempts the running one (its plan is cancelled)."""
        with self._lock:
            run = self._run
        if run is not None and not run.done:
            run.cancel()
        handle.execute()

    def _result(self, outcome: str, reply: str) -> Any:
        return to_msg(self._types[INSTRUCT].Result, {"outcome": outcome, "reply": reply})

    def _execute(self, handle: Any) -> Any:
        prompt = str(handle.request.prompt)
        fb_cls = self._types[INSTRUCT].Feedback

        def feedback(text: str) -> None:
            try:
                handle.publish_feedback(to_msg(fb_cls, {"step": text}))
            except Exception as exc:  # a goal that ended meanwhile: nothing to tell
                log.debug("feedback: %s", exc)

        try:
            feedback(f"reading {prompt!r} against the map")
            grid = self.robot.get_map()
            pose = pose_tuple(self.robot.get_robot_pose())
            plan = self._planner.plan(prompt, self._analyses.get(grid), pose)
            if plan.clarification is not None:
                handle.abort()
                return self._result("refused", plan.clarification)
            steps = [c.note or str(c.command) for c in plan.commands]
            feedback("plan: " + "; ".join(steps) if steps else "plan: nothing to do")
            run = self._executor.start(plan.items, on_event=lambda ev: self._on_event(ev, feedback))
            with self._lock:
                self._run = run
            deadline = time.monotonic() + INSTRUCT_TIMEOUT_S
            while not run.done:
                if handle.is_cancel_requested:
                    run.cancel()
                    run.wait(CANCEL_GRACE_S)
                    handle.canceled()
                    return self._result("canceled", "cancelled: the robot stopped")
                if time.monotonic() > deadline:
                    run.cancel()
                    run.wait(CANCEL_GRACE_S)
                    handle.abort()
                    return self._result("failed", f"the instruction took longer than {INSTRUCT_TIMEOUT_S:.0f} s")
                time.sleep(_POLL_S)
            outcome = OUTCOMES.get(run.status, "failed")
            reply = run.message or ("done" if run.status is PlanStatus.SUCCEEDED else outcome)
            if run.status is PlanStatus.SUCCEEDED:
                handle.succeed()
            elif run.status is PlanStatus.CANCELLED and handle.is_cancel_requested:
                handle.canceled()
            else:
                handle.abort()
            return self._result(outcome, reply)
        except Exception as exc:  # never leave a goal unanswered or the node broken
            log.exception("instruction %r failed", prompt)
            with contextlib.suppress(Exception):
                handle.abort()
            return self._result("failed", f"{type(exc).__name__}: {exc}")

    def _on_event(self, ev: ExecEvent, feedback: Any) -> None:
        text = step_words(ev)
        if text:
            feedback(text)

    def close(self) -> None:
        if self._closed:
            return
        self._closed = True
        with self._lock:
            run = self._run
        if run is not None and not run.done:
            run.cancel()
            with contextlib.suppress(LangnavError):
                run.wait(CANCEL_GRACE_S)
        self._rt.close()
