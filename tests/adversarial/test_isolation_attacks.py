"""Nodes that go after the grader or their classmates' share of the machine: each attack fails in every isolation
mode that claims to stop it (bubblewrap, namespaces via unshare, a per-node uid, rlimits only)."""
from __future__ import annotations

import os
import secrets
import sys
import time
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

from adversarial_helpers import assert_nothing_escaped, run_case  # noqa: E402

from grader.runtime import confine  # noqa: E402
from grader.runtime.spec import Limits  # noqa: E402
from sim import Scenario  # noqa: E402

CAP = confine.detect()


@pytest.fixture(autouse=True)
def _no_leftovers():
    yield
    assert_nothing_escaped()


def _with_argument(token: str) -> list[int]:
    """Live processes with `token` among their arguments (whatever their environment or uid)."""
    found = []
    for pid in confine.processes():
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as handle:
                args = handle.read().split(b"\0")
        except OSError:
            continue
        if token.encode() in args and not confine.status_fields(pid).get("State", "Z").startswith("Z"):
            found.append(pid)
    return found


def test_double_forked_daemon_without_marker_does_not_outlive_the_run(tmp_path):
    token = f"rosgrade-outliver-{secrets.token_hex(6)}"
    case = run_case("double_fork_token", tmp_path, args=(token,))
    assert "parent leaving" in case.output
    deadline = time.monotonic() + 2.0
    while _with_argument(token) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not _with_argument(token), f"a daemon of the node outlived the run ({CAP.isolation})"


def test_grader_is_out_of_reach_through_its_pid(tmp_path, capfd):
    """No /proc/<grader> environment, cwd or stdout, no ptrace, no terminal: in every mode (in a PID namespace the
    grader does not exist; without one it is non-dumpable, and the node has a session of its own)."""
    case = run_case("reach_grader", tmp_path, args=(str(os.getpid()),))
    assert case.node.status == "exited", case.node.message
    for what in ("environ", "cwd", "stdout", "tty", "ptrace"):
        assert f"blocked {what}" in case.output, (what, CAP.isolation, case.output)
    assert "REACHED" not in case.output
    assert "own stdout only" in case.output  # what the node prints is recorded, not shown to the grader's user
    out, err = capfd.readouterr()
    assert "PWNED" not in out and "PWNED" not in err


@pytest.mark.skipif(not CAP.namespaces, reason=f"nodes run without namespaces here ({CAP.isolation}): /dev/shm is "
                    "the host's, which only bubblewrap or unshare can replace")
def test_dev_shm_is_small_and_private(tmp_path):
    name = f"rosgrade-shm-{secrets.token_hex(6)}"
    case = run_case("fill_shm", tmp_path, args=(name,))
    assert f"stopped after {confine.SHM_MB} MB: No space left on device" in case.output, case.output
    assert not Path("/dev/shm", name).exists()


@pytest.mark.skipif(CAP.mode == "rlimits", reason="with rlimits only the node's files are the grader user's own: "
                    "nothing tells them apart")
def test_dev_shm_files_do_not_outlive_the_run(tmp_path):
    name = f"rosgrade-shm-{secrets.token_hex(6)}"
    case = run_case("fill_shm", tmp_path, args=(name,))
    assert " MB" in case.output, case.output  # it wrote (all, or until its private /dev/shm was full)
    assert not Path("/dev/shm", name).exists()


@pytest.mark.parametrize("parent", ["yielding", "hang"])
def test_children_together_over_the_memory_limit_are_stopped(tmp_path, parent):
    """Whether the parent goes on yielding or hangs without a word (the grader then checks while it waits), the
    memory is the cause named, not the silence."""
    limits = Limits(wall_s=30, silent_wall_s=5, cpu_s=20, memory_mb=300, processes=32, output_bytes=200_000)
    # The totals are checked once a wall second. A node that only sleeps runs its own wake-ups without round trips,
    # so the run lasts about as long as its physics: 600 s take several wall seconds however fast this machine is.
    case = run_case("memory_children", tmp_path, args=(parent,), limits=limits,
                    scenario=Scenario(duration=600.0, shutdown_at=598.0))
    assert case.node.status == "killed_by_limit", case.node.message
    assert "processes together used more than its memory limit of 300 MB" in case.node.message


def test_children_together_over_the_cpu_limit_are_stopped(tmp_path):
    limits = Limits(wall_s=30, silent_wall_s=5, cpu_s=2, memory_mb=300, processes=32, output_bytes=200_000)
    # The parent steps every 10 ms of sim time, so 900 s take several wall seconds: long enough for the 1 s usage
    # check to see the children's CPU time add up, however fast this machine runs the lockstep.
    case = run_case("spinning_children", tmp_path, limits=limits,
                    scenario=Scenario(duration=900.0, shutdown_at=898.0))
    assert case.node.status == "killed_by_limit", case.node.message
    assert "CPU-time limit" in case.node.message


def test_every_mode_names_its_isolation():
    assert CAP.isolation in confine.ISOLATION.values()
    weak = not CAP.namespaces
    assert (CAP.note is not None) == (weak or CAP.unshare is not None)
    if weak:
        assert "install bubblewrap" in CAP.note
