"""Shutdown response: after Ctrl+C, how soon the node commands a stop, how soon the robot rests, how the node exits."""
from __future__ import annotations

import math

import numpy as np

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.motion import path_length, rest_since
from grader.metrics.run import Commands, RunData


def zero_command_delay(commands: Commands, t_req: float) -> float:
    """Seconds from Ctrl+C to the node's first all-zero command; 0 if it had already stopped; NaN if never."""
    zero = commands.is_zero()
    after = commands.t >= t_req
    if np.any(after & zero):
        return float(commands.t[after & zero][0] - t_req)
    before = ~after
    if not np.any(after) and np.any(before) and zero[before][-1]:
        return 0.0
    return math.nan


class Params(TrajectoryParams):
    """Shutdown settings."""

    min_travel: float = 0.05  # m driven before Ctrl+C; a robot that never moved proves nothing about stopping


def measure(run: RunData, params: Params) -> Measurement:
    """Measure the stop after the Ctrl+C that the run recorded (or the scenario planned)."""
    t_req = run.shutdown_time()
    if t_req is None:
        raise MetricError("this scenario sends no Ctrl+C, so there is no shutdown to check")
    traj = run.trajectory(params.source)
    after = traj.between(t_req)
    if len(after) < 2:
        raise MetricError("the recording ends at the Ctrl+C, so the stop cannot be seen")
    rest_from = rest_since(after, params.rest_speed, params.rest_turn_rate)
    before = path_length(traj.between(end=t_req))
    # A robot that never moved proves nothing about stopping, unless the node answered the Ctrl+C with a zero
    # command its base takes and the robot stayed at rest: that is a stop.
    answered = (not run.ignored_command_types and rest_from is not None
                and bool(np.any(run.commands.is_zero() & (run.commands.t >= t_req))))
    if before < params.min_travel and not answered:
        raise MetricError(
            f"the robot drove only {before:.2f} m before Ctrl+C, so whether it stops on Ctrl+C cannot be seen"
        )
    stop_at = after.t[-1] if rest_from is None else rest_from
    cmd = run.commands
    ended = run.run.ended_s
    return {
        "zero_command_delay": zero_command_delay(cmd, t_req),
        "last_command_zero": bool(cmd.is_zero()[-1]) if len(cmd) else None,
        "rest_time": math.nan if rest_from is None else max(0.0, rest_from - t_req),
        "rest_distance": path_length(after.between(end=stop_at)),
        "moving_at_end": rest_from is None,
        "observed_s": float(after.t[-1] - t_req),
        "exited": ended is not None,
        "exit_delay": math.nan if ended is None else ended - t_req,
        "ended_before_shutdown": ended is not None and ended < t_req,
        "exited_before_shutdown_s": t_req - ended if ended is not None and ended < t_req else math.nan,
        "exit_code": run.run.exit_code,
        "exit_signal": None if run.run.exit_signal is None else str(run.run.exit_signal),
        "status": run.run.status,
    }


METRIC = Metric(
    name="shutdown",
    params=Params,
    quantities=frozenset({
        "zero_command_delay", "last_command_zero", "rest_time", "rest_distance", "moving_at_end", "observed_s",
        "exited", "exit_delay", "ended_before_shutdown", "exited_before_shutdown_s", "exit_code", "exit_signal", "status",
    }),
    measure=measure,
    needs_shutdown=True,
)
