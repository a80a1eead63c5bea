"""The batch gradebook: grades.csv (one row per student) and summary.md with a score histogram."""
from __future__ import annotations

import csv
import io
import statistics
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator

from grader.report import SubmissionReport
from grader.reports.escape import csv_cell, markdown_cell
from grader.reports.files import write_atomic
from grader.reports.text import fmt_number


@dataclass(frozen=True)
class TaskColumn:
    """One task of the assignment: the same for every student of the batch."""

    id: str
    max_score: float


@dataclass(frozen=True)
class StudentResult:
    """One student's outcome: their report, or why there is none (status error/timeout/pending)."""

    student: str
    report: SubmissionReport | None = None
    status: str = "pending"
    message: str = ""
    name: str = ""  # the student's name from the LMS download (the folder name otherwise)

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

    def points(self) -> float | None:
        """The student's score: the report's, 0 for a submission that could not be graded, None while pending."""
        if self.report is not None:
            return self.report.score
        return None if self.status == "pending" else 0.0


def criterion_columns(results: Sequence[StudentResult], tasks: Sequence[TaskColumn]) -> list[str]:
    """`task.criterion` columns, task by task, criteria in order of first appearance."""
    criteria: dict[str, None] = {}
    for task in tasks:
        for result in results:
            for report in result.report.tasks if result.report else []:
                if report.id == task.id:
                    for c in report.criteria:
                        criteria.setdefault(f"{task.id}.{c.id}")
    return list(criteria)


def grades_csv(results: Sequence[StudentResult], tasks: Sequence[TaskColumn]) -> str:
    """grades.csv: student, name, total, max, one column per task, one per criterion, status, message.

    Every row has the assignment's maximum; a submission that could not be graded scores 0 of it.
    """
    total_max = round(sum(t.max_score for t in tasks), 6)
    criterion_cols = criterion_columns(results, tasks)
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow([csv_cell(c) for c in ["student", "name", "total", "max", *(t.id for t in tasks), *criterion_cols,
                                           "status", "message"]])
    for result in results:
        points = result.points()
        cells: dict[str, object] = {t.id: (0.0 if points is not None else "") for t in tasks}
        for task in result.report.tasks if result.report else []:
            cells[task.id] = task.score
            cells.update({f"{task.id}.{c.id}": c.score for c in task.criteria})
        writer.writerow([csv_cell(value) for value in [
            result.student,
            result.name or result.student,
            "" if points is None else points,
            total_max,
            *(cells.get(col, "") for col in [t.id for t in tasks] + criterion_cols),
            result.effective_status,
            result.effective_message,
        ]])
    return buffer.getvalue()


def histogram_png(percents: Sequence[float]) -> bytes:
    """Histogram of the students' scores in percent, in 10 % bins."""
    figure = Figure(figsize=(6, 3.5))
    axes = figure.add_subplot()
    axes.hist(percents, bins=list(range(0, 101, 10)), color="tab:blue", edgecolor="white")
    axes.set_xlabel("score [%]")
    axes.set_ylabel("students")
    axes.yaxis.set_major_locator(MaxNLocator(integer=True))  # whole students: no 0.5 ticks for a small class
    axes.set_xlim(0, 100)
    axes.grid(True, axis="y", alpha=0.3)
    figure.tight_layout()
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png", dpi=90)
    return buffer.getvalue()


def percents(results: Sequence[StudentResult], tasks: Sequence[TaskColumn]) -> list[float]:
    """Every student's score in percent of the assignment's maximum (students still pending left out)."""
    total_max = sum(t.max_score for t in tasks)
    points = [result.points() for result in results]
    return [100 * p / total_max for p in points if p is not None and total_max > 0]


def summary_markdown(results: Sequence[StudentResult], tasks: Sequence[TaskColumn], histogram: str | None,
                     notes: Sequence[str] = ()) -> str:
    """summary.md: counts, score statistics, per-task means, per-criterion pass rates, what this run did, problems."""
    graded = [r for r in results if r.report is not None]
    scores = percents(results, tasks)
    by_status: dict[str, int] = {}
    for r in results:
        by_status[r.effective_status] = by_status.get(r.effective_status, 0) + 1
    counts = ", ".join(f"{k}: {v}" for k, v in sorted(by_status.items()))
    total_max = fmt_number(sum(t.max_score for t in tasks))
    lines = ["# rosgrade batch summary", "", f"Students: {len(results)}; {counts}", "",
             f"Tasks: {', '.join(t.id for t in tasks)} ({total_max} points; a submission that could not be "
             "graded counts as 0)", ""]
    lines += [f"- {note}" for note in notes] + ([""] if notes else [])
    if scores:
        lines += [
            f"Score: mean {statistics.mean(scores):.1f} %, median {statistics.median(scores):.1f} %, "
            f"min {min(scores):.1f} %, max {max(scores):.1f} %",
            "",
        ]
    if histogram:
        lines += [f"![score histogram]({histogram})", ""]
    if graded:
        lines += ["| Task / criterion | Mean points | Passed |", "|---|---|---|"]
        for task in tasks:
            found_tasks = [t for r in graded for t in r.report.tasks if t.id == task.id]
            mean = statistics.mean(t.score for t in found_tasks) if found_tasks else 0.0
            lines.append(f"| **{task.id}** | {fmt_number(mean)} / {fmt_number(task.max_score)} | |")
            ids = list(dict.fromkeys(c.id for t in found_tasks for c in t.criteria))
            for cid in ids:
                found = [c for t in found_tasks for c in t.criteria if c.id == cid]
                passed = sum(c.passed for c in found)
                lines.append(f"| {task.id}.{cid} | {fmt_number(statistics.mean(c.score for c in found))} | "
                             f"{passed}/{len(found)} |")
        lines.append("")
    problems = [r for r in results if r.effective_status != "graded" or r.effective_message]
    if problems:
        lines += ["## Errors, timeouts, missing tasks and students not graded yet", "", "| Student | Status | Message |", "|---|---|---|"]
        lines += [f"| {markdown_cell(r.student)} | {r.effective_status} | {markdown_cell(r.effective_message)} |"
                  for r in problems]
    return "\n".join(lines) + "\n"


def write_gradebook(out: Path, results: Sequence[StudentResult], tasks: Sequence[TaskColumn],
                    notes: Sequence[str] = ()) -> tuple[Path, Path]:
    """Write grades.csv, histogram.png and summary.md into out (summary last: it links the histogram)."""
    csv_path = write_atomic(out / "grades.csv", grades_csv(results, tasks))
    scores = percents(results, tasks)
    histogram = None
    if scores:
        write_atomic(out / "histogram.png", histogram_png(scores))
        histogram = "histogram.png"
    summary = write_atomic(out / "summary.md", summary_markdown(results, tasks, histogram, notes))
    return csv_path, summary
