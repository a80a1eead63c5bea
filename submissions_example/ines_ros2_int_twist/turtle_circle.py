#!/usr/bin/env python3
"""turtlesim (ROS 2): drive turtle1 in a circle until Ctrl+C, a Twist every 0.1 s from a timer.
Flaw: the speeds are written as ints (cmd.linear.x = 2), which rclpy sends as denormal doubles near 5e-324: the turtle
does not move."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class TurtleCircle(Node):

    def __init__(self):
        super().__init__('turtle_circle')
        self.publisher = self.create_publisher(Twist, 'turtle1/cmd_vel', 10)
        self.timer = self.create_timer(0.1, self.on_timer)

    def on_timer(self):
        cmd = Twist()
        cmd.linear.x = 2
        cmd.angular.z = 1
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
