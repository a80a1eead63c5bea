#!/usr/bin/env python3
"""Probe 21: turtlesim's update rule, its 1 s command timeout, holonomic off, and the wall's clamping warning.

Drives turtle1 at 1 m/s for 1 s (10 Twists, linear.y 0.5 too), waits, then at 5 m/s into the right wall for 1.5 s.
Prints facts that do not depend on DDS timing: the speeds the pose reported, that the turtle stopped about 1 s after the
last command and drove about 2 m (within wall time's jitter), whether y moved, where it was clamped, the warning's text.
"""
import re

import rclpy
from geometry_msgs.msg import Twist
from rcl_interfaces.msg import Log
from rclpy.node import Node
from std_srvs.srv import Empty
from turtlesim.msg import Pose


class Probe(Node):
    def __init__(self):
        super().__init__("p21_turtle_motion")
        self.poses = []
        self.logs = []
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)
        self.create_subscription(Log, "/rosout", self.on_log, 100)

    def on_pose(self, msg):
        self.poses.append((self.get_clock().now().nanoseconds / 1e9, msg))

    def on_log(self, msg):
        if msg.name == "turtlesim":
            self.logs.append(msg.msg)

    def wait(self, seconds):
        end = self.get_clock().now().nanoseconds / 1e9 + seconds
        while self.get_clock().now().nanoseconds / 1e9 < end:
            rclpy.spin_once(self, timeout_sec=0.05)

    def drive(self, vx, vy, count):
        for _ in range(count):
            msg = Twist()
            msg.linear.x, msg.linear.y = vx, vy
            self.pub.publish(msg)
            self.wait(0.1)
        return self.get_clock().now().nanoseconds / 1e9 - 0.1


rclpy.init()
node = Probe()
while len(node.poses) < 5 or node.count_subscribers("/turtle1/cmd_vel") == 0:
    rclpy.spin_once(node, timeout_sec=0.1)
reset = node.create_client(Empty, "/reset")  # the world as it starts, whatever ran before
reset.wait_for_service(timeout_sec=5.0)
rclpy.spin_until_future_complete(node, reset.call_async(Empty.Request()), timeout_sec=2.0)
node.wait(0.2)
start = node.poses[-1][1]
print("#REF %.6f" % (node.get_clock().now().nanoseconds / 1e9))
print("start x %.6f y %.6f theta %.6f" % (start.x, start.y, start.theta))
last = node.drive(1.0, 0.5, 10)
node.wait(1.5)
moving = [t for t, p in node.poses if p.linear_velocity > 0]
print("speeds reported", sorted({round(p.linear_velocity, 3) for _, p in node.poses}))
# Both on wall time at 1x on the real side (ten publications 0.1 s apart, then turtlesim's 1 s timeout): measured
# 1.0-1.3 s and 1.5-2.3 m over real runs, where rosgrade's sim time gives 1.0 s and 1.9 m.
print("stopped 0.9-1.4 s after the last command", 0.9 <= moving[-1] - last <= 1.4)
end = node.poses[-1][1]
print("distance 1.4-2.5 m", 1.4 <= end.x - start.x <= 2.5, "y moved", abs(end.y - start.y) > 1e-6,
      "theta %.6f" % end.theta)
node.logs.clear()
node.drive(5.0, 0.0, 15)
node.wait(1.2)
end = node.poses[-1][1]
print("at the wall x %.6f y %.6f" % (end.x, end.y))
walls = [line for line in node.logs if line.startswith("Oh no!")]
print("wall warnings more than 3", len(walls) > 3)
print("first warning", re.sub(r"x=\d+\.\d+", "x=<x>", walls[0]) if walls else None)
print("warning x beyond the canvas", all(float(re.search(r"x=(\d+\.\d+)", w).group(1)) > end.x for w in walls))
print("end")
