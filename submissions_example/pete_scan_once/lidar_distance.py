#!/usr/bin/env python3
# Reads /scan once, before the loop, and prints that same reading every second: the loop never re-reads the scan.
import math

import rospy
from sensor_msgs.msg import LaserScan

rospy.init_node("lidar_distance")
scan = rospy.wait_for_message("/scan", LaserScan)
rate = rospy.Rate(1)
while not rospy.is_shutdown():
    nearest, angle = float("inf"), 0.0
    for i, r in enumerate(scan.ranges):
        a = math.degrees(math.remainder(scan.angle_min + i * scan.angle_increment, 2 * math.pi))
        if abs(a) <= 20 and scan.range_min <= r <= scan.range_max and r < nearest:
            nearest, angle = r, a
    print("Nearest object ahead: %.3f m at %.1f degrees" % (nearest, angle))
    rate.sleep()
