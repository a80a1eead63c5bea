"""A full disk during a batch: one clear message, exit 2, everything graded kept, and the next run finishes the job.

Two ways to fill the disk: an injected writer that fails with ENOSPC after N writes (runs anywhere, and can hit
every point of a batch), and a real 1 MB tmpfs (needs root and mount; skipped otherwise).
"""
from __future__ import annotations

import errno
import os
import subprocess
from pathlib import Path

import pytest

from grader import batch
from grader.cli import main
from grader.reports import files, folder, gradebook
from grader.report import SubmissionReport

from .conftest import grades

WRITERS = (batch, folder, gradebook)  # every module that writes into the output folder through write_atomic


class FullDisk:
    """write_atomic that succeeds `allowed` times, then fails as a full disk does."""

    def __init__(self, allowed: int) -> None:
        self.allowed = allowed
        self.writes = 0

    def __call__(self, path: Path, data: str | bytes) -> Path:
        self.writes += 1
        if self.writes > self.allowed:
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(path))
        return files.write_atomic(path, data)


def fill_disk_after(monkeypatch: pytest.MonkeyPatch, allowed: int) -> FullDisk:
    """Make every write into the output folder go through a FullDisk (until `monkeypatch` is undone)."""
    writer = FullDisk(allowed)
    for module in WRITERS:
        monkeypatch.setattr(module, "write_atomic", writer)
    return writer


def complete_reports(out: Path) -> list[str]:
    """Students whose report.json is there and loads (what a full disk must never take away)."""
    names = []
    for path in sorted(out.glob("*/report.json")):
        SubmissionReport.model_validate_json(path.read_text())
        names.append(path.parent.name)
    return names


@pytest.mark.parametrize("allowed", [0, 2, 7, 19])  # the plan file, a first student, mid-class, the gradebook
def test_full_disk_at_any_point_stops_with_one_message_and_the_next_run_resumes(
        grading, klass, reference, capsys, allowed):
    with pytest.MonkeyPatch.context() as full:
        fill_disk_after(full, allowed)
        assert main(["batch", str(klass), "--out", "out", "-j", "2"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    message = [line for line in err if line.startswith("rosgrade: error:")]
    assert len(message) == 1 and "Traceback" not in "\n".join(err)
    assert "is full" in message[0] and "a student's results need about" in message[0]
    assert "run the same command again" in message[0]
    kept = complete_reports(Path("out"))
    assert main(["batch", str(klass), "--out", "out", "-j", "2"]) == 0
    assert Path("out/grades.csv").read_text() == reference
    assert set(kept) <= set(complete_reports(Path("out")))


def test_what_was_graded_before_the_disk_filled_is_in_grades_csv_when_it_can_be_written(
        grading, klass, monkeypatch, capsys):
    writer = FullDisk(12)  # enough for the first students' results, not for all

    def writes_results_not_gradebook(path: Path, data: str | bytes) -> Path:
        if path.name in ("grades.csv", "summary.md", "histogram.png", "batch.json"):
            return files.write_atomic(path, data)
        return writer(path, data)

    for module in WRITERS:
        monkeypatch.setattr(module, "write_atomic", writes_results_not_gradebook)
    assert main(["batch", str(klass), "--out", "out", "-j", "1"]) == 2
    assert "grades.csv and summary.md are written for what is done" in capsys.readouterr().err
    table = grades(Path("out"))
    graded = [r["student"] for r in table if r["status"] != "pending"]
    assert graded and len(graded) < len(table)
    assert all(r["total"] == "" for r in table if r["status"] == "pending")


def test_an_output_folder_that_is_read_only_is_refused_before_grading(grading, klass, capsys):
    out = Path("out")
    out.mkdir()
    out.chmod(0o555)
    try:
        if os.access(out, os.W_OK):
            pytest.skip("running as root: a read-only folder is still writable (the tmpfs test covers root)")
        assert main(["batch", str(klass), "--out", "out"]) == 2
    finally:
        out.chmod(0o755)
    assert "choose an --out folder you can write to" in capsys.readouterr().err


def _mount_tmpfs(where: Path, size: str) -> bool:
    where.mkdir(exist_ok=True)
    try:
        done = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", str(where)],
                              capture_output=True, timeout=20)
    except (OSError, subprocess.TimeoutExpired):
        return False
    return done.returncode == 0


def test_a_real_full_tmpfs_then_more_space(grading, klass, reference, tmp_path, capsys):
    disk = tmp_path / "disk"
    if not _mount_tmpfs(disk, "400k"):
        pytest.skip("cannot mount a tmpfs here (needs root and mount); the injected writer covers ENOSPC")
    try:
        capsys.readouterr()
        assert main(["batch", str(klass), "--out", str(disk / "out"), "-j", "2"]) == 2
        err = capsys.readouterr().err
        assert f"the disk holding {disk / 'out'} is full" in err and "Traceback" not in err
        kept = complete_reports(disk / "out")
        subprocess.run(["mount", "-o", "remount,size=20m", str(disk)], check=True, timeout=20)
        assert main(["batch", str(klass), "--out", str(disk / "out"), "-j", "2"]) == 0
        assert (disk / "out" / "grades.csv").read_text() == reference
        assert set(kept) <= set(complete_reports(disk / "out"))
    finally:
        subprocess.run(["umount", "-l", str(disk)], timeout=20)
