"""`rosgrade batch`: parallel reports, grades.csv, resume, error rows, timeouts and Ctrl+C."""
from __future__ import annotations

import csv
import zipfile
from pathlib import Path

import pytest

from grader.batch import run_batch
from grader.cli import main

from .conftest import calls


def make_students(root: Path, names: list[str]) -> Path:
    """One submission per name: a package folder, or a .zip for names ending in .zip."""
    folder = root / "submissions"
    folder.mkdir(exist_ok=True)
    for name in names:
        if name.endswith(".zip"):
            with zipfile.ZipFile(folder / name, "w") as archive:
                archive.writestr("scripts/move_circle.py", "import rospy\n")
        else:
            (folder / name / "scripts").mkdir(parents=True)
            (folder / name / "scripts" / "move_circle.py").write_text("import rospy\n")
    return folder


def rows(out: Path) -> list[dict[str, str]]:
    with (out / "grades.csv").open(newline="") as handle:
        return list(csv.DictReader(handle))


def test_parallel_batch_writes_every_report_and_the_gradebook(grading, tmp_path, capsys):
    folder = make_students(tmp_path, ["ann", "ben", "cat.zip", "dan_wobbly", "eve"])
    assert main(["batch", str(folder), "--out", "out", "-j", "3", "--task", "move_circle", "--task", "move_square"]) == 0
    assert sorted(p.parent.name for p in Path("out").glob("*/report.json")) == ["ann", "ben", "cat", "dan_wobbly", "eve"]
    table = rows(Path("out"))
    assert [r["student"] for r in table] == ["ann", "ben", "cat", "dan_wobbly", "eve"]
    assert list(table[0]) == ["student", "name", "total", "max", "move_circle", "move_square", "move_circle.radius",
                              "move_circle.speed_limit", "move_circle.stops", "move_square.closes",
                              "move_square.corners", "status", "message"]
    assert table[0]["total"] == "14.5" and table[3]["move_circle.radius"] == "1.5"
    assert {r["status"] for r in table} == {"graded"}
    assert Path("out/summary.md").read_text().startswith("# rosgrade batch summary")
    assert Path("out/histogram.png").read_bytes().startswith(b"\x89PNG")


def test_rerun_skips_students_whose_report_is_complete(grading, tmp_path, capsys):
    folder = make_students(tmp_path, ["ann", "ben", "cat"])
    assert main(["batch", str(folder), "--out", "out", "-j", "2"]) == 0
    assert sorted(calls(grading)) == ["ann", "ben", "cat"]
    (folder / "dan").mkdir()
    assert main(["batch", str(folder), "--out", "out", "-j", "2"]) == 0
    assert sorted(calls(grading)) == ["ann", "ben", "cat", "dan"]
    assert len(rows(Path("out"))) == 4


def test_a_crashing_student_becomes_an_error_row_and_the_batch_continues(grading, tmp_path, capsys):
    folder = make_students(tmp_path, ["ann", "bob_crash", "cat_bad", "dan"])
    assert main(["batch", str(folder), "--out", "out", "-j", "2"]) == 0
    table = {r["student"]: r for r in rows(Path("out"))}
    assert table["bob_crash"]["status"] == "error" and "simulated crash" in table["bob_crash"]["message"]
    assert table["cat_bad"]["status"] == "error" and "no ROS scripts" in table["cat_bad"]["message"]
    assert table["ann"]["status"] == table["dan"]["status"] == "graded"
    assert "bob_crash" in Path("out/summary.md").read_text()


def test_errors_are_retried_on_the_next_run(grading, tmp_path, capsys):
    folder = make_students(tmp_path, ["ann", "bob_crash"])
    main(["batch", str(folder), "--out", "out", "-j", "1"])
    main(["batch", str(folder), "--out", "out", "-j", "1"])
    assert calls(grading) == ["ann", "bob_crash", "bob_crash"]


def test_a_killed_worker_becomes_an_error_row(grading, tmp_path, capsys):
    folder = make_students(tmp_path, ["ann", "bob_die"])
    assert main(["batch", str(folder), "--out", "out", "-j", "2"]) == 0
    table = {r["student"]: r for r in rows(Path("out"))}
    assert table["bob_die"]["status"] == "error" and "signal 9" in table["bob_die"]["message"]


def test_a_slow_student_times_out_without_stopping_the_batch(grading, tmp_path, capsys):
    folder = make_students(tmp_path, ["ann", "bob_slow"])
    assert main(["batch", str(folder), "--out", "out", "-j", "2", "--timeout", "1"]) == 0
    table = {r["student"]: r for r in rows(Path("out"))}
    assert table["bob_slow"]["status"] == "timeout" and table["ann"]["status"] == "graded"


def test_ctrl_c_keeps_the_students_already_graded(grading, tmp_path, capsys):
    folder = make_students(tmp_path, ["a1", "a2", "a3_interrupt", "a4", "a5"])
    assert main(["batch", str(folder), "--out", "out", "-j", "1"]) == 130
    assert sorted(p.parent.name for p in Path("out").glob("*/report.json")) == ["a1", "a2"]
    assert [r["status"] for r in rows(Path("out"))] == ["graded", "graded", "pending", "pending", "pending"]
    assert "run the same command again" in capsys.readouterr().err
    assert not list(Path("out").rglob(".*.tmp"))


