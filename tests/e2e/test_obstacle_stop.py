"""obstacle_stop end to end: the rospy and rclpy references earn full marks in every scenario (walls named by course
worlds, contacts recorded), the recordings re-score to the live result and repeat bit for bit."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.grading import grade_submission
from grader.metrics.run import RunData
from grader.recording import Recording
from grader.reports.replay import scenario_times
from grader.rubric import load_rubrics
from grader.scoring import score_task

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
REFERENCES = {"rospy": ROOT / "reference_solutions" / "obstacle_stop.py",
              "rclpy": ROOT / "reference_solutions_ros2" / "part3_lidar"}


@pytest.fixture(scope="module", params=sorted(REFERENCES))
def result(request, tmp_path_factory):
    report = grade_submission(REFERENCES[request.param], tmp_path_factory.mktemp(request.param), ["obstacle_stop"])
    return next(t for t in report.tasks if t.id == "obstacle_stop")


def test_reference_scores_full_marks(result):
    assert result.status == "graded", result.message
    assert {c.id: c.feedback for c in result.criteria if c.score < c.max_score} == {}
    assert sorted(Path(p).stem for p in result.recordings) == ["arena_north", "corridor", "corridor_halfway"]


def test_recordings_hold_the_worlds_walls_and_rescore_identically(result):
    recordings = {Path(p).stem: Recording.open(p) for p in result.recordings}
    for recording in recordings.values():
        run = RunData.from_recording(recording, *scenario_times(recording))
        assert run.obstacles and run.robot == "turtlebot3_waffle" and run.contacts == ()
    again = score_task(load_rubrics()["obstacle_stop"], recordings)
    assert [c.model_dump() for c in again.criteria] == [c.model_dump() for c in result.criteria]


def test_a_collision_is_recorded_and_repeats_bit_for_bit(tmp_path):
    student = ROOT / "submissions_example" / "lara_scan_middle"
    first, second = (grade_submission(student, tmp_path / str(k), ["obstacle_stop"]).tasks[0] for k in (1, 2))
    path = next(p for p in first.recordings if Path(p).stem == "corridor")
    run = RunData.from_recording(Recording.open(path), *scenario_times(Recording.open(path)))
    assert run.contacts and {c.obstacle for c in run.contacts} == {"end wall"}
    assert abs(run.contacts[0].x - 4.0) < 0.01  # the end wall's face
    again = next(p for p in second.recordings if Path(p).stem == "corridor")
    assert Path(path).read_bytes() == Path(again).read_bytes()
