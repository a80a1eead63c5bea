#!/usr/bin/env python3
"""Reference for odom_subscriber in ROS 2: the robot's pose (x, y, yaw) from /odom, every 10th message."""

import rclpy
from nav_msgs.msg import Odometry
from rclpy.node import Node

from part2_navigation_modules.tb3_tools import quaternion_to_yaw


class OdomSubscriber(Node):

    def __init__(self):
        super().__init__("odom_subscriber")
        self.my_subscriber = self.create_subscription(Odometry, "odom", self.odom_callback, 10)
        self.counter = 0
        self.get_logger().info(f"The '{self.get_name()}' node is initialised.")

    def odom_callback(self, msg_data):
        pose = msg_data.pose.pose
        q = pose.orientation
        yaw = quaternion_to_yaw(q.x, q.y, q.z, q.w)
        # /odom arrives tens of times a second: print every 10th message so the output stays readable.
        if self.counter % 10 == 0:
            print(f"(x,y,θz) = ({pose.position.x:.3f}, {pose.position.y:.3f}, {yaw:.3f})")
        self.counter += 1


def main(args=None):
    rclpy.init(args=args)
    node = OdomSubscriber()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
