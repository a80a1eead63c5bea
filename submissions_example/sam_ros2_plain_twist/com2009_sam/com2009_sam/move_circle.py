# move_circle from a Humble tutorial: geometry_msgs/msg/Twist on cmd_vel. The Jazzy TurtleBot3 only drives on
# TwistStamped, so the robot never moves, although the shutdown procedure is right.

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions


class Circle(Node):

    def __init__(self):
        super().__init__("move_circle")
        self.my_publisher = self.create_publisher(Twist, "cmd_vel", 10)
        self.timer = self.create_timer(0.1, self.timer_callback)
        self.shutdown = False

    def timer_callback(self):
        msg = Twist()
        msg.linear.x = 0.1
        msg.angular.z = 0.1 / 0.5
        self.my_publisher.publish(msg)
        self.get_logger().info(f"v = {msg.linear.x:.2f} m/s, w = {msg.angular.z:.2f} rad/s", throttle_duration_sec=1)

    def on_shutdown(self):
        self.my_publisher.publish(Twist())
        self.shutdown = True


def main(args=None):
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    node = Circle()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.on_shutdown()
        node.destroy_node()
        rclpy.shutdown()
