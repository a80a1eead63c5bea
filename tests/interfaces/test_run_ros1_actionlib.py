"""A run of the actionlib tutorials' rospy server and client (a catkin package with its own Fibonacci.action,
add_action_files + generate_messages): both nodes build the seven genmsg classes from START, the client's goal,
feedback and result go through rosgrade's actionlib, and the recording holds actionlib's five topics in the
package's own types, the same on a second run."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.interfaces import run_interfaces
from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from grader.workspace import read_workspace
from sim import Scenario

pytestmark = pytest.mark.slow

PACKAGE = Path(__file__).resolve().parents[2] / "reference_solutions_ros1_actionlib" / "actionlib_tutorials"
SEQUENCE = [0, 1, 1, 2, 3, 5, 8, 13, 21, 34, 55, 89, 144, 233, 377, 610, 987, 1597, 2584, 4181, 6765]


def _run(folder: Path):
    interfaces = run_interfaces(read_workspace(PACKAGE), "ros1")
    assert interfaces.findings == [] and "actionlib_tutorials/msg/Fibonacci" in interfaces.actions
    nodes = tuple(NodeSpec(script=PACKAGE / "scripts" / name) for name in ("fibonacci_server.py",
                                                                            "fibonacci_client.py"))
    spec = RunSpec(scenario=Scenario(duration=4.0), nodes=nodes, interfaces=interfaces)
    folder.mkdir()
    result = run(spec, folder / "run.mcap", folder / "run.log")
    return result, Recording.open(folder / "run.mcap")


@pytest.fixture(scope="module")
def first(tmp_path_factory):
    return _run(tmp_path_factory.mktemp("actionlib") / "first")


def test_the_client_gets_every_feedback_and_the_result(first):
    result, recording = first
    assert [node.status for node in result.nodes] == ["stopped_at_end", "exited"], result.nodes
    printed = [text for _, stream, text in recording.output_lines()
               if stream == "stdout" and text.startswith(("Feedback", "Result"))]
    assert printed == [f"Feedback: {SEQUENCE[:n]}" for n in range(3, 22)] + [
        "Result: " + ", ".join(map(str, SEQUENCE))]


def test_the_recording_holds_actionlibs_topics_in_the_packages_own_types(first):
    _, recording = first
    channels = {(i.topic, i.type, i.callerid) for i in recording.topics() if i.topic.startswith("/fibonacci/")}
    assert channels == {
        ("/fibonacci/goal", "actionlib_tutorials/FibonacciActionGoal", "/fibonacci_client"),
        ("/fibonacci/status", "actionlib_msgs/GoalStatusArray", "/fibonacci"),
        ("/fibonacci/feedback", "actionlib_tutorials/FibonacciActionFeedback", "/fibonacci"),
        ("/fibonacci/result", "actionlib_tutorials/FibonacciActionResult", "/fibonacci"),
    }
    [(_, _, message)] = list(recording.messages_on({"/fibonacci/result"}))
    assert (message.status.status, list(message.result.sequence)) == (3, SEQUENCE)  # SUCCEEDED


def test_a_second_run_is_bit_identical(first, tmp_path):
    _, recording = first
    _run(tmp_path / "second")
    assert (tmp_path / "second" / "run.mcap").read_bytes() == Path(recording.path).read_bytes()
