#!/usr/bin/env python3
"""Follow the left wall at the distance and speed the parameters give."""

import math

import rospy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan

GAIN = 3.0  # rad/s per metre of distance error
MAX_TURN = 1.5  # rad/s

latest = None


def nearest(scan, low_deg, high_deg):
    """The least valid reading of the beams between two angles (degrees, anticlockwise, 0 ahead)."""
    found = math.inf
    for i, r in enumerate(scan.ranges):
        angle = math.degrees(math.remainder(scan.angle_min + i * scan.angle_increment, 2 * math.pi))
        if low_deg <= angle <= high_deg and scan.range_min <= r <= scan.range_max:
            found = min(found, r)
    return found


def scan_callback(scan):
    global latest
    latest = scan


def command(scan, side, desired, speed):
    """side +1 follows the left wall, -1 the right one."""
    ahead = nearest(scan, -25, 25)
    beside = nearest(scan, 60, 120) if side > 0 else nearest(scan, -120, -60)
    cmd = Twist()
    if ahead < desired + 0.2:  # the wall turns in front: turn away from the followed side on the spot
        cmd.angular.z = -side * MAX_TURN
        return cmd
    error = min(beside, 2 * desired) - desired  # no wall beside (inf): curve round towards where it went
    cmd.linear.x = speed
    cmd.angular.z = side * max(-MAX_TURN, min(MAX_TURN, GAIN * error))
    return cmd


def main():
    rospy.init_node("wall_follower")
    side = 1  # the lab's first test follows the left wall
    desired = float(rospy.get_param("~desired_distance", 0.5))
    speed = float(rospy.get_param("~velocity", 0.15))
    pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
    rospy.Subscriber("/scan", LaserScan, scan_callback, queue_size=1)
    rospy.on_shutdown(lambda: pub.publish(Twist()))
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        if latest is not None:
            pub.publish(command(latest, side, desired, speed))
        rate.sleep()


if __name__ == "__main__":
    try:
        main()
    except rospy.ROSInterruptException:
        pass
