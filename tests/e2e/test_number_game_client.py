"""The number_game_client task end to end: the student's client, started with `--ros-args -p guess:=99 -p
cheat:=True`, against the grader's own number game server (grader/nodes/number_game_server.py, confined like the
student's node); the reference earns full marks, its recording holds the client's request and the grader server's
answer, re-scores identically (`rosgrade score` too) and repeats bit for bit; the grader's server is not reported as
the student's node."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from grader.cli import main
from grader.grading import grade_submission
from grader.metrics.run import service_calls
from grader.recording import Recording
from grader.rubric import load_rubrics
from grader.scoring import score_task

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "reference_solutions_ros2_cmake" / "part4_services"


@pytest.fixture(scope="module")
def reference(graded):
    return graded(PACKAGE, ("number_game_client",)).tasks[0]


def test_the_reference_client_scores_full_marks(reference):
    assert reference.status == "graded", reference.message
    assert reference.score == reference.max_score, {c.id: c.feedback for c in reference.criteria}
    assert not [d for d in reference.diagnostics if "number_game_server" in d], reference.diagnostics


def test_the_recording_holds_the_clients_request_and_the_graders_answer(reference):
    recording = Recording.open(reference.recordings[0])
    [call] = service_calls(recording)
    assert (call.service, call.request, call.response) == (
        "/guess_the_number", {"guess": 99, "cheat": True},
        {"num_guesses": 7, "hint": "The answer is 37!", "correct": False})
    callers = {(i.topic.rsplit("/", 1)[1], i.callerid, i.origin) for i in recording.topics()
               if i.topic.startswith("/rosgrade/service/")}
    assert callers == {("request", "/number_game_client", "node"), ("response", "/number_game_service", "node")}
    said = [text for _, stream, text in recording.output_lines() if stream == "rosout"]
    assert said[-1] == ("The server responded with:\n - Incorrect guess :(\n - Number of attempts so far: 7\n"
                        " - A hint: 'The answer is 37!'.")


def test_the_recording_rescores_identically_and_repeats_bit_for_bit(reference, tmp_path, capsys):
    recordings = {Path(p).stem: Recording.open(p) for p in reference.recordings}
    again = score_task(load_rubrics()["number_game_client"], recordings)
    assert [c.model_dump() for c in again.criteria] == [c.model_dump() for c in reference.criteria]
    assert main(["score", *reference.recordings, "--task", "number_game_client", "--json"]) == 0
    [cli] = json.loads(capsys.readouterr().out)["tasks"]
    assert [(c["id"], c["score"], c["feedback"]) for c in cli["criteria"]] == \
        [(c.id, c.score, c.feedback) for c in reference.criteria]
    second = grade_submission(PACKAGE, tmp_path, ["number_game_client"]).tasks[0]
    assert Path(second.recordings[0]).read_bytes() == Path(reference.recordings[0]).read_bytes()
