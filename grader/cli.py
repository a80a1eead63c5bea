"""rosgrade's command line: check, batch, score, tasks, bench and gradescope-package (the names are a contract)."""
from __future__ import annotations

import argparse
import contextlib
import importlib
import json
import os
import sys
import time
import traceback
import zipfile
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import Any

from rich.console import Console
from rich.markup import escape
from rich.table import Table
from rich.text import Text

from grader import __version__
from grader.report import SubmissionReport
from grader.reports.folder import ReportFiles
from grader.reports.table import print_report
from grader.reports.escape import one_line, plain
from grader.reports.text import fmt_number, fmt_points, foxglove_help, percent, watch_first_text

EXIT_OK = 0
EXIT_BELOW_THRESHOLD = 1
EXIT_ERROR = 2
EXIT_INTERRUPTED = 130
DEFAULT_OUT = Path("rosgrade-out")
NOMINAL_SCENARIO = "nominal"


class CliError(Exception):
    """A usage or input problem: shown as one line, exit code 2."""


def _module(name: str) -> Any:
    """Import a grader module when it is needed (keeps `rosgrade --help` fast, and tests can stand in for it)."""
    return importlib.import_module(name)


def _command(module: str, name: str) -> Callable[[argparse.Namespace], int]:
    """The handler of a command that lives in a module of its own, imported when the command runs."""
    return lambda args: getattr(_module(module), name)(args)


def _domain_errors() -> tuple[type[Exception], ...]:
    """The error classes whose message is written for the user (the CLI shows them as one line)."""
    from grader.batch import BatchError
    from grader.platforms.gradescope_package import PackageError

    errors: list[type[Exception]] = [BatchError, PackageError]
    for module, name in (("grader.grading", "SubmissionError"), ("grader.rubric", "RubricError"),
                         ("grader.recording", "RecordingError"), ("grader.dask_pool", "DaskPoolError"),
                         ("grader.rubricfile", "RubricFileError")):
        try:
            errors.append(getattr(_module(module), name))
        except (ImportError, AttributeError):  # a module that is not there cannot have raised its error
            continue
    return tuple(errors)


@contextlib.contextmanager
def _stdout_to_stderr(active: bool) -> Iterator[None]:
    """Send everything written to stdout (Python and C level) to stderr, so `--json` stdout stays pure JSON."""
    if not active:
        yield
        return
    sys.stdout.flush()
    try:
        fds: tuple[int, int] | None = (sys.stdout.fileno(), sys.stderr.fileno())
    except (AttributeError, OSError, ValueError):  # captured streams have no file descriptor
        fds = None
    saved = os.dup(fds[0]) if fds else None
    if fds:
        os.dup2(fds[1], fds[0])
    try:
        with contextlib.redirect_stdout(sys.stderr):
            yield
    finally:
        if fds and saved is not None:
            os.dup2(saved, fds[0])
            os.close(saved)


# Folders a script sits in that say nothing about whose it is; the submission is named by the folder above.
_GENERIC_FOLDERS = {"scripts", "src", "nodes", "bin", ""}


def default_out(path: Path) -> Path:
    """rosgrade-out/<submission>: a folder's or zip's name (the workspace's for `src/`), for a script the package or
    folder it is in, so checking alice/move_circle.py and bob/move_circle.py keeps both (tasks are subfolders)."""
    resolved = path.resolve()
    if resolved.is_file() and resolved.suffix.lower() == ".py":
        folder = resolved.parent
        while folder.name in _GENERIC_FOLDERS and folder != folder.parent:
            folder = folder.parent
        name = folder.name
    else:
        name = resolved.parent.name if resolved.name == "src" else resolved.stem if resolved.is_file() else resolved.name
    return DEFAULT_OUT / (name or "submission")


