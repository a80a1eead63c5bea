"""The pen redrawn from poses and served calls equals the canvas the turtlesim world drew, pixel for pixel.

The world is driven directly (commands, service calls at chosen times, some exactly on a 16 ms update), and its
published poses and the calls it answered become the RunData a recording would give."""
from __future__ import annotations

import numpy as np
import pytest

from grader.metrics import coverage
from grader.metrics.pen import redraw
from grader.metrics.run import RunData, ServiceCall, Trajectory
from sim import Scenario, TurtlesimWorld
from sim.samples import TurtlePoseSample
from sim.turtle_canvas import DEFAULT_BACKGROUND
from sim.turtlesim import DEFAULT_PEN

MS = 1_000_000


class Driven:
    """A turtlesim world and what a recording of it would hold: every pose, and every call with its answer."""

    def __init__(self) -> None:
        self.world = TurtlesimWorld(Scenario(robot="turtlesim", duration=30.0))
        self.poses: dict[str, list[tuple[float, float, float, float]]] = {}
        self.calls: list[ServiceCall] = []

    def until(self, t_ms: int) -> None:
        """Run to ``t_ms`` after the start (2 s, itself a multiple of the 16 ms update)."""
        for sample in self.world.advance_to(self.world.scenario.start_ns + t_ms * MS):
            if isinstance(sample, TurtlePoseSample):
                self.poses.setdefault(sample.topic, []).append((sample.t_ns / 1e9, sample.x, sample.y, sample.theta))

    def call(self, service: str, **request: object) -> None:
        result = self.world.call(service, request)
        answer = result.response if result.ok else None
        self.calls.append(ServiceCall(self.world.time_ns / 1e9, service, request, answer))

    def drive(self, turtle: str, linear: float, angular: float) -> None:
        assert self.world.command(f"/{turtle}/cmd_vel", (linear, 0.0, 0.0), (0.0, 0.0, angular))

    def run_data(self, with_calls: bool = True) -> RunData:
        paths = {topic: Trajectory.of(*zip(*rows)) for topic, rows in self.poses.items()}
        return RunData(odometry=paths["/turtle1/pose"], poses=paths,
                       service_calls=tuple(self.calls) if with_calls else ())


def pen(r: int, g: int, b: int, width: int = 3, off: int = 0) -> dict[str, int]:
    return {"r": r, "g": g, "b": b, "width": width, "off": off}


@pytest.fixture(scope="module")
def driven() -> Driven:
    d = Driven()
    d.until(100)
    d.drive("turtle1", 1.0, 0.8)
    d.until(900)
    d.call("/reset")
    d.drive("turtle1", 1.2, -0.3)
    d.until(1600)  # a multiple of 16 ms: the calls come after this update
    d.call("/turtle1/set_pen", **pen(250, 10, 10, width=6))
    d.drive("turtle1", 1.0, 0.9)
    d.until(2500)
    d.call("/clear")
    d.call("/turtle1/set_pen", **pen(0, 0, 0, off=1))
    d.call("/turtle1/teleport_absolute", x=2.0, y=3.0, theta=0.4)  # pen up: nothing drawn
    d.call("/turtle1/set_pen", **pen(40, 220, 40, width=2))  # down again before the next update
    d.call("/turtle1/teleport_relative", linear=1.5, angular=1.0)  # drawn in green at the next update
    d.until(2530)
    d.call("/spawn", x=7.0, y=8.0, theta=-2.0, name="")
    d.call("/turtle2/set_pen", **pen(10, 10, 250, width=0))  # 1 px
    d.call("/spawn", x=1.0, y=1.0, theta=0.0, name="turtle2")  # taken: fails, changes nothing
    d.drive("turtle1", 1.1, 0.2)
    d.drive("turtle2", 1.4, 0.7)
    d.until(4000)
    d.call("/turtle2/teleport_absolute", x=9.0, y=9.0, theta=0.0)  # killed before its next update: never drawn
    d.call("/kill", name="turtle2")
    d.drive("turtle1", 0.6, -0.5)
    d.until(5000)
    return d


def test_the_redraw_is_the_worlds_canvas_pixel_for_pixel(driven: Driven) -> None:
    drawing = redraw(driven.run_data())
    assert np.array_equal(drawing.canvas.pixels, driven.world.canvas.pixels)
    assert np.array_equal(drawing.canvas.inked, driven.world.canvas.inked)
    assert [t.name for t in drawing.turtles] == ["turtle1"]
    colours = {tuple(c) for c in drawing.canvas.pixels.reshape(-1, 3)}
    assert {(40, 220, 40), (10, 10, 250), DEFAULT_BACKGROUND} <= colours
    assert not {DEFAULT_PEN, (250, 10, 10)} & colours  # the reset and the clear took them off


def test_without_the_calls_the_redraw_is_not_the_worlds(driven: Driven) -> None:
    assert not np.array_equal(redraw(driven.run_data(with_calls=False)).canvas.pixels, driven.world.canvas.pixels)


def test_coverage_counts_every_pixel_a_pen_drew_even_if_cleared_later(driven: Driven) -> None:
    measured = coverage.measure(driven.run_data(), coverage.Params())
    shown = np.any(driven.world.canvas.pixels != np.array(DEFAULT_BACKGROUND, dtype=np.uint8), axis=2)
    assert measured["pixel_coverage"] == pytest.approx(driven.world.canvas.inked.mean())
    assert measured["pixel_coverage"] > shown.mean()  # the reset and the clear took lines off the window


def test_a_lifted_pen_covers_nothing() -> None:
    d = Driven()
    d.call("/turtle1/set_pen", **pen(0, 0, 0, off=1))
    d.drive("turtle1", 2.0, 0.5)
    d.until(800)
    assert not d.world.canvas.inked.any()
    assert coverage.measure(d.run_data(), coverage.Params())["pixel_coverage"] == 0.0
