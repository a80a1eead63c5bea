#!/usr/bin/env python3
"""turtle_circle in rclpy with the timer never created: the callback that publishes is defined but nothing calls it,
so the node spins without ever sending a Twist."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class TurtleCircle(Node):

    def __init__(self):
        super().__init__('turtle_circle')
        self.publisher = self.create_publisher(Twist, 'turtle1/cmd_vel', 10)

    def on_timer(self):
        cmd = Twist()
        cmd.linear.x = 2.0
        cmd.angular.z = 1.8
        self.publisher.publish(cmd)


def main():
    rclpy.init()
    node = TurtleCircle()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass


if __name__ == '__main__':
    main()
