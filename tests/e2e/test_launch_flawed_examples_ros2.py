"""The ROS 2 launch-file examples that `ros2 launch` itself refuses end with its error and the line to change, before
any run: a launch file CMakeLists.txt does not install, and a LaunchConfiguration that nothing declares or passes."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.grading import grade_task
from grader.rubric import load_rubrics

EXAMPLES = Path(__file__).resolve().parents[2] / "submissions_example"


@pytest.mark.parametrize(("student", "says"), [
    ("nia_ros2_launch_not_installed",
     ["file 'move_turtlebot.launch.py' was not found in the share directory of package 'move_distance_ros2' which is "
      "at '/rosgrade/install/move_distance_ros2/share/move_distance_ros2'",
      "add install(DIRECTORY launch DESTINATION share/${PROJECT_NAME}) to CMakeLists.txt"]),
    ("tomas_ros2_launch_undeclared",
     ["[ERROR] [launch]: Caught exception in launch (see debug for traceback): launch configuration 'speed' does not "
      "exist. ", "DeclareLaunchArgument('speed', default_value=...)"]),  # launch's text, then the fix
])
def test_a_launch_file_ros2_launch_refuses_is_reported_with_its_error(tmp_path: Path, student: str,
                                                                      says: list[str]) -> None:
    report = grade_task(EXAMPLES / student, load_rubrics()["move_distance_launch"], tmp_path)
    assert report.status == "error"
    assert report.score == 0 and not report.recordings
    for text in says:
        assert text in report.message, report.message
