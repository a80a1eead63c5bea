"""Batch grading: one isolated process per student, N at a time, resumable, and never stopped by one submission."""
from __future__ import annotations

import importlib
import json
import multiprocessing
import os
import signal
import time
import traceback
from collections.abc import Sequence
from dataclasses import dataclass, field
from multiprocessing.connection import wait
from multiprocessing.process import BaseProcess
from pathlib import Path

from rich.console import Console
from rich.markup import escape
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

from grader.report import SubmissionReport
from grader.reports.files import write_atomic
from grader.reports.folder import ReportFiles, write_report_folder
from grader.reports.gradebook import StudentResult, write_gradebook

REPORT_FILE = "report.json"
ERROR_FILE = "batch-error.json"
DEFAULT_TIMEOUT_S = 900.0


class BatchError(Exception):
    """The batch cannot start (no such folder, no submissions in it)."""


@dataclass(frozen=True)
class Student:
    """One submission in the batch folder: a folder or a .zip."""

    name: str
    path: Path


@dataclass
class BatchResult:
    """What a batch run did."""

    results: list[StudentResult] = field(default_factory=list)
    graded_now: int = 0
    skipped: int = 0
    interrupted: bool = False
    grades: Path | None = None
    summary: Path | None = None


def find_students(folder: Path, exclude: Path | None = None) -> list[Student]:
    """The submissions in folder (sub-folders and .zip files, hidden entries and exclude left out), by name."""
    if not folder.is_dir():
        raise BatchError(f"{folder} is not a folder")
    students: dict[str, Student] = {}
    for entry in sorted(folder.iterdir()):
        if entry.name.startswith((".", "_")) or (exclude is not None and entry.resolve() == exclude.resolve()):
            continue
        if entry.is_dir() or entry.suffix.lower() == ".zip":
            name = entry.stem if entry.suffix.lower() == ".zip" else entry.name
            if name in students:  # alice/ and alice.zip side by side
                name = entry.name
            students[name] = Student(name, entry)
    return list(students.values())


def grade_one(submission: Path, out_dir: Path, task_ids: Sequence[str] | None) -> tuple[SubmissionReport, ReportFiles]:
    """Grade one submission into out_dir and write its report folder (report.json last)."""
    grading = importlib.import_module("grader.grading")
    report = grading.grade_submission(submission, out_dir, task_ids).total()
    return report, write_report_folder(report, out_dir)


def load_result(student: str, folder: Path) -> StudentResult:
    """A student's outcome as found on disk: a complete report, a recorded error, or pending."""
    try:
        return StudentResult(student, SubmissionReport.model_validate_json((folder / REPORT_FILE).read_text("utf-8")), "graded")
    except (OSError, ValueError):
        pass
    try:
        error = json.loads((folder / ERROR_FILE).read_text("utf-8"))
        return StudentResult(student, None, str(error["status"]), str(error["message"]))
    except (OSError, ValueError, KeyError):
        return StudentResult(student, None, "pending", "")


def _record_error(folder: Path, status: str, message: str, details: str = "") -> None:
    write_atomic(folder / ERROR_FILE, json.dumps({"status": status, "message": message, "details": details}, indent=2))


def _worker(student: Student, folder: Path, task_ids: Sequence[str] | None) -> None:
    """Child process body: its own process group, so Ctrl+C and kills reach it and its nodes only through us."""
    os.setpgid(0, 0)
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        grading = importlib.import_module("grader.grading")
        try:
            grade_one(student.path, folder, task_ids)
        except grading.SubmissionError as exc:
            _record_error(folder, "error", str(exc))
    except Exception as exc:  # a crash in one student's grading must not stop the batch
        _record_error(folder, "error", f"grading crashed: {type(exc).__name__}: {exc}", traceback.format_exc())


def _kill(process: BaseProcess) -> None:
    """Kill a worker and everything it started (its process group)."""
    try:
        os.killpg(process.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        process.kill()
    process.join()


def run_batch(
    folder: Path,
    out: Path,
    jobs: int = 1,
    task_ids: Sequence[str] | None = None,
    timeout_s: float = DEFAULT_TIMEOUT_S,
    console: Console | None = None,
) -> BatchResult:
    """Grade every student not yet graded in out, then write grades.csv and summary.md (also after Ctrl+C)."""
    students = find_students(folder, exclude=out)
    if not students:
        raise BatchError(f"no submissions (folders or .zip files) in {folder}")
    out.mkdir(parents=True, exist_ok=True)
    result = BatchResult()
    todo = [s for s in students if not (out / s.name / REPORT_FILE).is_file()]
    result.skipped = len(students) - len(todo)
    context = multiprocessing.get_context("fork")
    running: dict[int, tuple[Student, BaseProcess, float]] = {}
    progress = Progress(
        TextColumn("grading"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(), TextColumn("{task.description}"),
        console=console or Console(stderr=True), transient=False,
    )
    bar = progress.add_task("", total=len(students), completed=result.skipped)
    try:
        with progress:
            while todo or running:
                while todo and len(running) < max(1, jobs):
                    student = todo.pop(0)
                    (out / student.name / ERROR_FILE).unlink(missing_ok=True)
                    process = context.Process(target=_worker, args=(student, out / student.name, task_ids), daemon=False)
                    process.start()
                    running[process.sentinel] = (student, process, time.monotonic())
                for sentinel in wait(list(running), timeout=0.5):
                    student, process, _ = running.pop(sentinel)
                    process.join()
                    _check_finished(student, out / student.name, process.exitcode)
                    result.graded_now += 1
                    progress.update(bar, advance=1, description=escape(student.name))
                for sentinel, (student, process, started) in list(running.items()):
                    if time.monotonic() - started > timeout_s:
                        _kill(process)
                        del running[sentinel]
                        _record_error(out / student.name, "timeout", f"grading took longer than {timeout_s:g} s")
                        result.graded_now += 1
                        progress.update(bar, advance=1, description=escape(student.name))
    except KeyboardInterrupt:
        result.interrupted = True
        for _student, process, _started in running.values():
            _kill(process)
    result.results = [load_result(s.name, out / s.name) for s in students]
    result.grades, result.summary = write_gradebook(out, result.results)
    return result


def _check_finished(student: Student, folder: Path, exitcode: int | None) -> None:
    """Record an error for a worker that died without leaving a report or an error (killed, out of memory)."""
    if (folder / REPORT_FILE).is_file() or (folder / ERROR_FILE).is_file():
        return
    how = f"signal {-exitcode}" if exitcode is not None and exitcode < 0 else f"exit code {exitcode}"
    hint = " (out of memory?)" if exitcode == -signal.SIGKILL else ""
    _record_error(folder, "error", f"grading process of {student.name} died with {how}{hint}")
