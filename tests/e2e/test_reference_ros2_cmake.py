"""The ROS 2 references in COM2009's ament_cmake template (nodes in scripts/ importing part2_navigation_modules)
score what their ament_python twin scores, with nothing for `colcon build` or `ros2 run` to trip over."""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from mcap.reader import make_reader

from grader.grading import grade_submission

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
CMAKE_TWIN = ROOT / "reference_solutions_ros2_cmake" / "part2_navigation"
PYTHON_TWIN = ROOT / "reference_solutions_ros2" / "part2_navigation"
TASKS = ("move_circle", "move_square", "odom_subscriber")


def _task(report, task):
    return next(t for t in report.tasks if t.id == task)


def test_the_cmake_package_is_found_as_the_three_tasks_and_its_launch_file(graded):
    # its launch/square_and_odom.launch.py is square_odom_launch (scored in test_reference_ros2_launch.py)
    assert sorted(t.id for t in graded(CMAKE_TWIN).tasks) == sorted((*TASKS, "square_odom_launch"))


@pytest.mark.parametrize("task", TASKS)
def test_cmake_twin_scores_what_the_ament_python_twin_scores(graded, task):
    cmake, python = _task(graded(CMAKE_TWIN), task), _task(graded(PYTHON_TWIN), task)
    assert cmake.status == "graded", cmake.message
    assert cmake.score == cmake.max_score == python.score
    assert [(c.id, c.score, c.measured) for c in cmake.criteria] == \
        [(c.id, c.score, c.measured) for c in python.criteria]


@pytest.mark.parametrize("task", TASKS)
def test_nothing_for_colcon_or_ros2_run_to_trip_over(graded, task):
    diagnostics = _task(graded(CMAKE_TWIN), task).diagnostics
    assert not [d for d in diagnostics if "ros2 run" in d or "colcon" in d or "Error" in d], diagnostics


def test_an_rclpy_script_that_does_not_parse_is_run_and_reported_as_rclpy(tmp_path):
    package = tmp_path / "submission" / "part2_navigation"
    shutil.copytree(CMAKE_TWIN, package)
    script = package / "scripts" / "move_circle.py"
    script.write_text(script.read_text().replace("        self.shutdown = True\n", "      self.shutdown = True\n", 1))
    report = grade_submission(tmp_path / "submission", tmp_path / "out", ["move_circle"])
    [task] = report.tasks
    with open(task.recordings[0], "rb") as stream:
        assert make_reader(stream).get_header().profile == "ros2"
    assert any("IndentationError" in d for d in task.diagnostics)
    assert not any("rospy.init_node" in d for d in task.diagnostics), task.diagnostics
