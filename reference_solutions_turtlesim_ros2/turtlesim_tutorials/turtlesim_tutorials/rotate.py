#!/usr/bin/env python3
"""turtlesim (ROS 2): rotate turtle1 by an angle at a speed, both typed in degrees, clockwise or not (the wiki's
"Rotating Left and Right" in rclpy), then stop it with a zero Twist."""
import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Rotator(Node):

    def __init__(self, speed_deg, angle_deg, clockwise):
        super().__init__('rotate')
        self.publisher = self.create_publisher(Twist, 'turtle1/cmd_vel', 10)
        self.angular_speed = math.radians(abs(speed_deg))
        self.relative_angle = math.radians(angle_deg)
        self.cmd = Twist()
        self.cmd.angular.z = -self.angular_speed if clockwise else self.angular_speed
        self.start = None
        self.done = False
        self.timer = self.create_timer(0.01, self.on_timer)

    def on_timer(self):
        if self.start is None:
            if self.publisher.get_subscription_count() == 0:
                return  # turtlesim has not matched yet
            self.start = self.get_clock().now()
        elapsed = (self.get_clock().now() - self.start).nanoseconds * 1e-9
        if self.angular_speed * elapsed < self.relative_angle:
            self.publisher.publish(self.cmd)
            return
        self.publisher.publish(Twist())
        self.timer.cancel()
        self.done = True


def main(args=None):
    rclpy.init(args=args)
    print("Let's rotate your robot")
    speed = float(input('Input your speed (degrees/sec): '))
    angle = float(input('Type your distance (degrees): '))
    clockwise = input('Clockwise? (1/0): ').strip() in ('1', 'y', 'yes', 'True', 'true')
    node = Rotator(speed, angle, clockwise)
    while rclpy.ok() and not node.done:
        rclpy.spin_once(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
