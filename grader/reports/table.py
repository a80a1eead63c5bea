"""The console view of a report (rich): per task, one block per criterion that stays readable in 80 columns."""
from __future__ import annotations

from rich.console import Console, Group
from rich.padding import Padding
from rich.table import Table
from rich.text import Text

from grader.report import CriterionResult, SubmissionReport, TaskReport
from grader.reports.cause import criterion_feedback, criterion_measured, lead_lines, noticed
from grader.reports.escape import one_line, plain
from grader.reports.text import NOTICED_HEADING, fmt_points, percent

INDENT = 2


def _indented(text: str, style: str = "") -> Padding:
    """Wrapped text indented under its criterion, so every wrapped line keeps the indent."""
    return Padding(Text(plain(text), style=style), (0, 0, 0, INDENT))


def _criterion_cell(task: TaskReport, criterion: CriterionResult) -> Group:
    style, mark = ("green", "✔") if criterion.passed else ("red", "✘")
    parts: list[Text | Padding] = [Text(f"{mark} {one_line(criterion.title or criterion.id)}", style=style)]
    measured = criterion_measured(task, criterion)
    if measured:
        parts.append(_indented(measured, "dim"))
    feedback = criterion_feedback(task, criterion)
    if feedback:
        parts.append(_indented(feedback.splitlines()[0]))
    return Group(*parts)


def report_table(report: SubmissionReport) -> Table:
    """One row per criterion (title, measured values, one line of feedback) with its points on the right."""
    table = Table(title=Text(f"rosgrade: {one_line(report.submission)}"), expand=False, show_lines=False)
    table.add_column("Task / criterion", ratio=1)
    table.add_column("Points", justify="right", no_wrap=True)
    for task in report.tasks:
        table.add_row(Text(f"{one_line(task.title or task.id)} ({task.id})", style="bold"),
                      Text(fmt_points(task.score, task.max_score), style="bold"))
        for line in lead_lines(task):
            table.add_row(Text(plain(line), style="yellow"), "")
        for criterion in task.criteria:
            table.add_row(_criterion_cell(task, criterion), fmt_points(criterion.score, criterion.max_score))
        notes = noticed(task)
        if notes:
            table.add_row(Group(Text(f"{NOTICED_HEADING}:", style="italic"),
                                *(_indented(f"• {one_line(n)}") for n in notes)), "")
        table.add_section()
    return table


def print_report(console: Console, report: SubmissionReport) -> None:
    """Print the table and the total."""
    console.print(report_table(report))
    console.print(Text(f"Total: {fmt_points(report.score, report.max_score)} ({percent(report):.0f} %)", style="bold"))
    if report.isolation:
        console.print(Text(f"Nodes isolated by {report.isolation}.",
                           style="yellow" if "rlimits" in report.isolation else "dim"))
