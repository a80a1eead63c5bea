"""`rosgrade rubric check` and `rubric try`: what an instructor's rubric will run and score, and a grade with it."""
from __future__ import annotations

import argparse
import json
import math
from pathlib import Path
from typing import Any

from rich.console import Console
from rich.markup import escape
from rich.table import Table
from rich.text import Text

from grader.cli import (EXIT_OK, _module, _print_footer, _rubric_dict, _stdout_to_stderr, check_input,
                        default_out)
from grader.reports.table import print_report
from grader.reports.text import fmt_number


def _tolerance_text(tolerance: Any) -> str:
    """A criterion's tolerance in short words: full credit range, then how far outside credit lasts."""
    lo, hi = tolerance.bounds
    full = f"= {lo:g}" if lo == hi else f"in [{lo:g}, {hi:g}]"
    if tolerance.margin == 0:
        return f"{full}, else 0"
    return f"{full} ±{tolerance.margin:g}" + ("" if tolerance.sigmoid == "linear" else f" {tolerance.sigmoid}")


def _start_pose(scenario: Any) -> tuple[float, float, float]:
    pose = _module("sim.worlds").start_pose(scenario)
    return pose.x, pose.y, pose.yaw


def rubric_plan(rubric: Any) -> dict[str, Any]:
    """What a rubric will run and score, as data (for `rubric check` and its --json)."""
    return {
        **_rubric_dict(rubric),
        "file": str(rubric.source),
        "nodes": [{"script": n.script, "aliases": n.aliases, "args": n.args} for n in rubric.nodes],
        "sim_seconds": sum(s.duration for s in rubric.scenarios),
        "scenarios": [{
            "name": s.name, "description": s.description, "start_pose": list(_start_pose(s)),
            "start_time": s.start_time, "duration": s.duration, "shutdown_at": s.shutdown_at,
            "imperfections": s.imperfections.model_dump(), "scripted_commands": len(s.script),
            "stdin": s.stdin, "params": s.params,
        } for s in rubric.scenarios],
        "criteria": [{
            "id": c.id, "title": c.title, "points": c.points, "visibility": c.visibility, "metric": c.metric,
            "scored": [{"quantity": q, "tolerance": _tolerance_text(t)}
                       for q, t in [(c.quantity, c.tolerance), *((p.quantity, p.tolerance) for p in c.parts)]],
            "scenarios": [s.name for s in rubric.scenario_list(c)], "combine": c.combine, "hints": len(c.hints),
        } for c in rubric.criteria],
    }


def cmd_rubric_check(args: argparse.Namespace) -> int:
    """Validate a rubric file and show what it will run and score."""
    plan = rubric_plan(_module("grader.rubric").load_rubric(args.file))
    if args.json:
        print(json.dumps(plan, indent=2))
        return EXIT_OK
    console = Console()
    scripts = ", ".join(" or ".join([n["script"], *n["aliases"]]) for n in plan["nodes"])
    console.print(f"{plan['file']}: task {plan['id']!r} ({plan['title']}), robot {plan['robot']}, runs {scripts}",
                  highlight=False, markup=False)
    runs = Table(title="scenarios (each one run of the node)")
    for column in ("Scenario", "Start pose (x, y, yaw)", "Clock", "Length", "Ctrl+C", "Other"):
        runs.add_column(column)
    for s in plan["scenarios"]:
        x, y, yaw = s["start_pose"]
        other = [f"{k} {v:g}" for k, v in s["imperfections"].items() if v]
        other += [f"{s['scripted_commands']} scripted commands"] if s["scripted_commands"] else []
        other += [f"stdin {s['stdin']!r}"] if s["stdin"] is not None else []
        other += [f"{k} {v}" for k, v in s["params"].items()]
        runs.add_row(Text(s["name"]), f"{fmt_number(x)}, {fmt_number(y)}, {math.degrees(yaw):.0f}°", f"{s['start_time']:g} s",
                     f"{s['duration']:g} s", "-" if s["shutdown_at"] is None else f"at {s['shutdown_at']:g} s",
                     Text(", ".join(other) or "-"))
    console.print(runs)
    scored = Table(title="criteria (credit: full in the range, falling to 0 at ± margin outside it)")
    scored.add_column("Criterion", no_wrap=True)
    for column in ("Points", "Metric", "Scored on", "Scenarios"):
        scored.add_column(column)
    for c in plan["criteria"]:
        every = len(c["scenarios"]) == len(plan["scenarios"])
        where = "all" if every else ", ".join(c["scenarios"])
        scored.add_row(Text(c["id"] + ("" if c["visibility"] == "visible" else f" [{c['visibility']}]")),
                       fmt_number(float(c["points"])), Text(c["metric"]),
                       Text("\n".join(f"{p['quantity']} {p['tolerance']}" for p in c["scored"])),
                       Text(where if c["combine"] == "min" else f"{where} (mean)"))
    console.print(scored)
    n_criteria, n_scenarios = len(plan["criteria"]), len(plan["scenarios"])
    console.print(f"OK: {n_criteria} criteri{'on' if n_criteria == 1 else 'a'} worth "
                  f"{fmt_number(float(plan['max_score']))} points over {n_scenarios} scenario"
                  f"{'' if n_scenarios == 1 else 's'} ({plan['sim_seconds']:g} s of simulated time per submission).",
                  highlight=False, markup=False)
    return EXIT_OK


def cmd_rubric_try(args: argparse.Namespace) -> int:
    """Grade one submission with a rubric file that need not be installed (an instructor's new task)."""
    from grader.reports.folder import write_report_folder

    rubric = _module("grader.rubric").load_rubric(args.file)
    check_input(args.submission)
    out_dir: Path = args.out or default_out(args.submission)
    err = Console(stderr=True)
    with _stdout_to_stderr(args.json), err.status(f"Grading {escape(str(args.submission))} with {rubric.id} …"):
        report = _module("grader.grading").grade_submission(
            args.submission, out_dir, [rubric.id], rubrics={rubric.id: rubric}).total()
        files = write_report_folder(report, out_dir)
    if args.json:
        print(report.model_dump_json(indent=2))
        return EXIT_OK
    console = Console()
    print_report(console, report)
    _print_footer(console, report, files)
    return EXIT_OK
