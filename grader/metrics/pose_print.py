"""Pose printing: parse (x, y, yaw) from each output line and check it against odometry at that line's sim time."""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

from grader.metrics.base import Measurement, Metric, MetricError, MetricParams
from grader.metrics.motion import wrap
from grader.metrics.run import LOG_PREFIX, OutputLine, RunData, Trajectory

_NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_UNIT = r"(?:\s*\[?\s*(?:m|deg(?:rees)?|rad(?:ians)?|°)\s*\]?)?"
_LABELS = {
    "x": r"(?:pos(?:ition)?[ _.]?)?x",
    "y": r"(?:pos(?:ition)?[ _.]?)?y",
    "yaw": r"(?:yaw|theta[ _]?z?|θ[ _]?z?|th|heading|angle|rot(?:ation)?[ _]?z?)",
}
_LABELLED = {
    k: re.compile(rf"(?<![A-Za-z_]){label}{_UNIT}\s*(?:[:=]|is)\s*\(?\s*({_NUM})", re.I) for k, label in _LABELS.items()
}
_NUMBER = re.compile(_NUM)
_DEGREES = re.compile(r"deg|°", re.I)


@dataclass(frozen=True)
class PoseLine:
    """A printed pose: when it was printed, the three numbers, and whether the text says degrees."""

    t: float
    x: float
    y: float
    yaw: float
    says_degrees: bool
    stream: str


def parse_pose(text: str) -> tuple[float, float, float] | None:
    """(x, y, yaw) from one line: labelled values (``x=``, ``yaw:``, ``theta =``), else a line of exactly 3 numbers."""
    body = LOG_PREFIX.sub("", text)  # the console prefix's wall and sim times are not pose numbers
    found = {k: pattern.search(body) for k, pattern in _LABELLED.items()}
    if all(found.values()):
        return tuple(float(m.group(1)) for m in found.values())  # type: ignore[union-attr,return-value]
    numbers = _NUMBER.findall(body)
    if len(numbers) == 3:  # "(x,y,θz) = (0.50, -0.20, 1.57)", "0.50 -0.20 1.57"
        return float(numbers[0]), float(numbers[1]), float(numbers[2])
    return None


def pose_lines(lines: tuple[OutputLine, ...]) -> list[PoseLine]:
    """The pose lines of the one stream that printed most of them (loginfo shows up on stdout and /rosout)."""
    by_stream: dict[str, list[PoseLine]] = {}
    for line in lines:
        pose = parse_pose(line.text)
        if pose is not None:
            by_stream.setdefault(line.stream, []).append(
                PoseLine(line.t, *pose, says_degrees=bool(_DEGREES.search(line.text)), stream=line.stream)
            )
    if not by_stream:
        return []
    rank = {"stdout": 0, "stderr": 1}
    return max(by_stream.values(), key=lambda ps: (len(ps), -rank.get(ps[0].stream, 2)))


def _errors(
    pose: PoseLine, odom: Trajectory, window: float, degrees: bool, tolerances: tuple[float, float]
) -> tuple[float, float]:
    """Smallest (position error m, yaw error rad) against the odometry samples published in the latency window."""
    lo, hi = np.searchsorted(odom.t, pose.t - window, "left"), np.searchsorted(odom.t, pose.t + 1e-9, "right")
    if hi <= lo:
        return math.inf, math.inf
    yaw = math.radians(pose.yaw) if degrees else pose.yaw
    pos = np.maximum(np.abs(odom.x[lo:hi] - pose.x), np.abs(odom.y[lo:hi] - pose.y))
    ang = np.abs(wrap(odom.yaw[lo:hi] - yaw))
    best = int(np.argmin(np.maximum(pos / tolerances[0], ang / tolerances[1])))
    return float(pos[best]), float(ang[best])


class Params(MetricParams):
    """How exact a printed pose must be: students print 2 decimals, so allow rounding plus one odometry period."""

    position_tolerance: float = 0.02  # m
    yaw_tolerance_deg: float = 2.0
    latency_periods: float = 1.0  # odometry periods a line may lag behind the sample it prints
    slack_s: float = 0.02  # plus the clock period and call costs in between


def measure(run: RunData, params: Params) -> Measurement:
    """Parse every pose line, pick radians or degrees by which fits, and count the lines that match odometry."""
    odom = run.odometry
    if len(odom) < 2:
        raise MetricError("the recording has no odometry to compare the printed poses with")
    poses = pose_lines(run.lines)
    if not poses:
        raise MetricError("no line of the output contained an (x, y, yaw) pose")
    window = params.latency_periods * float(np.median(np.diff(odom.t))) + params.slack_s
    yaw_tol = math.radians(params.yaw_tolerance_deg)

    def judged(degrees: bool) -> list[tuple[float, float, bool]]:
        return [
            (p, a, p <= params.position_tolerance and a <= yaw_tol)
            for p, a in (_errors(pose, odom, window, degrees, (params.position_tolerance, yaw_tol)) for pose in poses)
        ]

    in_rad, in_deg = judged(False), judged(True)
    says_degrees = sum(p.says_degrees for p in poses) > len(poses) / 2
    n_rad, n_deg = sum(ok for *_, ok in in_rad), sum(ok for *_, ok in in_deg)
    degrees = n_deg > n_rad or (n_deg == n_rad and says_degrees)
    results = in_deg if degrees else in_rad
    matched = [(p, a) for p, a, _ in results if math.isfinite(p)]
    times = np.array([p.t for p in poses])
    idx = np.clip(np.searchsorted(odom.t, times, "right") - 1, 0, len(odom) - 1)
    quat_z = np.abs(np.array([p.yaw for p in poses]) - np.sin(odom.yaw[idx] / 2.0)) <= 0.01
    n = len(poses)
    return {
        "n_lines": n,
        "n_correct": sum(ok for *_, ok in results),
        "fraction_correct": sum(ok for *_, ok in results) / n,
        "yaw_unit": "degrees" if degrees else "radians",
        "position_error_max": max((p for p, _ in matched), default=math.nan),
        "yaw_error_max_deg": math.degrees(max((a for _, a in matched), default=math.nan)),
        "quaternion_z_fraction": float(np.mean(quat_z)),
        "rate_hz": (n - 1) / float(times[-1] - times[0]) if n > 1 and times[-1] > times[0] else 0.0,
        "max_gap_s": float(np.max(np.diff(times))) if n > 1 else math.nan,
        "first_line_s": float(times[0] - run.start_time),
        "stream": poses[0].stream,
    }


METRIC = Metric(
    name="pose_print",
    params=Params,
    quantities=frozenset({
        "n_lines", "n_correct", "fraction_correct", "yaw_unit", "position_error_max", "yaw_error_max_deg",
        "quaternion_z_fraction", "rate_hz", "max_gap_s", "first_line_s", "stream",
    }),
    measure=measure,
)
