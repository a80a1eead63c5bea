"""Batch grading: a class graded with one task set and one rubric set, resumable, never stopped by one submission.

Each student is one job (`grader.gradejob`), run by the local process pool or by Dask workers; the results come
back as data and only this process writes the output folder, so a fault there (full disk, folder gone) stops the
batch with one message and everything already written stays usable for the next run.
"""
from __future__ import annotations

import importlib
import json
import shutil
import zipfile
from collections import Counter
from collections.abc import Callable, Iterable, Sequence
from multiprocessing.connection import wait as wait_ready
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from rich.console import Console
from rich.markup import escape
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

from grader.gradejob import Job, Outcome, RunningJob
from grader.outfolder import OutputFault, OutputLock, describe, prepare
from grader.report import SubmissionReport
from grader.reports.files import write_atomic
from grader.reports.folder import ReportFiles, write_report_folder
from grader.reports.gradebook import StudentResult, TaskColumn, write_gradebook
from grader.resume import ERROR_FILE, REPORT_FILE, Decision, decide, rescore
from grader.roster import RosterError, Student, find_students
from grader.rubricfile import RubricFile, RubricFileError, rubric_files
from grader.taskfit import fitting_tasks, in_zip

PLAN_FILE = "batch.json"
DEFAULT_TIMEOUT_S = 900.0
SCENARIO_BYTES = 400_000  # a scenario's recording and log, before any student's results tell the real size
TASK_BYTES = 300_000  # a task's share of the report files and plots

OnDone = Callable[[Outcome], None]
Executor = Callable[[Sequence[Student], Callable[[Student], Job], OnDone], None]


class BatchError(Exception):
    """The batch cannot start or had to stop (no such folder, output folder not writable, disk full)."""


@dataclass
class BatchResult:
    """What a batch run did."""

    results: list[StudentResult] = field(default_factory=list)
    tasks: list[TaskColumn] = field(default_factory=list)
    graded_now: int = 0
    rescored: int = 0
    skipped: int = 0
    interrupted: bool = False
    notes: list[str] = field(default_factory=list)
    grades: Path | None = None
    summary: Path | None = None


def grade_one(submission: Path, out_dir: Path, task_ids: Sequence[str] | None,
              rubrics: dict[str, Any] | None = None, jobs: int = 1) -> tuple[SubmissionReport, ReportFiles]:
    """Grade one submission into out_dir (`jobs` scenarios at once) and write its report folder (report.json last)."""
    grading = importlib.import_module("grader.grading")
    report = grading.grade_submission(submission, out_dir, task_ids, rubrics, jobs=jobs).total()
    files = write_report_folder(report, out_dir, jobs=jobs)
    return files.report, files


def choose_tasks(task_ids: Sequence[str] | None, table: dict[str, Any], students: Sequence[Student],
                 out: Path) -> tuple[list[str], str]:
    """The assignment's tasks, the same for every student: --task, else those of the batch's first run, else the
    tasks whose scripts most submissions hold. Returns them and a sentence saying where they came from."""
    if task_ids:
        return list(dict.fromkeys(task_ids)), "given with --task"
    try:
        stored = json.loads((out / PLAN_FILE).read_text("utf-8"))["tasks"]
        if stored and all(t in table for t in stored):
            return list(stored), f"as in this folder's first run ({PLAN_FILE}); pass --task to change them"
    except (OSError, ValueError, KeyError, TypeError):
        pass
    counts = Counter(task for student in students for task in _tasks_present(student, table))
    chosen = [task for task in table if counts[task] * 2 >= len(students) and counts[task] > 0]
    if not chosen:
        raise BatchError("no task's scripts are in most submissions; name the tasks with --task "
                         "(`rosgrade tasks` lists them)")
    left_out = [f"{t} ({counts[t]})" for t in table if 0 < counts[t] and t not in chosen]
    found = ", ".join(f"{t} ({counts[t]}/{len(students)})" for t in chosen)
    return chosen, (f"found in most submissions: {found}" + (f"; left out: {', '.join(left_out)}" if left_out else "")
                    + "; pass --task to choose")


