"""Example instructor metric for rubrics/examples/spiral/spiral.toml: how a spiral's turning radius grows."""
from __future__ import annotations

import numpy as np

from grader.metrics import MetricError
from grader.metrics.plugin import metric


@metric(quantities=["radius_start", "radius_end", "growth", "turns"],
        params={"source": "ground_truth", "min_speed": 0.02})
def spiral_score(run, params):
    """Turning radius (speed / yaw rate) over the first and last quarter of the drive, and the turns made."""
    path = run.trajectory(params.source)
    dt = np.diff(path.t)
    speed = np.hypot(np.diff(path.x), np.diff(path.y)) / dt
    yaw_rate = np.abs(np.diff(np.unwrap(path.yaw))) / dt
    driving = (speed > params.min_speed) & (yaw_rate > 1e-3)
    if driving.sum() < 8:
        raise MetricError("the robot hardly drove, so there is no spiral to measure")
    radius = speed[driving] / yaw_rate[driving]
    quarter = len(radius) // 4
    start, end = float(np.median(radius[:quarter])), float(np.median(radius[-quarter:]))
    return {"radius_start": start, "radius_end": end, "growth": end - start,
            "turns": float(np.sum(yaw_rate[driving] * dt[driving]) / (2 * np.pi))}
