"""The turtlesim window's path image: the pen lines the turtles draw, on a 500 x 500 px background.

The colour sensor reads it and the report shows it, so it is kept as pixels, not as a list of lines.
Qt draws the real one with an aliased pen; here a line of width w covers every pixel whose centre lies within w/2
of the segment, extended by w/2 beyond each end (Qt's default square cap). Edge pixels may differ from Qt's.
"""
from __future__ import annotations

import numpy as np

CANVAS_PX = 500
METER_PX = 45.0  # one metre is the turtle image's height
DEFAULT_BACKGROUND = (69, 86, 255)
PATH_EMPTY = (255, 255, 255)  # an unpainted pixel of Jazzy's transparent path image, as its colour sensor reads it

Rgb = tuple[int, int, int]


class CanvasError(Exception):
    """A colour outside 0..255 or a pen width that is not a positive number of pixels."""


def _check_rgb(rgb: Rgb) -> Rgb:
    if any(not 0 <= c <= 255 for c in rgb):
        raise CanvasError(f"colour {rgb} has a channel outside 0..255")
    return (int(rgb[0]), int(rgb[1]), int(rgb[2]))


class Canvas:
    """Pixels of the path image, indexed [row, column] with row 0 at the top (screen y grows downwards).

    ``inked`` marks every pixel a pen line has covered since the canvas was made, whatever the colour; ``clear``
    leaves it alone. It is the pen's whole trail (what coverage counts), where ``pixels`` is what the window shows.
    ``painted`` marks the pixels a pen covered since the last ``clear``: Jazzy keeps them in a transparent path image
    over the background, which its colour sensor reads (white where nothing is painted) and which a new background
    colour shows through at once (``repaint``).
    """

    def __init__(self, background: Rgb = DEFAULT_BACKGROUND) -> None:
        self.background = _check_rgb(background)
        self.pixels = np.empty((CANVAS_PX, CANVAS_PX, 3), dtype=np.uint8)
        self.inked = np.zeros((CANVAS_PX, CANVAS_PX), dtype=bool)
        self.painted = np.zeros((CANVAS_PX, CANVAS_PX), dtype=bool)
        self.clear()

    def clear(self, background: Rgb | None = None) -> None:
        """Fill with the background (a new one if given), as /clear and /reset do."""
        if background is not None:
            self.background = _check_rgb(background)
        self.pixels[:] = self.background
        self.painted[:] = False

    def repaint(self, background: Rgb) -> None:
        """A new background under the pen lines, which stay (Jazzy's window repaints as a parameter changes)."""
        self.background = _check_rgb(background)
        self.pixels[~self.painted] = self.background

    def color_at(self, x_px: float, y_px: float) -> Rgb:
        """The pixel at a screen point, rounded as Qt's ``QPointF::toPoint`` does (half away from zero)."""
        row, column = _pixel(x_px, y_px)
        r, g, b = self.pixels[row, column]
        return (int(r), int(g), int(b))

    def path_color_at(self, x_px: float, y_px: float) -> Rgb:
        """The path image's pixel at a screen point: the pen's colour, or white where no pen painted since the last
        clear (Jazzy fills it with ``qRgba(255, 255, 255, 0)``, whose red, green and blue are 255)."""
        row, column = _pixel(x_px, y_px)
        return self.color_at(x_px, y_px) if self.painted[row, column] else PATH_EMPTY

    def line(self, start_px: tuple[float, float], end_px: tuple[float, float], rgb: Rgb, width: int) -> None:
        """Draw a square-capped segment of ``width`` px between two screen points."""
        if width <= 0:
            raise CanvasError(f"pen width {width} px is not positive")
        half = width / 2.0
        (x0, y0), (x1, y1) = start_px, end_px
        lo_x = max(int(np.floor(min(x0, x1) - half)), 0)
        hi_x = min(int(np.ceil(max(x0, x1) + half)), CANVAS_PX - 1)
        lo_y = max(int(np.floor(min(y0, y1) - half)), 0)
        hi_y = min(int(np.ceil(max(y0, y1) + half)), CANVAS_PX - 1)
        if lo_x > hi_x or lo_y > hi_y:
            return
        columns = np.arange(lo_x, hi_x + 1, dtype=np.float64)[None, :]
        rows = np.arange(lo_y, hi_y + 1, dtype=np.float64)[:, None]
        dx, dy = x1 - x0, y1 - y0
        length = float(np.hypot(dx, dy))
        if length == 0.0:
            covered = (np.abs(columns - x0) <= half) & (np.abs(rows - y0) <= half)
        else:
            ux, uy = dx / length, dy / length
            along = (columns - x0) * ux + (rows - y0) * uy
            across = (columns - x0) * -uy + (rows - y0) * ux
            covered = (along >= -half) & (along <= length + half) & (np.abs(across) <= half)
        self.pixels[lo_y:hi_y + 1, lo_x:hi_x + 1][covered] = _check_rgb(rgb)
        self.inked[lo_y:hi_y + 1, lo_x:hi_x + 1] |= covered
        self.painted[lo_y:hi_y + 1, lo_x:hi_x + 1] |= covered


def _pixel(x_px: float, y_px: float) -> tuple[int, int]:
    """(row, column) of a screen point, rounded as Qt's ``QPointF::toPoint`` does, kept on the image."""
    column = min(max(int(np.floor(x_px + 0.5)), 0), CANVAS_PX - 1)
    row = min(max(int(np.floor(y_px + 0.5)), 0), CANVAS_PX - 1)
    return row, column
