"""Reports a resumed batch cannot keep: unreadable, from an older rosgrade, or made with another rubric.

Each is re-scored from its recordings when they are usable (no student code runs), else graded again; the
summary says how many and why, and grades.csv never mixes rubric versions.
"""
from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from grader.cli import main

from cli import fakes
from cli.conftest import calls

from .conftest import grades


@pytest.fixture
def graded(grading, klass, capsys) -> Path:
    assert main(["batch", str(klass), "--out", "out", "-j", "2"]) == 0
    capsys.readouterr()
    return Path("out")


def rerun(klass: Path, capsys: pytest.CaptureFixture[str]) -> str:
    assert main(["batch", str(klass), "--out", "out", "-j", "2"]) == 0
    return capsys.readouterr().err


def test_a_truncated_report_is_rescored_from_its_recordings(graded, klass, grading, reference, capsys):
    report = graded / "ann" / "report.json"
    report.write_text(report.read_text()[:200])
    err = rerun(klass, capsys)
    assert calls(grading).count("ann") == 1  # no student code ran again
    assert "Re-scored from their recordings (no code run): 1 (1: report.json unreadable" in err
    assert "Re-scored from their recordings (no code run): 1" in (graded / "summary.md").read_text()
    assert (graded / "grades.csv").read_text() == reference


def test_a_report_from_an_older_rosgrade_is_rescored(graded, klass, grading, reference, capsys):
    report = graded / "ben_nap" / "report.json"
    data = json.loads(report.read_text())
    data["rosgrade_version"] = "0.0.9"
    data.pop("recording_format")
    for task in data["tasks"]:
        task.pop("rubric")
    report.write_text(json.dumps(data))
    err = rerun(klass, capsys)
    assert "1: made by rosgrade 0.0.9 before reports named their rubric" in err
    assert (graded / "grades.csv").read_text() == reference


def test_a_report_whose_recordings_are_unusable_is_graded_again(graded, klass, grading, reference, capsys):
    (graded / "dan_wobbly" / "report.json").write_text("{not json")
    (graded / "dan_wobbly" / "move_circle" / "nominal.mcap").write_bytes(b"garbage, not an MCAP")
    err = rerun(klass, capsys)
    assert calls(grading).count("dan_wobbly") == 2
    assert "Graded again: 1 (1: report.json unreadable (truncated, or written by another version), and its " \
           "recordings are unusable)" in err.replace("\n", " ")
    assert (graded / "grades.csv").read_text() == reference


def test_a_report_without_recordings_is_graded_again(graded, klass, grading, capsys):
    (graded / "ann" / "report.json").write_text("")
    shutil.rmtree(graded / "ann" / "move_circle")
    rerun(klass, capsys)
    assert calls(grading).count("ann") == 2
    assert {r["status"] for r in grades(graded) if r["student"] == "ann"} == {"graded"}


def test_a_rubric_edit_rescores_everyone_and_grades_csv_has_one_rubric(grading, klass, tmp_path, monkeypatch, capsys):
    rubrics = tmp_path / "rubrics"
    shutil.copytree(fakes.ROOT / "rubrics", rubrics)
    monkeypatch.setenv(fakes.RUBRICS_ENV, str(rubrics))
    assert main(["batch", str(klass), "--out", "out", "-j", "2"]) == 0
    first = json.loads(Path("out/ann/report.json").read_text())["tasks"][0]["rubric"]["sha256"]
    rubric = rubrics / "move_circle.toml"
    rubric.write_text(rubric.read_text().replace("points = 4", "points = 6", 1))
    capsys.readouterr()
    err = rerun(klass, capsys)
    assert "Re-scored from their recordings (no code run): 4 (4: made with another move_circle rubric)" in err
    hashes = {json.loads(p.read_text())["tasks"][0]["rubric"]["sha256"] for p in Path("out").glob("*/report.json")}
    assert len(hashes) == 1 and first not in hashes
    assert calls(grading).count("ann") == 1
    plan = json.loads(Path("out/batch.json").read_text())
    assert plan["rubrics"]["move_circle"]["sha256"] in hashes


def test_a_report_made_for_other_tasks_is_not_done(graded, klass, grading, capsys):
    assert main(["batch", str(klass), "--out", "out", "--task", "move_circle", "--task", "move_square"]) == 0
    err = capsys.readouterr().err
    assert "graded for other tasks (move_circle)" in err
    assert {r["max"] for r in grades(graded)} == {"20.0"}
