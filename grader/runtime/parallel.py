"""Run independent scenarios side by side: one forked grader process per run, at most N at a time.

A run's recording depends only on its nodes and its scenario (lockstep), so running several at once changes
nothing in what is written; the caller gets the results in the order it gave the runs. Longer runs start first,
so the last one to finish is a short one. Each worker is its own grader process: it confines its nodes itself
(`confine.detect` hardens a forked process again), dies with its parent, and sends back its result and, when a
benchmark is collecting them, its stage timings.
"""
from __future__ import annotations

import contextlib
import ctypes
import os
import pickle
import signal
import sys
import traceback
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from multiprocessing.connection import Connection, wait
from pathlib import Path
from typing import NoReturn

from grader import timing
from grader.runtime.session import RunError, run
from grader.runtime.spec import RunResult, RunSpec

PR_SET_PDEATHSIG = 1


class WorkerError(Exception):
    """A worker process failed for a reason of the grader's own (its traceback is in the message)."""


@dataclass(frozen=True)
class Run:
    """One scenario run to carry out: what to run and where its recording and log go."""

    spec: RunSpec
    recording: Path
    log: Path


Outcome = RunResult | RunError


def _attempt(item: Run) -> Outcome:
    try:
        return run(item.spec, item.recording, item.log)
    except RunError as exc:
        return exc


def run_all(runs: Sequence[Run], jobs: int = 1, started: Callable[[Run], None] | None = None) -> list[Outcome]:
    """Carry out every run, `jobs` at a time; a RunError is returned in the run's place, not raised."""
    if jobs <= 1 or len(runs) <= 1:
        outcomes = []
        for item in runs:
            if started:
                started(item)
            outcomes.append(_attempt(item))
        return outcomes
    order = sorted(range(len(runs)), key=lambda i: -runs[i].spec.scenario.duration)
    outcomes: dict[int, Outcome] = {}
    running: dict[Connection, tuple[int, int]] = {}  # reader -> (run index, worker pid)
    try:
        while order or running:
            while order and len(running) < jobs:
                index = order.pop(0)
                if started:
                    started(runs[index])
                reader, pid = _fork(runs[index])
                running[reader] = (index, pid)
            for reader in wait(list(running)):
                index, pid = running.pop(reader)
                outcomes[index] = _collect(reader, pid)
    finally:
        for reader, (_index, pid) in running.items():
            _kill(pid)
            reader.close()
    return [outcomes[i] for i in range(len(runs))]


def _fork(item: Run) -> tuple[Connection, int]:
    read_fd, write_fd = os.pipe()
    pid = os.fork()
    if pid == 0:
        os.close(read_fd)
        _child(item, Connection(write_fd, readable=False))
    os.close(write_fd)
    return Connection(read_fd, writable=False), pid


def _collect(reader: Connection, pid: int) -> Outcome:
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


def _child(item: Run, writer: Connection) -> NoReturn:
    """Worker body: Ctrl+C is the parent's to handle (it kills us), and we die with the parent."""
    code = 0
    try:
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        with contextlib.suppress(OSError, AttributeError):
            ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGKILL)
        # Fresh standard streams: a thread of the parent (a progress display) may have held their locks at fork.
        sys.stdout = open(1, "w", closefd=False, encoding="utf-8", errors="replace")  # noqa: SIM115
        sys.stderr = open(2, "w", closefd=False, encoding="utf-8", errors="replace")  # noqa: SIM115
        timing.restart()
        outcome = _attempt(item)
        writer.send(("done", outcome, timing.snapshot()))
    except BaseException as exc:  # noqa: BLE001 - whatever it is, the parent must hear of it
        try:
            writer.send(("crash", f"{type(exc).__name__}: {exc}\n{traceback.format_exc()}", timing.snapshot()))
        except (OSError, pickle.PicklingError):
            code = 1
    finally:
        writer.close()
        os._exit(code)


def _kill(pid: int) -> None:
    with contextlib.suppress(ProcessLookupError, PermissionError):
        os.kill(pid, signal.SIGKILL)
    with contextlib.suppress(ChildProcessError):
        os.waitpid(pid, 0)