def _tasks_present(student: Student, table: dict[str, Any]) -> list[str]:
    """Tasks whose launch file or every script (or an alias) is in the submission, judged by file names alone."""
    names = set(_file_names(student))

    def present(rubric: Any) -> bool:
        launch = getattr(rubric, "launch", None)
        if launch is not None:
            return bool({launch.file, *launch.aliases} & names)
        return all({node.script, *node.aliases} & names for node in rubric.nodes)

    found = [task for task, rubric in table.items() if present(rubric)]
    try:  # one script for a TurtleBot and a turtlesim task (move_circle.py): its topics decide (grader.taskfit)
        return fitting_tasks(found, table, in_zip(student.pack))
    except (OSError, zipfile.BadZipFile):
        return found


def _file_names(student: Student) -> Iterable[str]:
    if student.files:
        return [name.rsplit("/", 1)[-1] for name, _ in student.files]
    if student.path.is_dir():
        return [p.name for p in student.path.rglob("*") if p.is_file()]
    if student.path.suffix.lower() == ".zip":
        try:
            with zipfile.ZipFile(student.path) as archive:
                return [n.rsplit("/", 1)[-1] for n in archive.namelist()]
        except (OSError, zipfile.BadZipFile):
            return []
    return [student.path.name]


class _Writer:
    """Everything the batch writes into `out`, with OSErrors turned into one OutputFault message."""

    def __init__(self, out: Path, rubrics: dict[str, Any]) -> None:
        self.out = out
        self.rubrics = rubrics
        self.need_bytes = sum(TASK_BYTES + SCENARIO_BYTES * len(r.scenarios) for r in rubrics.values())

    def fault(self, exc: OSError, where: Path) -> OutputFault:
        path = Path(exc.filename) if isinstance(exc.filename, str) else where
        return OutputFault(describe(exc, path, self.out, self.need_bytes))

    def graded(self, student: Student, graded: Any) -> None:
        """Store one student's results: old report out first, then recordings, then the report folder."""
        folder = self.out / student.key
        try:
            (folder / REPORT_FILE).unlink(missing_ok=True)
            (folder / ERROR_FILE).unlink(missing_ok=True)
            for task in self.rubrics:
                shutil.rmtree(folder / task, ignore_errors=True)
            for name, data in graded.files.items():
                write_atomic(folder / name, data)
            tasks = [t.model_copy(update={"recordings": [str(folder / r) for r in t.recordings]})
                     for t in graded.report.tasks]
            report = graded.report.model_copy(update={"tasks": tasks})
            write_report_folder(report, folder)
        except OSError as exc:
            raise self.fault(exc, folder) from None
        self.need_bytes = max(self.need_bytes, _size(folder))

    def rescored(self, student: Student, report: SubmissionReport) -> None:
        folder = self.out / student.key
        try:
            (folder / ERROR_FILE).unlink(missing_ok=True)
            write_report_folder(report, folder)
        except OSError as exc:
            raise self.fault(exc, folder) from None

    def error(self, student: Student, status: str, message: str, details: str = "") -> None:
        path = self.out / student.key / ERROR_FILE
        try:
            write_atomic(path, json.dumps({"status": status, "message": message, "details": details}, indent=2))
        except OSError as exc:
            raise self.fault(exc, path) from None

    def plan(self, tasks: list[str], files: dict[str, RubricFile]) -> None:
        path = self.out / PLAN_FILE
        plan = {"tasks": tasks, "rubrics": {t: {"file": f.source, "sha256": f.sha256} for t, f in files.items()}}
        try:
            write_atomic(path, json.dumps(plan, indent=2))
        except OSError as exc:
            raise self.fault(exc, path) from None


