"""A ROS 2 node's velocity publisher with a BEST_EFFORT QoS never reaches the robot's command subscriber, which
requests RELIABLE on Jazzy (the TurtleBot3 simulation's ros_gz_bridge and the real robot's turtlebot3_node with
KeepLast(10); turtlesim's turtle.cpp with KeepLast(7)): the robot stays where it started, the node logs rclpy's
publisher-side warning once, and the report says why and what to write instead. The default QoS still drives it."""
from __future__ import annotations

import math

from pathlib import Path

import pytest

from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Scenario

pytestmark = pytest.mark.slow

DRIVER = """import rclpy
from geometry_msgs.msg import {type}
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy


class Drive(Node):
    def __init__(self):
        super().__init__("drive")
        self.pub = self.create_publisher({type}, "{topic}", {qos})
        self.create_timer(0.1, self.tick)

    def tick(self):
        msg = {type}()
        {twist}.linear.x = 0.2
        self.pub.publish(msg)


rclpy.init()
rclpy.spin(Drive())
"""
BEST_EFFORT = "QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT)"
ROBOTS = {  # robot: (scenario robot, topic, message type, how the twist is reached)
    "turtlebot3": ("turtlebot3_burger", "cmd_vel", "TwistStamped", "msg.twist"),
    "turtlesim": ("turtlesim", "turtle1/cmd_vel", "Twist", "msg"),
}


def _run(tmp_path: Path, robot: str, qos: str):
    name, topic, type_name, twist = ROBOTS[robot]
    script = tmp_path / "drive.py"
    script.write_text(DRIVER.format(type=type_name, topic=topic, qos=qos, twist=twist))
    result = run(RunSpec(scenario=Scenario(robot=name, duration=2.0), nodes=(NodeSpec(script=script, flavour="ros2"),)),
                 tmp_path / "r.mcap", tmp_path / "r.log")
    return result, Recording.open(tmp_path / "r.mcap")


@pytest.mark.parametrize("robot", sorted(ROBOTS))
@pytest.mark.parametrize("qos", ["10", BEST_EFFORT])
def test_best_effort_cmd_vel_never_drives_the_robot(tmp_path: Path, robot: str, qos: str) -> None:
    result, recording = _run(tmp_path, robot, qos)
    truth = recording.ground_truth()
    moved = math.hypot(truth.x[-1] - truth.x[0], truth.y[-1] - truth.y[0])
    named = [line for line in result.diagnostics if "incompatible RELIABILITY" in line]
    if qos == "10":
        assert named == [], result.diagnostics
        assert moved > 0.1, moved
        assert not [line for line in recording.rosout() if "incompatible QoS" in line.msg]
    else:
        assert moved < 1e-3, moved
        assert len(named) == 1, result.diagnostics
        assert "offers BEST_EFFORT QoS" in named[0] and "requests RELIABLE" in named[0], named
        assert "never received a command" in named[0] and ", 10)" in named[0], named
        warned = [line.msg for line in recording.rosout() if "incompatible QoS" in line.msg]
        assert warned == [f"New subscription discovered on topic '/{ROBOTS[robot][1]}', requesting incompatible QoS. "
                          "No messages will be sent to it. Last incompatible policy: RELIABILITY"], warned
