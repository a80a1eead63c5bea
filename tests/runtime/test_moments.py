"""Batches of moments: the world runs ahead of a node, the node runs the later moments (deliveries, and its own
wake-ups up to the horizon) on its own while what it does cannot change the world, and the world is taken back to
the moment where the node did something that could. The recording must be the plain lockstep's, byte for byte,
whatever the node does."""
from __future__ import annotations

import hashlib
from pathlib import Path

import pytest

from grader import timing
from grader.runtime import NodeSpec, RunSpec
from grader.runtime import lookahead
from grader.runtime.session import run
from sim import Pose2D, Scenario
from sim.scenario import ScriptedCommand

REFERENCE = Path(__file__).resolve().parents[2] / "reference_solutions"

pytestmark = pytest.mark.slow

_ODOM_NODE = """import os, rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
rospy.init_node("moments")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
seen = [0]
def callback(msg):
    seen[0] += 1
    n = seen[0]
{callback}
rospy.Subscriber("/odom", Odometry, callback)
{main}
"""
_RATE_LOOP = """rate = rospy.Rate(4)
cmd = Twist()
while not rospy.is_shutdown():
    cmd.linear.x = 0.1 if seen[0] < 60 else 0.0
    pub.publish(cmd)
    rate.sleep()"""

# Each node does something visible (or changes its wake-up) in some of its /odom callbacks, not in others: every
# way a later moment ends the batch early, and a node that never does (the first).
NODES = {
    "silent callback, rate loop": ("    x = msg.pose.pose.position.x", _RATE_LOOP),
    "publishes in every 5th callback, spin": (
        "    if n % 5 == 0:\n        pub.publish(Twist())", "rospy.spin()"),
    "logs in every 7th callback": (
        "    if n % 7 == 0:\n        rospy.loginfo('seen %d', n)", "rospy.spin()"),
    "prints in every 3rd callback": ("    if n % 3 == 0:\n        print('x', msg.pose.pose.position.x)",
                                     _RATE_LOOP),
    "sleeps in every 4th callback (a new wake-up, nothing sent)": (
        "    if n % 4 == 0:\n        rospy.sleep(0.05)", _RATE_LOOP),
    "many library calls in a callback (charged time)": (
        "    if n % 6 == 0:\n        for _ in range(12):\n            rospy.get_time()", _RATE_LOOP),
    "raises in every 9th callback": ("    if n % 9 == 0:\n        raise ValueError(n)", "rospy.spin()"),
    "shuts down from a callback": (
        "    if n == 50:\n        rospy.signal_shutdown('enough')", "rospy.spin()\nprint('after spin', seen[0])"),
    "main thread waits for messages": (
        "    pass",
        "while not rospy.is_shutdown():\n"
        "    msg = rospy.wait_for_message('/odom', Odometry)\n"
        "    if seen[0] % 10 == 0:\n        pub.publish(Twist())"),
}

_RCLPY_NODE = """import rclpy
from geometry_msgs.msg import TwistStamped
from nav_msgs.msg import Odometry
from rclpy.node import Node


class Listener(Node):
    def __init__(self):
        super().__init__("moments")
        self.x, self.seen = 0.0, 0
        self.pub = self.create_publisher(TwistStamped, "cmd_vel", 10)
        self.create_subscription(Odometry, "odom", self.odom, 10)
        self.create_timer(0.25, self.tick)

    def odom(self, msg):
        self.seen += 1
        self.x = msg.pose.pose.position.x
        if self.seen % 8 == 0:
            self.get_logger().info(f"x {self.x:.3f}")

    def tick(self):
        cmd = TwistStamped()
        cmd.twist.linear.x = 0.1 if self.x < 0.3 else 0.0
        self.pub.publish(cmd)


rclpy.init()
try:
    rclpy.spin(Listener())
except KeyboardInterrupt:
    pass
"""


def _run(tmp: Path, script: Path, scenario: Scenario, name: str, moments: int, monkeypatch,
         flavour: str) -> tuple[str, dict]:
    monkeypatch.setattr(lookahead, "MAX_MOMENTS", moments)
    spec = RunSpec(scenario=scenario, nodes=(NodeSpec(script=script, flavour=flavour),))
    with timing.collect() as counts:
        result = run(spec, tmp / f"{name}.mcap", tmp / f"{name}.log")
    assert result.nodes[0].name and result.nodes[0].status != "protocol_violation", result.nodes[0]
    return hashlib.sha256((tmp / f"{name}.mcap").read_bytes()).hexdigest(), counts


def _both(tmp: Path, script: Path, scenario: Scenario, monkeypatch, flavour: str = "ros1") -> tuple[dict, dict]:
    ahead, batched = _run(tmp, script, scenario, "ahead", lookahead.MAX_MOMENTS, monkeypatch, flavour)
    lockstep, stepped = _run(tmp, script, scenario, "lockstep", 0, monkeypatch, flavour)
    assert ahead == lockstep, "the recording with batches of moments differs from the plain lockstep's"
    assert stepped.get("# moments run without a round trip", 0) == 0
    return stepped, batched


@pytest.mark.parametrize("case", sorted(NODES))
def test_a_node_running_later_moments_on_its_own_is_recorded_as_in_the_lockstep(tmp_path, monkeypatch, case):
    callback, main = NODES[case]
    script = tmp_path / "moments.py"
    script.write_text(_ODOM_NODE.format(callback=callback, main=main))
    stepped, batched = _both(tmp_path, script, Scenario(duration=8.0, shutdown_at=7.0), monkeypatch)
    assert batched["# moments run without a round trip"] > 0
    assert batched["# node steps (BATCH frames)"] < stepped["# node steps (BATCH frames)"]


