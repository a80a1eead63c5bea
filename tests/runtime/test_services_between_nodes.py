"""Whole runs of nodes that serve and call each other's services: the grader routes each call to the node that serves
it and the answer back, in sim time; rclpy's call inside a callback deadlocks a single-threaded executor as it does for
real, and returns under a MultiThreadedExecutor with a reentrant group; rospy's handler errors reach the caller in
rospy's words; both recordings hold request and response, and repeat bit for bit."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.metrics.run import service_calls
from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Scenario

pytestmark = pytest.mark.slow

NODES = Path(__file__).resolve().parent / "nodes" / "services"


def _run(tmp: Path, name: str, *nodes: NodeSpec):
    result = run(RunSpec(scenario=Scenario(duration=3.0), nodes=nodes), tmp / f"{name}.mcap", tmp / f"{name}.log")
    recording = Recording.open(tmp / f"{name}.mcap")
    printed = [(round(t, 3), text) for t, stream, text in recording.output_lines() if stream == "stdout"]
    return result, recording, printed


def _ros2(script: str, *args: str) -> NodeSpec:
    return NodeSpec(script=NODES / script, args=args, flavour="ros2")


@pytest.fixture(scope="module")
def tmp(tmp_path_factory) -> Path:
    return tmp_path_factory.mktemp("services")


@pytest.fixture(scope="module")
def rclpy_pair(tmp):
    return _run(tmp, "rclpy", _ros2("add_client.py"), _ros2("add_server.py"))


def test_an_rclpy_client_waits_for_the_service_then_gets_each_sum_at_the_time_it_called(rclpy_pair) -> None:
    result, _, printed = rclpy_pair
    assert result.nodes[0].status == "exited", result.nodes[0].message
    # both start 0.35 s in (rclpy.init); wait_for_service looks every 0.25 s; the server takes each request at the
    # time it was sent, and the response comes back then
    assert printed == [(2.35, "ready before: False"), (2.6, "ready at 0"), (2.6, "serve 2+3 at 2600000000"),
                       (2.6, "sum 5 sent 0 got 2600000000"), (2.6, "serve 40+2 at 2600000000"),
                       (2.6, "sum 42 sent 2600000000 got 2600000000")]


def test_requests_and_responses_are_recorded_under_the_caller_and_the_server(rclpy_pair) -> None:
    _, recording, _ = rclpy_pair
    calls = service_calls(recording)
    assert [(c.service, c.request, c.response) for c in calls] == [
        ("/add_two_ints", {"a": 2, "b": 3}, {"sum": 5}), ("/add_two_ints", {"a": 40, "b": 2}, {"sum": 42})]
    channels = {(i.topic, i.callerid, i.origin) for i in recording.topics() if i.topic.startswith("/rosgrade/service")}
    assert channels == {("/rosgrade/service/add_two_ints/request", "/add_two_ints_client", "node"),
                        ("/rosgrade/service/add_two_ints/response", "/add_two_ints_server", "node")}


def test_the_run_repeats_bit_for_bit(tmp, rclpy_pair) -> None:
    _run(tmp, "again", _ros2("add_client.py"), _ros2("add_server.py"))
    assert (tmp / "again.mcap").read_bytes() == (tmp / "rclpy.mcap").read_bytes()


@pytest.mark.parametrize("group, returns", [("reentrant", True), ("single", False)])
def test_call_in_a_timer_returns_only_with_a_reentrant_group_and_a_multithreaded_executor(tmp, group: str,
                                                                                          returns: bool) -> None:
    _, recording, printed = _run(tmp, group, _ros2("call_in_timer.py", group), _ros2("add_server.py"))
    # the server answers either way: the single-threaded caller never takes the response (the classic deadlock)
    assert printed[:2] == [(2.45, "calling"), (2.45, "serve 1+2 at 2450000000")]
    assert ((2.45, "returned 3") in printed) == returns
    assert [c.response for c in service_calls(recording)] == [{"sum": 3}]


def test_a_rospy_service_serves_another_node_and_its_handler_error_reaches_the_caller(tmp) -> None:
    result, recording, printed = _run(tmp, "rospy", NodeSpec(script=NODES / "rospy_client.py"),
                                      NodeSpec(script=NODES / "rospy_server.py"))
    assert result.nodes[0].status == "exited", result.nodes[0].message
    assert printed == [(2.4, "up at 2.400"), (2.4, "serve True at 2.400"), (2.4, "got done at 2.400"),
                       (2.4, "serve False at 2.400"),
                       (2.4, "failed: service [/switch] responded with an error: b'error processing request: no "
                             "thanks'")]
    assert [(c.request, c.response) for c in service_calls(recording)] == [
        ({"data": True}, {"success": True, "message": "done"}), ({"data": False}, None)]


def test_a_call_whose_server_ends_before_answering_fails_as_rospys_closed_connection(tmp) -> None:
    result, recording, printed = _run(tmp, "dying", NodeSpec(script=NODES / "rospy_die_caller.py"),
                                      NodeSpec(script=NODES / "rospy_dying_server.py"))
    assert result.nodes[1].exit_code == 3
    assert [text for _, text in printed] == [
        "failed: transport error completing service call: unable to receive data from sender, check sender's logs for "
        "details"]
    assert [c.response for c in service_calls(recording)] == [None]
