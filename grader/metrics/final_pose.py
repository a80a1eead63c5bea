"""Final pose against the start: distance from the start point, from the start line (each wheel), heading error.

The start line passes through the start point across the robot's starting heading, as a line taped on the floor
under the wheels. Both wheels' distances from it are measured, half the wheel track either side of the centre.
"""
from __future__ import annotations

import math

import numpy as np

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.motion import path_length, wrap
from grader.metrics.run import RunData


class Params(TrajectoryParams):
    """The wheel track (m) places the wheels for the start-line distance; 0 measures the robot's centre only."""

    track: float = 0.0
    min_travel: float = 0.05  # m: a robot that never moved has not come back anywhere


def measure(run: RunData, params: Params) -> Measurement:
    """The pose at the end of the run (or at Ctrl+C, if the scenario sends one) against the pose at the start."""
    window = run.until_shutdown(params.source)
    if len(window) < 2:
        raise MetricError("the recording has no positions to locate the robot")
    if path_length(window) < params.min_travel:
        raise MetricError(f"the robot drove only {path_length(window):.2f} m, so it never left the start")
    x0, y0, yaw0 = float(window.x[0]), float(window.y[0]), float(window.yaw[0])
    x1, y1, yaw1 = float(window.x[-1]), float(window.y[-1]), float(window.yaw[-1])
    ahead = np.array([math.cos(yaw0), math.sin(yaw0)])  # the start heading: the line's normal
    left = np.array([-math.sin(yaw1), math.cos(yaw1)])  # the axle at the end
    centre = np.array([x1 - x0, y1 - y0])
    wheels = [centre + side * params.track / 2.0 * left for side in (1.0, -1.0)]
    along = float(centre @ ahead)
    return {
        "start_distance": math.hypot(*centre),
        "line_distance": max(abs(float(w @ ahead)) for w in wheels),
        "along_start_heading": along,
        "across_start_heading": float(centre @ np.array([-ahead[1], ahead[0]])),
        "heading_error_deg": abs(math.degrees(float(wrap(yaw1 - yaw0)))),
        "final_x": x1, "final_y": y1, "final_yaw_deg": math.degrees(yaw1),
        "at_s": float(window.t[-1] - run.start_time),
    }


METRIC = Metric(
    name="final_pose",
    params=Params,
    quantities=frozenset({
        "start_distance", "line_distance", "along_start_heading", "across_start_heading", "heading_error_deg",
        "final_x", "final_y", "final_yaw_deg", "at_s",
    }),
    measure=measure,
)
