"""What a resumed batch still has to do for each student: nothing, re-score the recordings, or grade again, and why.

A report counts as done only when it loads and every task in it was made with the batch's rubric (same hash).
Otherwise its recordings are re-scored when they are all there, readable and made in the scenarios the rubric
runs now (no student code runs); else the submission is graded again.
"""
from __future__ import annotations

import importlib
import json
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

from grader.report import RECORDING_FORMAT, SubmissionReport, TaskReport
from grader.rubricfile import RubricFile, stamp

REPORT_FILE = "report.json"
ERROR_FILE = "batch-error.json"

Action = Literal["done", "rescore", "grade"]


@dataclass(frozen=True)
class Decision:
    """What to do for one student, why the report on disk is not kept (empty: there was none), and that report."""

    action: Action
    reason: str = ""
    report: SubmissionReport | None = None


def read_report(folder: Path) -> tuple[SubmissionReport | None, str]:
    """The report in folder, or None and why it cannot be used ('' when there is none)."""
    path = folder / REPORT_FILE
    try:
        text = path.read_text("utf-8")
    except FileNotFoundError:
        return None, ""
    except (OSError, UnicodeDecodeError) as exc:
        return None, f"report.json unreadable ({getattr(exc, 'strerror', None) or exc})"
    try:
        return SubmissionReport.model_validate_json(text), ""
    except ValueError:
        return None, "report.json unreadable (truncated, or written by another version)"


def decide(folder: Path, rubrics: Mapping[str, Any], files: Mapping[str, RubricFile]) -> Decision:
    """Done, re-score or grade for the student whose results are in folder (rubrics: the batch's tasks, in order)."""
    report, problem = read_report(folder)
    if report is None and not problem:
        return Decision("grade")
    if report is not None:
        stale = stale_tasks(report, files)
        if not stale and [t.id for t in report.tasks] == list(rubrics):
            return Decision("done", report=report)
        problem = _why_stale(report, stale, list(rubrics))
    redo = [task for task in rubrics if report is None or task in stale_tasks(report, files)]
    recorded = all((folder / task / f"{s.name}.mcap").is_file() for task in redo for s in rubrics[task].scenarios)
    return Decision("rescore" if recorded else "grade", problem, report)


def stale_tasks(report: SubmissionReport, files: Mapping[str, RubricFile]) -> list[str]:
    """The batch's tasks whose report is missing or was made with another rubric (or before reports named it)."""
    made = {t.id: t.rubric.sha256 if t.rubric else None for t in report.tasks}
    return [task for task, file in files.items() if made.get(task) != file.sha256]


def _why_stale(report: SubmissionReport, stale: Sequence[str], tasks: Sequence[str]) -> str:
    ids = [t.id for t in report.tasks]
    if sorted(ids) != sorted(tasks):
        return f"graded for other tasks ({', '.join(ids) or 'none'})"
    if any(t.rubric is None for t in report.tasks):
        return f"made by rosgrade {report.rosgrade_version} before reports named their rubric"
    return f"made with another {', '.join(stale)} rubric"


def rescore(folder: Path, decision: Decision, rubrics: Mapping[str, Any], files: Mapping[str, RubricFile],
            label: str) -> SubmissionReport | None:
    """The student's report from their recordings and the batch's rubrics; None when a recording is unusable."""
    kept = {t.id: t for t in decision.report.tasks} if decision.report else {}
    stale = set(stale_tasks(decision.report, files)) if decision.report else set(rubrics)
    tasks: list[TaskReport] = []
    for task_id, rubric in rubrics.items():
        if task_id not in stale:
            tasks.append(kept[task_id])
            continue
        task = _rescore_task(folder, rubric, kept.get(task_id))
        if task is None:
            return None
        tasks.append(task.model_copy(update={"rubric": stamp(rubric, files[task_id])}))
    submission = decision.report.submission if decision.report else label
    return SubmissionReport(submission=submission, tasks=tasks, recording_format=RECORDING_FORMAT).total()


def _rescore_task(folder: Path, rubric: Any, previous: TaskReport | None) -> TaskReport | None:
    recording_module = importlib.import_module("grader.recording")
    scoring = importlib.import_module("grader.scoring")
    recordings: dict[str, Any] = {}
    paths: list[str] = []
    timed_out = False
    notes: list[str] = []
    for scenario in rubric.scenarios:
        path = folder / rubric.id / f"{scenario.name}.mcap"
        try:
            recording = recording_module.Recording.open(path)
        except (recording_module.RecordingError, OSError):
            return None
        made = recording.metadata.get("rosgrade") or {}
        if not _same_scenario(made.get("scenario"), scenario):
            return None
        run = recording.metadata.get("rosgrade.run") or {}
        timed_out |= any(node.get("status") == "timeout" for node in _json_list(run.get("nodes")))
        for note in _json_list(run.get("diagnostics")) + (_json_list(run.get("topics")) if not paths else []):
            if note not in notes:
                notes.append(str(note))
        recordings[scenario.name] = recording
        paths.append(str(path))
    try:
        report = scoring.score_task(rubric, recordings)
    except scoring.ScoringError:
        return None
    # The script checks made while grading are only in the old report; scoring's and the runs' notes are recomputed.
    diagnostics = list(previous.diagnostics) if previous is not None else report.diagnostics + notes
    return report.model_copy(update={"status": "timeout" if timed_out else report.status, "recordings": paths,
                                     "diagnostics": diagnostics})


def _same_scenario(recorded: Any, scenario: Any) -> bool:
    """Whether a recording was made in this scenario (its description aside, which does not change the run)."""
    try:
        made = json.loads(recorded) if isinstance(recorded, str) else recorded
    except ValueError:
        return False
    if not isinstance(made, dict):
        return False
    made = dict(made)
    now = scenario.model_dump(mode="json")
    made.pop("description", None)
    now.pop("description", None)
    return made == now


def _json_list(text: Any) -> list[Any]:
    try:
        value = json.loads(text) if isinstance(text, str) else text
    except ValueError:
        return []
    return value if isinstance(value, list) else []
