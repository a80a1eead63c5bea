#!/usr/bin/env python3
"""Probe 1: Ctrl+C with rclpy's default signal handlers, caught as the course's pre-Exercise-5 nodes catch it.

A 10 Hz TwistStamped timer drives the robot; SIGINT comes 1.05 s after the origin. Which exception spin() raises,
rclpy.ok() in the except block, a publish and a log call there and in finally, destroy_node/shutdown afterwards.
"""
import rclpy
from geometry_msgs.msg import TwistStamped
from rclpy.node import Node


def outcome(label, fn):
    try:
        value = fn()
        print(label, "->", repr(value))
    except Exception as e:
        print(label, "!! %s.%s: %s" % (type(e).__module__, type(e).__name__, e))


class Mover(Node):
    def __init__(self):
        super().__init__("p01_sigint_default")
        self.pub = self.create_publisher(TwistStamped, "/cmd_vel", 10)
        self.n = 0

    def tick(self):
        msg = TwistStamped()
        msg.header.stamp = self.get_clock().now().to_msg()
        msg.twist.linear.x = 0.1
        msg.twist.linear.z = float(self.n)
        self.pub.publish(msg)
        self.n += 1


rclpy.init()
node = Mover()
# The robot must hear us and we must have sim time before the measured part starts (discovery takes 0-2.7 s).
while node.get_clock().now().nanoseconds == 0 or node.pub.get_subscription_count() == 0:
    rclpy.spin_once(node, timeout_sec=0.01)
print("#REF %.6f" % (node.get_clock().now().nanoseconds / 1e9))
node.create_timer(0.1, node.tick)
try:
    rclpy.spin(node)
    print("spin returned")
except KeyboardInterrupt as e:
    print("caught %s.%s %r" % (type(e).__module__, type(e).__name__, e))
    print("rclpy.ok() in except", rclpy.ok())
    outcome("publish zero in except", lambda: node.pub.publish(TwistStamped()))
    node.get_logger().info("Stopping the robot...")
except Exception as e:
    print("caught other %s.%s %r" % (type(e).__module__, type(e).__name__, e))
finally:
    print("ticks published", "more than 5" if node.n > 5 else node.n)
    outcome("publish zero in finally", lambda: node.pub.publish(TwistStamped()))
    outcome("destroy_node", node.destroy_node)
    outcome("rclpy.ok() after destroy_node", rclpy.ok)
    outcome("rclpy.shutdown", rclpy.shutdown)
    outcome("rclpy.try_shutdown", rclpy.try_shutdown)
print("end")
