#!/usr/bin/env python3
"""Reference for wall_follower in ROS 2 (Jazzy): follow the wall on the side the parameters name, at their distance
and speed."""

import math

import rclpy
from geometry_msgs.msg import TwistStamped
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from rclpy.signals import SignalHandlerOptions
from sensor_msgs.msg import LaserScan

GAIN = 3.0  # rad/s per metre of distance error
MAX_TURN = 1.5  # rad/s


def nearest(scan, low_deg, high_deg):
    """The least valid reading of the beams between two angles (degrees, anticlockwise, 0 ahead)."""
    found = math.inf
    for i, r in enumerate(scan.ranges):
        angle = math.degrees(math.remainder(scan.angle_min + i * scan.angle_increment, 2 * math.pi))
        if low_deg <= angle <= high_deg and scan.range_min <= r <= scan.range_max:
            found = min(found, r)
    return found


class WallFollower(Node):

    def __init__(self):
        super().__init__("wall_follower")
        self.side = 1 if self.declare_parameter("side", "left").value == "left" else -1
        self.desired = float(self.declare_parameter("desired_distance", 0.5).value)
        self.speed = float(self.declare_parameter("velocity", 0.15).value)
        self.cmd_pub = self.create_publisher(TwistStamped, "cmd_vel", 10)
        # Sensor-data QoS (best effort) hears the simulation's reliable /scan and the real robot's best-effort one
        self.create_subscription(LaserScan, "scan", self.scan_callback, qos_profile_sensor_data)
        self.timer = self.create_timer(0.1, self.timer_callback)  # 10 Hz
        self.latest = None

    def scan_callback(self, scan):
        self.latest = scan

    def publish(self, linear, angular):
        cmd = TwistStamped()
        cmd.header.stamp = self.get_clock().now().to_msg()
        cmd.twist.linear.x = linear
        cmd.twist.angular.z = angular
        self.cmd_pub.publish(cmd)

    def timer_callback(self):
        if self.latest is None:
            return
        ahead = nearest(self.latest, -25, 25)
        beside = nearest(self.latest, 60, 120) if self.side > 0 else nearest(self.latest, -120, -60)
        if ahead < self.desired + 0.2:  # the wall turns in front: turn away from the followed side on the spot
            self.publish(0.0, -self.side * MAX_TURN)
            return
        error = min(beside, 2 * self.desired) - self.desired  # no wall beside (inf): curve round towards it
        self.publish(self.speed, self.side * max(-MAX_TURN, min(MAX_TURN, GAIN * error)))


def main(args=None):
    # Without the default signal handlers the context stays valid after Ctrl+C, so the zero still goes out.
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    node = WallFollower()
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
