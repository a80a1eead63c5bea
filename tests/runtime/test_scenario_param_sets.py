"""A scenario's param_sets become the SetParameters calls `ros2 param set` makes: the value typed as YAML reads it,
in one script with the service calls, in time order; for ROS 1 nodes `rosparam set` on the run's parameter server;
the scenario keeps them in order within its duration; a node of either library reads each set at its time."""
from __future__ import annotations

import hashlib

import pydantic
import pytest

from grader import timing
from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec, lookahead
from grader.runtime.scenario_calls import SET_PARAMETERS, planned_calls
from grader.runtime.session import run
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


def test_for_ros1_a_set_is_rosparam_set_of_the_nodes_private_parameter() -> None:
    scenario = Scenario(duration=5.0, param_sets=[{"t": 1.0, "node": "/circle", "name": "gains.p", "value": 1.2}])
    [planned] = planned_calls(scenario.service_calls, wire_for("ros1"), scenario.param_sets)
    assert (planned.t_ns, planned.call, planned.param) == (1_000_000_000, None, ("/circle/gains/p", 1.2))


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


ROSPY_NODE = """import rospy
rospy.init_node("param_circle")
rate = rospy.Rate(10)
last = None
while not rospy.is_shutdown():
    radius = rospy.get_param("~radius", 0.5)
    if radius != last:
        print("%.2f radius %r" % (rospy.get_time(), radius))
        last = radius
    rate.sleep()
"""

RCLPY_NODE = """import rclpy
from rclpy.node import Node
rclpy.init()
node = Node("param_circle")
node.declare_parameter("radius", 0.5)
node.add_post_set_parameters_callback(
    lambda params: print("%.2f radius %r" % (node.get_clock().now().nanoseconds / 1e9, params[0].value)))
rclpy.spin(node)
"""


@pytest.mark.slow
@pytest.mark.parametrize("flavour,source", [("ros1", ROSPY_NODE), ("ros2", RCLPY_NODE)])
def test_a_node_reads_each_set_at_its_time(tmp_path, flavour, source) -> None:
    """rospy: `rosparam set` on the run's parameter server, which the node's own get_param reads at its next step;
    rclpy: the set reaches the node's set_parameters, which its executor answers at once."""
    script = tmp_path / "param_circle.py"
    script.write_text(source)
    scenario = Scenario(duration=3.0, param_sets=[{"t": 1.0, "node": "/param_circle", "name": "radius", "value": 1.2},
                                                  {"t": 2.0, "node": "/param_circle", "name": "radius", "value": 0.8}])
    run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=script, flavour=flavour),)), tmp_path / "r.mcap",
        tmp_path / "r.log")
    lines = [text for _, stream, text in Recording.open(tmp_path / "r.mcap").output_lines() if stream == "stdout"]
    seen = [(float(t), value) for t, _, value in (line.split() for line in lines[-2:])]
    # within one step of the node's (rospy: its 10 Hz loop; rclpy: the executor takes the request at once)
    assert [(value, 0.0 <= t - due < 0.1) for (t, value), due in zip(seen, (3.0, 4.0))] == [("1.2", True), ("0.8", True)]
    if flavour == "ros2":
        assert [t for t, _ in seen] == [3.0, 4.0]


# Nodes that listen to /odom and do nothing visible but when a set reaches them: the world runs ahead of them.
QUIET_NODES = {
    "ros1": """import rospy
from nav_msgs.msg import Odometry
rospy.init_node("param_circle")
pose = [None]
rospy.Subscriber("/odom", Odometry, lambda msg: pose.__setitem__(0, msg.pose.pose))
rate = rospy.Rate(2)
last = None
while not rospy.is_shutdown():
    radius = rospy.get_param("~radius", 0.5)
    if radius != last:
        print("radius", radius)
        last = radius
    rate.sleep()
""",
    "ros2": """import rclpy
from nav_msgs.msg import Odometry
from rclpy.node import Node
rclpy.init()
node = Node("param_circle")
node.declare_parameter("radius", 0.5)
pose = [None]
node.create_subscription(Odometry, "/odom", lambda msg: pose.__setitem__(0, msg.pose.pose), 10)
node.add_post_set_parameters_callback(lambda params: print("radius", params[0].value))
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
""",
}


@pytest.mark.slow
@pytest.mark.parametrize("flavour", ["ros1", "ros2"])
def test_a_run_with_sets_records_as_the_plain_lockstep(tmp_path, monkeypatch, flavour) -> None:
    """The world runs ahead of a node only up to the grader's next set: with batches of moments the recording is
    the lockstep's, byte for byte, and the node did run moments on its own."""
    script = tmp_path / "param_circle.py"
    script.write_text(QUIET_NODES[flavour])
    scenario = Scenario(duration=6.0, shutdown_at=5.0,
                        param_sets=[{"t": 2.0, "node": "/param_circle", "name": "radius", "value": 1.2},
                                    {"t": 4.0, "node": "/param_circle", "name": "radius", "value": 0.8}])
    digests, ahead = [], []
    for moments in (lookahead.MAX_MOMENTS, 0):
        monkeypatch.setattr(lookahead, "MAX_MOMENTS", moments)
        path = tmp_path / f"{moments}.mcap"
        with timing.collect() as counts:
            run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=script, flavour=flavour),)), path,
                tmp_path / f"{moments}.log")
        digests.append(hashlib.sha256(path.read_bytes()).hexdigest())
        ahead.append(counts.get("# moments run without a round trip", 0))
        lines = [text for _, stream, text in Recording.open(path).output_lines() if stream == "stdout"]
        assert lines[-2:] == ["radius 1.2", "radius 0.8"]
    assert digests[0] == digests[1], "the recording with batches of moments differs from the plain lockstep's"
    assert ahead[0] > 0 and ahead[1] == 0
