"""GitHub Classroom / Actions: the runner result (version 1, base64 in $GITHUB_OUTPUT) and the job step summary."""
from __future__ import annotations

import base64
import json
import math
import os
from pathlib import Path
from typing import Any

from grader.report import SubmissionReport
from grader.reports.cause import criterion_feedback, lead_lines
from grader.reports.escape import markdown, one_line
from grader.reports.markdown import render_markdown
from grader.reports.text import fmt_score, watch_first

RESULT_OUTPUT = "result"
# The official reporter's log shows passed tests / tests × max_score, while Classroom records the sum of the tests'
# scores. Both agree only if every test is worth the same and scores all or nothing: so each criterion becomes
# as many equal "point" tests as it has units, and the submission's points are rounded to that unit.
UNITS = (1.0, 0.5, 0.25, 0.1)
MAX_TESTS = 200


def point_unit(report: SubmissionReport) -> float:
    """The largest unit that every maximum and every score is a whole number of (exact points, no rounding); when
    no unit fits the scores, the smallest that keeps the maxima whole within MAX_TESTS tests (scores rounded)."""
    maxima = [c.max_score for t in report.tasks for c in t.criteria] + [t.max_score for t in report.tasks if not t.criteria]
    scores = [c.score for t in report.tasks for c in t.criteria]

    def whole(values: list[float], unit: float) -> bool:
        return all(math.isclose(v / unit, round(v / unit), abs_tol=1e-6) for v in values)

    fitting = [u for u in UNITS if whole(maxima, u) and sum(round(m / u) for m in maxima) <= MAX_TESTS]
    exact = [u for u in fitting if whole(scores, u)]
    if exact:
        return exact[0]
    if fitting:
        return fitting[-1]
    return max(report.max_score / 100, 1e-6)  # odd weights: hundredths of the total


def runner_result(report: SubmissionReport) -> dict[str, Any]:
    """Runner result JSON whose log total and Classroom points are the same number (see UNITS)."""
    unit = point_unit(report)
    tests: list[dict[str, Any]] = []
    for task in report.tasks:
        code = f"rosgrade check . --task {task.id}"
        lead = " ".join(lead_lines(task))
        if not task.criteria:
            tests += _unit_tests(f"{task.id}: {task.status}", 0.0, task.max_score, unit, lead, code)
        for criterion in task.criteria:
            message = criterion_feedback(task, criterion) if criterion.visibility == "visible" else ""
            if lead and not criterion.passed:
                message = f"{lead} {message}"
            tests += _unit_tests(f"{task.id}: {criterion.title or criterion.id}", criterion.score,
                                 criterion.max_score, unit, message, code)
    overall = "fail" if not tests or any(t["status"] != "pass" for t in tests) else "pass"
    return {"version": 1, "status": overall, "max_score": _round(len(tests) * unit), "tests": tests}


def _unit_tests(name: str, score: float, max_score: float, unit: float, message: str, code: str) -> list[dict[str, Any]]:
    """A criterion as `max_score / unit` tests of one unit each, the first `score / unit` (rounded) passed."""
    count = max(1, round(max_score / unit))
    passed = min(count, max(0, round(score / unit + 1e-9)))
    return [
        _test(name if count == 1 else f"{name} ({i + 1}/{count})", "pass" if i < passed else "fail",
              unit if i < passed else 0.0, message if i == 0 else "", code)
        for i in range(count)
    ]


def _round(value: float) -> float:
    return round(value, 6)


def _test(name: str, status: str, score: float, message: str, code: str) -> dict[str, Any]:
    return {
        "name": _log_safe(name),
        "status": status,
        "score": _round(score),
        "message": _log_safe(message),
        "test_code": code,
        "filename": "",
        "line_no": 0,
        "duration": 0,
    }


def _log_safe(text: str) -> str:
    """One line without terminal controls that cannot start an Actions workflow command (`::set-output` ...)."""
    line = one_line(text)
    return f" {line}" if line.startswith("::") else line


def classroom_points(result: dict[str, Any]) -> tuple[float, float]:
    """(points, maximum) as the reporter sends them to Classroom: the sum of the test scores, and max_score."""
    return _round(sum(t["score"] for t in result["tests"])), float(result["max_score"])


def log_points(result: dict[str, Any]) -> float:
    """The points the reporter prints in the Actions log: passed tests / tests × max_score."""
    tests = result["tests"]
    return _round(sum(t["status"] == "pass" for t in tests) / len(tests) * result["max_score"]) if tests else 0.0


def encode_result(result: dict[str, Any]) -> str:
    """The result as the base64 string the grading reporter decodes."""
    return base64.b64encode(json.dumps(result, separators=(",", ":")).encode("utf-8")).decode("ascii")


def write_output(path: Path, result: dict[str, Any]) -> None:
    """Append `result=<base64>` to a $GITHUB_OUTPUT file."""
    with path.open("a", encoding="utf-8") as handle:
        handle.write(f"{RESULT_OUTPUT}={encode_result(result)}\n")


def run_url() -> str | None:
    """This Actions run's page (where the report artifact is), when running inside GitHub Actions."""
    server, repo, run = (os.environ.get(k) for k in ("GITHUB_SERVER_URL", "GITHUB_REPOSITORY", "GITHUB_RUN_ID"))
    return f"{server}/{repo}/actions/runs/{run}" if server and repo and run else None


def step_summary(report: SubmissionReport, artifact: str = "rosgrade-report") -> str:
    """Markdown for the job summary: the tables, and where the plots are (GitHub strips inline data: images)."""
    text = render_markdown(report, public_only=True, heading_level=2)
    url = run_url()
    where = f"the [`{artifact}` artifact]({url}#artifacts)" if url else f"the `{artifact}` artifact of this run"
    unit = point_unit(report)
    rounding = "" if unit == 1.0 and report.score == round(report.score) else \
        f" Classroom records the points in steps of {fmt_score(unit)}."
    first = watch_first(report)
    watch = " " + markdown(f"Watch first: {first[0].id}, scenario '{first[1]}'.", line_start=False) if first else ""
    return text + (f"\nA replay of each run, and plots of your robot's path and commands, are in `report.html` in "
                   f"{where}.{watch}{rounding}\n")


def write_summary(path: Path, report: SubmissionReport) -> None:
    """Append the step summary to a $GITHUB_STEP_SUMMARY file."""
    with path.open("a", encoding="utf-8") as handle:
        handle.write(step_summary(report))


def failure_summary(message: str) -> str:
    """The step summary for a submission that could not be graded at all."""
    return f"## rosgrade could not grade this submission\n\n{markdown(message)}\n"


def runner_failure(message: str, max_score: float = 0.0) -> dict[str, Any]:
    """A runner result for a submission that could not be graded: 0 points of the assignment's real maximum."""
    return {"version": 1, "status": "error", "max_score": _round(max_score),
            "tests": [_test("rosgrade", "error", 0.0, message, "rosgrade check .")]}
