"""Timing of the motion: when the robot first moved, when it came to rest for good, and how long it moved."""
from __future__ import annotations

import math

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.motion import first_motion, path_length, rest_since
from grader.metrics.run import RunData


class Params(TrajectoryParams):
    """Timing settings: how long the robot must stand still at the end to count as at rest for good."""

    min_rest_s: float = 2.0


def measure(run: RunData, params: Params) -> Measurement:
    """Times are seconds after the node started; the motion is judged up to Ctrl+C, if the scenario sends one."""
    window = run.until_shutdown(params.source)
    if len(window) < 2:
        raise MetricError("the recording has no positions to time the motion")
    start = first_motion(window, params.rest_speed, params.rest_turn_rate)
    if start is None or path_length(window) < 0.01:
        raise MetricError("the robot never moved")
    rest_from = rest_since(window, params.rest_speed, params.rest_turn_rate)
    rest_s = math.nan if rest_from is None else float(window.t[-1] - rest_from)
    at_rest = rest_from is not None and rest_s >= params.min_rest_s
    stopped = rest_from if at_rest else None
    return {
        "first_motion_s": start - run.start_time,
        "rest_at_s": math.nan if stopped is None else stopped - run.start_time,
        "motion_s": math.nan if stopped is None else stopped - start,
        "moving_at_end": not at_rest,
        "rest_at_end_s": 0.0 if rest_from is None else rest_s,
        "observed_s": float(window.t[-1] - run.start_time),
        "interrupted": run.shutdown_time() is not None,
    }


METRIC = Metric(
    name="timing",
    params=Params,
    quantities=frozenset({
        "first_motion_s", "rest_at_s", "motion_s", "moving_at_end", "rest_at_end_s", "observed_s", "interrupted",
    }),
    measure=measure,
)
