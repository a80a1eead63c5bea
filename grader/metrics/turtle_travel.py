"""How far and which way the turtle drove: the distance task's measure (move a distance at a speed, fwd or back)."""
from __future__ import annotations

import math

from pydantic import Field

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.motion import path_length
from grader.metrics.run import RunData


class Params(TrajectoryParams):
    """What the run asked for (a scenario sets them to the values its stdin types)."""

    distance: float = Field(1.0, gt=0.0)  # m asked for
    forward: bool = True
    min_travel: float = 0.01  # m below which the turtle did not go anywhere


def measure(run: RunData, params: Params) -> Measurement:
    """Distance along the path, and the net displacement along the start heading (negative: backwards)."""
    traj = run.trajectory(params.source)
    if len(traj) < 2:
        raise MetricError("the recording holds no pose of the turtle")
    travelled = path_length(traj)
    along = (traj.x[-1] - traj.x[0]) * math.cos(traj.yaw[0]) + (traj.y[-1] - traj.y[0]) * math.sin(traj.yaw[0])
    moved = "nowhere" if travelled < params.min_travel else "forwards" if along > 0 else "backwards"
    asked = "forwards" if params.forward else "backwards"
    return {
        "travelled": travelled,
        "displacement": float(along),
        "distance": params.distance,
        "distance_error_rel": abs(travelled - params.distance) / params.distance,
        "ratio": travelled / params.distance,
        "moved_direction": moved,
        "asked_direction": asked,
        "direction_ok": moved == asked,
    }


METRIC = Metric(
    name="turtle_travel",
    params=Params,
    quantities=frozenset({"travelled", "displacement", "distance", "distance_error_rel", "ratio", "moved_direction",
                          "asked_direction", "direction_ok"}),
    measure=measure,
)
