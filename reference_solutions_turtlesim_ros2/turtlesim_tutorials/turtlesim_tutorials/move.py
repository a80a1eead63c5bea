#!/usr/bin/env python3
"""turtlesim (ROS 2): move turtle1 a distance at a speed, forwards or backwards, as typed in (the wiki's "Moving in a
Straight Line" in rclpy); a timer publishes the Twist until speed × elapsed time reaches the distance, then a zero."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Mover(Node):

    def __init__(self, speed, distance, forward):
        super().__init__('move')
        self.publisher = self.create_publisher(Twist, 'turtle1/cmd_vel', 10)
        self.speed = abs(speed)
        self.distance = distance
        self.cmd = Twist()
        self.cmd.linear.x = self.speed if forward else -self.speed
        self.start = None
        self.done = False
        self.timer = self.create_timer(0.01, self.on_timer)

    def on_timer(self):
        if self.start is None:
            if self.publisher.get_subscription_count() == 0:
                return  # turtlesim has not matched yet: a message published now would be lost
            self.start = self.get_clock().now()
        elapsed = (self.get_clock().now() - self.start).nanoseconds * 1e-9
        if self.speed * elapsed < self.distance:
            self.publisher.publish(self.cmd)
            return
        self.publisher.publish(Twist())
        self.timer.cancel()
        self.done = True


def main(args=None):
    rclpy.init(args=args)
    print("Let's move your robot")
    speed = float(input('Input your speed: '))
    distance = float(input('Type your distance: '))
    forward = input('Forward? (1/0): ').strip() in ('1', 'y', 'yes', 'True', 'true')
    node = Mover(speed, distance, forward)
    while rclpy.ok() and not node.done:
        rclpy.spin_once(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
