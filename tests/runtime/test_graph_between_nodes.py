"""Whole runs of two nodes that look at the graph: an rclpy node sees the other node (its namespace, publishers,
subscriptions, services and parameter services), the world's node and counts across them; a rospy node sees another
node's topic among the published ones from its registration on; and the recording repeats bit for bit."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Scenario

pytestmark = pytest.mark.slow

NODES = Path(__file__).resolve().parent / "nodes" / "graph"


def _run(tmp: Path, name: str, flavour: str, scripts: tuple[str, str]):
    nodes = tuple(NodeSpec(script=NODES / script, flavour=flavour) for script in scripts)
    run(RunSpec(scenario=Scenario(duration=1.0), nodes=nodes), tmp / f"{name}.mcap", tmp / f"{name}.log")
    recording = Recording.open(tmp / f"{name}.mcap")
    return tmp / f"{name}.mcap", [text for _, stream, text in recording.output_lines() if stream == "stdout"]


@pytest.fixture(scope="module")
def ros2(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("graph2")
    return [_run(tmp, name, "ros2", ("graph_watcher.py", "graph_talker.py")) for name in ("first", "again")]


def _at(printed: list[str], what: str) -> str:
    return next(line.split(" ", 2)[2] for line in printed if line.split(" ", 2)[1] == what)


def test_an_rclpy_node_sees_the_other_node_and_the_world_with_their_endpoints(ros2) -> None:
    _, printed = ros2[0]
    assert _at(printed, "nodes") == "[('graph_watcher', '/'), ('gazebo', '/'), ('graph_talker', '/team')]"
    # the robot's base subscribes to /cmd_vel; the talker publishes /chatter and serves /graph_switch
    assert _at(printed, "counts") == "chatter pub 1 cmd_vel sub 1 switch 1"
    # an action server's feedback and status publishers are the node's, as rcl lists them
    assert _at(printed, "talker") == (
        "pub [('/chatter', ['std_msgs/msg/String']), ('/parameter_events', ['rcl_interfaces/msg/ParameterEvent']), "
        "('/rosout', ['rcl_interfaces/msg/Log']), ('/team/count/_action/feedback', "
        "['example_interfaces/action/Fibonacci_FeedbackMessage']), ('/team/count/_action/status', "
        "['action_msgs/msg/GoalStatusArray'])]")
    assert "talker sub [('/odom', ['nav_msgs/msg/Odometry'])]" in [line.split(" ", 1)[1] for line in printed]
    assert _at(printed, "switch") == (
        "['std_srvs/srv/SetBool'] talker params ['/team/graph_talker/describe_parameters', "
        "'/team/graph_talker/get_parameter_types', '/team/graph_talker/get_parameters', "
        "'/team/graph_talker/list_parameters', '/team/graph_talker/set_parameters', "
        "'/team/graph_talker/set_parameters_atomically']")
    assert _at(printed, "chatter") == "['std_msgs/msg/String']"
    assert _at(printed, "actions") == ("[('/team/count', ['example_interfaces/action/Fibonacci'])] served by talker "
                                       "[('/team/count', ['example_interfaces/action/Fibonacci'])]")
    assert _at(printed, "nobody") == ("NodeNameNonExistentError cannot get publisher names and types for nonexistent "
                                      "node: error not set")


def test_a_run_that_asks_the_graph_repeats_bit_for_bit(ros2) -> None:
    (first, _), (again, _) = ros2
    assert first.read_bytes() == again.read_bytes()


def test_a_rospy_node_sees_another_nodes_publication_once_it_registered(tmp_path) -> None:
    _, printed = _run(tmp_path, "ros1", "ros1", ("graph_rospy_watcher.py", "graph_rospy_talker.py"))
    seen = [line.split(" ", 2)[2] for line in printed]
    # the watcher starts first and looks before the talker has registered; from then on the master knows /chatter
    assert seen[0] == "None" and set(seen[1:]) == {"std_msgs/String"}


def test_a_rospy_node_sees_what_the_scenario_publishes_as_rostopic_pub_registers_it(tmp_path) -> None:
    publication = {"t": 0.0, "topic": "/chatter", "type": "std_msgs/String", "values": {"data": "hi"}, "rate": 2}
    run(RunSpec(scenario=Scenario(duration=1.0, publications=[publication]),
                nodes=(NodeSpec(script=NODES / "graph_rospy_watcher.py", flavour="ros1"),)),
        tmp_path / "run.mcap", tmp_path / "run.log")
    printed = [text for _, stream, text in Recording.open(tmp_path / "run.mcap").output_lines() if stream == "stdout"]
    assert printed and {line.split(" ", 2)[2] for line in printed} == {"std_msgs/String"}
