"""Hostile action servers and clients: a server flooding feedback, a server that never answers a goal, clients
(actionlib's and rclpy's) sending goals without end. Each ends in a recorded status with a plain message, in bounded
time."""
from __future__ import annotations

import dataclasses
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

from adversarial_helpers import CORPUS, LIMITS, assert_nothing_escaped, refuses_to_run_nodes  # noqa: E402

from grader.metrics import METRICS  # noqa: E402
from grader.metrics.run import RunData  # noqa: E402
from grader.recording import Recording  # noqa: E402
from grader.runtime import NodeSpec, RunSpec  # noqa: E402
from grader.runtime.session import run  # noqa: E402
from sim import Scenario  # noqa: E402

pytestmark = pytest.mark.slow
GOAL = {"t": 0.5, "action": "/fibonacci", "type": "example_interfaces/action/Fibonacci", "goal": {"order": 5}}


@pytest.fixture(autouse=True)
def _no_leftovers():
    if refuses_to_run_nodes():
        pytest.skip("as root without bubblewrap or user namespaces, rosgrade refuses to run nodes")
    yield
    assert_nothing_escaped()


def _run(name: str, tmp: Path, flavour: str, scenario: Scenario, limits=LIMITS):
    result = run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=CORPUS / f"{name}.py", flavour=flavour),),
                         limits=limits), tmp / "run.mcap", tmp / "run.log")
    return result, Recording.open(tmp / "run.mcap")


def _goal_measure(recording: Recording, **params) -> dict:
    metric = METRICS["action_goals"]
    return metric.judge(RunData.from_recording(recording), metric.params(**params))


def test_a_server_flooding_feedback_pays_sim_time_for_each_message(tmp_path):
    result, recording = _run("action_feedback_flood", tmp_path, "ros2", Scenario(duration=3.0, action_goals=[GOAL]))
    assert result.nodes[0].status == "stopped_at_end"
    [goal] = RunData.from_recording(recording).action_goals
    # one library-call quantum (1 ms) a publish: about 2500 in the 2.5 s after the goal, never more
    assert goal.accepted and 2000 < len(goal.feedback_t) <= 2500 and goal.result_status is None
    measured = _goal_measure(recording, goal=0)
    assert measured["status_name"] == "EXECUTING" and measured["n_feedback"] == len(goal.feedback_t)
    assert result.wall_s < LIMITS.wall_s


def test_a_server_that_never_answers_a_goal_leaves_it_unanswered(tmp_path):
    result, recording = _run("action_never_answers", tmp_path, "ros2", Scenario(duration=3.0, action_goals=[GOAL]))
    assert result.nodes[0].status == "stopped_at_end"
    [goal] = RunData.from_recording(recording).action_goals
    assert (goal.accepted, goal.feedback_t, goal.statuses, goal.result_status) == (None, (), (), None)
    measured = _goal_measure(recording, goal=0)
    assert (measured["accepted"], measured["first_wrong"]) == (0.0, "no result came back")
    assert result.wall_s < LIMITS.wall_s


def test_a_client_sending_goals_without_end_is_stopped_by_the_wall_clock_budget(tmp_path):
    """actionlib's server lists every goal in each status message and its client looks each of its goals up in
    each one, as Debian's does: the node's work grows with the square of its goals, and the run's wall-clock budget
    ends it (here 6 s) with a plain status."""
    limits = dataclasses.replace(LIMITS, wall_s=6)
    result, recording = _run("action_goal_flood", tmp_path, "ros1", Scenario(duration=4.0), limits)
    assert (result.nodes[0].status, result.nodes[0].message) == (
        "timeout", "the run exceeded its wall-clock budget of 6 s")
    printed = [text for _, stream, text in recording.output_lines() if stream == "stdout"]
    assert printed and printed[0] == "goals 100"
    assert result.wall_s < 8.0


def test_an_rclpy_client_sending_goals_without_end_pays_sim_time_for_each(tmp_path):
    """Each goal is a send_goal call (a library-call quantum of sim time and a routed call): a few thousand goals in
    the run's seconds, the run ending on time."""
    result, recording = _run("action_goal_flood_ros2", tmp_path, "ros2", Scenario(duration=4.0))
    assert result.nodes[0].status == "stopped_at_end"
    printed = [text for _, stream, text in recording.output_lines() if stream == "stdout"]
    assert printed and 1000 <= int(printed[-1].split()[1]) <= 4000
    assert result.wall_s < LIMITS.wall_s
