"""The turtlesim window at the end of a run, redrawn from the recording: the pen's picture with the turtle on it."""
from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Polygon

from grader.metrics.pen import redraw, screen_px
from grader.metrics.run import Trajectory
from sim.turtle_canvas import CANVAS_PX

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


def canvas_figure(path: Trajectory) -> Figure:
    """The 500 × 500 px picture the window would show after ``path``, with the turtle where the run ended."""
    figure = Figure(figsize=(5.0, 5.2))
    axes = figure.add_subplot()
    axes.imshow(redraw(path).pixels, interpolation="nearest", extent=(-0.5, CANVAS_PX - 0.5, CANVAS_PX - 0.5, -0.5))
    columns, rows = screen_px(path.x[-1:], path.y[-1:])
    axes.add_patch(Polygon(turtle_outline(float(columns[0]), float(rows[0]), float(path.yaw[-1])), closed=True,
                           facecolor=TURTLE_COLOUR, edgecolor="black", lw=0.8))
    axes.set_xlim(-0.5, CANVAS_PX - 0.5)
    axes.set_ylim(CANVAS_PX - 0.5, -0.5)
    axes.set_xticks([])
    axes.set_yticks([])
    axes.set_title("the turtlesim window at the end of the run", fontsize=9)
    figure.tight_layout()
    return figure
