#!/usr/bin/env python3
"""Probe 2: Ctrl+C with default handlers and nothing caught (the course's main before Exercise 5).

spin() raises KeyboardInterrupt out of main(): the traceback ends the run and the process dies by SIGINT (-2).
"""
import rclpy
from geometry_msgs.msg import TwistStamped
from rclpy.node import Node


class Mover(Node):
    def __init__(self):
        super().__init__("p02_sigint_uncaught")
        self.pub = self.create_publisher(TwistStamped, "/cmd_vel", 10)

    def tick(self):
        msg = TwistStamped()
        msg.twist.linear.x = 0.1
        self.pub.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    node = Mover()
    while node.get_clock().now().nanoseconds == 0 or node.pub.get_subscription_count() == 0:
        rclpy.spin_once(node, timeout_sec=0.01)
    print("#REF %.6f" % (node.get_clock().now().nanoseconds / 1e9))
    node.create_timer(0.1, node.tick)
    rclpy.spin(node)
    print("not reached")
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
