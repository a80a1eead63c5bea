"""`rosgrade batch --scheduler` against a real `dask scheduler` and two `dask worker` processes on 127.0.0.1.

The example submissions graded through Dask give the local batch's results: recordings byte for byte, reports
field for field; killing a worker mid-batch loses no submission (Dask re-runs its job) and leaves no process.
"""
from __future__ import annotations

import hashlib
import json
import os
import shutil
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from grader.cli import main

from .conftest import ROOT, Cluster, alive, descendants, restart_worker, wait_until

pytestmark = pytest.mark.slow
STUDENTS = ["alice_correct", "dana_swapped", "gus_hook_parens"]


@pytest.fixture(scope="module")
def klass(tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = tmp_path_factory.mktemp("class")
    for name in STUDENTS:
        shutil.copytree(ROOT / "submissions_example" / name, folder / name)
    return folder


@pytest.fixture(scope="module")
def local(klass: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The class graded by the local process pool (the results Dask must reproduce)."""
    out = tmp_path_factory.mktemp("local") / "out"
    assert main(["batch", str(klass), "--out", str(out), "-j", "2", "--task", "move_circle"]) == 0
    return out


def report(out: Path, student: str) -> dict:
    """A student's report.json with the output folder taken out of its recording paths."""
    data = json.loads((out / student / "report.json").read_text())
    for task in data["tasks"]:
        task["recordings"] = [str(Path(r).relative_to(out)) for r in task["recordings"]]
    return data


def recordings(out: Path) -> dict[str, str]:
    """SHA-256 of each recording by its path in the output folder (digests keep a failing comparison readable)."""
    return {str(p.relative_to(out)): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(out.glob("*/*/*.mcap"))}


def test_dask_batch_gives_the_local_results(cluster: Cluster, klass: Path, local: Path, tmp_path: Path):
    out = tmp_path / "out"
    assert main(["batch", str(klass), "--out", str(out), "--scheduler", cluster.address, "--task", "move_circle"]) == 0
    assert recordings(out) == recordings(local) and len(recordings(out)) == 3 * len(STUDENTS)
    for student in STUDENTS:
        assert report(out, student) == report(local, student)
    assert (out / "grades.csv").read_text() == (local / "grades.csv").read_text()


def test_a_worker_killed_mid_batch_loses_no_submission_and_leaves_no_process(cluster: Cluster, klass: Path,
                                                                            local: Path, tmp_path: Path):
    out = tmp_path / "out"
    batch = subprocess.Popen([sys.executable, "-m", "grader.cli", "batch", str(klass), "--out", str(out),
                              "--scheduler", cluster.address, "--task", "move_circle"],
                             cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    victim = cluster.workers[0]
    # Wait until the victim is grading (it has forked a grading process), then kill it with everything it started.
    assert wait_until(lambda: len(descendants(victim.pid)) > 0, 180), "worker 0 never started a job"
    wait_until(lambda: False, 1.5)  # let the job get into its scenarios
    below = descendants(victim.pid)
    os.kill(victim.pid, signal.SIGKILL)
    victim.wait()
    try:
        _, err = batch.communicate(timeout=600)
        assert batch.returncode == 0, err.decode()
        assert wait_until(lambda: not alive(below), 30), f"left behind: {alive(below)}"
        assert (out / "grades.csv").read_text() == (local / "grades.csv").read_text()
        assert recordings(out) == recordings(local)
    finally:
        restart_worker(cluster, 0)


def test_a_local_dask_cluster_grades_like_the_pool(klass: Path, local: Path, tmp_path: Path):
    out = tmp_path / "out"
    assert main(["batch", str(klass), "--out", str(out), "--dask-workers", "2", "--task", "move_circle"]) == 0
    assert (out / "grades.csv").read_text() == (local / "grades.csv").read_text()
    assert recordings(out) == recordings(local)


def test_an_unreachable_scheduler_is_one_clear_error(tmp_path: Path, klass: Path, capsys):
    code = main(["batch", str(klass), "--out", str(tmp_path / "out"), "--scheduler", "tcp://127.0.0.1:9",
                 "--task", "move_circle"])
    assert code == 2
    assert "cannot reach the Dask scheduler at tcp://127.0.0.1:9" in capsys.readouterr().err
