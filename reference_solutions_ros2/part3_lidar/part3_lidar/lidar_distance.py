#!/usr/bin/env python3
"""Reference for lidar_distance in ROS 2 (Jazzy): print the distance and direction of the nearest object ahead."""

import math

import rclpy
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from rclpy.signals import SignalHandlerOptions
from sensor_msgs.msg import LaserScan

HALF_WIDTH = math.radians(20)  # the beams within 20 degrees either side of straight ahead


class LidarDistance(Node):

    def __init__(self):
        super().__init__("lidar_distance")
        # Sensor-data QoS (best effort) hears the simulation's reliable /scan and the real robot's best-effort one
        self.create_subscription(LaserScan, "scan", self.scan_callback, qos_profile_sensor_data)

    def scan_callback(self, scan):
        nearest, direction = math.inf, 0.0
        for i, r in enumerate(scan.ranges):
            # angle_min is 0 on a TurtleBot3: beam i looks i * angle_increment anticlockwise of ahead
            angle = math.remainder(scan.angle_min + i * scan.angle_increment, 2 * math.pi)
            if abs(angle) <= HALF_WIDTH and scan.range_min <= r <= scan.range_max and r < nearest:
                nearest, direction = r, angle  # inf (nothing in range) and 0 (no return) are never the nearest
        if math.isinf(nearest):
            self.get_logger().info("Nothing within range ahead")
        else:
            self.get_logger().info(
                f"Nearest object ahead: {nearest:.3f} m at {math.degrees(direction):.1f} degrees")


def main(args=None):
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    node = LidarDistance()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
