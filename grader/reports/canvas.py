"""The turtlesim window at the end of a run, redrawn from the recording: the pens' picture with the turtles on it."""
from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Polygon

from grader.metrics.pen import redraw, window_run
from grader.metrics.run import RunData
from sim.turtle_canvas import CANVAS_PX, METER_PX
from sim.turtlesim import NODE_NAME

TURTLE_PX = 14.0  # the marker's length: about the turtle image's size in the window
TURTLE_COLOUR = "#3c8c3c"


def turtle_outline(x_px: float, y_px: float, theta: float) -> np.ndarray:
    """An arrowhead at the turtle's screen position pointing along its heading (screen y grows downwards)."""
    ahead = np.array([np.cos(theta), -np.sin(theta)])
    side = np.array([ahead[1], -ahead[0]])
    centre = np.array([x_px, y_px])
    nose = centre + ahead * TURTLE_PX * 0.6
    tail = centre - ahead * TURTLE_PX * 0.4
    return np.array([nose, tail + side * TURTLE_PX * 0.4, tail + ahead * TURTLE_PX * 0.1, tail - side * TURTLE_PX * 0.4])


def canvas_figure(run: RunData, window: str = NODE_NAME) -> Figure:
    """The 500 × 500 px picture the window would show at the end of ``run``, with each turtle alive then; ``window``:
    a further turtlesim window's node (``/turtlesim2/sim``), else the first window's."""
    drawing = redraw(run) if window == NODE_NAME else redraw(window_run(run, window), node=window)
    figure = Figure(figsize=(5.0, 5.2))
    axes = figure.add_subplot()
    axes.imshow(drawing.canvas.pixels, interpolation="nearest",
                extent=(-0.5, CANVAS_PX - 0.5, CANVAS_PX - 0.5, -0.5))
    for turtle in drawing.turtles:
        outline = turtle_outline(turtle.x * METER_PX, turtle.y_screen * METER_PX, turtle.theta)
        axes.add_patch(Polygon(outline, closed=True, facecolor=TURTLE_COLOUR, edgecolor="black", lw=0.8))
    axes.set_xlim(-0.5, CANVAS_PX - 0.5)
    axes.set_ylim(CANVAS_PX - 0.5, -0.5)
    axes.set_xticks([])
    axes.set_yticks([])
    title = "the turtlesim window" if window == NODE_NAME else f"the turtlesim window of {window}"
    axes.set_title(f"{title} at the end of the run", fontsize=9)
    figure.tight_layout()
    return figure
