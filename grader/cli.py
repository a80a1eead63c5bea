"""rosgrade's command line: check, batch, score, tasks, bench and gradescope-package (the names are a contract)."""
from __future__ import annotations

import argparse
import contextlib
import importlib
import json
import os
import sys
import tempfile
import time
import traceback
import zipfile
from collections.abc import Iterator, Sequence
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
from grader.reports.text import fmt_number, fmt_points, foxglove_help, percent

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


def _domain_errors() -> tuple[type[Exception], ...]:
    """The error classes whose message is written for the user (the CLI shows them as one line)."""
    from grader.batch import BatchError
    from grader.platforms.gradescope_package import PackageError

    errors: list[type[Exception]] = [BatchError, PackageError]
    for module, name in (("grader.grading", "SubmissionError"), ("grader.rubric", "RubricError"),
                         ("grader.recording", "RecordingError")):
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


def default_out(path: Path) -> Path:
    """rosgrade-out/<name>: the file's stem, the folder's name, or the workspace's name for a `src/` folder."""
    resolved = path.resolve()
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


def check_tasks(task_ids: Sequence[str] | None) -> None:
    """Reject task ids that have no rubric, listing the ones that exist."""
    if not task_ids:
        return
    rubrics = _module("grader.rubric").load_rubrics()
    unknown = [t for t in task_ids if t not in rubrics]
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


def _write_platform_failures(args: argparse.Namespace, message: str, out_dir: Path) -> None:
    """Valid platform files that explain why nothing could be graded (a missing file is worse than a zero)."""
    from grader.platforms import github, gradescope, junit, prairielearn

    if args.gradescope:
        gradescope.write_results(args.gradescope, gradescope.gradescope_failure(message))
    if args.prairielearn:
        prairielearn.write_results(args.prairielearn, prairielearn.prairielearn_failure(message))
    if args.junit:
        junit.write_junit(args.junit, junit.junit_failure(message))
    if args.github_summary:
        target = _env_path("GITHUB_STEP_SUMMARY", out_dir / "github-summary.md")
        target.parent.mkdir(parents=True, exist_ok=True)
        with target.open("a", encoding="utf-8") as handle:
            handle.write(f"## rosgrade could not grade this submission\n\n{message}\n")
    if args.github_result:
        target = _env_path("GITHUB_OUTPUT", out_dir / "github-output.txt")
        target.parent.mkdir(parents=True, exist_ok=True)
        github.write_output(target, github.runner_failure(message))


def cmd_check(args: argparse.Namespace) -> int:
    """Grade one submission, print the table, write the report folder and the platform outputs."""
    from grader.batch import grade_one
    from grader.platforms import gradescope

    started = time.monotonic()
    err = Console(stderr=True)
    out_dir: Path = args.out or default_out(args.path)
    if args.gradescope:  # if we are killed (time, memory) Gradescope still finds a valid file that says why
        gradescope.write_results(args.gradescope, gradescope.gradescope_failure(gradescope.UNFINISHED_MESSAGE))
    try:
        check_input(args.path)
        check_tasks(args.task)
        with _stdout_to_stderr(args.json), err.status(f"Grading {escape(str(args.path))} …"):
            report, files = grade_one(args.path, out_dir, args.task)
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
        err.print(f"Score {fmt_points(report.score, report.max_score)}; report folder: {out_dir}", highlight=False, markup=False)
    else:
        console = Console()
        print_report(console, report)
        _print_footer(console, report, files)
    if args.fail_under is not None and percent(report) < args.fail_under:
        err.print(f"Score {percent(report):.1f} % is below --fail-under {args.fail_under:g} %.", highlight=False, markup=False)
        return EXIT_BELOW_THRESHOLD
    return EXIT_OK


def _print_footer(console: Console, report: SubmissionReport, files: ReportFiles) -> None:
    console.print(f"\nReport: {files.html}  (also {files.markdown.name} and {files.json.name})", highlight=False, markup=False)
    for note in files.notes:
        console.print(f"Note: {note}", highlight=False, markup=False)
    recordings = [r for t in report.tasks for r in t.recordings]
    if recordings:
        console.print("Recordings: " + ", ".join(recordings), highlight=False, markup=False)
        for line in foxglove_help(recordings[0]):
            console.print(line, highlight=False, markup=False)


