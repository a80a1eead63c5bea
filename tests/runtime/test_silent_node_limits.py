"""While the grader waits for a silent node it keeps checking the node's totals: a node over its memory or CPU limit
is stopped for that, within a check period, not for its silence once the watchdog runs out; time it spends
waiting for a CPU on a busy machine is not silence."""
from __future__ import annotations

import os
import time
from collections.abc import Iterator

import pytest

from grader.recording import default_catalog
from grader.runtime.node_link import MAX_QUEUED_CREDIT, NodeLink, NodeOverLimit, NodeSilent

CATALOG = default_catalog()


class Totals:
    """A stand-in for NodeProcess.over_limit: over the limit from the ``over_from``-th check on."""

    def __init__(self, over_from: int | None) -> None:
        self.over_from = over_from
        self.checks = 0

    def __call__(self) -> str | None:
        self.checks += 1
        if self.over_from is not None and self.checks >= self.over_from:
            return "its processes together used more than its memory limit of 300 MB"
        return None


@pytest.fixture
def pipes() -> Iterator[tuple[int, int]]:
    to_grader_r, to_grader_w = os.pipe()
    to_node_r, to_node_w = os.pipe()
    yield to_grader_r, to_node_w
    for fd in (to_grader_r, to_grader_w, to_node_r, to_node_w):
        os.close(fd)


def silent_link(pipes: tuple[int, int], totals: Totals | None, silent_wall_s: float) -> NodeLink:
    return NodeLink(*pipes, CATALOG, silent_wall_s=silent_wall_s, output_cap=1 << 20, over_limit=totals,
                    check_every_s=0.05)


def test_a_silent_node_over_its_limit_is_stopped_for_the_limit_before_the_watchdog(pipes) -> None:
    totals = Totals(over_from=3)
    started = time.monotonic()
    with pytest.raises(NodeOverLimit, match="memory limit of 300 MB"):
        silent_link(pipes, totals, silent_wall_s=5.0).run_until_wait(0, lambda event: None)
    assert totals.checks == 3
    assert time.monotonic() - started < 2.0


def test_a_silent_node_within_its_limits_is_stopped_for_its_silence(pipes) -> None:
    totals = Totals(over_from=None)
    with pytest.raises(NodeSilent, match="did not yield to the grader for 0.3 s"):
        silent_link(pipes, totals, silent_wall_s=0.3).run_until_wait(0, lambda event: None)
    assert totals.checks >= 4  # every 0.05 s of the 0.3 s, and once more when the watchdog ran out


def test_the_limit_is_named_when_the_watchdog_runs_out_between_two_checks(pipes) -> None:
    totals = Totals(over_from=1)
    link = NodeLink(*pipes, CATALOG, silent_wall_s=0.1, output_cap=1 << 20, over_limit=totals, check_every_s=60.0)
    with pytest.raises(NodeOverLimit):
        link.run_until_wait(0, lambda event: None)
    assert totals.checks == 1


def test_without_a_check_a_silent_node_is_stopped_for_its_silence(pipes) -> None:
    with pytest.raises(NodeSilent):
        NodeLink(*pipes, CATALOG, silent_wall_s=0.1, output_cap=1 << 20).run_until_wait(0, lambda event: None)


class RunQueue:
    """A stand-in for NodeProcess.queued_s: the node waits ``share`` of every wall second for a CPU."""

    def __init__(self, share: float) -> None:
        self.share = share
        self.started = time.monotonic()

    def __call__(self) -> float:
        return (time.monotonic() - self.started) * self.share


def test_time_a_starved_node_waits_for_a_cpu_is_not_its_silence(pipes) -> None:
    link = NodeLink(*pipes, CATALOG, silent_wall_s=0.3, output_cap=1 << 20, check_every_s=0.05,
                    queued_s=RunQueue(share=0.5))
    started = time.monotonic()
    with pytest.raises(NodeSilent):
        link.run_until_wait(0, lambda event: None)
    # Half of each second was the machine's: the watchdog needs 0.3 s of the node's own, about 0.6 s of wall time.
    assert time.monotonic() - started >= 0.5



def test_on_any_load_a_silence_ends_within_its_limit_and_the_run_queue_credit(pipes) -> None:
    """A node that waits for a CPU nearly all the time is still stopped: the run-queue wait moves the watchdog on by
    at most MAX_QUEUED_CREDIT silence limits."""
    link = NodeLink(*pipes, CATALOG, silent_wall_s=0.2, output_cap=1 << 20, check_every_s=0.02,
                    queued_s=RunQueue(share=0.99))
    started = time.monotonic()
    with pytest.raises(NodeSilent):
        link.run_until_wait(0, lambda event: None)
    waited = time.monotonic() - started
    assert (1 + MAX_QUEUED_CREDIT) * 0.2 - 0.05 <= waited < (1 + MAX_QUEUED_CREDIT) * 0.2 + 0.5
