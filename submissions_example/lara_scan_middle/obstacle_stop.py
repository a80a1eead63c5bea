#!/usr/bin/env python3
# Takes the middle beam, ranges[180], as "ahead", as on a scanner whose angles run from -pi to pi. The TurtleBot3's
# scan starts at angle_min = 0 (straight ahead), so ranges[180] looks behind: the robot drives on into the wall.
import rospy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan

ahead = None


def callback(scan):
    global ahead
    ahead = scan.ranges[len(scan.ranges) // 2]


rospy.init_node("obstacle_stop")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
rospy.Subscriber("/scan", LaserScan, callback)
rate = rospy.Rate(10)
while not rospy.is_shutdown():
    cmd = Twist()
    if ahead is not None and ahead > 0.5:
        cmd.linear.x = 0.2
    pub.publish(cmd)
    rate.sleep()
