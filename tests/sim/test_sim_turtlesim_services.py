"""turtlesim's services at the world level: each one's effect against turtle_frame.cpp / turtle.cpp, in closed form."""
from __future__ import annotations

import math
import struct

import numpy as np
import pytest

from sim import (LogSample, Scenario, ServiceResult, TurtlePoseSample, TurtlesimError, World, WorldService,
                 open_world)
from sim.turtle_canvas import DEFAULT_BACKGROUND, METER_PX
from sim.turtlesim import CANVAS_M, DEFAULT_PEN, DT, TURTLE_PI, UPDATE_NS, TurtlesimWorld

CENTRE = CANVAS_M / 2
START_NS = 2_000_000_000  # a scenario's default start time
GLOBAL = ("/clear", "/reset", "/spawn", "/kill")
PER_TURTLE = ("set_pen", "teleport_absolute", "teleport_relative")


def world() -> TurtlesimWorld:
    made = open_world(Scenario(robot="turtlesim", duration=5.0))
    assert isinstance(made, TurtlesimWorld)
    return made


def f32(value: float) -> float:
    """A float32 request field as the wire carries it."""
    return struct.unpack("<f", struct.pack("<f", value))[0]


def spawn(w: TurtlesimWorld, x: float, y: float, theta: float = 0.0, name: str = "") -> ServiceResult:
    return w.call("/spawn", {"x": f32(x), "y": f32(y), "theta": f32(theta), "name": name})


