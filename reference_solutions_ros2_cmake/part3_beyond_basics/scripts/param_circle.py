#!/usr/bin/env python3
"""Reference for param_circle in ROS 2 (Jazzy): move_circle with its radius a parameter, read at every tick, so that
`ros2 param set /param_circle radius 1.2` changes the circle while the node runs; a zero on Ctrl+C."""

import rclpy
from geometry_msgs.msg import TwistStamped
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions


class ParamCircle(Node):

    def __init__(self):
        super().__init__("param_circle")
        self.declare_parameter(name="radius", value=0.5)  # m
        self.my_publisher = self.create_publisher(TwistStamped, "cmd_vel", 10)
        self.timer = self.create_timer(0.1, self.timer_callback)  # 10 Hz
        self.shutdown = False
        self.get_logger().info(f"The '{self.get_name()}' node is initialised.")

    def on_shutdown(self):
        # Stop the robot: the base keeps the last command it was given.
        self.get_logger().info("Stopping the robot...")
        self.my_publisher.publish(TwistStamped())
        self.shutdown = True

    def timer_callback(self):
        # read here, not in __init__: a set while the node runs takes effect at the next tick
        radius = self.get_parameter("radius").get_parameter_value().double_value
        linear_velocity = 0.1  # m/s, below the 0.26 m/s limit
        angular_velocity = linear_velocity / radius  # rad/s: v = r * omega

        topic_msg = TwistStamped()
        topic_msg.header.stamp = self.get_clock().now().to_msg()
        topic_msg.twist.linear.x = linear_velocity
        topic_msg.twist.angular.z = angular_velocity
        self.my_publisher.publish(topic_msg)
        self.get_logger().info(
            f"Moving with radius: {radius:.2f} [m]\n"
            f"Linear Velocity: {topic_msg.twist.linear.x:.2f} [m/s], "
            f"Angular Velocity: {topic_msg.twist.angular.z:.2f} [rad/s].",
            throttle_duration_sec=1)


def main(args=None):
    # Without the default signal handlers the context stays valid after Ctrl+C, so the zero still goes out.
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    node = ParamCircle()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        print(f"{node.get_name()} received a shutdown request (Ctrl+C).")
    finally:
        node.on_shutdown()
        while not node.shutdown:
            continue
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
