"""Going to a goal point: how close the robot ended, how close it ever came, and when it first got there."""
from __future__ import annotations

import math

import numpy as np

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.run import RunData


class Params(TrajectoryParams):
    """The goal (a scenario sets it to the point its stdin types) and what counts as there."""

    goal_x: float = 0.0
    goal_y: float = 0.0
    within: float = 0.1  # m: "reached" for reached_s


def measure(run: RunData, params: Params) -> Measurement:
    """Distances to the goal at the end, at the start and at the closest point of the path."""
    traj = run.trajectory(params.source)
    if len(traj) < 1:
        raise MetricError("the recording holds no pose of the robot")
    distance = np.hypot(traj.x - params.goal_x, traj.y - params.goal_y)
    inside = np.flatnonzero(distance <= params.within)
    return {
        "final_error": float(distance[-1]),
        "closest": float(distance.min()),
        "start_error": float(distance[0]),
        "final_x": float(traj.x[-1]), "final_y": float(traj.y[-1]),
        "goal_x": params.goal_x, "goal_y": params.goal_y,
        "reached_s": float(traj.t[inside[0]] - run.start_time) if len(inside) else math.nan,
    }


METRIC = Metric(
    name="goal_reach",
    params=Params,
    quantities=frozenset({"final_error", "closest", "start_error", "final_x", "final_y", "goal_x", "goal_y",
                          "reached_s"}),
    measure=measure,
)
