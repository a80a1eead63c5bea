"""How a turtlesim move ended: stopped by the node's zero command, by turtlesim's 1 s command timeout, or not at all.

turtlesim zeroes a command older than 1 s, so a turtle always stops once its node goes quiet; a node that relies on
that has left the last motion command in force for a second. ``stop_credit`` is 1 for a zero command sent after the
last motion command (also one that came after the timeout had already stopped the turtle: the node did end its move,
and a move cut short by the timeout loses its credit in the criteria that measure the move), 0.5 for a turtle
stopped by the timeout alone, 0 for one still moving or still being driven at the end.
"""
from __future__ import annotations

import numpy as np

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.motion import moving, rest_since
from grader.metrics.run import RunData

CREDIT = {"zero_command": 1.0, "timeout": 0.5, "commanding": 0.0, "moving": 0.0}


class Params(TrajectoryParams):
    """turtlesim's command timeout."""

    timeout_s: float = 1.0


def measure(run: RunData, params: Params) -> Measurement:
    """Classify the end of the run (``how``) and time it."""
    traj = run.trajectory(params.source)
    if len(traj) < 2 or not np.any(moving(traj, params.rest_speed, params.rest_turn_rate)):
        raise MetricError("the turtle never moved, so there was nothing to stop")
    rest_from = rest_since(traj, params.rest_speed, params.rest_turn_rate)
    commands = run.commands
    zero = commands.is_zero()
    last_motion = float(commands.t[~zero][-1]) if np.any(~zero) else None
    zero_after = commands.t[zero & (commands.t >= (last_motion if last_motion is not None else -np.inf))]
    end = float(traj.t[-1])
    if last_motion is not None and not zero_after.size and end - last_motion <= params.timeout_s:
        how = "commanding"  # the node still sends motion at the end of the run
    elif rest_from is None:
        how = "moving"
    elif zero_after.size:
        how = "zero_command"
    else:
        how = "timeout"
    return {
        "how": how,
        "stop_credit": CREDIT[how],
        "moving_at_end": rest_from is None,
        "rest_at_end_s": 0.0 if rest_from is None else end - rest_from,
        "stopped_at_s": np.nan if rest_from is None else rest_from - run.start_time,
        "last_motion_command_s": np.nan if last_motion is None else last_motion - run.start_time,
        "zero_command_sent": bool(zero_after.size),
    }


METRIC = Metric(
    name="turtle_stop",
    params=Params,
    quantities=frozenset({"how", "stop_credit", "moving_at_end", "rest_at_end_s", "stopped_at_s",
                          "last_motion_command_s", "zero_command_sent"}),
    measure=measure,
)
