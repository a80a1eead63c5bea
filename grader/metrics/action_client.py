"""An action client judged by what it sent and what it said: the goal its node's send_goal calls carried, and whether
its output reported the feedback and the result the server gave back (the ROS 2 action tutorial's client logs each
feedback's sequence and the result's)."""
from __future__ import annotations

from typing import Any

from pydantic import JsonValue

from grader.metrics.action_record import plain
from grader.metrics.base import Measurement, Metric, MetricParams
from grader.metrics.run import RunData
from grader.metrics.service_client import _in_text
from grader.metrics.service_responses import _matches


class Params(MetricParams):
    """The action called, the goal fields its goal must carry, and the result's list field whose growing prefixes
    (a Fibonacci server's feedback: the sequence so far, from its third number) and whole value the output must
    hold."""

    action: str
    goal: dict[str, JsonValue] = {}
    sequence: str = "sequence"
    first_feedback_length: int = 3
    tolerance: float = 1e-9


def _calls(run: RunData, action: str, part: str) -> list:
    service = f"{action}/_action/{part}"
    return [call for call in run.service_calls if call.service == service]


def measure(run: RunData, params: Params) -> Measurement:
    """The first goal's fields against ``goal`` (a task of this metric sends no goals of its own); the result of the
    first answered get_result call; which of the result's prefixes (the feedback a server sent on the way) and the
    whole result are in the node's lines after the goal was sent."""
    goals = _calls(run, params.action, "send_goal")
    results = [call for call in _calls(run, params.action, "get_result") if call.response is not None]
    sent = plain(goals[0].request.get("goal")) if goals else None
    wrong = ""
    if goals:
        for name, want in params.goal.items():
            got = (sent or {}).get(name)
            if not _matches(got, want, params.tolerance):
                wrong = f"The goal's {name} was {got!r}, expected {want!r}"
                break
    accepted = bool(goals and goals[0].response is not None and goals[0].response.get("accepted"))
    result = plain(results[0].response.get("result")) if results else None
    sequence: list[Any] = list((result or {}).get(params.sequence) or [])
    lines = [line.message()[1] for line in run.lines if goals and line.t >= goals[0].t]
    prefixes = [sequence[:n] for n in range(params.first_feedback_length, len(sequence))]
    reported = [p for p in prefixes if any(_in_text(p, text) for text in lines)]
    missing = next((p for p in prefixes if p not in reported), None)
    never = f"no goal reached {params.action}" if not goals else (
        f"{params.action} never answered the goal" if goals[0].response is None else "")
    return {
        "n_goals": len(goals),
        "goal_correct": 1.0 if goals and not wrong else 0.0,
        "first_wrong_goal": wrong or never[:1].upper() + never[1:],
        "accepted": 1.0 if accepted else 0.0,
        "result": "" if result is None else f"{params.sequence}={sequence}",
        "n_feedback_expected": len(prefixes),
        "feedback_reported_fraction": len(reported) / len(prefixes) if prefixes else 0.0,
        "first_unreported_feedback": "" if missing is None else f"The feedback {missing} is in no line your node wrote",
        "result_reported": 1.0 if result is not None and any(_in_text(sequence, text) for text in lines) else 0.0,
        "no_result": "" if result is not None else (never or "the node never asked for the result (get_result_async)"),
    }


METRIC = Metric(
    name="action_client",
    params=Params,
    quantities=frozenset({"n_goals", "goal_correct", "first_wrong_goal", "accepted", "result", "n_feedback_expected",
                          "feedback_reported_fraction", "first_unreported_feedback", "result_reported",
                          "no_result"}),
    measure=measure,
)
