"""A scenario's param_sets become the SetParameters calls `ros2 param set` makes: the value typed as YAML reads it,
in one script with the service calls, in time order; a ROS 1 run cannot take them, and the scenario keeps them in
order within its duration."""
from __future__ import annotations

import pydantic
import pytest

from grader.runtime.scenario_calls import SET_PARAMETERS, planned_calls
from grader.runtime.services import ServiceRouteError
from grader.runtime.wire import wire_for
from sim import Scenario

ADD = "example_interfaces/srv/AddTwoInts"


def _request(wire, planned):
    return wire.catalog.decode(wire.service_part(SET_PARAMETERS, "Request"), planned.call.request)


@pytest.mark.parametrize("value,kind,field,expected", [
    (1.2, 3, "double_value", 1.2), (1, 2, "integer_value", 1), (True, 1, "bool_value", True),
    ("fast", 4, "string_value", "fast"), ([0.5, 1.5], 8, "double_array_value", [0.5, 1.5]),
    (["a", "b"], 9, "string_array_value", ["a", "b"])])
def test_a_value_is_typed_as_ros2_param_set_reads_it(value, kind, field, expected) -> None:
    wire = wire_for("ros2")
    scenario = Scenario(duration=5.0, param_sets=[{"t": 1.0, "node": "/ns/circle", "name": "radius", "value": value}])
    [planned] = planned_calls(scenario.service_calls, wire, scenario.param_sets)
    assert (planned.t_ns, planned.call.service, planned.call.type) == (
        1_000_000_000, "/ns/circle/set_parameters", SET_PARAMETERS)
    assert planned.call.md5sum == wire.catalog.service_md5sum(SET_PARAMETERS)
    [parameter] = _request(wire, planned).parameters
    got = getattr(parameter.value, field)
    assert (parameter.name, parameter.value.type) == ("radius", kind)
    assert (list(got) if isinstance(expected, list) else got) == expected


def test_sets_and_calls_make_one_script_in_time_order() -> None:
    wire = wire_for("ros2")
    scenario = Scenario(duration=5.0,
                        service_calls=[{"t": t, "service": "/add", "type": ADD, "request": {"a": 1, "b": 2}}
                                       for t in (1.0, 3.0)],
                        param_sets=[{"t": t, "node": "/n", "name": "p", "value": t} for t in (0.5, 1.0, 4.0)])
    planned = planned_calls(scenario.service_calls, wire, scenario.param_sets)
    assert [(p.t_ns / 1e9, p.call.service) for p in planned] == [
        (0.5, "/n/set_parameters"), (1.0, "/add"), (1.0, "/n/set_parameters"), (3.0, "/add"),
        (4.0, "/n/set_parameters")]


def test_a_ros1_run_cannot_take_parameter_sets() -> None:
    scenario = Scenario(duration=5.0, param_sets=[{"t": 1.0, "node": "/circle", "name": "radius", "value": 1.2}])
    with pytest.raises(ServiceRouteError, match=r"param_sets\[0\] \(/circle radius\).*ROS 1"):
        planned_calls(scenario.service_calls, wire_for("ros1"), scenario.param_sets)


@pytest.mark.parametrize("sets,says", [
    ([{"t": 2.0, "node": "/n", "name": "p", "value": 1.0}, {"t": 1.0, "node": "/n", "name": "p", "value": 2.0}],
     "param_sets must come in time order"),
    ([{"t": 9.0, "node": "/n", "name": "p", "value": 1.0}], "param_sets must come in time order, within"),
    ([{"t": 1.0, "node": "n", "name": "p", "value": 1.0}], "should match pattern"),
    ([{"t": 1.0, "node": "/n", "name": "p", "value": []}], "value"),
    ([{"t": 1.0, "node": "/n", "name": "p", "value": {"x": 1}}], "value")])
def test_the_scenario_refuses_sets_out_of_order_or_malformed(sets, says) -> None:
    with pytest.raises(pydantic.ValidationError, match=says):
        Scenario(duration=5.0, param_sets=sets)
