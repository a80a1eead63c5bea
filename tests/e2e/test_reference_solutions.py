"""Every reference solution, written as a student following the course would, earns full marks in every scenario."""
from __future__ import annotations

import pytest

from grader.rubric import load_rubrics

pytestmark = pytest.mark.slow

TASKS = sorted(load_rubrics())


@pytest.fixture(scope="module")
def report(graded, reference_dir):
    return graded(reference_dir)


def test_every_task_is_found_from_the_script_names(report):
    assert sorted(t.id for t in report.tasks) == TASKS


@pytest.mark.parametrize("task", TASKS)
def test_reference_scores_full_marks(report, task):
    result = next(t for t in report.tasks if t.id == task)
    assert result.status == "graded", result.message
    lost = {c.id: c.feedback for c in result.criteria if c.score < c.max_score}
    assert lost == {}
    assert result.score == result.max_score > 0


@pytest.mark.parametrize("task", TASKS)
def test_reference_runs_raise_no_exception(report, task):
    result = next(t for t in report.tasks if t.id == task)
    assert not [d for d in result.diagnostics if "uncaught" in d or "never called" in d]


@pytest.mark.parametrize("task", TASKS)
def test_rescoring_the_recordings_gives_exactly_the_live_result(report, task):
    from pathlib import Path

    from grader.recording import Recording
    from grader.scoring import score_task

    live = next(t for t in report.tasks if t.id == task)
    recordings = {Path(p).stem: Recording.open(p) for p in live.recordings}
    again = score_task(load_rubrics()[task], recordings)
    assert [c.model_dump() for c in again.criteria] == [c.model_dump() for c in live.criteria]


def test_a_ros1_bag_without_ground_truth_is_scored_from_odometry(report, tmp_path):
    from pathlib import Path

    from rosbags.rosbag1 import Writer
    from rosbags.typesys import Stores, get_typestore

    from grader.recording import Recording
    from grader.scoring import score_task

    live = next(t for t in report.tasks if t.id == "move_circle")
    source = Recording.open(next(p for p in live.recordings if Path(p).stem == "nominal"))
    store = get_typestore(Stores.ROS1_NOETIC)
    bag = tmp_path / "real_robot.bag"
    with Writer(bag) as writer:
        for topic, kind in (("/cmd_vel", "geometry_msgs/msg/Twist"), ("/odom", "nav_msgs/msg/Odometry")):
            connection = writer.add_connection(topic, kind, typestore=store)
            for t_ns, msg in source.messages(topic):
                writer.write(connection, t_ns, store.serialize_ros1(msg, kind))
    recording = Recording.open(bag)
    assert recording.ground_truth() is None
    result = score_task(load_rubrics()["move_circle"].restricted_to(["nominal"]), {"nominal": recording})
    radius = next(c for c in result.criteria if c.id == "radius")
    assert radius.score == radius.max_score
    assert any("ground truth" in note for note in result.diagnostics)
