"""`rosgrade check`: exit codes, the table, the report folder, --json purity and one-line input errors."""
from __future__ import annotations

import json
import zipfile
from pathlib import Path

import pytest

from grader.cli import main
from grader.report import SubmissionReport

from . import fakes
from .validators import validate_gradescope


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_graded_submission_exits_0(grading, submission, capsys):
    code, _, _ = run(capsys, "check", str(submission), "--out", "out")
    assert code == 0


def test_table_shows_tasks_criteria_points_measured_and_feedback(grading, submission, capsys):
    _, out, _ = run(capsys, "check", str(submission), "--out", "out")
    for text in ("move_circle", "move_square", "Circle radius", "4 / 4", "radius 0.497 m",
                 "Ended 2 cm from the start.", "Total: 14.5 / 20"):
        assert text in out, text


def test_footer_says_where_the_report_is(grading, submission, capsys):
    _, out, _ = run(capsys, "check", str(submission), "--out", "out")
    assert "report.html" in " ".join(out.split())


def test_report_folder_has_json_markdown_and_self_contained_html(grading, submission, capsys):
    run(capsys, "check", str(submission), "--out", "out")
    report = SubmissionReport.model_validate_json(Path("out/report.json").read_text())
    assert report.score == 14.5 and report.max_score == 20
    assert "| ✅ | Circle radius | 4 / 4 |" in Path("out/report.md").read_text()
    html = Path("out/report.html").read_text()
    assert html.startswith("<!DOCTYPE html>") and "<link" not in html and "src=\"plots/" not in html


def test_default_report_folder_is_named_after_the_submission(grading, submission, capsys):
    run(capsys, "check", str(submission))
    assert Path("rosgrade-out/alice_pkg/report.json").is_file()


def test_src_folder_report_is_named_after_the_workspace(grading, tmp_path, capsys):
    src = tmp_path / "catkin_ws" / "src"
    src.mkdir(parents=True)
    run(capsys, "check", str(src))
    assert Path("rosgrade-out/catkin_ws/report.json").is_file()


def test_json_stdout_is_exactly_the_report(grading, submission, capsys):
    code, out, err = run(capsys, "check", str(submission), "--out", "out", "--json")
    assert code == 0
    assert json.loads(out) == json.loads(Path("out/report.json").read_text())
    assert "Score 14.5 / 20" in err


def test_json_stdout_stays_clean_when_grading_prints(grading, tmp_path, capsys):
    noisy = tmp_path / "noisy.py"
    noisy.write_text("print('hi')\n")
    code, out, err = run(capsys, "check", str(noisy), "--out", "out", "--json")
    assert code == 0 and json.loads(out)["submission"] == str(noisy)
    assert "noise" in err and "noise" not in out


def test_task_option_is_passed_to_grading(grading, submission, capsys):
    _, out, _ = run(capsys, "check", str(submission), "--task", "move_circle", "--out", "out", "--json")
    assert [t["id"] for t in json.loads(out)["tasks"]] == ["move_circle"]


@pytest.mark.parametrize(("threshold", "expected"), [("72.5", 0), ("50", 0), ("72.6", 1), ("100", 1)])
def test_fail_under(grading, submission, capsys, threshold, expected):
    code, _, err = run(capsys, "check", str(submission), "--out", "out", "--fail-under", threshold)
    assert code == expected
    assert ("below --fail-under" in err) == (expected == 1)


def test_fail_under_must_be_a_percentage(grading, submission, capsys):
    with pytest.raises(SystemExit) as exc:
        main(["check", str(submission), "--fail-under", "150"])
    assert exc.value.code == 2


def one_line_error(code: int, out: str, err: str) -> str:
    assert code == 2 and out == ""
    lines = err.strip().splitlines()
    # without namespaces rosgrade first warns that nodes are not confined (tests/isolation checks that warning)
    if lines and lines[0].startswith("Warning: "):
        lines = lines[next((i for i, line in enumerate(lines) if line.startswith("rosgrade: error: ")), 0):]
    assert len(lines) == 1 and lines[0].startswith("rosgrade: error: ") and "Traceback" not in err
    return lines[0]


def test_missing_path_is_exit_2_with_one_line(grading, capsys):
    line = one_line_error(*run(capsys, "check", "does/not/exist"))
    assert "no such file or folder" in line


def test_unreadable_zip_is_exit_2(grading, tmp_path, capsys):
    broken = tmp_path / "broken.zip"
    broken.write_bytes(b"PK\x03\x04 this is not really a zip")
    assert "not a readable zip file" in one_line_error(*run(capsys, "check", str(broken)))


def test_readable_zip_is_graded(grading, tmp_path, capsys):
    archive = tmp_path / "bob.zip"
    with zipfile.ZipFile(archive, "w") as z:
        z.writestr("bob/scripts/move_circle.py", "import rospy\n")
    assert run(capsys, "check", str(archive), "--out", "out")[0] == 0


def test_other_file_types_are_exit_2(grading, tmp_path, capsys):
    text = tmp_path / "notes.txt"
    text.write_text("hello")
    assert "expected a .py file" in one_line_error(*run(capsys, "check", str(text)))


def test_submission_error_is_exit_2_with_its_message(grading, tmp_path, capsys):
    bad = tmp_path / "bad_pkg"
    bad.mkdir()
    assert "no ROS scripts" in one_line_error(*run(capsys, "check", str(bad)))


def test_unknown_task_is_exit_2_and_lists_known_tasks(grading, submission, capsys):
    line = one_line_error(*run(capsys, "check", str(submission), "--task", "move_hexagon"))
    assert "move_hexagon" in line and "move_circle" in line


def test_grader_crash_is_exit_2_and_keeps_the_traceback_in_a_file(grading, tmp_path, capsys):
    crash = tmp_path / "crash_pkg"
    crash.mkdir()
    line = one_line_error(*run(capsys, "check", str(crash), "--out", "out", "--gradescope", "results.json"))
    assert "RuntimeError" in line
    assert "Traceback" in Path("out/rosgrade-error.txt").read_text()
    data = validate_gradescope(Path("results.json").read_text())
    assert data["score"] == 0 and "simulated crash" in data["tests"][0]["output"]


def test_no_command_is_a_usage_error(capsys):
    with pytest.raises(SystemExit) as exc:
        main([])
    assert exc.value.code == 2


def test_recordings_get_plots_and_foxglove_hint(grading, submission, capsys, monkeypatch):
    mcap = Path("circle.mcap")
    mcap.write_bytes(b"MCAP")
    report = fakes.make_report(str(submission), recordings=[str(mcap)])
    monkeypatch.setattr(fakes, "fake_grade_submission", lambda *a, **k: report)
    fakes.install(monkeypatch, "grader.grading", fakes.grading_module())
    _, out, _ = run(capsys, "check", str(submission), "--out", "out")
    flat = " ".join(out.split())
    assert "foxglove" in flat.lower() and "circle.mcap" in flat and "/odom.pose.pose.position.x" in flat
    assert Path("out/plots/move_circle-circle-path.png").is_file()
    assert "data:image/png;base64," in Path("out/report.html").read_text()
    assert "](plots/move_circle-circle-path.png)" in Path("out/report.md").read_text()
