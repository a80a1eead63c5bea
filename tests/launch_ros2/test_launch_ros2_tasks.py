"""A task started from a ROS 2 launch file ([launch] with a .launch.py): move_distance_launch's distance argument
reaches the node as an argument or as a parameter (a --params-file launch_ros writes) and scores full marks; a
launch file that hard-codes the distance loses exactly stop_position; recordings repeat bit for bit."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.grading import grade_task
from grader.rubric import load_rubric
from grader.report import TaskReport

pytestmark = pytest.mark.slow  # four graded runs of two scenarios each, about 20 s

ROOT = Path(__file__).resolve().parents[2]
SUBMISSIONS = Path(__file__).resolve().parent / "submissions"


@pytest.fixture(scope="module")
def rubric(tmp_path_factory: pytest.TempPathFactory):
    """move_distance_launch with the launch file named as a ROS 2 package names it."""
    folder = tmp_path_factory.mktemp("rubric")
    text = (ROOT / "rubrics" / "move_distance_launch.toml").read_text()
    (folder / "move_distance_launch.toml").write_text(
        text.replace('file = "move_turtlebot.launch"', 'file = "move_turtlebot.launch.py"'))
    return load_rubric(folder / "move_distance_launch.toml")


@pytest.fixture(scope="module")
def graded(rubric, tmp_path_factory: pytest.TempPathFactory) -> dict[str, TaskReport]:
    out = tmp_path_factory.mktemp("graded")
    return {name: grade_task(SUBMISSIONS / name, rubric, out / name)
            for name in ("launch_distance", "launch_distance_param", "launch_distance_hardcoded")}


def _lost(report: TaskReport) -> set[str]:
    assert report.status == "graded", report.message
    return {c.id for c in report.criteria if c.score < c.max_score}


@pytest.mark.parametrize("name", ["launch_distance", "launch_distance_param"])
def test_references_score_full_marks(graded: dict[str, TaskReport], name: str) -> None:
    assert _lost(graded[name]) == set()
    assert graded[name].score == graded[name].max_score


def test_text_of_a_node_without_output_screen_is_said_to_go_to_the_log(graded: dict[str, TaskReport]) -> None:
    assert any("its Node has no output='screen': ros2 launch sends that text to ~/.ros/log" in d
               for d in graded["launch_distance"].diagnostics)
    assert not any("output=" in d for d in graded["launch_distance_param"].diagnostics)


def test_hard_coded_distance_loses_exactly_stop_position(graded: dict[str, TaskReport]) -> None:
    report = graded["launch_distance_hardcoded"]
    assert _lost(report) == {"stop_position"}
    assert any("declares no argument distance" in d for d in report.diagnostics)


def test_recordings_repeat_bit_for_bit(rubric, graded: dict[str, TaskReport], tmp_path: Path) -> None:
    again = grade_task(SUBMISSIONS / "launch_distance_param", rubric, tmp_path)
    first = graded["launch_distance_param"]
    assert [Path(p).read_bytes() for p in again.recordings] == [Path(p).read_bytes() for p in first.recordings]
