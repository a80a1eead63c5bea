"""The grader as a caller: a scenario's service calls and parameter sets, made at their sim times through the run's
service routing, one after the other, as a script of ``ros2 service call`` and ``ros2 param set`` commands would (for
ROS 1 nodes a set is ``rosparam set`` on the run's parameter server, which the node reads again when it asks); its
action goals beside them, each as its own ``ros2 action send_goal`` (scenario_goals.py)."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from grader.recording import RecordingError
from grader.runtime.node_link import ServiceCall
from grader.runtime.param_server import GRADER, ParamServer
from grader.runtime.services import Caller, ServiceRouteError, ServiceRouter
from grader.runtime.scenario_goals import GoalSender, PlannedGoal
from grader.runtime.message_values import MessageValueError, build_message
from grader.runtime.wire import Wire
from sim.scenario import ParamSetSpec, ServiceCallSpec

# The grader's name on the graph (``ros2 service call`` is a node of its own too); names under /rosgrade are refused
# to student nodes, so scoring can trust what this name called.
CALLER_ID = "/rosgrade"
SET_PARAMETERS = "rcl_interfaces/srv/SetParameters"
# rcl_interfaces/msg/ParameterType and the ParameterValue field of each Python type ``ros2 param set`` reads a value as
_PARAMETER_TYPES = {bool: (1, "bool_value"), int: (2, "integer_value"), float: (3, "double_value"),
                    str: (4, "string_value")}
_ARRAY_TYPES = {bool: (6, "bool_array_value", bool), int: (7, "integer_array_value", np.int64),
                float: (8, "double_array_value", np.float64), str: (9, "string_array_value", None)}


@dataclass(frozen=True)
class PlannedCall:
    """A scenario's call with its request's bytes and its srv type's md5sum (RIHS01), built before the run starts;
    or, for ROS 1 nodes, a ``rosparam set`` (``param``: the absolute name and the value)."""

    t_ns: int  # relative to the start
    call: ServiceCall | None
    param: tuple[str, object] | None = None


def planned_calls(calls: list[ServiceCallSpec], wire: Wire, param_sets: list[ParamSetSpec] = ()) -> list[PlannedCall]:
    """The scenario's calls and parameter sets encoded for the run's wire, in time order (a call before a set at the
    same time); ServiceRouteError names one that cannot be made."""
    planned = []
    for index, spec in enumerate(calls):
        try:
            # as the service call CLIs fill a request: every field not given at its zero value
            part = wire.service_part(spec.type, "Request")
            request = wire.catalog.encode(part, build_message(wire, part, spec.request))
            md5sum = wire.catalog.service_md5sum(spec.type)
        except (RecordingError, MessageValueError, TypeError, ValueError) as exc:
            raise ServiceRouteError(f"scenario service_calls[{index}] to {spec.service}: {spec.request} is not a "
                                    f"request of {spec.type}: {exc}") from None
        planned.append(PlannedCall(spec.t_ns, ServiceCall(spec.service, spec.type, md5sum, False, request)))
    for index, param in enumerate(param_sets):
        if wire.name == "ros1":  # `rosparam set /node/name value`: the node's private parameter
            name = f"{param.node.rstrip('/')}/{param.name.replace('.', '/')}"
            planned.append(PlannedCall(param.t_ns, None, (name, param.value)))
            continue
        service = f"{param.node.rstrip('/')}/set_parameters"
        try:
            request = _set_parameters_request(wire, param)
            md5sum = wire.catalog.service_md5sum(SET_PARAMETERS)
        except RecordingError as exc:
            raise ServiceRouteError(f"scenario param_sets[{index}] ({param.node} {param.name}): {exc}") from None
        planned.append(PlannedCall(param.t_ns, ServiceCall(service, SET_PARAMETERS, md5sum, False, request)))
    return sorted(planned, key=lambda call: call.t_ns)


def _set_parameters_request(wire: Wire, param: ParamSetSpec) -> bytes:
    """The SetParameters request ``ros2 param set`` sends: one Parameter, its value typed as YAML reads it."""
    catalog = wire.catalog
    value_class = catalog.message_class("rcl_interfaces/msg/ParameterValue")
    fields = {"type": 0, "bool_value": False, "integer_value": 0, "double_value": 0.0, "string_value": "",
              "byte_array_value": np.array([], dtype=np.uint8), "bool_array_value": np.array([], dtype=bool),
              "integer_array_value": np.array([], dtype=np.int64),
              "double_array_value": np.array([], dtype=np.float64), "string_array_value": []}
    if isinstance(param.value, list):
        kind, field, dtype = _ARRAY_TYPES[type(param.value[0])]
        fields.update(type=kind, **{field: list(param.value) if dtype is None else np.array(param.value, dtype)})
    else:
        kind, field = _PARAMETER_TYPES[type(param.value)]
        fields.update(type=kind, **{field: param.value})
    parameter = catalog.message_class("rcl_interfaces/msg/Parameter")(name=param.name, value=value_class(**fields))
    request_type = wire.service_part(SET_PARAMETERS, "Request")
    return catalog.encode(request_type, catalog.message_class(request_type)(parameters=[parameter]))


class ScenarioCaller:
    """Makes each call once its time has come and the one before it has been answered; a call whose service is not
    offered yet waits for it (``ros2 service call`` prints "waiting for service to become available..." meanwhile)
    and goes out when a node offers it."""

    def __init__(self, calls: list[PlannedCall], start_ns: int, router: ServiceRouter,
                 params: ParamServer | None = None, goals: list[PlannedGoal] = ()) -> None:
        self._calls = [(start_ns + planned.t_ns, planned) for planned in calls]
        self._goals = [GoalSender(goal, start_ns, router) for goal in goals]
        self._params = params
        self._next = 0
        self._busy = False  # a call is out and not answered yet
        self._router = router
        router.on_offer.append(self.tick)

    def next_ns(self) -> int | None:
        """When the loop must stop for the next call or goal request (None: none, or they wait for answers or
        servers)."""
        times = [due for goal in self._goals if (due := goal.next_ns()) is not None]
        if not self._busy and self._next < len(self._calls):
            due, planned = self._calls[self._next]
            if planned.param is not None or self._router.server(planned.call.service) is not None:
                times.append(due)
        return min(times, default=None)

    def tick(self, t: int) -> None:
        """Make the next call if it is due at t and its service is offered; a ROS 1 set is made at once (it reaches
        each node in its next BATCH), and what follows it may go out at t too; then the goals' requests due at t."""
        for goal in self._goals:
            goal.tick(t)
        while not self._busy and self._next < len(self._calls):
            due, planned = self._calls[self._next]
            if due > t:
                return
            if planned.param is not None:
                self._params.set(*planned.param, author=GRADER)
                self._next += 1
                continue
            if self._router.server(planned.call.service) is None:
                return
            self._busy = True
            self._router.call(Caller(CALLER_ID, "grader", done=self._answered), planned.call, t)

    def _answered(self, status: str, error: str, response: bytes, t: int) -> None:
        self._busy = False
        self._next += 1
