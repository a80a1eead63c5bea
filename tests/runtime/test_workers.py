"""fork_map: any independent work in forked workers, results in the items' order, failures raised here."""
from __future__ import annotations

import os
import signal
import time

import pytest

from grader import timing
from grader.workers import WorkerError, ctrl_c_after_fork, fork_map


def _square_and_pid(n: int) -> tuple[int, int]:
    timing.count("items")
    return n * n, os.getpid()


@pytest.mark.parametrize("jobs", [2, 3, 8])
def test_results_come_back_in_the_items_order_from_other_processes(jobs: int) -> None:
    results = fork_map(_square_and_pid, [5, 1, 4, 2, 3], jobs)
    assert [value for value, _ in results] == [25, 1, 16, 4, 9]
    assert os.getpid() not in {pid for _, pid in results}


def test_one_job_works_here_in_the_items_order() -> None:
    started: list[int] = []
    results = fork_map(_square_and_pid, [3, 1, 2], 1, started=started.append, first=lambda n: n)
    assert [value for value, _ in results] == [9, 1, 4] and started == [3, 1, 2]
    assert {pid for _, pid in results} == {os.getpid()}


def test_first_decides_which_items_start_first() -> None:
    started: list[int] = []
    fork_map(_square_and_pid, [3, 1, 2, 5], 2, started=started.append, first=lambda n: -n)
    assert started == [5, 3, 2, 1]


def test_a_closure_needs_no_pickling_only_its_result_does() -> None:
    offset = 10
    assert fork_map(lambda n: n + offset, [1, 2, 3], 2) == [11, 12, 13]


def test_a_failing_item_raises_worker_error_with_its_traceback() -> None:
    def fail_on_two(n: int) -> int:
        if n == 2:
            raise KeyError("two")
        return n

    with pytest.raises(WorkerError, match="KeyError: 'two'"):
        fork_map(fail_on_two, [1, 2, 3], 2)


def test_a_worker_that_dies_raises_worker_error() -> None:
    with pytest.raises(WorkerError, match="died without a result"):
        fork_map(lambda n: os._exit(3) if n == 2 else n, [1, 2], 2)


def test_the_workers_timings_are_added_to_the_parents() -> None:
    with timing.collect() as stages:
        fork_map(_square_and_pid, [1, 2, 3], 2)
    assert stages["# items"] == 3.0


def test_a_ctrl_c_during_a_fork_is_raised_once_the_fork_is_over():
    reached_end = False
    with pytest.raises(KeyboardInterrupt):
        with ctrl_c_after_fork():
            os.kill(os.getpid(), signal.SIGINT)  # as a child that Ctrl+C's its parent at once
            time.sleep(0.05)  # the handler runs here: held, not raised (nor dropped, as in the fork's own hooks)
            reached_end = True
    assert reached_end
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
