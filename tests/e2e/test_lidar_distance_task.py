"""lidar_distance end to end: the rospy and rclpy references earn full marks in every scenario, and their recordings
re-score to the live result."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.grading import grade_submission
from grader.recording import Recording
from grader.rubric import load_rubrics
from grader.scoring import score_task

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
REFERENCES = {"rospy": ROOT / "reference_solutions" / "lidar_distance.py",
              "rclpy": ROOT / "reference_solutions_ros2" / "part3_lidar"}


@pytest.fixture(scope="module", params=sorted(REFERENCES))
def result(request, tmp_path_factory):
    report = grade_submission(REFERENCES[request.param], tmp_path_factory.mktemp(request.param), ["lidar_distance"])
    return next(t for t in report.tasks if t.id == "lidar_distance")


def test_reference_scores_full_marks(result):
    assert result.status == "graded", result.message
    assert {c.id: c.feedback for c in result.criteria if c.score < c.max_score} == {}
    assert sorted(Path(p).stem for p in result.recordings) == ["arena_centre", "corridor", "turtlebot3_world"]


def test_recordings_rescore_identically(result):
    recordings = {Path(p).stem: Recording.open(p) for p in result.recordings}
    again = score_task(load_rubrics()["lidar_distance"], recordings)
    assert [c.model_dump() for c in again.criteria] == [c.model_dump() for c in result.criteria]
