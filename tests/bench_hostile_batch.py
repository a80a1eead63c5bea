#!/usr/bin/env python3
"""Benchmark (run by hand, not by pytest): a batch of 100 submissions, 25 of them hostile, graded with -j 2.

Builds the batch in a temporary folder from tests/adversarial/corpus (each hostile script renamed move_circle.py)
and copies of reference_solutions/move_circle.py, runs `rosgrade batch DIR --out OUT -j 2 --task move_circle`,
checks that grades.csv has 100 rows and that every honest copy scored exactly as the reference graded alone,
and prints the wall time and peak memory (the grader and its workers and nodes, sampled from /proc).

    python tests/bench_hostile_batch.py [--keep]
"""
from __future__ import annotations

import csv
import json
import resource
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

from grader.runtime import confine

ROOT = Path(__file__).resolve().parents[1]
CORPUS = ROOT / "tests" / "adversarial" / "corpus"
REFERENCE = ROOT / "reference_solutions" / "move_circle.py"
TOTAL, HOSTILE = 100, 25


def _tree_rss_kb(root: int) -> tuple[int, int]:
    """(sum of RSS over root and all its descendants, number of processes), in KiB, from /proc."""
    tree = confine.descendants(root)
    return sum(confine.rss_kib(pid) for pid in tree), len(tree)


def build(folder: Path) -> tuple[list[str], list[str]]:
    hostile_scripts = sorted(CORPUS.glob("*.py"))
    hostile, honest = [], []
    for index in range(TOTAL):
        name = f"student{index:03d}"
        package = folder / name / "scripts"
        package.mkdir(parents=True)
        if index % 4 == 3 and len(hostile) < HOSTILE:
            source = hostile_scripts[len(hostile) % len(hostile_scripts)]
            hostile.append(f"{name}={source.stem}")
        else:
            source = REFERENCE
            honest.append(name)
        shutil.copy(source, package / "move_circle.py")
    return hostile, honest


def criteria(report: dict) -> dict[str, float]:
    return {c["id"]: c["score"] for task in report["tasks"] for c in task["criteria"]}


def main() -> int:
    keep = "--keep" in sys.argv
    tmp = Path(tempfile.mkdtemp(prefix="rosgrade-bench-hostile-"))
    batch, out, alone = tmp / "batch", tmp / "out", tmp / "alone"
    hostile, honest = build(batch)
    print(f"batch of {TOTAL} in {batch}: {len(hostile)} hostile, {len(honest)} honest")

    subprocess.run([sys.executable, "-m", "grader.cli", "check", str(batch / honest[0]), "--task", "move_circle",
                    "--json", "--out", str(alone)], check=True, capture_output=True)
    expected = criteria(json.loads((alone / "report.json").read_text()))

    started = time.monotonic()
    process = subprocess.Popen([sys.executable, "-m", "grader.cli", "batch", str(batch), "--out", str(out), "-j", "2",
                                "--task", "move_circle"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    peak = {"rss_kb": 0, "processes": 0}

    def sample() -> None:
        while process.poll() is None:
            rss, count = _tree_rss_kb(process.pid)
            peak["rss_kb"] = max(peak["rss_kb"], rss)
            peak["processes"] = max(peak["processes"], count)
            time.sleep(0.2)

    sampler = threading.Thread(target=sample, daemon=True)
    sampler.start()
    _, stderr = process.communicate()
    wall = time.monotonic() - started
    sampler.join()
    children = resource.getrusage(resource.RUSAGE_CHILDREN)

    with open(out / "grades.csv", newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    mismatched = [name for name in honest
                  if criteria(json.loads((out / name / "report.json").read_text())) != expected]
    hostile_rows = []
    for entry in hostile:
        name, case = entry.split("=")
        path = out / name / "report.json"
        if path.is_file():
            task = json.loads(path.read_text())["tasks"][0]
            hostile_rows.append((name, case, task["status"], task["score"]))
        else:
            hostile_rows.append((name, case, "error", None))

    print(f"exit code {process.returncode}; grades.csv rows: {len(rows)} (expected {TOTAL})")
    print(f"honest copies scored as the reference alone ({sum(expected.values()):g} points): "
          f"{len(honest) - len(mismatched)}/{len(honest)}" + (f"; differ: {mismatched}" if mismatched else ""))
    for name, case, status, score in hostile_rows:
        print(f"  {name} {case:18s} {status:10s} {score}")
    print(f"wall time: {wall:.1f} s")
    print(f"peak memory: {peak['rss_kb'] / 1024:.0f} MiB RSS summed over the grader, its workers and nodes "
          f"(sampled every 0.2 s; at most {peak['processes']} processes); largest single process "
          f"{children.ru_maxrss / 1024:.0f} MiB (getrusage RUSAGE_CHILDREN)")
    leftovers = subprocess.run(["sh", "-c", "grep -l ROSGRADE_NODE_MARKER /proc/[0-9]*/environ 2>/dev/null"],
                               capture_output=True, text=True).stdout.split()
    print(f"node processes left afterwards: {len(leftovers)}")
    if stderr and process.returncode:
        print(stderr.decode("utf-8", "replace")[-2000:])
    if not keep:
        shutil.rmtree(tmp, ignore_errors=True)
    ok = process.returncode == 0 and len(rows) == TOTAL and not mismatched and not leftovers
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
