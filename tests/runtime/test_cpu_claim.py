"""A run claims one CPU for itself and its nodes; claims spread parallel runs; nothing is pinned when none is free."""
from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import pytest

from grader.runtime import cpu_claim
from grader.runtime.cpu_claim import one_cpu

ALLOWED = os.sched_getaffinity(0)
needs_two_cpus = pytest.mark.skipif(len(ALLOWED) < 2, reason="pinning needs at least two CPUs to choose from")


@pytest.fixture(autouse=True)
def own_lock_folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Claims in a folder of the test's own, so graders running beside the tests neither see nor block them."""
    monkeypatch.setattr(cpu_claim, "_lock_folder", lambda: tmp_path)


def test_claims_live_where_every_grader_looks_whatever_its_temporary_directory(tmp_path: Path,
                                                                               monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.undo()
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    if Path("/dev/shm").is_dir() and os.access("/dev/shm", os.W_OK):
        assert cpu_claim._lock_path(0) == Path("/dev/shm/rosgrade-cpu-0.lock")
    else:
        assert cpu_claim._lock_path(0) == tmp_path / "rosgrade-cpu-0.lock"


@needs_two_cpus
def test_the_block_runs_on_the_claimed_cpu_and_the_affinity_comes_back() -> None:
    with one_cpu() as cpu:
        assert cpu in ALLOWED
        assert os.sched_getaffinity(0) == {cpu}
    assert os.sched_getaffinity(0) == ALLOWED


@needs_two_cpus
def test_a_process_started_in_the_block_inherits_the_cpu() -> None:
    with one_cpu() as cpu:
        out = subprocess.run([sys.executable, "-c", "import os; print(sorted(os.sched_getaffinity(0)))"],
                             capture_output=True, text=True, check=True).stdout
    assert out.strip() == str([cpu])


@needs_two_cpus
def test_concurrent_claims_get_different_cpus_until_none_is_left() -> None:
    claims = len(ALLOWED) + 1
    got: list[int | None] = []
    inside, leave = threading.Barrier(claims + 1), threading.Event()

    def claim() -> None:
        with one_cpu() as cpu:
            got.append(cpu)
            inside.wait()
            leave.wait()

    threads = []
    for _ in range(claims):  # one after the other, so the last one comes when the others hold theirs
        threads.append(threading.Thread(target=claim))
        threads[-1].start()
        while len(got) < len(threads):
            time.sleep(0.01)
    inside.wait()
    leave.set()
    for thread in threads:
        thread.join()
    pinned = [cpu for cpu in got if cpu is not None]
    assert set(pinned) == ALLOWED and len(pinned) == len(ALLOWED)
    assert got[-1] is None


@needs_two_cpus
def test_a_claim_held_by_another_process_is_respected_and_freed_when_it_dies(tmp_path: Path) -> None:
    holder = subprocess.Popen(
        [sys.executable, "-c",
         "import fcntl, os, sys, time\n"
         "fds = [os.open(p, os.O_RDONLY | os.O_CREAT) for p in sys.argv[1:]]\n"
         "[fcntl.flock(fd, fcntl.LOCK_EX) for fd in fds]\n"
         "print('held', flush=True); time.sleep(60)\n",
         *[str(cpu_claim._lock_path(cpu)) for cpu in ALLOWED]],
        stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout.readline().strip() == "held"
        with one_cpu() as cpu:
            assert cpu is None
            assert os.sched_getaffinity(0) == ALLOWED
    finally:
        holder.kill()
        holder.wait()
    with one_cpu() as cpu:
        assert cpu in ALLOWED


@needs_two_cpus
def test_an_unusable_lock_folder_leaves_the_run_unpinned(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(cpu_claim, "_lock_folder", lambda: tmp_path / "missing")
    with one_cpu() as cpu:
        assert cpu is None
        assert os.sched_getaffinity(0) == ALLOWED
