"""Finding the students in a batch folder: plain entries and the Moodle, Canvas and Gradescope download layouts."""
from __future__ import annotations

import io
import zipfile
from pathlib import Path

import pytest

from grader.roster import RosterError, Student, find_students, gradescope_names


def zip_with(path: Path, members: dict[str, str]) -> Path:
    with zipfile.ZipFile(path, "w") as archive:
        for name, text in members.items():
            archive.writestr(name, text)
    return path


def names_in(packed: bytes) -> list[str]:
    return sorted(zipfile.ZipFile(io.BytesIO(packed)).namelist())


def test_plain_folders_and_zips_are_students_named_after_themselves(tmp_path):
    (tmp_path / "ann").mkdir()
    zip_with(tmp_path / "ben.zip", {"move_circle.py": ""})
    (tmp_path / ".hidden").mkdir()
    (tmp_path / "notes.txt").write_text("")
    assert [(s.key, s.name) for s in find_students(tmp_path)] == [("ann", "ann"), ("ben", "ben")]


def test_a_folder_and_a_zip_of_the_same_name_get_distinct_keys(tmp_path):
    (tmp_path / "ann").mkdir()
    zip_with(tmp_path / "ann.zip", {"move_circle.py": ""})
    assert sorted(s.key for s in find_students(tmp_path)) == ["ann", "ann.zip"]


def test_moodle_folder_holding_one_zip_is_that_zip_with_the_students_name(tmp_path):
    folder = tmp_path / "Zoë van Dijk_31337_assignsubmission_file_"
    folder.mkdir()
    zipped = zip_with(folder / "part2.zip", {"part2/scripts/move_circle.py": ""})
    (student,) = find_students(tmp_path)
    assert (student.name, student.key, student.path) == ("Zoë van Dijk", "Zoë_van_Dijk_31337", zipped)


def test_moodle_folder_of_loose_files_is_the_folder_and_online_text_is_ignored(tmp_path):
    files = tmp_path / "Ann Lee_7_assignsubmission_file_"
    files.mkdir()
    (files / "move_circle.py").write_text("")
    (files / "move_square.py").write_text("")
    (tmp_path / "Ann Lee_7_assignsubmission_onlinetext_").mkdir()
    (student,) = find_students(tmp_path)
    assert student.path == files and student.name == "Ann Lee"


def test_canvas_flat_files_are_grouped_per_student_with_the_latest_reupload(tmp_path):
    (tmp_path / "leeann_11_100_move_circle.py").write_text("old")
    (tmp_path / "leeann_11_101_move_circle-1.py").write_text("new")
    (tmp_path / "leeann_11_102_move_square.py").write_text("square")
    (tmp_path / "doejo_late_12_103_package.zip").write_bytes(
        zip_with(tmp_path.parent / "package.zip", {"move_circle.py": ""}).read_bytes())
    students = {s.key: s for s in find_students(tmp_path)}
    assert sorted(students) == ["doejo_12", "leeann_11"]
    lee = students["leeann_11"]
    assert lee.name == "leeann" and [name for name, _ in lee.files] == ["move_circle.py", "move_square.py"]
    assert zipfile.ZipFile(io.BytesIO(lee.pack())).read("move_circle.py") == b"new"
    assert students["doejo_12"].path.name == "doejo_late_12_103_package.zip" and not students["doejo_12"].files


GRADESCOPE_METADATA = """\
:submission_4242:
  :submitters:
  - :name: Jane Doe
    :sid: '123'
    :email: jane@example.edu
  - :name: Max Mustermann
    :email: max@example.edu
  :created_at: 2026-01-01 10:00:00.000000000 +00:00
:submission_4243:
  :submitters:
  - :name: "Ann O'Neil"
"""


def test_gradescope_export_names_each_submission_from_its_metadata(tmp_path):
    (tmp_path / "submission_metadata.yml").write_text(GRADESCOPE_METADATA)
    for folder in ("submission_4242", "submission_4243", "submission_4244"):
        (tmp_path / folder).mkdir()
    assert [(s.key, s.name) for s in find_students(tmp_path)] == [
        ("submission_4242", "Jane Doe & Max Mustermann"), ("submission_4243", "Ann O'Neil"),
        ("submission_4244", "submission_4244")]


def test_gradescope_names_reads_only_names():
    assert gradescope_names(GRADESCOPE_METADATA)["submission_4242"] == "Jane Doe & Max Mustermann"


def test_gradescope_export_without_submissions_is_an_error(tmp_path):
    (tmp_path / "submission_metadata.yml").write_text(GRADESCOPE_METADATA)
    with pytest.raises(RosterError, match="no submission_<id> folders"):
        find_students(tmp_path)


def test_packing_is_byte_identical_for_the_same_files(tmp_path):
    for name in ("a", "b"):
        (tmp_path / name / "scripts").mkdir(parents=True)
        (tmp_path / name / "scripts" / "move_circle.py").write_text("import rospy\n")
    first, second = (Student(n, n, tmp_path / n).pack() for n in ("a", "b"))
    assert first == second and names_in(first) == ["scripts/move_circle.py"]


def test_a_zip_is_packed_as_it_is(tmp_path):
    zipped = zip_with(tmp_path / "ann.zip", {"x/move_circle.py": ""})
    assert Student("ann", "ann", zipped).pack() == zipped.read_bytes()


def test_a_missing_batch_folder_is_an_error(tmp_path):
    with pytest.raises(RosterError, match="is not a folder"):
        find_students(tmp_path / "nowhere")


def test_a_link_to_a_file_outside_the_submission_is_not_packed(tmp_path):
    (tmp_path / "classmate").mkdir()
    (tmp_path / "classmate" / "move_circle.py").write_text("their work")
    (tmp_path / "ann").mkdir()
    (tmp_path / "ann" / "move_circle.py").symlink_to(tmp_path / "classmate" / "move_circle.py")
    (tmp_path / "ann" / "notes.txt").write_text("mine")
    assert names_in(Student("ann", "ann", tmp_path / "ann").pack()) == ["notes.txt"]
