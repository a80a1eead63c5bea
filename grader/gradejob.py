"""One student's grading as a job: a child process of its own, a time limit, results back as data.

The local pool and a Dask worker both call `run_job`; it is the only place a student's grading is started, so
a submission gets the same isolation (own process group, killed with its nodes on timeout, on Ctrl+C and when
the process that started it dies) wherever it runs.
"""
from __future__ import annotations

import contextlib
import importlib
import os
import shutil
import signal
import tempfile
import time
import traceback
from dataclasses import dataclass
from pathlib import Path
from multiprocessing.connection import Connection
from typing import Any, Literal, NoReturn

from grader.submission import OWNER_FILE, STAGE_PREFIX, claim, remove_if_abandoned
from grader.workers import ctrl_c_after_fork, die_with_parent

SCRATCH_PREFIX = "rosgrade-worker-"

Status = Literal["graded", "error", "timeout"]


@dataclass(frozen=True)
class Job:
    """What a grader process needs, as plain data: the submission as zip bytes, the tasks and their rubric files."""

    key: str  # the student's output folder
    label: str  # the submission as the report names it
    submission: bytes
    task_ids: tuple[str, ...]
    rubrics: tuple[Any, ...]  # grader.grading.RubricFile
    timeout_s: float


@dataclass
class Outcome:
    """How a job ended: its results (grader.grading.GradedSubmission) or why there are none."""

    key: str
    status: Status
    graded: Any = None
    message: str = ""
    details: str = ""


class RunningJob:
    """A job's child process: started at once, its results read when `reader` is ready or its time is up."""

    def __init__(self, job: Job) -> None:
        self.job = job
        self.deadline = time.monotonic() + job.timeout_s
        # The submission is unpacked at a fixed place (its path reaches the recordings); every other temporary
        # folder of the job goes under `scratch`, removed however the job ends.
        self.stage_root = Path(tempfile.gettempdir())
        for abandoned in self.stage_root.glob(f"{SCRATCH_PREFIX}*"):  # left by a batch that was killed
            remove_if_abandoned(abandoned)
        self.scratch = Path(tempfile.mkdtemp(prefix=SCRATCH_PREFIX))
        claim(self.scratch)
        importlib.import_module("grader.grading")  # imported once here rather than again in every child
        read_fd, write_fd = os.pipe()
        # Forked directly (not with multiprocessing), so this also works inside Dask's daemonic worker processes.
        interrupted = False
        try:
            with ctrl_c_after_fork():
                self.pid = os.fork()
                if self.pid == 0:  # the child never returns from here
                    os.close(read_fd)
                    _child(job, Connection(write_fd, readable=False), self.scratch, self.stage_root)
                # Its own group from here, whichever of the two runs first, so that a kill of the group reaches it.
                with contextlib.suppress(OSError):
                    os.setpgid(self.pid, self.pid)
        except KeyboardInterrupt:
            interrupted = True
        os.close(write_fd)
        self.reader = Connection(read_fd, writable=False)
        if interrupted:  # Ctrl+C during the fork: no one else knows of this child yet
            self.stop()
            raise KeyboardInterrupt

    def expired(self) -> bool:
        """Whether the job has used up its time."""
        return time.monotonic() >= self.deadline

    def outcome(self) -> Outcome:
        """The results (call when `reader` is ready), or a timeout when it is not; the child is gone afterwards."""
        try:
            if not self.reader.poll():
                return Outcome(self.job.key, "timeout", message=f"grading took longer than {self.job.timeout_s:g} s")
            try:
                status, payload, details = self.reader.recv()
            except (EOFError, OSError):  # the child died before sending anything
                _kill_group(self.pid)
                code = _reap(self.pid)
                how = f"signal {-code}" if code is not None and code < 0 else f"exit code {code}"
                hint = " (out of memory?)" if code == -signal.SIGKILL else ""
                return Outcome(self.job.key, "error", message=f"grading process of {self.job.key} died with {how}{hint}")
            if status == "graded":
                return Outcome(self.job.key, "graded", graded=payload)
            return Outcome(self.job.key, "error", message=payload, details=details)
        finally:
            self.stop()

    def stop(self) -> None:
        """Kill the child and its nodes (its process group), release the pipe and remove its temporary folders."""
        _kill_group(self.pid)
        _reap(self.pid)
        self.reader.close()
        shutil.rmtree(self.scratch, ignore_errors=True)
        for staged in self.stage_root.glob(f"{STAGE_PREFIX}*/{OWNER_FILE}"):
            with contextlib.suppress(OSError, ValueError):
                if int(staged.read_text()) == self.pid:
                    shutil.rmtree(staged.parent, ignore_errors=True)


def run_job(job: Job) -> Outcome:
    """Grade job's submission in a child process and wait for it; never raises for anything the submission does."""
    running = RunningJob(job)
    running.reader.poll(max(0.0, running.deadline - time.monotonic()))
    return running.outcome()


def _reap(pid: int) -> int | None:
    """Wait for the child; its exit code, or minus the signal that killed it (None if already reaped)."""
    try:
        _, status = os.waitpid(pid, 0)
    except ChildProcessError:
        return None
    return os.waitstatus_to_exitcode(status)


def _child(job: Job, writer: Connection, scratch: Path, stage_root: Path) -> NoReturn:
    """Child body: its own process group (kills reach its nodes), no Ctrl+C of its own, dies with its parent."""
    code = 0
    try:
        tempfile.tempdir = str(scratch)
        os.setpgid(0, 0)
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        die_with_parent()
        grading = importlib.import_module("grader.grading")
        try:
            graded = grading.grade_as_data(job.submission, job.label, job.task_ids, job.rubrics, stage_root)
            writer.send(("graded", graded, ""))
        except grading.SubmissionError as exc:
            writer.send(("error", str(exc), ""))
    except BaseException as exc:  # a crash in one student's grading must not stop the batch
        try:
            writer.send(("error", f"grading crashed: {type(exc).__name__}: {exc}", traceback.format_exc()))
        except OSError:
            code = 1
    finally:
        writer.close()
        os._exit(code)


def _kill_group(group: int) -> None:
    try:
        os.killpg(group, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass
