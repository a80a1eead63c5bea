"""Circle fit: radius, centre, residual and revolutions of a driven arc, plus the radius the commands imply."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from grader import exact
from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.motion import first_motion, path_length
from grader.metrics.run import Commands, RunData
from sim.scenario import TURTLESIM


@dataclass(frozen=True)
class CircleFit:
    """A fitted circle: centre (m), radius (m), RMS geometric residual (m), revolutions swept around the centre."""

    cx: float
    cy: float
    radius: float
    rms: float
    revolutions: float


def _algebraic(x: np.ndarray, y: np.ndarray, w: np.ndarray) -> tuple[float, float, float]:
    """Weighted Kasa fit (linear in a, b, c of x^2 + y^2 = a x + b y + c): a fast, unbiased-enough start."""
    sw = np.sqrt(w)
    a_mat = np.column_stack([x, y, np.ones_like(x)]) * sw[:, None]
    sol, *_ = np.linalg.lstsq(a_mat, (x * x + y * y) * sw, rcond=None)
    cx, cy = sol[0] / 2.0, sol[1] / 2.0
    return cx, cy, math.sqrt(max(sol[2] + cx * cx + cy * cy, 0.0))


def _huber_weights(residual: np.ndarray) -> np.ndarray:
    """Huber IRLS weights, scaled by the residuals' MAD, so a few outliers cannot drag the fit."""
    sigma = max(1.4826 * float(np.median(np.abs(residual - np.median(residual)))), 1e-4)
    k = 1.345 * sigma
    a = np.abs(residual)
    return np.where(a <= k, 1.0, k / np.maximum(a, 1e-300))


def fit_circle(x: np.ndarray, y: np.ndarray, iterations: int = 30) -> CircleFit:
    """Robust algebraic fit refined geometrically (Gauss-Newton on distance-to-circle with Huber weights)."""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    if len(x) < 5:
        raise MetricError("too few positions to fit a circle (need at least 5)")
    # Centre the data: keeps the normal equations well conditioned far from the origin.
    mx, my = exact.mean(x), exact.mean(y)
    u, v = x - mx, y - my
    w = np.ones_like(u)
    cx, cy, r = _algebraic(u, v, w)
    for _ in range(iterations):
        d = np.maximum(np.hypot(u - cx, v - cy), 1e-12)
        res = d - r
        w = _huber_weights(res)
        jac = np.column_stack([-(u - cx) / d, -(v - cy) / d, -np.ones_like(d)])
        sw = np.sqrt(w)
        step, *_ = np.linalg.lstsq(jac * sw[:, None], -res * sw, rcond=None)
        cx, cy, r = cx + step[0], cy + step[1], r + step[2]
        if float(np.max(np.abs(step))) < 1e-12:
            break
    if not all(math.isfinite(val) for val in (cx, cy, r)):
        raise MetricError("the path is not curved enough to fit a circle")
    d = np.hypot(u - cx, v - cy)
    angles = np.unwrap(exact.atan2(v - cy, u - cx))
    return CircleFit(
        cx=float(cx + mx), cy=float(cy + my), radius=float(abs(r)),
        rms=math.sqrt(exact.mean((d - abs(r)) ** 2)),
        revolutions=float(abs(angles[-1] - angles[0]) / (2.0 * math.pi)),
    )


def _median_command(commands: Commands, end: float) -> tuple[float, float]:
    """Median linear.x and angular.z over the node's non-zero commands before ``end``."""
    m = (commands.t <= end) & ~commands.is_zero()
    if not np.any(m):
        return math.nan, math.nan
    return float(np.median(commands.linear[m, 0])), float(np.median(commands.angular[m, 2]))


class Params(TrajectoryParams):
    """Circle fit settings."""

    settle_s: float = 1.0  # skip the first seconds of motion (acceleration)
    min_path: float = 0.2  # m of driving needed before a circle is meaningful
    target_radius: float | None = None  # the radius asked for: lets feedback say which omega would give it


def measure(run: RunData, params: Params) -> Measurement:
    """Fit a circle to the driven path (from first motion + settle time to Ctrl+C) and read the commands."""
    traj = run.trajectory(params.source)
    started = first_motion(traj, params.rest_speed, params.rest_turn_rate)
    end = run.shutdown_time() or math.inf
    window = traj.between((started or 0.0) + params.settle_s, end)
    driven = path_length(window)
    if started is None or driven < params.min_path:
        mover = "the turtle" if run.robot == TURTLESIM else "the robot"
        raise MetricError(f"{mover} drove only {path_length(traj):.2f} m, so there is no circle to measure")
    fit = fit_circle(window.x, window.y)
    v, w = _median_command(run.commands, end)
    return {
        "radius": fit.radius, "centre_x": fit.cx, "centre_y": fit.cy, "rms_residual": fit.rms,
        "revolutions": fit.revolutions, "arc_length": driven,
        "cmd_linear": v, "cmd_angular": w,
        "cmd_radius": abs(v / w) if w else math.inf,
        # How far the driven radius is from the one the commands ask for (v/ω), as a share of it.
        "radius_error_rel": abs(fit.radius - abs(v / w)) / abs(v / w) if v and w else math.inf,
        "swapped_radius": abs(w / v) if v else math.inf,
        "needed_angular": abs(v) / params.target_radius if params.target_radius else math.nan,
    }


METRIC = Metric(
    name="circle_fit",
    params=Params,
    quantities=frozenset({
        "radius", "centre_x", "centre_y", "rms_residual", "revolutions", "arc_length",
        "cmd_linear", "cmd_angular", "cmd_radius", "radius_error_rel", "swapped_radius", "needed_angular",
    }),
    measure=measure,
)
