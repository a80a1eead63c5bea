#!/usr/bin/env python3
"""turtlesim (ROS 2): draw an equilateral triangle, "forward one side, turn left 120 degrees" three times, each step
timed on the node's clock by a timer and followed by a zero Twist."""
import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node

SIDE = 2.0  # m
SPEED = 1.0  # m/s
TURN_SPEED = math.radians(60)  # rad/s
STEPS = [(SPEED, 0.0, SIDE / SPEED), (0.0, TURN_SPEED, math.radians(120) / TURN_SPEED)] * 3


class Triangle(Node):

    def __init__(self):
        super().__init__('triangle')
        self.publisher = self.create_publisher(Twist, 'turtle1/cmd_vel', 10)
        self.step = 0
        self.step_start = None
        self.done = False
        self.timer = self.create_timer(0.01, self.on_timer)

    def on_timer(self):
        if self.step_start is None:
            if self.publisher.get_subscription_count() == 0:
                return  # turtlesim has not matched yet
            self.step_start = self.get_clock().now()
        linear, angular, duration = STEPS[self.step]
        elapsed = (self.get_clock().now() - self.step_start).nanoseconds * 1e-9
        if elapsed < duration:
            cmd = Twist()
            cmd.linear.x = linear
            cmd.angular.z = angular
            self.publisher.publish(cmd)
            return
        self.publisher.publish(Twist())
        self.step += 1
        self.step_start = self.get_clock().now()
        if self.step == len(STEPS):
            self.timer.cancel()
            self.done = True


def main(args=None):
    rclpy.init(args=args)
    node = Triangle()
    while rclpy.ok() and not node.done:
        rclpy.spin_once(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
