"""Two turtlesim windows and mimic (the roslaunch and ROS 2 launch tutorials): how far the first window's turtle drove
under the grader's commands, and how closely the other window's turtle1 followed it.

mimic drives its output turtle with the velocities of each pose its input turtle publishes, so the follower draws
the leader's path one or two 16 ms updates late: at 2 m/s a few centimetres behind. A follower that never moved, or
a leader that never moved (nothing reached it), follows nothing, whatever the gap.
"""
from __future__ import annotations

import math
import re

import numpy as np
from pydantic import Field

from grader.metrics.base import Measurement, Metric, MetricError, MetricParams
from grader.metrics.motion import path_length
from grader.metrics.run import RunData, Trajectory

# A further window's first turtle: /<its namespace>/turtle1/pose
_TURTLE1 = re.compile(r"^(/[^/]+)+/turtle1/pose$")


class Params(MetricParams):
    """Which turtle leads (the first window's turtle1) and how far it must drive for the follower to be judged."""

    leader: str = "/turtle1/pose"
    min_travel: float = Field(0.5, gt=0.0)  # m the leader must drive before following means anything


def _gap(leader: Trajectory, follower: Trajectory) -> float:
    """The largest distance between the two turtles at the follower's poses (the leader's interpolated)."""
    x = np.interp(follower.t, leader.t, leader.x)
    y = np.interp(follower.t, leader.t, leader.y)
    return float(np.max(np.hypot(follower.x - x, follower.y - y)))


def measure(run: RunData, params: Params) -> Measurement:
    """The windows the run had, each turtle's travel, and the follower's largest gap from the leader."""
    leader = run.poses.get(params.leader)
    if leader is None or len(leader) < 2:
        raise MetricError(f"the recording holds no pose of the first window's turtle ({params.leader})")
    others = sorted(topic for topic in run.window_poses if _TURTLE1.match(topic))
    travelled = path_length(leader)
    follower_travelled = max((path_length(run.window_poses[topic]) for topic in others), default=0.0)
    # The follower is the other window's turtle1 that drove furthest (the first of them when none did).
    follower = max(others, key=lambda topic: path_length(run.window_poses[topic]), default="")
    gap = _gap(leader, run.window_poses[follower]) if follower and len(run.window_poses[follower]) else math.inf
    follows = travelled >= params.min_travel and follower_travelled >= params.min_travel
    return {
        "windows": 1 + len(others),
        "leader_travelled": travelled,
        "follower": follower or "none",
        "follower_travelled": follower_travelled,
        "max_gap": gap if follows else math.inf,
        "follows": follows,
    }


METRIC = Metric(
    name="mimic",
    params=Params,
    quantities=frozenset({"windows", "leader_travelled", "follower", "follower_travelled", "max_gap", "follows"}),
    measure=measure,
)
