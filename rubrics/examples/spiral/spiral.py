#!/usr/bin/env python3
"""Example node for the spiral task: constant speed, turn rate falling from 0.6 to 0.15 rad/s over 30 s."""

import rospy
from geometry_msgs.msg import Twist

rospy.init_node("spiral")
pub = rospy.Publisher("cmd_vel", Twist, queue_size=10)
rospy.on_shutdown(lambda: pub.publish(Twist()))
rate = rospy.Rate(10)
while rospy.get_time() == 0 and not rospy.is_shutdown():
    rate.sleep()
start = rospy.get_time()
while not rospy.is_shutdown():
    elapsed = rospy.get_time() - start
    vel = Twist()
    if elapsed < 30.0:
        vel.linear.x = 0.15
        vel.angular.z = 0.6 - 0.45 * elapsed / 30.0
    pub.publish(vel)
    rate.sleep()
