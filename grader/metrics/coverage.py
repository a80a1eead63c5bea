"""Canvas coverage: the share of the turtlesim window the pens drew on, redrawn from the recording (``pen.redraw``).

What counts is every pixel a pen line covered during the run, by any turtle, in any colour: a lifted pen draws
nothing, and a later /clear or /reset does not take back what was drawn (the turtle did go there with its pen down).
``coverage`` counts square cells of ``cell_px`` pixels the pens touched (``cell_px = 1``: single pixels, which a
3 px pen covers only by passing every few pixels); ``pixel_coverage`` is always the share of pixels drawn on.
"""
from __future__ import annotations

import numpy as np
from pydantic import Field

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.motion import path_length
from grader.metrics.pen import redraw
from grader.metrics.run import RunData
from sim.turtle_canvas import CANVAS_PX


class Params(TrajectoryParams):
    """Cell size of the coverage grid."""

    cell_px: int = Field(1, ge=1, le=CANVAS_PX)


def measure(run: RunData, params: Params) -> Measurement:
    """Redraw the pen lines and count the pixels and cells they covered; ``path_length`` is turtle1's."""
    traj = run.trajectory(params.source)
    if len(traj) < 2:
        raise MetricError("the recording holds no pose of the turtle")
    paint = redraw(run, params.source).canvas.inked
    n = -(-CANVAS_PX // params.cell_px)  # cells per side; the last row and column may be narrower
    padded = np.pad(paint, (0, n * params.cell_px - CANVAS_PX))
    touched = padded.reshape(n, params.cell_px, n, params.cell_px).any(axis=(1, 3))
    return {
        "coverage": float(touched.mean()),
        "pixel_coverage": float(paint.mean()),
        "cells": n * n,
        "path_length": path_length(traj),
    }


METRIC = Metric(
    name="canvas_coverage",
    params=Params,
    quantities=frozenset({"coverage", "pixel_coverage", "cells", "path_length"}),
    measure=measure,
)
