"""Evaluate a ROS 2 launch file (student code) in the node sandbox, bounded in time, CPU, memory and output, and
return what `ros2 launch` would start, as data read from a pipe (nothing the launch file prints is trusted)."""
from __future__ import annotations

import json
import os
import select
import signal
import subprocess
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from grader.launch.known import DEFAULT_ENV
from grader.launch.ros2_index import launch_index
from grader.runtime import confine
from grader.runtime.process import _child_setup, node_environment, rlimit_pairs
from grader.runtime.spec import Limits, NodeSpec
from grader.workspace.model import Workspace

MAX_RESULT_BYTES = 8 << 20
LIMITS = Limits(wall_s=20.0, cpu_s=10.0, memory_mb=1024, processes=16, file_mb=16)


class Ros2LaunchError(Exception):
    """The launch file could not be evaluated (it failed, or went past a limit)."""


@dataclass(frozen=True)
class Evaluation:
    """What the evaluator returned, and the tail of what the launch file printed."""

    result: dict[str, Any]
    output: str


def _kill(popen: subprocess.Popen[bytes]) -> None:
    try:
        os.killpg(popen.pid, signal.SIGKILL)
    except OSError:
        pass
    popen.wait()


def _read(fd: int, popen: subprocess.Popen[bytes], limits: Limits) -> tuple[bytes, str | None]:
    """Everything written to the pipe until it closes, or why reading stopped."""
    data = bytearray()
    deadline = time.monotonic() + limits.wall_s
    while True:
        left = deadline - time.monotonic()
        if left <= 0:
            return bytes(data), f"did not finish within {limits.wall_s:g} s (a loop that never ends?)"
        ready, _, _ = select.select([fd], [], [], min(left, 0.5))
        if not ready:
            if popen.poll() is not None:  # ended; a process it left behind may still hold the pipe open
                return bytes(data), None
            continue
        chunk = os.read(fd, 1 << 16)
        if not chunk:
            return bytes(data), None
        data += chunk
        if len(data) > MAX_RESULT_BYTES:
            return bytes(data), f"described more than {MAX_RESULT_BYTES >> 20} MB of processes"


def evaluate(file: Path, workspace: Workspace, arguments: list[tuple[str, str]], show_args: bool = False,
             limits: Limits = LIMITS) -> Evaluation:
    """Run launch.rosgrade_evaluate on `file` confined, with the workspace's packages as the install it sees."""
    file = file.resolve()
    with tempfile.TemporaryDirectory(prefix="rosgrade-launch-") as tmp:
        workdir = Path(tmp)
        command = ["-B", "-m", "launch.rosgrade_evaluate", str(file), *(f"{k}:={v}" for k, v in arguments)]
        if show_args:
            command.append("--show-args")
        try:
            plan = confine.plan(command, file, workdir / "home", limits.file_mb, (workspace.root.resolve(),))
        except confine.ConfineError as exc:
            raise Ros2LaunchError(str(exc)) from None
        (workdir / "home").mkdir(exist_ok=True)
        read_fd, write_fd = os.pipe()
        env = node_environment(NodeSpec(script=file, flavour="ros2"), "", plan.home)
        env.pop("ROSGRADE_CHANNEL", None)
        env.pop("ROS_MASTER_URI", None)
        # What a course machine's shell sets (ROS sourced, the TurtleBot3 model in ~/.bashrc), for os.environ reads.
        env.update(ROSGRADE_LAUNCH_FD=str(write_fd), ROSGRADE_LAUNCH_INDEX=json.dumps(launch_index(workspace)),
                   ROS_DISTRO="jazzy", ROS_VERSION="2", ROS_PYTHON_VERSION="3",
                   TURTLEBOT3_MODEL=DEFAULT_ENV["TURTLEBOT3_MODEL"])
        pairs = rlimit_pairs(limits, limits.processes if plan.uid is not None or plan.sandboxed else None)
        uid = None if plan.sandboxed else plan.uid
        log_path = workdir / "output.txt"
        with open(log_path, "wb") as log:
            popen = subprocess.Popen(plan.argv, cwd=plan.cwd, env=env, stdin=subprocess.DEVNULL, stdout=log,
                                     stderr=subprocess.STDOUT, pass_fds=(write_fd,), start_new_session=True,
                                     preexec_fn=lambda: _child_setup(pairs, uid))
        os.close(write_fd)
        try:
            data, stopped = _read(read_fd, popen, limits)
        finally:
            os.close(read_fd)
            if popen.poll() is None:
                try:
                    popen.wait(timeout=2.0)
                except subprocess.TimeoutExpired:
                    pass
            _kill(popen)
        output = log_path.read_bytes()[-4000:].decode("utf-8", "replace")
    if stopped is not None:
        raise Ros2LaunchError(f"{file.name}: the launch file {stopped}; rosgrade stopped it")
    if popen.returncode and not data:
        reason = _ended(popen.returncode, limits)
        raise Ros2LaunchError(f"{file.name}: reading the launch file {reason} before it described anything"
                              + (f"; it printed:\n{output.strip()}" if output.strip() else ""))
    try:
        result = json.loads(data)
    except ValueError:
        raise Ros2LaunchError(f"{file.name}: reading the launch file ended before it described anything (exit "
                              f"{popen.returncode})" + (f"; it printed:\n{output.strip()}" if output.strip() else ""))
    return Evaluation(result, output)


def _ended(code: int, limits: Limits) -> str:
    if code == -signal.SIGKILL or code == 128 + signal.SIGKILL:
        return "was killed (over its memory or CPU limit)"
    if code in (-signal.SIGXCPU, 128 + signal.SIGXCPU):
        return f"used more than {limits.cpu_s:g} s of CPU"
    return f"ended with exit code {code}"
