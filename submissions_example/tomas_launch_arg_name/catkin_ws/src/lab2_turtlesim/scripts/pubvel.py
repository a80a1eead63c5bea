#!/usr/bin/env python3
# Publishes random velocities so the turtle wanders around
import random

import rospy
from geometry_msgs.msg import Twist

rospy.init_node("publish_velocity")
pub = rospy.Publisher("turtle1/cmd_vel", Twist, queue_size=1000)
rate = rospy.Rate(2)
while not rospy.is_shutdown():
    msg = Twist()
    msg.linear.x = 1.0 + random.random()  # between 1 and 2 m/s
    msg.angular.z = 2 * random.random() - 1
    pub.publish(msg)
    rate.sleep()
