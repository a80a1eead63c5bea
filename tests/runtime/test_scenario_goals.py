"""The grader as an action client: a scenario's action_goals are sent as `ros2 action send_goal` sends them (waiting
for the server, the goal, then its result; Ctrl+C at cancel_at cancels it), through the service routing, and the
recording holds the goals, feedback, status and results that the action_goals metric reads back."""
from __future__ import annotations

from pathlib import Path

import pytest
from pydantic import ValidationError

from grader.metrics.action_goals import METRIC, Params
from grader.metrics.run import RunData
from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import RunError, run
from sim import Scenario
from sim.scenario import ActionGoalSpec

pytestmark = pytest.mark.slow

NODES = Path(__file__).resolve().parent / "nodes" / "actions"
FIBONACCI = "example_interfaces/action/Fibonacci"
GOALS = [ActionGoalSpec(t=0.5, action="/fibonacci", type=FIBONACCI, goal={"order": 4}),
         ActionGoalSpec(t=3.0, action="/fibonacci", type=FIBONACCI, goal={"order": 8}, cancel_at=4.2)]


def _run(tmp: Path, name: str, *args: str) -> RunData:
    spec = RunSpec(scenario=Scenario(duration=6.0, action_goals=GOALS),
                   nodes=(NodeSpec(script=NODES / "fib_server.py", args=args, flavour="ros2"),))
    run(spec, tmp / f"{name}.mcap", tmp / f"{name}.log")
    return RunData.from_recording(Recording.open(tmp / f"{name}.mcap"), start_time=2.0)


@pytest.fixture(scope="module")
def tmp(tmp_path_factory) -> Path:
    return tmp_path_factory.mktemp("goals")


def test_goals_feedback_status_and_results_of_a_server_that_cancels(tmp) -> None:
    data = _run(tmp, "cancels", "cancel")
    first, second = data.action_goals
    # the node is up at 0.35 s and serves from then on, so each goal goes out at its time
    assert (first.t, first.goal, first.accepted, first.feedback_t) == (2.5, {"order": 4}, True, (2.5, 3.0, 3.5))
    assert first.statuses == (2, 4) and first.result == {"sequence": [0, 1, 1, 2, 3]}
    assert (second.t, second.cancel_t, second.cancel_return_code, second.statuses) == (5.0, 6.2, 0, (2, 3, 5))
    assert METRIC.measure(data, Params(goal=0, expected_result={"sequence": [0, 1, 1, 2, 3]}))["result_correct"] == 1
    measured = METRIC.measure(data, Params(goal=1, expected_status=5))
    assert (measured["status_name"], measured["n_feedback"], measured["feedback_rate_hz"]) == ("CANCELED", 3, 2.0)


def test_a_single_threaded_server_cannot_take_a_cancel_while_it_executes(tmp) -> None:
    data = _run(tmp, "ignores")
    # the server blocks in its execute callback, so the cancel waits: the run ends before the goal does
    assert data.action_goals[1].statuses == (2,) and data.action_goals[1].cancel_return_code is None
    measured = METRIC.measure(data, Params(goal=1, expected_status=5))
    assert (measured["status_as_expected"], measured["status_name"]) == (0, "EXECUTING")


def test_the_run_repeats_bit_for_bit(tmp) -> None:
    _run(tmp, "one", "cancel")
    _run(tmp, "two", "cancel")
    assert (tmp / "one.mcap").read_bytes() == (tmp / "two.mcap").read_bytes()


def test_goals_of_an_action_unknown_to_rospy_and_cancelled_before_they_are_sent_are_refused(tmp) -> None:
    # a rospy run sends goals with actionlib (tests/runtime/test_scenario_actionlib_goals.py), in its catkin types
    with pytest.raises(RunError, match="is not an action the run knows"):
        run(RunSpec(scenario=Scenario(duration=1.0, action_goals=GOALS[:1]),
                    nodes=(NodeSpec(script=NODES / "fib_server.py", flavour="ros1"),)), tmp / "r.mcap", tmp / "r.log")
    with pytest.raises(ValidationError, match="cancelled at 0.2 s"):
        Scenario(duration=1.0, action_goals=[ActionGoalSpec(t=0.5, action="/a", type=FIBONACCI, cancel_at=0.2)])
    with pytest.raises(ValidationError):
        ActionGoalSpec(t=0.5, action="/a", type="example_interfaces/srv/AddTwoInts")
