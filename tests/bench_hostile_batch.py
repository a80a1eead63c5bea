#!/usr/bin/env python3
"""Benchmark (run by hand, not by pytest): a batch of 100 submissions, 25 of them hostile, graded with -j 2.

Builds the batch in a temporary folder from tests/adversarial/corpus (each hostile script renamed move_circle.py)
and copies of reference_solutions/move_circle.py, runs `rosgrade batch DIR --out OUT -j 2 --task move_circle`,
checks that grades.csv has 100 rows and that every honest copy scored exactly as the reference graded alone,
and prints the wall time and peak memory (the grader and its workers and nodes, sampled from /proc).

The hostile 25 are the round-2 kinds first (issue 16: bad frames, a node that stops reading, endpoint and name
forgery, a fake world, double forks, reaching the grader, children over the limits, /dev/shm), then submission-level
attacks (a symlink to a classmate's script, a symlink to a secret outside the batch, a FIFO, a NUL byte), then the
rest of the corpus. A smaller batch keeps the same one-in-four share: --total 40 gives 10 hostile.

    python tests/bench_hostile_batch.py [--keep] [--total N]
"""
from __future__ import annotations

import argparse
import csv
import json
import os
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


# Round-2 corpus nodes first, with the arguments their tests give them (a node sees sys.argv[1:] as given here).
ROUND2 = {"bad_frame": "nested_json", "stop_reading": None, "endpoint_flood": None, "rename_driver": None,
          "impersonate_world": "gazebo", "double_fork_token": "rosgrade-bench-outliver", "reach_grader": "PPID",
          "memory_children": None, "spinning_children": None, "fill_shm": "rosgrade-bench-shm"}
SUBMISSION_ATTACKS = ("symlink_classmate", "symlink_secret", "fifo_script", "nul_script")
SECRET = "db password: hunter2-bench-do-not-leak"


def _hostile_kinds() -> list[str]:
    rest = sorted(p.stem for p in CORPUS.glob("*.py") if p.stem not in ROUND2)
    return [*ROUND2, *SUBMISSION_ATTACKS, *rest]


def _node_source(stem: str) -> str:
    """A corpus script as move_circle.py, with the arguments its test would pass (a batch passes none)."""
    source = (CORPUS / f"{stem}.py").read_text()
    arg = ROUND2.get(stem)
    if arg is None:
        return source
    value = "str(__import__('os').getppid())" if arg == "PPID" else repr(arg)
    shebang, _, body = source.partition("\n")  # the shebang stays the first line
    return f"{shebang}\nimport sys as _s\n_s.argv[1:] = _s.argv[1:] or [{value}]\n{body}"


def build(folder: Path, total: int, hostile_count: int) -> tuple[list[str], list[str]]:
    kinds = _hostile_kinds()
    hostile, honest = [], []
    (folder.parent / "secret.py").write_text(SECRET + "\n")  # outside the batch folder
    for index in range(total):
        name = f"student{index:03d}"
        package = folder / name / "scripts"
        package.mkdir(parents=True)
        target = package / "move_circle.py"
        if index % 4 == 3 and len(hostile) < hostile_count:
            kind = kinds[len(hostile) % len(kinds)]
            hostile.append(f"{name}={kind}")
            if kind == "symlink_classmate":  # plagiarism by symlink: the student just before is honest
                target.symlink_to(f"../../student{index - 1:03d}/scripts/move_circle.py")
            elif kind == "symlink_secret":
                target.symlink_to(folder.parent / "secret.py")
            elif kind == "fifo_script":
                os.mkfifo(target)
            elif kind == "nul_script":
                target.write_bytes(REFERENCE.read_bytes() + b"\x00\n")
            else:
                target.write_text(_node_source(kind))
        else:
            shutil.copy(REFERENCE, target)
            honest.append(name)
    return hostile, honest


def criteria(report: dict) -> dict[str, float]:
    return {c["id"]: c["score"] for task in report["tasks"] for c in task["criteria"]}


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--keep", action="store_true")
    parser.add_argument("--total", type=int, default=TOTAL)
    options = parser.parse_args()
    keep, total = options.keep, options.total
    tmp = Path(tempfile.mkdtemp(prefix="rosgrade-bench-hostile-"))
    tmp.chmod(0o755)  # a node's own uid must read its script (mkdtemp makes it 0700)
    batch, out, alone = tmp / "batch", tmp / "out", tmp / "alone"
    hostile, honest = build(batch, total, total * HOSTILE // TOTAL)
    print(f"batch of {total} in {batch}: {len(hostile)} hostile, {len(honest)} honest")

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

    print(f"exit code {process.returncode}; grades.csv rows: {len(rows)} (expected {total})")
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
    leaked = [str(p.relative_to(out)) for p in out.rglob("*") if p.is_file() and SECRET.encode() in p.read_bytes()]
    print(f"files of the output quoting the secret outside the batch: {leaked or 'none'}")
    if stderr and process.returncode:
        print(stderr.decode("utf-8", "replace")[-2000:])
    if not keep:
        shutil.rmtree(tmp, ignore_errors=True)
    ok = process.returncode == 0 and len(rows) == total and not mismatched and not leftovers and not leaked
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
