"""Canvas coverage: the share of the turtlesim window the pens drew on, redrawn from the recording (``pen.redraw``).

What counts is every pixel a pen line covered during the run, by any turtle, in any colour: a lifted pen draws
nothing, and a later /clear or /reset does not take back what was drawn (the turtle did go there with its pen down).
``coverage`` counts square cells of ``cell_px`` pixels the pens touched (``cell_px = 1``: single pixels, which a
3 px pen covers only by passing every few pixels); ``pixel_coverage`` is always the share of pixels drawn on.
With ``sweep_px``, a cleaning task's measure, what the turtles swept counts too: a band that wide along each turtle's
driven path (not its teleports), pen up or down, as a vacuum cleans what its body passes over. ``outline_coverage``
is the share of the area inside the outline of the turtles' paths (their convex hull) that was covered: a spiral
leaves the canvas's corners, which it never meant to clean, but no gaps inside; rows too far apart leave stripes.
"""
from __future__ import annotations

import math
from typing import Literal

import numpy as np
from pydantic import Field

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.motion import path_length
from grader.metrics.pen import redraw
from grader.metrics.run import TURTLE_POSE_TOPIC, RunData, Trajectory
from sim.turtle_canvas import CANVAS_PX, METER_PX, Canvas
from sim.turtlesim import CANVAS_M


class Params(TrajectoryParams):
    """Cell size of the coverage grid."""

    cell_px: int = Field(1, ge=1, le=CANVAS_PX)
    sweep_px: int = Field(0, ge=0, le=CANVAS_PX)  # width a turtle cleans as it drives (45: its 1 m body); 0: pens only


def measure(run: RunData, params: Params) -> Measurement:
    """Redraw the pen lines and count the pixels and cells they covered; ``path_length`` is turtle1's."""
    traj = run.trajectory(params.source)
    if len(traj) < 2:
        raise MetricError("the recording holds no pose of the turtle")
    paint = redraw(run, params.source).canvas.inked
    if params.sweep_px:
        paint = paint | swept(run, params.source, params.sweep_px)
    n = -(-CANVAS_PX // params.cell_px)  # cells per side; the last row and column may be narrower
    padded = np.pad(paint, (0, n * params.cell_px - CANVAS_PX))
    touched = padded.reshape(n, params.cell_px, n, params.cell_px).any(axis=(1, 3))
    outline = _inside_hull(_pixel_points(run, params.source))
    return {
        "outline_coverage": float(paint[outline].mean()) if outline.any() else math.nan,
        "coverage": float(touched.mean()),
        "pixel_coverage": float(paint.mean()),
        "cells": n * n,
        "path_length": path_length(traj),
    }


# Calls after which a turtle may be somewhere it did not drive to: its own teleports, and whatever reset or respawns it.
_JUMPS = ("/teleport_absolute", "/teleport_relative")
_RESPAWNS = ("/reset", "/spawn", "/kill")
CHORD_PX = 4.0


def _paths(run: RunData, source: Literal["ground_truth", "odometry"]) -> dict[str, Trajectory]:
    """Every turtle's recorded poses by topic, turtle1's from ``source``."""
    paths = dict(run.poses)
    if len(first := run.trajectory(source)):
        paths[TURTLE_POSE_TOPIC] = first
    return paths


def _pixel_points(run: RunData, source: Literal["ground_truth", "odometry"]) -> np.ndarray:
    """Every recorded position of every turtle as (x, y) canvas pixels, y down."""
    paths = _paths(run, source).values()
    return np.array([(x * METER_PX, (CANVAS_M - y) * METER_PX)
                     for path in paths for x, y in zip(path.x.tolist(), path.y.tolist())]).reshape(-1, 2)


def _inside_hull(points: np.ndarray) -> np.ndarray:
    """The canvas pixels inside the convex hull of ``points`` (Andrew's monotone chain over whole pixels), filled row
    by row between the hull's edges; none when it has no area."""
    pts = [tuple(p) for p in np.unique(np.round(points), axis=0).tolist()]

    def half(seq: list[tuple[float, float]]) -> list[tuple[float, float]]:
        chain: list[tuple[float, float]] = []
        for p in seq:
            while len(chain) >= 2 and _cross(chain[-2], chain[-1], p) <= 0:
                chain.pop()
            chain.append(p)
        return chain[:-1]

    hull = half(pts) + half(pts[::-1])
    inside = np.zeros((CANVAS_PX, CANVAS_PX), dtype=bool)
    if len(hull) < 3:
        return inside
    rows = np.arange(CANVAS_PX, dtype=float)
    lo, hi = np.full(CANVAS_PX, np.inf), np.full(CANVAS_PX, -np.inf)
    for (ax, ay), (bx, by) in zip(hull, hull[1:] + hull[:1]):
        if ay == by:
            span = rows == ay
            lo[span], hi[span] = np.minimum(lo[span], min(ax, bx)), np.maximum(hi[span], max(ax, bx))
            continue
        span = (rows >= min(ay, by)) & (rows <= max(ay, by))
        xs = ax + (rows - ay) * (bx - ax) / (by - ay)
        lo[span], hi[span] = np.minimum(lo[span], xs[span]), np.maximum(hi[span], xs[span])
    cols = np.arange(CANVAS_PX, dtype=float)[None, :]
    return (cols >= lo[:, None]) & (cols <= hi[:, None])


def _cross(o: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> float:
    """Twice the signed area of o, a, b: positive when b lies left of o -> a."""
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def swept(run: RunData, source: Literal["ground_truth", "odometry"], width_px: int) -> np.ndarray:
    """The pixels within ``width_px / 2`` of every turtle's path between consecutive poses, leaving out the steps
    over which a call moved it (a teleport, a reset, a respawn under the same name)."""
    canvas = Canvas()
    for topic, path in _paths(run, source).items():
        namespace = topic.rpartition("/")[0]
        jumps = np.array(sorted(c.t for c in run.service_calls if c.response is not None and (
            c.service in _RESPAWNS or (c.service.startswith(namespace + "/") and c.service.endswith(_JUMPS)))))
        xs, ys = (path.x * METER_PX).tolist(), ((CANVAS_M - path.y) * METER_PX).tolist()
        # A step from pose i to i + 1 is driven unless a jump was served at t_i <= t < t_i+1.
        moved_by_call = np.searchsorted(jumps, path.t[:-1], "left") < np.searchsorted(jumps, path.t[1:], "left")
        drawn = 0  # the band is drawn in chords of CHORD_PX (a chord's sagitta on a turn is a fraction of a pixel)
        for i in range(1, len(xs)):
            if moved_by_call[i - 1]:
                canvas.line((xs[drawn], ys[drawn]), (xs[i - 1], ys[i - 1]), (0, 0, 0), width_px)
                drawn = i
            elif math.hypot(xs[i] - xs[drawn], ys[i] - ys[drawn]) >= CHORD_PX or i == len(xs) - 1:
                canvas.line((xs[drawn], ys[drawn]), (xs[i], ys[i]), (0, 0, 0), width_px)
                drawn = i
    return canvas.inked


METRIC = Metric(
    name="canvas_coverage",
    params=Params,
    quantities=frozenset({"outline_coverage", "coverage", "pixel_coverage", "cells", "path_length"}),
    measure=measure,
)
