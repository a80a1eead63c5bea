"""An rclpy node drives turtle1 into the wall: turtlesim clamps it and warns on /rosout once per update, a ROS 2
rcl_interfaces/msg/Log at WARN, and the wall_hits metric counts the warnings.

From ros/ros_tutorials rolling 1.8.2 (Jazzy's turtlesim), turtlesim/src/turtle.cpp lines 283-300: after moving, a
position outside [0, canvas] logs ``RCLCPP_WARN(..., "Oh no! I hit the wall! (Clamping from [x=%f, y=%f])", ...)`` with
the unclamped screen position, then x and y are clamped to the canvas.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.metrics import wall_hits
from grader.metrics.run import RunData
from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Scenario
from sim.turtlesim import CANVAS_M

NODE = Path(__file__).resolve().parent / "turtlesim_ros2_nodes" / "into_the_wall_ros2.py"

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def walled(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("turtle_wall_ros2")
    spec = RunSpec(scenario=Scenario(robot="turtlesim", duration=3.0, command_types=["geometry_msgs/Twist"]),
                   nodes=(NodeSpec(script=NODE, flavour="ros2"),))
    run(spec, tmp / "run.mcap", tmp / "run.log")
    return Recording.open(tmp / "run.mcap")


def test_the_wall_warnings_are_ros2_logs(walled) -> None:
    schemas = {info.topic: info.type for info in walled.topics()}
    assert schemas["/rosout"] == "rcl_interfaces/Log"  # TopicInfo spells types as ROS 1 does
    warned = [line for line in walled.rosout() if line.msg.startswith("Oh no! I hit the wall!")]
    assert warned and {line.level for line in warned} == {4}  # WARN (the reader gives ROS 1's levels; 30 on the wire)
    assert warned[0].msg.startswith("Oh no! I hit the wall! (Clamping from [x=11.1")


def test_the_turtle_is_clamped_and_the_hits_counted(walled) -> None:
    data = RunData.from_recording(walled)
    assert float(data.trajectory("ground_truth").x[-1]) == pytest.approx(CANVAS_M)
    measured = wall_hits.measure(data, wall_hits.Params())
    assert measured["n_wall_hits"] == len([line for line in walled.rosout() if line.msg.startswith("Oh no!")]) > 10
