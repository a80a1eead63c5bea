"""Instructors' own rubrics in a batch: `--rubric FILE` grades a task that is not in the package, and the report
says which rubric file (and which content) made each task's scores."""
from __future__ import annotations

import csv
import hashlib
import json
import shutil
from pathlib import Path

import pytest

from grader.cli import main
from grader.rubricfile import RubricFile

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture
def my_task(tmp_path: Path) -> Path:
    """move_circle's rubric as an instructor's own task `my_circle` (a 1 m circle is not asked: same node)."""
    text = (ROOT / "rubrics" / "move_circle.toml").read_text().replace('id = "move_circle"', 'id = "my_circle"', 1)
    path = tmp_path / "rubrics" / "my_circle.toml"
    path.parent.mkdir()
    path.write_text(text)
    return path


@pytest.mark.slow
def test_batch_grades_a_task_from_an_instructors_rubric_file(my_task: Path, tmp_path: Path, capsys):
    klass = tmp_path / "class"
    shutil.copytree(ROOT / "submissions_example" / "alice_correct", klass / "alice")
    out = tmp_path / "out"
    assert main(["batch", str(klass), "--out", str(out), "--rubric", str(my_task), "--task", "my_circle"]) == 0
    with (out / "grades.csv").open(newline="") as handle:
        (row,) = list(csv.DictReader(handle))
    assert row["status"] == "graded" and row["my_circle"] == row["total"] == row["max"]
    stamp = json.loads((out / "alice" / "report.json").read_text())["tasks"][0]["rubric"]
    assert stamp["file"] == str(my_task)
    assert stamp["sha256"] == hashlib.sha256(my_task.read_bytes()).hexdigest()


def test_an_own_rubric_with_a_builtin_task_id_is_a_clear_error(tmp_path: Path, capsys):
    clash = tmp_path / "move_circle.toml"
    shutil.copy(ROOT / "rubrics" / "move_circle.toml", clash)
    (tmp_path / "class" / "ann").mkdir(parents=True)
    assert main(["batch", str(tmp_path / "class"), "--out", str(tmp_path / "out"), "--rubric", str(clash)]) == 2
    assert "task 'move_circle' is already defined by" in capsys.readouterr().err


def test_a_missing_rubric_file_is_a_clear_error(tmp_path: Path, capsys):
    (tmp_path / "class" / "ann").mkdir(parents=True)
    assert main(["batch", str(tmp_path / "class"), "--out", str(tmp_path / "out"),
                 "--rubric", str(tmp_path / "nope.toml")]) == 2
    assert "--rubric" in capsys.readouterr().err


def test_a_rubric_hash_covers_its_plugin_files():
    plain = RubricFile("r/spiral.toml", b"rubric")
    with_plugin = RubricFile("r/spiral.toml", b"rubric", (("my_metrics.py", b"def f(): pass"),))
    edited = RubricFile("r/spiral.toml", b"rubric", (("my_metrics.py", b"def f(): return 1"),))
    assert len({plain.sha256, with_plugin.sha256, edited.sha256}) == 3
    assert plain.task_id == "spiral"


def test_check_and_score_take_an_own_rubric(my_task: Path, tmp_path: Path, capsys):
    assert main(["tasks"]) == 0
    capsys.readouterr()
    code = main(["score", str(tmp_path / "missing.mcap"), "--task", "my_circle", "--rubric", str(my_task)])
    assert code == 2 and "missing.mcap: no such file" in capsys.readouterr().err  # the task was known


def test_the_gradescope_package_carries_an_own_rubric_and_grades_with_it(my_task: Path, tmp_path: Path, capsys):
    import zipfile

    package = tmp_path / "autograder.zip"
    assert main(["gradescope-package", "--task", "my_circle", "--rubric", str(my_task), "--out", str(package)]) == 0
    with zipfile.ZipFile(package) as archive:
        assert archive.read("rubrics_extra/0/my_circle.toml") == my_task.read_bytes()
        run = archive.read("run_autograder").decode()
    assert '--task my_circle --rubric "$WORK/rubrics_extra/0/my_circle.toml"' in run
