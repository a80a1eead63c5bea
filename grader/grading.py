"""Grade a submission: find each task's node, run every scenario of its rubric, score the recordings."""
from __future__ import annotations

import fnmatch
import hashlib
import shutil
import tempfile
import time
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field, replace
from pathlib import Path

from grader import timing
from grader.interfaces import InterfaceSet, run_interfaces
from grader.launch import LaunchError, find_packages, read_launch, turtlesim
from grader.launch.ros2_acts import LaunchActs, with_acts
from grader.launch.ros2_cli import build_type_of, is_ros2_file
from grader.launch.ros2_specs import ros2_node_specs
from grader.launch.specs import node_specs
from grader.provided_nodes import provided_specs
from grader.recording import Recording, RecordingError
from grader.recording.ros2_messages import ACTIONS as BUILTIN_ACTIONS
from grader.recording.ros2_messages import SERVICES as BUILTIN_SERVICES
from grader.report import RECORDING_FORMAT, SubmissionReport, TaskReport
from grader.rubric import Node, Rubric, Scenario, load_rubrics
from grader.rubricfile import RubricFile, load_rubric_files, stamp
from grader.runtime import NodeSpec, RunSpec, ScriptNotFound, check_script, find_script
from grader.runtime.client_library import (
    ROS1, ROS2, client_library, entry_point, import_roots, package_findings, param_args,
)
from grader.runtime.confine import detect, package_folder
from grader.runtime.int_fields import int_field_findings
from grader.runtime.scripts import candidates
from grader.runtime.parallel import Outcome, Run, run_all
from grader.runtime.session import RunError, node_log_path
from grader.scoring import score_task
from grader.taskfit import fitting_tasks, in_folder
from grader.submission import (
    STAGE_PREFIX, SubmissionError, claim, links_leaving, open_submission, remove_if_abandoned, unzip,
)
from grader.workers import fork_map
from grader.workspace import Workspace, read_workspace

__all__ = ["GradedSubmission", "SubmissionError", "grade_as_data", "grade_submission", "grade_task"]

STAGE_WAIT_S = 5.0  # longest wait for a killed grading of the same submission to release its unpack folder

Progress = Callable[[str], None]
# A rubric's service type spelled "*/srv/<Name>" is the submission's own srv <Name>, in whichever of its packages
# generates it: the student calls it by their own package's name (`ros2 service call ... part4_services/srv/...`).
OWN_TYPE = "*/"


class _NoOwnType(Exception):
    """The task names a type of the submission's own that no package of it generates."""


def _own_type(name: str, interfaces: InterfaceSet | None, flavour: str = ROS2) -> str:
    """``name``, or for "*/srv/<Name>" ("*/action/<Name>") the submission's own srv (action) of that name (the first
    package's, by name), as the run's client library spells it (rospy: ``pkg/Name`` for a srv); without one, rclpy's
    built-in type of that name, as the tutorials use either (example_interfaces' AddTwoInts and Fibonacci, or their
    own with the same fields). rospy's tutorials always build their own (catkin's add_service_files/add_action_files)."""
    if not name.startswith(OWN_TYPE):
        return name
    wanted = name[len(OWN_TYPE):]
    kind, _, base = wanted.partition("/")
    owned = (interfaces.services if kind == "srv" else interfaces.actions) if interfaces else {}
    # a catkin package's actions are keyed pkg/msg/Name (genmsg makes messages of them)
    owners = sorted(f"{t.split('/', 1)[0]}/{kind}/{base}" for t in owned if t.rsplit("/", 1)[-1] == base)
    if not owners and flavour == ROS2:
        owners = sorted(t for t in (BUILTIN_ACTIONS if kind == "action" else BUILTIN_SERVICES)
                        if t.split("/", 1)[-1] == wanted)
    if not owners:
        build = (f"list {base}.{kind} in add_{'service' if kind == 'srv' else 'action'}_files() and call "
                 "generate_messages() in its CMakeLists.txt" if flavour == ROS1 else
                 f"list \"{wanted}.{kind}\" in rosidl_generate_interfaces() in its CMakeLists.txt")
        raise _NoOwnType(f"no package in your submission generates the {kind} type {base} this task calls: write "
                         f"{wanted}.{kind} in your package and {build}")
    package, _, _ = owners[0].partition("/")
    return f"{package}/{base}" if flavour == ROS1 and kind == "srv" else owners[0]


