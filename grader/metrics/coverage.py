"""Canvas coverage: the share of the turtlesim window the pens drew on, redrawn from the recording (``pen.redraw``).

What counts is every pixel a pen line covered during the run, by any turtle, in any colour: a lifted pen draws
nothing, and a later /clear or /reset does not take back what was drawn (the turtle did go there with its pen down).
``coverage`` counts square cells of ``cell_px`` pixels the pens touched (``cell_px = 1``: single pixels, which a
3 px pen covers only by passing every few pixels); ``pixel_coverage`` is always the share of pixels drawn on.
With ``sweep_px``, a cleaning task's measure, what the turtles swept counts too: a band that wide along each turtle's
driven path (not its teleports), pen up or down, as a vacuum cleans what its body passes over.
"""
from __future__ import annotations

from typing import Literal

import numpy as np
from pydantic import Field

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.motion import path_length
from grader.metrics.pen import redraw
from grader.metrics.run import TURTLE_POSE_TOPIC, RunData
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
    return {
        "coverage": float(touched.mean()),
        "pixel_coverage": float(paint.mean()),
        "cells": n * n,
        "path_length": path_length(traj),
    }


# Calls after which a turtle may be somewhere it did not drive to: its own teleports, and whatever reset or respawns it.
_JUMPS = ("/teleport_absolute", "/teleport_relative")
_RESPAWNS = ("/reset", "/spawn", "/kill")


def swept(run: RunData, source: Literal["ground_truth", "odometry"], width_px: int) -> np.ndarray:
    """The pixels within ``width_px / 2`` of every turtle's path between consecutive poses, leaving out the steps
    over which a call moved it (a teleport, a reset, a respawn under the same name)."""
    paths = dict(run.poses)
    if len(first := run.trajectory(source)):
        paths[TURTLE_POSE_TOPIC] = first
    canvas = Canvas()
    for topic, path in paths.items():
        namespace = topic.rpartition("/")[0]
        jumps = np.array(sorted(c.t for c in run.service_calls if c.response is not None and (
            c.service in _RESPAWNS or (c.service.startswith(namespace + "/") and c.service.endswith(_JUMPS)))))
        xs, ys = path.x * METER_PX, (CANVAS_M - path.y) * METER_PX
        # A step from pose i to i + 1 is driven unless a jump was served at t_i <= t < t_i+1.
        moved_by_call = np.searchsorted(jumps, path.t[:-1], "left") < np.searchsorted(jumps, path.t[1:], "left")
        for i in np.flatnonzero(~moved_by_call):
            canvas.line((xs[i], ys[i]), (xs[i + 1], ys[i + 1]), (0, 0, 0), width_px)
    return canvas.inked


METRIC = Metric(
    name="canvas_coverage",
    params=Params,
    quantities=frozenset({"coverage", "pixel_coverage", "cells", "path_length"}),
    measure=measure,
)
