"""Clearance: how close the robot's body came to the walls and pillars along its path (minimum and percentiles)."""
from __future__ import annotations

import math

from pydantic import Field

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.run import RunData
from grader.metrics.stop_distance import robot_body
from sim.scenario import Box, Cylinder

Corners = list[tuple[float, float]]


class Params(TrajectoryParams):
    """Which percentile of the distances to report besides the minimum and the median."""

    percentile: float = Field(5.0, ge=0.0, le=100.0)


def _corners(cx: float, cy: float, yaw: float, half_l: float, half_w: float) -> Corners:
    c, s = math.cos(yaw), math.sin(yaw)
    return [(cx + c * u - s * v, cy + s * u + c * v) for u, v in
            ((half_l, half_w), (-half_l, half_w), (-half_l, -half_w), (half_l, -half_w))]


def _to_rectangle(px: float, py: float, cx: float, cy: float, yaw: float, half_l: float, half_w: float) -> float:
    """Distance from a point to a filled rectangle (0 inside)."""
    c, s = math.cos(yaw), math.sin(yaw)
    u, v = c * (px - cx) + s * (py - cy), -s * (px - cx) + c * (py - cy)
    return math.hypot(max(abs(u) - half_l, 0.0), max(abs(v) - half_w, 0.0))


def _separated(a: Corners, b: Corners) -> bool:
    """Whether some edge normal of either rectangle separates them (the separating axis test)."""
    for poly in (a, b):
        for (x1, y1), (x2, y2) in zip(poly, poly[1:] + poly[:1]):
            nx, ny = y2 - y1, x1 - x2
            pa = [nx * x + ny * y for x, y in a]
            pb = [nx * x + ny * y for x, y in b]
            if max(pa) < min(pb) or max(pb) < min(pa):
                return True
    return False


def gap(body: tuple[float, float, float, float, float], obstacle: Box | Cylinder) -> float:
    """The free distance between the robot's body (centre x, y, yaw, half length, half width) and an obstacle."""
    cx, cy, yaw, half_l, half_w = body
    if isinstance(obstacle, Cylinder):
        return max(_to_rectangle(obstacle.x, obstacle.y, *body) - obstacle.radius, 0.0)
    other = (obstacle.x, obstacle.y, obstacle.yaw, obstacle.length / 2, obstacle.width / 2)
    mine, theirs = _corners(*body), _corners(*other)
    if not _separated(mine, theirs):
        return 0.0
    # two disjoint convex polygons are closest at a corner of one of them
    return min([_to_rectangle(x, y, *other) for x, y in mine] + [_to_rectangle(x, y, *body) for x, y in theirs])


def _percentile(ordered: list[float], q: float) -> float:
    """The q-th percentile of sorted values, interpolated linearly between neighbours (numpy's default)."""
    k = (len(ordered) - 1) * q / 100.0
    low = math.floor(k)
    high = min(low + 1, len(ordered) - 1)
    return ordered[low] + (ordered[high] - ordered[low]) * (k - low)


def measure(run: RunData, params: Params) -> Measurement:
    """The body's distance to the nearest wall or pillar at each pose of the path."""
    traj = run.trajectory(params.source)
    if len(traj) == 0:
        raise MetricError("the recording has no poses to locate the robot")
    if not run.obstacles:
        raise MetricError("this run had no walls or pillars to keep clear of")
    b = robot_body(run)
    names = [o.name or f"{o.kind} {n}" for n, o in enumerate(run.obstacles, start=1)]
    nearest, which = [], []
    for x, y, yaw in zip(traj.x.tolist(), traj.y.tolist(), traj.yaw.tolist()):
        body = (x + b.x * math.cos(yaw), y + b.x * math.sin(yaw), yaw, b.length / 2, b.width / 2)
        gaps = [gap(body, obstacle) for obstacle in run.obstacles]
        closest = min(range(len(gaps)), key=gaps.__getitem__)
        nearest.append(gaps[closest])
        which.append(closest)
    at = min(range(len(nearest)), key=nearest.__getitem__)
    ordered = sorted(nearest)
    return {
        "min_clearance": nearest[at],
        "min_clearance_at_s": float(traj.t[at]) - run.start_time,
        "closest_obstacle": names[which[at]],
        "percentile_clearance": _percentile(ordered, params.percentile),
        "median_clearance": _percentile(ordered, 50.0),
    }


METRIC = Metric(
    name="clearance",
    params=Params,
    quantities=frozenset({"min_clearance", "min_clearance_at_s", "closest_obstacle", "percentile_clearance",
                          "median_clearance"}),
    measure=measure,
)
