"""What a submission contains cannot hang or crash the grader, nor grade or leak a file outside the submission."""
from __future__ import annotations

import os
import stat
import threading
import time
import zipfile
from pathlib import Path

import pytest

from grader.grading import grade_submission
from grader.runtime.scripts import MAX_SCRIPT_BYTES, check_script
from grader.submission import SubmissionError, open_submission

GOOD = "#!/usr/bin/env python3\nimport rospy\nrospy.init_node('mover')\n"
SECRET = "db password: hunter2-do-not-leak\n"  # not Python: a SyntaxError would quote it


def _script(folder: Path, text: str | bytes = GOOD, name: str = "move_circle.py") -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / name
    path.write_bytes(text.encode() if isinstance(text, str) else text)
    path.chmod(0o755)
    return path


def _check_within(path: Path, seconds: float = 5.0) -> list[str]:
    """check_script in a thread, so that a hang fails the test instead of blocking the suite."""
    result: list = []
    worker = threading.Thread(target=lambda: result.append(check_script(path)), daemon=True)
    worker.start()
    worker.join(seconds)
    assert not worker.is_alive(), f"check_script({path}) did not return within {seconds} s"
    return result[0]


# -- check_script reads only regular files, size-capped, without hanging ---------------------------------------------
def test_fifo_script_is_a_finding_not_a_hang(tmp_path):
    fifo = tmp_path / "move_circle.py"
    os.mkfifo(fifo)
    notes = _check_within(fifo)
    assert any("not a regular file" in n for n in notes), notes


def test_symlink_to_dev_zero_is_a_finding_not_exhaustion(tmp_path):
    link = tmp_path / "move_circle.py"
    link.symlink_to("/dev/zero")
    started = time.monotonic()
    notes = _check_within(link)
    assert time.monotonic() - started < 2.0
    assert any("not a regular file" in n for n in notes), notes


def test_oversize_script_is_a_finding(tmp_path):
    script = _script(tmp_path, GOOD + "#" * (MAX_SCRIPT_BYTES + 10) + "\n")
    notes = _check_within(script)
    assert any("too large" in n for n in notes), notes


def test_nul_byte_is_a_finding_not_a_crash(tmp_path):
    script = _script(tmp_path, GOOD.encode() + b"x = 1\x00\n")
    notes = _check_within(script)
    assert any("NUL" in n and "line 4" in n for n in notes), notes


@pytest.mark.slow
def test_nul_byte_script_does_not_crash_the_grading(tmp_path):
    _script(tmp_path / "sub" / "scripts", GOOD.encode() + b"\x00\n")
    report = grade_submission(tmp_path / "sub", tmp_path / "out", task_ids=["move_circle"])
    task = report.tasks[0]
    assert any("NUL" in d for d in task.diagnostics), task.diagnostics


# -- symlinks leaving the submission are refused --------------------------------------------------------------------
def _classmates(tmp_path: Path) -> tuple[Path, Path]:
    honest = tmp_path / "class" / "alice"
    _script(honest / "scripts", GOOD + "# alice's own work\n")
    attacker = tmp_path / "class" / "mallory" / "scripts"
    attacker.mkdir(parents=True)
    (attacker / "move_circle.py").symlink_to("../../alice/scripts/move_circle.py")
    return honest, attacker.parent


def test_symlink_to_a_classmates_script_is_refused(tmp_path):
    _, attacker = _classmates(tmp_path)
    report = grade_submission(attacker, tmp_path / "out", task_ids=["move_circle"])
    task = report.tasks[0]
    assert task.status == "error" and task.score == 0
    assert "symbolic link" in task.message and "outside" in task.message
    assert not list((tmp_path / "out").rglob("*.mcap"))  # nothing was run


def test_symlink_to_a_secret_is_refused_without_quoting_it(tmp_path):
    secret = tmp_path / "grader_secrets.py"
    secret.write_text(SECRET)
    package = tmp_path / "sub" / "scripts"
    package.mkdir(parents=True)
    (package / "move_circle.py").symlink_to(secret)
    report = grade_submission(tmp_path / "sub", tmp_path / "out", task_ids=["move_circle"])
    task = report.tasks[0]
    assert task.status == "error"
    assert "hunter2" not in report.model_dump_json()


def test_symlinked_helper_module_leaving_the_submission_is_refused(tmp_path):
    secret = tmp_path / "grader_secrets.py"
    secret.write_text(SECRET)
    package = tmp_path / "sub" / "scripts"
    _script(package)
    (package / "helper.py").symlink_to(secret)
    report = grade_submission(tmp_path / "sub", tmp_path / "out", task_ids=["move_circle"])
    task = report.tasks[0]
    assert task.status == "error" and "helper.py" in task.message


def test_symlink_inside_the_submission_is_fine(tmp_path):
    package = tmp_path / "sub" / "scripts"
    _script(package, name="circle_impl.py")
    (package / "move_circle.py").symlink_to("circle_impl.py")
    with open_submission(tmp_path / "sub") as folder:
        assert folder == tmp_path / "sub"


def test_zip_with_a_symlink_is_refused(tmp_path):
    archive = tmp_path / "sub.zip"
    with zipfile.ZipFile(archive, "w") as zf:
        zf.writestr("scripts/other.py", GOOD)
        link = zipfile.ZipInfo("scripts/move_circle.py")
        link.external_attr = (stat.S_IFLNK | 0o777) << 16
        zf.writestr(link, "../../alice/scripts/move_circle.py")
    with pytest.raises(SubmissionError, match="symbolic link"):
        with open_submission(archive):
            pass