def _size(folder: Path) -> int:
    return sum(p.stat().st_size for p in folder.rglob("*") if p.is_file())


def local_pool(jobs: int) -> Executor:
    """The default executor: `jobs` students at a time, each in a child process of this machine.

    One thread starts and collects every job: a process forked while other threads hold locks could hang.
    """

    def execute(students: Sequence[Student], make_job: Callable[[Student], Job], on_done: OnDone) -> None:
        queue = list(students)
        running: dict[Any, RunningJob] = {}
        finished: dict[Any, Outcome] = {}  # collected but not stored yet
        try:
            while queue or running:
                while queue and len(running) < max(1, jobs):
                    student = queue.pop(0)
                    try:
                        job = make_job(student)
                    except OSError as exc:
                        on_done(Outcome(student.key, "error", message=f"cannot read the submission: {exc.strerror or exc}"))
                        continue
                    started = RunningJob(job)
                    running[started.reader] = started
                ready = wait_ready(list(running), timeout=0.5)
                for reader, job_running in list(running.items()):
                    if reader in ready or job_running.expired():
                        finished[reader] = job_running.outcome()
                        del running[reader]
                for reader in list(finished):
                    on_done(finished[reader])
                    del finished[reader]  # only once stored: after Ctrl+C in on_done it is stored below
        except KeyboardInterrupt:
            # Results that came back before Ctrl+C are kept; the jobs still running are killed (finally).
            finished.update({r: j.outcome() for r, j in running.items() if not r.closed and r.poll()})
            running = {r: j for r, j in running.items() if r not in finished}
            for outcome in finished.values():
                if outcome.status == "graded":
                    on_done(outcome)
            raise
        finally:
            for job_running in running.values():
                job_running.stop()

    return execute


def run_batch(
    folder: Path,
    out: Path,
    jobs: int = 1,
    task_ids: Sequence[str] | None = None,
    timeout_s: float = DEFAULT_TIMEOUT_S,
    console: Console | None = None,
    rubric_paths: Sequence[Path] = (),
    executor: Executor | None = None,
) -> BatchResult:
    """Grade every student not yet graded with the batch's rubrics in out, then write grades.csv and summary.md.

    Also after Ctrl+C, and after a fault in the output folder as far as the disk allows (then BatchError).
    """
    try:
        students = find_students(folder, exclude=out)
    except RosterError as exc:
        raise BatchError(str(exc)) from None
    if not students:
        raise BatchError(f"no submissions (folders or .zip files) in {folder}")
    try:
        prepare(out)
        with OutputLock(out):
            return _run_locked(students, out, task_ids, timeout_s, console or Console(stderr=True), rubric_paths,
                               executor or local_pool(jobs))
    except OutputFault as exc:
        raise BatchError(str(exc)) from None


