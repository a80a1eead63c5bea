#!/usr/bin/env python3
"""Reference for obstacle_stop in ROS 2 (Jazzy): drive ahead, stop when /scan reads the wall 0.5 m ahead."""

import math

import rclpy
from geometry_msgs.msg import TwistStamped
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from rclpy.signals import SignalHandlerOptions
from sensor_msgs.msg import LaserScan

STOP_AT = 0.5  # m, as /scan reads it straight ahead
HALF_WIDTH = math.radians(10)  # the beams within 10 degrees either side of straight ahead


class ObstacleStop(Node):

    def __init__(self):
        super().__init__("obstacle_stop")
        self.cmd_pub = self.create_publisher(TwistStamped, "cmd_vel", 10)
        # Sensor-data QoS (best effort) hears the simulation's reliable /scan and the real robot's best-effort one
        self.create_subscription(LaserScan, "scan", self.scan_callback, qos_profile_sensor_data)
        self.timer = self.create_timer(0.1, self.timer_callback)  # 10 Hz
        self.ahead = None
        self.stopped = False

    def scan_callback(self, scan):
        # angle_min is 0 on a TurtleBot3: the beams from both ends of the array look straight ahead
        valid = [r for i, r in enumerate(scan.ranges)
                 if abs(math.remainder(scan.angle_min + i * scan.angle_increment, 2 * math.pi)) <= HALF_WIDTH
                 and scan.range_min <= r <= scan.range_max]  # inf (nothing in range) and 0 are not distances
        self.ahead = min(valid) if valid else math.inf

    def publish(self, speed):
        cmd = TwistStamped()
        cmd.header.stamp = self.get_clock().now().to_msg()
        cmd.twist.linear.x = speed
        self.cmd_pub.publish(cmd)

    def timer_callback(self):
        if self.ahead is None or self.stopped:
            return
        remaining = self.ahead - STOP_AT
        if remaining <= 0.0:
            self.get_logger().info(f"Wall {self.ahead:.2f} m ahead: stopping")
            self.stopped = True
            self.publish(0.0)
            return
        self.publish(min(0.2, max(0.03, 0.5 * remaining)))  # slow down over the last 40 cm (the scan is 5 Hz)


def main(args=None):
    # Without the default signal handlers the context stays valid after Ctrl+C, so the zero still goes out.
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    node = ObstacleStop()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.publish(0.0)
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
