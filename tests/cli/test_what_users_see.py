"""What students, instructors and platforms see (issue 14): notes in every output, the real cause first, files
readable by others, default report folders per submission, not_found is an error, a single script with --task."""
from __future__ import annotations

import io
import json
import os
import stat
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from rich.console import Console

from grader.cli import default_out, main
from grader.platforms import github, gradescope, junit, prairielearn
from grader.report import CriterionResult, SubmissionReport, TaskReport
from grader.reports.advice import command_rate_note
from grader.reports.cause import node_cause
from grader.reports.files import write_atomic
from grader.reports.plots import _command_figure, _ideal_outline, _path_figure
from grader.reports.table import print_report
from grader.wording import tidy

from . import fakes
from .validators import decode_github_output

NOTE = "published 202 messages on /turtle1/cmd_vel; this robot listens on /cmd_vel"
CRASH = "move_circle.py stopped with an uncaught NameError at move_circle.py line 16 (`print(x)`): name 'x' is not defined"
TAB = "move_circle.py stopped with an uncaught TabError: inconsistent use of tabs and spaces in indentation (line 5)"


def report_with(diagnostics: list[str], passed: bool = True) -> SubmissionReport:
    criterion = CriterionResult(id="velocity_limits", title="Velocity limits", score=2.0 if passed else 0.0,
                                max_score=2.0, passed=passed, feedback="No velocity command reached the robot: "
                                "publish geometry_msgs/Twist messages on /cmd_vel.",
                                measured={"n_violations": 0, "n_messages": 0})
    task = TaskReport(id="move_circle", title="Circle", status="graded", score=criterion.score, max_score=2.0,
                      criteria=[criterion], diagnostics=diagnostics)
    return SubmissionReport(submission="alice", tasks=[task]).total()


def console_text(report: SubmissionReport, width: int = 80) -> str:
    buffer = io.StringIO()
    print_report(Console(file=buffer, width=width, color_system=None), report)
    return " ".join(buffer.getvalue().replace("│", " ").split())


@pytest.mark.parametrize("render", [
    console_text,
    lambda r: json.dumps(gradescope.gradescope_results(r)),
    lambda r: json.dumps(prairielearn.prairielearn_results(r)),
    junit.junit_xml,
    github.step_summary,
], ids=["console", "gradescope", "prairielearn", "junit", "classroom-summary"])
def test_noticed_notes_reach_every_output(render):
    assert "this robot listens on /cmd_vel" in render(report_with([NOTE]))


def test_a_crash_leads_every_output():
    report = report_with([NOTE, CRASH], passed=False)
    console = console_text(report)
    assert console.index("Your node crashed") < console.index("Velocity limits")
    assert "Your node had crashed (see the error above); fix that first. No velocity command" in console
    assert "NameError" in gradescope.gradescope_results(report)["output"]
    assert "NameError" in github.runner_result(report)["tests"][0]["message"]


def test_a_node_that_never_ran_is_told_so_not_about_topics():
    report = report_with([TAB], passed=False)
    assert node_cause(report.tasks[0]).never_ran
    console = console_text(report)
    assert "Your node never ran" in console and "TabError" in console
    assert "publish geometry_msgs/Twist" not in console and "0 of 0" not in console


def test_a_node_that_ran_normally_has_no_cause():
    assert node_cause(report_with([NOTE]).tasks[0]) is None


INTERRUPTED = ("figure_eight.py stopped with an uncaught rospy.exceptions.ROSInterruptException at figure_eight.py "
               "line 53 (`rate.sleep()`): ROS shutdown request")


def test_rate_sleep_raising_at_ctrl_c_is_not_called_a_crash():
    """rospy's Rate.sleep() raises ROSInterruptException once the node is shut down: a node without try/except
    ends that way at every Ctrl+C; its lost criteria must keep their own feedback, not 'fix the crash first'."""
    report = report_with([INTERRUPTED, NOTE], passed=False)
    assert node_cause(report.tasks[0]) is None
    console = console_text(report)
    assert "crashed" not in console and "ROSInterruptException" in console  # still noticed, not the lead
    assert node_cause(report_with([INTERRUPTED, CRASH], passed=False).tasks[0]).note == CRASH
    dotted = CRASH.replace("uncaught NameError", "uncaught genpy.message.SerializationError")
    assert node_cause(report_with([dotted], passed=False).tasks[0]).note == dotted


def test_console_table_fits_80_columns_without_one_word_lines():
    buffer = io.StringIO()
    print_report(Console(file=buffer, width=80, color_system=None), fakes.make_report())
    lines = buffer.getvalue().splitlines()
    assert all(len(line) <= 80 for line in lines)
    feedback_lines = [line for line in lines if "Two corners" in line]
    assert feedback_lines and "off." in feedback_lines[0]  # the feedback sentence stays on one line


