"""Grade a submission: find each task's node, run every scenario of its rubric, score the recordings."""
from __future__ import annotations

import shutil
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path

from grader.recording import Recording, RecordingError
from grader.report import SubmissionReport, TaskReport
from grader.rubric import Node, Rubric, load_rubrics
from grader.runtime import NodeSpec, RunSpec, ScriptNotFound, check_script, find_script
from grader.runtime.scripts import candidates
from grader.runtime.session import RunError, run
from grader.scoring import score_task
from grader.submission import SubmissionError, open_submission

__all__ = ["SubmissionError", "grade_submission", "grade_task"]

Progress = Callable[[str], None]


def _script_names(node: Node) -> list[str]:
    return [node.script, *node.aliases]


def _locate(folder: Path, node: Node) -> tuple[Path, list[str]]:
    for name in _script_names(node):
        try:
            return find_script(folder, name)
        except ScriptNotFound:
            continue
    raise ScriptNotFound(f"no file named {' or '.join(_script_names(node))} in the submission")


def _present_tasks(folder: Path, rubrics: Mapping[str, Rubric]) -> list[str]:
    return [task for task, rubric in rubrics.items()
            if all(any(candidates(folder, n) for n in _script_names(node)) for node in rubric.nodes)]


def _node_spec(script: Path, node: Node) -> NodeSpec:
    args = (*node.args, *(f"{name}:={target}" for name, target in node.remaps.items()))
    return NodeSpec(script=script.resolve(), args=tuple(args), stdin=node.stdin, ros_namespace=node.namespace)


def grade_task(folder: Path, rubric: Rubric, out_dir: Path, progress: Progress | None = None) -> TaskReport:
    """Run every scenario of one rubric on the submission in `folder` and score the recordings."""
    try:
        located = [_locate(folder, node) for node in rubric.nodes]
    except ScriptNotFound as exc:
        return TaskReport(id=rubric.id, title=rubric.title, status="not_found", max_score=rubric.max_score,
                          message=f"{exc}; name your script as the task asks.")
    findings: list[str] = []
    for script, notes in located:
        findings += notes + check_script(script)
    task_dir = out_dir / rubric.id
    if task_dir.exists():
        shutil.rmtree(task_dir)
    task_dir.mkdir(parents=True)
    nodes = tuple(_node_spec(script, node) for (script, _), node in zip(located, rubric.nodes))
    recordings: dict[str, Recording] = {}
    paths: list[str] = []
    run_notes: list[str] = []
    timed_out = False
    for scenario in rubric.scenarios:
        if progress:
            progress(f"{rubric.id}: scenario {scenario.name}")
        mcap = task_dir / f"{scenario.name}.mcap"
        try:
            result = run(RunSpec(scenario=scenario, nodes=nodes, limits=rubric.limits, name=scenario.name),
                         mcap, task_dir / f"{scenario.name}.log")
            recordings[scenario.name] = Recording.open(mcap)
        except (RunError, RecordingError) as exc:
            return TaskReport(id=rubric.id, title=rubric.title, status="error", max_score=rubric.max_score,
                              recordings=paths, diagnostics=findings, message=f"scenario {scenario.name}: {exc}")
        paths.append(str(mcap))
        timed_out |= any(n.status == "timeout" for n in result.nodes)
        # Counts differ from scenario to scenario; the first (nominal) run's are the ones worth showing.
        for note in result.diagnostics + (result.topics if len(paths) == 1 else []):
            if note not in run_notes:
                run_notes.append(note)
    report = score_task(rubric, recordings)
    return report.model_copy(update={
        "status": "timeout" if timed_out else report.status,
        "recordings": paths,
        "diagnostics": findings + [n for n in report.diagnostics if n not in findings] + run_notes,
    })


def grade_submission(submission: Path, out_dir: Path, task_ids: Sequence[str] | None = None,
                     rubrics: Mapping[str, Rubric] | None = None,
                     progress: Progress | None = None) -> SubmissionReport:
    """Grade the named tasks (default: those whose scripts are present) and return the whole report."""
    rubrics = rubrics if rubrics is not None else load_rubrics()
    unknown = [t for t in task_ids or () if t not in rubrics]
    if unknown:
        raise SubmissionError(f"unknown task {', '.join(unknown)}; `rosgrade tasks` lists the tasks.")
    out_dir.mkdir(parents=True, exist_ok=True)
    with open_submission(submission) as folder:
        tasks = list(task_ids) if task_ids else _present_tasks(folder, rubrics)
        if not tasks:
            scripts = ", ".join(sorted({node.script for r in rubrics.values() for node in r.nodes}))
            raise SubmissionError(f"found none of the task scripts ({scripts}) in {submission}; "
                                  "name your script as the task asks, or pass --task.")
        reports = [grade_task(folder, rubrics[task], out_dir, progress) for task in tasks]
    return SubmissionReport(submission=str(submission), tasks=reports).total()
