#!/usr/bin/env python3
# Looks for obstacles with one beam only, ranges[0] (straight ahead): a box or pillar beside the path is never seen,
# and the robot's side runs into it.
import rospy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan

ahead = 10.0


def callback(scan):
    global ahead
    ahead = scan.ranges[0]


rospy.init_node("obstacle_avoidance")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
rospy.Subscriber("/scan", LaserScan, callback)
rate = rospy.Rate(10)
start = rospy.get_time()
while not rospy.is_shutdown() and rospy.get_time() - start < 90:
    cmd = Twist()
    if ahead < 0.5:
        cmd.angular.z = 0.8
    else:
        cmd.linear.x = 0.22
        cmd.angular.z = 0.15
    pub.publish(cmd)
    rate.sleep()
pub.publish(Twist())
