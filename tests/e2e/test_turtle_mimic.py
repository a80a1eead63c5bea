"""turtle_mimic, the launch tutorials' two turtlesims and mimic, in ROS 2: the reference's turtlesim_mimic_launch.py
(and the same launch file in XML) runs two turtlesim windows, the grader's `ros2 topic pub` on
/turtlesim1/turtle1/cmd_vel reaches the first through its bridge, Jazzy's mimic drives the second under its own
names, and it scores full marks; a recording repeats bit for bit. (The rospy reference is graded with the rest of
reference_solutions_turtlesim in test_reference_solutions.)"""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from grader.grading import grade_task
from grader.metrics.pen import redraw, window_run
from grader.metrics.run import RunData
from grader.recording import Recording
from grader.rubric import load_rubrics

pytestmark = pytest.mark.slow  # two gradings of two 8 s scenarios, about 10 s on 2 cores

ROOT = Path(__file__).resolve().parents[2]
REFERENCE = ROOT / "reference_solutions_turtlesim_ros2" / "lab2_turtlesim"
XML = """<launch>
  <node pkg="turtlesim" exec="turtlesim_node" name="sim" namespace="turtlesim1"/>
  <node pkg="turtlesim" exec="turtlesim_node" name="sim" namespace="turtlesim2">
    <param name="background_r" value="200"/>
  </node>
  <node pkg="turtlesim" exec="mimic" name="mimic">
    <remap from="/input/pose" to="/turtlesim1/turtle1/pose"/>
    <remap from="/output/cmd_vel" to="/turtlesim2/turtle1/cmd_vel"/>
  </node>
</launch>
"""


@pytest.fixture(scope="module")
def reference(tmp_path_factory: pytest.TempPathFactory):
    return grade_task(REFERENCE, load_rubrics()["turtle_mimic"], tmp_path_factory.mktemp("reference"))


def _full_marks(report) -> None:
    assert report.status == "graded", report.message
    assert {c.id: c.feedback for c in report.criteria if c.score < c.max_score} == {}
    assert report.score == report.max_score == 10


def test_the_ros2_reference_scores_full_marks_with_two_windows(reference) -> None:
    _full_marks(reference)
    recording = Recording.open(next(p for p in reference.recordings if Path(p).stem == "tutorial"))
    by_topic = {topic.topic: topic.callerid for topic in recording.topics()}
    # the first window under turtlesim's own names, the second under its node's; mimic drives the second
    assert by_topic["/turtle1/pose"] == "/turtlesim"
    assert by_topic["/turtlesim2/turtle1/pose"] == "/turtlesim2/sim"
    assert by_topic["/turtlesim2/turtle1/cmd_vel"] == "/mimic"
    assert by_topic["/turtle1/cmd_vel"] == "/rosgrade"  # the grader's ros2 topic pub, bridged from turtlesim1's name


def test_the_same_launch_file_in_xml_scores_full_marks_and_each_window_is_drawn(tmp_path: Path) -> None:
    package = tmp_path / "src" / "lab2_turtlesim"
    shutil.copytree(REFERENCE, package, ignore=shutil.ignore_patterns("__pycache__"))
    (package / "launch" / "turtlesim_mimic_launch.py").unlink()
    (package / "launch" / "turtlesim_mimic_launch.xml").write_text(XML)
    report = grade_task(tmp_path / "src", load_rubrics()["turtle_mimic"], tmp_path / "out")
    _full_marks(report)
    run = RunData.from_recording(Recording.open(report.recordings[0]))
    assert run.windows == ("/turtlesim2/sim",) and set(run.window_poses) == {"/turtlesim2/turtle1/pose"}
    first, second = redraw(run), redraw(window_run(run, "/turtlesim2/sim"), node="/turtlesim2/sim")
    # each window's own background (the launch file gives turtlesim2's background_r), and its own pen line
    assert tuple(first.canvas.pixels[2, 2]) == (69, 86, 255) and tuple(second.canvas.pixels[2, 2]) == (200, 86, 255)
    assert second.canvas.inked.sum() > 0.8 * first.canvas.inked.sum() > 0


def test_a_two_window_recording_repeats_bit_for_bit(reference, tmp_path: Path) -> None:
    again = grade_task(REFERENCE, load_rubrics()["turtle_mimic"], tmp_path)
    assert [Path(p).read_bytes() for p in again.recordings] == [Path(p).read_bytes() for p in reference.recordings]
