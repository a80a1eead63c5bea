"""The LiDAR tasks end to end (lidar_distance, obstacle_avoidance, wall_follower): each task's rospy and rclpy
references earn full marks in every scenario, and their recordings re-score to the live result (one grading per task
and reference)."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.grading import grade_submission
from grader.recording import Recording
from grader.rubric import load_rubrics
from grader.scoring import score_task

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
TASKS = {"lidar_distance": ["arena_centre", "corridor", "turtlebot3_world"],
         "obstacle_avoidance": ["centre", "mirrored", "south"],
         "wall_follower": ["corridor", "left_turn", "right_turn"]}
CASES = [(task, library) for task in sorted(TASKS) for library in ("rclpy", "rospy")]


def _reference(task: str, library: str) -> Path:
    if library == "rospy":
        return ROOT / "reference_solutions" / f"{task}.py"
    return ROOT / "reference_solutions_ros2" / "part3_lidar"


@pytest.fixture(scope="module", params=CASES, ids=["-".join(case) for case in CASES])
def graded(request, tmp_path_factory):
    task, library = request.param
    report = grade_submission(_reference(task, library), tmp_path_factory.mktemp(f"{task}-{library}"), [task])
    return task, next(t for t in report.tasks if t.id == task)


def test_reference_scores_full_marks(graded):
    task, result = graded
    assert result.status == "graded", result.message
    assert {c.id: c.feedback for c in result.criteria if c.score < c.max_score} == {}
    assert sorted(Path(p).stem for p in result.recordings) == TASKS[task]


def test_recordings_rescore_identically(graded):
    task, result = graded
    recordings = {Path(p).stem: Recording.open(p) for p in result.recordings}
    again = score_task(load_rubrics()[task], recordings)
    assert [c.model_dump() for c in again.criteria] == [c.model_dump() for c in result.criteria]
