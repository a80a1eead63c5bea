"""The spawn_draw metric on synthetic runs: two turtles' squares and pens, a refused spawn, a lifted pen, a filled
square (too much ink for an outline) and a square of the wrong size."""
from __future__ import annotations

import pytest

from grader.metrics import spawn_draw
from grader.metrics.run import RunData, ServiceCall, Trajectory

PENS = {"turtle1": (255, 0, 0), "turtle2": (0, 255, 0)}
PARAMS = spawn_draw.Params(pens=PENS, width=3, side=2.0)


def _square(x0: float, y0: float, side: float, t0: float) -> list[tuple[float, float, float, float]]:
    corners = [(x0, y0), (x0 + side, y0), (x0 + side, y0 + side), (x0, y0 + side), (x0, y0)]
    return [(t0 + k, x, y, 0.0) for k, (x, y) in enumerate(corners)]


def _path(poses: list[tuple[float, float, float, float]]) -> Trajectory:
    return Trajectory.of(*zip(*poses))


def _pen(turtle: str, rgb: tuple[int, int, int], off: int = 0) -> ServiceCall:
    r, g, b = rgb
    return ServiceCall(0.2, f"/{turtle}/set_pen", {"r": r, "g": g, "b": b, "width": 3, "off": off}, {})


def _run(turtle1=None, turtle2=None, spawned="turtle2", pens=None) -> RunData:
    turtle1 = turtle1 or _square(5.0, 5.0, 2.0, 1.0)
    turtle2 = turtle2 or _square(2.0, 2.0, 2.0, 1.0)
    spawn = ServiceCall(0.1, "/spawn", {"x": 2.0, "y": 2.0, "theta": 0.0, "name": "turtle2"}, {"name": spawned})
    calls = (spawn, *(pens if pens is not None else [_pen(name, rgb) for name, rgb in PENS.items()]))
    poses = {"/turtle2/pose": _path(turtle2)} if spawned else {}
    return RunData(odometry=_path(turtle1), poses=poses, service_calls=calls)


def test_two_squares_with_their_pens() -> None:
    m = spawn_draw.measure(_run(), PARAMS)
    assert (m["n_spawned"], m["spawned_names"], m["pens_wrong"], m["figures_missing"]) == (1, "turtle2", 0, 0)
    assert m["figure_error_rel"] < 0.02 and 0.95 < m["ink_ratio"] < 1.1


def test_a_refused_spawn_spawns_nothing() -> None:
    m = spawn_draw.measure(_run(spawned=""), PARAMS)
    assert m["n_spawned"] == 0 and m["figures_missing"] == 1 and m["figure_error_rel"] == 1.0


def test_a_lifted_pen_is_not_the_colour_asked_for() -> None:
    pens = [_pen("turtle1", PENS["turtle1"]), _pen("turtle2", PENS["turtle2"], off=1)]
    m = spawn_draw.measure(_run(pens=pens), PARAMS)
    assert (m["pens_wrong"], m["pens_wrong_names"], m["figures_missing"]) == (1, "turtle2", 1)
    assert m["figure_worst_turtle"] == "turtle2"


def test_a_filled_square_has_too_much_ink() -> None:
    rows = [(1.0 + k, 5.0 + (2.0 if k % 2 else 0.0), 5.0 + 0.1 * (k // 2), 0.0) for k in range(41)]  # 2 m wide zigzag
    m = spawn_draw.measure(_run(turtle1=rows), PARAMS)
    assert m["ink_ratio"] > 2.0 and m["figure_error_rel"] < 0.05  # the right size, but no outline


@pytest.mark.parametrize("side, error", [(1.0, 0.5), (2.4, 0.2)])
def test_a_square_of_another_size(side: float, error: float) -> None:
    m = spawn_draw.measure(_run(turtle1=_square(5.0, 5.0, side, 1.0)), PARAMS)
    assert m["figure_worst_turtle"] == "turtle1" and m["figure_error_rel"] == pytest.approx(error, abs=0.02)
