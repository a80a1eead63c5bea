"""Opening submissions: folders, single files and zips, including hostile archives."""
from __future__ import annotations

import zipfile
from pathlib import Path

import pytest

from grader.submission import SubmissionError, open_submission


def make_zip(path: Path, members: dict[str, bytes]) -> Path:
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as archive:
        for name, data in members.items():
            archive.writestr(name, data)
    return path


def test_zip_is_unpacked_and_removed_afterwards(tmp_path):
    archive = make_zip(tmp_path / "s.zip", {"pkg/src/move_circle.py": b"print(1)\n"})
    with open_submission(archive) as folder:
        assert (folder / "pkg" / "src" / "move_circle.py").read_bytes() == b"print(1)\n"
        kept = folder
    assert not kept.exists()


def test_path_traversal_is_refused(tmp_path):
    archive = make_zip(tmp_path / "evil.zip", {"../../outside.py": b"x"})
    with pytest.raises(SubmissionError, match="unsafe path"):
        with open_submission(archive):
            pass
    assert not (tmp_path.parent / "outside.py").exists()


def test_zip_bomb_is_refused(tmp_path):
    archive = make_zip(tmp_path / "bomb.zip", {"a.txt": b"\0" * (50 << 20)})
    with pytest.raises(SubmissionError, match="zip bomb"):
        with open_submission(archive):
            pass


def test_corrupt_zip_says_what_to_do(tmp_path):
    archive = tmp_path / "broken.zip"
    archive.write_bytes(b"PK\x03\x04 not really a zip")
    with pytest.raises(SubmissionError, match="not a readable .zip"):
        with open_submission(archive):
            pass


def test_missing_path_is_an_error(tmp_path):
    with pytest.raises(SubmissionError, match="does not exist"):
        with open_submission(tmp_path / "nope"):
            pass


def test_other_file_types_are_refused(tmp_path):
    doc = tmp_path / "report.pdf"
    doc.write_bytes(b"%PDF")
    with pytest.raises(SubmissionError, match="neither a .py script"):
        with open_submission(doc):
            pass


def test_folder_with_spaces_and_non_ascii_is_used_as_is(tmp_path):
    folder = tmp_path / "Zoë Smith submission"
    folder.mkdir()
    with open_submission(folder) as opened:
        assert opened == folder
