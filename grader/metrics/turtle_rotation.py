"""How far and which way the turtle turned: the rotation task's measure (an angle in degrees, clockwise or not)."""
from __future__ import annotations

import math

import numpy as np
from pydantic import Field

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.run import RunData


class Params(TrajectoryParams):
    """What the run asked for (a scenario sets them to the values its stdin types)."""

    angle_deg: float = Field(90.0, gt=0.0)
    clockwise: bool = False
    min_turn_deg: float = 1.0  # below this the turtle did not turn


def measure(run: RunData, params: Params) -> Measurement:
    """The heading's total change as one continuous angle (anticlockwise positive), in degrees."""
    traj = run.trajectory(params.source)
    if len(traj) < 2:
        raise MetricError("the recording holds no pose of the turtle")
    turned = math.degrees(float(np.unwrap(traj.yaw)[-1] - traj.yaw[0]))
    size = abs(turned)
    moved = "nowhere" if size < params.min_turn_deg else "anticlockwise" if turned > 0 else "clockwise"
    asked = "clockwise" if params.clockwise else "anticlockwise"
    return {
        "turned_deg": turned,
        "turned_abs_deg": size,
        "angle_deg": params.angle_deg,
        "angle_error_deg": abs(size - params.angle_deg),
        "ratio": size / params.angle_deg,
        "moved_direction": moved,
        "asked_direction": asked,
        "direction_ok": moved == asked,
    }


METRIC = Metric(
    name="turtle_rotation",
    params=Params,
    quantities=frozenset({"turned_deg", "turned_abs_deg", "angle_deg", "angle_error_deg", "ratio", "moved_direction",
                          "asked_direction", "direction_ok"}),
    measure=measure,
)
