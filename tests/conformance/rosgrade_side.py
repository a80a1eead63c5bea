"""Run a probe node under rosgrade (our client library, the MuJoCo world, lockstep sim time) and collect its outputs."""
from __future__ import annotations

import dataclasses
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

from real_ros import Command  # the same /cmd_vel record on both sides

START_TIME_S = 2.0
# The real side times Ctrl+C from the probe's first /clock, which comes as init_node returns; ours from the start of
# the run, and init_node takes this long here (rospy.client.INIT_NODE_NS).
INIT_NODE_S = 0.1


@dataclass
class OursResult:
    """What one probe run under rosgrade produced (stdout/stderr rebuilt from the recording's output lines)."""

    stdout: str
    stderr: str
    exit_code: int | None
    exit_signal: int | None
    status: str
    commands: list[Command]
    lines: list[tuple[float, str, str, int | None]]   # (t, stream, text, level) as the recording gives them
    start_s: float = START_TIME_S
    wall_s: float = 0.0
    notes: list[str] = field(default_factory=list)


def run_ours(probe: Path, args: tuple[str, ...] = (), *, shutdown_at: float | None = None, duration: float = 4.0,
             ros_namespace: str | None = None, workdir: Path | None = None) -> OursResult:
    """Run `probe` with `args` under rosgrade; Ctrl+C at `shutdown_at` s after the start, stopped at `duration`."""
    from grader.recording import Recording
    from grader.runtime.session import run
    from grader.runtime.spec import Limits, NodeSpec, RunSpec
    from sim import Scenario

    workdir = Path(workdir or tempfile.mkdtemp(prefix="rosgrade-conformance-"))
    recording_path = workdir / f"{Path(probe).stem}.mcap"
    log_path = workdir / f"{Path(probe).stem}.log"
    # A probe that hangs must fail fast, not after the default budgets; and the world need not run on long after
    # the probe has gone. (Only options this version of RunSpec has are passed: the runtime is still moving.)
    options = {"limits": Limits(wall_s=60.0, silent_wall_s=5.0), "settle_s": 0.1}
    accepted = {f.name for f in dataclasses.fields(RunSpec)}
    spec = RunSpec(
        scenario=Scenario(robot="turtlebot3_waffle", start_time=START_TIME_S, duration=duration,
                          shutdown_at=None if shutdown_at is None else shutdown_at + INIT_NODE_S),
        nodes=(NodeSpec(script=Path(probe).resolve(), args=tuple(args), ros_namespace=ros_namespace),),
        **{k: v for k, v in options.items() if k in accepted},
    )
    wall0 = time.monotonic()
    result = run(spec, recording_path, log_path)
    wall = time.monotonic() - wall0
    recording = Recording.open(recording_path)
    lines = [(float(line[0]), line[1], line[2], line[3] if len(line) > 3 else None)
             for line in recording.output_lines()]
    stdout = "".join(text + "\n" for _, stream, text, _ in lines if stream == "stdout")
    stderr = "".join(text + "\n" for _, stream, text, _ in lines if stream == "stderr")
    series = recording.commands()
    commands = [Command(float(series.t[i]), tuple(float(v) for v in series.linear[i]),
                        tuple(float(v) for v in series.angular[i]), str(series.callerid[i]))
                for i in range(len(series))]
    node = result.nodes[0]
    notes = [f"{node.status}: {node.message}"] + list(result.diagnostics)
    return OursResult(stdout, stderr, node.exit_code, node.exit_signal, node.status, commands, lines,
                      wall_s=wall, notes=notes)
