"""Whole runs of an rclpy action server and client (the ROS 2 action tutorial's Fibonacci): the goal, cancel and result
requests are routed as services and feedback and status travel as topics, as rcl_action builds them; statuses follow
action_msgs' values, a cancelled goal ends CANCELED, and the recording holds all of it and repeats bit for bit."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.metrics.run import service_calls
from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Scenario

pytestmark = pytest.mark.slow

NODES = Path(__file__).resolve().parent / "nodes" / "actions"
EXECUTING, CANCELING, SUCCEEDED, CANCELED = 2, 3, 4, 5


def _run(tmp: Path, name: str, mode: tuple[str, ...] = ()):
    nodes = tuple(NodeSpec(script=NODES / script, args=mode, flavour="ros2")
                  for script in ("fib_client.py", "fib_server.py"))
    result = run(RunSpec(scenario=Scenario(duration=5.0), nodes=nodes), tmp / f"{name}.mcap", tmp / f"{name}.log")
    recording = Recording.open(tmp / f"{name}.mcap")
    printed = [(round(t, 3), text) for t, stream, text in recording.output_lines() if stream == "stdout"]
    return result, recording, printed


def _statuses(recording) -> list[list[int]]:
    return [[s.status for s in msg.status_list] for _, msg in recording.messages("/fibonacci/_action/status")]


@pytest.fixture(scope="module")
def tmp(tmp_path_factory) -> Path:
    return tmp_path_factory.mktemp("actions")


@pytest.fixture(scope="module")
def fibonacci(tmp):
    return _run(tmp, "fibonacci")


def test_the_client_gets_every_feedback_and_the_result_of_a_goal_the_server_executes(fibonacci) -> None:
    result, _, printed = fibonacci
    assert result.nodes[0].status == "exited", result.nodes[0].message
    # a single-threaded server blocks in its execute callback, so its clock stays at the goal's time (as rclpy's
    # /clock subscription waits for the executor); its feedback goes out every 0.5 s of sim time
    # wait_for_server looks every 0.25 s until the services are served and the feedback and status topics matched
    assert printed == [(2.35, "ready before: False"), (2.61, "server at 0"), (2.61, "executing order 5 at 2610000000"),
                       (2.61, "feedback [0, 1, 1] at 2610000000"), (2.61, "accepted True at 2610000000"),
                       (3.11, "feedback [0, 1, 1, 2] at 3110000000"), (3.61, "feedback [0, 1, 1, 2, 3] at 3610000000"),
                       (4.11, "feedback [0, 1, 1, 2, 3, 5] at 4110000000"), (4.61, "succeeded at 2610000000"),
                       (4.61, f"result status {SUCCEEDED} [0, 1, 1, 2, 3, 5] handle status {SUCCEEDED} "
                              "at 4610000000")]


def test_goal_and_result_are_recorded_as_service_calls_and_feedback_and_status_as_topics(fibonacci) -> None:
    _, recording, _ = fibonacci
    calls = service_calls(recording)
    assert [c.service for c in calls] == ["/fibonacci/_action/send_goal", "/fibonacci/_action/get_result"]
    goal_id = bytes(calls[0].request["goal_id"].uuid)
    assert calls[0].request["goal"].order == 5 and calls[0].response["accepted"] is True
    assert bytes(calls[1].request["goal_id"].uuid) == goal_id and goal_id[6] >> 4 == 4  # a version 4 UUID
    assert calls[1].response["status"] == SUCCEEDED
    assert list(calls[1].response["result"].sequence) == [0, 1, 1, 2, 3, 5]
    feedback = [list(msg.feedback.sequence) for _, msg in recording.messages("/fibonacci/_action/feedback")]
    assert feedback == [[0, 1, 1], [0, 1, 1, 2], [0, 1, 1, 2, 3], [0, 1, 1, 2, 3, 5]]
    assert _statuses(recording) == [[EXECUTING], [SUCCEEDED]]


def test_a_goal_cancelled_while_it_executes_ends_canceled(tmp) -> None:
    _, recording, printed = _run(tmp, "cancel", ("cancel",))
    # a MultiThreadedExecutor with a reentrant group takes the cancel while the goal executes in a worker
    assert (3.11, "cancel return_code 0 canceling 1 at 3110000000") in printed
    assert printed[-1][1].startswith(f"result status {CANCELED} [0, 1, 1, 2] handle status {CANCELED}")
    assert _statuses(recording) == [[EXECUTING], [CANCELING], [CANCELED]]
    cancel = [c for c in service_calls(recording) if c.service == "/fibonacci/_action/cancel_goal"]
    assert [c.response["return_code"] for c in cancel] == [0]


def test_server_callbacks_and_a_blocking_send_goal_as_real_rclpy_runs_them(tmp) -> None:
    """What Jazzy's rclpy 7.1.6 printed for this node (5 runs of nodes/actions/callbacks.py, then named p16_*, under
    the wheels' venv: `AMENT_PREFIX_PATH=$VENV RMW_IMPLEMENTATION=rmw_fastrtps_cpp $VENV/bin/python callbacks.py`,
    Fibonacci from test_msgs; the same lines each time but the wall stamps and the traceback's library frames). Not a
    conformance probe: under the harness's simulated clock the real side was stopped before it printed (unexplained)."""
    result = run(RunSpec(scenario=Scenario(duration=3.0), nodes=(
        NodeSpec(script=NODES / "callbacks.py", flavour="ros2"),)), tmp / "callbacks.mcap", tmp / "callbacks.log")
    assert result.nodes[0].status == "exited", result.nodes[0].message
    lines = Recording.open(tmp / "callbacks.mcap").output_lines()
    assert [text for _, stream, text in lines if stream == "stdout"] == [
        "wait_for_server -> True", "order 1 SUCCEEDED [0, 1]", "order 2 ABORTED []", "order 3 ABORTED [0, 1, 1, 2]",
        "order 7 accepted False", "deferred goal status ACCEPTED result done False", "order 0 SUCCEEDED [0]", "end"]
    logged = [text.split("] ", 2)[-1] for _, stream, text in lines if stream == "stderr" and text.startswith("[")]
    assert logged == [
        "[callbacks_server.action_server]: Error raised in execute callback: order 2 is not allowed",
        "[callbacks_server.action_server]: Goal state not set, assuming aborted. Goal ID: [2 2 2 2 2 2 2 2 2 2 2 2 2 2 "
        "2 2]",
        "[callbacks_server.action_server]: Goal state not set, assuming aborted. Goal ID: [3 3 3 3 3 3 3 3 3 3 3 3 3 3 "
        "3 3]",
        "[callbacks_server.action_server]: Goal request callback did not return a GoalResponse type. Rejecting goal."]
    assert "ValueError: order 2 is not allowed" in [text for _, stream, text in lines if stream == "stderr"]


def test_the_run_repeats_bit_for_bit(tmp, fibonacci) -> None:
    _run(tmp, "again")
    assert (tmp / "again.mcap").read_bytes() == (tmp / "fibonacci.mcap").read_bytes()
