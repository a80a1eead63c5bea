"""turtlesim's background_r/g/b as noetic turtle_frame.cpp uses them: defaults set at start when unset, a launch
file's values kept, read again (roscpp's int reading, qRgb's low 8 bits) by /clear and /reset only."""
from __future__ import annotations

import numpy as np
import pytest

from grader.runtime.param_server import ParamServer
from sim import Scenario, open_world
from sim.turtle_canvas import DEFAULT_BACKGROUND
from sim.turtlesim import BACKGROUND_PARAMS, UPDATE_NS, TurtlesimWorld, background, roscpp_int

R, G, B = BACKGROUND_PARAMS


def started(tree: dict | None = None) -> tuple[TurtlesimWorld, ParamServer]:
    world = open_world(Scenario(robot="turtlesim", duration=5.0))
    server = ParamServer(tree if tree is not None else {}, lambda text, author: None)
    world.use_parameters(server)
    server.start()
    return world, server


def only(world: TurtlesimWorld, rgb: tuple[int, int, int]) -> bool:
    return bool(np.all(world.canvas.pixels == np.array(rgb, dtype=np.uint8)))


def sensed(world: TurtlesimWorld) -> tuple[int, int, int]:
    """What turtle1's colour sensor says at the next update."""
    samples = world.advance_to(world.time_ns + UPDATE_NS)
    colour = next(s for s in samples if s.topic == "/turtle1/color_sensor")
    return colour.r, colour.g, colour.b


def test_the_names_are_turtlesims_private_parameters() -> None:
    assert BACKGROUND_PARAMS == ("/turtlesim/background_r", "/turtlesim/background_g", "/turtlesim/background_b")


def test_at_start_unset_parameters_get_their_defaults_on_the_server() -> None:
    world, server = started()
    assert [server.get(n) for n in BACKGROUND_PARAMS] == [69, 86, 255] and only(world, DEFAULT_BACKGROUND)


def test_a_launch_files_value_is_kept_and_fills_the_canvas_from_the_start() -> None:
    world, server = started({"turtlesim": {"background_r": 10, "background_b": 0.6}})
    assert [server.get(n) for n in BACKGROUND_PARAMS] == [10, 86, 0.6]
    assert only(world, (10, 86, 1)) and sensed(world) == (10, 86, 1)


def test_a_change_shows_only_after_clear() -> None:
    world, server = started()
    server.set(R, 255)
    server.set(G, 0)
    assert only(world, DEFAULT_BACKGROUND) and sensed(world) == DEFAULT_BACKGROUND
    world.call("/clear", {})
    assert only(world, (255, 0, 255)) and sensed(world) == (255, 0, 255)


def test_reset_reads_them_again_and_a_deleted_one_is_its_default_again() -> None:
    world, server = started()
    server.set(B, 7)
    world.call("/clear", {})
    server.delete(B)
    server.set(G, 300)
    world.call("/reset", {})
    assert only(world, (69, 300 & 0xFF, 255)) and server.has(R) and not server.has(B)


@pytest.mark.parametrize(("value", "read"), [
    (5, 5), (5.4, 5), (5.5, 6), (254.7, 255), (-0.3, -1), (-1.5, -2),  # fmod(d, 1) < 0.5 floors, else ceils
    (True, 69), ("200", 69), ([1], 69), ({"a": 1}, 69), (None, 69),  # not an int or a double: the default
    (float("nan"), -(1 << 31)), (float("inf"), -(1 << 31)), (1e12, -(1 << 31)),  # x86's int for them
])
def test_roscpp_reads_an_int_parameter_so(value: object, read: int) -> None:
    assert roscpp_int(value, 69) == read


@pytest.mark.parametrize(("tree", "rgb"), [
    ({}, DEFAULT_BACKGROUND),
    ({"turtlesim": {"background_r": 256, "background_g": -1, "background_b": 255.5}}, (0, 255, 0)),
    ({"turtlesim": {"background_r": "red", "background_g": False, "background_b": float("nan")}}, (69, 86, 0)),
])
def test_qrgb_keeps_the_low_eight_bits(tree: dict, rgb: tuple[int, int, int]) -> None:
    server = ParamServer(tree, lambda text, author: None)
    assert background(server) == rgb


def test_without_a_server_the_background_is_the_default() -> None:
    world = open_world(Scenario(robot="turtlesim", duration=5.0))
    assert background(None) == DEFAULT_BACKGROUND
    world.call("/clear", {})
    assert only(world, DEFAULT_BACKGROUND)
