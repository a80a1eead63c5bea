"""The ROS 2 launch-started tasks' references, found by `rosgrade check` as a course's packages hold them, score full
marks: an ament_python package whose setup.py data_files installs move_turtlebot.launch.py (move_distance_launch, and
move_distance from the same node's defaults), COM2009's ament_cmake part2_navigation with launch/ installed by
install(DIRECTORY) (square_odom_launch), and a COM2009 team package whose task1.launch.py starts the figure of eight;
a recording repeats bit for bit."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.grading import grade_task
from grader.rubric import load_rubrics

pytestmark = pytest.mark.slow  # three packages, four launch-started tasks: about a minute on 2 cores

ROOT = Path(__file__).resolve().parents[2]
PACKAGES = {"turtlebot_launch": ROOT / "reference_solutions_ros2" / "turtlebot_launch",
            "part2_navigation": ROOT / "reference_solutions_ros2_cmake" / "part2_navigation",
            "com2009_team1": ROOT / "reference_solutions_ros2_cmake" / "com2009_team1"}
LAUNCHED = {"turtlebot_launch": {"move_distance_launch", "move_distance"},
            "part2_navigation": {"square_odom_launch"},
            "com2009_team1": {"figure_of_eight"}}


def _task(report, task):
    return next(t for t in report.tasks if t.id == task)


@pytest.mark.parametrize("package", sorted(LAUNCHED))
def test_the_launch_started_tasks_are_found(graded, package: str) -> None:
    assert LAUNCHED[package] <= {t.id for t in graded(PACKAGES[package]).tasks}


@pytest.mark.parametrize(("package", "task"), sorted((p, t) for p, tasks in LAUNCHED.items() for t in tasks))
def test_references_score_full_marks(graded, package: str, task: str) -> None:
    result = _task(graded(PACKAGES[package]), task)
    assert result.status == "graded", result.message
    assert {c.id: c.feedback for c in result.criteria if c.score < c.max_score} == {}
    assert not [d for d in result.diagnostics if "Error" in d or "never" in d or "not installed" in d], \
        result.diagnostics


def test_a_launch_started_recording_repeats_bit_for_bit(graded, tmp_path: Path) -> None:
    first = _task(graded(PACKAGES["turtlebot_launch"]), "move_distance_launch")
    again = grade_task(PACKAGES["turtlebot_launch"], load_rubrics()["move_distance_launch"], tmp_path)
    assert [Path(p).read_bytes() for p in again.recordings] == [Path(p).read_bytes() for p in first.recordings]
