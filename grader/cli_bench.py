"""`rosgrade bench`: physics, node runs and a whole check of the reference solutions, as ratios measured in one run."""
from __future__ import annotations

import argparse
import json
from typing import Any

from rich.console import Console
from rich.markup import escape
from rich.table import Table
from rich.text import Text

from grader.cli import EXIT_OK, CliError, _module
from grader.reports.text import fmt_number, fmt_points


def cmd_bench(args: argparse.Namespace) -> int:
    """Speed on this machine: physics real-time factor, node runs, and a whole check of the reference solutions."""
    err = Console(stderr=True)
    check_bench = _module("grader.check_bench")
    figures: dict[str, Any] = {"load_average_before": check_bench.load_average()}
    samples: list[dict[str, Any]] = []

    def measure_physics() -> None:
        with err.status(f"Measuring physics speed (best of {args.repeats}) …"):
            samples.extend(_module("sim.bench").physics_benchmark(robot=args.robot, sim_seconds=args.seconds)
                           for _ in range(max(1, args.repeats)))

    measure_physics()
    runtime: dict[str, Any] = {}
    if not args.no_node_runs:
        move_circle = args.reference / "move_circle.py" if args.reference else None
        ros2 = args.reference_ros2 / "move_circle.py" if args.reference_ros2 else None
        if ros2 is not None and not ros2.is_file():
            ros2 = next(args.reference_ros2.rglob("move_circle.py"), None)
        with err.status("Measuring node runs (40 s of sim time each) and what /scan costs a run (60 s with and "
                        "without) …"):
            runtime = _module("grader.runtime.bench").runtime_benchmark(
                move_circle if move_circle is not None and move_circle.is_file() else None, repeats=args.repeats,
                move_circle_ros2=ros2)
    checks = []
    if args.reference:
        if not args.reference.exists():
            raise CliError(f"{args.reference} does not exist; give the reference solutions folder")
        jobs = args.jobs or _module("grader.runtime.cores").available_cores()
        for n in dict.fromkeys((1, jobs)):
            with err.status(f"Checking {escape(str(args.reference))} with -j {n} (best of {args.repeats}) …"):
                checks.append(check_bench.best_of(args.reference, n, args.repeats))
    if checks:
        measure_physics()  # again after the checks: the machine's speed drifts, and the checks keep their best too
    # Load only ever slows a run down: the fastest sample is the physics figure, as the best check is the check's.
    physics = {**max(samples, key=lambda sample: sample["rtf"]),
               "rtf_samples": " ".join(f"{sample['rtf']:.0f}" for sample in samples)}
    figures["load_average_after"] = check_bench.load_average()
    if args.json:
        print(json.dumps({"physics": physics, "runtime": runtime, "check": [_check_dict(c, physics) for c in checks],
                          **figures}, indent=2, default=str))
        return EXIT_OK
    console = Console()
    tables = [(f"physics ({args.robot}, {args.seconds:g} s simulated)", physics)]
    if runtime:
        tables.append(("node runs: process start to closed recording", runtime))
    for title, values in tables:
        table = Table(title=title)
        table.add_column("Figure")
        table.add_column("Value", justify="right")
        for key, value in values.items():
            table.add_row(Text(str(key)), Text(fmt_number(value) if isinstance(value, (int, float)) else str(value)))
        console.print(table)
    if checks:
        _print_checks(console, checks, physics)
    console.print(Text(f"Load average before: {figures['load_average_before']}; after: "
                       f"{figures['load_average_after']} (on a loaded machine wall times grow; ratios less so)."))
    return EXIT_OK


def _check_dict(check: Any, physics: dict[str, Any]) -> dict[str, Any]:
    return {"jobs": check.jobs, "wall_s": round(check.wall_s, 3), "cpu_s": round(check.cpu_s, 3),
            "sim_s": round(check.sim_s, 3), "runs": check.runs, "frames": check.frames,
            "moments_without_round_trip": check.moments,
            "sim_s_per_wall_s": round(check.sim_per_wall, 2), "sim_s_per_cpu_s": round(check.sim_per_cpu, 2),
            "of_physics_rtf": round(check.sim_per_wall / physics["rtf"], 3),
            "of_physics_cpu_rtf": round(check.sim_per_cpu / physics["cpu_rtf"], 3) if physics.get("cpu_rtf") else None,
            "score": check.score, "max_score": check.max_score,
            "stages_s": {name: round(value, 3) for name, value in check.breakdown()}}


def _print_checks(console: Console, checks: list[Any], physics: dict[str, Any]) -> None:
    """The per-stage breakdown of the -j 1 check, then every -j figure against the physics real-time factor."""
    single = checks[0]
    stages = Table(title=f"where the -j 1 check's {single.wall_s:.1f} s go ({single.runs} runs, {single.frames} "
                         f"round trips to nodes and {single.moments} moments nodes ran without one, "
                         f"{single.sim_s:.0f} s simulated)")
    for column in ("Stage", "Seconds", "Share", "Per round trip [µs]"):
        stages.add_column(column, justify="left" if column == "Stage" else "right")
    for name, seconds in single.breakdown():
        per_step = f"{seconds / single.frames * 1e6:.0f}" if single.frames else ""
        stages.add_row(Text(name), f"{seconds:.2f}", f"{seconds / single.wall_s:.0%}", per_step)
    console.print(stages)
    summary = Table(title=f"graded sim-s per second against physics alone ({physics['rtf']:.0f}x real time, "
                          "same run)")
    for column in ("-j", "Wall [s]", "Machine CPU [s]", "Sim-s / wall-s", "Of physics RTF", "Sim-s / CPU-s",
                   "Of physics per CPU-s", "Points"):
        summary.add_column(column, justify="right")
    cpu_rtf = physics.get("cpu_rtf")
    for check in checks:
        summary.add_row(str(check.jobs), f"{check.wall_s:.2f}", f"{check.cpu_s:.2f}", f"{check.sim_per_wall:.1f}",
                        f"{check.sim_per_wall / physics['rtf']:.2f}", f"{check.sim_per_cpu:.1f}",
                        f"{check.sim_per_cpu / cpu_rtf:.2f}" if cpu_rtf else "", fmt_points(check.score, check.max_score))
    console.print(summary)
