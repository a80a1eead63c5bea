"""Every run removes the temporary folders it made (rosgrade-node-*, rosgrade-sub-*, rosgrade-worker-*), whether it
ends normally, with an error, at a batch timeout or by Ctrl+C: the temporary directory is left as it was."""
from __future__ import annotations

import os
import tempfile
import time
import zipfile
from pathlib import Path

import pytest

from grader import batch, grading
from grader.runtime import session
from grader.runtime.spec import NodeSpec, RunSpec
from grader.submission import OWNER_FILE, STAGE_PREFIX, open_submission, remove_if_abandoned
from sim import Scenario

NODE = "import rospy\nrospy.init_node('tidy')\nprint('ran')\n"


@pytest.fixture
def temp_dir(tmp_path, monkeypatch) -> Path:
    """A temporary directory of our own, so that other runs on this machine do not count."""
    folder = tmp_path / "tmp"
    folder.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(folder))
    return folder


def _spec(tmp_path: Path) -> RunSpec:
    script = tmp_path / "tidy.py"  # beside the temporary directory: copying the package must not copy that
    script.write_text(NODE)
    return RunSpec(scenario=Scenario(duration=2.0, shutdown_at=1.0), nodes=(NodeSpec(script=script),),
                   shutdown_grace_s=0.5)


def test_a_normal_run_leaves_nothing(tmp_path, temp_dir):
    result = session.run(_spec(tmp_path), tmp_path / "run.mcap", tmp_path / "run.log")
    assert result.nodes[0].status == "exited"
    assert list(temp_dir.iterdir()) == []


def test_folders_of_a_killed_grader_are_removed_by_the_next_run(tmp_path, temp_dir):
    stale = temp_dir / f"{session.WORKROOT_PREFIX}{2**22 + 1}-x"  # above any pid Linux gives: that grader is gone
    (stale / "node0").mkdir(parents=True)
    session.run(_spec(tmp_path), tmp_path / "run.mcap", tmp_path / "run.log")
    assert list(temp_dir.iterdir()) == []


def test_ctrl_c_during_a_run_leaves_nothing(tmp_path, temp_dir, monkeypatch):
    def interrupted(self, wall0):
        raise KeyboardInterrupt

    monkeypatch.setattr(session.Session, "_loop", interrupted)
    with pytest.raises(KeyboardInterrupt):
        session.run(_spec(tmp_path), tmp_path / "run.mcap", tmp_path / "run.log")
    assert list(temp_dir.iterdir()) == []


def test_a_node_that_cannot_start_leaves_nothing(tmp_path, temp_dir, monkeypatch):
    def refused(*args, **kwargs):
        raise session.ProcessError("refused")

    monkeypatch.setattr(session, "NodeProcess", refused)
    with pytest.raises(session.RunError, match="refused"):
        session.run(_spec(tmp_path), tmp_path / "run.mcap", tmp_path / "run.log")
    assert list(temp_dir.iterdir()) == []


def test_an_unpacked_zip_is_removed_even_after_an_error(tmp_path, temp_dir):
    archive = tmp_path / "student.zip"
    with zipfile.ZipFile(archive, "w") as handle:
        handle.writestr("move_circle.py", NODE)
    with pytest.raises(RuntimeError), open_submission(archive) as folder:
        assert (folder / "move_circle.py").exists()
        raise RuntimeError("grading failed")
    assert list(temp_dir.iterdir()) == []


def _slow_grading(submission, label, task_ids, rubrics, stage_root):
    """Stands in for grading in a batch worker: stages and unpacks as grading does, then hangs past --timeout."""
    staged = stage_root / f"{STAGE_PREFIX}0123456789abcdef"
    staged.mkdir()
    (staged / OWNER_FILE).write_text(str(os.getpid()))
    Path(tempfile.mkdtemp(prefix="rosgrade-sub-"), "move_circle.py").write_text(NODE)
    time.sleep(60)


def test_a_batch_worker_stopped_at_its_timeout_leaves_nothing(tmp_path, temp_dir, monkeypatch):
    students = tmp_path / "students"
    (students / "ann").mkdir(parents=True)
    (students / "ann" / "move_circle.py").write_text(NODE)
    monkeypatch.setattr(grading, "grade_as_data", _slow_grading)
    result = batch.run_batch(students, tmp_path / "out", jobs=1, timeout_s=2.0, task_ids=["move_circle"])
    assert [r.status for r in result.results] == ["timeout"]
    assert list(temp_dir.iterdir()) == []


def _zombie() -> int:
    """A child that has exited and is not reaped yet (what a killed Dask worker's grading process becomes)."""
    pid = os.fork()
    if pid == 0:
        os._exit(0)
    deadline = time.monotonic() + 10
    while Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0] != "Z":
        assert time.monotonic() < deadline, "the child did not exit"
        time.sleep(0.01)
    return pid


def test_a_folder_owned_by_a_zombie_counts_as_abandoned(tmp_path):
    folder = tmp_path / f"{STAGE_PREFIX}0123456789abcdef"
    folder.mkdir()
    pid = _zombie()
    try:
        (folder / OWNER_FILE).write_text(str(pid))
        assert remove_if_abandoned(folder) and not folder.exists()
    finally:
        os.waitpid(pid, 0)


def test_a_folder_owned_by_a_live_process_is_kept(tmp_path):
    folder = tmp_path / f"{STAGE_PREFIX}0123456789abcdef"
    folder.mkdir()
    (folder / OWNER_FILE).write_text(str(os.getpid()))
    assert not remove_if_abandoned(folder) and folder.exists()


def test_a_regrade_after_a_killed_grading_unpacks_at_the_same_path(tmp_path):
    """The path reaches the recordings: a job Dask re-runs after its worker died must not get another one."""
    archive = tmp_path / "student.zip"
    with zipfile.ZipFile(archive, "w") as handle:
        handle.writestr("move_circle.py", NODE)
    submission = archive.read_bytes()
    with grading._unpacked(submission, tmp_path) as first:
        expected = first
    left = expected.parent
    left.mkdir()
    pid = _zombie()
    try:
        (left / OWNER_FILE).write_text(str(pid))  # the killed grading's folder, still there
        with grading._unpacked(submission, tmp_path) as again:
            assert again == expected
    finally:
        os.waitpid(pid, 0)
