"""The add_two_ints task end to end: the grader calls the student's AddTwoInts server (the ROS 2 service tutorial's)
from the scenario; the reference package earns full marks, its recording holds the grader's requests and the
server's responses, re-scores identically and repeats bit for bit; a server that subtracts loses only the sums, with
feedback naming the field and the value it sent."""
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
MINUS = ROOT / "submissions_example" / "uma_ros2_add_minus"


@pytest.fixture(scope="module")
def reference(graded):
    return next(t for t in graded(PACKAGE, ("add_two_ints",)).tasks if t.id == "add_two_ints")


def test_the_reference_server_scores_full_marks(reference):
    assert reference.status == "graded", reference.message
    assert reference.score == reference.max_score, {c.id: c.feedback for c in reference.criteria}


def test_the_recording_holds_the_graders_calls_and_the_servers_answers(reference):
    recording = Recording.open(reference.recordings[0])
    calls = service_calls(recording)
    assert [(round(c.t - 2.0, 3), c.request, c.response) for c in calls] == [
        (0.5, {"a": 2, "b": 3}, {"sum": 5}), (1.0, {"a": -7, "b": 4}, {"sum": -3}),
        (1.5, {"a": 4000000000, "b": 1}, {"sum": 4000000001})]
    callers = {(i.topic.rsplit("/", 1)[1], i.callerid, i.origin) for i in recording.topics()
               if i.topic.startswith("/rosgrade/service/")}
    assert callers == {("request", "/rosgrade", "grader"), ("response", "/add_two_ints_server", "node")}


def test_the_recording_rescores_identically_and_repeats_bit_for_bit(reference, tmp_path):
    recordings = {Path(p).stem: Recording.open(p) for p in reference.recordings}
    again = score_task(load_rubrics()["add_two_ints"], recordings)
    assert [c.model_dump() for c in again.criteria] == [c.model_dump() for c in reference.criteria]
    second = grade_submission(PACKAGE, tmp_path, ["add_two_ints"]).tasks[0]
    assert Path(second.recordings[0]).read_bytes() == Path(reference.recordings[0]).read_bytes()


def test_a_server_that_subtracts_loses_the_sums_and_is_told_the_field_and_value(graded):
    result = graded(MINUS, ("add_two_ints",)).tasks[0]
    scores = {c.id: c.score == c.max_score for c in result.criteria}
    assert scores == {"serves": True, "sums": False}
    assert next(c.feedback for c in result.criteria if c.id == "sums") == "call 1 (a=2, b=3): sum = -1, expected 5."
