#!/usr/bin/env python3
"""move_turtlebot in ROS 2: drive along x at the speed parameter until odometry x reaches the distance parameter."""

import rclpy
from geometry_msgs.msg import TwistStamped
from nav_msgs.msg import Odometry
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions


class MoveTurtlebot(Node):

    def __init__(self):
        super().__init__("move_turtlebot")
        self.speed = self.declare_parameter("speed", 0.2).value
        self.distance = self.declare_parameter("distance", 3.0).value
        self.done = False
        self.pub = self.create_publisher(TwistStamped, "cmd_vel", 10)
        self.create_subscription(Odometry, "odom", self.odom_callback, 10)

    def odom_callback(self, msg):
        if msg.pose.pose.position.x >= self.distance:
            self.done = True
        cmd = TwistStamped()
        cmd.header.stamp = self.get_clock().now().to_msg()
        cmd.twist.linear.x = 0.0 if self.done else self.speed
        self.pub.publish(cmd)


def main(args=None):
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    node = MoveTurtlebot()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.pub.publish(TwistStamped())
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
