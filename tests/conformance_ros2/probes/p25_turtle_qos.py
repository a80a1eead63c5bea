#!/usr/bin/env python3
"""Probe 25: turtlesim's topics' QoS (reliable, volatile, depth 7) met by a student's QoS choices: a best-effort
Twist publisher on cmd_vel, and transient-local and best-effort pose subscriptions; whether the turtle moves and
which subscriptions hear it.
"""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from std_srvs.srv import Empty
from turtlesim.msg import Pose

BEST_EFFORT = QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT)
LATCHED = QoSProfile(depth=10, durability=DurabilityPolicy.TRANSIENT_LOCAL)


class Probe(Node):
    def __init__(self):
        super().__init__("p25_turtle_qos")
        self.heard = {"default": [], "best_effort": [], "transient_local": []}
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", BEST_EFFORT)
        self.create_subscription(Pose, "/turtle1/pose", self.on_default, 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_best_effort, BEST_EFFORT)
        self.create_subscription(Pose, "/turtle1/pose", self.on_transient_local, LATCHED)

    def on_default(self, msg):
        self.heard["default"].append(msg)

    def on_best_effort(self, msg):
        self.heard["best_effort"].append(msg)

    def on_transient_local(self, msg):
        self.heard["transient_local"].append(msg)

    def wait(self, seconds):
        end = self.get_clock().now().nanoseconds + seconds * 1e9
        while self.get_clock().now().nanoseconds < end:
            rclpy.spin_once(self, timeout_sec=0.05)


rclpy.init()
node = Probe()
while not node.heard["default"] or node.get_clock().now().nanoseconds == 0:
    rclpy.spin_once(node, timeout_sec=0.1)
reset = node.create_client(Empty, "/reset")
reset.wait_for_service(timeout_sec=5.0)
rclpy.spin_until_future_complete(node, reset.call_async(Empty.Request()), timeout_sec=2.0)
node.wait(0.5)
print("#REF %.6f" % (node.get_clock().now().nanoseconds / 1e9))
start = node.heard["default"][-1]
for _ in range(10):
    msg = Twist()
    msg.linear.x = 1.0
    node.pub.publish(msg)
    node.wait(0.1)
end = node.heard["default"][-1]
print("best-effort commands moved the turtle", abs(end.x - start.x) > 0.1)
print("cmd_vel subscribers seen", node.count_subscribers("/turtle1/cmd_vel"))
for name, heard in node.heard.items():
    print(name, "subscription heard poses", len(heard) > 10)
print("end")