def _with_own_types(scenario: Scenario, nodes: tuple[NodeSpec, ...], interfaces: InterfaceSet | None,
                    ) -> tuple[Scenario, tuple[NodeSpec, ...]]:
    """The scenario's calls and goals and the nodes' arguments with every "*/srv/<Name>" ("*/action/<Name>") made the
    submission's own type, spelled for the nodes' client library."""
    flavour = nodes[0].flavour if nodes else ROS2
    calls = [call.model_copy(update={"type": _own_type(call.type, interfaces, flavour)})
             for call in scenario.service_calls]
    goals = [goal.model_copy(update={"type": _own_type(goal.type, interfaces, flavour)})
             for goal in scenario.action_goals]
    nodes = tuple(replace(spec, args=tuple(_own_type(arg, interfaces, spec.flavour) for arg in spec.args))
                  for spec in nodes)
    return scenario.model_copy(update={"service_calls": calls, "action_goals": goals}), nodes


def _script_names(node: Node) -> list[str]:
    return [node.script, *node.aliases]


def _locate(folder: Path, node: Node, only_node: bool) -> tuple[Path, list[str]]:
    if folder.is_file() and only_node:  # one script named on the command line with --task: grade that file
        if folder.name in _script_names(node):
            return folder, []
        return folder, [f"Graded {folder.name} as {node.script}; on a ROS machine the task expects it under "
                        f"that name."]
    for name in _script_names(node):
        try:
            return find_script(folder, name)
        except ScriptNotFound:
            continue
    raise ScriptNotFound(f"no file named {' or '.join(_script_names(node))} in the submission")


def _present(folder: Path, rubric: Rubric) -> bool:
    if rubric.launch is not None and any(candidates(folder, name)
                                         for name in [rubric.launch.file, *rubric.launch.aliases]):
        return True
    return bool(rubric.nodes) and all(any(candidates(folder, n) for n in _script_names(node)) for node in rubric.nodes)


def _present_tasks(folder: Path, rubrics: Mapping[str, Rubric]) -> list[str]:
    """The tasks whose files are in the submission; a script both a TurtleBot and a turtlesim task would run counts
    for the one whose world its topics name (``grader.taskfit``)."""
    return fitting_tasks([task for task, rubric in rubrics.items() if _present(folder, rubric)], rubrics,
                         in_folder(folder))


def _node_spec(script: Path, node: Node, workspace: Workspace) -> NodeSpec:
    flavour = client_library(script, workspace)
    roots = import_roots(script, workspace, flavour)
    if flavour == ROS2:
        # rclpy reads remaps after --ros-args (`ros2 run pkg exe --ros-args -r cmd_vel:=/x`)
        remaps = [part for name, target in node.remaps.items() for part in ("-r", f"{name}:={target}")]
        args = (*node.args, *param_args(ROS2, node.params), *(("--ros-args", *remaps) if remaps else ()))
        return NodeSpec(script=script.resolve(), args=tuple(args), stdin=node.stdin, ros_namespace=node.namespace,
                        flavour=ROS2, entry=entry_point(script, workspace), import_roots=roots)
    remaps = [f"{name}:={target}" for name, target in node.remaps.items()]
    args = (*node.args, *param_args(ROS1, node.params), *remaps)
    return NodeSpec(script=script.resolve(), args=tuple(args), stdin=node.stdin, ros_namespace=node.namespace,
                    import_roots=roots)


def _links_leaving(folder: Path, scripts: list[Path]) -> list[str]:
    """The scripts and the files of their packages that are links out of the submission, relative to it."""
    if not folder.is_dir():  # a single script given on the command line: the user chose that file
        return []
    paths = [p for script in scripts for p in (script, package_folder(script))]
    return [str(link.relative_to(folder)) for link in links_leaving(folder, paths)]


Started = tuple[tuple[NodeSpec, ...], list[str], list[Path]]  # node specs, findings, the scripts as found


