#!/usr/bin/env python3
"""turtle_circle in rclpy: Twist on turtle1/cmd_vel at 10 Hz, 2.0 m/s and 1.8 rad/s, until Ctrl+C."""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions


class Circle(Node):

    def __init__(self):
        super().__init__('turtle_circle')
        self.pub = self.create_publisher(Twist, 'turtle1/cmd_vel', 10)
        self.create_timer(0.1, self.tick)

    def tick(self):
        command = Twist()
        command.linear.x = 2.0
        command.angular.z = 1.8
        self.pub.publish(command)


def main(args=None):
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    node = Circle()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.pub.publish(Twist())
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
