#!/usr/bin/env python3
# Turtle in a big circle. Flaw: v/ω = 3.0 / 0.5 = 6 m, wider than the 11 m window allows.
import rospy
from geometry_msgs.msg import Twist

rospy.init_node('turtle_circle')
pub = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=10)
rate = rospy.Rate(10)
vel = Twist()
vel.linear.x = 3.0
vel.angular.z = 0.5
while not rospy.is_shutdown():
    pub.publish(vel)
    rate.sleep()
