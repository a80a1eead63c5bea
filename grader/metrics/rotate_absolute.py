"""A turtlesim rotate_absolute client judged by where turtle1 ended, how it got there and what the node said: the final
heading against the goal's theta, whether the turn went through the action (a goal turtlesim accepted and ended
SUCCEEDED, and no velocity command of the node's own outside the goal), and whether the node's output holds the
result's ``delta``.

Velocity commands are the node's and the action server's alike in the recording; the server's come only while a goal
runs, ending with a zero Twist when it succeeds, and a command of the node's during a goal makes turtlesim abort it,
so a command before the goal or after that stop is the node's own driving.
"""
from __future__ import annotations

import math
import re

import numpy as np

from grader.metrics.action_record import plain
from grader.metrics.base import Measurement, Metric, MetricError, MetricParams
from grader.metrics.motion import wrap
from grader.metrics.run import RunData

SUCCEEDED = 4
STATUS_NAMES = {2: "EXECUTING", 4: "SUCCEEDED", 5: "CANCELED", 6: "ABORTED"}
_NUMBER = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?")


class Params(MetricParams):
    """The goal's heading (rad), the action, and how close a logged number must be to the result's delta."""

    theta: float = 0.0
    action: str = "/turtle1/rotate_absolute"
    reported_within: float = 0.006  # a delta printed to two decimals is within 0.005 of it


def _own_commands(run: RunData, start: float) -> int:
    """The node's own velocity commands: those before the goal and after the server's stop (its first zero Twist
    from the goal on), which a completed goal ends with."""
    commands = run.commands
    still = ~np.any(commands.linear != 0.0, axis=1) & ~np.any(commands.angular != 0.0, axis=1)
    during = commands.t >= start
    stops = np.nonzero(during & still)[0]
    after = np.zeros(len(commands.t), dtype=bool)
    if len(stops):
        after[stops[0] + 1:] = True
    return int(np.count_nonzero(~during | after))


def measure(run: RunData, params: Params) -> Measurement:
    """Final heading error (deg), the first goal's acceptance and end, the node's own commands, the logged delta."""
    path = run.trajectory("ground_truth")
    if not len(path):
        raise MetricError("the recording holds no pose of turtle1")
    goals = [c for c in run.service_calls if c.service == f"{params.action}/_action/send_goal"]
    results = [c for c in run.service_calls
               if c.service == f"{params.action}/_action/get_result" and c.response is not None]
    accepted = bool(goals and goals[0].response is not None and goals[0].response.get("accepted"))
    status = int(results[0].response["status"]) if results else None
    delta = float(plain(results[0].response["result"])["delta"]) if results else None
    own = _own_commands(run, goals[0].t if goals else math.inf)
    lines = [line.message()[1] for line in run.lines if results and line.t >= results[0].t]
    logged = [float(n) for text in lines for n in _NUMBER.findall(text)]
    reported = delta is not None and any(abs(n - delta) <= params.reported_within for n in logged)
    uses_action = accepted and status == SUCCEEDED and own == 0
    return {
        "heading_error_deg": math.degrees(abs(float(wrap(float(path.yaw[-1]) - params.theta)))),
        "final_heading": float(path.yaw[-1]),
        "theta": params.theta,
        "n_goals": len(goals),
        "accepted": 1.0 if accepted else 0.0,
        "status_name": STATUS_NAMES.get(status, "no result") if status is not None else "no result",
        "own_commands": own,
        "uses_action": 1.0 if uses_action else 0.0,
        "delta": "" if delta is None else f"{delta:.4f}",
        "delta_reported": 1.0 if reported else 0.0,
    }


METRIC = Metric(
    name="rotate_absolute",
    params=Params,
    quantities=frozenset({"heading_error_deg", "final_heading", "theta", "n_goals", "accepted", "status_name",
                          "own_commands", "uses_action", "delta", "delta_reported"}),
    measure=measure,
)