def test_resume_after_ctrl_c_grades_only_the_rest(grading, tmp_path, capsys):
    folder = make_students(tmp_path, ["a1", "a2", "a3_interrupt", "a4"])
    main(["batch", str(folder), "--out", "out", "-j", "1"])
    (folder / "a3_interrupt").rename(folder / "a3")
    assert main(["batch", str(folder), "--out", "out", "-j", "1"]) == 0
    assert calls(grading) == ["a1", "a2", "a3_interrupt", "a3", "a4"]


def test_task_ids_reach_every_student(grading, tmp_path):
    folder = make_students(tmp_path, ["ann"])
    run_batch(folder, Path("out"), jobs=1, task_ids=["move_square"])
    assert list(rows(Path("out"))[0])[4:6] == ["move_square", "move_square.closes"]


def test_missing_batch_folder_is_exit_2(grading, capsys):
    assert main(["batch", "nowhere", "--out", "out"]) == 2
    assert capsys.readouterr().err.strip().splitlines()[-1] == "rosgrade: error: nowhere is not a folder"


def test_empty_batch_folder_is_exit_2(grading, tmp_path, capsys):
    (tmp_path / "empty").mkdir()
    assert main(["batch", str(tmp_path / "empty"), "--out", "out"]) == 2


def test_jobs_must_be_positive(grading, tmp_path):
    with pytest.raises(SystemExit) as exc:
        main(["batch", str(tmp_path), "--out", "out", "-j", "0"])
    assert exc.value.code == 2


def test_without_task_the_tasks_most_submissions_hold_are_chosen_once_and_printed(grading, tmp_path, capsys):
    folder = make_students(tmp_path, ["ann", "ben", "cat"])
    (folder / "ann" / "scripts" / "move_square.py").write_text("import rospy\n")
    assert main(["batch", str(folder), "--out", "out", "-j", "2"]) == 0
    err = capsys.readouterr().err
    assert "Tasks: move_circle (found in most submissions: move_circle (3/3); left out: move_square (1)" in err
    assert {r["max"] for r in rows(Path("out"))} == {"10.0"}


def test_a_resumed_batch_keeps_the_task_set_of_its_first_run(grading, tmp_path, capsys):
    folder = make_students(tmp_path, ["ann"])
    main(["batch", str(folder), "--out", "out", "--task", "move_circle", "--task", "move_square"])
    for name in ("ben", "cat"):
        (folder / name).mkdir()
    assert main(["batch", str(folder), "--out", "out"]) == 0
    assert "as in this folder's first run" in capsys.readouterr().err
    assert {r["max"] for r in rows(Path("out"))} == {"20.0"}


def test_a_submission_that_could_not_be_graded_counts_as_zero_of_the_class_maximum(grading, tmp_path, capsys):
    folder = make_students(tmp_path, ["ann", "bob_crash"])
    main(["batch", str(folder), "--out", "out", "--task", "move_circle", "--task", "move_square"])
    table = {r["student"]: r for r in rows(Path("out"))}
    assert (table["bob_crash"]["total"], table["bob_crash"]["max"]) == ("0.0", "20.0")
    assert table["bob_crash"]["move_circle"] == "0.0"
    summary = Path("out/summary.md").read_text()
    assert "mean 36.2 %" in summary and "min 0.0 %" in summary  # (14.5 / 20 + 0) / 2


def test_a_second_batch_on_the_same_folder_is_refused(grading, tmp_path, capsys):
    from grader.outfolder import OutputLock

    folder = make_students(tmp_path, ["ann"])
    Path("out").mkdir()
    with OutputLock(Path("out")):
        assert main(["batch", str(folder), "--out", "out"]) == 2
    assert "another rosgrade batch (pid " in capsys.readouterr().err
    assert not Path("out/grades.csv").exists()
    assert main(["batch", str(folder), "--out", "out"]) == 0  # released: the next batch runs


def test_an_output_folder_that_cannot_be_written_stops_before_grading(grading, tmp_path, capsys):
    folder = make_students(tmp_path, ["ann"])
    Path("blocked").write_text("a file where the output folder should be")
    assert main(["batch", str(folder), "--out", "blocked/out"]) == 2
    assert "could not write blocked/out" in capsys.readouterr().err
    assert calls(grading) == []


def test_moodle_canvas_and_plain_layouts_give_names_to_grades_csv(grading, tmp_path, capsys):
    folder = tmp_path / "submissions"
    moodle = folder / "Jane Doe_4242_assignsubmission_file_"
    moodle.mkdir(parents=True)
    with zipfile.ZipFile(moodle / "my_package.zip", "w") as archive:
        archive.writestr("pkg/scripts/move_circle.py", "import rospy\n")
    (folder / "smithalex_late_77_1001_move_circle.py").write_text("import rospy\n")
    (folder / "plain_student" / "scripts").mkdir(parents=True)
    (folder / "plain_student" / "scripts" / "move_circle.py").write_text("import rospy\n")
    assert main(["batch", str(folder), "--out", "out"]) == 0
    table = {r["student"]: r for r in rows(Path("out"))}
    assert {k: v["name"] for k, v in table.items()} == {
        "Jane_Doe_4242": "Jane Doe", "smithalex_77": "smithalex", "plain_student": "plain_student"}
    assert {r["status"] for r in table.values()} == {"graded"}
