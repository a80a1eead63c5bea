"""lidar_distance: printed readings (distance and angle of the nearest object ahead) against the scans the node had,
rebuilt from the world's geometry; lines with units or bare numbers; the rate."""
from __future__ import annotations

import math
from dataclasses import replace

import pytest
from scoring_synth import run

from grader.metrics.base import MetricError
from grader.metrics.lidar_distance import Params, beams_ahead, measure, nearest, reading
from grader.metrics.run import OutputLine
from sim.course import load_course_world
from sim.profile import load_robot

ARENA = load_course_world("arena").obstacles
SCAN = load_robot("turtlebot3_waffle").modes["gazebo"].sensors.scan
# at rest in the arena's south start, facing north: the north wall's face (y = 2.5) 3.5 m from the base frame
POSE = (0.3, -1.0, math.pi / 2)


def _at_rest(lines: list[tuple[float, str]], robot: str = "turtlebot3_waffle"):
    still = run([(10.0, 0.0, 0.0)], x0=POSE[0], y0=POSE[1], yaw0=POSE[2])
    return replace(still, obstacles=ARENA, robot=robot,
                   lines=tuple(OutputLine(t, "stdout", text) for t, text in lines))


def test_readings_with_and_without_units() -> None:
    assert reading("Closest object ahead: 1.23 m at -12.5 degrees") == (1.23, -12.5)
    assert reading("angle 7° distance 0.8m") == (0.8, 7.0)
    assert reading("1.5, 30") == (1.5, 30.0)
    assert reading("0.9 m away, -0.5 rad") == (0.9, pytest.approx(math.degrees(-0.5)))
    assert reading("no numbers here") is None and reading("only 2.0 m") is None


def test_the_nearest_object_ahead_from_the_geometry() -> None:
    distance, angle = nearest(beams_ahead(_at_rest([]), SCAN, POSE, math.radians(20)))
    # the LiDAR sits 0.064 m behind the base frame: the north wall 3.5 + 0.064 m straight ahead is beyond its 3.5 m
    # range, and nothing else is within 20°
    assert math.isinf(distance) and math.isnan(angle)
    # from the arena's centre facing east, 14° to the right the long box's corner is nearer than the east wall
    distance, angle = nearest(beams_ahead(_at_rest([]), SCAN, (0.0, 0.0, 0.0), math.radians(20)))
    assert distance < 1.8 and -20 <= angle < -10
    distance, angle = nearest(beams_ahead(_at_rest([]), SCAN, (0.0, 0.0, 0.0), math.radians(10)))
    assert distance == pytest.approx(2.5 + 0.064, abs=1e-9) and angle == pytest.approx(0.0, abs=1e-9)


def test_right_and_wrong_readings_and_the_rate() -> None:
    east = run([(10.0, 0.0, 0.0)])  # at the arena's centre facing east
    good = [(1.0 + 0.5 * k, f"{2.564 + 0.01 * (-1) ** k:.3f} m at 0.0 degrees") for k in range(12)]
    bad = [(7.0, "1.000 m at 0.0 degrees")]
    data = replace(east, obstacles=ARENA, robot="turtlebot3_waffle",
                   lines=tuple(OutputLine(t, "stdout", text) for t, text in good + bad))
    m = measure(data, Params(arc_deg=10))
    assert m["n_readings"] == 13 and m["distance_fraction"] == pytest.approx(12 / 13)
    assert m["angle_fraction"] == pytest.approx(12 / 13)
    assert m["first_wrong"] == "at 7.0 s the node printed 1 m at 0°; /scan read 2.56 m at 0°"
    assert m["rate_hz"] == pytest.approx(12 / 6.0) and m["max_gap_s"] == pytest.approx(0.5)


def test_a_reading_at_the_wrong_angle_is_a_right_distance_only() -> None:
    east = run([(10.0, 0.0, 0.0)])
    data = replace(east, obstacles=ARENA, robot="turtlebot3_waffle",
                   lines=(OutputLine(1.0, "stdout", "2.564 m at 30 degrees"),))
    m = measure(data, Params(arc_deg=10))
    assert (m["distance_fraction"], m["angle_fraction"]) == (1.0, 0.0)


def test_a_robot_without_lidar_is_named() -> None:
    with pytest.raises(MetricError, match="no LiDAR"):
        measure(_at_rest([(1.0, "1 m 0 degrees")], robot="turtlebot2"), Params())