def check_input(path: Path) -> None:
    """Fail early, in one line, on a path rosgrade cannot read."""
    if not path.exists():
        raise CliError(f"{path}: no such file or folder")
    if not os.access(path, os.R_OK):
        raise CliError(f"{path}: permission denied")
    if path.is_file():
        suffix = path.suffix.lower()
        if suffix == ".zip":
            try:
                with zipfile.ZipFile(path) as archive:
                    archive.namelist()
            except (zipfile.BadZipFile, OSError) as exc:
                raise CliError(f"{path} is not a readable zip file ({exc})") from None
        elif suffix != ".py":
            raise CliError(f"{path}: expected a .py file, a catkin package, a workspace src/ folder or a .zip")


def rubric_paths(args: argparse.Namespace) -> list[Path]:
    """The instructor's rubric files (--rubric) and folders (--rubrics), checked to be what they claim to be."""
    for path in args.rubric or []:
        if not path.is_file():
            raise CliError(f"--rubric {path}: no such rubric file (a task's .toml)")
    for path in args.rubrics or []:
        if not path.is_dir():
            raise CliError(f"--rubrics {path}: no such folder of rubric .toml files")
    return [*(args.rubric or []), *(args.rubrics or [])]


def task_table(args: argparse.Namespace) -> dict[str, Any]:
    """The tasks this command knows: the built-in rubrics plus --rubric files and --rubrics folders."""
    return dict(_module("grader.rubric").task_table(rubric_paths(args)))


def check_tasks(task_ids: Sequence[str] | None, rubrics: dict[str, Any]) -> None:
    """Reject task ids that have no rubric, listing the ones that exist."""
    unknown = [t for t in task_ids or () if t not in rubrics]
    if unknown:
        raise CliError(f"unknown task {', '.join(map(repr, unknown))}; known tasks: {', '.join(sorted(rubrics))}")


def _env_path(variable: str, fallback: Path) -> Path:
    """The file a GitHub Actions variable names, else a file in the report folder (for trying it locally)."""
    return Path(os.environ[variable]) if os.environ.get(variable) else fallback


def _write_platforms(args: argparse.Namespace, report: SubmissionReport, files: ReportFiles, seconds: float, err: Console) -> None:
    """Write every platform output asked for on the command line."""
    from grader.platforms import github, gradescope, junit, prairielearn

    if args.gradescope:
        gradescope.write_results(args.gradescope, gradescope.gradescope_results(report, seconds))
    if args.prairielearn:
        prairielearn.write_results(args.prairielearn, prairielearn.prairielearn_results(report, files.plots))
    if args.junit:
        junit.write_junit(args.junit, junit.junit_xml(report, seconds))
    if args.github_summary:
        target = _env_path("GITHUB_STEP_SUMMARY", files.folder / "github-summary.md")
        github.write_summary(target, report)
        err.print(f"GitHub step summary: {target}", highlight=False, markup=False)
    if args.github_result:
        target = _env_path("GITHUB_OUTPUT", files.folder / "github-output.txt")
        github.write_output(target, github.runner_result(report))
        err.print(f"GitHub runner result: {target}", highlight=False, markup=False)


def _assignment_max(args: argparse.Namespace) -> float | None:
    """The points the --task tasks are worth (None when no --task named them, or their rubrics cannot be read)."""
    if not args.task:
        return None
    try:
        rubrics = task_table(args)
        return float(sum(rubrics[t].max_score for t in args.task))
    except Exception:  # the failure being reported may be this very rubric: then the maximum is unknown
        return None


def _write_platform_failures(args: argparse.Namespace, message: str, out_dir: Path) -> None:
    """Valid platform files that explain why nothing could be graded (a missing file is worse than a zero):
    0 points of the assignment's real maximum, when --task says what the assignment is."""
    from grader.platforms import github, gradescope, junit, prairielearn

    maximum = _assignment_max(args)
    if args.gradescope:
        gradescope.write_results(args.gradescope, gradescope.gradescope_failure(message, maximum))
    if args.prairielearn:
        prairielearn.write_results(args.prairielearn, prairielearn.prairielearn_failure(message))
    if args.junit:
        junit.write_junit(args.junit, junit.junit_failure(message))
    if args.github_summary:
        target = _env_path("GITHUB_STEP_SUMMARY", out_dir / "github-summary.md")
        target.parent.mkdir(parents=True, exist_ok=True)
        with target.open("a", encoding="utf-8") as handle:
            handle.write(github.failure_summary(message))
    if args.github_result:
        target = _env_path("GITHUB_OUTPUT", out_dir / "github-output.txt")
        target.parent.mkdir(parents=True, exist_ok=True)
        github.write_output(target, github.runner_failure(message, maximum or 0.0))


