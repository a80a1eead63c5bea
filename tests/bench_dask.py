"""Benchmark (run by hand, not a test): the same class through `batch -j N` and through Dask with N workers.

Each submission is a copy of reference_solutions/ (a comment line makes each one distinct) graded on three
TurtleBot tasks. The class is split into rounds that alternate local and Dask, so both see the same machine load;
the Dask cluster (a `dask scheduler` and N `dask worker` on 127.0.0.1) is started once, before timing, as a
cluster would be. Prints submissions per minute each way and the Dask overhead as a ratio.

    python tests/bench_dask.py [SUBMISSIONS] [WORKERS] [ROUNDS]      # defaults: 20 2 4
"""
from __future__ import annotations

import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TASKS = ("move_circle", "move_square", "odom_subscriber")


def make_class(folder: Path, first: int, count: int) -> None:
    for index in range(first, first + count):
        student = folder / f"student{index:03d}"
        shutil.copytree(ROOT / "reference_solutions", student)
        for script in student.glob("*.py"):
            script.write_text(script.read_text() + f"\n# student {index}\n")


def batch(folder: Path, out: Path, *how: str) -> float:
    command = [sys.executable, "-m", "grader.cli", "batch", str(folder), "--out", str(out), *how]
    for task in TASKS:
        command += ["--task", task]
    started = time.perf_counter()
    subprocess.run(command, cwd=ROOT, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - started


def start_cluster(workers: int) -> tuple[str, list[subprocess.Popen[bytes]]]:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    address = f"tcp://127.0.0.1:{port}"
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    quiet = {"env": env, "stdout": subprocess.DEVNULL, "stderr": subprocess.DEVNULL, "start_new_session": True}
    processes = [subprocess.Popen(["dask", "scheduler", "--host", "127.0.0.1", "--port", str(port),
                                   "--no-dashboard", "--no-show"], **quiet)]
    processes += [subprocess.Popen(["dask", "worker", address, "--host", "127.0.0.1", "--nthreads", "1",
                                    "--no-nanny", "--no-dashboard"], **quiet) for _ in range(workers)]
    from distributed import Client

    with Client(address, timeout=120) as client:
        client.wait_for_workers(workers, timeout=120)
    return address, processes


def main() -> None:
    submissions = int(sys.argv[1]) if len(sys.argv) > 1 else 20
    workers = int(sys.argv[2]) if len(sys.argv) > 2 else 2
    rounds = int(sys.argv[3]) if len(sys.argv) > 3 else 4
    per_round = max(1, submissions // rounds)
    address, cluster = start_cluster(workers)
    spent = {"local": 0.0, "dask": 0.0}
    graded = {"local": 0, "dask": 0}
    try:
        with tempfile.TemporaryDirectory(prefix="rosgrade-bench-") as tmp:
            tmp_path = Path(tmp)
            ways = [("local", ["-j", str(workers)]), ("dask", ["--scheduler", address])]
            for index in range(rounds):
                # Alternate which goes first, so neither always meets the same moment of the machine's load.
                for way, how in ways if index % 2 == 0 else ways[::-1]:
                    folder = tmp_path / f"{way}{index}"
                    make_class(folder, index * per_round, per_round)
                    spent[way] += batch(folder, tmp_path / f"{way}{index}-out", *how)
                    graded[way] += per_round
                    print(f"round {index + 1}/{rounds} {way}: {per_round} submissions", flush=True)
    finally:
        for process in cluster:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
    rate = {way: 60 * graded[way] / spent[way] for way in spent}
    print(f"{graded['local']} submissions x {len(TASKS)} tasks ({', '.join(TASKS)}) each way, {workers} workers, "
          f"{os.cpu_count()} CPUs, load average now {os.getloadavg()[0]:.1f}")
    print(f"local batch -j {workers}: {spent['local']:.1f} s, {rate['local']:.2f} submissions/min")
    print(f"Dask, {workers} workers:   {spent['dask']:.1f} s, {rate['dask']:.2f} submissions/min")
    print(f"Dask / local wall time: {spent['dask'] / spent['local']:.3f}")


if __name__ == "__main__":
    main()
