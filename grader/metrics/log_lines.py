"""Log lines: the node's log (/rosout and stdout) against a format, a level, a rate and the robot's real pose.

The format is written as the line should read, with named numeric fields and their decimals, e.g.
``x={x:.2f} [m], y={y:.2f} [m], yaw={yaw:.1f} [degrees].`` A line is one of the node's pose lines when its fields can
be read from it in order after their labels (the word before each field), whatever the spacing, units or decimals;
it has the right format only if it reads exactly as written. Fields named x, y and yaw are compared with the robot's
pose relative to where it started: in the start frame (rotated by the start heading) or just offset, whichever
fits more lines.
"""
from __future__ import annotations

import math
import re
import string
from dataclasses import dataclass
from typing import Literal

import numpy as np
from pydantic import field_validator

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.motion import wrap
from grader.metrics.run import OutputLine, RunData, Trajectory

_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_FIXED = re.compile(r"^\.(\d+)f$")
Level = Literal["DEBUG", "INFO", "WARN", "ERROR", "FATAL"]
Frame = Literal["start_frame", "offset", "absolute"]


@dataclass(frozen=True)
class LineFormat:
    """A compiled format: the exact pattern, the lenient one that finds pose lines, and the field names in order."""

    exact: re.Pattern[str]
    lenient: re.Pattern[str]
    fields: tuple[str, ...]


def compile_format(text: str) -> LineFormat:
    """Compile ``x={x:.2f} [m], ...``; raise ValueError on a field that is unnamed, repeated or not ``.Nf``."""
    exact, lenient, fields = [], [], []
    try:
        parts = list(string.Formatter().parse(text))
    except ValueError as e:
        raise ValueError(f"format {text!r} is malformed: {e}") from None
    for literal, name, spec, _ in parts:
        exact.append(re.escape(literal))
        if name is None:
            continue
        if not name.isidentifier() or name in fields:
            raise ValueError(f"format field {{{name}}} must be a unique name such as {{x:.2f}}")
        fixed = _FIXED.match(spec or "")
        if spec and fixed is None:
            raise ValueError(f"format field {{{name}:{spec}}}: write decimals as .Nf (e.g. {{{name}:.2f}}) or none")
        decimals = int(fixed.group(1)) if fixed else None
        exact.append(rf"(?P<{name}>[-+]?\d+" + ("" if decimals == 0 else rf"\.\d{{{decimals}}}" if decimals else
                                                r"(?:\.\d+)?") + ")")
        labels = re.findall(r"[A-Za-z_]\w*", literal)
        label = rf"(?<![A-Za-z0-9_]){re.escape(labels[-1])}[^0-9+\-.]*?" if labels else ""
        lenient.append(rf".*?{label}(?P<{name}>{_NUMBER})")
        fields.append(name)
    if not fields:
        raise ValueError(f"format {text!r} has no {{field}} to read a number from")
    return LineFormat(re.compile("".join(exact)), re.compile("".join(lenient), re.I), tuple(fields))


class Params(TrajectoryParams):
    """What the log should look like, and how close its x, y, yaw must be to the robot's pose."""

    format: str
    level: Level | None = None
    yaw_unit: Literal["degrees", "radians"] = "degrees"
    frame: Literal["start", "absolute"] = "start"  # start: relative to the start pose, as the task asks
    position_tolerance: float = 0.05  # m, each of x and y
    yaw_tolerance_deg: float = 3.0
    latency_s: float = 0.2  # a line may report a pose up to this much older than the line

    @field_validator("format")
    @classmethod
    def _compiles(cls, v: str) -> str:
        compile_format(v)
        return v


@dataclass(frozen=True)
class _Line:
    t: float
    stream: str
    level: str | None
    body: str
    values: dict[str, float]
    exact: bool


def _node_lines(lines: tuple[OutputLine, ...], fmt: LineFormat) -> list[_Line]:
    """The pose lines of the one stream that has most of them (loginfo shows on stdout and /rosout; /rosout wins)."""
    by_stream: dict[str, list[_Line]] = {}
    for line in lines:
        level, body = line.message()
        body = body.strip()
        found = fmt.lenient.match(body)
        if found is None:
            continue
        values = {k: float(v) for k, v in found.groupdict().items()}
        by_stream.setdefault(line.stream, []).append(_Line(line.t, line.stream, level, body, values, bool(fmt.exact.fullmatch(body))))
    if not by_stream:
        return []
    rank = {"rosout": 0, "stdout": 1}
    return max(by_stream.values(), key=lambda found: (len(found), -rank.get(found[0].stream, 2)))


def _start_pose(traj: Trajectory, start_time: float) -> tuple[float, float, float]:
    k = min(int(np.searchsorted(traj.t, start_time)), len(traj) - 1)
    return float(traj.x[k]), float(traj.y[k]), float(traj.yaw[k])


