"""Synthetic runs for the scoring tests: exact unicycle paths from piecewise-constant velocity segments."""
from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from grader.metrics import Commands, OutputLine, RunData, RunInfo, Trajectory

Segment = tuple[float, float, float]  # duration (s), linear (m/s), angular (rad/s)


def path(
    segments: Sequence[Segment], x0: float = 0.0, y0: float = 0.0, yaw0: float = 0.0,
    t0: float = 0.0, rate: float = 30.0, source: str = "odometry",
) -> Trajectory:
    """Sample the exact path of a unicycle driven by ``segments`` at ``rate`` Hz from sim time ``t0``."""
    total = sum(d for d, _, _ in segments)
    times = t0 + np.arange(0.0, total + 1e-9, 1.0 / rate)
    xs, ys, yaws = [], [], []
    for t in times:
        x, y, yaw, left = x0, y0, yaw0, t - t0
        for d, v, w in segments:
            tau = min(d, left)
            if abs(w) > 1e-12:
                x += v / w * (math.sin(yaw + w * tau) - math.sin(yaw))
                y -= v / w * (math.cos(yaw + w * tau) - math.cos(yaw))
            else:
                x += v * tau * math.cos(yaw)
                y += v * tau * math.sin(yaw)
            yaw += w * tau
            left -= tau
            if left <= 0:
                break
        xs.append(x)
        ys.append(y)
        yaws.append(math.atan2(math.sin(yaw), math.cos(yaw)))
    return Trajectory.of(times, xs, ys, yaws, source)


def commands(segments: Sequence[Segment], t0: float = 0.0, rate: float = 10.0) -> Commands:
    """The commands a node publishing each segment's velocity at ``rate`` Hz would have sent."""
    t, lin, ang, start = [], [], [], t0
    for d, v, w in segments:
        for k in range(max(1, int(round(d * rate)))):
            t.append(start + k / rate)
            lin.append(v)
            ang.append(w)
        start += d
    return Commands.of(t, lin, ang, "/cmd_vel")


def square_segments(side: float = 1.0, loops: int = 2, v: float = 0.2, w: float = 0.5, turn_deg: float = 90.0,
                    pause: float = 0.0) -> list[Segment]:
    """Forward ``side`` then turn ``turn_deg``, ``4 * loops`` times, optionally pausing after each move."""
    segs: list[Segment] = []
    for _ in range(4 * loops):
        segs.append((side / v, v, 0.0))
        if pause:
            segs.append((pause, 0.0, 0.0))
        segs.append((math.radians(turn_deg) / w, 0.0, w))
        if pause:
            segs.append((pause, 0.0, 0.0))
    return segs


def run(
    segments: Sequence[Segment], *, x0: float = 0.0, y0: float = 0.0, yaw0: float = 0.0, t0: float = 0.0,
    command_segments: Sequence[Segment] | None = None, lines: Sequence[OutputLine] = (),
    info: RunInfo = RunInfo(), shutdown_at: float | None = None, ground_truth: bool = True,
) -> RunData:
    """A RunData whose odometry and ground truth both follow ``segments`` (the sim's TB3 odom is the world pose)."""
    odom = path(segments, x0, y0, yaw0, t0)
    truth = path(segments, x0, y0, yaw0, t0, source="ground_truth") if ground_truth else None
    return RunData(
        odometry=odom, ground_truth=truth, commands=commands(command_segments or segments, t0),
        lines=tuple(lines), run=info, start_time=t0, shutdown_at=shutdown_at,
    )
