"""Clearance: the body's distance to the nearest wall or pillar along the path, from the world's geometry."""
from __future__ import annotations

import math
from dataclasses import replace

import pytest
from scoring_synth import run

from grader.metrics.base import MetricError
from grader.metrics.clearance import Params, gap, measure
from sim.scenario import Box, Cylinder

WALL = Box(kind="box", name="end wall", x=4.05, y=0.0, length=0.1, width=1.4)
PILLAR = Cylinder(kind="cylinder", x=1.0, y=0.8, radius=0.1)
FRONT, HALF_WIDTH = 0.069, 0.133  # the Waffle's body: front 0.069 m ahead of the base frame, 0.266 m wide


def _drive(seconds: float, obstacles: tuple):
    return replace(run([(seconds, 0.2, 0.0), (2.0, 0.0, 0.0)]), obstacles=obstacles, robot="turtlebot3_waffle")


def test_passing_a_pillar_and_stopping_short_of_the_wall() -> None:
    m = measure(_drive(17.0, (WALL, PILLAR)), Params())  # 3.4 m: the front ends 0.531 m from the wall
    # abeam of the pillar its side is 0.8 - 0.1 - 0.133 = 0.567 m away; the wall comes closer at the end
    assert m["min_clearance"] == pytest.approx(4.0 - 3.4 - FRONT, abs=1e-3) and m["closest_obstacle"] == "end wall"
    assert m["median_clearance"] > m["percentile_clearance"] >= m["min_clearance"]
    assert m["min_clearance_at_s"] == pytest.approx(17.0, abs=0.05)


def test_gap_between_the_body_and_each_shape() -> None:
    body = (0.0, 0.0, 0.0, 0.133, 0.133)
    assert gap(body, Cylinder(kind="cylinder", x=1.0, y=0.0, radius=0.1)) == pytest.approx(1.0 - 0.133 - 0.1)
    assert gap(body, Box(kind="box", x=0.0, y=1.0, length=2.0, width=0.2)) == pytest.approx(1.0 - 0.1 - 0.133)
    turned = Box(kind="box", x=1.0, y=1.0, yaw=math.pi / 4, length=0.2, width=0.2)  # an edge faces the body's corner
    assert gap(body, turned) == pytest.approx(math.hypot(1.0 - 0.133, 1.0 - 0.133) - 0.1)
    across = Box(kind="box", x=0.0, y=0.0, length=3.0, width=0.05)  # through the body, no corner inside either
    assert gap(body, across) == 0.0


def test_no_obstacle_is_nothing_to_measure() -> None:
    with pytest.raises(MetricError, match="no walls or pillars"):
        measure(_drive(1.0, ()), Params())
