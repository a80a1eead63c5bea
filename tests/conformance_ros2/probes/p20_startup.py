#!/usr/bin/env python3
"""Probe 20 (issue 33 item 1): what a node's start costs, and the first timer tick's message.

The imports and rclpy.init take 0.17-0.6 s (0.17-0.23 s with a warm file cache, measured on a 2-core CI machine;
0.2 s was once too tight a bound there), then DDS discovery matches the node with the robot
(bimodal in real rclpy: about 0.1 s, or about 3 s); /clock reaches the node only then. The 10 Hz timer made in
__init__ fires at the first /clock, and its message (linear.y numbers the ticks) reaches the robot when the
publisher matched with the /clock subscription, as it did in 22 of 23 real runs. time.monotonic() is wall time in
real rclpy (= sim time at 1x) and sim time under rosgrade.
"""
import time

FIRST_LINE = time.monotonic()

import rclpy  # noqa: E402
from geometry_msgs.msg import TwistStamped  # noqa: E402
from rclpy.node import Node  # noqa: E402

rclpy.init()
INIT = time.monotonic()


class Startup(Node):
    def __init__(self):
        super().__init__("p20_startup")
        print("now in __init__", self.get_clock().now().nanoseconds)
        self.pub = self.create_publisher(TwistStamped, "/cmd_vel", 10)
        self.timer = self.create_timer(0.1, self.tick)
        self.ticks = 0

    def tick(self):
        self.ticks += 1
        msg = TwistStamped()
        msg.twist.linear.y = float(self.ticks)
        self.pub.publish(msg)
        if self.ticks == 1:
            first = time.monotonic()
            print("#REF %.6f" % (self.get_clock().now().nanoseconds / 1e9))
            print("imports and rclpy.init took at least 0.1 s", INIT - FIRST_LINE >= 0.1)
            print("discovery before the first tick took at least 0.03 s", first - INIT >= 0.03)
            print("first tick within 4 s of the first line", first - FIRST_LINE < 4.0)


node = Startup()
while node.ticks < 5:
    rclpy.spin_once(node, timeout_sec=0.5)
rclpy.spin_once(node, timeout_sec=0.2)
rclpy.shutdown()
print("end")
