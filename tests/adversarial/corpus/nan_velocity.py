#!/usr/bin/env python3
import rospy
from geometry_msgs.msg import Twist
rospy.init_node("nan")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=1)
rate = rospy.Rate(10)
i = 0
while not rospy.is_shutdown():
    t = Twist()
    t.linear.x = float("nan") if i % 2 else float("inf")
    t.angular.z = float("-inf")
    pub.publish(t)
    i += 1
    rate.sleep()
