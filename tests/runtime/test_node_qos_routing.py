"""Two students' rclpy nodes on one topic: the grader routes the talker's messages to the listener only when their
QoS match, as two real Jazzy nodes do (a BEST_EFFORT publisher and a RELIABLE subscription: nothing arrives; the
reverse pair, and the defaults, connect). The counts the nodes see (get_subscription_count/get_publisher_count)
leave out the unmatched peer too, each node logs real rclpy's warning once (publisher and subscription side, texts
from the record), and the report names the mismatch."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.recording import Recording
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Scenario

pytestmark = pytest.mark.slow

TALKER = """import rclpy
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy, DurabilityPolicy
from std_msgs.msg import String


class Talk(Node):
    def __init__(self):
        super().__init__("talk")
        self.pub = self.create_publisher(String, "chatter", {qos})
        self.create_timer(0.1, self.tick)
        self.create_timer(0.95, self.report)

    def tick(self):
        self.pub.publish(String(data="hi"))

    def report(self):
        print("subscriptions", self.pub.get_subscription_count(), flush=True)


rclpy.init()
rclpy.spin(Talk())
"""
LISTENER = """import rclpy
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy, DurabilityPolicy
from std_msgs.msg import String


class Listen(Node):
    def __init__(self):
        super().__init__("listen")
        self.n = 0
        self.sub = self.create_subscription(String, "chatter", self.on_msg, {qos})
        self.create_timer(0.95, self.report)

    def on_msg(self, msg):
        self.n += 1

    def report(self):
        print("heard", self.n, "publishers", self.sub.get_publisher_count(), flush=True)


rclpy.init()
rclpy.spin(Listen())
"""
BEST_EFFORT = "QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT)"
RELIABLE = "QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE)"
TRANSIENT_LOCAL = "QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)"
CASES = {  # (talker's QoS, listener's QoS, the policy they fail in: None, connected) as in qos_matrix_jazzy.json
    "defaults": ("10", "10", None),
    "best_effort_to_reliable": (BEST_EFFORT, RELIABLE, "RELIABILITY"),
    "reliable_to_best_effort": (RELIABLE, BEST_EFFORT, None),
    "volatile_to_transient_local": ("10", TRANSIENT_LOCAL, "DURABILITY"),
}
# What each side logs once it has discovered the other (the record's publisher_warnings, subscription_warnings).
WARNINGS = {"/talk": "New subscription discovered on topic '/chatter', requesting incompatible QoS. No messages will be "
                     "sent to it. Last incompatible policy: {}",
            "/listen": "New publisher discovered on topic '/chatter', offering incompatible QoS. No messages will be "
                       "received from it. Last incompatible policy: {}"}


@pytest.mark.parametrize("case", sorted(CASES))
def test_two_nodes_connect_by_qos(tmp_path: Path, case: str) -> None:
    talker_qos, listener_qos, policy = CASES[case]
    connected = policy is None
    talker, listener = tmp_path / "talker.py", tmp_path / "listener.py"
    talker.write_text(TALKER.format(qos=talker_qos))
    listener.write_text(LISTENER.format(qos=listener_qos))
    scenario = Scenario(duration=3.0)
    result = run(RunSpec(scenario=scenario, nodes=(NodeSpec(script=talker, flavour="ros2"),
                                                   NodeSpec(script=listener, flavour="ros2"))),
                 tmp_path / "r.mcap", tmp_path / "r.log")
    named = [line for line in result.diagnostics if "incompatible" in line]
    recording = Recording.open(tmp_path / "r.mcap")
    heard = [line.text.split() for line in recording.output_lines() if line.text.startswith("heard")]
    subs = [line.text.split() for line in recording.output_lines() if line.text.startswith("subscriptions")]
    assert heard and subs, recording.output_lines()
    warned = sorted((line.name, line.msg) for line in recording.rosout() if "incompatible QoS" in line.msg)
    assert warned == ([] if connected else sorted((name, text.format(policy)) for name, text in WARNINGS.items()))
    if connected:
        assert int(heard[-1][1]) >= 10 and heard[-1][3] == "1", heard
        assert subs[-1][1] == "1", subs
        assert named == [], named
    else:
        assert heard[-1][1] == "0" and heard[-1][3] == "0", heard
        assert subs[-1][1] == "0", subs
        assert len(named) == 1 and named[0].startswith("listener.py's subscription to /chatter requests "), named
        assert f"talker.py's publisher offers {'BEST_EFFORT' if 'BEST' in talker_qos else 'VOLATILE'}" in named[0]
