#!/usr/bin/env python3
"""turtle_circle in rclpy, written from the Jazzy TurtleBot3 examples: a TwistStamped on turtle1/cmd_vel, which
turtlesim (a Twist subscriber) never hears."""
import rclpy
from geometry_msgs.msg import TwistStamped
from rclpy.node import Node


class TurtleCircle(Node):

    def __init__(self):
        super().__init__('turtle_circle')
        self.publisher = self.create_publisher(TwistStamped, 'turtle1/cmd_vel', 10)
        self.timer = self.create_timer(0.1, self.on_timer)

    def on_timer(self):
        cmd = TwistStamped()
        cmd.header.stamp = self.get_clock().now().to_msg()
        cmd.twist.linear.x = 2.0
        cmd.twist.angular.z = 1.8
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