@pytest.mark.parametrize("umask, mode", [(0o022, 0o644), (0o077, 0o600), (0o002, 0o664)])
def test_written_files_honour_the_umask(tmp_path, umask, mode):
    previous = os.umask(umask)
    try:
        path = write_atomic(tmp_path / "report.json", "{}")
    finally:
        os.umask(previous)
    assert stat.S_IMODE(path.stat().st_mode) == mode


@pytest.mark.parametrize("relative, expected", [
    ("alice/move_circle.py", "alice"),
    ("ws/src/bob_pkg/scripts/move_circle.py", "bob_pkg"),
    ("ws/src", "ws"),
    ("carol.zip", "carol"),
])
def test_default_report_folder_is_named_after_the_submission(tmp_path, relative, expected):
    path = tmp_path / relative
    path.parent.mkdir(parents=True, exist_ok=True)
    if path.suffix:
        path.write_text("")
    else:
        path.mkdir(exist_ok=True)
    assert default_out(path).name == expected


def test_not_found_task_is_an_error_exit(grading, submission, monkeypatch, capsys):
    module = fakes.grading_module()
    module.grade_submission = lambda path, out, tasks=None, rubrics=None, jobs=1: SubmissionReport(submission=str(path), tasks=[
        TaskReport(id="move_square", status="not_found", max_score=10.0, message="no file named move_square.py")]).total()
    fakes.install(monkeypatch, "grader.grading", module)
    assert main(["check", str(submission), "--out", "out", "--task", "move_square"]) == 2
    assert "no script found for move_square" in capsys.readouterr().err


