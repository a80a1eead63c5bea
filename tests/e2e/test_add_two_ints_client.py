"""The add_two_ints_client task end to end: the student's client (the ROS 2 service tutorial's), started with the
arguments 2 3, against the grader's own AddTwoInts server (grader/nodes/add_two_ints_server.py, confined like the
student's); the reference earns full marks, its recording holds the client's request and the grader's answer,
re-scores identically and repeats bit for bit; a client that ignores its arguments loses only sends_request."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.grading import grade_submission
from grader.metrics.run import service_calls
from grader.recording import Recording
from grader.rubric import load_rubrics
from grader.scoring import score_task

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "reference_solutions_ros2" / "py_srvcli"
HARDCODED = ROOT / "submissions_example" / "kai_ros2_add_client_hardcoded"


@pytest.fixture(scope="module")
def reference(graded):
    return next(t for t in graded(PACKAGE, ("add_two_ints_client",)).tasks if t.id == "add_two_ints_client")


def test_the_reference_client_scores_full_marks(reference):
    assert reference.status == "graded", reference.message
    assert reference.score == reference.max_score, {c.id: c.feedback for c in reference.criteria}
    assert not [d for d in reference.diagnostics if "add_two_ints_server" in d], reference.diagnostics


def test_the_recording_holds_the_request_and_the_graders_answer(reference):
    recording = Recording.open(reference.recordings[0])
    [call] = service_calls(recording)
    assert (call.service, call.request, call.response) == ("/add_two_ints", {"a": 2, "b": 3}, {"sum": 5})
    callers = {(i.topic.rsplit("/", 1)[1], i.callerid) for i in recording.topics()
               if i.topic.startswith("/rosgrade/service/")}
    assert callers == {("request", "/add_two_ints_client"), ("response", "/add_two_ints_server")}


def test_the_recording_rescores_identically_and_repeats_bit_for_bit(reference, tmp_path):
    recordings = {Path(p).stem: Recording.open(p) for p in reference.recordings}
    again = score_task(load_rubrics()["add_two_ints_client"], recordings)
    assert [c.model_dump() for c in again.criteria] == [c.model_dump() for c in reference.criteria]
    second = grade_submission(PACKAGE, tmp_path, ["add_two_ints_client"]).tasks[0]
    assert Path(second.recordings[0]).read_bytes() == Path(reference.recordings[0]).read_bytes()


def test_a_client_that_ignores_its_arguments_loses_only_sends_request(graded):
    result = graded(HARDCODED, ("add_two_ints_client",)).tasks[0]
    assert {c.id: c.score == c.max_score for c in result.criteria} == {
        "sends_request": False, "reports_response": True}
