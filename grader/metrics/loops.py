"""Loops: split a path into full turns of the heading (figure of eight, circles, spirals); direction, size, closure.

The heading is followed as one continuous angle. A change of turning direction starts a new stretch once the
heading has come back by more than ``reverse_deg`` from its extreme, so steering wobble does not split a loop. In a
stretch, every 360 degrees turned is one loop (a last loop counts from ``min_loop_deg``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader import exact
from grader.metrics.circle import fit_circle
from grader.metrics.motion import moving, path_length
from grader.metrics.run import RunData, Trajectory

Direction = Literal["anticlockwise", "clockwise"]


@dataclass(frozen=True)
class Loop:
    """One loop: its turning direction, fitted diameter (m), gap between its start and end (m), and when it ran."""

    direction: Direction
    diameter: float
    closure: float
    start_s: float
    end_s: float


def _stretches(heading: np.ndarray, reverse: float) -> list[tuple[int, int]]:
    """Index ranges [i, j] over which the heading keeps one turning direction (with hysteresis ``reverse`` rad)."""
    bounds, start, extreme, sign = [], 0, 0, 0
    for k in range(1, len(heading)):
        change = heading[k] - heading[extreme]
        if sign == 0:
            if abs(heading[k] - heading[start]) > reverse:
                sign, extreme = (1 if heading[k] > heading[start] else -1), k
        elif change * sign > 0:
            extreme = k
        elif -change * sign > reverse:  # turned back by more than the hysteresis: the extreme ends the stretch
            bounds.append((start, extreme))
            start, sign = extreme, -sign
            extreme = k
    bounds.append((start, len(heading) - 1))
    return bounds


def find_loops(traj: Trajectory, reverse_deg: float = 45.0, min_loop_deg: float = 300.0) -> list[Loop]:
    """The loops of ``traj`` in the order driven."""
    heading = np.unwrap(traj.yaw)
    loops: list[Loop] = []
    for i, j in _stretches(heading, math.radians(reverse_deg)):
        turned = np.abs(heading[i:j + 1] - heading[i])
        reach = np.maximum.accumulate(turned)
        full = int(reach[-1] // (2 * math.pi))
        count = full + (1 if reach[-1] - full * 2 * math.pi >= math.radians(min_loop_deg) else 0)
        direction: Direction = "anticlockwise" if heading[j] > heading[i] else "clockwise"
        begin = i
        for n in range(count):
            end = i + int(np.searchsorted(reach, 2 * math.pi * (n + 1))) if n < full else j
            end = min(end, j)
            xs, ys = traj.x[begin:end + 1], traj.y[begin:end + 1]
            diameter = 2.0 * fit_circle(xs, ys).radius if len(xs) >= 5 else math.nan
            closure = math.hypot(xs[-1] - xs[0], ys[-1] - ys[0])
            loops.append(Loop(direction, diameter, closure, float(traj.t[begin]), float(traj.t[end])))
            begin = end
    return loops


class Params(TrajectoryParams):
    """Loop settings: the loops expected (in order) and their diameter, for the error quantities."""

    order: list[Direction] = []  # e.g. ["anticlockwise", "clockwise"]; empty: no order expected
    diameter: float | None = None  # m
    reverse_deg: float = 45.0  # turning back this far from the extreme heading starts a new stretch
    min_loop_deg: float = 300.0  # a last, unfinished turn counts as a loop from this many degrees


def _stat(values: list[float], how: str) -> float:
    finite = [v for v in values if math.isfinite(v)]
    return float(getattr(np, how)(finite)) if finite else math.nan


def measure(run: RunData, params: Params) -> Measurement:
    """Find the loops driven before Ctrl+C (if any) and compare them with the expected order and diameter."""
    window = run.until_shutdown(params.source)
    if len(window) < 3 or path_length(window) < 0.05:
        raise MetricError("the robot hardly moved, so there are no loops to measure")
    driving = moving(window, params.rest_speed, params.rest_turn_rate)
    if not np.any(driving):
        raise MetricError("the robot never moved, so there are no loops to measure")
    loops = find_loops(window, params.reverse_deg, params.min_loop_deg)
    directions = [loop.direction for loop in loops]
    expected = list(params.order)
    matched = sum(a == b for a, b in zip(directions, expected))
    longest = max(len(directions), len(expected))
    diameters = [loop.diameter for loop in loops]
    target = params.diameter
    errors = [abs(d - target) for d in diameters] if target is not None else []
    return {
        "n_loops": len(loops),
        "order": ", ".join(directions) or "none",
        "expected_order": ", ".join(expected),
        "order_fraction": matched / longest if longest else 1.0,
        "order_correct": bool(expected) and directions == expected,
        "first_direction": directions[0] if directions else "none",
        "n_anticlockwise": directions.count("anticlockwise"),
        "n_clockwise": directions.count("clockwise"),
        "diameter_min": _stat(diameters, "min"), "diameter_max": _stat(diameters, "max"),
        "diameter_mean": _stat(diameters, "mean"),
        # Loops missing from the expected number count as wholly wrong: one loop can't look like a figure of eight.
        "diameter_worst_error": (max(errors) if len(loops) >= len(expected) else target) if errors else math.nan,
        "closure_worst": _stat([loop.closure for loop in loops], "max"),
        "turned_deg": math.degrees(exact.total(np.abs(np.diff(np.unwrap(window.yaw))))),
        "loops_s": float(loops[-1].end_s - loops[0].start_s) if loops else math.nan,
    }


METRIC = Metric(
    name="loops",
    params=Params,
    quantities=frozenset({
        "n_loops", "order", "expected_order", "order_fraction", "order_correct", "first_direction", "n_anticlockwise",
        "n_clockwise", "diameter_min", "diameter_max", "diameter_mean", "diameter_worst_error", "closure_worst",
        "turned_deg", "loops_s",
    }),
    measure=measure,
)
