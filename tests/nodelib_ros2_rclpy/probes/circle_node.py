"""A course-style class node: TwistStamped publisher, /odom subscriber, 10 Hz timer, spin, Ctrl+C handling."""
import sys

import rclpy
from geometry_msgs.msg import TwistStamped
from nav_msgs.msg import Odometry
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions


class Circle(Node):
    def __init__(self):
        super().__init__("move_circle")
        self.pub = self.create_publisher(TwistStamped, "cmd_vel", 10)
        self.sub = self.create_subscription(Odometry, "/odom", self.odom_cb, 10)
        self.timer = self.create_timer(0.1, self.tick)
        self.ticks = 0
        self.get_logger().info(f"init now={self.get_clock().now()}")

    def odom_cb(self, msg):
        print(f"odom x={msg.pose.pose.position.x:.2f} now={self.get_clock().now().nanoseconds}")

    def tick(self):
        self.ticks += 1
        msg = TwistStamped()
        msg.header.stamp = self.get_clock().now().to_msg()
        msg.twist.linear.x = 0.1
        self.pub.publish(msg)
        self.get_logger().info(f"tick {self.ticks}", throttle_duration_sec=1.0)


def main():
    mode = sys.argv[1]
    rclpy.init(args=sys.argv, signal_handler_options=SignalHandlerOptions.NO if mode == "no" else None)
    node = Circle()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt as e:
        print(f"CAUGHT {e!r} ok={rclpy.ok()}")
        try:
            node.pub.publish(TwistStamped())
            print("PUBLISH in except: ok")
        except Exception as exc:
            print(f"PUBLISH in except: {type(exc).__module__}.{type(exc).__name__}: {exc}")
        node.get_logger().info("Stopping the robot...")
    finally:
        node.destroy_node()
        rclpy.try_shutdown()
        print("done")


if __name__ == "__main__":
    main()
