"""A polygon drawn by driving straight and turning on the spot: its sides, the turns between them, and closure.

A side is a stretch of driving (speed above ``rest_speed``) at least ``min_side`` long, measured start to end; the
turn between two sides is the change of their driving direction, so it is the exterior angle (120 degrees for an
equilateral triangle). Only the first ``sides`` sides count; closure is how far the last of them ends from where the
first began.
"""
from __future__ import annotations

import math

import numpy as np

from grader import exact
from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.motion import speeds, wrap
from grader.metrics.run import RunData, Trajectory


class Params(TrajectoryParams):
    """The polygon asked for."""

    sides: int = 3
    turn_deg: float = 120.0  # exterior angle between consecutive sides
    min_side: float = 0.1  # m: shorter stretches of driving are not sides


def straight_runs(traj: Trajectory, rest_speed: float, min_side: float) -> list[tuple[int, int]]:
    """(first, last) sample indices of each stretch of driving at least ``min_side`` long, in order."""
    driving = speeds(traj)[0] > rest_speed
    runs, start = [], None
    for i, d in enumerate(np.append(driving, False)):
        if d and start is None:
            start = i
        elif not d and start is not None:
            if math.hypot(traj.x[i] - traj.x[start], traj.y[i] - traj.y[start]) >= min_side:
                runs.append((start, i))
            start = None
    return runs


def measure(run: RunData, params: Params) -> Measurement:
    """Side lengths and their spread, the exterior turns and their worst error, and the closure."""
    traj = run.trajectory(params.source)
    runs = straight_runs(traj, params.rest_speed, params.min_side)
    if len(runs) < params.sides:
        raise MetricError(f"the turtle drove {len(runs)} straight sides; the shape has {params.sides} (stop and "
                          "turn on the spot between sides)")
    runs = runs[:params.sides]
    lengths = np.array([math.hypot(traj.x[b] - traj.x[a], traj.y[b] - traj.y[a]) for a, b in runs])
    headings = np.array([math.atan2(traj.y[b] - traj.y[a], traj.x[b] - traj.x[a]) for a, b in runs])
    turns = np.degrees(np.abs(wrap(np.diff(headings))))
    mean = exact.mean(lengths)
    closure = math.hypot(traj.x[runs[-1][1]] - traj.x[runs[0][0]], traj.y[runs[-1][1]] - traj.y[runs[0][0]])
    return {
        "n_sides": len(runs),
        "side_mean": mean, "side_min": float(lengths.min()), "side_max": float(lengths.max()),
        "side_spread_rel": float(lengths.max() - lengths.min()) / mean,
        "turn_mean_deg": exact.mean(turns),
        "turn_worst_error_deg": float(np.max(np.abs(turns - params.turn_deg))),
        "turn_deg": params.turn_deg,
        "closure": closure,
        "closure_rel": closure / mean,
    }


METRIC = Metric(
    name="polygon",
    params=Params,
    quantities=frozenset({"n_sides", "side_mean", "side_min", "side_max", "side_spread_rel", "turn_mean_deg",
                          "turn_worst_error_deg", "turn_deg", "closure", "closure_rel"}),
    measure=measure,
)
