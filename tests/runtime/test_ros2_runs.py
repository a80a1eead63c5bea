"""Whole runs of rclpy nodes: the Jazzy TurtleBot3 drives on TwistStamped only (unless the scenario accepts Twist),
the run is recorded as ROS 2, and a Twist sent to it is named in the findings."""
from __future__ import annotations

from pathlib import Path

import pytest
from mcap.reader import make_reader

from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Scenario

pytestmark = pytest.mark.slow

NODE = """import rclpy
from geometry_msgs.msg import {type}
from rclpy.node import Node


class Drive(Node):
    def __init__(self):
        super().__init__("drive")
        self.pub = self.create_publisher({type}, "cmd_vel", 10)
        self.create_timer(0.1, self.tick)
        self.get_logger().info("driving")

    def tick(self):
        cmd = {type}()
        twist = cmd.twist if hasattr(cmd, "twist") else cmd
        twist.linear.x = 0.2
        self.pub.publish(cmd)


rclpy.init()
rclpy.spin(Drive())
"""


def _run(tmp: Path, message_type: str, command_types: list[str] | None = None):
    script = tmp / f"drive_{message_type}.py"
    script.write_text(NODE.format(type=message_type))
    scenario = Scenario(duration=3.0, command_types=command_types)
    result = run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=script, flavour="ros2"),)),
                 tmp / f"{message_type}.mcap", tmp / f"{message_type}.log")
    return result, Recording.open(tmp / f"{message_type}.mcap")


def _driven(recording: Recording) -> float:
    truth = recording.ground_truth()
    return float(truth.x[-1] - truth.x[0])


def test_twist_stamped_drives_the_jazzy_turtlebot(tmp_path: Path) -> None:
    result, recording = _run(tmp_path, "TwistStamped")
    assert result.nodes[0].status == "stopped_at_end"
    assert _driven(recording) > 0.3
    assert [line.level for line in recording.rosout()] == [2]  # INFO, on the ROS 1 scale the metrics use
    with open(recording.path, "rb") as stream:
        assert make_reader(stream).get_header().profile == "ros2"


def test_a_plain_twist_is_ignored_and_named(tmp_path: Path) -> None:
    result, recording = _run(tmp_path, "Twist")
    assert _driven(recording) < 1e-3
    assert any("carries geometry_msgs/msg/TwistStamped on this robot" in d and "geometry_msgs/msg/Twist there" in d
               for d in result.diagnostics), result.diagnostics


def test_a_scenario_may_accept_twist_as_humble_does(tmp_path: Path) -> None:
    _, recording = _run(tmp_path, "Twist", command_types=["geometry_msgs/Twist"])
    assert _driven(recording) > 0.3
    assert recording.metadata["rosgrade"]["command_types"] == ["geometry_msgs/msg/Twist"]


TALKER = """import rclpy
from rclpy.node import Node
from std_msgs.msg import String

rclpy.init()
node = Node("talker")
pub = node.create_publisher(String, "chatter", 10)
node.create_timer(0.01, lambda: pub.publish(String(data=str(node.get_clock().now().nanoseconds))))
rclpy.spin(node)
"""

LISTENER = """import time

import rclpy
from rclpy.node import Node
from std_msgs.msg import String

time.sleep(1.0)  # its first node comes 0.65 s after the talker's
rclpy.init()
node = Node("listener")
heard = []
node.create_subscription(String, "chatter", lambda msg: heard.append(msg.data), 10)
while not heard:
    rclpy.spin_once(node)
print("first heard", heard[0], "clock", node.get_clock().now().nanoseconds)
"""


def test_a_ros2_node_hears_another_from_its_own_discovery_on(tmp_path: Path) -> None:
    """Start-up (rclpy.context.STARTUP_NS, wire.DISCOVERY_NS): the talker's rclpy.init returns 0.35 s after the
    start and it publishes from its discovery 0.1 s later; the listener's first node comes at 1 s, and it hears the
    talker only from its own discovery, 0.1 s after that, when its /clock starts too."""
    for name, text in (("talker", TALKER), ("listener", LISTENER)):
        (tmp_path / f"{name}.py").write_text(text)
    scenario = Scenario(duration=2.0)
    result = run(RunSpec(scenario=scenario, nodes=tuple(NodeSpec(script=tmp_path / f"{name}.py", flavour="ros2")
                                                        for name in ("talker", "listener"))),
                 tmp_path / "chat.mcap", tmp_path / "chat.log")
    recording = Recording.open(tmp_path / "chat.mcap")
    printed = [text for _, stream, text, *_ in recording.output_lines() if stream == "stdout"]
    start = round(scenario.start_time * 1e9)
    heard = start + 1_100_000_000
    assert printed == [f"first heard {heard} clock {heard}"], (printed, result.diagnostics)
