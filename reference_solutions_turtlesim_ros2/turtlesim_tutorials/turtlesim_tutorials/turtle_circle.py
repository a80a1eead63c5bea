#!/usr/bin/env python3
"""turtlesim (ROS 2): drive turtle1 in a circle of radius v/ω until Ctrl+C, a Twist every 0.1 s from a timer
(turtlesim stops a turtle whose last command is older than 1 s)."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node

LINEAR = 2.0  # m/s
ANGULAR = 1.8  # rad/s: a circle of radius 2.0 / 1.8 = 1.11 m


class TurtleCircle(Node):

    def __init__(self):
        super().__init__('turtle_circle')
        self.publisher = self.create_publisher(Twist, 'turtle1/cmd_vel', 10)
        self.timer = self.create_timer(0.1, self.on_timer)

    def on_timer(self):
        cmd = Twist()
        cmd.linear.x = LINEAR
        cmd.angular.z = ANGULAR
        self.publisher.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    node = TurtleCircle()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass


if __name__ == '__main__':
    main()
