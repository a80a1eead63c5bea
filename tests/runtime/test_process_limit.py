"""A node held at its process limit is named a fork bomb, whether the limit counts its own uid's tasks or, under the
grader's unprivileged uid, the user's: there its ceiling is what the user's other tasks leave, which moves."""
from __future__ import annotations

import pytest

from grader.runtime import process as process_module
from grader.runtime.node_link import NodeState
from grader.runtime.process import NodeProcess, Usage
from grader.runtime.spec import Limits
from grader.runtime.verdicts import refine

LIMITS = Limits(wall_s=20, silent_wall_s=3, cpu_s=15, memory_mb=300, processes=32, output_bytes=200_000)


def node(tasks: list[int], shared_nproc: int | None = None, user_tasks: int = 0,
         monkeypatch: pytest.MonkeyPatch | None = None) -> NodeProcess:
    """A NodeProcess whose usage() reads the next of ``tasks`` (no process behind it)."""
    proc = object.__new__(NodeProcess)
    proc.limits = LIMITS
    proc.peak_tasks = 0
    proc.hit_process_limit = False
    proc._at_process_limit = False
    proc._shared_nproc = shared_nproc
    counts = iter(tasks)
    proc.usage = lambda: Usage(memory_bytes=50 << 20, cpu_s=1.0, tasks=next(counts))  # type: ignore[method-assign]
    if monkeypatch is not None:
        monkeypatch.setattr(process_module, "_own_process_count", lambda: user_tasks)
    return proc


def test_a_node_over_its_process_count_is_stopped_at_once() -> None:
    assert "fork bomb" in node([33]).over_limit()


def test_a_node_at_its_own_uid_limit_for_two_checks_is_a_fork_bomb() -> None:
    proc = node([31, 31])
    assert proc.over_limit() is None
    assert "at or over its limit of 32" in proc.over_limit()


def test_a_node_that_reaches_its_limit_once_and_comes_back_is_not_stopped() -> None:
    proc = node([31, 12, 31])
    assert [proc.over_limit(), proc.over_limit(), proc.over_limit()] == [None, None, None]
    assert proc.hit_process_limit  # but if it ends badly, the verdict names the limit


def test_under_a_shared_uid_the_ceiling_is_the_users_total(monkeypatch) -> None:
    # The user's other tasks grew since the node started: its forks fail at 27 of its own.
    proc = node([27, 27], shared_nproc=40, user_tasks=39, monkeypatch=monkeypatch)
    assert proc.over_limit() is None
    assert "fork bomb" in proc.over_limit()


def test_under_a_shared_uid_a_node_with_headroom_is_left_alone(monkeypatch) -> None:
    proc = node([27, 27], shared_nproc=40, user_tasks=30, monkeypatch=monkeypatch)
    assert [proc.over_limit(), proc.over_limit()] == [None, None]
    assert not proc.hit_process_limit


def test_a_small_node_never_scans_the_users_tasks(monkeypatch) -> None:
    def scan() -> int:
        raise AssertionError("scanned /proc for a node with 3 tasks")
    proc = node([3], shared_nproc=40)
    monkeypatch.setattr(process_module, "_own_process_count", scan)
    assert proc.over_limit() is None


@pytest.mark.parametrize("status", ["timeout", "exited", "crashed", "protocol_violation"])
def test_a_node_stopped_after_hitting_its_process_limit_is_named_for_it(status, monkeypatch) -> None:
    proc = node([27], shared_nproc=40, user_tasks=40, monkeypatch=monkeypatch)
    proc.over_limit()
    verdict, message = refine(status, "did not yield to the grader for 3 s of wall time", None, NodeState(), proc,
                              LIMITS)
    assert verdict == "killed_by_limit"
    assert message.startswith("started 27 processes and threads and could start no more, at its limit of 32")


def test_a_silent_node_that_never_hit_its_limit_stays_a_timeout() -> None:
    proc = node([30])
    proc.over_limit()
    assert refine("timeout", "did not yield to the grader for 3 s of wall time", None, NodeState(), proc,
                  LIMITS)[0] == "timeout"
