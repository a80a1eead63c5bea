#!/usr/bin/env python3
# Steers by one beam, ranges[90] (straight to the left), and never looks ahead: where the corridor turns right it
# drives into the wall in front.
import rospy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan

left = None


def callback(scan):
    global left
    left = scan.ranges[90]


rospy.init_node("wall_follower")
desired = float(rospy.get_param("~desired_distance", 0.5))
speed = float(rospy.get_param("~velocity", 0.15))
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
rospy.Subscriber("/scan", LaserScan, callback)
rate = rospy.Rate(10)
while not rospy.is_shutdown():
    if left is not None:
        cmd = Twist()
        cmd.linear.x = speed
        cmd.angular.z = max(-1.0, min(1.0, 2.0 * (min(left, 2 * desired) - desired)))
        pub.publish(cmd)
    rate.sleep()
