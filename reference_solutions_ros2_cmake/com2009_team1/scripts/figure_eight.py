#!/usr/bin/env python3
"""COM2009 Assignment 2 Task 1 in rclpy (the team package's scripts/, started by launch/task1.launch.py): two 1 m
loops, anticlockwise then clockwise, back at the start in about 60 s, logging the pose relative to the start once a
second."""

import math

import rclpy
from geometry_msgs.msg import TwistStamped
from nav_msgs.msg import Odometry
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions

RADIUS = 0.5  # m
SPEED = 0.105  # m/s: two loops (2 pi m) in 60 s
TURN_RATE = SPEED / RADIUS  # rad/s


def wrap(angle):
    return math.atan2(math.sin(angle), math.cos(angle))


def yaw_of(q):
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


class FigureEight(Node):

    def __init__(self):
        super().__init__('figure_eight')
        self.pub = self.create_publisher(TwistStamped, 'cmd_vel', 10)
        self.create_subscription(Odometry, 'odom', self.odom_callback, 10)
        self.pose = None
        self.start = None
        self.loops = [1, -1]  # anticlockwise, then clockwise
        self.turned = 0.0
        self.last_yaw = None
        self.shutdown = False
        self.create_timer(1 / 30, self.control)
        self.create_timer(1.0, self.log_pose)

    def odom_callback(self, msg):
        p = msg.pose.pose
        self.pose = (p.position.x, p.position.y, yaw_of(p.orientation))
        if self.start is None:
            self.start = self.pose

    def log_pose(self):
        if self.start is None:
            return
        (x, y, yaw), (x0, y0, yaw0) = self.pose, self.start
        dx, dy = x - x0, y - y0
        rel_x = math.cos(yaw0) * dx + math.sin(yaw0) * dy
        rel_y = -math.sin(yaw0) * dx + math.cos(yaw0) * dy
        self.get_logger().info(
            f'x={rel_x:.2f} [m], y={rel_y:.2f} [m], yaw={math.degrees(wrap(yaw - yaw0)):.1f} [degrees].')

    def control(self):
        if self.pose is None or self.shutdown:
            return
        command = TwistStamped()
        command.header.stamp = self.get_clock().now().to_msg()
        if self.loops:
            if self.last_yaw is not None:
                self.turned += wrap(self.pose[2] - self.last_yaw)
            self.last_yaw = self.pose[2]
            remaining = 2 * math.pi - abs(self.turned)
            if remaining <= 0.005:
                self.loops.pop(0)
                self.turned = 0.0
            else:
                scale = min(1.0, max(0.2, remaining / 0.2))
                command.twist.linear.x = SPEED * scale
                command.twist.angular.z = self.loops[0] * TURN_RATE * scale
        self.pub.publish(command)

    def stop(self):
        self.shutdown = True
        self.pub.publish(TwistStamped())


def main(args=None):
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    node = FigureEight()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.stop()
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
