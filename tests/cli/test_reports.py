"""Report rendering: text formatting, Markdown, HTML and the plots, from fake reports and recordings."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from grader.reports.html import render_html
from grader.reports.markdown import cell, render_markdown
from grader.reports.plots import Plot, fit_circle_centre, printed_positions, shape_for, task_plots
from grader.reports.text import fmt_number, measured_text

from . import fakes


def test_numbers_are_short():
    assert [fmt_number(v) for v in (0.49712, 4.0, 12, True, None, 1e-6)] == ["0.497", "4", "12", "yes", "–", "1e-06"]


def test_measured_values_pair_with_expected_and_show_units():
    text = measured_text({"radius_m": 0.497, "expected_radius_m": 0.5, "max_linear_mps": 0.1, "corner_deg": 91.0})
    assert text == "radius 0.497 m (expected 0.5 m), max linear 0.1 m/s, corner 91°"


def test_markdown_cells_escape_pipes_and_newlines():
    assert cell("a | b\nc") == "a \\| b<br>c"


def test_markdown_warns_about_tasks_that_were_not_graded():
    text = render_markdown(fakes.make_report(square_status="timeout"))
    assert "> ⚠️ Your node did not finish within the time limit." in text


def test_html_escapes_student_text_and_inlines_plots():
    report = fakes.make_report()
    report.tasks[0].criteria[0].feedback = "<script>alert(1)</script>"
    html = render_html(report, [Plot("move_circle", "nominal", "path", "path", b"\x89PNG")])
    assert "<script>" not in html and "&lt;script&gt;" in html and "data:image/png;base64,iVBORw==" in html


def test_task_kinds_come_from_the_task_id():
    assert [shape_for(t) for t in ("move_circle", "move_square", "odom_subscriber", "move_distance")] == [
        "circle", "square", "printed", None]


def test_circle_fit_finds_the_centre():
    angles = np.linspace(0, 5, 50)
    assert np.allclose(fit_circle_centre(1 + 0.5 * np.cos(angles), -2 + 0.5 * np.sin(angles)), (1, -2))
    assert fit_circle_centre(np.arange(5.0), np.zeros(5)) is None


def test_printed_positions_are_parsed_from_labelled_or_plain_lines():
    rows = printed_positions([(1.0, "stdout", "x=0.50 [m], y=-1.25 [m], yaw=10.0 [degrees]."),
                              (2.0, "stdout", "(0.1, 0.2, 0.3)"), (3.0, "stdout", "starting up")])
    assert rows.tolist() == [[1.0, 0.5, -1.25], [2.0, 0.1, 0.2]]


def test_circle_task_gets_path_and_command_plots():
    plots = task_plots("move_circle", "nominal", fakes.FakeRecording(Path("x.mcap")))
    assert [p.name for p in plots] == ["path", "commands"]
    assert all(p.png.startswith(b"\x89PNG") for p in plots)


def test_odom_subscriber_gets_a_printed_vs_true_plot():
    plots = task_plots("odom_subscriber", "nominal", fakes.FakeRecording(Path("x.mcap")))
    assert "printed" in [p.name for p in plots]


def test_square_plot_without_ground_truth_uses_odometry():
    plots = task_plots("move_square", "nominal", fakes.FakeRecording(Path("x.bag"), ground_truth=False, metadata={}))
    assert [p.name for p in plots] == ["path", "commands"]
