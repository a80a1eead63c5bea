"""GitHub Classroom / Actions: the runner result (version 1, base64 in $GITHUB_OUTPUT) and the job step summary."""
from __future__ import annotations

import base64
import json
import os
from pathlib import Path
from typing import Any

from grader.report import SubmissionReport
from grader.reports.markdown import render_markdown
from grader.reports.text import task_status_text

RESULT_OUTPUT = "result"


def runner_result(report: SubmissionReport) -> dict[str, Any]:
    """Runner result JSON: one test per criterion, 'pass' exactly when it got full points (so log and gradebook agree)."""
    tests: list[dict[str, Any]] = []
    for task in report.tasks:
        code = f"rosgrade check . --task {task.id}"
        if task.status != "graded" and not task.criteria:
            tests.append(_test(f"{task.id}: {task.status}", "error", 0.0, task_status_text(task), code))
        for criterion in task.criteria:
            status = "pass" if criterion.score >= criterion.max_score else "fail"
            message = criterion.feedback if criterion.visibility == "visible" else ""
            tests.append(_test(f"{task.id}: {criterion.title or criterion.id}", status, criterion.score, message, code))
    statuses = {t["status"] for t in tests}
    overall = "error" if "error" in statuses else "fail" if "fail" in statuses or not tests else "pass"
    return {"version": 1, "status": overall, "max_score": report.max_score, "tests": tests}


def _test(name: str, status: str, score: float, message: str, code: str) -> dict[str, Any]:
    return {
        "name": name,
        "status": status,
        "score": score,
        "message": message,
        "test_code": code,
        "filename": "",
        "line_no": 0,
        "duration": 0,
    }


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
    return text + f"\nPlots of your robot's path and commands are in `report.html` in {where}.\n"


def write_summary(path: Path, report: SubmissionReport) -> None:
    """Append the step summary to a $GITHUB_STEP_SUMMARY file."""
    with path.open("a", encoding="utf-8") as handle:
        handle.write(step_summary(report))


def runner_failure(message: str) -> dict[str, Any]:
    """A runner result for a submission that could not be graded at all."""
    return {"version": 1, "status": "error", "max_score": 0, "tests": [_test("rosgrade", "error", 0.0, message, "rosgrade check .")]}