def _script_nodes(folder: Path, rubric: Rubric) -> Started:
    located = [_locate(folder, node, len(rubric.nodes) == 1) for node in rubric.nodes]
    findings: list[str] = []
    workspace = read_workspace(folder)
    nodes = tuple(_node_spec(script, node, workspace) for (script, _), node in zip(located, rubric.nodes))
    for (script, notes), spec in zip(located, nodes):
        # rosrun's needs (shebang, execute bit) are not `ros2 run`'s: package_findings says what it would trip over
        findings += notes + check_script(script, rosrun=spec.flavour == ROS1)
        if spec.flavour == ROS2:
            findings += package_findings(script, spec.entry, workspace) + int_field_findings(script)
    if len({spec.flavour for spec in nodes}) > 1:
        raise ScriptNotFound("the task's nodes mix rospy and rclpy scripts; ROS 1 and ROS 2 nodes cannot talk to "
                             "each other: write them all with one client library")
    # The grader's own nodes (a server the student's client calls, teleop) are neither checked nor the student's files.
    provided = provided_specs(rubric.grader_nodes, nodes[0].flavour, workspace)
    return nodes + provided, findings, [script for script, _ in located]


def _launch_nodes(folder: Path, rubric: Rubric) -> tuple[Started, LaunchActs]:
    """The nodes the student's launch file starts, as `roslaunch pkg file args...` (or `ros2 launch`) would, and what
    the grader carries out for a ROS 2 launch file's ros2 command lines (LaunchError if it cannot be read); without
    the launch file, the rubric's [[nodes]] when it names some too."""
    task = rubric.launch
    names = [task.file, *task.aliases]
    try:
        where = _launch_package(folder, task.package) if task.package else folder
        found = next((candidates(where, name) for name in names if candidates(where, name)), None)
        if not found:
            inside = f"package {where.name}" if task.package else "the submission"
            raise ScriptNotFound(f"no launch file named {' or '.join(names)} in {inside}; put it in your "
                                 "package's launch/ folder")
    except ScriptNotFound as exc:
        if not rubric.nodes:
            raise
        try:
            return _script_nodes(folder, rubric), LaunchActs()
        except ScriptNotFound as missing:
            raise ScriptNotFound(f"{missing}, and {exc}") from None
    if is_ros2_file(found[0], build_type_of(found[0])):
        return _ros2_launch_nodes(folder, found[0], rubric)
    packages = find_packages(folder)
    launch = read_launch(found[0], task.args, packages, confine_to=folder)
    nodes, findings = node_specs(launch, packages, task.stdin, task.allow_not_executable)
    for name, value in task.args.items():
        if name not in launch.args:
            findings.append(f"{found[0].name} declares no <arg name=\"{name}\">, so roslaunch ignored the "
                            f"task's {name}:={value}: declare it and use $(arg {name}) where the value is needed.")
    world_node = turtlesim.world_node(launch)
    findings += turtlesim.check_robot(launch, world_node, rubric.robot)
    for world in launch.worlds:
        if world.robot != rubric.robot:
            findings.append(f"{world.where}: {world.package}/{world.file} starts a {world.robot}, but this task is "
                            f"graded on a {rubric.robot}.")
    # The grader's own nodes (turtle_teleop_key, mimic) are neither checked nor shown as the student's files.
    scripts = list(dict.fromkeys(spec.script for spec in nodes if not spec.provided))
    for script in scripts:
        findings += check_script(script)
    acts = LaunchActs() if world_node is None else \
        LaunchActs(turtlesim_windows=world_node.windows, world_names=world_node.world_names)
    return (nodes, findings, [found[0], *scripts]), acts


def _launch_package(folder: Path, pattern: str) -> Path:
    """The folder of the submission's package a rubric's [launch] names (package.xml's name; wildcards allowed)."""
    packages = read_workspace(folder).folders if folder.is_dir() else {}
    names = sorted(name for name in packages if fnmatch.fnmatchcase(name, pattern))
    if not names:
        raise ScriptNotFound(f"no package named {pattern} in the submission (the <name> in package.xml); the task "
                             f"runs `ros2 launch {pattern} <file>` (or roslaunch), so name your package that way")
    return packages[names[0]]


