"""A whole run of an rclpy node calling turtlesim's services with their ROS 2 types (turtlesim/srv/Spawn, SetPen,
TeleportAbsolute, Kill; std_srvs/srv/Empty): the calls reach the world, a ROS 2 caller gets a reply where rospy's would
fail, and the picture redrawn from the recording is the world's own canvas.

From ros/ros_tutorials rolling 1.8.2 (Jazzy's turtlesim): turtle_frame.cpp's spawnCallback and killCallback log their
error and ``return false``, a value rclcpp's service callback ignores, so the response goes out as the callback left it
(a taken name: ``name`` empty; an unknown turtle: Kill's empty response); the services are created with their
``turtlesim::srv::*`` and ``std_srvs::srv::Empty`` types on the node ``turtlesim`` in the root namespace.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from grader.metrics.pen import redraw
from grader.metrics.run import RunData
from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import Session
from sim import Scenario

NODE = Path(__file__).resolve().parent / "turtlesim_ros2_nodes" / "turtle_services_ros2.py"

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def served(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("turtle_services_ros2")
    spec = RunSpec(scenario=Scenario(robot="turtlesim", duration=4.0),
                   nodes=(NodeSpec(script=NODE, flavour="ros2"),))
    session = Session(spec, tmp / "run.mcap", tmp / "run.log")
    result = session.run()
    assert result.nodes[0].status == "exited", result.nodes[0].message
    recording = Recording.open(tmp / "run.mcap")
    printed = [line.text for line in recording.output_lines() if line.stream == "stdout"]
    return session.world.canvas, RunData.from_recording(recording), printed


def test_ros2_callers_get_turtlesims_replies(served) -> None:
    _, _, printed = served
    assert printed == ["spawn free: 'turtle2'", "spawn taken: ''", "kill nobody: turtlesim.srv.Kill_Response()",
                       "done"]


def test_the_recording_holds_every_call_answered(served) -> None:
    _, run, _ = served
    assert [(c.service, c.response is not None) for c in run.service_calls] == [
        ("/spawn", True), ("/spawn", True), ("/clear", True), ("/turtle2/set_pen", True),
        ("/turtle2/teleport_absolute", True), ("/kill", True)]
    assert set(run.poses) == {"/turtle1/pose", "/turtle2/pose"}


def test_the_redraw_from_the_ros2_recording_is_the_worlds_canvas(served) -> None:
    world, run, _ = served
    drawing = redraw(run)
    assert np.array_equal(drawing.canvas.pixels, world.pixels)
    assert [t.name for t in drawing.turtles] == ["turtle1", "turtle2"]  # the refused spawn drew no turtle
    assert (255, 0, 0) in {tuple(c) for c in world.pixels.reshape(-1, 3)}  # turtle2's teleport, in its red pen
