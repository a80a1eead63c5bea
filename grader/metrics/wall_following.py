"""Wall following, scored as MIT RSS's wall follower tests score a run: the distance from the robot to the wall on
its followed side along the run, the loss (mean absolute error from the desired distance) and the score
1 / (alpha * loss + 1), which MIT gives only to a run that reached the end zone (0 otherwise).

The distance is measured from the ground truth and the world's geometry, not from a scan: from the robot's centre
to the nearest point of any wall or pillar on the followed side (lateral offset of that sign, within ``reach`` m).
"""
from __future__ import annotations

import math
from typing import Literal

from pydantic import Field

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.course_zones import zones
from grader.metrics.run import RunData
from sim.scenario import Box, Cylinder


# A robot this much nearer the wall on the other side is following that wall (the middle of a corridor is neither)
OTHER_SIDE_MARGIN = 0.1


class Params(TrajectoryParams):
    """The task's side and desired distance (as the node was told them), the score's alpha and the end zone."""

    side: Literal["left", "right"] = "left"
    desired_distance: float = Field(0.5, gt=0)
    alpha: float = Field(1.0, gt=0)  # per metre of loss: a 0.05 m loss scores 0.95
    end_zone: str = "end"
    reach: float = Field(2.0, gt=0)  # walls farther than this to the side are not the followed wall
    sample_period: float = Field(0.1, gt=0)  # seconds between the distances averaged (MIT: each scan)


def _nearest_point(px: float, py: float, obstacle: Box | Cylinder) -> tuple[float, float]:
    """The point of an obstacle's outline (or inside it) nearest to (px, py)."""
    if isinstance(obstacle, Cylinder):
        dx, dy = px - obstacle.x, py - obstacle.y
        norm = math.hypot(dx, dy)
        if norm <= obstacle.radius:
            return px, py
        return obstacle.x + dx * obstacle.radius / norm, obstacle.y + dy * obstacle.radius / norm
    c, s = math.cos(obstacle.yaw), math.sin(obstacle.yaw)
    u, v = c * (px - obstacle.x) + s * (py - obstacle.y), -s * (px - obstacle.x) + c * (py - obstacle.y)
    u = min(max(u, -obstacle.length / 2), obstacle.length / 2)
    v = min(max(v, -obstacle.width / 2), obstacle.width / 2)
    return obstacle.x + c * u - s * v, obstacle.y + s * u + c * v


def wall_distance(x: float, y: float, yaw: float, side: int, obstacles: tuple[Box | Cylinder, ...],
                  reach: float) -> float:
    """Distance from (x, y) to the nearest obstacle point on ``side`` (+1 left, -1 right); inf when none within
    ``reach``."""
    best = math.inf
    for obstacle in obstacles:
        qx, qy = _nearest_point(x, y, obstacle)
        lateral = -math.sin(yaw) * (qx - x) + math.cos(yaw) * (qy - y)
        if side * lateral > 0:
            best = min(best, math.hypot(qx - x, qy - y))
    return best if best <= reach else math.inf


def measure(run: RunData, params: Params) -> Measurement:
    """Distances to the followed wall every ``sample_period`` until the end zone is reached (or the run ends)."""
    traj = run.trajectory(params.source)
    if len(traj) == 0:
        raise MetricError("the recording has no poses to locate the robot")
    if not run.obstacles:
        raise MetricError("this run had no walls to follow")
    end = zones(run, [params.end_zone])[params.end_zone]
    side = 1 if params.side == "left" else -1
    distances: list[float] = []
    nearer_other_side = 0  # samples where the other side's wall was clearly the nearer: following the wrong wall
    reached_at = math.nan
    next_t = -math.inf
    for t, x, y, yaw in zip(traj.t.tolist(), traj.x.tolist(), traj.y.tolist(), traj.yaw.tolist()):
        if end.contains(x, y):
            reached_at = t - run.start_time
            break
        if t >= next_t:
            distances.append(wall_distance(x, y, yaw, side, run.obstacles, params.reach))
            other = wall_distance(x, y, yaw, -side, run.obstacles, params.reach)
            nearer_other_side += other + OTHER_SIDE_MARGIN < distances[-1]
            next_t = t + params.sample_period
    lost = sum(1 for d in distances if math.isinf(d))
    errors = [abs(d - params.desired_distance) if math.isfinite(d) else params.reach for d in distances]
    loss = sum(errors) / len(errors) if errors else math.nan
    finite = [d for d in distances if math.isfinite(d)]
    return {
        "loss": loss,
        "mit_score": 1.0 / (params.alpha * loss + 1.0) if errors and not math.isnan(reached_at) else 0.0,
        "mean_distance": (mean := sum(finite) / len(finite) if finite else math.nan),
        "mean_excess": mean - params.desired_distance,  # > 0: farther from the wall than asked
        "min_distance": min(finite, default=math.nan),
        "max_distance": max(finite, default=math.nan),
        "no_wall_fraction": lost / len(distances) if distances else math.nan,
        "other_side_fraction": nearer_other_side / len(distances) if distances else math.nan,
        "side": params.side,
        "desired_distance": params.desired_distance,
        "reached_end": not math.isnan(reached_at),
        "reached_end_at_s": reached_at,
    }


METRIC = Metric(
    name="wall_following",
    params=Params,
    quantities=frozenset({"loss", "mit_score", "mean_distance", "mean_excess", "min_distance", "max_distance",
                          "no_wall_fraction", "other_side_fraction", "side", "desired_distance", "reached_end",
                          "reached_end_at_s"}),
    measure=measure,
)
