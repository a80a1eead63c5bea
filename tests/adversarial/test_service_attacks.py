"""Hostile and broken service servers and clients: a server that never answers, an answer to a request never given,
a client that calls without end. Each ends in a recorded status with a plain message, in bounded time."""
from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

from adversarial_helpers import CORPUS, LIMITS, assert_nothing_escaped, refuses_to_run_nodes  # noqa: E402

from grader.metrics.run import service_calls  # noqa: E402
from grader.recording import Recording  # noqa: E402
from grader.runtime import NodeSpec, RunSpec  # noqa: E402
from grader.runtime.session import run  # noqa: E402
from sim import Scenario  # noqa: E402

pytestmark = pytest.mark.slow
ADD = "example_interfaces/srv/AddTwoInts"


@pytest.fixture(autouse=True)
def _no_leftovers():
    if refuses_to_run_nodes():
        pytest.skip("as root without bubblewrap or user namespaces, rosgrade refuses to run nodes")
    yield
    assert_nothing_escaped()


def _run(name: str, tmp: Path, flavour: str, scenario: Scenario):
    result = run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=CORPUS / f"{name}.py", flavour=flavour),),
                         limits=LIMITS), tmp / "run.mcap", tmp / "run.log")
    return result, Recording.open(tmp / "run.mcap")


def test_a_server_that_never_answers_leaves_the_graders_calls_unanswered(tmp_path):
    calls = [{"t": t, "service": "/add_two_ints", "type": ADD, "request": {"a": 1, "b": 2}} for t in (0.5, 1.0)]
    result, recording = _run("service_never_answers", tmp_path, "ros2", Scenario(duration=3.0, service_calls=calls))
    assert result.nodes[0].status == "stopped_at_end"
    # the first call reached the server and was never answered, so the second (as ros2 service call would) waits
    assert [(round(c.t, 3), c.response) for c in service_calls(recording)] == [(2.5, None)]
    assert result.wall_s < LIMITS.wall_s


def test_an_answer_to_a_request_never_given_is_a_protocol_violation(tmp_path):
    result, _ = _run("service_forged_answer", tmp_path, "ros1", Scenario(duration=2.0))
    assert result.nodes[0].status == "protocol_violation"
    assert result.nodes[0].message == ("the node broke the grader's channel: RESPOND to request 99 of /forged, which "
                                       "it was not given or has answered")


def test_a_client_calling_without_end_pays_sim_time_for_each_call(tmp_path):
    result, recording = _run("service_call_flood", tmp_path, "ros2", Scenario(duration=2.0))
    assert result.nodes[0].status == "stopped_at_end"
    printed = [text for _, stream, text in recording.output_lines() if stream == "stdout"]
    # one library-call quantum (1 ms) each: about 1650 calls in the 1.65 s after rclpy.init, never more
    assert printed and printed[-1] == "calls 1000" and len(printed) == 1
    assert result.wall_s < LIMITS.wall_s