def _warn_weak_isolation(err: Console) -> None:
    """Say before grading (a node might kill the grader before any report exists) when nodes are not confined."""
    cap = _module("grader.runtime.confine").detect()
    if not cap.namespaces and cap.note:
        err.print(Text(f"Warning: {cap.note}", style="yellow"))


def cmd_check(args: argparse.Namespace) -> int:
    """Grade one submission, print the table, write the report folder and the platform outputs."""
    from grader.batch import grade_one
    from grader.platforms import gradescope
    from grader.runtime.cores import available_cores

    started = time.monotonic()
    err = Console(stderr=True)
    out_dir: Path = args.out or default_out(args.path)
    if args.gradescope:  # if we are killed (time, memory) Gradescope still finds a valid file that says why
        gradescope.write_results(args.gradescope, gradescope.gradescope_failure(gradescope.UNFINISHED_MESSAGE))
    try:
        check_input(args.path)
        rubrics = task_table(args)
        check_tasks(args.task, rubrics)
        _warn_weak_isolation(err)
        with _stdout_to_stderr(args.json), err.status(f"Grading {escape(one_line(str(args.path)))} …"):
            report, files = grade_one(args.path, out_dir, args.task, rubrics, jobs=args.jobs or available_cores())
    except (CliError, *_domain_errors()) as exc:
        _write_platform_failures(args, str(exc), out_dir)
        raise CliError(str(exc)) from None
    except Exception as exc:  # our bug, not the student's: still leave valid platform files and a trace to report
        trace = out_dir / "rosgrade-error.txt"
        trace.parent.mkdir(parents=True, exist_ok=True)
        trace.write_text(traceback.format_exc(), encoding="utf-8")
        message = f"rosgrade failed while grading ({type(exc).__name__}: {exc}); details in {trace}"
        _write_platform_failures(args, message, out_dir)
        raise CliError(message) from None
    _write_platforms(args, report, files, time.monotonic() - started, err)
    if args.json:
        print(report.model_dump_json(indent=2))
        err.print(Text(plain(f"Score {fmt_points(report.score, report.max_score)}; report folder: {out_dir}")))
    else:
        console = Console()
        print_report(console, report)
        _print_footer(console, report, files)
    missing = [t.id for t in report.tasks if t.status == "not_found"]
    if missing:
        err.print(f"rosgrade: error: no script found for {', '.join(missing)}: nothing was graded for "
                  f"{'it' if len(missing) == 1 else 'them'} (see the table).", highlight=False, markup=False)
        return EXIT_ERROR
    if args.fail_under is not None and percent(report) < args.fail_under:
        err.print(f"Score {percent(report):.1f} % is below --fail-under {args.fail_under:g} %.", highlight=False, markup=False)
        return EXIT_BELOW_THRESHOLD
    return EXIT_OK


def _print_footer(console: Console, report: SubmissionReport, files: ReportFiles) -> None:
    """Where the report is, notes, and how to open a recording (paths hold folder names a student chose: plain)."""
    lines = [f"\nReport: {files.html}  (also {files.markdown.name} and {files.json.name})"]
    lines += [f"Note: {note}" for note in files.notes]
    recordings = [r for t in report.tasks for r in t.recordings]
    if recordings:
        lines += [watch_first_text(report), "Recordings: " + ", ".join(recordings), *foxglove_help(recordings[0])]
    for line in lines:
        console.print(Text(plain(line)))


