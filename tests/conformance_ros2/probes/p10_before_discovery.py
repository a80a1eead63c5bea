#!/usr/bin/env python3
"""Probe 10: messages published right after create_publisher, before discovery matched the robot, are lost.

The course's nodes sometimes publish once in __init__; with volatile QoS those messages are dropped silently (no
error), even in a fast-discovery run. linear.y numbers the publishes: 1-3 before matching, 4-5 after.
"""
import rclpy
from geometry_msgs.msg import TwistStamped
from rclpy.node import Node


def marked(n):
    msg = TwistStamped()
    msg.twist.linear.y = float(n)
    return msg


rclpy.init()
node = Node("p10_before_discovery")
pub = node.create_publisher(TwistStamped, "/cmd_vel", 10)
print("subscribers right after create_publisher", pub.get_subscription_count())
for n in (1, 2, 3):
    pub.publish(marked(n))
while node.get_clock().now().nanoseconds == 0 or pub.get_subscription_count() == 0:
    rclpy.spin_once(node, timeout_sec=0.01)
print("#REF %.6f" % (node.get_clock().now().nanoseconds / 1e9))
print("subscribers once matched", pub.get_subscription_count())
for n in (4, 5):
    pub.publish(marked(n))
    rclpy.spin_once(node, timeout_sec=0.05)
rclpy.spin_once(node, timeout_sec=0.2)
rclpy.shutdown()
print("end")