def _run_locked(students: list[Student], out: Path, task_ids: Sequence[str] | None, timeout_s: float,
                console: Console, rubric_paths: Sequence[Path], execute: Executor) -> BatchResult:
    table = importlib.import_module("grader.rubric").task_table(rubric_paths)
    unknown = [t for t in task_ids or () if t not in table]
    if unknown:
        raise BatchError(f"unknown task {', '.join(map(repr, unknown))}; known tasks: {', '.join(sorted(table))}")
    tasks, how = choose_tasks(task_ids, table, students, out)
    rubrics = {t: table[t] for t in tasks}
    try:
        files = {f.task_id: f for f in rubric_files(rubrics.values())}
    except RubricFileError as exc:
        raise BatchError(str(exc)) from None
    result = BatchResult(tasks=[TaskColumn(t, float(r.max_score)) for t, r in rubrics.items()])
    console.print(f"Tasks: {', '.join(tasks)} ({how})", highlight=False, markup=False)
    writer = _Writer(out, rubrics)
    by_key = {s.key: s for s in students}
    decisions = {s.key: decide(out / s.key, rubrics, files) for s in students}
    why_rescored: Counter[str] = Counter()
    why_regraded: Counter[str] = Counter()
    todo: list[Student] = []
    # No refresh thread: grading processes are forked from this process, which must then have one thread only.
    progress = Progress(TextColumn("grading"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(),
                        TextColumn("{task.description}"), console=console, transient=False, auto_refresh=False)
    bar = progress.add_task("", total=len(students))
    fault: OutputFault | None = None

    def finished(outcome: Outcome) -> None:
        student = by_key[outcome.key]
        if outcome.status == "graded":
            writer.graded(student, outcome.graded)
        else:
            writer.error(student, outcome.status, outcome.message, outcome.details)
        result.graded_now += 1
        progress.update(bar, advance=1, description=escape(student.key), refresh=True)

    def make_job(student: Student) -> Job:
        return Job(student.key, str(student.path), student.pack(), tuple(tasks), tuple(files.values()), timeout_s)

    try:
        with progress:
            writer.plan(tasks, files)
            for student in students:
                decision = decisions[student.key]
                if decision.action == "done":
                    result.skipped += 1
                    progress.update(bar, advance=1, refresh=True)
                elif decision.action == "rescore" and _rescored(writer, student, decision, rubrics, files):
                    why_rescored[decision.reason] += 1
                    result.rescored += 1
                    progress.update(bar, advance=1, description=escape(f"{student.key} (re-scored)"), refresh=True)
                else:
                    if decision.reason:
                        why_regraded[decision.reason if decision.action == "grade"
                                     else f"{decision.reason}, and its recordings are unusable"] += 1
                    todo.append(student)
            execute(todo, make_job, finished)
    except KeyboardInterrupt:
        result.interrupted = True
    except OutputFault as exc:
        fault = exc
    result.notes = _notes(why_rescored, why_regraded)
    result.results = [_result(s, out / s.key, rubrics, files) for s in students]
    try:
        result.grades, result.summary = write_gradebook(out, result.results, result.tasks, result.notes)
    except OSError as exc:
        fault = fault or writer.fault(exc, out)
        written = "grades.csv and summary.md could not be written either"
    else:
        written = "grades.csv and summary.md are written for what is done"
    if fault is not None:
        done = sum(r.effective_status != "pending" for r in result.results)
        raise OutputFault(f"{fault}. The batch stopped: {done} of {len(students)} students are graded and kept, "
                          f"{written}; run the same command again to continue.")
    return result


def _rescored(writer: _Writer, student: Student, decision: Decision, rubrics: dict[str, Any],
              files: dict[str, RubricFile]) -> bool:
    report = rescore(writer.out / student.key, decision, rubrics, files, str(student.path))
    if report is None:
        return False
    writer.rescored(student, report)
    return True


def _notes(rescored: Counter[str], regraded: Counter[str]) -> list[str]:
    notes = []
    if rescored:
        notes.append(f"Re-scored from their recordings (no code run): {sum(rescored.values())} ("
                     + "; ".join(f"{n}: {why}" for why, n in rescored.most_common()) + ")")
    if regraded:
        notes.append(f"Graded again: {sum(regraded.values())} ("
                     + "; ".join(f"{n}: {why}" for why, n in regraded.most_common()) + ")")
    return notes


def _result(student: Student, folder: Path, rubrics: dict[str, Any], files: dict[str, RubricFile]) -> StudentResult:
    """A student's row: their report when the batch's rubrics made it, else their recorded error, else pending."""
    decision = decide(folder, rubrics, files)
    if decision.action == "done":
        return StudentResult(student.key, decision.report, "graded", name=student.name)
    try:
        error = json.loads((folder / ERROR_FILE).read_text("utf-8"))
        return StudentResult(student.key, None, str(error["status"]), str(error["message"]), name=student.name)
    except (OSError, ValueError, KeyError, TypeError):
        return StudentResult(student.key, None, "pending", "", name=student.name)
