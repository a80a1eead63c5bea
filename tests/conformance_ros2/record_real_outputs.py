"""Write what every ROS 2 probe prints under real rclpy, normalised, as Markdown: the target for rosgrade's rclpy.

Usage: python tests/conformance_ros2/record_real_outputs.py OUT.md [RUNS] [TURTLESIM_INTERFACES]. Each probe runs
RUNS times (default 2) beside one real robot; the first run is shown, and any line a later run printed differently is
listed under it. With TURTLESIM_INTERFACES (the install folder build_turtlesim_interfaces.sh made; nothing is built
or fetched here), the turtlesim probes run instead, beside real_turtlesim2.py.
"""
from __future__ import annotations

import sys
from pathlib import Path

from conformance_compare2 import diff_lines, normalise, summarise_commands
from probe_cases2 import CASES, TURTLE_CASES, Case
from real_ros2 import RealRos2, RealResult

TURTLESIM_MODEL = Path(__file__).resolve().parent / "real_turtlesim2.py"


def _facts(case: Case, result: RealResult) -> dict[str, list[str]]:
    facts = {"stdout": normalise(result.stdout), "stderr": normalise(result.stderr),
             "exit": [f"exit status {result.exit_code}" + (" (killed by the harness)" if result.killed else "")]}
    if case.commands is not None:
        facts["/cmd_vel"] = summarise_commands(result.commands, result.sigint_s, case.markers)
    return facts


def _section(case: Case, results: list[RealResult]) -> str:
    first = _facts(case, results[0])
    out = [f"## {case.id}", "", f"`{case.script} {' '.join(case.args)}`"
           + (f", Ctrl+C {case.shutdown_at} s after #REF" if case.shutdown_at is not None else ""), ""]
    for name, lines in first.items():
        out += [f"{name}:", "```", *lines, "```"]
    for i, later in enumerate(results[1:], start=2):
        changes = [p.replace("real only", "run 1 only").replace("ours only", f"run {i} only")
                   for name, lines in _facts(case, later).items() for p in diff_lines(name, first[name], lines)]
        out.append(f"run {i}: " + ("the same" if not changes else "differs:\n" + "\n".join(f"    {c}" for c in changes)))
    if not results[0].commands:
        return "\n".join(out + ["", "/cmd_vel: nothing received", ""])
    out += ["", "/cmd_vel as received (t: sim s after #REF), first run:", "```"]
    out += [f"t={c.t:.3f} {c.type.split('/')[-1]} linear={c.linear} angular={c.angular}"
            f"{' after Ctrl+C' if c.after_sigint else ''}" for c in results[0].commands]
    return "\n".join(out + ["```", ""])


def main(path: Path, runs: int, interfaces: Path | None = None) -> None:
    sections = []
    cases, beside = (CASES, "real_robot2.py") if interfaces is None else (TURTLE_CASES, "real_turtlesim2.py")
    side = RealRos2() if interfaces is None else RealRos2(robot_node=TURTLESIM_MODEL, interfaces=interfaces)
    with side as ros:
        for case in cases:
            results = [ros.run_probe(case.path, case.args, shutdown_at=case.shutdown_at, duration=case.duration)
                       for _ in range(runs)]
            sections.append(_section(case, results))
    head = ("# ROS 2 probes under real rclpy (measured)\n\nWritten by tests/conformance_ros2/record_real_outputs.py: "
            f"Jazzy's real rclpy 7.1.6 (PyPI's ros-jazzy-* wheels, Fast DDS) beside {beside} at 1x, "
            "each probe run "
            f"{runs} times; outputs normalised as the suite compares them.\n\n")
    path.write_text(head + "\n".join(sections), encoding="utf-8")


if __name__ == "__main__":
    main(Path(sys.argv[1]), int(sys.argv[2]) if len(sys.argv) > 2 else 2,
         Path(sys.argv[3]) if len(sys.argv) > 3 else None)
