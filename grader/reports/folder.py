"""Writes a submission's report folder: report.json (the contract), report.md, report.html with its replays, the plots."""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from grader import timing
from grader.report import SubmissionReport
from grader.reports.advice import with_advice
from grader.reports.files import write_atomic
from grader.reports.html import render_html
from grader.reports.markdown import render_markdown
from grader.reports.plots import Plot, report_media
from grader.reports.replay import Replay

PLOTS_DIR = "plots"


@dataclass
class ReportFiles:
    """What was written, and the plots and notes the platform outputs reuse."""

    folder: Path
    report: SubmissionReport  # the report as written: with the advice read from its recordings
    json: Path
    markdown: Path
    html: Path
    plots: list[Plot] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    replays: list[Replay] = field(default_factory=list)


def write_report_folder(report: SubmissionReport, folder: Path, with_plots: bool = True,
                        jobs: int = 1) -> ReportFiles:
    """Write the report files into folder (``jobs`` processes drawing the plots); report.json goes last, so its
    presence means the folder is complete."""
    with timing.stage("advice"):
        report = with_advice(report) if with_plots else report
    with timing.stage("plots"):
        plots, replays, notes = report_media(report, jobs=jobs) if with_plots else ([], [], [])
    with timing.stage("report files"):
        return _write(report, folder, plots, notes, replays)


def _write(report: SubmissionReport, folder: Path, plots: list[Plot], notes: list[str],
           replays: list[Replay]) -> ReportFiles:
    for plot in plots:
        write_atomic(folder / PLOTS_DIR / plot.filename, plot.png)
    markdown = write_atomic(
        folder / "report.md", render_markdown(report, plots, lambda p: f"{PLOTS_DIR}/{p.filename}", notes)
    )
    html = write_atomic(folder / "report.html", render_html(report, plots, notes, replays))
    json_path = write_atomic(folder / "report.json", report.model_dump_json(indent=2))
    return ReportFiles(folder, report, json_path, markdown, html, plots, notes, replays)
