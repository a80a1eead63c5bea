"""Report rendering: text formatting, Markdown, HTML and the plots, from fake reports and recordings."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from grader.reports.html import render_html
from grader.reports.escape import markdown_cell
from grader.reports.markdown import render_markdown
from grader.reports.measured import describe
from grader.reports.plots import Plot, fit_circle_centre, printed_positions, shape_for, task_plots
from grader.reports.text import fmt_number, fmt_points

from . import fakes


def test_numbers_are_short():
    assert [fmt_number(v) for v in (0.49712, 4.0, 12, True, None, 1e-6)] == ["0.497", "4", "12", "yes", "–", "1e-06"]


def test_points_are_rounded_for_people():
    assert [fmt_points(15.297, 16), fmt_points(0.04, 1), fmt_points(0, 2), fmt_points(7.999, 8)] == [
        "15.3 / 16", "0.04 / 1", "0 / 2", "8 / 8"]


def test_measured_shows_the_criterions_quantity_and_its_companions_in_words():
    text = describe({"radius": 0.9998, "cmd_radius": 1.0, "cmd_linear": 0.2, "cmd_angular": 0.2,
                     "revolutions": 0.6, "arc_length": 3.77, "swapped_radius": 1.0, "rms_residual": 1e-16})
    assert text == "circle radius 1 m; your commands give v/ω = 0.2/0.2 = 1 m; 0.6 laps, 3.77 m driven"


def test_measured_hides_internal_counters_and_shows_limits_with_units():
    text = describe({"violating_fraction": 0.995, "n_messages": 201, "n_violations": 200, "n_nonfinite": 0,
                     "n_off_axis": 0, "max_linear": 0.5, "max_angular": 1.0, "limit_linear": 0.26,
                     "limit_angular": 1.82})
    assert text == ("200 of 201 commands over the limits; fastest linear.x 0.5 m/s (limit 0.26 m/s); "
                    "fastest angular.z 1 rad/s (limit 1.82 rad/s)")
    assert "nonfinite" not in text and "off axis" not in text


def test_measured_skips_values_that_were_not_measured():
    assert describe({"rest_time": float("nan"), "zero_command_delay": None, "moving_at_end": True}) == (
        "still moving when the recording ended")
    assert "n/a" not in describe({"final_x": None, "final_distance": float("nan")})


def test_measured_collapses_a_range_whose_ends_are_equal():
    assert describe({"side_mean": 1.02, "side_min": 1.02, "side_max": 1.02}) == "sides 1.02 m long"
    assert describe({"side_mean": 1.0, "side_min": 0.98, "side_max": 1.02}) == "sides 0.98–1.02 m long"


def test_unknown_quantities_of_new_metrics_are_shown_by_name_and_unit():
    assert describe({"spiral_pitch_m": 0.25, "other": 3}) == "spiral pitch 0.25 m"


def test_markdown_cells_escape_pipes_and_newlines():
    assert markdown_cell("a | b\nc") == "a \\| b<br>c"


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


def test_printed_positions_skip_the_console_prefix_s_times():
    line = "[INFO] [1700000000.100000, 0.000000]: The 'odom_subscriber' node is active..."
    rows = printed_positions([(0.0, "stdout", line), (1.0, "stdout", "(x,y,θz) = (0.500, -0.200, 1.571)")])
    assert rows.tolist() == [[1.0, 0.5, -0.2]]


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


def test_unreadable_recordings_get_a_note_each_in_report_order_with_any_number_of_jobs(tmp_path):
    from grader.report import SubmissionReport
    from grader.reports.plots import report_plots

    missing = [str(tmp_path / f"{name}.mcap") for name in ("a", "b", "c")]
    report = SubmissionReport(submission="s", tasks=[fakes.circle_task(recordings=missing)]).total()
    for jobs in (1, 2, 5):
        plots, notes = report_plots(report, jobs=jobs)
        assert plots == [] and [n.split("could not plot ")[1].split(":")[0] for n in notes] == ["a.mcap", "b.mcap",
                                                                                                 "c.mcap"]
