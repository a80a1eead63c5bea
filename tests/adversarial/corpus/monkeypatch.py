#!/usr/bin/env python3
"""Monkeypatches the client library and publishes fake odometry, hoping to be scored on it."""
import time
import rospy
import rosgrade_node.runtime as rt
from nav_msgs.msg import Odometry
from geometry_msgs.msg import Twist

rospy.init_node("cheater")
time.time = lambda: 1e12
rospy.get_time = lambda: 1e12
odom = rospy.Publisher("/odom", Odometry, queue_size=10)
cmd = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
rate = rospy.Rate(10)
fake = Odometry()
while not rospy.is_shutdown():
    fake.pose.pose.position.x += 1.0
    odom.publish(fake)
    cmd.publish(Twist())
    rate.sleep()