def test_ungradable_submission_posts_zero_of_the_real_maximum(grading, tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("GITHUB_OUTPUT", str(tmp_path / "gh_output"))
    assert main(["check", "missing", "--task", "move_circle", "--github-result", "--gradescope", "r.json"]) == 2
    result = decode_github_output((tmp_path / "gh_output").read_text())
    assert github.classroom_points(result) == (0.0, 10.0)
    assert json.loads(Path("r.json").read_text())["tests"][0]["max_score"] == 10.0


def test_help_describes_every_argument(capsys):
    for command in ("check", "batch", "score", "tasks", "bench", "gradescope-package"):
        with pytest.raises(SystemExit):
            main([command, "--help"])
        text = capsys.readouterr().out
        options = text.split("options:")[-1]
        for line in options.splitlines():
            stripped = line.strip()
            if stripped.startswith("-") and "  " not in stripped and not stripped.endswith(","):
                pytest.fail(f"{command}: {stripped!r} has no description")


def test_tasks_table_is_not_cut_at_80_columns(grading, monkeypatch, capsys):
    monkeypatch.setenv("COLUMNS", "80")
    assert main(["tasks"]) == 0
    out = capsys.readouterr().out
    assert "…" not in out and all(len(line) <= 80 for line in out.splitlines())


def test_a_script_with_another_name_is_graded_for_the_task_given(tmp_path):
    from grader.grading import _locate
    from grader.rubric import load_rubrics

    script = tmp_path / "my_node.py"
    script.write_text("#!/usr/bin/env python3\n")
    node = load_rubrics()["move_circle"].nodes[0]
    found, notes = _locate(script, node, True)
    assert found == script and "Graded my_node.py as move_circle.py" in notes[0]


def commands_at(rate_hz: float, seconds: float, origin: str = "node"):
    from grader.recording.series import CommandSeries

    t = np.arange(0.0, seconds, 1.0 / rate_hz)
    n = len(t)
    return CommandSeries(t, np.zeros((n, 3)), np.zeros((n, 3)), np.array(["/cmd_vel"] * n, dtype=object),
                         np.array(["/mover"] * n, dtype=object), np.array([origin] * n, dtype=object))


def test_a_flood_of_commands_is_told_its_rate_and_why_rate_sleep_matters():
    note = command_rate_note(commands_at(500, 20), shutdown_s=None)
    assert note is not None and "about 500 a second" in note and "rate.sleep()" in note


def test_a_10_hz_loop_gets_no_rate_advice():
    assert command_rate_note(commands_at(10, 20), shutdown_s=None) is None


def test_the_graders_own_commands_are_not_counted_as_a_flood():
    assert command_rate_note(commands_at(500, 20, origin="grader"), shutdown_s=None) is None


def clockwise_path(kind: str):
    """A path that starts at the origin heading +x and turns right (clockwise)."""
    angles = np.linspace(0, 2 * np.pi, 200)
    if kind == "circle":  # centre (0, -0.5)
        x, y, yaw = 0.5 * np.sin(angles), -0.5 + 0.5 * np.cos(angles), -angles
    else:
        x = np.concatenate([np.linspace(0, 1, 50), np.ones(50), np.linspace(1, 0, 50), np.zeros(50)])
        y = np.concatenate([np.zeros(50), np.linspace(0, -1, 50), -np.ones(50), np.linspace(-1, 0, 50)])
        yaw = np.repeat([0.0, -np.pi / 2, -np.pi, np.pi / 2], 50)
    t = np.linspace(0, 40, len(x))
    return SimpleNamespace(t=t, x=x, y=y, yaw=yaw, vx=np.full(len(t), 0.1), wz=np.full(len(t), -0.2))


@pytest.mark.parametrize("kind", ["circle", "square"])
def test_the_ideal_shape_is_drawn_on_the_side_the_robot_turned_to(kind):
    xs, ys, _ = _ideal_outline(kind, clockwise_path(kind))
    assert ys.max() <= 1e-9 and ys.min() < -0.9  # below the start: the robot turned right


def test_the_path_plot_shows_the_run_after_ctrl_c_with_a_mark():
    figure = _path_figure(clockwise_path("circle"), "circle", has_truth=True, stop_s=30.0)
    labels = [line.get_label() for line in figure.axes[0].get_lines()]
    assert "after Ctrl+C" in labels and "Ctrl+C" in labels


def test_the_command_plot_covers_the_whole_recording():
    path = clockwise_path("circle")
    figure = _command_figure(commands_at(10, 20), None, 20.0, path)
    assert figure.axes[0].get_xlim()[1] >= path.t[-1]


@pytest.mark.parametrize("rendered, expected", [
    ("All 1 velocity commands were within the limits.", "The only velocity command was within the limits."),
    ("All 4 sides were between 1.02 m and 1.02 m; expected 1 m.", "All 4 sides were 1.02 m; expected 1 m."),
    ("All 4 turns were between 89.9° and 89.9°.", "All 4 turns were 89.9°."),
    ("The robot drove a circle of radius n/a m.", "The robot drove a circle of radius not measured."),
    ("All 12 velocity commands were within the limits.", "All 12 velocity commands were within the limits."),
    ("sides between 1.02 and 1.025 m", "sides between 1.02 and 1.025 m"),
    ("exception: n/a", "exception: n/a"),
    ("2 loops of 1.00–1.00 m, each closing within 0.01 m.", "2 loops of 1.00 m, each closing within 0.01 m."),
    ("turns of 89.9°–89.9°.", "turns of 89.9°."),
    ("2 loops of 0.98–1.00 m.", "2 loops of 0.98–1.00 m."),
    ("loops of 1.0–1.00 m", "loops of 1.0–1.00 m"),
    ("scored 11.0–1.00 m", "scored 11.0–1.00 m"),
])
def test_feedback_wording_reads_right_whatever_the_numbers(rendered, expected):
    assert tidy(rendered) == expected


def test_rubric_feedback_is_tidied_when_rendered():
    from grader.rubric import render

    assert render("All {n} velocity commands were within the limits.", {"n": 1}) == (
        "The only velocity command was within the limits.")


def test_histogram_counts_whole_students(monkeypatch):
    from matplotlib.figure import Figure

    from grader.reports import gradebook

    made: list[Figure] = []

    class Recorded(Figure):
        def __init__(self, *args, **kwargs):
            super().__init__(*args, **kwargs)
            made.append(self)

    monkeypatch.setattr(gradebook, "Figure", Recorded)
    gradebook.histogram_png([50.0, 90.0])  # one student per bar: matplotlib would tick at 0.2, 0.4, ...
    ticks = made[0].axes[0].get_yticks()
    assert len(ticks) and all(float(tick).is_integer() for tick in ticks)


TAB_ERROR_NODE = "#!/usr/bin/env python3\nimport rospy\nif True:\n\tx = 1\n        y = 2\n"
CRASHING_NODE = """#!/usr/bin/env python3
import rospy
from geometry_msgs.msg import Twist
rospy.init_node("mover")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
rate = rospy.Rate(10)
for n in range(1, 1000):
    twist = Twist()
    twist.linear.x, twist.angular.z = 0.1, 0.2
    pub.publish(twist)
    if n == 50:
        print(undefined_name)
    rate.sleep()
"""


@pytest.mark.slow
@pytest.mark.parametrize("source, never_ran, where", [(TAB_ERROR_NODE, True, "TabError"),
                                                      (CRASHING_NODE, False, "NameError")])
def test_real_runs_of_broken_nodes_lead_with_their_error(tmp_path, source, never_ran, where):
    from grader.grading import grade_submission

    script = tmp_path / "move_circle.py"
    script.write_text(source)
    script.chmod(0o755)
    report = grade_submission(script, tmp_path / "out", ["move_circle"])
    cause = node_cause(report.tasks[0])
    assert cause is not None and cause.never_ran is never_ran and where in cause.headline
    assert console_text(report).index(where) < console_text(report).index("✘" if never_ran else "✔")
