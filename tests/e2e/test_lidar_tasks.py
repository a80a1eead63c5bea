"""The LiDAR tasks end to end in ROS 2: the rclpy reference package part3_lidar, graded once for lidar_distance,
obstacle_avoidance and wall_follower, earns full marks in every scenario, and its recordings re-score to the live
result. (The rospy references are graded with the rest of reference_solutions in test_reference_solutions.)"""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.grading import grade_submission
from grader.recording import Recording
from grader.rubric import load_rubrics
from grader.scoring import score_task

pytestmark = pytest.mark.slow

PACKAGE = Path(__file__).resolve().parents[2] / "reference_solutions_ros2" / "part3_lidar"
TASKS = {"lidar_distance": ["arena_centre", "corridor", "turtlebot3_world"],
         "obstacle_avoidance": ["centre", "mirrored", "south"],
         "wall_follower": ["corridor", "corridor_right", "left_turn", "left_turn_right_wall", "right_turn",
                           "right_turn_right_wall"]}


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    return grade_submission(PACKAGE, tmp_path_factory.mktemp("part3_lidar"), sorted(TASKS))


@pytest.mark.parametrize("task", sorted(TASKS))
def test_reference_scores_full_marks(report, task):
    result = next(t for t in report.tasks if t.id == task)
    assert result.status == "graded", result.message
    assert {c.id: c.feedback for c in result.criteria if c.score < c.max_score} == {}
    assert sorted(Path(p).stem for p in result.recordings) == TASKS[task]


@pytest.mark.parametrize("task", sorted(TASKS))
def test_recordings_rescore_identically(report, task):
    result = next(t for t in report.tasks if t.id == task)
    recordings = {Path(p).stem: Recording.open(p) for p in result.recordings}
    again = score_task(load_rubrics()[task], recordings)
    assert [c.model_dump() for c in again.criteria] == [c.model_dump() for c in result.criteria]
