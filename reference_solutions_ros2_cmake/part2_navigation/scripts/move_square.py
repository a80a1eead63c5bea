#!/usr/bin/env python3
"""Reference for move_square in ROS 2: a 1 m square from odometry on a 10 Hz timer, stopping after two loops."""

import math

import rclpy
from geometry_msgs.msg import TwistStamped
from nav_msgs.msg import Odometry
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions

from part2_navigation_modules.tb3_tools import angle_diff, quaternion_to_yaw

SIDE = 1.0  # m
LOOPS = 2
FORWARD = 0.2  # m/s
TURN = 0.4  # rad/s


class Square(Node):

    def __init__(self):
        super().__init__("move_square")
        self.vel_pub = self.create_publisher(TwistStamped, "cmd_vel", 10)
        self.odom_sub = self.create_subscription(Odometry, "odom", self.odom_callback, 10)
        self.timer = self.create_timer(0.1, self.timer_callback)  # 10 Hz

        self.x = self.y = self.theta = None
        self.start = None  # (x, y) of the current side, or the heading the current turn aims for
        self.turning = False
        self.edges = 0
        self.done = False
        self.shutdown = False
        self.get_logger().info(f"The '{self.get_name()}' node is initialised.")

    def odom_callback(self, msg):
        pose = msg.pose.pose
        q = pose.orientation
        self.x, self.y = pose.position.x, pose.position.y
        self.theta = quaternion_to_yaw(q.x, q.y, q.z, q.w)

    def drive(self, linear, angular):
        msg = TwistStamped()
        msg.header.stamp = self.get_clock().now().to_msg()
        msg.twist.linear.x = linear
        msg.twist.angular.z = angular
        self.vel_pub.publish(msg)

    def timer_callback(self):
        if self.x is None or self.done:
            return
        if self.start is None:
            self.start = (self.x, self.y) if not self.turning else self.theta + math.pi / 2
        if not self.turning:
            remaining = SIDE - math.hypot(self.x - self.start[0], self.y - self.start[1])
            if remaining > 0.002:
                self.drive(min(FORWARD, max(0.03, remaining)), 0.0)  # slow down near the corner
                return
            self.turning, self.start = True, None
        else:
            remaining = angle_diff(self.start, self.theta)
            if abs(remaining) > math.radians(0.5):
                self.drive(0.0, math.copysign(min(TURN, max(0.05, abs(remaining))), remaining))
                return
            self.turning, self.start = False, None
            self.edges += 1
            if self.edges == 4 * LOOPS:
                self.get_logger().info("Two loops done: stopping.")
                self.done = True
        self.drive(0.0, 0.0)

    def on_shutdown(self):
        self.drive(0.0, 0.0)
        self.shutdown = True


def main(args=None):
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    node = Square()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        print(f"{node.get_name()} received a shutdown request (Ctrl+C).")
    finally:
        node.on_shutdown()
        while not node.shutdown:
            continue
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
