"""The turtlesim exercises graded on rclpy nodes: the ROS 2 (Jazzy) reference package earns full marks on the same
rubrics and criterion ids as the rospy references, its Twist commands drive the turtle (turtlesim takes Twist in ROS 2
too, not the Jazzy TurtleBot3's TwistStamped), and its recordings are ROS 2 MCAP with turtlesim's schemas that re-score
to exactly the live result and repeat bit for bit."""
from __future__ import annotations

from pathlib import Path

import pytest
from mcap.reader import make_reader

from grader.grading import grade_submission
from grader.recording import Recording
from grader.rubric import load_rubrics
from grader.scoring import score_task

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "reference_solutions_turtlesim_ros2" / "turtlesim_tutorials"
TASKS = ("turtle_circle", "turtle_clean", "turtle_goal", "turtle_move", "turtle_rotate", "turtle_rotate_absolute",
         "turtle_spawn_draw", "turtle_triangle")


@pytest.fixture(scope="module")
def report(graded):
    return graded(PACKAGE)


def _task(report, task):
    return next(t for t in report.tasks if t.id == task)


def test_the_package_is_found_as_the_eight_tasks(report):
    assert sorted(t.id for t in report.tasks) == sorted(TASKS)


@pytest.mark.parametrize("task", TASKS)
def test_ros2_turtlesim_reference_scores_full_marks(report, task):
    result = _task(report, task)
    assert result.status == "graded", result.message
    assert {c.id: c.feedback for c in result.criteria if c.score < c.max_score} == {}
    assert result.score == result.max_score > 0
    assert not [d for d in result.diagnostics if "uncaught" in d or "never" in d or "ignores" in d], \
        result.diagnostics


@pytest.mark.parametrize("task", TASKS)
def test_recordings_are_ros2_mcap_with_turtlesim_schemas_and_rescore_identically(report, task):
    live = _task(report, task)
    for path in live.recordings:
        with open(path, "rb") as stream:
            summary = make_reader(stream).get_summary()
        schemas = {s.name: s.encoding for s in summary.schemas.values()}
        assert schemas["turtlesim/msg/Pose"] == "ros2msg"
        assert schemas["geometry_msgs/msg/Twist"] == "ros2msg" or task == "turtle_spawn_draw"
        assert "geometry_msgs/msg/TwistStamped" not in schemas
        assert {c.message_encoding for c in summary.channels.values()} == {"cdr"}
    recordings = {Path(p).stem: Recording.open(p) for p in live.recordings}
    again = score_task(load_rubrics()[task], recordings)
    assert [c.model_dump() for c in again.criteria] == [c.model_dump() for c in live.criteria]


def test_ros2_turtlesim_recording_repeats_bit_for_bit(report, tmp_path):
    first = Path(next(p for p in _task(report, "turtle_goal").recordings if Path(p).stem == "nominal"))
    again = grade_submission(PACKAGE / "turtlesim_tutorials" / "go_to_goal.py", tmp_path, ["turtle_goal"])
    second = Path(next(p for p in again.tasks[0].recordings if Path(p).stem == "nominal"))
    assert first.read_bytes() == second.read_bytes()


def test_the_foxglove_hint_plots_the_turtles_pose_not_odom(report):
    from grader.reports.text import foxglove_help

    plot = foxglove_help(_task(report, "turtle_circle").recordings[0])[1]
    assert "/turtle1/pose.x" in plot and "/odom" not in plot and "turtlesim picture" in plot
