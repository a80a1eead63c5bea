"""Exploration: which zones of the course world the robot reached and when, and how many floor cells it entered
(COM2009 Assignment 2 Task 2 marks an arena run by the zones the robot reached in its 90 s)."""
from __future__ import annotations

import math

from pydantic import Field

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.course_zones import zones
from grader.metrics.run import RunData


class Params(TrajectoryParams):
    """Which zones count (None: all of the world's), until when (seconds after the start; None: the whole run), and
    the side of the floor cells counted as visited."""

    zones: list[str] | None = None
    until_s: float | None = Field(None, gt=0)
    cell_size: float = Field(0.5, gt=0)


def measure(run: RunData, params: Params) -> Measurement:
    """The first time the robot's centre was inside each zone, and the cells of the floor its centre crossed."""
    traj = run.trajectory(params.source)
    if len(traj) == 0:
        raise MetricError("the recording has no poses to locate the robot")
    targets = zones(run, params.zones)
    if params.until_s is not None:
        traj = traj.between(end=run.start_time + params.until_s)
    reached: dict[str, float] = {}
    cells: set[tuple[int, int]] = set()
    for t, x, y in zip(traj.t.tolist(), traj.x.tolist(), traj.y.tolist()):
        cells.add((math.floor(x / params.cell_size), math.floor(y / params.cell_size)))
        for name, zone in targets.items():
            if name not in reached and zone.contains(x, y):
                reached[name] = t - run.start_time
    missed = [name for name in targets if name not in reached]
    return {
        "zones_reached": len(reached),
        "n_zones": len(targets),
        "zone_fraction": len(reached) / len(targets) if targets else math.nan,
        "zone_times": ", ".join(f"{name} {at:.1f} s" for name, at in sorted(reached.items(), key=lambda kv: kv[1])),
        "zones_missed": ", ".join(missed),
        "last_zone_at_s": max(reached.values()) if reached else math.nan,
        "cells_visited": len(cells),
    }


METRIC = Metric(
    name="exploration",
    params=Params,
    quantities=frozenset({"zones_reached", "n_zones", "zone_fraction", "zone_times", "zones_missed",
                          "last_zone_at_s", "cells_visited"}),
    measure=measure,
)
