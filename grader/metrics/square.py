"""Square analysis: split a path into straight sides and corners; side lengths, corner angles, closure, loops, pauses."""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader import exact
from grader.metrics.motion import moving, path_length, rest_since, speeds
from grader.metrics.run import RunData, Trajectory


@dataclass(frozen=True)
class SquareAnalysis:
    """The segmented path: vertex points (start first), sides (m), corners (signed deg), closures (m), pauses (s)."""

    points: list[tuple[float, float]]
    times: list[float]  # when the robot was at each vertex (s, the recording's clock)
    sides: list[float]
    corners_deg: list[float]
    closures: list[float]
    pauses: list[float]
    heading_turns: float  # accumulated heading change / 360 deg
    rest_s: float | None  # how long the robot has stood still at the end; None if moving


def _runs(mask: np.ndarray) -> list[tuple[int, int]]:
    """Half-open index ranges [i, j) where ``mask`` is True."""
    edges = np.diff(np.concatenate(([0], mask.astype(np.int8), [0])))
    return list(zip(np.flatnonzero(edges == 1).tolist(), np.flatnonzero(edges == -1).tolist()))


def _turns(traj: Trajectory, w: np.ndarray, turn_rate: float, merge_gap_s: float) -> list[tuple[int, int, float]]:
    """Turning runs as (first interval, end interval, heading change rad); same-direction runs split by a blip merge."""
    merged: list[list[int]] = []
    for i, j in _runs(np.abs(w) > turn_rate):
        same_way = merged and np.sign(w[i]) == np.sign(w[merged[-1][0]])
        if same_way and traj.t[i] - traj.t[merged[-1][1]] < merge_gap_s:
            merged[-1][1] = j
        else:
            merged.append([i, j])
    # A corner is the heading change between the middles of the straight stretches either side of the turn,
    # so the slow final approach of a controller that eases into its target angle (below turn_rate) still counts.
    heading = np.unwrap(traj.yaw)
    bounds = [0, *(k for run in merged for k in run), len(traj) - 1]
    middles = [(a + b) // 2 for a, b in zip(bounds[::2], bounds[1::2])]
    return [(i, j, float(heading[middles[n + 1]] - heading[middles[n]])) for n, (i, j) in enumerate(merged)]


def _middle(traj: Trajectory, turn: tuple[int, int, float]) -> tuple[float, float]:
    """The position in the middle of a turn: the corner, also for rounded corners."""
    k = (turn[0] + turn[1]) // 2
    return float(traj.x[k]), float(traj.y[k])


def analyse_square(
    traj: Trajectory,
    rest_speed: float = 0.01,
    rest_turn_rate: float = 0.05,
    turn_rate: float = 0.1,
    min_corner_deg: float = 30.0,
    merge_gap_s: float = 0.5,
    min_pause_s: float = 0.3,
    interrupted: bool = False,
    min_side: float = 0.05,
) -> SquareAnalysis:
    """Segment ``traj`` at its turns: a vertex is the middle of each turn, sides join consecutive vertices.

    ``interrupted``: the path was cut short by Ctrl+C, so a turn still under way at its end is not a corner.
    Turns within ``min_side`` (m) of the start come before the first side and are left out.
    """
    if len(traj) < 3:
        raise MetricError("too few positions to analyse the path")
    _, w = speeds(traj)
    turns = [t for t in _turns(traj, w, turn_rate, merge_gap_s) if abs(t[2]) >= math.radians(min_corner_deg)]
    if interrupted and turns and turns[-1][1] == len(w):
        turns.pop()
    start = (float(traj.x[0]), float(traj.y[0]))
    # Turning on the spot before the first side only sets the starting heading: it is not a corner.
    while turns and math.dist(start, _middle(traj, turns[0])) < min_side:
        turns.pop(0)
    points = [start, *(_middle(traj, turn) for turn in turns)]
    times = [float(traj.t[0]), *(float(traj.t[(turn[0] + turn[1]) // 2]) for turn in turns)]
    rest_from = rest_since(traj, rest_speed, rest_turn_rate)
    end_point = (float(traj.x[-1]), float(traj.y[-1]))
    sides = [math.dist(a, b) for a, b in zip(points, points[1:])]
    # The stretch after the last corner is a side only if the robot finished it (it is at rest at the end).
    last_stretch = math.dist(points[-1], end_point)
    typical = float(np.median(sides)) if sides else last_stretch
    if rest_from is not None and last_stretch > max(0.3 * typical, 0.05):
        points.append(end_point)
        times.append(rest_from)
        sides.append(last_stretch)
    closures = [math.dist(points[0], points[k]) for k in range(4, len(points), 4)]
    still = ~moving(traj, rest_speed, rest_turn_rate)
    pauses = [
        float(traj.t[j] - traj.t[i]) for i, j in _runs(still)
        if j < len(still) and i > 0 and traj.t[j] - traj.t[i] >= min_pause_s  # not the rest before or after
    ]
    return SquareAnalysis(
        points=points, times=times, sides=sides, corners_deg=[math.degrees(t[2]) for t in turns], closures=closures,
        pauses=pauses, heading_turns=abs(exact.total(w * np.diff(traj.t))) / (2.0 * math.pi),
        rest_s=None if rest_from is None else float(traj.t[-1] - rest_from),
    )


class Params(TrajectoryParams):
    """Square analysis settings; by default the odometry path, which is what an odometry-based node controls."""

    source: Literal["ground_truth", "odometry"] = "odometry"
    side: float | None = None  # the side length asked for (m); None compares sides with their median (timed squares)
    corner_deg: float = 90.0
    turn_rate: float = 0.1  # rad/s above which the robot is turning
    min_corner_deg: float = 30.0  # smaller heading changes are steering corrections, not corners
    min_rest_s: float = 3.0  # standing still this long at the end counts as having stopped
    side_tolerance_rel: float = 0.05  # a side within this share of ``side`` counts as right (side_share)
    corner_tolerance_deg: float = 5.0  # a corner within this of ``corner_deg`` counts as right (corner_share)
    min_sides: int = 4  # a square has four sides and three corners between them: shares count at least these


def _stat(values: np.ndarray, how: str) -> float:
    """min/mean/max of ``values``, NaN when there are none (so the criterion earns nothing)."""
    return float(getattr(np, how)(values)) if len(values) else math.nan


def measure(run: RunData, params: Params) -> Measurement:
    """Analyse the path up to Ctrl+C (if any) and summarise the sides, corners, loops and the final stop."""
    shutdown = run.shutdown_time()
    window = run.until_shutdown(params.source)
    if path_length(window) < 0.05:
        raise MetricError(f"the robot drove only {path_length(window):.2f} m, so there is no square to measure")
    sq = analyse_square(
        window, params.rest_speed, params.rest_turn_rate, params.turn_rate, params.min_corner_deg,
        interrupted=shutdown is not None,
    )
    sides, corners = np.array(sq.sides), np.abs(np.array(sq.corners_deg))
    # A timed square has no side length: the median side is what the node meant, whatever one odd side measured.
    ref_side = params.side if params.side is not None else (float(np.median(sides)) if len(sides) else math.nan)
    # A side never driven is wholly wrong, so fewer than four sides can never look like a good square.
    side_err = float(np.max(np.abs(sides - ref_side))) if len(sides) >= params.min_sides else ref_side
    corner_err = float(np.max(np.abs(corners - params.corner_deg))) if len(corners) else math.nan
    # Credit by share: each side (corner) within tolerance earns its part, and a square driven only in part counts
    # the sides (corners) it never drove as wrong, so one odd side costs its share, not the criterion.
    sides_ok = int(np.sum(np.abs(sides - ref_side) <= params.side_tolerance_rel * ref_side))
    corners_ok = int(np.sum(np.abs(corners - params.corner_deg) <= params.corner_tolerance_deg))
    others = float(np.median(sides[1:])) if len(sides) > 1 else math.nan
    # At rest long enough by itself, before any Ctrl+C (the window ends there): it stopped by itself.
    stopped = sq.rest_s is not None and sq.rest_s >= params.min_rest_s
    return {
        "n_sides": len(sides), "n_corners": len(corners),
        "n_sides_ok": sides_ok, "n_sides_off": len(sides) - sides_ok,
        "side_share": sides_ok / max(len(sides), params.min_sides),
        "n_corners_ok": corners_ok, "n_corners_off": len(corners) - corners_ok,
        "corner_share": corners_ok / max(len(corners), params.min_sides - 1),
        "side_mean": _stat(sides, "mean"), "side_min": _stat(sides, "min"),
        "side_max": _stat(sides, "max"), "side_worst_error": side_err,
        "corner_mean_deg": _stat(corners, "mean"), "corner_min_deg": _stat(corners, "min"),
        "corner_max_deg": _stat(corners, "max"), "corner_worst_error_deg": corner_err,
        "closure_worst": _stat(np.array(sq.closures), "max"),
        "closure_first": sq.closures[0] if sq.closures else math.nan,
        "loops": len(sides) / 4.0, "heading_loops": sq.heading_turns,
        "loops_at_rest": len(sides) / 4.0 if stopped else math.nan,
        "final_rest_s": sq.rest_s, "moving_at_end": sq.rest_s is None, "pauses": len(sq.pauses),
        "side_error_rel": side_err / ref_side, "corner_error_rel": corner_err / params.corner_deg,
        "shape_error": max(side_err / ref_side, corner_err / params.corner_deg) if len(sides) >= 4 else math.nan,
        "side_first": float(sides[0]) if len(sides) else math.nan,
        "side_first_ratio": float(sides[0]) / others if len(sides) > 1 and others > 0 else math.nan,
        # The report's moment: where the square ended, its last vertex (the report shows the whole square there).
        "decided_at_s": sq.times[-1] - run.start_time,
    }


METRIC = Metric(
    name="square",
    params=Params,
    quantities=frozenset({
        "n_sides", "n_corners", "n_sides_ok", "n_sides_off", "side_share", "n_corners_ok", "n_corners_off",
        "corner_share", "side_mean", "side_min", "side_max", "side_worst_error", "corner_mean_deg",
        "corner_min_deg", "corner_max_deg", "corner_worst_error_deg", "closure_worst", "closure_first", "loops",
        "heading_loops", "loops_at_rest", "final_rest_s", "moving_at_end", "pauses", "shape_error", "side_error_rel",
        "corner_error_rel", "side_first", "side_first_ratio", "decided_at_s",
    }),
    measure=measure,
)
