"""PrairieLearn external-grader results.json: score in [0, 1], tests with points, the path plot inline, under 1 MB."""
from __future__ import annotations

import json
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from grader.report import SubmissionReport, TaskReport
from grader.reports.files import write_atomic
from grader.reports.cause import criterion_feedback, criterion_measured, lead_lines, noticed
from grader.reports.escape import one_line, plain
from grader.reports.html import data_uri
from grader.reports.markdown import HIDDEN_TEXT
from grader.reports.plots import Plot
from grader.reports.text import NOTICED_HEADING, fmt_points, is_public, percent, replay_elsewhere_text

MAX_BYTES = 1_000_000
# Trajectory plots first: they are what students look at; commands and printed pose only if there is room.
_PLOT_ORDER = {"path": 0, "printed": 1, "commands": 2}


def prairielearn_results(report: SubmissionReport, plots: Sequence[Plot] = (), max_bytes: int = MAX_BYTES) -> dict[str, Any]:
    """The results.json object; images are dropped (least useful first) until the file fits max_bytes."""
    tests = []
    for task in report.tasks:
        if task.status != "graded" and not task.criteria:
            tests.append(_test(task.id, task.title, 0.0, task.max_score, " ".join(lead_lines(task)), ""))
        for c in task.criteria:
            public = is_public(c)
            tests.append(
                _test(
                    f"{task.id}: {c.title or c.id}",
                    task.title,
                    c.score,
                    c.max_score,
                    criterion_feedback(task, c) if public else HIDDEN_TEXT,
                    criterion_measured(task, c) if public else "",
                )
            )
    score = report.score / report.max_score if report.max_score > 0 else 0.0
    results: dict[str, Any] = {
        "gradable": True,
        "score": min(1.0, max(0.0, score)),
        "message": f"rosgrade: {fmt_points(report.score, report.max_score)} ({percent(report):.0f} %)",
        # PrairieLearn shows the plots but no files: the replay is in the report a local check writes.
        "output": plain("\n".join([*(_task_output(t) for t in report.tasks if lead_lines(t) or t.diagnostics),
                                    replay_elsewhere_text(report)]).strip()),
        "tests": tests,
        "images": [],
    }
    for plot in sorted(plots, key=lambda p: _PLOT_ORDER.get(p.name, 9)):
        image = {"label": plot.title, "url": data_uri(plot.png)}
        if _size(results) + len(json.dumps(image)) + 2 < max_bytes:
            results["images"].append(image)
    return results


def _task_output(task: TaskReport) -> str:
    """A task's crash, status and notes as plain text (PrairieLearn shows `output` preformatted)."""
    notes = noticed(task)
    lines = [f"{task.title or task.id}:", *lead_lines(task)]
    if notes:
        lines += [f"{NOTICED_HEADING}:", *(f"- {n}" for n in notes)]
    return "\n".join(lines) + "\n"


def _test(name: str, description: str, points: float, max_points: float, message: str, output: str) -> dict[str, Any]:
    return {
        "name": one_line(name),
        "description": one_line(description),
        "points": points,
        "max_points": max_points,
        "message": plain(message),
        "output": plain(output),
    }


def _size(results: dict[str, Any]) -> int:
    return len(json.dumps(results).encode("utf-8"))


def prairielearn_failure(message: str) -> dict[str, Any]:
    """Results for input that cannot be graded: not gradable, so the student does not lose an attempt."""
    return {"gradable": False, "score": 0.0, "format_errors": [plain(message)], "message": plain(message)}


def write_results(path: Path, results: dict[str, Any]) -> Path:
    """Write results.json atomically."""
    return write_atomic(path, json.dumps(results, allow_nan=False))
