"""Writes a submission's report folder: report.json (the contract), report.md, report.html and the plot PNGs."""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from grader.report import SubmissionReport
from grader.reports.files import write_atomic
from grader.reports.html import render_html
from grader.reports.markdown import render_markdown
from grader.reports.plots import Plot, report_plots

PLOTS_DIR = "plots"


@dataclass
class ReportFiles:
    """What was written, and the plots and notes the platform outputs reuse."""

    folder: Path
    json: Path
    markdown: Path
    html: Path
    plots: list[Plot] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)


def write_report_folder(report: SubmissionReport, folder: Path, with_plots: bool = True) -> ReportFiles:
    """Write the report files into folder; report.json goes last, so its presence means the folder is complete."""
    plots, notes = report_plots(report) if with_plots else ([], [])
    for plot in plots:
        write_atomic(folder / PLOTS_DIR / plot.filename, plot.png)
    markdown = write_atomic(
        folder / "report.md", render_markdown(report, plots, lambda p: f"{PLOTS_DIR}/{p.filename}", notes)
    )
    html = write_atomic(folder / "report.html", render_html(report, plots, notes))
    json_path = write_atomic(folder / "report.json", report.model_dump_json(indent=2))
    return ReportFiles(folder, json_path, markdown, html, plots, notes)
