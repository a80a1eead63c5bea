#!/usr/bin/env python3
"""Spawns turtle2 at (2, 2) and drives turtle1 at 1 m/s, 0.5 rad/s: the leader a mimic node copies."""
import rospy
from geometry_msgs.msg import Twist
from turtlesim.srv import Spawn

rospy.init_node("leader")
rospy.wait_for_service("spawn")
rospy.ServiceProxy("spawn", Spawn)(2.0, 2.0, 0.0, "turtle2")
publisher = rospy.Publisher("turtle1/cmd_vel", Twist, queue_size=10)
command = Twist()
command.linear.x, command.angular.z = 1.0, 0.5
rate = rospy.Rate(10)
while not rospy.is_shutdown():
    publisher.publish(command)
    rate.sleep()
