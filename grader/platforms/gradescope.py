"""Gradescope results.json: one test per rubric criterion; a valid file in every outcome, because a missing or
invalid one shows students only "The autograder failed to execute correctly"."""
from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from grader.report import SubmissionReport, TaskReport
from grader.reports.files import write_atomic
from grader.reports.cause import criterion_feedback, criterion_measured, lead_lines, noticed
from grader.reports.escape import markdown, one_line
from grader.reports.markdown import criterion_markdown, noticed_markdown
from grader.reports.text import fmt_points, percent, replay_elsewhere_text

UNFINISHED_MESSAGE = (
    "rosgrade started grading but did not finish, so no points could be given. The usual causes are a node that "
    "never stops on its own or that uses a lot of memory (the autograder has half a CPU and 768 MB). Check that your "
    "node finishes and try again; ask your instructor if this keeps happening."
)


def _task_problem_test(task: TaskReport, number: str) -> dict[str, Any]:
    """A test explaining why a task was not graded normally; it carries the task's points only if no criterion does."""
    lines = [markdown(line) + "\n" for line in lead_lines(task)] + noticed_markdown(noticed(task))
    test: dict[str, Any] = {
        "name": one_line(f"{task.title or task.id}: {task.status.replace('_', ' ')}"),
        "number": number,
        "status": "failed",
        "output": "\n".join(lines),
        "output_format": "md",
        "tags": [task.id, task.status],
        "visibility": "visible",
    }
    if not task.criteria:
        test.update(score=0.0, max_score=task.max_score)
    return test


def gradescope_results(report: SubmissionReport, execution_time: float | None = None) -> dict[str, Any]:
    """The results.json object for a graded submission."""
    tests: list[dict[str, Any]] = []
    for i, task in enumerate(report.tasks, start=1):
        if task.status != "graded":
            tests.append(_task_problem_test(task, f"{i}.0"))
        for j, criterion in enumerate(task.criteria, start=1):
            tests.append(
                {
                    "score": criterion.score,
                    "max_score": criterion.max_score,
                    "name": one_line(f"{task.title or task.id}: {criterion.title or criterion.id}"),
                    "number": f"{i}.{j}",
                    "output": criterion_markdown(criterion.model_copy(
                        update={"feedback": criterion_feedback(task, criterion),
                                "measured": criterion.measured if criterion_measured(task, criterion) else {}})),
                    "output_format": "md",
                    "tags": [task.id, criterion.id],
                    "visibility": criterion.visibility,
                }
            )
    summary = [f"**rosgrade {markdown(report.rosgrade_version, line_start=False)}: {fmt_points(report.score, report.max_score)} "
               f"({percent(report):.0f} %)**"]
    for task in report.tasks:  # the crash and the notes are often the whole answer: show them on top
        lines = [markdown(line) for line in lead_lines(task)] + noticed_markdown(noticed(task))
        if lines:
            summary += ["", f"**{markdown(task.title or task.id, line_start=False)}**", ""] + lines
    watch = replay_elsewhere_text(report)  # Gradescope shows students no files, so no report.html either
    if watch:
        summary += ["", markdown(watch)]
    results: dict[str, Any] = {
        "score": report.score,
        "output": "\n".join(summary),
        "output_format": "md",
        "tests": tests,
        "extra_data": {"rosgrade_version": report.rosgrade_version, "max_score": report.max_score},
    }
    if execution_time is not None:
        results["execution_time"] = round(execution_time)
    return results


def gradescope_failure(message: str, max_score: float | None = None) -> dict[str, Any]:
    """A valid results.json for a submission that could not be graded at all, with the reason as a test."""
    test: dict[str, Any] = {
        "name": "rosgrade could not grade this submission",
        "score": 0.0,
        "status": "failed",
        "output": markdown(message),
        "output_format": "md",
        "visibility": "visible",
    }
    if max_score is not None:
        test["max_score"] = max_score
    return {"score": 0.0, "output": markdown(message), "output_format": "md", "tests": [test]}


def write_results(path: Path, results: dict[str, Any]) -> Path:
    """Write results.json in one atomic step (never a half-written file)."""
    return write_atomic(path, json.dumps(results, indent=2, allow_nan=False))
