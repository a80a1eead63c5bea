#!/usr/bin/env python3
"""turtlesim (ROS 2): grid cleaning: go to the lower-left corner, then sweep the window in rows 0.5 m apart, each
waypoint reached by a go-to-goal controller on turtle1/pose in a timer; a zero Twist at the end."""
import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose

LOW, HIGH = 0.5, 10.5  # m: the sweep keeps this far from the walls
ROW = 0.5  # m between rows
TOLERANCE = 0.05  # m


def waypoints():
    """Lower-left corner, then a back-and-forth sweep upwards."""
    points, y, rightwards = [], LOW, True
    while y <= HIGH + 1e-9:
        points += [(LOW, y), (HIGH, y)] if rightwards else [(HIGH, y), (LOW, y)]
        y += ROW
        rightwards = not rightwards
    return points


class GridCleaner(Node):

    def __init__(self):
        super().__init__('grid_cleaner')
        self.points = waypoints()
        self.pose = None
        self.done = False
        self.publisher = self.create_publisher(Twist, 'turtle1/cmd_vel', 10)
        self.subscription = self.create_subscription(Pose, 'turtle1/pose', self.on_pose, 10)
        self.timer = self.create_timer(0.02, self.on_timer)

    def on_pose(self, msg):
        self.pose = msg

    def on_timer(self):
        if self.pose is None:
            return
        x, y = self.points[0]
        distance = math.hypot(x - self.pose.x, y - self.pose.y)
        if distance < TOLERANCE:
            self.points.pop(0)
            if not self.points:
                self.publisher.publish(Twist())
                self.get_logger().info('cleaning done')
                self.timer.cancel()
                self.done = True
            return
        heading = math.atan2(y - self.pose.y, x - self.pose.x)
        error = math.atan2(math.sin(heading - self.pose.theta), math.cos(heading - self.pose.theta))
        cmd = Twist()
        cmd.angular.z = 6.0 * error
        cmd.linear.x = min(2.0 * distance, 4.0) if abs(error) < 0.2 else 0.0
        self.publisher.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    node = GridCleaner()
    while rclpy.ok() and not node.done:
        rclpy.spin_once(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