def _ros2_launch_nodes(folder: Path, file: Path, rubric: Rubric) -> tuple[Started, LaunchActs]:
    """The nodes a ROS 2 launch file starts, as `ros2 launch pkg file args...` would, and its ros2 command lines as
    the grader's acts (LaunchError if it cannot be read)."""
    workspace = read_workspace(folder)
    nodes, findings, acts = ros2_node_specs(file, workspace, rubric.launch.args, rubric.launch.stdin)
    own = [spec for spec in nodes if not spec.provided]  # the grader's turtlesim nodes are not the student's files
    scripts = list(dict.fromkeys(spec.script for spec in own))
    for spec in {spec.script: spec for spec in own}.values():
        findings += check_script(spec.script, rosrun=spec.flavour == ROS1)
        if spec.flavour == ROS2:
            findings += package_findings(spec.script, spec.entry, workspace)
    return (nodes, findings, [file, *scripts]), acts


def _hidden_text(nodes: tuple[NodeSpec, ...], log: Path) -> list[str]:
    """Launched nodes whose text roslaunch would have written to a log file rather than the terminal."""
    return [(f"{spec.script.name} wrote text, but its Node has no output='screen': ros2 launch shows only its "
             "stderr (rclpy's log messages) and sends what it print()s to ~/.ros/log, not to the terminal (the grader "
             "read it either way)." if spec.flavour == ROS2 else
             f"{spec.script.name} wrote text, but its <node> has no output=\"screen\": roslaunch sends that text to "
             "~/.ros/log, not to the terminal (the grader read it either way).")
            for index, spec in enumerate(nodes) if spec.output == "log" and node_log_path(log, index).exists()]


def _for_scenario(nodes: tuple[NodeSpec, ...], scenario: Scenario) -> tuple[NodeSpec, ...]:
    """The nodes as one scenario runs them: its stdin typed into each (other values typed in), its node parameters
    after the student nodes' own arguments, so that they win as a later ``_name:=``/``-p`` does."""
    out = []
    for spec in nodes:
        if scenario.stdin is not None:
            spec = replace(spec, stdin=scenario.stdin)
        if scenario.node_params and not spec.provided:
            spec = replace(spec, args=(*spec.args, *param_args(spec.flavour, scenario.node_params)))
        out.append(spec)
    return tuple(out)


@dataclass
class _TaskPlan:
    """One task ready to run: its nodes, what was found about them, and its scenario runs."""

    rubric: Rubric
    nodes: tuple[NodeSpec, ...]
    findings: list[str]
    runs: list[Run]


def _plan_task(folder: Path, rubric: Rubric, out_dir: Path) -> _TaskPlan | TaskReport:
    """The task's runs, or its report at once when there is nothing to run (no script, a bad launch file)."""
    try:
        (nodes, findings, scripts), acts = _launch_nodes(folder, rubric) if rubric.launch \
            else (_script_nodes(folder, rubric), LaunchActs())
    except ScriptNotFound as exc:
        hint = "" if rubric.launch else "; name your script as the task asks."
        return TaskReport(id=rubric.id, title=rubric.title, status="not_found", max_score=rubric.max_score,
                          message=f"{exc}{hint}")
    except LaunchError as exc:
        return TaskReport(id=rubric.id, title=rubric.title, status="error", max_score=rubric.max_score,
                          message=str(exc))
    leaving = _links_leaving(folder, scripts)
    if leaving:
        return TaskReport(id=rubric.id, title=rubric.title, status="error", max_score=rubric.max_score,
                          message=f"{', '.join(leaving)} is a symbolic link to a file outside your submission; "
                                  "the grader does not follow it. Submit the file itself.")
    task_dir = out_dir / rubric.id
    if task_dir.exists():
        shutil.rmtree(task_dir)
    task_dir.mkdir(parents=True)
    interfaces = run_interfaces(read_workspace(folder), nodes[0].flavour) if nodes and folder.is_dir() else None
    findings = findings + (interfaces.findings if interfaces else [])
    try:
        typed = [_with_own_types(with_acts(scenario, acts), nodes, interfaces) for scenario in rubric.scenarios]
    except _NoOwnType as exc:
        return TaskReport(id=rubric.id, title=rubric.title, status="error", max_score=rubric.max_score,
                          diagnostics=findings, message=str(exc))
    runs = [Run(RunSpec(scenario=scenario, nodes=_for_scenario(scenario_nodes, scenario), limits=rubric.limits,
                        name=scenario.name, interfaces=interfaces),
                task_dir / f"{scenario.name}.mcap", task_dir / f"{scenario.name}.log")
            for scenario, scenario_nodes in typed]
    return _TaskPlan(rubric, nodes, findings, runs)


