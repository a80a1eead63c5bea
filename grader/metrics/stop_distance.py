"""Stop distance: how far the obstacle ahead was when the robot came to rest (walls and pillars), from its front and
as its LiDAR read it straight ahead (what ``ranges[0]`` holds on a TurtleBot3)."""
from __future__ import annotations

import math

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.motion import path_length, rest_since
from grader.metrics.run import RunData
from sim.profile import Body, ProfileError, load_robot
from sim.scenario import Box, Cylinder

RAYS = 9  # parallel rays across the front edge: a pillar off the centre line still counts as ahead


class Params(TrajectoryParams):
    """Where the robot really was (ground truth) is what the distance is measured from."""

    min_travel: float = 0.05  # m: a robot that never moved has not "stopped" anywhere


def ray_distance(x: float, y: float, dx: float, dy: float, obstacle: Box | Cylinder) -> float:
    """How far along the unit direction (dx, dy) from (x, y) the ray meets ``obstacle``'s outline (inf: never)."""
    if isinstance(obstacle, Cylinder):
        ox, oy = x - obstacle.x, y - obstacle.y
        along = ox * dx + oy * dy
        gap = ox * ox + oy * oy - obstacle.radius ** 2
        if gap <= 0:
            return 0.0
        disc = along * along - gap
        return -along - math.sqrt(disc) if disc >= 0 and along < 0 else math.inf
    c, s = math.cos(obstacle.yaw), math.sin(obstacle.yaw)
    # the ray in the box's own frame, where it is the slab |u| <= length/2, |v| <= width/2
    u, v = c * (x - obstacle.x) + s * (y - obstacle.y), -s * (x - obstacle.x) + c * (y - obstacle.y)
    du, dv = c * dx + s * dy, -s * dx + c * dy
    near, far = 0.0, math.inf
    for p, d, half in ((u, du, obstacle.length / 2), (v, dv, obstacle.width / 2)):
        if d == 0:
            if abs(p) > half:
                return math.inf
            continue
        t1, t2 = sorted(((-half - p) / d, (half - p) / d))
        near, far = max(near, t1), min(far, t2)
    return near if near <= far else math.inf


def robot_body(run: RunData) -> Body:
    """The run's robot's collision box, which distances to obstacles are measured from."""
    try:
        body = load_robot(run.robot).geometry.body
    except ProfileError:
        body = None
    if body is None:
        raise MetricError(f"the robot {run.robot or '(not recorded)'} has no body outline to measure distances from")
    return body


def ahead(run: RunData, x: float, y: float, yaw: float) -> tuple[float, str]:
    """The free distance in front of a robot at (x, y, yaw), and what ends it: the shortest of parallel rays from
    points across the front edge of its body, straight ahead."""
    body = robot_body(run)
    dx, dy = math.cos(yaw), math.sin(yaw)
    best, what = math.inf, ""
    for i in range(RAYS):
        side = body.width * (i / (RAYS - 1) - 0.5)
        px, py = x + body.front * dx - side * dy, y + body.front * dy + side * dx
        for n, obstacle in enumerate(run.obstacles, start=1):
            d = ray_distance(px, py, dx, dy, obstacle)
            if d < best:
                best, what = d, obstacle.name or f"{obstacle.kind} {n}"
    return best, what


def scan_ahead(run: RunData, x: float, y: float, yaw: float) -> float:
    """What the robot's LiDAR reads straight ahead at (x, y, yaw): the ray from its mount along the heading (inf when
    the robot has no LiDAR or nothing is ahead)."""
    try:
        profile = load_robot(run.robot)
    except ProfileError:
        return math.inf
    scan = profile.modes[profile.default_mode].sensors.scan
    if scan is None:
        return math.inf
    dx, dy = math.cos(yaw), math.sin(yaw)
    mx, my = x + scan.mount[0] * dx - scan.mount[1] * dy, y + scan.mount[0] * dy + scan.mount[1] * dx
    return min((ray_distance(mx, my, dx, dy, obstacle) for obstacle in run.obstacles), default=math.inf)


def measure(run: RunData, params: Params) -> Measurement:
    """Where the robot came to rest at the end of the run, and the free distance ahead of its front there."""
    traj = run.trajectory(params.source)
    if len(traj) < 2:
        raise MetricError("the recording has no poses to locate the robot")
    if not run.obstacles:
        raise MetricError("this run had no walls or pillars to stop in front of")
    moved = path_length(traj) >= params.min_travel
    rest_from = rest_since(traj, params.rest_speed, params.rest_turn_rate) if moved else None
    at = -1 if rest_from is None else int(traj.t.searchsorted(rest_from))
    pose = float(traj.x[at]), float(traj.y[at]), float(traj.yaw[at])
    distance, obstacle = ahead(run, *pose)
    scanned = scan_ahead(run, *pose)
    return {
        "stop_distance": distance if rest_from is not None else math.nan,
        "distance_at_end": distance,
        "scan_distance": scanned if rest_from is not None else math.nan,
        "scan_at_end": scanned,
        "obstacle_ahead": obstacle,
        "moved": moved,
        "moving_at_end": moved and rest_from is None,
        "stopped_at_s": math.nan if rest_from is None else rest_from - run.start_time,
    }


METRIC = Metric(
    name="stop_distance",
    params=Params,
    quantities=frozenset({"stop_distance", "distance_at_end", "scan_distance", "scan_at_end", "obstacle_ahead", "moved",
                          "moving_at_end", "stopped_at_s"}),
    measure=measure,
)
