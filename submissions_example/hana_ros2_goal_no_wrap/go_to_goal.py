#!/usr/bin/env python3
"""turtlesim (ROS 2): drive turtle1 to the goal typed in (x, then y) with a proportional controller on turtle1/pose,
then stop with a zero Twist. Flaw: the heading error is the plain difference of two angles in [-pi, pi], never
wrapped, so a goal across ±pi is reached the long way round (nearly a full turn)."""
import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose

TOLERANCE = 0.05  # m


class GoToGoal(Node):

    def __init__(self, x, y):
        super().__init__('go_to_goal')
        self.goal = (x, y)
        self.pose = None
        self.done = False
        self.publisher = self.create_publisher(Twist, 'turtle1/cmd_vel', 10)
        self.subscription = self.create_subscription(Pose, 'turtle1/pose', self.on_pose, 10)
        self.timer = self.create_timer(0.05, self.on_timer)

    def on_pose(self, msg):
        self.pose = msg

    def on_timer(self):
        if self.pose is None:
            return
        dx, dy = self.goal[0] - self.pose.x, self.goal[1] - self.pose.y
        distance = math.hypot(dx, dy)
        if distance < TOLERANCE:
            self.publisher.publish(Twist())
            self.get_logger().info(f'reached ({self.pose.x:.2f}, {self.pose.y:.2f})')
            self.timer.cancel()
            self.done = True
            return
        heading = math.atan2(dy, dx)
        error = heading - self.pose.theta
        cmd = Twist()
        cmd.angular.z = 4.0 * error
        cmd.linear.x = min(1.5 * distance, 2.0) if abs(error) < 0.5 else 0.0
        self.publisher.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    x = float(input('goal x: '))
    y = float(input('goal y: '))
    node = GoToGoal(x, y)
    while rclpy.ok() and not node.done:
        rclpy.spin_once(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
