"""An action goal the grader sent (a scenario's ``action_goals``, as ``ros2 action send_goal`` or actionlib's client
sends them), as the student's action server handled it: accepted or not, its feedback count and rate, its final
status and its result's fields against the ones the rubric expects."""
from __future__ import annotations

import math

from pydantic import JsonValue

from grader.metrics.base import Measurement, Metric, MetricError, MetricParams
from grader.metrics.run import RunData
from grader.metrics.service_responses import _matches

# action_msgs/msg/GoalStatus
STATUS_NAMES = {0: "UNKNOWN", 1: "ACCEPTED", 2: "EXECUTING", 3: "CANCELING", 4: "SUCCEEDED", 5: "CANCELED",
                6: "ABORTED"}


def _name(status: int | None) -> str:
    return "no status" if status is None else STATUS_NAMES.get(status, str(status))


class Params(MetricParams):
    """Which of the grader's goals (0: the first it sent), the status it should end in and the result fields
    expected (numbers within ``tolerance``)."""

    goal: int = 0
    expected_status: int = 4
    expected_result: dict[str, JsonValue] = {}
    tolerance: float = 1e-9


def measure(run: RunData, params: Params) -> Measurement:
    """The goal's fate; a goal the grader never sent (its server never came up) is a MetricError saying so."""
    if params.goal >= len(run.action_goals):
        raise MetricError(f"the grader's goal {params.goal + 1} was never sent: no node served the action (its "
                          "send_goal, get_result and cancel_goal services; with rospy, a SimpleActionServer's goal "
                          "topic) with the action type the task names; is the ActionServer created with that type and "
                          "spinning (rospy: a SimpleActionServer made with auto_start=False serves nothing until "
                          "server.start())?")
    goal = run.action_goals[params.goal]
    feedback = goal.feedback_t
    span = feedback[-1] - feedback[0] if len(feedback) > 1 else 0.0
    final = goal.final_status
    wrong = ""
    field = got = want = ""
    if goal.result is None:
        wrong = "no result came back"
    elif final != params.expected_status:
        wrong = f"the goal ended {_name(final)}, expected {_name(params.expected_status)}"
    else:
        for name, value in params.expected_result.items():
            if name not in goal.result or not _matches(goal.result[name], value, params.tolerance):
                field, got, want = name, repr(goal.result.get(name)), repr(value)
                wrong = f"result {name} = {goal.result.get(name)!r}, expected {value!r}"
                break
    return {
        "accepted": 1.0 if goal.accepted else 0.0,
        "n_feedback": len(feedback),
        "feedback_rate_hz": (len(feedback) - 1) / span if span > 0 else math.nan,
        "final_status": -1 if final is None else final,
        "status_name": _name(final),
        "status_as_expected": 1.0 if final == params.expected_status else 0.0,
        "result_correct": 0.0 if wrong else 1.0,
        "first_wrong": wrong,
        "wrong_field": field,
        "wrong_value": got,
        "expected_value": want,
        "cancel_return_code": -1 if goal.cancel_return_code is None else goal.cancel_return_code,
        "decided_at_s": goal.t - run.start_time,  # the report's moment: when the goal was sent
    }


METRIC = Metric(
    name="action_goals",
    params=Params,
    quantities=frozenset({"accepted", "n_feedback", "feedback_rate_hz", "final_status", "status_name",
                          "status_as_expected", "result_correct", "first_wrong", "wrong_field", "wrong_value",
                          "expected_value", "cancel_return_code", "decided_at_s"}),
    measure=measure,
)
