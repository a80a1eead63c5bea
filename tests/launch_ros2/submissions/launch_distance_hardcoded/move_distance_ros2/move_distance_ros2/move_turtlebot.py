#!/usr/bin/env python3
"""move_turtlebot SPEED 0 DIST in ROS 2: drive along x at SPEED until odometry x >= DIST, then stop (seed 003)."""

import sys

import rclpy
from geometry_msgs.msg import TwistStamped
from nav_msgs.msg import Odometry
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions
from rclpy.utilities import remove_ros_args


class Mover(Node):

    def __init__(self, speed, distance):
        super().__init__('move_turtlebot')
        self.speed = speed
        self.distance = distance
        self.done = False
        self.pub = self.create_publisher(TwistStamped, 'cmd_vel', 10)
        self.create_subscription(Odometry, 'odom', self.odom_callback, 10)

    def odom_callback(self, msg):
        robot_x = msg.pose.pose.position.x
        command = TwistStamped()
        command.header.stamp = self.get_clock().now().to_msg()
        if not self.done and robot_x >= self.distance:
            self.get_logger().info(f'Reached x = {robot_x:.3f} m')
            self.done = True
        if not self.done:
            command.twist.linear.x = self.speed
        self.pub.publish(command)


def main(args=None):
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    words = remove_ros_args(sys.argv)[1:]
    node = Mover(float(words[0]), float(words[2]))
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.pub.publish(TwistStamped())
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
