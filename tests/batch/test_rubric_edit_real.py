"""Issue 20's rubric edit, with real grading: radius worth 6 instead of 4 after a first run of the batch.

Every student ends with the new maximum (12), re-scored from the recordings of the first run: no node runs again.
"""
from __future__ import annotations

import csv
import shutil
from pathlib import Path

import pytest

from grader.cli import main
from grader.rubric import RUBRICS_ENV

ROOT = Path(__file__).resolve().parents[2]
pytestmark = pytest.mark.slow


def test_a_rubric_fixed_between_runs_rescores_everyone_from_their_recordings(tmp_path, monkeypatch, capsys):
    rubrics = tmp_path / "rubrics"
    shutil.copytree(ROOT / "rubrics", rubrics, ignore=shutil.ignore_patterns("examples", "__pycache__"))
    monkeypatch.setenv(RUBRICS_ENV, str(rubrics))
    klass = tmp_path / "class"
    for name in ("alice_correct", "dana_swapped"):
        shutil.copytree(ROOT / "submissions_example" / name, klass / name)
    out = tmp_path / "out"
    assert main(["batch", str(klass), "--out", str(out), "--task", "move_circle", "-j", "2"]) == 0
    recorded = {p: p.stat().st_mtime_ns for p in out.glob("*/move_circle/*.mcap")}
    circle = rubrics / "move_circle.toml"
    text = circle.read_text()
    assert text.count("points = 4") >= 1
    circle.write_text(text.replace("points = 4", "points = 6", 1))
    capsys.readouterr()
    assert main(["batch", str(klass), "--out", str(out), "-j", "2"]) == 0
    err = capsys.readouterr().err
    assert "2 re-scored from their recordings" in err.replace("\n", " ")
    with (out / "grades.csv").open(newline="") as handle:
        rows = list(csv.DictReader(handle))
    assert {r["max"] for r in rows} == {"12.0"}
    assert {p: p.stat().st_mtime_ns for p in out.glob("*/move_circle/*.mcap")} == recorded  # nothing ran again
    assert "Re-scored from their recordings (no code run): 2" in (out / "summary.md").read_text()
