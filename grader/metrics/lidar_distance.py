"""LiDAR readings a node printed, checked against what its /scan read (COM2009 Part 3 Ex 4: the distance and the
direction of the nearest object ahead).

Each printed or logged line holding a distance (m) and an angle (degrees) is one reading. The scans the node can have
had then are rebuilt from the world's geometry at the robot's ground-truth pose at each sweep (the LiDAR's beams from
its mount, nearest wall or pillar; the simulated noise, 1 cm, is well inside the tolerance): a reading is right when
it matches the nearest object within ``arc_deg`` of straight ahead in one of the ``lag_scans`` sweeps before it.
"""
from __future__ import annotations

import math
import re

from pydantic import Field

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.run import OutputLine, RunData
from grader.metrics.stop_distance import ray_distance
from sim.profile import ProfileError, ScanConfig, load_robot

_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_WITH_METRES = re.compile(rf"({_NUMBER})\s*(?:m\b|metres\b|meters\b)")
_WITH_DEGREES = re.compile(rf"({_NUMBER})\s*(?:°|deg\b|degs\b|degrees\b)")
_ANY = re.compile(_NUMBER)


class Params(TrajectoryParams):
    """The arc the task calls "ahead", the tolerances, and how many sweeps back a reading may be from."""

    arc_deg: float = Field(20.0, gt=0, le=180)  # either side of straight ahead
    distance_tolerance: float = Field(0.05, gt=0)  # metres
    angle_tolerance_deg: float = Field(5.0, gt=0)
    lag_scans: int = Field(3, ge=1)


def reading(text: str) -> tuple[float, float] | None:
    """(distance m, angle deg) from a line: numbers marked m and deg (or °) if it has them, else its first two."""
    metres, degrees = _WITH_METRES.search(text), _WITH_DEGREES.search(text)
    if metres and degrees:
        return float(metres.group(1)), float(degrees.group(1))
    numbers = _ANY.findall(text)
    if len(numbers) >= 2 and not (metres or degrees):
        return float(numbers[0]), float(numbers[1])
    return None


def nearest_ahead(run: RunData, scan: ScanConfig, pose: tuple[float, float, float], arc: float
                  ) -> tuple[float, float]:
    """(distance, angle in degrees) of the beam within ``arc`` rad of ahead that reads least at ``pose`` (inf, nan:
    none in range)."""
    x, y, yaw = pose
    mx = x + scan.mount[0] * math.cos(yaw) - scan.mount[1] * math.sin(yaw)
    my = y + scan.mount[0] * math.sin(yaw) + scan.mount[1] * math.cos(yaw)
    increment = (scan.angle_max - scan.angle_min) / (scan.samples - 1)
    best, at = math.inf, math.nan
    for i in range(scan.samples):
        angle = math.remainder(scan.angle_min + i * increment, 2 * math.pi)
        if abs(angle) > arc:
            continue
        dx, dy = math.cos(yaw + angle), math.sin(yaw + angle)
        d = min((ray_distance(mx, my, dx, dy, o) for o in run.obstacles), default=math.inf)
        if scan.range_min <= d <= scan.range_max and d < best:
            best, at = d, math.degrees(angle)
    return best, at


def _matches(read: tuple[float, float], truth: tuple[float, float], params: Params) -> tuple[bool, bool]:
    distance, angle = read
    right_distance = math.isfinite(truth[0]) and abs(distance - truth[0]) <= params.distance_tolerance
    off = abs(math.remainder(math.radians(angle - truth[1]), 2 * math.pi)) if math.isfinite(truth[1]) else math.inf
    return right_distance, right_distance and math.degrees(off) <= params.angle_tolerance_deg


def _readings(lines: tuple[OutputLine, ...]) -> list[tuple[float, float, float]]:
    """(t, distance, angle) of the stream that holds most readings (loginfo shows on stdout and /rosout alike;
    /rosout wins a tie)."""
    by_stream: dict[str, list[tuple[float, float, float]]] = {}
    for line in lines:
        found = reading(line.message()[1])
        if found is not None:
            by_stream.setdefault(line.stream, []).append((line.t, *found))
    rank = {"rosout": 0, "stdout": 1}
    return max(by_stream.items(), key=lambda kv: (len(kv[1]), -rank.get(kv[0], 2)), default=("", []))[1]


def measure(run: RunData, params: Params) -> Measurement:
    """Each reading against the nearest object ahead in the sweeps just before it; the readings' rate."""
    try:
        profile = load_robot(run.robot)
    except ProfileError:
        raise MetricError("the recording does not say which robot ran, so its LiDAR is unknown") from None
    scan = profile.modes[profile.default_mode].sensors.scan
    if scan is None:
        raise MetricError("this robot has no LiDAR to check readings against")
    traj = run.trajectory(params.source)
    if len(traj) == 0:
        raise MetricError("the recording has no poses to locate the robot")
    readings = [r for r in _readings(run.lines) if r[0] >= run.start_time]
    period = 1.0 / scan.rate_hz
    truths: dict[int, tuple[float, float]] = {}
    right = right_angles = 0
    first_wrong = ""
    for t, distance, angle in readings:
        sweep = math.floor(t / period + 1e-9)
        matched = (False, False)
        for k in range(sweep, sweep - params.lag_scans, -1):
            if k not in truths:
                at = min(int(traj.t.searchsorted(k * period)), len(traj) - 1)
                pose = float(traj.x[at]), float(traj.y[at]), float(traj.yaw[at])
                truths[k] = nearest_ahead(run, scan, pose, math.radians(params.arc_deg))
            found = _matches((distance, angle), truths[k], params)
            matched = max(matched, found)
            if matched == (True, True):
                break
        right += matched[0]
        right_angles += matched[1]
        if not matched[0] and not first_wrong:
            truth = truths[sweep]
            first_wrong = (f"at {t - run.start_time:.1f} s the node printed {distance:g} m at {angle:g}°; /scan read "
                           f"{truth[0]:.2f} m at {truth[1]:.0f}°")
    times = [r[0] for r in readings]
    span = times[-1] - times[0] if len(times) > 1 else 0.0
    n = len(readings)
    return {
        "n_readings": n,
        "distance_fraction": right / n if n else 0.0,
        "angle_fraction": right_angles / n if n else 0.0,
        "first_wrong": first_wrong,
        "rate_hz": (n - 1) / span if span > 0 else 0.0,
        "max_gap_s": max((b - a for a, b in zip(times, times[1:])), default=math.inf),
    }


METRIC = Metric(
    name="lidar_distance",
    params=Params,
    quantities=frozenset({"n_readings", "distance_fraction", "angle_fraction", "first_wrong", "rate_hz",
                          "max_gap_s"}),
    measure=measure,
)
