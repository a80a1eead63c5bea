#!/usr/bin/env python3
# Runs its control loop inside the constructor with time.sleep and never spins: the /scan callback never runs, so
# the loop drives on what it assumed before any scan arrived (nothing ahead) until the robot meets a wall.
import math
import time

import rclpy
from geometry_msgs.msg import TwistStamped
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from sensor_msgs.msg import LaserScan


class ObstacleAvoidance(Node):
    def __init__(self):
        super().__init__("obstacle_avoidance")
        self.pub = self.create_publisher(TwistStamped, "cmd_vel", 10)
        self.create_subscription(LaserScan, "scan", self.callback, qos_profile_sensor_data)
        self.ahead = math.inf
        start = time.time()
        while time.time() - start < 90:
            cmd = TwistStamped()
            if self.ahead < 0.5:
                cmd.twist.angular.z = 0.8
            else:
                cmd.twist.linear.x = 0.2
            self.pub.publish(cmd)
            time.sleep(0.1)
        self.pub.publish(TwistStamped())

    def callback(self, scan):
        ahead = [r for r in list(scan.ranges[:25]) + list(scan.ranges[-25:]) if scan.range_min <= r <= scan.range_max]
        self.ahead = min(ahead) if ahead else math.inf


def main():
    rclpy.init()
    rclpy.spin(ObstacleAvoidance())


if __name__ == "__main__":
    main()