def step(w: TurtlesimWorld, updates: int = 1) -> list:
    """Advance exactly ``updates`` 16 ms updates (the world's updates fall on multiples of 16 ms)."""
    return w.advance_to((w.time_ns // UPDATE_NS + updates) * UPDATE_NS)


def last_pose(samples: list, turtle: str) -> TurtlePoseSample:
    return [s for s in samples if isinstance(s, TurtlePoseSample) and s.topic == f"/{turtle}/pose"][-1]


def logs(result: ServiceResult) -> list[tuple[int, str]]:
    return [(s.level, s.msg) for s in result.samples]


def background_only(w: TurtlesimWorld) -> bool:
    return bool(np.all(w.canvas.pixels == np.array(DEFAULT_BACKGROUND, dtype=np.uint8)))


# -- what is declared ------------------------------------------------------------------------------------------------
def test_turtlesim_serves_its_four_services_and_turtle1s_three() -> None:
    w = world()
    assert w.services == (WorldService("/clear", "std_srvs/Empty"), WorldService("/reset", "std_srvs/Empty"),
                          WorldService("/spawn", "turtlesim/Spawn"), WorldService("/kill", "turtlesim/Kill"),
                          WorldService("/turtle1/set_pen", "turtlesim/SetPen"),
                          WorldService("/turtle1/teleport_absolute", "turtlesim/TeleportAbsolute"),
                          WorldService("/turtle1/teleport_relative", "turtlesim/TeleportRelative"))


def test_the_robot_world_serves_nothing() -> None:
    robot = World(Scenario(duration=1.0))
    assert robot.services == ()


def test_a_service_turtlesim_does_not_serve_is_an_error() -> None:
    with pytest.raises(TurtlesimError, match="/turtle2/set_pen"):
        world().call("/turtle2/set_pen", {"r": 0, "g": 0, "b": 0, "width": 1, "off": 0})


# -- /spawn and /kill -------------------------------------------------------------------------------------------------
def test_spawn_with_no_name_makes_turtle2_with_its_own_topics_and_services() -> None:
    w = world()
    result = spawn(w, 2.0, 3.0, 0.5)
    assert result.ok and result.response == {"name": "turtle2"}
    assert logs(result) == [(2, "Spawning turtle [turtle2] at x=[2.000000], y=[3.000000], theta=[0.500000]")]
    assert result.samples[0].t_ns == w.time_ns and result.samples[0].name == "/turtlesim"
    assert "/turtle2/cmd_vel" in w.command_topics
    assert {"/turtle2/pose", "/turtle2/color_sensor"} <= {p.topic for p in w.publications}
    assert {f"/turtle2/{leaf}" for leaf in PER_TURTLE} <= {s.name for s in w.services}
    pose = last_pose(step(w), "turtle2")
    assert (pose.x, pose.theta) == (2.0, 0.5) and pose.y == pytest.approx(3.0, abs=1e-12)


def test_a_spawned_turtle_drives_on_its_own_cmd_vel_and_turtle1_stays() -> None:
    w = world()
    spawn(w, 2.0, 3.0, 0.0)
    assert w.command("/turtle2/cmd_vel", linear=(1.0, 0.0, 0.0), angular=(0.0, 0.0, 0.5))
    samples = step(w, 10)
    x, y, theta = 2.0, 3.0, 0.0
    for _ in range(10):  # turtle.cpp's update, closed form
        theta += 0.5 * DT
        theta -= 2 * TURTLE_PI * math.floor((theta + TURTLE_PI) / (2 * TURTLE_PI))
        x, y = x + math.cos(theta) * DT, y + math.sin(theta) * DT
    pose = last_pose(samples, "turtle2")
    assert (pose.x, pose.y, pose.theta) == pytest.approx((x, y, theta), abs=1e-12)
    still = last_pose(samples, "turtle1")
    assert (still.x, still.y, still.linear_velocity) == pytest.approx((CENTRE, CENTRE, 0.0), abs=1e-12)


def test_unnamed_spawns_take_the_next_free_turtle_number() -> None:
    w = world()
    assert spawn(w, 1, 1).response == {"name": "turtle2"}
    assert w.call("/kill", {"name": "turtle2"}).ok
    assert spawn(w, 1, 1).response == {"name": "turtle3"}  # the counter goes on after a kill
    assert spawn(w, 1, 1, name="turtle4").response == {"name": "turtle4"}
    assert spawn(w, 1, 1).response == {"name": "turtle5"}  # turtle4 is taken: skipped


def test_spawning_a_taken_name_fails_and_logs_turtlesims_error() -> None:
    w = world()
    result = spawn(w, 1.0, 1.0, name="turtle1")
    assert not result.ok and result.error == "" and result.response == {"name": ""}  # what a ROS 2 caller gets back
    assert logs(result) == [(8, "A turtled named [turtle1] already exists")]
    assert list(w.turtles) == ["turtle1"]
    assert w.turtles["turtle1"].x == CENTRE


@pytest.mark.parametrize("name, error", [
    ("2nd", "Character [2] is not valid as the first character in Graph Resource Name [2nd].  Valid characters are "
            "a-z, A-Z, / and in some cases ~."),
    ("my turtle", "Character [ ] at element [2] is not valid in Graph Resource Name [my turtle].  Valid characters "
                  "are a-z, A-Z, 0-9, / and _."),
])
def test_a_name_roscpp_refuses_fails_with_roscpps_text(name: str, error: str) -> None:
    w = world()
    result = spawn(w, 1.0, 1.0, name=name)
    assert not result.ok and result.error == error
    assert logs(result) == [(8, f"Exception thrown while processing service call: {error}")]
    assert list(w.turtles) == ["turtle1"]


def test_kill_removes_the_turtle_its_topics_and_its_services() -> None:
    w = world()
    spawn(w, 1.0, 1.0)
    assert w.call("/kill", {"name": "turtle2"}) == ServiceResult(True, {})
    assert "/turtle2/cmd_vel" not in w.command_topics
    assert not any("turtle2" in p.topic for p in w.publications)
    assert not any("turtle2" in s.name for s in w.services)
    assert not any("turtle2" in s.topic for s in step(w, 3))


def test_killing_an_unknown_turtle_fails_and_logs_turtlesims_error() -> None:
    result = world().call("/kill", {"name": "nobody"})
    assert not result.ok and result.error == ""
    assert logs(result) == [(8, "Tried to kill turtle [nobody], which does not exist")]


def test_turtles_update_in_name_order_as_turtlesims_std_map_keeps_them() -> None:
    w = world()
    for name in ("zed", "alpha"):
        spawn(w, 1.0, 1.0, name=name)
    topics = [s.topic for s in step(w) if isinstance(s, TurtlePoseSample)]
    assert topics == ["/alpha/pose", "/turtle1/pose", "/zed/pose"]


def test_scripted_commands_outlive_a_killed_turtle1() -> None:
    w = world()
    assert w.call("/kill", {"name": "turtle1"}).ok
    assert w.state() == {} and w.command_topics == ()
    step(w, 2)  # nothing left to move: no error


# -- set_pen --------------------------------------------------------------------------------------------------------
def test_with_the_pen_off_moving_draws_nothing() -> None:
    w = world()
    assert w.call("/turtle1/set_pen", {"r": 255, "g": 0, "b": 0, "width": 5, "off": 1}).ok
    turtle = w.turtles["turtle1"]
    assert not turtle.pen_on and turtle.pen == DEFAULT_PEN  # off keeps the colour
    w.command("/turtle1/cmd_vel", linear=(1.0, 0.0, 0.0))
    step(w, 20)
    assert background_only(w)


def drawn_rows(pen: dict[str, int], rgb: tuple[int, int, int]) -> int:
    """How many pixels across the line turtle1 draws eastwards with ``pen`` are of colour ``rgb``."""
    w = world()
    if pen:
        assert w.call("/turtle1/set_pen", {"r": rgb[0], "g": rgb[1], "b": rgb[2], "off": 0, **pen}).ok
    w.command("/turtle1/cmd_vel", linear=(1.0, 0.0, 0.0))
    step(w, 30)
    column = round((CENTRE + 0.2) * METER_PX)
    return int(np.sum(np.all(w.canvas.pixels[:, column] == rgb, axis=1)))


def test_set_pen_draws_in_its_colour_and_width() -> None:
    default = drawn_rows({}, DEFAULT_PEN)
    assert 3 <= default <= 4  # 3 px, give or take the edge pixel of this canvas model
    assert 7 <= drawn_rows({"width": 7}, (255, 0, 0)) <= 8


def test_pen_width_zero_is_qts_one_pixel_pen() -> None:
    assert 1 <= drawn_rows({"width": 0}, (0, 255, 0)) <= 2


# -- teleports --------------------------------------------------------------------------------------------------------
def test_teleport_absolute_is_applied_at_the_next_update_and_draws_its_jump() -> None:
    w = world()
    assert w.call("/turtle1/teleport_absolute", {"x": 2.0, "y": 9.0, "theta": f32(1.2)}) == ServiceResult(True, {})
    assert w.turtles["turtle1"].x == CENTRE  # queued, as turtle.cpp queues it
    samples = step(w)
    pose = last_pose(samples, "turtle1")
    assert (pose.x, pose.theta) == (2.0, f32(1.2)) and pose.y == pytest.approx(9.0, abs=1e-12)
    colour = [s for s in samples if s.topic == "/turtle1/color_sensor"][-1]
    assert (colour.r, colour.g, colour.b) == DEFAULT_PEN  # the pen drew the jump; the sensor reads it after


def test_teleport_relative_turns_then_moves_along_the_new_heading() -> None:
    w = world()
    w.call("/turtle1/teleport_relative", {"linear": 2.0, "angular": f32(0.5)})
    w.call("/turtle1/teleport_relative", {"linear": 1.0, "angular": f32(3.0)})  # queued in order
    pose = last_pose(step(w), "turtle1")
    theta1 = f32(0.5)
    x, y = CENTRE + 2.0 * math.cos(theta1), CENTRE + 2.0 * math.sin(theta1)
    theta2 = theta1 + f32(3.0)
    x, y = x + math.cos(theta2), y + math.sin(theta2)
    wrapped = theta2 - 2 * TURTLE_PI * math.floor((theta2 + TURTLE_PI) / (2 * TURTLE_PI))
    assert (pose.x, pose.y, pose.theta) == pytest.approx((x, y, wrapped), abs=1e-12)


def test_a_teleport_with_the_pen_off_leaves_no_line() -> None:
    w = world()
    w.call("/turtle1/set_pen", {"r": 0, "g": 0, "b": 0, "width": 3, "off": 1})
    w.call("/turtle1/teleport_absolute", {"x": 1.0, "y": 1.0, "theta": 0.0})
    samples = step(w)
    assert background_only(w)
    colour = [s for s in samples if s.topic == "/turtle1/color_sensor"][-1]
    assert (colour.r, colour.g, colour.b) == DEFAULT_BACKGROUND


# -- /clear and /reset ------------------------------------------------------------------------------------------------
def test_clear_wipes_the_drawing_and_leaves_the_turtles() -> None:
    w = world()
    w.command("/turtle1/cmd_vel", linear=(1.0, 0.0, 0.0))
    step(w, 20)
    assert not background_only(w)
    moved = w.turtles["turtle1"].x
    result = w.call("/clear", {})
    assert result.ok and logs(result) == [(2, "Clearing turtlesim.")]
    assert background_only(w) and w.turtles["turtle1"].x == moved


def test_reset_kills_every_turtle_respawns_turtle1_and_clears() -> None:
    w = world()
    spawn(w, 1.0, 1.0)
    w.call("/turtle1/set_pen", {"r": 255, "g": 0, "b": 0, "width": 9, "off": 0})
    w.command("/turtle1/cmd_vel", linear=(1.0, 0.0, 0.0), angular=(0.0, 0.0, 1.0))
    step(w, 20)
    result = w.call("/reset", {})
    assert result.ok
    assert logs(result) == [(2, "Resetting turtlesim."),
                            (2, "Spawning turtle [turtle1] at x=[5.544445], y=[5.544445], theta=[0.000000]")]
    assert list(w.turtles) == ["turtle1"] and background_only(w)
    turtle = w.turtles["turtle1"]
    assert (turtle.x, turtle.y, turtle.theta, turtle.pen, turtle.pen_width) == (CENTRE, CENTRE, 0.0, DEFAULT_PEN, 3)
    pose = last_pose(step(w), "turtle1")
    assert (pose.x, pose.y, pose.linear_velocity) == pytest.approx((CENTRE, CENTRE, 0.0), abs=1e-12)  # no command
    assert spawn(w, 1, 1).response == {"name": "turtle2"}  # names counted from 1 again


def test_service_logs_are_stamped_at_the_call_time() -> None:
    w = world()
    step(w, 5)
    result = w.call("/clear", {})
    assert w.time_ns == START_NS + 5 * UPDATE_NS  # the start time falls on an update
    assert [(type(s), s.t_ns) for s in result.samples] == [(LogSample, w.time_ns)]


def test_a_teleport_or_command_that_is_not_a_number_leaves_the_world_running() -> None:
    w = world()
    w.call("/turtle1/teleport_absolute", {"x": float("inf"), "y": 1.0, "theta": 0.0})
    spawn(w, 1.0, 1.0)
    w.command("/turtle2/cmd_vel", linear=(float("nan"), 0.0, 0.0))
    samples = step(w, 2)
    assert last_pose(samples, "turtle1").x == CANVAS_M  # clamped, as turtle.cpp clamps an infinite x
    assert math.isnan(last_pose(samples, "turtle2").x)
    colour = [s for s in samples if s.topic == "/turtle2/color_sensor"][-1]
    assert (colour.r, colour.g, colour.b) == (0, 48, 57)  # QImage::pixel off the image: 12345
