"""`ros2 param set /turtlesim background_r 255` in an rclpy run (a scenario's param_sets): the call reaches the world
through the run's service routing (the world is one server among others), Jazzy's turtlesim answers it as rclcpp does,
the change is recorded, and the picture redrawn from the recording shows the new background at once, under the line
the turtle drew (Jazzy repaints on its own parameter events; Noetic waits for /clear). Refused values change nothing.
Source lines: tests/params/test_turtlesim_jazzy_world.py."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.metrics.pen import redraw
from grader.metrics.run import RunData
from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Scenario

NODE = Path(__file__).resolve().parents[1] / "e2e" / "turtlesim_ros2_nodes" / "publish_once_ros2.py"

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def data(tmp_path_factory) -> RunData:
    tmp = tmp_path_factory.mktemp("jazzy_param_set")
    scenario = Scenario(robot="turtlesim", duration=3.0, command_types=["geometry_msgs/Twist"], param_sets=[
        {"t": 1.5, "node": "/turtlesim", "name": "background_r", "value": 255},
        {"t": 1.6, "node": "/turtlesim", "name": "background_g", "value": 256},
        {"t": 1.7, "node": "/turtlesim", "name": "background_b", "value": 1.5}])
    run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=NODE, flavour="ros2"),)), tmp / "r.mcap", tmp / "r.log")
    return RunData.from_recording(Recording.open(tmp / "r.mcap"))


def test_each_set_is_answered_as_rclcpp_answers_it(data: RunData) -> None:
    calls = [c for c in data.service_calls if c.service == "/turtlesim/set_parameters"]
    answers = [[(r.successful, r.reason) for r in c.response["results"]] for c in calls]
    assert answers == [[(True, "")], [(False, "Parameter {background_g} doesn't comply with integer range.")],
                       [(False, "Wrong parameter type, parameter {background_b} is of type {integer}, setting it to "
                                "{double} is not allowed.")]]


def test_only_the_accepted_change_is_recorded_by_the_world(data: RunData) -> None:
    changes = [(c.name, c.value) for c in data.param_changes[1:]]
    assert changes == [("/turtlesim/background_r", 255)]
    first = next(c for c in data.service_calls if c.service == "/turtlesim/set_parameters")
    assert data.param_changes[1].t == first.t  # made as the call was answered


def test_the_picture_shows_the_new_background_at_once_under_the_line(data: RunData) -> None:
    pixels = redraw(data).canvas.pixels
    assert tuple(pixels[10, 10]) == (255, 86, 255)
    assert tuple(pixels[250, 260]) == (179, 184, 255)  # the 1 m the turtle drove, in the default pen