def cmd_batch(args: argparse.Namespace) -> int:
    """Grade a folder of submissions (local processes or Dask) and write the gradebook."""
    from grader.batch import run_batch

    err = Console(stderr=True)
    _warn_weak_isolation(err)
    executor = None
    if args.scheduler or args.dask_workers:
        executor = _module("grader.dask_pool").dask_pool(args.scheduler, args.dask_workers)
    result = run_batch(args.dir, args.out, jobs=args.jobs, task_ids=args.task, timeout_s=args.timeout, console=err,
                       rubric_paths=rubric_paths(args), executor=executor)
    problems = [r for r in result.results if r.effective_status not in ("graded", "pending")]
    err.print(
        f"{len(result.results)} students: {result.graded_now} graded now, {result.rescored} re-scored from their "
        f"recordings, {result.skipped} already done, {len(problems)} with errors or timeouts.",
        highlight=False, markup=False,
    )
    for note in result.notes:
        err.print(note, highlight=False, markup=False)
    err.print(f"Grades: {result.grades}\nSummary: {result.summary}", highlight=False, markup=False)
    if result.interrupted:
        err.print("Interrupted: finished reports are kept; run the same command again to continue.", highlight=False, markup=False)
        return EXIT_INTERRUPTED
    return EXIT_OK


def scenario_name(recording: Any, path: Path) -> str:
    """The scenario a recording was made in: from its rosgrade metadata, 'nominal' for foreign bags."""
    record = (recording.metadata or {}).get("rosgrade")
    if not isinstance(record, dict):
        return NOMINAL_SCENARIO
    scenario = record.get("scenario")
    try:
        parsed = json.loads(scenario) if isinstance(scenario, str) else scenario
    except ValueError:
        parsed = None
    name = parsed.get("name") if isinstance(parsed, dict) else None
    return str(name) if name else path.stem


def cmd_score(args: argparse.Namespace) -> int:
    """Re-score recordings against a task's rubric without running any code."""
    err = Console(stderr=True)
    recording_module = _module("grader.recording")
    rubrics = task_table(args)
    if args.task not in rubrics:
        raise CliError(f"unknown task {args.task!r}; known tasks: {', '.join(sorted(rubrics))}")
    recordings: dict[str, Any] = {}
    for path in args.recordings:
        if not path.exists():
            raise CliError(f"{path}: no such file or folder")
        recording = recording_module.Recording.open(path)
        scenario = scenario_name(recording, path)
        if scenario in recordings:
            raise CliError(f"two recordings of scenario {scenario!r}; score them one at a time")
        if recording.ground_truth() is None:
            err.print(f"{path} has no ground truth: it is scored from its odometry only.", highlight=False, markup=False)
        recordings[scenario] = recording
    # Only the scenarios given are scored: the rubric's other scenarios were not recorded here.
    task = _module("grader.scoring").score_task(rubrics[args.task].restricted_to(recordings), recordings)
    if not task.recordings:
        task = task.model_copy(update={"recordings": [str(p) for p in args.recordings]})
    report = SubmissionReport(submission=", ".join(str(p) for p in args.recordings), tasks=[task]).total()
    if args.json:
        print(report.model_dump_json(indent=2))
    else:
        print_report(Console(), report)
    return EXIT_OK


def cmd_tasks(args: argparse.Namespace) -> int:
    """List the rubrics: task id, title, robot, points and criteria."""
    rubrics = _module("grader.rubric").load_rubrics()
    if args.json:
        print(json.dumps([_rubric_dict(r) for r in rubrics.values()], indent=2))
        return EXIT_OK
    # Three columns that wrap (task with its title and robot, points, criteria): nothing is cut at 80 columns.
    table = Table(title="rosgrade tasks")
    table.add_column("Task", ratio=2)
    table.add_column("Points", justify="right", no_wrap=True)
    table.add_column("Criteria (points)", ratio=3)
    for rubric in rubrics.values():
        task = Text.assemble((rubric.id, "bold"), "\n", plain(rubric.title), "\n", (f"robot: {rubric.robot}", "dim"))
        criteria = "\n".join(
            f"• {c.title} ({fmt_number(float(c.points))})" + ("" if c.visibility == "visible" else f" [{c.visibility}]")
            for c in rubric.criteria
        )
        table.add_row(task, fmt_number(float(rubric.max_score)), Text(plain(criteria)))
        table.add_section()
    Console().print(table)
    return EXIT_OK


