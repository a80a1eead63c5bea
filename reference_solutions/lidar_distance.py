#!/usr/bin/env python3
"""Reference for lidar_distance: print the distance and direction of the nearest object within 20° ahead."""

import math

import rospy
from sensor_msgs.msg import LaserScan

HALF_WIDTH = math.radians(20)  # the beams within 20 degrees either side of straight ahead


def scan_callback(scan):
    nearest, direction = math.inf, 0.0
    for i, r in enumerate(scan.ranges):
        # angle_min is 0 on a TurtleBot3: beam i looks i * angle_increment anticlockwise of ahead
        angle = math.remainder(scan.angle_min + i * scan.angle_increment, 2 * math.pi)
        if abs(angle) <= HALF_WIDTH and scan.range_min <= r <= scan.range_max and r < nearest:
            nearest, direction = r, angle  # inf (nothing in range) and 0 (no return) are never the nearest
    if math.isinf(nearest):
        print("Nothing within range ahead")
    else:
        print(f"Nearest object ahead: {nearest:.3f} m at {math.degrees(direction):.1f} degrees")


def main():
    rospy.init_node("lidar_distance")
    rospy.Subscriber("/scan", LaserScan, scan_callback, queue_size=1)
    rospy.spin()


if __name__ == "__main__":
    main()
