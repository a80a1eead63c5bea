"""Benchmark (run by hand, not a test): `rosgrade check` of every reference solution, and a 30-student batch on 2 workers.

Prints wall time and peak resident memory, sampled from /proc every 50 ms: the largest grader process (the
batch parent or one of its per-student workers) and the largest student node process.

    python tests/bench_batch.py [N_STUDENTS] [WORKERS]
"""
from __future__ import annotations

import csv
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

from grader.runtime import confine

ROOT = Path(__file__).resolve().parents[1]


def _is_node(pid: int) -> bool:
    try:
        return b"ROSGRADE_CHANNEL=" in Path(f"/proc/{pid}/environ").read_bytes()
    except OSError:
        return False


def measure(command: list[str]) -> dict[str, float]:
    """Run `command`, sampling the RSS of its process tree; returns wall time and peak RSS (MiB) by kind."""
    peaks = {"grader": 0, "node": 0}
    started = time.perf_counter()
    process = subprocess.Popen(command, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    done = threading.Event()

    def sample() -> None:
        while not done.is_set():
            for pid in confine.descendants(process.pid):
                kind = "node" if _is_node(pid) else "grader"
                peaks[kind] = max(peaks[kind], confine.rss_kib(pid))
            time.sleep(0.05)

    sampler = threading.Thread(target=sample, daemon=True)
    sampler.start()
    code = process.wait()
    done.set()
    sampler.join()
    return {"exit_code": code, "wall_s": round(time.perf_counter() - started, 2),
            "peak_grader_mib": round(peaks["grader"] / 1024, 1), "peak_node_mib": round(peaks["node"] / 1024, 1)}


def make_class(folder: Path, students: int) -> None:
    """`students` submissions: the example students and reference solutions, repeated under new names."""
    sources = sorted(p for p in (ROOT / "submissions_example").iterdir() if p.is_dir())
    sources.append(ROOT / "reference_solutions")
    for i in range(students):
        source = sources[i % len(sources)]
        shutil.copytree(source, folder / f"student{i:03d}_{source.name}")


def main() -> None:
    students = int(sys.argv[1]) if len(sys.argv) > 1 else 30
    workers = int(sys.argv[2]) if len(sys.argv) > 2 else 2
    rosgrade = [sys.executable, "-m", "grader.cli"]
    with tempfile.TemporaryDirectory(prefix="rosgrade-bench-") as tmp:
        tmp_path = Path(tmp)
        check = measure([*rosgrade, "check", str(ROOT / "reference_solutions"), "--out", str(tmp_path / "check")])
        print(f"check reference_solutions (all {7} tasks): {check}")
        make_class(tmp_path / "class", students)
        batch = measure([*rosgrade, "batch", str(tmp_path / "class"), "--out", str(tmp_path / "grades"),
                         "-j", str(workers)])
        with open(tmp_path / "grades" / "grades.csv", newline="") as f:
            rows = list(csv.DictReader(f))
        print(f"batch of {students} on {workers} workers: {batch}; grades.csv rows: {len(rows)}; "
              f"statuses: {sorted({r['status'] for r in rows})}; cpus: {os.cpu_count()}")


if __name__ == "__main__":
    main()
