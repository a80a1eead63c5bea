"""The grader as an actionlib client (rospy runs): a scenario's action goals sent as actionlib's ActionClient sends
them, on topics, through the grader's publisher (scenario_topics.py).

actionlib 1.14's client (read from Debian's python3-actionlib) publishes ``<ns>/goal`` (the ActionGoal: header stamp
and goal id stamp the client's now, goal id ``<node name>-<count>-<seconds to the ms>`` from a per-process counter) and
``<ns>/cancel`` (a GoalID with the goal's id and a zero stamp), both made when the client starts; its
``wait_for_server`` looks every 10 ms until the server's goal subscriber is connected (it also waits for the
server's first status message, which is not modelled). All goals come from one client, /rosgrade.
"""
from __future__ import annotations

from grader.nodelib.common import rosgrade_channel as ch
from grader.recording import RecordingError
from grader.runtime.message_values import MessageValueError, build_message
from grader.runtime.scenario_topics import CALLER_ID, PlannedPublication, PublicationError
from grader.runtime.wire import Wire
from sim.scenario import ActionGoalSpec

WAIT_POLL_NS = 10_000_000  # wait_for_server's time.sleep(0.01)
_NS = 1_000_000_000


def goal_id_text(count: int, clock_ns: int) -> str:
    """actionlib's ActionClient goal id (GoalManager._generate_id): the node name, the process's goal count from 1,
    and the time in seconds to the millisecond, as ``"%s-%i-%.3f"`` prints ``Time.to_sec()``."""
    return "%s-%i-%.3f" % (CALLER_ID, count, float(clock_ns // _NS) + float(clock_ns % _NS) / 1e9)


def _clock(t: int) -> int:
    """rospy.Time.now() under /clock at t: the last 10 ms tick."""
    return t // ch.CLOCK_PERIOD_NS * ch.CLOCK_PERIOD_NS


def planned_actionlib_goals(goals: list[ActionGoalSpec], wire: Wire) -> list[PlannedPublication]:
    """Each goal's ActionGoal publication (waiting for the server) and, with ``cancel_at``, its cancel."""
    planned: list[PlannedPublication] = []
    for index, spec in enumerate(goals):
        package, _, name = spec.type.split("/")
        action_goal = f"{package}/{name}ActionGoal"
        where = f"scenario action_goals[{index}] to {spec.action}"
        try:
            goal = build_message(wire, f"{package}/{name}Goal", spec.goal)
            wire.catalog.encode(action_goal, wire.catalog.message_class(action_goal)(
                header=build_message(wire, "std_msgs/Header", {}), goal_id=build_message(wire, "actionlib_msgs/GoalID",
                                                                                         {}), goal=goal))
        except (RecordingError, KeyError) as exc:
            raise PublicationError(f"{where}: {spec.type} is not an action the run knows ({exc})") from None
        except MessageValueError as exc:
            raise PublicationError(f"{where}: {exc}") from None
        goal_bytes = _GoalBytes(wire, action_goal, goal, index + 1)
        planned.append(PlannedPublication(spec.t_ns, f"{spec.action}/goal", action_goal, b"", None, 1, False, True,
                                          None, CALLER_ID, WAIT_POLL_NS, make=goal_bytes))
        if spec.cancel_ns is not None:
            planned.append(PlannedPublication(spec.cancel_ns, f"{spec.action}/cancel", "actionlib_msgs/GoalID", b"",
                                              None, 1, False, False, None, CALLER_ID, register_ns=spec.t_ns,
                                              make=goal_bytes.cancel))
    return planned


class _GoalBytes:
    """A goal's ActionGoal at the time it goes out (its id and stamps are the client's clock then)."""

    def __init__(self, wire: Wire, action_goal: str, goal: object, count: int) -> None:
        self._wire, self._type, self._goal, self._count = wire, action_goal, goal, count
        self.sent_clock: int | None = None

    def __call__(self, t: int) -> bytes:
        now = self.sent_clock = _clock(t)
        stamp = {"sec": now // _NS, "nanosec": now % _NS}
        wire = self._wire
        message = wire.catalog.message_class(self._type)(
            header=build_message(wire, "std_msgs/Header", {"stamp": stamp}),
            goal_id=build_message(wire, "actionlib_msgs/GoalID", {"stamp": stamp,
                                                                  "id": goal_id_text(self._count, now)}),
            goal=self._goal)
        return wire.catalog.encode(self._type, message)

    def cancel(self, t: int) -> bytes | None:
        """The goal's cancel, as ClientGoalHandle.cancel sends it; None before the goal went out (an empty id would
        cancel every goal of the server)."""
        if self.sent_clock is None:
            return None
        message = build_message(self._wire, "actionlib_msgs/GoalID", {"id": goal_id_text(self._count,
                                                                                          self.sent_clock)})
        return self._wire.catalog.encode("actionlib_msgs/GoalID", message)
