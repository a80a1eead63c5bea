"""The batch gradebook: grades.csv (one row per student) and summary.md with a score histogram."""
from __future__ import annotations

import csv
import io
import statistics
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from matplotlib.figure import Figure

from grader.report import SubmissionReport
from grader.reports.files import write_atomic
from grader.reports.text import fmt_number


@dataclass(frozen=True)
class StudentResult:
    """One student's outcome: their report, or why there is none (status error/timeout/pending)."""

    student: str
    report: SubmissionReport | None = None
    status: str = "pending"
    message: str = ""

    @property
    def effective_status(self) -> str:
        """'graded' when a report exists (a node that crashed is a graded outcome), else error/timeout/pending."""
        return "graded" if self.report is not None else self.status

    @property
    def effective_message(self) -> str:
        """The batch message, or the tasks that were not graded normally (node errors, timeouts, missing scripts)."""
        if self.report is None:
            return self.message
        return "; ".join(f"{t.id}: {t.status}" + (f" ({t.message})" if t.message else "")
                         for t in self.report.tasks if t.status != "graded")


def columns(results: Sequence[StudentResult]) -> tuple[list[str], list[str]]:
    """Task columns and `task.criterion` columns, in order of first appearance."""
    tasks: dict[str, None] = {}
    criteria: dict[str, None] = {}
    for result in results:
        for task in result.report.tasks if result.report else []:
            tasks.setdefault(task.id)
            for c in task.criteria:
                criteria.setdefault(f"{task.id}.{c.id}")
    return list(tasks), list(criteria)


def grades_csv(results: Sequence[StudentResult]) -> str:
    """grades.csv: student, total, max, one column per task, one per criterion, status, message."""
    task_cols, criterion_cols = columns(results)
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["student", "total", "max", *task_cols, *criterion_cols, "status", "message"])
    for result in results:
        cells: dict[str, object] = {}
        report = result.report
        if report is not None:
            for task in report.tasks:
                cells[task.id] = task.score
                cells.update({f"{task.id}.{c.id}": c.score for c in task.criteria})
        writer.writerow(
            [
                result.student,
                report.score if report else "",
                report.max_score if report else "",
                *(cells.get(col, "") for col in task_cols + criterion_cols),
                result.effective_status,
                result.effective_message,
            ]
        )
    return buffer.getvalue()


def histogram_png(percents: Sequence[float]) -> bytes:
    """Histogram of the students' scores in percent, in 10 % bins."""
    figure = Figure(figsize=(6, 3.5))
    axes = figure.add_subplot()
    axes.hist(percents, bins=list(range(0, 101, 10)), color="tab:blue", edgecolor="white")
    axes.set_xlabel("score [%]")
    axes.set_ylabel("students")
    axes.set_xlim(0, 100)
    axes.grid(True, axis="y", alpha=0.3)
    figure.tight_layout()
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png", dpi=90)
    return buffer.getvalue()


def summary_markdown(results: Sequence[StudentResult], histogram: str | None) -> str:
    """summary.md: counts, score statistics, per-task means, per-criterion pass rates, problems list."""
    graded = [r for r in results if r.report is not None]
    percents = [100 * r.report.score / r.report.max_score for r in graded if r.report.max_score > 0]
    by_status: dict[str, int] = {}
    for r in results:
        by_status[r.effective_status] = by_status.get(r.effective_status, 0) + 1
    counts = ", ".join(f"{k}: {v}" for k, v in sorted(by_status.items()))
    lines = ["# rosgrade batch summary", "", f"Students: {len(results)}; {counts}", ""]
    if percents:
        lines += [
            f"Score: mean {statistics.mean(percents):.1f} %, median {statistics.median(percents):.1f} %, "
            f"min {min(percents):.1f} %, max {max(percents):.1f} %",
            "",
        ]
    if histogram:
        lines += [f"![score histogram]({histogram})", ""]
    task_cols, _ = columns(results)
    if task_cols:
        lines += ["| Task / criterion | Mean points | Passed |", "|---|---|---|"]
        for task_id in task_cols:
            tasks = [t for r in graded for t in r.report.tasks if t.id == task_id]
            lines.append(f"| **{task_id}** | {fmt_number(statistics.mean(t.score for t in tasks))} / "
                         f"{fmt_number(max(t.max_score for t in tasks))} | |")
            ids = list(dict.fromkeys(c.id for t in tasks for c in t.criteria))
            for cid in ids:
                found = [c for t in tasks for c in t.criteria if c.id == cid]
                passed = sum(c.passed for c in found)
                lines.append(f"| {task_id}.{cid} | {fmt_number(statistics.mean(c.score for c in found))} | "
                             f"{passed}/{len(found)} |")
        lines.append("")
    problems = [r for r in results if r.effective_status != "graded" or r.effective_message]
    if problems:
        lines += ["## Errors, timeouts, missing tasks and students not graded yet", "", "| Student | Status | Message |", "|---|---|---|"]
        lines += [f"| {r.student} | {r.effective_status} | {r.effective_message.replace('|', '/')} |" for r in problems]
    return "\n".join(lines) + "\n"


def write_gradebook(out: Path, results: Sequence[StudentResult]) -> tuple[Path, Path]:
    """Write grades.csv, summary.md and histogram.png into out."""
    csv_path = write_atomic(out / "grades.csv", grades_csv(results))
    percents = [100 * r.report.score / r.report.max_score for r in results if r.report and r.report.max_score > 0]
    histogram = None
    if percents:
        write_atomic(out / "histogram.png", histogram_png(percents))
        histogram = "histogram.png"
    summary = write_atomic(out / "summary.md", summary_markdown(results, histogram))
    return csv_path, summary
