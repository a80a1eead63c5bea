"""Stop distance: the free distance ahead of the robot's front where it came to rest, from the world's geometry."""
from __future__ import annotations

import math
from dataclasses import replace

import pytest
from scoring_synth import run

from grader.metrics.base import MetricError
from grader.metrics.stop_distance import Params, measure, ray_distance
from sim.scenario import Box, Cylinder

END_WALL = Box(kind="box", name="end wall", x=4.05, y=0.0, length=0.1, width=1.4)
FRONT = 0.069  # the Waffle's body reaches this far ahead of its base frame


def _stopped_at(x: float, obstacles: tuple, segments=None, yaw0: float = 0.0):
    data = run(segments or [(x / 0.2, 0.2, 0.0), (5.0, 0.0, 0.0)], yaw0=yaw0)
    return replace(data, obstacles=obstacles, robot="turtlebot3_waffle")


def test_the_front_is_measured_to_the_wall_ahead() -> None:
    m = measure(_stopped_at(3.431, (END_WALL,)), Params())
    assert m["stop_distance"] == pytest.approx(4.0 - 3.431 - FRONT, abs=1e-3) and m["obstacle_ahead"] == "end wall"
    assert m["moving_at_end"] is False and m["stopped_at_s"] == pytest.approx(3.431 / 0.2, abs=0.05)


def test_the_scan_reads_the_wall_from_the_lidar_behind_the_front() -> None:
    m = measure(_stopped_at(3.431, (END_WALL,)), Params())
    # The Waffle's LiDAR sits 0.064 m behind its base frame: /scan reads 0.133 m more than the front's gap.
    assert m["scan_distance"] == pytest.approx(4.0 - 3.431 + 0.064, abs=1e-3)
    assert m["scan_distance"] - m["stop_distance"] == pytest.approx(FRONT + 0.064, abs=1e-9)


def test_a_pillar_off_the_centre_line_but_in_the_robots_way_is_ahead() -> None:
    pillar = Cylinder(kind="cylinder", x=2.0, y=0.1, radius=0.05)  # misses the centre line, not the 0.266 m body
    m = measure(_stopped_at(1.0, (END_WALL, pillar)), Params())
    assert m["obstacle_ahead"] == "cylinder 2" and m["stop_distance"] < 1.0 - FRONT


def test_a_robot_still_moving_has_no_stop_distance() -> None:
    m = measure(_stopped_at(0.0, (END_WALL,), segments=[(10.0, 0.2, 0.0)]), Params())
    assert math.isnan(m["stop_distance"]) and m["moving_at_end"] is True and m["distance_at_end"] < 2.0


def test_no_obstacle_is_nothing_to_measure() -> None:
    with pytest.raises(MetricError, match="no walls or pillars"):
        measure(_stopped_at(1.0, ()), Params())


def test_rays_meet_boxes_and_cylinders_at_their_outline() -> None:
    turned = Box(kind="box", x=2.0, y=0.0, yaw=math.pi / 4, length=1.0, width=1.0)
    assert ray_distance(0.0, 0.0, 1.0, 0.0, turned) == pytest.approx(2.0 - math.sqrt(0.5))  # its corner first
    assert ray_distance(0.0, 0.0, 1.0, 0.0, Cylinder(kind="cylinder", x=2.0, y=0.0, radius=0.5)) == 1.5
    assert ray_distance(0.0, 0.0, -1.0, 0.0, Cylinder(kind="cylinder", x=2.0, y=0.0, radius=0.5)) == math.inf
    assert ray_distance(0.0, 0.0, 0.0, 1.0, END_WALL) == math.inf
