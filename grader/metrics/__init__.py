"""The metrics a rubric can name: each module measures one thing from a run's arrays."""
from __future__ import annotations

from grader.metrics import (
    action_client, action_goals, circle, clearance, collisions, coverage, exploration, final_pose, goal,
    goal_turning, lidar_distance, log_lines, loops, mimic, number_game, param_radius, polygon, pose_print,
    rotate_absolute, service_client, service_responses, shutdown, spawn_draw, square, stop, stop_distance, timing,
    turtle_rotation, turtle_stop, turtle_travel, velocity, wall_following, wall_hits,
)
from grader.metrics.base import Measurement, Metric, MetricError, MetricParams, TrajectoryParams
from grader.metrics.run import Commands, OutputLine, RunData, RunInfo, Trajectory

METRICS: dict[str, Metric] = {
    m.name: m for m in (
        circle.METRIC, square.METRIC, velocity.METRIC, shutdown.METRIC, pose_print.METRIC, stop.METRIC,
        loops.METRIC, timing.METRIC, final_pose.METRIC, log_lines.METRIC, turtle_travel.METRIC,
        turtle_rotation.METRIC, turtle_stop.METRIC, polygon.METRIC, goal.METRIC, goal_turning.METRIC, coverage.METRIC,
        wall_hits.METRIC,
        service_responses.METRIC, param_radius.METRIC, number_game.METRIC, service_client.METRIC,
        action_goals.METRIC, action_client.METRIC, collisions.METRIC, stop_distance.METRIC, clearance.METRIC,
        spawn_draw.METRIC, rotate_absolute.METRIC,
        exploration.METRIC, wall_following.METRIC, lidar_distance.METRIC, mimic.METRIC,
    )
}

__all__ = [
    "METRICS", "Commands", "Measurement", "Metric", "MetricError", "MetricParams", "OutputLine", "RunData",
    "RunInfo", "Trajectory", "TrajectoryParams",
]
