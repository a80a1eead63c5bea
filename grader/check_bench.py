"""How fast a whole `check` is: where its wall time goes, graded sim-seconds per second, and what -j N gains.

The figures that matter are ratios measured in the same process run, so a loaded machine shifts them less than
absolute times: graded simulated seconds per wall second (and per busy CPU second of the machine) against the
physics-only real-time factor (`sim.bench`), and -j N against -j 1.
"""
from __future__ import annotations

import os
import resource
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

from grader import timing
from grader.batch import grade_one

# Stages in the order a check goes through them (timing.py names); anything else is listed after them.
STAGE_ORDER = (
    "node start-up", "world set-up (model, run to the start)", "physics and sensors",
    "world messages (encode, record, queue)", "node steps (channel, node publications)", "waiting for nodes",
    "world run ahead and taken back", "stopping nodes", "reading recordings", "scoring", "advice", "plots", "report files",
)
OTHER = "other (grader bookkeeping, recording close)"


@dataclass
class CheckTiming:
    """One timed `check` of a submission."""

    jobs: int
    wall_s: float
    cpu_s: float  # busy CPU seconds of the whole machine while the check ran (see _cpu_s)
    sim_s: float
    runs: int
    frames: int  # BATCH frames: round trips between the grader and a node
    stages: dict[str, float] = field(default_factory=dict)  # exclusive wall seconds, summed over worker processes
    score: float = 0.0
    max_score: float = 0.0
    moments: int = 0  # later moments nodes ran on their own, without a round trip

    @property
    def sim_per_wall(self) -> float:
        return self.sim_s / self.wall_s if self.wall_s else 0.0

    @property
    def sim_per_cpu(self) -> float:
        return self.sim_s / self.cpu_s if self.cpu_s else 0.0

    def breakdown(self) -> list[tuple[str, float]]:
        """(stage, seconds) adding up to the summed wall time of every grading process, in check order."""
        named = [(name, self.stages[name]) for name in STAGE_ORDER if name in self.stages]
        named += sorted((n, v) for n, v in self.stages.items() if n not in STAGE_ORDER and not n.startswith("# "))
        if self.jobs == 1:
            named.append((OTHER, max(0.0, self.wall_s - sum(v for _, v in named))))
        return named


def _cpu_s() -> float:
    """Busy CPU seconds of the machine so far (/proc/stat), else this process's and its reaped children's.

    A sandboxed node killed at the end of its run is reaped by its sandbox's init, which dies with it, so its CPU
    time never reaches our RUSAGE_CHILDREN: that figure misses the nodes' share (a third of a check). The machine's
    busy time counts them; on a loaded machine it also counts the others' work, as the bench's load line warns.
    """
    try:
        fields = Path("/proc/stat").read_text().split("\n", 1)[0].split()[1:]
        user, nice, system, _idle, _iowait, irq, softirq = (int(v) for v in fields[:7])
        return (user + nice + system + irq + softirq) / os.sysconf("SC_CLK_TCK")
    except (OSError, ValueError):
        own, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
        return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def time_check(submission: Path, jobs: int) -> CheckTiming:
    """Grade `submission` as `rosgrade check -j jobs` does (report folder included), timing every stage."""
    with tempfile.TemporaryDirectory(prefix="rosgrade-bench-") as tmp, timing.collect() as stages:
        cpu0, started = _cpu_s(), time.perf_counter()
        report, _files = grade_one(submission, Path(tmp) / "out", None, jobs=jobs)
        wall, cpu = time.perf_counter() - started, _cpu_s() - cpu0
    return CheckTiming(jobs, wall, cpu, stages.get("# simulated milliseconds", 0.0) / 1000,
                       int(stages.get("# runs", 0)), int(stages.get("# node steps (BATCH frames)", 0)),
                       stages, report.score, report.max_score,
                       int(stages.get("# moments run without a round trip", 0)))


def best_of(submission: Path, jobs: int, repeats: int) -> CheckTiming:
    """The fastest of `repeats` checks (load on a shared machine only ever slows a run down)."""
    return min((time_check(submission, jobs) for _ in range(max(1, repeats))), key=lambda t: t.wall_s)


def load_average() -> str:
    """The 1, 5 and 15 minute load averages, for the record."""
    try:
        return " ".join(f"{v:.2f}" for v in os.getloadavg())
    except OSError:
        return "unknown"
