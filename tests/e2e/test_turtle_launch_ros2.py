"""turtle_launch on ROS 2 launch files: the ament_python reference's teleopturtlesim4.launch.py (IfCondition/
UnlessCondition on a teleop argument) runs Jazzy's turtle_teleop_key as the grader's node, with the arrow keys typed
on its stdin, and scores full marks, as does the same launch file written in XML; a recording repeats bit for bit."""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from grader.grading import grade_task
from grader.recording import Recording
from grader.rubric import load_rubrics

pytestmark = pytest.mark.slow  # three gradings of four 5 s scenarios, about 25 s on 2 cores

ROOT = Path(__file__).resolve().parents[2]
REFERENCE = ROOT / "reference_solutions_turtlesim_ros2" / "lab2_turtlesim"
XML = """<launch>
  <arg name="teleop" default="0"/>
  <node pkg="turtlesim" exec="turtlesim_node" name="turtlesim"/>
  <node pkg="turtlesim" exec="turtle_teleop_key" name="teleop_key" output="screen" if="$(var teleop)"/>
  <node pkg="lab2_turtlesim" exec="pubvel" name="pubvel" unless="$(var teleop)"/>
</launch>
"""


@pytest.fixture(scope="module")
def reference(tmp_path_factory: pytest.TempPathFactory):
    return grade_task(REFERENCE, load_rubrics()["turtle_launch"], tmp_path_factory.mktemp("reference"))


def _full_marks(report) -> None:
    assert report.status == "graded", report.message
    assert {c.id: c.feedback for c in report.criteria if c.score < c.max_score} == {}
    assert report.score == report.max_score == 8
    assert not [d for d in report.diagnostics if "never" in d or "not run" in d or "Error" in d], report.diagnostics


def test_the_ros2_reference_scores_full_marks_through_the_graders_teleop(reference) -> None:
    _full_marks(reference)
    # turtle1 was driven by the node the launch file names teleop_key: the grader's Jazzy teleop, keys from stdin
    drivers = {topic.callerid for recording in reference.recordings for topic in Recording.open(recording).topics()
               if topic.topic == "/turtle1/cmd_vel"}
    assert drivers == {"/teleop_key"}, drivers


def test_the_same_launch_file_in_xml_scores_full_marks(tmp_path: Path) -> None:
    package = tmp_path / "src" / "lab2_turtlesim"
    shutil.copytree(REFERENCE, package, ignore=shutil.ignore_patterns("__pycache__"))
    (package / "launch" / "teleopturtlesim4.launch.py").unlink()
    (package / "launch" / "teleopturtlesim4.launch.xml").write_text(XML)
    _full_marks(grade_task(tmp_path / "src", load_rubrics()["turtle_launch"], tmp_path / "out"))


def test_a_ros2_turtle_launch_recording_repeats_bit_for_bit(reference, tmp_path: Path) -> None:
    again = grade_task(REFERENCE, load_rubrics()["turtle_launch"], tmp_path)
    assert [Path(p).read_bytes() for p in again.recordings] == [Path(p).read_bytes() for p in reference.recordings]
