#!/usr/bin/env python3
"""Drives a perfect 0.5 m circle for 10 s, then hangs in a blocking call outside the client library."""
import os
import rospy
from geometry_msgs.msg import Twist
rospy.init_node("move_circle")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
rate = rospy.Rate(10)
vel = Twist()
vel.linear.x = 0.1
vel.angular.z = 0.2
for _ in range(100):
    pub.publish(vel)
    rate.sleep()
read_end, _write_end = os.pipe()
os.read(read_end, 1)  # nobody ever writes: hangs without yielding to the grader
