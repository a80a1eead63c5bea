"""The explore_forward task end to end (COM2009 Part 5, Exercise 4): the grader sends the student's ExploreForward
server (its own action, in its ament_cmake package) a goal in the corridor and, in a second scenario, cancels one; the
reference package earns full marks, its recording holds the goals, feedback, status and results, re-scores
identically and repeats bit for bit."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.grading import grade_submission
from grader.metrics.run import RunData
from grader.recording import Recording
from grader.rubric import load_rubrics
from grader.scoring import score_task

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "reference_solutions_ros2_cmake" / "part5_actions"


@pytest.fixture(scope="module")
def reference(graded):
    return graded(PACKAGE, ("explore_forward",)).tasks[0]


def test_the_reference_server_scores_full_marks(reference):
    assert reference.status == "graded", reference.message
    assert reference.score == reference.max_score, {c.id: c.feedback for c in reference.criteria}


def test_the_recordings_hold_the_goals_in_the_students_own_type(reference):
    by_name = {Path(p).stem: Recording.open(p) for p in reference.recordings}
    [to_wall] = RunData.from_recording(by_name["to_the_wall"], start_time=2.0).action_goals
    assert (to_wall.accepted, to_wall.statuses, to_wall.result_status) == (True, (2, 4), 4)
    assert to_wall.result["total_distance_travelled"] == pytest.approx(2.03, abs=0.05)
    assert to_wall.result["closest_obstacle"] == pytest.approx(0.5, abs=0.02)
    assert len(to_wall.feedback_t) > 100  # the server's 10 Hz loop, all the way to the wall
    [cancelled] = RunData.from_recording(by_name["cancelled"], start_time=2.0).action_goals
    assert (cancelled.cancel_t, cancelled.cancel_return_code, cancelled.statuses) == (6.0, 0, (2, 3, 5))
    channels = {i.topic: i.type for i in by_name["cancelled"].topics() if "explore_forward" in i.topic}
    assert channels["/rosgrade/service/explore_forward/_action/send_goal/request"] == (
        "part5_actions/action/ExploreForward_SendGoal_Request")


def test_the_recordings_rescore_identically_and_repeat_bit_for_bit(reference, tmp_path):
    recordings = {Path(p).stem: Recording.open(p) for p in reference.recordings}
    again = score_task(load_rubrics()["explore_forward"], recordings)
    assert [c.model_dump() for c in again.criteria] == [c.model_dump() for c in reference.criteria]
    second = grade_submission(PACKAGE, tmp_path, ["explore_forward"]).tasks[0]
    assert [Path(p).read_bytes() for p in second.recordings] == [Path(p).read_bytes() for p in reference.recordings]