def test_the_reference_odometry_square_takes_half_the_round_trips(tmp_path, monkeypatch):
    """move_square.py: a 30 Hz /odom callback that only stores the pose and a 30 Hz Rate loop, so without moments
    every wake-up is preceded by a step that only delivers /odom."""
    scenario = Scenario(duration=30.0, initial_pose=Pose2D(x=-2.0, y=-0.5, yaw=2.96706))
    stepped, batched = _both(tmp_path, REFERENCE / "move_square.py", scenario, monkeypatch)
    assert batched["# node steps (BATCH frames)"] < 0.6 * stepped["# node steps (BATCH frames)"]


def test_an_rclpy_node_runs_later_moments_too(tmp_path, monkeypatch):
    script = tmp_path / "moments_rclpy.py"
    script.write_text(_RCLPY_NODE)
    stepped, batched = _both(tmp_path, script, Scenario(duration=6.0, shutdown_at=5.0), monkeypatch, "ros2")
    assert batched["# moments run without a round trip"] > 0
    assert batched["# node steps (BATCH frames)"] < stepped["# node steps (BATCH frames)"]


def test_a_world_run_ahead_is_taken_back_when_the_node_acts_early(tmp_path, monkeypatch):
    """A node that publishes from a callback now and then: the world it ran ahead is taken back and re-run."""
    script = tmp_path / "moments.py"
    script.write_text(_ODOM_NODE.format(callback="    if n % 5 == 0:\n        pub.publish(Twist())",
                                        main="rospy.spin()"))
    _, batched = _both(tmp_path, script, Scenario(duration=8.0, shutdown_at=7.0), monkeypatch)
    assert batched["# world advances taken back"] > 0


_DRIVER = """import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
rospy.init_node("driver")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10{latch})
x = [0.0]
def callback(msg):
    x[0] = msg.pose.pose.position.x
{subscribe}
rate = rospy.Rate({hz})
cmd = Twist()
while not rospy.is_shutdown():
{body}
    rate.sleep()
"""
_ODOM = 'rospy.Subscriber("/odom", Odometry, callback)'
_ONE_COMMAND = "    cmd.linear.x = 0.2 if x[0] < 0.5 else 0.0\n    pub.publish(cmd)"

# Nodes that drive the robot (publish from their main loop), on scenarios where repeating a command is, or is not,
# something the world notices: (scenario, node fields). The Husky's odometry is not /odom: that node only publishes,
# and as its command times out before it repeats it, each repeat is a new command.
DRIVERS = {
    "repeats one command, then another": (Scenario(duration=8.0), {}),
    "a proportional controller: a new command every time": (
        Scenario(duration=8.0), {"body": "    cmd.linear.x = 0.5 * (0.6 - x[0])\n    pub.publish(cmd)"}),
    "publishes only (no subscription: batches of its own wake-ups)": (Scenario(duration=8.0), {"subscribe": ""}),
    "stops publishing for a while, past the base's 0.5 s timeout": (
        Scenario(duration=8.0, base_mode="real"),
        {"body": "    if int(rospy.get_time()) % 3 != 0:\n        cmd.linear.x = 0.1\n        pub.publish(cmd)"}),
    "repeats its command less often than the Husky's 0.25 s timeout": (
        Scenario(duration=8.0, robot="husky_a200"), {"hz": 3}),
    "repeats its command across a scripted one": (
        Scenario(duration=8.0, script=[ScriptedCommand(t=2.0, linear=-0.1), ScriptedCommand(t=2.5, angular=0.5)]),
        {}),
    "subscribes to its own commands": (
        Scenario(duration=8.0), {"subscribe": _ODOM + '\nrospy.Subscriber("/cmd_vel", Twist, lambda m: None)'}),
    "latches its commands": (Scenario(duration=8.0), {"latch": ", latch=True"}),
    "logs and prints as it drives": (
        Scenario(duration=8.0), {"body": _ONE_COMMAND + "\n    rospy.loginfo('x %.3f', x[0])\n    print(x[0])"}),
}


@pytest.mark.parametrize("case", sorted(DRIVERS))
def test_a_driving_node_running_ahead_is_recorded_as_in_the_lockstep(tmp_path, monkeypatch, case):
    scenario, fields = DRIVERS[case]
    script = tmp_path / "driver.py"
    script.write_text(_DRIVER.format(**{"latch": "", "subscribe": _ODOM, "hz": 10, "body": _ONE_COMMAND, **fields}))
    stepped, batched = _both(tmp_path, script, scenario, monkeypatch)
    if "Husky" not in case:
        assert batched["# node steps (BATCH frames)"] < stepped["# node steps (BATCH frames)"]


def test_a_node_that_repeats_its_command_needs_a_round_trip_only_now_and_then(tmp_path, monkeypatch):
    """Repeating the robot's command in force changes nothing in the world but the base's timeout (Gazebo's has
    none): the node runs its own wake-ups, a quarter of a second past each, without the grader."""
    script = tmp_path / "driver.py"
    script.write_text(_DRIVER.format(latch="", subscribe=_ODOM, hz=10, body=_ONE_COMMAND))
    stepped, batched = _both(tmp_path, script, Scenario(duration=8.0), monkeypatch)
    assert batched["# node steps (BATCH frames)"] < 0.25 * stepped["# node steps (BATCH frames)"]