def cmd_batch(args: argparse.Namespace) -> int:
    """Grade a folder of submissions in parallel and write the gradebook."""
    from grader.batch import run_batch

    err = Console(stderr=True)
    check_tasks(args.task)
    result = run_batch(args.dir, args.out, jobs=args.jobs, task_ids=args.task, timeout_s=args.timeout, console=err)
    problems = [r for r in result.results if r.effective_status not in ("graded", "pending")]
    err.print(
        f"{len(result.results)} students: {result.graded_now} graded now, {result.skipped} already done, "
        f"{len(problems)} with errors or timeouts.\nGrades: {result.grades}\nSummary: {result.summary}",
        highlight=False, markup=False,
    )
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
    rubric_module, recording_module = _module("grader.rubric"), _module("grader.recording")
    rubrics = rubric_module.load_rubrics()
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
    table = Table(title="rosgrade tasks")
    table.add_column("Task", no_wrap=True)
    table.add_column("Title", ratio=1)
    table.add_column("Robot", no_wrap=True)
    table.add_column("Points", justify="right")
    table.add_column("Criteria", ratio=2)
    for rubric in rubrics.values():
        criteria = "\n".join(
            f"{c.id}: {c.title} ({fmt_number(float(c.points))})" + ("" if c.visibility == "visible" else f" [{c.visibility}]")
            for c in rubric.criteria
        )
        points = fmt_number(float(rubric.max_score))
        table.add_row(Text(rubric.id), Text(rubric.title), Text(str(rubric.robot)), points, Text(criteria))
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


def _reference_entries(folder: Path) -> list[Path]:
    if not folder.is_dir():
        raise CliError(f"{folder} is not a folder")
    return sorted(p for p in folder.iterdir() if not p.name.startswith((".", "_")) and (p.is_dir() or p.suffix in (".py", ".zip")))


def cmd_bench(args: argparse.Namespace) -> int:
    """Speed on this machine: physics real-time factor, and grading wall time per reference solution."""
    err = Console(stderr=True)
    with err.status("Measuring physics speed …"):
        physics = _module("sim.bench").physics_benchmark(robot=args.robot, sim_seconds=args.seconds)
    move_circle = args.reference / "move_circle.py" if args.reference else None
    with err.status("Measuring node runs (40 s of sim time each) …"):
        runtime = _module("grader.runtime.bench").runtime_benchmark(
            move_circle if move_circle is not None and move_circle.is_file() else None)
    rows: list[dict[str, Any]] = []
    if args.reference:
        grading = _module("grader.grading")
        with tempfile.TemporaryDirectory(prefix="rosgrade-bench-") as tmp:
            for entry in _reference_entries(args.reference):
                with err.status(f"Grading {escape(entry.name)} …"):
                    started = time.monotonic()
                    report = grading.grade_submission(entry, Path(tmp) / entry.stem, None).total()
                    rows.append(
                        {
                            "solution": entry.name,
                            "tasks": [t.id for t in report.tasks],
                            "score": report.score,
                            "max_score": report.max_score,
                            "wall_s": round(time.monotonic() - started, 3),
                        }
                    )
    if args.json:
        print(json.dumps({"physics": physics, "runtime": runtime, "reference": rows}, indent=2, default=str))
        return EXIT_OK
    console = Console()
    for title, figures in ((f"physics ({args.robot}, {args.seconds:g} s simulated)", physics),
                           ("node runs: process start to closed recording", runtime)):
        table = Table(title=title)
        table.add_column("Figure")
        table.add_column("Value", justify="right")
        for key, value in figures.items():
            table.add_row(Text(str(key)), Text(fmt_number(value) if isinstance(value, (int, float)) else str(value)))
        console.print(table)
    if rows:
        grading_table = Table(title="grading wall time per reference solution")
        for column in ("Solution", "Tasks", "Points", "Wall time [s]"):
            grading_table.add_column(column)
        for row in rows:
            points = fmt_points(row["score"], row["max_score"])
            grading_table.add_row(Text(row["solution"]), Text(", ".join(row["tasks"])), points, f"{row['wall_s']:.2f}")
        console.print(grading_table)
    return EXIT_OK


