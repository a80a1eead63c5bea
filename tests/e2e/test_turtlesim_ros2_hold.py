"""A Twist from an rclpy node drives turtlesim for 1 s, as Jazzy's turtlesim holds a command, then the turtle stops.

From ros/ros_tutorials rolling 1.8.2 (Jazzy's turtlesim), turtlesim/src/turtle.cpp: ``velocityCallback`` stores the
command and ``last_command_time_ = nh_->now()`` (line 122); ``update`` zeroes the velocities when ``nh_->now() -
last_command_time_ > rclcpp::Duration(1.0, 0)`` (line 268), before moving by ``velocity * dt``; turtle_frame.cpp
updates every 16 ms (``setInterval(16)``, line 67) with ``dt = 0.001 * interval`` (line 308). So a 1 m/s command moves
the turtle by 0.016 m on each update no more than 1 s after it arrived: 62 or 63 updates, 0.992 or 1.008 m.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from grader.metrics.run import RunData
from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Scenario

NODE = Path(__file__).resolve().parent / "turtlesim_ros2_nodes" / "publish_once_ros2.py"

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def held(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("turtle_hold_ros2")
    spec = RunSpec(scenario=Scenario(robot="turtlesim", duration=4.0, command_types=["geometry_msgs/Twist"]),
                   nodes=(NodeSpec(script=NODE, flavour="ros2"),))
    run(spec, tmp / "run.mcap", tmp / "run.log")
    return RunData.from_recording(Recording.open(tmp / "run.mcap"))


def test_one_command_drives_the_turtle_for_one_second(held) -> None:
    path = held.trajectory("ground_truth")
    travelled = float(path.x[-1] - path.x[0])
    assert travelled in (pytest.approx(0.992), pytest.approx(1.008))
    moving = path.t[np.nonzero(np.diff(path.x) > 0)[0] + 1]
    assert moving[-1] - held.commands.t[0] <= 1.0 + 1e-9
    assert float(path.y[-1]) == pytest.approx(float(path.y[0]))
