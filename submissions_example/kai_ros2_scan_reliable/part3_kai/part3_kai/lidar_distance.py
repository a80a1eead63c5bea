#!/usr/bin/env python3
# Subscribes to /scan with an explicitly RELIABLE profile. The Jazzy simulation's bridge publishes /scan RELIABLE, so
# this hears it and scores full marks here; on the real TurtleBot3, whose LiDAR driver publishes best effort, it would
# hear nothing (a mistake the simulation cannot show: qos_profile_sensor_data works on both).
import math

import rclpy
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy
from sensor_msgs.msg import LaserScan


class LidarDistance(Node):
    def __init__(self):
        super().__init__("lidar_distance")
        qos = QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE)
        self.create_subscription(LaserScan, "scan", self.callback, qos)

    def callback(self, scan):
        nearest, angle = float("inf"), 0.0
        for i, r in enumerate(scan.ranges):
            a = math.degrees(math.remainder(scan.angle_min + i * scan.angle_increment, 2 * math.pi))
            if abs(a) <= 20 and scan.range_min <= r <= scan.range_max and r < nearest:
                nearest, angle = r, a
        self.get_logger().info(f"Nearest object ahead: {nearest:.3f} m at {angle:.1f} degrees")


def main():
    rclpy.init()
    node = LidarDistance()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass


if __name__ == "__main__":
    main()