def _rubric_dict(rubric: Any) -> dict[str, Any]:
    return {
        "id": rubric.id,
        "title": rubric.title,
        "robot": str(rubric.robot),
        "max_score": rubric.max_score,
        "criteria": [{"id": c.id, "title": c.title, "points": c.points, "visibility": c.visibility} for c in rubric.criteria],
    }


def cmd_gradescope_package(args: argparse.Namespace) -> int:
    """Build the Gradescope autograder zip."""
    from grader.platforms.gradescope_package import build_autograder_zip

    from grader.rubricfile import rubric_files

    rubrics = task_table(args)
    check_tasks(args.task, rubrics)
    builtin = _module("grader.rubric").load_rubrics()
    extra = rubric_files(rubrics[t] for t in dict.fromkeys(args.task) if t not in builtin)
    path = build_autograder_zip(args.task, args.out, timeout_s=args.timeout, extra_rubrics=extra,
                                max_score=_assignment_max(args))
    Console().print(
        f"Wrote {path} ({path.stat().st_size / 1e6:.1f} MB) for tasks {', '.join(args.task)}. Upload it on "
        "Gradescope as the autograder zip (Ubuntu 22.04 or 24.04 base); its README.md says what it does and how long it takes.",
        highlight=False, markup=False,
    )
    return EXIT_OK


def _percent(text: str) -> float:
    value = float(text)
    if not 0 <= value <= 100:
        raise argparse.ArgumentTypeError("must be a percentage between 0 and 100")
    return value


def _positive_int(text: str) -> int:
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError("must be at least 1")
    return value


def _add_rubric_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--rubric", action="append", type=Path, metavar="FILE",
                        help="an instructor's rubric file <task>.toml, beside the built-in tasks (repeatable)")
    parser.add_argument("--rubrics", action="append", type=Path, metavar="DIR",
                        help="a folder of instructor rubric files (repeatable)")


# The first screen a newcomer sees (`rosgrade`, `rosgrade -h`): what it grades, and each command with an example.
DESCRIPTION = """Grade ROS robot nodes written with rospy (ROS 1) or rclpy (ROS 2) against a
deterministic simulation of a TurtleBot3, TurtleBot2 or Husky, or of turtlesim.
Each run is recorded (MCAP), scored on the task's rubric and explained in a
report: report.html replays every run."""
EXAMPLES = """one example per command:
  rosgrade check ~/catkin_ws/src/my_pkg          grade one submission (a .py, a
                                                 package, src/ folder or .zip)
  rosgrade batch submissions/ --out grades/      grade a class
  rosgrade score run.mcap --task move_circle     score recordings again
  rosgrade tasks                                 list the tasks (rubrics)
  rosgrade bench                                 speed figures on this machine
  rosgrade gradescope-package --task move_circle the Gradescope autograder zip
  rosgrade launch my_pkg/launch/go.launch --nodes   read a launch file
  rosgrade rubric check my_course/spiral.toml    check a rubric file"""


