"""The action_client metric on made-up runs: a tutorial client's goal, feedback and result found in its log; a client
that sent nothing, one whose goal went unanswered, one that logged only some feedback."""
from __future__ import annotations

import math

from grader.metrics import METRICS, OutputLine, RunData
from grader.metrics.run import ServiceCall
from grader.rubric import load_rubrics
from grader.scoring import score_task

from scoring_synth import run

METRIC = METRICS["action_client"]
SEQUENCE = [0, 1, 1, 2, 3, 5, 8]
GOAL = ServiceCall(1.0, "/fibonacci/_action/send_goal", {"goal": {"order": 6}}, {"accepted": True})
RESULT = ServiceCall(1.1, "/fibonacci/_action/get_result", {}, {"status": 4, "result": {"sequence": SEQUENCE}})


def _measure(calls, said) -> dict:
    data = RunData(odometry=run([]).odometry, service_calls=tuple(calls),
                   lines=tuple(OutputLine(1.2 + 0.1 * k, "rosout", text, "INFO") for k, text in enumerate(said)))
    return METRIC.judge(data, METRIC.params(action="/fibonacci", goal={"order": 6}))


def test_a_client_that_logs_feedback_as_arrays_and_the_result():
    said = [f"Received feedback: array('i', {SEQUENCE[:n]})" for n in range(3, 8)] + [f"Result: {SEQUENCE}"]
    m = _measure([GOAL, RESULT], said)
    assert (m["goal_correct"], m["accepted"], m["n_feedback_expected"], m["feedback_reported_fraction"],
            m["result_reported"]) == (1.0, 1.0, 4, 1.0, 1.0)


def test_a_list_is_found_whole_not_inside_a_longer_one():
    m = _measure([GOAL, RESULT], [f"Feedback {SEQUENCE[:4]}", f"Result: {SEQUENCE}"])
    assert m["feedback_reported_fraction"] == 0.25  # [0, 1, 1, 2] only: [0, 1, 1] is not in "[0, 1, 1, 2]"
    assert m["first_unreported_feedback"] == "The feedback [0, 1, 1] is in no line your node wrote"


def test_a_client_that_sent_nothing_and_one_never_answered():
    nothing = _measure([], [])
    assert (nothing["n_goals"], nothing["goal_correct"], nothing["first_wrong_goal"], nothing["no_result"]) == (
        0, 0.0, "No goal reached /fibonacci", "no goal reached /fibonacci")
    unanswered = _measure([ServiceCall(1.0, GOAL.service, GOAL.request, None)], [])
    assert (unanswered["accepted"], unanswered["no_result"]) == (0.0, "/fibonacci never answered the goal")
    wrong = _measure([ServiceCall(1.0, GOAL.service, {"goal": {"order": 20}}, {"accepted": True})], [])
    assert wrong["first_wrong_goal"] == "The goal's order was 20, expected 6"
    assert not math.isnan(wrong["feedback_reported_fraction"])


def test_the_rubric_names_the_cause_when_no_goal_was_sent():
    rubric = load_rubrics()["fibonacci_client"]
    data = RunData(odometry=run([]).odometry)
    report = score_task(rubric, {s.name: data for s in rubric.scenarios})
    feedback = {c.id: c.feedback for c in report.criteria}
    assert feedback["reports_feedback"].startswith("Your node sent no goal to /fibonacci")
    assert feedback["reports_result"] == "No result came back: no goal reached /fibonacci."
