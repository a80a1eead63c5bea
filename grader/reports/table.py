"""The console view of a report (rich): one row per criterion, readable in an 80-column terminal."""
from __future__ import annotations

from rich.console import Console
from rich.table import Table
from rich.text import Text

from grader.report import SubmissionReport
from grader.reports.text import fmt_points, measured_text, percent, task_status_text


def report_table(report: SubmissionReport) -> Table:
    """Task, criterion, points, measured values and one line of feedback per row."""
    table = Table(title=Text(f"rosgrade: {report.submission}"), show_lines=False, expand=False)
    table.add_column("Task", style="bold", no_wrap=True)
    table.add_column("Criterion")
    table.add_column("Points", justify="right", no_wrap=True)
    table.add_column("Measured")
    table.add_column("Feedback")
    for task in report.tasks:
        task_cell = f"{task.id}\n{fmt_points(task.score, task.max_score)}"
        status = task_status_text(task)
        if status or not task.criteria:
            table.add_row(Text(task_cell), Text(task.status, style="yellow"), "", "", Text(status))
            task_cell = ""
        for criterion in task.criteria:
            style = "green" if criterion.passed else "red"
            mark = "✔" if criterion.passed else "✘"
            # Text, not markup: student and rubric text may contain brackets such as "[m]".
            table.add_row(
                Text(task_cell),
                Text(f"{mark} {criterion.title or criterion.id}", style=style),
                fmt_points(criterion.score, criterion.max_score),
                Text(measured_text(criterion.measured, limit=1)),
                Text(criterion.feedback.splitlines()[0] if criterion.feedback else ""),
            )
            task_cell = ""
        table.add_section()
    return table


def print_report(console: Console, report: SubmissionReport) -> None:
    """Print the table and the total."""
    console.print(report_table(report))
    console.print(
        f"[bold]Total: {fmt_points(report.score, report.max_score)} ({percent(report):.0f} %)[/bold]", highlight=False
    )