def build_parser() -> argparse.ArgumentParser:
    """The argument parser for every subcommand."""
    parser = argparse.ArgumentParser(prog="rosgrade", description=DESCRIPTION, epilog=EXAMPLES,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--version", action="version", version=f"rosgrade {__version__}")
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    check = commands.add_parser("check", help="grade one submission", description="Grade one submission and explain the result.")
    check.add_argument("path", type=Path, metavar="PATH", help="a .py file, a catkin package, a workspace src/ folder or a .zip")
    check.add_argument("--task", action="append", metavar="ID", help="task to grade (repeatable; default: found from script names)")
    check.add_argument("--out", type=Path, metavar="DIR",
                       help="report folder (default: rosgrade-out/<submission>, one subfolder per task)")
    check.add_argument("--json", action="store_true", help="print the report JSON on stdout and nothing else")
    check.add_argument("-j", "--jobs", type=_positive_int, default=None, metavar="N",
                       help="scenarios run at once (default: the cores this process may use); the report is the same")
    check.add_argument("--fail-under", type=_percent, metavar="PERCENT", help="exit 1 when the score is below PERCENT")
    check.add_argument("--gradescope", type=Path, metavar="FILE", help="write a Gradescope results.json")
    check.add_argument("--prairielearn", type=Path, metavar="FILE", help="write a PrairieLearn results.json")
    check.add_argument("--junit", type=Path, metavar="FILE", help="write JUnit XML")
    check.add_argument("--github-summary", action="store_true",
                       help="append a Markdown summary to $GITHUB_STEP_SUMMARY (else to the report folder)")
    check.add_argument("--github-result", action="store_true",
                       help="append the Classroom runner result (result=<base64>) to $GITHUB_OUTPUT (else to the report folder)")
    _add_rubric_options(check)
    check.set_defaults(handler=cmd_check)

    batch = commands.add_parser("batch", help="grade a folder of submissions", description="Grade one folder or .zip per student.")
    batch.add_argument("dir", type=Path, metavar="DIR", help="folder holding one folder or .zip per student")
    batch.add_argument("--out", type=Path, required=True, metavar="OUT",
                       help="folder for the students' reports, grades.csv and summary.md (a rerun resumes there)")
    batch.add_argument("-j", "--jobs", type=_positive_int, default=os.cpu_count() or 1, metavar="N", help="parallel workers")
    batch.add_argument("--task", action="append", metavar="ID", help="task to grade for every student (repeatable)")
    batch.add_argument("--timeout", type=float, default=900.0, metavar="SECONDS", help="per-student limit (default 900)")
    _add_rubric_options(batch)
    dask = batch.add_mutually_exclusive_group()
    dask.add_argument("--scheduler", metavar="ADDRESS",
                      help="grade on a Dask cluster: its scheduler, e.g. tcp://host:8786 (needs rosgrade[dask])")
    dask.add_argument("--dask-workers", type=_positive_int, metavar="N",
                      help="grade on a local Dask cluster of N workers (needs rosgrade[dask])")
    batch.set_defaults(handler=cmd_batch)

    score = commands.add_parser("score", help="re-score recordings", description="Score recordings without running code.")
    score.add_argument("recordings", type=Path, nargs="+", metavar="RECORDING",
                       help="an .mcap from rosgrade, a ROS 1 .bag or a ROS 2 bag, one per scenario")
    score.add_argument("--task", required=True, metavar="ID", help="the task whose rubric scores the recordings")
    score.add_argument("--json", action="store_true", help="print the report JSON instead of the table")
    _add_rubric_options(score)
    score.set_defaults(handler=cmd_score)

    tasks = commands.add_parser("tasks", help="list the tasks and their rubrics")
    tasks.add_argument("--json", action="store_true", help="print the tasks as JSON")
    tasks.set_defaults(handler=cmd_tasks)

    bench = commands.add_parser("bench", help="speed figures on this machine")
    bench.add_argument("--reference", type=Path, metavar="DIR",
                       help="also time a whole check of DIR (e.g. reference_solutions): per stage, -j 1 and -j N")
    bench.add_argument("--reference-ros2", type=Path, metavar="DIR",
                       help="also time the rclpy move_circle.py found under DIR (e.g. "
                            "reference_solutions_ros2) beside the rospy one")
    bench.add_argument("-j", "--jobs", type=_positive_int, default=None, metavar="N",
                       help="the parallel check's -j (default: the cores this process may use)")
    bench.add_argument("--repeats", type=_positive_int, default=3, metavar="N",
                       help="time each figure N times and keep the best (default 3)")
    bench.add_argument("--no-node-runs", action="store_true", help="skip the single-node run figures")
    bench.add_argument("--robot", default="turtlebot3_waffle", help="robot for the physics figure (default turtlebot3_waffle)")
    bench.add_argument("--seconds", type=float, default=300.0,
                       help="simulated seconds for each physics sample (default 300: a few wall seconds, long "
                            "enough to average a virtual machine's speed drift, as a whole check does)")
    bench.add_argument("--json", action="store_true", help="print the figures as JSON")
    bench.set_defaults(handler=_command("grader.cli_bench", "cmd_bench"))

    package = commands.add_parser("gradescope-package", help="build the Gradescope autograder zip")
    package.add_argument("--task", action="append", required=True, metavar="ID", help="task to grade (repeatable)")
    package.add_argument("--out", type=Path, default=Path("autograder.zip"), metavar="ZIP",
                         help="where to write the zip (default autograder.zip)")
    package.add_argument("--timeout", type=int, default=540, metavar="SECONDS", help="stop grading after this (default 540)")
    _add_rubric_options(package)
    package.set_defaults(handler=cmd_gradescope_package)
    launch = commands.add_parser("launch", help="read a launch file as roslaunch / ros2 launch do",
                                 description="Print a launch file's parameters or nodes exactly as roslaunch does, or "
                                             "what `ros2 launch` would start for a ROS 2 .launch.py.")
    launch.add_argument("file", type=Path, metavar="FILE",
                        help="a roslaunch XML or ROS 2 .launch.py file (or PKG, then the file's name)")
    launch.add_argument("args", nargs="*", metavar="NAME:=VALUE", help="launch args (before --dump-params/--nodes)")
    launch.add_argument("--packages", type=Path, action="append", metavar="DIR",
                        help="where $(find) looks for packages (repeatable; default: the folder around FILE's package)")
    launch.add_argument("--workspace", type=Path, metavar="DIR",
                        help="ROS 2: the submission or workspace whose packages the launch file sees (default: here)")
    shown = launch.add_mutually_exclusive_group()
    shown.add_argument("--dump-params", action="store_true", help="the parameters, as `roslaunch --dump-params`")
    shown.add_argument("--nodes", action="store_true", help="the node names, as `roslaunch --nodes` (ROS 2: the "
                                                            "processes `ros2 launch` would start)")
    shown.add_argument("--show-args", action="store_true", help="ROS 2: the arguments, as `ros2 launch --show-args`")
    shown.add_argument("--json", action="store_true", help="ROS 2: every process with its argv and parameter files")
    launch.set_defaults(handler=_command("grader.cli_launch", "cmd_launch"))
    rubric = commands.add_parser("rubric", help="check or try out a rubric file",
                                 description="Work on a task's rubric TOML (see rubrics/README.md).")
    rubric_commands = rubric.add_subparsers(dest="rubric_command", required=True, metavar="ACTION")
    rubric_check = rubric_commands.add_parser("check", help="validate a rubric and show what it runs and scores")
    rubric_check.add_argument("file", type=Path, metavar="FILE", help="the rubric .toml")
    rubric_check.add_argument("--json", action="store_true")
    rubric_check.set_defaults(handler=_command("grader.cli_rubric", "cmd_rubric_check"))
    rubric_try = rubric_commands.add_parser("try", help="grade one submission with a rubric file")
    rubric_try.add_argument("file", type=Path, metavar="FILE", help="the rubric .toml")
    rubric_try.add_argument("submission", type=Path, metavar="SUBMISSION",
                            help="a .py file, a catkin package, a workspace src/ folder or a .zip")
    rubric_try.add_argument("--out", type=Path, metavar="DIR", help="report folder (default: rosgrade-out/<name>)")
    rubric_try.add_argument("--json", action="store_true", help="print the report JSON on stdout and nothing else")
    rubric_try.set_defaults(handler=_command("grader.cli_rubric", "cmd_rubric_try"))
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point: run a subcommand and turn user-facing errors into one line and exit code 2."""
    parser = build_parser()
    if not (sys.argv[1:] if argv is None else argv):  # no command: the first screen, not only an argparse error
        parser.print_help()
        parser.exit(EXIT_ERROR)
    args = parser.parse_args(argv)
    try:
        return int(args.handler(args))
    except CliError as exc:  # messages quote paths and names a student chose: no terminal controls
        print(f"rosgrade: error: {one_line(str(exc))}", file=sys.stderr)
        return EXIT_ERROR
    except Exception as exc:
        if not isinstance(exc, _domain_errors()):
            raise
        print(f"rosgrade: error: {one_line(str(exc))}", file=sys.stderr)
        return EXIT_ERROR
    except KeyboardInterrupt:
        print("rosgrade: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED


if __name__ == "__main__":
    sys.exit(main())
