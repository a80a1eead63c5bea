"""Human-readable reports of a graded submission: Markdown, self-contained HTML, plots and the console table."""
from __future__ import annotations

from grader.reports.folder import ReportFiles, write_report_folder

__all__ = ["ReportFiles", "write_report_folder"]
