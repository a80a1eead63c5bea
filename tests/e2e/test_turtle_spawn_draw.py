"""turtle_spawn_draw: the ROS 2 reference (rclpy: /spawn, both turtles' set_pen, a 2 m square each; its full marks are
checked with the package's other tasks in test_reference_turtlesim_ros2.py) has its figures measured on the picture
redrawn from the recording."""
from __future__ import annotations

from pathlib import Path

import pytest

pytestmark = pytest.mark.slow

PACKAGE = Path(__file__).resolve().parents[2] / "reference_solutions_turtlesim_ros2" / "turtlesim_tutorials"


@pytest.fixture(scope="module")
def result(graded):
    report = graded(PACKAGE)  # graded once with test_reference_turtlesim_ros2.py's run (the conftest caches it)
    return next(t for t in report.tasks if t.id == "turtle_spawn_draw")


def test_the_squares_are_measured_on_the_picture(result):
    figure = next(c for c in result.criteria if c.id == "figure")
    assert figure.measured["figure_error_rel"] < 0.02  # 2.02 m where 2 m was asked: 91 px of 90
    assert 1.0 <= figure.measured["ink_ratio"] < 1.1 and figure.measured["figures_missing"] == 0