def cmd_gradescope_package(args: argparse.Namespace) -> int:
    """Build the Gradescope autograder zip."""
    from grader.platforms.gradescope_package import build_autograder_zip

    check_tasks(args.task)
    path = build_autograder_zip(args.task, args.out, timeout_s=args.timeout)
    Console().print(
        f"Wrote {path} ({path.stat().st_size / 1e6:.1f} MB) for tasks {', '.join(args.task)}. Upload it on "
        "Gradescope as the autograder zip (Ubuntu 22.04 base); its README.md says what it does and how long it takes.",
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


def build_parser() -> argparse.ArgumentParser:
    """The argument parser for every subcommand."""
    parser = argparse.ArgumentParser(
        prog="rosgrade", description="Grade ROS 1 rospy robot nodes against a deterministic simulation."
    )
    parser.add_argument("--version", action="version", version=f"rosgrade {__version__}")
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    check = commands.add_parser("check", help="grade one submission", description="Grade one submission and explain the result.")
    check.add_argument("path", type=Path, metavar="PATH", help="a .py file, a catkin package, a workspace src/ folder or a .zip")
    check.add_argument("--task", action="append", metavar="ID", help="task to grade (repeatable; default: found from script names)")
    check.add_argument("--out", type=Path, metavar="DIR", help="report folder (default: rosgrade-out/<name>)")
    check.add_argument("--json", action="store_true", help="print the report JSON on stdout and nothing else")
    check.add_argument("--fail-under", type=_percent, metavar="PERCENT", help="exit 1 when the score is below PERCENT")
    check.add_argument("--gradescope", type=Path, metavar="FILE", help="write a Gradescope results.json")
    check.add_argument("--prairielearn", type=Path, metavar="FILE", help="write a PrairieLearn results.json")
    check.add_argument("--junit", type=Path, metavar="FILE", help="write JUnit XML")
    check.add_argument("--github-summary", action="store_true",
                       help="append a Markdown summary to $GITHUB_STEP_SUMMARY (else to the report folder)")
    check.add_argument("--github-result", action="store_true",
                       help="append the Classroom runner result (result=<base64>) to $GITHUB_OUTPUT (else to the report folder)")
    check.set_defaults(handler=cmd_check)

    batch = commands.add_parser("batch", help="grade a folder of submissions", description="Grade one folder or .zip per student.")
    batch.add_argument("dir", type=Path, metavar="DIR")
    batch.add_argument("--out", type=Path, required=True, metavar="OUT")
    batch.add_argument("-j", "--jobs", type=_positive_int, default=os.cpu_count() or 1, metavar="N", help="parallel workers")
    batch.add_argument("--task", action="append", metavar="ID")
    batch.add_argument("--timeout", type=float, default=900.0, metavar="SECONDS", help="per-student limit (default 900)")
    batch.set_defaults(handler=cmd_batch)

    score = commands.add_parser("score", help="re-score recordings", description="Score recordings without running code.")
    score.add_argument("recordings", type=Path, nargs="+", metavar="RECORDING")
    score.add_argument("--task", required=True, metavar="ID")
    score.add_argument("--json", action="store_true")
    score.set_defaults(handler=cmd_score)

    tasks = commands.add_parser("tasks", help="list the tasks and their rubrics")
    tasks.add_argument("--json", action="store_true")
    tasks.set_defaults(handler=cmd_tasks)

    bench = commands.add_parser("bench", help="speed figures on this machine")
    bench.add_argument("--reference", type=Path, metavar="DIR", help="also time grading each reference solution in DIR")
    bench.add_argument("--robot", default="turtlebot3_waffle")
    bench.add_argument("--seconds", type=float, default=60.0, help="simulated seconds for the physics figure")
    bench.add_argument("--json", action="store_true")
    bench.set_defaults(handler=cmd_bench)

    package = commands.add_parser("gradescope-package", help="build the Gradescope autograder zip")
    package.add_argument("--task", action="append", required=True, metavar="ID")
    package.add_argument("--out", type=Path, default=Path("autograder.zip"))
    package.add_argument("--timeout", type=int, default=540, metavar="SECONDS", help="stop grading after this (default 540)")
    package.set_defaults(handler=cmd_gradescope_package)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point: run a subcommand and turn user-facing errors into one line and exit code 2."""
    args = build_parser().parse_args(argv)
    try:
        return int(args.handler(args))
    except CliError as exc:
        print(f"rosgrade: error: {exc}", file=sys.stderr)
        return EXIT_ERROR
    except Exception as exc:
        if not isinstance(exc, _domain_errors()):
            raise
        print(f"rosgrade: error: {exc}", file=sys.stderr)
        return EXIT_ERROR
    except KeyboardInterrupt:
        print("rosgrade: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED


if __name__ == "__main__":
    sys.exit(main())
