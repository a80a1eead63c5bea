"""The metrics a rubric can name: each module measures one thing from a run's arrays."""
from __future__ import annotations

from grader.metrics import (
    circle, final_pose, log_lines, loops, pose_print, shutdown, square, stop, timing, velocity,
)
from grader.metrics.base import Measurement, Metric, MetricError, MetricParams, TrajectoryParams
from grader.metrics.run import Commands, OutputLine, RunData, RunInfo, Trajectory

METRICS: dict[str, Metric] = {
    m.name: m for m in (
        circle.METRIC, square.METRIC, velocity.METRIC, shutdown.METRIC, pose_print.METRIC, stop.METRIC,
        loops.METRIC, timing.METRIC, final_pose.METRIC, log_lines.METRIC,
    )
}

__all__ = [
    "METRICS", "Commands", "Measurement", "Metric", "MetricError", "MetricParams", "OutputLine", "RunData",
    "RunInfo", "Trajectory", "TrajectoryParams",
]
