#!/usr/bin/env python3
"""Reference for obstacle_avoidance: explore the arena for 90 s without touching anything, then stop.

It follows the walls on its right at 0.35 m: the arena's outer wall leads through every corner.
"""

import math

import rospy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan

RUN_FOR = 90.0  # s
WALL = 0.35  # m from the wall on the right (as /scan reads it)
FRONT_CLEAR = 0.5  # m ahead within 25 degrees: turn left on the spot below this
SPEED = 0.25  # m/s (the Waffle's limit is 0.26)
FAR = 0.8  # m: a wall farther than this on the right is not being followed yet

sectors = None


def nearest(scan, low_deg, high_deg):
    """The least valid reading of the beams between two angles (degrees, anticlockwise, 0 ahead)."""
    found = math.inf
    for i, r in enumerate(scan.ranges):
        angle = math.degrees(math.remainder(scan.angle_min + i * scan.angle_increment, 2 * math.pi))
        if low_deg <= angle <= high_deg and scan.range_min <= r <= scan.range_max:
            found = min(found, r)
    return found


def scan_callback(scan):
    global sectors
    sectors = (nearest(scan, -25, 25), nearest(scan, -110, -30))  # ahead, right


def command(front, right):
    cmd = Twist()
    if front < FRONT_CLEAR:
        cmd.angular.z = 0.8  # a wall or an obstacle ahead: turn left on the spot
    elif right > FAR:
        cmd.linear.x = SPEED  # no wall near on the right: straight on until one is ahead, then turn left to it
    else:
        cmd.linear.x = SPEED
        cmd.angular.z = max(-0.8, min(0.8, 2.5 * (WALL - right)))  # too close: left; too far: right
    return cmd


def main():
    rospy.init_node("obstacle_avoidance")
    pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
    rospy.Subscriber("/scan", LaserScan, scan_callback, queue_size=1)
    rospy.on_shutdown(lambda: pub.publish(Twist()))
    rate = rospy.Rate(10)
    while sectors is None and not rospy.is_shutdown():
        rate.sleep()
    start = rospy.get_time()
    while not rospy.is_shutdown() and rospy.get_time() - start < RUN_FOR:
        pub.publish(command(*sectors))
        rate.sleep()
    pub.publish(Twist())
    rospy.loginfo("90 s of exploring done: stopped")
    rospy.spin()


if __name__ == "__main__":
    try:
        main()
    except rospy.ROSInterruptException:
        pass
