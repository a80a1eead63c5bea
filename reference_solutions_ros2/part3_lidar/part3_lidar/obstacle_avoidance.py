#!/usr/bin/env python3
"""Reference for obstacle_avoidance in ROS 2 (Jazzy): explore the arena for 90 s without touching anything, then stop.

It follows the walls on its right at 0.35 m: the arena's outer wall leads through every corner.
"""

import math

import rclpy
from geometry_msgs.msg import TwistStamped
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from rclpy.signals import SignalHandlerOptions
from sensor_msgs.msg import LaserScan

RUN_FOR = 90.0  # s
WALL = 0.35  # m from the wall on the right (as /scan reads it)
FRONT_CLEAR = 0.5  # m ahead within 25 degrees: turn left on the spot below this
SPEED = 0.25  # m/s (the Waffle's limit is 0.26)
FAR = 0.8  # m: a wall farther than this on the right is not being followed yet


def nearest(scan, low_deg, high_deg):
    """The least valid reading of the beams between two angles (degrees, anticlockwise, 0 ahead)."""
    found = math.inf
    for i, r in enumerate(scan.ranges):
        angle = math.degrees(math.remainder(scan.angle_min + i * scan.angle_increment, 2 * math.pi))
        if low_deg <= angle <= high_deg and scan.range_min <= r <= scan.range_max:
            found = min(found, r)
    return found


class ObstacleAvoidance(Node):

    def __init__(self):
        super().__init__("obstacle_avoidance")
        self.cmd_pub = self.create_publisher(TwistStamped, "cmd_vel", 10)
        # Sensor-data QoS (best effort) hears the simulation's reliable /scan and the real robot's best-effort one
        self.create_subscription(LaserScan, "scan", self.scan_callback, qos_profile_sensor_data)
        self.timer = self.create_timer(0.1, self.timer_callback)  # 10 Hz
        self.sectors = None
        self.start = None
        self.done = False

    def scan_callback(self, scan):
        self.sectors = (nearest(scan, -25, 25), nearest(scan, -110, -30))  # ahead, right

    def publish(self, linear, angular):
        cmd = TwistStamped()
        cmd.header.stamp = self.get_clock().now().to_msg()
        cmd.twist.linear.x = linear
        cmd.twist.angular.z = angular
        self.cmd_pub.publish(cmd)

    def timer_callback(self):
        if self.sectors is None or self.done:
            return
        now = self.get_clock().now().nanoseconds / 1e9
        if self.start is None:
            self.start = now
        if now - self.start >= RUN_FOR:
            self.done = True
            self.publish(0.0, 0.0)
            self.get_logger().info("90 s of exploring done: stopped")
            return
        front, right = self.sectors
        if front < FRONT_CLEAR:
            self.publish(0.0, 0.8)  # a wall or an obstacle ahead: turn left on the spot
        elif right > FAR:
            self.publish(SPEED, 0.0)  # no wall near on the right: straight on until one is ahead, then turn left
        else:
            self.publish(SPEED, max(-0.8, min(0.8, 2.5 * (WALL - right))))  # too close: left; too far: right


def main(args=None):
    # Without the default signal handlers the context stays valid after Ctrl+C, so the zero still goes out.
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    node = ObstacleAvoidance()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.publish(0.0, 0.0)
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
