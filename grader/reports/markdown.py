"""Markdown report (report.md, the GitHub step summary, Gradescope test output): tables a beginner can read."""
from __future__ import annotations

from collections.abc import Callable, Sequence

from grader.report import CriterionResult, SubmissionReport, TaskReport
from grader.reports.plots import Plot
from grader.reports.text import fmt_points, foxglove_help, is_public, measured_text, percent, task_status_text

HIDDEN_TEXT = "(details shown later)"


def cell(text: str) -> str:
    """Text made safe for one Markdown table cell."""
    return text.replace("\\", "\\\\").replace("|", "\\|").replace("\r", "").replace("\n", "<br>")


def mark(criterion: CriterionResult) -> str:
    """✅ for a passed criterion, ❌ otherwise."""
    return "✅" if criterion.passed else "❌"


def criterion_markdown(criterion: CriterionResult, public_only: bool = False) -> str:
    """One criterion as a short Markdown block (Gradescope's per-test output)."""
    if public_only and not is_public(criterion):
        return f"{mark(criterion)} {fmt_points(criterion.score, criterion.max_score)} points. {HIDDEN_TEXT}"
    lines = [f"{mark(criterion)} **{fmt_points(criterion.score, criterion.max_score)} points**"]
    if criterion.feedback:
        lines.append("")
        lines.append(criterion.feedback)
    measured = measured_text(criterion.measured)
    if measured:
        lines.append("")
        lines.append(f"Measured: {measured}")
    if criterion.scenario:
        lines.append("")
        lines.append(f"Scenario: `{criterion.scenario}`")
    return "\n".join(lines)


def task_table(task: TaskReport, public_only: bool = False) -> list[str]:
    """A task's criteria as a Markdown table (empty when it has none)."""
    if not task.criteria:
        return []
    lines = ["| | Criterion | Points | Measured | Feedback |", "|---|---|---|---|---|"]
    for criterion in task.criteria:
        hidden = public_only and not is_public(criterion)
        measured = "" if hidden else measured_text(criterion.measured)
        feedback = HIDDEN_TEXT if hidden else criterion.feedback
        lines.append(
            f"| {mark(criterion)} | {cell(criterion.title or criterion.id)} "
            f"| {fmt_points(criterion.score, criterion.max_score)} | {cell(measured)} | {cell(feedback)} |"
        )
    return lines


def render_markdown(
    report: SubmissionReport,
    plots: Sequence[Plot] = (),
    image_src: Callable[[Plot], str] | None = None,
    notes: Sequence[str] = (),
    public_only: bool = False,
    heading_level: int = 1,
) -> str:
    """The whole report as Markdown; images are linked through image_src (omitted when None)."""
    h = "#" * heading_level
    lines = [
        f"{h} rosgrade report: {report.submission}",
        "",
        f"**Score: {fmt_points(report.score, report.max_score)} ({percent(report):.0f} %)** · rosgrade {report.rosgrade_version}",
        "",
        "| Task | Status | Points |",
        "|---|---|---|",
    ]
    lines += [f"| {cell(t.title or t.id)} | {t.status} | {fmt_points(t.score, t.max_score)} |" for t in report.tasks]
    for task in report.tasks:
        lines += ["", f"{h}# {task.title or task.id} (`{task.id}`): {fmt_points(task.score, task.max_score)}", ""]
        status = task_status_text(task)
        if status:
            lines += [f"> ⚠️ {status}", ""]
        lines += task_table(task, public_only)
        if task.diagnostics:
            lines += ["", "What rosgrade noticed while running your node:", ""]
            lines += [f"- {d}" for d in task.diagnostics]
        if image_src is not None:
            for plot in (p for p in plots if p.task == task.id):
                lines += ["", f"![{plot.title}]({image_src(plot)})"]
        if task.recordings:
            lines += ["", "Recordings: " + ", ".join(f"`{r}`" for r in task.recordings)]
    if notes:
        lines += ["", "Notes:", ""] + [f"- {n}" for n in notes]
    recordings = [r for t in report.tasks for r in t.recordings]
    if recordings:
        lines += ["", f"{h}# Looking at a recording", ""] + [f"- {line}" for line in foxglove_help(recordings[0])]
    return "\n".join(lines) + "\n"
