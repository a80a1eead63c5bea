"""The grader as an action client: a scenario's action goals, each sent as ``ros2 action send_goal`` sends one.

rclpy's ActionClient under that command waits for the action's three services, calls ``<action>/_action/send_goal``
with a new goal id, and once the goal is accepted asks ``get_result`` and waits; Ctrl+C (``cancel_at``) before the
result calls ``cancel_goal`` for the goal. Each goal is its own command, so goals run side by side; the calls go
through the run's service routing (callerid ``/rosgrade``, origin ``grader``) and are recorded like any call, and the
server's feedback and status are recorded on its topics.
"""
from __future__ import annotations

import random
import uuid
from dataclasses import dataclass

import numpy as np

from grader.nodelib.common import rosgrade_channel as ch
from grader.recording import RecordingError
from grader.runtime.node_link import ServiceCall
from grader.runtime.services import Caller, ServiceRouteError, ServiceRouter
from grader.runtime.wire import Wire
from sim.scenario import ActionGoalSpec

CALLER_ID = "/rosgrade"
CANCEL_GOAL = "action_msgs/srv/CancelGoal"
_SERVICES = ("send_goal", "cancel_goal", "get_result")


def goal_id(index: int) -> bytes:
    """The id of the scenario's goal ``index``: a version-4 UUID as rclpy draws one, from a fixed seed per goal, so
    that a recording repeats and scoring knows the grader's goals."""
    return uuid.UUID(int=random.Random(f"rosgrade action goal {index}").getrandbits(128), version=4).bytes


@dataclass(frozen=True)
class PlannedGoal:
    """A scenario's goal with its three requests encoded for the run's wire, built before the run starts."""

    t_ns: int  # relative to the start
    cancel_ns: int | None
    action: str
    send_goal: ServiceCall
    get_result: ServiceCall
    cancel: ServiceCall
    accepted: type  # decodes a send_goal response: ``accepted(bytes)`` -> bool


def planned_goals(goals: list[ActionGoalSpec], wire: Wire) -> list[PlannedGoal]:
    """The scenario's goals encoded for the run's (ROS 2) wire; ServiceRouteError names one that cannot be sent."""
    return [_planned(index, spec, wire) for index, spec in enumerate(goals)]


def _planned(index: int, spec: ActionGoalSpec, wire: Wire) -> PlannedGoal:
    catalog = wire.catalog
    uuid_class = catalog.message_class("unique_identifier_msgs/msg/UUID")
    goal_uuid = uuid_class(uuid=np.frombuffer(goal_id(index), dtype=np.uint8).copy())
    send_goal, get_result = f"{spec.type}_SendGoal", f"{spec.type}_GetResult"
    try:
        goal = catalog.message_class(f"{spec.type}_Goal")(**spec.goal)
        requests = {
            send_goal: wire.part_bytes(send_goal, "Request", {"goal_id": goal_uuid, "goal": goal}),
            get_result: wire.part_bytes(get_result, "Request", {"goal_id": goal_uuid}),
            CANCEL_GOAL: wire.part_bytes(CANCEL_GOAL, "Request", {"goal_info": catalog.message_class(
                "action_msgs/msg/GoalInfo")(goal_id=goal_uuid, stamp=catalog.message_class(
                    "builtin_interfaces/msg/Time")(sec=0, nanosec=0))}),
        }
        md5s = {name: catalog.service_md5sum(name) for name in requests}
    except (RecordingError, TypeError, ValueError) as exc:
        raise ServiceRouteError(f"scenario action_goals[{index}] to {spec.action}: {spec.goal} is not a goal of "
                                f"{spec.type}: {exc}") from None
    response_type = wire.service_part(send_goal, "Response")

    def call(service: str, srv_type: str) -> ServiceCall:
        return ServiceCall(f"{spec.action}/_action/{service}", srv_type, md5s[srv_type], False, requests[srv_type])

    def accepted(data: bytes) -> bool:
        return bool(catalog.decode(response_type, data).accepted)
    return PlannedGoal(spec.t_ns, spec.cancel_ns, spec.action, call("send_goal", send_goal),
                       call("get_result", get_result), call("cancel_goal", CANCEL_GOAL), accepted)


class GoalSender:
    """One goal's ``ros2 action send_goal``: waiting for the server, then the goal, its result and its cancel."""

    def __init__(self, planned: PlannedGoal, start_ns: int, router: ServiceRouter) -> None:
        self._goal = planned
        self._due = start_ns + planned.t_ns
        self._cancel_due = None if planned.cancel_ns is None else start_ns + planned.cancel_ns
        self._router = router
        self._state = "waiting"  # then "sent", "running" (accepted, result asked), "done"

    def _offered(self) -> bool:
        """The three services served with the goal's types: with another action type, rclpy's client matches no
        server, and ``ros2 action send_goal`` keeps waiting for one."""
        calls = (self._goal.send_goal, self._goal.cancel, self._goal.get_result)
        servers = [self._router.server(call.service) for call in calls]
        return all(server is not None and server.type == call.type for server, call in zip(servers, calls))

    def next_ns(self) -> int | None:
        """When the loop must stop for this goal's next request (None: it waits for an answer or a server)."""
        if self._state == "waiting":
            return self._due if self._offered() else None
        if self._state == "running" and self._cancel_due is not None:
            return self._cancel_due
        return None

    def tick(self, t: int) -> None:
        if self._state == "waiting" and self._due <= t and self._offered():
            self._state = "sent"
            self._router.call(Caller(CALLER_ID, "grader", done=self._goal_answered), self._goal.send_goal, t)
        elif self._state == "running" and self._cancel_due is not None and self._cancel_due <= t:
            self._cancel_due = None  # Ctrl+C: one cancel request, after which the command ends
            self._router.call(Caller(CALLER_ID, "grader"), self._goal.cancel, t)

    def _goal_answered(self, status: str, error: str, response: bytes, t: int) -> None:
        if status != ch.SERVICE_OK or not self._goal.accepted(response):
            self._state = "done"
            return
        self._state = "running"
        self._router.call(Caller(CALLER_ID, "grader", done=self._result_answered), self._goal.get_result, t)

    def _result_answered(self, status: str, error: str, response: bytes, t: int) -> None:
        self._state = "done"
