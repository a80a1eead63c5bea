"""Plot legends drawn once per report and pasted: a legend cost more to lay out and draw than the rest of a plot.

The legends of a report's plots repeat (the same entries, scenario after scenario), so each distinct legend is
drawn by matplotlib once, on a transparent figure, and kept as pixels. A `PastedLegend` artist puts those pixels
where matplotlib's loc="best" would put the legend: the first of its ten places, in its order, that covers the
fewest line vertices and crosses the fewest lines.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.transforms import Bbox, IdentityTransform

LEGEND_ZORDER = 5  # matplotlib's: above the data
BORDER_AXES_PAD = 0.5  # matplotlib's legend.borderaxespad, in font sizes
SCRATCH_SIZE_IN = (6.0, 3.0)  # room for the longest legends (7 entries, a 45-character label)
SCRATCH_MARGIN_PX = 4  # the legend is drawn this far from the scratch figure's corner, so no edge is clipped
# The anchors of matplotlib's codes 1-10 ("upper right" ... "center"), in the order "best" tries them.
_ANCHORS = ("NE", "NW", "SW", "SE", "E", "W", "E", "S", "N", "C")


@dataclass(frozen=True)
class LegendPicture:
    """A legend's pixels (RGBA, bottom row first, as `draw_image` takes them) and its box within them: the box
    matplotlib places (the frame's antialiased edge lies just outside it)."""

    pixels: np.ndarray
    box_left: int
    box_bottom: int
    box_width: float
    box_height: float


class Legends:
    """The legend pictures of one report, by their entries and look."""

    def __init__(self, dpi: int) -> None:
        self.dpi = dpi
        self._pictures: dict[tuple[Any, ...], LegendPicture | None] = {}

    def add(self, axes: Axes, fontsize: float) -> None:
        """Give `axes` the legend of its labelled lines at the best place: matplotlib's own legend when a handle
        is not a line (this cache keys on lines' looks) or the legend does not fit the scratch figure."""
        handles, labels = axes.get_legend_handles_labels()
        if not handles:
            return
        key = (fontsize, tuple(labels), tuple(_look(handle) for handle in handles))
        if key not in self._pictures:
            self._pictures[key] = (_draw_alone(handles, labels, fontsize, self.dpi)
                                   if all(isinstance(handle, Line2D) for handle in handles) else None)
        picture = self._pictures[key]
        if picture is None:  # a legend this cache cannot take: matplotlib's own
            axes.legend(loc="best", fontsize=fontsize)
        else:
            axes.add_artist(PastedLegend(picture, fontsize * self.dpi / 72 * BORDER_AXES_PAD))


class PastedLegend(Artist):
    """Legend pixels pasted at draw time, when the axes' limits and so the lines' places are final."""

    def __init__(self, picture: LegendPicture, pad_px: float) -> None:
        super().__init__()
        self.picture, self.pad_px = picture, pad_px
        self.set_zorder(LEGEND_ZORDER)

    def draw(self, renderer: Any) -> None:
        if not self.get_visible() or self.axes is None:
            return
        picture = self.picture
        x, y = best_place(self.axes, picture.box_width, picture.box_height, self.pad_px)
        gc = renderer.new_gc()
        renderer.draw_image(gc, round(x) - picture.box_left, round(y) - picture.box_bottom, picture.pixels)
        gc.restore()
        self.stale = False


def best_place(axes: Axes, width: float, height: float, pad_px: float) -> tuple[float, float]:
    """Bottom-left corner (display pixels) of a width × height box where loc="best" would put a legend."""
    lines = [line.get_transform().transform_path(line.get_path()) for line in axes.lines]
    container = axes.bbox.padded(-pad_px, -pad_px)
    box = Bbox.from_bounds(0, 0, width, height)
    candidates = []
    for index, anchor in enumerate(_ANCHORS):
        left, bottom = box.anchored(anchor, container=container).p0
        placed = Bbox.from_bounds(left, bottom, width, height)
        badness = sum(placed.count_contains(path.vertices) + path.intersects_bbox(placed, filled=False)
                      for path in lines)
        candidates.append((badness, index, (left, bottom)))
        if badness == 0:
            break
    return min(candidates)[2]


def _look(handle: Any) -> tuple[Any, ...]:
    """What a line's legend handle shows (other handles: their type and label, and they are not cached)."""
    if not isinstance(handle, Line2D):
        return (type(handle).__name__, handle.get_label())
    line = handle
    return (line.get_color(), line.get_linestyle(), line.get_linewidth(), line.get_drawstyle(), line.get_alpha(),
            str(line.get_marker()), line.get_markersize(), str(line.get_markerfacecolor()),
            str(line.get_markeredgecolor()), line.get_markeredgewidth())


def _draw_alone(handles: list[Any], labels: list[str], fontsize: float, dpi: int) -> LegendPicture | None:
    """The legend drawn on a transparent figure with its box's corner on a pixel corner, cropped to its pixels;
    None when it does not fit that figure."""
    figure = Figure(figsize=SCRATCH_SIZE_IN, dpi=dpi, facecolor="none")
    canvas = FigureCanvasAgg(figure)
    legend = figure.legend(handles, labels, fontsize=fontsize, loc="lower left", borderaxespad=0,
                           bbox_to_anchor=(SCRATCH_MARGIN_PX, SCRATCH_MARGIN_PX), bbox_transform=IdentityTransform())
    canvas.draw()
    box = legend.get_window_extent(canvas.get_renderer())
    rgba = np.asarray(canvas.buffer_rgba())[::-1]  # bottom row first, like display coordinates
    rows, columns = np.nonzero(rgba[:, :, 3])
    if not len(rows) or rows.max() >= rgba.shape[0] - 1 or columns.max() >= rgba.shape[1] - 1:  # cut at the edge
        return None
    bottom, left = rows.min(), columns.min()
    pixels = rgba[bottom:rows.max() + 1, left:columns.max() + 1]
    return LegendPicture(np.ascontiguousarray(pixels), SCRATCH_MARGIN_PX - int(left), SCRATCH_MARGIN_PX - int(bottom),
                         box.width, box.height)
