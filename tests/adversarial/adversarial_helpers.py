"""Run one corpus node in a short scenario with tight limits, and check that nothing of it escaped."""
from __future__ import annotations

import os
import shutil
import signal
import time
from dataclasses import dataclass
from pathlib import Path

from grader.runtime import confine
from grader.runtime.process import MARKER_ENV
from grader.runtime.session import run
from grader.runtime.spec import Limits, NodeSpec, RunResult, RunSpec
from sim import Scenario

CORPUS = Path(__file__).resolve().parent / "corpus"
LIMITS = Limits(wall_s=20, silent_wall_s=3, cpu_s=15, memory_mb=300, processes=32, output_bytes=200_000)


@dataclass
class Case:
    result: RunResult
    folder: Path        # the run folder: recording, log, raw output
    package: Path       # the node's own folder (a copy of the corpus script)
    output: str         # everything the node printed (recorded stdout/stderr and raw output)

    @property
    def node(self):
        return self.result.nodes[0]


def marked_processes() -> list[int]:
    """Processes still carrying a node marker (any run's)."""
    found = []
    for pid in confine.processes():
        try:
            with open(f"/proc/{pid}/environ", "rb") as handle:
                env = handle.read().split(b"\0")
        except OSError:
            continue
        if any(item.startswith(MARKER_ENV.encode() + b"=") for item in env):
            if not confine.status_fields(pid).get("State", "").startswith("Z"):
                found.append(pid)
    return found


def node_uid_processes() -> list[int]:
    """Live processes running as one of the nodes' private uids."""
    return [p for p in confine.processes()
            if (confine.uid_of(p) or 0) >= confine.UID_BASE
            and not confine.status_fields(p).get("State", "").startswith("Z")]


def run_case(name: str, tmp: Path, args: tuple[str, ...] = (), duration: float = 8.0, shutdown_at: float = 3.0,
             limits: Limits = LIMITS, scenario: Scenario | None = None, script: Path | None = None) -> Case:
    package = tmp / "student pkg ü" / "scripts"   # spaces and non-ASCII in the path, on purpose
    package.mkdir(parents=True, exist_ok=True)
    target = package / (script.name if script else f"{name}.py")
    shutil.copy(script or CORPUS / f"{name}.py", target)
    folder = tmp / "run"
    folder.mkdir(exist_ok=True)
    scenario = scenario or Scenario(duration=duration, shutdown_at=shutdown_at)
    result = run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=target, args=args),), limits=limits,
                         shutdown_grace_s=1.0),
                 folder / "run.mcap", folder / "run.log")
    output = (folder / "run.log").read_text("utf-8", "replace")
    for raw in folder.glob("run.raw*.log"):
        output += raw.read_text("utf-8", "replace")
    return Case(result, folder, package, output)


def assert_nothing_escaped(case: Case | None = None) -> None:
    """No process of any node is left, by marker and by uid (a little grace for the kernel to reap)."""
    deadline = time.monotonic() + 2.0
    while True:
        left = sorted(set(marked_processes()) | set(node_uid_processes()))
        if not left or time.monotonic() > deadline:
            break
        time.sleep(0.05)
    for pid in left:  # do not leave them running for the next test, but fail this one
        try:
            os.kill(pid, signal.SIGKILL)
        except OSError:
            pass
    assert not left, f"processes left behind: {left}"
