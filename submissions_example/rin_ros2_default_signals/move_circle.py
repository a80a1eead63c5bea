#!/usr/bin/env python3
# A ROS 2 move_circle with rclpy's default signal handlers: Ctrl+C shuts rclpy down before the except block runs,
# so the zero command fails with "publisher's context is invalid" and the robot keeps circling.

import rclpy
from geometry_msgs.msg import TwistStamped
from rclpy.node import Node


class Circle(Node):

    def __init__(self):
        super().__init__("move_circle")
        self.my_publisher = self.create_publisher(TwistStamped, "cmd_vel", 10)
        self.timer = self.create_timer(0.1, self.timer_callback)
        self.get_logger().info(f"The '{self.get_name()}' node is initialised.")

    def timer_callback(self):
        msg = TwistStamped()
        msg.twist.linear.x = 0.1
        msg.twist.angular.z = 0.2
        self.my_publisher.publish(msg)

    def on_shutdown(self):
        self.get_logger().info("Stopping the robot...")
        self.my_publisher.publish(TwistStamped())


def main(args=None):
    rclpy.init(args=args)
    node = Circle()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        node.on_shutdown()
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