def _expected(traj: Trajectory, start: tuple[float, float, float], frame: Frame) -> tuple[np.ndarray, ...]:
    """The pose series as a node would report it: absolute, offset from the start, or in the start frame."""
    if frame == "absolute":
        return traj.x, traj.y, traj.yaw
    x0, y0, yaw0 = start
    dx, dy = traj.x - x0, traj.y - y0
    yaw = np.asarray(wrap(traj.yaw - yaw0))
    if frame == "offset":
        return dx, dy, yaw
    c, s = math.cos(yaw0), math.sin(yaw0)
    return c * dx + s * dy, -s * dx + c * dy, yaw


def _errors(line: _Line, traj: Trajectory, pose: tuple[np.ndarray, ...], window: float,
            radians: bool, tol: tuple[float, float]) -> tuple[float, float]:
    """(position error m, yaw error rad) of the line against the best pose in the latency window before it."""
    lo, hi = np.searchsorted(traj.t, line.t - window, "left"), np.searchsorted(traj.t, line.t + 1e-9, "right")
    if hi <= lo:
        return math.inf, math.inf
    v = line.values
    pos = np.zeros(hi - lo)
    for name, series in (("x", pose[0]), ("y", pose[1])):
        if name in v:
            pos = np.maximum(pos, np.abs(series[lo:hi] - v[name]))
    ang = np.zeros(hi - lo)
    if "yaw" in v:
        yaw = v["yaw"] if radians else math.radians(v["yaw"])
        ang = np.abs(np.asarray(wrap(pose[2][lo:hi] - yaw)))
    best = int(np.argmin(np.maximum(pos / tol[0], ang / tol[1])))
    return float(pos[best]), float(ang[best])


def _fraction(errors: list[tuple[float, float]], tol: tuple[float, float]) -> float:
    return sum(p <= tol[0] and a <= tol[1] for p, a in errors) / len(errors) if errors else math.nan


def measure(run: RunData, params: Params) -> Measurement:
    """Find the node's pose lines and judge their format, level, rate and values."""
    fmt = compile_format(params.format)
    found = _node_lines(run.lines, fmt)
    if not found:
        raise MetricError(f"no line of the node's log or output reads like {params.format!r}")
    traj = run.trajectory(params.source)
    times = np.array([line.t for line in found])
    n = len(found)
    result: Measurement = {
        "n_lines": n,
        "n_format_ok": sum(line.exact for line in found),
        "format_fraction": sum(line.exact for line in found) / n,
        "format_example": next((line.body[:100] for line in found if not line.exact), ""),
        "level_fraction": math.nan if params.level is None else sum(line.level == params.level for line in found) / n,
        "levels": ", ".join(sorted({line.level or "print" for line in found})),
        "rate_hz": (n - 1) / float(times[-1] - times[0]) if n > 1 and times[-1] > times[0] else 0.0,
        "max_gap_s": float(np.max(np.diff(times))) if n > 1 else math.nan,
        "first_line_s": float(times[0] - run.start_time),
        "stream": found[0].stream,
    }
    checked = [line for line in found if {"x", "y", "yaw"} & set(line.values)]
    if len(traj) < 2 or not checked:
        return {**result, "values_fraction": math.nan, "n_values_ok": 0, "position_error_max": math.nan,
                "yaw_error_max_deg": math.nan, "relative_frame": "none", "absolute_fraction": math.nan,
                "other_unit_fraction": math.nan}
    tol = (params.position_tolerance, math.radians(params.yaw_tolerance_deg))
    start = _start_pose(traj, run.start_time)
    radians = params.yaw_unit == "radians"

    def errors(frame: Frame, in_radians: bool = radians) -> list[tuple[float, float]]:
        pose = _expected(traj, start, frame)
        return [_errors(line, traj, pose, params.latency_s, in_radians, tol) for line in checked]

    frames: list[Frame] = ["start_frame", "offset"] if params.frame == "start" else ["absolute"]
    frame = max(frames, key=lambda f: _fraction(errors(f), tol))  # first on ties: the start frame
    chosen = errors(frame)
    finite = [(p, a) for p, a in chosen if math.isfinite(p)]
    return {
        **result,
        "values_fraction": _fraction(chosen, tol),
        "n_values_ok": sum(p <= tol[0] and a <= tol[1] for p, a in chosen),
        "position_error_max": max((p for p, _ in finite), default=math.nan),
        "yaw_error_max_deg": math.degrees(max((a for _, a in finite), default=math.nan)),
        "relative_frame": frame,
        "absolute_fraction": _fraction(errors("absolute"), tol),
        "other_unit_fraction": _fraction(errors(frame, not radians), tol),
    }


METRIC = Metric(
    name="log_lines",
    params=Params,
    quantities=frozenset({
        "n_lines", "n_format_ok", "format_fraction", "format_example", "level_fraction", "levels", "rate_hz",
        "max_gap_s", "first_line_s", "stream", "values_fraction", "n_values_ok", "position_error_max",
        "yaw_error_max_deg", "relative_frame", "absolute_fraction", "other_unit_fraction",
    }),
    measure=measure,
)
