#!/usr/bin/env python3
"""Reference for obstacle_stop: drive ahead and stop when /scan reads the wall 0.5 m ahead."""

import math

import rospy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan

STOP_AT = 0.5  # m, as /scan reads it straight ahead
HALF_WIDTH = math.radians(10)  # the beams within 10 degrees either side of straight ahead

ahead = None


def scan_callback(scan):
    global ahead
    # angle_min is 0 on a TurtleBot3: the beams from both ends of the array look straight ahead
    valid = [r for i, r in enumerate(scan.ranges)
             if abs(math.remainder(scan.angle_min + i * scan.angle_increment, 2 * math.pi)) <= HALF_WIDTH
             and scan.range_min <= r <= scan.range_max]  # inf (nothing in range) and 0 (no return) are not distances
    ahead = min(valid) if valid else math.inf


def main():
    rospy.init_node("obstacle_stop")
    pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
    rospy.Subscriber("/scan", LaserScan, scan_callback, queue_size=1)
    rospy.on_shutdown(lambda: pub.publish(Twist()))
    rate = rospy.Rate(10)
    while ahead is None and not rospy.is_shutdown():  # wait for the first scan
        rate.sleep()
    while not rospy.is_shutdown():
        remaining = ahead - STOP_AT
        if remaining <= 0.0:
            rospy.loginfo("Wall %.2f m ahead: stopping", ahead)
            break
        cmd = Twist()
        cmd.linear.x = min(0.2, max(0.03, 0.5 * remaining))  # slow down over the last 40 cm (the scan is 5 Hz)
        pub.publish(cmd)
        rate.sleep()
    pub.publish(Twist())
    rospy.spin()  # stay up, the robot stopped, until Ctrl+C


if __name__ == "__main__":
    try:
        main()
    except rospy.ROSInterruptException:
        pass
