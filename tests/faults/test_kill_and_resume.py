"""SIGKILL of a batch at random moments: the next run always ends with the grades.csv of an uninterrupted run,
no process of the killed batch is left behind, and its lock does not keep the next batch out."""
from __future__ import annotations

import os
import random
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest


RUNNER = Path(__file__).with_name("fake_rosgrade.py")
TRIALS = int(os.environ.get("ROSGRADE_KILL_TRIALS", "12"))  # more for a longer hunt


def start_batch(folder: Path, out: Path, *extra: str) -> subprocess.Popen[bytes]:
    """The batch in a process of its own, with a temporary folder of its own (beside `out`)."""
    temp = out.parent / "tmp"
    temp.mkdir(exist_ok=True)
    return subprocess.Popen([sys.executable, str(RUNNER), "batch", str(folder), "--out", str(out), "-j", "2", *extra],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, start_new_session=True,
                            env={**os.environ, "TMPDIR": str(temp)})


def processes_of(marker: str) -> list[int]:
    """Processes whose command line names `marker` (the batch and any job it forked)."""
    found = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                if marker in (entry / "cmdline").read_bytes().decode(errors="replace"):
                    found.append(int(entry.name))
            except OSError:
                continue
    return found


def wait_gone(marker: str, seconds: float = 10.0) -> list[int]:
    deadline = time.monotonic() + seconds
    while (left := processes_of(marker)) and time.monotonic() < deadline:
        time.sleep(0.05)
    return left


def test_sigkill_at_random_moments_then_resume_gives_the_uninterrupted_grades(klass, reference, tmp_path):
    rng = random.Random(20)  # fixed seed: the same moments on every run of the suite
    for trial in range(TRIALS):
        out = tmp_path / f"out{trial}"
        batch = start_batch(klass, out)
        time.sleep(rng.uniform(0.2, 4.0))
        batch.send_signal(signal.SIGKILL)
        batch.wait()
        assert wait_gone(str(out)) == [], f"trial {trial}: processes of the killed batch are still running"
        resumed = start_batch(klass, out)
        _, err = resumed.communicate(timeout=300)
        assert resumed.returncode == 0, err.decode()
        assert (out / "grades.csv").read_text() == reference, f"trial {trial}"
        # The next batch removed the temporary folders the killed one could not.
        assert list((tmp_path / "tmp").iterdir()) == [], f"trial {trial}"


def test_a_second_batch_on_the_same_folder_is_refused_while_the_first_runs(klass, tmp_path):
    (klass / "zed_slow").mkdir()
    first = start_batch(klass, tmp_path / "out", "--timeout", "60")
    try:
        deadline = time.monotonic() + 30
        while not (tmp_path / "out" / "batch.json").exists() and time.monotonic() < deadline:
            time.sleep(0.05)
        second = start_batch(klass, tmp_path / "out")
        _, err = second.communicate(timeout=60)
        assert second.returncode == 2
        assert f"another rosgrade batch (pid {first.pid} on " in err.decode()
        assert f"is writing into {tmp_path / 'out'}" in err.decode()
    finally:
        first.send_signal(signal.SIGKILL)
        first.wait()
    assert wait_gone(str(tmp_path / "out")) == []
    third = start_batch(klass, tmp_path / "out", "--timeout", "1")  # the killed batch left no stuck lock
    _, err = third.communicate(timeout=120)
    assert third.returncode == 0, err.decode()


@pytest.fixture(autouse=True)
def _no_leftovers(tmp_path):
    yield
    for pid in processes_of(str(tmp_path)):
        os.kill(pid, signal.SIGKILL)
