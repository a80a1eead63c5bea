#!/usr/bin/env python3
"""agitr chapter 3's pubvel in rclpy: random velocities for turtle1 at 2 Hz (forward speed in [0, 1] m/s, turn rate
in [-1, 1] rad/s)."""
import random

import rclpy
from geometry_msgs.msg import Twist
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node


class PubVel(Node):

    def __init__(self):
        super().__init__('publish_velocity')
        self.publisher = self.create_publisher(Twist, 'turtle1/cmd_vel', 10)
        self.create_timer(0.5, self.on_timer)

    def on_timer(self):
        msg = Twist()
        msg.linear.x = random.random()
        msg.angular.z = 2 * random.random() - 1
        self.publisher.publish(msg)
        self.get_logger().info(f'Sending random velocity command: linear={msg.linear.x:f} angular={msg.angular.z:f}')


def main(args=None):
    rclpy.init(args=args)
    node = PubVel()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
