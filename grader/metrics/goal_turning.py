"""How much the turtle turned on its way to a goal, against the least turn that faces it: the long way round shows."""
from __future__ import annotations

import math

import numpy as np

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.run import RunData


class Params(TrajectoryParams):
    """The goal (a scenario sets it to the point its stdin types)."""

    goal_x: float = 0.0
    goal_y: float = 0.0


def measure(run: RunData, params: Params) -> Measurement:
    """Every turn summed (either way), the turn that faces the goal from the start (the short way), and the excess."""
    traj = run.trajectory(params.source)
    if len(traj) < 1:
        raise MetricError("the recording holds no pose of the robot")
    turned = float(np.abs(np.diff(np.unwrap(traj.yaw))).sum())
    bearing = math.atan2(params.goal_y - float(traj.y[0]), params.goal_x - float(traj.x[0]))
    off = bearing - float(traj.yaw[0])
    needed = abs(math.atan2(math.sin(off), math.cos(off)))
    return {"turned_rad": turned, "needed_rad": needed, "extra_turn_rad": turned - needed,
            "goal_x": params.goal_x, "goal_y": params.goal_y}


METRIC = Metric(
    name="goal_turning",
    params=Params,
    quantities=frozenset({"turned_rad", "needed_rad", "extra_turn_rad", "goal_x", "goal_y"}),
    measure=measure,
)
