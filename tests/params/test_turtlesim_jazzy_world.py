"""What Jazzy's turtlesim does differently from Noetic's, in the world of a ROS 2 run (open_world(..., "ros2")).

Read from ros/ros_tutorials rolling 1.8.2, the turtlesim Jazzy ships (the snapshot has no jazzy branch), and
ros2/rclcpp branch jazzy; the facts, with their lines:
- turtle.cpp velocityCallback (lines 119-128): linear.y is taken only while the node's ``holonomic`` parameter is
  true; otherwise the turtle keeps the linear.y it had. Noetic's (noetic-devel turtle.cpp line 71) always takes it.
- turtle.cpp update (lines 311-318) reads the colour sensor from ``path_image``, which turtle_frame.cpp clear() fills
  with ``qRgba(255, 255, 255, 0)`` (lines 254-258): white where no pen painted since the last clear.
- turtle_frame.cpp declares background_r/g/b as integers in 0..255 step 1 and ``holonomic`` false (lines 73-98);
  paintEvent reads them on every repaint (lines 270-287) and parameterEventCallback repaints on its own node's
  parameter events (lines 203-210): a background change shows at once, not at the next /clear.
- turtle_frame.cpp spawnCallback logs "A turtle named [...] already exists" (line 177; noetic line 139: "turtled").
- rclcpp parameter_service.cpp sets a request's parameters one at a time (lines 77-97) and answers get_parameters with
  no values when a name is undeclared (lines 36-54); node_parameters.cpp words the refusals: range (lines 188-191),
  type (lines 252-260), undeclared (line 744), read-only (line 751).
"""
from __future__ import annotations

import pytest

from grader.runtime.param_server import ParamServer
from sim import Scenario, open_world
from sim.turtle_canvas import PATH_EMPTY
from sim.turtlesim import UPDATE_NS, TurtlesimWorld

INTEGER, DOUBLE, BOOL = 2, 3, 1


def started(flavour: str = "ros2") -> tuple[TurtlesimWorld, ParamServer]:
    world = open_world(Scenario(robot="turtlesim", duration=5.0), flavour)
    server = ParamServer({}, lambda text, author: None)
    world.use_parameters(server)
    server.start()
    return world, server


def step(world: TurtlesimWorld, n: int = 1) -> list:
    return world.advance_to(world.time_ns + n * UPDATE_NS)


def sensed(world: TurtlesimWorld) -> tuple[int, int, int]:
    colour = next(s for s in step(world) if s.topic == "/turtle1/color_sensor")
    return colour.r, colour.g, colour.b


def set_parameter(world: TurtlesimWorld, name: str, kind: int, value: object) -> dict:
    field = {INTEGER: "integer_value", DOUBLE: "double_value", BOOL: "bool_value"}[kind]
    result = world.call("/turtlesim/set_parameters",
                        {"parameters": [{"name": name, "value": {"type": kind, field: value}}]})
    assert result.ok
    return result.response["results"][0]


@pytest.mark.parametrize("flavour,moved_y", [("ros1", True), ("ros2", False)])
def test_linear_y_moves_the_turtle_sideways_only_in_noetic_by_default(flavour: str, moved_y: bool) -> None:
    world, _ = started(flavour)
    world.command("/turtle1/cmd_vel", linear=(0.0, 1.0, 0.0))
    step(world, 10)
    assert (world.state()["y"] > 5.6) is moved_y


def test_jazzy_takes_linear_y_once_holonomic_is_set() -> None:
    world, server = started()
    assert server.get("/turtlesim/holonomic") is False  # declared, false
    assert set_parameter(world, "holonomic", BOOL, True) == {"successful": True, "reason": ""}
    world.command("/turtle1/cmd_vel", linear=(0.0, 1.0, 0.0))
    step(world, 10)
    assert world.state()["y"] == pytest.approx(5.544445 + 0.16, abs=1e-4)


