#!/usr/bin/env python3
# Turtle in a circle, like `rostopic pub -1 /turtle1/cmd_vel ... '[2.0, 0.0, 0.0]' '[0.0, 0.0, 1.8]'`.
# Flaw: publishes once; turtlesim stops the turtle 1 s later.
import rospy
from geometry_msgs.msg import Twist

rospy.init_node('move_circle')
pub = rospy.Publisher('/turtle1/cmd_vel', Twist, queue_size=10)
rospy.sleep(1.0)  # wait for the connection

vel = Twist()
vel.linear.x = 2.0
vel.angular.z = 1.8
pub.publish(vel)
rospy.spin()
