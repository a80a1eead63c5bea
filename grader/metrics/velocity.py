"""Velocity compliance: check every command the node published against the robot's limits and its 2-D base."""
from __future__ import annotations

import math

import numpy as np

from grader.metrics.base import Measurement, Metric, MetricParams
from grader.metrics.run import RunData


class Params(MetricParams):
    """The limits: |linear.x| <= max_linear (m/s), |angular.z| <= max_angular (rad/s), other components zero."""

    max_linear: float
    max_angular: float
    slack: float = 1e-9  # absolute; a value printed as the limit must not fail by float rounding


def measure(run: RunData, params: Params) -> Measurement:
    """Count the messages that break a limit, are not finite, or ask for motion a differential drive cannot make."""
    cmd = run.commands
    components = np.hstack([cmd.linear, cmd.angular]) if len(cmd) else np.zeros((0, 6))
    finite = np.all(np.isfinite(components), axis=1)
    vx = np.abs(np.where(finite, cmd.linear[:, 0], 0.0))
    wz = np.abs(np.where(finite, cmd.angular[:, 2], 0.0))
    over_linear = vx > params.max_linear + params.slack
    over_angular = wz > params.max_angular + params.slack
    off_axis = finite & np.any(components[:, [1, 2, 3, 4]] != 0.0, axis=1)
    bad = over_linear | over_angular | ~finite | off_axis
    n = len(cmd)
    first_bad = float(cmd.t[np.argmax(bad)] - run.start_time) if np.any(bad) else math.nan
    # No command at all is nothing to count, not "0 of 0 commands over the limits": NaN, as the fastest command.
    return {
        "n_messages": n,
        "n_violations": int(np.sum(bad)) if n else math.nan,
        "violating_fraction": float(np.mean(bad)) if n else math.nan,
        "n_over_linear": int(np.sum(over_linear)),
        "n_over_angular": int(np.sum(over_angular)),
        "n_nonfinite": int(np.sum(~finite)),
        "n_off_axis": int(np.sum(off_axis)),
        "max_linear": float(np.max(vx)) if n else math.nan,
        "max_angular": float(np.max(wz)) if n else math.nan,
        "first_violation_s": first_bad,
        "limit_linear": params.max_linear,
        "limit_angular": params.max_angular,
    }


METRIC = Metric(
    name="velocity_compliance",
    params=Params,
    quantities=frozenset({
        "n_messages", "n_violations", "violating_fraction", "n_over_linear", "n_over_angular", "n_nonfinite",
        "n_off_axis", "max_linear", "max_angular", "first_violation_s", "limit_linear", "limit_angular",
    }),
    measure=measure,
)
