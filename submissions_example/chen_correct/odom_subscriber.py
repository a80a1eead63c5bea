#!/usr/bin/env python3
import math
import rospy
from nav_msgs.msg import Odometry
from tf.transformations import euler_from_quaternion


def callback(msg):
    p = msg.pose.pose.position
    q = msg.pose.pose.orientation
    yaw = euler_from_quaternion([q.x, q.y, q.z, q.w])[2]
    rospy.loginfo_throttle(1.0, "x=%.2f [m], y=%.2f [m], yaw=%.1f [degrees]." % (p.x, p.y, math.degrees(yaw)))


rospy.init_node("odom_subscriber")
rospy.Subscriber("/odom", Odometry, callback)
rospy.spin()
