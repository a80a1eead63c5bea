"""The fibonacci_client task end to end: the student's action client (the ROS 2 action tutorial's) against the
grader's own Fibonacci server (grader/nodes/fibonacci_server.py, confined like the student's); the reference earns
full marks, its recording holds the client's goal and result calls and the server's feedback, re-scores identically
and repeats bit for bit; a client without a feedback callback loses only reports_feedback."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.grading import grade_submission
from grader.metrics.action_record import plain
from grader.metrics.run import service_calls
from grader.recording import Recording
from grader.rubric import load_rubrics
from grader.scoring import score_task

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "reference_solutions_ros2" / "py_action"
NO_FEEDBACK = ROOT / "submissions_example" / "una_ros2_action_client_no_feedback"
SEQUENCE = [0, 1, 1, 2, 3, 5, 8, 13, 21, 34, 55]


@pytest.fixture(scope="module")
def reference(graded):
    return next(t for t in graded(PACKAGE, ("fibonacci_client",)).tasks if t.id == "fibonacci_client")


def test_the_reference_client_scores_full_marks(reference):
    assert reference.status == "graded", reference.message
    assert reference.score == reference.max_score, {c.id: c.feedback for c in reference.criteria}


def test_the_recording_holds_the_clients_goal_the_result_and_the_servers_feedback(reference):
    recording = Recording.open(reference.recordings[0])
    goal, result = service_calls(recording)
    assert (goal.service, plain(goal.request["goal"]), goal.response["accepted"]) == (
        "/fibonacci/_action/send_goal", {"order": 10}, True)
    assert (result.service, result.response["status"], plain(result.response["result"])) == (
        "/fibonacci/_action/get_result", 4, {"sequence": SEQUENCE})
    said = [text for _, stream, text in recording.output_lines() if stream == "rosout"]
    assert said[-1] == f"Result: {SEQUENCE}"
    assert [text for text in said if text.startswith("Received feedback")] == [
        f"Received feedback: {SEQUENCE[:n]}" for n in range(3, 12)]
    callers = {(i.topic, i.callerid) for i in recording.topics() if i.topic.startswith("/fibonacci/")}
    assert callers == {("/fibonacci/_action/feedback", "/fibonacci_action_server"),
                       ("/fibonacci/_action/status", "/fibonacci_action_server")}


def test_the_recording_rescores_identically_and_repeats_bit_for_bit(reference, tmp_path):
    recordings = {Path(p).stem: Recording.open(p) for p in reference.recordings}
    again = score_task(load_rubrics()["fibonacci_client"], recordings)
    assert [c.model_dump() for c in again.criteria] == [c.model_dump() for c in reference.criteria]
    second = grade_submission(PACKAGE, tmp_path, ["fibonacci_client"]).tasks[0]
    assert Path(second.recordings[0]).read_bytes() == Path(reference.recordings[0]).read_bytes()


def test_a_client_without_a_feedback_callback_loses_only_reports_feedback(graded):
    result = graded(NO_FEEDBACK, ("fibonacci_client",)).tasks[0]
    assert {c.id: c.score == c.max_score for c in result.criteria} == {
        "sends_goal": True, "reports_feedback": False, "reports_result": True}
