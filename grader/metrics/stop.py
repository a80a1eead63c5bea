"""Stop position and distance, and whether the robot stays stopped: where a drive-then-stop task ended up."""
from __future__ import annotations

import math
from typing import Literal

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.motion import path_length, rest_since
from grader.metrics.run import RunData


class Params(TrajectoryParams):
    """Stop settings; odometry by default, because the node decides when to stop from what odometry says."""

    source: Literal["ground_truth", "odometry"] = "odometry"
    min_travel: float = 0.05  # m: a robot that never moved has not "stopped" anywhere


def measure(run: RunData, params: Params) -> Measurement:
    """Final pose, distance from the start, and how long the robot has been standing still at the end."""
    traj = run.trajectory(params.source)
    if len(traj) < 2:
        raise MetricError("the recording has no odometry to locate the robot")
    travelled = path_length(traj)
    rest_from = rest_since(traj, params.rest_speed, params.rest_turn_rate)
    moved = travelled >= params.min_travel
    rest_at_end = math.nan if rest_from is None or not moved else float(traj.t[-1] - rest_from)
    return {
        "final_x": float(traj.x[-1]), "final_y": float(traj.y[-1]),
        "start_x": float(traj.x[0]), "start_y": float(traj.y[0]),
        "final_distance": math.hypot(traj.x[-1] - traj.x[0], traj.y[-1] - traj.y[0]),
        "travelled": travelled,
        "moving_at_end": rest_from is None,
        "rest_at_end_s": 0.0 if rest_from is None and moved else rest_at_end,
        "stopped_at_s": math.nan if rest_from is None or not moved else rest_from - run.start_time,
    }


METRIC = Metric(
    name="stop",
    params=Params,
    quantities=frozenset({
        "final_x", "final_y", "start_x", "start_y", "final_distance", "travelled", "moving_at_end",
        "rest_at_end_s", "stopped_at_s",
    }),
    measure=measure,
)
