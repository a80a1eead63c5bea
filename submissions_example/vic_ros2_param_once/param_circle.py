#!/usr/bin/env python3
# A param_circle.py that declares the radius parameter but reads it once, in __init__: `ros2 param set` changes the
# parameter (the set succeeds) and the robot keeps its first circle.
import rclpy
from geometry_msgs.msg import TwistStamped
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions


class ParamCircle(Node):

    def __init__(self):
        super().__init__("param_circle")
        self.declare_parameter(name="radius", value=0.5)
        self.radius = self.get_parameter("radius").get_parameter_value().double_value
        self.my_publisher = self.create_publisher(TwistStamped, "cmd_vel", 10)
        self.timer = self.create_timer(0.1, self.timer_callback)
        self.shutdown = False

    def on_shutdown(self):
        self.my_publisher.publish(TwistStamped())
        self.shutdown = True

    def timer_callback(self):
        topic_msg = TwistStamped()
        topic_msg.twist.linear.x = 0.1
        topic_msg.twist.angular.z = 0.1 / self.radius
        self.my_publisher.publish(topic_msg)
        self.get_logger().info(f"Moving with radius: {self.radius:.2f} [m]", throttle_duration_sec=1)


def main(args=None):
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    node = ParamCircle()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.on_shutdown()
        while not node.shutdown:
            continue
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
