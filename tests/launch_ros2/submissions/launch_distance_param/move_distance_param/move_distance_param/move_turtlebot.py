#!/usr/bin/env python3
"""move_turtlebot in ROS 2 with parameters speed and distance: drive along x until odometry x >= distance, then stop."""


import rclpy
from geometry_msgs.msg import TwistStamped
from nav_msgs.msg import Odometry
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions


class Mover(Node):

    def __init__(self):
        super().__init__('move_turtlebot')
        self.speed = self.declare_parameter('speed', 0.1).value
        self.distance = self.declare_parameter('distance', 1.0).value
        self.get_logger().info(f'Driving to x = {self.distance} m at {self.speed} m/s')
        self.done = False
        self.pub = self.create_publisher(TwistStamped, 'cmd_vel', 10)
        self.create_subscription(Odometry, 'odom', self.odom_callback, 10)

    def odom_callback(self, msg):
        robot_x = msg.pose.pose.position.x
        command = TwistStamped()
        command.header.stamp = self.get_clock().now().to_msg()
        if not self.done and robot_x >= self.distance:
            self.get_logger().info(f'Reached x = {robot_x:.3f} m')
            self.done = True
        if not self.done:
            command.twist.linear.x = self.speed
        self.pub.publish(command)


def main(args=None):
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    node = Mover()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.pub.publish(TwistStamped())
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
