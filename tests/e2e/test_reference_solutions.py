"""Every reference solution, written as a student following the course would, earns full marks in every scenario."""
from __future__ import annotations

import pytest

from grader.rubric import load_rubrics

pytestmark = pytest.mark.slow

TASKS = sorted(load_rubrics())


@pytest.fixture(scope="module")
def report(graded, reference_dir):
    return graded(reference_dir)


def test_every_task_is_found_from_the_script_names(report):
    assert sorted(t.id for t in report.tasks) == TASKS


@pytest.mark.parametrize("task", TASKS)
def test_reference_scores_full_marks(report, task):
    result = next(t for t in report.tasks if t.id == task)
    assert result.status == "graded", result.message
    lost = {c.id: c.feedback for c in result.criteria if c.score < c.max_score}
    assert lost == {}
    assert result.score == result.max_score > 0


@pytest.mark.parametrize("task", TASKS)
def test_reference_runs_raise_no_exception(report, task):
    result = next(t for t in report.tasks if t.id == task)
    assert not [d for d in result.diagnostics if "uncaught" in d or "never called" in d]
