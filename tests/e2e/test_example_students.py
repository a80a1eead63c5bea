"""The example students lose exactly the criteria their flaws cost, and the feedback names the cause."""
from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow

EXPECTED = tomllib.loads((Path(__file__).resolve().parents[2] / "submissions_example" / "EXPECTED.toml").read_text())
CASES = [(student, task) for student, tasks in EXPECTED.items() for task in tasks]


def task_report(graded, examples_dir, student, task):
    tasks = tuple(sorted(EXPECTED[student]))
    report = graded(examples_dir / student, tasks)
    return next(t for t in report.tasks if t.id == task)


@pytest.mark.parametrize("student,task", CASES, ids=[f"{s}-{t}" for s, t in CASES])
def test_loses_exactly_the_expected_criteria(graded, examples_dir, student, task):
    expected = EXPECTED[student][task]
    result = task_report(graded, examples_dir, student, task)
    assert result.status in ("graded", "timeout"), result.message
    scores = {c.id: (c.score, c.max_score) for c in result.criteria}
    lost = sorted(c for c, (score, full) in scores.items() if score < full)
    assert set(expected.get("lose", [])) <= set(lost), {c.id: c.feedback for c in result.criteria}
    assert not set(expected.get("keep", [])) & set(lost), {c.id: c.feedback for c in result.criteria}


@pytest.mark.parametrize("student,task", [c for c in CASES if EXPECTED[c[0]][c[1]].get("says")],
                         ids=[f"{s}-{t}" for s, t in CASES if EXPECTED[s][t].get("says")])
def test_feedback_names_the_cause(graded, examples_dir, student, task):
    result = task_report(graded, examples_dir, student, task)
    feedback = {c.id: c.feedback for c in result.criteria}
    for criterion, text in EXPECTED[student][task]["says"].items():
        assert text.lower() in feedback[criterion].lower() + " ".join(result.diagnostics).lower(), feedback[criterion]