@pytest.mark.parametrize("flavour,unpainted", [("ros1", (69, 86, 255)), ("ros2", PATH_EMPTY)])
def test_the_colour_sensor_reads_the_window_in_noetic_and_the_path_image_in_jazzy(flavour, unpainted) -> None:
    world, _ = started(flavour)
    world.call("/turtle1/set_pen", {"r": 10, "g": 20, "b": 30, "width": 3, "off": False})
    assert sensed(world) == unpainted  # nothing painted under the turtle yet
    world.command("/turtle1/cmd_vel", linear=(1.0, 0.0, 0.0))
    step(world, 5)
    assert sensed(world) == (10, 20, 30)  # its own line, behind it
    world.call("/clear", {})
    world.command("/turtle1/cmd_vel")
    assert sensed(world) == unpainted


def test_a_background_set_shows_at_once_under_the_lines_in_jazzy() -> None:
    world, server = started()
    world.command("/turtle1/cmd_vel", linear=(1.0, 0.0, 0.0))
    step(world, 20)
    assert set_parameter(world, "background_r", INTEGER, 255) == {"successful": True, "reason": ""}
    assert server.get("/turtlesim/background_r") == 255
    assert tuple(world.canvas.pixels[10, 10]) == (255, 86, 255)  # no /clear needed
    assert tuple(world.canvas.pixels[250, 255]) == (179, 184, 255)  # the pen's line stays


@pytest.mark.parametrize("name,kind,value,reason", [
    ("background_r", INTEGER, 256, "Parameter {background_r} doesn't comply with integer range."),
    ("background_g", INTEGER, -1, "Parameter {background_g} doesn't comply with integer range."),
    ("background_b", DOUBLE, 255.0, "Wrong parameter type, parameter {background_b} is of type {integer}, setting it "
                                    "to {double} is not allowed."),
    ("holonomic", INTEGER, 1, "Wrong parameter type, parameter {holonomic} is of type {bool}, setting it to "
                              "{integer} is not allowed."),
    ("background", INTEGER, 1, "parameter 'background' cannot be set because it was not declared"),
    ("start_type_description_service", BOOL, False,
     "parameter 'start_type_description_service' cannot be set because it is read-only"),
])
def test_jazzy_refuses_a_set_as_rclcpp_words_it_and_nothing_changes(name, kind, value, reason) -> None:
    world, server = started()
    before = dict(server.tree["turtlesim"])
    assert set_parameter(world, name, kind, value) == {"successful": False, "reason": reason}
    assert server.tree["turtlesim"] == before
    assert tuple(world.canvas.pixels[0, 0]) == (69, 86, 255)


def test_parameters_are_set_one_at_a_time_and_read_back_all_or_nothing() -> None:
    world, _ = started()
    result = world.call("/turtlesim/set_parameters", {"parameters": [
        {"name": "background_g", "value": {"type": INTEGER, "integer_value": 300}},
        {"name": "background_b", "value": {"type": INTEGER, "integer_value": 0}}]})
    assert [r["successful"] for r in result.response["results"]] == [False, True]
    got = world.call("/turtlesim/get_parameters", {"names": ["background_b", "holonomic"]}).response["values"]
    assert got == [{"type": INTEGER, "integer_value": 0}, {"type": BOOL, "bool_value": False}]
    assert world.call("/turtlesim/get_parameters", {"names": ["background_b", "nope"]}).response == {"values": []}


def test_noetic_serves_no_parameter_services_and_jazzy_spells_a_taken_name_right() -> None:
    noetic, _ = started("ros1")
    assert "/turtlesim/set_parameters" not in {s.name for s in noetic.services}
    jazzy, _ = started("ros2")
    said = jazzy.call("/spawn", {"name": "turtle1", "x": 1.0, "y": 1.0, "theta": 0.0}).samples[0].msg
    assert said == "A turtle named [turtle1] already exists"
    assert noetic.call("/spawn", {"name": "turtle1", "x": 1.0, "y": 1.0, "theta": 0.0}).samples[0].msg == \
        "A turtled named [turtle1] already exists"
