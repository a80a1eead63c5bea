"""A ROS 2 node's /scan subscription under each QoS a student writes: the simulated robot offers /scan as the Jazzy
simulation's bridge does (RELIABLE, VOLATILE), so the default and the sensor-data profiles hear it, while a
TRANSIENT_LOCAL subscription, or a BEST_AVAILABLE one made in the constructor, gets nothing and the node logs real
rclpy's "offering incompatible QoS" warning once; a BEST_AVAILABLE one made after discovery hears it
(tests/conformance_ros2/qos_matrix_jazzy.json is the real record)."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Scenario

pytestmark = pytest.mark.slow

NODE = """import rclpy
from geometry_msgs.msg import TwistStamped
from rclpy.node import Node
from rclpy.qos import {imports}
from sensor_msgs.msg import LaserScan


class Listen(Node):
    def __init__(self):
        super().__init__("listen")
        self.n = 0
        self.sub = None
        self.create_publisher(TwistStamped, "cmd_vel", 10)  # matched with the robot once discovery is over
        if {later}:
            self.once = self.create_timer(0.5, self.subscribe)
        else:
            self.subscribe()
        self.create_timer(0.95, self.report)

    def subscribe(self):
        if {later}:
            self.once.cancel()
        self.sub = self.create_subscription(LaserScan, "scan", self.on_scan, {qos})

    def on_scan(self, msg):
        self.n += 1

    def report(self):
        if self.sub is not None:
            print("scans", self.n, "publishers", self.sub.get_publisher_count(), flush=True)


rclpy.init()
rclpy.spin(Listen())
"""
WARNING = ("New publisher discovered on topic '/scan', offering incompatible QoS. No messages will be received from "
           "it. Last incompatible policy: DURABILITY")
CASES = {  # (imports, QoS, made 0.5 s after the start (after discovery), hears /scan)
    "depth": ("qos_profile_sensor_data", "10", False, True),
    "sensor_data": ("qos_profile_sensor_data", "qos_profile_sensor_data", False, True),
    "best_effort": ("QoSProfile, ReliabilityPolicy", "QoSProfile(depth=5, reliability=ReliabilityPolicy.BEST_EFFORT)",
                    False, True),
    "transient_local": ("QoSProfile, DurabilityPolicy",
                        "QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)", False, False),
    "best_available": ("qos_profile_best_available", "qos_profile_best_available", False, False),
    # resolved against the robot's publisher, discovered by then: RELIABLE, VOLATILE
    "best_available_later": ("qos_profile_best_available", "qos_profile_best_available", True, True),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_scan_subscription_by_qos(tmp_path: Path, case: str) -> None:
    imports, qos, later, hears = CASES[case]
    script = tmp_path / "listen.py"
    script.write_text(NODE.format(imports=imports, qos=qos, later=later))
    scenario = Scenario(duration=2.0, world="corridor", start="entrance")
    run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=script, flavour="ros2"),)), tmp_path / "r.mcap",
        tmp_path / "r.log")
    recording = Recording.open(tmp_path / "r.mcap")
    printed = [line.text for line in recording.output_lines() if line.text.startswith("scans")]
    warnings = [line.msg for line in recording.rosout() if "incompatible QoS" in line.msg]
    assert printed, recording.output_lines()
    last = printed[-1].split()
    if hears:
        assert int(last[1]) >= 5 and last[3] == "1", printed  # /scan at 5 Hz once discovered; one publisher (the robot)
        assert warnings == []
    else:
        assert last[1] == "0" and last[3] == "0", printed
        assert warnings == [WARNING]
