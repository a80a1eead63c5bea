"""The fibonacci task end to end: the grader sends the student's Fibonacci action server (the ROS 2 action
tutorial's) two goals from the scenario and cancels the second; the reference package earns full marks, its
recording holds the goals, feedback, status and results where ROS 2 carries them, re-scores identically and repeats
bit for bit; the tutorial's first server (no cancel callback, single-threaded) loses only cancel_stops."""
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
PACKAGE = ROOT / "reference_solutions_ros2" / "py_action"
NO_CANCEL = ROOT / "submissions_example" / "wes_ros2_action_no_cancel"
OWN_ACTION = ROOT / "submissions_example" / "yara_ros2_action_tutorial"


@pytest.fixture(scope="module")
def reference(graded):
    return next(t for t in graded(PACKAGE, ("fibonacci",)).tasks if t.id == "fibonacci")


def test_the_reference_server_scores_full_marks(reference):
    assert reference.status == "graded", reference.message
    assert reference.score == reference.max_score, {c.id: c.feedback for c in reference.criteria}


def test_the_recording_holds_goals_feedback_status_and_results(reference):
    recording = Recording.open(reference.recordings[0])
    first, second = RunData.from_recording(recording, start_time=2.0).action_goals
    assert (first.t, first.goal, first.accepted, first.statuses, first.result) == (
        2.5, {"order": 5}, True, (2, 4), {"sequence": [0, 1, 1, 2, 3, 5]})
    assert first.feedback_t == (2.51, 3.51, 4.51, 5.51)  # one a second, as the tutorial sleeps
    assert (second.t, second.cancel_t, second.cancel_return_code, second.statuses) == (7.5, 9.0, 0, (2, 3, 5))
    channels = {(i.topic, i.callerid, i.origin) for i in recording.topics() if "fibonacci" in i.topic}
    assert channels == {
        *((f"/rosgrade/service/fibonacci/_action/{s}/request", "/rosgrade", "grader")
          for s in ("send_goal", "get_result", "cancel_goal")),
        *((f"/rosgrade/service/fibonacci/_action/{s}/response", "/fibonacci_action_server", "node")
          for s in ("send_goal", "get_result", "cancel_goal")),
        ("/fibonacci/_action/feedback", "/fibonacci_action_server", "node"),
        ("/fibonacci/_action/status", "/fibonacci_action_server", "node")}


def test_the_recording_rescores_identically_and_repeats_bit_for_bit(reference, tmp_path):
    recordings = {Path(p).stem: Recording.open(p) for p in reference.recordings}
    again = score_task(load_rubrics()["fibonacci"], recordings)
    assert [c.model_dump() for c in again.criteria] == [c.model_dump() for c in reference.criteria]
    second = grade_submission(PACKAGE, tmp_path, ["fibonacci"]).tasks[0]
    assert Path(second.recordings[0]).read_bytes() == Path(reference.recordings[0]).read_bytes()


def test_the_submissions_own_fibonacci_action_is_the_one_the_goals_are_sent_as(graded):
    result = graded(OWN_ACTION, ("fibonacci",)).tasks[0]
    assert result.score == result.max_score, {c.id: c.feedback for c in result.criteria}
    channels = {i.topic: i.type for i in Recording.open(result.recordings[0]).topics() if "fibonacci" in i.topic}
    assert channels["/rosgrade/service/fibonacci/_action/send_goal/request"] == (
        "custom_action_interfaces/action/Fibonacci_SendGoal_Request")


def test_a_server_without_a_cancel_callback_loses_only_cancel_stops(graded):
    result = graded(NO_CANCEL, ("fibonacci",)).tasks[0]
    assert {c.id: c.score == c.max_score for c in result.criteria} == {
        "accepts_goal": True, "feedback": True, "result": True, "cancel_stops": False}
    assert next(c.feedback for c in result.criteria if c.id == "cancel_stops").startswith(
        "The cancelled goal ended EXECUTING.")
