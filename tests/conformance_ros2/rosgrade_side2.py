"""Run a ROS 2 probe under rosgrade (our rclpy, the simulated world, lockstep sim time) and collect its outputs."""
from __future__ import annotations

import dataclasses
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

from tests.conformance_harness import reference_time

START_TIME_S = 2.0
ROBOT = "turtlebot3_waffle"  # the world's TurtleBot3; its ROS 2 mode (TwistStamped on /cmd_vel) comes with the lead's wiring
# Real probes time Ctrl+C from their '#REF' line (sim time and the robot matched). Ours is given as sim seconds from
# the start of the run: first guessed as the probe's '#REF' plus this, then corrected from the '#REF' it printed.
ORIGIN_GUESS_S = 0.1


class RosgradeSideError(Exception):
    """rosgrade could not run a probe (the runtime raised, or Ctrl+C could not be placed relative to its origin)."""


@dataclass
class OurCommand:
    """A /cmd_vel message as recorded; t is sim time relative to the probe's origin (its '#REF')."""

    t: float
    type: str
    linear: tuple[float, float, float]
    angular: tuple[float, float, float]


@dataclass
class OursResult:
    """What one probe run under rosgrade produced (stdout/stderr rebuilt from the recording's output lines)."""

    stdout: str
    stderr: str
    exit_code: int | None
    exit_signal: int | None
    status: str
    commands: list[OurCommand]
    origin_s: float | None
    sigint_s: float | None            # relative to the origin
    wall_s: float = 0.0
    notes: list[str] = field(default_factory=list)


def run_ours(probe: Path, args: tuple[str, ...] = (), *, shutdown_at: float | None = None, duration: float = 4.0,
             workdir: Path | None = None, robot: str = ROBOT, beside: tuple[Path, ...] = ()) -> OursResult:
    """Run `probe` with `args` under rosgrade; Ctrl+C `shutdown_at` sim s after its '#REF', stopped at `duration`.

    `robot` is the world (``turtlesim`` for Jazzy's turtlesim); `beside` are grader-provided nodes run with the probe
    (turtlesim's rotate_absolute server, which real turtlesim serves itself)."""
    workdir = Path(workdir or tempfile.mkdtemp(prefix="rosgrade-conformance2-"))
    offset = ORIGIN_GUESS_S
    world = (robot, beside)
    result = _run_once(probe, args, shutdown_at, duration, offset, workdir / "first", world)
    if shutdown_at is None or result.origin_s is None or result.sigint_s is None:
        return result
    if abs(result.sigint_s - shutdown_at) > 1e-6:
        # Our runs are deterministic: the second run reaches the same '#REF', and Ctrl+C lands where asked.
        offset = result.origin_s - START_TIME_S
        result = _run_once(probe, args, shutdown_at, duration, offset, workdir / "second", world)
        if result.sigint_s is None or abs(result.sigint_s - shutdown_at) > 1e-6:
            raise RosgradeSideError(f"Ctrl+C landed at {result.sigint_s} s after the origin, not {shutdown_at} s")
    return result


def _run_once(probe: Path, args: tuple[str, ...], shutdown_at: float | None, duration: float, origin_offset_s: float,
              workdir: Path, world: tuple[str, tuple[Path, ...]]) -> OursResult:
    from grader.recording import Recording
    from grader.runtime.session import run
    from grader.runtime.spec import Limits, NodeSpec, RunSpec
    from sim import Scenario

    workdir.mkdir(parents=True, exist_ok=True)
    recording_path = workdir / f"{probe.stem}.mcap"
    log_path = workdir / f"{probe.stem}.log"
    # A probe that hangs must fail fast, not after the default budgets.
    options = {"limits": Limits(wall_s=60.0, silent_wall_s=5.0)}
    accepted = {f.name for f in dataclasses.fields(RunSpec)}
    spec = RunSpec(
        scenario=Scenario(robot=world[0], start_time=START_TIME_S, duration=origin_offset_s + duration,
                          shutdown_at=None if shutdown_at is None else origin_offset_s + shutdown_at),
        nodes=(NodeSpec(script=probe.resolve(), args=tuple(args), flavour="ros2"),
               *(NodeSpec(script=node, flavour="ros2", provided=True) for node in world[1])),
        **{k: v for k, v in options.items() if k in accepted},
    )
    wall0 = time.monotonic()
    outcome = run(spec, recording_path, log_path)
    wall = time.monotonic() - wall0
    recording = Recording.open(recording_path)
    lines = list(recording.output_lines())
    stdout = "".join(line[2] + "\n" for line in lines if line[1] == "stdout")
    stderr = "".join(line[2] + "\n" for line in lines if line[1] == "stderr")
    origin = reference_time(stdout)
    base = origin if origin is not None else 0.0
    series = recording.commands()
    types = getattr(series, "type", None)
    commands = [OurCommand(float(series.t[i]) - base, str(types[i]) if types is not None else "",
                           tuple(float(v) for v in series.linear[i]), tuple(float(v) for v in series.angular[i]))
                for i in range(len(series))]
    sigint = None if outcome.shutdown_requested_s is None else outcome.shutdown_requested_s - base
    node = outcome.nodes[0]
    return OursResult(stdout, stderr, node.exit_code, node.exit_signal, node.status, commands, origin, sigint,
                      wall_s=wall, notes=[f"{node.status}: {node.message}", *outcome.diagnostics])