def _score_task(plan: _TaskPlan, outcomes: Sequence[Outcome]) -> TaskReport:
    """Score the task's recordings, in scenario order; the first scenario that could not run is the task's error."""
    rubric, nodes, findings = plan.rubric, plan.nodes, plan.findings
    recordings: dict[str, Recording] = {}
    paths: list[str] = []
    run_notes: list[str] = []
    timed_out = False
    # The grader's own nodes serve until the run ends: that they were then stopped says nothing of the student's.
    serving = tuple(f"{node.script}: still running when the scenario ended" for node in rubric.grader_nodes)
    for item, result in zip(plan.runs, outcomes):
        name = item.spec.name
        try:
            if isinstance(result, RunError):
                raise result
            recordings[name] = Recording.open(item.recording)
        except (RunError, RecordingError) as exc:
            return TaskReport(id=rubric.id, title=rubric.title, status="error", max_score=rubric.max_score,
                              recordings=paths, diagnostics=findings, message=f"scenario {name}: {exc}")
        paths.append(str(item.recording))
        timed_out |= any(n.status == "timeout" for n in result.nodes)
        # Counts differ from scenario to scenario; the first (nominal) run's are the ones worth showing.
        firsts = result.topics + _hidden_text(nodes, item.log) if len(paths) == 1 else []
        for note in result.diagnostics + firsts:
            if note not in run_notes and not note.startswith(serving):
                run_notes.append(note)
    with timing.stage("scoring"):
        report = score_task(rubric, recordings)
    return report.model_copy(update={
        "status": "timeout" if timed_out else report.status,
        "recordings": paths,
        "diagnostics": findings + [n for n in report.diagnostics if n not in findings] + run_notes,
    })


def _grade_tasks(folder: Path, rubrics: Sequence[Rubric], out_dir: Path, progress: Progress | None,
                 jobs: int) -> list[TaskReport]:
    """Plan every task, run all their scenarios (`jobs` at a time), then score each task."""
    plans = [_plan_task(folder, rubric, out_dir) for rubric in rubrics]
    runs = [item for plan in plans if isinstance(plan, _TaskPlan) for item in plan.runs]
    task_of = {id(item): plan.rubric.id for plan in plans if isinstance(plan, _TaskPlan) for item in plan.runs}

    def started(item: Run) -> None:
        if progress:
            progress(f"{task_of[id(item)]}: scenario {item.spec.name}")

    outcomes = iter(run_all(runs, jobs, started))
    ran = [(plan, [next(outcomes) for _ in plan.runs]) for plan in plans if isinstance(plan, _TaskPlan)]
    scored = iter(fork_map(lambda task: _score_task(*task), ran, jobs))  # tasks score independently
    return [next(scored) if isinstance(plan, _TaskPlan) else plan for plan in plans]


def grade_task(folder: Path, rubric: Rubric, out_dir: Path, progress: Progress | None = None) -> TaskReport:
    """Run every scenario of one rubric on the submission in `folder` and score the recordings."""
    return _grade_tasks(folder, [rubric], out_dir, progress, jobs=1)[0]


