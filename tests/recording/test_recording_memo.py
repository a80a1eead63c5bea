"""Recording memo: a file read before and unchanged gives the same series without being read again."""
from __future__ import annotations

import os
import shutil
from pathlib import Path

import numpy as np
import pytest

from grader.recording import Recording, RecordingError
from grader.recording import memo
from recording_helpers import make_run, record


@pytest.fixture(autouse=True)
def clean_memos():
    memo.forget_all()
    yield
    memo.forget_all()


@pytest.fixture
def copied(recorded: Path, tmp_path: Path) -> Path:
    return Path(shutil.copy(recorded, tmp_path / "run.mcap"))


def test_unchanged_file_is_not_read_again(copied: Path) -> None:
    first = Recording.open(copied)
    truth, commands, lines = first.ground_truth(), first.commands(), first.output_lines()
    again = Recording.open(copied)
    assert again._loaded is None  # nothing parsed yet
    assert again.ground_truth() is truth and again.commands() is commands
    assert again.output_lines() == lines and again.output_lines() is not lines
    assert again._loaded is None
    assert again.metadata == first.metadata and again.format == first.format


def test_what_the_memo_lacks_is_read_from_the_file(copied: Path) -> None:
    Recording.open(copied).ground_truth()
    again = Recording.open(copied)
    listed = list(again.messages("/cmd_vel"))
    assert again._loaded is not None and len(listed) == len(again.commands()) > 0


def test_rewritten_file_is_read_afresh(copied: Path, tmp_path: Path) -> None:
    before = Recording.open(copied).odometry()
    record(copied, make_run(seconds=3.0))
    after = Recording.open(copied).odometry()
    assert len(after) != len(before)


def test_same_size_and_time_but_other_content_is_read_afresh(copied: Path) -> None:
    assert Recording.open(copied).metadata["rosgrade.run"]["status"] == "exited"
    stat = copied.stat()
    data = copied.read_bytes()
    copied.write_bytes(data.replace(b"status\x06\x00\x00\x00exited", b"status\x06\x00\x00\x00exitex"))
    os.utime(copied, ns=(stat.st_atime_ns, stat.st_mtime_ns))
    assert copied.stat().st_size == stat.st_size and copied.read_bytes() != data
    assert Recording.open(copied).metadata["rosgrade.run"]["status"] == "exitex"


def test_identity_tells_content_apart(tmp_path: Path) -> None:
    path = tmp_path / "f"
    path.write_bytes(b"a" * 100)
    stat = path.stat()
    before = memo.identity(path)
    path.write_bytes(b"b" * 100)
    os.utime(path, ns=(stat.st_atime_ns, stat.st_mtime_ns))
    assert memo.identity(path) != before and memo.identity(tmp_path) is None and memo.identity(tmp_path / "x") is None


def test_shared_arrays_are_read_only(copied: Path) -> None:
    truth = Recording.open(copied).ground_truth()
    with pytest.raises(ValueError, match="read-only"):
        truth.x[0] = 1.0
    lines = Recording.open(copied).output_lines()
    lines.clear()
    assert Recording.open(copied).output_lines()


def test_truncated_file_still_refused_when_asked(copied: Path) -> None:
    copied.write_bytes(copied.read_bytes()[:-200])
    assert Recording.open(copied).truncated
    with pytest.raises(RecordingError, match="not a readable recording"):
        Recording.open(copied, allow_truncated=False)


def test_memos_are_bounded(recorded: Path, tmp_path: Path) -> None:
    paths = [Path(shutil.copy(recorded, tmp_path / f"run{i}.mcap")) for i in range(memo.KEPT_FILES + 3)]
    for path in paths:
        Recording.open(path).ground_truth()
    assert len(memo._memos) == memo.KEPT_FILES
    assert Recording.open(paths[0])._loaded is not None  # the oldest was forgotten
    assert Recording.open(paths[-1])._loaded is None
