"""Run one corpus node in a short scenario with tight limits, and check that nothing of it escaped."""
from __future__ import annotations

import os
import shutil
import signal
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import pytest

from grader.runtime import confine
from grader.runtime.process import MARKER_ENV, marker_prefix
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


def _alive(pid: int) -> bool:
    return not confine.status_fields(pid).get("State", "Z").startswith("Z")


def marked_processes(grader_pid: int | None = None) -> list[int]:
    """Live processes carrying the node marker of one grader (default: this test process, which runs the nodes).

    Other graders run on this machine at the same time (other test sessions, batch workers): their nodes carry
    markers with their own grader pid and are none of this run's business.
    """
    wanted = f"{MARKER_ENV}={marker_prefix(grader_pid)}".encode()
    found = []
    for pid in confine.processes():
        try:
            with open(f"/proc/{pid}/environ", "rb") as handle:
                env = handle.read().split(b"\0")
        except OSError:
            continue
        if any(item.startswith(wanted) for item in env) and _alive(pid):
            found.append(pid)
    return found


def node_uid_processes(grader_pid: int | None = None) -> list[int]:
    """Live processes running as one of the private uids of one grader's nodes (default: this test process)."""
    uids = confine.uid_range(grader_pid)
    return [p for p in confine.processes() if confine.uid_of(p) in uids and _alive(p)]


def refuses_to_run_nodes() -> bool:
    """Root without namespaces and an interpreter only root can read: rosgrade will not run any node here."""
    cap = confine.detect()
    return cap.mode == "uid" and not confine.readable_by_others(Path(sys.executable))


def run_case(name: str, tmp: Path, args: tuple[str, ...] = (), duration: float = 8.0, shutdown_at: float = 3.0,
             limits: Limits = LIMITS, scenario: Scenario | None = None, script: Path | None = None) -> Case:
    if refuses_to_run_nodes():
        pytest.skip("as root without bubblewrap or user namespaces, rosgrade refuses to run nodes with an interpreter "
                    "only root can read (test_fallback_as_root_never_runs_the_node_as_root checks that)")
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


def assert_nothing_escaped(grader_pid: int | None = None) -> None:
    """No process of one grader's nodes is left, by marker and by uid (a little grace for the kernel to reap).

    grader_pid is the process that ran the nodes: this test process by default, or a grader the test started.
    Only that grader's leftovers are looked for and killed, never other runs' nodes on the same machine.
    """
    deadline = time.monotonic() + 2.0
    while True:
        left = sorted(set(marked_processes(grader_pid)) | set(node_uid_processes(grader_pid)))
        if not left or time.monotonic() > deadline:
            break
        time.sleep(0.05)
    for pid in left:  # do not leave them running for the next test, but fail this one
        try:
            os.kill(pid, signal.SIGKILL)
        except OSError:
            pass
    assert not left, f"processes left behind: {left}"