def grade_submission(submission: Path, out_dir: Path, task_ids: Sequence[str] | None = None,
                     rubrics: Mapping[str, Rubric] | None = None,
                     progress: Progress | None = None,
                     sources: Mapping[str, RubricFile] | None = None, jobs: int = 1) -> SubmissionReport:
    """Grade the named tasks (default: those whose scripts are present) and return the whole report.

    Each task's report is stamped with the rubric that made it: `sources` by task id when the rubrics were
    handed over as bytes, else the files they were loaded from. `jobs` scenarios run at once (the report and
    recordings are the same for any number); it defaults to 1 so that a batch, which already grades one
    submission per core, does not run cores x cores processes.
    """
    rubrics = rubrics if rubrics is not None else load_rubrics()
    unknown = [t for t in task_ids or () if t not in rubrics]
    if unknown:
        raise SubmissionError(f"unknown task {', '.join(unknown)}; `rosgrade tasks` lists the tasks.")
    out_dir.mkdir(parents=True, exist_ok=True)
    with open_submission(submission) as folder:
        tasks = list(task_ids) if task_ids else _present_tasks(folder, rubrics)
        if not tasks:
            files = {node.script for r in rubrics.values() for node in r.nodes}
            files |= {r.launch.file for r in rubrics.values() if r.launch is not None}
            raise SubmissionError(f"found none of the task scripts or launch files ({', '.join(sorted(files))}) in "
                                  f"{submission}; name your files as the task asks, or pass --task.")
        reports = _grade_tasks(folder, [rubrics[task] for task in tasks], out_dir, progress, jobs)
    stamped = [r.model_copy(update={"rubric": stamp(rubrics[r.id], (sources or {}).get(r.id))}) for r in reports]
    return SubmissionReport(submission=str(submission), tasks=stamped, recording_format=RECORDING_FORMAT,
                            isolation=detect().isolation).total()


@dataclass
class GradedSubmission:
    """A whole submission's results as data: what a grader process anywhere hands back to the batch."""

    report: SubmissionReport  # recordings named relative to the student's report folder
    files: dict[str, bytes] = field(default_factory=dict)  # recordings and node logs, by that relative path


def grade_as_data(submission: bytes, label: str, task_ids: Sequence[str], rubrics: Sequence[RubricFile],
                  stage_root: Path | None = None) -> GradedSubmission:
    """Grade a submission handed over as zip bytes with rubrics handed over as bytes, and return the results.

    Reads and leaves nothing outside its own temporary folders, so the same call runs in a local worker process
    or on a Dask worker without a shared file system. The submission is unpacked at a path named after its
    content, so the same submission is graded at the same path anywhere (node log records carry script paths):
    under `stage_root` (default: the temporary folder), which must not depend on the run.
    """
    with tempfile.TemporaryDirectory(prefix="rosgrade-results-") as tmp:
        root = Path(tmp)
        loaded = load_rubric_files(rubrics, root / "rubrics")
        with _unpacked(submission, stage_root or Path(tempfile.gettempdir())) as folder:
            report = grade_submission(folder, root / "out", list(task_ids), loaded,
                                      sources={f.task_id: f for f in rubrics})
        return _as_data(report.model_copy(update={"submission": label}), root / "out")


def _as_data(report: SubmissionReport, out: Path) -> GradedSubmission:
    files = {p.relative_to(out).as_posix(): p.read_bytes() for p in sorted(out.rglob("*")) if p.is_file()}
    tasks = [t.model_copy(update={"recordings": [Path(r).relative_to(out).as_posix() for r in t.recordings]})
             for t in report.tasks]
    return GradedSubmission(report.model_copy(update={"tasks": tasks}), files)


@contextmanager
def _unpacked(submission: bytes, root: Path) -> Iterator[Path]:
    """The zip unpacked at <root>/rosgrade-grade-<content hash>[-n] (-n only when the same content is being graded
    twice at once). Its OWNER_FILE names this process, so whoever started a killed grader can remove it."""
    base = root / f"{STAGE_PREFIX}{hashlib.sha256(submission).hexdigest()[:16]}"
    # A grading of the same content that was just killed (its Dask worker died, and Dask re-runs the job here) is
    # still exiting: wait a moment for its folder rather than take another path, which would reach the recordings.
    deadline = time.monotonic() + STAGE_WAIT_S
    while not remove_if_abandoned(base) and time.monotonic() < deadline:
        time.sleep(0.05)
    for attempt in range(1000):
        folder = base if attempt == 0 else base.with_name(f"{base.name}-{attempt}")
        remove_if_abandoned(folder)
        try:
            folder.mkdir(mode=0o755)
            break
        except FileExistsError:
            continue
    else:
        raise SubmissionError(f"cannot make a folder to unpack the submission in {base.parent}")
    try:
        claim(folder)
        archive = folder / ".submission.zip"
        archive.write_bytes(submission)
        unzip(archive, folder / "submission")
        archive.unlink()
        yield folder / "submission"
    finally:
        shutil.rmtree(folder, ignore_errors=True)

