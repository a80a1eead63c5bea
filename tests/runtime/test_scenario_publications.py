"""The grader as a publisher: a scenario's publications go out as rostopic pub / ros2 topic pub send them (latched
once, at a rate, --once after a matching subscription, -t times), from /rosgrade, routed to node subscribers."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.scenario_participant import ParticipantError, plan
from grader.runtime.wire import wire_for
from grader.runtime.session import run
from sim import Scenario

NODES = Path(__file__).resolve().parent / "nodes" / "topics"


def _pub(t: float, data: str, type_name: str = "std_msgs/String", **options: object) -> dict:
    return {"t": t, "topic": "/chatter", "type": type_name, "values": {"data": data}, **options}


def _run(tmp_path: Path, flavour: str, script: str, publications: list[dict]) -> Recording:
    scenario = Scenario(duration=4.0, publications=publications)
    run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=NODES / script, flavour=flavour),)),
        tmp_path / "run.mcap", tmp_path / "run.log")
    return Recording.open(tmp_path / "run.mcap")


@pytest.mark.slow
def test_rostopic_pub_latches_once_and_publishes_at_a_rate_as_its_own_node(tmp_path) -> None:
    recording = _run(tmp_path, "ros1", "rospy_listener.py", [_pub(0.0, "hi"), _pub(0.5, "r", rate=2)])
    heard = [line.text for line in recording.output_lines()]
    # the latched message reaches the subscriber made after it, and the node's later subscriber from its connection;
    # the rate's first message went out before the publisher connected (50 ms) and was lost, as rospy loses it
    assert heard[:5] == ["early hi /rosgrade 2.100", "early r /rosgrade/pub1 3.000", "early r /rosgrade/pub1 3.500",
                         "early r /rosgrade/pub1 4.000", "late hi /rosgrade 4.110"]
    topics = {(i.topic, i.callerid, i.origin) for i in recording.topics()}
    assert topics >= {("/chatter", "/rosgrade", "grader"), ("/chatter", "/rosgrade/pub1", "grader"),
                      ("/rosgrade/lost/chatter", "/rosgrade/pub1", "grader")}
    assert [(t, m.data) for t, m in recording.messages("/chatter")][:2] == [(2_050_000_000, "hi"),
                                                                           (3_000_000_000, "r")]


@pytest.mark.slow
def test_ros2_topic_pub_waits_for_a_subscription_with_once_and_times(tmp_path) -> None:
    string = "std_msgs/msg/String"
    recording = _run(tmp_path, "ros2", "rclpy_listener.py", [
        _pub(0.0, "once", string, once=True), _pub(0.0, "rate", string), _pub(0.2, "t3", string, times=3, rate=5)])
    # the listener subscribes at 2.85 s; --once and -t look every 0.1 s and find it at 2.9 s; the endless 1 Hz
    # command does not wait: its first message (2.0 s, before discovery) reached nobody
    assert [line.text for line in recording.output_lines()] == [
        "heard once 2.900", "heard t3 2.900", "heard rate 3.000", "heard t3 3.100", "heard t3 3.300",
        "heard rate 4.000", "heard rate 5.000"]
    (tmp_path / "again").mkdir()
    _run(tmp_path / "again", "ros2", "rclpy_listener.py", [
        _pub(0.0, "once", string, once=True), _pub(0.0, "rate", string), _pub(0.2, "t3", string, times=3, rate=5)])
    assert (tmp_path / "run.mcap").read_bytes() == (tmp_path / "again" / "run.mcap").read_bytes()


@pytest.mark.parametrize("flavour, publication, says", [
    ("ros1", _pub(0.0, "x") | {"values": {"text": "x"}}, "std_msgs/msg/String has no field 'text'; its fields are data"),
    ("ros1", _pub(0.0, "x") | {"values": {"data": 3}}, "data: expected a string, got 3"),
    ("ros1", _pub(0.0, "x", times=2, rate=1), "rostopic pub has no -t/--times"),
    ("ros2", _pub(0.0, "x", "std_msgs/msg/String", latch=True), "latch is rostopic pub's -l"),
    ("ros2", _pub(0.0, "x", "nope/msg/Nope"), "nope/msg/Nope is not a message type the run knows"),
])
def test_a_publication_that_cannot_be_made_is_named(flavour: str, publication: dict, says: str) -> None:
    with pytest.raises(ParticipantError, match=re.escape(says)):
        plan(Scenario(duration=1.0, publications=[publication]), wire_for(flavour))


def test_nested_fields_take_yaml_values_and_default_the_rest() -> None:
    twist = {"t": 0.0, "topic": "/cmd", "type": "geometry_msgs/msg/Twist", "values": {"linear": {"x": 0.5}}}
    wire = wire_for("ros2")
    [planned] = plan(Scenario(duration=1.0, publications=[twist]), wire).publications
    message = wire.catalog.decode("geometry_msgs/msg/Twist", planned.data)
    assert (message.linear.x, message.linear.y, message.angular.z) == (0.5, 0.0, 0.0)
    assert (planned.period_ns, planned.times, planned.wait, planned.latch) == (1_000_000_000, 0, False, False)


def test_once_with_a_rate_is_refused_by_the_scenario() -> None:
    with pytest.raises(ValueError, match="give once, or a rate and times, not both"):
        Scenario(duration=1.0, publications=[_pub(0.0, "x", once=True, rate=2)])


@pytest.mark.slow
@pytest.mark.parametrize("flavour, twist", [("ros1", "geometry_msgs/Twist"), ("ros2", "geometry_msgs/msg/Twist")])
def test_topic_pub_on_a_turtles_cmd_vel_drives_it(tmp_path: Path, flavour: str, twist: str) -> None:
    """As in the ROS 2 launch tutorial (`ros2 topic pub -r 1 /turtlesim1/turtle1/cmd_vel ...`): the grader's command
    reaches the robot's base, while the run's node only listens."""
    listener = "rospy_listener.py" if flavour == "ros1" else "rclpy_listener.py"
    drive = {"t": 0.0, "topic": "/turtle1/cmd_vel", "type": twist, "values": {"linear": {"x": 1.0}}, "rate": 1}
    scenario = Scenario(robot="turtlesim", duration=4.0, publications=[drive])
    run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=NODES / listener, flavour=flavour),)),
        tmp_path / "run.mcap", tmp_path / "run.log")
    poses = [m.x for _, m in Recording.open(tmp_path / "run.mcap").messages("/turtle1/pose")]
    assert poses[-1] - poses[0] > 2.0  # about 1 m/s while commands come each second (turtlesim holds one for 1 s)


def test_a_service_call_fills_the_fields_it_does_not_give_as_the_cli_does() -> None:
    """`ros2 service call /spawn turtlesim/srv/Spawn "{x: 2, y: 2, theta: 0.2}"` (the substitutions tutorial): the
    name the request does not give is empty, as ros2 service call leaves it."""
    from grader.runtime.scenario_calls import planned_calls
    from sim.scenario import ServiceCallSpec

    wire = wire_for("ros2")
    [call] = planned_calls([ServiceCallSpec(t=0.0, service="/spawn", type="turtlesim/srv/Spawn",
                                            request={"x": 2, "y": 2, "theta": 0.2})], wire)
    request = wire.catalog.decode("turtlesim/srv/Spawn_Request", call.call.request)
    assert (request.x, request.y, request.name) == (2.0, 2.0, "")


@pytest.mark.slow
@pytest.mark.parametrize("durability, heard", [("VOLATILE", True), ("TRANSIENT_LOCAL", False)])
def test_ros2_topic_pub_offers_the_default_qos(tmp_path: Path, durability: str, heard: bool) -> None:
    """ros2 topic pub publishes RELIABLE and VOLATILE: a TRANSIENT_LOCAL subscription requests more than it offers
    and hears nothing, as between two real rclpy nodes."""
    listener = tmp_path / "listener.py"
    listener.write_text((NODES / "rclpy_listener.py").read_text().replace(
        ", 10)\n", f", rclpy.qos.QoSProfile(depth=10, durability=rclpy.qos.DurabilityPolicy.{durability}))\n")
        .replace("import rclpy\n", "import rclpy\nimport rclpy.qos\n"))
    scenario = Scenario(duration=4.0, publications=[_pub(0.0, "rate", "std_msgs/msg/String")])
    run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=listener, flavour="ros2"),)),
        tmp_path / "run.mcap", tmp_path / "run.log")
    lines = [line.text for line in Recording.open(tmp_path / "run.mcap").output_lines()]
    assert any(text.startswith("heard rate") for text in lines) is heard, lines
