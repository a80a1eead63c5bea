"""Benchmark (run by hand as root, not a test): `rosgrade check` under Gradescope's default container limits.

Gradescope gives an autograder ½ vCPU and 768 MB. This puts a `check` in a cgroup with the same limits (cgroup v2
`cpu.max 50000 100000` + `memory.max 768M`, or the v1 `cpu.cfs_quota_us` and `memory.limit_in_bytes` on a v1 or
hybrid machine), runs it, and prints its wall time, the cgroup's CPU seconds and peak memory, and the physics
real-time factor measured just before on the same machine (so a loaded machine can be told apart).

    sudo python3 tests/bench_gradescope_limits.py [SUBMISSION] (default: reference_solutions)
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
# Run as a script, this folder comes first on sys.path, and its sim/ (the simulator's tests) would hide the simulator.
sys.path.insert(0, str(ROOT))
from sim.bench import physics_benchmark  # noqa: E402
CGROUP = Path("/sys/fs/cgroup")
NAME = f"rosgrade-gradescope-{os.getpid()}"
CPU_QUOTA_US, CPU_PERIOD_US, MEMORY_BYTES = 50_000, 100_000, 768 << 20


def _own(controller: str) -> Path:
    """This process's cgroup folder for a v1 controller (memory may be nested under the machine's manager)."""
    for line in Path("/proc/self/cgroup").read_text().splitlines():
        _, controllers, path = line.split(":", 2)
        if controller in controllers.split(","):
            return CGROUP / controller / path.lstrip("/")
    return CGROUP / controller


def make_cgroups() -> tuple[list[Path], Path, Path | None]:
    """Create the limited cgroup(s); returns (folders to join, where peak memory is read, where CPU time is)."""
    if (CGROUP / "cgroup.controllers").exists():  # unified v2 hierarchy
        folder = CGROUP / NAME
        folder.mkdir()
        (folder / "cpu.max").write_text(f"{CPU_QUOTA_US} {CPU_PERIOD_US}\n")
        (folder / "memory.max").write_text(f"{MEMORY_BYTES}\n")
        return [folder], folder / "memory.peak", folder / "cpu.stat"
    cpu, memory = CGROUP / "cpu" / NAME, _own("memory") / NAME
    for folder in (cpu, memory):
        folder.mkdir()
    (cpu / "cpu.cfs_period_us").write_text(f"{CPU_PERIOD_US}\n")
    (cpu / "cpu.cfs_quota_us").write_text(f"{CPU_QUOTA_US}\n")
    (memory / "memory.limit_in_bytes").write_text(f"{MEMORY_BYTES}\n")
    cpuacct = CGROUP / "cpuacct" / NAME
    cpuacct.mkdir()
    return [cpu, memory, cpuacct], memory / "memory.max_usage_in_bytes", cpuacct / "cpuacct.usage"


def _cpu_s(path: Path | None) -> float | None:
    if path is None or not path.exists():
        return None
    text = path.read_text()
    if path.name == "cpu.stat":
        return int(text.split("usage_usec")[1].split()[0]) / 1e6
    return int(text) / 1e9


def main(submission: Path) -> None:
    physics = physics_benchmark(sim_seconds=30.0)
    folders, peak, cpu = make_cgroups()
    joins = " && ".join(f"echo $$ > {folder / 'cgroup.procs'}" for folder in folders)
    try:
        with tempfile.TemporaryDirectory(prefix="rosgrade-gs-bench-") as out:
            started = time.perf_counter()
            done = subprocess.run(["sh", "-c", f'{joins} && exec "$0" "$@"', sys.executable, "-m", "grader.cli",
                                   "check", str(submission), "--out", out, "--json"],
                                  cwd=ROOT, capture_output=True, text=True, check=False)
            wall = time.perf_counter() - started
        report = json.loads(done.stdout) if done.stdout.strip() else {}
        print(json.dumps({
            "limits": "1/2 vCPU, 768 MB", "exit_code": done.returncode, "wall_s": round(wall, 1),
            "cgroup_cpu_s": _cpu_s(cpu), "peak_memory_mb": round(int(peak.read_text()) / 2**20, 1),
            "score": f"{report.get('score')} / {report.get('max_score')}",
            "physics_rtf_unlimited": round(physics["rtf"], 1), "load_average": os.getloadavg(),
        }, indent=2))
    finally:
        for folder in reversed(folders):
            folder.rmdir()


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "reference_solutions")
