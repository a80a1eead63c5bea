"""Independent pieces of work (scenario runs, task scores, plots) in forked worker processes, N at a time.

A worker is a fork of this process, so it needs nothing pickled but its result. It ignores Ctrl+C (the parent
handles it and kills its workers), dies with its parent, and sends back its result with its stage timings
(`timing`), which the parent adds to its own.
"""
from __future__ import annotations

import contextlib
import ctypes
import os
import pickle
import signal
import sys
import threading
import traceback
from collections.abc import Callable, Iterator, Sequence
from multiprocessing.connection import Connection, wait
from typing import NoReturn, TypeVar

from grader import timing

PR_SET_PDEATHSIG = 1
T = TypeVar("T")
R = TypeVar("R")


class WorkerError(Exception):
    """A worker process failed for a reason of the grader's own (its traceback is in the message)."""


def fork_map(function: Callable[[T], R], items: Sequence[T], jobs: int = 1, *,
             started: Callable[[T], None] | None = None, first: Callable[[T], float] | None = None) -> list[R]:
    """``function(item)`` for every item, each in a forked worker, ``jobs`` at a time (in this process when 1), the
    results in the items' order. Items start in ``first`` order (smallest first), else in theirs. A worker that
    raises or dies raises WorkerError here, with its traceback."""
    if jobs <= 1 or len(items) <= 1:
        results = []
        for item in items:
            if started:
                started(item)
            results.append(function(item))
        return results
    order = sorted(range(len(items)), key=lambda i: first(items[i])) if first else list(range(len(items)))
    results: dict[int, R] = {}
    running: dict[Connection, tuple[int, int]] = {}  # reader -> (item index, worker pid)
    try:
        while order or running:
            while order and len(running) < jobs:
                index = order.pop(0)
                if started:
                    started(items[index])
                reader, pid = _fork(function, items[index])
                running[reader] = (index, pid)
            for reader in wait(list(running)):
                index, pid = running.pop(reader)
                results[index] = _collect(reader, pid)
    finally:
        for reader, (_index, pid) in running.items():
            _kill(pid)
            reader.close()
    return [results[i] for i in range(len(items))]


@contextlib.contextmanager
def ctrl_c_after_fork() -> Iterator[None]:
    """Hold a Ctrl+C that comes while the parent forks until the fork is over, then raise it. A KeyboardInterrupt
    raised in the fork's own hooks (logging releases its lock there) is printed and dropped by Python: a child that
    Ctrl+C'd its parent at once was lost that way on a busy machine, and the batch went on."""
    if threading.current_thread() is not threading.main_thread():
        yield  # signals reach the main thread only
        return
    parent, caught = os.getpid(), []
    previous = signal.signal(signal.SIGINT, lambda signum, frame: caught.append(signum))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
    if caught and os.getpid() == parent:
        if previous is signal.default_int_handler:
            raise KeyboardInterrupt  # here, where the caller can still stop the child it just started
        os.kill(parent, signal.SIGINT)  # to whatever handles Ctrl+C instead


def _fork(function: Callable[[T], R], item: T) -> tuple[Connection, int]:
    read_fd, write_fd = os.pipe()
    try:
        with ctrl_c_after_fork():
            pid = os.fork()
            if pid == 0:
                os.close(read_fd)
                _child(function, item, Connection(write_fd, readable=False))
    except KeyboardInterrupt:
        _kill(pid)  # Ctrl+C during the fork: no one else knows of this worker yet
        os.close(read_fd)
        raise
    finally:
        os.close(write_fd)
    return Connection(read_fd, writable=False), pid


def _collect(reader: Connection, pid: int) -> object:
    try:
        kind, payload, timings = reader.recv()
    except (EOFError, OSError):
        kind, payload, timings = "crash", "the worker process died without a result", {}
    finally:
        reader.close()
        with contextlib.suppress(ChildProcessError):
            os.waitpid(pid, 0)
    timing.merge(timings)
    if kind == "crash":
        raise WorkerError(f"a grading worker failed: {payload}")
    return payload


def _child(function: Callable[[T], R], item: T, writer: Connection) -> NoReturn:
    """Worker body: Ctrl+C is the parent's to handle (it kills us), and we die with the parent."""
    code = 0
    try:
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        die_with_parent()
        # Fresh standard streams: a thread of the parent (a progress display) may have held their locks at fork.
        sys.stdout = open(1, "w", closefd=False, encoding="utf-8", errors="replace")  # noqa: SIM115
        sys.stderr = open(2, "w", closefd=False, encoding="utf-8", errors="replace")  # noqa: SIM115
        timing.restart()
        outcome = function(item)
        writer.send(("done", outcome, timing.snapshot()))
    except BaseException as exc:  # noqa: BLE001 - whatever it is, the parent must hear of it
        try:
            writer.send(("crash", f"{type(exc).__name__}: {exc}\n{traceback.format_exc()}", timing.snapshot()))
        except (OSError, pickle.PicklingError):
            code = 1
    finally:
        writer.close()
        os._exit(code)


def die_with_parent() -> None:
    """Ask Linux to SIGKILL this process when its parent dies (a killed grader, batch or Dask worker leaves no
    orphans); exit at once if the parent is already gone."""
    try:
        ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGKILL)
    except (OSError, AttributeError):  # not Linux: the batch's own kill on exit still applies
        return
    if os.getppid() == 1:  # the parent died before the request was made
        os._exit(1)


def _kill(pid: int) -> None:
    with contextlib.suppress(ProcessLookupError, PermissionError):
        os.kill(pid, signal.SIGKILL)
    with contextlib.suppress(ChildProcessError):
        os.waitpid(pid, 0)
