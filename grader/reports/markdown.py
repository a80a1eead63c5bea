"""Markdown report (report.md, the GitHub step summary, Gradescope test output): tables a beginner can read."""
from __future__ import annotations

from collections.abc import Callable, Sequence

from grader.report import CriterionResult, SubmissionReport, TaskReport
from grader.reports.cause import criterion_feedback, criterion_measured, lead_lines, noticed
from grader.reports.escape import markdown, markdown_cell, one_line
from grader.reports.measured import describe
from grader.reports.plots import Plot
from grader.reports.text import NOTICED_HEADING, fmt_points, foxglove_help, is_public, percent, watch_first_text

HIDDEN_TEXT = "(details shown later)"


def code(text: str) -> str:
    """Text as inline code whatever backticks it holds (the fence is longer than any run of them inside)."""
    text = one_line(text)
    run, fence = 0, 1
    for char in text:
        run = run + 1 if char == "`" else 0
        fence = max(fence, run + 1)
    ticks = "`" * fence
    return f"{ticks} {text} {ticks}" if text.startswith("`") or text.endswith("`") else f"{ticks}{text}{ticks}"


def mark(criterion: CriterionResult) -> str:
    """✅ for a passed criterion, ❌ otherwise."""
    return "✅" if criterion.passed else "❌"


def criterion_markdown(criterion: CriterionResult, public_only: bool = False) -> str:
    """One criterion as a short Markdown block (Gradescope's per-test output)."""
    if public_only and not is_public(criterion):
        return f"{mark(criterion)} {fmt_points(criterion.score, criterion.max_score)} points. {HIDDEN_TEXT}"
    lines = [f"{mark(criterion)} **{fmt_points(criterion.score, criterion.max_score)} points**"]
    if criterion.feedback:
        lines += ["", markdown(criterion.feedback)]
    measured = describe(criterion.measured)
    if measured:
        lines += ["", f"Measured: {markdown(measured, line_start=False)}"]
    if criterion.scenario:
        lines += ["", f"Scenario: {markdown(criterion.scenario, line_start=False)}"]
    return "\n".join(lines)


def noticed_markdown(notes: Sequence[str], heading: str = NOTICED_HEADING) -> list[str]:
    """The notes rosgrade made while running the node, as a Markdown list under a heading (none: no lines)."""
    if not notes:
        return []
    return [f"{heading}:", ""] + [f"- {markdown_cell(n)}" for n in notes]


def task_table(task: TaskReport, public_only: bool = False) -> list[str]:
    """A task's criteria as a Markdown table (empty when it has none)."""
    if not task.criteria:
        return []
    lines = ["| | Criterion | Points | Measured | Feedback |", "|---|---|---|---|---|"]
    for criterion in task.criteria:
        hidden = public_only and not is_public(criterion)
        measured = "" if hidden else criterion_measured(task, criterion)
        feedback = HIDDEN_TEXT if hidden else criterion_feedback(task, criterion)
        lines.append(
            f"| {mark(criterion)} | {markdown_cell(criterion.title or criterion.id)} "
            f"| {fmt_points(criterion.score, criterion.max_score)} | {markdown_cell(measured)} | {markdown_cell(feedback)} |"
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
        f"{h} rosgrade report: {markdown(report.submission, line_start=False)}",
        "",
        f"**Score: {fmt_points(report.score, report.max_score)} ({percent(report):.0f} %)** · "
        f"rosgrade {markdown(report.rosgrade_version, line_start=False)}"
        + (f" · nodes isolated by {markdown(report.isolation, line_start=False)}" if report.isolation else ""),
        "",
        "| Task | Status | Points |",
        "|---|---|---|",
    ]
    lines += [f"| {markdown_cell(t.title or t.id)} | {markdown_cell(t.status)} | {fmt_points(t.score, t.max_score)} |"
              for t in report.tasks]
    for task in report.tasks:
        lines += ["", f"{h}# {markdown(task.title or task.id, line_start=False)} ({code(task.id)}): {fmt_points(task.score, task.max_score)}", ""]
        lines += [line for lead in lead_lines(task) for line in (f"> ⚠️ {markdown_cell(lead)}", "")]
        lines += task_table(task, public_only)
        if task.diagnostics:
            lines += [""] + noticed_markdown(noticed(task))
        if image_src is not None:
            for plot in (p for p in plots if p.task == task.id):
                lines += ["", f"![{markdown(plot.title, line_start=False)}]({image_src(plot)})"]
        if task.recordings:
            lines += ["", "Recordings: " + ", ".join(code(r) for r in task.recordings)]
    if notes:
        lines += ["", "Notes:", ""] + [f"- {markdown_cell(n)}" for n in notes]
    recordings = [r for t in report.tasks for r in t.recordings]
    if recordings:
        lines += ["", f"{h}# Looking at a recording", "", f"- {markdown(watch_first_text(report))}"]
        lines += [f"- {markdown(line)}" for line in foxglove_help(recordings[0])]
    return "\n".join(lines) + "\n"
