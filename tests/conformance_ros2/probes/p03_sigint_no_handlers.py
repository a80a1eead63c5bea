#!/usr/bin/env python3
"""Probe 3: Ctrl+C with SignalHandlerOptions.NO (COM2009 Exercise 5): the zero command in except/finally arrives.

Python's own handler raises KeyboardInterrupt out of spin(); the context is still valid, so rclpy.ok() is True and
publishing a zero TwistStamped in except and in finally works, before destroy_node() and shutdown().
"""
import rclpy
from geometry_msgs.msg import TwistStamped
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions


def outcome(label, fn):
    try:
        value = fn()
        print(label, "->", repr(value))
    except Exception as e:
        print(label, "!! %s.%s: %s" % (type(e).__module__, type(e).__name__, e))


class Circle(Node):
    def __init__(self):
        super().__init__("p03_sigint_no_handlers")
        self.pub = self.create_publisher(TwistStamped, "/cmd_vel", 10)
        self.shutdown = False

    def tick(self):
        msg = TwistStamped()
        msg.twist.linear.x = 0.1
        msg.twist.angular.z = 0.2
        self.pub.publish(msg)

    def on_shutdown(self):
        self.get_logger().info("Stopping the robot...")
        for _ in range(5):
            self.pub.publish(TwistStamped())
        self.shutdown = True


rclpy.init(args=None, signal_handler_options=SignalHandlerOptions.NO)
node = Circle()
while node.get_clock().now().nanoseconds == 0 or node.pub.get_subscription_count() == 0:
    rclpy.spin_once(node, timeout_sec=0.01)
print("#REF %.6f" % (node.get_clock().now().nanoseconds / 1e9))
node.create_timer(0.1, node.tick)
try:
    rclpy.spin(node)
except KeyboardInterrupt as e:
    print("caught %s.%s %r" % (type(e).__module__, type(e).__name__, e))
    print("rclpy.ok() in except", rclpy.ok())
    outcome("publish zero in except", lambda: node.pub.publish(TwistStamped()))
finally:
    node.on_shutdown()
    while not node.shutdown:
        continue
    outcome("destroy_node", node.destroy_node)
    outcome("rclpy.shutdown", rclpy.shutdown)
    outcome("rclpy.ok() after shutdown", rclpy.ok)
    outcome("rclpy.shutdown again", rclpy.shutdown)
print("end")
