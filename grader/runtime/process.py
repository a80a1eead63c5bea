"""Start a student's node as its own process, with our client library first on its path, and clean it up."""
from __future__ import annotations

import os
import resource
import signal
import subprocess
import sys
from pathlib import Path

from grader.runtime.spec import Limits, NodeSpec

NODELIB = Path(__file__).resolve().parents[1] / "nodelib"

# Nothing of the grader's environment leaks into the node except what a terminal on a ROS machine would give it;
# ROS_* and PYTHONPATH are dropped so a real ROS install on this machine is never picked up.
_KEPT_ENV = ("PATH", "LANG", "LC_ALL", "TZ", "TERM")


class ProcessError(Exception):
    """A node process could not be started."""


def node_environment(spec: NodeSpec, channel: str, home: Path) -> dict[str, str]:
    env = {k: os.environ[k] for k in _KEPT_ENV if k in os.environ}
    env.update(
        HOME=str(home),
        TMPDIR=str(home),
        PYTHONPATH=str(NODELIB),
        PYTHONDONTWRITEBYTECODE="1",
        PYTHONNOUSERSITE="1",
        # Set iteration order (and so anything a node prints from a set) must not vary between runs.
        PYTHONHASHSEED="0",
        PYTHONIOENCODING="utf-8",
        ROSGRADE_CHANNEL=channel,
        ROS_MASTER_URI="http://localhost:11311",
    )
    env.setdefault("LANG", "C.UTF-8")
    if spec.ros_namespace:
        env["ROS_NAMESPACE"] = spec.ros_namespace
    return env


def _apply_limits(limits: Limits) -> None:
    """Runs in the child between fork and exec: rlimits that the kernel enforces for us."""
    cpu = int(limits.cpu_s)
    pairs = [
        (resource.RLIMIT_CPU, (cpu, cpu + 5)),
        (resource.RLIMIT_AS, (limits.memory_mb << 20, limits.memory_mb << 20)),
        (resource.RLIMIT_FSIZE, (limits.file_mb << 20, limits.file_mb << 20)),
        (resource.RLIMIT_CORE, (0, 0)),
    ]
    if os.geteuid() != 0:  # root ignores RLIMIT_NPROC; the process-group kill covers root runs
        pairs.append((resource.RLIMIT_NPROC, (limits.processes, limits.processes)))
    for which, value in pairs:
        try:
            resource.setrlimit(which, value)
        except (ValueError, OSError):
            pass
    # Ctrl+C from the grader's terminal must not reach the node directly: shutdown is the grader's decision.
    signal.signal(signal.SIGINT, signal.SIG_DFL)


class NodeProcess:
    """One running node: its Popen, the grader's ends of the channel pipes, and its raw-output file."""

    def __init__(self, spec: NodeSpec, workdir: Path, raw_output: Path, limits: Limits) -> None:
        node_to_grader_r, node_to_grader_w = os.pipe()
        grader_to_node_r, grader_to_node_w = os.pipe()
        home = workdir
        home.mkdir(parents=True, exist_ok=True)
        env = node_environment(spec, f"{grader_to_node_r},{node_to_grader_w}", home)
        self._raw = open(raw_output, "wb")
        try:
            self.popen = subprocess.Popen(
                [sys.executable, "-B", str(spec.script), *spec.args],
                cwd=str(home),
                env=env,
                stdin=subprocess.PIPE if spec.stdin is not None else subprocess.DEVNULL,
                stdout=self._raw,
                stderr=subprocess.STDOUT,
                pass_fds=(grader_to_node_r, node_to_grader_w),
                start_new_session=True,
                preexec_fn=lambda: _apply_limits(limits),
            )
        except OSError as exc:
            self._raw.close()
            for fd in (node_to_grader_r, node_to_grader_w, grader_to_node_r, grader_to_node_w):
                os.close(fd)
            raise ProcessError(f"could not start {spec.script.name}: {exc}") from None
        os.close(grader_to_node_r)
        os.close(node_to_grader_w)
        self.read_fd = node_to_grader_r
        self.write_fd = grader_to_node_w
        if spec.stdin is not None:
            try:
                self.popen.stdin.write(spec.stdin.encode())
                self.popen.stdin.close()
            except OSError:
                pass  # the node closed stdin or died; its outcome says why

    @property
    def pid(self) -> int:
        return self.popen.pid

    def signal_group(self, sig: int) -> None:
        """Signal the node and everything it started (it leads its own session)."""
        try:
            os.killpg(self.popen.pid, sig)
        except (ProcessLookupError, PermissionError):
            pass

    def wait(self, timeout: float | None = None) -> int | None:
        try:
            return self.popen.wait(timeout)
        except subprocess.TimeoutExpired:
            return None

    def close(self) -> None:
        """Kill whatever is left of the process group and release every descriptor."""
        self.signal_group(signal.SIGKILL)
        self.wait(5.0)
        for fd in (self.read_fd, self.write_fd):
            try:
                os.close(fd)
            except OSError:
                pass
        self._raw.close()
